//! How many gas turbines should run (thesis ch. 6.1: "a more intelligent operating schedule ...
//! for the four prime mover power source to optimize efficiency over the ship's entire operating
//! range"): for each speed and sea state 2-6, the online set that burns least fuel while the sea's
//! power swings leave it a reserve.
//!
//! The fuel of a cell: the plant's calm-water steady state at the speed with the sea's mean
//! added resistance R (eq. 2.60's mean, 2 sum S(w) R_aw(w) dw over the Bretschneider spectrum,
//! eq. 2.58, long-crested head seas, the worst heading for added resistance), solved with that
//! many sets online (`plant.online`: with fewer than four the buses are tied and the online sets
//! share the load), and each set's fuel from the part-load curve (ch. 5.2.4, `plant::fuel`).
//!
//! The reserve: the chance that the propulsion power exceeds the online sets' rating within
//! `plant.online.reserve_window_s` must stay below `plant.online.reserve_probability`. The swing
//! is estimated in the frequency domain, not by Monte Carlo: the slowly varying added resistance of
//! our time-domain model is Newman's |sum_i a_i sqrt(F_i) e^{i theta_i}|^2 (sea/waves.rs,
//! eq. 2.60), the squared envelope of a Gaussian process, so it is exponentially distributed with
//! mean R and crosses a level f upward at Rice's rate nu(f) = beta sqrt(x / pi) e^{-x}, x = f / R,
//! beta the rms bandwidth of the weights S(w) F(w) in encounter frequency (the envelope's
//! derivative is Gaussian with variance R beta^2 / 2, independent of the envelope). The force
//! reaches the turbines quasi-statically through the steady state's sensitivity dP/dR (the speed
//! loop holding speed, the propeller's efficiency at the loaded point): an upper bound, since the
//! ship's mass and the loop's trim filter the slow force (checked against the time domain in
//! tests/schedule.rs). The chance of at least one overload in the window T is 1 - e^{-nu T}.
//! Why this and not the rare-event machinery: the whole grid (16 speeds x 5 sea states x 4
//! counts) costs a few hundred steady states and no run, in about the time of one RAO-table
//! build; a Monte Carlo estimate of a 1e-3 chance per hour needs thousands of simulated hours per
//! cell. What it leaves out: the propellers' ventilation (it lowers the load while it lasts) and
//! the wave-frequency torque ripple, which the turbines' inertia averages out (ch. 5.2.4).

use crate::numerics::units::kn_to_m_s;
use crate::plant::fuel::{fuel_power, part_load_curve};
use crate::plant::online::{label, mask, SETS};
use crate::scenario::{Scenario, SeaKind};
use crate::sea::waves::{bretschneider, sea_state, G};
use serde::Serialize;
use std::f64::consts::PI;

/// The sea states of the schedule (Table 2.4).
pub const SEA_STATES: [u32; 5] = [2, 3, 4, 5, 6];
/// Frequencies of the spectral sums \[-\].
const N_OMEGA: usize = 120;
/// The step of added resistance for dP/dR, share of the calm-water thrust power's force \[-\].
const SENSITIVITY_STEP: f64 = 0.05;

/// The sea's slowly varying added resistance in head seas at one speed (Newman's approximation).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SlowDrift {
    /// Mean added resistance R \[N\].
    pub mean_n: f64,
    /// Rms bandwidth beta of the envelope's spectrum in encounter frequency \[rad/s\].
    pub bandwidth_rad_s: f64,
}

/// The mean and bandwidth of the slowly varying added resistance at ship speed `u` \[m/s\] in sea
/// state `state`, long-crested head seas, from the RAO table's mean force per amplitude squared.
pub fn slow_drift(sc: &Scenario, table: &crate::sea::seakeeping::tables::RaoTable, u: f64, state: u32) -> SlowDrift {
    let (wn, h) = sea_state(state).unwrap_or((0.507, 5.0));
    let mut sea = sc.sea.clone();
    sea.kind = SeaKind::Random;
    sea.sea_state = state;
    sea.h_sig_m = 0.0;
    sea.omega_n_rad_s = 0.0;
    let (lo, hi) = sea.band();
    let dw = (hi - lo) / N_OMEGA as f64;
    let (mut m0, mut m1, mut m2) = (0.0, 0.0, 0.0);
    for i in 0..N_OMEGA {
        let w = lo + (i as f64 + 0.5) * dw;
        // Added resistance per amplitude squared (N/m^2), as the fuel study's.
        let f = -table.interpolate(w, u, PI).fx;
        if f <= 0.0 {
            continue; // Newman's sum drops a component of the other sign (sea/waves.rs)
        }
        let weight = 2.0 * bretschneider(w, h, wn) * dw * f; // a_i^2 F_i
        let we = w + w * w * u / G; // head seas: omega_e = omega + k U
        m0 += weight;
        m1 += weight * we;
        m2 += weight * we * we;
    }
    if m0 <= 0.0 {
        return SlowDrift { mean_n: 0.0, bandwidth_rad_s: 0.0 };
    }
    SlowDrift { mean_n: m0, bandwidth_rad_s: (m2 / m0 - (m1 / m0) * (m1 / m0)).max(0.0).sqrt() }
}

