//! Saved FMU states (`fmi2GetFMUstate`) and their byte format (`fmi2SerializeFMUstate`).
//!
//! A state stands alone (FMI 2.0.4 section 2.1.8 counts the parameter values as part of the
//! FMU state): it carries every parameter's value and the experiment, so that it restores
//! in an instance straight after `fmi2Instantiate`, before any `fmi2Set*`, as fmusim
//! restores one (`--initial-fmu-state-file`), or in an instance configured otherwise; the
//! instance takes the state's parameters and experiment as its own.
//!
//! Bytes, all little-endian, no padding, nothing position-dependent:
//!
//! | bytes | field |
//! |---|---|
//! | 4 | magic `SDFS` |
//! | 4 | format version (u32, [`FORMAT_VERSION`]) |
//! | 8 | fingerprint of the resolved problem (u64, [`fingerprint`]) |
//! | 1 | instance state ([`MachineState::code`]; never Error) |
//! | 1 | 1 when a simulation snapshot follows the parameters, else 0 |
//! | 8 | last successful time (f64, finite; from the start time to the instance's time: the snapshot's, else the start time) |
//! | 32 | inputs Fx_ext, Fy_ext, Mz_ext, windVelocity_ext (4 f64, finite; the last at least 0) |
//! | 8 | experiment start time (f64, finite) |
//! | 1 | 1 when the experiment has a stop time, else 0 |
//! | 8 | stop time (f64, finite and after the start time; all bits 0 without a stop time) |
//! | 4 | number of parameters (u32): modelDescription.xml's, which the reader requires |
//! | ... | each parameter in the XML's order: its value reference (u32), its type (one byte: `R` Real, `I` Integer, `S` String), whether the master set it (one byte, 0 or 1: an unset parameter takes the configuration's value), its value: Real 8 bytes (f64, finite), Integer 4 bytes (i32), String a length (u32, at most [`MAX_STRING_BYTES`]) and that many bytes of UTF-8 without NUL |
//! | 104 | the snapshot ([`Snapshot::to_bytes`]), present exactly when the instance state is StepComplete, StepFailed or Terminated: every value finite ([`Snapshot::check`]), its step positive and the `stepSize` the master set (if it did), its time from the start time to the stop time (if any), where a double resolves the step |
//! | 8 | checksum: FNV-1a (u64) of every byte before it |
//!
//! The records are not saved: they are a pure function of the parameters, the experiment
//! and the base configuration they name (`hydroDatabase`, the FMU's resources or the
//! embedded default). The restoring instance rebuilds them (`fmi2SetFMUstate`; unless the
//! records it has were built from the same problem) and compares the fingerprint of the
//! problem it resolves with the saved one. The fingerprint covers the data read from the
//! files, not their paths, so a `hydroDatabase` file whose content changed since the save,
//! or that cannot be read, refuses the state, and the message says which file.
//!
//! `fmi2DeSerializeFMUstate` only reads and checks the bytes ([`FmuState::from_bytes`]: the
//! magic, the version, the checksum, every length and flag, finite values and the rules
//! between fields where the table says so, the parameters against modelDescription.xml),
//! every field that `fmi2SetFMUstate` would refuse without resolving the problem, so that a
//! damaged state is refused at once; resolving the problem (reading
//! files, running solvers) is deferred to `fmi2SetFMUstate`, which fmusim and fmpy call
//! right after, so that it happens once.

use super::machine::MachineState;
use super::parameters::{Base, Experiment, FmuValue, Parameters, MAX_STRING_BYTES};
use crate::error::{Error, Result};
use crate::fmi2::model_description::VariableType;
use crate::problem::{largest_resolved_time, time_resolved, Problem};
use crate::simulation::{Held, Snapshot};

/// First bytes of a serialized state.
pub const MAGIC: [u8; 4] = *b"SDFS";
/// Version of the byte format of the module documentation; a state of any other version is
/// refused (its bytes would be read as other fields). Raised whenever a field is added,
/// removed or reinterpreted.
pub const FORMAT_VERSION: u32 = 5;
/// Bytes of the fixed fields before the parameters (magic to the parameter count).
const FIXED_BYTES: usize = 4 + 4 + 8 + 2 + 8 + 32 + 8 + 1 + 8 + 4;
/// Bytes of the checksum at the end.
const CHECKSUM_BYTES: usize = 8;
/// Offset of the last successful time.
const LAST_SUCCESSFUL_TIME_AT: usize = 18;
/// The parameter whose value, when the master set it, is the snapshot's step.
const STEP_SIZE: &str = "stepSize";

