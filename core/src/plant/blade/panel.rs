//! A 2D panel method for a blade section (Hess & Smith 1967): constant-strength sources on each
//! panel and one vortex strength common to all, with the Kutta condition at the trailing edge,
//! giving the surface pressure coefficient and -Cp_min at any angle of attack.
//!
//! The solution is linear in the free stream, so two solves (flow along x and along y) give the
//! surface speed at every angle: v_t(alpha) = cos(alpha) A + sin(alpha) B. A section's
//! -Cp_min(alpha) then costs one pass over its panels, and a [`Bucket`] tabulates it once.

use nalgebra::{DMatrix, DVector};

/// A section's solved panels.
#[derive(Debug, Clone)]
pub struct Panels {
    /// Control points (panel midpoints) \[chords\].
    pub mid: Vec<[f64; 2]>,
    /// Outward unit normals.
    pub normal: Vec<[f64; 2]>,
    /// Panel lengths \[chords\].
    pub length: Vec<f64>,
    /// Panels before this index are on the lower (pressure, face) side, from it on the upper
    /// (suction, back) side.
    pub first_upper: usize,
    /// Surface speed over free-stream speed for a unit stream along x (A) and along y (B).
    a: Vec<f64>,
    b: Vec<f64>,
}

/// -Cp_min on each side of a section at one angle of attack \[-\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MinPressure {
    /// -Cp_min on the upper surface (back, suction side).
    pub suction: f64,
    /// -Cp_min on the lower surface (face, pressure side).
    pub pressure: f64,
}

impl MinPressure {
    /// -Cp_min over the whole section.
    pub fn both(&self) -> f64 {
        self.suction.max(self.pressure)
    }
}

