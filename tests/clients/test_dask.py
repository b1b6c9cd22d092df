"""Monte Carlo on a Dask cluster: fmu-pack/python/slowdrift_dask on a
LocalCluster of 3 worker processes (one thread each), against the native
`slowdrift montecarlo` as the independent route.

The campaign: tests/data/example.toml (inline drift table, four columns with drag) for
1200 s at h = 1 s, seeds 1-3, a case table with an oblique sea, head seas with a current,
separate drag, and a case the model refuses (Hs = -1).

1. FMU backend: both result files equal the native tool's byte for byte (runs compared as a
   set of lines: they are written in finishing order). The FMU runs the same records as
   the native run (they do not depend on the stop time, which is the case's end:
   src/fmi2/campaign.rs) and is read at t = 0 and after each of the same steps, so every
   statistic must agree bit for bit; the refused case fails on both with the same message,
   the others complete, the exit status is 1. Every worker made at most one FMU instance
   and reused it (fmi2Reset) for all its runs.
2. CLI backend: the same files again.
3. Resume: a cut-off last line and a fixed table; only the failed case runs again, and the
   summary equals the native tool's on the fixed table; the native tool resumes the files.
4. Malformed table and a case the FMU cannot express: nothing runs, exit status 2, the
   native reader's message naming file, line, row and column.
5. A task that raises is retried, then its runs are recorded as failed with the reason; a
   worker process killed (SIGKILL) while it holds runs: the campaign still completes with
   every run, equal to the native tool's.
6. Number formatting against values printed by rustc; seeds grouped into tasks.
7. One campaign per --out whichever tool runs it: a client on the --out of a
   running native campaign is refused naming its pid, and the native tool on the --out of
   a client's campaign is refused naming the client's; the summary is replaced atomically.
"""

import hashlib
import os
import signal
import subprocess
import tempfile
import sys
import threading
import time
from pathlib import Path

import pytest

from mooring_loop import REPO
from routes import native_tool
from slowdrift_dask import Settings, run_campaign
from slowdrift_dask.worker import FMU_EVENTS, plugin_name

EXAMPLE = os.path.join(REPO, "tests", "data", "example.toml")
DURATION = 1200.0
SEEDS = 3
TABLE = """name,hs,tp,direction_deg,current_speed,drag,cd_slow,cd_fast
oblique,3,9,30,,,,
head,4,10,0,1.0,,,
separate,3,8,60,,separate,0.5,0.9
bad,-1,9,30,,,,
"""


@pytest.fixture(scope="module")
def slowdrift():
    """The native tool, built by cargo (routes.native_tool)."""
    return native_tool()


