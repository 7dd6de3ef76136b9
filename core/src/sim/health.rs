//! The plant's health: checks of a finished run against the limits an engineer would expect a
//! real plant to have, each with its threshold and reason declared once here. The model itself
//! runs on past every one of them (its divergence limits, `sim::limits`, are far wider); a check
//! that fails adds a sentence to the summary's `warnings`, saying when, how long and how far.
//! The book's table (docs/reference/health.md, `aes-sim health --markdown`) and the page's live drive train
//! (`output::presentation::WarningLevels`) read these declarations.

use super::Trace;
pub use crate::plant::bus_part::CheckInfo;
use crate::plant::propeller_losses::DISK_AT_SURFACE_H_OVER_R;
use crate::plant::BusParts;
use crate::scenario::Scenario;
use crate::signals::Signal;

/// Turbine speed below which a gas turbine set is stalled by its load rather than governed
/// [pu of the governor set point].
pub const TURBINE_MIN_RUNNING_PU: f64 = 0.5;
/// How long the turbines may stay below [`TURBINE_MIN_RUNNING_PU`] before a warning \[s\].
pub const TURBINE_MIN_RUNNING_FOR_S: f64 = 5.0;
/// Turbine overspeed [pu of the governor set point]: an LM2500's overspeed protection trips near
/// 1.1 (the same figure as `sim::limits`' note); any recorded row above it warns.
pub const TURBINE_OVERSPEED_PU: f64 = 1.1;
/// Lower edge of the bus voltage's allowed band \[pu of the set point\].
pub const BUS_LOW_PU: f64 = 0.9;
/// How long the bus may stay outside its band before a warning \[s\].
pub const BUS_OUTSIDE_FOR_S: f64 = 5.0;
/// How long a motor may stay at its slip limit (rated power or peak torque) before a warning \[s\].
pub const MOTOR_AT_LIMIT_FOR_S: f64 = 30.0;
/// Share of the run a propeller's disc may break the surface (h/R below
/// [`DISK_AT_SURFACE_H_OVER_R`]) before a warning \[-\].
pub const PROPELLER_EMERGED_SHARE: f64 = 0.5;
pub use crate::plant::bus_loads::FILTER_OSCILLATION_PU;

/// The speed order is held when the mean speed over the last [`SPEED_HELD_OVER_S`] of the run is
/// within the larger of [`SPEED_HELD_KN`] and [`SPEED_HELD_SHARE`] of it (the order in force all
/// that time, and the run at least twice as long).
pub const SPEED_HELD_OVER_S: f64 = 60.0;
pub const SPEED_HELD_KN: f64 = 2.0;
pub const SPEED_HELD_SHARE: f64 = 0.2;

/// The upper edge of the bus voltage's allowed band \[pu of the set point\]: the top of the brake
/// chopper's band (`plant.dc_link.brake_on_pu` + `brake_band_pu`).
pub fn bus_high_pu(sc: &Scenario) -> f64 {
    sc.plant.dc_link.brake_on_pu + sc.plant.dc_link.brake_band_pu
}

