//! How big a storage does a seaway need (thesis ch. 5.2.2 and 6.1)? One run of the scenario per
//! storage size (energy x power rating, on each bus) beside the run without storage, each measured
//! as a power-system engineer sizes a storage: how much steadier the turbines turn, how far the
//! bus sags and rises, the fuel burnt, and what the storage pays for it in cycling (the charge's
//! range, the time it spent in its taper near a limit, the time at its power rating, and the equivalent full
//! cycles an hour that set a battery's life).
//!
//! Every cell is the scenario's own run with `plant.storage.energy_j` and `power_w` set (the
//! other storage fields as the scenario has them), the whole run measured: the sizes compare on
//! one sea (the scenario's seed), as a design sweep should.
//!
//! On the study pipeline ([`StorageSizing`]): item 0 is the run without storage, item k the k-th
//! size (energies outer, powers inner); a part keeps each item's cell, so shards merge to the
//! bits of one run.

use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::RunResult;
use crate::studies::study::{merge_records, records_of, Study};
use serde::{Deserialize, Serialize};

/// Most storage sizes in one study (each a run of the scenario).
pub const MAX_SIZES: usize = 100;

/// A cell is "at its power rating" while the storages give or take at least this share of it.
pub const AT_RATING: f64 = 0.99;

/// One run's measures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cell {
    /// Storage energy on each bus \[J\] (0: no storage).
    pub energy_j: f64,
    /// Storage power rating on each bus \[W\].
    pub power_w: f64,
    /// Standard deviation of the turbines' speed over the run \[pu\].
    pub turbine_speed_std_pu: f64,
    /// Highest minus lowest turbine speed \[pu\].
    pub turbine_speed_range_pu: f64,
    /// Lowest and highest bus voltage \[pu\].
    pub bus_voltage_min_pu: f64,
    pub bus_voltage_max_pu: f64,
    /// Mean fuel power of the turbines online \[W\].
    pub fuel_power_mean_w: f64,
    /// Mean shaft power of the turbines \[W\]: what the fuel paid for, whatever the curve.
    pub turbine_power_mean_w: f64,
    /// Share of the run the online sets ran below the part-load curve's first point (30 % load),
    /// where the curve is extrapolated and gives too little fuel (no idle flow): a run whose
    /// turbines swing down there is charged too little fuel beside a steady one \[-\].
    pub below_curve_share: f64,
    /// Net energy the storages gave the buses over the run \[J\] (their charge's fall, less losses):
    /// the turbines must put it back later.
    pub storage_net_j: f64,
    /// Energy burnt in the brake resistors \[J\].
    pub brake_energy_j: f64,
    /// Lowest and highest state of charge (mean of the two storages) \[-\]; 0 without storage.
    pub soc_min: f64,
    pub soc_max: f64,
    /// Share of the run the charge spent in the taper before either limit, where the controller
    /// gives or takes less and less (`plant::storage::taper_j`: at least a second of the rated
    /// power wide, so a storage small beside its rating lives in it and never reaches its
    /// rating) \[-\].
    pub taper_share: f64,
    /// Share of the run the storages spent at their power rating \[-\] (of the two buses' sum, as
    /// the cycles: right for the symmetric head-seas runs, where both buses give and take alike).
    pub at_rating_share: f64,
    /// Equivalent full cycles an hour: the energy through the storages' terminals, both ways,
    /// over twice their usable energy (soc_max - soc_min of energy_j, both buses), per hour.
    pub cycles_per_hour: f64,
    /// The run's health warnings.
    pub warnings: Vec<String>,
}

/// The study: the run without storage, then every size.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sizing {
    pub scenario: String,
    pub duration_s: f64,
    /// The run without storage.
    pub without: Cell,
    /// Sizes, energies outer and powers inner.
    pub cells: Vec<Cell>,
}

/// The sizes of a study, checked: energies within the storage's range, powers within its rating's,
/// at most [`MAX_SIZES`] pairs.
pub fn sizes(sc: &Scenario, energies_j: &[f64], powers_w: &[f64]) -> Result<Vec<Scenario>, String> {
    if energies_j.is_empty() || powers_w.is_empty() {
        return Err("give at least one storage energy and one power rating".into());
    }
    let n = energies_j.len() * powers_w.len();
    if n > MAX_SIZES {
        return Err(format!(
            "{} energies x {} powers = {n} sizes: at most {MAX_SIZES} (each is a run)",
            energies_j.len(),
            powers_w.len()
        ));
    }
    let mut out = Vec::with_capacity(n);
    for &e in energies_j {
        for &p in powers_w {
            if e.is_nan() || e <= 0.0 {
                return Err(format!(
                    "plant.storage.energy_j = {}: each size needs a storage (the run without one is always made)",
                    crate::checks::num(e)
                ));
            }
            let mut s = sc.clone();
            s.plant.storage.energy_j = e;
            s.plant.storage.power_w = p;
            s.validate().map_err(|err| err.to_string())?;
            out.push(s);
        }
    }
    Ok(out)
}

