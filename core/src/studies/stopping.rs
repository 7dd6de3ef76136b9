//! The full-astern stopping test of the maneuvers booklet (IMO MSC.137(76) 5.3.4, with the
//! definitions of MSC/Circ.1053): from straight running at the approach speed, full astern is
//! ordered at once (`crash_stop`), and the ship's track is measured until it is dead in the water.
//!
//! Unlike the booklet's other maneuvers (the hull at a fixed shaft speed) the stop runs the whole
//! drive train: the windmilling propellers drive the motors as generators (ch. 5.2.2's AC
//! braking), the returned power raises the buses and is burnt in the brake resistors or taken by
//! storage, and the turbines unload. So the test also reports the electrical side: the peak bus
//! voltage, the brake energy and the peak power the motors return.
//!
//! IMO's criterion (track reach at most 15 ship lengths; an Administration may accept up to 20) is
//! for merchant ships; the thesis' ship is a naval destroyer, so the verdict is a reference, not a
//! requirement.

use crate::scenario::{Command, PropellerModelKind, RectifierKind, Scenario};
use crate::signals::Signal;
use serde::Serialize;

/// Straight running before the order \[s\] (the run starts in its steady state).
pub const ORDER_S: f64 = 10.0;
/// Longest stop simulated after the order \[s\].
pub const MAX_STOP_S: f64 = 400.0;
/// IMO's track reach limit \[ship lengths\] and what an Administration may allow.
pub const IMO_TRACK_REACH_L: f64 = 15.0;
pub const IMO_TRACK_REACH_ALLOWED_L: f64 = 20.0;
/// Recording interval of the stop \[s\].
const RECORD_S: f64 = 0.5;

/// The stopping test's answers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stopping {
    /// Approach speed \[kn\].
    pub approach_kn: f64,
    /// Distance along the track from the order until dead in the water \[m\] and in ship lengths.
    pub track_reach_m: f64,
    pub track_reach_l: f64,
    /// Distance along the approach course (the advance of the stop) \[m\] and in ship lengths.
    pub head_reach_m: f64,
    pub head_reach_l: f64,
    /// Distance across the approach course at the stop \[m\] (positive to starboard) and in ship
    /// lengths.
    pub lateral_deviation_m: f64,
    pub lateral_deviation_l: f64,
    /// From the order until the ship's way ahead is gone (its speed along its heading crosses
    /// zero) \[s\].
    pub time_to_dead_s: f64,
    /// Highest bus voltage of the stop \[pu\] and \[V\].
    pub peak_bus_voltage_pu: f64,
    pub peak_bus_voltage_v: f64,
    /// Energy the brake resistors burnt, both buses, until dead in the water \[J\].
    pub brake_energy_j: f64,
    /// Energy the storages took, both buses, until dead in the water \[J\] (0 without).
    pub storage_taken_j: f64,
    /// Highest power the motors returned to the buses (both inverters) \[W\].
    pub peak_regenerated_w: f64,
    /// Whether the track reach is within IMO's 15 L (a reference for a naval ship).
    pub imo_pass: bool,
    /// What the test changed in the scenario to run it, in words (empty: nothing).
    pub adjustments: Vec<String>,
    /// The run's health warnings.
    pub warnings: Vec<String>,
    /// The stop every 0.5 s from the order: the track and the electrical traces on one time axis.
    pub track: Vec<StopSample>,
}

/// One sample of the stop: time from the order \[s\], position from the order's \[m\] (north,
/// east), heading change \[deg\], speed through the water \[kn\], shaft speed (port) \[rpm\], bus
/// voltage \[pu\], power the motors take (negative: return) and the brake resistors burn \[W\].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StopSample {
    pub t_s: f64,
    pub x_m: f64,
    pub y_m: f64,
    pub heading_deg: f64,
    pub speed_kn: f64,
    pub shaft_rpm: f64,
    pub bus_voltage_pu: f64,
    pub motor_power_w: f64,
    pub brake_power_w: f64,
}

