//! The run summary: statistics of every recorded signal, the power inventory of Table 5.6 at the
//! final time, stage efficiencies (Table 5.7) and the energy books of the whole run.

use super::plant::{Energy, N_ENERGY};
use super::Trace;
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
}

/// Table 5.6 power inventory [W], sums over machines.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PowerInventory {
    pub turbine: f64,
    pub generator: f64,
    pub inverter: f64,
    pub motor: f64,
    pub ship: f64,
}

/// Stage efficiencies at the final time (Table 5.7 definitions: each stage's output over its
/// input in the Table 5.6 chain).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Efficiencies {
    /// generator / turbine.
    pub generator: f64,
    /// inverter / generator (rectifier, stator resistance, notching, inverter).
    pub power_electronics: f64,
    /// motor / inverter.
    pub motor: f64,
    /// ship / motor.
    pub propeller: f64,
}

/// Energy books over the whole run [J].
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
    /// Generator friction, stator copper, notching, motor copper and mechanical, brake resistor and
    /// propeller losses.
    pub losses: f64,
    /// Change of kinetic energy (turbines, shafts, ship) and of the bus capacitors' energy.
    pub stored_change: f64,
    /// turbine - ship - losses - stored_change.
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
        energy: &[f64; N_ENERGY],
        stored_change: f64,
        warnings: Vec<String>,
    ) -> Summary {
        let mut signals = BTreeMap::new();
        for (info, col) in SIGNALS.iter().zip(&trace.columns) {
            let name = info.name;
            if col.is_empty() {
                continue;
            }
            let min = col.iter().copied().fold(f64::INFINITY, f64::min);
            let max = col.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let mean = col.iter().sum::<f64>() / col.len() as f64;
            signals.insert(name.to_string(), TraceStats { final_: col[col.len() - 1], min, max, mean });
        }
        // Every run records its initial row, so a column is never empty here.
        let last = |s: Signal| trace.get(s).last().copied().unwrap_or(f64::NAN);
        let inv = PowerInventory {
            turbine: last(Signal::PTurbineW),
            generator: last(Signal::PGeneratorW),
            inverter: last(Signal::PInverterW),
            motor: last(Signal::PMotorW),
            ship: last(Signal::PShipW),
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
        let residual = e(Energy::Turbine) - e(Energy::Ship) - losses - stored_change;
        Summary {
            scenario: scenario.name.clone(),
            final_time_s,
            steps,
            signals,
            power_inventory_w: inv,
            efficiency: Efficiencies {
                generator: ratio(inv.generator, inv.turbine),
                power_electronics: ratio(inv.inverter, inv.generator),
                motor: ratio(inv.motor, inv.inverter),
                propeller: ratio(inv.ship, inv.motor),
            },
            energy_j: EnergyBalance {
                turbine: e(Energy::Turbine),
                generator: e(Energy::Generator),
                inverter: e(Energy::Inverter),
                motor: e(Energy::Motor),
                ship: e(Energy::Ship),
                brake: e(Energy::Brake),
                regenerated: e(Energy::Regenerated),
                losses,
                stored_change,
                residual,
                relative_residual: ratio(residual, e(Energy::Turbine)),
            },
            warnings,
        }
    }

    /// The public JSON form (documented in the README).
    pub fn to_json_value(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or_default()
    }
}
