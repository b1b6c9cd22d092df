//! NEMOH v3's Tecplot results of the first-order problem, as its postProc writes them
//! (NEMOH's `Results.f90`, `SaveTResults`):
//!
//! - `results/RadiationCoefficients.tec`: a `VARIABLES="w (rad/s)"` line (or `"f (Hz)"`,
//!   `"T (s)"`), one `"A   1   j" "B   1   j"` line per generalised force j, then per
//!   radiating DOF i a `Zone t="Motion of body 1 in DoF i",I=N,F=POINT` and N rows
//!   `w A_1 B_1 ... A_n B_n`: the force j (a generalised force of Nemoh.cal) due to the
//!   motion i (a DOF of Nemoh.cal), so the zone is the matrix's column: A[j][i] with the
//!   force's row first (kg, kg m, kg m^2; B in N s/m, ...).
//! - `results/ExcitationForce.tec`: the same header with `"abs(F 1 j)" "angle(F 1 j)"`,
//!   then per heading a `Zone t="Excitation force - beta = B deg",I=N,F=POINT` and N rows
//!   `w |F_1| arg(F_1) ... |F_n| arg(F_n)`: F = |F| e^{i arg} (arg in radians, atan2 of
//!   the complex force) per unit amplitude, N/m, N m/m, with NEMOH's time factor
//!   e^{-i w t} and the phase relative to the incident elevation at the origin.
//!
//! Values are read as written (dimensional, NEMOH's convention); the first-order import
//! turns them into the database's. Errors name `file:line` and the field.

use super::cal::FrequencyUnit;
use super::matrices::Lines;
use crate::error::{Error, Result};
use crate::files::Cost;
use rustfft::num_complex::Complex64;
use std::path::Path;

/// What reading a Tecplot result costs: up to 14 bytes of memory per byte of the file
/// (measured on its costliest contents: one-number lines and one-DOF rows, each a line of
/// the reader's), with a margin for the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "NEMOH Tecplot file",
    per_byte: 28.0,
};

/// A Tecplot result's zones, every zone on the same frequencies.
#[derive(Debug, Clone, PartialEq)]
struct Zones {
    /// Frequencies, rad/s, in the file's order.
    omegas: Vec<f64>,
    /// The number each zone's title gives after its key (the DoF, the heading in deg).
    titles: Vec<f64>,
    /// Pairs per row after the frequency: one per generalised force.
    forces: usize,
    /// `values[((zone * n_omega) + k) * 2 * forces + c]`.
    values: Vec<f64>,
}

impl Zones {
    fn pair(&self, zone: usize, k: usize, force: usize) -> (f64, f64) {
        let at = (zone * self.omegas.len() + k) * 2 * self.forces + 2 * force;
        (self.values[at], self.values[at + 1])
    }
}

/// `RadiationCoefficients.tec`: added mass and damping per frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct Radiation {
    /// Frequencies, rad/s, in the file's order.
    pub omegas: Vec<f64>,
    zones: Zones,
}

impl Radiation {
    /// (A, B) of the force `force` due to the motion `motion` (0-based indices of
    /// Nemoh.cal's generalised forces and DOFs) at the `k`-th frequency.
    pub fn coefficients(&self, k: usize, force: usize, motion: usize) -> (f64, f64) {
        self.zones.pair(motion, k, force)
    }
}

/// `ExcitationForce.tec`: the excitation per frequency and heading.
#[derive(Debug, Clone, PartialEq)]
pub struct Excitation {
    /// Frequencies, rad/s, in the file's order.
    pub omegas: Vec<f64>,
    /// Headings, rad, in the file's order (the zones' titles).
    pub headings: Vec<f64>,
    zones: Zones,
}

impl Excitation {
    /// F = |F| e^{i arg} of the generalised force `force` (0-based) at the `k`-th
    /// frequency and `h`-th heading, as NEMOH gives it (e^{-i w t}).
    pub fn force(&self, k: usize, h: usize, force: usize) -> Complex64 {
        let (modulus, phase) = self.zones.pair(h, k, force);
        Complex64::from_polar(modulus, phase)
    }
}

