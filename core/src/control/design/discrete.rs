//! Zero-order-hold discretisation: a continuous system x' = A x + B u whose input is held
//! between samples T apart is exactly x[k+1] = Phi x\[k\] + Gamma u\[k\], with Phi = e^(A T) and
//! Gamma = (integral from 0 to T of e^(A s) ds) B. Both come from one exponential of the block
//! matrix [[A, B], [0, 0]] T (Van Loan 1978), by Pade scaling and squaring (nalgebra's own
//! exponential needs its std feature, which would bring run-time SIMD dispatch into every matrix
//! product and break native/wasm bit identity).

use nalgebra::DMatrix;

/// Phi and Gamma of `a`, `b` held over `ts` \[s\]; an error if the exponential is not finite.
pub fn zero_order_hold(a: &DMatrix<f64>, b: &DMatrix<f64>, ts: f64) -> Result<(DMatrix<f64>, DMatrix<f64>), String> {
    let (n, m) = (a.nrows(), b.ncols());
    if a.ncols() != n || b.nrows() != n {
        return Err(format!("zero-order hold: A is {}x{}, B {}x{}", n, a.ncols(), b.nrows(), m));
    }
    if !(ts.is_finite() && ts > 0.0) {
        return Err(format!("zero-order hold: sample period {ts} s must be above 0"));
    }
    let mut blk = DMatrix::zeros(n + m, n + m);
    blk.view_mut((0, 0), (n, n)).copy_from(&(a * ts));
    blk.view_mut((0, n), (n, m)).copy_from(&(b * ts));
    let e = expm(&blk);
    if !e.iter().all(|v| v.is_finite()) {
        return Err("zero-order hold: the matrix exponential overflowed (a mode too fast for the sample period)".into());
    }
    Ok((e.view((0, 0), (n, n)).into_owned(), e.view((0, n), (n, m)).into_owned()))
}

/// Order of the diagonal Pade approximant: with ||X||_1 <= 1/2 its relative error bound is
/// about 3.4e-16 (Moler and Van Loan 2003, eq. for (p, q) = (6, 6)), at double precision.
const PADE: usize = 6;

/// e^X by the [6/6] Pade approximant of X / 2^s, squared s times, with s chosen so that
/// ||X / 2^s||_1 <= 1/2.
pub fn expm(x: &DMatrix<f64>) -> DMatrix<f64> {
    let n = x.nrows();
    let norm1 = (0..n).map(|j| x.column(j).iter().map(|v| v.abs()).sum::<f64>()).fold(0.0, f64::max);
    if !norm1.is_finite() {
        return DMatrix::from_element(n, n, f64::NAN);
    }
    let mut s = 0i32;
    let mut scaled = norm1;
    while scaled > 0.5 && s < 1100 {
        scaled *= 0.5;
        s += 1;
    }
    let xs = x * libm::ldexp(1.0, -s);
    let (mut num, mut den) = (DMatrix::identity(n, n), DMatrix::identity(n, n));
    let (mut c, mut power) = (1.0, DMatrix::identity(n, n));
    for k in 1..=PADE {
        c *= (PADE - k + 1) as f64 / (k * (2 * PADE - k + 1)) as f64;
        power = &power * &xs;
        num += &power * c;
        den += &power * if k % 2 == 0 { c } else { -c };
    }
    let mut e = match den.lu().solve(&num) {
        Some(e) => e,
        None => return DMatrix::from_element(n, n, f64::NAN),
    };
    for _ in 0..s {
        e = &e * &e;
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Scalar: Phi = e^(aT), Gamma = (e^(aT) - 1) / a b, to 1e-14 relative (measured 1e-16).
    #[test]
    fn scalar_closed_form() {
        for (a, b, ts) in [(-3.0, 2.0, 0.005), (-250.0, 1.0, 0.005), (0.7, -1.5, 0.1)] {
            let (phi, gam) =
                zero_order_hold(&DMatrix::from_element(1, 1, a), &DMatrix::from_element(1, 1, b), ts).unwrap();
            let e = libm::exp(a * ts);
            assert!((phi[(0, 0)] - e).abs() <= 1e-14 * e, "{a}: {} vs {e}", phi[(0, 0)]);
            let g = (e - 1.0) / a * b;
            assert!((gam[(0, 0)] - g).abs() <= 1e-14 * g.abs(), "{a}: {} vs {g}", gam[(0, 0)]);
        }
    }

    /// A rotation generator: e^(theta J) is the rotation by theta, to 1e-14.
    #[test]
    fn rotation() {
        let th = 7.3;
        let e = expm(&DMatrix::from_row_slice(2, 2, &[0.0, -th, th, 0.0]));
        let want = DMatrix::from_row_slice(2, 2, &[libm::cos(th), -libm::sin(th), libm::sin(th), libm::cos(th)]);
        assert!((e - want).amax() < 1e-14);
    }

    /// A double integrator x'' = u: Phi = [[1, T], [0, 1]], Gamma = [T^2/2, T], to 1e-15.
    #[test]
    fn double_integrator() {
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
        let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
        let ts = 0.2;
        let (phi, gam) = zero_order_hold(&a, &b, ts).unwrap();
        let want_phi = DMatrix::from_row_slice(2, 2, &[1.0, ts, 0.0, 1.0]);
        let want_gam = DMatrix::from_row_slice(2, 1, &[ts * ts / 2.0, ts]);
        assert!((phi - want_phi).amax() < 1e-15 && (gam - want_gam).amax() < 1e-15);
    }
}
