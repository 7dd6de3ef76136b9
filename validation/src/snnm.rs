//! The added resistance of ITTC 2021's recommended semi-empirical method, SNNM (Liu and
//! Papanikolaou 2020, "Regression analysis of experimental data for added resistance in waves of
//! arbitrary heading and development of a semi-empirical formula", Ocean Engineering 206, 107357;
//! ITTC 7.5-04-01-01.1, 2021): a motion part R_AWM fitted to model tests of many hulls and a
//! reflection part R_AWR (Faltinsen's short-wave formula over a waterline of wedge ends, the
//! entrance and run angles E1 and E2, with empirical factors). Written from the published formula
//! for the comparison in the validation report only: the runs use their own strip theory.
//!
//! Headings as in the simulator's strip theory: alpha = pi head seas, 0 following seas.

use std::f64::consts::PI;

/// What SNNM needs of a hull.
#[derive(Debug, Clone, Copy)]
pub struct SnnmHull {
    /// Length between perpendiculars, beam, mean draught [m].
    pub lpp: f64,
    pub beam: f64,
    pub draft: f64,
    /// Trim |T_aft - T_fore| [m] (0 on an even keel).
    pub trim: f64,
    /// Block coefficient [-].
    pub cb: f64,
    /// Pitch radius of gyration over Lpp [-].
    pub kyy: f64,
    /// Lengths of entrance and run [m]: from the ends to where the waterline reaches 99 % of its
    /// largest beam.
    pub entrance: f64,
    pub run: f64,
}

/// Liu and Papanikolaou's a1 and a2 at heading `alpha` in [pi/2, pi] and Froude number `fr`.
fn a1_a2_bow(h: &SnnmHull, alpha: f64, fr: f64) -> (f64, f64) {
    let c = libm::cos(alpha);
    let a1 = 60.3
        * libm::pow(h.cb, 1.34)
        * (4.0 * h.kyy)
        * (4.0 * h.kyy)
        * libm::pow(0.87 / h.cb, -(1.0 + fr) * c)
        * (1.0 - 2.0 * c)
        / (3.0 * libm::log(h.beam / h.draft));
    (a1, a2_of(fr))
}

fn a2_of(fr: f64) -> f64 {
    if fr < 0.12 {
        0.0072 + 0.1676 * fr
    } else {
        libm::pow(fr, 1.5) * libm::exp(-3.5 * fr)
    }
}