impl Panels {
    /// Solves the section whose closed outline runs clockwise (lower surface trailing edge to
    /// nose, upper surface back), `points[nose]` the nose; the trailing edge may be open (a blunt
    /// base) or closed. Refuses an outline with fewer than 8 points or a zero-length panel.
    pub fn new(points: &[[f64; 2]], nose: usize) -> Result<Panels, String> {
        let n = points.len().saturating_sub(1);
        if n < 8 || nose == 0 || nose >= n {
            return Err(format!("a section outline needs at least 9 points and a nose inside it; it has {}", n + 1));
        }
        let mut mid = Vec::with_capacity(n);
        let mut tangent = Vec::with_capacity(n);
        let mut normal = Vec::with_capacity(n);
        let mut length = Vec::with_capacity(n);
        for j in 0..n {
            let (p, q) = (points[j], points[j + 1]);
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let l = (dx * dx + dy * dy).sqrt();
            if l.is_nan() || l <= 0.0 {
                return Err(format!("panel {j} of the section outline has no length"));
            }
            mid.push([0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])]);
            tangent.push([dx / l, dy / l]);
            // Clockwise outline: the left-hand normal points out of the section.
            normal.push([-dy / l, dx / l]);
            length.push(l);
        }
        // Velocity at control point i induced by panel j's unit source (us) and unit vortex (uv),
        // in global axes (Hess & Smith 1967; Katz & Plotkin 2001, eqs. 10.21-10.22 and 10.41-10.42).
        let mut vs = vec![[0.0; 2]; n * n];
        let mut vv = vec![[0.0; 2]; n * n];
        let two_pi = 2.0 * std::f64::consts::PI;
        for i in 0..n {
            for j in 0..n {
                let (t, nn) = (tangent[j], normal[j]);
                let (rx, ry) = (mid[i][0] - points[j][0], mid[i][1] - points[j][1]);
                // The point in panel j's axes (x along it from its start, z along its normal).
                let (x, z) = (rx * t[0] + ry * t[1], rx * nn[0] + ry * nn[1]);
                let (dtheta, log_r1_r2) = if i == j {
                    (std::f64::consts::PI, 0.0)
                } else {
                    let x2 = x - length[j];
                    let th = libm::atan2(z * length[j], x * x2 + z * z);
                    (th, 0.5 * libm::log((x * x + z * z) / (x2 * x2 + z * z)))
                };
                // Source: u = ln(r1/r2)/2pi along the panel, w = dtheta/2pi normal to it.
                let (us, ws) = (log_r1_r2 / two_pi, dtheta / two_pi);
                // Vortex (clockwise positive): u = dtheta/2pi, w = -ln(r1/r2)/2pi.
                let (uv, wv) = (dtheta / two_pi, -log_r1_r2 / two_pi);
                vs[i * n + j] = [us * t[0] + ws * nn[0], us * t[1] + ws * nn[1]];
                vv[i * n + j] = [uv * t[0] + wv * nn[0], uv * t[1] + wv * nn[1]];
            }
        }
        let dot = |v: [f64; 2], w: [f64; 2]| v[0] * w[0] + v[1] * w[1];
        // Unknowns q_0..q_{n-1}, gamma: no flow through any panel, and the Kutta condition
        // v_t(first) + v_t(last) = 0 (equal speeds leaving the trailing edge on both sides).
        let mut m = DMatrix::<f64>::zeros(n + 1, n + 1);
        for i in 0..n {
            for j in 0..n {
                m[(i, j)] = dot(vs[i * n + j], normal[i]);
                m[(i, n)] += dot(vv[i * n + j], normal[i]);
            }
        }
        for j in 0..n {
            m[(n, j)] = dot(vs[j], tangent[0]) + dot(vs[(n - 1) * n + j], tangent[n - 1]);
            m[(n, n)] += dot(vv[j], tangent[0]) + dot(vv[(n - 1) * n + j], tangent[n - 1]);
        }
        let lu = m.lu();
        let speeds = |u: [f64; 2]| -> Result<Vec<f64>, String> {
            let mut rhs = DVector::<f64>::zeros(n + 1);
            for i in 0..n {
                rhs[i] = -dot(u, normal[i]);
            }
            rhs[n] = -(dot(u, tangent[0]) + dot(u, tangent[n - 1]));
            let sol = lu.solve(&rhs).ok_or("the section's panel equations are singular")?;
            Ok((0..n)
                .map(|i| {
                    let induced: f64 = (0..n)
                        .map(|j| sol[j] * dot(vs[i * n + j], tangent[i]) + sol[n] * dot(vv[i * n + j], tangent[i]))
                        .sum();
                    dot(u, tangent[i]) + induced
                })
                .collect())
        };
        let (a, b) = (speeds([1.0, 0.0])?, speeds([0.0, 1.0])?);
        if a.iter().chain(&b).any(|v| !v.is_finite()) {
            return Err("the section's panel solution is not finite".into());
        }
        Ok(Panels { mid, normal, length, first_upper: nose, a, b })
    }

    /// Surface speed over free-stream speed at each control point, at `alpha` \[rad\] (positive
    /// nose up: the stream comes along (cos alpha, sin alpha)); signed along the outline.
    pub fn surface_speed(&self, alpha: f64) -> impl Iterator<Item = f64> + '_ {
        let (c, s) = (libm::cos(alpha), libm::sin(alpha));
        self.a.iter().zip(&self.b).map(move |(a, b)| c * a + s * b)
    }

    /// Pressure coefficient Cp = 1 - (v/V)^2 at each control point at `alpha` \[rad\].
    pub fn cp(&self, alpha: f64) -> Vec<f64> {
        self.surface_speed(alpha).map(|v| 1.0 - v * v).collect()
    }

    /// -Cp_min on each side at `alpha` \[rad\].
    pub fn min_pressure(&self, alpha: f64) -> MinPressure {
        let mut out = MinPressure { suction: f64::NEG_INFINITY, pressure: f64::NEG_INFINITY };
        for (i, v) in self.surface_speed(alpha).enumerate() {
            let side = if i < self.first_upper { &mut out.pressure } else { &mut out.suction };
            *side = side.max(v * v - 1.0);
        }
        out
    }

    /// Lift coefficient per chord of the nose-tail line (the outline's x extent is 1) at
    /// `alpha` \[rad\], from the surface pressures: C_L = -sum Cp (n . e_lift) ds.
    pub fn lift_coefficient(&self, alpha: f64) -> f64 {
        let lift_dir = [-libm::sin(alpha), libm::cos(alpha)];
        self.cp(alpha)
            .iter()
            .zip(&self.normal)
            .zip(&self.length)
            .map(|((cp, n), l)| -cp * (n[0] * lift_dir[0] + n[1] * lift_dir[1]) * l)
            .sum()
    }
}

/// A section's cavitation bucket: -Cp_min on each side tabulated over the angle of attack, built
/// once, read by interpolation.
#[derive(Debug, Clone, PartialEq)]
pub struct Bucket {
    /// First angle of the table \[rad\].
    pub alpha0: f64,
    /// Step of the table \[rad\].
    pub step: f64,
    /// -Cp_min of the back (suction side) at each angle.
    pub suction: Vec<f64>,
    /// -Cp_min of the face (pressure side) at each angle.
    pub pressure: Vec<f64>,
}

