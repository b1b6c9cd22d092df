"""slowdrift_dask: `slowdrift montecarlo` on a Dask cluster.

`python -m slowdrift_dask --cases CASES.csv --seeds N --out RESULTS.csv` runs every
(case, seed) of a campaign as a Dask task, through SlowDrift.fmu with fmpy (`--backend fmu`,
default: one FMU instance per worker, reused through fmi2Reset) or the native tool
(`--backend cli`), and writes the same RESULTS.runs.csv and RESULTS.csv as
`slowdrift montecarlo`, byte for byte for the same runs. See README "Monte Carlo on a
cluster (Dask)".
"""

from .campaign import Settings, run_campaign
from .plan import CampaignError

__all__ = ["CampaignError", "Settings", "run_campaign"]
