//! `slowdrift study sensitivity`: mean and rms against a case-table column (drag coefficients,
//! current speed; E&S Figs 12-15).

use super::{report, sea_text, surge_values, threads, write_text, SensitivityArgs};
use crate::cli::montecarlo::{run_campaign, Campaign};
use crate::cli::Failure;
use crate::plot::{padded_range, write_figure, Figure, LegendAt, Panel, Series, Style, Ticks};
use slowdrift::montecarlo::cases::read_case_table;
use slowdrift::montecarlo::{seed_statistics, Job};
use slowdrift::Problem;
use std::fmt::Write as _;

/// The axis description of a case-table column.
fn column_label(column: &str) -> String {
    match column {
        "cd" => "combined drag coefficient C_D [-]".into(),
        "cd_slow" => "slow-drift drag coefficient C_DS [-]".into(),
        "cd_fast" => "wave-frequency drag coefficient C_DL [-]".into(),
        "current_speed" => "current speed [m/s]".into(),
        "current_direction_deg" => "current direction [deg]".into(),
        "wind_speed" => "wind speed [m/s]".into(),
        "wind_direction_deg" => "wind direction [deg]".into(),
        "wind_reference_height" => "height of the wind speed [m]".into(),
        "hs" => "Hs [m]".into(),
        "tp" => "Tp [s]".into(),
        "direction_deg" => "wave direction [deg]".into(),
        "duration" => "duration [s]".into(),
        other => other.into(),
    }
}

/// Figs 12-15: surge mean and rms (mean over seeds, +- 1 standard error) against one
/// column of a case table.
pub(super) fn sensitivity(base: &Problem, args: &SensitivityArgs) -> Result<(), Failure> {
    let table = &args.cases;
    let column = args.x.as_str();
    let seeds = args.seeds;
    let out = args.out.as_path();
    let rows = read_case_table(table, base.run.memory_limit).map_err(|e| e.to_string())?;
    let source = table.display().to_string();
    let mut cases = Vec::new();
    let mut xs = Vec::new();
    for row in &rows {
        let x = row.number(column).ok_or_else(|| {
            format!(
                "{source}: row {} ('{}') has no value in column '{column}'",
                row.row, row.name
            )
        })?;
        xs.push(x);
        cases.push(row.case(base, None, &source).map_err(|e| e.to_string())?);
    }
    let stem = table
        .file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .to_string();
    let jobs: Vec<Job> = (0..cases.len())
        .flat_map(|case| (1..=seeds as u64).map(move |seed| Job { case, seed }))
        .collect();
    let runs_path = out.join(format!("{stem}.runs.csv"));
    let Campaign { runs, interrupted } = run_campaign(
        &cases,
        &jobs,
        threads(args.threads),
        &runs_path,
        base.run.memory_limit,
    )?;
    if let Some(interrupted) = interrupted {
        return Err(interrupted.failure(&runs_path, None));
    }
    let mut csv = format!(
        "case,{column},seeds_done,surge_mean_m,surge_mean_se_m,surge_rms_m,surge_rms_se_m\n"
    );
    let (mut mean_points, mut rms_points) = (Vec::new(), Vec::new());
    for (case, &x) in cases.iter().zip(&xs) {
        let (means, rmss) = surge_values(&runs, case, seeds);
        let (Some(m), Some(r)) = (seed_statistics(&means), seed_statistics(&rmss)) else {
            return Err(format!(
                "case '{}': no successful run (see {stem}.runs.csv)",
                case.name
            )
            .into());
        };
        let (mse, rse) = (
            m.standard_error.unwrap_or(0.0),
            r.standard_error.unwrap_or(0.0),
        );
        writeln!(
            csv,
            "{},{x},{},{},{mse},{},{rse}",
            case.name, m.n, m.mean, r.mean
        )
        .ok();
        mean_points.push((x, m.mean, mse));
        rms_points.push((x, r.mean, rse));
    }
    let x_range = padded_range(xs.iter().copied(), 0.08);
    let panel = |title: &str, y_label: &str, points: &[(f64, f64, f64)]| {
        let series = Series::new(
            "",
            points.iter().map(|p| (p.0, p.1)).collect(),
            Style::Markers,
            1,
        )
        .with_errors(points.iter().map(|p| p.2).collect());
        // From zero when every value is positive, so that the panel shows proportions.
        let (lo, hi) = padded_range(
            points
                .iter()
                .flat_map(|p| [p.1 - p.2, p.1 + p.2])
                .chain([0.0]),
            0.1,
        );
        let positive = points.iter().all(|p| p.1 - p.2 >= 0.0);
        let y_range = (if positive { 0.0 } else { lo }, hi);
        Panel {
            title: title.into(),
            x_label: column_label(column),
            y_label: y_label.into(),
            x_range,
            y_range,
            x_ticks: Ticks::Plain,
            series: vec![series],
            boxes: Vec::new(),
            legend: LegendAt::UpperRight,
        }
    };
    let figure = Figure {
        title: format!(
            "Surge vs {} ({stem}): mean of {seeds} seeds ± 1 standard error; {}",
            column_label(column).split(" [").next().unwrap_or(column),
            sea_text(base).split(", seed").next().unwrap_or_default()
        ),
        panels: vec![
            panel("surge mean", "surge mean [m]", &mean_points),
            panel("surge rms", "surge rms [m]", &rms_points),
        ],
        columns: 2,
        size: (1400, 560),
    };
    let csv_path = out.join(format!("{stem}.summary.csv"));
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&figure, &out.join(&stem))?);
    print!("{csv}");
    report(&written);
    Ok(())
}
