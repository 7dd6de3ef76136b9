//! Velocities induced at a lifting line by Z helical trailing vortices of constant pitch, one per
//! blade: Wrench's (1957) closed-form approximation of Lerbs' induction factors, as written in
//! Kerwin's lecture notes (MIT 13.04, "Hydrofoils and Propellers", 2001). The tests
//! check it against a direct Biot-Savart sum over discretised helices.

use std::f64::consts::PI;

/// Axial and tangential velocity induced at radius `rc` by Z semi-infinite helical vortices of unit
/// circulation leaving the lifting line at radius `rv` with pitch angle atan(`tan_beta_w`) \[1/length
/// of rc\]. A vortex points downstream; the helix advances in +theta; axial is positive downstream,
/// tangential positive in +theta.
pub fn wrench(z: u32, tan_beta_w: f64, rc: f64, rv: f64) -> (f64, f64) {
    let zf = z as f64;
    let y = rc / (rv * tan_beta_w);
    let y0 = 1.0 / tan_beta_w;
    let s = (1.0 + y * y).sqrt();
    let s0 = (1.0 + y0 * y0).sqrt();
    let a = (s0 / s).sqrt();
    let b = ((9.0 * y0 * y0 + 2.0) / (s0 * s0 * s0) + (3.0 * y * y - 2.0) / (s * s * s)) / (24.0 * zf);
    // U = [y0 (s - 1) exp(s - s0) / (y (s0 - 1))]^Z, taken through its logarithm for large Z.
    let ln_u = zf * (libm::log(y0 * (s - 1.0) / (y * (s0 - 1.0))) + s - s0);
    if rc < rv {
        // U < 1: 1 / (1/U - 1) = U / (1 - U).
        let u = libm::exp(ln_u);
        let f1 = -a / (2.0 * zf * y0) * (u / (1.0 - u) + b * libm::log(1.0 / (1.0 - u)));
        let ua = zf / (4.0 * PI * rc) * (y - 2.0 * zf * y * y0 * f1);
        let ut = zf * zf / (2.0 * PI * rc) * y0 * f1;
        (ua, ut)
    } else {
        // U > 1: 1 / (U - 1) = e / (1 - e) with e = 1/U.
        let e = libm::exp(-ln_u);
        let f2 = a / (2.0 * zf * y0) * (e / (1.0 - e) - b * libm::log(1.0 / (1.0 - e)));
        let ua = -zf * zf / (2.0 * PI * rc) * y * y0 * f2;
        let ut = zf / (4.0 * PI * rc) * (1.0 + 2.0 * zf * y0 * f2);
        (ua, ut)
    }
}

/// The same, summed by Biot-Savart over Z discretised helices (the check of [`wrench`]): `turns`
/// turns of `per_turn` straight segments each, the rest of the helix's far wake added as its
/// asymptote (a semi-infinite line on the axis and a semi-infinite solenoid, whose ends induce at
/// the lifting line half of what an infinite one does).
pub fn biot_savart(z: u32, tan_beta_w: f64, rc: f64, rv: f64, turns: usize, per_turn: usize) -> (f64, f64) {
    let pitch = 2.0 * PI * rv * tan_beta_w;
    let n = turns * per_turn;
    let point = |k: usize, phase: f64| {
        let phi = 2.0 * PI * k as f64 / per_turn as f64 + phase;
        [pitch * phi / (2.0 * PI) - pitch * phase / (2.0 * PI), rv * libm::cos(phi), rv * libm::sin(phi)]
    };
    // The field point at theta = 0: (x, y, z) = (0, rc, 0); +theta there is +z.
    let p = [0.0, rc, 0.0];
    let (mut ux, mut uz) = (0.0, 0.0);
    for blade in 0..z {
        let phase = 2.0 * PI * blade as f64 / z as f64;
        for k in 0..n {
            let a = point(k, phase);
            let b = point(k + 1, phase);
            let u = segment(a, b, p);
            ux += u[0];
            uz += u[2];
        }
    }
    // The helices beyond `turns`: far downstream the Z helices look like a line vortex on the axis
    // carrying Z (tangential at rc) and a solenoid of Z / pitch turns per length (axial inside).
    let x_end = pitch * turns as f64;
    let zf = z as f64;
    let far = |x: f64, r: f64| x / (x * x + r * r).sqrt();
    uz += zf / (4.0 * PI * rc) * (1.0 - far(x_end, rc)) * if rc > rv { 1.0 } else { 0.0 };
    if rc < rv {
        ux += zf / pitch / 2.0 * (1.0 - far(x_end, rv));
    }
    (ux, uz)
}

