//! `slowdrift study boxplots`: surge mean and rms over many seeds for record lengths
//! 2^11 .. 2^17 s as box plots (E&S Fig. 10).

use super::{report, sea_text, surge_values, ten_cycles, threads, write_text, BoxplotsArgs};
use crate::cli::montecarlo::{run_campaign, Campaign};
use crate::cli::Failure;
use crate::plot::{
    padded_range, write_figure, BoxItem, Figure, LegendAt, Panel, Series, Style, Ticks,
};
use slowdrift::montecarlo::{Case, Job};
use slowdrift::studies::distribution::{box_stats, log_log_slope, sample_std};
use slowdrift::Problem;
use std::fmt::Write as _;

/// Default sample counts of `boxplots` for record lengths 2^11 .. 2^17 s: 1000 where runs
/// are cheap, fewer for the long records (about 4 minutes on 2 cores for the default
/// platform with drag).
const DEFAULT_SAMPLES: [usize; 7] = [1000, 1000, 1000, 400, 200, 200, 200];

/// Fig. 10: box plots of the surge mean and rms over many seeds for record lengths
/// 2^A .. 2^B s (analysed after the transient), and their scatter against length.
pub(super) fn boxplots(base: &Problem, args: &BoxplotsArgs) -> Result<(), Failure> {
    let exponents = &args.exponents.0;
    let out = args.out.as_path();
    let samples: Vec<usize> = match &args.samples {
        Some(counts) => counts.0.clone(),
        None if exponents.len() == DEFAULT_SAMPLES.len() => DEFAULT_SAMPLES.to_vec(),
        None => vec![200],
    };
    let samples = match samples.len() {
        1 => vec![samples[0]; exponents.len()],
        n if n == exponents.len() => samples,
        n => {
            return Err(format!(
                "--samples: {n} counts for {} record lengths (give one, or one per length)",
                exponents.len()
            )
            .into())
        }
    };
    let transient = match args.transient {
        Some(seconds) => seconds,
        None => ten_cycles(base)?,
    };
    let cases: Vec<Case> = exponents
        .iter()
        .map(|&k| {
            let mut config = base.clone();
            config.run.duration = transient + 2f64.powi(k as i32);
            Case {
                name: format!("L2^{k}"),
                problem: config,
                transient,
            }
        })
        .collect();
    let jobs: Vec<Job> = samples
        .iter()
        .enumerate()
        .flat_map(|(case, &n)| (1..=n as u64).map(move |seed| Job { case, seed }))
        .collect();
    let runs_path = out.join("fig10.runs.csv");
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

    let mut csv = String::from("record_length_s,samples,mean_median_m,mean_iqr_m,mean_std_m,rms_median_m,rms_iqr_m,rms_std_m\n");
    let (mut mean_boxes, mut rms_boxes) = (Vec::new(), Vec::new());
    let (mut lengths, mut mean_std, mut rms_std) = (Vec::new(), Vec::new(), Vec::new());
    for ((case, &k), &n) in cases.iter().zip(exponents).zip(&samples) {
        let (means, rmss) = surge_values(&runs, case, n);
        if means.len() < 2 {
            return Err(format!(
                "{}: fewer than 2 successful runs (see fig10.runs.csv)",
                case.name
            )
            .into());
        }
        let (bm, br) = (
            box_stats(&means).map_err(|e| e.to_string())?,
            box_stats(&rmss).map_err(|e| e.to_string())?,
        );
        let (sm, sr) = (
            sample_std(&means).map_err(|e| e.to_string())?,
            sample_std(&rmss).map_err(|e| e.to_string())?,
        );
        writeln!(
            csv,
            "{},{},{},{},{sm},{},{},{sr}",
            2u64.pow(k),
            means.len(),
            bm.median,
            bm.iqr(),
            br.median,
            br.iqr()
        )
        .ok();
        lengths.push(2f64.powi(k as i32));
        mean_std.push(sm);
        rms_std.push(sr);
        mean_boxes.push(BoxItem {
            x: k as f64,
            width: 0.5,
            stats: bm,
        });
        rms_boxes.push(BoxItem {
            x: k as f64,
            width: 0.5,
            stats: br,
        });
    }
    let slopes = [
        log_log_slope(&lengths, &mean_std).map_err(|e| e.to_string())?,
        log_log_slope(&lengths, &rms_std).map_err(|e| e.to_string())?,
    ];
    let (k0, k1) = (
        exponents[0] as f64 - 0.6,
        *exponents.last().unwrap_or(&17) as f64 + 0.6,
    );
    let box_panel = |title: &str, y_label: &str, boxes: Vec<BoxItem>| {
        let y_range = padded_range(
            boxes.iter().flat_map(|b| {
                [b.stats.lower_whisker, b.stats.upper_whisker]
                    .into_iter()
                    .chain(b.stats.outliers.iter().copied())
            }),
            0.05,
        );
        Panel {
            title: title.into(),
            x_label: "record length after the transient [s]".into(),
            y_label: y_label.into(),
            x_range: (k0, k1),
            y_range,
            x_ticks: Ticks::PowerOfTwo,
            series: Vec::new(),
            boxes,
            legend: LegendAt::UpperRight,
        }
    };
    let log_std = |std: &[f64]| -> Vec<(f64, f64)> {
        exponents
            .iter()
            .zip(std)
            .map(|(&k, s)| (k as f64, s.log2()))
            .collect()
    };
    let (mean_points, rms_points) = (log_std(&mean_std), log_std(&rms_std));
    let anchor = mean_points[0];
    let reference: Vec<(f64, f64)> = [k0, k1]
        .iter()
        .map(|&k| (k, anchor.1 - 0.5 * (k - anchor.0)))
        .collect();
    let scatter = Panel {
        title: "scatter over seeds (log₂ of the sample std)".into(),
        x_label: "record length after the transient [s]".into(),
        y_label: "log₂ std [log₂ m]".into(),
        x_range: (k0, k1),
        y_range: padded_range(
            mean_points
                .iter()
                .chain(&rms_points)
                .chain(&reference)
                .map(|p| p.1),
            0.08,
        ),
        x_ticks: Ticks::PowerOfTwo,
        series: vec![
            Series::new("∝ length^-1/2", reference, Style::Dashed, 0),
            Series::new(
                format!("surge mean (slope {:.2})", slopes[0]),
                mean_points,
                Style::Markers,
                1,
            ),
            Series::new(
                format!("surge rms (slope {:.2})", slopes[1]),
                rms_points,
                Style::Markers,
                2,
            ),
        ],
        boxes: Vec::new(),
        legend: LegendAt::UpperRight,
    };
    let counts: Vec<String> = samples.iter().map(usize::to_string).collect();
    let figure = Figure {
        title: format!("Surge mean and rms vs record length (E&S Fig. 10): {}; seeds per length {}, transient {transient:.0} s dropped", sea_text(base).split(", seed").next().unwrap_or_default(), counts.join("/")),
        panels: vec![box_panel("surge mean", "surge mean [m]", mean_boxes), box_panel("surge rms", "surge rms [m]", rms_boxes), scatter],
        columns: 3,
        size: (1700, 620),
    };
    let csv_path = out.join("fig10_scatter.csv");
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&figure, &out.join("fig10_boxplots"))?);
    print!("{csv}");
    println!("log-log slope of the scatter against record length: surge mean {:.3}, surge rms {:.3} (1/sqrt(length): -0.5)", slopes[0], slopes[1]);
    report(&written);
    Ok(())
}
