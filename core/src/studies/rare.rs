//! How often, and how bad (issue 32): the consequences of rare propeller surface events by
//! conditioned simulation.
//!
//! Brute-force Monte Carlo waits for an event; at the thesis' hub depth (h0 = 6 m, SS6, 25 kn) it
//! waits days. Here every trial makes one: its sea is a Gaussian random sea conditioned on the
//! chosen hub falling through the chosen h/R at `rare_event.time_s` (`sim::conditioned`:
//! Slepian's model, exact for the linear seaway), and the full nonlinear model (surface losses
//! with their hysteresis, motors, controllers, buses, turbines) runs through it. Of the methods
//! for rare events in ship dynamics (importance sampling, splitting, the split-time method,
//! conditioned episodes), conditioning fits here because the trigger is linear in the waves: no
//! weights to tune, no level-by-level restarts, and every trial costs one short run whatever the
//! event's rarity; the nonlinearity is all downstream of the event, where the model runs
//! unchanged.
//!
//! Trial j's sea is seed s_j's (frequencies and directions of the scenario's sampler, Gaussian
//! amplitudes) conditioned on one of its crossings; seeds' spectra differ a little, so seed s_j's
//! crossing rate nu_j (its own Rice rate) is trial j's weight. The rate of events is
//! E\[nu\] (estimated by the mean of nu_j, with its 95 % interval), the rate of events whose
//! consequence exceeds a threshold E[nu 1{c > threshold}] (the mean of nu_j 1_j, with its
//! interval), and the distribution of a consequence given the event is weighted by nu_j.
//! Rice's rate from the continuous spectrum stands beside them.

use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::RunResult;
use crate::studies::stats::trial_seed;
use crate::studies::study::Study;
use serde::{Deserialize, Serialize};

/// The pilot run's speed is averaged over this long before the event [s].
const SPEED_AVERAGE_S: f64 = 60.0;

/// Runs to the event that correct the ship's place in a trial's own sea before the trial (with
/// the event at 150 s, one pass left h/R at the event 0.108 off at worst in 20 trials at h0 =
/// 4.5 m, two passes 0.061; 0.060 on the RAO table cubic in frequency).
pub const CORRECTIONS: usize = 2;

/// Units of work of one trial of the study whose trials run `trial_sc` (its run holds the event
/// and its window): the [`CORRECTIONS`] runs to the event that place the ship, then the trial's
/// run ([`Trials::run`]). Counting the trial's run alone, estimates were half the time taken.
pub fn trial_work(trial_sc: &Scenario) -> f64 {
    let mut to_event = trial_sc.clone();
    to_event.sim.duration_s = trial_sc.rare_event.time_s.max(trial_sc.sim.record_interval_s);
    trial_sc.work() + CORRECTIONS as f64 * to_event.work()
}

/// Most trials of one rare-event study (each is a run of `time_s + window_s`).
pub const MAX_TRIALS: u64 = 100_000;

/// Fewest trials of a study: the event's 95 % interval is the spread of the trials' seas'
/// crossing rates, and one trial has no spread (its sample variance has no degree of freedom; a
/// zero-width interval would claim a certainty the study does not have).
pub const MIN_TRIALS: u64 = 2;

/// A consequence of the event: its name (with its unit), label, and whether larger is worse.
pub struct Consequence {
    pub name: &'static str,
    pub label: &'static str,
    pub larger_is_worse: bool,
}

/// The motor power before an event is its mean over this long \[s\].
pub const PRE_EVENT_S: f64 = 5.0;

/// The consequences measured from the event to `window_s` after it.
pub const CONSEQUENCES: [Consequence; 5] = [
    Consequence {
        name: "min_bus_voltage_pu",
        label: "lowest bus voltage (mean of the two buses)",
        larger_is_worse: false,
    },
    Consequence {
        name: "peak_turbine_speed_pu",
        label: "highest gas turbine speed (mean of the four)",
        larger_is_worse: true,
    },
    Consequence {
        name: "shaft_speed_swing_rpm",
        label: "the event's shaft: highest minus lowest speed",
        larger_is_worse: true,
    },
    Consequence {
        name: "motor_power_drop_mw",
        label: "motor power (both motors): its mean over the 5 s before the event minus its lowest after",
        larger_is_worse: true,
    },
    Consequence { name: "brake_energy_mj", label: "energy burnt in the brake resistors", larger_is_worse: true },
];

