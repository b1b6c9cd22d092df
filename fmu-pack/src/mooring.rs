//! The mooring FMU, `target/fmu/Mooring.fmu`: the `slowdrift-mooring` cdylib (`mooring/`),
//! MoorDyn's C library, the spread mooring of the default platform and the coupling page.
//!
//! MoorDyn's library is not built here and not kept in the repository: it is taken from the
//! `moordyn` wheel on PyPI ([`MOORDYN`], the same MoorDyn as the Python tests' `moordyn`
//! package), which `pip download` fetches once into `target/moordyn-wheel/` (`$PYTHON`,
//! default `python3`; the wheel is a zip, read with the `zip` crate). The archive:
//!
//! - `modelDescription.xml` (mooring/modelDescription.xml);
//! - `binaries/linux64/Mooring.so` and, beside it, MoorDyn's `libmoordyn.so.2.7` (the FMU
//!   loads it from its own folder);
//! - `resources/spread_mooring.dat` (mooring/spread_mooring.dat, the default `mooringFile`);
//! - `documentation/index.html` (docs/coupling.md) and `documentation/licenses/MoorDyn.txt`
//!   (MoorDyn's BSD-3-Clause licence, which its binary's redistribution must carry).
//!
//! Beside it, `target/fmu/fmi3/Mooring/modelDescription.xml`: the FMU's FMI 3.0 model
//! description, as its build script generated it, and `target/fmu/fmi3/Mooring.fmu`: the
//! same archive as FMI 3.0 (that description, the libraries in `binaries/x86_64-linux/`, and
//! the terminal of the mechanical connection, mooring/terminalsAndIcons.xml, in
//! `terminalsAndIcons/`).
//!
//! The check: the packed FMU, loaded from the unpacked archive through its C ABI, holds the
//! platform 10 m off in surge for 60 s and must pull it back (Fx < 0, Fy and Mz nil by
//! symmetry), with a fairlead tension above zero; the FMI 3.0 archive, through its `fmi3*`
//! C ABI, gives the same four outputs at every second bit for bit.

use crate::{
    archive, cargo_build, cdylib_in_messages, file_uri, fmu_entries, master, master3,
    out_dir_in_messages, read, write_fmi3_description, write_fmu, FMI2_BINARIES, FMI3_BINARIES,
};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Command;

const MODEL_IDENTIFIER: &str = "Mooring";
/// The pinned MoorDyn release on PyPI.
pub const MOORDYN: &str = "moordyn==2.7.2";
/// The name of MoorDyn's library in the FMU (the FMU loads it under this name).
const LIBRARY_FILE: &str = "libmoordyn.so.2.7";
/// The default mooring, packed as the FMU's resource of the same name.
const DEFAULT_MOORING: &str = "spread_mooring.dat";
/// The check's surge offset (m) and duration (s).
const CHECK_OFFSET: f64 = 10.0;
const CHECK_SECONDS: f64 = 60.0;

pub fn pack_and_check(root: &Path, target: &Path) -> Result<(), String> {
    // The library, and the FMI 3.0 description its build script generated (its crate
    // cannot be linked into fmu-pack beside SlowDrift's: both export the fmi2* symbols).
    let messages = cargo_build(root, &["--lib", "-p", "slowdrift-mooring"])?;
    let library = cdylib_in_messages(&messages, "slowdrift_mooring")
        .ok_or("cargo build -p slowdrift-mooring reported no shared library")?;
    let out_dir = out_dir_in_messages(&messages, "slowdrift-mooring")
        .ok_or("cargo build -p slowdrift-mooring reported no build-script output")?;
    let fmi3 = read(&out_dir.join("fmi3/modelDescription.xml"))?;
    let fmi3 = String::from_utf8(fmi3).map_err(|e| format!("{}: {e}", out_dir.display()))?;
    write_fmi3_description(&target.join("fmu"), MODEL_IDENTIFIER, &fmi3)?;
    let (moordyn, licence) = moordyn_library(&target.join("moordyn-wheel"))?;
    let fmu_path = target.join("fmu").join(format!("{MODEL_IDENTIFIER}.fmu"));
    let coupling = String::from_utf8_lossy(&read(&root.join("docs/coupling.md"))?).into_owned();
    let terminals = root.join("mooring/terminalsAndIcons.xml");
    let entries = |xml: Vec<u8>, binaries: &str| -> Result<Vec<archive::Entry>, String> {
        let extra = vec![
            archive::Entry {
                path: format!("binaries/{binaries}/{LIBRARY_FILE}"),
                data: moordyn.clone(),
            },
            archive::Entry {
                path: format!("resources/{DEFAULT_MOORING}"),
                data: read(&root.join("mooring").join(DEFAULT_MOORING))?,
            },
            archive::Entry {
                path: "documentation/index.html".into(),
                data: crate::documentation("Mooring", &coupling).into_bytes(),
            },
            archive::Entry {
                path: "documentation/licenses/MoorDyn.txt".into(),
                data: licence.clone(),
            },
        ];
        fmu_entries(
            MODEL_IDENTIFIER,
            (xml, binaries),
            &library,
            extra,
            &terminals,
        )
    };
    let xml = read(&root.join("mooring/modelDescription.xml"))?;
    write_fmu(&fmu_path, &entries(xml, FMI2_BINARIES)?)?;
    println!("wrote {}", fmu_path.display());
    let unpacked = target.join("fmu").join("unpacked-mooring");
    let two = check_by_running(&fmu_path, &unpacked).inspect_err(|_| {
        let _ = std::fs::remove_file(&fmu_path);
    })?;
    let fmi3_path = target
        .join("fmu")
        .join("fmi3")
        .join(format!("{MODEL_IDENTIFIER}.fmu"));
    write_fmu(&fmi3_path, &entries(fmi3.into_bytes(), FMI3_BINARIES)?)?;
    println!("wrote {}", fmi3_path.display());
    check_fmi3(
        &fmi3_path,
        &target.join("fmu").join("unpacked-mooring-fmi3"),
        &two,
    )
    .inspect_err(|_| {
        let _ = std::fs::remove_file(&fmi3_path);
    })
}

