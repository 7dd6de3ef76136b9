//! Rectifier, DC bus and inverter (thesis ch. 2.2.3, eqs. 2.7-2.10), average models that
//! conserve power.
//!
//! Each generator feeds the bus through a six-pulse diode bridge and the notching resistance R_p.
//! Eq. 2.8 with the commutating reactance X_co = omega L_sg gives the bridge's DC voltage; the
//! stator resistance adds the equivalent DC resistance (18/pi^2) R_sg, whose loss is the stator
//! copper loss 3 R_sg |i_s|^2 with the fundamental |i_s| = (sqrt(6)/pi) i_gDC. The thesis' power
//! balance across the rectifier, Re{3 (E_a i_s^* - R |i_s|^2)} = v_DC i_gDC, then holds exactly and
//! fixes the generator's electrical power 3 Re{E_a i_s^*} (eq. 2.3).

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// (3 sqrt(6) / pi): six-pulse bridge, phase rms to mean DC voltage (eq. 2.8).
pub const BRIDGE_VOLTAGE_RATIO: f64 = 3.0 * 2.449_489_742_783_178 / PI;
/// sqrt(6)/pi: fundamental phase rms current per unit DC current of a six-pulse bridge.
pub const BRIDGE_CURRENT_RATIO: f64 = 2.449_489_742_783_178 / PI;

/// Constants of one rectifier branch and the bus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DcLink {
    /// Bus capacitance C \[F\].
    pub capacitance: f64,
    /// Notching resistance R_p \[ohm\].
    pub r_p: f64,
    /// Generator stator inductance (commutating) \[H\].
    pub l_commutation: f64,
    /// Equivalent DC resistance of the stator resistance, (18/pi^2) R_sg \[ohm\].
    pub r_stator_dc: f64,
    /// Inverter: largest fundamental phase rms voltage per volt of bus [-].
    pub inverter_voltage_ratio: f64,
}

/// What one rectifier branch does at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RectifierFlow {
    /// DC current into the bus i_gDC \[A\] (eq. 2.9), never negative (diodes).
    pub i_dc: f64,
    /// Bridge DC voltage \[V\], eq. 2.8's v_DC: the bus voltage plus R_p i_gDC (eq. 2.9). Not the
    /// IPS study's `v_dc`, which is its bus after the DC filter.
    pub v_bridge: f64,
    /// Generator electrical (air-gap) power 3 Re{E_a i_s^*} \[W\] (eq. 2.3, Table 5.6).
    pub p_generator: f64,
    /// Stator copper loss 3 R_sg |i_s|^2 \[W\].
    pub p_stator_loss: f64,
    /// Notching loss R_p i_gDC^2 \[W\].
    pub p_notching_loss: f64,
    /// Fundamental stator current |i_s| [A rms].
    pub i_s: f64,
}

/// 18/pi^2: the stator resistance's equivalent DC resistance per ohm (its loss is the copper loss
/// of the fundamental current, see the module notes).
pub const STATOR_DC_RESISTANCE_RATIO: f64 = 18.0 / (PI * PI);

impl DcLink {
    /// The link between a generator of stator resistance `r_s` \[ohm\] and inductance `l_s` \[H\]
    /// and its bus.
    pub fn new(p: &DcLinkParams, r_s: f64, l_s: f64) -> DcLink {
        DcLink {
            capacitance: p.capacitance_f,
            r_p: p.notching_resistance_ohm,
            l_commutation: l_s,
            r_stator_dc: STATOR_DC_RESISTANCE_RATIO * r_s,
            inverter_voltage_ratio: p.inverter_voltage_ratio,
        }
    }

    /// Commutation resistance (3/pi) omega L of eq. 2.8 at electrical speed `omega` \[ohm\].
    pub fn commutation_resistance(&self, omega: f64) -> f64 {
        3.0 / PI * omega * self.l_commutation
    }

    /// Resistance between the bridge's open-circuit voltage and the bus \[ohm\].
    pub fn total_resistance(&self, omega: f64) -> f64 {
        self.r_p + self.commutation_resistance(omega) + self.r_stator_dc
    }

