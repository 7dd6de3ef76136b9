//! Nonlinear 3-DOF maneuvering: Abkowitz's third-order expansion about u0 (thesis ch. 2.4,
//! eqs. 2.17-2.25) with the Table 2.3 coefficients (Stettler's kayak tests at the Froude-scaled
//! equivalent of 22 knots for a DDG-51).
//!
//! Non-dimensionalisation ("prime" system, L = 180 m): forces by q = (1/2) rho L^2 U^2, the yaw
//! moment by q L, v' = v/U, r' = r L/U, du' = (u - u0)/U, masses by (1/2) rho L^3, inertias by
//! (1/2) rho L^5, with U = sqrt(u^2 + v^2) the instantaneous speed (as in Fossen's Mariner model).
//!
//! Table 2.3 gives the mass-carrying combinations directly ((X_udot - m), (Y_vdot - m),
//! (N_rdot - I_z), (X_vr + m), (Y_r - m u)), which are exactly the combinations eqs. 2.21-2.24 use,
//! so no separate kayak mass is needed. Entries the equations do not name:
//! - Y_vvr and N_vvr multiply v^2 r, the monomial the equations call Y_rvv and N_rvv: used as those.
//! - Y_0, N_0 (and with them Y_0u, Y_0uu, N_0u, N_0uu) are side force and yaw moment with the ship
//!   going straight. The thesis sets Y_0 = N_0 = 0 by symmetry but keeps the Delta-u terms; a port-
//!   starboard symmetric hull has none of the family (they measure the kayak's asymmetry), so by
//!   default all six are dropped (`symmetric_hull = true`); `false` keeps eqs. 2.23-2.24 literally.
//! - X_vvu, X_rru are the terms eq. 2.22 prints as X_vvv v^2 du and X_rrr r^2 du.

use crate::checks::Validator;
pub use crate::ship::hull_forces::HullForces;
use crate::ship::rudder::{rudder_force, stern_inflow, RudderParams};
use serde::{Deserialize, Serialize};

// Every Abkowitz coefficient shares its unit, range, source and help: one line each below.
macro_rules! abkowitz_coefficients {
    ($($field:ident = $default:expr, $label:literal;)*) => {
        crate::params! {
            /// Table 2.3 (22-knot test), non-dimensional, in units of 1e-5 (as printed).
            #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
            #[serde(deny_unknown_fields, default)]
            pub struct AbkowitzCoefficients {
                $(pub $field: f64 = $default => {
                    label: $label,
                    unit: "1e-5",
                    range: -1.0e6..=1.0e6,
                    source: "Table 2.3",
                    help: "Abkowitz coefficient, non-dimensional (prime system) x 1e5.",
                },)*
            }
        }
    };
}

abkowitz_coefficients! {
    xudot_minus_m = -646.9, "X_udot - m";
    x0 = -65.01, "X_0";
    xu = -167.3, "X_u";
    xuu = -178.1, "X_uu";
    xuuu = -80.78, "X_uuu";
    xvr_plus_m = 93.65, "X_vr + m";
    xvv = -268.7, "X_vv";
    xrr = -101.58, "X_rr";
    xvvu = -496.4, "X_vvu";
    xrru = -79.74, "X_rru";
    xvru = 117.2, "X_vru";
    yvdot_minus_m = -939.0, "Y_vdot - m";
    y0 = 3.216, "Y_0";
    y0u = 6.836, "Y_0u";
    y0uu = 3.590, "Y_0uu";
    yrdot = -13.17, "Y_rdot";
    yr_minus_mu = -381.6, "Y_r - m u";
    yrrr = -156.8, "Y_rrr";
    yv = -124.6, "Y_v";
    yvvv = -39.94, "Y_vvv";
    yvvr = -3704.0, "Y_vvr";
    yvrr = -4580.0, "Y_vrr";
    yvu = -2140.0, "Y_vu";
    yvuu = -1332.0, "Y_vuu";
    yru = -543.5, "Y_ru";
    yruu = -111.4, "Y_ruu";
    nrdot_minus_iz = -55.08, "N_rdot - I_z";
    n0 = -6.813, "N_0";
    n0u = -17.38, "N_0u";
    n0uu = -10.57, "N_0uu";
    nvdot = 16.85, "N_vdot";
    nv = -308.8, "N_v";
    nvvv = -3857.0, "N_vvv";
    nr = -219.9, "N_r";
    nrrr = -442.0, "N_rrr";
    nvvr = -1666.0, "N_vvr";
    nvrr = -14820.0, "N_vrr";
    nvu = -900.5, "N_vu";
    nvuu = -671.1, "N_vuu";
    nru = -607.0, "N_ru";
    nruu = -561.8, "N_ruu";
}

