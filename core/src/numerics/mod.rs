//! Small numerical helpers shared by the physics modules.

pub mod complex;
pub mod fft;
pub mod interp;
pub mod units;

/// Bisection for a sign change of `f` between `lo` and `hi`: `iterations` halvings, returns the
/// midpoint of the last bracket. The side that keeps `lo` is the one with the sign of `f(lo)`.
pub fn bisect(f: impl Fn(f64) -> f64, lo: f64, hi: f64, iterations: u32) -> f64 {
    let (mut a, mut b) = (lo, hi);
    let positive_at_lo = f(a) > 0.0;
    for _ in 0..iterations {
        let m = 0.5 * (a + b);
        // The midpoint of adjacent (or equal) ends is one of them, bit for bit: after this
        // halving every further one leaves (a, b) as it is, so stopping then changes no bit of
        // the answer.
        let last = m.to_bits() == a.to_bits() || m.to_bits() == b.to_bits();
        if (f(m) > 0.0) == positive_at_lo {
            a = m;
        } else {
            b = m;
        }
        if last {
            break;
        }
    }
    0.5 * (a + b)
}

/// x^n by repeated squaring, in the order LLVM expands `f64::powi` with a constant exponent
/// (x^4 = (x x)(x x), x^5 = x ((x x)(x x))), so replacing such a `powi` by this kept every preset's
/// numbers (the golden test). Plain multiplications in a fixed order: the same in every build,
/// unlike `powi`, whose lowering is up to the optimizer (or a runtime call).
pub fn powi(x: f64, n: u32) -> f64 {
    let (mut result, mut square, mut n) = (1.0, x, n);
    while n > 0 {
        if n & 1 == 1 {
            result *= square;
        }
        n >>= 1;
        if n > 0 {
            square *= square;
        }
    }
    result
}

/// One classical fourth-order Runge-Kutta step of dx/dt = f(t, x) from `t` over `dt` \[s\], the
/// stability tool's integrator and the simulator's default (`stepping.integrator`). `f(t, y, dx)` writes the derivative into
/// every entry of `dx`. With a fixed-size array state nothing is allocated.
pub fn rk4<S>(x: &mut S, t: f64, dt: f64, mut f: impl FnMut(f64, &S, &mut S))
where
    S: Clone + AsRef<[f64]> + AsMut<[f64]>,
{
    let n = x.as_ref().len();
    // One buffer for the stages' slopes and the weighted sum k1 + 2 k2 + 2 k3 (+ k4) formed as
    // they come, added in that order: the same bits as keeping all four.
    let (mut k, mut y) = (x.clone(), x.clone());
    f(t, x, &mut k);
    let mut sum = k.clone();
    for i in 0..n {
        y.as_mut()[i] = x.as_ref()[i] + 0.5 * dt * k.as_ref()[i];
    }
    f(t + 0.5 * dt, &y, &mut k);
    for i in 0..n {
        sum.as_mut()[i] += 2.0 * k.as_ref()[i];
        y.as_mut()[i] = x.as_ref()[i] + 0.5 * dt * k.as_ref()[i];
    }
    f(t + 0.5 * dt, &y, &mut k);
    for i in 0..n {
        sum.as_mut()[i] += 2.0 * k.as_ref()[i];
        y.as_mut()[i] = x.as_ref()[i] + dt * k.as_ref()[i];
    }
    f(t + dt, &y, &mut k);
    let (sum, k) = (sum.as_ref(), k.as_ref());
    for (i, xi) in x.as_mut().iter_mut().enumerate() {
        *xi += dt / 6.0 * (sum[i] + k[i]);
    }
}

/// One explicit midpoint (second-order Runge-Kutta) step of dx/dt = f(t, x) from `t` over `dt`
/// \[s\]: the slope at the half step, found from the start's, carries the whole step. Two
/// evaluations instead of RK4's four; stable for a decaying real mode while |lambda dt| <= 2
/// (RK4: 2.78); an undamped oscillation grows slowly (by (omega dt)^4 / 8 a step), harmless for
/// the drive train's slow modes (omega dt below 0.01 at 5 ms). No allocation with a fixed-size array state.
pub fn midpoint<S>(x: &mut S, t: f64, dt: f64, mut f: impl FnMut(f64, &S, &mut S))
where
    S: Clone + AsRef<[f64]> + AsMut<[f64]>,
{
    let n = x.as_ref().len();
    let (mut k, mut y) = (x.clone(), x.clone());
    f(t, x, &mut k);
    for i in 0..n {
        y.as_mut()[i] = x.as_ref()[i] + 0.5 * dt * k.as_ref()[i];
    }
    f(t + 0.5 * dt, &y, &mut k);
    for (xi, ki) in x.as_mut().iter_mut().zip(k.as_ref()) {
        *xi += dt * ki;
    }
}

