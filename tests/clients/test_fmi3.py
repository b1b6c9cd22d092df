"""SlowDrift's FMI 3.0 archive (target/fmu/fmi3/SlowDrift.fmu, which fmu-pack packs beside
the FMI 2.0 one: the same library, its fmi3* functions) in fmpy, against the FMI 2.0 FMU:

1. fmpy validates the archive (its FMI 3.0 schema and rules) and reads it as a
   co-simulation FMU whose states can be saved and serialized;
2. fmpy's simulate_fmu runs it for 3 hours at 1 s, with the parameters of the client tests
   and a ramped external force, with and without a stop time: every output equals the FMI
   2.0 FMU's run of the same call bit for bit;
3. through fmpy's FMU3Slave, a state saved at 1 h, serialized, deserialized and restored in a
   fresh instance continues as the saving instance does, bit for bit.
"""

import os

import numpy as np
import pytest

from routes import INPUTS, OUTPUTS, PARAMETERS

STOP = 3 * 3600.0


@pytest.fixture(scope="module")
def fmu3(fmu):
    path = os.path.join(os.path.dirname(fmu), "fmi3", "SlowDrift.fmu")
    if not os.path.isfile(path):
        pytest.fail(f"{path} not found (fmu-pack packs it: cargo run --release -p fmu-pack)")
    return path


def test_fmpy_validates_and_reads_the_fmi3_archive(fmu3):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(fmu3) == []
    md = read_model_description(fmu3)
    assert md.fmiVersion == "3.0"
    assert md.coSimulation is not None and md.modelExchange is None
    # fmpy keeps FMI 2.0's attribute names for FMI 3.0's canGetAndSetFMUState and
    # canSerializeFMUState.
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    names = {v.name for v in md.modelVariables}
    assert set(OUTPUTS) <= names and set(INPUTS) <= names


def ramp():
    signal = np.zeros(2, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    signal["time"] = [0.0, STOP]
    signal["Fx_ext"] = [0.0, 2.0e5]
    signal["Fy_ext"] = 1.0e5
    signal["Mz_ext"] = 5.0e7
    return signal


@pytest.mark.parametrize("set_stop_time", [True, False])
def test_fmi3_runs_are_the_fmi2_runs_bit_for_bit(fmu, fmu3, set_stop_time):
    from fmpy import simulate_fmu

    def run(path):
        return simulate_fmu(path, start_time=0.0, stop_time=STOP, output_interval=1.0,
                            start_values=dict(PARAMETERS), input=ramp(),
                            output=list(OUTPUTS), set_stop_time=set_stop_time)

    two, three = run(fmu), run(fmu3)
    assert len(three) == len(two) == int(STOP) + 1
    assert np.array_equal(three["time"], two["time"])
    for name in OUTPUTS:
        assert np.array_equal(three[name].view(np.uint64), two[name].view(np.uint64)), name
    assert np.max(np.abs(three["Y"])) > 0.0, "the oblique sea moves the platform sideways"


def test_fmi3_states_continue_in_a_fresh_instance(fmu3, tmp_path):
    from fmpy import extract, read_model_description
    from fmpy.fmi3 import FMU3Slave

    unzipdir = extract(fmu3, str(tmp_path / "fmi3-states"))
    md = read_model_description(unzipdir)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outputs = [vr[n] for n in OUTPUTS]

    def instance(name):
        slave = FMU3Slave(guid=md.guid, unzipDirectory=unzipdir,
                          modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        slave.instantiate()
        return slave

    a = instance("a")
    a.enterInitializationMode(startTime=0.0, stopTime=STOP)
    a.setFloat64([vr["waveDirection"], vr["Hs"]], [PARAMETERS["waveDirection"], PARAMETERS["Hs"]])
    a.exitInitializationMode()
    for n in range(3600):
        a.setFloat64([vr["Fx_ext"]], [1.0e5])
        a.doStep(currentCommunicationPoint=float(n), communicationStepSize=1.0)
    state = a.getFMUState()
    data = a.serializeFMUState(state)
    a.freeFMUState(state)
    b = instance("b")
    restored = b.deserializeFMUState(data)
    b.setFMUState(restored)
    b.freeFMUState(restored)
    assert np.array_equal(np.array(b.getFloat64(outputs)), np.array(a.getFloat64(outputs)))
    for n in range(3600, 4200):
        for s in (a, b):
            s.setFloat64([vr["Fx_ext"]], [1.0e5 + n])
            s.doStep(currentCommunicationPoint=float(n), communicationStepSize=1.0)
        assert np.array_equal(np.array(b.getFloat64(outputs)), np.array(a.getFloat64(outputs))), n
    for s in (a, b):
        s.terminate()
        s.freeInstance()