/// Lowest speed used to non-dimensionalise [m/s]: below it the ship is all but stopped and the
/// prime variables would divide by nearly zero.
const U_FLOOR: f64 = 0.5;
/// Lowest du' used in the expansion: the 11-knot test point of the kayak data (du' = -1 at U = u).
const DU_MIN: f64 = -1.0;

/// Dimensional Abkowitz model for one ship length and density.
#[derive(Debug, Clone, PartialEq)]
pub struct Abkowitz {
    c: AbkowitzCoefficients,
    symmetric: bool,
    /// Linearisation speed u0 [m/s].
    pub u0: f64,
    /// Ship length L \[m\].
    pub length: f64,
    rho: f64,
    /// Surge mass m - X_udot \[kg\] (eq. 2.21).
    pub m11: f64,
    /// Inverse of the sway-yaw block of eq. 2.21.
    inv22: [[f64; 2]; 2],
    /// The sway-yaw block itself [kg, kg m; kg m, kg m^2].
    pub m22: [[f64; 2]; 2],
}

impl Abkowitz {
    pub fn new(c: &AbkowitzCoefficients, symmetric: bool, u0: f64, length: f64, rho: f64) -> Abkowitz {
        let e = 1e-5;
        let half_rho = 0.5 * rho;
        let l3 = half_rho * length * length * length;
        let l4 = l3 * length;
        let l5 = l4 * length;
        // Eq. 2.21.
        let m22 = [[-c.yvdot_minus_m * e * l3, -c.yrdot * e * l4], [-c.nvdot * e * l4, -c.nrdot_minus_iz * e * l5]];
        let det = m22[0][0] * m22[1][1] - m22[0][1] * m22[1][0];
        let inv22 = [[m22[1][1] / det, -m22[0][1] / det], [-m22[1][0] / det, m22[0][0] / det]];
        Abkowitz { c: c.clone(), symmetric, u0, length, rho, m11: -c.xudot_minus_m * e * l3, inv22, m22 }
    }

    /// Eqs. 2.22-2.24 (hull terms): surge force, sway force and yaw moment at (u, v, r).
    pub fn forces(&self, u: f64, v: f64, r: f64) -> HullForces {
        let c = &self.c;
        let big_u = (u * u + v * v).sqrt().max(U_FLOOR);
        let q = 0.5 * self.rho * self.length * self.length * big_u * big_u * 1e-5;
        let vp = v / big_u;
        let rp = r * self.length / big_u;
        let du = ((u - self.u0) / big_u).max(DU_MIN);
        let (du2, du3) = (du * du, du * du * du);
        let (v2, r2) = (vp * vp, rp * rp);
        let x_straight = c.x0 + c.xu * du + c.xuu * du2 + c.xuuu * du3;
        let x = x_straight
            + c.xvv * v2
            + c.xrr * r2
            + c.xvvu * v2 * du
            + c.xrru * r2 * du
            + c.xvr_plus_m * vp * rp
            + c.xvru * vp * rp * du;
        let mut y = c.yv * vp
            + c.yvvv * v2 * vp
            + c.yr_minus_mu * rp
            + c.yrrr * r2 * rp
            + c.yvrr * vp * r2
            + c.yvu * vp * du
            + c.yvuu * vp * du2
            + c.yvvr * rp * v2
            + c.yru * rp * du
            + c.yruu * rp * du2;
        let mut n = c.nv * vp
            + c.nr * rp
            + c.nvvv * v2 * vp
            + c.nvrr * vp * r2
            + c.nvu * vp * du
            + c.nvuu * vp * du2
            + c.nrrr * r2 * rp
            + c.nvvr * rp * v2
            + c.nru * rp * du
            + c.nruu * rp * du2;
        if !self.symmetric {
            y += c.y0 + c.y0u * du + c.y0uu * du2;
            n += c.n0 + c.n0u * du + c.n0uu * du2;
        }
        HullForces { x: q * x, y: q * y, n: q * self.length * n, x_straight: q * x_straight }
    }