/// Every check, its threshold and its reason.
pub fn checks() -> Vec<CheckInfo> {
    vec![
        CheckInfo {
            name: "turbine below its minimum running speed",
            threshold: format!(
                "turbine speed (mean of the four sets) below {TURBINE_MIN_RUNNING_PU} pu for longer than \
                 {TURBINE_MIN_RUNNING_FOR_S} s"
            ),
            reason: "a gas turbine generator set runs between idle and overspeed with its governor holding the set \
                     point; held far below it the set is stalled by its load (full throttle, torque not enough), \
                     the generator's frequency and voltage are far below what the rectifier and the loads are built \
                     for, and a real set would be shed or tripped (the presets' transients, the thesis' studies among them, \
                     stay above 0.6 pu)",
        },
        CheckInfo {
            name: "turbine overspeed",
            threshold: format!("turbine speed above {TURBINE_OVERSPEED_PU} pu at any recorded time"),
            reason: "an LM2500's overspeed protection trips near 1.1 pu: a real plant would lose the set there, \
                     the model runs on (a propeller that ventilates or a motor that brakes unloads the turbines)",
        },
        CheckInfo {
            name: "bus voltage outside its band",
            threshold: format!(
                "bus voltage (mean of the two buses) below {BUS_LOW_PU} pu or above the top of the brake chopper's \
                 band (`plant.dc_link.brake_on_pu` + `brake_band_pu`, {:.2} pu by default) for longer than \
                 {BUS_OUTSIDE_FOR_S} s",
                bus_high_pu(&Scenario::default())
            ),
            reason: "below 0.9 pu the inverters cannot give the motors their voltage (the dynamic saturation of \
                     ch. 2.2.3) and the ship's other loads see a sag beyond a few seconds' ride-through; above the \
                     chopper's band the brake resistor is not holding the bus (or there is none) and the converters' \
                     insulation and capacitors are stressed",
        },
        CheckInfo {
            name: "motor at its slip limit",
            threshold: format!(
                "a motor's slip held at its upper limit (rated power, or the peak-torque slip when the bus is \
                 low) for longer than {MOTOR_AT_LIMIT_FOR_S} s"
            ),
            reason: "the slip controller cannot give what the speed loop asks: the order is beyond the plant's \
                     power, or a sagging bus leaves the motor at its pull-out torque",
        },
        CheckInfo {
            name: "propeller out of the water",
            threshold: format!(
                "a propeller's disc breaking the surface (h/R below {DISK_AT_SURFACE_H_OVER_R}) for more than \
                 {:.0} % of the run",
                PROPELLER_EMERGED_SHARE * 100.0
            ),
            reason: "the hub is too shallow for the sea (or for the ship's loading): the propeller works \
                     emerged and ventilated most of the time, which no design accepts",
        },
        CheckInfo {
            name: "speed order not held",
            threshold: format!(
                "the mean ship speed over the run's last {SPEED_HELD_OVER_S} s further from the order than \
                 {SPEED_HELD_KN} kn or {:.0} % of it, whichever is larger (runs of at least {} s whose last order \
                 came before that minute)",
                SPEED_HELD_SHARE * 100.0,
                2.0 * SPEED_HELD_OVER_S
            ),
            reason: "the speed loop cannot give the order: the plant's power is not enough (the motors at their \
                     limit), its trim is at its limit, or the waves' mean push carries the ship faster than \
                     ordered with the propellers stopped (the loop never reverses them)",
        },
        CheckInfo {
            name: "online set overloaded",
            threshold: format!(
                "an online turbine-generator set above its rating (`plant.turbine.rated_power_w`), or at full \
                 throttle with its speed below {SET_FALLING_PU} pu, for longer than {SET_OVERLOADED_FOR_S} s"
            ),
            reason: "the online sets cannot give what the motors draw: too few sets run for the speed and the sea \
                     (start another, `plant.online`), and a real set would trip on overload or its frequency",
        },
        CheckInfo {
            name: "shaft overspeed",
            threshold: "a propeller shaft faster than the speed controller's largest shaft speed \
                        (`controllers.speed.max_shaft_rpm`) at any recorded time"
                .into(),
            reason: "the speed loop never orders more: the shaft is racing (a propeller emerged or ventilated \
                     unloads it faster than the slip controller can react)",
        },
    ]
    .into_iter()
    .chain(BusParts::checks())
    .collect()
}

/// The book's table of the checks (docs/reference/health.md, between its `health:begin` and
/// `health:end` markers).
pub fn markdown() -> String {
    let mut s = String::from("| check | warns when | why |\n|---|---|---|\n");
    for c in checks() {
        s.push_str(&format!("| {} | {} | {} |\n", c.name, c.threshold, c.reason));
    }
    s
}

/// The longest stretch of consecutive samples for which a condition held, found as the samples
/// come: its length \[s\] and its start \[s\].
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Stretch {
    since: Option<f64>,
    pub longest_s: f64,
    pub from_s: f64,
}

impl Stretch {
    /// One more sample at time `t`, covering `dt` \[s\], at which the condition holds or not.
    pub fn sample(&mut self, holds: bool, t: f64, dt: f64) {
        if !holds {
            self.since = None;
            return;
        }
        let since = *self.since.get_or_insert(t);
        let len = t - since + dt;
        if len > self.longest_s {
            self.longest_s = len;
            self.from_s = since;
        }
    }

