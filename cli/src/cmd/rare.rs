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
    /// The same events with another plant: a scenario (file, `-` or `preset:NAME`) that differs
    /// from FILE only in its `plant` section (e.g. `preset:head-seas-ss6-storage` against
    /// head-seas-ss6). Every trial runs in both plants through the same conditioned sea; prints both
    /// summaries and the consequences trial by trial (the second minus the first, with 95 %
    /// intervals).
    #[arg(long, value_name = "FILE", conflicts_with = "brute_force")]
    against: Option<String>,
    /// Override one parameter (repeatable; applied to both scenarios with --against).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(a: Args) -> Result<(), Failure> {
    let mut sc = load(&a.file, &a.sets)?;
    let raw = sc.clone();
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
            return Err(format!("--brute-force {}: from 0.1 to 10000 hours", aes_core::checks::num(hours)).into());
        }
    }
    // The shard flags before the run to the event that places the ship (as long as the event's
    // time: minutes of work for a late event).
    crate::study::range_of(&a.shards, a.trials, "trial")?;
    if let Some(p) = &a.shards.partial {
        crate::common::OutFile::check(p, "--partial", &[&a.file])?;
    }
    // The brute-force runs come after the study: their work and the trials' (each a run to the
    // event and through its window) are judged against the budget now, before any run.
    if let Some(hours) = a.brute_force {
        let n = crate::study::threads(a.shards.threads, "rare");
        let (runs, run_s) = brute_force_runs(&sc, hours);
        let work_of = |duration_s: f64| {
            let mut run = sc.clone();
            run.sim.duration_s = duration_s;
            run.work()
        };
        let mut trial = sc.clone();
        trial.sim.duration_s = sc.rare_event.time_s + sc.rare_event.window_s;
        let work = runs as f64 * work_of(run_s) + a.trials as f64 * aes_core::studies::rare::trial_work(&trial);
        use aes_core::studies::study::{wall_estimate_s, Platform};
        crate::study::check_budget(
            "rare",
            &format!("{} trials and {runs} brute-force runs of {run_s:.0} s", a.trials),
            wall_estimate_s(1, work, n, Platform::Native),
            n,
            a.shards.allow_long,
        )?;
    }
    // With --merge too: the shards must be of this study (its key), as the options give it.
    let mut spec = RareSpec::new(&sc, a.trials).map_err(|e| format!("{}: {e}", shorten(&a.file)))?;
    spec.thresholds = thresholds;
    if let Some(other) = &a.against {
        let other_sc = load(other, &a.sets)?;
        let spec_b =
            rare::with_plant(&spec, &raw, &other_sc).map_err(|e| format!("--against {}: {e}", shorten(other)))?;
        // The same trials in two plants: a study of its own on the pipeline (its estimate, its
        // shards), both summaries and the paired consequences.
        let pair = rare::RarePair::new(rare::PairedSpec { first: spec, second: spec_b })?;
        return execute(pair, &a.shards, "rare", &a.file, |_, s| {
            aes_core::checks::check_finite(s)?;
            emit_json(s)
        });
    }
    let study = RareEvents::new(spec)?;
    let brute_force = a.brute_force;
    let threads = a.shards.threads;
    execute(study, &a.shards, "rare", &a.file, |study, summary| match brute_force {
        None => emit_json(summary),
        Some(hours) => compare_brute_force(study, summary, hours, threads),
    })
}

