//! The consequences an event is measured by, over its window after the event.

use super::*;

/// A consequence of the event: its name (with its unit), label, and whether larger is worse.
pub struct Consequence {
    pub name: &'static str,
    pub label: &'static str,
    pub larger_is_worse: bool,
}

/// The motor power before an event is its mean over this long \[s\].
pub const PRE_EVENT_S: f64 = 5.0;

/// The consequences measured from the event to `window_s` after it.
pub const CONSEQUENCES: [Consequence; 5] = [
    Consequence {
        name: "min_bus_voltage_pu",
        label: "lowest bus voltage (mean of the two buses)",
        larger_is_worse: false,
    },
    Consequence {
        name: "peak_turbine_speed_pu",
        label: "highest gas turbine speed (mean of the four)",
        larger_is_worse: true,
    },
    Consequence {
        name: "shaft_speed_swing_rpm",
        label: "the event's shaft: highest minus lowest speed",
        larger_is_worse: true,
    },
    Consequence {
        name: "motor_power_drop_mw",
        label: "motor power (both motors): its mean over the 5 s before the event minus its lowest after",
        larger_is_worse: true,
    },
    Consequence { name: "brake_energy_mj", label: "energy burnt in the brake resistors", larger_is_worse: true },
];

/// The consequences in `trace` of an event of shaft `shaft` at time `t` \[s\], over `\[t, t + window\]`,
/// and h/R there: the one measure of a conditioned trial and of an event counted in a long run.
pub fn consequences_at(r: &RunResult, shaft: usize, t: f64, window: f64) -> Option<([f64; 5], f64)> {
    let tr = &r.trace;
    let ts = tr.get(Signal::TS);
    let i0 = ts.partition_point(|&x| x < t - 1e-9);
    let i1 = ts.partition_point(|&x| x <= t + window + 1e-9);
    if i0 >= ts.len() || i1 <= i0 + 1 || ts[i1 - 1] < t + window - 1e-6 {
        return None;
    }
    let col = |s: Signal| &tr.get(s)[i0..i1];
    let min = |x: &[f64]| x.iter().copied().fold(f64::INFINITY, f64::min);
    let max = |x: &[f64]| x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let rpm = col([Signal::PropRpm1, Signal::PropRpm2][shaft]);
    let pm = col(Signal::PMotorW);
    // The power before the event: its mean over the 5 s before, not its value at one row (it
    // swings at the encounter frequency, and a row 0.1 s later moved the rate of drops past
    // 9.5 MW by 40 %).
    let before = &tr.get(Signal::PMotorW)[ts.partition_point(|&x| x < t - PRE_EVENT_S - 1e-9)..=i0];
    let p_before = before.iter().sum::<f64>() / before.len() as f64;
    let dt = if ts.len() > 1 { ts[1] - ts[0] } else { 0.0 };
    let brake: f64 = col(Signal::BrakePowerW).iter().sum::<f64>() * dt;
    let h_r = tr.get([Signal::HOverR, Signal::HOverRStbd][shaft])[i0];
    Some((
        [
            min(col(Signal::BusVoltagePu)),
            max(col(Signal::TurbineSpeedPu)),
            max(rpm) - min(rpm),
            (p_before - min(pm)) / 1e6,
            brake / 1e6,
        ],
        h_r,
    ))
}
