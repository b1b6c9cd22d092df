//! The memory reading a file takes, checked before the file is read: a
//! file under the 1 GiB size limit could still abort the process, because a reader holds
//! many times the file's size (a TOML configuration of 400 MB took 2.9 GB in the TOML
//! reader, a CSV of 1 GiB 4 GB).
//!
//! Each reader states its [`Cost`]: the most memory it holds per byte of the file, the text
//! and everything it makes from it, measured on its format's costliest content (the test
//! suite checks every reader's constant against the peak it measures, `tests/all/
//! reading_cost.rs`). A file whose size times that cost exceeds the memory limit is refused
//! before anything is allocated, naming the file, its size, the estimate and the limit; an
//! estimate within the limit is allocated once and freed ([`crate::allocator::can_allocate`])
//! so that a process whose own limit is lower (`ulimit -v`, a container) gets an error
//! instead of an abort, as the records' budget does (`record_plan::budget`). What a file's
//! content makes beyond its size (the frequency grid of a QTF) is checked the same way where
//! it is made ([`afford`]).

use crate::error::{bytes_text, Error, FileOverBudget, Result, BYTES_PER_GB};

/// The default memory limit (`run.memory_limit_gb`, FMU `memoryLimit`, the CLI's
/// `--memory-limit-gb`): 4 GB (4e9 bytes), for a workstation that runs a few simulations at
/// once. The records of a simulation and the reading of a file are each budgeted against it.
pub const DEFAULT_MEMORY_LIMIT: f64 = 4.0e9;

/// Refuses a memory limit (bytes) that is not a finite number greater than zero, naming
/// `field` (the setting as the user wrote it) with the value in GB.
pub fn check_memory_limit(field: &str, limit: f64) -> Result<()> {
    if limit.is_finite() && limit > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            field,
            limit / BYTES_PER_GB,
            "must be a finite number greater than zero",
        ))
    }
}

/// What reading one format costs in memory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    /// The format, as messages name it (`TOML configuration`).
    pub format: &'static str,
    /// The most bytes of memory the reader holds per byte of the file.
    pub per_byte: f64,
}

impl Cost {
    /// Refuses reading `size` bytes of this format at `path` beyond `limit` bytes of memory
    /// (or beyond what this process can allocate).
    pub fn check(&self, path: &str, size: u64, limit: f64) -> Result<()> {
        afford(
            path,
            size as f64 * self.per_byte,
            || {
                format!(
                    "a {} of {}, up to {} bytes of memory per byte",
                    self.format,
                    size_text(size),
                    self.per_byte
                )
            },
            limit,
        )
    }
}

/// A file's size for a message: "419430400 bytes (419 MB)".
fn size_text(size: u64) -> String {
    if size < 1000 {
        format!("{size} bytes")
    } else {
        format!("{size} bytes ({})", bytes_text(size as f64))
    }
}

/// Refuses `needs` bytes of memory for reading the file at `path` beyond `limit`, or beyond
/// what this process can allocate now; `what` says what the estimate is made of.
pub fn afford(path: &str, needs: f64, what: impl Fn() -> String, limit: f64) -> Result<()> {
    let refuse = |process: bool| {
        Error::FileOverBudget(Box::new(FileOverBudget {
            path: path.to_string(),
            what: what(),
            needs,
            limit,
            process,
        }))
    };
    // A NaN estimate is refused too.
    if needs.is_nan() || needs > limit {
        return Err(refuse(false));
    }
    if !crate::allocator::can_allocate(needs as usize) {
        return Err(refuse(true));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOML: Cost = Cost {
        format: "TOML configuration",
        per_byte: 900.0,
    };

    #[test]
    fn a_file_beyond_the_limit_is_refused_with_its_size_the_estimate_and_the_limit() {
        assert!(TOML.check("a.toml", 1000, 1e6).is_ok());
        let message = TOML
            .check("a.toml", 400 << 20, 4e9)
            .unwrap_err()
            .to_string();
        assert_eq!(
            message,
            "a.toml: reading it needs 377 GB of memory (a TOML configuration of 419430400 \
             bytes (419 MB), up to 900 bytes of memory per byte); the limit is 4.000 GB \
             (run.memory_limit_gb = 4)"
        );
        let message = TOML.check("a.toml", 12, 1e4).unwrap_err().to_string();
        assert!(
            message.contains("configuration of 12 bytes, up to"),
            "{message}"
        );
    }

    /// Within the limit, but beyond any address space: the probe refuses it, naming the
    /// process.
    #[test]
    fn beyond_what_the_process_can_allocate_is_refused_naming_the_process() {
        let message = afford("q.12d", 1e18, || "a QTF".into(), 1e19)
            .unwrap_err()
            .to_string();
        assert!(
            message.starts_with(
                "q.12d: reading it needs 1000000 TB of memory (a QTF) and this \
                                 process cannot allocate them"
            ),
            "{message}"
        );
    }
}
