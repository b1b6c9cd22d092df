//! `slowdrift study transient`: the rms per block of slow-drift cycles over many runs, and how
//! the initial condition changes it (E&S Fig. 11).

use super::{report, sea_text, ten_cycles, threads, write_text, TransientArgs};
use crate::plot::{padded_range, write_figure, Figure, LegendAt, Panel, Series, Style, Ticks};
use slowdrift::montecarlo::{seed_statistics, simulate_positions, SeedStatistics};
use slowdrift::scenario::TRANSIENT_CYCLES;
use slowdrift::studies::blocks::block_summaries;
use slowdrift::studies::parallel_map;
use slowdrift::Problem;
use std::fmt::Write as _;

/// Fig. 11: surge mean and rms per block of `--block-cycles` (default ten) undamped surge
/// periods from the start, averaged over runs (seeds 1..=runs, the same seeds for every
/// initial condition), for initial surge offsets added to the configuration's initial
/// position (released at rest).
pub(super) fn transient(base: &Problem, args: &TransientArgs) -> Result<(), String> {
    let (runs, blocks, cycles) = (args.runs, args.blocks, args.block_cycles);
    let offsets = &args.offsets.0;
    let out = args.out.as_path();
    let block = ten_cycles(base)? / TRANSIENT_CYCLES * cycles;
    let dt = base.run.time_step;
    let jobs = offsets.len() * runs;
    println!(
        "{} initial offsets x {runs} runs of {blocks} blocks of {block:.0} s on {} thread(s)",
        offsets.len(),
        threads(args.threads)
    );
    let started = std::time::Instant::now();
    let results = parallel_map(jobs, threads(args.threads), |i| {
        let mut config = base.clone();
        config.sea.seed = (i % runs) as u64 + 1;
        config.run.duration = blocks as f64 * block;
        config.initial.position[0] += offsets[i / runs];
        let [surge, _, _] = simulate_positions(config)?;
        block_summaries(&surge, dt, block)
    });
    println!("{jobs} runs in {:.1} s", started.elapsed().as_secs_f64());
    let mut csv =
        String::from("initial_offset_m,block,start_s,end_s,runs,mean_m,mean_se_m,rms_m,rms_se_m\n");
    let (mut mean_series, mut rms_series) = (Vec::new(), Vec::new());
    for (o, offset) in offsets.iter().enumerate() {
        let mine = results[o * runs..(o + 1) * runs]
            .iter()
            .map(|r| r.clone().map_err(|e| e.to_string()))
            .collect::<Result<Vec<_>, _>>()?;
        let (mut means, mut rmss) = (Vec::new(), Vec::new());
        for b in 0..blocks {
            let stat = |f: fn(&slowdrift::stats::Summary) -> f64| -> SeedStatistics {
                let values: Vec<f64> = mine.iter().map(|r| f(&r[b])).collect();
                seed_statistics(&values).expect("at least two runs")
            };
            let (m, r) = (stat(|s| s.mean), stat(|s| s.rms));
            let (mse, rse) = (
                m.standard_error.unwrap_or(0.0),
                r.standard_error.unwrap_or(0.0),
            );
            writeln!(
                csv,
                "{offset},{},{},{},{runs},{},{mse},{},{rse}",
                b + 1,
                b as f64 * block,
                (b + 1) as f64 * block,
                m.mean,
                r.mean
            )
            .ok();
            // Series side by side (dodged by 2 % of the axis) so that equal values stay visible.
            let dodge =
                (o as f64 - 0.5 * (offsets.len() - 1) as f64) * 0.02 * blocks as f64 * cycles;
            let x = (b as f64 + 0.5) * cycles + dodge;
            means.push((x, m.mean, mse));
            rmss.push((x, r.mean, rse));
        }
        let start = base.initial.position[0] + offset;
        let label = if start == 0.0 {
            "from rest at X = 0".to_string()
        } else {
            format!("released at rest from X = {start} m")
        };
        let series = |points: &[(f64, f64, f64)]| {
            Series::new(
                label.clone(),
                points.iter().map(|p| (p.0, p.1)).collect(),
                Style::Markers,
                o + 1,
            )
            .with_errors(points.iter().map(|p| p.2).collect())
        };
        mean_series.push(series(&means));
        rms_series.push(series(&rmss));
    }
    let x_range = (0.0, blocks as f64 * cycles);
    let panel = |title: &str, y_label: &str, series: Vec<Series>, legend: LegendAt| {
        let y_range = padded_range(
            series.iter().flat_map(|s| {
                s.points
                    .iter()
                    .zip(&s.errors)
                    .flat_map(|(p, e)| [p.1 - e, p.1 + e])
            }),
            0.25,
        );
        Panel {
            title: title.into(),
            x_label: "slow-drift cycles from the start (block centres) [-]".into(),
            y_label: y_label.into(),
            x_range,
            y_range,
            x_ticks: Ticks::Plain,
            series,
            boxes: Vec::new(),
            legend,
        }
    };
    let figure = Figure {
        title: format!("Start-up transient (E&S Fig. 11): surge per block of {cycles} cycles ({block:.0} s), mean of {runs} runs ± 1 standard error; {}", sea_text(base).split(", seed").next().unwrap_or_default()),
        panels: vec![
            panel("surge rms per block", "surge rms about the block mean [m]", rms_series, LegendAt::UpperRight),
            panel("surge mean per block", "surge mean [m]", mean_series, LegendAt::LowerRight),
        ],
        columns: 2,
        size: (1500, 600),
    };
    let csv_path = out.join(format!("fig11_blocks_{cycles}cycles.csv"));
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(
        &figure,
        &out.join(format!("fig11_transient_{cycles}cycles")),
    )?);
    print!("{csv}");
    report(&written);
    Ok(())
}
