//! LM2500 gas turbine (thesis ch. 2.1, eq. 2.1) and its discrete PI speed governor with
//! throttle saturation and slew limit.

use crate::scenario::{GovernorParams, TurbineParams};
use crate::units::rpm_to_rad_s;

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
    pub kp: f64,
    pub ki: f64,
    /// Largest throttle change per second [1/s].
    pub slew: f64,
    /// Integrator [throttle fraction].
    pub integral: f64,
    /// Throttle now applied [fraction of full fuel].
    pub throttle: f64,
}

impl Governor {
    pub fn new(p: &GovernorParams, throttle0: f64) -> Governor {
        Governor { kp: p.kp, ki: p.ki, slew: p.slew_rate_per_s, integral: throttle0, throttle: throttle0 }
    }

    /// One controller sample of period `ts` [s] with speed error `err_pu` (set point minus speed,
    /// per unit of the set point). Returns the throttle to hold until the next sample.
    pub fn update(&mut self, err_pu: f64, ts: f64) -> f64 {
        let unsat = self.kp * err_pu + self.integral;
        let cmd = unsat.clamp(0.0, 1.0);
        // Integrate only while the command is not pushed further into saturation.
        if crate::numerics::may_integrate(unsat, 0.0, 1.0, err_pu) {
            self.integral += self.ki * err_pu * ts;
        }
        let step = self.slew * ts;
        self.throttle += (cmd - self.throttle).clamp(-step, step);
        self.throttle
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
        assert!(g.integral <= 1.0 + 10.0 * 0.5 * 0.005 + 1e-12);
    }
}
