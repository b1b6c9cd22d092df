"""The default platform's hydro database from its radiation-diffraction solution.

    python tests/bem/make_database.py --bem target/bem/platform_2.0.npz \
        --slowdrift target/release/slowdrift --out src/hydro/default_platform.json \
        --model tests/bem/platform_model.json

Reads Capytaine's raw results (solve_platform.py), adds the platform's mass, inertia and
hydrostatics, the mooring's stiffness and a linear viscous damping in heave, roll and pitch,
solves for the first-order motions, and computes the mean drift of every pair of headings
from the far-field Kochin function (semi_bem.far_field_drift). Above JOIN_END the drift is
the column solver's (`slowdrift hydro columns --bidirectional`): there the waves no longer
reach the pontoons (e^{-2 k 16 m} < 3e-6 at 1.6 rad/s) nor the columns' bottom, the platform
hardly moves (surge amplitude 0.01 m/m), and the column solver is exact for potential flow
while the panels grow coarse against the wavelength; between JOIN_START and JOIN_END the two
are blended linearly. Writes the native database (SlowDrift's conventions, see semi_bem) in
two files, as the library embeds it (`hydro::default_platform`): OUT without its
bi-directional drift, and that table alone in OUT with `_bidirectional` before `.json`.

OUT also holds the first-order motions (its `rao`): the RAOs solved above, on the BEM's own
frequencies (0.04-2.0 rad/s every 0.02) and headings (every 10 degrees), converted to
SlowDrift's conventions (slowdrift_rao). Above 2.0 rad/s there is no RAO (the column solver's
columns are held fixed) and none is needed: the platform hardly moves there (surge 0.01 m/m
at 1.6 rad/s). Before writing, the RAOs are checked against Capytaine's own
`capytaine.post_pro.rao` on the same solution and matrices (capytaines_rao).

With --keep-drift, OUT, its bi-directional table and MODEL are read rather than rewritten:
everything recomputed must agree with them within KEEP_TOLERANCE of each component's largest
value (the same solution: a re-solve differs from the committed one in round-off only), and
OUT gets the new `rao` and `source` alone, its other bytes unchanged.
"""

import argparse
import json
import pathlib
import subprocess
import tempfile

import numpy as np

import semi_bem
import semi_mesh as geometry

# The join of the radiation-diffraction data to the column solver's, rad/s.
JOIN_START = 1.6
JOIN_END = 2.0
# The database's frequencies: the BEM grid continued to OMEGA_MAX every 0.02 rad/s.
OMEGA_MAX = 3.0
OMEGA_STEP = 0.02
# The bi-directional table keeps every BIDIRECTIONAL_EVERY-th frequency (size).
BIDIRECTIONAL_EVERY = 2
# Digits kept in the file, against a discretisation error of about 1 %.
SIGNIFICANT_DIGITS = 6
# Digits kept of the RAOs (its size: the database is parsed at every start; the rounding,
# 5e-5 relative, is far below the mesh's 1 %), and the largest relative difference to
# Capytaine's own RAOs of the same solution that is round-off (6 x 6 solves).
RAO_DIGITS = 4
RAO_ROUND_OFF = 1e-10
# --keep-drift: the largest difference, as a fraction of each component's largest value,
# between the recomputed drift, bi-directional drift, low-frequency added mass and model and
# the committed ones (a re-solve of the same mesh differs in round-off: 8e-12 of the largest
# in #29's, where a few values written to 6 digits changed in their 6th).
KEEP_TOLERANCE = 1e-5
# Mooring: the paper's natural periods in surge and sway (200 s) and yaw (100 s).
SURGE_PERIOD = 200.0
YAW_PERIOD = 100.0
# Linear viscous damping in heave, roll and pitch, as a fraction of critical: stands in for
# the drag of the pontoons and columns, which potential flow lacks, and bounds the motions at
# the heave and pitch resonances (0.23-0.30 rad/s).
VISCOUS_DAMPING_RATIO = 0.05
# The frequency taken as omega -> 0 for the low-frequency added mass, rad/s.
SLOW = 0.04
SLOW_DOFS = [0, 1, 5]  # surge, sway, yaw among Capytaine's six