    /// Sway and yaw accelerations from the sway force and yaw moment (eq. 2.20).
    pub fn sway_yaw_acceleration(&self, y: f64, n: f64) -> (f64, f64) {
        (self.inv22[0][0] * y + self.inv22[0][1] * n, self.inv22[1][0] * y + self.inv22[1][1] * n)
    }
}

/// The hull with its rudder (eqs. 2.23-2.24 with the rudder of eqs. 2.26-2.30 standing `x_p` [m]
/// aft of G, water density `rho` [kg/m^3]): the hydrodynamic side force [N] and yaw moment [N m]
/// at (u, v, r) with the rudder at `delta` [rad].
fn side_force_and_moment(
    a: &Abkowitz,
    rudder: &RudderParams,
    rho: f64,
    x_p: f64,
    uvr: (f64, f64, f64),
    delta: f64,
) -> (f64, f64) {
    let (u, v, r) = uvr;
    let f = a.forces(u, v, r);
    let (_, fy_r) = rudder_force(rudder, rho, &stern_inflow(u, v, r, x_p), delta);
    (f.y + fy_r, f.n - x_p * fy_r) // eq. 2.24: - x_p F_y
}

/// A steady turn of the hull with its rudder at surge `u` [m/s] and yaw rate `r` [rad/s]: the sway
/// speed v [m/s] and rudder angle delta \[rad\] that make f_2 = f_3 = 0 (eqs. 2.23-2.24 with v_dot
/// = r_dot = 0; the mass terms are in (Y_r - m u)), the point of the spiral-test curve delta(r).
/// The rudder's side force F_y must cancel the hull's, so N_hull + x_p Y_hull = 0 fixes v (the
/// root nearest v = 0, searched to |v| = U/2); then delta follows from F_y(delta) = -Y_hull
/// (searched within 60 deg). None when either has no root.
pub fn steady_turn(a: &Abkowitz, rudder: &RudderParams, rho: f64, x_p: f64, u: f64, r: f64) -> Option<(f64, f64)> {
    let g = |v: f64| {
        let f = a.forces(u, v, r);
        f.n + x_p * f.y
    };
    let step = 1e-3 * u;
    let v = if g(0.0) == 0.0 {
        0.0
    } else {
        (1..=500)
            .flat_map(|k| [-1.0, 1.0].map(|dir| (dir * (k - 1) as f64 * step, dir * k as f64 * step)))
            .find(|&(v0, v1)| (g(v0) > 0.0) != (g(v1) > 0.0))
            .map(|(v0, v1)| crate::numerics::bisect(g, v0, v1, 80))?
    };
    let lim = 60f64.to_radians();
    let h = |d: f64| side_force_and_moment(a, rudder, rho, x_p, (u, v, r), d).0;
    if (h(-lim) > 0.0) == (h(lim) > 0.0) {
        return None;
    }
    Some((v, crate::numerics::bisect(h, -lim, lim, 80)))
}