/// The consequences in `trace` of an event of shaft `shaft` at time `t` \[s\], over `[t, t + window]`,
/// and h/R there: the one measure of a conditioned trial and of an event counted in a long run.
pub fn consequences_at(r: &RunResult, shaft: usize, t: f64, window: f64) -> Option<([f64; 5], f64)> {
    let tr = &r.trace;
    let ts = tr.get(Signal::TS);
    let i0 = ts.partition_point(|&x| x < t - 1e-9);
    let i1 = ts.partition_point(|&x| x <= t + window + 1e-9);
    if i0 >= ts.len() || i1 <= i0 + 1 || ts[i1 - 1] < t + window - 1e-6 {
        return None;
    }
    let col = |s: Signal| &tr.get(s)[i0..i1];
    let min = |x: &[f64]| x.iter().copied().fold(f64::INFINITY, f64::min);
    let max = |x: &[f64]| x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let rpm = col([Signal::PropRpm1, Signal::PropRpm2][shaft]);
    let pm = col(Signal::PMotorW);
    // The power before the event: its mean over the 5 s before, not its value at one row (it
    // swings at the encounter frequency, and a row 0.1 s later moved the rate of drops past
    // 9.5 MW by 40 %).
    let before = &tr.get(Signal::PMotorW)[ts.partition_point(|&x| x < t - PRE_EVENT_S - 1e-9)..=i0];
    let p_before = before.iter().sum::<f64>() / before.len() as f64;
    let dt = if ts.len() > 1 { ts[1] - ts[0] } else { 0.0 };
    let brake: f64 = col(Signal::BrakePowerW).iter().sum::<f64>() * dt;
    let h_r = tr.get([Signal::HOverR, Signal::HOverRStbd][shaft])[i0];
    Some((
        [
            min(col(Signal::BusVoltagePu)),
            max(col(Signal::TurbineSpeedPu)),
            max(rpm) - min(rpm),
            (p_before - min(pm)) / 1e6,
            brake / 1e6,
        ],
        h_r,
    ))
}

/// One conditioned trial.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrialRecord {
    pub trial: u64,
    /// The sea's seed: `aes-sim run` with this `sim.seed` and the study's scenario replays it.
    pub seed: u64,
    /// This sea's crossing rate of the level [1/s] (the trial's weight).
    pub crossing_rate_per_s: f64,
    /// h/R of the hub at the event's time as the run recorded it (the level, up to the ship's
    /// small departure from its ordered track).
    pub h_over_r_at_event: f64,
    /// The ship's place and speed the sea was conditioned on (`rare_event.ship_x_m`,
    /// `ship_speed_kn` of its replay).
    pub ship_x_m: f64,
    pub ship_y_m: f64,
    pub ship_heading_deg: f64,
    pub ship_speed_kn: f64,
    /// The consequences in the order of [`CONSEQUENCES`].
    pub values: [f64; 5],
}

/// Checks a study before it runs: the conditioning is on, the sea random, the trials in range.
pub fn check_study(sc: &Scenario, trials: u64) -> Result<(), String> {
    if sc.sea.kind != crate::scenario::SeaKind::Random {
        return Err(format!("sea.kind must be \"random\" for a rare-event study (got {:?})", sc.sea.kind));
    }
    if !sc.rare_event.active() {
        return Err(
            "rare_event.level_h_over_r: set the h/R the hub falls through (e.g. 1.1 for ventilation, 1 for emergence)"
                .into(),
        );
    }
    if !(MIN_TRIALS..=MAX_TRIALS).contains(&trials) {
        return Err(format!(
            "trials = {trials}: must be from {MIN_TRIALS} to {MAX_TRIALS} (the event's 95 % interval is the spread of \
             the trials' seas' rates: fewer than {MIN_TRIALS} trials have none)"
        ));
    }
    let need = sc.rare_event.time_s + sc.rare_event.window_s;
    if sc.sim.duration_s + 1e-9 < need {
        return Err(format!(
            "sim.duration_s = {}: a trial runs to rare_event.time_s + window_s = {need} s",
            crate::checks::num(sc.sim.duration_s)
        ));
    }
    Ok(())
}

/// The study's scenario as each trial runs it: the run ends with the window, and unless the
/// scenario says where the ship is at the event (`rare_event.ship_x_m`, `ship_speed_kn`), they
/// are taken from a run of the scenario to the event in its unconditioned (Gaussian) sea of
/// `sim.seed`: the ship slows in waves, and the sea is conditioned where the ship is.
pub fn trial_scenario(sc: &Scenario) -> Result<Scenario, String> {
    let mut s = sc.clone();
    let ev = &sc.rare_event;
    s.sim.duration_s = ev.time_s + ev.window_s;
    if ev.ship_x_m == 0.0 || ev.ship_speed_kn == 0.0 {
        let mut pilot = s.clone();
        pilot.rare_event.level_h_over_r = 0.0;
        pilot.sea.gaussian = true;
        pilot.sim.duration_s = ev.time_s.max(pilot.sim.record_interval_s);
        let r = crate::sim::run(&pilot).map_err(|e| format!("the run to the event's place: {e}"))?;
        let ts = r.trace.get(Signal::TS);
        let i = ts.partition_point(|&t| t < ev.time_s - 1e-9).min(ts.len() - 1);
        if ev.ship_x_m == 0.0 {
            s.rare_event.ship_x_m = r.trace.get(Signal::XM)[i];
            s.rare_event.ship_y_m = r.trace.get(Signal::YM)[i];
            s.rare_event.ship_heading_deg = r.trace.get(Signal::HeadingDeg)[i];
        }
        if ev.ship_speed_kn == 0.0 {
            // The speed of the trials' weights: its mean over the last minute before the event
            // (the ship's speed swings by +-0.7 kn with the wave groups in SS6).
            let j = ts.partition_point(|&t| t < ev.time_s - SPEED_AVERAGE_S).min(i);
            let v = &r.trace.get(Signal::ShipSpeedKn)[j..=i];
            s.rare_event.ship_speed_kn = (v.iter().sum::<f64>() / v.len() as f64).max(0.01);
        }
    }
    Ok(s)
}

/// Trials `a..b` (run one after another; the command line spreads them over threads).
pub struct Trials {
    /// The scenario each trial runs ([`trial_scenario`]): replay trial i with `aes-sim run` of
    /// it with `sim.seed` = the trial's seed.
    pub sc: Scenario,
}

