"""A saved FMU state stands alone, through fmpy 0.3.32.

fmusim (Reference-FMUs) restores `--initial-fmu-state-file` right after fmi2Instantiate and
before it sets anything: fmi2DeSerializeFMUstate, fmi2SetFMUstate, fmi2FreeFMUstate, then
(with no --start-value) it samples the outputs, applies the inputs and steps, without
fmi2SetupExperiment or initialisation. fmusim is not packaged on PyPI or Debian, so these
tests make the same calls in the same order with fmpy's low-level FMU2Slave, and once more
through fmpy.simulate_fmu(fmu_state=bytes), which restores a serialized state in that order
too. The state comes from an instance with non-default parameters (tests/clients/routes.py's,
plus dragModel, driftDamping and a hydroDatabase file: a copy of tests/data/example.toml)
and a stop time, written to a file and read back as fmusim does.

1. The fresh instance continues bit for bit like the uninterrupted run, and its getters
   return the saved parameters.
2. The same through simulate_fmu(fmu_state=bytes, initialize=False).
3. After the hydroDatabase file changed, the state is refused with a message naming the
   file; the file restored, the same state restores the same instance. A deleted file is
   refused as unreadable.
"""

import os
import shutil
import numpy as np
import pytest

from mooring_loop import REPO
from routes import INPUTS, OUTPUTS, PARAMETERS, set_parameters

EXAMPLE_TOML = os.path.join(REPO, "tests", "data", "example.toml")
STOP = 1200.0
SAVE = 600  # steps of 1 s before the state is saved
# dragModel separate, driftDamping aranha (example.toml's drift table has no damping
# columns, so the start value, table, would not build), and the drag coefficients.
EXTRA = {"dragModel": 1, "driftDamping": 2, "cdSlow": 0.8, "cdFast": 0.5}
BEFORE = (3.0e4, -2.0e4, 1.0e7)  # N, N, N m: external force before the save
AFTER = (-1.0e4, 5.0e4, 0.0)  # and after


class Logged:
    """An FMU2Slave instantiated with a logger that keeps every message (the FMU passes the
    message as its printf format, every % doubled, and no further arguments)."""

    def __init__(self, md, unzipdir, name):
        from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

        self.messages = []

        def logger(env, instance, status, category, message):
            self.messages.append((status, category.decode(), message.decode().replace("%%", "%")))

        self._logger = fmi2CallbackLoggerTYPE(logger)  # kept alive with the instance
        callbacks = fmi2CallbackFunctions()
        callbacks.logger = self._logger
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                             modelIdentifier=md.coSimulation.modelIdentifier,
                             instanceName=name)
        self.fmu.instantiate(callbacks=callbacks, loggingOn=True)

    def errors(self):
        return [m for status, _, m in self.messages if status >= 3]

    def outputs(self):
        return np.array(self.fmu.getReal([self.vr[n] for n in OUTPUTS]))

    def steps(self, t0, n, force):
        """fmusim's loop: set the inputs, step, sample; the outputs after each step."""
        rec = np.empty((n, len(OUTPUTS)))
        inputs = [self.vr[name] for name in INPUTS]
        for k in range(n):
            self.fmu.setReal(inputs, list(force))
            self.fmu.doStep(currentCommunicationPoint=t0 + k, communicationStepSize=1.0)
            rec[k] = self.outputs()
        return rec

    def parameters(self, names):
        reals = [n for n in names if isinstance(names[n], float)]
        ints = [n for n in names if isinstance(names[n], int)]
        got = dict(zip(reals, self.fmu.getReal([self.vr[n] for n in reals])))
        got.update(zip(ints, self.fmu.getInteger([self.vr[n] for n in ints])))
        got["hydroDatabase"] = self.fmu.getString([self.vr["hydroDatabase"]])[0].decode()
        return got

    def restore_file(self, path):
        """fmusim's FMIRestoreFMUStateFromFile: read, deserialize, set, free."""
        with open(path, "rb") as f:
            data = f.read()
        state = self.fmu.deSerializeFMUstate(data)
        try:
            self.fmu.setFMUstate(state)
        finally:
            self.fmu.freeFMUstate(state)

    def close(self):
        self.fmu.freeInstance()


def bits(a):
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