/// Rice's up-crossing rate \[1/s\] of level `f` \[N\] by Newman's slowly varying force of `drift`
/// (the squared envelope of a Gaussian process): beta sqrt(x / pi) e^{-x}, x = f / R.
pub fn upcrossing_rate(drift: &SlowDrift, f: f64) -> f64 {
    if drift.mean_n <= 0.0 || f <= 0.0 {
        return if f <= 0.0 { f64::INFINITY } else { 0.0 };
    }
    let x = f / drift.mean_n;
    drift.bandwidth_rad_s * (x / PI).sqrt() * libm::exp(-x)
}

/// Chance of at least one up-crossing in `window_s` \[s\] at rate `nu` \[1/s\].
pub fn chance_in(nu: f64, window_s: f64) -> f64 {
    if nu.is_infinite() {
        1.0
    } else {
        -libm::expm1(-nu * window_s)
    }
}

/// One online set at one cell.
#[derive(Debug, Clone, Serialize)]
pub struct Candidate {
    /// The sets, e.g. "1+3".
    pub sets: String,
    pub count: usize,
    /// None: the sets cannot drive this speed (throttle past full, or the motors' limit).
    pub turbine_power_w: Option<f64>,
    pub fuel_power_w: Option<f64>,
    /// Least load of a set \[pu of rating\].
    pub load_pu: Option<f64>,
    /// dP/dR at the point \[W/N\].
    pub sensitivity_w_per_n: Option<f64>,
    /// Chance of an overload in the reserve window \[-\].
    pub overload_chance: Option<f64>,
    /// Whether each set carries at least the minimum load (one set always may).
    pub min_load_ok: bool,
    /// Whether it obeys the minimum load and the reserve.
    pub admissible: bool,
}

/// One cell of the schedule.
#[derive(Debug, Clone, Serialize)]
pub struct Cell {
    pub speed_kn: f64,
    pub sea_state: u32,
    pub drift: SlowDrift,
    /// The chosen number of sets online (None: not even four drive this speed).
    pub count: Option<usize>,
    pub fuel_power_w: Option<f64>,
    /// Fuel energy per nautical mile \[J/nmi\].
    pub fuel_per_nmi_j: Option<f64>,
    /// All four online.
    pub fuel_power_four_w: Option<f64>,
    /// (four - chosen) / four \[-\].
    pub saving: Option<f64>,
    /// The reserve, not fuel, decides: fewer sets would burn less but overload too often.
    pub reserve_decides: bool,
    /// No count holds the reserve (the most sets that drive the speed are chosen).
    pub reserve_unmet: bool,
    /// The reserve needs more sets than keep each at its minimum load.
    pub below_min_load: bool,
    /// One entry per count, 1 to 4 (first sets of the list: the tied buses make them alike).
    pub options: Vec<Candidate>,
}

/// The whole schedule.
#[derive(Debug, Clone, Serialize)]
pub struct Schedule {
    pub speeds_kn: Vec<f64>,
    pub sea_states: Vec<u32>,
    pub reserve_probability: f64,
    pub reserve_window_s: f64,
    pub cells: Vec<Cell>,
}

impl Schedule {
    /// The cell at `speed_kn` and sea state `state`.
    pub fn cell(&self, speed_kn: f64, state: u32) -> Option<&Cell> {
        self.cells.iter().find(|c| c.speed_kn == speed_kn && c.sea_state == state)
    }
}

/// The schedule's speeds: 0 to the top speed in steps (the top speed last).
pub fn speeds(sc: &Scenario) -> Vec<f64> {
    let o = &sc.plant.online;
    let n = (o.schedule_top_speed_kn / o.schedule_step_kn + 1e-9).floor() as usize;
    let mut v: Vec<f64> = (0..=n).map(|i| i as f64 * o.schedule_step_kn).collect();
    if o.schedule_top_speed_kn - v[v.len() - 1] > 1e-9 {
        v.push(o.schedule_top_speed_kn);
    }
    v
}

