"""The paper's Fig. 10 run (default platform, long-crested head seas, Newman geometric,
tabulated drift damping (the Rust run's Aranha damping), combined Morison drag on 4 columns x 20 strips, RK4 at 1 s) in pure
NumPy, written the way a user would: the speed reference of `cargo bench --bench montecarlo`.

Fair to NumPy: every record is built vectorised (one batched inverse FFT for all 80 strip
velocities, one pair per Newman record); the RK4 loop is plain Python over small NumPy
arrays, as a user without Numba or Cython would write it (each stage reads one sample of
every record; records are sampled at h/2 so no interpolation is needed).

Input: the drift and damping table as a SlowDrift hydro database (JSON), e.g.
`slowdrift hydro columns --out platform.json` (the default platform's table, with Aranha's damping).
Output: one JSON line with the seconds per run (records and stepping separately) and the
surge mean and rms after the transient, for a plausibility check against the Rust tool.

    python bench_numpy.py platform.json [--runs 2] [--duration 16384] [--seed 1]
"""

import argparse
import json
import time

import numpy as np

G, RHO = 9.80665, 1025.0
HS, TP, H = 7.0, 12.0, 1.0
MASS, IZZ = 9.9737e7, 1.8898e11
ADDED = np.diag([6.0417e7, 6.0417e7, 6.4807e10])
STIFF = np.diag([1.5807e5, 1.5807e5, 1.0019e9])
COLUMNS = np.array([[35.0, 35.0], [-35.0, 35.0], [-35.0, -35.0], [35.0, -35.0]])
DIAMETER, DRAFT, STRIPS, CD = 20.0, 30.0, 20, 0.6
TRANSIENT_PERIODS = 10


def jonswap(w):
    wp = 2 * np.pi / TP
    ratio = TP / np.sqrt(HS)
    gamma = 5.0 if ratio <= 3.6 else (np.exp(5.75 - 1.15 * ratio) if ratio < 5 else 1.0)
    sigma = np.where(w <= wp, 0.07, 0.09)
    pm = 5 / 16 * HS**2 * wp**4 * w**-5.0 * np.exp(-1.25 * (wp / w) ** 4)
    return (1 - 0.287 * np.log(gamma)) * pm * gamma ** np.exp(-((w - wp) ** 2) / (2 * sigma**2 * wp**2))


def load_table(path):
    db = json.load(open(path))
    rows = sorted((r for r in db["drift"] if abs(r["heading"]) < 1e-9), key=lambda r: r["omega"])
    omega = np.array([r["omega"] for r in rows])
    drift = np.array([[r["surge"], r["sway"], r["yaw"]] for r in rows])
    damping = np.array([r["damping"] for r in rows])  # (n, 3, 3)
    return omega, drift, damping


def series(coefficients, first, n):
    """x_m = sum_k c_k e^{i w_k t_m} for the band bins first.. (complex), batched."""
    spectrum = np.zeros(coefficients.shape[:-1] + (n,), complex)
    spectrum[..., first:first + coefficients.shape[-1]] = coefficients
    return np.fft.ifft(spectrum, axis=-1) * n


def newman(a, t, first, n):
    """Geometric Newman record: |sum a sqrt(T+)|^2 - |sum a sqrt(T-)|^2 (E&S 4)."""
    pos = series(a * np.sqrt(np.maximum(t, 0)), first, n)
    neg = series(a * np.sqrt(np.maximum(-t, 0)), first, n)
    return np.abs(pos) ** 2 - np.abs(neg) ** 2