@pytest.fixture(scope="module")
def client():
    from distributed import Client, LocalCluster

    # The worker processes import slowdrift_dask too.
    package = os.path.join(REPO, "fmu-pack", "python")
    os.environ["PYTHONPATH"] = os.pathsep.join(
        p for p in (package, os.environ.get("PYTHONPATH")) if p)
    cluster = LocalCluster(n_workers=3, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


# Case tables by content: the native tool and a Dask campaign of the same table read the same
# file, so that the messages of refused cases (which name the table's path) agree.
TABLES = Path(tempfile.mkdtemp(prefix="slowdrift-dask-tables-"))


def table_file(table_text):
    path = TABLES / (hashlib.sha1(table_text.encode()).hexdigest()[:12] + ".cases.csv")
    path.write_text(table_text)
    return path


def native(slowdrift, workdir, table_text, name, seeds=SEEDS, duration=DURATION):
    """The native campaign: (exit status, summary text, set of run lines)."""
    table = table_file(table_text)
    out = workdir / f"{name}.csv"
    done = subprocess.run([slowdrift, "montecarlo", "--config", EXAMPLE, "--cases", str(table),
                           "--seeds", str(seeds), "--duration", repr(duration), "--out", str(out)],
                          capture_output=True, text=True)
    return done.returncode, out.read_text(), run_lines(out)


def run_lines(out):
    runs = out.with_name(out.stem + ".runs.csv").read_text().splitlines()
    assert len(runs) == len(set(runs)), "a run written twice"
    return runs[0], set(runs[1:])


def dask_campaign(client, fmu, slowdrift, workdir, table_text, name, backend, campaign=None,
                  **kw):
    table = table_file(table_text)
    out = workdir / f"{name}.csv"
    settings = Settings(seeds=kw.pop("seeds", SEEDS), out=str(out), config=EXAMPLE,
                        cases=str(table), duration=kw.pop("duration", DURATION),
                        backend=backend, fmu=fmu, slowdrift=slowdrift, **kw)
    status = run_campaign(settings, client=client, campaign=campaign)
    return status, out


@pytest.fixture(scope="module")
def reference(slowdrift, tmp_path_factory):
    status, summary, runs = native(slowdrift, tmp_path_factory.mktemp("native"), TABLE, "ref")
    assert status == 1, "the native tool reports the failed case"
    return summary, runs


def check_equal_to_native(out, reference):
    summary, (header, runs) = reference
    assert out.read_text() == summary
    got_header, got_runs = run_lines(out)
    assert got_header == header
    assert got_runs == runs


@pytest.mark.parametrize("backend", ["fmu", "cli"])
def test_campaign_equals_the_native_tool(client, fmu, slowdrift, reference, tmp_path, backend):
    started = time.monotonic()
    campaign = f"equal-{backend}"
    status, out = dask_campaign(client, fmu, slowdrift, tmp_path, TABLE, "d", backend,
                                campaign=campaign)
    elapsed = time.monotonic() - started
    print(f"\n{backend} backend: 12 runs on 3 workers in {elapsed:.1f} s")
    assert status == 1, "the refused case makes the exit status non-zero"
    check_equal_to_native(out, reference)
    summary = out.read_text().splitlines()
    # The other cases are complete; the refused one is marked with the model's message.
    for line in summary[1:]:
        case = line.split(",")[0]
        expected = "failed" if case == "bad" else "complete"
        assert f",{SEEDS},{SEEDS if case != 'bad' else 0},{0 if case != 'bad' else SEEDS}," \
               f"{expected}," in line, line
    bad = [line for line in summary if line.startswith("bad,")]
    assert len(bad) == 3 and all("column 'hs' = -1" in line for line in bad), bad
    # Not a trivial comparison: every ok run moved in surge, the oblique sea in all DOF.
    _, (_, runs) = reference
    for run in runs:
        fields = run.split(",")
        if fields[3] == "ok":
            moved = [float(fields[4 + 4 * d + 1]) > 0.0 for d in range(3)]
            assert moved[0] and (fields[0] != "oblique" or all(moved)), run
    if backend == "fmu":
        # The runners' last reports (a worker's events reach the scheduler before its
        # results): one instance each, reused through fmi2Reset for all its runs (a refused
        # run needs no new one), one runner per worker process.
        last = {}
        for _, event in client.get_events(FMU_EVENTS):
            if event["campaign"] == campaign:
                last[event["runner"]] = (event["runs"], event["instances"])
        # The refused case's runs fail before any FMU is used: three cases ran on the FMU.
        assert sum(runs for runs, _ in last.values()) == 3 * SEEDS, last
        assert all(instances == 1 for _, instances in last.values()), last
        pids = [runner.split("-")[0] for runner in last]
        assert len(set(pids)) == len(pids) >= 2, f"spread over the workers: {last}"
        # The campaign removed its plugin (and with it the instances) at the end.
        names = client.run(lambda dask_worker: list(dask_worker.plugins))
        assert all(plugin_name(campaign) not in n for n in names.values()), names


def test_resume_runs_only_what_is_missing(client, fmu, slowdrift, tmp_path):
    status, out = dask_campaign(client, fmu, slowdrift, tmp_path, TABLE, "r", "fmu")
    assert status == 1
    runs = out.with_name("r.runs.csv")
    # A kill while writing: the last line cut off without its newline.
    text = runs.read_text()
    runs.write_text(text + "oblique,9,0123456789abcdef,ok,1.5")
    fixed = TABLE.replace("bad,-1,", "bad,2,")
    status, out = dask_campaign(client, fmu, slowdrift, tmp_path, fixed, "r", "fmu")
    assert status == 0
    lines = runs.read_text().splitlines()
    assert not any(line.startswith("oblique,9,") for line in lines)
    # 12 first lines + the 3 reruns of the fixed case, nothing else ran again.
    assert len(lines) == 1 + 12 + 3, lines
    native_status, summary, _ = native(slowdrift, tmp_path, fixed, "fixed")
    assert native_status == 0
    assert out.read_text() == summary
    # The native tool resumes the Dask files: a fourth seed is all it runs.
    done = subprocess.run([slowdrift, "montecarlo", "--config", EXAMPLE, "--cases",
                           str(table_file(fixed)), "--seeds", "4", "--duration",
                           repr(DURATION), "--out", str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "= 16 runs; 12 already in" in done.stdout, done.stdout


def run_module(args, cwd):
    env = dict(os.environ, PYTHONPATH=os.path.join(REPO, "fmu-pack", "python"))
    return subprocess.run([sys.executable, "-m", "slowdrift_dask", *args], cwd=cwd, env=env,
                          capture_output=True, text=True)


def test_bad_input_stops_before_anything_runs(fmu, slowdrift, tmp_path):
    (tmp_path / "cases.csv").write_text("hs,tp\n3,9\n4,x9\n")
    common = ["--config", EXAMPLE, "--seeds", "2", "--fmu", fmu, "--slowdrift", slowdrift,
              "--workers", "1"]
    done = run_module([*common, "--cases", "cases.csv", "--out", "r.csv"], tmp_path)
    assert done.returncode == 2, done
    assert "cases.csv:3: row 2, column 'tp': 'x9' is not a finite number" in done.stderr
    assert not (tmp_path / "r.runs.csv").exists()
    # A duration that is not a whole number of steps cannot go through the FMU's stopTime.
    (tmp_path / "odd.csv").write_text("name,duration\nodd,600.6\n")
    done = run_module([*common, "--cases", "odd.csv", "--out", "o.csv"], tmp_path)
    assert done.returncode == 2, done
    assert "case 'odd': the FMU cannot run it" in done.stderr
    assert "--backend cli" in done.stderr


def test_a_task_that_raises_is_retried_then_recorded(client, fmu, slowdrift, tmp_path):
    """CLI backend with a tool that prints the cases but dies without a result on the
    workers: the task raises, is retried once (two attempts counted by the tool itself),
    and its runs are recorded as failed with the reason; the other case is not lost."""
    calls = tmp_path / "calls.txt"
    broken = tmp_path / "slowdrift-broken"
    broken.write_text(f"""#!/bin/sh
case " $* " in
  *" --print-cases "*|*" --case good "*) exec {slowdrift} "$@" ;;
esac
echo attempt >> {calls}
echo "simulated crash" >&2
exit 101
""")
    broken.chmod(0o755)
    table = "name,hs\ngood,3\nlost,3\n"
    status, out = dask_campaign(client, fmu, str(broken), tmp_path, table, "x", "cli",
                                retries=1)
    assert status == 1
    assert calls.read_text().count("attempt") == 2, "one try and one retry"
    summary = out.read_text()
    assert "good,surge,m,3,3,0,complete," in summary, summary
    assert "lost,surge,m,3,0,3,failed," in summary, summary
    assert "the run's task was lost: CliRunError" in summary and "simulated crash" in summary


def test_a_killed_worker_loses_no_run(client, fmu, slowdrift, tmp_path):
    """Longer runs (4 cases x 3 seeds of 6000 s, about 0.1-0.3 s each through fmpy) so that
    workers are busy when one is killed: the kill comes when the first run is written, on
    a worker the scheduler lists as processing runs."""
    table = TABLE.replace("bad,-1,", "bad,2,")
    duration = 6000.0
    pids_before = client.run(os.getpid)
    result = {}

    def campaign():
        result["status"], result["out"] = dask_campaign(
            client, fmu, slowdrift, tmp_path, table, "k", "fmu", duration=duration)

    thread = threading.Thread(target=campaign)
    thread.start()
    runs = tmp_path / "k.runs.csv"
    killed = None
    deadline = time.monotonic() + 60.0
    while killed is None and time.monotonic() < deadline and thread.is_alive():
        if runs.exists() and len(runs.read_text().splitlines()) >= 2:
            busy = [w for w, keys in client.processing().items() if keys and w in pids_before]
            if busy:
                killed = (busy[0], list(client.processing()[busy[0]]))
                os.kill(pids_before[busy[0]], signal.SIGKILL)
        time.sleep(0.01)
    thread.join(timeout=120.0)
    assert not thread.is_alive(), "the campaign did not finish"
    assert killed is not None, "no worker was busy to kill"
    print(f"\nkilled {killed[0]} while it held {killed[1]}")
    assert result["status"] == 0
    native_status, summary, native_runs = native(slowdrift, tmp_path, table, "kn",
                                                 duration=duration)
    assert native_status == 0
    check_equal_to_native(result["out"], (summary, native_runs))
    # The killed process is gone (the nanny started a new one).
    deadline = time.monotonic() + 30.0
    while time.monotonic() < deadline:
        pids_after = set(client.run(os.getpid).values())
        if pids_before[killed[0]] not in pids_after:
            break
        time.sleep(0.2)
    assert pids_before[killed[0]] not in pids_after


def test_numbers_are_written_as_rust_writes_them():
    """Rust's `{}` of f64, as rustc 1.95 printed these values (format!("{}", x))."""
    from slowdrift_dask.numbers import fmax, fmin, rust_display, total

    expected = {1e-300: "0." + "0" * 299 + "1", 1e21: "1" + "0" * 21, 3.0: "3", -0.0: "-0",
                0.1 + 0.2: "0.30000000000000004", 100.0: "100", -2.5e10: "-25000000000",
                1.0 / 3.0: "0.3333333333333333"}
    for x, text in expected.items():
        assert rust_display(x) == text, x
    # Rust: [-0.0, -0.0].iter().sum() is -0.0; f64::max prefers +0.0, f64::min -0.0.
    assert str(total([-0.0, -0.0])) == "-0.0"
    assert str(fmax(-0.0, 0.0)) == str(fmax(0.0, -0.0)) == "0.0"
    assert str(fmin(-0.0, 0.0)) == str(fmin(0.0, -0.0)) == "-0.0"


def test_tasks_group_consecutive_missing_seeds():
    from slowdrift_dask.campaign import tasks

    a, b = object(), object()
    jobs = [(a, 1), (a, 2), (a, 3), (a, 5), (b, 1), (b, 2)]
    assert tasks(jobs, 2) == [(a, [1, 2]), (a, [3]), (a, [5]), (b, [1, 2])]
    assert tasks(jobs, 1) == [(c, [s]) for c, s in jobs]


def test_one_campaign_per_out_whichever_tool(fmu, slowdrift, tmp_path):
    """The client takes the lock the native tool takes (flock on RESULTS.runs.csv.lock,
    which holds the pid): each is refused on the other's --out at once, naming the other's
    pid, and nothing is written to the runs file by the one refused."""
    from slowdrift_dask.plan import CampaignError
    from slowdrift_dask.runs_file import lock

    out = tmp_path / "r.csv"
    runs = tmp_path / "r.runs.csv"
    lock_file = tmp_path / "r.runs.csv.lock"
    native_run = subprocess.Popen(
        [slowdrift, "montecarlo", "--config", EXAMPLE, "--duration", "8192", "--seeds", "400",
         "--threads", "1", "--out", str(out)],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        while not (lock_file.exists() and lock_file.read_text().strip() == str(native_run.pid)
                   and runs.exists() and len(runs.read_text().splitlines()) > 2):
            assert time.monotonic() < deadline, "the native campaign did not start"
            time.sleep(0.01)
        settings = Settings(seeds=2, out=str(out), config=EXAMPLE, duration=8192.0,
                            backend="fmu", fmu=fmu, slowdrift=slowdrift)
        with pytest.raises(CampaignError) as refused:
            run_campaign(settings)
        assert f"r.runs.csv: in use by process {native_run.pid}, which holds its lock " \
            f"{lock_file}" in str(refused.value)
        assert native_run.poll() is None, "refused while the native campaign ran"
    finally:
        native_run.send_signal(signal.SIGTERM)
        _, stderr = native_run.communicate(timeout=60)
    assert native_run.returncode == 143, stderr
    assert "stopped by SIGTERM" in stderr
    lines = runs.read_text().splitlines()
    assert lines and all(line.count(",") >= 16 for line in lines[1:])
    assert not lock_file.exists()

    held = lock(str(runs))
    try:
        done = subprocess.run(
            [slowdrift, "montecarlo", "--config", EXAMPLE, "--duration", "8192", "--seeds", "1",
             "--out", str(out)], capture_output=True, text=True)
        assert done.returncode == 1, done
        assert f"in use by process {os.getpid()}, which holds its lock {lock_file}" \
            in done.stderr
        assert runs.read_text().splitlines() == lines
    finally:
        held.release()
    assert not lock_file.exists()
