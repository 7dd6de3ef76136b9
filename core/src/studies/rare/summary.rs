//! The study's summary: rates with their intervals, the consequences' weighted distribution.

use super::*;

/// A rate per hour with its 95 % interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Rate {
    pub per_hour: f64,
    pub low_per_hour: f64,
    pub high_per_hour: f64,
    /// Once every so many hours (1 / per_hour; left out when the rate is 0: no event in the
    /// trials has no finite period, and no `null` stands for an infinity).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub once_every_hours: Option<f64>,
}

impl Rate {
    pub(super) fn per_hour(mean: f64, lo: f64, hi: f64) -> Rate {
        let h = 3600.0;
        Rate {
            per_hour: mean * h,
            low_per_hour: lo * h,
            high_per_hour: hi * h,
            once_every_hours: (mean > 0.0).then(|| 1.0 / (mean * h)),
        }
    }

    /// The mean of `x` \[1/s\] with the normal 95 % interval of its standard error (the event's
    /// rate: the seeds' crossing rates differ only through the sampled spectrum).
    fn mean_of(x: &[f64]) -> Rate {
        let n = x.len() as f64;
        let mean = x.iter().sum::<f64>() / n;
        let var = x.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0).max(1.0);
        let se = (var / n).sqrt();
        Rate::per_hour(mean, (mean - 1.96 * se).max(0.0), mean + 1.96 * se)
    }

    /// The rate of events past a threshold, sum_j nu_j 1_j / n \[1/s\], with the event's mean rate
    /// `nu` times Wilson's 95 % score interval of the share k of n trials past it: right for few
    /// trials past it as for many (for k = 0 its top is 3.84 / (n + 3.84), the rule of three's
    /// kin).
    fn past(x: &[f64], nu: f64) -> Rate {
        let n = x.len() as f64;
        let k = x.iter().filter(|&&v| v > 0.0).count() as f64;
        let mean = x.iter().sum::<f64>() / n;
        let (z, p) = (1.96, k / n);
        let centre = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
        let half = z / (1.0 + z * z / n) * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt();
        let (lo, hi) = (nu * (centre - half).max(0.0), nu * (centre + half).min(1.0));
        Rate::per_hour(mean, lo.min(mean), hi.max(mean))
    }
}

/// One consequence's distribution given the event, and its rates beyond the thresholds asked.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConsequenceSummary {
    pub name: &'static str,
    pub label: &'static str,
    /// Weighted quantiles given the event: 5, 50, 95, 99 %.
    pub q05: f64,
    pub q50: f64,
    pub q95: f64,
    pub q99: f64,
    pub min: f64,
    pub max: f64,
    /// Beyond each threshold (past it in the worse direction): the rate of such events.
    pub beyond: Vec<Beyond>,
    /// The trials' values in trial order (for histograms).
    pub values: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Beyond {
    pub threshold: f64,
    pub trials: usize,
    pub rate: Rate,
}

