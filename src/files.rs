//! Reading the files a user names (configurations, case tables, runs files, hydro databases,
//! WAMIT output): a path must name a regular file no larger than [`MAX_INPUT_BYTES`]. A FIFO,
//! a device, a socket or a directory is refused by what it is before anything reads it (a
//! FIFO would block the reader until a writer comes, `/dev/zero` would be read until memory
//! runs out), and reading stops at the limit whatever the file does meanwhile. The memory
//! its reader will take ([`Cost`], per byte of the file) must be within the memory limit and
//! allocatable by this process before the file is read ([`budget`]).
//!
//! The files a program writes again and again (a campaign's summary, a study's data and
//! figures) are written anew atomically ([`replace`]: a temporary file renamed), and a
//! campaign's runs file is kept off by a second process ([`lock`]).

pub mod budget;
mod lock;
mod replace;

pub use budget::{afford, Cost};
pub use lock::{lock, lock_path, Lock};
pub use replace::replace;

use crate::error::{Error, Result};
use std::fs::{File, FileType, OpenOptions};
use std::io::Read;
use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
use std::path::Path;

/// The largest input file read, bytes (1 GiB: the largest WAMIT QTF files users bring are a
/// few hundred MB).
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// The text of the regular file at `path` (at most [`MAX_INPUT_BYTES`]), read by a reader
/// of `cost` within `memory_limit` bytes; errors name the path and what is wrong.
pub fn read_text(path: &Path, cost: &Cost, memory_limit: f64) -> Result<String> {
    read_text_within(path, MAX_INPUT_BYTES, cost, memory_limit)?.ok_or_else(|| Error::Io {
        path: path.display().to_string(),
        message: "No such file or directory".into(),
    })
}

/// As [`read_text`], but `None` when nothing exists at `path`.
pub fn read_text_if_exists(path: &Path, cost: &Cost, memory_limit: f64) -> Result<Option<String>> {
    read_text_within(path, MAX_INPUT_BYTES, cost, memory_limit)
}

/// What a file type that is not a regular file is, in words.
fn kind(file_type: FileType) -> &'static str {
    if file_type.is_dir() {
        "a directory"
    } else if file_type.is_fifo() {
        "a FIFO (named pipe)"
    } else if file_type.is_char_device() {
        "a character device"
    } else if file_type.is_block_device() {
        "a block device"
    } else if file_type.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

/// The regular file at `path`, open for reading, no larger than `limit` and read by a reader
/// of `cost` within `memory_limit` bytes (the module's checks); `None` when nothing exists at
/// `path`.
fn open_within(path: &Path, limit: u64, cost: &Cost, memory_limit: f64) -> Result<Option<File>> {
    let io = |message: String| Error::Io {
        path: path.display().to_string(),
        message,
    };
    let refuse = |file_type: FileType| {
        io(format!(
            "is {}, not a regular file: give the path of a file",
            kind(file_type)
        ))
    };
    // The path's type first (stat does not block), then the opened file's own (the path may
    // have changed between the two); O_NONBLOCK so that not even that open can wait.
    let meta = match std::fs::metadata(path) {
        Ok(meta) => meta,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(io(e.to_string())),
    };
    if !meta.is_file() {
        return Err(refuse(meta.file_type()));
    }
    let file = OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)
        .map_err(|e| io(e.to_string()))?;
    let meta = file.metadata().map_err(|e| io(e.to_string()))?;
    if !meta.is_file() {
        return Err(refuse(meta.file_type()));
    }
    if meta.len() > limit {
        return Err(io(format!(
            "is {} bytes, more than the {limit} bytes an input file may have",
            meta.len()
        )));
    }
    cost.check(&path.display().to_string(), meta.len(), memory_limit)?;
    Ok(Some(file))
}

/// An input file read as a stream (a case table read row by row): the checks of
/// [`read_text`], and a read error, not an end, past [`MAX_INPUT_BYTES`] (the file grew
/// while it was read).
#[derive(Debug)]
pub struct Input {
    file: File,
    read: u64,
    limit: u64,
}

impl Read for Input {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.file.read(buf)?;
        self.read += n as u64;
        if self.read > self.limit {
            return Err(std::io::Error::other(format!(
                "grew past the {} bytes an input file may have while it was read",
                self.limit
            )));
        }
        Ok(n)
    }
}

/// The regular file at `path` as a stream ([`Input`]), read by a reader of `cost` within
/// `memory_limit` bytes; errors name the path.
pub fn open(path: &Path, cost: &Cost, memory_limit: f64) -> Result<Input> {
    let file =
        open_within(path, MAX_INPUT_BYTES, cost, memory_limit)?.ok_or_else(|| Error::Io {
            path: path.display().to_string(),
            message: "No such file or directory".into(),
        })?;
    Ok(Input {
        file,
        read: 0,
        limit: MAX_INPUT_BYTES,
    })
}