/// The linear sway-yaw derivatives (Y_v, Y_r - m u, N_v, N_r) in prime units at surge `u` [m/s]
/// (forces over (1/2) rho L^2 u^2, moments over (1/2) rho L^3 u^2, v' = v/u, r' = r L/u), from
/// central differences of eqs. 2.23-2.24 about straight running: of the hull alone, or with the
/// rudder (`Some((rudder, x_p))`, at delta = 0), whose lift adds to all four.
pub fn linear_derivatives(a: &Abkowitz, rudder: Option<(&RudderParams, f64)>, rho: f64, u: f64) -> [f64; 4] {
    let l = a.length;
    let q = 0.5 * rho * l * l * u * u;
    let yn = |v: f64, r: f64| match rudder {
        Some((rp, x_p)) => side_force_and_moment(a, rp, rho, x_p, (u, v, r), 0.0),
        None => {
            let f = a.forces(u, v, r);
            (f.y, f.n)
        }
    };
    let (dv, dr) = (1e-4 * u, 1e-4 * u / l);
    let d = |a: (f64, f64), b: (f64, f64), h: f64| ((a.0 - b.0) / (2.0 * h), (a.1 - b.1) / (2.0 * h));
    let (yv, nv) = d(yn(dv, 0.0), yn(-dv, 0.0), dv);
    let (yr, nr) = d(yn(0.0, dr), yn(0.0, -dr), dr);
    // To prime units: Y_v' = Y_v u / q, Y_r' = Y_r u / (q L), N_v' = N_v u / (q L), N_r' = N_r u / (q L^2).
    [yv * u / q, yr * u / (q * l), nv * u / (q * l), nr * u / (q * l * l)]
}

/// Abkowitz's straight-line stability index C = Y_v N_r - N_v (Y_r - m u) of
/// [`linear_derivatives`]. Positive: the straight course is stable (the determinant of eq. 2.20's
/// linearisation, whose mass matrix has a positive determinant).
pub fn stability_index(a: &Abkowitz, rudder: Option<(&RudderParams, f64)>, rho: f64, u: f64) -> f64 {
    let [yv, yr, nv, nr] = linear_derivatives(a, rudder, rho, u);
    yv * nr - nv * yr
}

/// Smooth weight of the maneuvering model in surge, 0 below `lo` and 1 above `hi` [m/s]
/// (a cubic smoothstep, so the surge force and its slope are continuous across the hand-over).
pub fn handover_weight(u: f64, lo: f64, hi: f64) -> f64 {
    let s = ((u - lo) / (hi - lo)).clamp(0.0, 1.0);
    s * s * (3.0 - 2.0 * s)
}

crate::params! {
    /// Hull model selection and the maneuvering model's data (ch. 2.4, Table 2.3).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct HullParams {
        pub model: HullModelKind = HullModelKind::Surge => {
            label: "Hull model", source: "ch. 2.3 (surge), ch. 2.4 (maneuvering)", group: "ship",
            help: "Straight line only, or turns with a rudder.",
        },
        /// The hull's own model (sectional.rs) unless the thesis' Table 2.3 is asked for.
        pub forces: ManeuveringForces = ManeuveringForces::OwnHull => {
            label: "Maneuvering forces", source: "our model from the hull's sections, or the thesis' Table 2.3", group: "ship",
            help: "The hull's own model holds from rest to full speed; Table 2.3 is the thesis' (kayak tests, about 17 to 32 kn).",
        },
        pub own: crate::ship::sectional::OwnHullParams = crate::ship::sectional::OwnHullParams::default() => {},
        pub abkowitz: AbkowitzCoefficients = AbkowitzCoefficients::default() => {},
        pub linearization_speed_kn: f64 = 22.0 => {
            label: "Expansion speed u0", unit: "kn", range: 1.0..=40.0, source: "ch. 2.4",
            help: "Speed about which Table 2.3's expansion was made.",
        },
        /// Drops the straight-running side force and yaw moment (Y_0, N_0 and their Delta-u
        /// terms), as a port-starboard symmetric hull must (see maneuvering.rs).
        pub symmetric_hull: bool = true => {
            label: "Symmetric hull", source: "our choice: a port-starboard symmetric hull has no Y_0, N_0",
            help: "Drop the straight-running side force and yaw moment of Table 2.3.",
        },
        /// The Abkowitz surge polynomial, fitted at 11 and 22 knots, turns propulsive near 11
        /// knots. Without `as_printed.table_5_ship` the straight-line resistance is eq. 2.15's at
        /// every speed and these two are not used.
        pub handover_low_kn: f64 = 17.0 => {
            label: "Hand-over from", unit: "kn", range: 0.0..=40.0,
            source: "our choice: the surge polynomial turns propulsive near 11 kn",
            help: "With as_printed.table_5_ship: below this speed surge follows the surge model alone.",
        },
        pub handover_high_kn: f64 = 21.0 => {
            label: "Hand-over to", unit: "kn", range: 0.0..=40.0, source: "our choice",
            help: "With as_printed.table_5_ship: above this speed surge follows the Abkowitz model alone.",
        },
    }
}