/// Type bytes of the parameters.
const REAL: u8 = b'R';
const INTEGER: u8 = b'I';
const STRING: u8 = b'S';

/// Everything an instance needs to continue from a saved point.
#[derive(Debug, Clone, PartialEq)]
pub struct FmuState {
    /// Of the problem the parameters and the experiment resolved to when saved.
    pub fingerprint: u64,
    pub parameters: Parameters,
    pub experiment: Experiment,
    pub machine: MachineState,
    pub last_successful_time: f64,
    pub inputs: Held,
    /// `None` before initialisation (no simulation yet).
    pub snapshot: Option<Snapshot>,
}

impl FmuState {
    /// Length of [`FmuState::to_bytes`].
    pub fn byte_len(&self) -> usize {
        let parameters: usize = self
            .parameters
            .iter()
            .map(|(_, value, _)| {
                4 + 1
                    + 1
                    + match value {
                        FmuValue::Real(_) => 8,
                        FmuValue::Integer(_) => 4,
                        FmuValue::String(s) => 4 + s.len(),
                    }
            })
            .sum();
        FIXED_BYTES
            + parameters
            + self.snapshot.as_ref().map_or(0, |_| Snapshot::BYTES)
            + CHECKSUM_BYTES
    }

    /// The byte format of the module documentation. Errors for a String parameter longer
    /// than [`MAX_STRING_BYTES`] (which `fmi2SetString` does not let in).
    pub fn to_bytes(&self) -> Result<Vec<u8>> {
        let mut out = Vec::with_capacity(self.byte_len());
        out.extend_from_slice(&MAGIC);
        out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        out.extend_from_slice(&self.fingerprint.to_le_bytes());
        out.push(self.machine.code());
        out.push(u8::from(self.snapshot.is_some()));
        out.extend_from_slice(&self.last_successful_time.to_le_bytes());
        for v in self.inputs.force.iter().chain([&self.inputs.wind_speed]) {
            out.extend_from_slice(&v.to_le_bytes());
        }
        out.extend_from_slice(&self.experiment.start_time.to_le_bytes());
        out.push(u8::from(self.experiment.stop_time.is_some()));
        out.extend_from_slice(&self.experiment.stop_time.unwrap_or(0.0).to_le_bytes());
        let count = u32::try_from(Parameters::variables().count()).expect("a few parameters");
        out.extend_from_slice(&count.to_le_bytes());
        for (info, value, set) in self.parameters.iter() {
            out.extend_from_slice(&info.value_reference.to_le_bytes());
            match value {
                FmuValue::Real(x) => {
                    out.push(REAL);
                    out.push(u8::from(set));
                    out.extend_from_slice(&x.to_le_bytes());
                }
                FmuValue::Integer(i) => {
                    out.push(INTEGER);
                    out.push(u8::from(set));
                    out.extend_from_slice(&i.to_le_bytes());
                }
                FmuValue::String(s) => {
                    if s.len() > MAX_STRING_BYTES {
                        return Err(Error::invalid(
                            format!("FMU parameter {}", info.name),
                            format!("a text of {} bytes", s.len()),
                            format!("is longer than {MAX_STRING_BYTES} bytes"),
                        ));
                    }
                    out.push(STRING);
                    out.push(u8::from(set));
                    let len = u32::try_from(s.len()).expect("bounded above");
                    out.extend_from_slice(&len.to_le_bytes());
                    out.extend_from_slice(s.as_bytes());
                }
            }
        }
        if let Some(s) = &self.snapshot {
            out.extend_from_slice(&s.to_bytes());
        }
        let checksum = crate::fingerprint::of_bytes(&out);
        out.extend_from_slice(&checksum.to_le_bytes());
        debug_assert_eq!(out.len(), self.byte_len());
        Ok(out)
    }