/// The scenario without storage (the study's reference): every storage field at its default, so
/// that the fields the sizes share raise no "ignored" warning here.
pub fn without(sc: &Scenario) -> Scenario {
    let mut s = sc.clone();
    s.plant.storage = crate::scenario::StorageParams::default();
    s
}

/// One run's measures.
pub fn measure(sc: &Scenario, r: &RunResult) -> Cell {
    let tr = &r.trace;
    let col = |s: Signal| tr.get(s);
    let min = |x: &[f64]| x.iter().copied().fold(f64::INFINITY, f64::min);
    let max = |x: &[f64]| x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len().max(1) as f64;
    let ts = col(Signal::TS);
    let dt = if ts.len() > 1 { ts[1] - ts[0] } else { 0.0 };
    let w = col(Signal::TurbineSpeedPu);
    let m = mean(w);
    let std = (w.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / w.len().max(1) as f64).sqrt();
    let bus = col(Signal::BusVoltagePu);
    let st = &sc.plant.storage;
    let has = st.energy_j > 0.0;
    let soc = col(Signal::StorageSoc);
    let p = col(Signal::StoragePowerW);
    let (soc_min, soc_max) = if has { (min(soc), max(soc)) } else { (0.0, 0.0) };
    let rating = 2.0 * st.power_w;
    let at_rating = if has { p.iter().filter(|v| v.abs() >= AT_RATING * rating).count() as f64 } else { 0.0 };
    let usable = 2.0 * (st.soc_max - st.soc_min) * st.energy_j;
    let through: f64 = p.iter().map(|v| v.abs()).sum::<f64>() * dt;
    let duration = sc.sim.duration_s;
    let online = crate::plant::online::mask(&sc.plant.online.sets).iter().filter(|&&o| o).count().max(1);
    let first = crate::plant::fuel::part_load_curve()[0].0 * online as f64 * sc.plant.turbine.rated_power_w;
    let pt = col(Signal::PTurbineW);
    let below = pt.iter().filter(|&&v| v < first).count() as f64 / pt.len().max(1) as f64;
    Cell {
        energy_j: if has { st.energy_j } else { 0.0 },
        power_w: if has { st.power_w } else { 0.0 },
        turbine_speed_std_pu: std,
        turbine_speed_range_pu: max(w) - min(w),
        bus_voltage_min_pu: min(bus),
        bus_voltage_max_pu: max(bus),
        fuel_power_mean_w: mean(col(Signal::FuelPowerW)),
        turbine_power_mean_w: mean(pt),
        below_curve_share: below,
        storage_net_j: r.summary.energy_j.storage_to_bus,
        brake_energy_j: r.summary.energy_j.brake,
        soc_min,
        soc_max,
        taper_share: if has {
            let taper = crate::plant::storage::taper_j(st.energy_j, st.power_w) / st.energy_j;
            let (lo, hi) = (st.soc_min + taper, st.soc_max - taper);
            soc.iter().filter(|&&q| q < lo || q > hi).count() as f64 / soc.len().max(1) as f64
        } else {
            0.0
        },
        at_rating_share: at_rating / p.len().max(1) as f64,
        cycles_per_hour: if has && usable > 0.0 && duration > 0.0 {
            through / (2.0 * usable) * 3600.0 / duration
        } else {
            0.0
        },
        warnings: r.summary.warnings.clone(),
    }
}

/// Runs one scenario and measures it.
pub fn run_cell(sc: &Scenario) -> Result<Cell, String> {
    let r = crate::sim::run(sc).map_err(|e| e.to_string())?;
    Ok(measure(sc, &r))
}

/// The whole study, one item after another (the command line spreads the items over threads,
/// with the same result).
pub fn run(sc: &Scenario, energies_j: &[f64], powers_w: &[f64]) -> Result<Sizing, String> {
    let spec = StorageSizingSpec { scenario: sc.clone(), energies_j: energies_j.to_vec(), powers_w: powers_w.to_vec() };
    crate::studies::study::run_all(&StorageSizing::new(spec)?)
}