crate::choices! {
    /// Which hull model moves the ship.
    pub enum HullModelKind {
        /// Straight-line surge (eqs. 2.15-2.16), as ch. 5.1 uses for start-up.
        Surge = "surge", "surge only: straight line (ch. 2.3)",
        /// Abkowitz 3-DOF maneuvering (eqs. 2.17-2.25) with the rudder; in surge it hands over
        /// smoothly to the surge model below `hull.handover_low_kn`.
        Maneuvering = "maneuvering", "maneuvering: 3 DOF with rudder (ch. 2.4)",
    }
}

crate::choices! {
    /// Where the maneuvering model's hull forces come from.
    pub enum ManeuveringForces {
        /// The hull's own sections (sectional.rs): dimensional, from rest to full speed.
        OwnHull = "own_hull", "the hull's own sections (0 to 30 kn)",
        /// Table 2.3's Abkowitz expansion (eqs. 2.17-2.25), as the thesis' ch. 5.2 runs.
        Table23 = "table_2_3", "Table 2.3 (the thesis' kayak tests)",
    }
}

impl crate::params::CrossCheck for HullParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.handover_high_kn <= self.handover_low_kn {
            v.fail("handover_high_kn", self.handover_high_kn, format!("must be above {}", v.path("handover_low_kn")));
        }
    }
}