/// The outputs of the check.
const CHECKED: [&str; 4] = ["Fx", "Fy", "Mz", "fairleadTensionMax"];

/// The FMI 3.0 archive through its `fmi3*` C ABI: the check's run, whose outputs must equal
/// `fmi2_samples` (the FMI 2.0 archive's) bit for bit.
fn check_fmi3(fmu_path: &Path, unpack_dir: &Path, fmi2_samples: &[Vec<f64>]) -> Result<(), String> {
    archive::unpack(fmu_path, unpack_dir)?;
    let library = unpack_dir.join(format!("binaries/{FMI3_BINARIES}/{MODEL_IDENTIFIER}.so"));
    let xml_path = unpack_dir.join("modelDescription.xml");
    let xml =
        String::from_utf8(read(&xml_path)?).map_err(|e| format!("{}: {e}", xml_path.display()))?;
    let description = master::ModelDescription::parse_fmi3(xml)?;
    let fmu = master3::Fmu::load(&library)?;
    let resources = unpack_dir
        .join("resources")
        .canonicalize()
        .map_err(|e| e.to_string())?;
    let path = format!("{}/", resources.to_str().ok_or("resources path not UTF-8")?);
    let samples = master3::run(
        &fmu,
        &description,
        &path,
        (&[("X", CHECK_OFFSET)], &CHECKED),
        (0.0, CHECK_SECONDS, 1.0),
    )?;
    for ((name, a), b) in CHECKED.iter().zip(&samples).zip(fmi2_samples) {
        if let Some(m) = (0..a.len()).find(|&m| a[m].to_bits() != b[m].to_bits()) {
            return Err(format!(
                "the FMI 3.0 mooring FMU's {name} at {m} s, {}, differs from the FMI 2.0 one's, {}",
                a[m], b[m]
            ));
        }
    }
    println!(
        "ran the packed FMI 3.0 mooring FMU through its fmi3 C ABI: {} at every second of the \
         check equal to the FMI 2.0 FMU's bit for bit",
        CHECKED.join(", ")
    );
    Ok(())
}

