"""The Capytaine route into SlowDrift, run by tests/bem/run_bem.sh in the
README's test command: Capytaine 3.0 on a coarse vertical cylinder (radius 5 m, draft 60 m,
deep water, held fixed) at three frequencies and three headings, its far-field mean drift for
every pair of headings written as a WAMIT `.8` by Capytaine's own `export_to_wamit` through
capytaine_to_wamit.py (which corrects Capytaine's two-heading yaw term and the convention),
imported by `slowdrift hydro wamit` and checked against
answers that do not come from either code: Havelock's closed form for one heading, and for two
headings the phase a translation of the cylinder must add (e^{-i (k_k - k_l) . x_c}) and the
moment identity of an offset cylinder (M = x_c F_y - y_c F_x). The imported bi-directional
drift then runs a spread sea through `slowdrift simulate`. The last test records why the route
is deep water only: Capytaine's far-field drift in finite depth, against the closed form.

Needs the slowdrift binary that `cargo test --release --workspace` builds (the test command
runs it first); refuses to run without it.
"""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest
import xarray as xr

import semi_bem
from capytaine_to_wamit import export_drift
from test_bem import havelock

REPO = pathlib.Path(__file__).resolve().parents[2]
OMEGAS = np.array([0.7, 1.0, 1.3])
HEADINGS_DEG = np.array([30.0, 90.0, 150.0])
RADIUS = 5.0
OFFSET = (20.0, 10.0)


def slowdrift_binary():
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    if not target.is_absolute():
        target = REPO / target
    binary = target / "release" / "slowdrift"
    if not binary.is_file():
        pytest.fail(f"{binary} is absent: run `cargo test --release --workspace` first "
                    "(tests/run_all.sh does)")
    return binary


def cylinder(xc, yc):
    import capytaine as cpt
    mesh = cpt.mesh_vertical_cylinder(length=60.0, radius=RADIUS, center=(xc, yc, -30.0),
                                      resolution=(6, 48, 40)).immersed_part()
    return cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(xc, yc, -10.0)),
                            center_of_mass=(xc, yc, -10.0))


