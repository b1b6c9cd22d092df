//! The FMU archive, written and read with the `zip` crate: a standard ZIP with deflated
//! entries (FMI 2.0 section 2.3 allows deflate or store), forward slashes, no links.
//!
//! Nothing is truncated: an entry of 4 GiB or more gets zip64 sizes (`large_file`), and the
//! crate writes a zip64 end record once there are more than 65535 entries. Unpacking refuses
//! any entry whose name would land outside the target folder (`..`, absolute paths) and
//! symbolic links, before it writes a single file.

use std::fmt::Display;
use std::fs::File;
use std::io::{self, BufReader, Read, Seek, Write};
use std::path::{Path, PathBuf};
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipArchive, ZipWriter};

/// One entry to pack: a path inside the archive (forward slashes) and its bytes.
pub struct Entry {
    pub path: String,
    pub data: Vec<u8>,
}

/// Writes the entries, in order, as a ZIP archive of deflated files. Every entry carries
/// the same timestamp (1980-01-01 00:00, the earliest MS-DOS time) and mode 0644, so the
/// same entries give the same bytes.
pub fn write<W: Write + Seek>(out: W, entries: &[Entry]) -> zip::result::ZipResult<W> {
    let mut zip = ZipWriter::new(out);
    for entry in entries {
        let options = SimpleFileOptions::default()
            .compression_method(CompressionMethod::Deflated)
            .last_modified_time(DateTime::default())
            .unix_permissions(0o644)
            // Zip64 sizes only where the 32-bit fields cannot hold them; the crate refuses
            // to write past 4 GiB into an entry without them.
            .large_file(entry.data.len() as u64 >= u64::from(u32::MAX));
        zip.start_file(entry.path.as_str(), options)?;
        zip.write_all(&entry.data)?;
    }
    zip.finish()
}

/// Unpacks the archive at `fmu` into `dir`, which is emptied first, as a master unpacks an
/// FMU. The crate checks each entry's CRC-32 as it is read. Returns the unpacked files,
/// relative to `dir`, in archive order.
pub fn unpack(fmu: &Path, dir: &Path) -> Result<Vec<PathBuf>, String> {
    let at = |e: &dyn Display| format!("{}: {e}", fmu.display());
    let file = File::open(fmu).map_err(|e| at(&e))?;
    let mut archive = ZipArchive::new(BufReader::new(file)).map_err(|e| at(&e))?;
    let paths = safe_paths(&mut archive).map_err(|e| at(&e))?;
    match std::fs::remove_dir_all(dir) {
        Ok(()) => {}
        Err(e) if e.kind() == io::ErrorKind::NotFound => {}
        Err(e) => return Err(format!("{}: {e}", dir.display())),
    }
    let mut files = Vec::new();
    for (index, relative) in paths.into_iter().enumerate() {
        let mut entry = archive.by_index(index).map_err(|e| at(&e))?;
        let target = dir.join(&relative);
        let created = |e: io::Error| format!("{}: {e}", target.display());
        if entry.is_dir() {
            std::fs::create_dir_all(&target).map_err(created)?;
            continue;
        }
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(created)?;
        }
        let mut out = File::create(&target).map_err(created)?;
        // A read error here (a bad CRC, a truncated entry) belongs to the archive.
        io::copy(&mut entry, &mut out).map_err(|e| at(&format!("{}: {e}", relative.display())))?;
        files.push(relative);
    }
    Ok(files)
}

