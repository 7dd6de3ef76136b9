//! Brute force: long unconditioned runs counting the events, the check of the conditioned rates.

use super::*;

/// Brute force, the check of the conditioned estimates: long runs of the same scenario in its
/// unconditioned Gaussian sea (`sea.gaussian`), every down-crossing of the level by the hub's
/// h/R after the warm-up (`rare_event.time_s`) counted, and its consequences measured over the
/// window as a conditioned trial's are.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct BruteForce {
    /// Per run: its usable hours (after the warm-up, with a whole window left) and its events'
    /// consequences.
    pub runs: Vec<(f64, Vec<[f64; 5]>)>,
}

impl BruteForce {
    /// Runs `a..b` of `run_s` seconds each (seeds `trial_seed(sim.seed ^ BRUTE_STREAM, i)`).
    pub fn run(sc: &Scenario, run_s: f64, a: u64, b: u64) -> Result<BruteForce, String> {
        let ev = &sc.rare_event;
        let mut runs = Vec::new();
        for i in a..b {
            let mut s = sc.clone();
            s.rare_event.level_h_over_r = 0.0;
            s.sea.gaussian = true;
            s.sim.duration_s = run_s;
            s.sim.seed = trial_seed(sc.sim.seed ^ BRUTE_STREAM, i);
            let r = crate::sim::run(&s).map_err(|e| format!("brute-force run {i}: {e}"))?;
            let ts = r.trace.get(Signal::TS);
            let h = r.trace.get([Signal::HOverR, Signal::HOverRStbd][ev.shaft.index()]);
            let last = run_s - ev.window_s;
            let events = (1..ts.len())
                .filter(|&k| {
                    ts[k] >= ev.time_s && ts[k] <= last && h[k - 1] >= ev.level_h_over_r && h[k] < ev.level_h_over_r
                })
                // From the last row before the crossing: a row after it may already hold some of
                // the drop (the conditioned trials start exactly at the crossing).
                .filter_map(|k| consequences_at(&r, ev.shaft.index(), ts[k - 1], ev.window_s).map(|(v, _)| v))
                .collect();
            runs.push(((last - ev.time_s).max(0.0) / 3600.0, events));
        }
        Ok(BruteForce { runs })
    }

    /// The rate per hour of events whose consequence `k` is past `threshold` (every event with
    /// None), with the 95 % interval from the runs' spread (events come in groups, so not
    /// Poisson's).
    pub fn rate(&self, past: Option<(usize, f64)>) -> Rate {
        let counts: Vec<f64> = self
            .runs
            .iter()
            .map(|(_, ev)| {
                ev.iter()
                    .filter(|v| match past {
                        None => true,
                        Some((k, th)) => {
                            if CONSEQUENCES[k].larger_is_worse {
                                v[k] > th
                            } else {
                                v[k] < th
                            }
                        }
                    })
                    .count() as f64
            })
            .collect();
        let hours: Vec<f64> = self.runs.iter().map(|r| r.0).collect();
        let (n, total_h) = (counts.len() as f64, hours.iter().sum::<f64>());
        if total_h.is_nan() || total_h <= 0.0 {
            return Rate::per_hour(0.0, 0.0, 0.0);
        }
        let rate = counts.iter().sum::<f64>() / total_h;
        // Ratio estimator's variance over runs.
        let var =
            counts.iter().zip(&hours).map(|(c, h)| (c - rate * h) * (c - rate * h)).sum::<f64>() / (n - 1.0).max(1.0);
        let se = (var * n).sqrt() / total_h;
        Rate {
            per_hour: rate,
            low_per_hour: (rate - 1.96 * se).max(0.0),
            high_per_hour: rate + 1.96 * se,
            once_every_hours: (rate > 0.0).then(|| 1.0 / rate),
        }
    }
}

/// The brute-force runs' seed stream, apart from the conditioned trials'.
const BRUTE_STREAM: u64 = 0x0B1F_0C2E_0000_0001;
