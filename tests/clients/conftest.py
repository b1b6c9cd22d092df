"""Shared fixtures of the Python client tests (run them with tests/clients/run_clients.sh)."""

import os
import shutil
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# The Dask package (fmu-pack/python/slowdrift_dask).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "fmu-pack", "python"))

import mooring_stiffness  # noqa: E402
import mooring_loop  # noqa: E402
import routes  # noqa: E402


@pytest.fixture(scope="session", autouse=True)
def native_tool():
    """The native CLI built (or found up to date) before any test runs, so that no test's
    build of it follows fmu-pack's (routes.native_tool)."""
    return routes.native_tool()


@pytest.fixture(scope="session")
def stiffness():
    """The mooring's measured static stiffness (mooring_stiffness.measure), computed once."""
    return mooring_stiffness.measure()


@pytest.fixture(scope="session")
def fmu():
    """Path of SlowDrift.fmu. Missing: skip, or fail when SLOWDRIFT_REQUIRE_FMU=1
    (run_clients.sh sets it after building the FMU, so a missing FMU never passes silently)."""
    path = mooring_loop.fmu_path()
    if not os.path.isfile(path):
        msg = f"{path} not found (build it with: cargo run --release -p fmu-pack)"
        if os.environ.get("SLOWDRIFT_REQUIRE_FMU") == "1":
            pytest.fail(msg)
        pytest.skip(msg)
    return path


@pytest.fixture(scope="session")
def mooring_fmu(fmu):
    """Path of Mooring.fmu, which fmu-pack writes beside SlowDrift.fmu: its absence fails."""
    path = mooring_loop.mooring_fmu_path()
    if not os.path.isfile(path):
        pytest.fail(f"{path} not found (build it with: cargo run --release -p fmu-pack)")
    return path


@pytest.fixture(scope="module")
def md(fmu):
    """The FMU's model description, read by fmpy."""
    from fmpy import read_model_description

    return read_model_description(fmu)


@pytest.fixture(scope="module")
def unzipdir(fmu):
    """The FMU extracted by fmpy into a temporary directory, removed after the module."""
    from fmpy import extract

    d = extract(fmu)
    yield d
    shutil.rmtree(d, ignore_errors=True)


@pytest.fixture(scope="session")
def glue_runs(fmu, stiffness):
    """The fmpy-glue loop for the FMU's default experiment (three hours at 1 s), once per
    session: "moored", SlowDrift (internal stiffness off) moored by MoorDyn's Python API in
    the Gauss-Seidel scheme (mooring_loop.run_loop); "linear", SlowDrift alone with its
    internal stiffness set to the lines' static stiffness diagonal (mooring_stiffness.py).
    Records as mooring_loop.COLUMNS, also written to target/client-tests/."""
    import time

    import numpy as np

    from mooring_loop import COLUMNS, LINES_ONLY, REPO, FmuBody, default_experiment, run_free, run_loop

    k = np.array(stiffness["K"])
    duration, dt = default_experiment(fmu)
    t0 = time.perf_counter()
    with FmuBody(fmu, LINES_ONLY, instance_name="moored") as body:
        moored = run_loop(body, duration, dt)
    t1 = time.perf_counter()
    with FmuBody(fmu, {"stiffnessSurge": k[0, 0], "stiffnessSway": k[1, 1], "stiffnessYaw": k[2, 2]},
                 instance_name="linear") as body:
        linear = run_free(body, duration, dt)
    t2 = time.perf_counter()
    out = os.path.join(REPO, "target", "client-tests")
    os.makedirs(out, exist_ok=True)
    for name, rec in (("mooring_loop_moored.csv", moored), ("mooring_loop_linear.csv", linear)):
        np.savetxt(os.path.join(out, name), rec, delimiter=",", header=",".join(COLUMNS), comments="")
    print(f"\nmooring loop: {duration:.0f} s in steps of {dt:g} s; moored run {t1 - t0:.1f} s, "
          f"linear run {t2 - t1:.1f} s (records in {out})")
    return {"moored": moored, "linear": linear, "K": k, "dt": dt}
