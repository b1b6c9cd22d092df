"""Mesh convergence of the platform's radiation-diffraction solution.

    python tests/bem/convergence.py target/bem/conv_3.0.npz target/bem/conv_2.5.npz \
        target/bem/platform_2.0.npz

Prints, for each mesh, the head-sea surge drift, the 30-degree yaw drift moment and the
surge and heave added mass at the frequencies every mesh has, and the relative change from
each mesh to the finest.
"""

import sys

import numpy as np

import make_database


def quantities(path):
    bem = dict(np.load(path))
    _, inertia, stiffness, _, damping, _, _ = make_database.platform_matrices(bem)
    t = make_database.slowdrift_drift(bem, inertia, stiffness, damping)
    head = int(np.argmin(np.abs(bem["heading"])))
    oblique = int(np.argmin(np.abs(bem["heading"] - np.radians(30.0))))
    return bem, {
        "surge drift, head sea (N/m^2)": t[:, head, head, 0].real,
        "yaw drift, 30 deg (N m/m^2)": t[:, oblique, oblique, 2].real,
        "A11 (kg)": bem["added_mass"][:, 0, 0],
        "A33 (kg)": bem["added_mass"][:, 2, 2],
    }


def main():
    meshes = [quantities(p) for p in sys.argv[1:]]
    common = set(np.round(meshes[0][0]["omega"], 6))
    for bem, _ in meshes[1:]:
        common &= set(np.round(bem["omega"], 6))
    omegas = np.array(sorted(common))
    finest_bem, finest = meshes[-1]
    pick = lambda bem: [int(np.argmin(np.abs(bem["omega"] - w))) for w in omegas]
    print("omega (rad/s): " + " ".join(f"{w:>9.2f}" for w in omegas))
    for name in finest:
        print(name)
        ref = finest[name][pick(finest_bem)]
        for bem, q in meshes:
            values = q[name][pick(bem)]
            print(f"  {float(bem['size']):.1f} m, {int(bem['panels'])} panels: "
                  + " ".join(f"{v:9.4g}" for v in values))
            if bem is not finest_bem:
                change = (values - ref) / np.abs(ref).max()
                print("      change / largest value: " + " ".join(f"{c:9.2%}" for c in change))


if __name__ == "__main__":
    main()