impl crate::params::CrossCheck for AbkowitzCoefficients {
    fn cross_check(&self, v: &mut Validator) {
        for (name, x) in [
            ("xudot_minus_m", self.xudot_minus_m),
            ("yvdot_minus_m", self.yvdot_minus_m),
            ("nrdot_minus_iz", self.nrdot_minus_iz),
        ] {
            if x >= 0.0 {
                v.fail(name, x, "must be negative (added mass less the mass)");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::units::kn_to_m_s;

    fn model() -> Abkowitz {
        Abkowitz::new(&AbkowitzCoefficients::default(), true, kn_to_m_s(22.0), 180.0, 1025.0)
    }

    /// Straight ahead at u0 the hull force is X0 q: 65.01e-5 * (1/2) 1025 * 180^2 * (11.318)^2 =
    /// 1.383 MN of resistance, and no side force or moment.
    #[test]
    fn resistance_at_u0_is_x0() {
        let m = model();
        let f = m.forces(kn_to_m_s(22.0), 0.0, 0.0);
        let want = -65.01e-5 * 0.5 * 1025.0 * 180.0 * 180.0 * kn_to_m_s(22.0) * kn_to_m_s(22.0);
        assert!((f.x - want).abs() < 1e-6 * want.abs(), "{} vs {want}", f.x);
        assert!(want < -1.38e6 && want > -1.39e6);
        assert_eq!((f.y, f.n), (0.0, 0.0));
    }

    /// Mirror symmetry: (v, r) -> (-v, -r) flips Y and N and keeps X.
    #[test]
    fn port_starboard_symmetry() {
        let m = model();
        let a = m.forces(12.0, 0.8, 0.01);
        let b = m.forces(12.0, -0.8, -0.01);
        assert!((a.x - b.x).abs() < 1e-9 * a.x.abs());
        assert!((a.y + b.y).abs() < 1e-9 * a.y.abs().max(1.0));
        assert!((a.n + b.n).abs() < 1e-9 * a.n.abs().max(1.0));
    }

    /// Abkowitz's index of Table 2.3 at u0 (du' = 0), from the model's forces by differences,
    /// equals Y_v N_r - N_v (Y_r - m u) of the table: -9.04e-6 (course-unstable). With the rudder
    /// of Table 5.5 at 67.2 m aft of G on L = 142 m its lift adds Y_v' = -A_r C_L / L^2 = -3.28e-3,
    /// Y_r' = -N_v' = -Y_v' x_p / L and N_r' = Y_v' (x_p / L)^2: the index turns +9.82e-6 (stable).
    #[test]
    fn stability_index_with_and_without_rudder() {
        let (l, x_p) = (142.0, 67.2);
        let u0 = kn_to_m_s(22.0);
        let a = Abkowitz::new(&AbkowitzCoefficients::default(), true, u0, l, 1025.0);
        let c = AbkowitzCoefficients::default();
        let table = (c.yv * c.nr - c.nv * c.yr_minus_mu) * 1e-10;
        let hull = stability_index(&a, None, 1025.0, u0);
        assert!((hull / table - 1.0).abs() < 1e-6, "{hull} vs {table}");
        assert!((table + 9.04e-6).abs() < 0.01e-6);
        let rp = RudderParams::default();
        let yd = -rp.area_m2 * rp.lift_slope / (l * l);
        let k = x_p / l;
        let (yv, yr) = (c.yv * 1e-5 + yd, c.yr_minus_mu * 1e-5 - yd * k);
        let (nv, nr) = (c.nv * 1e-5 - yd * k, c.nr * 1e-5 + yd * k * k);
        let want = yv * nr - nv * yr;
        let with = stability_index(&a, Some((&rp, x_p)), 1025.0, u0);
        // Within 1e-4: the rudder's drag, C_D |alpha| sin(alpha), is odd in alpha and adds
        // C_D h to a central difference of step h (measured 2.2e-5).
        assert!((with / want - 1.0).abs() < 1e-4, "{with} vs {want}");
        assert!((with - 9.82e-6).abs() < 0.01e-6, "{with}");
    }

    /// The spiral-test curve of Table 2.3 with the rudder (L = 142 m, x_p = 67.2 m, 25 kn): the
    /// rudder a steady starboard turn needs grows to 3-4 deg (to port is positive) near r' = 0.12,
    /// then falls back and turns to counter-rudder by r' = 0.3: turns tighter than r' = 0.12 are
    /// unstable, and a rudder held beyond about 4 deg has no steady turn to settle in.
    #[test]
    fn spiral_curve_has_a_loop() {
        let (l, x_p, u) = (142.0, 67.2, kn_to_m_s(25.0));
        let a = Abkowitz::new(&AbkowitzCoefficients::default(), true, kn_to_m_s(22.0), l, 1025.0);
        let rp = RudderParams::default();
        let delta = |rp_: f64| steady_turn(&a, &rp, 1025.0, x_p, u, rp_ * u / l).unwrap().1.to_degrees();
        let curve: Vec<f64> = (1..=60).map(|i| delta(0.01 * i as f64)).collect();
        let (imin, dmin) = curve.iter().enumerate().fold((0, 0.0), |b, (i, &d)| if d < b.1 { (i, d) } else { b });
        assert!(dmin < -3.0 && dmin > -4.5, "{dmin}");
        assert!((0.08..=0.16).contains(&(0.01 * (imin + 1) as f64)), "{imin}");
        assert!(delta(0.3) > 0.0 && delta(1.0 / 3.0) > 0.0, "{}", delta(0.3));
        assert!(delta(0.0).abs() < 1e-12);
    }

    /// Masses of eq. 2.21: the sway-yaw block times its inverse is the identity.
    #[test]
    fn mass_matrix() {
        let m = model();
        let half_rho_l3 = 0.5 * 1025.0 * (180.0 * 180.0 * 180.0);
        assert!((m.m11 - 646.9e-5 * half_rho_l3).abs() < 1.0);
        let (a, b) = m.sway_yaw_acceleration(m.m22[0][0], m.m22[1][0]);
        assert!((a - 1.0).abs() < 1e-12 && b.abs() < 1e-12);
        assert_eq!(handover_weight(1.0, 2.0, 3.0), 0.0);
        assert_eq!(handover_weight(4.0, 2.0, 3.0), 1.0);
        assert!((handover_weight(2.5, 2.0, 3.0) - 0.5).abs() < 1e-12);
    }
}
