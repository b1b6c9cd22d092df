"""A campaign's cases, read by the native tool (`slowdrift montecarlo --print-cases`): one
reader of the case table and the configuration for both paths, with the same error
messages (file, line, row, column) and the same per-case fingerprint
(src/fmi2/campaign.rs describes the JSON)."""

import json
import subprocess
from dataclasses import dataclass


class CampaignError(Exception):
    """A campaign that cannot start (bad arguments, malformed case table, ...)."""


@dataclass(frozen=True)
class Case:
    name: str
    fingerprint: str
    # Start-up transient, s from the start of the run.
    transient: float
    # RK4 step h, s, and the number of steps of a run (samples k h, k = 0 ..= steps).
    time_step: float
    steps: int
    # FMU route: parameters by name (all but seed), start and stop time; None when the FMU
    # cannot run this case, and then `fmu_unavailable` says why.
    fmu_parameters: dict = None
    start_time: float = 0.0
    stop_time: float = 0.0
    fmu_unavailable: str = ""
    # The message every run of the case fails with when the model refuses its values (as
    # the native tool records it); empty for a case that runs.
    refused: str = ""


def case_arguments(config=None, cases=None, duration=None, transient=None):
    """The `slowdrift montecarlo` options that define the cases."""
    args = []
    if config is not None:
        args += ["--config", str(config)]
    if cases is not None:
        args += ["--cases", str(cases)]
    if duration is not None:
        args += ["--duration", repr(float(duration))]
    if transient is not None:
        args += ["--transient", repr(float(transient))]
    return args


def read_cases(slowdrift, arguments):
    """The cases of `slowdrift montecarlo ARGUMENTS --print-cases`; the tool's error message
    (naming file, line, row and column) as a CampaignError."""
    try:
        done = subprocess.run([str(slowdrift), "montecarlo", *arguments, "--print-cases"],
                              capture_output=True, text=True)
    except OSError as e:
        raise CampaignError(f"cannot run the native tool '{slowdrift}': {e}") from None
    if done.returncode != 0:
        message = done.stderr.strip().removeprefix("slowdrift: ")
        raise CampaignError(message or f"{slowdrift} exited with status {done.returncode}")
    document = json.loads(done.stdout)
    if document.get("format_version") != 1:
        raise CampaignError(f"{slowdrift}: unknown --print-cases format "
                            f"{document.get('format_version')!r}")
    out = []
    for c in document["cases"]:
        fmu = c["fmu"]
        common = dict(name=c["name"], fingerprint=c["fingerprint"], transient=c["transient"],
                      time_step=c["time_step"], steps=int(c["steps"]),
                      refused=c.get("refused", ""))
        if "unavailable" in fmu:
            out.append(Case(**common, fmu_unavailable=fmu["unavailable"]))
        else:
            out.append(Case(**common, fmu_parameters=fmu["parameters"],
                            start_time=fmu["start_time"], stop_time=fmu["stop_time"]))
    return out
