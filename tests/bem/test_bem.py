"""Checks of the default platform's radiation-diffraction data, run by
tests/bem/run_bem.sh in the README's test command.

Independent routes: closed forms of the geometry, Havelock's drift of a deep cylinder, the
moment identity of an offset cylinder, and a fresh Capytaine solution on the coarsest mesh
against the committed database (so the data cannot drift from its scripts).
"""

import json
import pathlib

import numpy as np
import pytest
import xarray as xr
from scipy.special import h1vp

import make_database
import semi_bem
import semi_mesh as geometry
import solve_platform

REPO = pathlib.Path(__file__).resolve().parents[2]
DATABASE = REPO / "src" / "hydro" / "default_platform.json"
BIDIRECTIONAL = REPO / "src" / "hydro" / "default_platform_bidirectional.json"
MODEL = REPO / "tests" / "bem" / "platform_model.json"


def inside(x, y, lower):
    """Points of a horizontal section of the solid: the columns, and below the pontoons'
    top the pontoons too (a direct description, not the meshing's)."""
    c, r, half_width = geometry.HALF_SPACING, geometry.RADIUS, geometry.PONTOON_WIDTH / 2
    hit = np.zeros_like(x, bool)
    for sx in (-1, 1):
        for sy in (-1, 1):
            hit |= (x - sx * c) ** 2 + (y - sy * c) ** 2 <= r**2
    if lower:
        along_x = (np.abs(np.abs(y) - c) <= half_width) & (np.abs(x) <= c)
        along_y = (np.abs(np.abs(x) - c) <= half_width) & (np.abs(y) <= c)
        hit |= along_x | along_y
    return hit


def test_section_integrals_match_a_grid_integration():
    """Area and second moment of both sections by the closed forms used for the mass
    properties, against a midpoint rule on a 2 cm grid of the direct description."""
    h = 0.02
    axis = np.arange(-45.0 + h / 2, 45.0, h)
    for (area, xx), lower in zip(semi_bem.section_integrals(), (False, True)):
        grid_area = grid_xx = 0.0
        for row in np.array_split(axis, 30):
            x, y = np.meshgrid(axis, row)
            hit = inside(x, y, lower)
            grid_area += hit.sum() * h * h
            grid_xx += (x**2 * hit).sum() * h * h
        assert grid_area == pytest.approx(area, rel=2e-4)
        assert grid_xx == pytest.approx(xx, rel=2e-4)


def test_mesh_is_closed_and_converges_to_the_volume():
    """The panels enclose the hull (the three divergence-theorem volumes agree), and the
    volume approaches the closed form as the polygons of the circles refine."""
    errors = []
    for size in (4.0, 2.5):
        mesh = geometry.platform_mesh(size).merged()
        volumes = np.array(mesh.volumes)
        assert np.ptp(volumes) < 1e-9 * volumes.mean()
        errors.append(abs(mesh.volume / geometry.VOLUME - 1))
    assert errors[1] < errors[0] and errors[1] < 2e-3


def cylinder_drift(xc, yc, omegas, headings):
    """Far-field drift pairs of a fixed vertical cylinder of radius 5 m and draft 60 m
    (deep enough to be infinitely deep at these frequencies) centred at (xc, yc)."""
    import capytaine as cpt
    mesh = cpt.mesh_vertical_cylinder(length=60.0, radius=5.0, center=(xc, yc, -30.0),
                                      resolution=(6, 48, 40)).immersed_part()
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(xc, yc, -10.0)),
                            center_of_mass=(xc, yc, -10.0))
    bem = semi_bem.solve_body(body, omegas, headings, 144)
    return semi_bem.far_field_drift(bem, np.zeros_like(bem["excitation"]))


def havelock(ka):
    """Havelock's mean drift of a fixed, infinitely deep cylinder / (rho g A^2 a)."""
    n = np.arange(0, int(ka) + 25)
    terms = (1 - n * (n + 1) / ka**2) ** 2 / (np.abs(h1vp(n, ka)) ** 2 * np.abs(h1vp(n + 1, ka)) ** 2)
    return 4 / (np.pi**2 * ka**3) * terms.sum()


