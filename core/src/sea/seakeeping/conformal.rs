//! Conformal maps of ship sections onto the unit circle (thesis ch. 2.5.1, eqs. 2.33-2.36).
//!
//! Section plane: x across (port positive), y up, the waterline at y = 0, the fluid below. Circle
//! plane: zeta outside the unit circle in the lower half-plane. Every map here is an odd Laurent
//! series with real coefficients,
//!
//!   z(zeta) = M (zeta + sum_k a_k zeta^-k),  k = 1, 3, 5, ...
//!
//! so that the real zeta axis maps onto the free surface and the section is symmetric. The Lewis
//! form keeps a_1 and a_3 (eq. 2.33); the bulb form's zeta + B zeta/(zeta^2 - A) expands into
//! a_{2n+1} = B A^n (eq. 2.35, see `bulb`). The radiation solver only needs the coefficients.

use crate::geometry::{lewis, LewisForm};
use crate::numerics::complex::cabs;
use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// Which family a section's map came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Form {
    Lewis,
    Bulb,
}

/// An odd Laurent-series map z = M (zeta + sum a_k zeta^-k).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionMap {
    /// Scale M \[m\].
    pub scale: f64,
    /// a_1, a_3, a_5, ... (coefficient of zeta^-(2i+1) at index i).
    pub coeffs: Vec<f64>,
    pub form: Form,
    /// True when the section's own (beam/draft, area coefficient) lay outside what the form can
    /// represent and the nearest representable pair was used.
    pub clamped: bool,
}

impl SectionMap {
    pub fn from_lewis(l: &LewisForm) -> SectionMap {
        SectionMap { scale: l.scale, coeffs: vec![l.a1, l.a3], form: Form::Lewis, clamped: l.clamped }
    }

    /// z(zeta).
    pub fn z(&self, zeta: C) -> C {
        let inv = C::new(1.0, 0.0) / zeta;
        let inv2 = inv * inv;
        let mut p = inv;
        let mut s = zeta;
        for &a in &self.coeffs {
            s += p * a;
            p *= inv2;
        }
        s * self.scale
    }

    /// dz/dzeta.
    pub fn dz(&self, zeta: C) -> C {
        let inv = C::new(1.0, 0.0) / zeta;
        let inv2 = inv * inv;
        let mut p = inv2;
        let mut s = C::new(1.0, 0.0);
        for (i, &a) in self.coeffs.iter().enumerate() {
            s -= p * (a * (2 * i + 1) as f64);
            p *= inv2;
        }
        s * self.scale
    }

    /// Half-beam at the waterline (zeta = 1) \[m\].
    pub fn half_beam(&self) -> f64 {
        self.scale * (1.0 + self.coeffs.iter().sum::<f64>())
    }

    /// Draft on the centreline (zeta = -i) \[m\].
    pub fn draft(&self) -> f64 {
        // (-i)^-(2i+1) = i^(2i+1) = i (-1)^i.
        self.scale * (1.0 + self.coeffs.iter().enumerate().map(|(i, a)| if i % 2 == 0 { -a } else { *a }).sum::<f64>())
    }

    /// Immersed area [m^2]: half the area enclosed by the image of the unit circle,
    /// pi M^2 (1 - sum k a_k^2) / 2 (the area theorem for exterior maps).
    pub fn area(&self) -> f64 {
        let s: f64 = self.coeffs.iter().enumerate().map(|(i, a)| (2 * i + 1) as f64 * a * a).sum();
        0.5 * PI * self.scale * self.scale * (1.0 - s)
    }

    /// Area coefficient A / (B T).
    pub fn area_coefficient(&self) -> f64 {
        self.area() / (2.0 * self.half_beam() * self.draft())
    }

