//! `slowdrift hydro wamit --root PATH/NAME [--ulen L] [--rho RHO] [--g G] --out FILE.json`:
//! imports the WAMIT files `NAME.1`, `.hst`, `.8`, `.9`, `.12d` (or `.11d`, `.10d`) that
//! exist into a native hydro database and prints what it found.
//!
//! `slowdrift hydro columns [--config FILE.toml] --out FILE.json`: writes the drift table
//! (and wave-drift damping) of a configuration (default: the embedded default platform,
//! whose `[drift]` is the column-array solver) as a native hydro database.

use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::wamit::WamitOptions;
use slowdrift::problem::{self, default_problem};
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use std::path::PathBuf;

pub const USAGE: &str =
    "slowdrift hydro wamit --root PATH/NAME [--ulen 1] [--rho 1025] [--g 9.80665] --out FILE.json";
pub const COLUMNS_USAGE: &str = "slowdrift hydro columns [--config FILE.toml] --out FILE.json";

/// Runs `slowdrift hydro ...` with the arguments after `hydro`.
pub fn run(args: &[String]) -> Result<(), String> {
    match args.first().map(String::as_str) {
        Some("wamit") => wamit(&args[1..]),
        Some("columns") => columns(&args[1..]),
        _ => Err(format!("usage: {USAGE}\n       {COLUMNS_USAGE}")),
    }
}

fn columns(args: &[String]) -> Result<(), String> {
    let (mut config_path, mut out) = (None, None);
    let mut rest = args.iter();
    while let Some(flag) = rest.next() {
        let value = rest
            .next()
            .ok_or_else(|| format!("{flag} needs a value\nusage: {COLUMNS_USAGE}"))?;
        match flag.as_str() {
            "--config" => config_path = Some(PathBuf::from(value)),
            "--out" => out = Some(PathBuf::from(value)),
            other => return Err(format!("unknown option '{other}'\nusage: {COLUMNS_USAGE}")),
        }
    }
    let out = out.ok_or_else(|| format!("--out is required\nusage: {COLUMNS_USAGE}"))?;
    let (config, source) = match &config_path {
        Some(path) => (
            problem::load(path).map_err(|e| e.to_string())?,
            format!("[drift] of {}", path.display()),
        ),
        None => (
            default_problem().map_err(|e| e.to_string())?,
            DEFAULT_DRIFT_LABEL.to_string(),
        ),
    };
    let table = &config.hydro.drift;
    let database = HydroDatabase::from_drift_table("platform", &source, &config.environment, table);
    database.save(&out).map_err(|e| e.to_string())?;
    println!(
        "drift{} on {} frequencies x {} headings ({source}) written to {}",
        if table.has_damping() {
            " and damping"
        } else {
            ""
        },
        table.omegas().len(),
        table.headings().len(),
        out.display()
    );
    Ok(())
}

fn wamit(args: &[String]) -> Result<(), String> {
    let mut root = None;
    let mut out = None;
    let mut options = WamitOptions::default();
    let mut rest = args.iter();
    while let Some(flag) = rest.next() {
        let value = rest
            .next()
            .ok_or_else(|| format!("{flag} needs a value\nusage: {USAGE}"))?;
        let number = || -> Result<f64, String> {
            match value.parse::<f64>() {
                Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
                _ => Err(format!("{flag} {value}: must be a positive number")),
            }
        };
        match flag.as_str() {
            "--root" => root = Some(PathBuf::from(value)),
            "--out" => out = Some(PathBuf::from(value)),
            "--ulen" => options.ulen = number()?,
            "--rho" => options.rho = number()?,
            "--g" => options.gravity = number()?,
            other => return Err(format!("unknown option '{other}'\nusage: {USAGE}")),
        }
    }
    let root = root.ok_or_else(|| format!("--root is required\nusage: {USAGE}"))?;
    let out = out.ok_or_else(|| format!("--out is required\nusage: {USAGE}"))?;
    let import = HydroDatabase::from_wamit(&root, &options).map_err(|e| e.to_string())?;
    println!(
        "WAMIT files {}.* (ULEN = {} m, rho = {} kg/m^3, g = {} m/s^2):",
        root.display(),
        options.ulen,
        options.rho,
        options.gravity
    );
    for line in &import.files {
        println!("  {line}");
    }
    let db = &import.database;
    if db.drift.is_empty() {
        println!("drift: none");
    } else {
        let table = db.to_drift_table().map_err(|e| e.to_string())?;
        let (w, h) = (table.omegas(), table.headings());
        println!(
            "drift (surge, sway, yaw): {} frequencies {:.4} .. {:.4} rad/s x {} headings [{}] deg",
            w.len(),
            w[0],
            w[w.len() - 1],
            h.len(),
            h.iter()
                .map(|x| format!("{:.2}", x.to_degrees()))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    match &db.qtf {
        Some(q) => println!(
            "QTF (surge, sway, yaw): {n} x {n} frequencies, {} blocks",
            q.blocks.len(),
            n = q.omegas.len()
        ),
        None => println!("QTF: none"),
    }
    let yes = |b: bool| if b { "yes" } else { "no" };
    println!(
        "low-frequency added mass: {}; hydrostatic stiffness: {}",
        yes(db.low_frequency_added_mass.is_some()),
        yes(db.stiffness.is_some())
    );
    db.save(&out).map_err(|e| e.to_string())?;
    println!("database \"{}\" written to {}", db.name, out.display());
    Ok(())
}
