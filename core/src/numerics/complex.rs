//! Complex elementary functions through `libm` (num-complex's own go through the platform's libm,
//! which differs between native and wasm builds), and the exponential integral of the free-surface
//! wave source.

use num_complex::Complex64 as C;

/// e^z.
pub fn cexp(z: C) -> C {
    let r = libm::exp(z.re);
    C::new(r * libm::cos(z.im), r * libm::sin(z.im))
}

/// Principal logarithm (branch cut on the negative real axis; -0.0 imaginary parts fall below it).
pub fn cln(z: C) -> C {
    C::new(libm::log(cabs(z)), libm::atan2(z.im, z.re))
}

/// |z| (libm's hypot, the same in every build).
pub fn cabs(z: C) -> f64 {
    libm::hypot(z.re, z.im)
}

/// arg z in (-pi, pi] (libm's atan2, the same in every build).
pub fn carg(z: C) -> f64 {
    libm::atan2(z.im, z.re)
}

const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// G(u) = e^u E1(u), the scaled exponential integral on its principal branch. The 2-D wave source
/// of the free surface is G(-i nu z) (see `radiation`); G stays O(1/|u|) where E1 itself grows
/// like e^{-u}. Power series where it is accurate (small |u|, or well into the left half-plane
/// where the series terms and the result grow alike); the continued fraction elsewhere
/// (the split of Zhang & Jin's E1Z).
pub fn exp_e1(u: C) -> C {
    let a = cabs(u);
    if a == 0.0 {
        return C::new(f64::INFINITY, 0.0);
    }
    if a <= 5.0 || (u.re < -2.0 * u.im.abs() && a < 40.0) {
        // E1 = -gamma - ln u - sum_{n>=1} (-u)^n / (n n!)
        let mut term = C::new(1.0, 0.0);
        let mut sum = C::new(0.0, 0.0);
        for n in 1..400 {
            term = term * (-u) / n as f64;
            let t = term / n as f64;
            sum += t;
            if cabs(t) <= 1e-17 * cabs(sum) && n as f64 > a {
                break;
            }
        }
        let e1 = -C::new(EULER_GAMMA, 0.0) - cln(u) - sum;
        cexp(u) * e1
    } else {
        // e^u E1(u) = 1/(u+1- 1/(u+3- 4/(u+5- ...))) by the modified Lentz method.
        let tiny = 1e-300;
        let mut b = u + 1.0;
        let mut c = C::new(1.0 / tiny, 0.0);
        let mut d = C::new(1.0, 0.0) / b;
        let mut h = d;
        for i in 1..1000 {
            let an = -((i * i) as f64);
            b += 2.0;
            d = C::new(1.0, 0.0) / (d * an + b);
            c = b + C::new(an, 0.0) / c;
            let del = c * d;
            h *= del;
            if cabs(del - 1.0) < 1e-16 {
                break;
            }
        }
        h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tabulated values (Abramowitz & Stegun table 5.1 and DLMF 6.2; E1(i) = -Ci(1) + i(Si(1) - pi/2)).
    #[test]
    fn matches_tabulated_values() {
        let e = std::f64::consts::E;
        let cases = [
            (C::new(1.0, 0.0), C::new(0.219_383_934_395_520_3 * e, 0.0)),
            (C::new(10.0, 0.0), C::new(4.156_968_929_685_324e-6 * libm::exp(10.0), 0.0)),
            (C::new(0.0, 1.0), cexp(C::new(0.0, 1.0)) * C::new(-0.337_403_922_900_968_1, -0.624_713_256_427_713_6)),
        ];
        for (u, want) in cases {
            let got = exp_e1(u);
            assert!(cabs(got - want) < 1e-13 * cabs(want), "{u}: {got} vs {want}");
        }
        // On the negative real axis from below: E1(-x - i0) = -Ei(x) + i pi; Ei(1) = 1.895117816355937.
        let got = exp_e1(C::new(-1.0, -0.0));
        let want = cexp(C::new(-1.0, 0.0)) * C::new(-1.895_117_816_355_937, std::f64::consts::PI);
        assert!(cabs(got - want) < 1e-13, "{got} vs {want}");
    }

    /// G' = G - 1/u holds across the switch between series and continued fraction (checked by a
    /// central difference at |u| = 5 and along the |Im u| = -Re u / 2 boundary).
    #[test]
    fn satisfies_its_differential_equation_across_the_branches() {
        for &u in &[C::new(3.0, -4.0), C::new(-4.0, -3.0), C::new(-20.0, -10.0), C::new(-0.1, -5.0), C::new(0.0, -30.0)]
        {
            let h = 1e-5;
            let d = (exp_e1(u + h) - exp_e1(u - h)) / (2.0 * h);
            let want = exp_e1(u) - C::new(1.0, 0.0) / u;
            assert!(cabs(d - want) < 1e-7 * (1.0 + cabs(want)), "{u}: {d} vs {want}");
        }
    }
}