    /// The longest stretch of rows of a recorded column for which `holds` is true.
    pub fn of(t: &[f64], col: &[f64], holds: impl Fn(f64) -> bool) -> Stretch {
        let dt = if t.len() > 1 { t[1] - t[0] } else { 0.0 };
        let mut s = Stretch::default();
        for (&ti, &v) in t.iter().zip(col) {
            s.sample(holds(v), ti, dt);
        }
        s
    }
}

/// What the run tracked that its trace does not show: each motor's longest stretch at its slip
/// limit, each online set's longest stretch overloaded.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Tracked {
    pub slip_limit: [Stretch; crate::ship::hull::N_SHAFTS],
    pub overload: [Stretch; super::plant::N_SETS],
}

/// Turbine speed below which a set at full throttle is falling [pu of the governor set point].
pub const SET_FALLING_PU: f64 = 0.97;
/// How long an online set may stay overloaded before a warning \[s\].
pub const SET_OVERLOADED_FOR_S: f64 = 10.0;

/// Whether a set giving shaft power `p_w` \[W\] at turbine speed `w` \[rad/s\] is overloaded: above
/// its rating, or at full throttle with its speed falling below [`SET_FALLING_PU`].
pub fn set_overloaded(p_w: f64, w: f64, plant: &super::plant::Plant) -> bool {
    let t = &plant.turbine;
    p_w > t.rated_power_w || (w < SET_FALLING_PU * t.rated_speed && t.torque(1.0, w) * w <= p_w * (1.0 + 1e-9))
}

/// A finding of each shaft (empty: none), once for both when they are the same.
fn push_per_shaft(out: &mut Vec<String>, found: &[String], names: [&str; 2], both: &str) {
    if found.len() == 2 && !found[0].is_empty() && found[0] == found[1] {
        out.push(format!("{both} {}", found[0]));
        return;
    }
    for (f, name) in found.iter().zip(names) {
        if !f.is_empty() {
            out.push(format!("{name} {f}"));
        }
    }
}

