//! The subcommands of the `slowdrift` tool.

pub mod args;
pub mod hydro;
pub mod interrupt;
pub mod montecarlo;
pub mod out;
pub mod simulate;
pub mod study;

/// Why a command failed: the message `main` prints and the exit status.
#[derive(Debug)]
pub struct Failure {
    pub message: String,
    /// 1, or 128 + the signal's number for a campaign a signal stopped.
    pub status: u8,
}

impl From<String> for Failure {
    fn from(message: String) -> Failure {
        Failure { message, status: 1 }
    }
}
