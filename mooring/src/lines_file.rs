//! The lines of a MoorDyn v2 input file, read for the quasi-static line model: each line's
//! type (diameter, mass per length, EA), its anchor (a `Fixed` point on the seabed) and its
//! fairlead (a point on `Body1`, in the body's frame), and the options `g`, `rho` (or
//! `WtrDnsty`) and `WtrDpth` (or `depth`).
//!
//! Only what a quasi-static spread mooring has is accepted: every line from a fixed point on
//! the seabed to a point on body 1; a free point, a rod, a second body, a nonlinear EA (a
//! file name in the EA column) is refused, naming the file and line. MoorDyn itself reads
//! the same file for the dynamic model (sections it knows and this reader does not, such as
//! the line types' drag coefficients, matter only there).

use crate::catenary::Line;
use std::collections::HashMap;
use std::path::Path;

/// One line of the mooring: its catenary properties, its anchor (inertial frame, m) and its
/// fairlead (body frame, relative to the body's reference point, m).
#[derive(Debug, Clone, PartialEq)]
pub struct MooringLine {
    pub id: String,
    pub line: Line,
    pub anchor: [f64; 3],
    pub fairlead: [f64; 3],
}

/// MoorDyn's defaults where the file sets no option.
const DEFAULT_G: f64 = 9.80665;
const DEFAULT_RHO: f64 = 1025.0;

struct LineType {
    diameter: f64,
    mass: f64,
    ea: f64,
}

enum Point {
    Fixed([f64; 3]),
    Body([f64; 3]),
}

/// Reads the lines of the MoorDyn input file `path`.
pub fn read(path: &Path) -> Result<Vec<MooringLine>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse(&text).map_err(|(line, e)| format!("{}:{line}: {e}", path.display()))
}