    /// True when the contour is a simple curve: |dz/dzeta| > 0 on the lower unit semicircle and the
    /// half contour's horizontal coordinate never turns negative (no loops through the centreline).
    pub fn is_simple(&self) -> bool {
        let n = 400;
        let jmin = (0..=n)
            .map(|i| {
                let th = -PI / 2.0 * i as f64 / n as f64;
                cabs(self.dz(C::new(libm::cos(th), libm::sin(th))))
            })
            .fold(f64::INFINITY, f64::min);
        let xmin = (0..=n)
            .map(|i| {
                let th = -PI / 2.0 * i as f64 / n as f64;
                self.z(C::new(libm::cos(th), libm::sin(th))).re
            })
            .fold(f64::INFINITY, f64::min);
        jmin > 1e-3 * self.scale && xmin > -1e-9 * self.scale
    }
}

/// The map for a section of half-beam `half_beam`, draft `draft` and area coefficient `sigma`:
/// the Lewis form when it represents the section; otherwise the bulb form (sonar domes, very full
/// sections: sigma above the Lewis form's re-entrant limit), when that represents it; otherwise the
/// Lewis form with sigma moved to its nearest limit (`clamped`). Sections without beam or draft
/// have no map (None): they carry no hydrodynamic load in strip theory.
pub fn section_map(half_beam: f64, draft: f64, sigma: f64) -> Option<SectionMap> {
    if !(half_beam > 1e-6 && draft > 1e-6 && sigma > 0.0) {
        return None;
    }
    let l = lewis(half_beam, draft, sigma);
    let lm = SectionMap::from_lewis(&l);
    if !l.clamped && lm.is_simple() {
        return Some(lm);
    }
    if let Some(b) = bulb(half_beam, draft, sigma) {
        return Some(b);
    }
    Some(lm)
}

/// Half-breadth of the mapped contour at `depth` below the waterline (the widest crossing) \[m\].
pub fn half_breadth_at(map: &SectionMap, depth: f64) -> f64 {
    let n = 400;
    let pts: Vec<C> = (0..=n)
        .map(|i| {
            let th = -PI / 2.0 * i as f64 / n as f64;
            map.z(C::new(libm::cos(th), libm::sin(th)))
        })
        .collect();
    let mut best: f64 = 0.0;
    for w in pts.windows(2) {
        let (y0, y1) = (-w[0].im, -w[1].im);
        if (y0 - depth) * (y1 - depth) <= 0.0 && y0 != y1 {
            let f = (depth - y0) / (y1 - y0);
            best = best.max(w[0].re + f * (w[1].re - w[0].re));
        }
    }
    best
}

/// RMS difference \[m\] between the mapped contour's half-breadths and a section's own
/// (depth below the waterline, half-breadth) rows.
pub fn profile_error(map: &SectionMap, profile: &[(f64, f64)]) -> f64 {
    if profile.is_empty() {
        return 0.0;
    }
    let s: f64 = profile
        .iter()
        .map(|&(d, hb)| {
            let e = half_breadth_at(map, d) - hb;
            e * e
        })
        .sum();
    (s / profile.len() as f64).sqrt()
}

/// Like `section_map`, but when both the Lewis and the bulb form represent the section (sonar-dome
/// sections often fit both), the one whose contour is closer to the section's own offsets
/// `profile` (depth below the waterline, half-breadth) is used.
pub fn best_section_map(half_beam: f64, draft: f64, sigma: f64, profile: &[(f64, f64)]) -> Option<SectionMap> {
    let first = section_map(half_beam, draft, sigma)?;
    if first.form == Form::Lewis && !first.clamped {
        if let Some(b) = bulb(half_beam, draft, sigma) {
            if profile_error(&b, profile) < profile_error(&first, profile) {
                return Some(b);
            }
        }
    }
    Some(first)
}

