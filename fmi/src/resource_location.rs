//! The resource location of an FMU: `fmuResourceLocation` (FMI 2.0) is a URI, and an FMU
//! reads its resources from the local folder it names ([`file_uri_to_path`]). A model also
//! reads a file a parameter names as a `file:` URI with the same function.

use std::path::PathBuf;

/// The local path of a `file:` URI in any form masters send: `file:///abs/path`,
/// `file://localhost/abs/path`, `file:/abs/path`, with or without a trailing slash, with
/// percent escapes (`%20`). `None` for other schemes, remote hosts, bad escapes or
/// non-UTF-8 results.
pub fn file_uri_to_path(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = match rest.strip_prefix("//") {
        Some(authority_and_path) => {
            let slash = authority_and_path.find('/')?;
            let host = &authority_and_path[..slash];
            if !(host.is_empty() || host.eq_ignore_ascii_case("localhost")) {
                return None;
            }
            &authority_and_path[slash..]
        }
        None => rest,
    };
    if !path.starts_with('/') {
        return None;
    }
    Some(PathBuf::from(percent_decode(path)?))
}

/// Decodes `%XX` escapes; `None` on a malformed escape or a result that is not UTF-8.
fn percent_decode(s: &str) -> Option<String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = s.get(i + 1..i + 3)?;
            if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                return None;
            }
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    #[test]
    fn every_uri_form_masters_send() {
        let expected = Path::new("/tmp/fmu x/resources");
        for uri in [
            "file:///tmp/fmu%20x/resources",
            "file:///tmp/fmu%20x/resources/",
            "file://localhost/tmp/fmu%20x/resources",
            "file:/tmp/fmu%20x/resources",
            "file:/tmp/fmu x/resources/",
            "file:///tmp/fmu%20%78/resources",
        ] {
            let path = file_uri_to_path(uri).unwrap_or_else(|| panic!("{uri}"));
            // A trailing slash names the same directory.
            assert_eq!(
                path.components().collect::<Vec<_>>(),
                expected.components().collect::<Vec<_>>(),
                "{uri}"
            );
        }
    }

    #[test]
    fn other_uris_are_refused() {
        for uri in [
            "http://host/resources",
            "file://remote/resources",
            "file:relative/resources",
            "file:///bad%2",
            "file:///bad%zz",
            "file:///bad%+1",
            "file:///not-utf8%ff",
            "/plain/path",
            "",
        ] {
            assert_eq!(file_uri_to_path(uri), None, "{uri}");
        }
    }
}