/// a1 and a2 in following seas (alpha = 0) at ship speed `u` against the waves' phase speed `c`:
/// at rest as at rest in head seas mirrored, none at c/4, as in head seas at c/2 (the ship meets
/// the waves from behind as if at rest), linear in between, and beyond c/2 as head seas at the
/// speed in excess of c/2.
fn a1_a2_following(h: &SnnmHull, u: f64, c: f64, g: f64) -> (f64, f64) {
    let rest = (a1_a2_bow(h, 0.0, 0.0).0, 0.0072);
    let quarter = (0.0, a2_of(u / libm::sqrt(g * h.lpp)));
    let half = (a1_a2_bow(h, PI, 0.0).0, 0.0072);
    let lerp = |a: (f64, f64), b: (f64, f64), t: f64| (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
    if u <= 0.0 {
        rest
    } else if u < 0.25 * c {
        lerp(rest, quarter, u / (0.25 * c))
    } else if u < 0.5 * c {
        lerp(quarter, half, (u - 0.25 * c) / (0.25 * c))
    } else {
        a1_a2_bow(h, PI, (u - 0.5 * c) / libm::sqrt(g * h.lpp))
    }
}

/// The motion part R_AWM / (rho g zeta^2 B^2 / L) at wave length `lambda` [m], heading `alpha`
/// [rad] and ship speed `u` [m/s].
pub fn motion_part(h: &SnnmHull, lambda: f64, alpha: f64, u: f64, g: f64) -> f64 {
    let fr = u / libm::sqrt(g * h.lpp);
    let c = libm::sqrt(g * lambda / (2.0 * PI));
    let alpha = alpha.rem_euclid(2.0 * PI);
    let alpha = if alpha > PI { 2.0 * PI - alpha } else { alpha };
    let (a1, a2) = if alpha >= 0.5 * PI {
        a1_a2_bow(h, alpha, fr)
    } else {
        // Linear in heading between beam seas and following seas.
        let beam = a1_a2_bow(h, 0.5 * PI, fr);
        let follow = a1_a2_following(h, u, c, g);
        let t = alpha / (0.5 * PI);
        (follow.0 + (beam.0 - follow.0) * t, follow.1 + (beam.1 - follow.1) * t)
    };
    let trim = libm::atan(h.trim / h.lpp);
    let a3 = 1.0 + 28.7 * trim;
    let ca = libm::cos(alpha);
    let w = 2.142
        * libm::cbrt(h.kyy)
        * libm::sqrt(h.lpp / lambda)
        * (1.0 - 0.111 / h.cb * (libm::log(h.beam / h.draft) - libm::log(2.75)))
        * libm::pow(h.cb / 0.65, 0.17)
        * ((-1.377 * fr * fr + 1.157 * fr) * ca.abs() + 0.618 * (13.0 + libm::cos(2.0 * alpha)) / 14.0);
    let (b1, d1) = if w < 1.0 {
        (11.0, 566.0 * libm::pow(h.lpp * h.cb / h.beam, -2.66))
    } else {
        (-8.5, -566.0 * libm::pow(h.lpp / h.beam, -2.66) * (4.0 - 125.0 * trim))
    };
    4.0 * a1 * a2 * a3 * libm::pow(w, b1) * libm::exp(b1 / d1 * (1.0 - libm::pow(w, d1)))
}

/// The reflection part R_AWR / (rho g zeta^2 B^2 / L).
pub fn reflection_part(h: &SnnmHull, lambda: f64, alpha: f64, u: f64, g: f64) -> f64 {
    let fr = u / libm::sqrt(g * h.lpp);
    let alpha = alpha.rem_euclid(2.0 * PI);
    let alpha = if alpha > PI { 2.0 * PI - alpha } else { alpha };
    let omega = libm::sqrt(2.0 * PI * g / lambda);
    let sp = 2.0 * omega * u / g;
    let e1 = libm::atan(0.495 * h.beam / h.entrance);
    let e2 = libm::atan(0.495 * h.beam / h.run);
    // The draft factor: 1 - exp(-4 pi (T/lambda - T/(2.5 L))), none past lambda = 2.5 L.
    let alpha_t = |t: f64| {
        if lambda / h.lpp <= 2.5 {
            1.0 - libm::exp(-4.0 * PI * (t / lambda - t / (2.5 * h.lpp)))
        } else {
            0.0
        }
    };
    let f = if alpha >= PI - e1 { -libm::cos(alpha) } else { 0.0 };
    let bow_factor = libm::pow(0.87 / h.cb, (1.0 + 4.0 * libm::sqrt(fr)) * f);
    let t_stern = if h.cb <= 0.75 {
        h.draft * (4.0 + libm::sqrt(libm::cos(alpha).abs())) / 5.0
    } else {
        h.draft * (2.0 + libm::sqrt(libm::cos(alpha).abs())) / 3.0
    };
    let part = |e: f64, angle: f64| {
        let s = libm::sin(angle);
        s * s + sp * (libm::cos(e) * libm::cos(angle) - libm::cos(alpha))
    };
    let k = 2.25 / 4.0 * h.beam;
    let mut r = 0.0;
    if alpha >= e1 {
        r += k * alpha_t(h.draft) * part(e1, e1 - alpha) * bow_factor;
    }
    if alpha >= PI - e1 {
        r += k * alpha_t(h.draft) * part(e1, e1 + alpha) * bow_factor;
    }
    if alpha <= PI - e2 {
        r -= k * alpha_t(t_stern) * part(e2, e2 + alpha);
    }
    if alpha <= e2 {
        r -= k * alpha_t(t_stern) * part(e2, e2 - alpha);
    }
    r * h.lpp / (h.beam * h.beam)
}

/// SNNM's added resistance per wave amplitude squared [N/m^2] at wave frequency `omega` [rad/s].
pub fn added_resistance(h: &SnnmHull, omega: f64, alpha: f64, u: f64, rho: f64, g: f64) -> f64 {
    let lambda = 2.0 * PI * g / (omega * omega);
    let norm = rho * g * h.beam * h.beam / h.lpp;
    norm * (motion_part(h, lambda, alpha, u, g) + reflection_part(h, lambda, alpha, u, g))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hull() -> SnnmHull {
        SnnmHull { lpp: 142.0, beam: 19.06, draft: 6.15, trim: 0.0, cb: 0.507, kyy: 0.25, entrance: 50.0, run: 40.0 }
    }

    /// Head seas in short waves at rest: only the bow reflects, and the reflection part is the
    /// wedge's Faltinsen force times SNNM's 2.25 and (0.87/C_B)^1: 2.25 (1/2) B alpha_T
    /// sin^2(E1) (0.87/C_B) over B^2/L (to 1e-12). Beam seas: the bow's and the stern's parts
    /// cancel to within their drafts' difference (the stern's is 4/5 of the draft abeam; measured
    /// 7 % of one flank's force at lambda/L 0.2, asserted 10 %), and the motion part of a fast ship
    /// in head seas peaks near lambda/L = 1 (between 0.6 and 1.6).
    #[test]
    fn the_formula_has_its_limits() {
        let h = hull();
        let g = 9.81;
        let lambda = 0.2 * h.lpp;
        let e1 = libm::atan(0.495 * h.beam / h.entrance);
        let at = 1.0 - libm::exp(-4.0 * PI * (h.draft / lambda - h.draft / (2.5 * h.lpp)));
        let want = 2.25 * 0.5 * h.beam * at * libm::sin(e1) * libm::sin(e1) * (0.87 / h.cb) * h.lpp / (h.beam * h.beam);
        let got = reflection_part(&h, lambda, PI, 0.0, g);
        assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
        let beam = reflection_part(&h, lambda, 0.5 * PI, 0.0, g);
        let flank = 2.25 / 4.0 * h.beam * at * libm::cos(e1) * libm::cos(e1) * h.lpp / (h.beam * h.beam);
        assert!(beam.abs() < 0.1 * flank, "{beam} against one flank's {flank}");
        let u = 0.28 * libm::sqrt(g * h.lpp);
        let (mut best, mut at_l) = (f64::MIN, 0.0);
        for i in 0..200 {
            let l = 0.3 + 0.01 * i as f64;
            let m = motion_part(&h, l * h.lpp, PI, u, g);
            if m > best {
                (best, at_l) = (m, l);
            }
        }
        assert!((0.6..1.6).contains(&at_l) && best > 1.0, "{best} at {at_l}");
    }
}
