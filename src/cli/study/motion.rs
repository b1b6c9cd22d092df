//! `slowdrift study motion`: the motion spectra of one long run, the slow drift (surge, sway,
//! yaw) and the wave-frequency motion (six DOFs), each against its frequency-domain
//! prediction (`slowdrift::studies::motion_spectra`).

use super::{report, sea_text, ten_cycles, write_text, MotionArgs};
use crate::plot::{write_figure, Figure, LegendAt, Panel, Series, Style, Ticks};
use slowdrift::stats::welch_spectrum;
use slowdrift::studies::motion_spectra::{
    motion_record, SlowDriftPrediction, WaveFrequencyPrediction,
};
use slowdrift::Problem;
use std::fmt::Write as _;

/// Welch segments of the slow drift (a resolution of 2 pi / 8192 = 0.00077 rad/s, a tenth
/// of the default's surge resonance width) and of the wave-frequency motion, s.
const SLOW_SEGMENT: f64 = 8192.0;
const WAVE_SEGMENT: f64 = 256.0;

/// Upper end of a slow-drift panel as a multiple of its DOF's undamped natural frequency,
/// and the end where nothing restores the DOF, rad/s.
const SLOW_RANGE: f64 = 4.0;
const UNMOORED_RANGE: f64 = 0.2;

/// A DOF whose simulated and predicted standard deviations are both below this (m, or rad)
/// is not excited by the sea (round-off: sway, roll and yaw in a head sea): its panel is
/// left out, and the summary says so.
const NOT_EXCITED: f64 = 1e-6;

/// How a quantity is drawn: its unit on the figure, its SI unit (the CSVs') and the factor
/// from the SI unit to the figure's.
#[derive(Clone, Copy)]
struct Quantity {
    unit: &'static str,
    si: &'static str,
    scale: f64,
}

const LENGTH: Quantity = Quantity {
    unit: "m",
    si: "m",
    scale: 1.0,
};
const ANGLE: Quantity = Quantity {
    unit: "deg",
    si: "rad",
    scale: 180.0 / std::f64::consts::PI,
};
const SPEED: Quantity = Quantity {
    unit: "(m/s)",
    si: "m/s",
    scale: 1.0,
};

/// The DOFs and whether each is an angle (drawn in degrees; the CSVs keep radians).
const SLOW_NAMES: [(&str, bool); 3] = [("surge X", false), ("sway Y", false), ("yaw θ", true)];
const WAVE_NAMES: [(&str, bool); 6] = [
    ("surge", false),
    ("sway", false),
    ("heave", false),
    ("roll", true),
    ("pitch", true),
    ("yaw", true),
];