/// The steady state of `sets` at `speed_kn` with added resistance `r` \[N\]: each set's shaft power
/// \[W\], or None when the sets cannot drive it.
fn steady_power(sc: &Scenario, sets: &[u32], speed_kn: f64, r: f64) -> Option<Vec<f64>> {
    let mut calm = sc.clone();
    calm.sea.kind = SeaKind::Calm;
    calm.initial.speed_kn = speed_kn;
    calm.commands.truncate(1);
    if let Some(c) = calm.commands.first_mut() {
        c.t_s = 0.0;
        c.speed_kn = Some(speed_kn);
        c.heading_deg = None;
        c.online_sets = None;
    }
    calm.plant.online.sets = sets.to_vec();
    let mut sim = crate::Simulation::with_extra_resistance(&calm, r).ok()?;
    let p = sim.turbine_power();
    let on = mask(sets);
    Some((0..SETS).filter(|&k| on[k]).map(|k| p[k]).collect())
}

/// One online set `sets` at one cell: its power, fuel and overload chance with added resistance
/// `drift`, and whether it obeys the minimum load and the reserve.
pub fn evaluate(sc: &Scenario, sets: &[u32], speed_kn: f64, drift: &SlowDrift) -> Candidate {
    let o = &sc.plant.online;
    let rated = sc.plant.turbine.rated_power_w;
    let eta = sc.seakeeping.turbine_rated_efficiency;
    let curve = part_load_curve();
    let count = sets.len();
    let mut out = Candidate {
        sets: label(&mask(sets)),
        count,
        turbine_power_w: None,
        fuel_power_w: None,
        load_pu: None,
        sensitivity_w_per_n: None,
        overload_chance: None,
        min_load_ok: false,
        admissible: false,
    };
    let Some(p) = steady_power(sc, sets, speed_kn, drift.mean_n) else { return out };
    let total: f64 = p.iter().sum();
    let fuel: f64 = p.iter().map(|&pk| fuel_power(&curve, pk, rated, eta).0).sum();
    let least = p.iter().copied().fold(f64::INFINITY, f64::min) / rated;
    // dP/dR by a step of the calm thrust's order (one more steady state).
    let u = kn_to_m_s(speed_kn);
    let capacity = count as f64 * rated;
    let chance = if u <= 0.0 || drift.mean_n <= 0.0 {
        if total < capacity {
            0.0
        } else {
            1.0
        }
    } else {
        let dr = SENSITIVITY_STEP * (total / u).max(1.0e4);
        match steady_power(sc, sets, speed_kn, drift.mean_n + dr) {
            Some(p2) => {
                let c = (p2.iter().sum::<f64>() - total) / dr;
                out.sensitivity_w_per_n = Some(c);
                let level = drift.mean_n + (capacity - total) / c.max(1e-9);
                chance_in(upcrossing_rate(drift, level), o.reserve_window_s)
            }
            // A little more resistance is past the sets: no reserve at all.
            None => 1.0,
        }
    };
    out.turbine_power_w = Some(total);
    out.fuel_power_w = Some(fuel);
    out.load_pu = Some(least);
    out.overload_chance = Some(chance);
    out.min_load_ok = count == 1 || least >= o.min_load_pu;
    out.admissible = out.min_load_ok && chance <= o.reserve_probability;
    out
}

/// The first `n` sets (with the buses tied any `n` sets are alike).
fn first_sets(n: usize) -> Vec<u32> {
    (1..=n as u32).collect()
}

/// What the schedule chose at a cell among its options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    /// The chosen option's index (None: no option drives the speed).
    pub pick: Option<usize>,
    /// Fewer sets would burn less (at their minimum load or above) but overload too often.
    pub reserve_decides: bool,
    /// No option keeps the reserve: the most sets that drive the speed are chosen.
    pub reserve_unmet: bool,
    /// The reserve needs more sets than keep each at its minimum load: the fewest that keep the
    /// reserve are chosen, each below its minimum load.
    pub below_min_load: bool,
}

