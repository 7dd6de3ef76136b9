//! The run summary: statistics of every recorded signal, the power inventory of Table 5.6 at the
//! final time, stage efficiencies (Table 5.7) over its last minute and the energy books of the whole run.

use super::plant::{part_accounts, Energy, StageStores, DRIVE_ACCOUNTS, N_ENERGY};
use super::Trace;
use crate::plant::bus_part::Book;
use crate::scenario::Scenario;
use crate::signals::{Signal, SIGNALS};
use serde::Serialize;
use std::collections::BTreeMap;

/// Final value, extremes and time average of one recorded signal.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TraceStats {
    #[serde(rename = "final")]
    pub final_: f64,
    pub min: f64,
    pub max: f64,
    pub mean: f64,
    /// Settling time \[s\] (see [`settling_time`]): only for a signal that has an order or a nominal
    /// value ([`settling_target`]), moved away from it and came back to stay; None (JSON null)
    /// otherwise: a signal without an order, one that never left the band (nothing settled) and
    /// one that ends outside it or leaves it again too late (it does not settle).
    pub settling_time_s: Option<f64>,
}

/// Half-width of the settling band, as a fraction of the order or nominal value (2 %, the usual
/// control-engineering choice): 0.02 pu of bus voltage or turbine speed, 0.5 kn of a 25 kn order.
pub const SETTLING_BAND: f64 = 0.02;

/// Share of the run at its end a signal must stay in the band for to be called settled: in a
/// seaway a signal that leaves the band again and again has a last exit, but that is not settling.
pub const SETTLED_HOLD_SHARE: f64 = 0.1;

/// The value a signal is meant to settle at, when it has one: the last order of the ship speed,
/// the shaft speeds and the heading (their reference columns' final values), and the nominal
/// 1 pu of the turbine speed (governor set point) and of the bus voltage (field controller set
/// point). None for every other signal (powers, thrust, motions): they follow from the orders
/// and have no value of their own to settle at.
pub fn settling_target(signal: Signal, trace: &Trace) -> Option<f64> {
    let last = |s: Signal| trace.get(s).last().copied();
    match signal {
        Signal::ShipSpeedKn => last(Signal::SpeedCmdKn),
        Signal::PropRpm | Signal::PropRpm1 | Signal::PropRpm2 => last(Signal::PropRpmRef),
        Signal::HeadingDeg => last(Signal::HeadingRefDeg),
        Signal::TurbineSpeedPu | Signal::BusVoltagePu => Some(1.0),
        _ => None,
    }
}

/// The settling time of a column recorded at times `t` towards `target`: the band is
/// `SETTLING_BAND` times |target| (or times the largest |value| when the target is 0) around the
/// target; the settling time is the time of the first row after the last row outside it. It is
/// None unless (1) some row was outside the band (the signal moved), (2) the final row is inside
/// (the signal ends at its order), and (3) it stays inside over at least the last
/// `SETTLED_HOLD_SHARE` of the run.
pub fn settling_time(t: &[f64], col: &[f64], target: f64) -> Option<f64> {
    let (&last, &t_end, &t0) = (col.last()?, t.last()?, t.first()?);
    let scale = if target != 0.0 { target.abs() } else { col.iter().fold(0.0, |a: f64, v| a.max(v.abs())) };
    let band = SETTLING_BAND * scale;
    let outside = |v: f64| v.is_nan() || (v - target).abs() > band;
    if outside(last) {
        return None;
    }
    let i = col.iter().rposition(|&v| outside(v))?;
    let settled = t.get(i + 1).copied()?;
    (t_end - settled >= SETTLED_HOLD_SHARE * (t_end - t0)).then_some(settled)
}

/// Table 5.6 power inventory \[W\], sums over machines.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PowerInventory {
    pub turbine: f64,
    pub generator: f64,
    pub inverter: f64,
    pub motor: f64,
    pub ship: f64,
    /// The buses' other loads (ship service converters' output and pulsed loads).
    pub bus_loads: f64,
    /// The storage's power to the buses (negative: charging).
    pub storage: f64,
}

/// The stage efficiencies' window: the run's last minute, or its second half when it is shorter
/// than two \[s\].
pub const EFFICIENCY_WINDOW_S: f64 = 60.0;