/// The lines of the file's text; an error carries the 1-based line number.
pub fn parse(text: &str) -> Result<Vec<MooringLine>, (usize, String)> {
    let mut section = String::new();
    let mut skip = 0;
    let mut types = HashMap::new();
    let mut points = HashMap::new();
    let mut rows = Vec::new();
    let (mut g, mut rho, mut depth) = (DEFAULT_G, DEFAULT_RHO, None);
    for (index, raw) in text.lines().enumerate() {
        let n = index + 1;
        let row = raw.trim();
        if row.starts_with("---") {
            section = row.trim_matches('-').trim().to_ascii_uppercase();
            // Table sections have a line of column names and a line of units.
            skip = if section == "OPTIONS" { 0 } else { 2 };
            continue;
        }
        if row.is_empty() || section.is_empty() {
            continue;
        }
        if skip > 0 {
            skip -= 1;
            continue;
        }
        let words: Vec<&str> = row.split_whitespace().collect();
        let number = |i: usize, what: &str| -> Result<f64, (usize, String)> {
            let word = words
                .get(i)
                .ok_or((n, format!("no {what} (column {})", i + 1)))?;
            word.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or((n, format!("{what} = {word} is not a finite number")))
        };
        match section.as_str() {
            "LINE TYPES" | "LINE DICTIONARY" => {
                let name = words[0].to_string();
                let ea = number(3, "EA").map_err(|(n, e)| {
                    (
                        n,
                        format!(
                            "{e} (a nonlinear EA table is not supported by the quasi-static model)"
                        ),
                    )
                })?;
                types.insert(
                    name,
                    LineType {
                        diameter: number(1, "Diam")?,
                        mass: number(2, "Mass/m")?,
                        ea,
                    },
                );
            }
            "POINTS" | "POINT LIST" | "POINT PROPERTIES" | "CONNECTION PROPERTIES" => {
                let at = [number(2, "X")?, number(3, "Y")?, number(4, "Z")?];
                let kind = words.get(1).copied().unwrap_or("").to_ascii_lowercase();
                let point = match kind.as_str() {
                    "fixed" | "anchor" => Point::Fixed(at),
                    "body1" => Point::Body(at),
                    other => {
                        return Err((
                            n,
                            format!(
                                "point {} is attached to {other:?}: the quasi-static model takes \
                                 lines from a Fixed point to a point on Body1 only",
                                words[0]
                            ),
                        ))
                    }
                };
                points.insert(words[0].to_string(), point);
            }
            "LINES" | "LINE LIST" | "LINE PROPERTIES" => {
                rows.push((
                    n,
                    words.iter().map(|w| w.to_string()).collect::<Vec<_>>(),
                    number(4, "UnstrLen")?,
                ));
            }
            "OPTIONS" => match words.get(1).copied().unwrap_or("") {
                "g" | "gravity" => g = number(0, "g")?,
                "rho" | "WtrDnsty" => rho = number(0, "rho")?,
                "WtrDpth" | "depth" => depth = Some(number(0, "WtrDpth")?),
                _ => {}
            },
            "RODS" | "ROD LIST" | "ROD PROPERTIES" => {
                return Err((n, "a rod: the quasi-static model takes lines only".into()));
            }
            _ => {}
        }
    }
    let mut lines = Vec::new();
    for (k, (n, words, length)) in rows.into_iter().enumerate() {
        // MoorDyn refuses any other numbering; the FMU's fairleadTension outputs follow it.
        if words[0].parse::<usize>() != Ok(k + 1) {
            return Err((
                n,
                format!(
                    "line ID {} where {} is due: MoorDyn numbers the lines 1, 2, ... in order",
                    words[0],
                    k + 1
                ),
            ));
        }
        let point = |i: usize| {
            points
                .get(&words[i])
                .ok_or((n, format!("line {}: no point {}", words[0], words[i])))
        };
        let (anchor, fairlead) = match (point(2)?, point(3)?) {
            (Point::Fixed(a), Point::Body(f)) | (Point::Body(f), Point::Fixed(a)) => (*a, *f),
            _ => {
                return Err((
                    n,
                    format!(
                        "line {} does not join a Fixed point to a Body1 point",
                        words[0]
                    ),
                ))
            }
        };
        if let Some(depth) = depth {
            if (anchor[2] + depth).abs() > 1e-6 * depth.max(1.0) {
                return Err((
                    n,
                    format!(
                        "line {}: its anchor at z = {} m is not on the seabed (WtrDpth {depth} m): \
                         the quasi-static model rests lines on the seabed at their anchor",
                        words[0], anchor[2]
                    ),
                ));
            }
        }
        let kind = types
            .get(&words[1])
            .ok_or((n, format!("line {}: no line type {}", words[0], words[1])))?;
        let buoyancy = rho * std::f64::consts::PI / 4.0 * kind.diameter * kind.diameter;
        lines.push(MooringLine {
            id: words[0].clone(),
            line: Line {
                length,
                ea: kind.ea,
                weight: (kind.mass - buoyancy) * g,
            },
            anchor,
            fairlead,
        });
    }
    if lines.is_empty() {
        return Err((
            text.lines().count(),
            "no LINES: nothing to moor the platform".into(),
        ));
    }
    Ok(lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPREAD: &str = include_str!("../spread_mooring.dat");

    /// The spread mooring: eight lines of 1000 m of the chain84 type, the weight in water
    /// (mass - rho pi d^2 / 4) g with the file's g and rho, anchors on the seabed.
    #[test]
    fn reads_the_spread_mooring() {
        let lines = parse(SPREAD).unwrap();
        assert_eq!(lines.len(), 8);
        let w = (140.4 - 1025.0 * std::f64::consts::PI / 4.0 * 0.1512 * 0.1512) * 9.80665;
        for l in &lines {
            assert_eq!(l.line.length, 1000.0);
            assert_eq!(l.line.ea, 6.03e8);
            assert!((l.line.weight - w).abs() < 1e-9 * w);
            assert_eq!(l.anchor[2], -300.0);
            assert_eq!(l.fairlead[2], -20.0);
        }
        assert_eq!(lines[0].anchor, [980.0, 35.0, -300.0]);
        assert_eq!(lines[0].fairlead, [45.0, 35.0, -20.0]);
    }

    /// What the quasi-static model cannot represent is refused with the line number.
    #[test]
    fn refuses_what_it_cannot_model() {
        let at = |text: &str| parse(text).unwrap_err();
        let free = SPREAD.replace("9    Body1", "9    Free ");
        let (n, e) = at(&free);
        assert!(SPREAD.lines().nth(n - 1).unwrap().starts_with("9 "), "{n}");
        assert!(e.contains("Free") || e.contains("free"), "{e}");
        let (_, e) = at(&SPREAD.replace("6.03e8", "ea_table.txt"));
        assert!(
            e.contains("EA = ea_table.txt") && e.contains("nonlinear"),
            "{e}"
        );
        let (_, e) = at(&SPREAD.replace("980.0   35.0    -300.0", "980.0   35.0    -290.0"));
        assert!(e.contains("not on the seabed"), "{e}");
        let (_, e) = at(&SPREAD.replace("1    chain84   1        9", "1    chain99   1        9"));
        assert!(e.contains("no line type chain99"), "{e}");
        let (n, e) = at(&SPREAD.replace("3    chain84", "9    chain84"));
        assert!(
            SPREAD
                .lines()
                .nth(n - 1)
                .unwrap()
                .starts_with("3    chain84"),
            "{n}"
        );
        assert!(e.contains("line ID 9 where 3 is due"), "{e}");
    }
}
