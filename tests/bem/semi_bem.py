"""Radiation-diffraction solution of the paper's platform with Capytaine.

The platform floats freely in deep water with its own mass, inertia and hydrostatics, plus
the mooring's weak horizontal stiffness and a stated linear viscous damping in heave, roll
and pitch; its first-order motions (RAOs) enter the mean drift, computed from the far-field
Kochin function (Maruo's momentum balance; Capytaine 3.0 gives no near-field drift).

Conventions. Capytaine's: time factor e^{-i omega t}, incident wave of unit amplitude
eta = Re[e^{i k (x cos b + y sin b) - i omega t}], phase at the origin. SlowDrift's (the
database, `hydro::bidirectional`): Re[a e^{i omega t}], phase at the body origin, and
F = sum_{p,q} a_p conj(a_q) T(b_p, b_q). A SlowDrift amplitude is the conjugate of
Capytaine's, so T_slowdrift = conj(T_capytaine) (checked in Rust against the column solver at
the frequencies where the pontoons and the draft no longer matter). Frame: x, y horizontal,
z up, origin at the waterplane's centre; forces in N, moments in N m, per unit amplitude
squared (N/m^2, N m/m^2).
"""

import numpy as np
import xarray as xr

import semi_mesh as geometry

RHO = 1025.0
G = 9.80665


def section_integrals():
    """Area and integral of x^2 of the two horizontal sections, exact geometry.

    Upper (z in [-16, 0]): the four columns. Lower (z in [-30, -16]): the square ring
    [-45, 45]^2 minus [-25, 25]^2 less its four outer corners beyond the columns (each the
    square [35, 45]^2 less the column's quarter section)."""
    r, c = geometry.RADIUS, geometry.HALF_SPACING
    area_upper = 4 * np.pi * r**2
    xx_upper = 4 * (np.pi * r**4 / 4 + np.pi * r**2 * c**2)
    outer, inner = c + r, c - r
    ring_area = (2 * outer) ** 2 - (2 * inner) ** 2
    ring_xx = 2 * outer * 2 * outer**3 / 3 - 2 * inner * 2 * inner**3 / 3
    corner_square_xx = r * ((c + r) ** 3 - c**3) / 3
    quarter_disc_xx = c**2 * np.pi * r**2 / 4 + 2 * c * r**3 / 3 + np.pi * r**4 / 16
    corner_area = r**2 - np.pi * r**2 / 4
    area_lower = ring_area - 4 * corner_area
    xx_lower = ring_xx - 4 * (corner_square_xx - quarter_disc_xx)
    return (area_upper, xx_upper), (area_lower, xx_lower)


def mass_properties(rho=RHO):
    """Uniformly dense platform floating at its draft: mass = rho V, centre of gravity at
    the centre of buoyancy, inertia of the solid. Returns (mass, z_G, I_xx, I_yy, I_zz), with
    the inertias about the centre of gravity (I_zz is the yaw inertia about the vertical axis
    through the body origin, the same axis)."""
    (a_u, xx_u), (a_l, xx_l) = section_integrals()
    h_u, h_l = -geometry.PONTOON_TOP, geometry.PONTOON_HEIGHT
    volume = a_u * h_u + a_l * h_l
    # z moments: upper layer z in [-16, 0], lower z in [-30, -16].
    z1 = a_u * (0 - geometry.PONTOON_TOP**2) / 2 + a_l * (geometry.PONTOON_TOP**2 - geometry.DRAFT**2) / 2
    z_g = z1 / volume

    def z2(a, lo, hi):
        return a * ((hi - z_g) ** 3 - (lo - z_g) ** 3) / 3

    zz = z2(a_u, geometry.PONTOON_TOP, 0.0) + z2(a_l, -geometry.DRAFT, geometry.PONTOON_TOP)
    xx = xx_u * h_u + xx_l * h_l  # = yy by symmetry
    mass = rho * volume
    return {"volume": volume, "mass": mass, "z_g": z_g, "i_xx": rho * (xx + zz),
            "i_yy": rho * (xx + zz), "i_zz": rho * 2 * xx}


def rigid_body_matrices(props, g=G):
    """6 x 6 inertia about the centre of gravity, and the hydrostatic stiffness of the exact
    waterplane (centre of gravity at the centre of buoyancy: C44 = C55 = rho g I_wp)."""
    m = props["mass"]
    inertia = np.diag([m, m, m, props["i_xx"], props["i_yy"], props["i_zz"]])
    stiffness = np.zeros((6, 6))
    stiffness[2, 2] = RHO * g * geometry.WATERPLANE_AREA
    stiffness[3, 3] = stiffness[4, 4] = RHO * g * geometry.WATERPLANE_INERTIA
    return inertia, stiffness