    /// Reads [`FmuState::to_bytes`], checking everything the bytes alone can tell: the magic,
    /// the version, the checksum, each flag, length and type, finite values where the
    /// format says so, the experiment's rules, and the parameters' value references and
    /// types against modelDescription.xml. Whether the parameters still resolve to the
    /// saved problem is [`FmuState::check_problem`]'s question.
    pub fn from_bytes(bytes: &[u8]) -> Result<FmuState> {
        if bytes.len() < 8 {
            return Err(refuse(
                format!("{} bytes", bytes.len()),
                "is truncated: shorter than its magic and version",
            ));
        }
        if bytes[..4] != MAGIC {
            return Err(refuse(
                format!("{:?}", &bytes[..4]),
                "does not start with SDFS: not a SlowDrift state",
            ));
        }
        let version = u32::from_le_bytes(bytes[4..8].try_into().expect("4 bytes"));
        if version != FORMAT_VERSION {
            return Err(refuse(
                format!("format version {version}"),
                &format!("is not this library's format version {FORMAT_VERSION}"),
            ));
        }
        if bytes.len() < FIXED_BYTES + CHECKSUM_BYTES {
            return Err(refuse(
                format!("{} bytes", bytes.len()),
                &format!(
                    "is truncated: shorter than its fixed fields and checksum ({} bytes)",
                    FIXED_BYTES + CHECKSUM_BYTES
                ),
            ));
        }
        let (body, checksum) = bytes.split_at(bytes.len() - CHECKSUM_BYTES);
        let saved = u64::from_le_bytes(checksum.try_into().expect("8 bytes"));
        let computed = crate::fingerprint::of_bytes(body);
        if saved != computed {
            return Err(refuse(
                format!("checksum {saved:016x}"),
                &format!(
                    "does not match its {} bytes (checksum {computed:016x}): the state was \
                     altered, truncated or extended",
                    bytes.len()
                ),
            ));
        }
        let mut r = Reader { bytes: body, at: 8 };
        let fingerprint = r.u64("fingerprint")?;
        let code = r.u8("instance state")?;
        let machine = MachineState::from_code(code)
            .ok_or_else(|| refuse(format!("instance state code {code}"), "is unknown"))?;
        let has_snapshot = r.flag("snapshot flag")?;
        let last_successful_time = r.finite("last successful time")?;
        let force = [
            r.finite("input Fx_ext")?,
            r.finite("input Fy_ext")?,
            r.finite("input Mz_ext")?,
        ];
        let wind_at = r.at;
        let wind_speed = r.finite("input windVelocity_ext")?;
        if wind_speed < 0.0 {
            return Err(refuse(
                format!("input windVelocity_ext = {wind_speed} at byte {wind_at}"),
                "must be at least 0 m/s",
            ));
        }
        let inputs = Held { force, wind_speed };
        let start_time = r.finite("startTime")?;
        let has_stop = r.flag("stop time flag")?;
        let stop_at = r.at;
        let stop_bits = r.u64("stopTime")?;
        let stop_time = if has_stop {
            Some(f64::from_bits(stop_bits))
        } else if stop_bits != 0 {
            return Err(refuse(
                format!("stopTime bits {stop_bits:016x} at byte {stop_at}"),
                "must be 0 when the stop time flag is 0",
            ));
        } else {
            None
        };
        let experiment = Experiment::new(start_time, stop_time)
            .map_err(|e| refuse("its experiment".to_string(), &e.to_string()))?;
        let parameters = r.parameters()?;
        let snapshot_at = r.at;
        let snapshot =
            if has_snapshot {
                let bytes = r.take(Snapshot::BYTES, "snapshot")?;
                Some(Snapshot::from_bytes(bytes).map_err(|e| {
                    refuse(format!("snapshot at byte {snapshot_at}"), &e.to_string())
                })?)
            } else {
                None
            };
        if r.at != body.len() {
            return Err(refuse(
                format!("{} bytes", bytes.len()),
                &format!(
                    "has {} bytes between its last field (ending at byte {}) and its checksum",
                    body.len() - r.at,
                    r.at
                ),
            ));
        }
        let state = FmuState {
            fingerprint,
            parameters,
            experiment,
            machine,
            last_successful_time,
            inputs,
            snapshot,
        };
        state.check_consistent(snapshot_at)?;
        Ok(state)
    }