crate::choices! {
    /// A fixed-step Runge-Kutta method.
    pub enum Integrator {
        /// Classical fourth order ([`rk4`]).
        Rk4 = "rk4", "RK4 (fourth order)",
        /// Explicit midpoint, second order ([`midpoint`]).
        Midpoint = "midpoint", "midpoint rule (second order)",
    }
}

impl Integrator {
    /// One step of this method (see [`rk4`] and [`midpoint`]).
    #[inline(always)]
    pub fn step<S>(self, x: &mut S, t: f64, dt: f64, f: impl FnMut(f64, &S, &mut S))
    where
        S: Clone + AsRef<[f64]> + AsMut<[f64]>,
    {
        match self {
            Integrator::Rk4 => rk4(x, t, dt, f),
            Integrator::Midpoint => midpoint(x, t, dt, f),
        }
    }
}

/// Most QR sweeps of the eigenvalue and singular value iterations (nalgebra's defaults iterate
/// without bound and can spin forever on some matrices; a few hundred sweeps suffice otherwise).
pub const MAX_SWEEPS: usize = 10_000;

/// Eigenvalues of a real square matrix by the real Schur form, with a bounded iteration; None when
/// the matrix has a non-finite entry or the iteration does not converge.
pub fn eigenvalues(m: &nalgebra::DMatrix<f64>) -> Option<Vec<num_complex::Complex64>> {
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    let schur = nalgebra::linalg::Schur::try_new(m.clone(), f64::EPSILON, MAX_SWEEPS)?;
    Some(schur.complex_eigenvalues().iter().copied().collect())
}

/// Singular values of a complex matrix, largest first, with a bounded iteration.
pub fn singular_values(m: &nalgebra::DMatrix<num_complex::Complex64>) -> Option<Vec<f64>> {
    if !m.iter().all(|v| v.re.is_finite() && v.im.is_finite()) {
        return None;
    }
    let svd = nalgebra::linalg::SVD::try_new(m.clone(), false, false, f64::EPSILON, MAX_SWEEPS)?;
    let mut s: Vec<f64> = svd.singular_values.iter().copied().collect();
    s.sort_by(|a, b| b.total_cmp(a));
    Some(s)
}

/// Gauss-Legendre nodes and weights on [`a`, `b`] with `n` points (Newton on the Legendre
/// recurrence; libm only, so native and wasm give the same nodes).
pub fn gauss_legendre(n: usize, a: f64, b: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut x, mut w) = (vec![0.0; n], vec![0.0; n]);
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    for i in 0..n.div_ceil(2) {
        let mut t = libm::cos(std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5));
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, t);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * t * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let p = if n == 0 { 1.0 } else { p1 };
            dp = n as f64 * (t * p - p0) / (t * t - 1.0);
            let dt = p / dp;
            t -= dt;
            if dt.abs() < 1e-15 {
                break;
            }
        }
        x[i] = mid - half * t;
        x[n - 1 - i] = mid + half * t;
        w[i] = 2.0 * half / ((1.0 - t * t) * dp * dp);
        w[n - 1 - i] = w[i];
    }
    (x, w)
}

#[cfg(test)]
mod tests {

