//! SIGINT and SIGTERM during a campaign (`slowdrift montecarlo`, and the studies that run
//! one): the first stops it cleanly. No run starts after it, the runs in flight are
//! abandoned at their next time step (`montecarlo::run_jobs`), every run finished is already
//! in the runs file (each line written whole and flushed as its run finishes), the summary
//! of the runs done is written, and the command says how to resume and exits with status
//! 128 + the signal's number (130 for SIGINT, 143 for SIGTERM). A second signal ends the
//! process at once as the signal's default action does (nothing is lost: the runs file
//! drops a cut last line, the summary is replaced atomically). Outside a campaign the
//! signals act as by default.
//!
//! The handlers only set atomic flags (`signal_hook::flag`); they are the CLI's: the library
//! and the FMU install none.

use signal_hook::consts::{SIGINT, SIGTERM};
use signal_hook::flag;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// The handlers of SIGINT and SIGTERM for one campaign; dropped when it is over, after
/// which the signals act as by default. One per process (a campaign per command).
pub struct Interrupts {
    /// Set by the first signal; set too once the campaign is over. While set, a signal
    /// takes its default action.
    stop: Arc<AtomicBool>,
    /// The number of the last signal received (0: none).
    signal: Arc<AtomicUsize>,
}

impl Interrupts {
    /// Installs the handlers.
    pub fn install() -> Result<Interrupts, String> {
        let stop = Arc::new(AtomicBool::new(false));
        let signal = Arc::new(AtomicUsize::new(0));
        for number in [SIGINT, SIGTERM] {
            // In this order (signal-hook runs a signal's actions in the order registered):
            // the default action if a signal came before, then the signal's number, then
            // the flag the campaign polls.
            let registered = flag::register_conditional_default(number, Arc::clone(&stop))
                .and_then(|_| flag::register_usize(number, Arc::clone(&signal), number as usize))
                .and_then(|_| flag::register(number, Arc::clone(&stop)));
            registered.map_err(|e| format!("installing the handler of signal {number}: {e}"))?;
        }
        Ok(Interrupts { stop, signal })
    }

    /// The flag that stops the campaign (`montecarlo::run_jobs`).
    pub fn stop(&self) -> &AtomicBool {
        &self.stop
    }

    /// The signal that stopped the campaign, if one did.
    pub fn received(&self) -> Option<Signal> {
        if !self.stop.load(Ordering::SeqCst) {
            return None;
        }
        match self.signal.load(Ordering::SeqCst) {
            0 => None,
            number => Some(Signal(number as i32)),
        }
    }
}

impl Drop for Interrupts {
    fn drop(&mut self) {
        // The campaign is over: from now on a signal takes its default action.
        self.stop.store(true, Ordering::SeqCst);
    }
}

/// A signal received.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Signal(i32);

impl Signal {
    /// Its name, `SIGINT` or `SIGTERM`.
    pub fn name(self) -> String {
        signal_hook::low_level::signal_name(self.0)
            .map_or_else(|| format!("signal {}", self.0), str::to_string)
    }

    /// The exit status of a command it stopped: 128 + its number, as a shell reports a
    /// process the signal ended.
    pub fn exit_status(self) -> u8 {
        u8::try_from(128 + self.0).unwrap_or(1)
    }
}

/// The command line of this process, quoted for a POSIX shell (to be run again to resume).
pub fn this_command() -> String {
    std::env::args_os()
        .map(|arg| shell_quoted(&arg.to_string_lossy()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// `word` as a POSIX shell reads it back: as it is when it has nothing special, else in
/// single quotes (a quote inside as `'\''`).
fn shell_quoted(word: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./=:,+@%".contains(c);
    if !word.is_empty() && word.chars().all(plain) {
        word.to_string()
    } else {
        format!("'{}'", word.replace('\'', "'\\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_quoted_for_the_shell_only_when_needed() {
        assert_eq!(shell_quoted("--out"), "--out");
        assert_eq!(shell_quoted("dir/r.csv"), "dir/r.csv");
        assert_eq!(shell_quoted("my runs.csv"), "'my runs.csv'");
        assert_eq!(shell_quoted("it's"), "'it'\\''s'");
        assert_eq!(shell_quoted(""), "''");
        assert_eq!(shell_quoted("$HOME"), "'$HOME'");
    }

    #[test]
    fn signals_are_named_with_their_exit_status() {
        assert_eq!(Signal(SIGINT).name(), "SIGINT");
        assert_eq!(Signal(SIGINT).exit_status(), 130);
        assert_eq!(Signal(SIGTERM).name(), "SIGTERM");
        assert_eq!(Signal(SIGTERM).exit_status(), 143);
    }
}
