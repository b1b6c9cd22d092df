"""What runs on the Dask workers.

`CampaignPlugin` is a Dask worker plugin: registered by the client, it is set up on every
worker, also on workers that join or are restarted later. It carries the files the runs need
(the FMU, or the native tool and the case table) and writes them into the worker's local
directory, so the workers need Python with dask, distributed and fmpy but no copy of the
project. The FMU instance is created at a worker thread's first run and reused for the
following runs (fmi2Reset); with one thread per worker (`dask worker --nthreads 1`, as the
client's local cluster) that is one instance per worker process.

Each campaign registers its own plugin (`plugin_name(campaign)`) and removes it at the end,
which frees the instances and files: campaigns on one cluster do not share them.

`run_task(plugin, case, seeds)` is the task: for each of a few consecutive seeds of one
case, the 12 statistics, or the message when the model refused or failed the run. Any other
exception propagates, so Dask retries the task; a worker that dies is replaced and its tasks
are rescheduled by the scheduler. After its runs an FMU task logs the Dask event
`FMU_EVENTS` {"campaign", "runner" (pid and thread), "runs", "instances"}: how many runs
this worker thread's runner made and how many FMU instances it created."""

import os
import stat
import threading

from distributed import WorkerPlugin, get_worker

from .cli_runner import run_cli
from .errors import RunFailed
from .fmu_runner import FmuRunner

# Topic of the Dask events of the FMU runners (Client.get_events).
FMU_EVENTS = "slowdrift-fmu-runner"


def plugin_name(campaign):
    return f"slowdrift-campaign-{campaign}"


class CampaignPlugin(WorkerPlugin):
    """backend "fmu": files = {"SlowDrift.fmu": bytes}; backend "cli": files =
    {"slowdrift": bytes, optionally "cases.csv": bytes}, `arguments` the tool's case options
    (`--cases` is replaced by the worker's copy)."""

    idempotent = False

    def __init__(self, campaign, backend, files, arguments=()):
        self.campaign = campaign
        self.name = plugin_name(campaign)
        self.backend = backend
        self.files = files
        self.arguments = list(arguments)
        self._local = threading.local()
        self._runners = []
        self._lock = threading.Lock()
        self.directory = None

    def __getstate__(self):
        return {"campaign": self.campaign, "backend": self.backend, "files": self.files,
                "arguments": self.arguments}

    def __setstate__(self, state):
        self.__init__(state["campaign"], state["backend"], state["files"], state["arguments"])

    def setup(self, worker):
        self.directory = os.path.join(worker.local_directory, "slowdrift")
        os.makedirs(self.directory, exist_ok=True)
        for name, data in self.files.items():
            path = os.path.join(self.directory, name)
            with open(path, "wb") as f:
                f.write(data)
            if name == "slowdrift":
                os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)

    def teardown(self, worker):
        with self._lock:
            for runner in self._runners:
                runner.close()
            self._runners.clear()

    def _path(self, name):
        return os.path.join(self.directory, name)

    def _fmu_runner(self):
        runner = getattr(self._local, "runner", None)
        if runner is None:
            unzip = os.path.join(self.directory, f"unzipped-{threading.get_ident()}")
            runner = FmuRunner(self._path("SlowDrift.fmu"), unzip,
                               name=f"slowdrift_dask_{os.getpid()}_{threading.get_ident()}")
            self._local.runner = runner
            with self._lock:
                self._runners.append(runner)
        return runner

    def run(self, case, seeds):
        """[(seed, "ok", statistics) or (seed, "failed", message)] for consecutive seeds."""
        if case.refused:
            # The model refuses the case's values whatever the seed: every run fails with the
            # native tool's message, which names where the values were written.
            return [(seed, "failed", case.refused) for seed in seeds]
        if self.backend == "fmu":
            runner = self._fmu_runner()
            results = []
            for seed in seeds:
                try:
                    results.append((seed, "ok", runner.run(case, seed)))
                except RunFailed as e:
                    results.append((seed, "failed", str(e)))
            get_worker().log_event(FMU_EVENTS, {
                "campaign": self.campaign, "runner": f"{os.getpid()}-{threading.get_ident()}",
                "runs": runner.runs, "instances": runner.instances})
            return results
        arguments = list(self.arguments)
        if "--cases" in arguments:
            arguments[arguments.index("--cases") + 1] = self._path("cases.csv")
        return run_cli(self._path("slowdrift"), arguments, case, seeds, self.directory)


def run_task(plugin, case, seeds):
    """Consecutive seeds of one case on this worker, with the campaign's plugin:
    [(seed, "ok", 12 statistics) or (seed, "failed", message)]."""
    return get_worker().plugins[plugin].run(case, seeds)
