//! `fmi2SetReal` (inputs), `fmi2DoStep` and `fmi2GetReal` (outputs) allocate nothing in the
//! simulation loop, across the joins of the record stream too: the binary's counting allocator (`counting`) counts this thread's
//! allocations around the loop. (Debug logging is off: with `logAll`
//! on, every call formats a log line.)

use crate::counting::allocations;
use crate::fmu::*;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::fmi2Status;

#[test]
fn the_simulation_loop_does_not_allocate() {
    let fmu = Fmu::instantiate("loop", None, false);
    // No stop time: the run crosses the first join of the records (at the default block
    // duration, 16384 s).
    assert_eq!(fmu.setup(0.0, None), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2OK);
    let outputs = output_vrs();
    let mut values = vec![0.0; outputs.len()];
    let inputs = [vr::FX_EXT, vr::FY_EXT, vr::MZ_EXT];
    // The counter sees an allocation of this thread.
    let probe = allocations();
    drop(std::hint::black_box(vec![0u8; 16]));
    assert_eq!(allocations(), probe + 1);
    let before = allocations();
    let mut t = 0.0;
    for n in 0..500 {
        // Whole steps, communication steps that split into substeps, long steps past the
        // join.
        let h = match n {
            0..150 => 1.0,
            150..300 => 0.7,
            _ => 90.0,
        };
        let force = external(n);
        let status = unsafe {
            slowdrift::fmi2::exports::fmi2SetReal(fmu.c, inputs.as_ptr(), 3, force.as_ptr())
        };
        assert_eq!(status, fmi2Status::fmi2OK);
        assert_eq!(fmu.step(t, h), fmi2Status::fmi2OK);
        let status = unsafe {
            slowdrift::fmi2::exports::fmi2GetReal(
                fmu.c,
                outputs.as_ptr(),
                outputs.len(),
                values.as_mut_ptr(),
            )
        };
        assert_eq!(status, fmi2Status::fmi2OK);
        t += h;
    }
    let during = allocations() - before;
    assert!(t > 16384.0 + 1000.0, "past the first join: t = {t}");
    assert!(values.iter().all(|v| v.is_finite()));
    assert_eq!(
        during, 0,
        "allocations in 500 SetReal/DoStep/GetReal rounds"
    );
}
