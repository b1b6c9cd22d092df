//! `slowdrift hydro wamit --root PATH/NAME [--ulen L] [--rho RHO] [--g G]
//! [--memory-limit-gb GB] --out FILE.json`: imports the WAMIT files `NAME.1`, `.hst`, `.8`,
//! `.9`, `.12d` (or `.11d`, `.10d`) that exist into a native hydro database and prints what
//! it found.
//!
//! `slowdrift hydro nemoh --dir DIR [--memory-limit-gb GB] --out FILE.json`: imports the NEMOH v3 results of the
//! project directory DIR (Nemoh.cal, results/CM.dat, Mechanics/, results/QTF/OUT_QTFM_N.dat)
//! into a native hydro database and prints what it found.
//!
//! `slowdrift hydro columns [--config FILE.toml] --out FILE.json`: writes the drift table
//! (and the wave-drift damping a run of it uses: the table's b_ij, or Aranha's) of a
//! configuration (default: the embedded default platform's database) as a native
//! hydro database; with
//! `--bidirectional`, also the bi-directional drift T(omega; beta_p, beta_q) of a column-array
//! source on the same frequencies and headings (`tests/bem` joins it to the radiation-
//! diffraction data above the frequencies where the pontoons and the draft still matter).

use super::args::{gigabytes, Checked};
use clap::{Args, Subcommand};
use slowdrift::error::numbers::written;
use slowdrift::error::BYTES_PER_GB;
use slowdrift::hydro::bidirectional::{BidirectionalSource, BidirectionalTable};
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::nemoh;
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::problem::{self, default_problem};
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT;
use std::path::PathBuf;

/// `slowdrift hydro`.
#[derive(Args)]
#[command(subcommand_required = true)]
pub struct HydroArgs {
    #[command(subcommand)]
    command: HydroCommand,
}

#[derive(Subcommand)]
enum HydroCommand {
    /// Imports the WAMIT files NAME.1, .hst, .8, .9 and .12d (else .11d, else .10d) that exist
    /// into a native hydro database (JSON) and prints what it found in each
    Wamit(WamitArgs),
    /// Imports NEMOH v3 results (Nemoh.cal, results/CM.dat, Mechanics/, the difference-frequency
    /// QTF results/QTF/OUT_QTFM_N.dat) into a native hydro database (JSON) and prints what it
    /// found in each
    Nemoh(NemohArgs),
    /// Writes the drift table (and wave-drift damping) of a configuration as a native hydro
    /// database (JSON)
    Columns(ColumnsArgs),
}

#[derive(Args)]
#[command(args_override_self = true)]
struct WamitArgs {
    /// The WAMIT output: PATH/NAME of the files NAME.1, NAME.hst, ...
    #[arg(long, value_name = "PATH/NAME", allow_hyphen_values = true)]
    root: PathBuf,
    /// WAMIT's length scale ULEN of the non-dimensional values, m
    #[arg(long, value_name = "ULEN", allow_hyphen_values = true,
          default_value_t = WamitOptions::default().ulen, value_parser = Checked(positive))]
    ulen: f64,
    /// Water density, kg/m^3 (a configuration using the database must have the same)
    #[arg(long, value_name = "RHO", allow_hyphen_values = true,
          default_value_t = WamitOptions::default().rho, value_parser = Checked(positive))]
    rho: f64,
    /// Gravitational acceleration, m/s^2 (a configuration using the database must have the
    /// same)
    #[arg(long, value_name = "G", allow_hyphen_values = true,
          default_value_t = WamitOptions::default().gravity, value_parser = Checked(positive))]
    g: f64,
    /// Memory reading each file may take, GB (1e9 bytes): a file whose reading needs more is
    /// refused before it is read
    #[arg(long, value_name = "GB", allow_hyphen_values = true,
          default_value_t = DEFAULT_MEMORY_LIMIT / BYTES_PER_GB, value_parser = gigabytes())]
    memory_limit_gb: f64,
    /// The native hydro database to write (JSON)
    #[arg(long, value_name = "FILE.json", allow_hyphen_values = true)]
    out: PathBuf,
}

#[derive(Args)]
#[command(args_override_self = true)]
struct NemohArgs {
    /// NEMOH's project directory (the one with Nemoh.cal; its results/ is accepted too)
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    dir: PathBuf,
    /// Memory reading each file may take, GB (1e9 bytes): a file whose reading needs more is
    /// refused before it is read
    #[arg(long, value_name = "GB", allow_hyphen_values = true,
          default_value_t = DEFAULT_MEMORY_LIMIT / BYTES_PER_GB, value_parser = gigabytes())]
    memory_limit_gb: f64,
    /// The native hydro database to write (JSON)
    #[arg(long, value_name = "FILE.json", allow_hyphen_values = true)]
    out: PathBuf,
}

