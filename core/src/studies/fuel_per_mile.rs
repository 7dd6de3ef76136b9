//! Fuel per nautical mile against speed, over seas of several seeds: the scenario sailed at each
//! ordered speed, the fuel power of the turbines (the part-load curve, `fuel_power_w`) and the
//! distance run integrated from `from_s` to the end. Where the ship is most economical in a given
//! sea, and how much the sea's realisation moves it. Written on the study pipeline from the start:
//! this file, `cli/src/cmd/fuel_per_mile.rs` and the page's view module are all it took.
//!
//! Item i is speed i / seeds in the sea of seed `trial_seed(sim.seed, i % seeds)`; a part keeps,
//! per speed, the exact moments of the kilograms per nautical mile and of the mean speed, so shards
//! merge to the bits of one run.

use crate::numerics::units::kn_to_m_s;
use crate::scenario::{Command, Scenario};
use crate::signals::Signal;
use crate::studies::stats::{trial_seed, ExactMoments};
use crate::studies::study::Study;
use serde::{Deserialize, Serialize};

/// Lower heating value of marine gas oil \[J/kg\]: 42.7 MJ/kg (ISO 8217 DMA distillate, the usual
/// figure for gas turbine fuel; the thesis gives fuel as power, not mass).
pub const LHV_J_PER_KG: f64 = 42.7e6;
/// One nautical mile \[m\].
pub const NAUTICAL_MILE_M: f64 = 1852.0;
/// Most speeds and seeds of one study.
pub const MAX_SPEEDS: usize = 50;
pub const MAX_SEEDS: u64 = 1000;
/// Slowest speed taken \[kn\]: per mile, fuel grows without bound as the speed goes to 0.
pub const MIN_SPEED_KN: f64 = 1.0;
/// Exact moments' quantum: 2^-16 kg/nmi or kn (values to 2^29).
const BITS: i32 = 16;

/// The definition: the scenario (its sea, ship and plant), the ordered speeds, the seeds per speed,
/// and when the measurement starts (after the speed has settled).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FuelPerMileSpec {
    pub scenario: Scenario,
    pub speeds_kn: Vec<f64>,
    pub seeds: u64,
    pub from_s: f64,
}

/// Per speed: kilograms of fuel per nautical mile, and the mean speed through the water \[kn\].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedMoments {
    pub kg_per_nmi: ExactMoments,
    pub speed_kn: ExactMoments,
}

/// One speed of the summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FuelRow {
    pub ordered_kn: f64,
    pub seeds: u64,
    pub mean_speed_kn: Option<f64>,
    pub kg_per_nmi_mean: Option<f64>,
    pub kg_per_nmi_std: Option<f64>,
    pub kg_per_nmi_min: Option<f64>,
    pub kg_per_nmi_max: Option<f64>,
}

/// The JSON of `aes-sim fuel-per-mile`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FuelPerMile {
    pub scenario: String,
    pub definition: &'static str,
    pub lhv_j_per_kg: f64,
    pub from_s: f64,
    pub rows: Vec<FuelRow>,
    /// The ordered speed of least mean fuel per mile among those with every seed run.
    pub most_economical_kn: Option<f64>,
}

pub struct FuelPerMileStudy {
    spec: FuelPerMileSpec,
}

impl FuelPerMileStudy {
    /// The scenario of item `i`: its speed ordered from the start (and the run starting at that
    /// speed's calm-water steady state), its sea's seed.
    pub fn item_scenario(&self, i: u64) -> Scenario {
        let s = &self.spec;
        let v = s.speeds_kn[(i / s.seeds) as usize];
        let mut sc = s.scenario.clone();
        sc.sim.seed = trial_seed(s.scenario.sim.seed, i % s.seeds);
        sc.initial.speed_kn = v;
        let mut ordered = false;
        for c in sc.commands.iter_mut().filter(|c| c.speed_kn.is_some()) {
            c.speed_kn = Some(v);
            ordered = true;
        }
        if !ordered {
            sc.commands.insert(
                0,
                Command {
                    t_s: 0.0,
                    speed_kn: Some(v),
                    heading_deg: None,
                    heading_rate_deg_s: None,
                    online_sets: None,
                    crash_stop: false,
                },
            );
        }
        sc
    }
}