    /// Refuses fields that no instance can hold together (each readable alone): a snapshot
    /// in an instance that was not initialised, or none in one that was; a snapshot time
    /// before the start time, past the stop time, or where a double no longer resolves its
    /// step; a snapshot step other than the `stepSize` the master set; a last successful
    /// time before the start time or beyond the instance's time (its snapshot's, else the
    /// start time). `snapshot_at`: the snapshot's byte offset, for the messages.
    fn check_consistent(&self, snapshot_at: usize) -> Result<()> {
        let initialised = matches!(
            self.machine,
            MachineState::StepComplete | MachineState::StepFailed | MachineState::Terminated
        );
        if initialised != self.snapshot.is_some() {
            return Err(refuse(
                format!(
                    "instance state {:?} {} a snapshot",
                    self.machine,
                    if initialised { "without" } else { "with" }
                ),
                "an instance has a snapshot once it is initialised (StepComplete, StepFailed, \
                 Terminated), and only then",
            ));
        }
        let experiment = &self.experiment;
        let start = experiment.start_time;
        let time = match &self.snapshot {
            Some(snapshot) => {
                let (t, h) = (snapshot.time(), snapshot.step());
                let at = |what: &str| format!("snapshot {what} at byte {snapshot_at}");
                if t < start {
                    return Err(refuse(
                        at(&format!("time {t} s")),
                        &format!("is before startTime = {start} s"),
                    ));
                }
                if let (true, Some(stop)) = (experiment.passes_stop(t), experiment.stop_time) {
                    return Err(refuse(
                        at(&format!("time {t} s")),
                        &format!("is past stopTime = {stop} s"),
                    ));
                }
                if !time_resolved(t, h) {
                    return Err(refuse(
                        at(&format!("time {t:e} s")),
                        &format!(
                            "is where a double no longer resolves its step of {h} s (beyond \
                             {:e} s)",
                            largest_resolved_time(h)
                        ),
                    ));
                }
                if let Some(FmuValue::Real(step_size)) = self.parameters.set_value(STEP_SIZE) {
                    if h != *step_size {
                        return Err(refuse(
                            at(&format!("step {h} s")),
                            &format!("is not the state's stepSize = {step_size} s"),
                        ));
                    }
                }
                t
            }
            None => start,
        };
        let last = self.last_successful_time;
        let field = format!("last successful time {last} s at byte {LAST_SUCCESSFUL_TIME_AT}");
        if last < start {
            return Err(refuse(field, &format!("is before startTime = {start} s")));
        }
        if last > time {
            return Err(refuse(
                field,
                &format!("is beyond the instance's time {time} s"),
            ));
        }
        Ok(())
    }

    /// Checks that `problem`, built now from this state's parameters and experiment on
    /// `base`, is the one the state was saved with; `problem` is `Err` when it could not be
    /// built (a file that cannot be read now). The error names `base`.
    pub fn check_problem(&self, base: &Base, problem: Result<Problem>) -> Result<Problem> {
        let saved = self.fingerprint;
        let problem = problem.map_err(|e| {
            let why = match &e {
                Error::Io { .. } => "which cannot be read now",
                _ => "which no longer gives a valid configuration with the state's parameters",
            };
            refuse(
                format!("fingerprint {saved:016x}"),
                &format!("was saved with {base}, {why}: {e}"),
            )
        })?;
        let now = fingerprint(&problem);
        if now == saved {
            return Ok(problem);
        }
        let reason = match base {
            Base::Database(_) => format!(
                "was saved with {base} whose content at the save differs from what that file \
                 holds now (fingerprint {now:016x}); restore it where that file holds the data \
                 it was saved with"
            ),
            Base::Resources(_) => format!(
                "was saved with another configuration than what {base} gives with the state's \
                 parameters (fingerprint {now:016x}): the state comes from another FMU or \
                 another build of SlowDrift"
            ),
            Base::Embedded => format!(
                "was saved with another configuration than what {base} gives with the state's \
                 parameters (fingerprint {now:016x}): this instance has no resources/\
                 platform.toml, or the state comes from another build of SlowDrift"
            ),
        };
        Err(refuse(format!("fingerprint {saved:016x}"), &reason))
    }
}

/// The error for a state's bytes or content.
fn refuse(value: String, reason: &str) -> Error {
    Error::invalid("FMU state", value, reason)
}