/// The warnings of a finished run (none when every check passes).
pub fn assess(sc: &Scenario, trace: &Trace, tracked: &Tracked) -> Vec<String> {
    let mut out = Vec::new();
    let t = trace.get(Signal::TS);
    if t.len() < 2 {
        return out;
    }
    let dt = t[1] - t[0];
    let lowest = |col: &[f64]| col.iter().copied().fold(f64::INFINITY, f64::min);
    let highest = |col: &[f64]| col.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let at = |col: &[f64], v: f64| t[col.iter().position(|&x| x == v).unwrap_or(0)];

    let turbine = trace.get(Signal::TurbineSpeedPu);
    let s = Stretch::of(t, turbine, |v| v < TURBINE_MIN_RUNNING_PU);
    if s.longest_s > TURBINE_MIN_RUNNING_FOR_S {
        out.push(format!(
            "turbines stalled: speed below their minimum running speed of {TURBINE_MIN_RUNNING_PU} pu for {:.1} s \
             from t = {:.1} s (lowest {:.3} pu), longer than the {TURBINE_MIN_RUNNING_FOR_S} s allowed: the load \
             holds them down instead of the governor holding their speed",
            s.longest_s,
            s.from_s,
            lowest(turbine)
        ));
    }
    let top = highest(turbine);
    if top > TURBINE_OVERSPEED_PU {
        let above = turbine.iter().filter(|&&v| v > TURBINE_OVERSPEED_PU).count() as f64 * dt;
        out.push(format!(
            "turbine overspeed: {top:.3} pu at t = {:.1} s ({above:.1} s above {TURBINE_OVERSPEED_PU} pu in all), \
             where an LM2500's overspeed protection trips; the model runs on",
            at(turbine, top)
        ));
    }

    let bus = trace.get(Signal::BusVoltagePu);
    let high = bus_high_pu(sc);
    let s = Stretch::of(t, bus, |v| !(BUS_LOW_PU..=high).contains(&v));
    if s.longest_s > BUS_OUTSIDE_FOR_S {
        out.push(format!(
            "bus voltage outside its band of {BUS_LOW_PU} to {high:.2} pu for {:.1} s from t = {:.1} s (lowest \
             {:.3} pu, highest {:.3} pu over the run), longer than the {BUS_OUTSIDE_FOR_S} s allowed",
            s.longest_s,
            s.from_s,
            lowest(bus),
            highest(bus)
        ));
    }

    let power = trace.get(Signal::ImPowerPu);
    let mut motors = Vec::new();
    for s in &tracked.slip_limit {
        if s.longest_s > MOTOR_AT_LIMIT_FOR_S {
            // Rated power or, below it, the pull-out torque: what the motors gave over the stretch.
            let (n, rated, sum) = t
                .iter()
                .zip(power)
                .filter(|(&ti, _)| ti >= s.from_s && ti < s.from_s + s.longest_s)
                .fold((0usize, 0usize, 0.0), |(n, r, a), (_, &p)| (n + 1, r + usize::from(p >= 0.999), a + p));
            let mean = sum / n.max(1) as f64;
            let what = if 2 * rated >= n {
                "mostly at rated power"
            } else {
                "mostly below rated power: at the peak-torque slip"
            };
            motors.push(format!(
                "at the slip limit ({what}, mean {mean:.2} pu) for {:.1} s from t = {:.1} s, longer than the \
                 {MOTOR_AT_LIMIT_FOR_S} s allowed: the speed loop asks for more than the motor gives",
                s.longest_s, s.from_s
            ));
        } else {
            motors.push(String::new());
        }
    }
    push_per_shaft(&mut out, &motors, ["motor 1", "motor 2"], "both motors");
    // Each bus part's own checks, in their order.
    BusParts::assess(&sc.plant, t, &|sig| trace.get(sig), &mut out);

    let duration = t[t.len() - 1] - t[0] + dt;
    let props: Vec<String> = [Signal::HOverR, Signal::HOverRStbd]
        .into_iter()
        .map(|sig| {
            let col = trace.get(sig);
            let rows = col.iter().filter(|&&v| v < DISK_AT_SURFACE_H_OVER_R).count() as f64 * dt;
            if rows <= PROPELLER_EMERGED_SHARE * duration {
                return String::new();
            }
            let mean = col.iter().sum::<f64>() / col.len() as f64;
            format!(
                "out of the water: the disc breaks the surface (h/R below {DISK_AT_SURFACE_H_OVER_R}) for {:.0} % \
                 of the run (mean h/R {mean:.2}), more than the {:.0} % allowed: the hub is too shallow for this \
                 sea and loading",
                100.0 * rows / duration,
                PROPELLER_EMERGED_SHARE * 100.0
            )
        })
        .collect();
    push_per_shaft(&mut out, &props, ["port propeller", "starboard propeller"], "both propellers");

    for (k, s) in tracked.overload.iter().enumerate() {
        if s.longest_s > SET_OVERLOADED_FOR_S {
            out.push(format!(
                "set {} overloaded for {:.1} s from t = {:.1} s (above its rating of {:.1} MW, or at full throttle \
                 with its speed falling below {SET_FALLING_PU} pu), longer than the {SET_OVERLOADED_FOR_S} s \
                 allowed: too few sets are online for this speed and sea; start another",
                k + 1,
                s.longest_s,
                s.from_s,
                sc.plant.turbine.rated_power_w / 1e6
            ));
        }
    }

    if let Some(w) = speed_not_held(t, trace, &motors) {
        out.push(w);
    }

    out.extend(astern_braking(sc, trace));

    let limit = sc.controllers.speed.max_shaft_rpm;
    for (k, sig) in [Signal::PropRpm1, Signal::PropRpm2].into_iter().enumerate() {
        let col = trace.get(sig);
        let top = col.iter().copied().fold(0.0, |a: f64, v| a.max(v.abs()));
        if top > limit {
            let when = t[col.iter().position(|&v| v.abs() == top).unwrap_or(0)];
            out.push(format!(
                "shaft overspeed: propeller shaft {} at {top:.0} rpm at t = {when:.1} s, above the speed \
                 controller's largest shaft speed of {limit} rpm",
                k + 1
            ));
        }
    }
    out
}

