//! Writing a file anew so that no reader and no interruption ever sees it cut: the text goes
//! to a temporary file in the same directory (`NAME.PID.tmp`), which is synced to the disk
//! and renamed over the file (a rename within one file system is atomic). A kill at any
//! moment leaves the old file or the new one whole (and at worst the temporary file beside
//! it); an error removes the temporary file and leaves the old one.

use crate::error::{Error, Result};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// The temporary file of [`replace`] for `path` in this process.
fn temporary(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(format!(".{}.tmp", std::process::id()));
    path.with_file_name(name)
}

/// Writes the file at `path` (made or replaced) with what `write` writes, atomically (the
/// module's doc); errors name `path`.
pub fn replace(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
) -> Result<()> {
    let temporary = temporary(path);
    let written = File::create(&temporary).and_then(|file| {
        let mut w = BufWriter::new(file);
        write(&mut w)?;
        let file = w.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()
    });
    let renamed = written.and_then(|()| std::fs::rename(&temporary, path));
    renamed.map_err(|e| {
        std::fs::remove_file(&temporary).ok();
        Error::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    /// The new text replaces the old; a write that fails half-way leaves the old text whole
    /// and no temporary file.
    #[test]
    fn a_failed_write_leaves_the_old_file_whole() {
        let dir = std::env::temp_dir().join(format!("slowdrift-replace-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("summary.csv");
        replace(&path, |w| w.write_all(b"old,1\nold,2\n")).unwrap();
        replace(&path, |w| w.write_all(b"new,1\nnew,2\n")).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new,1\nnew,2\n");
        let e = replace(&path, |w| {
            w.write_all(&[b'x'; 100_000])?;
            Err(std::io::Error::other("the disk is full"))
        })
        .unwrap_err()
        .to_string();
        assert_eq!(e, format!("{}: the disk is full", path.display()));
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new,1\nnew,2\n");
        let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 1, "{left:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