/// Velocity induced at `p` by a straight vortex segment from `a` to `b` of unit circulation.
pub(crate) fn segment(a: [f64; 3], b: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let r1 = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let r2 = [p[0] - b[0], p[1] - b[1], p[2] - b[2]];
    let c = [r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0]];
    let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    let n1 = (r1[0] * r1[0] + r1[1] * r1[1] + r1[2] * r1[2]).sqrt();
    let n2 = (r2[0] * r2[0] + r2[1] * r2[1] + r2[2] * r2[2]).sqrt();
    if c2 < 1e-18 || n1 < 1e-12 || n2 < 1e-12 {
        return [0.0; 3];
    }
    let r0 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let k = (r0[0] * r1[0] + r0[1] * r1[1] + r0[2] * r1[2]) / n1 - (r0[0] * r2[0] + r0[1] * r2[1] + r0[2] * r2[2]) / n2;
    let f = k / (4.0 * PI * c2);
    [f * c[0], f * c[1], f * c[2]]
}

/// Velocity induced at `p` by the polyline through `pts` of unit circulation: the sum of
/// [`segment`] over its segments, each vertex's distance computed once.
pub(crate) fn polyline(pts: &[[f64; 3]], p: [f64; 3]) -> [f64; 3] {
    let mut v = [0.0; 3];
    let Some(first) = pts.first() else { return v };
    let mut r1 = [p[0] - first[0], p[1] - first[1], p[2] - first[2]];
    let mut n1 = (r1[0] * r1[0] + r1[1] * r1[1] + r1[2] * r1[2]).sqrt();
    for b in &pts[1..] {
        let r2 = [p[0] - b[0], p[1] - b[1], p[2] - b[2]];
        let n2 = (r2[0] * r2[0] + r2[1] * r2[1] + r2[2] * r2[2]).sqrt();
        let c = [r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0]];
        let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        if c2 >= 1e-18 && n1 >= 1e-12 && n2 >= 1e-12 {
            let r0 = [r1[0] - r2[0], r1[1] - r2[1], r1[2] - r2[2]];
            let k = (r0[0] * r1[0] + r0[1] * r1[1] + r0[2] * r1[2]) / n1
                - (r0[0] * r2[0] + r0[1] * r2[1] + r0[2] * r2[2]) / n2;
            let f = k / (4.0 * PI * c2);
            v = [v[0] + f * c[0], v[1] + f * c[1], v[2] + f * c[2]];
        }
        (r1, n1) = (r2, n2);
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrench_matches_biot_savart() {
        // Inside and outside the helix, light and heavy pitch, 3 and 5 blades: the closed form agrees
        // with the direct sum to 2 % of the larger component (Wrench's stated accuracy is better than 1 %
        // away from the vortex; the sum's discretisation adds the rest).
        for &(z, tb, rc, rv) in
            &[(3, 0.4, 0.5, 0.8), (3, 0.4, 0.9, 0.6), (5, 0.25, 0.7, 0.75), (4, 0.6, 0.4, 0.3), (3, 0.3, 0.3, 1.0)]
        {
            let (wa, wt) = wrench(z, tb, rc, rv);
            let (ba, bt) = biot_savart(z, tb, rc, rv, 40, 360);
            let scale = wa.abs().max(wt.abs());
            assert!(
                (wa - ba).abs() < 0.02 * scale && (wt - bt).abs() < 0.02 * scale,
                "Z {z} tan {tb} rc {rc} rv {rv}: Wrench ({wa:.5}, {wt:.5}), Biot-Savart ({ba:.5}, {bt:.5})"
            );
        }
    }

    #[test]
    fn a_polyline_is_its_segments() {
        // The same sum as segment by segment, to rounding (1e-15 of the largest component).
        let pts: Vec<[f64; 3]> =
            (0..40).map(|i| [0.1 * i as f64, libm::cos(0.3 * i as f64), libm::sin(0.3 * i as f64)]).collect();
        for p in [[0.05, 0.2, 0.1], [1.0, 0.9, -0.4], [0.0, 1.0, 0.0]] {
            let v = polyline(&pts, p);
            let w = pts.windows(2).fold([0.0; 3], |s, w| {
                let u = segment(w[0], w[1], p);
                [s[0] + u[0], s[1] + u[1], s[2] + u[2]]
            });
            let big = w.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            assert!(v.iter().zip(&w).all(|(a, b)| (a - b).abs() <= 1e-13 * big), "{v:?} against {w:?}");
        }
    }
}
