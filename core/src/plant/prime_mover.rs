//! LM2500 gas turbine (thesis ch. 2.1, eq. 2.1) and its discrete PI speed governor with
//! throttle saturation and slew limit.

use crate::checks::Validator;
use crate::control::DiscretePi;
use crate::numerics::units::rpm_to_rad_s;
use serde::{Deserialize, Serialize};

/// Turbine constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GasTurbine {
    /// Full-throttle locking torque Q_lock [N m].
    pub locking_torque_nm: f64,
    /// Full-throttle no-load speed [rad/s].
    pub no_load_speed: f64,
    /// Governor set point [rad/s].
    pub rated_speed: f64,
    /// Inertia of turbine and generator rotor [kg m^2].
    pub inertia: f64,
    /// Rated power \[W\].
    pub rated_power_w: f64,
}

impl GasTurbine {
    pub fn new(p: &TurbineParams) -> GasTurbine {
        GasTurbine {
            locking_torque_nm: p.locking_torque_nm,
            no_load_speed: rpm_to_rad_s(p.no_load_speed_rpm),
            rated_speed: rpm_to_rad_s(p.rated_speed_rpm),
            inertia: p.inertia_kg_m2,
            rated_power_w: p.rated_power_w,
        }
    }

    /// Eq. 2.1: Q_t = Q_lock (f/f_max) (1 - n_t/n_t,max) [N m]. Past the no-load speed the
    /// linear model gives a braking torque, as the compressor then absorbs work.
    pub fn torque(&self, throttle: f64, omega: f64) -> f64 {
        self.locking_torque_nm * throttle * (1.0 - omega / self.no_load_speed)
    }

    /// Throttle that makes `torque_nm` at speed `omega` (inverse of eq. 2.1).
    pub fn throttle_for(&self, torque_nm: f64, omega: f64) -> f64 {
        torque_nm / (self.locking_torque_nm * (1.0 - omega / self.no_load_speed))
    }
}

/// Discrete PI governor: per-unit speed error to throttle fraction, with anti-windup by
/// conditional integration, saturation 0 <= f <= 1 and slew limit |df/dt| <= Delta_t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Governor {
    /// PI on the per-unit speed error; its integrator carries the steady throttle.
    pub pi: DiscretePi,
    /// Largest throttle change per second [1/s].
    pub slew: f64,
    /// Throttle now applied [fraction of full fuel].
    pub throttle: f64,
}

impl Governor {
    pub fn new(p: &GovernorParams, throttle0: f64) -> Governor {
        Governor { pi: DiscretePi::new(p.kp, p.ki, throttle0), slew: p.slew_rate_per_s, throttle: throttle0 }
    }

    /// One controller sample of period `ts` \[s\] with speed error `err_pu` (set point minus speed,
    /// per unit of the set point). Returns the throttle to hold until the next sample.
    pub fn update(&mut self, err_pu: f64, ts: f64) -> f64 {
        let cmd = self.pi.update(err_pu, 0.0, 1.0, ts);
        let step = self.slew * ts;
        self.throttle += (cmd - self.throttle).clamp(-step, step);
        self.throttle
    }
}

crate::params! {
    /// GE LM2500 gas turbine, linear torque model (eq. 2.1, Table 5.2).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct TurbineParams {
        pub locking_torque_nm: f64 = 123.0e3 => {
            label: "Locking torque Q_lock", unit: "N m", range: 1.0e3..=1.0e7, source: "Table 5.2",
            help: "Full-throttle torque at stall (eq. 2.1).",
        },
        pub no_load_speed_rpm: f64 = 6875.0 => {
            label: "No-load speed n_t,max", unit: "rpm", range: 100.0..=1.0e5, source: "Table 5.2",
            help: "Full-throttle speed at which the turbine gives no torque (eq. 2.1).",
        },
        pub rated_speed_rpm: f64 = 3600.0 => {
            label: "Governor set point n_t*", unit: "rpm", range: 100.0..=1.0e5,
            source: "ch. 2.1: 60 Hz from the two-pole generator",
            help: "Turbine speed the governor holds; the base of turbine speed in per unit.",
        },
        pub inertia_kg_m2: f64 = 400.0 => {
            label: "Turbine inertia I_t", unit: "kg m²", range: 1.0..=1.0e6, source: "Table 5.2", group: "plant",
            help: "Turbine and generator rotor together.",
        },
        pub rated_power_w: f64 = 21.5e6 => {
            label: "Turbine rating", unit: "W", range: 1.0e4..=1.0e9, source: "ch. 2.1 (LM2500)",
            help: "Rated shaft power; the base of turbine power in per unit.",
        },
    }
}

