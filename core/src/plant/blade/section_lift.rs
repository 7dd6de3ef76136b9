//! Lift of a blade section in the linear range: thin-wing theory about the mean line's ideal angle,
//! C_L = C_Li + 2 pi (alpha - alpha_i) (Abbott & von Doenhoff 1959, ch. 4.3 and 6.4), with the
//! lifting-surface factors of Morgan, Silovic & Denny (1968): the camber factor divides the camber
//! (so the ideal lift and the two-dimensional ideal angle), the ideal-angle factor scales that angle,
//! and the blade's thickness adds an angle of its own; the section lifts about that ideal angle.

use super::lifting_surface::Corrections;
use super::mean_line;
use std::f64::consts::PI;

/// Thin-wing lift slope dC_L/d alpha \[1/rad\].
pub const LIFT_SLOPE: f64 = 2.0 * PI;

/// Section lift coefficient at angle of attack `alpha_rad` from the nose-tail line, for camber
/// ratio `f0_c` and the lifting-surface factors `k` \[-\], and its slope dC_L/d alpha \[1/rad\].
pub fn lift(alpha_rad: f64, f0_c: f64, k: &Corrections) -> (f64, f64) {
    let ideal = ideal_angle_rad(f0_c, k);
    (mean_line::ideal_lift(f0_c / k.camber) + LIFT_SLOPE * (alpha_rad - ideal), LIFT_SLOPE)
}

/// The blade's ideal angle from the nose-tail line with the lifting-surface factors `k`: Morgan et
/// al. 1968's alpha_i(3D) = k_a alpha_i(2D, f0/c / k_c) + k_t BTF \[rad\]; at it the blade meets the
/// flow shock-free, as its 2D section does at its own ideal angle.
pub fn ideal_angle_rad(f0_c: f64, k: &Corrections) -> f64 {
    k.ideal_angle * mean_line::ideal_angle_rad(f0_c / k.camber) + k.thickness_angle_rad
}

/// The angle from the nose-tail line at which the section's own 2D shape meets the flow as the
/// blade does at `alpha_rad`: the same distance from the ideal angle (the 2D section's, against
/// the blade's [`ideal_angle_rad`]) \[rad\]. The leading edge's pressure peak, which sets the
/// cavitation bucket, follows that distance.
pub fn equivalent_2d_angle_rad(alpha_rad: f64, f0_c: f64, k: &Corrections) -> f64 {
    alpha_rad - ideal_angle_rad(f0_c, k) + mean_line::ideal_angle_rad(f0_c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thin_wing_limits() {
        // Uncorrected: a flat plate lifts 2 pi alpha; the tabulated mean line lifts 1 at 1.54 deg.
        let (cl, slope) = lift(0.05, 0.0, &Corrections::NONE);
        assert!((cl - 2.0 * PI * 0.05).abs() < 1e-12 && (slope - 2.0 * PI).abs() < 1e-12);
        let (cl, _) = lift(1.54f64.to_radians(), 0.0679, &Corrections::NONE);
        assert!((cl - 1.0).abs() < 1e-12);
        // A camber factor of 2 halves the camber (C_Li 0.5, alpha_i 0.77 deg) and keeps the slope:
        // C_L = 0.5 + 2 pi (1.54 - 0.77) deg = 0.5844.
        let halved = Corrections { camber: 2.0, ..Corrections::NONE };
        let (cl2, slope2) = lift(1.54f64.to_radians(), 0.0679, &halved);
        assert!((cl2 - (0.5 + 2.0 * PI * 0.77f64.to_radians())).abs() < 1e-12 && slope2 == LIFT_SLOPE);
        // An ideal-angle factor of 2 doubles that 0.77 deg; a thickness angle of 0.01 rad adds to it:
        // the lift falls by 2 pi (0.77 deg + 0.01 rad) from C_Li at the same geometric angle.
        let morgan = Corrections { camber: 2.0, ideal_angle: 2.0, thickness_angle_rad: 0.01 };
        let (cl3, _) = lift(1.54f64.to_radians(), 0.0679, &morgan);
        assert!((cl3 - (0.5 - 2.0 * PI * 0.01)).abs() < 1e-12, "{cl3}");
        // The equivalent 2D angle: unchanged without corrections; at the blade's ideal angle, the
        // section's own ideal angle.
        assert_eq!(equivalent_2d_angle_rad(0.03, 0.02, &Corrections::NONE), 0.03);
        let at_ideal = equivalent_2d_angle_rad(ideal_angle_rad(0.0679, &morgan), 0.0679, &morgan);
        assert!((at_ideal - 1.54f64.to_radians()).abs() < 1e-12);
        // Symmetry: no camber, no angle, no thickness, no lift.
        assert_eq!(lift(0.0, 0.0, &Corrections { camber: 1.7, ..Corrections::NONE }).0, 0.0);
    }
}