/// Room for the speed loop above the ordered speed, as a fraction of it: the runs start at the
/// order's calm-water steady state and a sea only slows the ship, so the mean speed over the
/// measurement stays at the order but for the loop's small overshoot (measured: 1 + 7e-16 of the
/// order in calm water at 5 to 30 kn, 0.96 to 0.99 of it in SS6 head seas at 12 to 30 kn; 10 %
/// here).
pub const SPEED_ROOM: f64 = 0.10;

/// Most fuel power the turbines can burn \[W\]: each at eq. 2.1's highest shaft power (full
/// throttle at half the no-load speed, Q_lock n_nl / 4) at the rated efficiency times the least
/// ratio of the part-load curve (its value held below 5 % load).
pub fn max_fuel_power_w(sc: &Scenario) -> f64 {
    let t = crate::plant::prime_mover::GasTurbine::new(&sc.plant.turbine);
    let p_max = t.locking_torque_nm * t.no_load_speed / 4.0;
    let curve = crate::plant::fuel::part_load_curve();
    let r_min = curve.iter().map(|&(_, r)| r).fold(crate::plant::fuel::efficiency_ratio(&curve, 0.0).0, f64::min);
    crate::plant::layout::N_SETS as f64 * p_max / (sc.seakeeping.turbine_rated_efficiency * r_min)
}

/// Trapezoid of `y` over rows `from..` at interval `dt`.
fn integral(y: &[f64], from: usize, dt: f64) -> f64 {
    y.get(from..).unwrap_or(&[]).windows(2).map(|w| 0.5 * (w[0] + w[1]) * dt).sum()
}

impl FuelPerMileStudy {
    /// Speed `j`'s moments against what its runs can give: a mean speed above 0 (a run that
    /// makes no way is refused) and at most the order plus [`SPEED_ROOM`]; fuel per mile above 0
    /// and at most the turbines' most fuel power ([`max_fuel_power_w`]) over the slowest mean
    /// speed kept (kg/nmi = mean fuel power / (LHV x mean speed)). Room of 1e-9 for rounding.
    fn check_row(&self, j: usize, p: &SpeedMoments) -> Result<(), String> {
        use crate::checks::num;
        let ordered = self.spec.speeds_kn[j];
        let top = ordered * (1.0 + SPEED_ROOM);
        let (v_lo, v_hi) = (p.speed_kn.min, p.speed_kn.max);
        if !(v_lo > 0.0 && v_hi <= top * (1.0 + 1e-9)) {
            return Err(format!(
                "{j}.speed_kn: min = {}, max = {}: a mean speed is above 0 and at most {} kn ({} kn ordered; the sea \
                 only slows the ship, {:.0} % room for the speed loop)",
                num(v_lo),
                num(v_hi),
                num(top),
                num(ordered),
                SPEED_ROOM * 100.0
            ));
        }
        let per_kn = max_fuel_power_w(&self.spec.scenario) / LHV_J_PER_KG / kn_to_m_s(1.0) * NAUTICAL_MILE_M;
        let most = per_kn / v_lo;
        let (f_lo, f_hi) = (p.kg_per_nmi.min, p.kg_per_nmi.max);
        if !(f_lo > 0.0 && f_hi <= most * (1.0 + 1e-9)) {
            return Err(format!(
                "{j}.kg_per_nmi: min = {}, max = {}: above 0 and at most {} kg per nautical mile (the turbines' most \
                 fuel power, {} MW, at the slowest mean speed kept, {} kn)",
                num(f_lo),
                num(f_hi),
                num(most),
                num(max_fuel_power_w(&self.spec.scenario) / 1e6),
                num(v_lo)
            ));
        }
        Ok(())
    }
}

impl Study for FuelPerMileStudy {
    const KIND: &'static str = "fuel-per-mile";
    const ITEM: &'static str = "run";
    type Spec = FuelPerMileSpec;
    type Shared = ();
    type Part = Vec<SpeedMoments>;
    type Summary = FuelPerMile;