impl Trials {
    pub fn new(sc: &Scenario) -> Result<Trials, String> {
        let s = trial_scenario(sc)?;
        Ok(Trials { sc: s })
    }

    /// Trial `i`: the sea of seed `trial_seed(sim.seed, i)` conditioned on the event.
    pub fn run(&self, i: u64) -> Result<TrialRecord, String> {
        let seed = trial_seed(self.sc.sim.seed, i);
        let fail = |e: String| format!("trial {i} (sea seed {seed}): {e}");
        let mut s = self.sc.clone();
        s.sim.seed = seed;
        // The ship's place and speed at the event in this sea: the study's estimate, corrected
        // by a run to the event in the sea conditioned on them.
        place_ship(&mut s, CORRECTIONS).map_err(fail)?;
        // The trial's weight: its sea's crossing rate on the study's track. On the track of the
        // correction the ship has already met the conditioned wave group (slowed by it), and at
        // 5 sigma the rate's sensitivity to the speed biased the weights by a fifth.
        let mut nominal = self.sc.clone();
        nominal.sim.seed = seed;
        let (_, cond) = crate::sim::seaway::sea_of(&nominal).map_err(fail)?;
        let cond = cond.ok_or_else(|| fail("the sea is not conditioned".into()))?;
        let r = crate::sim::run(&s).map_err(|e| fail(e.to_string()))?;
        let ev = &self.sc.rare_event;
        let (values, h_r) = consequences_at(&r, ev.shaft.index(), ev.time_s, ev.window_s)
            .ok_or_else(|| fail("the run ended before the window".into()))?;
        Ok(TrialRecord {
            trial: i,
            seed,
            crossing_rate_per_s: cond.crossing_rate_per_s,
            h_over_r_at_event: h_r,
            ship_x_m: s.rare_event.ship_x_m,
            ship_y_m: s.rare_event.ship_y_m,
            ship_heading_deg: s.rare_event.ship_heading_deg,
            ship_speed_kn: s.rare_event.ship_speed_kn,
            values,
        })
    }
}

/// Corrects where the ship is at the event (`rare_event.ship_x_m`, `ship_y_m`,
/// `ship_heading_deg`, `ship_speed_kn`) by `passes` runs to the event in the sea conditioned on
/// the last estimate: the ship's track depends a little on the sea it meets (each trial's own, or
/// the most likely wave group's, where the ship slows less than in a random sea).
pub fn place_ship(s: &mut Scenario, passes: usize) -> Result<(), String> {
    let t0 = s.rare_event.time_s;
    for _ in 0..passes {
        let mut to_event = s.clone();
        to_event.sim.duration_s = t0.max(to_event.sim.record_interval_s);
        let r = crate::sim::run(&to_event).map_err(|e| e.to_string())?;
        let last = r.trace.get(Signal::TS).len() - 1;
        let ev = &mut s.rare_event;
        ev.ship_x_m = r.trace.get(Signal::XM)[last];
        ev.ship_y_m = r.trace.get(Signal::YM)[last];
        ev.ship_heading_deg = r.trace.get(Signal::HeadingDeg)[last];
        ev.ship_speed_kn = r.trace.get(Signal::ShipSpeedKn)[last].max(0.01);
    }
    Ok(())
}

/// The definition of a rare-event study: the scenario every trial runs ([`trial_scenario`]: the
/// ship placed at the event), the number of trials, and the thresholds of consequences whose
/// rates the summary gives (consequence name -> thresholds; not part of the study's key, so the
/// same trials can be summarised with other thresholds).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RareSpec {
    pub scenario: Scenario,
    pub trials: u64,
    #[serde(default)]
    pub thresholds: std::collections::BTreeMap<String, Vec<f64>>,
}

/// Most thresholds of one consequence.
pub const MAX_THRESHOLDS: usize = 20;

impl RareSpec {
    /// The study of `sc` (its `rare_event` section) with `trials` trials: places the ship at the
    /// event ([`trial_scenario`], a run to it unless the scenario says where it is).
    pub fn new(sc: &Scenario, trials: u64) -> Result<RareSpec, String> {
        check_study(sc, trials)?;
        Ok(RareSpec { scenario: trial_scenario(sc)?, trials, thresholds: Default::default() })
    }

    /// The thresholds in the order of [`CONSEQUENCES`]; an error names an unknown consequence.
    pub fn thresholds(&self) -> Result<[Vec<f64>; 5], String> {
        let mut th: [Vec<f64>; 5] = Default::default();
        for (name, v) in &self.thresholds {
            let k = CONSEQUENCES.iter().position(|c| c.name == name).ok_or_else(|| {
                format!(
                    "thresholds: no consequence named '{}' (one of {})",
                    crate::checks::shorten(name),
                    CONSEQUENCES.iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
                )
            })?;
            if v.iter().any(|x| !x.is_finite()) || v.len() > MAX_THRESHOLDS {
                return Err(format!("thresholds.{name}: at most {MAX_THRESHOLDS} finite numbers"));
            }
            th[k] = v.clone();
        }
        Ok(th)
    }
}

/// A rare-event study on the shared pipeline: trial i is the sea of `trial_seed(sim.seed, i)`
/// conditioned on the event; a part is the trials' records in trial order.
pub struct RareEvents {
    spec: RareSpec,
    thresholds: [Vec<f64>; 5],
}

