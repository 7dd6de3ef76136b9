//! Modal model reduction (thesis ch. 3.1: the F100 model was reduced before the design). The
//! plant is put in modal form, A = V diag(lambda) V^-1, so that G(s) = D + sum_i R_i / (s - lambda_i)
//! with residues R_i = (C v_i)(w_i B); modes faster than a bandwidth, or whose peak contribution
//! |R_i| / |Re lambda_i| is small beside the plant's peak gain, are dropped. Dropped modes may leave
//! their DC gain behind in D (`match_dc`, residualisation), so the reduced plant keeps the steady
//! state that the integral action and Gamma = Re{G(j omega_p)^-1} rest on. The realisation is
//! real: a conjugate pair becomes the block [[sigma, -omega], [omega, sigma]].

use super::state_space::StateSpace;
use crate::control::linear::log_space;
use crate::numerics::complex::cabs;
use nalgebra::DMatrix;
use num_complex::Complex64 as C;
use serde::{Deserialize, Serialize};

/// What to drop.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReduceOptions {
    /// Drop modes with |lambda| above this [rad/s].
    #[serde(default)]
    pub max_frequency_rad_s: Option<f64>,
    /// Drop modes whose peak contribution |R_i| / |Re lambda_i| is below this fraction of the
    /// plant's peak singular value over the frequency grid.
    #[serde(default)]
    pub min_relative_residue: Option<f64>,
    /// Keep the dropped modes' DC gain in D (default true).
    #[serde(default = "yes")]
    pub match_dc: bool,
}

fn yes() -> bool {
    true
}

/// A dropped mode and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DroppedMode {
    pub re: f64,
    pub im: f64,
    /// "fast" or "small residue".
    pub reason: String,
    /// Its peak contribution relative to the plant's peak gain [-].
    pub relative_residue: f64,
}

/// What the reduction did and the error it makes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReductionReport {
    pub states_full: usize,
    pub states_kept: usize,
    pub dropped: Vec<DroppedMode>,
    /// max over the grid of sigma_max(G - G_r) / max over the grid of sigma_max(G) [-].
    pub max_relative_error: f64,
    /// Where that largest error is [rad/s].
    pub frequency_of_max_error_rad_s: f64,
    /// sigma_max(G(0) - G_r(0)) / sigma_max(G(0)) [-] (0 with `match_dc` and stable dropped modes).
    pub dc_relative_error: f64,
}

/// Eigenvector of `a` for eigenvalue `l` by inverse iteration with a slightly shifted pivot.
fn eigenvector(a: &DMatrix<f64>, l: C) -> Option<nalgebra::DVector<C>> {
    let n = a.nrows();
    let shift = l + C::new(1e-10 * (1.0 + cabs(l)), 0.0);
    let m = DMatrix::<C>::from_fn(n, n, |i, j| C::new(a[(i, j)], 0.0) - if i == j { shift } else { C::new(0.0, 0.0) });
    let lu = m.lu();
    let mut v = nalgebra::DVector::<C>::from_fn(n, |i, _| C::new(1.0 / (i + 1) as f64, 0.0));
    for _ in 0..3 {
        v = lu.solve(&v)?;
        let nv = v.norm();
        if !(nv.is_finite() && nv > 0.0) {
            return None;
        }
        v /= C::new(nv, 0.0);
    }
    Some(v)
}

/// Largest singular value of a complex matrix.
fn sigma_max(m: &DMatrix<C>) -> f64 {
    crate::numerics::singular_values(m).and_then(|s| s.first().copied()).unwrap_or(f64::INFINITY)
}

