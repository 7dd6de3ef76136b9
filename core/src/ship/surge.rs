//! Ship surge in calm water (thesis ch. 2.3, eqs. 2.15-2.16).

use crate::checks::Validator;
use crate::ship::hull::HullSpec;
use serde::{Deserialize, Serialize};

/// Surge constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surge {
    /// m + m_a \[kg\].
    pub mass_total: f64,
    /// R_sp = c_r u |u| \[N\], c_r = rho C_r A_w / (2 (1 - t)) [kg/m].
    pub c_r: f64,
    /// Wake fraction w [-].
    pub wake: f64,
}

impl Surge {
    /// The surge model of a ship of displaced mass `mass_kg` (the hull's, `ship_hull`).
    pub fn new(p: &ShipParams, mass_kg: f64) -> Surge {
        Surge {
            mass_total: mass_kg * (1.0 + p.added_mass_fraction),
            c_r: 0.5 * p.water_density_kg_m3 * p.drag_coeff * p.wetted_area_m2 / (1.0 - p.thrust_deduction),
            wake: p.wake_fraction,
        }
    }

    /// Eq. 2.15: hull/propeller resistance R_sp = (1/2) rho C_r A_w u^2 / (1 - t) \[N\].
    pub fn resistance(&self, u: f64) -> f64 {
        self.c_r * u * u.abs()
    }

    /// Eq. 2.16: du/dt = (T_p - R_sp) / (m + m_a) [m/s^2].
    pub fn acceleration(&self, thrust: f64, u: f64) -> f64 {
        (thrust - self.resistance(u)) / self.mass_total
    }

    /// Eq. 2.12: advance speed V_a = u (1 - w) [m/s].
    pub fn advance_speed(&self, u: f64) -> f64 {
        u * (1.0 - self.wake)
    }
}

crate::params! {
    /// The ship: its hull (`ship_hull`: geometry, loading, appendages; the mass and the length
    /// every model uses) and the surge model's resistance and propulsion factors (thesis eqs. 2.12,
    /// 2.15-2.16, Table 5.1).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct ShipParams {
        pub hull: HullSpec = HullSpec::default() => {},
        /// The usual slender-hull value of -X_udot (Fossen 2011, ch. 6).
        pub added_mass_fraction: f64 = 0.05 => {
            label: "Surge added mass", unit: "-", range: 0.0..=1.0,
            source: "our choice: the usual slender-hull -X_udot (Fossen 2011, ch. 6)",
            help: "Surge added mass m_a as a fraction of the displaced mass.",
        },
        /// With C_r it is the thesis' calibration of the resistance, kept as printed: the 5415's own
        /// wetted area is 2973 m^2 (SIMMAN), with which C_r = 3e-3 would give 57 % of the
        /// resistance and not the powers of Table 5.7.
        pub wetted_area_m2: f64 = 5200.0 => {
            label: "Wetted area", unit: "m²", range: 1.0..=1.0e5, source: "Table 5.1", group: "ship",
            help: "Resistance area A_w of eq. 2.15 (the thesis' calibration with C_r).",
        },
        pub drag_coeff: f64 = 3.0e-3 => {
            label: "Drag coefficient C_r", unit: "-", range: 1.0e-5..=0.1, source: "Table 5.1", group: "ship",
            help: "Hull resistance coefficient of eq. 2.15.",
        },
        pub thrust_deduction: f64 = 0.1 => {
            label: "Thrust deduction t", unit: "-", range: 0.0..=0.5, source: "Table 5.1 (\"thrust coefficient\")", group: "ship",
            help: "Share of thrust lost to the hull's suction (eq. 2.15).",
        },
        pub wake_fraction: f64 = 0.1 => {
            label: "Wake fraction w", unit: "-", range: 0.0..=0.6, source: "Table 5.1", group: "ship",
            help: "The propeller meets water slowed by the hull: V_a = (1 - w) u (eq. 2.12).",
        },
        pub water_density_kg_m3: f64 = 1025.0 => {
            label: "Water density", unit: "kg/m³", range: 900.0..=1100.0, source: "Table 5.1",
            help: "Sea water density rho.",
        },
    }
}

impl crate::params::CrossCheck for ShipParams {
    /// The hull must resolve, float and carry its appendages, in this water.
    fn cross_check(&self, v: &mut Validator) {
        let named = crate::ship::hull::HULL_NAMES.contains(&self.hull.name.as_str());
        if named && (900.0..=1100.0).contains(&self.water_density_kg_m3) {
            v.section("hull", |v| self.hull.validate(v, self.water_density_kg_m3));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Table 5.1 at 25 knots: R_sp = 0.5 * 1025 * 3e-3 * 5200 * 12.861^2 / 0.9 = 1.469 MN.
    #[test]
    fn resistance_at_25_knots() {
        let s = Surge::new(&ShipParams::default(), 7.0e6);
        let r = s.resistance(crate::numerics::units::kn_to_m_s(25.0));
        assert!((r - 1.469e6).abs() < 1e3, "R = {r}");
        assert_eq!(s.acceleration(r, crate::numerics::units::kn_to_m_s(25.0)), 0.0);
    }
}
