"""Solves the platform with Capytaine and saves the raw results.

    python tests/bem/solve_platform.py --size 2.0 --out target/bem/platform_2.0.npz

Frequencies from 0.04 to 2.0 rad/s every 0.02 (or --omegas), headings every 10 degrees over
the circle, Kochin functions at 144 angles (2.5 degrees, so the headings lie on the grid).
"""

import argparse
import time

import numpy as np

import semi_bem

OMEGAS = np.round(np.arange(0.04, 2.0 + 1e-9, 0.02), 10)
HEADINGS = np.radians(np.arange(0.0, 360.0, 10.0))
N_THETA = 144


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=float, required=True, help="panel size, m")
    parser.add_argument("--omegas", type=float, nargs="*", help="frequencies, rad/s")
    parser.add_argument("--out", required=True, help="the .npz to write")
    args = parser.parse_args()
    omegas = np.array(args.omegas) if args.omegas else OMEGAS
    start = time.perf_counter()
    bem = semi_bem.solve(args.size, omegas, HEADINGS, N_THETA)
    bem["seconds"] = time.perf_counter() - start
    np.savez_compressed(args.out, **bem)
    print(f"{args.out}: {len(omegas)} frequencies x {len(HEADINGS)} headings, "
          f"{bem['panels']} panels + {bem['lid_panels']} on the lid, {bem['seconds']:.0f} s")


if __name__ == "__main__":
    main()