/// Reduces `g` as `opt` says, with the error measured on the grid `ws` [rad/s].
pub fn reduce(g: &StateSpace, opt: &ReduceOptions, ws: &[f64]) -> Result<(StateSpace, ReductionReport), String> {
    for (name, v) in
        [("max_frequency_rad_s", opt.max_frequency_rad_s), ("min_relative_residue", opt.min_relative_residue)]
    {
        if let Some(x) = v {
            if !(x.is_finite() && x > 0.0) {
                return Err(format!("reduce.{name} = {x}: must be a number above 0"));
            }
        }
    }
    let (n, m) = (g.a.nrows(), g.b.ncols());
    let lam = crate::numerics::eigenvalues(&g.a).ok_or("reduce: the eigenvalues of A did not converge")?;
    let scale = lam.iter().map(|&l| cabs(l)).fold(1.0, f64::max);
    for i in 0..n {
        for j in 0..i {
            if cabs(lam[i] - lam[j]) <= 1e-8 * scale {
                return Err(format!(
                    "reduce: A has a repeated eigenvalue ({:.4e} {:+.4e}j); modal reduction needs distinct modes",
                    lam[i].re, lam[i].im
                ));
            }
        }
    }
    let is_real = |l: C| l.im.abs() <= 1e-12 * scale;
    // Eigenvectors: conjugate pairs share one computation.
    let mut v = DMatrix::<C>::zeros(n, n);
    for (i, &l) in lam.iter().enumerate() {
        let col = if l.im < 0.0 && !is_real(l) {
            eigenvector(&g.a, l.conj()).map(|x| x.map(|z| z.conj()))
        } else {
            eigenvector(&g.a, l)
        }
        .ok_or("reduce: an eigenvector could not be found")?;
        v.set_column(i, &col);
    }
    let a_c = g.a.map(|x| C::new(x, 0.0));
    let resid = (&a_c * &v - &v * DMatrix::from_diagonal(&nalgebra::DVector::from_vec(lam.clone()))).norm();
    let w = v.clone().try_inverse().ok_or("reduce: A is not diagonalisable (its eigenvectors are dependent)")?;
    if resid.is_nan() || resid > 1e-8 * scale * v.norm() || !w.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
        return Err("reduce: A is too close to a defective matrix for a modal form".into());
    }
    let bm = &w * g.b.map(|x| C::new(x, 0.0));
    let cm = g.c.map(|x| C::new(x, 0.0)) * &v;
    let residue = |i: usize| cm.column(i) * bm.row(i);
    let peak_g = ws.iter().map(|&w| g.response(w).map_or(0.0, |r| sigma_max(&r))).fold(0.0, f64::max);
    // Keep or drop each mode (unstable and marginal modes always stay: the design must see them).
    let mut keep = vec![true; n];
    let mut why: Vec<Option<&'static str>> = vec![None; n];
    let mut rel = vec![f64::INFINITY; n];
    for i in 0..n {
        let l = lam[i];
        if l.re < 0.0 {
            rel[i] = sigma_max(&residue(i)) / -l.re / peak_g.max(1e-300);
        }
        why[i] = if l.re >= 0.0 {
            None
        } else if opt.max_frequency_rad_s.is_some_and(|f| cabs(l) > f) {
            Some("fast")
        } else if opt.min_relative_residue.is_some_and(|r| rel[i] < r) {
            Some("small residue")
        } else {
            None
        };
        keep[i] = why[i].is_none();
    }
    // A pair goes or stays together (its members have the same |lambda| and residue size, but
    // guard against rounding).
    for i in 0..n {
        if !is_real(lam[i]) && lam[i].im > 0.0 {
            if let Some(j) = (0..n).find(|&j| j != i && cabs(lam[j] - lam[i].conj()) <= 1e-8 * scale) {
                let k = keep[i] && keep[j];
                keep[i] = k;
                keep[j] = k;
                if !k {
                    let w = why[i].or(why[j]);
                    why[i] = w;
                    why[j] = w;
                }
            }
        }
    }
    let dropped: Vec<DroppedMode> = (0..n)
        .filter(|&i| !keep[i])
        .map(|i| DroppedMode {
            re: lam[i].re,
            im: lam[i].im,
            reason: why[i].unwrap_or("fast").into(),
            relative_residue: rel[i],
        })
        .collect();
    if keep.iter().all(|k| !k) {
        return Err("reduce: every mode would be dropped; keep at least one (raise max_frequency_rad_s or lower \
                    min_relative_residue)"
            .into());
    }
    // Real realisation of the kept modes.
    let reps: Vec<usize> = (0..n).filter(|&i| keep[i] && (is_real(lam[i]) || lam[i].im > 0.0)).collect();
    let nr: usize = reps.iter().map(|&i| if is_real(lam[i]) { 1 } else { 2 }).sum();
    let (mut a, mut b, mut c) = (DMatrix::zeros(nr, nr), DMatrix::zeros(nr, m), DMatrix::zeros(m, nr));
    let mut k = 0;
    for &i in &reps {
        let l = lam[i];
        if is_real(l) {
            a[(k, k)] = l.re;
            for j in 0..m {
                b[(k, j)] = bm[(i, j)].re;
                c[(j, k)] = cm[(j, i)].re;
            }
            k += 1;
        } else {
            a[(k, k)] = l.re;
            a[(k, k + 1)] = -l.im;
            a[(k + 1, k)] = l.im;
            a[(k + 1, k + 1)] = l.re;
            for j in 0..m {
                b[(k, j)] = bm[(i, j)].re;
                b[(k + 1, j)] = bm[(i, j)].im;
                c[(j, k)] = 2.0 * cm[(j, i)].re;
                c[(j, k + 1)] = -2.0 * cm[(j, i)].im;
            }
            k += 2;
        }
    }
    let mut d = g.d.clone();
    if opt.match_dc {
        for i in (0..n).filter(|&i| !keep[i]) {
            d += (-residue(i) / lam[i]).map(|z| z.re);
        }
    }
    let red = StateSpace { a, b, c, d };
    let err_at = |w: f64| -> f64 {
        match (g.response(w), red.response(w)) {
            (Some(x), Some(y)) => sigma_max(&(x - y)),
            _ => f64::INFINITY,
        }
    };
    let (mut worst, mut at) = (0.0, ws.first().copied().unwrap_or(0.0));
    for &w in ws {
        let e = err_at(w);
        if e > worst {
            worst = e;
            at = w;
        }
    }
    let dc = g.response(0.0).map_or(f64::INFINITY, |r| sigma_max(&r));
    let report = ReductionReport {
        states_full: n,
        states_kept: nr,
        dropped,
        max_relative_error: worst / peak_g.max(1e-300),
        frequency_of_max_error_rad_s: at,
        dc_relative_error: if dc > 0.0 && dc.is_finite() { err_at(0.0) / dc } else { 0.0 },
    };
    Ok((red, report))
}