/// Each entry's path relative to the target folder, or an error naming the first entry
/// that would escape it or is a symbolic link.
fn safe_paths<R: Read + Seek>(archive: &mut ZipArchive<R>) -> Result<Vec<PathBuf>, String> {
    (0..archive.len())
        .map(|index| {
            let entry = archive.by_index(index).map_err(|e| e.to_string())?;
            let name = String::from_utf8_lossy(entry.name_raw());
            if entry.is_symlink() {
                return Err(format!("refused entry {name:?}: it is a symbolic link"));
            }
            // `enclosed_name` would make "/etc/x" relative ("etc/x"); an FMU has no business
            // naming absolute paths (nor drive letters), so they are refused outright.
            if name.starts_with(['/', '\\']) || name.as_bytes().get(1) == Some(&b':') {
                return Err(format!("refused entry {name:?}: it is an absolute path"));
            }
            entry
                .enclosed_name()
                .filter(|path| path.components().next().is_some())
                .ok_or_else(|| {
                    format!("refused entry {name:?}: it names no path inside the target folder")
                })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;
    use std::process::Command;

    fn sample() -> Vec<Entry> {
        vec![
            Entry {
                path: "modelDescription.xml".into(),
                data: b"<xml/>".to_vec(),
            },
            Entry {
                path: "binaries/linux64/x.so".into(),
                data: (0..=255u8).cycle().take(70_000).collect(),
            },
            Entry {
                path: "resources/empty.txt".into(),
                data: Vec::new(),
            },
            Entry {
                path: "documentation/index.html".into(),
                // Pseudo-random bytes, which deflate cannot shrink.
                data: (0..5000u32)
                    .map(|i| (i.wrapping_mul(2_654_435_761) >> 24) as u8)
                    .collect(),
            },
        ]
    }

    fn packed(entries: &[Entry]) -> Vec<u8> {
        write(Cursor::new(Vec::new()), entries)
            .unwrap()
            .into_inner()
    }

    /// A fresh folder under the system's temporary one, named after the test.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("fmu-pack-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn entries_come_back_byte_identical_in_order_and_deflated() {
        let entries = sample();
        let mut archive = ZipArchive::new(Cursor::new(packed(&entries))).unwrap();
        assert_eq!(archive.len(), entries.len());
        for (index, expected) in entries.iter().enumerate() {
            let mut entry = archive.by_index(index).unwrap();
            assert_eq!(entry.name().unwrap(), expected.path);
            assert_eq!(entry.compression(), CompressionMethod::Deflated);
            assert_eq!(entry.last_modified(), Some(DateTime::default()));
            let mut data = Vec::new();
            entry.read_to_end(&mut data).unwrap();
            assert_eq!(data, expected.data, "{}", expected.path);
        }
        // The repeating library bytes shrink.
        assert!(archive.by_index(1).unwrap().compressed_size() < 10_000);
    }

    #[test]
    fn the_same_entries_give_the_same_bytes() {
        assert_eq!(packed(&sample()), packed(&sample()));
    }

    /// More entries than the 16-bit count of the end record holds: the crate writes zip64
    /// records and every entry reads back (the hand-written writer wrapped the count).
    #[test]
    fn more_than_65535_entries_are_kept() {
        let entries: Vec<Entry> = (0..65_600u32)
            .map(|i| Entry {
                path: format!("e/{i}"),
                data: Vec::new(),
            })
            .collect();
        let mut archive = ZipArchive::new(Cursor::new(packed(&entries))).unwrap();
        assert_eq!(archive.len(), 65_600);
        assert_eq!(archive.by_index(65_599).unwrap().name().unwrap(), "e/65599");
    }

    #[test]
    fn unpack_writes_every_entry_below_the_folder_and_empties_it_first() {
        let dir = scratch("unpack");
        let fmu = dir.join("a.fmu");
        std::fs::write(&fmu, packed(&sample())).unwrap();
        let target = dir.join("unpacked");
        std::fs::create_dir_all(&target).unwrap();
        std::fs::write(target.join("stale.txt"), b"from an earlier run").unwrap();
        let files = unpack(&fmu, &target).unwrap();
        let entries = sample();
        assert_eq!(
            files,
            entries
                .iter()
                .map(|e| PathBuf::from(&e.path))
                .collect::<Vec<_>>()
        );
        for entry in &entries {
            assert_eq!(
                std::fs::read(target.join(&entry.path)).unwrap(),
                entry.data,
                "{}",
                entry.path
            );
        }
        assert!(!target.join("stale.txt").exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn entries_that_escape_the_folder_are_refused_before_anything_is_written() {
        let dir = scratch("escape");
        let cases = [
            ("../evil", "it names no path inside the target folder"),
            ("a/../../evil", "it names no path inside the target folder"),
            ("..\\evil", "it names no path inside the target folder"),
            ("/tmp/evil", "it is an absolute path"),
            ("C:/evil", "it is an absolute path"),
        ];
        for (case, (evil, why)) in cases.iter().enumerate() {
            let mut entries = sample();
            entries.push(Entry {
                path: evil.to_string(),
                data: b"owned".to_vec(),
            });
            let fmu = dir.join(format!("evil{case}.fmu"));
            std::fs::write(&fmu, packed(&entries)).unwrap();
            let target = dir.join(format!("t{case}/unpacked"));
            let error = unpack(&fmu, &target).unwrap_err();
            assert!(error.contains(&fmu.display().to_string()), "{error}");
            assert!(
                error.contains(&format!("refused entry {evil:?}: {why}")),
                "{error}"
            );
            // Nothing was unpacked: not the good entries, not the bad one.
            assert!(!target.exists(), "{evil}");
            assert!(!dir.join(format!("t{case}/evil")).exists(), "{evil}");
        }
        assert!(!dir.join("evil").exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn symbolic_links_are_refused() {
        let dir = scratch("symlink");
        let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
        zip.add_symlink(
            "resources/link",
            "/etc/passwd",
            SimpleFileOptions::default(),
        )
        .unwrap();
        let fmu = dir.join("link.fmu");
        std::fs::write(&fmu, zip.finish().unwrap().into_inner()).unwrap();
        let target = dir.join("unpacked");
        let error = unpack(&fmu, &target).unwrap_err();
        assert!(
            error.contains("\"resources/link\": it is a symbolic link"),
            "{error}"
        );
        assert!(!target.exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_corrupted_entry_is_an_error_naming_the_archive() {
        let dir = scratch("corrupt");
        let entries = vec![Entry {
            path: "resources/data.bin".into(),
            data: vec![7u8; 1000],
        }];
        let mut bytes = packed(&entries);
        let mut archive = ZipArchive::new(Cursor::new(bytes.clone())).unwrap();
        let start = archive.by_index(0).unwrap().data_start().unwrap() as usize;
        // Flip a bit in the deflated data: it inflates to other bytes or fails outright.
        bytes[start + 1] ^= 0x10;
        let fmu = dir.join("corrupt.fmu");
        std::fs::write(&fmu, bytes).unwrap();
        let error = unpack(&fmu, &dir.join("unpacked")).unwrap_err();
        assert!(error.starts_with(&fmu.display().to_string()), "{error}");
        assert!(error.contains("resources/data.bin"), "{error}");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_missing_archive_is_an_error_naming_it() {
        let fmu = std::env::temp_dir().join("fmu-pack-no-such-archive.fmu");
        let error = unpack(&fmu, &std::env::temp_dir().join("fmu-pack-no-such")).unwrap_err();
        assert!(error.starts_with(&fmu.display().to_string()), "{error}");
    }

    /// Python's zipfile, an independent reader, lists and verifies the archive.
    #[test]
    fn python_zipfile_reads_the_archive() {
        let dir = scratch("python");
        let path = dir.join("a.zip");
        std::fs::write(&path, packed(&sample())).unwrap();
        let script = "import sys, zipfile\n\
                      z = zipfile.ZipFile(sys.argv[1])\n\
                      assert z.testzip() is None\n\
                      assert all(i.compress_type == zipfile.ZIP_DEFLATED for i in z.infolist())\n\
                      print(';'.join(f'{i.filename}:{i.file_size}' for i in z.infolist()))";
        let output = Command::new("python3")
            .arg("-c")
            .arg(script)
            .arg(&path)
            .output()
            .expect("python3 runs");
        std::fs::remove_dir_all(&dir).ok();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        assert_eq!(
            String::from_utf8_lossy(&output.stdout).trim(),
            "modelDescription.xml:6;binaries/linux64/x.so:70000;resources/empty.txt:0;\
             documentation/index.html:5000"
        );
    }
}