def capytaine_database(xc, yc, directory):
    """The drift of the cylinder centred at (xc, yc), held fixed, through capytaine_to_wamit
    (Capytaine's solution and `.8` writer) and `slowdrift hydro wamit`: the database's JSON."""
    body = cylinder(xc, yc)
    bem = semi_bem.solve_body(body, OMEGAS, np.radians(HEADINGS_DEG), 144)
    root = directory / "cylinder"
    export_drift(bem, np.zeros_like(bem["excitation"]), root)
    out = directory / "cylinder.json"
    run = subprocess.run([slowdrift_binary(), "hydro", "wamit", "--root", root,
                          "--rho", str(semi_bem.RHO), "--g", str(semi_bem.G), "--out", out],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "bi-directional drift on every pair" in run.stdout, run.stdout
    return json.loads(out.read_text())


def table(database):
    """T[n, p, q, i] of the database's bi-directional drift (SlowDrift's convention)."""
    t = database["bidirectional_drift"]
    return np.array(t["re"]) + 1j * np.array(t["im"])


@pytest.fixture(scope="module")
def databases(tmp_path_factory):
    centred = capytaine_database(0.0, 0.0, tmp_path_factory.mktemp("centred"))
    offset = capytaine_database(*OFFSET, tmp_path_factory.mktemp("offset"))
    return centred, offset


def test_imported_drift_against_havelock(databases):
    """One heading: Havelock's deep-water drift of a fixed cylinder, along the wave; the coarse
    mesh (48 panels round) is within 4 % of it."""
    centred, _ = databases
    t = table(centred)
    worst = 0.0
    for n, w in enumerate(centred["bidirectional_drift"]["omegas"]):
        expected = havelock(w**2 / semi_bem.G * RADIUS) * semi_bem.RHO * semi_bem.G * RADIUS
        for p, beta in enumerate(np.radians(HEADINGS_DEG)):
            f = t[n, p, p]
            assert abs(f[:2].imag).max() == 0.0
            magnitude = np.hypot(f[0].real, f[1].real)
            worst = max(worst, abs(magnitude / expected - 1))
            assert np.arctan2(f[1].real, f[0].real) == pytest.approx(beta, abs=1e-3)
    print(f"Capytaine through the WAMIT route vs Havelock: worst {100 * worst:.2f} %")
    assert worst < 0.04
    drift = {(round(p["omega"], 6), round(p["heading"], 6)): p for p in centred["drift"]}
    assert len(drift) == len(OMEGAS) * len(HEADINGS_DEG)


def test_two_headings_follow_the_physics_of_a_translated_cylinder(databases):
    """Moving the cylinder to x_c multiplies its two-heading force by e^{-i (k_k - k_l) . x_c}
    in SlowDrift's convention (the waves reach it with the phases e^{-i k . x_c}), which fixes
    the convention of the converted file; its yaw moment about the origin is x_c F_y - y_c F_x
    (no moment about its own axis), which fixes the yaw term's."""
    centred, offset = databases
    t0, tc = table(centred), table(offset)
    xc, yc = OFFSET
    beta = np.radians(HEADINGS_DEG)
    scale = np.abs(t0[..., :2]).max()
    for n, w in enumerate(centred["bidirectional_drift"]["omegas"]):
        k = w**2 / semi_bem.G
        phase = np.exp(-1j * k * ((np.cos(beta)[:, None] - np.cos(beta)[None, :]) * xc
                                  + (np.sin(beta)[:, None] - np.sin(beta)[None, :]) * yc))
        for i in range(2):
            assert np.abs(tc[n, :, :, i] - t0[n, :, :, i] * phase).max() < 0.01 * scale
            # The opposite convention would fail: it is not a round-off test.
            assert np.abs(tc[n, :, :, i] - t0[n, :, :, i] * phase.conj()).max() > 0.05 * scale
        moment = tc[n, :, :, 2]
        about = xc * tc[n, :, :, 1] - yc * tc[n, :, :, 0]
        assert np.abs(moment - about).max() < 3e-3 * np.abs(about).max()


def test_the_bidirectional_drift_runs_a_spread_sea(databases, tmp_path):
    """A cos^2 sea of three directions on the data's headings (30, 90, 150 deg), the drift
    and its cross terms from the imported table: `slowdrift simulate` runs it and says so."""
    centred, _ = databases
    database = tmp_path / "cylinder.json"
    database.write_text(json.dumps(centred))
    config = tmp_path / "spread.toml"
    config.write_text(f"""
[environment]
gravity = {semi_bem.G}
water_density = {semi_bem.RHO}

[sea]
spectrum = "jonswap"
hs = 3.0
tp = 7.0
spreading = "cos-n"
spreading_exponent = 2.0
direction_deg = 90.0
n_directions = 3
seed = 3
band = [0.7, 1.3]

[run]
duration = 3600.0
time_step = 1.0

[platform]
mass = 4.8e6
yaw_inertia = 6.0e7
stiffness = [[2.0e4, 0.0, 0.0], [0.0, 2.0e4, 0.0], [0.0, 0.0, 1.0e6]]
linear_damping = [[1.0e4, 0.0, 0.0], [0.0, 1.0e4, 0.0], [0.0, 0.0, 1.0e6]]

[model]
interaction = "bidirectional"
drift_damping = "off"

[drift]
source = "database"
file = "{database}"
""")
    run = subprocess.run([slowdrift_binary(), "simulate", "--config", config],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "3 directions, interaction between them: bidirectional" in run.stdout, run.stdout
    sway = next(line for line in run.stdout.splitlines() if line.startswith("sway"))
    print(run.stdout)
    # Waves towards +y on average: a positive mean sway drift.
    assert float(sway.split()[2]) > 0.0, sway


def capytaines_own_drift(body, omegas, headings, depth, theta):
    """Capytaine 3.0's own solution (its dataset, Kochin functions on `theta` included) and
    its own `far_field_mean_drift_force` of `body` held fixed, as Capytaine gives them."""
    import capytaine as cpt
    from capytaine.post_pro.mean_drift_force import far_field_mean_drift_force
    test_matrix = xr.Dataset(coords={
        "omega": omegas, "wave_direction": headings, "radiating_dof": list(body.dofs),
        "water_depth": depth, "rho": semi_bem.RHO, "g": semi_bem.G, "theta": theta})
    ds = cpt.BEMSolver().fill_dataset(test_matrix, body, progress_bar=False, hydrostatics=False)
    fixed = xr.DataArray(np.zeros((len(omegas), len(headings), len(body.dofs)), complex),
                         coords={"omega": omegas, "wave_direction": headings,
                                 "radiating_dof": list(body.dofs)},
                         dims=("omega", "wave_direction", "radiating_dof"))
    return ds, far_field_mean_drift_force(fixed, ds)


def test_capytaines_own_two_heading_yaw_misses_the_moment_identity():
    """What the converter corrects: Capytaine 3.0's own `far_field_mean_drift_force` on the
    offset cylinder (its forces conjugated to SlowDrift's convention; the yaw as it comes)
    misses M = x_c F_y - y_c F_x for two headings, by far more than the mesh's error, in a way
    no conjugation of the yaw term repairs."""
    _, drift = capytaines_own_drift(cylinder(*OFFSET), OMEGAS[1:2], np.radians(HEADINGS_DEG),
                                    np.inf, np.linspace(0.0, 2 * np.pi, 361))
    fx, fy = np.conj(drift["drift_force_surge"].values[0]), np.conj(drift["drift_force_sway"].values[0])
    mz = drift["drift_force_yaw"].values[0]
    about = OFFSET[0] * fy - OFFSET[1] * fx
    scale = np.abs(about).max()
    misses = [np.abs(m - about).max() / scale for m in (mz, np.conj(mz))]
    print(f"Capytaine's own two-heading yaw vs x_c F_y - y_c F_x: {100 * misses[0]:.1f} % "
          f"(conjugated: {100 * misses[1]:.1f} %) of the largest moment")
    assert min(misses) > 0.05
    # The single-heading yaw is right (the diagonal).
    assert np.abs(np.diag(mz) - np.diag(about)).max() < 3e-3 * scale


def test_capytaines_finite_depth_drift_falls_short_at_low_kh():
    """What we found about Capytaine 3.0's far-field drift in finite depth,
    and why the route above is deep water only. A bottom-mounted cylinder (radius 5 m, depth
    20 m, no panels on the seabed), held fixed, in waves of 0.5, 0.7, 1.0 and 1.3 rad/s
    (kh = 0.78, 1.20, 2.10, 3.45):

    - its first-order solution is right: the surge excitation is MacCamy and Fuchs's,
      |F| = 4 rho g A tanh(kh) / (k^2 |H1'(ka)|), within 2 % at every kh;
    - its `far_field_mean_drift_force` matches the closed form of
      docs/theory.md#checks-with-known-answers
      (Havelock's sum times 1 + 2kh / sinh 2kh) within the mesh's 4 % for kh >= 2, and falls
      short of it as kh falls: by more than 30 % at kh = 0.78 and 10 % at kh = 1.2;
    - the cause is in its drift coefficients, not the solution: for a fixed body, energy
      conservation ties the forward-scattering term to the scattered energy, so the two
      coefficients of the formula (coef1 = 2 pi rho omega on the linear term, coef2 = 2 pi rho m
      (k0 h)^2 / (h ((m h)^2 - (k0 h)^2 + k0 h)) on the quadratic, post_pro/mean_drift_force.py)
      must balance them, and with Capytaine's own Kochin function they are out of balance by
      1 / tanh(m h) (to 1 %), which is 1 in deep water. Which coefficient is wrong, and whether
      that is all, is not settled here: scaling either one by tanh(m h) restores the balance
      but not, by itself, the closed form.
    If a later Capytaine corrects this, this test fails and docs/bem.md must say so."""
    import capytaine as cpt
    from scipy.optimize import brentq
    from scipy.special import h1vp
    depth, rho, g = 20.0, semi_bem.RHO, semi_bem.G
    mesh = cpt.mesh_vertical_cylinder(length=depth + 2.0, radius=RADIUS,
                                      center=(0.0, 0.0, 1.0 - depth / 2),
                                      resolution=(6, 48, 16)).immersed_part()
    mesh = mesh.extract_faces([i for i, c in enumerate(mesh.faces_centers)
                               if c[2] > -depth + 1e-6])
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, 0)),
                            center_of_mass=(0.0, 0.0, 0.0))
    omegas = np.array([0.5, 0.7, 1.0, 1.3])
    theta = np.linspace(-0.1, 2 * np.pi + 0.1, 721)  # heading 0 inside, as Capytaine asks
    ds, drift = capytaines_own_drift(body, omegas, np.array([0.0]), depth, theta)
    drift = drift["drift_force_surge"].values[:, 0, 0]
    excitation = (ds["diffraction_force"] + ds["Froude_Krylov_force"]).sel(
        influenced_dof="Surge", wave_direction=0.0).values
    kochin = 1j * ds["kochin_diffraction"].sel(wave_direction=0.0).values
    whole = (theta >= 0.0) & (theta <= 2 * np.pi)
    ratios = []
    for n, w in enumerate(omegas):
        k = brentq(lambda k: g * k * np.tanh(k * depth) - w * w, 1e-9, 10.0)
        kh, ka = k * depth, k * RADIUS
        maccamy_fuchs = 4 * rho * g * np.tanh(kh) / (k**2 * abs(h1vp(1, ka)))
        assert abs(excitation[n]) == pytest.approx(maccamy_fuchs, rel=0.02)
        closed = havelock(ka) * (1 + 2 * kh / np.sinh(2 * kh)) * rho * g * RADIUS
        assert abs(drift[n].imag) < 1e-9 * abs(drift[n])
        ratios.append(drift[n].real / closed)
        k0 = w * w / g
        coef1 = 2 * np.pi * rho * w
        coef2 = 2 * np.pi * rho * k * (k0 * depth) ** 2 / (depth * (kh**2 - (k0 * depth) ** 2
                                                                    + k0 * depth))
        forward = -np.interp(0.0, theta, kochin[n].imag)
        scattered = np.trapezoid(np.abs(kochin[n][whole]) ** 2, theta[whole])
        balance = coef1 * forward / (coef2 * scattered)
        print(f"kh = {kh:.2f}: Capytaine's drift / closed form {ratios[-1]:.3f}, excitation / "
              f"MacCamy-Fuchs {abs(excitation[n]) / maccamy_fuchs:.3f}, energy balance of its "
              f"coefficients {balance:.3f} against 1 / tanh(kh) = {1 / np.tanh(kh):.3f}")
        assert balance == pytest.approx(1 / np.tanh(kh), rel=0.01)
    assert abs(ratios[2] - 1) < 0.04 and abs(ratios[3] - 1) < 0.04
    assert ratios[0] < 0.7 and ratios[1] < 0.9
