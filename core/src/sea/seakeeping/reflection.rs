//! The mean force of short waves reflected by the hull's waterline: the asymptotic formula of
//! Faltinsen, Minsaas, Liapis and Skjordal (1980, "Prediction of resistance and propulsion of a
//! ship in a seaway", 13th ONR Symposium) with Fujii and Takahashi's (1975) draft factor, the
//! reflection part that NMRI's and ITTC 2021's added-resistance methods are built on.
//!
//! Why it replaces eq. 2.48 (Salvesen's F7) for the ship a user sails: F7 integrates the sections'
//! damping b33, b22 over the whole length with the factor omega0^2 / omega_e and no regard for
//! which side the waves come from. In following seas omega_e falls well below omega0 and b33 is
//! taken at that low frequency, where it is large: at 15 kn in sea state 6 with waves from astern
//! F7 makes 1.3 MN per m^2 of wave amplitude at omega0 = 1.34 rad/s, fourteen times the mean force
//! on a wall as wide as the ship that reflects every wave (1/2 rho g B). The runs then saw the
//! waves push a ship ordered to 4-8 kn up to 6-14 kn. Here only the part of the waterline the
//! waves meet reflects, each piece by the angle at which they meet it, so a fine stern in following
//! seas reflects little and a beam sea meets the whole side.
//!
//! Per unit wave amplitude squared, along the waves' direction of travel d = (cos beta, sin beta)
//! (STF axes, beta = pi head seas), with n the waterline's outward normal, t its tangent and the
//! ship's speed U along x:
//!   F_R = 1/2 rho g sum over the lit waterline (d.n < 0) of
//!         alpha_T(k T) [ (d.n)^2 + (2 omega0 U / g)(-d_x + t_x (t.d)) ]_+ |d.n| dl,
//! which in head seas (d = -x) is Faltinsen's sin^2(theta + beta) + (2 omega0 U / g)(1 - cos theta
//! cos(theta + beta)) over sin(theta) dl. Written with the waves' direction rather than the angle
//! from the bow, the speed term changes sign where the ship runs away from the waves (following
//! seas): the reflected wave is then weaker, and a piece never pulls (the bracket is kept at zero
//! or more). alpha_T = pi^2 I1^2(kT) / (pi^2 I1^2(kT) + K1^2(kT)) takes the local draft T, so a
//! shallow transom (0.5 m on the DTMB 5415) reflects only short waves.

crate::choices! {
    /// The short-wave part of the second-order mean force (eqs. 2.46-2.48).
    pub enum ShortWaveForce {
        /// The waterline's reflection (`reflection`): Faltinsen et al. (1980), Fujii-Takahashi's
        /// draft factor.
        Reflection = "reflection", "reflection by the lit waterline (Faltinsen 1980)",
        /// Eq. 2.48's F7 (Salvesen 1978), as the thesis computes it.
        SalvesenF7 = "salvesen_f7", "eq. 2.48's F7 (Salvesen 1978, the thesis)",
    }
}

/// The reflection force along the waves' travel [N/m^2] and its first moment about x = 0 (the
/// sum of each piece's force times its x) [N m/m^2], for the waterline of half-breadths
/// `half_breadth` at stations `x` (increasing, forward of the centre of gravity) with drafts
/// `draft`, in waves of number `k` [rad/m] and frequency `omega0` [rad/s] from heading `beta`
/// \[rad\] at ship speed `u` [m/s]. The waterline closes to the centreline half a station beyond
/// the foremost station (as the strips' weights do) and ends aft in a transom as wide as the
/// aftmost station.
#[allow(clippy::too_many_arguments)]
pub fn reflection_force(
    x: &[f64],
    half_breadth: &[f64],
    draft: &[f64],
    k: f64,
    omega0: f64,
    u: f64,
    beta: f64,
    rho: f64,
    g: f64,
) -> (f64, f64) {
    let n = x.len();
    if n < 2 {
        return (0.0, 0.0);
    }
    let d = [libm::cos(beta), libm::sin(beta)];
    let speed = 2.0 * omega0 * u / g;
    let (mut force, mut moment) = (0.0, 0.0);
    // One straight piece of waterline from (x1, y1) to (x2, y2) with outward normal `nrm`.
    let mut piece = |x1: f64, y1: f64, x2: f64, y2: f64, nrm: [f64; 2], t_draft: f64| {
        let dl = libm::hypot(x2 - x1, y2 - y1);
        if dl <= 0.0 {
            return;
        }
        let dn = d[0] * nrm[0] + d[1] * nrm[1];
        if dn >= 0.0 {
            return; // in the shadow
        }
        let t = [(x2 - x1) / dl, (y2 - y1) / dl];
        let td = t[0] * d[0] + t[1] * d[1];
        let bracket = (dn * dn + speed * (-d[0] + t[0] * td)).max(0.0);
        let f = 0.5 * rho * g * draft_factor(k * t_draft) * bracket * (-dn) * dl;
        force += f;
        moment += f * 0.5 * (x1 + x2);
    };
    for side in [1.0, -1.0] {
        for i in 0..n - 1 {
            let (x1, x2) = (x[i], x[i + 1]);
            let (y1, y2) = (side * half_breadth[i], side * half_breadth[i + 1]);
            let (dx, dy) = (x2 - x1, y2 - y1);
            let nrm = if side > 0.0 { [-dy, dx] } else { [dy, -dx] };
            let len = libm::hypot(nrm[0], nrm[1]);
            if len > 0.0 {
                piece(x1, y1, x2, y2, [nrm[0] / len, nrm[1] / len], 0.5 * (draft[i] + draft[i + 1]));
            }
        }
        // The stem: to the centreline half a station ahead of the foremost station.
        let (xf, yf) = (x[n - 1], side * half_breadth[n - 1]);
        let xs = xf + 0.5 * (x[n - 1] - x[n - 2]);
        let (dx, dy) = (xs - xf, -yf);
        let nrm = if side > 0.0 { [-dy, dx] } else { [dy, -dx] };
        let len = libm::hypot(nrm[0], nrm[1]);
        if len > 0.0 {
            piece(xf, yf, xs, 0.0, [nrm[0] / len, nrm[1] / len], draft[n - 1]);
        }
    }
    // The transom: a wall across the aftmost station facing aft.
    piece(x[0], half_breadth[0], x[0], -half_breadth[0], [-1.0, 0.0], draft[0]);
    (force, moment)
}

