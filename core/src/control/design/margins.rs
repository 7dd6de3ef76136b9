//! Classical stability margins of a multivariable loop, one input channel at a time: the loop is
//! broken at plant input i while the other channels stay closed, which leaves the scalar loop
//! l_i = L_ii - L_io (I + L_oo)^-1 L_oi of L = K_tot G (negative feedback). Its gain margins
//! (how far the gain of that actuator may rise or fall) and phase margin are what a controls
//! class reads off a Bode plot; they are not guaranteed margins for simultaneous changes in all
//! channels.

use crate::control::linear::{crossings, log_space, Crossing};
use nalgebra::DMatrix;
use num_complex::Complex64 as C;
use serde::Serialize;

/// The margins of the loop broken at one input.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoopMargins {
    /// Input channel (0-based).
    pub input: usize,
    /// Gain increase that makes the loop marginally stable \[dB\], at a phase crossover where
    /// |l| < 1; None when no phase crossover has |l| < 1 (unlimited upward).
    pub gain_margin_db: Option<f64>,
    /// Gain decrease that makes it marginally stable [dB, negative], at a phase crossover where
    /// |l| > 1; None when there is none (the loop tolerates any reduction).
    pub gain_reduction_margin_db: Option<f64>,
    /// Phase margin at the worst gain crossover |l| = 1 \[deg\]: 180 + arg l wrapped to
    /// (-180, 180], negative when the phase is past -180 degrees there; None when |l| never
    /// crosses 1 in the band searched.
    pub phase_margin_deg: Option<f64>,
    /// Frequency of that gain crossover [rad/s].
    pub crossover_rad_s: Option<f64>,
}

/// Search band [rad/s] and points of the crossover search (200 a decade, then bisection).
const BAND: (f64, f64, usize) = (1e-4, 1e5, 1801);
const BISECTIONS: usize = 60;

/// The scalar loop at input `i` from the full loop matrix at one frequency.
fn broken_at(l: &DMatrix<C>, i: usize) -> Option<C> {
    let m = l.nrows();
    if m == 1 {
        return Some(l[(0, 0)]);
    }
    let others: Vec<usize> = (0..m).filter(|&k| k != i).collect();
    let oo = DMatrix::<C>::from_fn(m - 1, m - 1, |r, c| {
        l[(others[r], others[c])] + if r == c { C::new(1.0, 0.0) } else { C::new(0.0, 0.0) }
    });
    let oi = DMatrix::<C>::from_fn(m - 1, 1, |r, _| l[(others[r], i)]);
    let io = DMatrix::<C>::from_fn(1, m - 1, |_, c| l[(i, others[c])]);
    let x = oo.lu().solve(&oi)?;
    Some(l[(i, i)] - (io * x)[(0, 0)])
}