impl Study for RareEvents {
    const KIND: &'static str = "rare-events";
    const ITEM: &'static str = "trial";
    type Spec = RareSpec;
    type Shared = Trials;
    type Part = Vec<TrialRecord>;
    type Summary = RareSummary;

    fn new(spec: RareSpec) -> Result<RareEvents, String> {
        spec.scenario.validate().map_err(|e| format!("its scenario is not valid: {e}"))?;
        check_study(&spec.scenario, spec.trials)?;
        let ev = &spec.scenario.rare_event;
        if ev.ship_x_m == 0.0 || ev.ship_speed_kn == 0.0 {
            return Err("rare_event.ship_x_m, ship_speed_kn: the ship's place at the event is not set (the study's \
                        scenario is the one every trial runs, from rare::trial_scenario)"
                .into());
        }
        let thresholds = spec.thresholds()?;
        Ok(RareEvents { spec, thresholds })
    }
    fn spec(&self) -> &RareSpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        &self.spec.scenario
    }
    fn items(&self) -> u64 {
        self.spec.trials
    }
    fn item_work(&self) -> Option<f64> {
        Some(trial_work(&self.spec.scenario))
    }
    /// The key leaves out the thresholds: they only read the trials.
    fn key_of_spec(s: &RareSpec) -> String {
        crate::studies::study::key_of(&format!("{} {}", s.trials, s.scenario.to_json()))
    }
    fn same_study(a: &RareSpec, b: &RareSpec) -> bool {
        a.trials == b.trials && a.scenario == b.scenario
    }
    fn prepare(&self) -> Result<Trials, String> {
        Ok(Trials { sc: self.spec.scenario.clone() })
    }
    fn run(&self, trials: &Trials, i: u64) -> Result<Vec<TrialRecord>, String> {
        Ok(vec![trials.run(i)?])
    }
    fn empty(&self) -> Vec<TrialRecord> {
        Vec::new()
    }
    fn merge(&self, acc: &mut Vec<TrialRecord>, other: &Vec<TrialRecord>) -> Result<(), String> {
        crate::studies::study::merge_records(acc, other, |t| t.trial, "trial")
    }
    /// One record for each trial of the ranges, in order, each within what a trial of this study
    /// can give ([`TrialLimits`]).
    fn check_part(&self, part: &Vec<TrialRecord>, ranges: &[(u64, u64)]) -> Result<(), String> {
        let limits = TrialLimits::of(&self.spec.scenario)?;
        for (t, i) in crate::studies::study::records_of(part, ranges, |t| t.trial, "trial")? {
            limits.check(t, i).map_err(|e| format!("trial {i}: {e}"))?;
        }
        Ok(())
    }
    /// Of every trial: the rates weigh the trials' seas, and a summary of some would read as a
    /// smaller study.
    fn summary(&self, part: &Vec<TrialRecord>, ranges: &[(u64, u64)]) -> Result<RareSummary, String> {
        if let Some((a, b)) = crate::studies::study::missing(ranges, self.items()).first() {
            return Err(format!("trials {a}..{b} of the study's {} are in no shard", self.items()));
        }
        summary(&self.spec.scenario, part, &self.thresholds)
    }
}

