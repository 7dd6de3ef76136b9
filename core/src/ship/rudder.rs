//! Rudder (thesis ch. 2.4.1, eqs. 2.26-2.30) and the saturated PID heading autopilot.
//!
//! Sign conventions (SNAME, z down): y to starboard, positive r turns to starboard. The rudder
//! stands x_p aft of the centre of gravity, where the lateral flow is v - x_p r. Eqs. 2.26-2.27
//! print v + x_p r, which holds with x_p signed (negative aft); eq. 2.19's moment -x_p F_y takes x_p
//! positive aft, which is our convention. A positive rudder angle delta turns the ship to port.

use crate::control::DiscretePi;
use serde::{Deserialize, Serialize};

crate::params! {
    /// Rudder size and limits (Table 5.5). Its place, x_p, is the hull's (`ship.hull.rudder_x_m`).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct RudderParams {
        pub area_m2: f64 = 20.0 => {
            label: "Rudder area A_r", unit: "m²", range: 0.0..=500.0, source: "Table 5.5",
            help: "Area of each rudder (eqs. 2.28-2.30).",
        },
        pub lift_slope: f64 = 3.31 => {
            label: "Rudder lift slope", unit: "1/rad", range: 0.0..=10.0, source: "Table 5.5 (No. 1 rudder of [42])",
            help: "dC_L/dalpha of the rudder.",
        },
        pub drag_slope: f64 = 0.46 => {
            label: "Rudder drag slope", unit: "1/rad", range: 0.0..=5.0, source: "Table 5.5",
            help: "dC_D/dalpha of the rudder.",
        },
        pub max_angle_deg: f64 = 20.0 => {
            label: "Largest rudder angle", unit: "deg", range: 1.0..=45.0, source: "ch. 2.4.1",
            help: "The rudder saturates here, before it stalls.",
        },
        pub swing_rate_rad_s: f64 = 0.1 => {
            label: "Rudder swing rate", unit: "rad/s", range: 0.001..=1.0, source: "Table 5.5",
            help: "Fastest the steering gear moves the rudder.",
        },
    }
}

/// Inflow at the stern (eqs. 2.26-2.27): speed V_a [m/s], angle alpha_a \[rad\] and the angle's
/// sine and cosine (from the velocity components: no trigonometric call in the time loop).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inflow {
    pub speed: f64,
    pub angle: f64,
    pub sin: f64,
    pub cos: f64,
}

/// The stern's inflow for surge `u`, sway `v` [m/s] and yaw rate `r` [rad/s], `x_p` \[m\] aft.
pub fn stern_inflow(u: f64, v: f64, r: f64, x_p: f64) -> Inflow {
    let vs = v - x_p * r;
    let ux = u.abs().max(1e-6);
    let hyp = (ux * ux + vs * vs).sqrt();
    Inflow { speed: (u * u + vs * vs).sqrt(), angle: libm::atan2(vs, ux), sin: vs / hyp, cos: ux / hyp }
}

/// Rudder forces in the body frame \[N\] (eqs. 2.28, 2.30) with the stern's inflow `a` and rudder
/// angle `delta` \[rad\]. Lift is signed by (alpha - delta), drag always opposes the inflow.
pub fn rudder_force(p: &RudderParams, rho: f64, a: &Inflow, delta: f64) -> (f64, f64) {
    let q = 0.5 * rho * p.area_m2 * a.speed * a.speed;
    let aoa = a.angle - delta;
    let lift = q * p.lift_slope * aoa;
    let drag = q * p.drag_slope * aoa.abs();
    let (s, c) = (a.sin, a.cos);
    (lift * s - drag * c, -lift * c - drag * s)
}

crate::params! {
    /// Saturated PID heading autopilot gains.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct AutopilotParams {
        pub kp: f64 = 3.0 => {
            label: "Autopilot K_p", unit: "rad/rad", range: 0.0..=1.0e3, source: "our choice (not given in the thesis)",
            help: "Rudder per heading error.",
        },
        pub ki: f64 = 0.02 => {
            label: "Autopilot K_i", unit: "1/s", range: 0.0..=1.0e3, source: "our choice (not given in the thesis)",
            help: "Rudder per heading error and second.",
        },
        pub kd: f64 = 80.0 => {
            label: "Autopilot K_d", unit: "s", range: 0.0..=1.0e4, source: "our choice (not given in the thesis)",
            help: "Rudder per yaw rate error.",
        },
        /// About 8 ship lengths of radius at 25 knots. A step would put the rudder hard over and,
        /// since the Table 2.3 hull turns unstable in tight turns, spiral the ship into a turn
        /// tighter than full counter-rudder can stop.
        pub turn_rate_deg_s: f64 = 0.5 => {
            label: "Default turn rate", unit: "deg/s", range: 0.01..=10.0, group: "controllers",
            source: "our choice: about 8 ship lengths of radius at 25 kn",
            help: "How fast the heading order moves when an order gives no rate.",
        },
        /// With the Table 2.3 coefficients the hull's turning motion grows unstable above r' = 0.1
        /// (0.2 /s at r' = 0.2, 0.4 /s at r' = 0.33; its spiral curve loops at 3.6 deg of rudder,
        /// `maneuvering::steady_turn`). On the hull's ship (L = 142 m) the default gains still hold
        /// ramps up to r' = 0.6 (measured: radius 1.56 L, the rudder touching 20 deg on the way in)
        /// and diverge at 0.7; on Tables 5.1/5.5's ship (L = 180 m) the ramp at r' = 1/3 diverges
        /// 31 s after the order. Faster orders are slowed to this limit and a warning says so.
        pub max_turn_rate_nondim: f64 = 0.25 => {
            label: "Fastest turn r'", unit: "-", range: 0.01..=2.0,
            source: "our choice: 1 deg/s at 25 kn, within what the Table 2.3 hull holds",
            help: "Fastest turn the autopilot orders, as r' = r L / U; faster orders are slowed.",
        },
        /// Starts taking the rudder off while the turn is still gathering pace, which this
        /// directionally marginal hull needs (its rudder swings at only 0.1 rad/s).
        pub ka: f64 = 1000.0 => {
            label: "Autopilot yaw acceleration gain", unit: "s²", range: 0.0..=1.0e5,
            source: "our choice: eases the rudder off early on this marginal hull",
            help: "Rudder per yaw acceleration error.",
        },
    }
}