def records(table, duration, seed):
    dt = H / 2
    n = int(round(duration / dt))
    n = 1 << (n - 1).bit_length()  # next power of two
    dw = 2 * np.pi / (n * dt)
    wp = 2 * np.pi / TP
    first, last = int(np.ceil(0.5 * wp / dw)), int(4 * wp / dw)
    w = np.arange(first, last + 1) * dw
    rng = np.random.default_rng(seed)
    a = np.sqrt(jonswap(w) * dw) * (rng.standard_normal(w.size) + 1j * rng.standard_normal(w.size))
    omega, drift, damping = table
    force = np.array([newman(a, np.interp(w, omega, drift[:, i]), first, n) for i in range(3)])
    b = np.array([[newman(a, np.interp(w, omega, damping[:, i, j]), first, n)
                   for j in range(3)] for i in range(3)])
    k = w**2 / G
    phase = np.exp(-1j * k * COLUMNS[:, :1])  # head seas: k x_c, (4, count)
    eta = series(a * phase, first, n).real  # (4, n)
    levels = -DRAFT + (np.arange(STRIPS) + 0.5) * DRAFT / STRIPS  # stretched strip levels
    profile = w * np.exp(np.outer(levels, k))  # (strips, count)
    u = series(a * phase[:, None, :] * profile[None], first, n).real  # (4, strips, n)
    return force, b, eta, u


def simulate(recs, duration):
    force, b, eta, u = recs
    inv_mass = np.linalg.inv(np.diag([MASS, MASS, IZZ]) + ADDED)
    steps = int(round(duration / H))
    n = force.shape[1]
    q, qd = np.zeros(3), np.zeros(3)
    surge = np.empty(steps + 1)
    surge[0] = 0.0
    xc, yc = COLUMNS[:, 0], COLUMNS[:, 1]

    def acceleration(m, q, qd):
        c, s = np.cos(q[2]), np.sin(q[2])
        rot = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        v = rot.T @ qd
        f = force[:, m] - b[:, :, m] @ v
        # combined drag, body frame: w = u - U on every strip (head seas: no wave v)
        wx = u[:, :, m] - (v[0] - v[2] * yc)[:, None]
        wy = -np.broadcast_to((v[1] + v[2] * xc)[:, None], wx.shape)
        norm = np.sqrt(wx**2 + wy**2)
        scale = 0.5 * RHO * DIAMETER * np.maximum(DRAFT + eta[:, m], 0) / STRIPS * CD
        fx = scale * (wx * norm).sum(axis=1)
        fy = scale * (wy * norm).sum(axis=1)
        f = f + np.array([fx.sum(), fy.sum(), (xc * fy - yc * fx).sum()])
        total = rot @ f - STIFF @ q
        return rot @ (inv_mass @ (rot.T @ total))

    for step in range(steps):
        m = 2 * step
        k1v, k1a = qd, acceleration(m, q, qd)
        k2v = qd + 0.5 * H * k1a
        k2a = acceleration(m + 1, q + 0.5 * H * k1v, k2v)
        k3v = qd + 0.5 * H * k2a
        k3a = acceleration(m + 1, q + 0.5 * H * k2v, k3v)
        k4v = qd + H * k3a
        k4a = acceleration((m + 2) % n, q + H * k3v, k4v)  # FFT records are periodic
        q = q + H / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        qd = qd + H / 6 * (k1a + 2 * k2a + 2 * k3a + k4a)
        surge[step + 1] = q[0]
    return surge


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("database")
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--duration", type=float, default=16384.0)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    table = load_table(args.database)
    period = 2 * np.pi * np.sqrt((MASS + ADDED[0, 0]) / STIFF[0, 0])
    transient = int(min(TRANSIENT_PERIODS * period, args.duration / 2) / H)
    t_records = t_steps = 0.0
    stats = []
    for run in range(args.runs):
        t0 = time.perf_counter()
        recs = records(table, args.duration, args.seed + run)
        t1 = time.perf_counter()
        surge = simulate(recs, args.duration)[transient:]
        t2 = time.perf_counter()
        t_records += t1 - t0
        t_steps += t2 - t1
        stats.append((surge.mean(), surge.std()))
    print(json.dumps({
        "runs": args.runs,
        "seconds_per_run": (t_records + t_steps) / args.runs,
        "records_seconds_per_run": t_records / args.runs,
        "stepping_seconds_per_run": t_steps / args.runs,
        "surge_mean_m": float(np.mean([s[0] for s in stats])),
        "surge_rms_m": float(np.mean([s[1] for s in stats])),
    }))


if __name__ == "__main__":
    main()
