"""Runs consecutive seeds of one case with the native tool: `slowdrift montecarlo ...
--case NAME --seeds N --first-seed SEED --threads 1 --out DIR/run.csv` in a scratch
directory, and reads its per-run file. Each line's fingerprint must be the campaign's: a
worker whose configuration file or tool differs from the client's is refused rather than
mixed in. Several seeds per call pay the tool's start-up (for the default platform, its
column solver: about 1 s) once."""

import os
import subprocess
import tempfile

from .runs_file import RunsFileError, parse


class CliRunError(RuntimeError):
    """The tool did not produce every result (it could not start, or stopped early): an
    infrastructure failure that Dask retries."""


def run_cli(slowdrift, arguments, case, seeds, scratch):
    """[(seed, "ok", 12 statistics) or (seed, "failed", message)] for the consecutive
    `seeds` of `case`."""
    with tempfile.TemporaryDirectory(dir=scratch) as d:
        out = os.path.join(d, "run.csv")
        command = [str(slowdrift), "montecarlo", *arguments, "--case", case.name,
                   "--seeds", str(len(seeds)), "--first-seed", str(seeds[0]),
                   "--threads", "1", "--out", out]
        try:
            done = subprocess.run(command, capture_output=True, text=True)
        except OSError as e:
            raise CliRunError(f"cannot run '{slowdrift}': {e}") from None
        path = os.path.join(d, "run.runs.csv")
        try:
            with open(path) as f:
                runs = {r.seed: r for r in parse(f.read(), path) if r.case == case.name}
        except (OSError, RunsFileError) as e:
            raise CliRunError(f"{' '.join(command)} exited with status {done.returncode} "
                              f"and no runs ({e}): {done.stderr.strip()}") from None
        missing = [s for s in seeds if s not in runs]
        if missing:
            raise CliRunError(f"{' '.join(command)} exited with status {done.returncode} "
                              f"without seeds {missing}: {done.stderr.strip()}")
        results = []
        for seed in seeds:
            row = runs[seed]
            if row.fingerprint != case.fingerprint:
                results.append((seed, "failed", (
                    f"the worker ran case '{case.name}' with fingerprint {row.fingerprint}, "
                    f"the client's is {case.fingerprint}: its configuration file or "
                    "slowdrift differs from the client's")))
            elif row.ok:
                results.append((seed, "ok", row.values))
            else:
                results.append((seed, "failed", row.error))
        return results
