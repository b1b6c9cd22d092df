//! Saved FMU states (`fmi2GetFMUstate`) and their byte format (`fmi2SerializeFMUstate`).
//!
//! Bytes, all little-endian, no padding, nothing position-dependent:
//!
//! | bytes | field |
//! |---|---|
//! | 4 | magic `SDFS` |
//! | 4 | format version (u32, [`FORMAT_VERSION`]) |
//! | 8 | fingerprint of the configuration (u64, [`fingerprint`]) |
//! | 1 | instance state ([`MachineState::code`]) |
//! | 1 | terminated flag (0 or 1) |
//! | 1 | 1 when a simulation snapshot follows, else 0 |
//! | 8 | last successful time (f64) |
//! | 24 | inputs Fx_ext, Fy_ext, Mz_ext (3 f64) |
//! | 96 | the snapshot, when present ([`Snapshot::to_bytes`]) |
//!
//! The records are not saved: they are a pure function of the configuration, which the
//! restoring instance rebuilds from its own parameters. The fingerprint makes sure these are
//! the same: a state from a differently configured instance is refused.

use super::machine::MachineState;
use crate::error::{Error, Result};
use crate::problem::Problem;
use crate::simulation::Snapshot;

/// First bytes of a serialized state.
pub const MAGIC: [u8; 4] = *b"SDFS";
/// Version of the byte format; a state of any other version is refused. Version 2: the
/// fingerprint is the serde-JSON FNV-1a of the problem (version 1 hashed its `Debug` text).
pub const FORMAT_VERSION: u32 = 2;
/// Bytes before the optional snapshot.
const HEADER_BYTES: usize = 4 + 4 + 8 + 3 + 8 + 24;

/// Everything an instance needs to continue from a saved point.
#[derive(Debug, Clone, PartialEq)]
pub struct FmuState {
    pub fingerprint: u64,
    pub machine: MachineState,
    pub terminated: bool,
    pub last_successful_time: f64,
    pub inputs: [f64; 3],
    /// `None` before initialisation (no simulation yet).
    pub snapshot: Option<Snapshot>,
}

impl FmuState {
    /// Length of [`FmuState::to_bytes`].
    pub fn byte_len(&self) -> usize {
        HEADER_BYTES + self.snapshot.as_ref().map_or(0, |_| Snapshot::BYTES)
    }

    /// The byte format of the module documentation.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.byte_len());
        out.extend_from_slice(&MAGIC);
        out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        out.extend_from_slice(&self.fingerprint.to_le_bytes());
        out.push(self.machine.code());
        out.push(u8::from(self.terminated));
        out.push(u8::from(self.snapshot.is_some()));
        out.extend_from_slice(&self.last_successful_time.to_le_bytes());
        for v in self.inputs {
            out.extend_from_slice(&v.to_le_bytes());
        }
        if let Some(s) = &self.snapshot {
            out.extend_from_slice(&s.to_bytes());
        }
        out
    }

    /// Reads [`FmuState::to_bytes`]; refuses a wrong magic, version or length, or a
    /// fingerprint other than `expected_fingerprint` (the restoring instance's).
    pub fn from_bytes(bytes: &[u8], expected_fingerprint: u64) -> Result<FmuState> {
        let refuse = |value: String, reason: &str| Error::invalid("FMU state", value, reason);
        if bytes.len() < HEADER_BYTES {
            return Err(refuse(
                format!("{} bytes", bytes.len()),
                "is truncated: shorter than the header",
            ));
        }
        let (header, rest) = bytes.split_at(HEADER_BYTES);
        if header[..4] != MAGIC {
            return Err(refuse(
                format!("{:?}", &header[..4]),
                "does not start with SDFS: not a SlowDrift state",
            ));
        }
        let version = u32::from_le_bytes(header[4..8].try_into().expect("4 bytes"));
        if version != FORMAT_VERSION {
            return Err(refuse(
                format!("format version {version}"),
                &format!("is not this library's format version {FORMAT_VERSION}"),
            ));
        }
        let fingerprint = u64::from_le_bytes(header[8..16].try_into().expect("8 bytes"));
        if fingerprint != expected_fingerprint {
            return Err(mismatch(fingerprint, expected_fingerprint));
        }
        let machine = MachineState::from_code(header[16])
            .ok_or_else(|| refuse(format!("state code {}", header[16]), "is unknown"))?;
        let flag = |b: u8, name: &str| match b {
            0 => Ok(false),
            1 => Ok(true),
            other => Err(refuse(format!("{name} = {other}"), "must be 0 or 1")),
        };
        let terminated = flag(header[17], "terminated")?;
        let has_snapshot = flag(header[18], "snapshot flag")?;
        let real = |at: usize| f64::from_le_bytes(header[at..at + 8].try_into().expect("8"));
        let last_successful_time = real(19);
        let inputs = [real(27), real(35), real(43)];
        let snapshot = match (has_snapshot, rest.len()) {
            (false, 0) => None,
            (true, Snapshot::BYTES) => Some(Snapshot::from_bytes(rest)?),
            (_, n) => {
                return Err(refuse(
                    format!("{} bytes", bytes.len()),
                    &format!(
                        "has {n} bytes after the header, which does not match its snapshot flag"
                    ),
                ))
            }
        };
        Ok(FmuState {
            fingerprint,
            machine,
            terminated,
            last_successful_time,
            inputs,
            snapshot,
        })
    }
}

