"""A Monte Carlo campaign on a Dask cluster: the client side.

The cases come from the native tool (`plan.read_cases`), the runs already in the per-run
file are skipped (resume), the others are submitted as Dask tasks of a few consecutive
seeds of one case (`worker.run_task`; one seed per task with the FMU), and each result is
appended to RESULTS.runs.csv and flushed as its task completes, in whatever order they
finish. At the end the summary RESULTS.csv is recomputed from the per-run file, exactly as
`slowdrift montecarlo` does. A run whose task is lost for good (the scheduler gave up after
its workers died `allowed-failures` times, or it raised on every retry) is recorded as
failed with the reason, so nothing is silently missing: the summary's seeds_done /
seeds_requested and the exit status say so, and a restart runs it again."""

import os
import sys
import tempfile
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

from .plan import CampaignError, case_arguments, read_cases
from .runs_file import RunRow, RunsFileLocked, format_row, lock, open_runs, parse
from .summary import CaseSummary, print_summary, write_summary

# The FMU's seed parameter is an FMI Integer (32-bit signed).
FMU_MAX_SEED = 2**31 - 1


@dataclass
class Settings:
    seeds: int
    out: str
    config: str = None
    cases: str = None
    first_seed: int = 1
    duration: float = None
    transient: float = None
    # "fmu" (SlowDrift.fmu through fmpy) or "cli" (the native tool on the workers).
    backend: str = "fmu"
    fmu: str = None
    slowdrift: str = "slowdrift"
    # Dask: a scheduler address, else a local cluster of `workers` processes.
    scheduler: str = None
    workers: int = None
    # Retries of a task that raised (a worker that dies is handled by the scheduler).
    retries: int = 2
    # Consecutive seeds of a case per task; None: 1 with the FMU (its instance is reused,
    # a run has no start-up cost), 8 with the native tool (whose start-up is paid per task).
    seeds_per_task: int = None


def runs_path(out):
    """RESULTS.csv -> RESULTS.runs.csv, next to it (as the native tool)."""
    p = Path(out)
    return str(p.with_name(p.stem + ".runs.csv"))


def check_fingerprints(cases, done, path):
    for case in cases:
        other = next((r for r in done if r.case == case.name and r.ok
                      and r.fingerprint != case.fingerprint), None)
        if other is not None:
            raise CampaignError(
                f"{path}: case '{case.name}' was run with another configuration or transient "
                f"(fingerprint {other.fingerprint}, now {case.fingerprint}); give another "
                "--out or remove the file")


def _read(path):
    with open(path, "rb") as f:
        return f.read()


def _upload_package(client, directory):
    """Sends this package to every worker (also later ones) as a zip on their sys.path, so
    the workers need only dask, distributed and fmpy."""
    import zipfile

    package = Path(__file__).resolve().parent
    archive = os.path.join(directory, "slowdrift_dask.zip")
    with zipfile.ZipFile(archive, "w") as z:
        for source in sorted(package.glob("*.py")):
            z.write(source, f"{package.name}/{source.name}")
    client.upload_file(archive)


def _plugin(campaign, settings, arguments):
    from .worker import CampaignPlugin

    if settings.backend == "fmu":
        return CampaignPlugin(campaign, "fmu", {"SlowDrift.fmu": _read(settings.fmu)})
    files = {"slowdrift": _read(settings.slowdrift)}
    if settings.cases is not None:
        files["cases.csv"] = _read(settings.cases)
    return CampaignPlugin(campaign, "cli", files, arguments)


def _check_backend(settings, cases, seeds):
    if settings.backend == "cli":
        return
    if settings.backend != "fmu":
        raise CampaignError(f"--backend {settings.backend}: must be fmu or cli")
    if settings.fmu is None or not os.path.isfile(settings.fmu):
        raise CampaignError(f"--fmu {settings.fmu}: no such file (build it with: cargo run "
                            "--release -p fmu-pack)")
    for case in cases:
        if case.fmu_parameters is None:
            raise CampaignError(f"case '{case.name}': the FMU cannot run it: "
                                f"{case.fmu_unavailable}; use --backend cli")
    if seeds.stop - 1 > FMU_MAX_SEED:
        raise CampaignError(f"seed {seeds.stop - 1}: the FMU's seed is a 32-bit Integer "
                            f"(at most {FMU_MAX_SEED}); use --backend cli")


def tasks(jobs, size):
    """Jobs (case, seed) grouped into (case, [consecutive seeds]) of at most `size`."""
    out = []
    for case, seed in jobs:
        if out and out[-1][0] is case and out[-1][1][-1] == seed - 1 and len(out[-1][1]) < size:
            out[-1][1].append(seed)
        else:
            out.append((case, [seed]))
    return out