/// What one trial of a study can give, for the checks of a shard from outside: every number of
/// a trial's record within these bounds, or the shard was not made by this study's trials. Each
/// bound says why a trial cannot pass it; they are generous (a real trial stays well inside) but
/// finite, so a tampered shard cannot move a rate, a quantile or a replay's `--set` line.
pub struct TrialLimits {
    seed: u64,
    /// Highest crossing rate of the study's sea [1/s].
    max_rate_per_s: f64,
    /// h/R the hub can have at the event: a depth at most [`MAX_HUB_DEPTH_M`] from the surface.
    h_over_r: (f64, f64),
    /// (lowest, highest, unit, why) of each consequence, in the order of [`CONSEQUENCES`].
    values: [(f64, f64, &'static str, &'static str); 5],
    /// Farthest the ship can be from its start at the event [m].
    max_reach_m: f64,
    /// The declared ranges of `rare_event.ship_x_m`, `ship_y_m`, `ship_heading_deg` and
    /// `ship_speed_kn`: a trial's place is echoed into its replay's `--set` lines, which must be
    /// accepted.
    place: [(&'static str, f64, f64); 4],
}

/// Farthest the propeller hub is from the still water surface at an event, above or below \[m\]:
/// a hull's hub sits at most a few tens of metres deep, and the highest sea of the scenario's
/// ranges (H_1/3 up to 20 m) with the ship's heave and pitch moves it by tens more.
pub const MAX_HUB_DEPTH_M: f64 = 200.0;

/// Largest motor power drop, in units of both motors' rated power: a motor's torque stays under
/// its pull-out torque (a few times rated at the set point, growing as the square of the bus
/// voltage, which the run's guard keeps under 3 pu) at a shaft speed the guard keeps under 3 times
/// its largest reference: a drop (a mean before minus a lowest after) cannot reach 100 times the
/// rated power of both.
pub const MAX_POWER_DROP_OF_RATED: f64 = 100.0;

impl TrialLimits {
    /// The limits of a trial of the study whose trials run `sc`.
    pub fn of(sc: &Scenario) -> Result<TrialLimits, String> {
        use crate::sim::limits;
        let ev = &sc.rare_event;
        // The crossing rate of a sea is sqrt(m2 / m0) / (2 pi) times a factor at most 1, and
        // sqrt(m2 / m0) is at most the highest encounter frequency of its components: a wave of
        // the sampled band's top frequency met head on at the fastest speed a scenario declares
        // (40 kn). Twice that leaves room for rounding.
        let (_, w_max) = sc.sea.band();
        let u_max = crate::numerics::units::kn_to_m_s(40.0);
        // (Rounded up to a thousandth, as the message prints it.)
        let max_rate_per_s = libm::ceil(
            2.0 * (w_max + w_max * w_max * u_max / crate::sea::waves::G) / (2.0 * std::f64::consts::PI) * 1e3,
        ) / 1e3;
        let radius = 0.5 * sc.propeller.diameter_m;
        let h = MAX_HUB_DEPTH_M / radius;
        // The run stops (diverged) when a bus, a turbine or a shaft leaves these bands, so no
        // recorded row of a finished trial is outside them (the check allows a part in 1e9 for
        // the division by the rated value).
        let (v_lo, v_hi) = limits::BUS_VOLTAGE_PU;
        let (t_lo, t_hi) = limits::TURBINE_SPEED_PU;
        let max_shaft_rpm = limits::SHAFT_SPEED_OF_MAX_REF
            * sc.controllers.speed.max_shaft_rpm.max(crate::numerics::units::rad_s_to_rpm(1.0));
        let p_both_mw = crate::ship::hull::N_SHAFTS as f64 * sc.plant.motor.rated_power_w / 1e6;
        let v_max = v_hi * sc.bus_voltage_ref_v();
        let r_brake = sc.plant.dc_link.brake_resistor_ohm;
        let brake_mj = if r_brake > 0.0 {
            crate::ship::hull::N_SHAFTS as f64 * v_max * v_max / r_brake * (ev.window_s + sc.sim.record_interval_s)
                / 1e6
        } else {
            0.0
        };
        let declared = |name: &'static str| -> Result<(&'static str, f64, f64), String> {
            let m = crate::scenario::registry::find(&format!("rare_event.{name}"))
                .ok_or_else(|| format!("rare_event.{name}: no such parameter"))?;
            Ok((name, m.min.unwrap_or(f64::MIN), m.max.unwrap_or(f64::MAX)))
        };
        Ok(TrialLimits {
            seed: sc.sim.seed,
            max_rate_per_s,
            h_over_r: (-h, h),
            values: [
                (v_lo, v_hi, " pu", "the run stops when a bus leaves this band of its set point"),
                (t_lo, t_hi, " pu", "the run stops when a turbine leaves this band of its rated speed"),
                (
                    0.0,
                    2.0 * max_shaft_rpm,
                    " rpm",
                    "a highest minus a lowest speed, each within 3 times the largest shaft reference, where the run stops",
                ),
                (
                    -MAX_POWER_DROP_OF_RATED * p_both_mw,
                    MAX_POWER_DROP_OF_RATED * p_both_mw,
                    " MW",
                    "100 times both motors' rated power: beyond the pull-out torque at the highest bus voltage and shaft speed a run allows",
                ),
                (
                    0.0,
                    brake_mj,
                    " MJ",
                    "the brake resistors' power at the highest bus voltage a run allows, over the window; 0 without resistors",
                ),
            ],
            // The ship starts at the origin and the run stops when it surges faster than
            // SURGE_M_S or sways faster than SWAY_M_S (rounded up to a metre, and one more).
            max_reach_m: libm::ceil(libm::hypot(limits::SURGE_M_S, limits::SWAY_M_S) * ev.time_s) + 1.0,
            place: [
                declared("ship_x_m")?,
                declared("ship_y_m")?,
                declared("ship_heading_deg")?,
                declared("ship_speed_kn")?,
            ],
        })
    }

    /// Checks trial `i`'s record; the error names the field, its value and what is allowed.
    pub fn check(&self, t: &TrialRecord, i: u64) -> Result<(), String> {
        use crate::checks::num;
        // A part in 1e9 of room for rounding.
        let slack = |b: f64| 1e-9 * (1.0 + b.abs());
        let range = |field: &str, x: f64, lo: f64, hi: f64, unit: &str, why: &str| {
            if x.is_finite() && x >= lo - slack(lo) && x <= hi + slack(hi) {
                Ok(())
            } else {
                Err(format!("{field} = {}: must be from {} to {}{unit} ({why})", num(x), num(lo), num(hi)))
            }
        };
        let want = trial_seed(self.seed, i);
        if t.seed != want {
            return Err(format!(
                "seed = {}: trial {i}'s seed is {want} (from the study's sim.seed {} and the trial's number)",
                t.seed, self.seed
            ));
        }
        let nu = t.crossing_rate_per_s;
        if !(nu.is_finite() && nu > 0.0 && nu <= self.max_rate_per_s) {
            return Err(format!(
                "crossing_rate_per_s = {}: a trial's weight is its sea's crossing rate, above 0 and at most {} per second \
                 (the highest encounter frequency of the sea's band at 40 kn)",
                num(nu),
                num(self.max_rate_per_s)
            ));
        }
        range(
            "h_over_r_at_event",
            t.h_over_r_at_event,
            self.h_over_r.0,
            self.h_over_r.1,
            "",
            &format!("the hub within {MAX_HUB_DEPTH_M} m of the surface"),
        )?;
        for ((c, &x), &(lo, hi, unit, why)) in CONSEQUENCES.iter().zip(&t.values).zip(&self.values) {
            range(&format!("values.{}", c.name), x, lo, hi, unit, why)?;
        }
        let place = [t.ship_x_m, t.ship_y_m, t.ship_heading_deg, t.ship_speed_kn];
        for (&x, &(name, lo, hi)) in place.iter().zip(&self.place) {
            range(name, x, lo, hi, "", &format!("rare_event.{name}'s range: the trial's replay sets it"))?;
        }
        let reach = libm::hypot(t.ship_x_m, t.ship_y_m);
        if reach > self.max_reach_m {
            return Err(format!(
                "ship_x_m = {}, ship_y_m = {}: {} m from the start, at most {} m (the fastest a run allows for the \
                 event's time)",
                num(t.ship_x_m),
                num(t.ship_y_m),
                num(reach),
                num(self.max_reach_m)
            ));
        }
        Ok(())
    }
}

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
    fn per_hour(mean: f64, lo: f64, hi: f64) -> Rate {
        let h = 3600.0;
        Rate {
            per_hour: mean * h,
            low_per_hour: lo * h,
            high_per_hour: hi * h,
            once_every_hours: (mean > 0.0).then(|| 1.0 / (mean * h)),
        }
    }