def test_far_field_drift_of_a_cylinder():
    """One heading: Havelock's closed form, in the wave's direction. Two headings: the yaw
    moment about the origin is x_c F_y - y_c F_x (a vertical cylinder has no moment about its
    own axis), which Capytaine 3.0's own two-heading yaw term fails by a conjugation."""
    omegas = np.array([0.8, 1.2])
    headings = np.radians([0.0, 30.0, 100.0])
    xc, yc = 20.0, 10.0
    t = cylinder_drift(xc, yc, omegas, headings)
    for n, w in enumerate(omegas):
        expected = havelock(w**2 / semi_bem.G * 5.0) * semi_bem.RHO * semi_bem.G * 5.0
        for i, beta in enumerate(headings):
            f = t[n, i, i]
            assert np.abs(f.imag).max() < 1e-9 * abs(f[0])
            assert np.hypot(f[0].real, f[1].real) == pytest.approx(expected, rel=0.04)
            assert np.arctan2(f[1].real, f[0].real) == pytest.approx(np.angle(np.exp(1j * beta)), abs=1e-3)
        moment = t[n, :, :, 2]
        about_centre = xc * t[n, :, :, 1] - yc * t[n, :, :, 0]
        assert np.abs(moment - about_centre).max() < 3e-3 * np.abs(about_centre).max()


@pytest.fixture(scope="module")
def database():
    return json.loads(DATABASE.read_text()), json.loads(BIDIRECTIONAL.read_text())


def test_coarse_mesh_reproduces_the_database(database):
    """Capytaine on the coarsest mesh of the convergence study (3 m panels) at two
    frequencies of the database, with the committed 6-DOF model, gives the database's mean
    and bi-directional drift within 3 % of the largest value of each component there (the
    study's change from 3 m to 2 m panels is at most 1.6 %), and its RAOs within 3 % of each
    DOF's largest there."""
    model = json.loads(MODEL.read_text())
    omegas = np.array([0.52, 1.0])
    bem = semi_bem.solve(3.0, omegas, solve_platform.HEADINGS, solve_platform.N_THETA)
    matrices = [np.array(model[k]) for k in ("inertia", "stiffness", "viscous_damping")]
    t = make_database.slowdrift_drift(bem, *matrices)
    rao = make_database.slowdrift_rao(semi_bem.motions(bem, *matrices),
                                      model["centre_of_gravity_z"])
    database, table = database
    stored = database["rao"]
    assert np.allclose(stored["headings"], solve_platform.HEADINGS)
    at = [int(np.argmin(np.abs(np.array(stored["omegas"]) - w))) for w in omegas]
    assert np.allclose(np.array(stored["omegas"])[at], omegas)
    stored = (np.array(stored["re"]) + 1j * np.array(stored["im"]))[at]
    change = np.abs(rao - stored).max(axis=(0, 1)) / np.abs(stored).max(axis=(0, 1))
    print("RAOs of the 3 m mesh against the database's, per DOF:", np.round(change, 4))
    assert (change < 0.03).all()
    headings = np.array(table["headings"])
    assert np.allclose(headings, solve_platform.HEADINGS)
    for n, w in enumerate(omegas):
        points = {round(p["heading"], 9): p for p in database["drift"] if abs(p["omega"] - w) < 1e-9}
        stored = np.array([[points[round(b, 9)][k] for k in ("surge", "sway", "yaw")] for b in headings])
        fresh = np.einsum("kkd->kd", t[n]).real
        scale = np.abs(stored).max(axis=0)
        assert (np.abs(fresh - stored) <= 0.03 * scale).all(), (w, np.abs(fresh - stored) / scale)
        m = int(np.argmin(np.abs(np.array(table["omegas"]) - w)))
        assert abs(table["omegas"][m] - w) < 1e-9
        pairs = np.array(table["re"][m]) + 1j * np.array(table["im"][m])
        scale = np.abs(pairs).max(axis=(0, 1))
        assert (np.abs(t[n] - pairs) <= 0.03 * scale).all(), w


def test_coarse_mesh_reproduces_the_low_frequency_added_mass(database):
    """The database's low-frequency added mass (surge, sway, yaw; the default's [platform]
    added_mass) is a fresh 3 m mesh solution's at 0.04 rad/s within 1.5 % (the convergence
    study's change of A11 from 3 m to 2 m panels is under 1 %)."""
    database, _ = database
    bem = semi_bem.solve(3.0, [make_database.SLOW], solve_platform.HEADINGS[:1],
                         solve_platform.N_THETA)
    fresh = bem["added_mass"][0][np.ix_(make_database.SLOW_DOFS, make_database.SLOW_DOFS)]
    stored = np.array(database["low_frequency_added_mass"])
    for i in range(3):
        assert stored[i][i] == pytest.approx(fresh[i, i], rel=0.015), (i, stored[i][i], fresh[i, i])