/// The definition: the scenario (its run length included) and the sizes on each bus.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StorageSizingSpec {
    pub scenario: Scenario,
    pub energies_j: Vec<f64>,
    pub powers_w: Vec<f64>,
}

/// One item's cell.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SizeRecord {
    pub item: u64,
    pub cell: Cell,
}

/// Storage sizing on the study pipeline.
pub struct StorageSizing {
    spec: StorageSizingSpec,
    /// Item k's scenario: the run without storage, then the sizes.
    runs: Vec<Scenario>,
}

impl StorageSizing {
    /// The energy and power of item `i` (0 and 0 for the run without storage).
    fn size_of(&self, i: u64) -> (f64, f64) {
        match i.checked_sub(1) {
            None => (0.0, 0.0),
            Some(k) => {
                let p = self.spec.powers_w.len() as u64;
                (self.spec.energies_j[(k / p) as usize], self.spec.powers_w[(k % p) as usize])
            }
        }
    }
}

/// The shortest run a sizing compares \[s\]: about one modal wave period (6.3 s in sea state 2,
/// 12.4 s in sea state 6, Table 2.4), the least that shows a swing of the load.
pub const MIN_DURATION_S: f64 = 10.0;

impl Study for StorageSizing {
    const KIND: &'static str = "storage-sizing";
    const ITEM: &'static str = "size";
    type Spec = StorageSizingSpec;
    type Shared = ();
    type Part = Vec<SizeRecord>;
    type Summary = Sizing;

    fn new(spec: StorageSizingSpec) -> Result<StorageSizing, String> {
        spec.scenario.validate().map_err(|e| format!("its scenario is not valid: {e}"))?;
        // A run of no length has no swings to compare: its table would be zeros.
        let d = spec.scenario.sim.duration_s;
        if d.is_nan() || d < MIN_DURATION_S {
            return Err(format!(
                "sim.duration_s = {d}: a storage sizing needs at least {MIN_DURATION_S} s (the storages' effect is on \
                 the load's swings, which a shorter run does not show)"
            ));
        }
        let mut runs = vec![without(&spec.scenario)];
        runs.extend(sizes(&spec.scenario, &spec.energies_j, &spec.powers_w)?);
        Ok(StorageSizing { spec, runs })
    }
    fn spec(&self) -> &StorageSizingSpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        &self.spec.scenario
    }
    fn items(&self) -> u64 {
        self.runs.len() as u64
    }
    /// The runs' mean work (a storage adds states): the estimate of the whole study is their sum.
    fn item_work(&self) -> Option<f64> {
        Some(self.runs.iter().map(|s| s.work()).sum::<f64>() / self.runs.len() as f64)
    }
    fn prepare(&self) -> Result<(), String> {
        Ok(())
    }
    fn run(&self, _: &(), i: u64) -> Result<Vec<SizeRecord>, String> {
        Ok(vec![SizeRecord { item: i, cell: run_cell(&self.runs[i as usize])? }])
    }
    fn empty(&self) -> Vec<SizeRecord> {
        Vec::new()
    }
    fn merge(&self, acc: &mut Vec<SizeRecord>, other: &Vec<SizeRecord>) -> Result<(), String> {
        merge_records(acc, other, |r| r.item, Self::ITEM)
    }
    /// One cell per item of the ranges, each of its item's size.
    fn check_part(&self, part: &Vec<SizeRecord>, ranges: &[(u64, u64)]) -> Result<(), String> {
        for (r, i) in records_of(part, ranges, |r| r.item, Self::ITEM)? {
            let (e, p) = self.size_of(i);
            if r.cell.energy_j.to_bits() != e.to_bits() || r.cell.power_w.to_bits() != p.to_bits() {
                return Err(format!("size {i}: its cell is not of this size ({e} J, {p} W)"));
            }
        }
        Ok(())
    }
    /// Needs every size: the table compares each with the run without storage.
    fn summary(&self, part: &Vec<SizeRecord>, ranges: &[(u64, u64)]) -> Result<Sizing, String> {
        let lacking = crate::studies::study::missing(ranges, self.items());
        if let Some((a, b)) = lacking.first() {
            return Err(format!("the study lacks sizes {a}..{b} (of {}): merge every shard", self.items()));
        }
        let mut cells: Vec<Cell> = part.iter().map(|r| r.cell.clone()).collect();
        let without = cells.remove(0);
        let sc = &self.spec.scenario;
        Ok(Sizing { scenario: sc.name.clone(), duration_s: sc.sim.duration_s, without, cells })
    }
}