    /// The mean of `x` [1/s] with the normal 95 % interval of its standard error (the event's
    /// rate: the seeds' crossing rates differ only through the sampled spectrum).
    fn mean_of(x: &[f64]) -> Rate {
        let n = x.len() as f64;
        let mean = x.iter().sum::<f64>() / n;
        let var = x.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0).max(1.0);
        let se = (var / n).sqrt();
        Rate::per_hour(mean, (mean - 1.96 * se).max(0.0), mean + 1.96 * se)
    }

    /// The rate of events past a threshold, sum_j nu_j 1_j / n [1/s], with the event's mean rate
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
    /// Rice's rate from the continuous spectrum (eq. 5.3) for the hub's depth swing [1/h].
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

/// The summary of a study's trials; `thresholds[k]` are consequence k's thresholds.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::presets::preset;

    /// A trial's work is that of every second it simulates, as the summary counts them (the
    /// runs to the event that place the ship and the trial's own run): the estimate said before
    /// a study is that of the study's simulated seconds (to 1e-12).
    #[test]
    fn a_trials_work_counts_the_runs_that_place_the_ship() {
        let sc = trial_scenario_unplaced();
        let ev = &sc.rare_event;
        let mut all = sc.clone();
        all.sim.duration_s = ev.time_s * (1 + CORRECTIONS) as f64 + ev.window_s;
        let (w, want) = (trial_work(&sc), all.work());
        assert!((w - want).abs() <= 1e-12 * want, "{w} against {want}");
        assert!(w > 2.5 * sc.work(), "{w} against the trial's run {}", sc.work());
    }

    /// head-seas-ss6 as its trials run it (event and window within the run), not yet placed.
    fn trial_scenario_unplaced() -> Scenario {
        let mut sc = preset("head-seas-ss6").unwrap();
        sc.sim.duration_s = sc.rare_event.time_s + sc.rare_event.window_s;
        sc
    }

    /// The head-seas study (25 kn, SS6 head seas) with the hub at `h0` [m], the sea conditioned
    /// on the port hub falling through h/R 1.1.
    fn study(h0: f64) -> Scenario {
        let mut sc = preset("head-seas-ss6").unwrap();
        sc.set_hub_depth_m(h0);
        sc.rare_event.level_h_over_r = 1.1;
        sc.sim.duration_s = 165.0;
        sc
    }

    /// Trials 0..n of the study of `sc`, run one after another.
    fn trials_of(sc: &Scenario, n: u64) -> Vec<TrialRecord> {
        let study = RareEvents::new(RareSpec::new(sc, n).unwrap()).unwrap();
        crate::studies::study::run_range(&study, 0, n).unwrap().part
    }

    /// The conditioned sea puts the hub at the level, falling, at the event's time: in the seaway
    /// itself (the ship on the track it was conditioned on) to rounding (measured 1e-13 m, asserted
    /// 1e-9 m) with the rate imposed; in full runs, where the ship's own track moves it a little,
    /// h/R at the event is the level on average (measured 1.1000 against 1.1 over 20 trials,
    /// asserted within 0.01) and at worst 0.060 off (asserted 0.1). Away from the event the sea is
    /// the unconditioned one: over 1,500 seeds the hub swing's mean square 300 s after it is the
    /// seeds' mean m0 (measured ratio 1.029; the mean square of 1,500 Gaussian samples has a
    /// standard error of 3.7 %, asserted within 11 %, 3 standard errors), while at the event it is
    /// the level squared. The most likely wave group puts the hub at the level with zero rate and
    /// never deeper than it (|r(t)| <= |level|, to 1e-9).
    #[test]
    fn the_conditioned_sea_makes_the_event_and_nothing_else() {
        let base = trial_scenario(&study(4.5)).unwrap();
        let ev = base.rare_event.clone();
        let u = crate::numerics::units::kn_to_m_s(ev.ship_speed_kn);
        let psi = ev.ship_heading_deg.to_radians();
        let (ux, uy) = (u * libm::cos(psi), u * libm::sin(psi));
        // The ship on the track the sea was conditioned on.
        let at_time = |t: f64| (ev.ship_x_m + ux * (t - ev.time_s), ev.ship_y_m + uy * (t - ev.time_s));
        let (mut far, mut at, mut m0_mean, n) = (0.0, 0.0, 0.0, 1500);
        for seed in 0..n {
            let mut s = base.clone();
            s.sim.seed = seed;
            let (_, c) = crate::sim::seaway::sea_of(&s).unwrap();
            let c = c.unwrap();
            let mut sea = crate::sim::seaway::Seaway::new(&s).unwrap().unwrap();
            sea.refresh(u, psi);
            let h0 = s.ship_hull().unwrap().hub_depth_m;
            let (x, y) = at_time(ev.time_s);
            let now = sea.sample(ev.time_s, x, y, ux, uy);
            let r = now.hub[0] - h0;
            assert!((r - c.level_m).abs() < 1e-9, "seed {seed}: {r} against {}", c.level_m);
            assert!(
                (now.hub_rate[0] - c.rate_m_s).abs() < 1e-6 * (1.0 + c.rate_m_s.abs()),
                "{} {}",
                now.hub_rate[0],
                c.rate_m_s
            );
            at += r * r / n as f64;
            let (x, y) = at_time(ev.time_s + 300.0);
            let later = sea.sample(ev.time_s + 300.0, x, y, ux, uy).hub[0] - h0;
            far += later * later / n as f64;
            m0_mean += c.m0 / n as f64;
        }
        println!(
            "mean square at the event {at:.4} (level^2), 300 s later {far:.4}, m0 {m0_mean:.4}, ratio {:.3}",
            far / m0_mean
        );
        assert!((far / m0_mean - 1.0).abs() < 0.11);
        // The most likely wave group.
        let mut s = base.clone();
        s.rare_event.shape = crate::sea::conditioning::Shape::MostLikely;
        let (_, c) = crate::sim::seaway::sea_of(&s).unwrap();
        let c = c.unwrap();
        let mut sea = crate::sim::seaway::Seaway::new(&s).unwrap().unwrap();
        sea.refresh(u, psi);
        let h0 = s.ship_hull().unwrap().hub_depth_m;
        for k in 0..600 {
            let t = ev.time_s - 30.0 + 0.1 * k as f64;
            let (x, y) = at_time(t);
            let now = sea.sample(t, x, y, ux, uy);
            assert!((now.hub[0] - h0).abs() <= c.level_m.abs() + 1e-9, "t {t}: {}", now.hub[0] - h0);
            if k == 300 {
                assert!((now.hub[0] - h0 - c.level_m).abs() < 1e-9 && now.hub_rate[0].abs() < 1e-9);
            }
        }
        // Full runs.
        let p = trials_of(&study(4.5), 20);
        let h: Vec<f64> = p.iter().map(|t| t.h_over_r_at_event).collect();
        let mean = h.iter().sum::<f64>() / h.len() as f64;
        let worst = h.iter().map(|x| (x - 1.1).abs()).fold(0.0, f64::max);
        println!("h/R at the event: mean {mean:.4}, worst departure {worst:.3}");
        assert!((mean - 1.1).abs() < 0.01 && worst < 0.1);
        // Every real trial is within what a shard's trial may claim (the limits bind tampered
        // shards, never the study's own trials).
        let limits = TrialLimits::of(&trial_scenario(&study(4.5)).unwrap()).unwrap();
        for t in &p {
            limits.check(t, t.trial).unwrap();
        }
        let mut bad = p[3].clone();
        bad.values[0] = -5.0;
        assert_eq!(
            limits.check(&bad, 3).unwrap_err(),
            "values.min_bus_voltage_pu = -5: must be from -0.1 to 3 pu (the run stops when a bus leaves this band of its set point)"
        );
    }

    /// Conditioned trials against brute force where brute force sees many events (h0 = 4.5 m,
    /// ventilation onset h/R 1.1 on the port hub, about 22 an hour): the event's rate, and the rate
    /// of events whose motor power drop exceeds 9.5 MW (about half of them), agree within 2.5 joint
    /// standard errors (measured -0.19 and -0.61). Brute force: 60 runs of 1,200 s (17.3 usable
    /// hours after the 150 s warm-up, 385 events); conditioned: 160 trials. The simulated seconds
    /// each needs for the same interval width are printed; at this depth, where events come every
    /// few minutes, brute force is as cheap; the gain grows as the event gets rarer (the benchmark
    /// `aes-sim rare --brute-force` measures it at h0 = 5 m, README).
    #[test]
    fn conditioned_rates_agree_with_brute_force() {
        let sc = study(4.5);
        let p = trials_of(&sc, 160);
        let ts = trial_scenario(&sc).unwrap();
        let th: [Vec<f64>; 5] = [vec![], vec![], vec![], vec![9.5], vec![]];
        let c = summary(&ts, &p, &th).unwrap();
        let b = BruteForce::run(&ts, 1200.0, 0, 60).unwrap();
        for (name, cond, brute) in [
            ("event", c.rate, b.rate(None)),
            ("motor power drop > 9.5 MW", c.consequences[3].beyond[0].rate, b.rate(Some((3, 9.5)))),
        ] {
            let se = |r: Rate| (r.high_per_hour - r.low_per_hour) / (2.0 * 1.96);
            let joint = (se(cond) * se(cond) + se(brute) * se(brute)).sqrt();
            let z = (cond.per_hour - brute.per_hour) / joint;
            println!(
                "{name}: conditioned {:.2} +- {:.2} /h, brute force {:.2} +- {:.2} /h ({} events), {z:.2} joint standard errors",
                cond.per_hour,
                1.96 * se(cond),
                brute.per_hour,
                1.96 * se(brute),
                b.runs.iter().map(|r| r.1.len()).sum::<usize>()
            );
            assert!(z.abs() < 2.5, "{name}: {z}");
        }
    }
}

