//! `Nemoh.cal`, NEMOH v3's input file: the environment, the body's degrees of freedom and
//! generalised forces (with the points moments are taken about), and the frequencies of
//! the first-order and QTF computations.
//!
//! The file is read by sections (lines starting with `---`); every value is the first
//! numbers of its line (NEMOH's comments follow them). Errors name `Nemoh.cal:LINE` and the
//! field.

use crate::error::numbers::written;
use crate::error::{Error, Result};
use crate::files::Cost;
use std::path::Path;

/// Units NEMOH writes frequencies in (Nemoh.cal's "freq type" 1, 2, 3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrequencyUnit {
    RadPerSecond,
    Hertz,
    Second,
}

impl FrequencyUnit {
    /// The value of `omega` (rad/s) in this unit.
    pub fn of_omega(self, omega: f64) -> f64 {
        match self {
            FrequencyUnit::RadPerSecond => omega,
            FrequencyUnit::Hertz => omega / (2.0 * std::f64::consts::PI),
            FrequencyUnit::Second => 2.0 * std::f64::consts::PI / omega,
        }
    }

    /// The unit's name as NEMOH's headers write it.
    pub fn name(self) -> &'static str {
        match self {
            FrequencyUnit::RadPerSecond => "rad/s",
            FrequencyUnit::Hertz => "Hz",
            FrequencyUnit::Second => "s",
        }
    }
}

/// A degree of freedom or a generalised force of the body: a translation along
/// `direction`, or a rotation (a moment) about the axis `direction` through `point`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Generalised {
    pub rotation: bool,
    pub direction: [f64; 3],
    /// The point of a rotation's axis, m (zero for a translation).
    pub point: [f64; 3],
    /// Its line in Nemoh.cal, 1-based.
    pub line: usize,
}

impl Generalised {
    fn is(&self, rotation: bool, direction: [f64; 3]) -> bool {
        self.rotation == rotation && self.direction == direction
    }
}

/// The QTF settings of Nemoh.cal.
#[derive(Debug, Clone, PartialEq)]
pub struct QtfSettings {
    /// The QTF frequencies: `count` evenly spaced from `min` to `max`, rad/s.
    pub count: usize,
    pub min: f64,
    pub max: f64,
    /// Whether bi-directional QTFs were computed.
    pub bidirectional: bool,
    /// The unit of the frequencies in the QTF output files.
    pub output_unit: FrequencyUnit,
    /// Lines of the frequency and output-unit settings, 1-based.
    pub grid_line: usize,
    pub unit_line: usize,
}

impl QtfSettings {
    /// The QTF frequencies, rad/s.
    pub fn omegas(&self) -> Vec<f64> {
        let n = self.count;
        (0..n)
            .map(|k| {
                if n == 1 {
                    self.min
                } else {
                    self.min + (self.max - self.min) * k as f64 / (n - 1) as f64
                }
            })
            .collect()
    }
}

/// What SlowDrift takes from Nemoh.cal.
#[derive(Debug, Clone, PartialEq)]
pub struct NemohCal {
    pub path: String,
    /// Water density, kg/m^3, and gravity, m/s^2, that NEMOH's outputs are made with.
    pub rho: f64,
    pub gravity: f64,
    /// Water depth, m; 0 is NEMOH's infinite depth.
    pub depth: f64,
    /// The body's degrees of freedom (the radiation problems) and generalised forces.
    pub dofs: Vec<Generalised>,
    pub forces: Vec<Generalised>,
    /// First-order frequencies: count, min, max in `first_order_unit`, and their line.
    pub first_order: (usize, f64, f64),
    pub first_order_unit: FrequencyUnit,
    pub first_order_line: usize,
    /// The QTF settings, when the QTF section asks for a QTF (flag 1).
    pub qtf: Option<QtfSettings>,
}

/// Surge, sway and yaw: translations along x and y, the rotation about z.
pub const SLOW: [(bool, [f64; 3]); 3] = [
    (false, [1.0, 0.0, 0.0]),
    (false, [0.0, 1.0, 0.0]),
    (true, [0.0, 0.0, 1.0]),
];

/// The six rigid-body DOFs in the database's order: translations along x, y, z, rotations
/// about x, y, z.
pub const SIX: [(bool, [f64; 3]); 6] = [
    (false, [1.0, 0.0, 0.0]),
    (false, [0.0, 1.0, 0.0]),
    (false, [0.0, 0.0, 1.0]),
    (true, [1.0, 0.0, 0.0]),
    (true, [0.0, 1.0, 0.0]),
    (true, [0.0, 0.0, 1.0]),
];

/// What reading a Nemoh.cal costs: up to 18 bytes of memory per byte of the file (measured
/// on its costliest content: blank lines, each a line of the reader's), with a margin for
/// the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "Nemoh.cal",
    per_byte: 28.0,
};

