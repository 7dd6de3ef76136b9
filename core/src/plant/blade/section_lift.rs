//! Lift of a blade section in the linear range: thin-wing theory about the mean line's ideal angle,
//! C_L = C_Li + 2 pi (alpha - alpha_i) (Abbott & von Doenhoff 1959, ch. 4.3 and 6.4), with the
//! lifting-surface camber factor applied to the ideal lift.

use super::lifting_surface::Corrections;
use super::mean_line;
use std::f64::consts::PI;

/// Thin-wing lift slope dC_L/d alpha \[1/rad\].
pub const LIFT_SLOPE: f64 = 2.0 * PI;

/// Section lift coefficient at angle of attack `alpha_rad` from the nose-tail line, for camber
/// ratio `f0_c` and the lifting-surface factors `k` \[-\].
pub fn lift(alpha_rad: f64, f0_c: f64, k: &Corrections) -> f64 {
    let cli = k.camber * mean_line::ideal_lift(f0_c);
    let ai = mean_line::ideal_angle_rad(f0_c) + k.angle_rad;
    cli + LIFT_SLOPE * (alpha_rad - ai)
}
