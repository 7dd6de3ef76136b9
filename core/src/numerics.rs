//! Small numerical helpers shared by the physics modules.

/// Bisection for a sign change of `f` between `lo` and `hi`: `iterations` halvings, returns the
/// midpoint of the last bracket. The side that keeps `lo` is the one with the sign of `f(lo)`.
pub fn bisect(f: impl Fn(f64) -> f64, lo: f64, hi: f64, iterations: u32) -> f64 {
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

/// Conditional integration (anti-windup) of a PI whose unsaturated output `unsat` is clamped to
/// [`lo`, `hi`]: integrate the error `err` unless that would push the output further into the
/// limit it already sits at.
pub fn may_integrate(unsat: f64, lo: f64, hi: f64, err: f64) -> bool {
    (unsat < hi || err < 0.0) && (unsat > lo || err > 0.0)
}

#[cfg(test)]
mod tests {
    #[test]
    fn anti_windup_rule() {
        assert!(super::may_integrate(0.5, 0.0, 1.0, 1.0));
        assert!(!super::may_integrate(1.2, 0.0, 1.0, 1.0));
        assert!(super::may_integrate(1.2, 0.0, 1.0, -1.0));
        assert!(!super::may_integrate(-0.1, 0.0, 1.0, -1.0));
    }

    #[test]
    fn finds_roots_either_way_round() {
        assert!((super::bisect(|x| x * x - 2.0, 0.0, 2.0, 60) - 2f64.sqrt()).abs() < 1e-12);
        assert!((super::bisect(|x| 2.0 - x * x, 0.0, 2.0, 60) - 2f64.sqrt()).abs() < 1e-12);
    }
}