crate::params! {
    /// Discrete PI governor on turbine speed acting on the throttle (ch. 2.1).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct GovernorParams {
        /// Not given in the thesis; 10, which with K_i,t gives a critically damped loop near 2
        /// rad/s (throttle moves the per-unit speed at 0.39 /s per unit throttle at 3600 rpm).
        pub kp: f64 = 10.0 => {
            label: "Governor K_p,t", unit: "1/pu", range: 0.0..=1.0e3, group: "controllers",
            source: "our choice: a critically damped loop near 2 rad/s (not given in the thesis)",
            help: "Throttle per per-unit turbine speed error.",
        },
        pub ki: f64 = 10.0 => {
            label: "Governor K_i,t", unit: "1/(pu s)", range: 0.0..=1.0e3,
            source: "our choice, with K_p,t (not given in the thesis)",
            help: "Throttle per per-unit speed error and second.",
        },
        /// 0.1: zero to full fuel in 10 s, a conservative fuel schedule against compressor surge.
        pub slew_rate_per_s: f64 = 0.1 => {
            label: "Throttle slew limit", unit: "1/s", range: 1.0e-3..=100.0, group: "controllers",
            source: "our choice: zero to full fuel in 10 s, against compressor surge",
            help: "Fastest the throttle may move (fuel schedule limit).",
        },
    }
}

impl crate::params::CrossCheck for TurbineParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.rated_speed_rpm >= self.no_load_speed_rpm {
            v.fail(
                "rated_speed_rpm",
                self.rated_speed_rpm,
                format!("must be below {} (eq. 2.1 gives no torque there)", v.path("no_load_speed_rpm")),
            );
        }
    }
}

impl crate::params::CrossCheck for GovernorParams {}

#[cfg(test)]
mod tests {
    use super::*;

    /// Full throttle at 3600 rpm gives 22.1 MW, next to the 21.5 MW rating of ch. 2.1 (3 %).
    #[test]
    fn rated_power_from_eq_2_1() {
        let t = GasTurbine::new(&TurbineParams::default());
        let p = t.torque(1.0, t.rated_speed) * t.rated_speed;
        assert!((p - 21.5e6).abs() / 21.5e6 < 0.03, "P = {p}");
        assert_eq!(t.torque(1.0, t.no_load_speed), 0.0);
        assert!((t.torque(1.0, 0.0) - 123.0e3).abs() < 1e-9);
        let f = t.throttle_for(40.0e3, t.rated_speed);
        assert!((t.torque(f, t.rated_speed) - 40.0e3).abs() < 1e-6);
    }

    #[test]
    fn governor_slews_and_saturates() {
        let mut g = Governor::new(&GovernorParams::default(), 0.1);
        // Large speed loss: command saturates at 1 but the throttle climbs at 0.1 /s.
        let mut f = 0.0;
        for _ in 0..200 {
            f = g.update(0.5, 0.005);
        }
        assert!((f - 0.2).abs() < 1e-9, "after 1 s at 0.1/s from 0.1: {f}");
        for _ in 0..4000 {
            f = g.update(0.5, 0.005);
        }
        assert_eq!(f, 1.0);
        // Anti-windup: the integrator did not run away past the saturation.
        assert!(g.pi.integral <= 1.0 + 10.0 * 0.5 * 0.005 + 1e-12);
    }
}
