//! An exclusive lock that keeps a second process off a file (a campaign's runs file): the
//! kernel's `flock` on a lock file beside it, `NAME.lock`, which holds the pid of the
//! process that has it. The kernel releases the lock when that process ends, however it
//! ends (a kill -9 too), so a lock file left behind never blocks anyone; the holder removes
//! the file when it is done.
//!
//! A process refused names the holder by the pid in the file. The Dask client
//! (`fmu-pack/python/slowdrift_dask/runs_file.py`) takes the same lock the same way, so the
//! native tool and the client keep off each other's campaign too.

use crate::error::{Error, Result};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The lock of one file, held until dropped.
#[derive(Debug)]
pub struct Lock {
    /// The lock file, locked (closing it unlocks).
    _file: File,
    path: PathBuf,
}

/// The lock file of `locked`: `NAME.lock` beside it.
pub fn lock_path(locked: &Path) -> PathBuf {
    let mut name = locked.file_name().unwrap_or_default().to_os_string();
    name.push(".lock");
    locked.with_file_name(name)
}

/// Takes the exclusive lock of `locked` for this process, at once or not at all: when
/// another process holds it, an error that names `locked`, the holder's pid and the lock
/// file.
pub fn lock(locked: &Path) -> Result<Lock> {
    let path = lock_path(locked);
    let io = |e: std::io::Error| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    loop {
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(io)?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => return Err(held(locked, &path)),
            Err(TryLockError::Error(e)) => return Err(io(e)),
        }
        // The holder that just let go removes its file: a lock on that file, no longer
        // at `path`, keeps nobody off. Then again, on the file now there.
        let mine = file.metadata().map_err(io)?;
        match std::fs::metadata(&path) {
            Ok(there) if (there.dev(), there.ino()) == (mine.dev(), mine.ino()) => {}
            Ok(_) => continue,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(e) => return Err(io(e)),
        }
        file.set_len(0).map_err(io)?;
        writeln!(file, "{}", std::process::id()).map_err(io)?;
        file.flush().map_err(io)?;
        return Ok(Lock { _file: file, path });
    }
}

/// The error for `locked` held by another process: its pid as the lock file says (read
/// again for up to a tenth of a second while the holder has locked the file but not yet
/// written its pid).
fn held(locked: &Path, path: &Path) -> Error {
    let mut holder = None;
    for _ in 0..10 {
        holder = std::fs::read_to_string(path)
            .ok()
            .and_then(|text| text.trim().parse::<u32>().ok());
        if holder.is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let process = match holder {
        Some(pid) => format!("process {pid}"),
        None => "another process (its pid not yet written)".to_string(),
    };
    Error::Io {
        path: locked.display().to_string(),
        message: format!(
            "in use by {process}, which holds its lock {}: two campaigns on one file would \
             mix their runs; wait for that one to end, or stop it",
            path.display()
        ),
    }
}

impl Drop for Lock {
    fn drop(&mut self) {
        // Removed while still locked (a process that opened it meanwhile finds it gone and
        // starts again); the lock goes with the file handle. A lock file that cannot be
        // removed is harmless: the next process locks it.
        std::fs::remove_file(&self.path).ok();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str) -> PathBuf {
        std::env::temp_dir().join(format!("slowdrift-lock-{}-{name}", std::process::id()))
    }

    /// A second lock on the same file is refused at once, naming the file, this process's
    /// pid and the lock file; after the first is dropped the file is gone and locks again.
    #[test]
    fn a_second_lock_is_refused_naming_the_holder() {
        let locked = temp("runs.csv");
        let first = lock(&locked).unwrap();
        let pid = std::fs::read_to_string(lock_path(&locked)).unwrap();
        assert_eq!(pid, format!("{}\n", std::process::id()));
        let m = lock(&locked).unwrap_err().to_string();
        assert!(
            m.starts_with(&format!(
                "{}: in use by process {}, which holds its lock {}.lock",
                locked.display(),
                std::process::id(),
                locked.display()
            )),
            "{m}"
        );
        drop(first);
        assert!(!lock_path(&locked).exists());
        let again = lock(&locked).unwrap();
        drop(again);
    }

    /// A lock file left by a process that is gone (a kill -9) does not keep anyone off.
    #[test]
    fn a_lock_file_left_behind_locks_again() {
        let locked = temp("left.csv");
        std::fs::write(lock_path(&locked), "999999999\n").unwrap();
        let lock = lock(&locked).unwrap();
        let pid = std::fs::read_to_string(lock_path(&locked)).unwrap();
        assert_eq!(pid, format!("{}\n", std::process::id()));
        drop(lock);
    }
}
