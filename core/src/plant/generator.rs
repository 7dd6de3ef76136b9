//! Synchronous generator (thesis ch. 2.2.1, eqs. 2.2-2.4) and the PI bus-voltage control that
//! acts through its field voltage.
//!
//! Convention: E_a is the **phase** rms emf, E_a = M_g omega i_f / sqrt(2). The thesis calls E_a
//! "rms line-to-line" in ch. 2.2.3, but its rectifier equation 2.8, v_DC = (3 sqrt(6)/pi) E_a, is
//! the six-pulse bridge formula in phase rms (in line-to-line rms it reads (3 sqrt(2)/pi) V_ll).
//! The phase reading also makes Table 5.3 consistent: 4160 V line-to-line (2402 V phase) at 60 Hz
//! needs i_f = 500 A, and the bus sits at 5.6 kV, a medium-voltage DC bus; the line-to-line reading
//! would put the bus at 9.7 kV.

use crate::checks::Validator;
use crate::control::DiscretePi;
use serde::{Deserialize, Serialize};
use std::f64::consts::SQRT_2;

/// Generator constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SyncGenerator {
    /// Stator resistance R_sg \[ohm\].
    pub r_s: f64,
    /// Stator (commutating) inductance L_sg \[H\].
    pub l_s: f64,
    /// Mutual inductance M_g \[H\].
    pub m_g: f64,
    /// Pole pairs P_g / 2 [-].
    pub pole_pairs: f64,
    /// Field resistance R_fg \[ohm\] and inductance L_fg \[H\].
    pub r_f: f64,
    pub l_f: f64,
    /// Friction Q_fric = mu1 + mu2 omega_t [N m].
    pub mu1: f64,
    pub mu2: f64,
    /// Largest field voltage \[V\].
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

    /// Phase rms emf E_a = M_g omega i_f / sqrt(2) \[V\] (ch. 2.2.1).
    pub fn emf(&self, omega_t: f64, i_f: f64) -> f64 {
        self.m_g * self.electrical_speed(omega_t) * i_f / SQRT_2
    }

    /// Field current that gives phase emf `e_a` at shaft speed `omega_t` \[A\].
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

/// Discrete PI on bus voltage error \[V\] acting on the field voltage \[V\], with feed-forward of the
/// no-load field voltage, a ceiling and anti-windup.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldController {
    /// PI on the bus voltage error \[V\]; its integrator carries the steady field voltage \[V\].
    pub pi: DiscretePi,
    pub v_ref: f64,
    pub v_f_max: f64,
}

impl FieldController {
    pub fn new(p: &FieldControlParams, v_f0: f64, v_f_max: f64) -> FieldController {
        FieldController { pi: DiscretePi::new(p.kp, p.ki, v_f0), v_ref: p.bus_voltage_ref_v, v_f_max }
    }

    /// One sample: returns the field voltage \[V\] to hold until the next.
    pub fn update(&mut self, v_bus: f64, ts: f64) -> f64 {
        self.pi.update(self.v_ref - v_bus, 0.0, self.v_f_max, ts)
    }
}