/// Stage efficiencies (Table 5.7 definitions: each stage's output over its input in the Table 5.6
/// chain) from the energies of the run's last [`EFFICIENCY_WINDOW_S`], each stage's input less
/// what it stored over the window. The thesis gives them for steady running; a ratio of powers at
/// one instant is not one in a transient or a seaway (a rotor giving up speed passes on more
/// than it takes), a ratio of energies with the stores counted is, and it never exceeds 1.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Efficiencies {
    /// The window's start and end \[s\].
    pub from_s: f64,
    pub to_s: f64,
    /// generator / (turbine - the rotors' stored energy).
    pub generator: Option<f64>,
    /// (inverter + bus loads) / (generator - the bus's stored energy, the storage's charge
    /// included): rectifier, stator resistance, notching, inverter, brake resistors, filters and
    /// the storage's losses. Without bus parts this is Table 5.7's inverter / generator.
    pub power_electronics: Option<f64>,
    /// motor / inverter.
    pub motor: Option<f64>,
    /// ship / (motor - the shafts' and the ship's kinetic energy).
    pub propeller: Option<f64>,
    /// Each stage not given and why (its net input over the window was not positive: the power
    /// flowed back through it, as in braking).
    pub not_given: Vec<String>,
}

/// The run's books at its end: its energy accounts \[J\], the change of its stored energy since
/// the start \[J\], and the efficiency window's start and the stages' stores now.
pub(crate) struct Books<'a> {
    pub energy: &'a [f64; N_ENERGY],
    pub stored_change: f64,
    pub window: &'a WindowStart,
    pub stores: StageStores,
}

/// What the run books at the start of the efficiency window (see [`Efficiencies`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct WindowStart {
    pub time_s: f64,
    pub energy: [f64; N_ENERGY],
    pub stores: StageStores,
}

impl Efficiencies {
    /// The four, generator to propeller, or the first reason one is not given.
    pub fn all(&self) -> Result<[f64; 4], String> {
        match [self.generator, self.power_electronics, self.motor, self.propeller] {
            [Some(g), Some(p), Some(m), Some(q)] => Ok([g, p, m, q]),
            _ => Err(self.not_given.first().cloned().unwrap_or_default()),
        }
    }

    /// Over the window from `start` to the run's end at `end_s`, with its books `energy` and
    /// stores `stores` there.
    fn over(start: &WindowStart, end_s: f64, energy: &[f64; N_ENERGY], stores: &StageStores) -> Efficiencies {
        let d = |k: Energy| energy[k as usize] - start.energy[k as usize];
        let loads = |e: &[f64; N_ENERGY]| {
            part_accounts().zip(DRIVE_ACCOUNTS..).filter(|(a, _)| a.book == Book::Load).map(|(_, i)| e[i]).sum::<f64>()
        };
        let stages = [
            ("generator", d(Energy::Generator), d(Energy::Turbine) - (stores.rotors - start.stores.rotors)),
            (
                "power electronics",
                d(Energy::Inverter) + loads(energy) - loads(&start.energy),
                d(Energy::Generator) - (stores.bus - start.stores.bus),
            ),
            ("motor", d(Energy::Motor), d(Energy::Inverter)),
            ("propeller", d(Energy::Ship), d(Energy::Motor) - (stores.drive - start.stores.drive)),
        ];
        let mut not_given = Vec::new();
        let mut eta = stages.iter().map(|&(name, out, into)| {
            let ratio = out / into;
            let given = into > 0.0 && out >= 0.0 && ratio <= 1.0;
            if !given {
                let why = if into > 0.0 && out >= 0.0 {
                    format!("its books over the window give {ratio:.4}, more than it took")
                } else {
                    format!(
                        "power flowed back through it over the window (in {:.3} MJ, out {:.3} MJ), as in braking",
                        into / 1e6,
                        out / 1e6
                    )
                };
                not_given.push(format!("{name} efficiency: {why}"));
            }
            given.then_some(ratio)
        });
        let (generator, power_electronics, motor, propeller) =
            (eta.next().flatten(), eta.next().flatten(), eta.next().flatten(), eta.next().flatten());
        Efficiencies { from_s: start.time_s, to_s: end_s, generator, power_electronics, motor, propeller, not_given }
    }
}

/// Energy books over the whole run \[J\].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyBalance {
    /// Work of the turbines (input).
    pub turbine: f64,
    pub generator: f64,
    pub inverter: f64,
    pub motor: f64,
    /// Work against the ship's resistance (output).
    pub ship: f64,
    /// Energy dissipated in the brake resistors (part of `losses`).
    pub brake: f64,
    /// Energy the motors returned to the buses while braking.
    pub regenerated: f64,
    /// Energy the buses' other loads took (ship service converters' output and pulsed loads;
    /// output, like `ship`).
    pub bus_loads: f64,
    /// Energy the storage gave the buses (negative: took); its stored energy is in
    /// `stored_change`, its losses in `losses`.
    pub storage_to_bus: f64,
    /// Generator friction, stator copper, notching, motor copper and mechanical, brake resistor,
    /// propeller, ship service filter and storage losses.
    pub losses: f64,
    /// Change of kinetic energy (turbines, shafts, ship), of the bus capacitors' and filters'
    /// energy and of the storage's charge.
    pub stored_change: f64,
    /// turbine - ship - bus_loads - losses - stored_change.
    pub residual: f64,
    /// residual / turbine.
    pub relative_residual: f64,
}