/// The scenario of the stop: straight at `approach_kn`, the crash stop at [`ORDER_S`]; the
/// propellers on the four-quadrant series where they were the ahead-only B-series, braking
/// allowed, and the thesis' 1 ohm brake resistor where the buses had no way to take energy back.
/// Returns the scenario and what was changed, in words.
pub fn stop_scenario(sc: &Scenario, approach_kn: f64) -> (Scenario, Vec<String>) {
    let mut s = sc.clone();
    let mut changed = Vec::new();
    if s.propeller.model == PropellerModelKind::BSeries {
        s.propeller.model = PropellerModelKind::FourQuadrant;
        changed.push("propeller.model: four_quadrant (the B-series holds ahead only)".to_string());
    }
    if !s.controllers.slip.allow_braking {
        s.controllers.slip.allow_braking = true;
        changed.push("controllers.slip.allow_braking: true".to_string());
    }
    let storage = s.plant.storage.energy_j > 0.0;
    if s.plant.dc_link.brake_resistor_ohm <= 0.0 && s.plant.dc_link.rectifier != RectifierKind::Reversible && !storage {
        s.plant.dc_link.brake_resistor_ohm = 1.0;
        changed.push("plant.dc_link.brake_resistor_ohm: 1 (ch. 5.2.2's; the buses had no path back)".to_string());
    }
    s.sea.kind = crate::scenario::SeaKind::Calm;
    s.initial.speed_kn = approach_kn;
    let order = |t_s: f64, speed_kn: Option<f64>, crash_stop: bool| Command {
        t_s,
        speed_kn,
        heading_deg: None,
        heading_rate_deg_s: None,
        online_sets: None,
        crash_stop,
    };
    s.commands = vec![order(0.0, Some(approach_kn), false), order(ORDER_S, None, true)];
    s.sim.duration_s = ORDER_S + MAX_STOP_S;
    s.sim.record_interval_s = RECORD_S;
    (s, changed)
}

/// The full-astern stopping test of `sc`'s ship from `approach_kn`, with the ship length `l` \[m\].
pub fn stopping_test(sc: &Scenario, approach_kn: f64, l: f64) -> Result<Stopping, String> {
    let (s, adjustments) = stop_scenario(sc, approach_kn);
    let r = crate::sim::run(&s).map_err(|e| format!("the stopping test: {e}"))?;
    let tr = &r.trace;
    let (t, x, y, psi) = (tr.get(Signal::TS), tr.get(Signal::XM), tr.get(Signal::YM), tr.get(Signal::HeadingDeg));
    let (speed, rpm) = (tr.get(Signal::ShipSpeedKn), tr.get(Signal::PropRpm1));
    let (bus, p_inv, brake) = (tr.get(Signal::BusVoltagePu), tr.get(Signal::PInverterW), tr.get(Signal::BrakePowerW));
    let i0 = t.iter().position(|&ti| ti >= ORDER_S - 1e-9).ok_or("the stopping test: no row at the order")?;
    // Way ahead: the displacement between rows along the heading. Dead in the water where it is
    // first zero or less after the order.
    let ahead = |i: usize| {
        let h = psi[i].to_radians();
        (x[i + 1] - x[i]) * libm::cos(h) + (y[i + 1] - y[i]) * libm::sin(h)
    };
    let stop = (i0..t.len() - 1)
        .find(|&i| ahead(i) <= 0.0)
        .ok_or_else(|| format!("the stopping test: the ship still had way ahead {MAX_STOP_S} s after the order"))?;
    let track_reach_m: f64 = (i0..stop).map(|i| libm::hypot(x[i + 1] - x[i], y[i + 1] - y[i])).sum();
    let h0 = psi[i0].to_radians();
    let (dx, dy) = (x[stop] - x[i0], y[stop] - y[i0]);
    let head_reach_m = dx * libm::cos(h0) + dy * libm::sin(h0);
    let lateral_deviation_m = -dx * libm::sin(h0) + dy * libm::cos(h0);
    let span = i0..=stop;
    let peak = |sig: Signal| tr.get(sig)[span.clone()].iter().copied().fold(f64::MIN, f64::max);
    let dt = RECORD_S;
    let integral = |sig: Signal| tr.get(sig)[span.clone()].iter().sum::<f64>() * dt;
    let storage_taken_j = if s.plant.storage.energy_j > 0.0 { -integral(Signal::StoragePowerW).min(0.0) } else { 0.0 };
    let track = (i0..t.len())
        .map(|i| StopSample {
            t_s: t[i] - ORDER_S,
            x_m: x[i] - x[i0],
            y_m: y[i] - y[i0],
            heading_deg: psi[i] - psi[i0],
            speed_kn: speed[i],
            shaft_rpm: rpm[i],
            bus_voltage_pu: bus[i],
            motor_power_w: p_inv[i],
            brake_power_w: brake[i],
        })
        .collect();
    let track_reach_l = track_reach_m / l;
    Ok(Stopping {
        approach_kn,
        track_reach_m,
        track_reach_l,
        head_reach_m,
        head_reach_l: head_reach_m / l,
        lateral_deviation_m,
        lateral_deviation_l: lateral_deviation_m / l,
        time_to_dead_s: t[stop] - t[i0],
        peak_bus_voltage_pu: peak(Signal::BusVoltagePu),
        peak_bus_voltage_v: peak(Signal::BusVoltageV),
        brake_energy_j: integral(Signal::BrakePowerW),
        storage_taken_j,
        peak_regenerated_w: -tr.get(Signal::PInverterW)[span.clone()].iter().copied().fold(f64::MAX, f64::min),
        imo_pass: track_reach_l <= IMO_TRACK_REACH_L,
        adjustments,
        warnings: r.summary.warnings,
        track,
    })
}
