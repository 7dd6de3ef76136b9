//! PI against LQG/LTR (thesis ch. 3.1 applied to the ch. 5.2 studies): the acceleration, AC
//! braking and head seas SS6 presets run with each controller, and what a power-system engineer
//! compares: turbine dip, bus-voltage excursion, settling, fuel (`aes-sim design compare`, the
//! the table in docs/studies/controller-design.md).

use crate::scenario::{ControllerDesign, LqgLtrParams};
use crate::signals::Signal;
use serde::Serialize;

/// The studies compared, by preset name.
pub const STUDIES: &[&str] = &["acceleration", "ac-braking", "head-seas-ss6"];

/// Half-width of the band around the set point that counts as recovered \[per unit\].
pub const RECOVERY_BAND: f64 = 0.01;

/// One run's figures.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ControllerRun {
    pub study: String,
    /// "pi" or "lqg_ltr".
    pub controller: ControllerDesign,
    /// Lowest and highest turbine speed \[per unit of rated\].
    pub turbine_speed_min_pu: f64,
    pub turbine_speed_max_pu: f64,
    /// Lowest and highest bus voltage [per unit of the set point].
    pub bus_voltage_min_pu: f64,
    pub bus_voltage_max_pu: f64,
    /// Recovery of the bus voltage and of the turbine speed: time from the order (the second
    /// command) until the signal is back within +-1 % of its set point for good \[s\]; None in
    /// waves (the load never settles) or when it is not back by the end of the run.
    pub bus_recovery_s: Option<f64>,
    pub turbine_recovery_s: Option<f64>,
    /// Fuel energy of the run \[J\] and the peak fuel power \[W\], all four prime movers.
    pub fuel_energy_j: f64,
    pub fuel_power_peak_w: f64,
    /// Largest field voltage \[V\] (what the exciter was asked for).
    pub field_voltage_max_v: f64,
}

/// Runs every study with the PI loops and with LQG/LTR tuned by `tuning`.
pub fn compare(tuning: &LqgLtrParams) -> Result<Vec<ControllerRun>, String> {
    let mut out = Vec::new();
    for name in STUDIES {
        for design in [ControllerDesign::Pi, ControllerDesign::LqgLtr] {
            let mut sc = crate::scenario::presets::preset(name).ok_or_else(|| format!("no preset {name}"))?;
            sc.controllers.design = design;
            sc.controllers.lqg_ltr = tuning.clone();
            let r = crate::run(&sc).map_err(|e| format!("{name} ({design:?}): {e}"))?;
            let st = |s: Signal| r.summary.signals[s.name()];
            let calm = sc.sea.kind == crate::scenario::SeaKind::Calm;
            let fuel = st(Signal::FuelPowerW);
            let order = sc.commands.get(1).map_or(0.0, |c| c.t_s);
            let recovery = |s: Signal| -> Option<f64> {
                let (t, x) = (r.trace.column("t_s")?, r.trace.column(s.name())?);
                let out = x.iter().rposition(|v| (v - 1.0).abs() > RECOVERY_BAND);
                match out {
                    None => Some(0.0),
                    Some(i) if i + 1 < t.len() => Some((t[i + 1] - order).max(0.0)),
                    Some(_) => None,
                }
            };
            out.push(ControllerRun {
                study: name.to_string(),
                controller: design,
                turbine_speed_min_pu: st(Signal::TurbineSpeedPu).min,
                turbine_speed_max_pu: st(Signal::TurbineSpeedPu).max,
                bus_voltage_min_pu: st(Signal::BusVoltagePu).min,
                bus_voltage_max_pu: st(Signal::BusVoltagePu).max,
                bus_recovery_s: if calm { recovery(Signal::BusVoltagePu) } else { None },
                turbine_recovery_s: if calm { recovery(Signal::TurbineSpeedPu) } else { None },
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
        "| study | controller | turbine speed min / max [pu] | bus voltage min / max [pu] | bus back within 1 % \
         [s] | turbine back within 1 % [s] | fuel [GJ] | peak fuel power [MW] | peak field voltage [V] |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let calm = |r: &ControllerRun| r.study != "head-seas-ss6";
    let opt = |r: &ControllerRun, v: Option<f64>| match v {
        Some(x) => format!("{x:.1}"),
        None if calm(r) => "not by the end".to_string(),
        None => "(waves)".to_string(),
    };
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
            opt(r, r.bus_recovery_s),
            opt(r, r.turbine_recovery_s),
            r.fuel_energy_j / 1e9,
            r.fuel_power_peak_w / 1e6,
            r.field_voltage_max_v,
        ));
    }
    s
}
