//! The `--out` of every command, checked before any work, so that a run of minutes is never
//! lost to a path it cannot write. A file (`simulate`'s time series, `montecarlo`'s summary
//! and the runs file beside it, `hydro`'s database) must be a regular file or a new name in
//! a directory that exists; a study's directory is made if missing (with its parents) and
//! must be a directory. Either way the place must take a new file: a probe file is made
//! there and removed (so a read-only file system, a directory without write permission or
//! one where nothing can be created is refused as it is), and an existing file must open
//! for writing (nothing is written to it). Refusals name `--out` and the path as given.

use std::fs::OpenOptions;
use std::io::ErrorKind;
use std::os::unix::ffi::OsStrExt;
use std::path::{Path, PathBuf};

/// Checks `--out PATH` for a file the command writes.
pub fn file(path: &Path) -> Result<(), String> {
    file_beside(path, path)
}

/// Checks `path`, a file the command writes beside `--out out` (the same when it is the
/// `--out` itself); the message names both.
pub fn file_beside(out: &Path, path: &Path) -> Result<(), String> {
    let refuse = |why: String| {
        if path == out {
            format!("--out {}: {why}", out.display())
        } else {
            format!(
                "--out {}: {}, written beside it, {why}",
                out.display(),
                path.display()
            )
        }
    };
    if path.as_os_str().as_bytes().ends_with(b"/") {
        return Err(refuse(
            "names a directory (it ends with /): give a file's path".into(),
        ));
    }
    let directory = parent(path);
    match std::fs::metadata(path) {
        Ok(meta) if meta.is_dir() => {
            return Err(refuse(format!(
                "is a directory: give a file's path (such as {})",
                path.join("results.csv").display()
            )))
        }
        Ok(meta) if !meta.is_file() => {
            return Err(refuse(
                "is not a regular file (a device, a FIFO or a socket): give a file's path".into(),
            ))
        }
        Ok(_) => {
            OpenOptions::new()
                .write(true)
                .open(path)
                .map_err(|e| refuse(format!("cannot be written: {e}")))?;
        }
        // Nothing there, or a path through something that is not a directory.
        Err(e) => match std::fs::metadata(&directory) {
            Ok(meta) if !meta.is_dir() => {
                return Err(refuse(format!(
                    "{} is not a directory",
                    directory.display()
                )))
            }
            Err(_) => {
                return Err(refuse(format!(
                    "its directory {} does not exist",
                    directory.display()
                )))
            }
            Ok(_) if e.kind() != ErrorKind::NotFound => return Err(refuse(e.to_string())),
            Ok(_) => {}
        },
    }
    probe(&directory).map_err(|e| refuse(format!("cannot write in {}: {e}", directory.display())))
}

/// Checks `--out DIR`, the directory a study writes its files into: made if missing, with
/// its parents.
pub fn directory(path: &Path) -> Result<(), String> {
    let refuse = |why: String| format!("--out {}: {why}", path.display());
    match std::fs::metadata(path) {
        Ok(meta) if meta.is_dir() => {}
        Ok(_) => {
            return Err(refuse(
                "is a file, not a directory: the study writes several files into a directory"
                    .into(),
            ))
        }
        Err(_) => std::fs::create_dir_all(path)
            .map_err(|e| refuse(format!("cannot make the directory: {e}")))?,
    }
    probe(path).map_err(|e| refuse(format!("cannot write in it: {e}")))
}

/// The directory `path` is in (`.` for a bare name).
fn parent(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Makes and removes a new file in `directory`.
fn probe(directory: &Path) -> std::io::Result<()> {
    let name = directory.join(format!(".slowdrift-out-probe.{}", std::process::id()));
    OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&name)?;
    std::fs::remove_file(&name)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory for one test.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("slowdrift-out-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// A new name and an existing file are accepted, and the check leaves nothing behind
    /// and the file as it was.
    #[test]
    fn a_writable_place_is_accepted_and_left_as_it_was() {
        let dir = scratch("accepted");
        let existing = dir.join("old.csv");
        std::fs::write(&existing, "kept").unwrap();
        file(&dir.join("new.csv")).unwrap();
        file(&existing).unwrap();
        directory(&dir.join("figures/more")).unwrap();
        assert_eq!(std::fs::read_to_string(&existing).unwrap(), "kept");
        let mut left: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        assert_eq!(left, ["figures", "old.csv"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn what_cannot_be_written_is_named() {
        let dir = scratch("refused");
        let as_dir = dir.display();
        assert_eq!(
            file(&dir).unwrap_err(),
            format!(
                "--out {as_dir}: is a directory: give a file's path (such as {as_dir}/results.csv)"
            )
        );
        let missing = dir.join("no/such.csv");
        assert_eq!(
            file(&missing).unwrap_err(),
            format!(
                "--out {}: its directory {as_dir}/no does not exist",
                missing.display()
            )
        );
        let slash = dir.join("new/");
        assert!(file(&slash)
            .unwrap_err()
            .ends_with("names a directory (it ends with /): give a file's path"));
        let plain = dir.join("plain.csv");
        std::fs::write(&plain, "").unwrap();
        assert_eq!(
            directory(&plain).unwrap_err(),
            format!(
                "--out {}: is a file, not a directory: the study writes several files into a \
                 directory",
                plain.display()
            )
        );
        assert!(file(&plain.join("x.csv"))
            .unwrap_err()
            .ends_with(&format!("{} is not a directory", plain.display())));
        assert!(file(Path::new("/dev/null"))
            .unwrap_err()
            .contains("is not a regular file"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