def rao_solution(body, omegas, headings, inertia, hydrostatics):
    """Capytaine's dataset of `body` (deep water) with the body's inertia and hydrostatic
    stiffness given the way Capytaine's `rao` reads them (on the body, copied into the
    dataset by fill_dataset), and the same solution as semi_bem.solve's plain arrays."""
    import capytaine as cpt
    body.inertia_matrix = body.add_dofs_labels_to_matrix(inertia)
    body.hydrostatic_stiffness = body.add_dofs_labels_to_matrix(hydrostatics)
    test_matrix = xr.Dataset(coords={
        "omega": omegas, "wave_direction": headings, "radiating_dof": list(body.dofs),
        "water_depth": [np.inf], "rho": [semi_bem.RHO], "g": [semi_bem.G]})
    ds = cpt.BEMSolver().fill_dataset(test_matrix, body, progress_bar=False, hydrostatics=True)
    square = ("omega", "influenced_dof", "radiating_dof")
    bem = {"omega": omegas, "heading": headings, "dofs": np.array(list(body.dofs)),
           "added_mass": ds["added_mass"].transpose(*square).values,
           "radiation_damping": ds["radiation_damping"].transpose(*square).values,
           "excitation": ds["excitation_force"].transpose(
               "omega", "wave_direction", "influenced_dof").values}
    return ds, bem


def test_rao_route_against_capytaines_own_rao():
    """The route make_database writes the database's `rao` with (semi_bem.motions, then
    make_database.slowdrift_rao) on a fresh solution of the platform (4 m panels, near the
    heave resonance and at the sea's peak, head, oblique and beam seas), with the committed
    6-DOF model, against Capytaine's own `capytaine.post_pro.rao` (inertia and hydrostatic
    stiffness on the body, the mooring as its `stiffness`, the viscous damping as its
    `dissipation`):

    - the same solution, DOFs about the centre of gravity G: semi_bem.motions is Capytaine's
      RAO to round-off;
    - a second body whose rotations are about the body origin O, solved afresh by Capytaine,
      with the model moved to O by the kinematics of a rigid body, q_G = T q_O (t_G = t_O +
      theta x (G - O)), so that each matrix K becomes T^T K T (the same energies; the
      mooring acts on G's displacement): its RAO, conjugated to SlowDrift's e^{+i omega t},
      is the route's to round-off. The route without its conjugation, or without moving the
      translations to O, misses it by far.

    Conventions: Capytaine's RAOs are per unit amplitude of Re[e^{i k (x cos b + y sin b) -
    i omega t}], SlowDrift's of Re[e^{i (omega t - k (x cos b + y sin b))}]; both headings are
    the direction the wave travels towards, from +x."""
    model = json.loads(MODEL.read_text())
    inertia, stiffness = np.array(model["inertia"]), np.array(model["stiffness"])
    mooring, damping = np.array(model["mooring_stiffness"]), np.array(model["viscous_damping"])
    hydrostatics = stiffness - mooring
    props = semi_bem.mass_properties()
    z_g = props["z_g"]
    omegas = np.array([0.24, 0.52])
    headings = np.radians([0.0, 30.0, 90.0])
    from capytaine.post_pro.rao import rao

    def capytaine(ds, mooring, damping):
        labelled = lambda m: xr.DataArray(m, dims=("influenced_dof", "radiating_dof"),
                                          coords={"influenced_dof": ds["influenced_dof"].values,
                                                  "radiating_dof": ds["radiating_dof"].values})
        x = rao(ds, dissipation=labelled(damping), stiffness=labelled(mooring))
        return x.squeeze(drop=True).transpose("omega", "wave_direction", "radiating_dof").values

    about_g = semi_bem.floating_body(4.0, props)
    ds_g, bem_g = rao_solution(about_g, omegas, headings, inertia, hydrostatics)
    x_g = semi_bem.motions(bem_g, inertia, stiffness, damping)
    own_g = capytaine(ds_g, mooring, damping)
    scale = np.abs(own_g).max(axis=(0, 1))
    same = (np.abs(x_g - own_g).max(axis=(0, 1)) / scale).max()

    t = np.eye(6)
    t[0, 4], t[1, 3] = z_g, -z_g
    moved = lambda k: t.T @ k @ t
    about_o = semi_bem.floating_body(4.0, props, rotation_center=(0.0, 0.0, 0.0))
    ds_o, _ = rao_solution(about_o, omegas, headings, moved(inertia), moved(hydrostatics))
    own_o = np.conj(capytaine(ds_o, moved(mooring), moved(damping)))
    route = make_database.slowdrift_rao(x_g, z_g)
    scale = np.abs(own_o).max(axis=(0, 1))
    miss = lambda x: (np.abs(x - own_o).max(axis=(0, 1)) / scale).max()
    unconjugated = np.conj(route)
    untranslated = np.conj(x_g)
    print(f"RAO route vs Capytaine's rao: same solution (about G) {same:.1e}; about O, solved "
          f"afresh, {miss(route):.1e}; without the conjugation {miss(unconjugated):.2f}, "
          f"without the move to O {miss(untranslated):.2f} of each DOF's largest")
    assert same < 1e-10
    assert miss(route) < 1e-9
    assert miss(unconjugated) > 0.1 and miss(untranslated) > 0.1