/// Reads `RadiationCoefficients.tec` within `memory_limit` bytes: `dofs` zones (Nemoh.cal's
/// DOFs, in its order) of `forces` (A, B) pairs.
pub fn read_radiation(
    path: &Path,
    dofs: usize,
    forces: usize,
    memory_limit: f64,
) -> Result<Radiation> {
    let zones = read_zones(path, "DoF", "the DoF", memory_limit)?;
    let name = path.display().to_string();
    check_counts(&name, &zones, dofs, forces, "radiating DOFs (zones)")?;
    for (z, &dof) in zones.titles.iter().enumerate() {
        if dof != (z + 1) as f64 {
            return Err(Error::Parse {
                path: name,
                line: None,
                message: format!(
                    "zone {} is titled DoF {dof}: the zones must be DoF 1 to {dofs} in order",
                    z + 1
                ),
            });
        }
    }
    Ok(Radiation {
        omegas: zones.omegas.clone(),
        zones,
    })
}

/// Reads `ExcitationForce.tec` within `memory_limit` bytes: one zone per heading of
/// `forces` (|F|, arg F) pairs.
pub fn read_excitation(path: &Path, forces: usize, memory_limit: f64) -> Result<Excitation> {
    let zones = read_zones(path, "beta =", "the heading (beta = B deg)", memory_limit)?;
    let name = path.display().to_string();
    check_counts(&name, &zones, zones.titles.len(), forces, "headings")?;
    for k in 0..zones.omegas.len() {
        for h in 0..zones.titles.len() {
            for f in 0..forces {
                if zones.pair(h, k, f).0 < 0.0 {
                    return Err(Error::Parse {
                        path: name,
                        line: None,
                        message: format!(
                            "|F| of force {} at heading {} deg, frequency {} rad/s is \
                             negative",
                            f + 1,
                            zones.titles[h],
                            zones.omegas[k]
                        ),
                    });
                }
            }
        }
    }
    Ok(Excitation {
        omegas: zones.omegas.clone(),
        headings: zones.titles.iter().map(|b| b.to_radians()).collect(),
        zones,
    })
}

fn check_counts(
    name: &str,
    zones: &Zones,
    expected_zones: usize,
    forces: usize,
    what: &str,
) -> Result<()> {
    if zones.forces != forces {
        return Err(Error::Parse {
            path: name.to_string(),
            line: None,
            message: format!(
                "{} generalised forces in the header, Nemoh.cal has {forces}",
                zones.forces
            ),
        });
    }
    if zones.titles.len() != expected_zones || expected_zones == 0 {
        return Err(Error::Parse {
            path: name.to_string(),
            line: None,
            message: format!(
                "{} zones, expected {expected_zones} {what}",
                zones.titles.len()
            ),
        });
    }
    Ok(())
}

/// The number after `key` in a zone's title (`Zone t="... DoF   3",I=...`).
fn title_number(line: &str, key: &str) -> Option<f64> {
    let title = line.split('"').nth(1)?;
    let rest = &title[title.find(key)? + key.len()..];
    rest.split_whitespace()
        .next()?
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
}

/// The zone's point count `I=N`.
fn zone_count(line: &str) -> Option<usize> {
    let after_title = line.rsplit('"').next()?;
    let at = after_title.find("I=")?;
    let digits: String = after_title[at + 2..]
        .trim_start()
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits.parse().ok()
}