/// Everything a run reports (its JSON is the public summary format).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    pub scenario: String,
    pub final_time_s: f64,
    pub steps: u64,
    pub signals: BTreeMap<String, TraceStats>,
    pub power_inventory_w: PowerInventory,
    pub efficiency: Efficiencies,
    pub energy_j: EnergyBalance,
    pub warnings: Vec<String>,
    /// With `propeller.model = "geometry"`: the geometry's table and where the run left it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub propeller: Option<GeometryNote>,
}

/// What a run on a propeller's blade geometry says about it: the points the four-quadrant series
/// is scaled to and the recorded rows outside the geometry's own first quadrant (a shaft at rest
/// or turning astern, J < 0, or J past zero thrust), where the scaled series carried the load.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GeometryNote {
    /// `propeller.geometry.name`.
    pub geometry: String,
    pub handover: crate::plant::propeller_table::Handover,
    /// Recorded rows handed over to the scaled four-quadrant series, and the first one's time \[s\]
    /// (None: the run stayed in the first quadrant).
    pub rows_handed_over: usize,
    pub first_handover_s: Option<f64>,
    /// The hub depth over tip radius below which a blade section at 12 o'clock cavitates (2D
    /// sections, steady: `blade::cavitation`), at the run's mean first-quadrant J and shaft speed
    /// (None: the run never turned ahead in its first quadrant, or the analysis failed) \[-\].
    pub cavitation_onset_h_over_r: Option<f64>,
    /// The J and shaft speed \[rev/s\] it was found at.
    pub cavitation_at_j: Option<f64>,
    pub cavitation_at_rev_per_s: Option<f64>,
    /// The ventilation loop the run used (`seakeeping.ventilation_onset`) and the h/R it started
    /// at \[-\]; with "derived", the blades' cavitation onset h/R it came from and the calm point
    /// (the run's fastest ordered speed) it was found at.
    pub ventilation_onset: crate::plant::propeller_losses::VentilationOnset,
    pub ventilation_on_h_over_r: f64,
    pub generic_ventilation_on_h_over_r: f64,
    pub derived_from_cavitation_h_over_r: Option<f64>,
    pub derived_at: Option<crate::sim::propeller_cavitation::CalmPoint>,
    /// The lowest ship speed at which a section at 12 o'clock cavitates in calm water, the shaft
    /// at the ship's self-propulsion speed and the hub at the scenario's calm-water depth (None:
    /// none up to 40 kn, or the analysis failed).
    pub calm_inception: Option<crate::sim::propeller_cavitation::Inception>,
    /// The same in words.
    pub note: String,
}