impl NemohCal {
    /// Reads `path` (Nemoh.cal) within `memory_limit` bytes; one body only.
    pub fn read(path: &Path, memory_limit: f64) -> Result<Self> {
        let name = path.display().to_string();
        let text = crate::files::read_text(path, &READING, memory_limit)?;
        let lines: Vec<&str> = text.lines().collect();
        let mut cursor = Cursor {
            name: &name,
            lines: &lines,
            at: 0,
        };
        cursor.section("Environment")?;
        let rho = cursor.numbers(1, "RHO")?[0];
        let gravity = cursor.numbers(1, "G")?[0];
        let depth = cursor.numbers(1, "DEPTH")?[0];
        for (value, field) in [(rho, "RHO"), (gravity, "G")] {
            if value.is_nan() || value <= 0.0 {
                return Err(cursor.error_at(
                    cursor.at,
                    format!("{field} = {} must be positive", written(value)),
                ));
            }
        }
        if depth < 0.0 {
            return Err(cursor.error_at(
                cursor.at,
                format!(
                    "DEPTH = {} must be 0 (infinite) or positive",
                    written(depth)
                ),
            ));
        }
        cursor.section("Description of floating bodies")?;
        let bodies = cursor.numbers(1, "Number of bodies")?[0];
        if bodies != 1.0 {
            return Err(cursor.error_at(
                cursor.at,
                format!("Number of bodies = {bodies}: SlowDrift reads single-body results only"),
            ));
        }
        cursor.section("Body 1")?;
        cursor.skip(2); // the mesh file's name; its points and panels
        let dofs = cursor.generalised("Number of degrees of freedom")?;
        let forces = cursor.generalised("Number of resulting generalised forces")?;
        cursor.section("Load cases to be solved")?;
        let (first_order_unit, first_order, first_order_line) = {
            let values = cursor.leading_numbers("frequencies (type, count, min, max)")?;
            let line = cursor.at;
            match values.as_slice() {
                [unit, count, min, max, ..] => (
                    cursor.unit(*unit, "Freq type")?,
                    (
                        cursor.count(*count, "Number of wave frequencies")?,
                        *min,
                        *max,
                    ),
                    line,
                ),
                _ => {
                    return Err(cursor.error_at(
                        line,
                        "expected the frequency type, count, min and max".to_string(),
                    ))
                }
            }
        };
        let qtf = match cursor.find_section("QTF") {
            None => None,
            Some(()) => {
                let flag = cursor.numbers(1, "QTF flag")?[0];
                if flag != 1.0 {
                    None
                } else {
                    let grid = cursor.numbers(3, "QTF frequencies (count, min, max)")?;
                    let grid_line = cursor.at;
                    let count = cursor.count(grid[0], "Number of radial frequencies")?;
                    let bidirectional = cursor.numbers(1, "Unidirection/Bidirection")?[0] == 1.0;
                    cursor.skip(4); // contributions, free-surface mesh and its parameters, hydrostatic terms
                    let unit = cursor.numbers(1, "For QTFposProc, output freq type")?[0];
                    let unit_line = cursor.at;
                    Some(QtfSettings {
                        count,
                        min: grid[1],
                        max: grid[2],
                        bidirectional,
                        output_unit: cursor.unit(unit, "For QTFposProc, output freq type")?,
                        grid_line,
                        unit_line,
                    })
                }
            }
        };
        Ok(NemohCal {
            path: name.clone(),
            rho,
            gravity,
            depth,
            dofs,
            forces,
            first_order,
            first_order_unit,
            first_order_line,
            qtf,
        })
    }

    /// The 1-based indices of surge, sway and yaw among `list` (the DOFs or the forces);
    /// the error names what is missing.
    pub fn slow_indices(&self, list: &[Generalised], what: &str) -> Result<[usize; 3]> {
        let mut out = [0; 3];
        for (k, (rotation, direction)) in SLOW.iter().enumerate() {
            match list.iter().position(|g| g.is(*rotation, *direction)) {
                Some(i) => out[k] = i + 1,
                None => {
                    return Err(Error::Parse {
                        path: self.path.clone(),
                        line: None,
                        message: format!(
                            "the body has no {what} {} ({}); SlowDrift needs surge, sway and yaw",
                            ["surge", "sway", "yaw"][k],
                            [
                                "translation along 1 0 0",
                                "translation along 0 1 0",
                                "rotation about 0 0 1"
                            ][k]
                        ),
                    })
                }
            }
        }
        Ok(out)
    }
}