/// The schedule's rule: among the options that keep the reserve, the least fuel of those whose
/// sets carry their minimum load; if the reserve needs more sets than that allows, the fewest
/// sets that keep it (safety before the minimum load); if no option keeps it, the most sets that
/// drive the speed.
pub fn choose(options: &[Candidate], reserve: f64) -> Choice {
    let driven = |o: &Candidate| o.fuel_power_w.is_some();
    let safe = |o: &Candidate| driven(o) && o.overload_chance.is_some_and(|c| c <= reserve);
    let fuel = |i: &usize| options[*i].fuel_power_w.unwrap_or(f64::INFINITY);
    let by_fuel = |a: &usize, b: &usize| fuel(a).total_cmp(&fuel(b));
    let idx = 0..options.len();
    let pick_ml = idx.clone().filter(|&i| safe(&options[i]) && options[i].min_load_ok).min_by(by_fuel);
    let pick_safe = idx.clone().filter(|&i| safe(&options[i])).min_by_key(|&i| options[i].count);
    let fuel_only = idx.clone().filter(|&i| driven(&options[i]) && options[i].min_load_ok).min_by(by_fuel);
    match (pick_ml, pick_safe) {
        (Some(i), _) => Choice {
            pick: Some(i),
            reserve_decides: fuel_only.is_some_and(|f| fuel(&f) < fuel(&i)),
            reserve_unmet: false,
            below_min_load: false,
        },
        (None, Some(i)) => Choice { pick: Some(i), reserve_decides: true, reserve_unmet: false, below_min_load: true },
        (None, None) => {
            let most = idx.filter(|&i| driven(&options[i])).max_by_key(|&i| options[i].count);
            Choice { pick: most, reserve_decides: most.is_some(), reserve_unmet: true, below_min_load: false }
        }
    }
}

/// The schedule over the scenario's speeds and sea states 2-6.
pub fn run(sc: &Scenario) -> Result<Schedule, String> {
    sc.validate().map_err(|e| e.to_string())?;
    let table = sc.rao_table()?;
    let speeds = speeds(sc);
    let mut cells = Vec::new();
    for &v in &speeds {
        let u = kn_to_m_s(v);
        for state in SEA_STATES {
            let drift = slow_drift(sc, &table, u, state);
            let options: Vec<Candidate> = (1..=SETS).map(|n| evaluate(sc, &first_sets(n), v, &drift)).collect();
            cells.push(cell_of(v, state, drift, options, sc.plant.online.reserve_probability));
        }
    }
    Ok(Schedule {
        speeds_kn: speeds,
        sea_states: SEA_STATES.to_vec(),
        reserve_probability: sc.plant.online.reserve_probability,
        reserve_window_s: sc.plant.online.reserve_window_s,
        cells,
    })
}

/// A cell from its options.
fn cell_of(v: f64, state: u32, drift: SlowDrift, options: Vec<Candidate>, reserve: f64) -> Cell {
    let Choice { pick, reserve_decides, reserve_unmet, below_min_load } = choose(&options, reserve);
    let fuel = pick.and_then(|i| options[i].fuel_power_w);
    let four = options.iter().find(|o| o.count == SETS).and_then(|o| o.fuel_power_w);
    Cell {
        speed_kn: v,
        sea_state: state,
        drift,
        count: pick.map(|i| options[i].count),
        fuel_power_w: fuel,
        fuel_per_nmi_j: fuel.filter(|_| v > 0.0).map(|f| f * 3600.0 / v),
        fuel_power_four_w: four,
        saving: fuel.zip(four).map(|(f, f4)| (f4 - f) / f4),
        reserve_decides,
        reserve_unmet,
        below_min_load,
        options,
    }
}

/// The exhaustive check at one cell: all 15 online sets evaluated, each with its own steady state;
/// returns them and the least fuel among the admissible.
pub fn exhaustive(sc: &Scenario, speed_kn: f64, state: u32) -> Result<(Vec<Candidate>, Option<f64>), String> {
    let table = sc.rao_table()?;
    let drift = slow_drift(sc, &table, kn_to_m_s(speed_kn), state);
    let all: Vec<Candidate> = (1u32..(1 << SETS))
        .map(|bits| {
            let sets: Vec<u32> = (0..SETS as u32).filter(|k| bits & (1 << k) != 0).map(|k| k + 1).collect();
            evaluate(sc, &sets, speed_kn, &drift)
        })
        .collect();
    let pick = choose(&all, sc.plant.online.reserve_probability).pick;
    let best = pick.and_then(|i| all[i].fuel_power_w);
    Ok((all, best))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rice's rate for the exponential force: at the mean it is beta / sqrt(pi) e^{-1}; it falls
    /// as e^{-x}; the chance in a window follows 1 - e^{-nu T}.
    #[test]
    fn rate_of_the_squared_envelope() {
        let d = SlowDrift { mean_n: 1.0e5, bandwidth_rad_s: 0.2 };
        let nu1 = upcrossing_rate(&d, 1.0e5);
        assert!((nu1 - 0.2 / PI.sqrt() * libm::exp(-1.0)).abs() < 1e-15);
        let nu10 = upcrossing_rate(&d, 1.0e6);
        assert!((nu10 / nu1 - (10.0f64).sqrt() * libm::exp(-9.0)).abs() < 1e-12);
        assert!((chance_in(1e-4, 3600.0) - (1.0 - libm::exp(-0.36))).abs() < 1e-15);
        assert_eq!(chance_in(upcrossing_rate(&d, -1.0), 3600.0), 1.0);
    }
}