/// The header, the variable lines and the zones of a Tecplot result.
fn read_zones(path: &Path, key: &str, field: &str, memory_limit: f64) -> Result<Zones> {
    let name = path.display().to_string();
    let text = crate::files::read_text(path, &READING, memory_limit)?;
    let file = Lines::new(name.clone(), &text);
    let at = |line: usize, message: String| Error::Parse {
        path: name.clone(),
        line: Some(line),
        message,
    };
    let mut rows = file.rows.iter().copied().peekable();
    let (line, header) = rows.next().ok_or_else(|| Error::Parse {
        path: name.clone(),
        line: None,
        message: "empty file".into(),
    })?;
    let unit = if !header
        .trim_start()
        .to_ascii_uppercase()
        .starts_with("VARIABLES")
    {
        None
    } else if header.contains("\"w (rad/s)\"") {
        Some(FrequencyUnit::RadPerSecond)
    } else if header.contains("\"f (Hz)\"") {
        Some(FrequencyUnit::Hertz)
    } else if header.contains("\"T (s)\"") {
        Some(FrequencyUnit::Second)
    } else {
        None
    };
    let unit = unit.ok_or_else(|| {
        at(
            line,
            format!(
                "expected VARIABLES=\"w (rad/s)\" (or \"f (Hz)\", \"T (s)\"), found \"{}\"",
                header.trim()
            ),
        )
    })?;
    let mut forces = 0;
    while let Some(&(line, text)) = rows.peek() {
        if !text.trim_start().starts_with('"') {
            break;
        }
        if text.matches('"').count() != 4 {
            return Err(at(
                line,
                "expected two quoted variable names (one generalised force)".into(),
            ));
        }
        forces += 1;
        rows.next();
    }
    if forces == 0 {
        return Err(at(line, "no variable names after VARIABLES".into()));
    }
    let width = 1 + 2 * forces;
    let mut omegas: Vec<f64> = Vec::new();
    let mut titles = Vec::new();
    let mut values = Vec::new();
    let mut row_reference = None;
    while let Some((line, zone)) = rows.next() {
        if !zone.trim_start().to_ascii_uppercase().starts_with("ZONE") {
            return Err(at(
                line,
                format!(
                    "expected a Zone line (zone {}), found \"{}\"",
                    titles.len() + 1,
                    zone.trim()
                ),
            ));
        }
        let title = title_number(zone, key)
            .ok_or_else(|| at(line, format!("the zone's title has no {field}")))?;
        let count = zone_count(zone)
            .filter(|&n| n > 0)
            .ok_or_else(|| at(line, "the zone has no point count I=N (N > 0)".into()))?;
        if !titles.is_empty() && count != omegas.len() {
            return Err(at(
                line,
                format!(
                    "I={count}: the first zone has {} frequencies, every zone must have as many",
                    omegas.len()
                ),
            ));
        }
        let first = titles.is_empty();
        titles.push(title);
        for k in 0..count {
            let (line, text) = match rows.peek() {
                Some(&(l, t)) if !t.trim_start().to_ascii_uppercase().starts_with("ZONE") => {
                    rows.next();
                    (l, t)
                }
                _ => {
                    return Err(Error::Parse {
                        path: name.clone(),
                        line: None,
                        message: format!(
                            "zone {} announces I={count} rows, it ends after {k}",
                            titles.len()
                        ),
                    })
                }
            };
            let row = file.numbers(line, text, &mut row_reference)?;
            if row.len() != width {
                return Err(at(
                    line,
                    format!(
                        "expected {width} numbers (the frequency and two per generalised \
                         force), found {}",
                        row.len()
                    ),
                ));
            }
            if row[0] <= 0.0 {
                return Err(at(
                    line,
                    format!("the frequency {} must be positive", row[0]),
                ));
            }
            let omega = match unit {
                FrequencyUnit::RadPerSecond => row[0],
                FrequencyUnit::Hertz => 2.0 * std::f64::consts::PI * row[0],
                FrequencyUnit::Second => 2.0 * std::f64::consts::PI / row[0],
            };
            if first {
                omegas.push(omega);
            } else if (omega - omegas[k]).abs() > 1e-6 * omegas[k] {
                return Err(at(
                    line,
                    format!(
                        "frequency {} rad/s: row {} of the first zone is at {} rad/s; every \
                         zone must list the same frequencies",
                        omega,
                        k + 1,
                        omegas[k]
                    ),
                ));
            }
            values.extend_from_slice(&row[1..]);
        }
    }
    if titles.is_empty() {
        return Err(Error::Parse {
            path: name,
            line: None,
            message: "no zone".into(),
        });
    }
    Ok(Zones {
        omegas,
        titles,
        forces,
        values,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(name: &str, text: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("slowdrift-tec-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    }

    /// Two DOFs, two forces: zone i holds the force j of motion i; periods are turned into
    /// rad/s; excitation as |F| e^{i arg}.
    #[test]
    fn zones_read_as_written() {
        let path = write(
            "rad.tec",
            "VARIABLES=\"T (s)\"\n\"A   1   1\" \"B   1   1\"\n\"A   1   2\" \"B   1   2\"\n\
             Zone t=\"Motion of body    1 in DoF   1\",I=   2,F=POINT\n\
             10.0 1.0 2.0 3.0 4.0\n5.0 5.0 6.0 7.0 8.0\n\
             Zone t=\"Motion of body    1 in DoF   2\",I=   2,F=POINT\n\
             10.0 11.0 12.0 13.0 14.0\n5.0 15.0 16.0 17.0 18.0\n",
        );
        let r = read_radiation(&path, 2, 2, 1e9).unwrap();
        let two_pi = 2.0 * std::f64::consts::PI;
        assert_eq!(r.omegas, vec![two_pi / 10.0, two_pi / 5.0]);
        // Force 2 due to motion 1 at the second period: zone 1, pair 2.
        assert_eq!(r.coefficients(1, 1, 0), (7.0, 8.0));
        assert_eq!(r.coefficients(0, 0, 1), (11.0, 12.0));
        let path = write(
            "exc.tec",
            "VARIABLES=\"w (rad/s)\"\n\"abs(F   1   1)\" \"angle(F   1   1)\"\n\
             Zone t=\"Excitation force - beta =   0.000 deg\",I=   1,F=POINT\n0.5 2.0 -1.5\n\
             Zone t=\"Excitation force - beta =  90.000 deg\",I=   1,F=POINT\n0.5 3.0 0.25\n",
        );
        let e = read_excitation(&path, 1, 1e9).unwrap();
        assert_eq!(e.headings, vec![0.0, 90f64.to_radians()]);
        assert!((e.force(0, 1, 0) - Complex64::from_polar(3.0, 0.25)).norm() < 1e-15);
    }

    #[test]
    fn bad_files_are_refused_at_file_and_line() {
        let head = "VARIABLES=\"w (rad/s)\"\n\"A   1   1\" \"B   1   1\"\n";
        for (text, expected) in [
            (
                format!(
                    "{head}Zone t=\"Motion of body    1 in DoF   1\",I=   2,F=POINT\n0.5 1 2\n"
                ),
                "announces I=2 rows, it ends after 1".to_string(),
            ),
            (
                format!(
                    "{head}Zone t=\"Motion of body    1 in DoF   1\",I=   1,F=POINT\n0.5 1 x\n"
                ),
                ":4: field 3 (\"x\") is not a finite number".to_string(),
            ),
            (
                format!("{head}Zone t=\"Motion of body    1 in DoF   1\",I=   1,F=POINT\n0.5 1\n"),
                ":4: expected 3 numbers".to_string(),
            ),
            (
                format!(
                    "{head}Zone t=\"Motion of body    1 in DoF   2\",I=   1,F=POINT\n0.5 1 2\n"
                ),
                "titled DoF 2".to_string(),
            ),
            (
                "VARIABLES=\"omega\"\n".to_string(),
                ":1: expected VARIABLES=".to_string(),
            ),
            (
                format!(
                    "{head}Zone t=\"Motion of body    1 in DoF   1\",I=   1,F=POINT\n\
                     0.1234E+01 0.1E+01 0.2E+01\n\
                     Zone t=\"Motion of body    1 in DoF   2\",I=   1,F=POINT\n\
                     0.1234E+01 0.1 0.2E+01\n"
                ),
                ":6: field 2 (\"0.1\")".to_string(),
            ),
        ] {
            let path = write("bad.tec", &text);
            let dofs = if text.contains("DoF   2\",I=   1,F=POINT\n0.1234") {
                2
            } else {
                1
            };
            let err = read_radiation(&path, dofs, 1, 1e9).unwrap_err().to_string();
            assert!(
                err.contains("bad.tec") && err.contains(&expected),
                "{err} (expected {expected})"
            );
        }
    }
}
