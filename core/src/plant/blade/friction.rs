//! Viscous drag of a blade section: the ITTC 1957 model-ship correlation line for the skin friction
//! of each side, times Hoerner's form factor of a foil section (Hoerner 1965, Fluid-Dynamic Drag,
//! ch. 6, eq. 23: C_D = 2 C_F (1 + 2 t/c + 60 (t/c)^4)).

/// Below this chord Reynolds number the ITTC line is not used (it is singular at Re = 100) and the
/// laminar Blasius line C_F = 1.328 / sqrt(Re) is, whichever is larger \[-\].
const LAMINAR_BELOW: f64 = 1.0e4;

/// Skin friction coefficient of one side of a plate at chord Reynolds number `re` \[-\]
/// (ITTC 1957: C_F = 0.075 / (log10 Re - 2)^2).
pub fn skin_friction(re: f64) -> f64 {
    let blasius = |re: f64| 1.328 / libm::sqrt(re.max(1.0));
    if re < LAMINAR_BELOW {
        return blasius(re);
    }
    let l = libm::log10(re) - 2.0;
    0.075 / (l * l)
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
    fn the_ittc_line_at_published_points() {
        // ITTC 1957 at Re = 1e6 and 1e9: 0.075/16 = 0.0046875 and 0.075/49 = 0.0015306.
        assert!((skin_friction(1e6) - 0.0046875).abs() < 1e-12);
        assert!((skin_friction(1e9) - 0.075 / 49.0).abs() < 1e-12);
        // A flat plate of no thickness has form factor 1; a 10 % foil 1.206 (Hoerner).
        assert_eq!(form_factor(0.0), 1.0);
        assert!((form_factor(0.1) - 1.206).abs() < 1e-12);
        // Drag falls as the Reynolds number rises, and is finite down to Re = 0.
        assert!(section_drag(1e5, 0.1) > section_drag(1e7, 0.1));
        assert!(section_drag(0.0, 0.1).is_finite());
    }
}