/// MoorDyn's library and licence from the wheel in `dir`, downloaded first if absent.
fn moordyn_library(dir: &Path) -> Result<(Vec<u8>, Vec<u8>), String> {
    let wheel = match find_wheel(dir) {
        Some(wheel) => wheel,
        None => {
            download_wheel(dir)?;
            find_wheel(dir).ok_or_else(|| {
                format!("pip download {MOORDYN} left no wheel in {}", dir.display())
            })?
        }
    };
    let at = |e: &dyn std::fmt::Display| format!("{}: {e}", wheel.display());
    let file = std::fs::File::open(&wheel).map_err(|e| at(&e))?;
    let mut zip = zip::ZipArchive::new(std::io::BufReader::new(file)).map_err(|e| at(&e))?;
    let names: Vec<String> = zip
        .file_names()
        .map(|n| n.map(|n| n.into_owned()))
        .collect::<Result<_, _>>()
        .map_err(|e| at(&e))?;
    let mut entry = |pick: &dyn Fn(&str) -> bool, what: &str| -> Result<Vec<u8>, String> {
        let name = names
            .iter()
            .find(|n| pick(n))
            .ok_or_else(|| at(&format!("the wheel has no {what}")))?;
        let mut bytes = Vec::new();
        zip.by_name(name)
            .map_err(|e| at(&e))?
            .read_to_end(&mut bytes)
            .map_err(|e| at(&e))?;
        Ok(bytes)
    };
    let library = entry(
        &|n| n.starts_with("moordyn.libs/libmoordyn") && n.contains(".so"),
        "moordyn.libs/libmoordyn*.so*",
    )?;
    // The licence file, not its folder's own entry (`.dist-info/licenses/`, empty), which
    // the name alone would also match.
    let licence = entry(
        &|n| {
            n.rsplit_once(".dist-info/licenses/")
                .is_some_and(|(_, file)| file.to_ascii_lowercase().starts_with("license"))
        },
        "licence file in its .dist-info/licenses/",
    )?;
    // BSD-3-Clause: a redistribution of the binary must carry the text.
    if !String::from_utf8_lossy(&licence).contains("Redistribution and use") {
        return Err(at(
            &"the wheel's licence file is not MoorDyn's BSD-3-Clause text",
        ));
    }
    Ok((library, licence))
}

/// The manylinux x86_64 wheel of [`MOORDYN`] in `dir`, if there is one.
fn find_wheel(dir: &Path) -> Option<PathBuf> {
    let version = MOORDYN.split("==").nth(1)?;
    std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .map(|e| e.path())
        .find(|p| {
            p.file_name().and_then(|n| n.to_str()).is_some_and(|n| {
                n.starts_with(&format!("moordyn-{version}-"))
                    && n.ends_with(".whl")
                    && n.contains("manylinux")
                    && n.contains("x86_64")
            })
        })
}

fn download_wheel(dir: &Path) -> Result<(), String> {
    let python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".into());
    let status = Command::new(&python)
        .args([
            "-m",
            "pip",
            "download",
            "--quiet",
            "--disable-pip-version-check",
        ])
        .args(["--no-deps", "--only-binary=:all:", "--dest"])
        .arg(dir)
        .arg(MOORDYN)
        .status()
        .map_err(|e| format!("running {python} -m pip download {MOORDYN}: {e}"))?;
    status.success().then_some(()).ok_or_else(|| {
        format!(
            "{python} -m pip download {MOORDYN} failed: MoorDyn's library comes from that wheel"
        )
    })
}

/// The check of the FMI 2.0 archive; its outputs' samples.
fn check_by_running(fmu_path: &Path, unpack_dir: &Path) -> Result<Vec<Vec<f64>>, String> {
    archive::unpack(fmu_path, unpack_dir)?;
    let library = unpack_dir.join(format!("binaries/{FMI2_BINARIES}/{MODEL_IDENTIFIER}.so"));
    let xml_path = unpack_dir.join("modelDescription.xml");
    let xml =
        String::from_utf8(read(&xml_path)?).map_err(|e| format!("{}: {e}", xml_path.display()))?;
    let description = master::ModelDescription::parse(xml)?;
    let fmu = master::Fmu::load(&library)?;
    let resources = unpack_dir.join("resources");
    let uri = file_uri(&resources.canonicalize().map_err(|e| e.to_string())?)?;
    let names = CHECKED;
    let started = std::time::Instant::now();
    let samples = master::run(
        &fmu,
        &description,
        &uri,
        (&[("X", CHECK_OFFSET)], &names),
        (0.0, CHECK_SECONDS, 1.0),
    )?;
    let elapsed = started.elapsed().as_secs_f64();
    let last: Vec<f64> = samples.iter().map(|s| *s.last().expect("steps")).collect();
    println!(
        "ran the packed mooring FMU through its C ABI: the platform held {CHECK_OFFSET} m off in \
         surge for {CHECK_SECONDS} s in {elapsed:.2} s: Fx {:.4e} N, Fy {:.3e} N, Mz {:.3e} N m, \
         largest fairlead tension {:.4e} N",
        last[0], last[1], last[2], last[3]
    );
    let (fx, fy, mz, tension) = (last[0], last[1], last[2], last[3]);
    if !(fx < 0.0
        && fy.abs() < 1e-3 * fx.abs()
        && mz.abs() < 1e-3 * fx.abs() * 50.0
        && tension > 0.0)
    {
        return Err(format!(
            "the mooring FMU does not pull a platform {CHECK_OFFSET} m off in surge back \
             (Fx {fx}, Fy {fy}, Mz {mz}, tension {tension})"
        ));
    }
    Ok(samples)
}
