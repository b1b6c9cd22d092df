use super::*;
use crate::hydro::column_drift::{far_field_drift_coefficient, havelock_drift_coefficient};
use crate::special::bessel::{bessel_j_y, hankel_derivatives};
use std::f64::consts::PI;

fn column(x: f64, y: f64, radius: f64) -> Column {
    Column {
        x,
        y,
        diameter: 2.0 * radius,
        draft: 30.0,
    }
}

/// The paper's platform: radius 10 m at (+-35, +-35) m.
fn square(half_side: f64, radius: f64) -> Vec<Column> {
    [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
        .iter()
        .map(|&(sx, sy)| column(sx * half_side, sy * half_side, radius))
        .collect()
}

/// Four unequal columns without symmetry.
fn irregular() -> Vec<Column> {
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
    cylinders: &[Cylinder],
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
        let cylinders: Vec<Cylinder> = columns
            .iter()
            .map(|c| Cylinder {
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
