//! PI against LQG/LTR (thesis ch. 3.1 applied to the ch. 5.2 studies): the acceleration, AC
//! braking and head seas SS6 presets run with each controller, and what a power-system engineer
//! compares: turbine dip, bus-voltage excursion, settling, fuel (`aes-sim design compare`, the
//! README's table).

use crate::scenario::{ControllerDesign, LqgLtrParams};
use crate::signals::Signal;
use serde::Serialize;

/// The studies compared, by preset name.
pub const STUDIES: &[&str] = &["acceleration", "ac-braking", "head-seas-ss6"];

/// One run's figures.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ControllerRun {
    pub study: String,
    /// "pi" or "lqg_ltr".
    pub controller: ControllerDesign,
    /// Lowest and highest turbine speed [per unit of rated].
    pub turbine_speed_min_pu: f64,
    pub turbine_speed_max_pu: f64,
    /// Lowest and highest bus voltage [per unit of the set point].
    pub bus_voltage_min_pu: f64,
    pub bus_voltage_max_pu: f64,
    /// Settling time of the bus voltage and of the turbine speed (2 % band) [s]; None in waves,
    /// where the load never settles.
    pub bus_settling_s: Option<f64>,
    pub turbine_settling_s: Option<f64>,
    /// Fuel energy of the run [J] and the peak fuel power [W], all four prime movers.
    pub fuel_energy_j: f64,
    pub fuel_power_peak_w: f64,
    /// Largest field voltage [V] (what the exciter was asked for).
    pub field_voltage_max_v: f64,
}

/// Runs every study with the PI loops and with LQG/LTR tuned by `tuning`.
pub fn compare(tuning: &LqgLtrParams) -> Result<Vec<ControllerRun>, String> {
    let mut out = Vec::new();
    for name in STUDIES {
        for design in [ControllerDesign::Pi, ControllerDesign::LqgLtr] {
            let mut sc = crate::presets::preset(name).ok_or_else(|| format!("no preset {name}"))?;
            sc.controllers.design = design;
            sc.controllers.lqg_ltr = tuning.clone();
            let r = crate::run(&sc).map_err(|e| format!("{name} ({design:?}): {e}"))?;
            let st = |s: Signal| r.summary.signals[s.name()];
            let calm = sc.sea.kind == crate::scenario::SeaKind::Calm;
            let fuel = st(Signal::FuelPowerW);
            out.push(ControllerRun {
                study: name.to_string(),
                controller: design,
                turbine_speed_min_pu: st(Signal::TurbineSpeedPu).min,
                turbine_speed_max_pu: st(Signal::TurbineSpeedPu).max,
                bus_voltage_min_pu: st(Signal::BusVoltagePu).min,
                bus_voltage_max_pu: st(Signal::BusVoltagePu).max,
                bus_settling_s: calm.then_some(st(Signal::BusVoltagePu).settling_time_s),
                turbine_settling_s: calm.then_some(st(Signal::TurbineSpeedPu).settling_time_s),
                fuel_energy_j: fuel.mean * r.summary.final_time_s,
                fuel_power_peak_w: fuel.max,
                field_voltage_max_v: st(Signal::FieldVoltageV).max,
            });
        }
    }
    Ok(out)
}

/// The comparison as a Markdown table.
pub fn markdown(rows: &[ControllerRun]) -> String {
    let mut s = String::from(
        "| study | controller | turbine speed min / max [pu] | bus voltage min / max [pu] | bus settling [s] \
         | turbine settling [s] | fuel [GJ] | peak fuel power [MW] | peak field voltage [V] |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let opt = |v: Option<f64>| v.map_or("(waves)".to_string(), |x| format!("{x:.1}"));
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {:.3} / {:.3} | {:.3} / {:.3} | {} | {} | {:.3} | {:.1} | {:.0} |\n",
            r.study,
            match r.controller {
                ControllerDesign::Pi => "PI",
                ControllerDesign::LqgLtr => "LQG/LTR",
            },
            r.turbine_speed_min_pu,
            r.turbine_speed_max_pu,
            r.bus_voltage_min_pu,
            r.bus_voltage_max_pu,
            opt(r.bus_settling_s),
            opt(r.turbine_settling_s),
            r.fuel_energy_j / 1e9,
            r.fuel_power_peak_w / 1e6,
            r.field_voltage_max_v,
        ));
    }
    s
}