/// The error for a state taken with another configuration.
pub fn mismatch(found: u64, expected: u64) -> Error {
    Error::invalid(
        "FMU state fingerprint",
        format!("{found:016x}"),
        format!(
            "was saved with another configuration (this instance: {expected:016x}); \
             set the same parameters and hydroDatabase first"
        ),
    )
}

/// The [`crate::fingerprint`] of the problem: any change to anything that determines the
/// records (sea, seed, platform, drift table, run) changes it. Where the configuration came
/// from (embedded, resources, a file at any path) does not enter, only its content, so a
/// state moves between processes that unpacked the FMU in different places.
pub fn fingerprint(config: &Problem) -> u64 {
    crate::fingerprint::fingerprint(config)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::resolve;
    use crate::scenario::default::default_scenario;

    fn state(snapshot: bool) -> FmuState {
        FmuState {
            fingerprint: 0x0123_4567_89ab_cdef,
            machine: MachineState::StepComplete,
            terminated: true,
            last_successful_time: 12.5,
            inputs: [1.0, -2.0, 3e9],
            snapshot: snapshot.then(|| Snapshot::from_bytes(&[7u8; Snapshot::BYTES]).unwrap()),
        }
    }

    #[test]
    fn bytes_round_trip_with_and_without_snapshot() {
        for with in [false, true] {
            let s = state(with);
            let bytes = s.to_bytes();
            assert_eq!(bytes.len(), s.byte_len());
            assert_eq!(&bytes[..4], b"SDFS");
            assert_eq!(FmuState::from_bytes(&bytes, s.fingerprint).unwrap(), s);
        }
    }

    #[test]
    fn damaged_bytes_are_refused() {
        let s = state(true);
        let good = s.to_bytes();
        let f = s.fingerprint;
        let mut cases: Vec<(Vec<u8>, &str)> = vec![
            (good[..good.len() - 1].to_vec(), "truncated snapshot"),
            (good[..10].to_vec(), "truncated header"),
            ([good.clone(), vec![0]].concat(), "trailing byte"),
        ];
        let mut patch = |at: usize, value: u8, what: &'static str| {
            let mut b = good.clone();
            b[at] = value;
            cases.push((b, what));
        };
        patch(0, b'X', "magic");
        patch(4, FORMAT_VERSION as u8 + 1, "version");
        patch(8, 0xee, "fingerprint");
        patch(16, 99, "machine state");
        patch(17, 2, "terminated flag");
        patch(18, 0, "snapshot flag");
        for (bytes, what) in cases {
            assert!(FmuState::from_bytes(&bytes, f).is_err(), "{what}");
        }
        assert!(
            FmuState::from_bytes(&good, f ^ 1).is_err(),
            "other instance"
        );
    }

    #[test]
    fn fingerprint_sees_every_change() {
        let a = resolve(&default_scenario().unwrap()).unwrap();
        assert_eq!(fingerprint(&a), fingerprint(&a.clone()));
        let mut b = a.clone();
        b.sea.seed += 1;
        let mut c = a.clone();
        c.platform.mass *= 1.0 + f64::EPSILON;
        let mut d = a.clone();
        d.run.duration += 1.0;
        for other in [b, c, d] {
            assert_ne!(fingerprint(&a), fingerprint(&other));
        }
    }
}
