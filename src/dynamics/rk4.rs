//! Classical fourth-order Runge-Kutta (docs/theory.md#equations-of-motion; the paper integrates
//! with
//! Runge-Kutta at a 1 s step). Stage times are t, t + h/2, t + h/2, t + h; the right-hand
//! side is evaluated with the forcing at exactly those times.

/// One RK4 step of y' = f(t, y) from (t, y) over h. `f` may fail (e.g. a time outside the
/// force records); the first failure is returned and nothing is advanced.
pub fn rk4_step<const N: usize, E>(
    t: f64,
    y: &[f64; N],
    h: f64,
    mut f: impl FnMut(f64, &[f64; N]) -> Result<[f64; N], E>,
) -> Result<[f64; N], E> {
    let offset = |base: &[f64; N], k: &[f64; N], scale: f64| -> [f64; N] {
        std::array::from_fn(|i| base[i] + scale * k[i])
    };
    let k1 = f(t, y)?;
    let k2 = f(t + 0.5 * h, &offset(y, &k1, 0.5 * h))?;
    let k3 = f(t + 0.5 * h, &offset(y, &k2, 0.5 * h))?;
    let k4 = f(t + h, &offset(y, &k3, h))?;
    Ok(std::array::from_fn(|i| {
        y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
    }))
}