/// The JSON of `aes-sim rare`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RareSummary {
    pub scenario: String,
    pub event: String,
    pub shaft: &'static str,
    pub level_h_over_r: f64,
    pub hub_depth_m: f64,
    pub speed_kn: f64,
    pub wave_heading_deg: f64,
    pub trials: usize,
    /// Simulated seconds of all the trials (with the runs to the event that place the ship).
    pub simulated_s: f64,
    /// The event's rate: the mean of the trials' seas' crossing rates (Rice for each seed's
    /// sampled spectrum). Its interval is the spread of that mean over the seeds' spectra (the
    /// sampled frequencies and directions of `sea.components` waves), not a count's: no trial
    /// waits for an event.
    pub rate: Rate,
    /// Rice's rate from the continuous spectrum (eq. 5.3) for the hub's depth swing \[1/h\].
    pub rice_per_hour: f64,
    /// The hub's depth swing, standard deviation \[m\], and the level's depth below the calm hub
    /// in standard deviations.
    pub hub_sigma_m: f64,
    pub level_sigmas: f64,
    /// h/R at the event's time as the runs recorded it: mean and largest departure from the
    /// level (the ship's own track in the conditioned group, corrected once, can still differ).
    pub h_over_r_at_event_mean: f64,
    pub h_over_r_at_event_worst: f64,
    /// The median departure from the level, and the share of trials within 0.1 of it.
    pub h_over_r_at_event_median_departure: f64,
    pub h_over_r_at_event_within_0_1: f64,
    pub consequences: Vec<ConsequenceSummary>,
    /// The overrides that make the study's scenario the one every trial ran: with a worst trial's
    /// own `sets` (its seed and the ship's place at its event), `aes-sim run` replays it exactly.
    pub replay_sets: Vec<String>,
    /// The trials whose consequences were worst (per consequence, up to 3): replay one with
    /// `aes-sim run` on the scenario with `sim.seed` set to its seed.
    pub worst: Vec<Worst>,
    pub method: &'static str,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Worst {
    pub consequence: &'static str,
    pub trial: u64,
    pub seed: u64,
    pub value: f64,
    /// The overrides, besides `replay_sets`, that replay this trial: its seed and where its ship
    /// was at the event.
    pub sets: Vec<String>,
}

/// Weighted quantile q of `(value, weight)` pairs (the value where the weight below reaches q).
fn quantile(sorted: &[(f64, f64)], q: f64) -> f64 {
    let total: f64 = sorted.iter().map(|x| x.1).sum();
    let mut acc = 0.0;
    for &(v, w) in sorted {
        acc += w;
        if acc >= q * total {
            return v;
        }
    }
    sorted.last().map(|x| x.0).unwrap_or(f64::NAN)
}