/// Fujii and Takahashi's (1975) draft factor alpha_T = pi^2 I1^2(kT) / (pi^2 I1^2(kT) +
/// K1^2(kT)) [-]: the share of a short wave's energy a wall of draft T stops (0 for kT = 0, 1 for
/// a deep wall).
pub fn draft_factor(kt: f64) -> f64 {
    if kt.is_nan() || kt <= 0.0 {
        return 0.0;
    }
    // ratio = K1 / (pi I1), from the scaled forms above 3.75 so that neither overflows.
    let ratio = if kt < 3.75 {
        bessel_k1(kt) / (std::f64::consts::PI * bessel_i1(kt))
    } else {
        let (i_scaled, k_scaled) = (bessel_i1_scaled(kt), bessel_k1_scaled(kt));
        k_scaled / (std::f64::consts::PI * i_scaled) * libm::exp(-2.0 * kt)
    };
    1.0 / (1.0 + ratio * ratio)
}

/// Horner's rule for the polynomial with coefficients `c` (constant first) at `t`.
fn poly(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &a| acc * t + a)
}

/// The modified Bessel function I1(x) for 0 <= x < 3.75 (Abramowitz and Stegun 9.8.3, relative
/// error below 1e-7).
fn bessel_i1(x: f64) -> f64 {
    let t = (x / 3.75) * (x / 3.75);
    x * poly(&[0.5, 0.878_905_94, 0.514_988_69, 0.150_849_34, 0.026_587_33, 0.003_015_32, 0.000_324_11], t)
}

/// sqrt(x) e^{-x} I1(x) for x >= 3.75 (Abramowitz and Stegun 9.8.4).
fn bessel_i1_scaled(x: f64) -> f64 {
    let t = 3.75 / x;
    poly(
        &[
            0.398_942_28,
            -0.039_880_24,
            -0.003_620_18,
            0.001_638_01,
            -0.010_315_55,
            0.022_829_67,
            -0.028_953_12,
            0.017_876_54,
            -0.004_200_59,
        ],
        t,
    )
}

/// sqrt(x) e^{x} K1(x) for x >= 2 (Abramowitz and Stegun 9.8.8).
fn bessel_k1_scaled(x: f64) -> f64 {
    let t = 2.0 / x;
    poly(&[1.253_314_14, 0.234_986_19, -0.036_556_20, 0.015_042_68, -0.007_803_53, 0.003_256_14, -0.000_682_45], t)
}