/// Discrete PID on heading with rudder saturation, swing-rate limit and anti-windup.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Autopilot {
    /// PI on the heading error taken as psi - psi_ref (positive rudder turns to port), so its
    /// integrator holds minus the rudder's integral action \[rad\].
    pub pi: DiscretePi,
    pub kd: f64,
    pub max_angle: f64,
    pub swing_rate: f64,
    pub ka: f64,
    /// Rudder angle now \[rad\].
    pub delta: f64,
    /// Yaw rate at the previous sample [rad/s] (for the yaw acceleration).
    last_rate_err: Option<f64>,
}

impl Autopilot {
    pub fn new(g: &AutopilotParams, r: &RudderParams) -> Autopilot {
        Autopilot {
            pi: DiscretePi::new(g.kp, g.ki, 0.0),
            kd: g.kd,
            ka: g.ka,
            last_rate_err: None,
            max_angle: r.max_angle_deg.to_radians(),
            swing_rate: r.swing_rate_rad_s,
            delta: 0.0,
        }
    }

    /// One sample: heading error `err` = psi_ref - psi \[rad\], yaw rate error `rate_err` =
    /// r_ref - r [rad/s]. Returns the rudder angle \[rad\] to hold. Positive rudder turns to port,
    /// hence the minus sign.
    pub fn update(&mut self, err: f64, rate_err: f64, ts: f64) -> f64 {
        let accel_err = self.last_rate_err.map_or(0.0, |last| (rate_err - last) / ts);
        self.last_rate_err = Some(rate_err);
        // -(kp e + I + kd e' + ka e''), written with the negated error (IEEE negation is exact).
        let e = -err;
        let unsat = self.pi.unsaturated(e) - self.kd * rate_err - self.ka * accel_err;
        let cmd = self.pi.saturate(unsat, e, -self.max_angle, self.max_angle, ts);
        let step = self.swing_rate * ts;
        self.delta += (cmd - self.delta).clamp(-step, step);
        self.delta
    }
}

impl crate::params::CrossCheck for RudderParams {}
impl crate::params::CrossCheck for AutopilotParams {}

#[cfg(test)]
mod tests {
    use super::*;

    /// Straight inflow, rudder over: the lateral force is q C_L delta (small angle), towards the
    /// side that makes the stern go to starboard and the bow to port for positive delta.
    #[test]
    fn lift_and_drag() {
        let p = RudderParams::default();
        let d = 5f64.to_radians();
        let straight = stern_inflow(10.0, 0.0, 0.0, 75.0);
        let (fx, fy) = rudder_force(&p, 1025.0, &straight, d);
        let q = 0.5 * 1025.0 * 20.0 * 100.0;
        assert!((fy - q * 3.31 * d).abs() < 1e-6 * fy);
        assert!((fx + q * 0.46 * d).abs() < 1e-6 * fx.abs());
        // Moment -x_p F_y < 0: bow to port.
        assert!(-75.0 * fy < 0.0);
        // Rudder aligned with the inflow: no force.
        let a = stern_inflow(10.0, -10.0 * libm::tan(0.1), 0.0, 75.0);
        assert!((a.sin - libm::sin(a.angle)).abs() < 1e-15 && (a.cos - libm::cos(a.angle)).abs() < 1e-15);
        let (fx, fy) = rudder_force(&p, 1025.0, &a, a.angle);
        assert!(fx.abs() < 1e-9 && fy.abs() < 1e-9);
    }

    #[test]
    fn autopilot_saturates_and_slews() {
        let mut a = Autopilot::new(&AutopilotParams::default(), &RudderParams::default());
        // Large heading error to starboard: rudder goes negative at 0.1 rad/s, stops at 20 deg.
        let d = a.update(1.0, 0.0, 1.0);
        assert!((d + 0.1).abs() < 1e-12);
        for _ in 0..10 {
            a.update(1.0, 0.0, 1.0);
        }
        assert!((a.delta + 20f64.to_radians()).abs() < 1e-12);
        let a = stern_inflow(10.0, 0.0, 0.01, 75.0);
        assert!((a.speed - (100.0f64 + 0.5625).sqrt()).abs() < 1e-12 && a.angle < 0.0);
    }
}