def platform_matrices(bem):
    """Inertia, stiffness (hydrostatic and mooring) and viscous damping, 6 x 6 about the
    centre of gravity (on the z axis: yaw about it is yaw about the body origin)."""
    props = semi_bem.mass_properties()
    inertia, stiffness = semi_bem.rigid_body_matrices(props)
    slow = int(np.argmin(np.abs(bem["omega"] - SLOW)))
    added = bem["added_mass"][slow]
    mooring = np.zeros((6, 6))
    for dof, period in [(0, SURGE_PERIOD), (1, SURGE_PERIOD), (5, YAW_PERIOD)]:
        mooring[dof, dof] = (inertia[dof, dof] + added[dof, dof]) * (2 * np.pi / period) ** 2
    damping = np.zeros((6, 6))
    natural = {}
    for dof in (2, 3, 4):
        # Natural frequency with the added mass at it: the fixed point of
        # omega = sqrt(C / (M + A(omega))).
        w = 0.25
        for _ in range(50):
            a = np.interp(w, bem["omega"], bem["added_mass"][:, dof, dof])
            w = np.sqrt(stiffness[dof, dof] / (inertia[dof, dof] + a))
        natural[dof] = w
        damping[dof, dof] = 2 * VISCOUS_DAMPING_RATIO * np.sqrt(
            stiffness[dof, dof] * (inertia[dof, dof] + a))
    return props, inertia, stiffness + mooring, mooring, damping, added, natural


def slowdrift_drift(bem, inertia, stiffness, damping):
    """T[omega, p, q, (surge, sway, yaw)] of the freely floating platform in SlowDrift's
    convention: Capytaine's conjugated (semi_bem's docstring)."""
    x = semi_bem.motions(bem, inertia, stiffness, damping)
    return np.conj(semi_bem.far_field_drift(bem, x))


def slowdrift_rao(x, z_g):
    """The first-order motions x[omega, heading, dof] as semi_bem.motions solves them
    (Capytaine's convention: e^{-i omega t}, rotations about the centre of gravity G = (0, 0,
    z_g)) in SlowDrift's, the database's `rao`: Re{xi e^{+i omega t}}, the translations those
    of the body origin O, per unit amplitude, phase relative to the incident elevation at O.

    One rigid body: a point p moves by t_G + theta x (p - G), so O's translation is
    t_O = t_G + theta x (O - G) = (t_x - z_g theta_y, t_y + z_g theta_x, t_z), the rotations
    unchanged. Capytaine's incident wave is Re[e^{i k (x cos b + y sin b) - i omega t}]: unit
    elevation at O, towards the heading b from +x, which is SlowDrift's heading; a SlowDrift
    amplitude is the conjugate of Capytaine's (semi_bem's docstring)."""
    x = np.asarray(x)
    out = x.copy()
    out[..., 0] = x[..., 0] - z_g * x[..., 4]
    out[..., 1] = x[..., 1] + z_g * x[..., 3]
    return np.conj(out)


def capytaines_rao(bem, inertia, hydrostatics, stiffness, damping):
    """Capytaine's own `capytaine.post_pro.rao` of the solution `bem` (semi_bem.solve's
    arrays) with the body's inertia and hydrostatic stiffness in the dataset, where Capytaine
    reads them, and the mooring's `stiffness` and the viscous `damping` as its stiffness and
    dissipation: X[omega, heading, dof] in Capytaine's convention, about the solution's
    rotation centre."""
    import xarray as xr
    from capytaine.post_pro.rao import rao
    dofs = [str(d) for d in bem["dofs"]]
    square = lambda m: xr.DataArray(np.asarray(m), dims=("influenced_dof", "radiating_dof"),
                                    coords={"influenced_dof": dofs, "radiating_dof": dofs})
    coords = {"omega": bem["omega"], "wave_direction": bem["heading"],
              "influenced_dof": dofs, "radiating_dof": dofs}
    dataset = xr.Dataset({
        "added_mass": (("omega", "influenced_dof", "radiating_dof"), bem["added_mass"]),
        "radiation_damping": (("omega", "influenced_dof", "radiating_dof"),
                              bem["radiation_damping"]),
        "excitation_force": (("omega", "wave_direction", "influenced_dof"), bem["excitation"]),
        "inertia_matrix": square(inertia), "hydrostatic_stiffness": square(hydrostatics),
    }, coords=coords)
    x = rao(dataset, dissipation=square(damping), stiffness=square(stiffness))
    return x.transpose("omega", "wave_direction", "radiating_dof").values


