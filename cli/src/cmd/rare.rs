//! `aes-sim rare`: the consequences of a rare propeller surface event by conditioned simulation
//! (issue 32), whole or one shard of it, and the merge of shards.

use crate::common::{emit_json, load, shorten, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::studies::rare::{self, RareEvents, RareSpec, CONSEQUENCES};
use aes_core::studies::study::Study;

// The command line of `aes-sim rare`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (file, `-` or `preset:NAME`) with a random sea: its ship, hub depth, speed
    /// (first order), sea and `rare_event` section.
    #[arg(default_value = "preset:head-seas-ss6")]
    file: String,
    /// The event: `ventilation` (h/R falls through the ventilation onset level,
    /// seakeeping.ventilation_on_h_over_r), `emergence` (h/R through 1), or `level` with --level.
    #[arg(long, default_value = "ventilation")]
    event: String,
    /// h/R the hub falls through (with --event level).
    #[arg(long)]
    level: Option<f64>,
    /// The shaft: port or starboard.
    #[arg(long, default_value = "port")]
    shaft: String,
    /// Trials (each a run of rare_event.time_s + window_s seconds).
    #[arg(long, default_value_t = 200)]
    trials: u64,
    /// Thresholds of consequences, NAME=VALUE (repeatable; names as in the output's
    /// consequences, e.g. min_bus_voltage_pu=0.95): the rate per hour of events past each.
    #[arg(long = "threshold", value_name = "NAME=VALUE")]
    thresholds: Vec<String>,
    /// Master seed (default: the scenario's sim.seed).
    #[arg(long)]
    seed: Option<u64>,
    #[command(flatten)]
    shards: ShardArgs,
    /// Also count events in this many hours of unconditioned Gaussian seas (runs of 1,200 s),
    /// and compare: each rate by both methods, and the simulated seconds each needs for the
    /// same 95 % interval width (the benchmark of the method).
    #[arg(long = "brute-force", value_name = "HOURS", conflicts_with_all = ["range", "merge"])]
    brute_force: Option<f64>,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(a: Args) -> Result<(), Failure> {
    let mut sc = load(&a.file, &a.sets)?;
    if let Some(s) = a.seed {
        sc.sim.seed = s;
    }
    let level = match (a.event.as_str(), a.level) {
        ("ventilation", None) => sc.seakeeping.ventilation_on_h_over_r,
        ("emergence", None) => 1.0,
        ("level", Some(l)) => l,
        ("level", None) => return Err("--event level needs --level H_OVER_R".into()),
        (_, Some(_)) => return Err("--level goes with --event level".into()),
        (e, _) => return Err(format!("--event '{}': one of ventilation, emergence, level", shorten(e)).into()),
    };
    sc.rare_event.level_h_over_r = level;
    sc.rare_event.shaft = match a.shaft.as_str() {
        "port" => aes_core::sea::conditioning::Shaft::Port,
        "starboard" => aes_core::sea::conditioning::Shaft::Starboard,
        s => return Err(format!("--shaft '{}': port or starboard", shorten(s)).into()),
    };
    sc.sim.duration_s = sc.sim.duration_s.max(sc.rare_event.time_s + sc.rare_event.window_s);
    sc.validate().map_err(|e| format!("{}: {e}", shorten(&a.file)))?;
    let mut thresholds = std::collections::BTreeMap::<String, Vec<f64>>::new();
    for t in &a.thresholds {
        let bad = || format!("--threshold '{}': expected NAME=VALUE with NAME one of {}", shorten(t), names());
        let (n, v) = t.split_once('=').ok_or_else(bad)?;
        let n = CONSEQUENCES.iter().find(|c| c.name == n.trim()).ok_or_else(bad)?.name;
        let v: f64 = v.trim().parse().ok().filter(|x: &f64| x.is_finite()).ok_or_else(bad)?;
        thresholds.entry(n.to_string()).or_default().push(v);
    }
    if let Some(hours) = a.brute_force {
        if !(hours.is_finite() && (0.1..=10_000.0).contains(&hours)) {
            return Err(format!("--brute-force {hours}: from 0.1 to 10000 hours").into());
        }
    }
    // With --merge too: the shards must be of this study (its key), as the options give it.
    let mut spec = RareSpec::new(&sc, a.trials).map_err(|e| format!("{}: {e}", shorten(&a.file)))?;
    spec.thresholds = thresholds;
    let study = RareEvents::new(spec)?;
    let brute_force = a.brute_force;
    let threads = a.shards.threads;
    execute(study, &a.shards, "rare", &a.file, |study, summary| match brute_force {
        None => emit_json(summary),
        Some(hours) => compare_brute_force(study, summary, hours, threads),
    })
}

/// Counts events in `hours` of unconditioned Gaussian seas and prints the summary beside them.
fn compare_brute_force(
    study: &RareEvents,
    summary: &rare::RareSummary,
    hours: f64,
    threads: Option<usize>,
) -> Result<(), Failure> {
    let trial_sc = &study.spec().scenario;
    let threads = crate::study::threads(threads, "rare");
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| format!("--threads: {e}"))?;
    // Runs long enough to hold the warm-up, the window and 20 minutes of sea; at least 10 of
    // them (the interval comes from their spread).
    let ev = &trial_sc.rare_event;
    let run_s = (ev.time_s + ev.window_s + 1200.0).max(1200.0);
    let usable = (run_s - ev.time_s - ev.window_s) / 3600.0;
    let runs = (hours / usable).ceil().clamp(10.0, 1.0e6) as u64;
    let brute = pool.install(|| -> Result<rare::BruteForce, String> {
        use rayon::prelude::*;
        let parts = (0..runs)
            .into_par_iter()
            .map(|i| rare::BruteForce::run(trial_sc, run_s, i, i + 1))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(rare::BruteForce { runs: parts.into_iter().flat_map(|b| b.runs).collect() })
    })?;
    let brute_s = runs as f64 * run_s;
    let compare = |name: String, c: rare::Rate, b: rare::Rate| {
        let w = |r: rare::Rate| r.high_per_hour - r.low_per_hour;
        serde_json::json!({
            "rate": name,
            "conditioned_per_hour": [c.per_hour, c.low_per_hour, c.high_per_hour],
            "brute_force_per_hour": [b.per_hour, b.low_per_hour, b.high_per_hour],
            "joint_standard_errors": (c.per_hour - b.per_hour) / ((w(c) * w(c) + w(b) * w(b)) / (3.92 * 3.92)).sqrt(),
            // Simulated seconds for the conditioned interval's width, by brute force, over the
            // conditioned study's: an interval's width goes as one over the root of the time.
            // (For the event's own rate this compares a count with the spread of the seeds'
            // spectra: no measure of the method.)
            "brute_force_seconds_for_the_same_width_over_conditioned": brute_s * (w(b) / w(c)) * (w(b) / w(c)) / summary.simulated_s,
        })
    };
    let mut rows = vec![compare("event".into(), summary.rate, brute.rate(None))];
    for (k, c) in summary.consequences.iter().enumerate() {
        for b in &c.beyond {
            rows.push(compare(format!("{} past {}", c.name, b.threshold), b.rate, brute.rate(Some((k, b.threshold)))));
        }
    }
    emit_json(&serde_json::json!({
        "summary": summary,
        "brute_force": {
            "runs": runs,
            "simulated_s": brute_s,
            "events": brute.runs.iter().map(|r| r.1.len()).sum::<usize>(),
            "conditioned_simulated_s": summary.simulated_s,
            "compare": rows,
        },
    }))
}

fn names() -> String {
    CONSEQUENCES.iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
}