/// Reads the fields of the state's bytes in order; every read names its field and offset.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8]> {
        let left = self.bytes.len() - self.at;
        if n > left {
            return Err(refuse(
                format!("{what} at byte {}", self.at),
                &format!("needs {n} bytes but only {left} are left before the checksum"),
            ));
        }
        let field = &self.bytes[self.at..self.at + n];
        self.at += n;
        Ok(field)
    }

    fn array<const N: usize>(&mut self, what: &str) -> Result<[u8; N]> {
        Ok(self.take(N, what)?.try_into().expect("N bytes"))
    }

    fn u8(&mut self, what: &str) -> Result<u8> {
        Ok(self.array::<1>(what)?[0])
    }

    fn u32(&mut self, what: &str) -> Result<u32> {
        Ok(u32::from_le_bytes(self.array(what)?))
    }

    fn u64(&mut self, what: &str) -> Result<u64> {
        Ok(u64::from_le_bytes(self.array(what)?))
    }

    fn flag(&mut self, what: &str) -> Result<bool> {
        let at = self.at;
        match self.u8(what)? {
            0 => Ok(false),
            1 => Ok(true),
            other => Err(refuse(
                format!("{what} = {other} at byte {at}"),
                "must be 0 or 1",
            )),
        }
    }

    fn finite(&mut self, what: &str) -> Result<f64> {
        let at = self.at;
        let x = f64::from_le_bytes(self.array(what)?);
        if x.is_finite() {
            Ok(x)
        } else {
            Err(refuse(
                format!("{what} = {x} at byte {at}"),
                "must be a finite number",
            ))
        }
    }

    /// The parameters, checked against modelDescription.xml's.
    fn parameters(&mut self) -> Result<Parameters> {
        let expected = Parameters::variables().count();
        let at = self.at;
        let count = self.u32("number of parameters")?;
        if usize::try_from(count).ok() != Some(expected) {
            return Err(refuse(
                format!("{count} parameters at byte {at}"),
                &format!("must be this FMU's {expected}: the state comes from another FMU"),
            ));
        }
        let mut parameters = Parameters::default();
        for info in Parameters::variables() {
            let name = info.name;
            let at = self.at;
            let vr = self.u32(&format!("value reference of {name}"))?;
            if vr != info.value_reference {
                return Err(refuse(
                    format!("value reference {vr} at byte {at}"),
                    &format!(
                        "must be {name}'s {}: the state comes from another FMU",
                        info.value_reference
                    ),
                ));
            }
            let at = self.at;
            let tag = self.u8(&format!("type of {name}"))?;
            let wanted = match info.var_type {
                VariableType::Real => REAL,
                VariableType::String => STRING,
                _ => INTEGER,
            };
            if tag != wanted {
                return Err(refuse(
                    format!("type byte {tag} of {name} at byte {at}"),
                    &format!("must be {wanted} ({})", char::from(wanted)),
                ));
            }
            let set = self.flag(&format!("set flag of {name}"))?;
            let value = match tag {
                REAL => FmuValue::Real(self.finite(name)?),
                INTEGER => FmuValue::Integer(i32::from_le_bytes(self.array(name)?)),
                _ => FmuValue::String(self.text(name)?),
            };
            assert!(parameters.set(name, value), "the type was checked");
            if !set {
                parameters.unset(name);
            }
        }
        Ok(parameters)
    }

    /// A length-prefixed UTF-8 text: the length is bounded before anything is allocated.
    fn text(&mut self, name: &str) -> Result<String> {
        let at = self.at;
        let len = self.u32(&format!("length of {name}"))?;
        let len = usize::try_from(len)
            .ok()
            .filter(|&n| n <= MAX_STRING_BYTES)
            .ok_or_else(|| {
                refuse(
                    format!("length {len} of {name} at byte {at}"),
                    &format!("is more than {MAX_STRING_BYTES} bytes"),
                )
            })?;
        let at = self.at;
        let raw = self.take(len, name)?;
        let text = std::str::from_utf8(raw).map_err(|e| {
            refuse(
                format!("{name} at byte {at}"),
                &format!("is not UTF-8: {e}"),
            )
        })?;
        if text.contains('\0') {
            return Err(refuse(
                format!("{name} at byte {at}"),
                "contains a NUL character, which no C string can",
            ));
        }
        Ok(text.to_string())
    }
}