/// The default error grid [rad/s]: 1e-2 to 1e3, 200 points (the singular-value plots' grid).
pub fn default_grid() -> Vec<f64> {
    log_space(1e-2, 1e3, 200)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// G = 1/(s+1) + 50/(s+100): dropping the fast mode with DC matching leaves
    /// 1/(s+1) + 0.5, whose error 0.5 w / |j w + 100| grows to the top of the grid (1000 rad/s:
    /// 0.4975, over the peak gain on the grid, |G(0.01 j)| = 1.49993). To 1e-12.
    #[test]
    fn drops_a_fast_real_mode_and_keeps_dc() {
        let g = StateSpace {
            a: DMatrix::from_row_slice(2, 2, &[-1.0, 0.0, 0.0, -100.0]),
            b: DMatrix::from_row_slice(2, 1, &[1.0, 50.0]),
            c: DMatrix::from_row_slice(1, 2, &[1.0, 1.0]),
            d: DMatrix::zeros(1, 1),
        };
        let opt = ReduceOptions { max_frequency_rad_s: Some(10.0), min_relative_residue: None, match_dc: true };
        let (r, rep) = reduce(&g, &opt, &default_grid()).unwrap();
        assert_eq!((rep.states_full, rep.states_kept, rep.dropped.len()), (2, 1, 1));
        assert!((r.d[(0, 0)] - 0.5).abs() < 1e-12 && rep.dc_relative_error < 1e-12);
        let s = C::new(0.0, 0.01);
        let peak = cabs(C::new(1.0, 0.0) / (s + 1.0) + C::new(50.0, 0.0) / (s + 100.0));
        let want = 0.5 * 1000.0 / libm::hypot(1000.0, 100.0) / peak;
        assert!((rep.max_relative_error - want).abs() < 1e-12, "{} vs {want}", rep.max_relative_error);
        assert!((rep.frequency_of_max_error_rad_s - 1000.0).abs() < 1e-9);
    }

    /// A lightly damped pair (omega 2 rad/s, zeta 0.1) and a fast real mode at -80, mixed by a
    /// similarity transform: the reduced model is the pair alone, equal to
    /// 4 / (s^2 + 0.4 s + 4) + DC of the fast mode, to 1e-10 at every grid frequency.
    #[test]
    fn keeps_a_mixed_pair_exactly() {
        let a0 = DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, -4.0, -0.4, 0.0, 0.0, 0.0, -80.0]);
        let b0 = DMatrix::from_row_slice(3, 1, &[0.0, 4.0, 8.0]);
        let c0 = DMatrix::from_row_slice(1, 3, &[1.0, 0.0, 1.0]);
        let t = DMatrix::from_row_slice(3, 3, &[1.0, 0.3, -0.2, 0.1, 1.0, 0.4, -0.5, 0.2, 1.0]);
        let ti = t.clone().try_inverse().unwrap();
        let g = StateSpace { a: &t * a0 * &ti, b: &t * b0, c: c0 * &ti, d: DMatrix::zeros(1, 1) };
        let opt = ReduceOptions { max_frequency_rad_s: Some(10.0), min_relative_residue: None, match_dc: true };
        let (r, rep) = reduce(&g, &opt, &default_grid()).unwrap();
        assert_eq!(rep.states_kept, 2);
        for w in default_grid() {
            let s = C::new(0.0, w);
            let want = C::new(4.0, 0.0) / (s * s + s * 0.4 + 4.0) + 0.1;
            let got = r.response(w).unwrap()[(0, 0)];
            assert!(cabs(got - want) < 1e-10, "w {w}: {got} vs {want}");
        }
    }

    /// A reduction that would keep nothing is refused with a clear message (it used to reach a
    /// 0 x 0 solve).
    #[test]
    fn dropping_every_mode_is_refused() {
        let g = StateSpace {
            a: DMatrix::from_element(1, 1, -100.0),
            b: DMatrix::from_element(1, 1, 100.0),
            c: DMatrix::from_element(1, 1, 1.0),
            d: DMatrix::zeros(1, 1),
        };
        let opt = ReduceOptions { max_frequency_rad_s: Some(10.0), min_relative_residue: None, match_dc: true };
        assert!(reduce(&g, &opt, &default_grid()).unwrap_err().contains("every mode"));
    }

    #[test]
    fn repeated_modes_are_refused() {
        let g = StateSpace {
            a: DMatrix::from_row_slice(2, 2, &[-1.0, 1.0, 0.0, -1.0]),
            b: DMatrix::from_row_slice(2, 1, &[0.0, 1.0]),
            c: DMatrix::from_row_slice(1, 2, &[1.0, 0.0]),
            d: DMatrix::zeros(1, 1),
        };
        let opt = ReduceOptions { max_frequency_rad_s: Some(0.5), min_relative_residue: None, match_dc: true };
        assert!(reduce(&g, &opt, &default_grid()).unwrap_err().contains("repeated"));
    }
}