    /// Eqs. 2.8-2.9 with the bus at `v_c`, generator phase emf `e_a` and electrical speed `omega`.
    /// A diode bridge blocks reverse current; a `reversible` converter (average model, same
    /// equations) lets power flow back into the generator.
    pub fn rectify(&self, e_a: f64, omega: f64, v_c: f64, reversible: bool) -> RectifierFlow {
        let r_commutation = self.commutation_resistance(omega);
        let v_open = BRIDGE_VOLTAGE_RATIO * e_a;
        let i_dc = (v_open - v_c) / self.total_resistance(omega);
        let i_dc = if reversible { i_dc } else { i_dc.max(0.0) };
        let v_bridge = v_open - (r_commutation + self.r_stator_dc) * i_dc;
        let p_stator_loss = self.r_stator_dc * i_dc * i_dc;
        RectifierFlow {
            i_dc,
            v_bridge,
            p_generator: v_bridge * i_dc + p_stator_loss,
            p_stator_loss,
            p_notching_loss: self.r_p * i_dc * i_dc,
            i_s: BRIDGE_CURRENT_RATIO * i_dc,
        }
    }

    /// Largest motor phase rms voltage the inverter can make from bus voltage `v_c` \[V\]: the
    /// dynamic saturation of ch. 2.2.3 through which a sagging bus limits the motor.
    pub fn max_phase_voltage(&self, v_c: f64) -> f64 {
        self.inverter_voltage_ratio * v_c.max(0.0)
    }

    /// Eq. 2.7: dv_c/dt = (sum i_gDC - i_mDC) / C, with eq. 2.10 i_mDC = P_inverter / v_c.
    pub fn bus_voltage_rate(&self, i_rectifiers: f64, p_inverter: f64, v_c: f64) -> f64 {
        let i_inv = if v_c.abs() > 1e-9 { p_inverter / v_c } else { 0.0 };
        (i_rectifiers - i_inv) / self.capacitance
    }
}

crate::params! {
    /// Rectifier, DC bus and inverter (eqs. 2.7-2.10, Table 5.4).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct DcLinkParams {
        pub capacitance_f: f64 = 0.037 => {
            label: "Bus capacitance", unit: "F", range: 1.0e-4..=100.0, source: "Table 5.4", group: "plant",
            help: "Capacitance C of each DC bus (eq. 2.7).",
        },
        pub notching_resistance_ohm: f64 = 0.05 => {
            label: "Notching resistance R_p", unit: "Ω", range: 1.0e-4..=10.0, source: "Table 5.4",
            help: "Between each rectifier and the bus.",
        },
        /// sqrt(2)/pi = 0.450, six-step operation, so that the nominal 5618 V bus can drive the
        /// 4160 V motor at rated frequency with 5 % to spare. This is the "dynamic saturation of
        /// motor voltage" of ch. 2.2.3.
        pub inverter_voltage_ratio: f64 = std::f64::consts::SQRT_2 / std::f64::consts::PI => {
            label: "Inverter voltage limit", unit: "-", range: 0.1..=0.5,
            source: "our choice: sqrt 2 / pi, six-step operation (not given in the thesis)",
            help: "Largest motor phase rms voltage as a fraction of the bus voltage (ch. 2.2.3).",
        },
        /// "reversible" is an average model of a converter that also returns power to the
        /// generators, as ch. 5.2.2's unbuffered braking needs to overspeed the turbines.
        pub rectifier: RectifierKind = RectifierKind::Diode => {
            label: "Rectifier", source: "ch. 2.2.1 (diode); ch. 5.2.2 (reversible)", group: "plant",
            help: "Which way power may flow between turbines and bus.",
        },
        /// Ch. 5.2.2's "ideal power management". Our value for the braking preset: 1 ohm (31.6 MW
        /// at 5.62 kV).
        pub brake_resistor_ohm: f64 = 0.0 => {
            label: "Brake resistor", unit: "Ω", range: 0.01..=1.0e4, empty: "none", group: "plant",
            source: "none by default; 1 Ω in the braking preset (31.6 MW at 5.62 kV)",
            help: "Dump resistor on each bus, switched by a chopper (ch. 5.2.2); 0 for none.",
        },
        /// Above the no-load voltage of the generators at the field current of full power (1.08),
        /// so that the resistor takes the braking energy and not the generators' output.
        pub brake_on_pu: f64 = 1.10 => {
            label: "Brake chopper threshold", unit: "pu", range: 1.0..=1.5, base: "the bus voltage set point (controllers.field.bus_voltage_ref_v)",
            source: "our choice: above the generators' full-power no-load voltage (1.08 pu)",
            help: "Bus voltage at which the chopper starts to conduct.",
        },
        /// A proportional band narrow enough to hold the bus within 5 % above the threshold at full
        /// braking power, wide enough to avoid chattering at the 1 ms step.
        pub brake_band_pu: f64 = 0.05 => {
            label: "Brake chopper band", unit: "pu", range: 0.001..=0.5, base: "the bus voltage set point (controllers.field.bus_voltage_ref_v)",
            source: "our choice: holds the bus within 5 % without chattering",
            help: "The chopper conducts fully this far above its threshold.",
        },
    }
}