/// The brute-force runs for `hours` of sea and each one's length [s]: long enough to hold the
/// warm-up, the window and 20 minutes of sea; at least 10 of them (the interval comes from their
/// spread).
fn brute_force_runs(trial_sc: &aes_core::Scenario, hours: f64) -> (u64, f64) {
    let ev = &trial_sc.rare_event;
    let run_s = (ev.time_s + ev.window_s + 1200.0).max(1200.0);
    let usable = (run_s - ev.time_s - ev.window_s) / 3600.0;
    ((hours / usable).ceil().clamp(10.0, 1.0e6) as u64, run_s)
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
    let pool = crate::study::pool(threads)?;
    let (runs, run_s) = brute_force_runs(trial_sc, hours);
    let brute = pool.install(|| -> Result<rare::BruteForce, String> {
        use rayon::prelude::*;
        let parts = (0..runs)
            .into_par_iter()
            .map(|i| rare::BruteForce::run(trial_sc, run_s, i, i + 1))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(rare::BruteForce { runs: parts.into_iter().flat_map(|b| b.runs).collect() })
    })?;
    let brute_s = runs as f64 * run_s;
    let compare = |name: String, c: rare::Rate, b: rare::Rate| compare_row(name, c, b, brute_s, summary.simulated_s);
    let mut rows = vec![compare("event".into(), summary.rate, brute.rate(None))?];
    for (k, c) in summary.consequences.iter().enumerate() {
        for b in &c.beyond {
            rows.push(compare(format!("{} past {}", c.name, b.threshold), b.rate, brute.rate(Some((k, b.threshold))))?);
        }
    }
    // The summary too, before `json!` takes it in (a NaN there would become a `null`).
    aes_core::checks::check_finite(summary)?;
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

/// One rate by both methods. The two ratios are given only where they are defined (finite): a
/// quantity that is not is left out and `undefined` says why, by its name (no `null` stands for
/// an infinity or a NaN).
fn compare_row(
    name: String,
    c: rare::Rate,
    b: rare::Rate,
    brute_s: f64,
    conditioned_s: f64,
) -> Result<serde_json::Value, String> {
    // (serde_json's `json!` turns a NaN into `null`: the rates are checked first.)
    aes_core::checks::check_finite(&c).map_err(|e| format!("{name}: conditioned rate: {e}"))?;
    aes_core::checks::check_finite(&b).map_err(|e| format!("{name}: brute-force rate: {e}"))?;
    let w = |r: rare::Rate| r.high_per_hour - r.low_per_hour;
    let mut row = serde_json::json!({
        "rate": name,
        "conditioned_per_hour": [c.per_hour, c.low_per_hour, c.high_per_hour],
        "brute_force_per_hour": [b.per_hour, b.low_per_hour, b.high_per_hour],
    });
    let mut undefined = serde_json::Map::new();
    // The difference in standard errors of both (an interval's half width is 1.96 of them).
    let joint = (w(c) * w(c) + w(b) * w(b)).sqrt() / 3.92;
    let z = (c.per_hour - b.per_hour) / joint;
    if joint > 0.0 && z.is_finite() {
        row["joint_standard_errors"] = z.into();
    } else {
        undefined.insert("joint_standard_errors".into(), "both intervals have zero width".into());
    }
    // Simulated seconds for the conditioned interval's width, by brute force, over the
    // conditioned study's: an interval's width goes as one over the root of the time. (For the
    // event's own rate this compares a count with the spread of the seeds' spectra: no measure
    // of the method.)
    let key = "brute_force_seconds_for_the_same_width_over_conditioned";
    let ratio = brute_s * (w(b) / w(c)) * (w(b) / w(c)) / conditioned_s;
    if w(b) <= 0.0 {
        undefined.insert(
            key.into(),
            "the brute-force interval has zero width (no event past it was counted): it has no width to scale".into(),
        );
    } else if !(w(c) > 0.0 && ratio.is_finite()) {
        undefined.insert(key.into(), "the conditioned interval has zero width: no width to reach".into());
    } else {
        row[key] = ratio.into();
    }
    if !undefined.is_empty() {
        row["undefined"] = undefined.into();
    }
    Ok(row)
}

fn names() -> String {
    CONSEQUENCES.iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rate(per_hour: f64, low_per_hour: f64, high_per_hour: f64) -> rare::Rate {
        rare::Rate { per_hour, low_per_hour, high_per_hour, once_every_hours: None }
    }

    /// A ratio that would be infinite or NaN is left out with its reason, never `null`.
    #[test]
    fn undefined_ratios_are_named_not_null() {
        let key = "brute_force_seconds_for_the_same_width_over_conditioned";
        // A conditioned interval of zero width (every trial's weight equal): the ratio would be
        // infinite.
        let row = compare_row("event".into(), rate(2.0, 2.0, 2.0), rate(1.0, 0.5, 1.5), 7200.0, 930.0).unwrap();
        assert!(row.get(key).is_none(), "{row}");
        assert_eq!(row["undefined"][key], "the conditioned interval has zero width: no width to reach");
        assert!(row["joint_standard_errors"].is_f64(), "{row}");
        // Both of zero width: no standard errors either (0 / 0).
        let row = compare_row("event".into(), rate(0.0, 0.0, 0.0), rate(0.0, 0.0, 0.0), 7200.0, 930.0).unwrap();
        assert!(row.get(key).is_none() && row.get("joint_standard_errors").is_none(), "{row}");
        assert_eq!(row["undefined"]["joint_standard_errors"], "both intervals have zero width");
        assert!(!row.to_string().contains("null"), "{row}");
        // Both defined: (1 / 0.5)^2 x 7200 / 900 = 32.
        let row = compare_row("event".into(), rate(1.0, 0.75, 1.25), rate(1.0, 0.5, 1.5), 7200.0, 900.0).unwrap();
        assert_eq!(row[key], 32.0);
        assert_eq!(row["joint_standard_errors"], 0.0);
        assert!(row.get("undefined").is_none(), "{row}");
        // A NaN rate is an error naming it, not a `null`.
        let e = compare_row("x".into(), rate(f64::NAN, 0.0, 1.0), rate(1.0, 0.5, 1.5), 1.0, 1.0).unwrap_err();
        assert!(e.starts_with("x: conditioned rate: per_hour = NaN"), "{e}");
    }
}