pub(super) fn motion(base: &Problem, args: &MotionArgs) -> Result<(), String> {
    let explain = |e: slowdrift::Error| base.explain(&e);
    let transient = match args.transient {
        Some(t) => t,
        None => ten_cycles(base)?,
    };
    let motions = base.first_order_motions().map_err(explain)?;
    let wave_frequency_on = motions.is_some()
        && base.model.wave_frequency_motion == slowdrift::model::WaveFrequencyMotion::On;
    let slow = SlowDriftPrediction::new(base).map_err(explain)?;
    let wave = match (&motions, wave_frequency_on) {
        (Some(m), true) => Some(WaveFrequencyPrediction::new(base, &m.rao).map_err(explain)?),
        _ => None,
    };
    println!(
        "simulating {} s after a transient of {transient} s",
        args.duration
    );
    let record = motion_record(base, transient, args.duration).map_err(explain)?;
    let mut csv = String::from("part,dof,source,omega_rad_s,density\n");
    let mut summary =
        String::from("part,dof,simulated_variance,predicted_variance,damping_linear,damping_wave_drift,damping_drag,damping_quadratic,damping_wind\n");
    let mut panels = Vec::new();

    for (i, &(name, angle)) in SLOW_NAMES.iter().enumerate() {
        let slow_top = if slow.stiffness[i] > 0.0 {
            SLOW_RANGE * (slow.stiffness[i] / slow.mass[i]).sqrt()
        } else {
            UNMOORED_RANGE
        };
        let simulated = welch(&record.slow[i], record.dt, SLOW_SEGMENT, slow_top)?;
        let predicted: Vec<(f64, f64)> = slow
            .mu()
            .enumerate()
            .skip(1)
            .take_while(|(_, mu)| *mu <= slow_top)
            .map(|(m, mu)| (mu, slow.density(i, m)))
            .collect();
        rows(&mut csv, "slow-drift", name, "simulated", &simulated);
        rows(&mut csv, "slow-drift", name, "predicted", &predicted);
        // With wind, the prediction's two parts: the waves' and the gusts'.
        let parts: Vec<(&str, Vec<(f64, f64)>)> = if slow.has_wind() {
            let part = |density: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
                slow.mu()
                    .enumerate()
                    .skip(1)
                    .take_while(|(_, mu)| *mu <= slow_top)
                    .map(|(m, mu)| (mu, density(m)))
                    .collect()
            };
            vec![
                ("wave drift", part(&|m| slow.wave_density(i, m))),
                ("wind gusts", part(&|m| slow.wind_density(i, m))),
            ]
        } else {
            Vec::new()
        };
        for (label, points) in &parts {
            let source = format!("predicted {label}");
            rows(&mut csv, "slow-drift", name, &source, points);
        }
        let d = &slow.damping[i];
        let variances = (variance(&record.slow[i]), slow.variance(i));
        writeln!(
            summary,
            "slow-drift,{name},{},{},{},{},{},{},{}",
            variances.0, variances.1, d.linear, d.wave_drift, d.drag, d.quadratic, d.wind
        )
        .ok();
        let quantity = if angle { ANGLE } else { LENGTH };
        panels.extend(
            panel(
                format!("slow drift, {name}"),
                quantity,
                slow_top,
                variances,
                simulated,
                predicted,
            )
            .map(|p| with_parts(p, quantity, parts)),
        );
    }
    if let Some(wave) = &wave {
        let (lo, hi) = base.band();
        for (i, &(name, angle)) in WAVE_NAMES.iter().enumerate() {
            let simulated = welch(&record.wave_frequency[i], record.dt, WAVE_SEGMENT, hi)?;
            let predicted: Vec<(f64, f64)> = (0..=400)
                .map(|n| {
                    let w = lo + n as f64 * (hi - lo) / 400.0;
                    (w, wave.density(i, w))
                })
                .collect();
            rows(&mut csv, "wave-frequency", name, "simulated", &simulated);
            rows(&mut csv, "wave-frequency", name, "predicted", &predicted);
            let h = (hi - lo) / 400.0;
            let predicted_variance = h
                * (predicted.iter().map(|p| p.1).sum::<f64>()
                    - 0.5 * (predicted[0].1 + predicted[400].1));
            let variances = (variance(&record.wave_frequency[i]), predicted_variance);
            writeln!(
                summary,
                "wave-frequency,{name},{},{},,,,,",
                variances.0, variances.1
            )
            .ok();
            panels.extend(panel(
                format!("wave-frequency {name}"),
                if angle { ANGLE } else { LENGTH },
                hi,
                variances,
                simulated,
                predicted,
            ));
        }
    } else {
        println!("no wave-frequency motion (no RAOs, or [model] wave_frequency_motion = \"off\"): slow drift only");
    }
    if let Some((height, gusts)) = base
        .run_wind()
        .map_err(explain)?
        .and_then(|wind| Some((wind.height, wind.gusts?)))
    {
        // The wind speed at the force's height: its Welch spectrum against the gust spectrum.
        let top = 1.0;
        let simulated = welch(&record.wind_speed, record.dt, SLOW_SEGMENT, top)?;
        let predicted: Vec<(f64, f64)> = (1..=400)
            .map(|n| {
                let w = n as f64 * top / 400.0;
                (w, gusts.spectrum.density_per_rad(w))
            })
            .collect();
        rows(&mut csv, "wind", "speed", "simulated", &simulated);
        rows(&mut csv, "wind", "speed", "predicted", &predicted);
        let sigma2 = gusts
            .spectrum
            .variance(0.5 / args.duration, 0.5 / record.dt)
            .map_err(explain)?;
        let variances = (variance(&record.wind_speed), sigma2);
        writeln!(summary, "wind,speed,{},{},,,,,", variances.0, variances.1).ok();
        panels.extend(panel(
            format!("wind speed at {} m", height),
            SPEED,
            top,
            variances,
            simulated,
            predicted,
        ));
    }
    let rows = panels.len().div_ceil(3).max(1) as u32;
    let figure = Figure {
        title: format!(
            "Motion spectra vs frequency domain: {}, {} s after {transient:.0} s (Welch, Hann)",
            sea_text(base),
            args.duration
        ),
        columns: 3,
        size: (1600, 80 + 380 * rows),
        panels,
    };
    let out = args.out.as_path();
    let (csv_path, summary_path) = (
        out.join("motion_spectra.csv"),
        out.join("motion_variances.csv"),
    );
    write_text(&csv_path, &csv)?;
    write_text(&summary_path, &summary)?;
    let mut written = vec![csv_path, summary_path];
    written.extend(write_figure(&figure, &out.join("motion_spectra"))?);
    print!("{summary}");
    report(&written);
    Ok(())
}

