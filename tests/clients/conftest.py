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
