//! Stable 64-bit fingerprints of what a result depends on: the 64-bit FNV-1a hash of a
//! value's JSON (serde: field names in declaration order, numbers in their shortest
//! round-trip form). It changes when the value changes or its type gains or loses a field,
//! and never with the compiler, unlike the `Debug` text, whose form Rust does not promise.
//! FMU states and the runs file of a Monte Carlo campaign store one, so that a state or a
//! resumed campaign cannot be mixed with another configuration.

use serde::Serialize;
use std::io::Write;

/// The FNV-1a hash of everything written to it.
struct Fnv1a(u64);

impl Write for Fnv1a {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        const PRIME: u64 = 0x0000_0100_0000_01b3;
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(PRIME);
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The FNV-1a offset basis: the hash of no bytes.
const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// The fingerprint of `value`.
pub fn fingerprint<T: Serialize>(value: &T) -> u64 {
    let mut hash = Fnv1a(OFFSET);
    serde_json::to_writer(&mut hash, value).expect("the fingerprinted types serialize to JSON");
    hash.0
}

/// The FNV-1a hash of `bytes` (the checksum of a serialized FMU state).
pub fn of_bytes(bytes: &[u8]) -> u64 {
    let mut hash = Fnv1a(OFFSET);
    hash.write_all(bytes).expect("hashing does not fail");
    hash.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a of the bytes of the JSON text, against the published test vectors of the
    /// algorithm (`""` and `"a"`) and a value's JSON written out by hand.
    #[test]
    fn fnv1a_of_the_json_text() {
        let hash = |bytes: &[u8]| {
            let mut h = Fnv1a(0xcbf2_9ce4_8422_2325);
            h.write_all(bytes).unwrap();
            h.0
        };
        assert_eq!(hash(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(hash(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(of_bytes(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(of_bytes(b"a"), 0xaf63_dc4c_8601_ec8c);
        #[derive(Serialize)]
        struct Point {
            x: f64,
            name: &'static str,
        }
        let p = Point { x: 0.1, name: "a" };
        assert_eq!(fingerprint(&p), hash(br#"{"x":0.1,"name":"a"}"#));
        assert_ne!(fingerprint(&p), fingerprint(&Point { x: 0.2, name: "a" }));
    }
}