    fn new(spec: FuelPerMileSpec) -> Result<FuelPerMileStudy, String> {
        use crate::checks::num;
        spec.scenario.validate().map_err(|e| format!("its scenario is not valid: {e}"))?;
        let n = spec.speeds_kn.len();
        if n == 0 || n > MAX_SPEEDS {
            return Err(format!("speeds_kn: {n} speeds: give 1 to {MAX_SPEEDS}"));
        }
        let top = 40.0f64.min(spec.scenario.seakeeping.grid.speed_max_kn);
        if let Some(v) = spec.speeds_kn.iter().find(|v| !(MIN_SPEED_KN..=top).contains(*v)) {
            return Err(format!("speeds_kn: {} kn is outside {MIN_SPEED_KN} to {} kn", num(*v), num(top)));
        }
        if !(1..=MAX_SEEDS).contains(&spec.seeds) {
            return Err(format!("seeds = {}: from 1 to {MAX_SEEDS}", spec.seeds));
        }
        let dur = spec.scenario.sim.duration_s;
        if !(spec.from_s >= 0.0 && spec.from_s + 10.0 <= dur) {
            return Err(format!(
                "from_s = {}: from 0 to sim.duration_s - 10 s = {} s (the measurement needs at least 10 s)",
                num(spec.from_s),
                num(dur - 10.0)
            ));
        }
        let work = n as f64 * spec.seeds as f64 * spec.scenario.work();
        let most = crate::studies::montecarlo::MAX_STUDY_WORK;
        if work > most {
            return Err(format!(
                "{n} speeds x {} seeds of {:.3e} units of work each: {work:.3e}; at most {most:e}: fewer speeds or seeds, or a shorter run",
                spec.seeds,
                spec.scenario.work()
            ));
        }
        Ok(FuelPerMileStudy { spec })
    }
    fn spec(&self) -> &FuelPerMileSpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        &self.spec.scenario
    }
    fn items(&self) -> u64 {
        self.spec.speeds_kn.len() as u64 * self.spec.seeds
    }
    fn item_work(&self) -> Option<f64> {
        Some(self.spec.scenario.work())
    }
    fn prepare(&self) -> Result<(), String> {
        Ok(())
    }
    fn run(&self, _: &(), i: u64) -> Result<Vec<SpeedMoments>, String> {
        let sc = self.item_scenario(i);
        let fail = |e: String| format!("run {i} ({} kn, sea seed {}): {e}", sc.initial.speed_kn, sc.sim.seed);
        let r = crate::sim::run(&sc).map_err(|e| fail(e.to_string()))?;
        let dt = sc.sim.record_interval_s;
        let from = libm::ceil(self.spec.from_s / dt) as usize;
        let fuel_j = integral(r.trace.get(Signal::FuelPowerW), from, dt);
        let run_kn_s = integral(r.trace.get(Signal::ShipSpeedKn), from, dt);
        let secs = dt * r.trace.len().saturating_sub(from + 1) as f64;
        let miles = kn_to_m_s(run_kn_s) / NAUTICAL_MILE_M;
        if !(miles > 0.0 && secs > 0.0) {
            return Err(fail("the ship made no way over the measurement".into()));
        }
        let mut part = self.empty();
        let j = (i / self.spec.seeds) as usize;
        part[j].kg_per_nmi.push(fuel_j / LHV_J_PER_KG / miles);
        part[j].speed_kn.push(run_kn_s / secs);
        Ok(part)
    }
    fn empty(&self) -> Vec<SpeedMoments> {
        let m = || ExactMoments::new(BITS, 2);
        vec![SpeedMoments { kg_per_nmi: m(), speed_kn: m() }; self.spec.speeds_kn.len()]
    }
    fn merge(&self, acc: &mut Vec<SpeedMoments>, other: &Vec<SpeedMoments>) -> Result<(), String> {
        for (a, b) in acc.iter_mut().zip(other) {
            a.kg_per_nmi.merge(&b.kg_per_nmi)?;
            a.speed_kn.merge(&b.speed_kn)?;
        }
        Ok(())
    }
    /// One row per speed, each counting exactly the runs of its speed in the ranges, with the
    /// moments' own consistency and each number within what a run can give (`check_row`).
    fn check_part(&self, part: &Vec<SpeedMoments>, ranges: &[(u64, u64)]) -> Result<(), String> {
        if part.len() != self.spec.speeds_kn.len() {
            return Err(format!("{} rows for {} speeds", part.len(), self.spec.speeds_kn.len()));
        }
        let mut want = vec![0u64; part.len()];
        for i in ranges.iter().flat_map(|&(a, b)| a..b) {
            want[(i / self.spec.seeds) as usize] += 1;
        }
        for (j, (p, w)) in part.iter().zip(want).enumerate() {
            for (name, x) in [("kg_per_nmi", &p.kg_per_nmi), ("speed_kn", &p.speed_kn)] {
                if x.bits != BITS || x.order != 2 || x.n != w || x.clamped > 0 {
                    return Err(format!("{j}.{name}: n = {}: the ranges hold {w} runs of this speed", x.n));
                }
                x.check_consistent().map_err(|e| format!("{j}.{name}: {e}"))?;
            }
            if w > 0 {
                self.check_row(j, p)?;
            }
        }
        Ok(())
    }
    fn summary(&self, part: &Vec<SpeedMoments>, _: &[(u64, u64)]) -> Result<FuelPerMile, String> {
        let stat = |x: &ExactMoments, v: f64| (x.n > 0).then_some(v);
        let rows: Vec<FuelRow> = part
            .iter()
            .zip(&self.spec.speeds_kn)
            .map(|(p, &v)| FuelRow {
                ordered_kn: v,
                seeds: p.kg_per_nmi.n,
                mean_speed_kn: stat(&p.speed_kn, p.speed_kn.mean()),
                kg_per_nmi_mean: stat(&p.kg_per_nmi, p.kg_per_nmi.mean()),
                kg_per_nmi_std: p.kg_per_nmi.std_defined(),
                kg_per_nmi_min: stat(&p.kg_per_nmi, p.kg_per_nmi.min),
                kg_per_nmi_max: stat(&p.kg_per_nmi, p.kg_per_nmi.max),
            })
            .collect();
        let most_economical_kn = rows
            .iter()
            .filter(|r| r.seeds == self.spec.seeds)
            .filter_map(|r| r.kg_per_nmi_mean.map(|m| (m, r.ordered_kn)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, v)| v);
        Ok(FuelPerMile {
            scenario: self.spec.scenario.name.clone(),
            definition: "fuel burnt (fuel_power_w over the lower heating value) over the distance run through the \
                         water, both from from_s to the end of each run; per ordered speed, over the seeds' seas",
            lhv_j_per_kg: LHV_J_PER_KG,
            from_s: self.spec.from_s,
            rows,
            most_economical_kn,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::units::KNOT_M_S;

    /// In calm water at 25 kn, fuel per mile is the fuel power over the speed: the study's number
    /// equals the run's own mean fuel power times an hour over the miles of an hour, to the
    /// trapezoid's rounding (asserted 1e-9 relative); speeds outside 1 kn to the RAO table's top
    /// are refused by name.
    #[test]
    fn calm_water_fuel_per_mile_is_power_over_speed() {
        let mut sc = crate::scenario::presets::preset("startup").unwrap();
        sc.sim.duration_s = 40.0;
        let spec = FuelPerMileSpec { scenario: sc.clone(), speeds_kn: vec![25.0], seeds: 1, from_s: 20.0 };
        let study = FuelPerMileStudy::new(spec.clone()).unwrap();
        let s = crate::studies::study::run_all(&study).unwrap();
        let r = crate::sim::run(&study.item_scenario(0)).unwrap();
        let dt = sc.sim.record_interval_s;
        let from = libm::ceil(20.0 / dt) as usize;
        let p = r.trace.get(Signal::FuelPowerW);
        let v = r.trace.get(Signal::ShipSpeedKn);
        let n = (p.len() - from - 1) as f64;
        let mean_p = integral(p, from, dt) / (n * dt);
        let mean_v = integral(v, from, dt) / (n * dt);
        let want = mean_p * 3600.0 / LHV_J_PER_KG / (mean_v * KNOT_M_S * 3600.0 / NAUTICAL_MILE_M);
        let got = s.rows[0].kg_per_nmi_mean.unwrap();
        assert!((got / want - 1.0).abs() < 1e-9, "{got} against {want}");
        assert_eq!(s.most_economical_kn, Some(25.0));
        for bad in [0.5, 99.0] {
            let e = FuelPerMileStudy::new(FuelPerMileSpec { speeds_kn: vec![bad], ..spec.clone() }).err().unwrap();
            assert!(e.starts_with("speeds_kn: "), "{e}");
        }
    }
}