    /// Stopping once the ends are adjacent gives the same bits as all the halvings (a sign
    /// change, none, a root at an end, a step).
    #[test]
    fn bisect_stops_early_with_the_same_answer() {
        fn every_halving(f: impl Fn(f64) -> f64, lo: f64, hi: f64, iterations: u32) -> f64 {
            let (mut a, mut b) = (lo, hi);
            let positive_at_lo = f(a) > 0.0;
            for _ in 0..iterations {
                let m = 0.5 * (a + b);
                if (f(m) > 0.0) == positive_at_lo {
                    a = m;
                } else {
                    b = m;
                }
            }
            0.5 * (a + b)
        }
        let fs: [&dyn Fn(f64) -> f64; 5] =
            [&|x| x * x - 2.0, &|x| 3.0 - x, &|x| x * x + 1.0, &|x| x, &|x| if x < 0.7 { -1.0 } else { 1.0 }];
        for f in fs {
            for (lo, hi) in [(0.0, 2.0), (-1.0, 10.0), (0.0, 1000.0), (1e-3, 3.0)] {
                for n in [5, 60, 100, 200] {
                    assert_eq!(
                        super::bisect(f, lo, hi, n).to_bits(),
                        every_halving(f, lo, hi, n).to_bits(),
                        "{lo} {hi} {n}"
                    );
                }
            }
        }
    }
    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [1, 2, 5, 16, 33] {
            let (x, w) = super::gauss_legendre(n, -1.0, 3.0);
            // Degree 2n-1 is exact: integral of t^(2n-1) over [-1, 3] = (3^(2n) - 1) / (2n).
            let d = 2 * n as u32 - 1;
            let exact = (super::powi(3.0, d + 1) - 1.0) / (d + 1) as f64;
            let got: f64 = x.iter().zip(&w).map(|(t, w)| w * super::powi(*t, d)).sum();
            assert!((got / exact - 1.0).abs() < 1e-12, "n={n}: {got} vs {exact}");
        }
    }

    /// The helper multiplies in LLVM's order for a constant `powi` exponent (binary decomposition,
    /// low bits first). Checked against explicit products rather than std's `powi`, whose bits
    /// depend on how the optimizer lowers it in context (with x.powi(2..=7) in one expression
    /// LLVM once gave x^6 one ulp off x^2 x^4).
    #[test]
    fn powi_multiplies_in_llvm_order() {
        let mut x = 0.123_456_789_f64;
        for _ in 0..10_000 {
            x = x * 1.618_033_988_749_895 + 0.1;
            if x > 50.0 {
                x -= 49.876_543_21;
            }
            let (p, x2) = (super::powi, x * x);
            let x4 = x2 * x2;
            for (n, want) in
                [(0, 1.0), (1, x), (2, x2), (3, x * x2), (4, x4), (5, x * x4), (6, x2 * x4), (7, x * x2 * x4)]
            {
                assert_eq!(p(x, n).to_bits(), want.to_bits(), "{x}^{n}");
            }
        }
    }

    /// The integrators' orders: on dx/dt = -x + cos t over [0, 2] the error falls 16 times per
    /// halving of the step with RK4 and 4 times with the midpoint rule (measured 16.36, 16.18,
    /// 16.09 and 4.07, 4.03, 4.02 from 40, 80 and 160 steps).
    #[test]
    fn integrators_converge_at_their_order() {
        use super::Integrator;
        // x(0) = 0: x(t) = (cos t + sin t - e^-t) / 2.
        let exact = |t: f64| 0.5 * (libm::cos(t) + libm::sin(t) - libm::exp(-t));
        let error = |m: Integrator, n: usize| {
            let dt = 2.0 / n as f64;
            let mut x = [0.0];
            for i in 0..n {
                m.step(&mut x, i as f64 * dt, dt, |t, y, dx| dx[0] = -y[0] + libm::cos(t));
            }
            (x[0] - exact(2.0)).abs()
        };
        for (m, ratio) in [(Integrator::Rk4, 16.0), (Integrator::Midpoint, 4.0)] {
            for n in [40, 80, 160] {
                let r = error(m, n) / error(m, 2 * n);
                println!("{m:?} {n} steps: error ratio {r:.2}");
                assert!((r / ratio - 1.0).abs() < 0.025, "{m:?} {n}: {r}");
            }
        }
    }

    #[test]
    fn finds_roots_either_way_round() {
        assert!((super::bisect(|x| x * x - 2.0, 0.0, 2.0, 60) - 2f64.sqrt()).abs() < 1e-12);
        assert!((super::bisect(|x| 2.0 - x * x, 0.0, 2.0, 60) - 2f64.sqrt()).abs() < 1e-12);
    }
}
