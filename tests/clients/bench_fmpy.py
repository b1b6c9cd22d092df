#!/usr/bin/env python3
"""Wall time of a three-hour run at a 1 s communication step through fmpy's FMU2Slave
(the target: under 2 s). Not a test: prints the numbers.

Timed: FMU2Slave construction (loading the library) + instantiate + setupExperiment(0, 10800)
+ enter/exitInitializationMode (which precomputes the records) + 10800 x (doStep, getReal of
X, Y, theta) + terminate + freeInstance, with the default parameters. Extracting the archive
is not timed. The median and the fastest of several repetitions are printed, with the
initialisation and the stepping loop split out.

    target/client-venv/bin/python tests/clients/bench_fmpy.py [FMU] [--repeat 5]
"""

import argparse
import os
import shutil
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mooring_loop import fmu_path  # noqa: E402

STOP = 10800.0
DT = 1.0


def one_run(md, unzipdir, vrs):
    from fmpy.fmi2 import FMU2Slave

    t0 = time.perf_counter()
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="bench")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0, stopTime=STOP)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    t1 = time.perf_counter()
    n = int(round(STOP / DT))
    x = None
    for k in range(n):
        fmu.doStep(currentCommunicationPoint=k * DT, communicationStepSize=DT)
        x = fmu.getReal(vrs)
    t2 = time.perf_counter()
    fmu.terminate()
    fmu.freeInstance()
    t3 = time.perf_counter()
    return t3 - t0, t1 - t0, t2 - t1, x


def main():
    from fmpy import __version__, extract, read_model_description

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("fmu", nargs="?", default=fmu_path())
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()

    md = read_model_description(args.fmu)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    vrs = [vr["X"], vr["Y"], vr["theta"]]
    unzipdir = extract(args.fmu)
    try:
        runs = [one_run(md, unzipdir, vrs) for _ in range(args.repeat)]
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
    total = [r[0] for r in runs]
    init = [r[1] for r in runs]
    loop = [r[2] for r in runs]
    steps = int(round(STOP / DT))
    print(f"fmpy {__version__}, {args.fmu}")
    print(f"3-hour run at {DT:g} s through FMU2Slave ({steps} doStep + getReal(3)), "
          f"{args.repeat} runs:")
    print(f"  total   median {statistics.median(total):.3f} s, fastest {min(total):.3f} s "
          f"(target < 2 s: {'met' if statistics.median(total) < 2.0 else 'NOT met'})")
    print(f"  instantiate + initialise (records)  median {statistics.median(init) * 1e3:.1f} ms")
    print(f"  stepping loop  median {statistics.median(loop):.3f} s = "
          f"{statistics.median(loop) / steps * 1e6:.1f} us per doStep + getReal")
    print(f"  final X, Y, theta = {runs[-1][3]}")


if __name__ == "__main__":
    main()
