//! `fmu-pack`: builds the SlowDrift cdylib in release mode, writes
//! `target/fmu/SlowDrift.fmu` (modelDescription.xml, binaries/linux64/SlowDrift.so,
//! resources/platform.toml with the default platform's drift precomputed in
//! resources/platform_drift.json, documentation/index.html), then loads the library from the
//! archive through its C ABI, as a master would, runs the default platform in the default
//! sea state for three hours and prints a short summary. Then the same for the mooring FMU,
//! `target/fmu/Mooring.fmu` ([`mooring`]), and last the coupled system for a co-simulation
//! master, `target/fmu/system/` ([`system`]: both FMUs, their OSP model descriptions, the OSP
//! system structure and the SSP package). Beside them, the FMUs' FMI 3.0 model descriptions
//! as their build scripts generate them (`slowdrift-fmi-xml`):
//! `target/fmu/fmi3/SlowDrift/modelDescription.xml` and
//! `target/fmu/fmi3/Mooring/modelDescription.xml`, and SlowDrift's FMI 3.0 archive,
//! `target/fmu/fmi3/SlowDrift.fmu` (the same library and resources, the binaries in
//! `binaries/x86_64-linux/`), checked by running it through its `fmi3*` C ABI beside the
//! FMI 2.0 archive: the same outputs bit for bit.

mod archive;
mod configured;
mod master;
mod master3;
mod mooring;
mod system;

use clap::Parser;
use slowdrift::fmi2::resources::{write_resources, RESOURCE_CONFIG, RESOURCE_DRIFT};
use slowdrift::stats::{summarize, Summary};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const MODEL_IDENTIFIER: &str = "SlowDrift";
/// The binaries' folder of the platform in an FMI 2.0 archive (FMI 2.0 section 2.3).
const FMI2_BINARIES: &str = "linux64";
/// The same in an FMI 3.0 archive (FMI 3.0 section 2.5.1: `<architecture>-<system>`).
const FMI3_BINARIES: &str = "x86_64-linux";
/// The terminals of an FMI 3.0 archive (FMI 3.0 section 2.4.9).
const TERMINALS: &str = "terminalsAndIcons/terminalsAndIcons.xml";
const THREE_HOURS: f64 = 3.0 * 3600.0;
const COMMUNICATION_STEP: f64 = 1.0;
/// Start-up transient dropped before the statistics, s: ten 200 s surge periods of the
/// default platform (at most half the checked run). As the CLI's
/// (`slowdrift::stats::summarize`), the statistics keep the samples at t >= the transient:
/// for the default, t = 2000, 2001, ..., 10800 s, 8801 of them.
const TRANSIENT: f64 = 2000.0;

