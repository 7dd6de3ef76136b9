//! A linear time-invariant model x' = A x + B u, y = C x + D u and its frequency response: what
//! the design (`lqg_ltr`), the modal reduction (`reduction`) and the linearised drive train
//! (`sim::linearize`) pass to each other.

use nalgebra::DMatrix;
use num_complex::Complex64 as C;

/// A state-space model.
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
    pub c: DMatrix<f64>,
    pub d: DMatrix<f64>,
}

impl StateSpace {
    /// Frequency response C (j w I - A)^-1 B + D.
    pub fn response(&self, w: f64) -> Option<DMatrix<C>> {
        let n = self.a.nrows();
        if n == 0 {
            return Some(self.d.map(|v| C::new(v, 0.0)));
        }
        let m = DMatrix::<C>::from_fn(n, n, |i, j| C::new(-self.a[(i, j)], if i == j { w } else { 0.0 }));
        let b = self.b.map(|v| C::new(v, 0.0));
        let x = m.lu().solve(&b)?;
        Some(self.c.map(|v| C::new(v, 0.0)) * x + self.d.map(|v| C::new(v, 0.0)))
    }
}
