//! A discrete Fourier transform that gives the same bits on every platform, for the Monte Carlo
//! periodogram. rustfft (which we used before) computes its twiddle factors with the platform's
//! sin/cos and picks SIMD kernels at run time, so a native periodogram and the browser's differed
//! in the last bits; here every twiddle comes from libm and the arithmetic order is fixed.
//! Powers of two use the iterative radix-2 Cooley-Tukey algorithm; other lengths Bluestein's
//! chirp-z transform on top of it. O(n log n) for every n.

use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// A forward transform of one length, planned once (twiddles and chirp precomputed).
#[derive(Debug, Clone)]
pub struct Fft {
    n: usize,
    plan: Plan,
}

#[derive(Debug, Clone)]
enum Plan {
    /// Radix-2: twiddles exp(-2 pi i j / n), j < n/2.
    Radix2(Vec<C>),
    /// Bluestein: the chirp exp(-i pi k^2 / n), the transformed conjugate chirp of length m, and
    /// the radix-2 twiddles of m.
    Bluestein { chirp: Vec<C>, b_hat: Vec<C>, m: usize, tw: Vec<C> },
}

fn twiddles(n: usize) -> Vec<C> {
    (0..n / 2)
        .map(|j| {
            let a = -2.0 * PI * j as f64 / n as f64;
            C::new(libm::cos(a), libm::sin(a))
        })
        .collect()
}

/// In-place radix-2 FFT of a power-of-two length with twiddles `tw` of that length.
fn radix2(buf: &mut [C], tw: &[C]) {
    let n = buf.len();
    if n < 2 {
        return;
    }
    let bits = n.trailing_zeros();
    for i in 0..n {
        let j = i.reverse_bits() >> (usize::BITS - bits);
        if j > i {
            buf.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let (half, step) = (len / 2, n / len);
        for start in (0..n).step_by(len) {
            for j in 0..half {
                let u = buf[start + j];
                let v = buf[start + j + half] * tw[j * step];
                buf[start + j] = u + v;
                buf[start + j + half] = u - v;
            }
        }
        len *= 2;
    }
}

impl Fft {
    /// Plans a forward transform of length `n` (at least 1).
    pub fn new(n: usize) -> Fft {
        let n = n.max(1);
        if n.is_power_of_two() {
            return Fft { n, plan: Plan::Radix2(twiddles(n)) };
        }
        let m = (2 * n - 1).next_power_of_two();
        let tw = twiddles(m);
        // k^2 mod 2n keeps the chirp's angle small (exact integer reduction, then libm).
        let chirp: Vec<C> = (0..n)
            .map(|k| {
                let q = ((k as u128 * k as u128) % (2 * n as u128)) as f64;
                let a = -PI * q / n as f64;
                C::new(libm::cos(a), libm::sin(a))
            })
            .collect();
        let mut b_hat = vec![C::new(0.0, 0.0); m];
        b_hat[0] = chirp[0].conj();
        for k in 1..n {
            b_hat[k] = chirp[k].conj();
            b_hat[m - k] = chirp[k].conj();
        }
        radix2(&mut b_hat, &tw);
        Fft { n, plan: Plan::Bluestein { chirp, b_hat, m, tw } }
    }

    /// Length of the transform.
    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// X_k = sum_j x_j exp(-2 pi i j k / n), in place; `buf` must have the planned length.
    pub fn forward(&self, buf: &mut [C]) {
        assert_eq!(buf.len(), self.n, "FFT planned for another length");
        match &self.plan {
            Plan::Radix2(tw) => radix2(buf, tw),
            Plan::Bluestein { chirp, b_hat, m, tw } => {
                let mut a = vec![C::new(0.0, 0.0); *m];
                for k in 0..self.n {
                    a[k] = buf[k] * chirp[k];
                }
                radix2(&mut a, tw);
                // Inverse transform of the product by conjugation: ifft(x) = conj(fft(conj x)) / m.
                for (x, b) in a.iter_mut().zip(b_hat) {
                    *x = (*x * b).conj();
                }
                radix2(&mut a, tw);
                let scale = 1.0 / *m as f64;
                for k in 0..self.n {
                    buf[k] = a[k].conj() * scale * chirp[k];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn direct(x: &[C]) -> Vec<C> {
        let n = x.len();
        (0..n)
            .map(|k| {
                x.iter()
                    .enumerate()
                    .map(|(j, v)| {
                        let a = -2.0 * PI * ((j * k) % n) as f64 / n as f64;
                        v * C::new(libm::cos(a), libm::sin(a))
                    })
                    .sum()
            })
            .collect()
    }

    /// Radix-2 and Bluestein lengths against the direct sum, to 1e-12 n (measured: at most 5.3e-16 n,
    /// 1.35e-13 at n = 257; the bound is the loose one of the determinism work, kept).
    #[test]
    fn matches_the_direct_transform() {
        for n in [1usize, 2, 8, 64, 3, 5, 50, 100, 257] {
            let x: Vec<C> =
                (0..n).map(|i| C::new(libm::sin(0.37 * i as f64 * i as f64), libm::cos(1.3 * i as f64))).collect();
            let mut y = x.clone();
            Fft::new(n).forward(&mut y);
            let d = direct(&x);
            let err = y.iter().zip(&d).map(|(a, b)| (a - b).norm_sqr().sqrt()).fold(0.0, f64::max);
            assert!(err < 1e-12 * n as f64, "n = {n}: {err:e}");
        }
    }
}
