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
        let mut all = RarePartial::default();
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
        return emit_json(&rare::summary(&rare::trial_scenario(&sc)?, &all, &thresholds)?);
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
        Ok((trials.sc, RarePartial { trials: records }))
    })?;
    match out {
        Some(o) => o.write(serde_json::to_string(&partial).map_err(|e| e.to_string())?.as_bytes())?,
        None => emit_json(&rare::summary(&trial_sc, &partial, &thresholds)?)?,
    }
    Ok(())
}

fn names() -> String {
    CONSEQUENCES.iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
}