/// The [`crate::fingerprint`] of the problem: any change to anything that determines the
/// records (sea, seed, platform, drift table, run) changes it. Where the configuration came
/// from (embedded, resources, a file at any path) does not enter, only its content, so a
/// state moves between processes that unpacked the FMU in different places.
pub fn fingerprint(problem: &Problem) -> u64 {
    crate::fingerprint::fingerprint(problem)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::resolve;
    use crate::scenario::default::default_scenario;

    /// A snapshot's bytes (module doc of [`Snapshot::to_bytes`]): time origin + count step,
    /// a state within the bounds, an external force.
    fn snapshot_bytes(origin: f64, count: u64, step: f64) -> [u8; Snapshot::BYTES] {
        let words = [origin.to_bits(), count, step.to_bits()]
            .into_iter()
            .chain([1.5, -2.0, 0.1, 0.25, -0.5, 0.01, 3e6, -4e6, 5e9].map(f64::to_bits));
        let mut out = [0u8; Snapshot::BYTES];
        for (chunk, word) in out.chunks_exact_mut(8).zip(words) {
            chunk.copy_from_slice(&word.to_le_bytes());
        }
        out
    }

    /// Offset of the snapshot in the bytes of a state with one.
    fn snapshot_offset(bytes: &[u8]) -> usize {
        bytes.len() - CHECKSUM_BYTES - Snapshot::BYTES
    }

    /// A state at t = 12.5 s (-3 + 31 x 0.5), its last successful time, from a start at -3 s
    /// to a stop at 1e4 s; with a snapshot, initialised, else in initialisation mode.
    fn state(snapshot: bool) -> FmuState {
        let mut parameters = Parameters::default();
        assert!(parameters.set("Hs", FmuValue::Real(5.25)));
        assert!(parameters.set("seed", FmuValue::Integer(-7)));
        assert!(parameters.set("dragModel", FmuValue::Integer(1)));
        assert!(parameters.set("hydroDatabase", FmuValue::String("/tmp/é x.toml".into())));
        FmuState {
            fingerprint: 0x0123_4567_89ab_cdef,
            parameters,
            experiment: Experiment::new(-3.0, Some(1e4)).unwrap(),
            machine: if snapshot {
                MachineState::StepComplete
            } else {
                MachineState::InitializationMode
            },
            last_successful_time: if snapshot { 12.5 } else { -3.0 },
            inputs: Held {
                force: [1.0, -2.0, 3e9],
                wind_speed: 7.5,
            },
            snapshot: snapshot
                .then(|| Snapshot::from_bytes(&snapshot_bytes(-3.0, 31, 0.5)).unwrap()),
        }
    }

    /// Recomputes the checksum after a change of `bytes`, so that a test reaches the check
    /// behind it.
    fn reseal(bytes: &mut [u8]) {
        let n = bytes.len() - CHECKSUM_BYTES;
        let sum = crate::fingerprint::of_bytes(&bytes[..n]);
        bytes[n..].copy_from_slice(&sum.to_le_bytes());
    }

    /// Offset of the first byte of parameter `name`'s value (after its reference, type and
    /// set flag).
    fn value_offset(s: &FmuState, name: &str) -> usize {
        let mut at = FIXED_BYTES;
        for (info, value, _) in s.parameters.iter() {
            at += 6;
            if info.name == name {
                return at;
            }
            at += match value {
                FmuValue::Real(_) => 8,
                FmuValue::Integer(_) => 4,
                FmuValue::String(t) => 4 + t.len(),
            };
        }
        panic!("no parameter {name}");
    }

    #[test]
    fn bytes_round_trip_with_and_without_snapshot_and_stop_time() {
        for with in [false, true] {
            for stop in [None, Some(20.0)] {
                let mut s = state(with);
                s.experiment = Experiment::new(-3.0, stop).unwrap();
                let bytes = s.to_bytes().unwrap();
                assert_eq!(bytes.len(), s.byte_len());
                assert_eq!(&bytes[..4], b"SDFS");
                assert_eq!(&bytes[4..8], &FORMAT_VERSION.to_le_bytes());
                let back = FmuState::from_bytes(&bytes).unwrap();
                assert_eq!(back, s);
                assert_eq!(back.parameters.hydro_database(), "/tmp/é x.toml");
            }
        }
    }

    /// The documented layout, field by field, at the documented offsets.
    #[test]
    fn layout_is_the_documented_one() {
        let s = state(true);
        let b = s.to_bytes().unwrap();
        let u64_at = |at: usize| u64::from_le_bytes(b[at..at + 8].try_into().unwrap());
        let f64_at = |at: usize| f64::from_bits(u64_at(at));
        assert_eq!(u64_at(8), s.fingerprint);
        assert_eq!((b[16], b[17]), (MachineState::StepComplete.code(), 1));
        assert_eq!(f64_at(18), 12.5);
        assert_eq!([f64_at(26), f64_at(34), f64_at(42)], s.inputs.force);
        assert_eq!(f64_at(50), s.inputs.wind_speed);
        assert_eq!((f64_at(58), b[66], f64_at(67)), (-3.0, 1, 1e4));
        let count = u32::from_le_bytes(b[75..79].try_into().unwrap()) as usize;
        assert_eq!(count, Parameters::variables().count());
        let first = Parameters::variables().next().unwrap();
        assert_eq!(
            u32::from_le_bytes(b[79..83].try_into().unwrap()),
            first.value_reference
        );
        let hs = value_offset(&s, "Hs");
        assert_eq!((b[hs - 2], b[hs - 1], f64_at(hs)), (REAL, 1, 5.25));
        // Tp is left to the configuration: its set flag is 0.
        assert_eq!(b[value_offset(&s, "Tp") - 1], 0);
        let seed = value_offset(&s, "seed");
        assert_eq!((b[seed - 2], b[seed - 1]), (INTEGER, 1));
        assert_eq!(
            i32::from_le_bytes(b[seed..seed + 4].try_into().unwrap()),
            -7
        );
        let db = value_offset(&s, "hydroDatabase");
        let len = u32::from_le_bytes(b[db..db + 4].try_into().unwrap()) as usize;
        assert_eq!((b[db - 2], len), (STRING, "/tmp/é x.toml".len()));
        assert_eq!(&b[db + 4..db + 4 + len], "/tmp/é x.toml".as_bytes());
        let n = b.len();
        assert_eq!(
            &b[n - 8 - Snapshot::BYTES..n - 8],
            &s.snapshot.as_ref().unwrap().to_bytes()
        );
        assert_eq!(u64_at(n - 8), crate::fingerprint::of_bytes(&b[..n - 8]));
    }

    #[test]
    fn damaged_bytes_are_refused_naming_the_field() {
        let s = state(true);
        let good = s.to_bytes().unwrap();
        let mut cases: Vec<(Vec<u8>, &str)> = vec![
            (good[..good.len() - 1].to_vec(), "checksum"),
            (good[..6].to_vec(), "truncated"),
            (good[..20].to_vec(), "truncated"),
            ([good.clone(), vec![0]].concat(), "checksum"),
            (Vec::new(), "truncated"),
        ];
        // Changed and resealed: the check behind the checksum answers.
        let mut patch = |at: usize, value: &[u8], needle: &'static str| {
            let mut b = good.clone();
            b[at..at + value.len()].copy_from_slice(value);
            if at >= 8 {
                reseal(&mut b);
            }
            cases.push((b, needle));
        };
        patch(0, b"X", "SDFS");
        patch(4, &(FORMAT_VERSION + 1).to_le_bytes(), "format version 5");
        patch(4, &2u32.to_le_bytes(), "format version 2");
        patch(16, &[99], "instance state code 99");
        patch(16, &[MachineState::Error.code()], "instance state code");
        patch(17, &[2], "snapshot flag = 2");
        patch(17, &[0], "between its last field");
        patch(18, &f64::NAN.to_le_bytes(), "last successful time");
        patch(34, &f64::INFINITY.to_le_bytes(), "input Fy_ext");
        patch(
            50,
            &(-1.0f64).to_le_bytes(),
            "input windVelocity_ext = -1 at byte 50",
        );
        patch(58, &f64::NAN.to_le_bytes(), "startTime");
        patch(66, &[0], "stopTime bits");
        patch(67, &(-4.0f64).to_le_bytes(), "stopTime");
        patch(75, &3u32.to_le_bytes(), "3 parameters");
        patch(79, &99_999u32.to_le_bytes(), "value reference 99999");
        let hs = value_offset(&s, "Hs");
        patch(hs - 2, b"I", "type byte");
        patch(hs - 1, &[2], "set flag of Hs = 2");
        patch(hs, &f64::NEG_INFINITY.to_le_bytes(), "Hs");
        let db = value_offset(&s, "hydroDatabase");
        patch(
            db,
            &u32::MAX.to_le_bytes(),
            "length 4294967295 of hydroDatabase",
        );
        patch(
            db,
            &(MAX_STRING_BYTES as u32 + 1).to_le_bytes(),
            "is more than 65536 bytes",
        );
        patch(db, &60_000u32.to_le_bytes(), "only");
        patch(db + 4, &[0xff], "is not UTF-8");
        patch(db + 4, &[0], "NUL");
        // The snapshot's fields, each finite (words: origin, count, step, X, Y, theta, X',
        // Y', theta', Fx, Fy, Mz), and consistent with the rest.
        let snap = snapshot_offset(&good);
        let word = |k: usize| snap + 8 * k;
        patch(word(0), &f64::NAN.to_le_bytes(), "snapshot origin = NaN");
        patch(word(2), &f64::INFINITY.to_le_bytes(), "snapshot step = inf");
        patch(word(2), &0f64.to_le_bytes(), "snapshot step = 0");
        patch(word(2), &(-0.5f64).to_le_bytes(), "snapshot step = -0.5");
        patch(
            word(10),
            &f64::INFINITY.to_le_bytes(),
            "external_force[1] = inf",
        );
        patch(word(11), &f64::NAN.to_le_bytes(), "external_force[2] = NaN");
        patch(
            word(1),
            &u64::MAX.to_le_bytes(),
            "is past stopTime = 10000 s",
        );
        patch(word(0), &(-30f64).to_le_bytes(), "time -14.5 s at byte");
        patch(
            16,
            &[MachineState::InitializationMode.code()],
            "with a snapshot",
        );
        patch(
            18,
            &13f64.to_le_bytes(),
            "beyond the instance's time 12.5 s",
        );
        patch(18, &(-4f64).to_le_bytes(), "is before startTime = -3 s");
        let without = state(false).to_bytes().unwrap();
        let mut b = without.clone();
        b[16] = MachineState::StepComplete.code();
        reseal(&mut b);
        cases.push((b, "StepComplete without a snapshot"));
        let mut b = without.clone();
        b[18..26].copy_from_slice(&0.5f64.to_le_bytes());
        reseal(&mut b);
        cases.push((b, "last successful time 0.5 s at byte 18"));
        for (bytes, needle) in cases {
            let message = FmuState::from_bytes(&bytes).unwrap_err().to_string();
            assert!(message.contains(needle), "{needle}: {message}");
            assert!(message.contains("FMU state"), "{message}");
        }
    }

    /// A snapshot time where a double no longer resolves the step (an open-ended run stops
    /// there), and a snapshot step other than the stepSize the master set, are refused.
    #[test]
    fn a_snapshot_must_suit_the_run() {
        let mut s = state(true);
        s.experiment = Experiment::new(-3.0, None).unwrap();
        // Doubles near 1e10 s are 1.9e-6 s apart: more than a millionth of a 0.5-s step.
        s.snapshot = Some(Snapshot::from_bytes(&snapshot_bytes(1e10, 0, 0.5)).unwrap());
        let message = FmuState::from_bytes(&s.to_bytes().unwrap())
            .unwrap_err()
            .to_string();
        assert!(message.contains("time 1e10 s at byte"), "{message}");
        assert!(message.contains("no longer resolves its step"), "{message}");
        let mut s = state(true);
        assert!(s.parameters.set("stepSize", FmuValue::Real(0.25)));
        let message = FmuState::from_bytes(&s.to_bytes().unwrap())
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("step 0.5 s at byte")
                && message.contains("is not the state's stepSize = 0.25 s"),
            "{message}"
        );
        assert!(s.parameters.set("stepSize", FmuValue::Real(0.5)));
        assert_eq!(FmuState::from_bytes(&s.to_bytes().unwrap()).unwrap(), s);
    }

    /// Every single bit flipped anywhere is refused, by the checksum or by the check in
    /// front of it; none panics.
    #[test]
    fn every_bit_flip_is_refused() {
        for with in [false, true] {
            let good = state(with).to_bytes().unwrap();
            for i in 0..good.len() * 8 {
                let mut b = good.clone();
                b[i / 8] ^= 1 << (i % 8);
                assert!(FmuState::from_bytes(&b).is_err(), "bit {i}");
            }
        }
    }

    #[test]
    fn a_string_longer_than_the_bound_is_not_written() {
        let mut s = state(false);
        assert!(s.parameters.set(
            "hydroDatabase",
            FmuValue::String("x".repeat(MAX_STRING_BYTES + 1))
        ));
        assert!(s
            .to_bytes()
            .unwrap_err()
            .to_string()
            .contains("hydroDatabase"));
        assert!(s.parameters.set(
            "hydroDatabase",
            FmuValue::String("x".repeat(MAX_STRING_BYTES))
        ));
        let bytes = s.to_bytes().unwrap();
        assert_eq!(FmuState::from_bytes(&bytes).unwrap(), s);
    }

    #[test]
    fn check_problem_names_the_base() {
        let problem = resolve(&default_scenario().unwrap()).unwrap();
        let mut s = state(false);
        s.fingerprint = fingerprint(&problem);
        assert_eq!(
            s.check_problem(&Base::Embedded, Ok(problem.clone()))
                .unwrap(),
            problem
        );
        let mut other = problem.clone();
        other.platform.mass = Some(2.0 * other.inertia().unwrap().mass);
        let base = Base::Database("/data/platform.toml");
        let message = s.check_problem(&base, Ok(other)).unwrap_err().to_string();
        assert!(
            message.contains("hydroDatabase = /data/platform.toml whose content"),
            "{message}"
        );
        let missing = Error::Io {
            path: "/data/platform.toml".into(),
            message: "No such file or directory".into(),
        };
        let message = s
            .check_problem(&base, Err(missing))
            .unwrap_err()
            .to_string();
        assert!(message.contains("cannot be read now"), "{message}");
        assert!(message.contains("No such file"), "{message}");
    }

    #[test]
    fn fingerprint_sees_every_change() {
        let a = resolve(&default_scenario().unwrap()).unwrap();
        assert_eq!(fingerprint(&a), fingerprint(&a.clone()));
        let mut b = a.clone();
        b.sea.seed += 1;
        let mut c = a.clone();
        c.platform.mass = Some(c.inertia().unwrap().mass * (1.0 + f64::EPSILON));
        let mut d = a.clone();
        d.run.duration += 1.0;
        for other in [b, c, d] {
            assert_ne!(fingerprint(&a), fingerprint(&other));
        }
    }
}