/// Margins at every input of the loop `loop_at(w)` (the m x m matrix L(j w) = K_tot G at the
/// plant input): the worst over every crossing in the band. An error when the loop cannot be
/// evaluated somewhere in the band.
pub fn input_margins(m: usize, loop_at: &dyn Fn(f64) -> Option<DMatrix<C>>) -> Result<Vec<LoopMargins>, String> {
    let ws = log_space(BAND.0, BAND.1, BAND.2);
    let mut out = Vec::with_capacity(m);
    for i in 0..m {
        let scalar = |w: f64| -> Result<C, String> {
            let l = loop_at(w).ok_or_else(|| format!("the loop cannot be evaluated at {w:.3e} rad/s"))?;
            broken_at(&l, i).ok_or_else(|| format!("I + L is singular at {w:.3e} rad/s"))
        };
        let (mut gm_up, mut gm_down, mut pm): (Option<f64>, Option<f64>, Option<(f64, f64)>) = (None, None, None);
        for c in crossings(&scalar, &ws, BISECTIONS)? {
            match c {
                Crossing::Phase { l, .. } if l.re < 0.0 => {
                    let db = -20.0 * libm::log10(-l.re);
                    if db > 0.0 {
                        gm_up = Some(gm_up.map_or(db, |g: f64| g.min(db)));
                    } else {
                        gm_down = Some(gm_down.map_or(db, |g: f64| g.max(db)));
                    }
                }
                Crossing::Gain { w, l } => {
                    // Signed, as the ch. 4 tool reports it: 180 + arg l wrapped to (-180, 180], so a
                    // loop past -180 degrees at crossover shows a negative margin.
                    let mut margin = libm::atan2(l.im, l.re).to_degrees() + 180.0;
                    if margin > 180.0 {
                        margin -= 360.0;
                    }
                    if pm.is_none_or(|(best, _)| margin < best) {
                        pm = Some((margin, w));
                    }
                }
                _ => {}
            }
        }
        out.push(LoopMargins {
            input: i,
            gain_margin_db: gm_up,
            gain_reduction_margin_db: gm_down,
            phase_margin_deg: pm.map(|p| p.0),
            crossover_rad_s: pm.map(|p| p.1),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// l(s) = k / (s (s + 1)^2): phase crossover at 1 rad/s where |l| = k/2, so the gain margin
    /// is 20 log10(2/k); with k = 0.5 that is 12.04 dB. The gain crossover w_c solves
    /// k / (w (1 + w^2)) = 1 and the phase margin is 90 - 2 atan(w_c) degrees. Tolerances 1e-9
    /// and 1e-7 degrees (bisection to 60 halvings).
    #[test]
    fn third_order_loop() {
        let k = 0.5;
        let l = |w: f64| {
            let s = C::new(0.0, w);
            Some(DMatrix::from_element(1, 1, C::new(k, 0.0) / (s * (s + 1.0) * (s + 1.0))))
        };
        let m = &input_margins(1, &l).unwrap()[0];
        let gm = m.gain_margin_db.unwrap();
        assert!((gm - 20.0 * libm::log10(2.0 / k)).abs() < 1e-9, "{gm}");
        assert!(m.gain_reduction_margin_db.is_none());
        let wc = m.crossover_rad_s.unwrap();
        assert!((k / (wc * (1.0 + wc * wc)) - 1.0).abs() < 1e-9, "{wc}");
        let pm = 90.0 - 2.0 * libm::atan(wc).to_degrees();
        assert!((m.phase_margin_deg.unwrap() - pm).abs() < 1e-7, "{:?} vs {pm}", m.phase_margin_deg);
        // k = 4: unstable. The phase crossover has |l| = 2 (a gain reduction margin of -6.02 dB)
        // and the phase margin is negative, 90 - 2 atan(w_c) = -18.2 degrees.
        let l4 = |w: f64| {
            let s = C::new(0.0, w);
            Some(DMatrix::from_element(1, 1, C::new(4.0, 0.0) / (s * (s + 1.0) * (s + 1.0))))
        };
        let m4 = &input_margins(1, &l4).unwrap()[0];
        assert!(m4.gain_margin_db.is_none());
        assert!((m4.gain_reduction_margin_db.unwrap() + 20.0 * libm::log10(2.0)).abs() < 1e-9);
        let wc4 = m4.crossover_rad_s.unwrap();
        let pm4 = 90.0 - 2.0 * libm::atan(wc4).to_degrees();
        assert!(pm4 < -18.0 && (m4.phase_margin_deg.unwrap() - pm4).abs() < 1e-7, "{:?} vs {pm4}", m4.phase_margin_deg);
    }

    /// Two decoupled loops: breaking one leaves exactly that loop's scalar margins.
    #[test]
    fn decoupled_loops_give_their_own_margins() {
        let l = |w: f64| {
            let s = C::new(0.0, w);
            let mut m = DMatrix::from_element(2, 2, C::new(0.0, 0.0));
            m[(0, 0)] = C::new(0.5, 0.0) / (s * (s + 1.0) * (s + 1.0));
            m[(1, 1)] = C::new(1.0, 0.0) / (s * (s + 1.0) * (s + 1.0));
            Some(m)
        };
        let ms = input_margins(2, &l).unwrap();
        assert!((ms[0].gain_margin_db.unwrap() - 20.0 * libm::log10(4.0)).abs() < 1e-9);
        assert!((ms[1].gain_margin_db.unwrap() - 20.0 * libm::log10(2.0)).abs() < 1e-9);
    }
}