def _client(settings):
    """(client, what to close afterwards)."""
    from distributed import Client, LocalCluster

    if settings.scheduler is not None:
        client = Client(settings.scheduler)
        return client, [client]
    cluster = LocalCluster(n_workers=settings.workers or os.cpu_count() or 1,
                           threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    return client, [client, cluster]


class Progress:
    """A line on stderr every 10 s and at the end: runs done/total, failures, rate."""

    def __init__(self, total):
        self.total, self.done, self.failed = total, 0, 0
        self.started = self.shown = time.monotonic()

    def show(self, last=False):
        now = time.monotonic()
        if not last and now - self.shown < 10.0:
            return
        self.shown = now
        elapsed = max(now - self.started, 1e-9)
        failed = f" ({self.failed} failed)" if self.failed else ""
        print(f"slowdrift_dask: {self.done}/{self.total} runs{failed}, "
              f"{self.done / elapsed:.2f} runs/s, {elapsed:.0f} s elapsed", file=sys.stderr)


def run_campaign(settings, client=None, campaign=None):
    """Runs the campaign and writes both files; returns the exit status: 0 when every
    requested run succeeded, 1 otherwise. CampaignError when it cannot start. `client`: an
    existing Dask client (else one is made from `settings` and closed at the end);
    `campaign`: the id in the task keys, plugin and events (default: random)."""
    if settings.seeds < 1:
        raise CampaignError(f"--seeds {settings.seeds}: must be a whole number of at least 1")
    if settings.first_seed < 0:
        raise CampaignError(f"--first-seed {settings.first_seed}: must not be negative")
    seeds = range(settings.first_seed, settings.first_seed + settings.seeds)
    config = None if settings.config is None else os.path.abspath(settings.config)
    arguments = case_arguments(config, settings.cases, settings.duration, settings.transient)
    cases = read_cases(settings.slowdrift, arguments)
    _check_backend(settings, cases, seeds)
    path = runs_path(settings.out)
    try:
        held = lock(path)
    except RunsFileLocked as e:
        raise CampaignError(str(e)) from None
    try:
        return _run_locked(settings, arguments, cases, seeds, path, client, campaign)
    finally:
        held.release()


def _run_locked(settings, arguments, cases, seeds, path, client, campaign):
    """`run_campaign` once the runs file `path` is locked."""
    done, runs = open_runs(path)
    try:
        check_fingerprints(cases, done, path)
        ok = {(r.case, r.seed) for r in done if r.ok}
        jobs = [(case, seed) for case in cases for seed in seeds if (case.name, seed) not in ok]
        total = len(cases) * settings.seeds
        print(f"{len(cases)} case(s) x {settings.seeds} seeds ({seeds.start} to {seeds.stop - 1})"
              f" = {total} runs; {total - len(jobs)} already in {path}; {len(jobs)} to run on "
              f"Dask ({settings.backend} backend)")
        for case in cases:
            print(f"  {case.name}: {case.steps} steps of {case.time_step} s, transient "
                  f"{case.transient:.1f} s")
        if jobs:
            _run_jobs(settings, arguments, jobs, runs, client,
                      campaign or uuid.uuid4().hex[:12])
    finally:
        runs.close()
    with open(path) as f:
        finished = parse(f.read(), path)
    summaries = [CaseSummary(case, finished, seeds) for case in cases]
    write_summary(settings.out, summaries, settings.seeds)
    print_summary(summaries, settings.seeds)
    print(f"summary written to {settings.out}, runs to {path}")
    failed = sum(s.failed for s in summaries)
    missing = sum(settings.seeds - s.done() - s.failed for s in summaries)
    if failed or missing:
        print(f"slowdrift_dask: {failed} of {total} runs failed, {missing} missing (their "
              f"errors are in {path} and the summary)", file=sys.stderr)
        return 1
    return 0


def _run_jobs(settings, arguments, jobs, runs, client, campaign):
    from distributed import as_completed

    from .worker import plugin_name, run_task

    owned = []
    if client is None:
        client, owned = _client(settings)
    try:
        with tempfile.TemporaryDirectory() as directory:
            _upload_package(client, directory)
        plugin = plugin_name(campaign)
        client.register_plugin(_plugin(campaign, settings, arguments))
        size = settings.seeds_per_task or (1 if settings.backend == "fmu" else 8)
        by_key, futures = {}, []
        for i, (case, seeds) in enumerate(tasks(jobs, size)):
            future = client.submit(run_task, plugin, case, seeds,
                                   key=f"slowdrift-{campaign}-{i}",
                                   retries=settings.retries, pure=False)
            by_key[future.key] = (case, seeds)
            futures.append(future)
        progress = Progress(len(jobs))
        for future in as_completed(futures):
            case, seeds = by_key[future.key]
            try:
                results = future.result()
            except Exception as e:  # noqa: BLE001 - every lost task is recorded
                lost = f"the run's task was lost: {type(e).__name__}: {e}"
                results = [(seed, "failed", lost) for seed in seeds]
            for seed, status, value in results:
                row = RunRow(case.name, seed, case.fingerprint)
                if status == "ok":
                    row.values = value
                else:
                    row.error = value
                    progress.failed += 1
                runs.write(format_row(row).encode("utf-8"))
                progress.done += 1
            runs.flush()
            future.release()
            progress.show()
        progress.show(last=True)
        client.unregister_worker_plugin(plugin)
    finally:
        for thing in owned:
            thing.close()