/// The same study with another plant (thesis ch. 6.1: an event's consequences with and without
/// storage): `other`'s plant in the study's trial scenario, so every trial meets the same
/// conditioned sea at the same place, speed estimate and time, and only the plant differs. The
/// two scenarios must differ in nothing but their `plant` section (a different sea, ship or event
/// would not be the same event).
pub fn with_plant(spec: &RareSpec, sc: &Scenario, other: &Scenario) -> Result<RareSpec, String> {
    let (a, b) =
        (serde_json::to_value(sc).map_err(|e| e.to_string())?, serde_json::to_value(other).map_err(|e| e.to_string())?);
    let (Some(a), Some(b)) = (a.as_object(), b.as_object()) else {
        return Err("a scenario is not an object".into());
    };
    let differ: Vec<&str> = a
        .iter()
        .filter(|(k, v)| !matches!(k.as_str(), "plant" | "name" | "description") && b.get(k.as_str()) != Some(v))
        .map(|(k, _)| k.as_str())
        .collect();
    if !differ.is_empty() {
        return Err(format!(
            "the two scenarios differ in {} as well as in their plant: only the plant may differ, so that the trials meet the same events",
            differ.join(", ")
        ));
    }
    let mut s = spec.clone();
    s.scenario.plant = other.plant.clone();
    s.scenario.validate().map_err(|e| e.to_string())?;
    Ok(s)
}