/// The summary of a study's trials; `thresholds\[k\]` are consequence k's thresholds.
pub fn summary(sc: &Scenario, trials: &[TrialRecord], thresholds: &[Vec<f64>; 5]) -> Result<RareSummary, String> {
    if trials.is_empty() {
        return Err("no trials".into());
    }
    let ev = &sc.rare_event;
    let hull = sc.ship_hull()?;
    let ordered = sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(0.0);
    let speed_kn = if ev.ship_speed_kn > 0.0 { ev.ship_speed_kn } else { ordered };
    // The waves' heading relative to the ship at the event (180: head seas).
    let heading = (180.0 - sc.sea.from_deg + ev.ship_heading_deg).rem_euclid(360.0);
    let m = crate::studies::operability::scenario_moments(sc, speed_kn, heading)?;
    let hub = m.0[crate::studies::operability::response::HUB[ev.shaft.index()]];
    let radius = 0.5 * sc.propeller.diameter_m;
    let level = ev.level_h_over_r * radius - hull.hub_depth_m;
    let rice = crate::studies::stats::rice_upcrossing_rate(hub[0], hub[1], level) * 3600.0;
    let nu: Vec<f64> = trials.iter().map(|t| t.crossing_rate_per_s).collect();
    let mean_nu = nu.iter().sum::<f64>() / nu.len() as f64;
    let consequences = CONSEQUENCES
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let mut pairs: Vec<(f64, f64)> = trials.iter().map(|t| (t.values[k], t.crossing_rate_per_s)).collect();
            pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
            let beyond = thresholds[k]
                .iter()
                .map(|&th| {
                    let past = |v: f64| if c.larger_is_worse { v > th } else { v < th };
                    let x: Vec<f64> =
                        trials.iter().map(|t| if past(t.values[k]) { t.crossing_rate_per_s } else { 0.0 }).collect();
                    Beyond {
                        threshold: th,
                        trials: x.iter().filter(|&&v| v > 0.0).count(),
                        rate: Rate::past(&x, mean_nu),
                    }
                })
                .collect();
            ConsequenceSummary {
                name: c.name,
                label: c.label,
                q05: quantile(&pairs, 0.05),
                q50: quantile(&pairs, 0.5),
                q95: quantile(&pairs, 0.95),
                q99: quantile(&pairs, 0.99),
                min: pairs[0].0,
                max: pairs[pairs.len() - 1].0,
                beyond,
                values: trials.iter().map(|t| t.values[k]).collect(),
            }
        })
        .collect();
    let worst = CONSEQUENCES
        .iter()
        .enumerate()
        .flat_map(|(k, c)| {
            let mut t: Vec<&TrialRecord> = trials.iter().collect();
            t.sort_by(|a, b| {
                let o = a.values[k].total_cmp(&b.values[k]);
                if c.larger_is_worse {
                    o.reverse()
                } else {
                    o
                }
            });
            t.into_iter().take(3).map(move |t| Worst {
                consequence: c.name,
                trial: t.trial,
                seed: t.seed,
                value: t.values[k],
                sets: vec![
                    format!("sim.seed={}", t.seed),
                    format!("rare_event.ship_x_m={}", t.ship_x_m),
                    format!("rare_event.ship_y_m={}", t.ship_y_m),
                    format!("rare_event.ship_heading_deg={}", t.ship_heading_deg),
                    format!("rare_event.ship_speed_kn={}", t.ship_speed_kn),
                ],
            })
        })
        .collect();
    let hr: Vec<f64> = trials.iter().map(|t| t.h_over_r_at_event).collect();
    Ok(RareSummary {
        scenario: sc.name.clone(),
        event: format!(
            "the {} hub falls through h/R = {} ({})",
            ["port", "starboard"][ev.shaft.index()],
            ev.level_h_over_r,
            if ev.level_h_over_r == sc.seakeeping.ventilation_on_h_over_r {
                "ventilation onset"
            } else if ev.level_h_over_r == 1.0 {
                "emergence: the disc reaches the surface"
            } else {
                "a level of h/R"
            }
        ),
        shaft: ["port", "starboard"][ev.shaft.index()],
        level_h_over_r: ev.level_h_over_r,
        hub_depth_m: hull.hub_depth_m,
        speed_kn,
        wave_heading_deg: heading,
        trials: trials.len(),
        simulated_s: trials.len() as f64 * (ev.time_s * (1 + CORRECTIONS) as f64 + ev.window_s),
        rate: Rate::mean_of(&nu),
        rice_per_hour: rice,
        hub_sigma_m: hub[0].sqrt(),
        level_sigmas: -level / hub[0].sqrt(),
        h_over_r_at_event_mean: hr.iter().sum::<f64>() / hr.len() as f64,
        h_over_r_at_event_worst: hr.iter().map(|h| (h - ev.level_h_over_r).abs()).fold(0.0, f64::max),
        h_over_r_at_event_median_departure: {
            let mut d: Vec<(f64, f64)> = hr.iter().map(|h| ((h - ev.level_h_over_r).abs(), 1.0)).collect();
            d.sort_by(|a, b| a.0.total_cmp(&b.0));
            quantile(&d, 0.5)
        },
        h_over_r_at_event_within_0_1: hr.iter().filter(|h| (*h - ev.level_h_over_r).abs() <= 0.1).count() as f64
            / hr.len() as f64,
        consequences,
        replay_sets: vec![
            format!("rare_event.level_h_over_r={}", ev.level_h_over_r),
            format!("rare_event.shaft={}", serde_json::to_string(&ev.shaft).unwrap_or_default()),
            format!("rare_event.ship_x_m={}", ev.ship_x_m),
            format!("rare_event.ship_speed_kn={}", ev.ship_speed_kn),
            format!("sim.duration_s={}", sc.sim.duration_s),
        ],
        worst,
        method: "conditioned Gaussian seas (Slepian model): each trial's sea is made to put the hub at the level at \
                 rare_event.time_s, falling; the event's rate is the mean of the trials' seas' crossing rates (its interval \
                 the spread of the seeds' sampled spectra); a rate past a threshold is that rate times the share of \
                 trials past it, with Wilson's 95 % interval of the share",
    })
}
