"""A user's platform as its own FMU (`fmu-pack --config FILE`), in fmpy and
libcosim: the FMU packed from tests/data/example.toml (a platform, sea and drift of its own).

1. Its model description shows the file: every start value is the file's value (read here
   from the TOML with Python's tomllib, degrees turned to radians), the model name is the
   file's stem, the DefaultExperiment is the file's run, the GUID is its own (not the
   default FMU's), and fmpy's validate_fmu finds nothing.
2. fmpy runs it with no start value set, and with every start value written back
   (apply_default_start_values, as a master that shows and writes back start values does):
   both equal, bit for bit, the native CLI run of the same file (`slowdrift simulate
   --config example.toml`, the independent route).
3. libcosim runs it with no initial value: the same run.
4. Its FMI 3.0 twin (fmi3/example.fmu beside it): fmpy validates it; its instantiation token
   is the FMI 2.0 FMU's GUID and its start values the same; fmpy runs it with no start value
   set: the same native run, bit for bit.
"""

import csv
import math
import os
import shutil
import subprocess
import sys
import tomllib

import numpy as np
import pytest

from mooring_loop import REPO
from routes import OUTPUTS, native_tool

EXAMPLE = os.path.join(REPO, "tests", "data", "example.toml")
STOP = 600  # s of the runs compared
STEP_NS = 1_000_000_000


@pytest.fixture(scope="module")
def user_fmu(tmp_path_factory, fmu):
    """example.toml packed by fmu-pack: $SLOWDRIFT_USER_FMU when set (tests/run_all.sh packs
    it right after the default FMU, before `cargo test` rebuilds the library's file with
    other features), else packed here."""
    given = os.environ.get("SLOWDRIFT_USER_FMU")
    if given:
        assert os.path.isfile(given), f"SLOWDRIFT_USER_FMU={given} is not a file"
        return given
    out = tmp_path_factory.mktemp("user-fmu") / "example.fmu"
    cargo = shutil.which("cargo") or "cargo"
    subprocess.run([cargo, "run", "--release", "--quiet", "-p", "fmu-pack", "--",
                    "--config", EXAMPLE, "--out", str(out)],
                   cwd=REPO, check=True, stdout=subprocess.DEVNULL)
    return str(out)


@pytest.fixture(scope="module")
def native(tmp_path_factory):
    """The CLI's run of example.toml: (time, outputs in the order of routes.OUTPUTS)."""
    out = tmp_path_factory.mktemp("user-native") / "example.csv"
    subprocess.run([native_tool(), "simulate", "--config", EXAMPLE, "--out", str(out)],
                   cwd=REPO, check=True, stdout=subprocess.DEVNULL)
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][0] == "time_s" and len(rows[0]) == 1 + len(OUTPUTS), rows[0]
    data = np.array([[float(v) for v in row] for row in rows[1:STOP + 2]])
    return data[:, 0], data[:, 1:]


def test_the_model_description_shows_the_file(user_fmu, fmu):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    with open(EXAMPLE, "rb") as f:
        toml = tomllib.load(f)
    md = read_model_description(user_fmu)
    start = {v.name: v.start for v in md.modelVariables if v.causality == "parameter"}
    sea, current, platform = toml["sea"], toml["current"], toml["platform"]
    expected = {
        "Hs": sea["hs"], "Tp": sea["tp"], "gamma": sea["gamma"],
        "waveDirection": math.radians(sea["direction_deg"]), "spreadingExponent": 0.0,
        "currentSpeed": current["speed"], "currentDirection": math.radians(current["direction_deg"]),
        "cd": toml["model"]["cd"], "stiffnessSurge": platform["stiffness"][0][0],
        "stiffnessSway": platform["stiffness"][1][1], "stiffnessYaw": platform["stiffness"][2][2],
        "stepSize": toml["run"]["time_step"], "seed": sea["seed"], "nDirections": 1,
        "dragModel": 2,  # combined, the file's drag
        "driftDamping": 2,  # aranha, the file's
    }
    for name, value in expected.items():
        assert float(start[name]) == float(value), (name, start[name], value)
    assert start["hydroDatabase"] == ""
    assert md.modelName == "example"
    assert float(md.defaultExperiment.stopTime) == toml["run"]["duration"]
    assert md.guid != read_model_description(fmu).guid
    assert validate_fmu(user_fmu) == []


