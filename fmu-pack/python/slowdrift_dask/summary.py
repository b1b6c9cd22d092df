"""RESULTS.csv and the printed table, as `slowdrift montecarlo` writes them
(src/cli/montecarlo.rs): per case and DOF, from the per-run file, for the requested seeds in
seed order, so the summary depends neither on the backend nor on the finishing order. The
file is written anew atomically, as the native tool writes it (src/files/replace.rs): to
RESULTS.csv.PID.tmp, synced, then renamed over it, so a kill never leaves it cut."""

import os

from .numbers import rust_display
from .runs_file import DOFS, STATISTICS
from .stats import seed_statistics


class CaseSummary:
    def __init__(self, case, runs, seeds):
        mine = sorted((r for r in runs if r.case == case.name and r.seed in seeds),
                      key=lambda r: r.seed)
        self.name = case.name
        # values[dof][statistic]: the values of the seeds done, in seed order.
        self.values = [[[] for _ in STATISTICS] for _ in DOFS]
        self.failed = 0
        self.first_error = None
        for run in mine:
            if run.ok:
                for d in range(len(DOFS)):
                    for s in range(len(STATISTICS)):
                        self.values[d][s].append(run.values[4 * d + s])
            else:
                self.failed += 1
                if self.first_error is None:
                    self.first_error = f"seed {run.seed}: {run.error}"

    def done(self):
        return len(self.values[0][0])

    def status(self, requested):
        """As the native tool's: complete, partial, failed (none done, some failed) or not
        started (none run)."""
        done = self.done()
        if done == 0:
            return "failed" if self.failed else "not started"
        return "complete" if done == requested else "partial"


def write_summary(path, summaries, requested):
    header = "case,dof,unit,seeds_requested,seeds_done,seeds_failed,status"
    header += "".join(f",{stat},{stat}_se" for stat in STATISTICS)
    lines = [header + ",error"]
    for s in summaries:
        for (dof, unit), stats in zip(DOFS, s.values):
            line = (f"{s.name},{dof},{unit},{requested},{s.done()},{s.failed},"
                    f"{s.status(requested)}")
            for values in stats:
                m = seed_statistics(values)
                if m is None:
                    line += ",,"
                else:
                    line += f",{rust_display(m[0])},{'' if m[1] is None else rust_display(m[1])}"
            error = s.first_error or ""
            line += "," + ('"' + error.replace('"', '""') + '"' if error else "")
            lines.append(line)
    temporary = f"{path}.{os.getpid()}.tmp"
    try:
        with open(temporary, "w", newline="") as f:
            f.write("\n".join(lines) + "\n")
            f.flush()
            os.fsync(f.fileno())
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def print_summary(summaries, requested):
    print(f"{'case':<16} {'dof':<11} {'seeds':>9} {'mean +- se':>24} {'rms +- se':>24} "
          f"{'max +- se':>24}")
    for s in summaries:
        for (dof, unit), stats in zip(DOFS, s.values):
            cells = []
            for values in stats[:3]:
                m = seed_statistics(values)
                cells.append("-" if m is None else f"{m[0]:.4f}" if m[1] is None
                             else f"{m[0]:.4f} +- {m[1]:.4f}")
            print(f"{s.name:<16} {f'{dof} [{unit}]':<11} {f'{s.done()}/{requested}':>9} "
                  f"{cells[0]:>24} {cells[1]:>24} {cells[2]:>24}")
        if s.first_error:
            print(f"{s.name:<16} {s.failed} run(s) failed; first: {s.first_error}")
        elif s.status(requested) == "not started":
            print(f"{s.name:<16} not started")