def column_solver(slowdrift, omegas, heading_step_deg):
    """The column solver's drift and bi-directional drift (SlowDrift's convention) at
    `omegas` (evenly spaced) for headings every heading_step_deg."""
    default = (pathlib.Path(__file__).resolve().parents[2] / "src" / "scenario"
               / "default.toml").read_text()
    body = default[:default.index("\n[drift]")]
    with tempfile.TemporaryDirectory() as tmp:
        config = pathlib.Path(tmp) / "columns.toml"
        config.write_text(
            body + f"\n[drift]\nsource = \"column-array\"\nomega_min = {omegas[0]}\n"
            f"omega_max = {omegas[-1]}\nn_omega = {len(omegas)}\n"
            f"heading_step_deg = {heading_step_deg}\n")
        out = pathlib.Path(tmp) / "columns.json"
        subprocess.run([slowdrift, "hydro", "columns", "--config", str(config), "--bidirectional",
                        "--out", str(out)], check=True, capture_output=True)
        db = json.loads(out.read_text())
    table = db["bidirectional_drift"]
    t = np.array(table["re"]) + 1j * np.array(table["im"])  # (omega, p, q, dof)
    return np.array(table["omegas"]), np.array(table["headings"]), t


def largest_change(old, new):
    """max |new - old| over the last axis's components, each as a fraction of that
    component's largest |old| (a component zero throughout: as a fraction of 1)."""
    old, new = np.asarray(old, float), np.asarray(new, float)
    old, new = old.reshape(-1, old.shape[-1]), new.reshape(-1, new.shape[-1])
    scale = np.abs(old).max(axis=0)
    scale[scale == 0] = 1.0
    return float((np.abs(new - old).max(axis=0) / scale).max())


def kept(path, model_path, database, bidirectional, model):
    """--keep-drift: the committed database at `path` with the recomputed `rao` and
    `source`, its other fields untouched, after checking that what was recomputed
    (`database`, `bidirectional`, `model`) is the committed data within KEEP_TOLERANCE."""
    committed = json.loads(path.read_text())
    committed_table = json.loads(path.with_name(path.stem + "_bidirectional.json").read_text())
    committed_model = json.loads(model_path.read_text())
    drift = lambda d: [[p[k] for k in ("omega", "heading", "surge", "sway", "yaw")]
                       for p in d["drift"]]
    whole = lambda m: np.ravel(m)[:, None]  # one component: scaled by the whole matrix
    changes = {
        "drift": largest_change(drift(committed), drift(database)),
        "bidirectional drift": max(largest_change(committed_table[k], bidirectional[k])
                                   for k in ("re", "im", "omegas", "headings")),
        "low-frequency added mass": largest_change(whole(committed["low_frequency_added_mass"]),
                                                   whole(database["low_frequency_added_mass"])),
        "mass properties": largest_change(
            [list(committed["mass_properties"].values())],
            [list(database["mass_properties"].values())]),
        "model": max(largest_change(whole(committed_model[k]), whole(model[k]))
                     for k in ("inertia", "stiffness", "mooring_stiffness", "viscous_damping")),
    }
    print("--keep-drift: recomputed against committed, largest change as a fraction of each "
          "component's largest: " + ", ".join(f"{k} {v:.2e}" for k, v in changes.items()))
    if any(v > KEEP_TOLERANCE for v in changes.values()):
        raise SystemExit(f"the recomputed data differ from the committed by more than "
                         f"{KEEP_TOLERANCE}: regenerate without --keep-drift")
    for key in ("format_version", "name", "water_density", "gravity", "stiffness", "qtf",
                "provenance"):
        if committed[key] != database[key]:
            raise SystemExit(f"--keep-drift: the committed {key} is not this script's")
    # Field order of this script's own output (rao before provenance).
    return {k: database[k] if k in ("rao", "source") else committed[k] for k in database}


