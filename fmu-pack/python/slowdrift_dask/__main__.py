"""Command line: python -m slowdrift_dask --help."""

import argparse
import os
import shutil
import sys
from pathlib import Path

from .campaign import Settings, run_campaign
from .plan import CampaignError

# fmu-pack/python/slowdrift_dask/__main__.py -> the repository.
REPO = Path(__file__).resolve().parents[3]


def target_dir():
    target = os.environ.get("CARGO_TARGET_DIR")
    return Path(target) if target else REPO / "target"


def default_slowdrift():
    return (os.environ.get("SLOWDRIFT_CLI") or shutil.which("slowdrift")
            or str(target_dir() / "release" / "slowdrift"))


def default_fmu():
    return os.environ.get("SLOWDRIFT_FMU") or str(target_dir() / "fmu" / "SlowDrift.fmu")


def whole(least):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            value = None
        if value is None or value < least:
            raise argparse.ArgumentTypeError(f"must be a whole number of at least {least}")
        return value
    return parse


def seconds(text):
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is None or not (value >= 0.0 and value < float("inf")):
        raise argparse.ArgumentTypeError("must be a non-negative number of seconds")
    return value


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="python -m slowdrift_dask",
        description="slowdrift montecarlo on a Dask cluster: same case table, same result "
                    "files. Exit status 0: every run done; 1: some runs failed or are missing "
                    "(recorded in the files; start again to rerun them); 2: nothing ran "
                    "(bad arguments or case table).")
    p.add_argument("--config", help="base configuration TOML (default: the embedded/packed "
                   "default platform); must be at the same absolute path on the workers")
    p.add_argument("--cases", help="case table CSV (as slowdrift montecarlo)")
    p.add_argument("--seeds", type=whole(1), required=True)
    p.add_argument("--first-seed", type=whole(0), default=1)
    p.add_argument("--duration", type=seconds)
    p.add_argument("--transient", type=seconds)
    p.add_argument("--out", required=True, help="RESULTS.csv (runs in RESULTS.runs.csv)")
    p.add_argument("--backend", choices=("fmu", "cli"), default="fmu")
    p.add_argument("--scheduler", help="Dask scheduler address, e.g. tcp://host:8786 "
                   "(default: a local cluster)")
    p.add_argument("--workers", type=whole(1), help="local cluster: worker processes "
                   "(default: the number of cores)")
    p.add_argument("--retries", type=whole(0), default=2,
                   help="retries of a task that raised (default 2)")
    p.add_argument("--seeds-per-task", type=whole(1), help="consecutive seeds of a case per "
                   "Dask task (default: 1 with the FMU, 8 with the native tool, whose start-up "
                   "is paid per task)")
    p.add_argument("--fmu", default=default_fmu(), help="SlowDrift.fmu (default: "
                   "$SLOWDRIFT_FMU or the target directory's fmu/SlowDrift.fmu)")
    p.add_argument("--slowdrift", default=default_slowdrift(), help="the native tool "
                   "(default: $SLOWDRIFT_CLI, slowdrift on PATH, or target/release/slowdrift)")
    a = p.parse_args(argv)
    if a.duration is not None and a.duration == 0.0:
        p.error("argument --duration: must be a positive number of seconds")
    settings = Settings(seeds=a.seeds, out=a.out, config=a.config, cases=a.cases,
                        first_seed=a.first_seed, duration=a.duration, transient=a.transient,
                        backend=a.backend, fmu=a.fmu, slowdrift=a.slowdrift,
                        scheduler=a.scheduler, workers=a.workers, retries=a.retries,
                        seeds_per_task=a.seeds_per_task)
    try:
        return run_campaign(settings)
    except CampaignError as e:
        print(f"slowdrift_dask: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
