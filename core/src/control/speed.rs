//! The ship-speed loop (ours; the thesis orders shaft speed directly): a calm-water map from
//! ordered ship speed to shaft speed, trimmed by a PI on the speed error, then a ramp limit.

use crate::control::DiscretePi;
use crate::numerics::units::{kn_to_m_s, rpm_to_rad_s};
use serde::{Deserialize, Serialize};
crate::params! {
    /// Outer ship-speed loop: a calm-water rpm map trimmed by a PI on ship speed error. Ours: the
    /// thesis orders shaft speed directly.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SpeedControlParams {
        /// The calm-water map has about 8 rpm per knot, so the loop gain is 0.5 and the 30 s surge
        /// lag closes near 20 s.
        pub kp_rpm_per_kn: f64 = 4.0 => {
            label: "Speed trim K_p", unit: "rpm/kn", range: 0.0..=100.0,
            source: "our design: loop gain 0.5 on the calm-water map's 8 rpm per knot",
            help: "Shaft speed added per knot of ship speed error.",
        },
        /// A 40 s integral time: it removes the steady error that waves, turns or fouling leave on
        /// the calm-water map.
        pub ki_rpm_per_kn_s: f64 = 0.2 => {
            label: "Speed trim K_i", unit: "rpm/(kn s)", range: 0.0..=100.0,
            source: "our design: a 40 s integral time",
            help: "Removes the steady speed error that waves, turns or fouling leave.",
        },
        /// A tight turn at 25 knots needs about a quarter more shaft speed than the straight-line
        /// map.
        pub trim_limit: f64 = 0.4 => {
            label: "Largest speed trim", unit: "-", range: 0.0..=1.0,
            source: "our design: a tight turn at 25 kn needs about +25 %",
            help: "Largest trim as a fraction of the mapped shaft speed.",
        },
        /// At low speed a share of the map is too little for a seaway: chosen when the mean added
        /// resistance into sea state 6 at 4 kn was eq. 2.48's (about 0.3 MN), which needed about 80
        /// rpm against the map's 32; with the waterline's reflection it is about 60 kN, and the
        /// span still lets a stopped ship drive ahead against the waves' push astern (25-50 rpm in
        /// SS6 beam seas, tests/own_hull.rs).
        pub trim_floor_rpm: f64 = 80.0 => {
            label: "Smallest speed trim span", unit: "rpm", range: 0.0..=1000.0,
            source: "our design: holds 4 kn into sea state 6 head seas",
            help: "The trim may always reach this many rpm, whatever the share of the map allows.",
        },
        /// 5 rpm/s keeps the turbines' load rise within their slew limit.
        pub shaft_ramp_rpm_per_s: f64 = 5.0 => {
            label: "Shaft ramp", unit: "rpm/s", range: 0.0..=1.0e4, group: "controllers",
            source: "our design: keeps the turbines' load rise within their slew limit",
            help: "Rate limit of the shaft speed reference; 0 for a step.",
        },
        /// The motor is rated near 300 rpm and ch. 5.2.1 shows it overrunning that at full ahead;
        /// astern the same limit holds.
        pub max_shaft_rpm: f64 = 320.0 => {
            label: "Largest shaft speed", unit: "rpm", range: 1.0..=2000.0,
            source: "our design: the 300 rpm motor overruns at full ahead (ch. 5.2.1)",
            help: "Upper limit of the shaft speed reference.",
        },
    }
}

impl crate::params::CrossCheck for SpeedControlParams {}

/// Speed step of the calm-water map [m/s].
pub const MAP_STEP_M_S: f64 = 0.25;
/// Highest ship speed of the calm-water map \[knots\] (the command range's top).
pub const MAP_TOP_KN: f64 = 40.0;

/// The ship-speed loop's state: calm-water map, PI trim and ramp-limited shaft reference.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedController {
    /// PI trim in SI: [rad/s of shaft per m/s], [rad/s per m]; its integrator is the trim [rad/s].
    pub pi: DiscretePi,
    /// Largest trim as a fraction of the mapped shaft speed [-], and at least `trim_floor`
    /// [rad/s].
    pub trim_limit: f64,
    pub trim_floor: f64,
    /// Ramp limit of the shaft speed reference [rad/s^2]; 0 for none.
    pub ramp: f64,
    pub max_shaft_speed: f64,
    /// Shaft speed reference now [rad/s].
    pub shaft_ref: f64,
    /// Calm-water map: equilibrium shaft speed [rad/s] at ship speeds 0, MAP_STEP_M_S, ...
    map: Vec<f64>,
    /// The last ordered speed's bits and its mapped shaft speed (the order holds for many
    /// samples).
    last_map: Option<(u64, f64)>,
    /// Astern map: equilibrium shaft speed [rad/s] (negative) at ship speeds 0, -MAP_STEP_M_S, ...
    /// down to the astern limit; empty unless the run orders astern (then the reference may go
    /// below zero).
    astern_map: Vec<f64>,
    /// Full astern at once (a crash stop order): the reference steps to zero, then ramps astern,
    /// until the next speed order.
    pub full_astern: bool,
}