crate::params! {
    /// Synchronous generator and its field circuit (eqs. 2.2-2.4, Table 5.3).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct GeneratorParams {
        pub stator_resistance_ohm: f64 = 2.27e-2 => {
            label: "Stator resistance R_sg", unit: "Ω", range: 0.0..=10.0, source: "Table 5.3",
            help: "Resistance of one stator phase (eqs. 2.2-2.4).",
        },
        /// Also the commutating inductance of the rectifier (X_co = omega L_sg in eq. 2.8).
        pub stator_inductance_h: f64 = 0.391e-3 => {
            label: "Stator inductance L_sg", unit: "H", range: 0.0..=1.0, source: "Table 5.3",
            help: "Also the rectifier's commutating inductance (eq. 2.8).",
        },
        pub mutual_inductance_h: f64 = 18.0e-3 => {
            label: "Mutual inductance M_g", unit: "H", range: 1.0e-5..=10.0, source: "Table 5.3",
            help: "Couples the field to the stator: the emf per field current and speed.",
        },
        pub poles: u32 = 2 => {
            label: "Generator poles P_g", unit: "-", range: 2.0..=64.0, source: "Table 5.3 (3600 rpm gives 60 Hz)",
            help: "An even number; with the turbine speed it sets the electrical frequency.",
        },
        /// Sets the initial field current (about 500 A with E_a taken as phase rms, see
        /// generator.rs).
        pub rated_voltage_ll_v: f64 = 4160.0 => {
            label: "Generator rated voltage", unit: "V", range: 100.0..=1.0e5, source: "Table 5.3 caption",
            help: "Line-to-line rms voltage at rated speed; sets the initial field current.",
        },
        pub field_resistance_ohm: f64 = 0.25 => {
            label: "Field resistance R_fg", unit: "Ω", range: 1.0e-3..=100.0,
            source: "our choice: 125 V no-load field voltage, usual for a 20-25 MVA machine",
            help: "Resistance of the field winding.",
        },
        pub field_inductance_h: f64 = 0.25 => {
            label: "Field inductance L_fg", unit: "H", range: 1.0e-3..=100.0,
            source: "our choice: a 1 s field time constant, the order of T'd for this size",
            help: "Inductance of the field winding; with R_fg the field's time constant.",
        },
        pub field_ceiling_ratio: f64 = 3.0 => {
            label: "Field voltage ceiling", unit: "-", range: 1.0..=10.0,
            source: "our choice: a common static-exciter ceiling",
            help: "Largest field voltage as a multiple of the no-load field voltage.",
        },
        pub friction_constant_nm: f64 = 0.0 => {
            label: "Friction torque mu_1", unit: "N m", range: 0.0..=1.0e5,
            source: "our choice: all of the loss is taken as speed-proportional (mu_2)",
            help: "Constant part of Q_fric = mu_1 + mu_2 omega_t.",
        },
        /// 2.46 is 350 kW of friction, windage and (unmodelled) core loss at 3600 rpm: the constant
        /// loss that Table 5.7's three generator efficiencies imply (0.35 MW at 20, 25 and 30
        /// knots within 0.03 MW).
        pub friction_viscous_nm_s: f64 = 2.46 => {
            label: "Viscous friction mu_2", unit: "N m s/rad", range: 0.0..=1.0e3,
            source: "our choice: 350 kW at 3600 rpm, the constant loss Table 5.7 implies",
            help: "Speed-proportional part of the friction torque.",
        },
    }
}

crate::params! {
    /// PI control of the bus voltage through the field voltage (ch. 2.2.1).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct FieldControlParams {
        /// The no-load output of the rectifier, (3 sqrt(2)/pi) 4160 V.
        pub bus_voltage_ref_v: f64 = 5618.0 => {
            label: "Bus voltage set point", unit: "V", range: 10.0..=1.0e5,
            source: "no-load rectifier output (3 sqrt 2 / pi) 4160 V (eq. 2.8)",
            help: "Bus voltage the field control holds; the base of bus voltage in per unit.",
        },
        /// The thesis does not state the units; volts per volt is the reading under which its own
        /// remark holds that this loop acts only "slightly".
        pub kp: f64 = 1.0e-4 => {
            label: "Field K_p,v", unit: "V/V", range: 0.0..=10.0, source: "ch. 5.2.1 baseline", group: "controllers",
            help: "Field voltage per volt of bus voltage error.",
        },
        pub ki: f64 = 5.0e-4 => {
            label: "Field K_i,v", unit: "V/(V s)", range: 0.0..=10.0, source: "ch. 5.2.1 baseline", group: "controllers",
            help: "Field voltage per volt of bus error and second.",
        },
    }
}

impl crate::params::CrossCheck for GeneratorParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.poles % 2 != 0 {
            v.fail("poles", self.poles, "must be even (2, 4, ...)");
        }
    }
}

impl crate::params::CrossCheck for FieldControlParams {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::units::rpm_to_rad_s;

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
