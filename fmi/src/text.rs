//! Rust text as C text, for the host's logger and for String variables.

use std::ffi::CString;

/// A C string of `s`, with interior NULs shown as `\0` (so that nothing is cut).
pub fn c_text(s: &str) -> CString {
    CString::new(s.replace('\0', "\\0")).expect("no interior NUL left")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interior_nuls_are_shown_not_cut() {
        assert_eq!(c_text("a\0b").as_bytes(), b"a\\0b");
        assert_eq!(c_text("plain").as_bytes(), b"plain");
    }
}
