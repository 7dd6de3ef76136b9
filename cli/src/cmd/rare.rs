//! `aes-sim rare`: the consequences of a rare propeller surface event by conditioned simulation
//! (issue 32), whole or one shard of it, and the merge of shards.

use crate::common::{emit_json, load, read_bounded, shorten, Failure, OutFile, Threads};
use aes_core::studies::rare::{self, RarePartial, CONSEQUENCES};

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
    /// Worker threads (default: all cores). The numbers do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    /// Run only trials A..B (a shard); needs --partial.
    #[arg(long = "trial-range", value_name = "A..B")]
    trial_range: Option<String>,
    /// Write the shard's trials to this file (JSON) instead of the summary.
    #[arg(long)]
    partial: Option<String>,
    /// Summarise these shards' files (of the same scenario and options) instead of running.
    #[arg(long, num_args = 1.., value_name = "FILE")]
    merge: Vec<String>,
    /// Also count events in this many hours of unconditioned Gaussian seas (runs of 1,200 s),
    /// and compare: each rate by both methods, and the simulated seconds each needs for the
    /// same 95 % interval width (the benchmark of the method).
    #[arg(long = "brute-force", value_name = "HOURS")]
    brute_force: Option<f64>,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

/// Largest shard file [bytes] (a trial is about 300 bytes).
const MAX_PARTIAL_BYTES: u64 = 64 << 20;

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
    let mut thresholds: [Vec<f64>; 5] = Default::default();
    for t in &a.thresholds {
        let bad = || format!("--threshold '{}': expected NAME=VALUE with NAME one of {}", shorten(t), names());
        let (n, v) = t.split_once('=').ok_or_else(bad)?;
        let k = CONSEQUENCES.iter().position(|c| c.name == n.trim()).ok_or_else(bad)?;
        let v: f64 = v.trim().parse().ok().filter(|x: &f64| x.is_finite()).ok_or_else(bad)?;
        thresholds[k].push(v);
    }
    if !a.merge.is_empty() {
        let trial_sc = rare::trial_scenario(&sc)?;
        let mut all = RarePartial { study: rare::study_key(&trial_sc), trials: Vec::new() };
        for f in &a.merge {
            let text = read_bounded(f, MAX_PARTIAL_BYTES, "a rare-event shard")?;
            let p: RarePartial =
                serde_json::from_str(&text).map_err(|e| format!("{}: not a rare-event shard: {e}", shorten(f)))?;
            all.merge(p).map_err(|e| format!("--merge: {e}"))?;
        }
        let missing = (0..a.trials).find(|i| all.trials.binary_search_by_key(i, |t| t.trial).is_err());
        if let Some(i) = missing {
            return Err(format!("--merge: trial {i} of {} is in no shard", a.trials).into());
        }
        if let Some(t) = all.trials.iter().find(|t| t.trial >= a.trials) {
            return Err(format!("--merge: trial {} is beyond --trials {}", t.trial, a.trials).into());
        }
        return emit_json(&rare::summary(&trial_sc, &all, &thresholds)?);
    }
    rare::check_study(&sc, a.trials).map_err(|e| format!("{}: {e}", shorten(&a.file)))?;
    let (lo, hi) = match &a.trial_range {
        None => (0, a.trials),
        Some(r) => {
            let bad = || format!("--trial-range '{}': expected A..B with A < B <= --trials", shorten(r));
            let (x, y) = r.split_once("..").ok_or_else(bad)?;
            let (x, y): (u64, u64) = (x.trim().parse().map_err(|_| bad())?, y.trim().parse().map_err(|_| bad())?);
            if !(x < y && y <= a.trials) {
                return Err(bad().into());
            }
            (x, y)
        }
    };
    let out = match (&a.partial, &a.trial_range) {
        (Some(p), _) => Some(OutFile::check(p, "--partial", &[&a.file])?),
        (None, Some(_)) => return Err("--trial-range needs --partial FILE (summarise the shards with --merge)".into()),
        (None, None) => None,
    };
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let threads = a.threads.unwrap_or(cores).clamp(1, cores);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| format!("--threads: {e}"))?;
    let (trial_sc, partial) = pool.install(|| -> Result<_, String> {
        use rayon::prelude::*;
        sc.rao_table_with(&Threads)?;
        let trials = rare::Trials::new(&sc)?;
        let records = (lo..hi).into_par_iter().map(|i| trials.run(i)).collect::<Result<Vec<_>, _>>()?;
        Ok((trials.sc.clone(), RarePartial { study: rare::study_key(&trials.sc), trials: records }))
    })?;
    if let Some(o) = out {
        return Ok(o.write(serde_json::to_string(&partial).map_err(|e| e.to_string())?.as_bytes())?);
    }
    let summary = rare::summary(&trial_sc, &partial, &thresholds)?;
    let Some(hours) = a.brute_force else {
        return emit_json(&summary);
    };
    if !(hours.is_finite() && (0.1..=10_000.0).contains(&hours)) {
        return Err(format!("--brute-force {hours}: from 0.1 to 10000 hours").into());
    }
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
            .map(|i| rare::BruteForce::run(&trial_sc, run_s, i, i + 1))
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