#[derive(Args)]
#[command(args_override_self = true)]
struct ColumnsArgs {
    /// Configuration (TOML) whose [drift] is written [default: the embedded default
    /// platform's database]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// The native hydro database to write (JSON)
    #[arg(long, value_name = "FILE.json", allow_hyphen_values = true)]
    out: PathBuf,
    /// Also write the bi-directional drift of every pair of the table's headings at its
    /// frequencies (needs a column-array [drift] source)
    #[arg(long)]
    bidirectional: bool,
}

/// `--ulen`, `--rho`, `--g`: a positive number.
fn positive(flag: &str, value: &str) -> Result<f64, String> {
    match value.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("{flag} {value}: must be a positive number")),
    }
}

/// Runs `slowdrift hydro ...`.
pub fn run(args: HydroArgs) -> Result<(), String> {
    match args.command {
        HydroCommand::Wamit(args) => wamit(args),
        HydroCommand::Nemoh(args) => nemoh(args),
        HydroCommand::Columns(args) => columns(args),
    }
}

fn columns(args: ColumnsArgs) -> Result<(), String> {
    let ColumnsArgs {
        config: config_path,
        out,
        bidirectional,
    } = args;
    super::out::file(&out)?;
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
    // The columns the table's damping (and a column solver) takes, within their ranges.
    config.check_columns().map_err(|e| e.to_string())?;
    // The damping a run of the configuration uses, written with the table (Aranha's on its
    // nodes when it asks for them; none when drift damping is off).
    let table = &config
        .damping_table()
        .map_err(|e| e.to_string())?
        .unwrap_or_else(|| config.hydro.drift.clone());
    let mut database =
        HydroDatabase::from_drift_table("platform", &source, &config.environment, table);
    if bidirectional {
        let Some(BidirectionalSource::ColumnArray { array, .. }) = &config.hydro.bidirectional
        else {
            return Err(format!(
                "--bidirectional: the [drift] of {source} is not the column-array solver"
            ));
        };
        database.bidirectional_drift = Some(
            BidirectionalTable::from_column_array(
                array,
                &config.environment,
                table.omegas(),
                table.headings(),
            )
            .map_err(|e| e.to_string())?,
        );
    }
    database.save(&out).map_err(|e| e.to_string())?;
    println!(
        "drift{}{} on {} frequencies x {} headings ({source}) written to {}",
        if table.has_damping() {
            " and damping"
        } else {
            ""
        },
        if bidirectional {
            ", bi-directional drift"
        } else {
            ""
        },
        table.omegas().len(),
        table.headings().len(),
        out.display()
    );
    Ok(())
}

fn wamit(args: WamitArgs) -> Result<(), String> {
    let root = args.root;
    let out = args.out;
    super::out::file(&out)?;
    let options = WamitOptions {
        ulen: args.ulen,
        rho: args.rho,
        gravity: args.g,
        memory_limit: args.memory_limit_gb * BYTES_PER_GB,
    };
    let import = wamit::import(&root, &options).map_err(|e| e.to_string())?;
    println!(
        "WAMIT files {}.* (ULEN = {} m, rho = {} kg/m^3, g = {} m/s^2):",
        root.display(),
        written(options.ulen),
        written(options.rho),
        written(options.gravity)
    );
    for line in &import.files {
        println!("  {line}");
    }
    summarize_and_save(&import.database, &out)
}

fn nemoh(args: NemohArgs) -> Result<(), String> {
    super::out::file(&args.out)?;
    let import =
        nemoh::import(&args.dir, args.memory_limit_gb * BYTES_PER_GB).map_err(|e| e.to_string())?;
    println!("NEMOH results {}:", args.dir.display());
    for line in &import.files {
        println!("  {line}");
    }
    summarize_and_save(&import.database, &args.out)
}

/// Prints what an imported database holds and writes it to `out`.
fn summarize_and_save(db: &HydroDatabase, out: &std::path::Path) -> Result<(), String> {
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
    if let Some(t) = &db.bidirectional_drift {
        println!(
            "bi-directional drift: {} frequencies x {} x {} headings",
            t.omegas.len(),
            t.headings.len(),
            t.headings.len()
        );
    }
    if let Some(m) = &db.mass_properties {
        println!(
            "mass properties: mass {:.6e} kg, yaw inertia {:.6e} kg m^2",
            m.mass, m.yaw_inertia
        );
    }
    db.save(out).map_err(|e| e.to_string())?;
    println!("database \"{}\" written to {}", db.name, out.display());
    Ok(())
}
