//! Cross-flow drag over the hull's own sections: the sway force and yaw moment of water flowing
//! across each section, -(1/2) rho T(x) C_D(x) |v + x r| (v + x r) per metre of length, with the
//! two-dimensional drag coefficient C_D of Hoerner's curve at each section's B/(2T)
//! (core/data/hoerner_crossflow_cd.csv). It is the damping a ship keeps when it is stopped or
//! drifting sideways, where lift-type forces, which grow with forward speed, vanish (Fossen, Handbook
//! of Marine Craft Hydrodynamics and Motion Control, 2021, ch. 6.4, "cross-flow drag").

use crate::numerics::interp::{bracket, lerp};

const HOERNER: &str = include_str!("../../data/hoerner_crossflow_cd.csv");

/// Hoerner's curve: (B/(2T), C_D) points with increasing B/(2T).
pub fn hoerner_curve() -> Vec<(f64, f64)> {
    crate::numerics::interp::csv_points(HOERNER)
}

/// The 2D cross-flow drag coefficient of a section of half-beam over draft `b_over_2t`,
/// interpolated on Hoerner's curve and held beyond its ends.
pub fn hoerner_cd(curve: &[(f64, f64)], b_over_2t: f64) -> f64 {
    let xs: Vec<f64> = curve.iter().map(|p| p.0).collect();
    let (j, f) = bracket(&xs, b_over_2t);
    lerp(curve[j].1, curve[j + 1].1, f)
}

/// The hull cut into strips for the cross-flow integral: each strip's position forward of the
/// centre of gravity x \[m\] and its weight (1/2) rho T C_D dx [kg/m].
#[derive(Debug, Clone, PartialEq)]
pub struct CrossFlow {
    strips: Vec<(f64, f64)>,
}

impl CrossFlow {
    /// From sections given as (x forward of G \[m\], beam \[m\], draft \[m\]) in increasing x, water
    /// density `rho` [kg/m^3]: the trapezoidal rule along the length.
    pub fn new(sections: &[(f64, f64, f64)], rho: f64) -> CrossFlow {
        let curve = hoerner_curve();
        let n = sections.len();
        let strips = (0..n)
            .map(|i| {
                let (x, b, t) = sections[i];
                let lo = if i > 0 { sections[i - 1].0 } else { x };
                let hi = if i + 1 < n { sections[i + 1].0 } else { x };
                let cd = if t > 0.0 && b > 0.0 { hoerner_cd(&curve, b / (2.0 * t)) } else { 0.0 };
                (x, 0.5 * rho * t * cd * 0.5 * (hi - lo))
            })
            .filter(|s| s.1 > 0.0)
            .collect();
        CrossFlow { strips }
    }

    /// Sway force \[N\] and yaw moment [N m] at sway speed `v` [m/s] and yaw rate `r` [rad/s] (the
    /// section at x moves sideways at v + x r).
    pub fn forces(&self, v: f64, r: f64) -> (f64, f64) {
        let (mut y, mut n) = (0.0, 0.0);
        for &(x, w) in &self.strips {
            let vx = v + x * r;
            let f = -w * vx.abs() * vx;
            y += f;
            n += x * f;
        }
        (y, n)
    }

    /// The sum of (1/2) rho T C_D dx over the strips [kg/m]: the side force per (m/s)^2 of pure
    /// drift.
    pub fn drift_coefficient(&self) -> f64 {
        self.strips.iter().map(|s| s.1).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The curve's end points as digitised: a flat plate across the flow (B/2T -> 0) has C_D
    /// 1.97; a wide, shallow section 0.56; a half circle (B/2T = 1) 0.826.
    #[test]
    fn hoerner_ends_and_circle() {
        let c = hoerner_curve();
        assert_eq!(c.len(), 20);
        assert!((hoerner_cd(&c, 0.0) - 1.96608).abs() < 1e-12);
        assert!((hoerner_cd(&c, 10.0) - 0.559315).abs() < 1e-12);
        // Between the points at 0.988 and 1.308: 0.828415 - 0.012 x 0.2139.
        let circle = hoerner_cd(&c, 1.0);
        assert!((circle - 0.825849).abs() < 1e-6, "{circle}");
    }

    /// A box of length L, draft T and uniform C_D drifting at v with no yaw: Y = -(1/2) rho T C_D
    /// L v|v| (to the trapezoid's exactness for a constant integrand) and, the box symmetric about
    /// G, no moment. Turning on the spot at r: no force, and N = -(1/2) rho T C_D r|r| L^4/32
    /// (the integral of x^2 |x| over -L/2..L/2), to 0.5 % with 201 strips.
    #[test]
    fn box_drift_and_turn() {
        let (l, t, b, rho) = (100.0, 5.0, 10.0, 1025.0);
        let secs: Vec<(f64, f64, f64)> = (0..=200).map(|i| (-0.5 * l + l * i as f64 / 200.0, b, t)).collect();
        let cf = CrossFlow::new(&secs, rho);
        let cd = hoerner_cd(&hoerner_curve(), b / (2.0 * t));
        let (y, n) = cf.forces(1.5, 0.0);
        let want = -0.5 * rho * t * cd * l * 1.5 * 1.5;
        assert!((y / want - 1.0).abs() < 1e-12, "{y} vs {want}");
        assert!(n.abs() < 1e-9 * want.abs());
        let r = 0.02;
        let (y, n) = cf.forces(0.0, r);
        let want = -0.5 * rho * t * cd * r * r * l * l * l * l / 32.0;
        assert!(y.abs() < 1e-9 * want.abs() * 1e3);
        assert!((n / want - 1.0).abs() < 5e-3, "{n} vs {want}");
    }
}
