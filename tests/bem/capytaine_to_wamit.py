"""Capytaine's far-field mean drift as a WAMIT `.8` file that `slowdrift hydro wamit` reads
(docs/file-formats.md), for every pair of headings.

Capytaine 3.0 has the pieces: `far_field_mean_drift_force` (every pair of headings) and
`export_to_wamit` (the `.8` file, beta1 != beta2 rows included). Two things stand between them
and SlowDrift, found by tests/bem/test_capytaine_route.py with an offset cylinder:

- Convention. Capytaine's time factor is e^{-i w t} and its two-heading terms pair the first
  heading's amplitude unconjugated (F = sum A_k conj(A_l) T[k, l]); its export writes them as
  computed. With SlowDrift's (and WAMIT's) amplitudes a = conj(A), e^{i w t}, the values are
  the conjugates. The test tells the two apart by the phase a translation of the body adds,
  e^{-i (k_k - k_l) . x_c} in SlowDrift's convention.
- The two-heading yaw term. Capytaine's takes the heading indices of its Kochin products the
  other way round from its force terms (docs/file-formats.md#wamit-import-and-the-hydro-database).
  The test finds the two-heading
  yaw moment about the origin of an offset cylinder (at (20, 10) m, 1 rad/s) off
  x_c F_y - y_c F_x by 218 % of the largest moment, and by 81 % when conjugated: not something
  a converter of the written file could undo. The term is recomputed from the Kochin functions.

So `export_drift` computes the drift with Capytaine's far-field formula, the yaw term in the
order of the force terms (semi_bem.far_field_drift, the formula the default platform's data
come from), conjugates it to SlowDrift's convention and writes it with Capytaine's own
`export_to_wamit`.

Deep water only (semi_bem.solve_body solves in deep water): Capytaine 3.0's far-field drift in
finite depth falls short of the closed form at low kh (docs/bem.md, measured by the route's
last test).

Usage (a library function; the test and tests/bem's scripts call it):
    bem = semi_bem.solve_body(body, omegas, headings, n_theta)   # headings on the theta grid
    export_drift(bem, motions, "PATH/NAME")                      # writes PATH/NAME.8
then `slowdrift hydro wamit --root PATH/NAME --out NAME.json`.
"""

import numpy as np
import xarray as xr

import semi_bem


def drift_dataset(bem, motions):
    """The drift of `bem` (semi_bem.solve_body's arrays) with the body moving as `motions`
    (omega, heading, dof; zeros for a fixed body) as Capytaine's drift variables, in
    SlowDrift's convention."""
    t = np.conj(semi_bem.far_field_drift(bem, motions))  # [omega, k, l, (surge, sway, yaw)]
    dims = ("omega", "wave_direction_k", "wave_direction_l")
    coords = {"omega": bem["omega"], "period": ("omega", 2 * np.pi / bem["omega"]),
              "wave_direction_k": bem["heading"], "wave_direction_l": bem["heading"],
              "rho": semi_bem.RHO, "g": semi_bem.G}
    return xr.Dataset({name: (dims, t[..., i]) for i, name in enumerate(
        ["drift_force_surge", "drift_force_sway", "drift_force_yaw"])}, coords=coords)


def export_drift(bem, motions, root):
    """Writes `root`.8 from `bem` (see drift_dataset) with Capytaine's `export_to_wamit`
    (which logs a failure instead of raising it: an absent file is an error here)."""
    import pathlib
    from capytaine.io.wamit import export_to_wamit
    path = pathlib.Path(f"{root}.8")
    path.unlink(missing_ok=True)
    export_to_wamit(drift_dataset(bem, motions), str(root), exports=("8",))
    if not path.is_file():
        raise RuntimeError(f"Capytaine's export_to_wamit did not write {path}")