def rounded(values, digits=SIGNIFICANT_DIGITS):
    """Nested lists of `values` to `digits` significant digits (the file's size; far below
    the solution's own accuracy)."""
    return np.vectorize(lambda v: float(f"{v:.{digits}g}"), otypes=[float])(values).tolist()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bem", required=True, help="solve_platform.py's .npz")
    parser.add_argument("--slowdrift", required=True, help="the slowdrift program")
    parser.add_argument("--out", required=True,
                        help="the database to write (JSON; its bi-directional table beside it)")
    parser.add_argument("--model", required=True,
                        help="where to write the platform's 6-DOF model (JSON)")
    parser.add_argument("--keep-drift", action="store_true",
                        help="add the RAOs to the committed OUT, leaving the rest of OUT, its "
                             "bi-directional table and MODEL as they are (after checking that "
                             "they are what this solution gives)")
    args = parser.parse_args()
    bem = dict(np.load(args.bem))
    props, inertia, stiffness, mooring, damping, added, natural = platform_matrices(bem)
    model = {
        "about": "The platform's 6-DOF model about its centre of gravity (SI units, DOFs surge, "
                 "sway, heave, roll, pitch, yaw) that tests/bem/make_database.py solved the "
                 "first-order motions with; test_bem.py reuses it.",
        "mesh_size": float(bem["size"]), "panels": int(bem["panels"]),
        "lid_panels": int(bem["lid_panels"]), "bem_seconds": float(bem["seconds"]),
        "capytaine_version": str(bem["capytaine_version"]),
        "centre_of_gravity_z": props["z_g"], "volume": props["volume"],
        "inertia": inertia.tolist(), "stiffness": stiffness.tolist(),
        "mooring_stiffness": mooring.tolist(), "viscous_damping": damping.tolist(),
        "natural_frequencies": {"heave": natural[2], "roll": natural[3], "pitch": natural[4]},
    }
    if not args.keep_drift:
        pathlib.Path(args.model).write_text(json.dumps(model, indent=1) + "\n")
    t_bem = slowdrift_drift(bem, inertia, stiffness, damping)
    omega_bem, headings = bem["omega"], bem["heading"]
    x = semi_bem.motions(bem, inertia, stiffness, damping)
    own = capytaines_rao(bem, inertia, stiffness - mooring, mooring, damping)
    rao_difference = (np.abs(x - own).max(axis=(0, 1)) / np.abs(own).max(axis=(0, 1))).max()
    print(f"RAOs against Capytaine's own post_pro.rao of the same solution: largest difference "
          f"{rao_difference:.2e} of each DOF's largest")
    if not rao_difference < RAO_ROUND_OFF:
        raise SystemExit("the RAOs are not Capytaine's")
    rao = slowdrift_rao(x, props["z_g"])

    omegas = np.round(np.arange(omega_bem[0], OMEGA_MAX + 1e-9, OMEGA_STEP), 10)
    join = omegas[omegas >= JOIN_START - 1e-9]
    omega_col, headings_col, t_col = column_solver(args.slowdrift, join, 10.0)
    if not np.allclose(headings_col, headings) or not np.allclose(omega_col, join):
        raise SystemExit("the column solver's grid is not the BEM's")

    t = np.empty((len(omegas),) + t_bem.shape[1:], complex)
    for n, w in enumerate(omegas):
        weight = np.clip((w - JOIN_START) / (JOIN_END - JOIN_START), 0.0, 1.0)
        bem_part = t_bem[np.argmin(np.abs(omega_bem - w))] if w <= omega_bem[-1] + 1e-9 else 0
        col_part = t_col[np.argmin(np.abs(omega_col - w))] if w >= JOIN_START - 1e-9 else 0
        t[n] = (1 - weight) * bem_part + weight * col_part

    overlap = [np.argmin(np.abs(omega_bem - w)) for w in join if w <= omega_bem[-1] + 1e-9]
    diag = lambda a: np.einsum("nkkd->nkd", a).real
    scale = np.abs(diag(t_col[: len(overlap)])[..., :2]).max()
    diff = np.abs(diag(t_bem[overlap])[..., :2] - diag(t_col[: len(overlap)])[..., :2]).max()
    print(f"overlap {JOIN_START}-{omega_bem[-1]} rad/s: largest difference of the drift force "
          f"BEM - columns {diff:.4g} N/m^2 ({diff / scale:.2%} of the largest)")

    drift = []
    for ih, beta in enumerate(headings):
        for n, w in enumerate(omegas):
            f = t[n, ih, ih].real
            f = rounded(f)
            drift.append({"omega": float(w), "heading": float(beta), "surge": f[0],
                          "sway": f[1], "yaw": f[2], "damping": None})
    keep = np.arange(0, len(omegas), BIDIRECTIONAL_EVERY)
    slow = [[added[i, j] for j in SLOW_DOFS] for i in SLOW_DOFS]
    database = {
        "format_version": 1,
        "name": "SlowDrift default platform (radiation-diffraction)",
        "source": (
            f"Capytaine {bem['capytaine_version']} (tests/bem): the paper's four columns on "
            f"pontoons, draft 30 m, deep water, {int(bem['panels'])} panels ({float(bem['size'])} m) "
            f"and a lid; freely floating (mass, inertia and hydrostatics of a uniformly dense "
            f"hull, mooring stiffness for natural periods of {SURGE_PERIOD:.0f} s and "
            f"{YAW_PERIOD:.0f} s, {VISCOUS_DAMPING_RATIO:.0%} of critical viscous damping in "
            f"heave, roll and pitch); far-field mean drift; above {JOIN_START}-{JOIN_END} rad/s "
            f"(blended) the column solver's; RAOs about the body origin on the BEM's "
            f"{omega_bem[0]:g}-{omega_bem[-1]:g} rad/s"),
        "water_density": semi_bem.RHO,
        "gravity": semi_bem.G,
        "mass_properties": {"mass": props["mass"], "yaw_inertia": props["i_zz"]},
        "low_frequency_added_mass": slow,
        "stiffness": None,
        "drift": drift,
        "qtf": None,
        "rao": {
            "omegas": [float(w) for w in omega_bem],
            "headings": [float(b) for b in headings],
            "re": rounded(rao.real, RAO_DIGITS),
            "im": rounded(rao.imag, RAO_DIGITS),
        },
        "provenance": {
            "mass_properties": "a uniformly dense hull of the displaced volume "
                               "(tests/bem/semi_bem.py)",
            "low_frequency_added_mass": f"Capytaine {bem['capytaine_version']} (tests/bem) at "
                                        f"omega = {float(bem['omega'][np.argmin(np.abs(bem['omega'] - SLOW))])} rad/s",
        },
    }
    bidirectional = {
        "omegas": [float(w) for w in omegas[keep]],
        "headings": [float(b) for b in headings],
        "re": rounded(t[keep].real),
        "im": rounded(t[keep].imag),
    }
    out = pathlib.Path(args.out)
    if args.keep_drift:
        database = kept(out, pathlib.Path(args.model), database, bidirectional, model)
    else:
        out.with_name(out.stem + "_bidirectional.json").write_text(
            json.dumps(bidirectional, separators=(",", ":")) + "\n")
    out.write_text(json.dumps(database, separators=(",", ":")) + "\n")
    print(f"{args.out}: {len(omegas)} frequencies x {len(headings)} headings; mass "
          f"{props['mass']:.5g} kg, yaw inertia {props['i_zz']:.5g} kg m^2, low-frequency added "
          f"mass {added[0, 0]:.5g} kg, {added[5, 5]:.5g} kg m^2; mooring "
          f"{mooring[0, 0]:.5g} N/m, {mooring[5, 5]:.5g} N m/rad; natural frequencies heave "
          f"{natural[2]:.4f}, roll/pitch {natural[3]:.4f} rad/s")


if __name__ == "__main__":
    main()