impl SpeedController {
    /// The loop for parameters `p` with the calm-water map made by `equilibrium(u)`: the shaft
    /// speed [rad/s] at which the propellers carry the hull's straight-line resistance at ship
    /// speed u [m/s], every 0.25 m/s up to 40 knots.
    pub fn new(p: &SpeedControlParams, equilibrium: impl Fn(f64) -> f64) -> SpeedController {
        let rpm_per_kn = rpm_to_rad_s(1.0) / kn_to_m_s(1.0);
        let n_map = (kn_to_m_s(MAP_TOP_KN) / MAP_STEP_M_S).ceil() as usize + 1;
        SpeedController {
            pi: DiscretePi::new(p.kp_rpm_per_kn * rpm_per_kn, p.ki_rpm_per_kn_s * rpm_per_kn, 0.0),
            trim_limit: p.trim_limit,
            trim_floor: rpm_to_rad_s(p.trim_floor_rpm),
            ramp: rpm_to_rad_s(p.shaft_ramp_rpm_per_s),
            max_shaft_speed: rpm_to_rad_s(p.max_shaft_rpm),
            shaft_ref: 0.0,
            map: (0..n_map).map(|i| equilibrium(i as f64 * MAP_STEP_M_S)).collect(),
            last_map: None,
            astern_map: Vec::new(),
            full_astern: false,
        }
    }

    /// Lets the reference go astern: the astern map made by `equilibrium(u)` (the shaft speed
    /// [rad/s], negative, at which the propellers carry the hull's resistance at ship speed u < 0
    /// [m/s]), every 0.25 m/s down to `limit_kn` \[kn\] (negative).
    pub fn with_astern(mut self, limit_kn: f64, equilibrium: impl Fn(f64) -> f64) -> SpeedController {
        let n_map = (kn_to_m_s(-limit_kn) / MAP_STEP_M_S).ceil() as usize + 1;
        self.astern_map = (0..n_map).map(|i| equilibrium(-(i as f64) * MAP_STEP_M_S)).collect();
        self.last_map = None;
        self
    }

    /// Whether the reference may go astern (the run orders astern).
    pub fn astern(&self) -> bool {
        !self.astern_map.is_empty()
    }

    /// The calm-water map at ship speed `u` [m/s] (linear interpolation, held at the ends; below
    /// zero the astern map when the run has one).
    pub fn map_speed(&self, u: f64) -> f64 {
        if u < 0.0 && !self.astern_map.is_empty() {
            return crate::numerics::interp::uniform(&self.astern_map, MAP_STEP_M_S, -u);
        }
        crate::numerics::interp::uniform(&self.map, MAP_STEP_M_S, u)
    }

    /// Starts in the steady state: shaft at `w_rm0` [rad/s] at ship speed `u0` [m/s].
    pub fn start(&mut self, w_rm0: f64, u0: f64) {
        self.shaft_ref = w_rm0;
        self.pi.integral = w_rm0 - self.map_speed(u0);
    }

    /// One sample with ordered speed `u_cmd` and speed through the water `u` [m/s]; returns the
    /// shaft speed reference [rad/s].
    pub fn update(&mut self, u_cmd: f64, u: f64, ts: f64) -> f64 {
        let map = match self.last_map {
            Some((bits, m)) if bits == u_cmd.to_bits() => m,
            _ => {
                let m = self.map_speed(u_cmd);
                self.last_map = Some((u_cmd.to_bits(), m));
                m
            }
        };
        let err_u = u_cmd - u;
        // Astern the map is negative: the trim's span is a share of its size.
        let trim_max = (self.trim_limit * map.abs()).max(self.trim_floor);
        let unsat = self.pi.unsaturated(err_u);
        let trim = unsat.clamp(-trim_max, trim_max);
        let lowest = if self.astern_map.is_empty() { 0.0 } else { -self.max_shaft_speed };
        let target = (map + trim).clamp(lowest, self.max_shaft_speed);
        // Full astern at once: the reference drops to zero in one sample (braking the shafts
        // loads no turbine: the motors return power), then ramps astern like any order (the ramp
        // keeps the turbines' load rise within their slew limit; without it the bus fell to 0.46
        // pu as both motors took rated power astern the moment the shafts passed zero).
        let from = if self.full_astern { self.shaft_ref.min(0.0) } else { self.shaft_ref };
        let next_ref =
            if self.ramp > 0.0 { from + (target - from).clamp(-self.ramp * ts, self.ramp * ts) } else { target };
        // Anti-windup: the trim integrates only while neither it nor the ramp is limiting, so a
        // long acceleration does not leave it wound up (which would overshoot the ordered speed).
        let limited = unsat.abs() > trim_max || (next_ref - target).abs() > 1e-12;
        if !limited {
            self.pi.integral = (self.pi.integral + self.pi.ki * err_u * ts).clamp(-trim_max, trim_max);
        }
        self.shaft_ref = next_ref;
        next_ref
    }
}