impl NemohCal {
    /// The 0-based indices of surge, sway, heave, roll, pitch and yaw among `list` (the
    /// DOFs or the forces) and the point of its rotations (all three about one point), or
    /// why not (a DOF missing, rotations about different points).
    pub fn six_indices(
        list: &[Generalised],
    ) -> std::result::Result<([usize; 6], [f64; 3]), String> {
        let names = ["surge", "sway", "heave", "roll", "pitch", "yaw"];
        let mut out = [0; 6];
        for (k, (rotation, direction)) in SIX.iter().enumerate() {
            out[k] = list
                .iter()
                .position(|g| g.is(*rotation, *direction))
                .ok_or_else(|| format!("no {}", names[k]))?;
        }
        let point = list[out[3]].point;
        for k in [4, 5] {
            let g = &list[out[k]];
            if g.point != point {
                return Err(format!(
                    "{} (line {}) is about ({}, {}, {}), roll (line {}) about ({}, {}, {}): \
                     the rotations must share one point",
                    names[k],
                    g.line,
                    g.point[0],
                    g.point[1],
                    g.point[2],
                    list[out[3]].line,
                    point[0],
                    point[1],
                    point[2]
                ));
            }
        }
        Ok((out, point))
    }
}

/// A position in Nemoh.cal's lines.
struct Cursor<'a> {
    name: &'a str,
    lines: &'a [&'a str],
    /// The 1-based number of the line last read.
    at: usize,
}

impl Cursor<'_> {
    fn error_at(&self, line: usize, message: String) -> Error {
        Error::Parse {
            path: self.name.to_string(),
            line: Some(line),
            message,
        }
    }

    /// Moves past the section header containing `title` (as NEMOH writes it); an error
    /// when there is none.
    fn section(&mut self, title: &str) -> Result<()> {
        self.find_section(title).ok_or_else(|| Error::Parse {
            path: self.name.to_string(),
            line: None,
            message: format!("no \"--- {title} ---\" section"),
        })
    }

    fn find_section(&mut self, title: &str) -> Option<()> {
        let k = self.lines[self.at..]
            .iter()
            .position(|l| l.trim_start().starts_with("---") && l.contains(title))?;
        self.at += k + 1;
        Some(())
    }

    fn skip(&mut self, lines: usize) {
        self.at += lines;
    }

    /// The numbers at the start of the next line (up to the first token that is not one).
    fn leading_numbers(&mut self, field: &str) -> Result<Vec<f64>> {
        self.at += 1;
        let line = self.lines.get(self.at - 1).ok_or_else(|| Error::Parse {
            path: self.name.to_string(),
            line: Some(self.at),
            message: format!("the file ends where {field} is expected"),
        })?;
        Ok(line
            .split_whitespace()
            .map_while(|t| t.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect())
    }

    /// At least `count` leading numbers of the next line.
    fn numbers(&mut self, count: usize, field: &str) -> Result<Vec<f64>> {
        let values = self.leading_numbers(field)?;
        if values.len() < count {
            return Err(self.error_at(
                self.at,
                format!(
                    "{field}: expected {count} number(s) at the start of the line, found {}",
                    values.len()
                ),
            ));
        }
        Ok(values)
    }

    fn count(&self, value: f64, field: &str) -> Result<usize> {
        if value.fract() == 0.0 && (1.0..=1.0e6).contains(&value) {
            Ok(value as usize)
        } else {
            Err(self.error_at(
                self.at,
                format!(
                    "{field} = {}: must be a whole number from 1 to 1e6",
                    written(value)
                ),
            ))
        }
    }

    fn unit(&self, value: f64, field: &str) -> Result<FrequencyUnit> {
        match value {
            1.0 => Ok(FrequencyUnit::RadPerSecond),
            2.0 => Ok(FrequencyUnit::Hertz),
            3.0 => Ok(FrequencyUnit::Second),
            v => Err(self.error_at(
                self.at,
                format!(
                    "{field} = {}: must be 1 (rad/s), 2 (Hz) or 3 (s)",
                    written(v)
                ),
            )),
        }
    }

    /// A count line followed by that many `type dx dy dz x y z` lines.
    fn generalised(&mut self, field: &str) -> Result<Vec<Generalised>> {
        let n = self.numbers(1, field)?[0];
        let n = self.count(n, field)?;
        let mut out = Vec::with_capacity(n);
        for _ in 0..n {
            let v = self.numbers(7, "type, direction and point (type dx dy dz x y z)")?;
            let rotation = match v[0] {
                1.0 => false,
                2.0 => true,
                t => {
                    return Err(self.error_at(
                        self.at,
                        format!("type = {t}: must be 1 (translation) or 2 (rotation)"),
                    ))
                }
            };
            out.push(Generalised {
                rotation,
                direction: [v[1], v[2], v[3]],
                point: if rotation {
                    [v[4], v[5], v[6]]
                } else {
                    [0.0; 3]
                },
                line: self.at,
            });
        }
        Ok(out)
    }
}