fn read_text_within(
    path: &Path,
    limit: u64,
    cost: &Cost,
    memory_limit: f64,
) -> Result<Option<String>> {
    let io = |message: String| Error::Io {
        path: path.display().to_string(),
        message,
    };
    let Some(file) = open_within(path, limit, cost, memory_limit)? else {
        return Ok(None);
    };
    let size = file.metadata().map_err(|e| io(e.to_string()))?.len();
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(size as usize)
        .map_err(|_| io(format!("{size} bytes cannot be allocated")))?;
    Input {
        file,
        read: 0,
        limit,
    }
    .read_to_end(&mut bytes)
    .map_err(|e| io(e.to_string()))?;
    String::from_utf8(bytes).map(Some).map_err(|e| {
        io(format!(
            "is not UTF-8 text (byte {})",
            e.utf8_error().valid_up_to()
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    fn temp(name: &str) -> std::path::PathBuf {
        std::env::temp_dir().join(format!("slowdrift-files-{}-{name}", std::process::id()))
    }

    fn message(result: Result<String>) -> String {
        result.unwrap_err().to_string()
    }

    /// A reader that holds the text alone, within a limit no test file reaches.
    const TEXT: Cost = Cost {
        format: "text",
        per_byte: 1.0,
    };
    const LIMIT: f64 = 1e9;

    fn read_text(path: &Path) -> Result<String> {
        super::read_text(path, &TEXT, LIMIT)
    }

    fn read_text_if_exists(path: &Path) -> Result<Option<String>> {
        super::read_text_if_exists(path, &TEXT, LIMIT)
    }

    #[test]
    fn a_regular_file_is_read_and_a_missing_one_named() {
        let path = temp("regular.txt");
        std::fs::write(&path, "a = 1\n").unwrap();
        assert_eq!(read_text(&path).unwrap(), "a = 1\n");
        std::fs::remove_file(&path).unwrap();
        assert!(read_text_if_exists(&path).unwrap().is_none());
        let m = message(read_text(&path));
        assert!(m.contains(&path.display().to_string()), "{m}");
    }

    /// A FIFO with no writer is refused at once (opening it for reading would block), a
    /// character device and a directory by what they are.
    #[test]
    fn fifos_devices_and_directories_are_refused_by_name() {
        let fifo = temp("fifo");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        let start = Instant::now();
        let m = message(read_text(&fifo));
        assert!(start.elapsed() < Duration::from_secs(5));
        std::fs::remove_file(&fifo).unwrap();
        assert!(
            m.contains("is a FIFO (named pipe), not a regular file"),
            "{m}"
        );
        let m = message(read_text(Path::new("/dev/zero")));
        assert!(m.contains("/dev/zero: is a character device"), "{m}");
        let m = message(read_text(&std::env::temp_dir()));
        assert!(m.contains("is a directory"), "{m}");
    }

    #[test]
    fn a_file_over_the_limit_is_refused_with_its_size() {
        let path = temp("large.txt");
        std::fs::write(&path, "0123456789").unwrap();
        let m = read_text_within(&path, 9, &TEXT, LIMIT)
            .unwrap_err()
            .to_string();
        assert_eq!(
            read_text_within(&path, 10, &TEXT, LIMIT).unwrap().unwrap(),
            "0123456789"
        );
        std::fs::remove_file(&path).unwrap();
        assert!(
            m.contains("is 10 bytes, more than the 9 bytes an input file may have"),
            "{m}"
        );
    }

    /// A file whose reader would take more than the memory limit is refused before it is
    /// read, naming its size, the estimate and the limit.
    #[test]
    fn a_file_its_reader_cannot_afford_is_refused_before_it_is_read() {
        let path = temp("costly.txt");
        std::fs::write(&path, "0123456789").unwrap();
        let costly = Cost {
            format: "costly text",
            per_byte: 100.0,
        };
        assert_eq!(
            super::read_text(&path, &costly, 1000.0).unwrap(),
            "0123456789"
        );
        let m = message(super::read_text(&path, &costly, 999.0));
        assert!(
            m.contains(
                "costly.txt: reading it needs 1.000 kB of memory (a costly text of 10 \
                        bytes, up to 100 bytes of memory per byte); the limit is 999 bytes"
            ),
            "{m}"
        );
        let m = super::open(&path, &costly, 999.0).unwrap_err().to_string();
        assert!(m.contains("reading it needs 1.000 kB"), "{m}");
        std::fs::remove_file(&path).unwrap();
    }
}