/// The bulb form z = M (zeta + B zeta / (zeta^2 - A)) (eq. 2.35 with the sign of A that makes it
/// agree with eq. 2.36's lambda = (1 - A^2 + AB + B)/(1 - A^2 + AB - B); eq. 2.35 prints
/// zeta^2 + A). Expanded as a_{2n+1} = B A^n, truncated where the terms fall below 1e-12.
/// A and B are found by Newton iteration on (half-beam/draft, area coefficient) from the exact
/// area of the series, so the printed eq. 2.36 area formula is not needed; None when no bulb
/// with |A| < 0.9 and a simple contour fits.
pub fn bulb(half_beam: f64, draft: f64, sigma: f64) -> Option<SectionMap> {
    let lam = half_beam / draft;
    let make = |a: f64, b: f64| -> SectionMap {
        let mut coeffs = Vec::new();
        let mut t = b;
        while coeffs.len() < 200 {
            coeffs.push(t);
            t *= a;
            if t.abs() < 1e-12 {
                break;
            }
        }
        let mut m = SectionMap { scale: 1.0, coeffs, form: Form::Bulb, clamped: false };
        m.scale = half_beam / m.half_beam();
        m
    };
    let resid = |a: f64, b: f64| -> (f64, f64) {
        let m = make(a, b);
        (m.half_beam() / m.draft() - lam, m.area_coefficient() - sigma)
    };
    // Start from a few (A, B) pairs; a bulb needs A > 0 (the dome) and B < 0.
    for &(mut a, mut b) in &[(0.5, -0.3), (0.7, -0.2), (0.3, -0.5), (0.8, -0.1)] {
        for _ in 0..60 {
            let (f1, f2) = resid(a, b);
            if f1.abs() < 1e-11 && f2.abs() < 1e-11 {
                let m = make(a, b);
                if a.abs() < 0.9 && m.draft() > 0.0 && m.is_simple() {
                    return Some(m);
                }
                break;
            }
            let h = 1e-7;
            let (fa1, fa2) = resid(a + h, b);
            let (fb1, fb2) = resid(a, b + h);
            let (j11, j21, j12, j22) = ((fa1 - f1) / h, (fa2 - f2) / h, (fb1 - f1) / h, (fb2 - f2) / h);
            let det = j11 * j22 - j12 * j21;
            if det.abs() < 1e-14 {
                break;
            }
            let da = (f1 * j22 - f2 * j12) / det;
            let db = (j11 * f2 - j21 * f1) / det;
            let step = (da * da + db * db).sqrt();
            let s = if step > 0.2 { 0.2 / step } else { 1.0 };
            a -= s * da;
            b -= s * db;
            if !(a.is_finite() && b.is_finite()) || a.abs() >= 0.95 {
                break;
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lewis_map_reproduces_the_section() {
        for &(hb, d, s) in &[(10.0, 6.0, 0.8), (5.0, 5.0, PI / 4.0), (9.0, 6.0, 0.6), (2.0, 6.0, 0.7)] {
            let m = section_map(hb, d, s).unwrap();
            assert_eq!(m.form, Form::Lewis);
            assert!((m.half_beam() - hb).abs() < 1e-12 && (m.draft() - d).abs() < 1e-12);
            assert!((m.area_coefficient() - s).abs() < 1e-12, "{} vs {s}", m.area_coefficient());
            assert!(m.is_simple());
        }
        // The semicircle is the identity map.
        let m = section_map(1.0, 1.0, PI / 4.0).unwrap();
        assert!(m.coeffs.iter().all(|a| a.abs() < 1e-12) && (m.scale - 1.0).abs() < 1e-12);
    }

    /// A sonar-dome section (narrow at the waterline, full below: sigma above the Lewis limit)
    /// gets a bulb map with the section's beam, draft and area; eq. 2.36's lambda formula holds
    /// for it.
    #[test]
    fn bulb_form_for_a_dome_section() {
        let (hb, d) = (3.0, 8.0);
        let smax = PI / 32.0 * (10.0 + hb / d + d / hb);
        let s = smax + 0.05;
        let m = section_map(hb, d, s).unwrap();
        assert_eq!(m.form, Form::Bulb, "{m:?}");
        assert!((m.half_beam() - hb).abs() < 1e-9 && (m.draft() - d).abs() < 1e-9);
        assert!((m.area_coefficient() - s).abs() < 1e-9);
        let (a, b) = (m.coeffs[1] / m.coeffs[0], m.coeffs[0]);
        let lam = (1.0 - a * a + a * b + b) / (1.0 - a * a + a * b - b);
        assert!((lam - hb / d).abs() < 1e-6, "eq 2.36: {lam} vs {}", hb / d);
    }
}