impl crate::params::CrossCheck for DcLinkParams {}

crate::choices! {
    /// Rectifier average model.
    pub enum RectifierKind {
        Diode = "diode", "diode: one way only",
        Reversible = "reversible", "reversible: back to the turbines too",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn link() -> DcLink {
        DcLink {
            capacitance: 0.037,
            r_p: 0.05,
            l_commutation: 0.391e-3,
            r_stator_dc: STATOR_DC_RESISTANCE_RATIO * 2.27e-2,
            inverter_voltage_ratio: std::f64::consts::SQRT_2 / PI,
        }
    }

    /// No load: the bridge gives (3 sqrt(2)/pi) 4160 V = 5618 V (the bus per-unit base).
    #[test]
    fn no_load_voltage() {
        let l = link();
        let f = l.rectify(4160.0 / 3f64.sqrt(), 377.0, 5618.0, false);
        assert!(f.i_dc.abs() < 1e-9, "i = {}", f.i_dc); // measured exactly 0
        assert!((BRIDGE_VOLTAGE_RATIO * 4160.0 / 3f64.sqrt() - 5617.9).abs() < 0.1);
        // A bus above the bridge voltage draws nothing back through the diodes.
        assert_eq!(l.rectify(2000.0, 377.0, 6000.0, false).i_dc, 0.0);
        // A reversible converter returns power, and the books still balance.
        let back = l.rectify(2000.0, 377.0, 6000.0, true);
        assert!(back.i_dc < 0.0 && back.p_generator < 0.0);
        let v_c = back.v_bridge - l.r_p * back.i_dc;
        let balance = back.p_generator - (v_c * back.i_dc + back.p_notching_loss + back.p_stator_loss);
        assert!(balance.abs() < 1e-12 * back.p_generator.abs()); // measured 1.2e-16
    }

    /// Power conservation across the rectifier: generator power = bus power + losses, and the
    /// AC-side power factor stays at or below one.
    #[test]
    fn rectifier_conserves_power() {
        let l = link();
        let e_a = 2400.0;
        let f = l.rectify(e_a, 377.0, 5300.0, false);
        assert!(f.i_dc > 1000.0);
        let v_c = f.v_bridge - l.r_p * f.i_dc; // eq. 2.9
        assert!((v_c - 5300.0).abs() < 1e-9); // measured exactly 0
        let balance = f.p_generator - (v_c * f.i_dc + f.p_notching_loss + f.p_stator_loss);
        assert!(balance.abs() < 1e-12 * f.p_generator, "residual {balance}"); // measured 1.3e-16
        let cos_phi = f.p_generator / (3.0 * e_a * f.i_s);
        assert!(cos_phi > 0.8 && cos_phi <= 1.0, "cos phi = {cos_phi}");
    }
}
