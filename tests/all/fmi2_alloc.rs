//! `fmi2SetReal` (inputs), `fmi2DoStep` and `fmi2GetReal` (outputs) allocate nothing in the
//! simulation loop: the binary's counting allocator (`counting`) counts this thread's
//! allocations around the loop. (Debug logging is off: with `logAll`
//! on, every call formats a log line.)

use crate::counting::allocations;
use crate::fmu::*;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::fmi2Status;

#[test]
fn the_simulation_loop_does_not_allocate() {
    let fmu = Fmu::instantiate("loop", None, false);
    assert_eq!(fmu.setup(0.0, Some(600.0)), fmi2Status::fmi2OK);
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
    for n in 0..300 {
        // Whole steps, then communication steps that split into substeps.
        let h = if n < 150 { 1.0 } else { 0.7 };
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
    assert!(values.iter().all(|v| v.is_finite()));
    assert_eq!(
        during, 0,
        "allocations in 300 SetReal/DoStep/GetReal rounds"
    );
}
