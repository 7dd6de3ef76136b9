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

use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::RunResult;
use serde::Serialize;

/// Most storage sizes in one study (each a run of the scenario).
pub const MAX_SIZES: usize = 100;

/// A cell is "at its power rating" while the storages give or take at least this share of it.
pub const AT_RATING: f64 = 0.99;

/// One run's measures.
#[derive(Debug, Clone, Serialize)]
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
    /// turbines swing down there is charged too little fuel beside a steady one [-].
    pub below_curve_share: f64,
    /// Net energy the storages gave the buses over the run \[J\] (their charge's fall, less losses):
    /// the turbines must put it back later.
    pub storage_net_j: f64,
    /// Energy burnt in the brake resistors \[J\].
    pub brake_energy_j: f64,
    /// Lowest and highest state of charge (mean of the two storages) [-]; 0 without storage.
    pub soc_min: f64,
    pub soc_max: f64,
    /// Share of the run the charge spent in the taper before either limit, where the controller
    /// gives or takes less and less (`plant::storage::taper_j`: at least a second of the rated
    /// power wide, so a storage small beside its rating lives in it and never reaches its
    /// rating) [-].
    pub taper_share: f64,
    /// Share of the run the storages spent at their power rating [-] (of the two buses' sum, as
    /// the cycles: right for the symmetric head-seas runs, where both buses give and take alike).
    pub at_rating_share: f64,
    /// Equivalent full cycles an hour: the energy through the storages' terminals, both ways,
    /// over twice their usable energy (soc_max - soc_min of energy_j, both buses), per hour.
    pub cycles_per_hour: f64,
    /// The run's health warnings.
    pub warnings: Vec<String>,
}

/// The study: the run without storage, then every size.
#[derive(Debug, Clone, Serialize)]
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

/// The whole study on one thread (the command line spreads the cells over threads with
/// [`sizes`] and [`run_cell`]).
pub fn run(sc: &Scenario, energies_j: &[f64], powers_w: &[f64]) -> Result<Sizing, String> {
    let cells = sizes(sc, energies_j, powers_w)?.iter().map(run_cell).collect::<Result<Vec<_>, _>>()?;
    Ok(Sizing { scenario: sc.name.clone(), duration_s: sc.sim.duration_s, without: run_cell(&without(sc))?, cells })
}