/// A run with an astern order whose bus rose over its band or whose turbines oversped after the
/// order, while the motors returned power: says so in words, with the power they returned (the
/// crash stop's energy had nowhere to go fast enough).
fn astern_braking(sc: &Scenario, trace: &Trace) -> Option<String> {
    let t_order = sc.commands.iter().find(|c| c.astern())?.t_s;
    let t = trace.get(Signal::TS);
    let from = t.partition_point(|&x| x < t_order);
    let (bus, turbine, p_inv) =
        (trace.get(Signal::BusVoltagePu), trace.get(Signal::TurbineSpeedPu), trace.get(Signal::PInverterW));
    let high = bus_high_pu(sc);
    let braking = |i: &usize| p_inv[*i] < 0.0;
    let bus_top = (from..t.len()).filter(braking).map(|i| bus[i]).fold(f64::NEG_INFINITY, f64::max);
    let turbine_top = (from..t.len()).filter(braking).map(|i| turbine[i]).fold(f64::NEG_INFINITY, f64::max);
    let mut what = Vec::new();
    if bus_top > high {
        what.push(format!("the bus rose to {bus_top:.3} pu, over its band's top of {high:.2} pu"));
    }
    if turbine_top > TURBINE_OVERSPEED_PU {
        what.push(format!("the turbines oversped to {turbine_top:.3} pu (trip near {TURBINE_OVERSPEED_PU} pu)"));
    }
    if what.is_empty() {
        return None;
    }
    let regen = (from..t.len()).map(|i| -p_inv[i]).fold(0.0, f64::max);
    Some(format!(
        "during the astern order from t = {t_order:.1} s the motors braked the shafts and returned up to {:.1} MW to \
         the buses: {}; the brake resistors and storage did not take it fast enough (plant.dc_link.brake_resistor_ohm, \
         plant.storage)",
        regen / 1e6,
        what.join(" and ")
    ))
}

/// The "speed order not held" finding, with its likely cause in words (`motors`: the slip-limit
/// findings per motor).
fn speed_not_held(t: &[f64], trace: &Trace, motors: &[String]) -> Option<String> {
    let end = t[t.len() - 1];
    if end - t[0] < 2.0 * SPEED_HELD_OVER_S {
        return None;
    }
    let (cmd, speed) = (trace.get(Signal::SpeedCmdKn), trace.get(Signal::ShipSpeedKn));
    let from = t.partition_point(|&x| x < end - SPEED_HELD_OVER_S);
    let order = cmd[cmd.len() - 1];
    if cmd[from..].iter().any(|&c| c != order) {
        return None;
    }
    let mean = |col: &[f64]| col[from..].iter().sum::<f64>() / (col.len() - from) as f64;
    // The trace's speed is the speed through the water, unsigned: under an astern order the
    // ship is taken to be going astern.
    let got = if order < 0.0 { -mean(speed) } else { mean(speed) };
    let band = SPEED_HELD_KN.max(SPEED_HELD_SHARE * order.abs());
    if (got - order).abs() <= band {
        return None;
    }
    let why = if got > order && mean(trace.get(Signal::PropRpmRef)) < 1.0 {
        format!(
            "the waves carry the ship: their mean push of {:.0} kN is more than the hull's resistance at the order, \
             and the speed loop stops the propellers but never reverses them",
            -mean(trace.get(Signal::AddedResistanceN)) / 1e3
        )
    } else if got < order && motors.iter().any(|m| !m.is_empty()) {
        "the order is beyond the plant's power (the motors at their limit)".to_string()
    } else {
        format!(
            "the speed loop's trim is at its limit (shaft reference {:.0} rpm)",
            mean(trace.get(Signal::PropRpmRef))
        )
    };
    Some(format!(
        "speed order not held: {got:.1} kn over the last {SPEED_HELD_OVER_S:.0} s against {order:.1} kn ordered \
         (allowed {band:.1} kn either way): {why}"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stretch is measured from its first row to the row after its last: 3 rows of 0.5 s.
    #[test]
    fn the_longest_stretch_counts_its_rows() {
        let t = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0];
        let x = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
        let s = Stretch::of(&t, &x, |v| v < 0.5);
        assert_eq!((s.longest_s, s.from_s), (1.5, 2.0));
        assert_eq!(Stretch::of(&t, &x, |v| v > 5.0).longest_s, 0.0);
    }

    /// Every check is in the book's table with its threshold and reason.
    #[test]
    fn every_check_has_a_threshold_and_a_reason() {
        let md = markdown();
        for c in checks() {
            assert!(!c.threshold.is_empty() && c.reason.len() > 40, "{}", c.name);
            assert!(md.contains(c.name));
        }
    }
}
