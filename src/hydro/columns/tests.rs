use super::*;
use crate::hydro::column_drift::{far_field_drift_coefficient, havelock_drift_coefficient};
use crate::special::bessel::{bessel_j_y, hankel_derivatives};
use std::f64::consts::PI;

fn column(x: f64, y: f64, radius: f64) -> Cylinder {
    Cylinder {
        x,
        y,
        diameter: 2.0 * radius,
        draft: 30.0,
    }
}

/// The paper's platform: radius 10 m at (+-35, +-35) m.
fn square(half_side: f64, radius: f64) -> Vec<Cylinder> {
    [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
        .iter()
        .map(|&(sx, sy)| column(sx * half_side, sy * half_side, radius))
        .collect()
}

/// Four unequal columns without symmetry.
fn irregular() -> Vec<Cylinder> {
    vec![
        column(3.0, -2.0, 8.0),
        column(41.0, 12.0, 10.0),
        column(-20.0, 37.0, 6.0),
        column(-33.0, -25.0, 9.0),
    ]
}

/// omega giving wavenumber k in deep water or depth h.
fn omega_of(k: f64, depth: Option<f64>, g: f64) -> f64 {
    (g * k * depth.map_or(1.0, |h| (k * h).tanh())).sqrt()
}

fn magnitude(v: [f64; 3], lever: f64) -> f64 {
    v[0].hypot(v[1]).max(v[2].abs() / lever)
}

#[test]
fn dispersion_relation_is_solved_to_round_off() {
    let g = 9.80665;
    for i in 0..=60 {
        let y: f64 = 10f64.powf(-8.0 + 12.0 * i as f64 / 60.0);
        for h in [1.0, 50.0, 3000.0] {
            let omega = (y * g / h).sqrt();
            let k = wavenumber(omega, g, Some(h));
            let residual = g * k * (k * h).tanh() / (omega * omega) - 1.0;
            assert!(residual.abs() < 4e-15, "y = {y}, h = {h}: {residual}");
        }
    }
    // Deep-water limit and shallow-water limit k -> omega / sqrt(g h).
    assert_eq!(wavenumber(2.0, g, Some(1.0e4)), 4.0 / g);
    let (omega, h) = (1e-4, 10.0);
    let shallow = omega / (g * h).sqrt();
    // k h = 1e-4: the first correction is (kh)^2/6 = 1.7e-9.
    assert!((wavenumber(omega, g, Some(h)) / shallow - 1.0).abs() < 3e-9);
}

/// MacCamy & Fuchs: on one column F_x = 4 rho g A D/(k H'_1(ka)) e^{-i omega t} with
/// D = tanh(kh)/k (deep water 1/k), i.e. |F| = 4 rho g A tanh(kh)/(k^2 |H'_1|); in the
/// project's convention the complex amplitude is the conjugate.
#[test]
fn single_column_excitation_is_maccamy_fuchs() {
    let env = Environment::default();
    let rho_g = env.water_density * env.gravity;
    for depth in [None, Some(25.0), Some(200.0)] {
        let radius = 7.0;
        let array = ColumnArray::new(vec![column(0.0, 0.0, radius)], depth).unwrap();
        let omegas: Vec<f64> = [0.02, 0.3, 1.0, 4.0]
            .iter()
            .map(|&ka| omega_of(ka / radius, depth, env.gravity))
            .collect();
        let headings = [0.0, 0.4, 2.5];
        let hydro = array.solve(&env, &omegas, &headings).unwrap();
        for (iw, &k) in hydro.wavenumbers().iter().enumerate() {
            let h1 = hankel_derivatives(1, k * radius)[1];
            let tanh = depth.map_or(1.0, |h| (k * h).tanh());
            let along = (4.0 * rho_g * tanh / (k * k) / h1).conj();
            assert!(
                (along.norm() - 4.0 * rho_g * tanh / (k * k * h1.norm())).abs()
                    < 1e-14 * along.norm()
            );
            for (ih, &beta) in headings.iter().enumerate() {
                let f = hydro.excitation(ih, iw);
                let expected = [along * beta.cos(), along * beta.sin()];
                for i in 0..2 {
                    assert!(
                        (f[i] - expected[i]).norm() < 1e-12 * along.norm(),
                        "depth {depth:?} ka {} beta {beta}: {} vs {}",
                        k * radius,
                        f[i],
                        expected[i]
                    );
                }
                assert!(f[2].norm() < 1e-12 * along.norm() * radius);
            }
        }
    }
}

/// One column: both routes reproduce Havelock's series (times 1 + 2kh/sinh 2kh in finite
/// depth) along the wave direction, at every heading, and the closed-form far field.
#[test]
fn single_column_drift_is_havelock() {
    let env = Environment::default();
    let rho_g = env.water_density * env.gravity;
    let radius = 5.0;
    for depth in [None, Some(12.0), Some(80.0)] {
        let array = ColumnArray::new(vec![column(0.0, 0.0, radius)], depth).unwrap();
        let kas = [0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0, 60.0];
        let omegas: Vec<f64> = kas
            .iter()
            .map(|&ka| omega_of(ka / radius, depth, env.gravity))
            .collect();
        let headings = [0.0, 1.0, -2.0];
        let hydro = array.solve(&env, &omegas, &headings).unwrap();
        for (iw, &k) in hydro.wavenumbers().iter().enumerate() {
            let ka = k * radius;
            let s = depth.map_or(0.0, |h| 2.0 * k * h / (2.0 * k * h).sinh());
            let expected = rho_g * radius * havelock_drift_coefficient(ka, 1.0 + s);
            let far_closed = rho_g * radius * far_field_drift_coefficient(ka, 0.5 * (1.0 + s));
            assert!((far_closed - expected).abs() < 1e-10 * expected);
            for (ih, &beta) in headings.iter().enumerate() {
                for (route, f) in [
                    ("near", hydro.drift_near(ih, iw)),
                    ("far", hydro.drift_far(ih, iw)),
                ] {
                    let want = [expected * beta.cos(), expected * beta.sin(), 0.0];
                    // The far-field yaw is the difference of two terms of size rho g a^2
                    // (H ~ (ka)^2, divided by k^2) while the drift is rho g a (ka)^3: at small
                    // ka it carries an absolute round-off of ~1e-14 rho g a^2.
                    let floor = [0.0, 0.0, 1e-14 * rho_g * radius * radius];
                    for i in 0..3 {
                        assert!(
                            (f[i] - want[i]).abs() < 1e-10 * expected + floor[i],
                            "{route} depth {depth:?} ka {ka} beta {beta} [{i}]: {} vs {}",
                            f[i],
                            want[i]
                        );
                    }
                }
            }
        }
    }
}

/// H_n(x) and H'_n(x) for n = -n_max..=n_max (index n + n_max).
fn hankel_and_derivative(n_max: usize, x: f64) -> (Vec<Complex64>, Vec<Complex64>) {
    let (j, y) = bessel_j_y(n_max + 1, x);
    let h: Vec<Complex64> = (0..=n_max + 1)
        .map(|n| Complex64::new(j[n], y[n]))
        .collect();
    let dh: Vec<Complex64> = (0..=n_max)
        .map(|n| {
            if n == 0 {
                -h[1]
            } else {
                0.5 * (h[n - 1] - h[n + 1])
            }
        })
        .collect();
    let signed = |v: &[Complex64]| -> Vec<Complex64> {
        (0..=2 * n_max)
            .map(|i| {
                let n = i.abs_diff(n_max);
                if i < n_max && n % 2 == 1 {
                    -v[n]
                } else {
                    v[n]
                }
            })
            .collect()
    };
    (signed(&h), signed(&dh))
}

/// psi and grad psi at (x, y), summed directly from the scattering coefficients (no
/// addition theorem).
fn field(
    cylinders: &[Circle],
    k: f64,
    modes: usize,
    beta: f64,
    scattered: &[Complex64],
    (x, y): (f64, f64),
) -> (Complex64, [Complex64; 2]) {
    let width = 2 * modes + 1;
    let incident = Complex64::from_polar(1.0, k * (x * beta.cos() + y * beta.sin()));
    let mut psi = incident;
    let mut grad = [
        Complex64::new(0.0, k * beta.cos()) * incident,
        Complex64::new(0.0, k * beta.sin()) * incident,
    ];
    for (j, c) in cylinders.iter().enumerate() {
        let (dx, dy) = (x - c.x, y - c.y);
        let (r, t) = (dx.hypot(dy), dy.atan2(dx));
        let (h, dh) = hankel_and_derivative(modes, k * r);
        for i in 0..width {
            let n = i as f64 - modes as f64;
            let e = Complex64::from_polar(1.0, n * t) * scattered[j * width + i];
            let radial = e * k * dh[i];
            let angular = e * Complex64::new(0.0, n / r) * h[i];
            psi += e * h[i];
            grad[0] += radial * t.cos() - angular * t.sin();
            grad[1] += radial * t.sin() + angular * t.cos();
        }
    }
    (psi, grad)
}

/// The total field of the solved system satisfies d psi/dn = 0 on every column surface at
/// points between the collocation modes, and equals the surface expansion sum u_m e^{i m t}
/// there: this checks Graf's theorem with the angle convention used in the matrix.
#[test]
fn boundary_condition_holds_on_every_column() {
    for ka_max in [0.05f64, 0.8, 3.0] {
        let columns = irregular();
        let cylinders: Vec<Circle> = columns
            .iter()
            .map(|c| Circle {
                x: c.x,
                y: c.y,
                radius: 0.5 * c.diameter,
            })
            .collect();
        let k = ka_max / 10.0;
        let array = ColumnArray::new(columns, None).unwrap();
        let modes = array.modes(k);
        let width = 2 * modes + 1;
        let system = FrequencySystem::new(&cylinders, k, modes).unwrap();
        let beta = 0.7;
        let solution = system.solve(&array.incident_matrix(&system, &[beta], false));
        let scattered = solution.scattered.as_slice();
        let surface = solution.surface.as_slice();
        for (c, cyl) in cylinders.iter().enumerate() {
            for l in 0..9 {
                let t = 0.31 + 2.0 * PI * l as f64 / 9.0;
                let point = (cyl.x + cyl.radius * t.cos(), cyl.y + cyl.radius * t.sin());
                let (psi, grad) = field(&cylinders, k, modes, beta, scattered, point);
                let normal = grad[0] * t.cos() + grad[1] * t.sin();
                assert!(
                    normal.norm() < 1e-12 * k,
                    "ka_max {ka_max}, column {c}, t {t}: d psi/dn = {normal}"
                );
                let expansion: Complex64 = (0..width)
                    .map(|i| {
                        let m = i as f64 - modes as f64;
                        surface[c * width + i] * Complex64::from_polar(1.0, m * t)
                    })
                    .sum();
                assert!(
                    (expansion - psi).norm() < 1e-10 * psi.norm().max(1.0),
                    "ka_max {ka_max}, column {c}: {expansion} vs {psi}"
                );
            }
        }
    }
}

/// Near field (pressure integration) and far field (Kochin function) agree for arrays of 2
/// and 4 columns, deep and finite depth, over k a_max from 0.01 to 8 and many headings.
#[test]
fn near_and_far_field_agree_for_arrays() {
    let env = Environment::default();
    let pair = vec![column(-15.0, 4.0, 6.0), column(18.0, -3.0, 9.0)];
    let mut worst: f64 = 0.0;
    for columns in [pair, square(35.0, 10.0), irregular()] {
        for depth in [None, Some(60.0)] {
            let array = ColumnArray::new(columns.clone(), depth).unwrap();
            let omegas: Vec<f64> = [0.001, 0.01, 0.1, 0.4, 1.0, 2.0, 4.0, 8.0]
                .iter()
                .map(|&ka| omega_of(ka / 10.0, depth, env.gravity))
                .collect();
            let headings: Vec<f64> = (0..13).map(|i| -PI + 0.5 * i as f64).collect();
            let hydro = array.solve(&env, &omegas, &headings).unwrap();
            for iw in 0..omegas.len() {
                for ih in 0..headings.len() {
                    let near = hydro.drift_near(ih, iw);
                    let far = hydro.drift_far(ih, iw);
                    let scale = magnitude(near, 50.0);
                    for i in 0..3 {
                        let lever = if i == 2 { 50.0 } else { 1.0 };
                        let error = (near[i] - far[i]).abs() / lever / scale;
                        worst = worst.max(error);
                        assert!(
                            error < 1e-8,
                            "depth {depth:?} iw {iw} ih {ih} [{i}]: {} vs {}",
                            near[i],
                            far[i]
                        );
                    }
                }
            }
        }
    }
    eprintln!("near vs far: worst relative difference {worst:e}");
}

/// A square array centred at the origin: at beta = 0 no sway and no yaw; at 45 deg surge
/// equals sway and again no yaw (mirror symmetries), for drift and excitation.
#[test]
fn square_array_symmetry() {
    let env = Environment::default();
    for depth in [None, Some(100.0)] {
        let array = ColumnArray::new(square(35.0, 10.0), depth).unwrap();
        let omegas = [0.2, 0.5, 0.8, 1.1, 1.6, 2.4];
        let headings = [0.0, 0.25 * PI];
        let hydro = array.solve(&env, &omegas, &headings).unwrap();
        for iw in 0..omegas.len() {
            let head = hydro.drift_near(0, iw);
            let scale = head[0].abs();
            assert!(head[1].abs() < 1e-11 * scale, "sway {:?}", head);
            assert!(head[2].abs() < 1e-11 * scale * 35.0, "yaw {:?}", head);
            let far = hydro.drift_far(0, iw);
            assert!(far[1].abs() < 1e-9 * scale && far[2].abs() < 1e-9 * scale * 35.0);
            let diagonal = hydro.drift_near(1, iw);
            assert!((diagonal[0] - diagonal[1]).abs() < 1e-11 * diagonal[0].abs());
            assert!(diagonal[2].abs() < 1e-11 * diagonal[0].abs() * 35.0);
            let f = hydro.excitation(0, iw);
            assert!(f[1].norm() < 1e-11 * f[0].norm() && f[2].norm() < 1e-11 * f[0].norm() * 35.0);
            let f = hydro.excitation(1, iw);
            assert!((f[0] - f[1]).norm() < 1e-11 * f[0].norm());
        }
    }
}

/// Two more modes than the rule change the drift and the exciting force by < 1e-8.
#[test]
fn two_more_modes_change_nothing() {
    let env = Environment::default();
    let mut worst: f64 = 0.0;
    for columns in [square(35.0, 10.0), irregular()] {
        let array = ColumnArray::new(columns, None).unwrap();
        let finer = array.clone().with_added_modes(2);
        let omegas: Vec<f64> = [0.01, 0.2, 1.0, 3.0, 8.0]
            .iter()
            .map(|&ka| omega_of(ka / 10.0, None, env.gravity))
            .collect();
        let headings = [0.3, 2.0];
        let coarse = array.solve(&env, &omegas, &headings).unwrap();
        let fine = finer.solve(&env, &omegas, &headings).unwrap();
        for iw in 0..omegas.len() {
            for ih in 0..headings.len() {
                let (a, b) = (coarse.drift_near(ih, iw), fine.drift_near(ih, iw));
                let scale = magnitude(b, 50.0);
                for i in 0..3 {
                    let lever = if i == 2 { 50.0 } else { 1.0 };
                    let change = (a[i] - b[i]).abs() / lever / scale;
                    worst = worst.max(change);
                    assert!(change < 1e-8, "iw {iw} ih {ih} [{i}]: {} vs {}", a[i], b[i]);
                }
                let (fa, fb) = (coarse.excitation(ih, iw), fine.excitation(ih, iw));
                let scale = fb[0].norm().hypot(fb[1].norm());
                assert!((fa[0] - fb[0]).norm() < 1e-8 * scale);
                assert!((fa[1] - fb[1]).norm() < 1e-8 * scale);
            }
        }
    }
    eprintln!("M + 2 vs M: worst relative drift change {worst:e}");
}

/// Two columns 1000 radii apart carry nearly the drift of two isolated columns. The
/// interaction is the cross term of the incident wave with the other column's scattered
/// wave, of amplitude ~ |H| sqrt(2/(pi k R)), with a phase k R (1 - cos(phi - beta)) that
/// turns with the spacing: its envelope (the largest deviation over one turn of the phase)
/// must fall like (k R)^{-1/2}, i.e. halve from 1000 a to 4000 a.
#[test]
fn far_apart_columns_approach_isolated_ones() {
    let env = Environment::default();
    let radius = 5.0;
    let omega = omega_of(1.0 / radius, None, env.gravity);
    let isolated = env.water_density * env.gravity * radius * havelock_drift_coefficient(1.0, 1.0);
    let beta = 0.4;
    let direction: f64 = 0.95f64.atan2(0.3);
    // One turn of the cross term's phase k R (1 - cos(phi - beta)), in radii (k a = 1).
    let turn = 2.0 * PI / (1.0 - (direction - beta).cos());
    let envelope = |spacing: f64| -> f64 {
        (0..8)
            .map(|i| {
                let distance = (spacing + turn * i as f64 / 8.0) * radius;
                let (dy, dx) = direction.sin_cos();
                let columns = vec![
                    column(0.0, 0.0, radius),
                    column(dx * distance, dy * distance, radius),
                ];
                let array = ColumnArray::new(columns, None).unwrap();
                let f = array
                    .solve(&env, &[omega], &[beta])
                    .unwrap()
                    .drift_near(0, 0);
                (f[0] - 2.0 * isolated * beta.cos()).hypot(f[1] - 2.0 * isolated * beta.sin())
                    / (2.0 * isolated)
            })
            .fold(0.0, f64::max)
    };
    let (near, far) = (envelope(1000.0), envelope(4000.0));
    eprintln!("interaction envelope: {near:e} at 1000 a, {far:e} at 4000 a");
    assert!(near < 2.0 / 1000f64.sqrt(), "{near}");
    let ratio = far / near;
    assert!(
        (ratio - 0.5).abs() < 0.1,
        "envelope ratio {ratio}, expected 1/2"
    );
}

/// Bi-directional drift: Hermitian, equal to the uni-directional drift on the diagonal, and
/// the mean force of two superposed waves (solved together) is sum a_p conj(a_q) T_pq.
#[test]
fn bidirectional_drift_is_hermitian_and_consistent() {
    let env = Environment::default();
    for depth in [None, Some(70.0)] {
        let array = ColumnArray::new(irregular(), depth).unwrap();
        let headings = [0.2, 1.3, -2.4, 3.0];
        let omega = 0.7;
        let t = array.bidirectional_drift(&env, omega, &headings).unwrap();
        let hydro = array.solve(&env, &[omega], &headings).unwrap();
        let scale = magnitude(hydro.drift_near(0, 0), 50.0);
        for p in 0..4 {
            let diagonal = t.get(p, p);
            let uni = hydro.drift_near(p, 0);
            for i in 0..3 {
                assert!((diagonal[i].re - uni[i]).abs() < 1e-12 * scale * 50.0);
                assert!(diagonal[i].im.abs() < 1e-12 * scale * 50.0);
            }
            for q in 0..4 {
                let (a, b) = (t.get(p, q), t.get(q, p));
                for i in 0..3 {
                    assert!((a[i] - b[i].conj()).norm() < 1e-12 * scale * 50.0);
                }
            }
        }
        // Two waves of project amplitudes a_0, a_1 (e^{i omega t}): Linton & Evans
        // amplitudes are their conjugates.
        let amplitudes = [Complex64::new(0.8, -0.3), Complex64::new(-0.2, 1.1)];
        let k = hydro.wavenumbers()[0];
        let system = FrequencySystem::new(&array.cylinders, k, array.modes(k)).unwrap();
        let both = array.incident_matrix(&system, &headings[..2], false);
        let combined =
            both.column(0) * amplitudes[0].conj() + both.column(1) * amplitudes[1].conj();
        let solution = system.solve(&DMatrix::from_column_slice(
            combined.len(),
            1,
            combined.as_slice(),
        ));
        let u = solution.surface.as_slice();
        let (s, _) = depth_terms(k, depth);
        let rho_g = env.water_density * env.gravity;
        let direct = near_field_form(&array.cylinders, array.modes(k), k, rho_g, s, u, u);
        for (i, expected) in direct.iter().enumerate() {
            let mut sum = Complex64::new(0.0, 0.0);
            for p in 0..2 {
                for q in 0..2 {
                    sum += amplitudes[p] * amplitudes[q].conj() * t.get(p, q)[i];
                }
            }
            assert!(sum.im.abs() < 1e-12 * scale * 50.0);
            assert!(
                (sum.re - expected.re).abs() < 1e-11 * scale * 50.0,
                "[{i}] {} vs {}",
                sum.re,
                expected.re
            );
        }
    }
}

/// The solver's derivatives: dF/dbeta (exact) and dF/domega (central difference,
/// FREQUENCY_STEP) against fourth-order difference stencils of the solver's drift.
#[test]
fn drift_derivatives_match_independent_differences() {
    let env = Environment::default();
    let array = ColumnArray::new(irregular(), None).unwrap();
    for omega in [0.35, 0.9, 1.7] {
        let beta = 0.6;
        let hydro = array.solve(&env, &[omega], &[beta]).unwrap();
        let (d_omega, d_beta) = hydro.drift_derivatives(0, 0);
        let f = hydro.drift_near(0, 0);
        let scale = magnitude(f, 50.0);
        // Fourth-order stencils; the drift varies on scales 1/(k L) in heading and
        // omega/(2 k L) in frequency.
        let k_extent = (array.wavenumber(omega, env.gravity) * array.extent()).max(1.0);
        let h = 1e-3 / k_extent;
        let turned: Vec<f64> = [-2.0, -1.0, 1.0, 2.0]
            .iter()
            .map(|s| beta + s * h)
            .collect();
        let side = array.solve(&env, &[omega], &turned).unwrap();
        let dw = 2e-3 * omega / k_extent;
        let stencil: Vec<f64> = [-2.0, -1.0, 1.0, 2.0]
            .iter()
            .map(|s| omega + s * dw)
            .collect();
        let around = array.solve(&env, &stencil, &[beta]).unwrap();
        for i in 0..3 {
            let lever = if i == 2 { 50.0 } else { 1.0 };
            let t = |j: usize| side.drift_near(j, 0)[i];
            let by_heading = (t(0) - 8.0 * t(1) + 8.0 * t(2) - t(3)) / (12.0 * h);
            assert!(
                (by_heading - d_beta[i]).abs() < 1e-8 * scale * lever * k_extent,
                "omega {omega} [{i}]: dF/dbeta {} vs {by_heading}",
                d_beta[i]
            );
            let g = |j: usize| around.drift_near(0, j)[i];
            let by_frequency = (g(0) - 8.0 * g(1) + 8.0 * g(2) - g(3)) / (12.0 * dw);
            assert!(
                (by_frequency - d_omega[i]).abs() < 1e-6 * scale * lever / omega,
                "omega {omega} [{i}]: dF/domega {} vs {by_frequency}",
                d_omega[i]
            );
        }
    }
}

/// Aranha's head-sea limit on one column: b_11 = (omega/g)(4 F + omega F') with F and F'
/// from Havelock's series (F' by a fourth-order difference of the closed form), b_22 =
/// (omega/g) 2 F (dF_2/dbeta = F at beta = 0), no coupling; and the table's drift is F.
#[test]
fn aranha_head_sea_limit_on_one_column() {
    let env = Environment::default();
    let (g, rho) = (env.gravity, env.water_density);
    let radius = 8.0;
    let array = ColumnArray::new(vec![column(0.0, 0.0, radius)], None).unwrap();
    let omegas = [0.4, 0.8, 1.2, 1.6];
    let headings = [-0.5, 0.0, 0.5];
    let table = array.drift_table(&env, &omegas, &headings).unwrap();
    let drift = |w: f64| rho * g * radius * havelock_drift_coefficient(w * w * radius / g, 1.0);
    for (iw, &w) in omegas.iter().enumerate() {
        let f = drift(w);
        let h = 1e-3 * w;
        let slope = (drift(w - 2.0 * h) - 8.0 * drift(w - h) + 8.0 * drift(w + h)
            - drift(w + 2.0 * h))
            / (12.0 * h);
        let b = table.damping(w, 0.0).unwrap().unwrap();
        let b11 = w / g * (4.0 * f + w * slope);
        let b22 = w / g * 2.0 * f;
        assert!((table.drift_at_node(1, iw)[0] - f).abs() < 1e-10 * f);
        assert!(
            (b[0][0] - b11).abs() < 1e-7 * b11.abs(),
            "{} vs {b11}",
            b[0][0]
        );
        assert!((b[1][1] - b22).abs() < 1e-9 * b22, "{} vs {b22}", b[1][1]);
        for (i, j) in [(0, 1), (1, 0), (2, 0), (2, 1), (0, 2), (1, 2), (2, 2)] {
            assert!(
                b[i][j].abs() < 1e-9 * b11.abs(),
                "b[{i}][{j}] = {}",
                b[i][j]
            );
        }
    }
}

fn field_of(err: Error) -> String {
    match err {
        Error::InvalidValue { field, .. } => field,
        other => panic!("unexpected error {other:?}"),
    }
}

#[test]
fn input_errors_name_the_field() {
    let env = Environment::default();
    let refuse = |columns: Vec<Cylinder>, depth: Option<f64>| {
        field_of(ColumnArray::new(columns, depth).expect_err("must be refused"))
    };
    assert_eq!(refuse(vec![], None), "platform.columns");
    let mut bad = square(35.0, 10.0);
    bad[2].diameter = 0.0;
    assert_eq!(refuse(bad, None), "platform.columns[2].diameter");
    let mut bad = square(35.0, 10.0);
    bad[1].y = f64::NAN;
    assert_eq!(refuse(bad, None), "platform.columns[1].y");
    let mut bad = square(35.0, 10.0);
    bad[3].x = -30.0;
    bad[3].y = 33.0; // 5.4 m from column 1's centre, radii sum 20 m
    let err = ColumnArray::new(bad, None).unwrap_err().to_string();
    assert!(
        err.contains("platform.columns[3]") && err.contains("overlaps"),
        "{err}"
    );
    assert_eq!(refuse(square(10.0, 10.0), None), "platform.columns[1]");
    assert_eq!(refuse(square(35.0, 10.0), Some(-5.0)), "environment.depth");

    let array = ColumnArray::new(square(35.0, 10.0), Some(200.0)).unwrap();
    let solve = |w: &[f64], b: &[f64]| field_of(array.solve(&env, w, b).expect_err("refused"));
    assert_eq!(solve(&[], &[0.0]), "drift.omegas");
    assert_eq!(solve(&[0.5, 0.0], &[0.0]), "drift.omegas[1]");
    assert_eq!(solve(&[0.5], &[]), "drift.headings");
    assert_eq!(solve(&[0.5], &[f64::NAN]), "drift.headings[0]");
    // k a = 10 omega^2/g > 200 above omega = 14 rad/s.
    let err = array
        .solve(&env, &[0.5, 15.0], &[0.0])
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("drift.omegas[1]") && err.contains("k a"),
        "{err}"
    );
    let no_gravity = Environment {
        gravity: -1.0,
        ..env.clone()
    };
    assert_eq!(
        field_of(array.solve(&no_gravity, &[0.5], &[0.0]).unwrap_err()),
        "environment.gravity"
    );
    // Drift tables need increasing frequencies.
    assert_eq!(
        field_of(
            array
                .drift_table(&env, &[0.6, 0.5], &[0.0, 1.0])
                .unwrap_err()
        ),
        "drift.rows[1].omega"
    );
}
