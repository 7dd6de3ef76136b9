//! LM2500 gas turbine (thesis ch. 2.1, eq. 2.1) and its discrete PI speed governor with
//! throttle saturation and slew limit.

use crate::check_range;
use crate::control::DiscretePi;
use crate::units::rpm_to_rad_s;
use crate::validate::Validator;
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
    /// Rated power [W].
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

    /// One controller sample of period `ts` [s] with speed error `err_pu` (set point minus speed,
    /// per unit of the set point). Returns the throttle to hold until the next sample.
    pub fn update(&mut self, err_pu: f64, ts: f64) -> f64 {
        let cmd = self.pi.update(err_pu, 0.0, 1.0, ts);
        let step = self.slew * ts;
        self.throttle += (cmd - self.throttle).clamp(-step, step);
        self.throttle
    }
}

/// GE LM2500 gas turbine, linear torque model (eq. 2.1, Table 5.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TurbineParams {
    /// Full-throttle locking torque Q_lock [N m]. Table 5.2: 123 kN m.
    pub locking_torque_nm: f64,
    /// Full-throttle no-load speed n_t,max [rpm]. Table 5.2: 6875.
    pub no_load_speed_rpm: f64,
    /// Governor set point n_t* [rpm]: 60 Hz, ch. 2.1 (3600 rpm for the two-pole generator).
    pub rated_speed_rpm: f64,
    /// Shaft inertia of turbine and generator rotor I_t [kg m^2]. Table 5.2: 400.
    pub inertia_kg_m2: f64,
    /// Rated power [W]: 21.5 MW (ch. 2.1). Per-unit base for turbine power.
    pub rated_power_w: f64,
}

impl Default for TurbineParams {
    fn default() -> Self {
        TurbineParams {
            locking_torque_nm: 123.0e3,
            no_load_speed_rpm: 6875.0,
            rated_speed_rpm: 3600.0,
            inertia_kg_m2: 400.0,
            rated_power_w: 21.5e6,
        }
    }
}

/// Discrete PI governor on turbine speed acting on the throttle (ch. 2.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GovernorParams {
    /// Proportional gain K_p,t [throttle fraction per per-unit speed error]. Not given in the
    /// thesis; 10, which with K_i,t gives a critically damped loop near 2 rad/s (throttle moves the
    /// per-unit speed at 0.39 /s per unit throttle at 3600 rpm).
    pub kp: f64,
    /// Integral gain K_i,t [throttle fraction per per-unit speed error per second]. Not given; 10.
    pub ki: f64,
    /// Throttle slew limit Delta_t [1/s]. Not given in the thesis; 0.1, i.e. zero to full fuel in
    /// 10 s, a conservative fuel schedule against compressor surge.
    pub slew_rate_per_s: f64,
}

impl Default for GovernorParams {
    fn default() -> Self {
        GovernorParams { kp: 10.0, ki: 10.0, slew_rate_per_s: 0.1 }
    }
}

impl TurbineParams {
    pub fn validate(&self, v: &mut Validator) {
        check_range!(v, self.locking_torque_nm, 1.0e3, 1.0e7);
        check_range!(v, self.no_load_speed_rpm, 100.0, 1.0e5);
        check_range!(v, self.rated_speed_rpm, 100.0, 1.0e5);
        if self.rated_speed_rpm >= self.no_load_speed_rpm {
            v.fail(
                "rated_speed_rpm",
                self.rated_speed_rpm,
                format!("must be below {} (eq. 2.1 gives no torque there)", v.path("no_load_speed_rpm")),
            );
        }
        check_range!(v, self.inertia_kg_m2, 1.0, 1.0e6);
        check_range!(v, self.rated_power_w, 1.0e4, 1.0e9);
    }
}

impl GovernorParams {
    pub fn validate(&self, v: &mut Validator) {
        check_range!(v, self.kp, 0.0, 1.0e3);
        check_range!(v, self.ki, 0.0, 1.0e3);
        check_range!(v, self.slew_rate_per_s, 1.0e-3, 100.0);
    }
}

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
