//! The panic firewall: every FMI function runs its body inside `catch_unwind`, so that a
//! panic never unwinds into the host (undefined behaviour across `extern "C"`); it becomes
//! the function's failure value, or an [`Error::Panic`] that the call reports.

use crate::Error;
use std::any::Any;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f`; a panic becomes `fallback` (NULL from `fmi2Instantiate`, `fmi2Error`, ...).
pub fn firewall<R>(fallback: R, f: impl FnOnce() -> R) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(fallback)
}

/// Runs `f`; a panic becomes [`Error::Panic`] with its message, for the call to report.
pub fn catch<R>(f: impl FnOnce() -> Result<R, Error>) -> Result<R, Error> {
    catch_unwind(AssertUnwindSafe(f))
        .unwrap_or_else(|payload| Err(Error::Panic(panic_text(payload.as_ref()))))
}

/// The message of a panic payload (`panic!` with a literal or a format).
fn panic_text(payload: &(dyn Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_becomes_the_fallback_or_an_error() {
        assert_eq!(firewall(7, || panic!("boom")), 7);
        assert_eq!(firewall(7, || 3), 3);
        assert_eq!(
            catch::<()>(|| panic!("boom {}%", 100)),
            Err(Error::Panic("boom 100%".into()))
        );
        assert_eq!(
            catch::<()>(|| panic!("literal")),
            Err(Error::Panic("literal".into()))
        );
        assert_eq!(
            catch::<()>(|| std::panic::panic_any(42)),
            Err(Error::Panic("unknown panic".into()))
        );
        assert_eq!(catch(|| Ok(5)), Ok(5));
    }
}