/// Packs SlowDrift's FMUs and checks each by running it through its C ABI.
///
/// Without options: target/fmu/SlowDrift.fmu (the embedded default platform),
/// target/fmu/Mooring.fmu and the coupled system, target/fmu/system/. With --config: one
/// FMU of that configuration only.
#[derive(Parser)]
#[command(name = "fmu-pack")]
struct Args {
    /// A configuration file (TOML, as `slowdrift simulate --config` reads it) to pack as an
    /// FMU of its own: its configuration embedded, its values as the start values
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,
    /// Where to write that FMU [default: target/fmu/<the configuration's file stem>.fmu]; its
    /// FMI 3.0 twin goes to the `fmi3` folder beside it, under the same file name
    #[arg(long, value_name = "FILE", requires = "config")]
    out: Option<PathBuf>,
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("fmu-pack: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &Args) -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .ok_or("no workspace root")?
        .to_path_buf();
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"));
    // The cdylib is built as fmu-pack's own dependency (`slowdrift` without its `cli`
    // feature), with the features of fmu-pack's build: under `cargo run -p fmu-pack` this
    // finds it built already, and building it any other way would compile the library a
    // second time with another feature set. A dependency's library stays in cargo's `deps`
    // folder under a name cargo chooses, so its path is taken from cargo's own report.
    let library = cdylib(&root, &["-p", "fmu-pack"], "slowdrift")?;
    let fmu_dir = target.join("fmu");
    if let Some(config) = &args.config {
        let stem = config
            .file_stem()
            .ok_or_else(|| format!("--config {}: not a file name", config.display()))?
            .to_string_lossy()
            .into_owned();
        let out = args
            .out
            .clone()
            .unwrap_or_else(|| fmu_dir.join(format!("{stem}.fmu")));
        return pack_configuration(&root, &library, config, &stem, (&out, true), &fmu_dir);
    }
    let fmu_path = fmu_dir.join(format!("{MODEL_IDENTIFIER}.fmu"));
    let resources = fmu_dir.join("resources");
    write_resources(&resources).map_err(|e| e.to_string())?;
    let xml = read(&root.join("modelDescription/modelDescription.xml"))?;
    let files = [RESOURCE_CONFIG, RESOURCE_DRIFT].map(String::from);
    pack(
        &root,
        &library,
        (xml, FMI2_BINARIES),
        (&resources, &files),
        &fmu_path,
    )?;
    let samples = check(
        &fmu_path,
        &fmu_dir.join("unpacked"),
        (0.0, Some(THREE_HOURS)),
    )?;
    let fmi3 = slowdrift::fmi2::fmi3_description::MODEL_DESCRIPTION_FMI3;
    write_fmi3_description(&fmu_dir, MODEL_IDENTIFIER, fmi3)?;
    let fmi3_path = fmu_dir.join("fmi3").join(format!("{MODEL_IDENTIFIER}.fmu"));
    pack(
        &root,
        &library,
        (fmi3.as_bytes().to_vec(), FMI3_BINARIES),
        (&resources, &files),
        &fmi3_path,
    )?;
    check_fmi3(
        &fmi3_path,
        &fmu_dir.join("unpacked-fmi3"),
        (0.0, THREE_HOURS),
        &samples,
    )?;
    mooring::pack_and_check(&root, &target)?;
    system::write(&root, &library, &fmu_dir)
}

/// Writes an FMU's FMI 3.0 model description `xml` to
/// `fmu_dir/fmi3/<model_identifier>/modelDescription.xml`.
fn write_fmi3_description(fmu_dir: &Path, model_identifier: &str, xml: &str) -> Result<(), String> {
    let dir = fmu_dir.join("fmi3").join(model_identifier);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let path = dir.join("modelDescription.xml");
    std::fs::write(&path, xml).map_err(|e| format!("{}: {e}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

/// The FMU of the configuration file `config`, named `model_name`, at `out`, checked by
/// running it (its folders for the resources and the check under `work`); with `fmi3`, its
/// FMI 3.0 twin in the `fmi3` folder beside it, checked against it.
fn pack_configuration(
    root: &Path,
    library: &Path,
    config: &Path,
    model_name: &str,
    (out, fmi3_twin): (&Path, bool),
    work: &Path,
) -> Result<(), String> {
    let resources = work.join(format!("{model_name}-resources"));
    let xml = String::from_utf8(read(&root.join("modelDescription/modelDescription.xml"))?)
        .map_err(|e| e.to_string())?;
    let configured = configured::prepare(config, &resources, &xml, model_name)?;
    let fmi3 = slowdrift_fmi_xml::fmi3_model_description(&configured.model_description)
        .map_err(|e| format!("the FMI 3.0 description of {}: {e}", config.display()))?;
    pack(
        root,
        library,
        (configured.model_description.into_bytes(), FMI2_BINARIES),
        (&resources, &configured.resources),
        out,
    )?;
    let stop = configured
        .experiment
        .1
        .unwrap_or(configured.experiment.0 + THREE_HOURS)
        .min(configured.experiment.0 + THREE_HOURS);
    let samples = check(
        out,
        &work.join(format!("{model_name}-unpacked")),
        (configured.experiment.0, Some(stop)),
    )?;
    if !fmi3_twin {
        return Ok(());
    }
    // The same FMU as FMI 3.0, in the `fmi3` folder beside it under the same file name.
    let fmi3_path = out
        .parent()
        .unwrap_or(Path::new("."))
        .join("fmi3")
        .join(out.file_name().ok_or("--out names no file")?);
    pack(
        root,
        library,
        (fmi3.into_bytes(), FMI3_BINARIES),
        (&resources, &configured.resources),
        &fmi3_path,
    )?;
    check_fmi3(
        &fmi3_path,
        &work.join(format!("{model_name}-unpacked-fmi3")),
        (configured.experiment.0, stop),
        &samples,
    )
}

/// Checks the FMU at `fmu_path` by running it ([`check_by_running`]) over `experiment`
/// (start, stop); a packed FMU that fails its own check is removed, so that no master finds
/// it. The samples of [`OUTPUTS`] of the run.
fn check(
    fmu_path: &Path,
    unpack_dir: &Path,
    experiment: (f64, Option<f64>),
) -> Result<Vec<Vec<f64>>, String> {
    println!("wrote {}", fmu_path.display());
    check_by_running(fmu_path, unpack_dir, experiment).inspect_err(|_| {
        let _ = std::fs::remove_file(fmu_path);
    })
}

/// Unpacks the FMI 3.0 archive `fmi3_path` into `dir3` and runs it through the `fmi3*` C
/// ABI over `(start, stop)` at 1 s with its start values: X, Y and theta at every
/// communication point must equal `two`, the FMI 2.0 archive's samples of the same run
/// ([`check`]), bit for bit. A failing FMI 3.0 archive is removed.
fn check_fmi3(
    fmi3_path: &Path,
    dir3: &Path,
    (start, stop): (f64, f64),
    two: &[Vec<f64>],
) -> Result<(), String> {
    println!("wrote {}", fmi3_path.display());
    let compare = || -> Result<usize, String> {
        archive::unpack(fmi3_path, dir3)?;
        let xml = String::from_utf8(read(&dir3.join("modelDescription.xml"))?)
            .map_err(|e| e.to_string())?;
        let resources = dir3
            .join("resources")
            .canonicalize()
            .map_err(|e| e.to_string())?;
        let path = format!("{}/", resources.to_str().ok_or("resources path not UTF-8")?);
        let fmu = master3::Fmu::load(
            &dir3.join(format!("binaries/{FMI3_BINARIES}/{MODEL_IDENTIFIER}.so")),
        )?;
        let three = master3::run(
            &fmu,
            &master::ModelDescription::parse_fmi3(xml)?,
            &path,
            (&[], &OUTPUTS),
            (start, stop, COMMUNICATION_STEP),
        )?;
        for ((name, a), b) in OUTPUTS.iter().zip(&three).zip(two) {
            if let Some(m) = (0..a.len()).find(|&m| a[m].to_bits() != b[m].to_bits()) {
                return Err(format!(
                    "{name} at {} s: FMI 3.0 {} differs from FMI 2.0 {}",
                    m as f64 * COMMUNICATION_STEP,
                    a[m],
                    b[m]
                ));
            }
        }
        Ok(three[0].len())
    };
    let samples = compare().inspect_err(|_| {
        let _ = std::fs::remove_file(fmi3_path);
    })?;
    println!(
        "ran the packed FMI 3.0 FMU through its fmi3 C ABI beside the FMI 2.0 one: {} at \
         every {COMMUNICATION_STEP} s of {} s ({samples} samples each) equal bit for bit",
        OUTPUTS.join(", "),
        stop - start
    );
    Ok(())
}

/// `cargo build --release` with `args` (the package and its targets), and the path of the
/// shared library (`cdylib`) it built of the library target `name`, as cargo reports it.
fn cdylib(root: &Path, args: &[&str], name: &str) -> Result<PathBuf, String> {
    let messages = cargo_build(root, args)?;
    cdylib_in_messages(&messages, name).ok_or_else(|| {
        format!(
            "cargo build ({}) reported no shared library of {name}",
            args.join(" ")
        )
    })
}

/// `cargo build --release` with `args`, and cargo's report (`--message-format=json`: one
/// JSON message a line on stdout; diagnostics still go to stderr as text).
fn cargo_build(root: &Path, args: &[&str]) -> Result<String, String> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let output = Command::new(cargo)
        .args([
            "build",
            "--release",
            "--message-format=json-render-diagnostics",
        ])
        .args(args)
        .current_dir(root)
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|e| format!("running cargo: {e}"))?;
    if !output.status.success() {
        return Err(format!("cargo build failed ({})", args.join(" ")));
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

/// The `OUT_DIR` of package `package`'s build script among cargo's JSON messages.
fn out_dir_in_messages(messages: &str, package: &str) -> Option<PathBuf> {
    let id = format!("#{package}@");
    messages
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .filter(|m| m["reason"] == "build-script-executed")
        .filter(|m| m["package_id"].as_str().is_some_and(|p| p.contains(&id)))
        .find_map(|m| m["out_dir"].as_str().map(PathBuf::from))
}

/// The `cdylib` file of library target `name` among cargo's JSON messages.
fn cdylib_in_messages(messages: &str, name: &str) -> Option<PathBuf> {
    messages
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .filter(|m| m["reason"] == "compiler-artifact" && m["target"]["name"] == name)
        .filter(|m| {
            m["target"]["kind"]
                .as_array()
                .is_some_and(|kinds| kinds.iter().any(|k| k == "cdylib"))
        })
        .flat_map(|m| m["filenames"].as_array().cloned().unwrap_or_default())
        .filter_map(|f| f.as_str().map(PathBuf::from))
        .find(|f| f.extension().is_some_and(|e| e == "so"))
}

fn read(path: &Path) -> Result<Vec<u8>, String> {
    std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Writes the SlowDrift FMU at `fmu_path`: the model description `xml` (FMI 2.0's or 3.0's),
/// the library in `binaries/<binaries>/`, the named files of the resources folder and the
/// documentation; an FMI 3.0 FMU (`binaries` [`FMI3_BINARIES`]) also its terminal,
/// `terminalsAndIcons/terminalsAndIcons.xml` (modelDescription/terminalsAndIcons.xml).
fn pack(
    root: &Path,
    library: &Path,
    (xml, binaries): (Vec<u8>, &str),
    (resources, files): (&Path, &[String]),
    fmu_path: &Path,
) -> Result<(), String> {
    let fmu_reference = String::from_utf8_lossy(&read(&root.join("docs/fmu.md"))?).into_owned();
    let mut extra = Vec::with_capacity(files.len() + 1);
    for name in files {
        extra.push(archive::Entry {
            path: format!("resources/{name}"),
            data: read(&resources.join(name))?,
        });
    }
    extra.push(archive::Entry {
        path: "documentation/index.html".into(),
        data: documentation("SlowDrift", &fmu_reference).into_bytes(),
    });
    let terminals = root.join("modelDescription/terminalsAndIcons.xml");
    let entries = fmu_entries(
        MODEL_IDENTIFIER,
        (xml, binaries),
        library,
        extra,
        &terminals,
    )?;
    write_fmu(fmu_path, &entries)
}

/// The entries of an FMU of this project: its model description `xml` and its library
/// (`binaries/<binaries>/<model>.so`) first, then `extra`, and for FMI 3.0 (`binaries`
/// [`FMI3_BINARIES`]) the terminal file `terminals` as [`TERMINALS`] last.
fn fmu_entries(
    model: &str,
    (xml, binaries): (Vec<u8>, &str),
    library: &Path,
    extra: Vec<archive::Entry>,
    terminals: &Path,
) -> Result<Vec<archive::Entry>, String> {
    let mut entries = vec![
        archive::Entry {
            path: "modelDescription.xml".into(),
            data: xml,
        },
        archive::Entry {
            path: format!("binaries/{binaries}/{model}.so"),
            data: read(library)?,
        },
    ];
    entries.extend(extra);
    if binaries == FMI3_BINARIES {
        entries.push(archive::Entry {
            path: TERMINALS.into(),
            data: read(terminals)?,
        });
    }
    Ok(entries)
}

/// Writes the archive of `entries` at `fmu_path` (an FMU or an SSP package: both are ZIP
/// archives), creating its folder.
fn write_fmu(fmu_path: &Path, entries: &[archive::Entry]) -> Result<(), String> {
    std::fs::create_dir_all(fmu_path.parent().expect("has a parent")).map_err(|e| e.to_string())?;
    let file =
        std::fs::File::create(fmu_path).map_err(|e| format!("{}: {e}", fmu_path.display()))?;
    archive::write(std::io::BufWriter::new(file), entries)
        // Flushing the buffer here, unlike dropping it, reports a failed write.
        .and_then(|out| {
            out.into_inner()
                .map(drop)
                .map_err(|e| e.into_error().into())
        })
        .map_err(|e| format!("{}: {e}", fmu_path.display()))
}

/// `file://` URI of an absolute path, percent-encoding every byte outside RFC 3986's
/// unreserved set and '/', so that paths with spaces or '%' arrive intact.
fn file_uri(path: &Path) -> Result<String, String> {
    let text = path
        .to_str()
        .ok_or_else(|| format!("{} is not UTF-8", path.display()))?;
    let mut uri = String::from("file://");
    for byte in text.bytes() {
        if byte.is_ascii_alphanumeric() || b"/-._~".contains(&byte) {
            uri.push(byte as char);
        } else {
            uri.push_str(&format!("%{byte:02X}"));
        }
    }
    Ok(uri)
}

/// A page of the docs (Markdown) as a preformatted HTML page.
fn documentation(title: &str, readme: &str) -> String {
    let escaped = readme
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    format!("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{title}</title></head>\n<body><pre>\n{escaped}</pre></body></html>\n")
}

/// Unpacks the whole archive, as a master would (refusing entries that would land outside
/// the folder), loads the library from it and runs it over `(start, stop)` (three hours
/// when open-ended) with no parameter set, as the model description describes it.
fn check_by_running(
    fmu_path: &Path,
    unpack_dir: &Path,
    (start, stop): (f64, Option<f64>),
) -> Result<Vec<Vec<f64>>, String> {
    archive::unpack(fmu_path, unpack_dir)?;
    let resources = unpack_dir.join("resources");
    let library = unpack_dir.join(format!("binaries/{FMI2_BINARIES}/{MODEL_IDENTIFIER}.so"));
    let xml_path = unpack_dir.join("modelDescription.xml");
    let xml =
        String::from_utf8(read(&xml_path)?).map_err(|e| format!("{}: {e}", xml_path.display()))?;
    let description = master::ModelDescription::parse(xml)?;
    let fmu = master::Fmu::load(&library)?;
    let uri = file_uri(&resources.canonicalize().map_err(|e| e.to_string())?)?;
    let stop = stop.unwrap_or(start + THREE_HOURS);
    let transient = TRANSIENT.min(0.5 * (stop - start));
    let started = std::time::Instant::now();
    let (samples, statistics) = run_statistics(&fmu, &description, &uri, (start, stop), transient)?;
    let elapsed = started.elapsed().as_secs_f64();
    println!(
        "ran the packed FMU through its C ABI: {} s at a {COMMUNICATION_STEP} s communication \
         step in {elapsed:.3} s",
        stop - start
    );
    println!(
        "statistics after a transient of {transient} s ({} samples at {COMMUNICATION_STEP} s):",
        statistics[0].samples
    );
    println!(
        "{:<10} {:>12} {:>12} {:>12}",
        "output", "mean", "rms", "max"
    );
    for (name, s) in OUTPUTS.iter().zip(&statistics) {
        println!(
            "{name:<10} {:>12.4} {:>12.4} {:>12.4}",
            s.mean, s.rms, s.max
        );
    }
    Ok(samples)
}

/// The outputs the self-check summarises.
const OUTPUTS: [&str; 3] = ["X", "Y", "theta"];

/// The self-check's run of the FMU from `start` to `stop` with its start values: the
/// samples of [`OUTPUTS`] and their statistics after `transient` (the record from the start,
/// as the CLI's).
fn run_statistics(
    fmu: &master::Fmu,
    description: &master::ModelDescription,
    uri: &str,
    (start, stop): (f64, f64),
    transient: f64,
) -> Result<(Vec<Vec<f64>>, Vec<Summary>), String> {
    let samples = master::run(
        fmu,
        description,
        uri,
        (&[], &OUTPUTS),
        (start, stop, COMMUNICATION_STEP),
    )?;
    let statistics = samples
        .iter()
        .map(|values| summarize(values, COMMUNICATION_STEP, transient).map_err(|e| e.to_string()))
        .collect::<Result<_, _>>()?;
    Ok((samples, statistics))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dependency's shared library is found where cargo says it put it (its `deps` folder),
    /// and only a `cdylib` of the named target counts.
    #[test]
    fn the_shared_library_is_taken_from_cargos_report() {
        let messages = concat!(
            "{\"reason\":\"compiler-artifact\",\"target\":{\"name\":\"other\",\"kind\":[\"cdylib\"]},\"filenames\":[\"/t/release/deps/libother.so\"]}\n",
            "{\"reason\":\"compiler-artifact\",\"target\":{\"name\":\"slowdrift\",\"kind\":[\"cdylib\",\"rlib\"]},\"filenames\":[\"/t/release/deps/libslowdrift.so\",\"/t/release/deps/libslowdrift-0123.rlib\"]}\n",
            "not json\n",
            "{\"reason\":\"build-finished\",\"success\":true}\n",
        );
        assert_eq!(
            cdylib_in_messages(messages, "slowdrift"),
            Some(PathBuf::from("/t/release/deps/libslowdrift.so"))
        );
        assert_eq!(cdylib_in_messages(messages, "mooring"), None);
    }

    /// The self-check keeps the samples `slowdrift simulate` keeps: run through the C ABI of
    /// this build's library (the one cargo built beside this test), the packed default's
    /// statistics after the transient are those of the native run's record from t = 0, bit
    /// for bit, over (10800 - 2000) / 1 + 1 = 8801 samples (t = 2000 .. 10800 s; the
    /// self-check counted 8800 before, its first sample the state after the first step).
    #[test]
    fn the_self_check_keeps_the_samples_the_cli_keeps() {
        let exe = std::env::current_exe().unwrap();
        let library = exe.parent().unwrap().join("libslowdrift.so");
        assert!(
            library.is_file(),
            "cargo builds {} with this test",
            library.display()
        );
        let resources =
            std::env::temp_dir().join(format!("fmu-pack-self-check-{}", std::process::id()));
        write_resources(&resources).unwrap();
        let xml = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../modelDescription/modelDescription.xml"
        ))
        .unwrap();
        let description = master::ModelDescription::parse(xml).unwrap();
        let fmu = master::Fmu::load(&library).unwrap();
        let (_, statistics) = run_statistics(
            &fmu,
            &description,
            &file_uri(&resources).unwrap(),
            (0.0, THREE_HOURS),
            TRANSIENT,
        )
        .unwrap();
        std::fs::remove_dir_all(&resources).ok();

        let mut native = slowdrift::problem::default_problem().unwrap();
        native.run.duration = THREE_HOURS;
        let records = slowdrift::montecarlo::simulate_positions(native).unwrap();
        for (s, record) in statistics.iter().zip(&records) {
            assert_eq!(*s, summarize(record, 1.0, 2000.0).unwrap());
            assert_eq!(s.samples, 8801);
        }
    }

    #[test]
    fn resource_uris_are_percent_encoded() {
        assert_eq!(
            file_uri(Path::new("/tmp/a b/100%/res")).unwrap(),
            "file:///tmp/a%20b/100%25/res"
        );
    }
}