/// `panel` with the prediction's parts drawn beside its total (dashed, in the palette's
/// third and fourth colours), scaled as the panel (degrees for angles).
fn with_parts(mut panel: Panel, quantity: Quantity, parts: Vec<(&str, Vec<(f64, f64)>)>) -> Panel {
    let scale = quantity.scale * quantity.scale;
    for (colour, (label, points)) in parts.into_iter().enumerate() {
        let points = points.into_iter().map(|(w, s)| (w, s * scale)).collect();
        panel.series.push(Series::new(
            format!("frequency domain: {label}"),
            points,
            Style::Dashed,
            2 + colour,
        ));
    }
    panel
}

/// The Welch estimate of `record` (mean removed by the estimator's segments) up to `top`.
fn welch(record: &[f64], dt: f64, segment: f64, top: f64) -> Result<Vec<(f64, f64)>, String> {
    let segment = ((segment / dt).round() as usize).min(record.len());
    let estimate = welch_spectrum(record, dt, segment).map_err(|e| e.to_string())?;
    Ok(estimate
        .omega
        .iter()
        .zip(&estimate.density)
        .skip(1)
        .filter(|(w, _)| **w <= top)
        .map(|(w, s)| (*w, *s))
        .collect())
}

fn variance(record: &[f64]) -> f64 {
    let n = record.len() as f64;
    let mean = record.iter().sum::<f64>() / n;
    record.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n
}

fn rows(csv: &mut String, part: &str, dof: &str, source: &str, points: &[(f64, f64)]) {
    for (w, s) in points {
        writeln!(csv, "{part},{dof},{source},{w},{s}").ok();
    }
}

/// The panel of one DOF, angles in degrees, its variances (simulated, predicted) in its
/// title; `None` (and a line saying so) when the DOF is not excited.
fn panel(
    title: String,
    quantity: Quantity,
    top: f64,
    variances: (f64, f64),
    simulated: Vec<(f64, f64)>,
    predicted: Vec<(f64, f64)>,
) -> Option<Panel> {
    let Quantity { unit, si, scale } = quantity;
    if variances.0.max(variances.1).sqrt() < NOT_EXCITED {
        println!(
            "{title}: not excited (standard deviations {:.1e} simulated, {:.1e} predicted, \
             below {NOT_EXCITED:e} {}): not drawn",
            variances.0.sqrt(),
            variances.1.sqrt(),
            si
        );
        return None;
    }
    let scaled = |points: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        points
            .into_iter()
            .map(|(w, s)| (w, s * scale * scale))
            .collect()
    };
    let (simulated, predicted) = (scaled(simulated), scaled(predicted));
    let variance_text = |v: f64| format!("{:.3}", v * scale * scale);
    let highest = simulated
        .iter()
        .chain(&predicted)
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    Some(Panel {
        title: format!(
            "{title}: variance {} vs {} {unit}²",
            variance_text(variances.0),
            variance_text(variances.1)
        ),
        x_label: "ω [rad/s]".into(),
        y_label: format!("S [{unit}² s/rad]"),
        x_range: (0.0, top),
        y_range: (0.0, if highest > 0.0 { 1.1 * highest } else { 1.0 }),
        x_ticks: Ticks::Plain,
        series: vec![
            Series::new("simulated (Welch)", simulated, Style::Trace, 1),
            Series::new("frequency domain", predicted, Style::Dashed, 0),
        ],
        boxes: Vec::new(),
        legend: LegendAt::UpperRight,
    })
}