/// Angles of a bucket table: -12 deg to +12 deg in 0.1 deg steps (a propeller section works within
/// a few degrees of its ideal angle; outside the table the end values hold).
pub const BUCKET_SPAN_RAD: f64 = 12.0 * std::f64::consts::PI / 180.0;
const BUCKET_STEPS: usize = 240;

/// Panels on each surface of a section for the cavitation analysis: 240 in all, a lift 3 % above
/// the converged one (see the lift-slope test), a solve of a few ms per section.
pub const PANELS_PER_SIDE: usize = 120;

impl Bucket {
    /// The bucket of solved `panels`.
    pub fn new(panels: &Panels) -> Bucket {
        let step = 2.0 * BUCKET_SPAN_RAD / BUCKET_STEPS as f64;
        let (mut suction, mut pressure) = (Vec::new(), Vec::new());
        for k in 0..=BUCKET_STEPS {
            let m = panels.min_pressure(-BUCKET_SPAN_RAD + step * k as f64);
            suction.push(m.suction);
            pressure.push(m.pressure);
        }
        Bucket { alpha0: -BUCKET_SPAN_RAD, step, suction, pressure }
    }

    /// -Cp_min on each side at `alpha` \[rad\], interpolated (held beyond the table).
    pub fn at(&self, alpha: f64) -> MinPressure {
        let x = alpha - self.alpha0;
        let u = crate::numerics::interp::uniform;
        MinPressure { suction: u(&self.suction, self.step, x), pressure: u(&self.pressure, self.step, x) }
    }

