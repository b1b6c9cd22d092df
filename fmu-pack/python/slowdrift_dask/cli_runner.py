"""Runs (case, seed) with the native tool: `slowdrift montecarlo ... --case NAME --seeds 1
--first-seed SEED --threads 1 --out DIR/run.csv` in a scratch directory, and reads the one
line of its per-run file. The line's fingerprint must be the campaign's: a worker whose
configuration file or tool differs from the client's is refused rather than mixed in."""

import os
import subprocess
import tempfile

from .errors import RunFailed
from .runs_file import RunsFileError, parse


class CliRunError(RuntimeError):
    """The tool did not produce a result (it could not start, or stopped without writing
    the run): an infrastructure failure that Dask retries."""


def run_cli(slowdrift, arguments, case, seed, scratch):
    """The 12 statistics of (case, seed); RunFailed with the tool's message when the run
    failed, CliRunError when there is no result."""
    with tempfile.TemporaryDirectory(dir=scratch) as d:
        out = os.path.join(d, "run.csv")
        command = [str(slowdrift), "montecarlo", *arguments, "--case", case.name,
                   "--seeds", "1", "--first-seed", str(seed), "--threads", "1", "--out", out]
        try:
            done = subprocess.run(command, capture_output=True, text=True)
        except OSError as e:
            raise CliRunError(f"cannot run '{slowdrift}': {e}") from None
        path = os.path.join(d, "run.runs.csv")
        try:
            with open(path) as f:
                runs = parse(f.read(), path)
        except (OSError, RunsFileError) as e:
            raise CliRunError(f"{' '.join(command)} exited with status {done.returncode} "
                              f"and no run ({e}): {done.stderr.strip()}") from None
        mine = [r for r in runs if r.case == case.name and r.seed == seed]
        if len(mine) != 1:
            raise CliRunError(f"{path}: expected the run of case '{case.name}' seed {seed}")
        row = mine[0]
        if row.fingerprint != case.fingerprint:
            raise RunFailed(f"the worker ran case '{case.name}' with fingerprint "
                            f"{row.fingerprint}, the client's is {case.fingerprint}: its "
                            "configuration file or slowdrift differs from the client's")
        if not row.ok:
            raise RunFailed(row.error)
        return row.values