@pytest.mark.parametrize("write_back", [False, True])
def test_fmpy_runs_the_file(user_fmu, native, write_back):
    from fmpy import simulate_fmu

    res = simulate_fmu(user_fmu, start_time=0.0, stop_time=float(STOP), output_interval=1.0,
                       output=list(OUTPUTS), apply_default_start_values=write_back)
    t_native, y_native = native
    assert np.array_equal(res["time"], t_native)
    for j, name in enumerate(OUTPUTS):
        assert np.array_equal(res[name], y_native[:, j]), name
    # The file's oblique sea (30 deg) moves sway and yaw too.
    assert np.all(np.max(np.abs(y_native[:, :3]), axis=0) > 0.0)


def test_libcosim_runs_the_file(user_fmu, native):
    """libcosim with no initial value set; its time series from step 1 (libcosimpy drops
    step 0, test_libcosim.py)."""
    script = f"""
import sys
import numpy as np
from libcosimpy.CosimEnums import CosimVariableType
from libcosimpy.CosimExecution import CosimExecution
from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
from libcosimpy.CosimObserver import CosimObserver
from libcosimpy.CosimSlave import CosimLocalSlave
log_output_level(CosimLogLevel.WARNING)
ex = CosimExecution.from_step_size(step_size={STEP_NS})
slave = CosimLocalSlave(fmu_path=sys.argv[1], instance_name="user")
index = ex.add_local_slave(local_slave=slave)
assert index >= 0
vr = {{v.name.decode(): v.reference for v in ex.slave_variables(index)}}
series = CosimObserver.create_time_series(buffer_size={STOP + 1})
assert ex.add_observer(observer=series)
for name in ("X", "Y", "theta"):
    assert series.start_time_series(index, vr[name], CosimVariableType.REAL)
assert ex.simulate_until(target_time={STOP} * {STEP_NS})
rows = []
for name in ("X", "Y", "theta"):
    _t, numbers, values = series.time_series_real_samples(index, vr[name], from_step=1,
                                                         sample_count={STOP})
    assert list(numbers) == list(range(1, {STOP} + 1))
    rows.append([v.hex() for v in values])
print("ROWS\\n" + "\\n".join(",".join(r) for r in rows), flush=True)
"""
    # In a process of its own: libcosimpy keeps state per process (test_libcosim.py).
    run = subprocess.run([sys.executable, "-c", script, user_fmu], capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    lines = run.stdout.split("ROWS\n", 1)[1].splitlines()[:3]
    got = np.array([[float.fromhex(v) for v in line.split(",")] for line in lines]).T
    _t, y_native = native
    assert np.array_equal(got, y_native[1:, :3])


def test_the_fmi3_twin_runs_the_file(user_fmu, native):
    from fmpy import read_model_description, simulate_fmu
    from fmpy.validation import validate_fmu

    twin = os.path.join(os.path.dirname(user_fmu), "fmi3", os.path.basename(user_fmu))
    assert validate_fmu(twin) == []
    md2, md3 = read_model_description(user_fmu), read_model_description(twin)
    assert md3.fmiVersion == "3.0" and md3.guid == md2.guid
    start2 = {v.name: v.start for v in md2.modelVariables if v.causality == "parameter"}
    start3 = {v.name: v.start for v in md3.modelVariables if v.causality == "parameter"}
    assert start3 == start2
    res = simulate_fmu(twin, start_time=0.0, stop_time=float(STOP), output_interval=1.0,
                       output=list(OUTPUTS))
    t_native, y_native = native
    assert np.array_equal(res["time"], t_native)
    for j, name in enumerate(OUTPUTS):
        assert np.array_equal(res[name], y_native[:, j]), name