    /// The angle of attack \[rad\] where -Cp_min (both sides) is least: the bottom of the bucket.
    pub fn bottom(&self) -> (f64, f64) {
        let (k, v) = self
            .suction
            .iter()
            .zip(&self.pressure)
            .map(|(s, p)| s.max(*p))
            .enumerate()
            .fold((0, f64::INFINITY), |best, (k, v)| if v < best.1 { (k, v) } else { best });
        (self.alpha0 + self.step * k as f64, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::complex::{cabs, cexp, cln};
    use crate::plant::blade::section_shape::{a08_camber_per_cli, a08_ideal_angle_per_cli, section};
    use num_complex::Complex64 as C;

    /// A symmetric Karman-Trefftz foil (circle centre -eps, radius 1 + eps; trailing-edge angle
    /// `tau` \[rad\]; z = k (1 + w^k) / (1 - w^k), w = (zeta - 1) / (zeta + 1), k = 2 - tau / pi)
    /// with `n` panels, scaled to unit chord with the nose at 0: its outline, the exact surface
    /// speed v/V at the panels' middle angles for `alpha`, and the exact C_L.
    fn karman_trefftz(eps: f64, tau: f64, n: usize, alpha: f64) -> (Vec<[f64; 2]>, Vec<f64>, f64) {
        let pi = std::f64::consts::PI;
        // w^k on the principal branch, through the crate's libm-based complex functions.
        let pow = |w: C, k: f64| cexp(cln(w) * k);
        let (r, k) = (1.0 + eps, 2.0 - tau / pi);
        let zc = C::new(-eps, 0.0);
        let map = |zeta: C| {
            let wk = pow((zeta - 1.0) / (zeta + 1.0), k);
            k * (1.0 + wk) / (1.0 - wk)
        };
        let dmap = |zeta: C| {
            let w = (zeta - 1.0) / (zeta + 1.0);
            let wk = pow(w, k);
            2.0 * k * k * pow(w, k - 1.0) * 2.0 / ((zeta + 1.0) * (zeta + 1.0)) / ((1.0 - wk) * (1.0 - wk))
        };
        let z_le = map(C::new(-1.0 - 2.0 * eps, 0.0)).re;
        let chord = k - z_le;
        let at = |th: f64| zc + C::new(r * libm::cos(th), r * libm::sin(th));
        let step = -2.0 * pi / n as f64;
        let pts = (0..=n)
            .map(|j| {
                let z = if j == 0 || j == n { C::new(k, 0.0) } else { map(at(step * j as f64)) };
                [(z.re - z_le) / chord, z.im / chord]
            })
            .collect();
        let gamma = 4.0 * pi * r * libm::sin(alpha);
        let e = C::new(libm::cos(alpha), -libm::sin(alpha));
        let speed = (0..n)
            .map(|j| {
                let zeta = at(step * (j as f64 + 0.5));
                let d = zeta - zc;
                let w = e - r * r * e.conj() / (d * d) + C::new(0.0, gamma / (2.0 * pi)) / d;
                cabs(w / dmap(zeta))
            })
            .collect();
        (pts, speed, 2.0 * gamma / chord)
    }

    /// Exact potential flow about a 12 % Karman-Trefftz foil (10 deg trailing-edge angle) at 0
    /// and 5 deg: the panel solution's Cp within 0.02 of the exact one off the two trailing-edge
    /// panels (measured 0.003 and 0.009), its -Cp_min within 1.5 % (measured -0.3 % and -0.2 %)
    /// and its lift within 1 % (measured -0.7 % at 5 deg).
    #[test]
    fn karman_trefftz_foil_matches_the_exact_solution() {
        let n = 240;
        for deg in [0.0f64, 5.0] {
            let alpha = deg.to_radians();
            let (pts, exact, cl_exact) = karman_trefftz(0.1, 10f64.to_radians(), n, alpha);
            let p = Panels::new(&pts, n / 2).unwrap();
            let cp = p.cp(alpha);
            let mut worst: f64 = 0.0;
            for i in 2..n - 2 {
                worst = worst.max((cp[i] - (1.0 - exact[i] * exact[i])).abs());
            }
            let exact_min = exact.iter().map(|v| v * v - 1.0).fold(f64::MIN, f64::max);
            let got = p.min_pressure(alpha).both();
            let cl = p.lift_coefficient(alpha);
            assert!(worst < 0.02, "{deg} deg: worst Cp difference {worst}");
            assert!((got / exact_min - 1.0).abs() < 0.015, "{deg} deg: -Cp_min {got} vs exact {exact_min}");
            if deg > 0.0 {
                assert!((cl / cl_exact - 1.0).abs() < 0.01, "C_L {cl} vs exact {cl_exact}");
            } else {
                assert!(cl.abs() < 1e-6, "C_L at 0 deg {cl}");
            }
        }
    }

    /// NACA 0012 (Abbott & von Doenhoff 1959, App. I): (v/V)^2 max 1.411 at 0 deg, so -Cp_min
    /// 0.411 (measured 0.4119, tolerance 2 %); at 2 and 4 deg their superposition
    /// v/V = (v/V)_t + C_l (Delta v_a / V) with our C_l: within 5 % (measured +0.1 % and +2.7 %:
    /// their table's first station, x = 0.5 % c, sits behind the true peak at 4 deg).
    #[test]
    fn naca_0012_matches_abbott_and_von_doenhoff() {
        let n = 150;
        let y = |x: f64| {
            0.6 * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1015 * x * x * x * x)
        };
        let xs: Vec<f64> =
            (0..=n).map(|k| 0.5 * (1.0 - libm::cos(std::f64::consts::PI * k as f64 / n as f64))).collect();
        let mut pts: Vec<[f64; 2]> = xs.iter().rev().map(|&x| [x, -y(x)]).collect();
        pts.extend(xs[1..].iter().map(|&x| [x, y(x)]));
        let p = Panels::new(&pts, n).unwrap();
        let m0 = p.min_pressure(0.0);
        assert!((m0.both() / 0.411 - 1.0).abs() < 0.02, "-Cp_min at 0 deg {m0:?}");
        assert!((m0.suction - m0.pressure).abs() < 1e-9, "symmetric");
        let v_t = [0.0, 0.800, 1.005, 1.114, 1.174, 1.184, 1.188, 1.188, 1.183, 1.174, 1.162, 1.135, 1.108];
        let dva = [1.988, 1.475, 1.199, 0.934, 0.685, 0.558, 0.479, 0.381, 0.319, 0.273, 0.239, 0.187, 0.149];
        for deg in [2.0f64, 4.0] {
            let a = deg.to_radians();
            let cl = p.lift_coefficient(a);
            let avd = v_t.iter().zip(&dva).map(|(v, d)| (v + cl * d) * (v + cl * d) - 1.0).fold(f64::MIN, f64::max);
            let got = p.min_pressure(a).suction;
            assert!((got / avd - 1.0).abs() < 0.05, "{deg} deg: -Cp_min {got} vs A&vD {avd} (C_l {cl})");
        }
    }

    /// The a = 0.8 mean line with a thin NACA 66 (DTRC modified) form (C_Li 0.5, t0/c 0.04) at
    /// its ideal angle, 0.77 deg: thin-airfoil theory gives C_L = C_Li = 0.5; the panel solution
    /// gives more: the thickness's lift gain of about 0.77 t/c (3 %) and the discretisation's
    /// excess (3 %, see the lift-slope test) less the camber's zero-lift angle reached at less
    /// than the thin-line slope (measured 0.5125, +2.5 %; tolerance 0.5 to 0.54).
    #[test]
    fn a08_section_lifts_its_design_cl_at_the_ideal_angle() {
        let cli = 0.5;
        let s = section(cli * a08_camber_per_cli(), 0.04, PANELS_PER_SIDE);
        let p = Panels::new(&s.points, s.nose).unwrap();
        let ai = cli * a08_ideal_angle_per_cli();
        let cl = p.lift_coefficient(ai);
        assert!((0.5..0.54).contains(&cl), "C_L at the ideal angle {cl}");
    }

    /// The cavitation bucket of an a = 0.8 + NACA 66 (DTRC modified) section (f0/c 0.02, t0/c
    /// 0.06: C_Li 0.29). At the ideal angle -Cp_min is within 20 % of the bucket's bottom
    /// (measured 14 %), the bottom is within 1 deg of the ideal angle (measured 0.85 deg below it),
    /// and -Cp_min at the ideal angle agrees within 6 % with Abbott & von Doenhoff's superposition
    /// (v/V_thickness + 0.278 C_Li)^2 - 1 (their Delta v/V = 0.278 for the a = 0.8 line at C_Li = 1,
    /// v/V_thickness from the symmetric section's panel solution; measured 0.338 vs 0.328, +3 %).
    /// Three degrees off
    /// the bottom the leading-edge peaks have more than doubled it on both sides.
    #[test]
    fn a08_66_bucket_is_flat_bottomed_at_the_ideal_angle() {
        let f0 = 0.02;
        let cli = f0 / a08_camber_per_cli();
        let s = section(f0, 0.06, PANELS_PER_SIDE);
        let p = Panels::new(&s.points, s.nose).unwrap();
        let b = Bucket::new(&p);
        let ai = cli * a08_ideal_angle_per_cli();
        let (a_bot, cp_bot) = b.bottom();
        let at_ideal = b.at(ai).both();
        let sym = section(0.0, 0.06, PANELS_PER_SIDE);
        let s0 = Panels::new(&sym.points, sym.nose).unwrap().min_pressure(0.0).both();
        let v = (1.0 + s0).sqrt() + 0.278 * cli;
        let avd = v * v - 1.0;
        let three = 3f64.to_radians();
        assert!(at_ideal < 1.2 * cp_bot, "-Cp_min {at_ideal} at the ideal angle, bottom {cp_bot}");
        assert!((a_bot - ai).abs() < 1f64.to_radians(), "bottom at {} deg", a_bot.to_degrees());
        assert!((at_ideal / avd - 1.0).abs() < 0.06, "at the ideal angle {at_ideal} vs superposition {avd}");
        assert!(b.at(a_bot + three).suction > 2.0 * cp_bot && b.at(a_bot - three).pressure > 2.0 * cp_bot);
        // The table reproduces the direct solution between its points (to 1e-3).
        let a = ai + 0.0123;
        assert!((b.at(a).suction - p.min_pressure(a).suction).abs() < 1e-3);
    }

    /// Lift slope of a 4 % NACA 66 (DTRC modified) section against thin-airfoil theory with the
    /// thickness correction (1 + 0.77 t/c) 2 pi = 1.031 x 2 pi (Abbott & von Doenhoff 1959,
    /// ch. 7: thicker sections lift more in potential flow): the method converges at first order
    /// (1.0655 with 120 panels a side, 1.0485 with 240); the Richardson limit 2 s(240) - s(120)
    /// is within 1 % of 1.031 (measured 1.0315). With [`PANELS_PER_SIDE`] the lift is 3 % high.
    #[test]
    fn lift_slope_converges_to_the_thickness_corrected_value() {
        let slope = |n: usize| {
            let s = section(0.0, 0.04, n);
            let p = Panels::new(&s.points, s.nose).unwrap();
            (p.lift_coefficient(0.01) - p.lift_coefficient(-0.01)) / 0.02 / (2.0 * std::f64::consts::PI)
        };
        let (s1, s2) = (slope(120), slope(240));
        let limit = 2.0 * s2 - s1;
        assert!((limit / 1.031 - 1.0).abs() < 0.01, "slopes {s1} {s2}, limit {limit}");
        assert!(s1 > s2 && s2 > limit, "converging from above: {s1} {s2}");
    }
}
