//! The NACA a = 0.8 mean line's design facts (Abbott & von Doenhoff 1959, Theory of Wing Sections,
//! ch. 6.4 and appendix II): at the ideal angle of attack the load is shockless, and both the ideal
//! angle and the ideal lift scale with the camber ratio.

/// Camber ratio f0/c of the tabulated a = 0.8 mean line, whose ideal lift coefficient is 1 \[-\].
pub const TABLE_CAMBER_RATIO: f64 = 0.0679;
/// Ideal angle of attack of the tabulated a = 0.8 mean line (C_Li = 1) \[deg\].
pub const TABLE_IDEAL_ANGLE_DEG: f64 = 1.54;

/// Ideal lift coefficient C_Li of an a = 0.8 mean line of camber ratio `f0_c` \[-\].
pub fn ideal_lift(f0_c: f64) -> f64 {
    f0_c / TABLE_CAMBER_RATIO
}

/// Ideal angle of attack alpha_i of an a = 0.8 mean line of camber ratio `f0_c` \[rad\].
pub fn ideal_angle_rad(f0_c: f64) -> f64 {
    TABLE_IDEAL_ANGLE_DEG.to_radians() * f0_c / TABLE_CAMBER_RATIO
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tabulated_mean_line_and_a_flat_plate() {
        assert!((ideal_lift(0.0679) - 1.0).abs() < 1e-12);
        assert!((ideal_angle_rad(0.0679).to_degrees() - 1.54).abs() < 1e-12);
        assert_eq!(ideal_lift(0.0), 0.0);
        assert_eq!(ideal_angle_rad(0.0), 0.0);
    }
}