def symmetric(quarter):
    import capytaine as cpt
    half = cpt.ReflectionSymmetricMesh(half=quarter, plane="xOz")
    return cpt.ReflectionSymmetricMesh(half=half, plane="yOz")


def floating_body(size, props, rotation_center=None):
    """The platform's wetted surface (panels of about `size` m) with a lid on its waterplane
    (Capytaine's extended boundary integral, which removes the irregular frequencies; the
    first of the columns' interior lies near 1.5 rad/s, inside the band), six rigid DOFs
    about the centre of gravity (or about `rotation_center`)."""
    import capytaine as cpt
    quarter = geometry.quarter_mesh(size)
    mesh = symmetric(quarter)
    lid = symmetric(quarter.generate_lid())
    centre = (0.0, 0.0, props["z_g"])
    rotation_center = centre if rotation_center is None else rotation_center
    return cpt.FloatingBody(mesh=mesh, lid_mesh=lid,
                            dofs=cpt.rigid_body_dofs(rotation_center=rotation_center),
                            center_of_mass=centre, mass=props["mass"], name=f"platform {size} m")


def solve(size, omegas, headings, n_theta, chunk=4):
    """Capytaine's solution as plain arrays: added mass, radiation damping (omega, dof, dof),
    excitation (omega, heading, dof), Kochin functions of the radiation (omega, dof, theta)
    and diffraction (omega, heading, theta) problems at n_theta angles over [0, 2 pi).

    The frequencies are solved `chunk` at a time, each chunk in a fresh process: Capytaine
    3.0 keeps about 0.5 GB per frequency of a 4400-panel mesh after each solution, which
    over a hundred frequencies exceeds the memory."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    omegas = np.asarray(omegas, float)
    chunks = [omegas[i:i + chunk] for i in range(0, len(omegas), chunk)]
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=1, mp_context=context, max_tasks_per_child=1) as pool:
        parts = list(pool.map(_solve_frequencies,
                              [(size, part, headings, n_theta) for part in chunks]))
    out = dict(parts[0])
    for name in ["omega", "wavenumber", "added_mass", "radiation_damping", "excitation",
                 "kochin_radiation", "kochin_diffraction"]:
        out[name] = np.concatenate([p[name] for p in parts])
    return out


def _solve_frequencies(task):
    """solve() for a few frequencies, in this process."""
    import capytaine as cpt
    size, omegas, headings, n_theta = task
    body = floating_body(size, mass_properties())
    out = solve_body(body, omegas, headings, n_theta)
    out.update({"size": size, "panels": body.mesh.nb_faces,
                "lid_panels": body.lid_mesh.nb_faces, "capytaine_version": cpt.__version__})
    return out


def solve_body(body, omegas, headings, n_theta):
    """Capytaine's solution for `body` in deep water as plain arrays (solve()'s, without the
    mesh's description), checked for the order of Capytaine's dimensions and coordinates."""
    import capytaine as cpt
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    test_matrix = xr.Dataset(coords={
        "omega": np.asarray(omegas, float), "wave_direction": np.asarray(headings, float),
        "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [RHO], "g": [G],
        "theta": theta})
    ds = cpt.BEMSolver().fill_dataset(test_matrix, body, progress_bar=False, hydrostatics=False)
    names = {"added_mass": ("omega", "influenced_dof", "radiating_dof"),
             "radiation_damping": ("omega", "influenced_dof", "radiating_dof"),
             "excitation_force": ("omega", "wave_direction", "influenced_dof"),
             "kochin_radiation": ("omega", "radiating_dof", "theta"),
             "kochin_diffraction": ("omega", "wave_direction", "theta")}
    for name, dims in names.items():
        if ds[name].dims != dims:
            raise RuntimeError(f"Capytaine's {name} has dimensions {ds[name].dims}, not {dims}")
    if ([str(d) for d in ds["radiating_dof"].values] != list(body.dofs)
            or not np.allclose(ds["theta"].values, theta)
            or not np.allclose(ds["wave_direction"].values, headings)
            or not np.allclose(ds["omega"].values, omegas)):
        raise RuntimeError("Capytaine reordered the frequencies, DOFs, headings or angles")
    return {
        "omega": np.asarray(omegas, float), "wavenumber": ds["wavenumber"].values,
        "heading": np.asarray(headings, float), "theta": theta,
        "dofs": np.array(list(body.dofs)),
        "added_mass": ds["added_mass"].values,
        "radiation_damping": ds["radiation_damping"].values,
        "excitation": ds["excitation_force"].values,
        "kochin_radiation": ds["kochin_radiation"].values,
        "kochin_diffraction": ds["kochin_diffraction"].values,
    }


def motions(bem, inertia, stiffness, damping):
    """First-order motion amplitudes X[omega, heading, dof] per unit wave amplitude
    (Capytaine's convention): [-omega^2 (M + A) - i omega (B + B_v) + C] X = F_exc."""
    out = np.empty_like(bem["excitation"])
    for n, w in enumerate(bem["omega"]):
        z = (-w**2 * (inertia + bem["added_mass"][n])
             - 1j * w * (bem["radiation_damping"][n] + damping) + stiffness)
        out[n] = np.linalg.solve(z, bem["excitation"][n].T).T
    return out


def _spectral_derivative(values):
    """d/dtheta along the last axis of values on a uniform periodic grid."""
    n = values.shape[-1]
    wavenumbers = np.fft.fftfreq(n, 1.0 / n)
    if n % 2 == 0:
        wavenumbers[n // 2] = 0.0
    return np.fft.ifft(1j * wavenumbers * np.fft.fft(values, axis=-1), axis=-1)


def far_field_drift(bem, x):
    """Mean drift T[omega, k, l, (surge, sway, yaw)] for every pair of headings (b_k, b_l),
    Capytaine's convention (F = sum a_k conj(a_l) T[k, l] with Capytaine's amplitudes), by the
    far-field momentum and angular-momentum balance in deep water (Maruo 1960; Newman 1967 for
    the yaw moment): the interference of each incident wave with the total Kochin function in
    its own direction, less the flux of the radiated-and-scattered waves.

    Same formula as Capytaine's `far_field_mean_drift_force`, vectorised, with its two-heading
    yaw term taken in the order of the force terms (Capytaine's takes the heading indices the
    other way round, which conjugates it; tests/bem checks the moment of an offset cylinder).
    Headings must lie on the uniform theta grid of the Kochin functions."""
    omega, k, beta, theta = bem["omega"], bem["wavenumber"], bem["heading"], bem["theta"]
    n_theta = len(theta)
    d_theta = 2 * np.pi / n_theta
    if not np.allclose(theta, d_theta * np.arange(n_theta)):
        raise ValueError("the Kochin functions must be on a uniform grid over [0, 2 pi)")
    at = np.rint(np.mod(beta, 2 * np.pi) / d_theta).astype(int) % n_theta
    if not np.allclose(np.mod(beta - theta[at] + np.pi, 2 * np.pi) - np.pi, 0.0, atol=1e-9):
        raise ValueError("headings must lie on the theta grid")
    h_diff = bem["kochin_diffraction"]  # (omega, heading, theta)
    h_rad = bem["kochin_radiation"]  # (omega, dof, theta)
    h = 1j * (h_diff + np.einsum("ndt,nkd->nkt", h_rad, x))
    hp = _spectral_derivative(h)
    c1 = (2 * np.pi * RHO * omega)[:, None, None]
    c2 = (2 * np.pi * RHO * k**2)[:, None, None]
    kk = k[:, None, None]
    h_at = h[:, :, at]  # [n, k, l] = H_k(b_l)
    hp_at = hp[:, :, at]
    cos_b, sin_b = np.cos(beta), np.sin(beta)
    quad = lambda weight: np.einsum("nkt,nlt,t->nkl", h, np.conj(h), weight) * d_theta
    fx = (-c1 * (cos_b[None, None, :] * h_at - cos_b[None, :, None] * np.conj(h_at.transpose(0, 2, 1))) / 2j
          - c2 * quad(np.cos(theta)))
    fy = (-c1 * (sin_b[None, None, :] * h_at - sin_b[None, :, None] * np.conj(h_at.transpose(0, 2, 1))) / 2j
          - c2 * quad(np.sin(theta)))
    cross = (np.einsum("nlt,nkt->nkl", np.conj(h), hp) - np.einsum("nkt,nlt->nkl", h, np.conj(hp))) / 2j
    mz = (c1 / kk * (hp_at + np.conj(hp_at.transpose(0, 2, 1))) / 2 - c2 / kk * cross * d_theta)
    return np.stack([fx, fy, mz], axis=-1)