impl GeometryNote {
    /// The note of a run of `scenario` that recorded `trace` with the ventilation onset `used`.
    pub(crate) fn of(
        scenario: &Scenario,
        trace: &Trace,
        used: &crate::sim::propeller_cavitation::Onset,
    ) -> Option<GeometryNote> {
        use crate::scenario::PropellerModelKind;
        use crate::sim::propeller_cavitation as pc;
        let spec = scenario
            .propeller
            .geometry
            .as_ref()
            .filter(|_| scenario.propeller.model == PropellerModelKind::Geometry)?;
        let g = spec.resolve(&scenario.propeller.b_series_of()).ok()?;
        let flow = scenario.propeller_design_flow();
        let h = crate::plant::propeller_table::GeometryPropeller::new(&g, flow).ok()?.handover;
        let (t, j) = (trace.get(Signal::TS), trace.get(Signal::AdvanceRatio));
        let (n1, n2) = (trace.get(Signal::PropRpm1), trace.get(Signal::PropRpm2));
        let out = |i: usize| n1[i] <= 0.0 || n2[i] <= 0.0 || j[i] < 0.0 || j[i] > h.j0;
        let rows: Vec<usize> = (0..t.len().min(j.len()).min(n1.len()).min(n2.len())).filter(|&i| out(i)).collect();
        let first = rows.first().map(|&i| t[i]);
        // The run's mean operating point ahead, in its own first quadrant.
        let ahead: Vec<usize> = (0..t.len().min(j.len()).min(n1.len())).filter(|&i| !out(i)).collect();
        let mean = |c: &[f64]| ahead.iter().map(|&i| c[i]).sum::<f64>() / ahead.len().max(1) as f64;
        let (j_mean, n_mean) = (mean(j), mean(n1) / 60.0);
        let u_mean = mean(trace.get(Signal::ShipSpeedKn));
        let onset = (!ahead.is_empty())
            .then(|| {
                let p = pc::CalmPoint { ship_speed_kn: u_mean, rev_per_s: n_mean, j: j_mean };
                pc::check_at(&g, scenario.propeller.diameter_m, p, 0.0).ok().map(|c| c.onset_h_over_r)
            })
            .flatten()
            .filter(|h| h.is_finite());
        // Calm water: the plant without the run's added resistance.
        let plant = crate::sim::plant::Plant::new(scenario).ok();
        let inception = plant.as_ref().and_then(|p| pc::scenario_inception(scenario, p).ok().flatten());
        let generic_on = scenario.seakeeping.ventilation_on_h_over_r;
        let on = used.losses.ventilation_on;
        let place = match first {
            None => "the run stayed there".to_string(),
            Some(t0) => format!("{} recorded rows handed over, the first at t = {t0:.1} s", rows.len()),
        };
        let note = format!(
            "propeller.geometry \"{}\": its own table from the vortex lattice (at n = {:.2} rev/s) for 0 <= J <= J0 = {:.3} \
             (kT(0) = {:.4}, 10 kQ(0) = {:.4}); astern and past zero thrust the four-quadrant B4-70 series scaled to these points: {place}",
            spec.name,
            flow.rev_per_s,
            h.j0,
            h.kt0,
            10.0 * h.kq0
        );
        let note = match onset {
            Some(o) if o < crate::plant::propeller_losses::DISK_AT_SURFACE_H_OVER_R => format!(
                "{note}. Its sections at 12 o'clock do not cavitate while the disc is under water at the run's mean J = \
                 {j_mean:.3} and {n_mean:.2} rev/s (onset h/R {o:.2}: steady 2D sections, no tip vortex)"
            ),
            Some(o) => format!(
                "{note}. Its sections at 12 o'clock cavitate with the hub shallower than h/R = {o:.2} at the run's mean J = \
                 {j_mean:.3} and {n_mean:.2} rev/s (steady 2D sections, no tip vortex)"
            ),
            None => note,
        };
        let note = match used.at.zip(used.cavitation_h_over_r) {
            Some((p, h)) => format!(
                "{note}; ventilation starts at the derived h/R {on:.2} (generic {generic_on:.2}): the blades' cavitation \
                 onset h/R {h:.2} at {} held between 1 (tips at the surface) and the generic onset",
                pc::describe(&p)
            ),
            None => format!("{note}; ventilation starts at the generic h/R {on:.2}"),
        };
        let note = match &inception {
            Some(i) => format!(
                "{note}. In calm water a section cavitates from {} with the hub {:.2} m deep",
                pc::describe(&i.at),
                i.hub_depth_m
            ),
            None => format!("{note}. In calm water no section cavitates up to 40 kn"),
        };
        Some(GeometryNote {
            geometry: spec.name.clone(),
            handover: h,
            rows_handed_over: rows.len(),
            first_handover_s: first,
            cavitation_onset_h_over_r: onset,
            cavitation_at_j: onset.map(|_| j_mean),
            cavitation_at_rev_per_s: onset.map(|_| n_mean),
            ventilation_onset: used.kind,
            ventilation_on_h_over_r: on,
            generic_ventilation_on_h_over_r: generic_on,
            derived_from_cavitation_h_over_r: used.cavitation_h_over_r,
            derived_at: used.at,
            calm_inception: inception,
            note,
        })
    }
}

fn ratio(a: f64, b: f64) -> f64 {
    if b.abs() > 1e-9 {
        a / b
    } else {
        0.0
    }
}