/// One consequence of the same events in two plants, trial by trial.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairedConsequence {
    pub name: &'static str,
    pub label: &'static str,
    pub larger_is_worse: bool,
    /// Means given the event (weighted by the trials' crossing rates), first plant and second.
    pub mean: f64,
    pub mean_other: f64,
    /// The second plant's value minus the first's: its weighted mean and 95 % interval (the
    /// ratio estimator's standard error over the trials).
    pub difference: f64,
    pub difference_low: f64,
    pub difference_high: f64,
    /// Share of the trials (weighted) in which the second plant did better.
    pub other_better_share: f64,
    /// Share of the trials (weighted) in which both gave the same value (no brake energy in
    /// either, say): neither better nor worse.
    pub tied_share: f64,
}

/// The paired comparison of two plants' trials of the same study ([`with_plant`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Paired {
    pub trials: usize,
    pub consequences: Vec<PairedConsequence>,
}

/// Trials `a` and `b` of the same events, matched by trial and sea seed; weights are `a`'s
/// crossing rates (the same seas on the same track give the same rates).
pub fn paired(a: &[TrialRecord], b: &[TrialRecord]) -> Result<Paired, String> {
    if a.len() != b.len() || a.len() < MIN_TRIALS as usize {
        return Err(format!("{} and {} trials: the same number, at least {MIN_TRIALS}, are needed", a.len(), b.len()));
    }
    if let Some((x, _)) = a.iter().zip(b).find(|(x, y)| x.trial != y.trial || x.seed != y.seed) {
        return Err(format!("trial {}: the two studies' trials are not the same events", x.trial));
    }
    let w: Vec<f64> = a.iter().map(|t| t.crossing_rate_per_s).collect();
    let sw: f64 = w.iter().sum();
    if sw.is_nan() || sw <= 0.0 {
        return Err("the trials' seas have no crossing rate".into());
    }
    let wmean = |x: &dyn Fn(usize) -> f64| (0..a.len()).map(|j| w[j] * x(j)).sum::<f64>() / sw;
    let consequences = CONSEQUENCES
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let d = |j: usize| b[j].values[k] - a[j].values[k];
            let mean_d = wmean(&d);
            // The ratio estimator's standard error with the n / (n - 1) of a sample variance (without
            // it the interval of 2 trials is 29 % too narrow).
            let n = a.len() as f64;
            let ss: f64 = (0..a.len()).map(|j| (w[j] * (d(j) - mean_d)) * (w[j] * (d(j) - mean_d))).sum();
            let se = libm::sqrt(n / (n - 1.0) * ss) / sw;
            let better = |j: usize| {
                let dj = d(j);
                f64::from(u8::from(if c.larger_is_worse { dj < 0.0 } else { dj > 0.0 }))
            };
            let tied = |j: usize| f64::from(u8::from(d(j) == 0.0));
            PairedConsequence {
                name: c.name,
                label: c.label,
                larger_is_worse: c.larger_is_worse,
                mean: wmean(&|j| a[j].values[k]),
                mean_other: wmean(&|j| b[j].values[k]),
                difference: mean_d,
                difference_low: mean_d - 1.96 * se,
                difference_high: mean_d + 1.96 * se,
                other_better_share: wmean(&better),
                tied_share: wmean(&tied),
            }
        })
        .collect();
    Ok(Paired { trials: a.len(), consequences })
}