/// The modified Bessel function K1(x) for x > 0 (Abramowitz and Stegun 9.8.7 below 2, 9.8.8
/// above).
fn bessel_k1(x: f64) -> f64 {
    if x <= 2.0 {
        let t = (x / 2.0) * (x / 2.0);
        let i1 = if x < 3.75 { bessel_i1(x) } else { bessel_i1_scaled(x) * libm::exp(x) / libm::sqrt(x) };
        (x * libm::log(x / 2.0) * i1
            + poly(&[1.0, 0.154_431_44, -0.672_785_79, -0.181_568_97, -0.019_194_02, -0.001_104_04, -0.000_046_86], t))
            / x
    } else {
        bessel_k1_scaled(x) * libm::exp(-x) / libm::sqrt(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The polynomial forms against tabulated values (Abramowitz and Stegun Table 9.8 and
    /// 9.1-style values): I1(0.5) 0.2578943054, I1(1) 0.5651591040, I1(2) 1.5906368546, I1(5)
    /// 24.33564214; K1(0.5) 1.656441120, K1(1) 0.6019072302, K1(2) 0.1398658818, K1(5)
    /// 0.004044613445. The forms promise 1e-7 relative at worst; asserted 5e-7.
    #[test]
    fn bessel_functions_match_tables() {
        let i1 = |x: f64| if x < 3.75 { bessel_i1(x) } else { bessel_i1_scaled(x) * libm::exp(x) / libm::sqrt(x) };
        for (x, want) in [(0.5, 0.257_894_305_4), (1.0, 0.565_159_104_0), (2.0, 1.590_636_854_6), (5.0, 24.335_642_14)]
        {
            assert!((i1(x) / want - 1.0).abs() < 5e-7, "I1({x}) = {}", i1(x));
        }
        for (x, want) in
            [(0.5, 1.656_441_120), (1.0, 0.601_907_230_2), (2.0, 0.139_865_881_8), (5.0, 0.004_044_613_445)]
        {
            assert!((bessel_k1(x) / want - 1.0).abs() < 5e-7, "K1({x}) = {}", bessel_k1(x));
        }
    }

    /// alpha_T rises from 0 to 1 with kT (strictly up to kT = 5), is continuous where the forms change (2 and 3.75: to
    /// 1e-6), and a deep wall (kT = 50, where I1 alone overflows nothing) stops every wave.
    #[test]
    fn draft_factor_runs_from_zero_to_one() {
        assert_eq!(draft_factor(0.0), 0.0);
        assert!(draft_factor(0.05) < 0.01);
        let mut last = 0.0;
        for i in 1..400 {
            let a = draft_factor(i as f64 * 0.025);
            // Rising, until 1 - alpha_T (about (K1 / pi I1)^2) is below a double's resolution.
            assert!(a >= last && a <= 1.0 && (a > last || i > 200), "kT {}", i as f64 * 0.025);
            last = a;
        }
        for x in [2.0, 3.75] {
            assert!((draft_factor(x - 1e-9) - draft_factor(x + 1e-9)).abs() < 1e-6, "at {x}");
        }
        assert!((draft_factor(50.0) - 1.0).abs() < 1e-15);
        assert_eq!(draft_factor(f64::NAN), 0.0);
    }

    /// A box waterline (length 100 m, beam 10 m) of great draft at rest: head seas meet the
    /// square bow, a wall 10 m wide, and the force is 1/2 rho g B exactly; beam seas meet one
    /// side, 1/2 rho g L; following seas the transom, 1/2 rho g B again; the moment of a
    /// symmetric box in head seas is the bow's x times its force. At speed in head seas the bow's
    /// force grows by 1 + 2 omega0 U / g, and in following seas the transom's falls by as much
    /// (to nothing once 2 omega0 U / g passes 1).
    #[test]
    fn a_deep_box_reflects_as_walls_do() {
        let x: Vec<f64> = (0..=20).map(|i| -50.0 + 5.0 * i as f64).collect();
        let hb = vec![5.0; x.len()];
        let t = vec![1.0e3; x.len()];
        let (rho, g, k) = (1025.0, 9.81, 1.0);
        let w0 = libm::sqrt(g * k);
        let wall = 0.5 * rho * g;
        // Closing the stem over half a station makes a wedge bow (half-angle atan(5 / 2.5)), so
        // the box's bow is the wedge: each flank meets head seas at sin(theta) = 2/sqrt(5).
        let s = 2.0 / libm::sqrt(5.0);
        let (head, m_head) = reflection_force(&x, &hb, &t, k, w0, 0.0, PI, rho, g);
        let flank = libm::hypot(2.5, 5.0);
        let want_head = 2.0 * wall * s * s * s * flank;
        assert!((head / want_head - 1.0).abs() < 1e-12, "{head} vs {want_head}");
        assert!((m_head / head - (50.0 + 1.25)).abs() < 1e-9);
        let (beam, _) = reflection_force(&x, &hb, &t, k, w0, 0.0, 0.5 * PI, rho, g);
        // One side (100 m) and the stem's starboard flank at sin(theta) = 1/sqrt(5) of its x.
        let c = 1.0 / libm::sqrt(5.0);
        let want_beam = wall * (100.0 + c * c * c * flank);
        assert!((beam / want_beam - 1.0).abs() < 1e-12, "{beam} vs {want_beam}");
        let (follow, m_follow) = reflection_force(&x, &hb, &t, k, w0, 0.0, 0.0, rho, g);
        assert!((follow / (wall * 10.0) - 1.0).abs() < 1e-12);
        assert!((m_follow / follow + 50.0).abs() < 1e-9);
        let u = 1.0;
        let f = 2.0 * w0 * u / g;
        let (head_u, _) = reflection_force(&x, &hb, &t, k, w0, u, PI, rho, g);
        // At speed each flank adds (2 omega0 U / g)(1 - cos^2 theta) = f s^2 to its s^2.
        assert!((head_u / (want_head * (1.0 + f)) - 1.0).abs() < 1e-12, "{head_u}");
        let (follow_u, _) = reflection_force(&x, &hb, &t, k, w0, u, 0.0, rho, g);
        assert!((follow_u / (wall * 10.0 * (1.0 - f)) - 1.0).abs() < 1e-12);
        let (follow_fast, _) = reflection_force(&x, &hb, &t, k, w0, g / w0, 0.0, rho, g);
        assert_eq!(follow_fast, 0.0);
    }
}