impl Summary {
    pub(crate) fn build(
        scenario: &Scenario,
        trace: &Trace,
        final_time_s: f64,
        steps: u64,
        books: Books<'_>,
        warnings: Vec<String>,
    ) -> Summary {
        let Books { energy, stored_change, window, stores } = books;
        let mut signals = BTreeMap::new();
        for (info, col) in SIGNALS.iter().zip(&trace.columns) {
            let name = info.name;
            if col.is_empty() {
                continue;
            }
            let min = col.iter().copied().fold(f64::INFINITY, f64::min);
            let max = col.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let mean = col.iter().sum::<f64>() / col.len() as f64;
            let settling_time_s = Signal::from_name(name)
                .and_then(|sig| settling_target(sig, trace))
                .and_then(|target| settling_time(trace.get(Signal::TS), col, target));
            signals
                .insert(name.to_string(), TraceStats { final_: col[col.len() - 1], min, max, mean, settling_time_s });
        }
        // Every run records its initial row, so a column is never empty here.
        let last = |s: Signal| trace.get(s).last().copied().unwrap_or(f64::NAN);
        let inv = PowerInventory {
            turbine: last(Signal::PTurbineW),
            generator: last(Signal::PGeneratorW),
            inverter: last(Signal::PInverterW),
            motor: last(Signal::PMotorW),
            ship: last(Signal::PShipW),
            bus_loads: last(Signal::ShipServiceW) + last(Signal::PulsedLoadW),
            storage: last(Signal::StoragePowerW),
        };
        let e = |k: Energy| energy[k as usize];
        let losses = e(Energy::Friction)
            + e(Energy::StatorLoss)
            + e(Energy::NotchingLoss)
            + e(Energy::MotorStatorLoss)
            + e(Energy::MotorRotorLoss)
            + e(Energy::MotorMechLoss)
            + e(Energy::Brake)
            + (e(Energy::Propeller) - e(Energy::Thrust));
        // The bus parts' accounts, each added to its book in their order (all 0 without them:
        // the books above as they were, bit for bit).
        let book = |b: Book, start: Option<f64>| {
            part_accounts()
                .zip(DRIVE_ACCOUNTS..)
                .filter(|(a, _)| a.book == b)
                .fold(start, |sum, (_, i)| Some(sum.map_or(energy[i], |s| s + energy[i])))
        };
        let losses = book(Book::Loss, Some(losses)).unwrap_or(losses);
        let bus_loads = book(Book::Load, None).unwrap_or(0.0);
        let residual = e(Energy::Turbine) - e(Energy::Ship) - bus_loads - losses - stored_change;
        Summary {
            scenario: scenario.name.clone(),
            final_time_s,
            steps,
            signals,
            power_inventory_w: inv,
            efficiency: Efficiencies::over(window, final_time_s, energy, &stores),
            energy_j: EnergyBalance {
                turbine: e(Energy::Turbine),
                generator: e(Energy::Generator),
                inverter: e(Energy::Inverter),
                motor: e(Energy::Motor),
                ship: e(Energy::Ship),
                brake: e(Energy::Brake),
                regenerated: e(Energy::Regenerated),
                bus_loads,
                storage_to_bus: book(Book::ToBus, None).unwrap_or(0.0),
                losses,
                stored_change,
                residual,
                relative_residual: ratio(residual, e(Energy::Turbine)),
            },
            warnings,
            // Set by the run, which knows the ventilation onset it used (`GeometryNote::of`).
            propeller: None,
        }
    }

    /// The public JSON form (documented in docs/cli.md).
    pub fn to_json_value(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order step x = 1 - e^(-t/tau) towards its order 1, sampled every 0.1 s, settles
    /// within 2 % of the order at t = tau ln(50) (3.91 tau), to the sample. A signal that stays at
    /// its order has nothing to settle, one that ends away from it does not settle, and one that
    /// comes into the band only near the end (the last 10 % of the run) does not either.
    #[test]
    fn settling_time_of_a_first_order_step() {
        let tau = 2.0;
        let t: Vec<f64> = (0..=400).map(|i| i as f64 * 0.1).collect();
        let x: Vec<f64> = t.iter().map(|t| 1.0 - libm::exp(-t / tau)).collect();
        let ts = settling_time(&t, &x, 1.0).unwrap();
        assert!((ts - tau * libm::log(50.0)).abs() <= 0.1 + 1e-9, "{ts}");
        assert_eq!(settling_time(&t, &vec![1.0; 401], 1.0), None);
        // Stalled at 0.4 of the order: no settling, whatever its own final value.
        let stall: Vec<f64> = x.iter().map(|v| 1.0 - 0.6 * v).collect();
        assert_eq!(settling_time(&t, &stall, 1.0), None);
        // tau = 9.5 s: within 2 % after 37.2 s of a 40 s run, less than 10 % of it before the end.
        let slow: Vec<f64> = t.iter().map(|t| 1.0 - libm::exp(-t / 9.5)).collect();
        assert_eq!(settling_time(&t, &slow, 1.0), None);
    }
}
