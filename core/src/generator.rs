//! Synchronous generator (thesis ch. 2.2.1, eqs. 2.2-2.4) and the PI bus-voltage control that
//! acts through its field voltage.
//!
//! Convention: E_a is the **phase** rms emf, E_a = M_g omega i_f / sqrt(2). The thesis calls E_a
//! "rms line-to-line" in ch. 2.2.3, but its rectifier equation 2.8, v_DC = (3 sqrt(6)/pi) E_a, is
//! the six-pulse bridge formula in phase rms (in line-to-line rms it reads (3 sqrt(2)/pi) V_ll).
//! The phase reading also makes Table 5.3 consistent: 4160 V line-to-line (2402 V phase) at 60 Hz
//! needs i_f = 500 A, and the bus sits at 5.6 kV, a medium-voltage DC bus; the line-to-line reading
//! would put the bus at 9.7 kV.

use crate::scenario::{FieldControlParams, GeneratorParams};
use std::f64::consts::SQRT_2;

/// Generator constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SyncGenerator {
    /// Stator resistance R_sg [ohm].
    pub r_s: f64,
    /// Stator (commutating) inductance L_sg [H].
    pub l_s: f64,
    /// Mutual inductance M_g [H].
    pub m_g: f64,
    /// Pole pairs P_g / 2 [-].
    pub pole_pairs: f64,
    /// Field resistance R_fg [ohm] and inductance L_fg [H].
    pub r_f: f64,
    pub l_f: f64,
    /// Friction Q_fric = mu1 + mu2 omega_t [N m].
    pub mu1: f64,
    pub mu2: f64,
    /// Largest field voltage [V].
    pub v_f_max: f64,
}

impl SyncGenerator {
    pub fn new(p: &GeneratorParams, rated_shaft_speed: f64) -> SyncGenerator {
        let mut g = SyncGenerator {
            r_s: p.stator_resistance_ohm,
            l_s: p.stator_inductance_h,
            m_g: p.mutual_inductance_h,
            pole_pairs: p.poles as f64 / 2.0,
            r_f: p.field_resistance_ohm,
            l_f: p.field_inductance_h,
            mu1: p.friction_constant_nm,
            mu2: p.friction_viscous_nm_s,
            v_f_max: 0.0,
        };
        let i_f0 = g.field_current_for(p.rated_voltage_ll_v / 3f64.sqrt(), rated_shaft_speed);
        g.v_f_max = p.field_ceiling_ratio * g.r_f * i_f0;
        g
    }

    /// Electrical frequency omega = (P_g/2) omega_t [rad/s].
    pub fn electrical_speed(&self, omega_t: f64) -> f64 {
        self.pole_pairs * omega_t
    }

    /// Phase rms emf E_a = M_g omega i_f / sqrt(2) [V] (ch. 2.2.1).
    pub fn emf(&self, omega_t: f64, i_f: f64) -> f64 {
        self.m_g * self.electrical_speed(omega_t) * i_f / SQRT_2
    }

    /// Field current that gives phase emf `e_a` at shaft speed `omega_t` [A].
    pub fn field_current_for(&self, e_a: f64, omega_t: f64) -> f64 {
        e_a * SQRT_2 / (self.m_g * self.electrical_speed(omega_t))
    }

    /// Friction torque Q_fric = mu1 + mu2 omega_t [N m], opposing rotation.
    pub fn friction_torque(&self, omega_t: f64) -> f64 {
        if omega_t > 0.0 {
            self.mu1 + self.mu2 * omega_t
        } else {
            self.mu2 * omega_t
        }
    }

    /// Eq. 2.2: di_f/dt = (v_f - i_f R_fg) / L_fg [A/s].
    pub fn field_current_rate(&self, v_f: f64, i_f: f64) -> f64 {
        (v_f - i_f * self.r_f) / self.l_f
    }
}

/// Discrete PI on bus voltage error [V] acting on the field voltage [V], with feed-forward of the
/// no-load field voltage, a ceiling and anti-windup.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldController {
    pub kp: f64,
    pub ki: f64,
    pub v_ref: f64,
    pub v_f_max: f64,
    /// Integrator, including the steady field voltage [V].
    pub integral: f64,
}

impl FieldController {
    pub fn new(p: &FieldControlParams, v_f0: f64, v_f_max: f64) -> FieldController {
        FieldController { kp: p.kp, ki: p.ki, v_ref: p.bus_voltage_ref_v, v_f_max, integral: v_f0 }
    }

    /// One sample: returns the field voltage [V] to hold until the next.
    pub fn update(&mut self, v_bus: f64, ts: f64) -> f64 {
        let err = self.v_ref - v_bus;
        let unsat = self.kp * err + self.integral;
        let out = unsat.clamp(0.0, self.v_f_max);
        if crate::numerics::may_integrate(unsat, 0.0, self.v_f_max, err) {
            self.integral += self.ki * err * ts;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::rpm_to_rad_s;

    /// Table 5.3: 4160 V line-to-line at 60 Hz, reached at about 500 A of field current.
    #[test]
    fn rated_voltage_at_500_amps() {
        let w = rpm_to_rad_s(3600.0);
        let g = SyncGenerator::new(&GeneratorParams::default(), w);
        let i_f = g.field_current_for(4160.0 / 3f64.sqrt(), w);
        assert!((i_f - 500.5).abs() < 0.5, "i_f = {i_f}");
        assert!((g.emf(w, i_f) * 3f64.sqrt() - 4160.0).abs() < 1e-9);
        assert!((g.electrical_speed(w) - 2.0 * std::f64::consts::PI * 60.0).abs() < 1e-9);
        // Field ceiling: three times 125 V.
        assert!((g.v_f_max - 3.0 * 0.25 * i_f).abs() < 1e-9);
    }
}