@pytest.fixture
def saved(md, unzipdir, tmp_path):
    """Instance A on a copy of example.toml: its state after SAVE steps written to a file,
    its outputs at the save and the SAVE steps after it."""
    db = tmp_path / "platform 50%.toml"
    shutil.copy(EXAMPLE_TOML, db)
    a = Logged(md, unzipdir, "original")
    a.fmu.setupExperiment(startTime=0.0, stopTime=STOP)
    set_parameters(a.fmu, md, dict(PARAMETERS, **EXTRA))
    a.fmu.setString([a.vr["hydroDatabase"]], [str(db)])
    a.fmu.enterInitializationMode()
    a.fmu.exitInitializationMode()
    a.steps(0.0, SAVE, BEFORE)
    at_save = a.outputs()
    state = a.fmu.getFMUstate()
    state_file = tmp_path / "state.bin"
    state_file.write_bytes(a.fmu.serializeFMUstate(state))
    a.fmu.freeFMUstate(state)
    ahead = a.steps(float(SAVE), int(STOP) - SAVE, AFTER)
    a.fmu.terminate()
    a.close()
    return {"db": db, "file": state_file, "at_save": at_save, "ahead": ahead}


def test_state_file_restores_before_any_set(md, unzipdir, saved):
    b = Logged(md, unzipdir, "fresh")
    try:
        b.restore_file(saved["file"])
        assert b.errors() == []
        # fmusim samples first, then sets the inputs and steps.
        assert np.array_equal(bits(b.outputs()), bits(saved["at_save"]))
        continued = b.steps(float(SAVE), int(STOP) - SAVE, AFTER)
        expected = dict(PARAMETERS, **EXTRA, hydroDatabase=str(saved["db"]))
        assert b.parameters(expected) == expected
        b.fmu.terminate()
    finally:
        b.close()
    assert np.array_equal(bits(continued), bits(saved["ahead"]))
    # Not a trivial comparison: the platform moves in surge, sway and yaw.
    assert np.all(np.max(np.abs(saved["ahead"][:, :3]), axis=0) > 0.0)


def test_simulate_fmu_from_a_serialized_state(fmu, md, saved):
    from fmpy import simulate_fmu

    # One row per step: fmpy interpolates between rows as w0 v0 + (1 - w0) v1, which is not
    # exactly v for a constant v at every time (1115 s gives 50000.00000000001 between rows
    # at 600 s and 1200 s); at a row's own time it is v1 exactly.
    times = np.arange(SAVE, int(STOP) + 1, dtype=np.float64)
    signal = np.zeros(len(times), dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    signal["time"] = times
    for name, value in zip(INPUTS, AFTER):
        signal[name] = value
    res = simulate_fmu(fmu, start_time=float(SAVE), stop_time=STOP, output_interval=1.0,
                       fmu_state=saved["file"].read_bytes(), initialize=False,
                       input=signal, output=list(OUTPUTS), model_description=md)
    assert len(res) == int(STOP) - SAVE + 1
    assert np.array_equal(res["time"], np.arange(SAVE, int(STOP) + 1, dtype=np.float64))
    got = np.column_stack([res[n] for n in OUTPUTS])
    assert np.array_equal(bits(got[0]), bits(saved["at_save"]))
    assert np.array_equal(bits(got[1:]), bits(saved["ahead"]))


def test_a_changed_or_missing_database_refuses_the_state(md, unzipdir, saved):
    from fmpy.fmi1 import FMICallException

    db = saved["db"]
    original = db.read_text()
    heavier = original.replace("mass = 1.2e7 ", "mass = 1.3e7 ")
    assert heavier != original
    db.write_text(heavier)
    b = Logged(md, unzipdir, "changed")
    try:
        with pytest.raises(FMICallException, match="fmi2SetFMUstate"):
            b.restore_file(saved["file"])
        [message] = b.errors()
        assert f"saved with hydroDatabase = {db} whose content" in message, message
        assert "differs from what that file holds now" in message, message
        # The file as it was: the same instance restores the same state (from Error).
        db.write_text(original)
        b.restore_file(saved["file"])
        continued = b.steps(float(SAVE), 20, AFTER)
        assert np.array_equal(bits(continued), bits(saved["ahead"][:20]))
    finally:
        b.close()

    os.remove(db)
    c = Logged(md, unzipdir, "missing")
    try:
        with pytest.raises(FMICallException, match="fmi2SetFMUstate"):
            c.restore_file(saved["file"])
        [message] = c.errors()
        assert f"saved with hydroDatabase = {db}, which cannot be read now" in message, message
    finally:
        c.close()
