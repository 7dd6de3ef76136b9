//! Ship surge in calm water (thesis ch. 2.3, eqs. 2.15-2.16).

use crate::scenario::ShipParams;

/// Surge constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surge {
    /// m + m_a [kg].
    pub mass_total: f64,
    /// R_sp = c_r u |u| [N], c_r = rho C_r A_w / (2 (1 - t)) [kg/m].
    pub c_r: f64,
    /// Wake fraction w [-].
    pub wake: f64,
}

impl Surge {
    pub fn new(p: &ShipParams) -> Surge {
        Surge {
            mass_total: p.mass_kg + p.added_mass_kg,
            c_r: 0.5 * p.water_density_kg_m3 * p.drag_coeff * p.wetted_area_m2 / (1.0 - p.thrust_deduction),
            wake: p.wake_fraction,
        }
    }

    /// Eq. 2.15: hull/propeller resistance R_sp = (1/2) rho C_r A_w u^2 / (1 - t) [N].
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Table 5.1 at 25 knots: R_sp = 0.5 * 1025 * 3e-3 * 5200 * 12.861^2 / 0.9 = 1.469 MN.
    #[test]
    fn resistance_at_25_knots() {
        let s = Surge::new(&ShipParams::default());
        let r = s.resistance(crate::units::kn_to_m_s(25.0));
        assert!((r - 1.469e6).abs() < 1e3, "R = {r}");
        assert_eq!(s.acceleration(r, crate::units::kn_to_m_s(25.0)), 0.0);
    }
}
