//! `slowdrift study drift`: the configuration's mean drift and wave-drift damping against
//! frequency beside the column-array solver's on the same columns (as E&S Figs 3-5 show the
//! drift and damping of their platform): for the default platform, its radiation-diffraction
//! data against the built-in solver. Deep water, per unit wave amplitude squared, body frame.

use super::{report, write_text, DriftArgs};
use crate::plot::{padded_range, write_figure, Figure, LegendAt, Panel, Series, Style, Ticks};
use slowdrift::hydro::DriftTable;
use slowdrift::problem::resolve_hydro;
use slowdrift::scenario::{ColumnGrid, DriftSource};
use slowdrift::Problem;
use std::fmt::Write as _;

/// The column solver's grid of this study: 100 frequencies over 0.05 .. 3 rad/s, headings every
/// 10 degrees.
const COLUMN_GRID: ColumnGrid = ColumnGrid {
    omega_min: 0.05,
    omega_max: 3.0,
    n_omega: 100,
    heading_step: std::f64::consts::PI / 18.0,
};

/// Frequencies of the figure and the CSV: every 0.01 rad/s over both tables' common range.
const OMEGA_STEP: f64 = 0.01;

/// The oblique heading of the yaw panels, rad (yaw drift vanishes in head seas and at 45
/// degrees on a doubly symmetric platform).
const OBLIQUE: f64 = std::f64::consts::PI / 6.0;

/// (surge drift at 0, b11 at 0, yaw drift at 30 deg, b66 at 0) of `table` at `omega`.
fn quantities(table: &DriftTable, omega: f64) -> Result<[f64; 4], String> {
    let head = table.drift(omega, 0.0).map_err(|e| e.to_string())?;
    let oblique = table.drift(omega, OBLIQUE).map_err(|e| e.to_string())?;
    let b = table
        .damping(omega, 0.0)
        .map_err(|e| e.to_string())?
        .unwrap_or([[f64::NAN; 3]; 3]);
    Ok([head[0], b[0][0], oblique[2], b[2][2]])
}

pub(super) fn drift(base: &Problem, args: &DriftArgs) -> Result<(), String> {
    if base.platform.columns.is_empty() {
        return Err("study drift: the platform has no [[platform.columns]] to compare with".into());
    }
    let source = DriftSource::ColumnArray {
        grid: COLUMN_GRID,
        depth: None,
    };
    let columns = resolve_hydro(
        &source,
        &base.platform,
        &base.environment,
        base.run.memory_limit,
    )
    .map_err(|e| e.to_string())?
    .drift;
    // The damping a run of the configuration uses (none drawn when it is off).
    let own = base
        .damping_table()
        .map_err(|e| e.to_string())?
        .unwrap_or_else(|| base.hydro.drift.clone());
    let span = |t: &DriftTable| (t.omegas()[0], t.omegas()[t.omegas().len() - 1]);
    let ((own_lo, own_hi), (col_lo, col_hi)) = (span(&own), span(&columns));
    let (lo, hi) = (own_lo.max(col_lo), own_hi.min(col_hi));
    let count = ((hi - lo) / OMEGA_STEP).floor() as usize + 1;
    let mut csv = String::from(
        "omega_rad_s,surge_drift_n_m2,surge_drift_columns_n_m2,b11_n_s_m3,b11_columns_n_s_m3,\
         yaw_drift_30deg_n_m_m2,yaw_drift_30deg_columns_n_m_m2,b66_n_m_s,b66_columns_n_m_s\n",
    );
    let mut series = [[(); 4].map(|_| Vec::new()), [(); 4].map(|_| Vec::new())];
    for i in 0..count {
        let omega = lo + i as f64 * OMEGA_STEP;
        let a = quantities(&own, omega)?;
        let c = quantities(&columns, omega)?;
        writeln!(
            csv,
            "{omega:.2},{},{},{},{},{},{},{},{}",
            a[0], c[0], a[1], c[1], a[2], c[2], a[3], c[3]
        )
        .ok();
        for k in 0..4 {
            series[0][k].push((omega, a[k]));
            series[1][k].push((omega, c[k]));
        }
    }
    let labels = [
        ("mean surge drift, head seas", "F1 / A² [N/m²]"),
        (
            "surge wave-drift damping b11, head seas",
            "b11 / A² [N s/m³]",
        ),
        ("mean yaw drift moment, waves from 30°", "F6 / A² [N m/m²]"),
        (
            "yaw wave-drift damping b66, head seas",
            "b66 / A² [N m s/m²]",
        ),
    ];
    let panels = labels
        .iter()
        .enumerate()
        .map(|(k, (title, y_label))| Panel {
            title: (*title).into(),
            x_label: "wave frequency ω [rad/s]".into(),
            y_label: (*y_label).into(),
            x_range: (lo, hi),
            y_range: padded_range(
                series
                    .iter()
                    .flat_map(|s| s[k].iter().map(|p| p.1))
                    .collect::<Vec<_>>(),
                0.05,
            ),
            x_ticks: Ticks::Plain,
            series: vec![
                Series::new(args.label.clone(), series[0][k].clone(), Style::Line, 1),
                Series::new(
                    "column solver (infinitely deep, fixed columns)",
                    series[1][k].clone(),
                    Style::Dashed,
                    2,
                ),
            ],
            boxes: Vec::new(),
            legend: LegendAt::UpperRight,
        })
        .collect();
    let figure = Figure {
        title: "Mean drift and wave-drift damping per unit amplitude squared (as E&S Figs 3-5)"
            .into(),
        panels,
        columns: 2,
        size: (1500, 1000),
    };
    let out = args.out.as_path();
    let csv_path = out.join("drift_comparison.csv");
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&figure, &out.join("drift_comparison"))?);
    report(&written);
    Ok(())
}
