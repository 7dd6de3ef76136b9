//! Viscous drag of a blade section: a flat plate's skin friction on each side, from the
//! Prandtl-Schlichting line with laminar-turbulent transition (Schlichting 1979, Boundary-Layer
//! Theory, 7th ed., ch. 21, eq. 21.16: C_F = 0.455 / (log10 Re)^2.58 - 1700 / Re, transition at
//! Re = 5e5), never below the laminar Blasius line (C_F = 1.328 / sqrt(Re)), times Hoerner's form
//! factor of a foil section (Hoerner 1965, Fluid-Dynamic Drag, ch. 6, eq. 23:
//! C_D = 2 C_F (1 + 2 t/c + 60 (t/c)^4)). A model propeller (chord Reynolds number near 1e6) runs
//! partly laminar, which the transition term carries; at full scale (1e7 to 1e8) it vanishes.

/// Skin friction coefficient of one side of a plate at chord Reynolds number `re` \[-\].
pub fn skin_friction(re: f64) -> f64 {
    let re = re.max(1.0);
    let laminar = 1.328 / libm::sqrt(re);
    if re < 1.0e4 {
        // Below the turbulent line's range: laminar only.
        return laminar;
    }
    let turbulent = 0.455 / libm::pow(libm::log10(re), 2.58) - 1700.0 / re;
    turbulent.max(laminar)
}

/// Hoerner's form factor of a foil section of thickness ratio `t_c` \[-\].
pub fn form_factor(t_c: f64) -> f64 {
    1.0 + 2.0 * t_c + 60.0 * t_c * t_c * t_c * t_c
}

/// Section drag coefficient (both sides, form factor included) \[-\].
pub fn section_drag(re: f64, t_c: f64) -> f64 {
    2.0 * skin_friction(re) * form_factor(t_c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_friction_lines_at_published_points() {
        // Fully turbulent at Re = 1e9: 0.455 / 9^2.58 - 1.7e-6 = 0.001568.
        assert!((skin_friction(1e9) - 0.001568).abs() < 1e-6, "{}", skin_friction(1e9));
        // Laminar at Re = 1e5: Blasius, 1.328 / 316.2 = 0.0041996.
        assert!((skin_friction(1e5) - 0.0041996).abs() < 1e-6);
        // At Re = 1e7 the transition term is 3 % of the turbulent line's 0.00299.
        assert!((skin_friction(1e7) - (0.455 / libm::pow(7.0, 2.58) - 1.7e-4)).abs() < 1e-12);
        // A flat plate of no thickness has form factor 1; a 10 % foil 1.206 (Hoerner).
        assert_eq!(form_factor(0.0), 1.0);
        assert!((form_factor(0.1) - 1.206).abs() < 1e-12);
        // Finite down to Re = 0, and falling with Re at full scale.
        assert!(section_drag(0.0, 0.1).is_finite());
        assert!(section_drag(1e7, 0.1) > section_drag(1e8, 0.1));
    }
}
