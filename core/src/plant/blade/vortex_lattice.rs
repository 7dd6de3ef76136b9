//! A steady vortex-lattice lifting surface of a propeller in open water: the blade's chord resolved,
//! where the lifting line ([`super::lifting_line`]) carries it only through Morgan's (1968)
//! lifting-surface factors. It is the check of those factors, not the run's model: a lattice point
//! costs about as much as 75 lifting-line points (28 ms against 0.36 ms on DTMB 4119).
//!
//! The method is the linear lifting surface of Kerwin & Lee (1978, "Prediction of steady and unsteady
//! marine propeller performance by numerical lifting-surface theory", Trans. SNAME 86), simplified:
//! - the blade's nose-tail helicoid (pitch P(r), no skew or rake) carries N chordwise by M spanwise
//!   horseshoes, uniformly spaced along the chord with the bound vortex at each panel's quarter and
//!   the control point at its three quarters (a rule that is exact for a flat plate in two
//!   dimensions; test `two_dimensional_limits`), the same cosine-spaced radii as the lifting line;
//! - each horseshoe's legs run along the blade to the trailing edge and leave it as helices of one
//!   pitch r tan(beta_w) = lambda_w for the whole wake, aligned (as the lifting line's) with the
//!   circulation-weighted hydrodynamic pitch of the total inflow at the bound vortices, with the
//!   lifting line's hub image of each trailer;
//! - the boundary condition on the camber: the total inflow's component normal to the helicoid
//!   equals V* times the slope of the NACA a = 0.8 mean line (Abbott & von Doenhoff 1959, ch. 4.3),
//!   V* the total inflow at the control point;
//! - forces: Kutta-Joukowski on the bound vortices with the local total velocity, split into its part
//!   normal to the blade (the pressure's) and its part along the surface (the leading edge's
//!   suction), the suction turned normal to the blade by Polhamus's leading-edge suction analogy
//!   (NASA TN D-3767, 1966): the flow separates at a thin edge and the vortex it rolls into gives back
//!   as normal force what potential flow gives as suction (no constant is fitted); and each strip's
//!   viscous drag from the lifting line's friction line.
//!
//! Thickness is not modelled (no source sheet): Morgan's thickness factor, the lifting line's, is
//! left out, which is the method's main known omission. Inside, lengths are in tip radii R and
//! speeds in n D, as in the lifting line.

use super::friction::section_drag;
use super::induction::segment;
use super::lifting_line::{interp, LiftingLine};
use super::mean_line::TABLE_CAMBER_RATIO;
use super::{BladeGeometry, Flow};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Chordwise panels (Kerwin & Lee used 6 to 10; 6 and 12 agree on KT to 1 %, test `converged_in_the_lattice`).
pub const CHORDWISE: usize = 6;
/// Spanwise panels (the lifting line's default).
pub const SPANWISE: usize = 12;
/// The wake is followed this far downstream of the trailing edge \[R\] (8 and 16 agree to 1 %).
pub const WAKE_LENGTH: f64 = 8.0;
/// Straight segments per turn of a wake helix.
const SEGMENTS_PER_TURN: usize = 24;
/// Smallest wake pitch lambda_w (near bollard pull), and the most turns followed: the work is bounded.
const MIN_WAKE_PITCH: f64 = 0.05;
const MAX_TURNS: f64 = 16.0;
/// Wake pitches tried before a point is called unconverged, and the tolerance on lambda_w.
const MAX_ALIGNMENTS: usize = 12;
const WAKE_TOLERANCE: f64 = 1e-6;

type V3 = [f64; 3];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Slope dy/dx of the NACA a = 0.8 mean line of ideal lift coefficient 1 at chord fraction `x`
/// (Abbott & von Doenhoff 1959, eq. 4.27 differentiated) \[-\]; log-singular at the leading edge and
/// at x = a, integrable.
pub fn a08_slope(x: f64) -> f64 {
    let a = 0.8f64;
    let g = -(a * a * (0.5 * libm::log(a) - 0.25) + 0.25) / (1.0 - a);
    let h = (0.5 * (1.0 - a) * (1.0 - a) * libm::log(1.0 - a) - 0.25 * (1.0 - a) * (1.0 - a)) / (1.0 - a) + g;
    let xlx = |v: f64| if v == 0.0 { 0.0 } else { v * libm::log(v.abs()) };
    ((xlx(1.0 - x) - xlx(a - x)) / (1.0 - a) - libm::log(x) - 1.0 - h) / (2.0 * PI * (a + 1.0))
}

/// The open-water point of the lattice at one advance ratio.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LatticePoint {
    /// Advance ratio J \[-\].
    pub j: f64,
    /// Thrust coefficient KT \[-\].
    pub kt: f64,
    /// Torque coefficient KQ \[-\].
    pub kq: f64,
    /// Open-water efficiency J KT / (2 pi KQ) \[-\]; 0 where KT or KQ is not positive.
    pub eta: f64,
    /// The aligned wake's pitch lambda_w = r tan(beta_w) over R \[-\].
    pub wake_pitch: f64,
    /// Whether the wake's pitch converged (to 1e-6).
    pub converged: bool,
}

/// A blade discretised for the lattice, ready to solve at any J.
pub struct Lattice {
    blades: u32,
    /// Chordwise and spanwise panels.
    n: usize,
    m: usize,
    hub: f64,
    /// Vortex radii (M + 1) and strip radii (M), r/R.
    rv: Vec<f64>,
    rc: Vec<f64>,
    /// Chord over R at the strips, and their t0/c.
    chord: Vec<f64>,
    t0_c: Vec<f64>,
    /// The key blade's lattice: at vortex radius k, the bound vortices' points (q < N) and the
    /// trailing edge (q = N), [k * (N + 1) + q].
    grid: Vec<V3>,
    /// Control points [i * N + q], their normals (toward the pressure face) and camber slopes.
    cps: Vec<V3>,
    normals: Vec<V3>,
    camber_slope: Vec<f64>,
    flow: Flow,
    line: LiftingLine,
    /// Whether the leading edge's suction is turned normal to the blade (Polhamus), as always but in
    /// the check that a narrow blade is the lifting line, whose Kutta-Joukowski forces keep it.
    polhamus: bool,
}

/// Rotates `p` by `angle` about the shaft (x) axis.
fn rotate(p: V3, angle: f64) -> V3 {
    let (s, c) = (libm::sin(angle), libm::cos(angle));
    [p[0], p[1] * c - p[2] * s, p[1] * s + p[2] * c]
}

/// The undisturbed inflow at `p` in the blade's frame: J along the shaft, pi r in +theta \[n D\].
fn inflow(j: f64, p: V3) -> V3 {
    [j, -PI * p[2], PI * p[1]]
}

impl Lattice {
    pub fn new(g: &BladeGeometry, flow: &Flow) -> Result<Lattice, String> {
        Self::with_panels(g, flow, CHORDWISE, SPANWISE)
    }

    /// The same with `n` chordwise (2 to 20) and `m` spanwise (4 to 40) panels.
    pub fn with_panels(g: &BladeGeometry, flow: &Flow, n: usize, m: usize) -> Result<Lattice, String> {
        if !(2..=20).contains(&n) {
            return Err(format!("chordwise panels: {n} is outside 2..=20"));
        }
        if !(4..=40).contains(&m) {
            return Err(format!("spanwise panels: {m} is outside 4..=40"));
        }
        let line = LiftingLine::with_panels(g, flow, m)?;
        let hub = g.hub_ratio.max(g.rows[0].r_r);
        let at = |k: f64| hub + (1.0 - hub) * 0.5 * (1.0 - libm::cos(k * PI / m as f64));
        let rv: Vec<f64> = (0..=m).map(|k| at(k as f64)).collect();
        let rc: Vec<f64> = (0..m).map(|k| at(k as f64 + 0.5)).collect();
        let xs: Vec<f64> = g.rows.iter().map(|r| r.r_r).collect();
        let column = |f: fn(&super::Row) -> f64| -> Vec<f64> { g.rows.iter().map(f).collect() };
        let (c_d, p_d, f0_c, t0_c) = (column(|r| r.c_d), column(|r| r.p_d), column(|r| r.f0_c), column(|r| r.t0_c));
        // A point of the helicoid at radius r and chord fraction u from the leading edge: the chord runs
        // downstream and toward +theta (the inflow's direction in the blade's frame) at the pitch angle.
        let point = |r: f64, u: f64| -> V3 {
            let s = (u - 0.5) * 2.0 * interp(&xs, &c_d, r);
            let phi = libm::atan(interp(&xs, &p_d, r) / (PI * r));
            let theta = s * libm::cos(phi) / r;
            [s * libm::sin(phi), r * libm::cos(theta), r * libm::sin(theta)]
        };
        let bound_u = |q: usize| (q as f64 + 0.25) / n as f64;
        let control_u = |q: usize| (q as f64 + 0.75) / n as f64;
        let mut grid = Vec::with_capacity((m + 1) * (n + 1));
        for &r in &rv {
            grid.extend((0..n).map(|q| point(r, bound_u(q))));
            grid.push(point(r, 1.0));
        }
        let (mut cps, mut normals, mut camber_slope) = (Vec::new(), Vec::new(), Vec::new());
        for &r in &rc {
            let phi = libm::atan(interp(&xs, &p_d, r) / (PI * r));
            for q in 0..n {
                let p = point(r, control_u(q));
                let theta = libm::atan2(p[2], p[1]);
                let e_theta = [0.0, -libm::sin(theta), libm::cos(theta)];
                cps.push(p);
                normals.push(add([libm::cos(phi), 0.0, 0.0], scale(e_theta, -libm::sin(phi))));
                camber_slope.push(interp(&xs, &f0_c, r) / TABLE_CAMBER_RATIO * a08_slope(control_u(q)));
            }
        }
        Ok(Lattice {
            blades: g.blades,
            n,
            m,
            hub,
            chord: rc.iter().map(|&r| 2.0 * interp(&xs, &c_d, r)).collect(),
            t0_c: rc.iter().map(|&r| interp(&xs, &t0_c, r)).collect(),
            rv,
            rc,
            grid,
            cps,
            normals,
            camber_slope,
            flow: *flow,
            line,
            polhamus: true,
        })
    }

    /// The same lattice with Kutta-Joukowski's forces as they are (the suction kept along the chord).
    #[cfg(test)]
    fn kutta_joukowski(mut self) -> Self {
        self.polhamus = false;
        self
    }

    /// The wake helix of the trailer leaving the trailing edge at vortex radius index `k` of blade
    /// `b`, at radius `radius` (its own, or its hub image's), pitch `lambda`.
    fn helix(&self, k: usize, b: usize, radius: f64, lambda: f64) -> Vec<V3> {
        let te = self.grid[k * (self.n + 1) + self.n];
        let theta0 = libm::atan2(te[2], te[1]) + 2.0 * PI * b as f64 / self.blades as f64;
        let turns = (WAKE_LENGTH / (2.0 * PI * lambda)).min(MAX_TURNS);
        let count = (turns * SEGMENTS_PER_TURN as f64).ceil() as usize;
        (0..=count)
            .map(|i| {
                let psi = 2.0 * PI * i as f64 / SEGMENTS_PER_TURN as f64;
                let theta = theta0 + psi;
                [te[0] + lambda * psi, radius * libm::cos(theta), radius * libm::sin(theta)]
            })
            .collect()
    }

    /// The velocity each horseshoe of unit circulation (on all Z blades) induces at `p`, given the
    /// wake helices (with hub images) `wakes[b][k]`: [element i * N + q].
    fn influence_at(&self, p: V3, wakes: &[Vec<(Vec<V3>, Vec<V3>)>]) -> Vec<V3> {
        let (n, m) = (self.n, self.m);
        let polyline = |pts: &[V3]| pts.windows(2).fold([0.0; 3], |v, w| add(v, segment(w[0], w[1], p)));
        let mut bound = vec![[0.0; 3]; m * n];
        // legs[k * N + q]: from the bound point q at vortex radius k along the blade to the trailing edge.
        let mut legs = vec![[0.0; 3]; (m + 1) * n];
        let mut trail = vec![[0.0; 3]; m + 1];
        for (b, blade_wakes) in wakes.iter().enumerate() {
            let angle = 2.0 * PI * b as f64 / self.blades as f64;
            let at = |k: usize, q: usize| rotate(self.grid[k * (n + 1) + q], angle);
            for k in 0..=m {
                let mut tail = [0.0; 3];
                for q in (0..n).rev() {
                    tail = add(tail, segment(at(k, q), at(k, q + 1), p));
                    legs[k * n + q] = add(legs[k * n + q], tail);
                }
                let (own, image) = &blade_wakes[k];
                trail[k] = add(trail[k], sub(polyline(own), polyline(image)));
                if k < m {
                    for q in 0..n {
                        bound[k * n + q] = add(bound[k * n + q], segment(at(k, q), at(k + 1, q), p));
                    }
                }
            }
        }
        // Horseshoe (i, q): in along the wake and blade at radius i, bound outward, out at radius i + 1.
        let mut out = Vec::with_capacity(m * n);
        for i in 0..m {
            for q in 0..n {
                let outer = add(legs[(i + 1) * n + q], trail[i + 1]);
                let inner = add(legs[i * n + q], trail[i]);
                out.push(add(bound[i * n + q], sub(outer, inner)));
            }
        }
        out
    }

    /// Circulation, thrust, torque and the wake's own pitch for a wake frozen at `lambda`.
    fn frozen_wake(&self, j: f64, lambda: f64) -> Result<(Vec<f64>, f64, f64, f64), String> {
        let (n, m, z) = (self.n, self.m, self.blades as usize);
        let hub2 = self.hub * self.hub;
        let wakes: Vec<Vec<(Vec<V3>, Vec<V3>)>> = (0..z)
            .map(|b| {
                (0..=m)
                    .map(|k| (self.helix(k, b, self.rv[k], lambda), self.helix(k, b, hub2 / self.rv[k], lambda)))
                    .collect()
            })
            .collect();
        let size = m * n;
        let at_cps: Vec<Vec<V3>> = self.cps.iter().map(|&p| self.influence_at(p, &wakes)).collect();
        let mut a = vec![0.0; size * size];
        for (row, infl) in at_cps.iter().enumerate() {
            for (col, v) in infl.iter().enumerate() {
                a[row * size + col] = dot(*v, self.normals[row]);
            }
        }
        // V* in the camber's condition is the total inflow: solve with the undisturbed speed, then
        // twice more with the speed the solution gives (the matrix is the same).
        let mut gamma = vec![0.0; size];
        for pass in 0..3 {
            let mut rhs = vec![0.0; size];
            for (row, &p) in self.cps.iter().enumerate() {
                let mut v = inflow(j, p);
                if pass > 0 {
                    v = at_cps[row].iter().zip(&gamma).fold(v, |s, (u, g)| add(s, scale(*u, *g)));
                }
                rhs[row] = -dot(inflow(j, p), self.normals[row]) - dot(v, v).sqrt() * self.camber_slope[row];
            }
            let mut lu = a.clone();
            gamma = super::lifting_line::solve_linear(&mut lu, &mut rhs, size)
                .ok_or("the vortex lattice's matrix is singular")?;
        }
        // Forces at the bound vortices' midpoints.
        let (mut kt, mut kq) = (0.0, 0.0);
        let (mut num, mut den) = (0.0, 0.0);
        let zf = z as f64;
        for i in 0..m {
            let mut strip = [0.0; 3];
            let mut strip_gamma = 0.0;
            let (mut strip_pressure, mut strip_suction, mut strip_kutta) = ([0.0; 3], [0.0; 3], [0.0; 3]);
            let mut strip_r = 0.0;
            for q in 0..n {
                let (pa, pb) = (self.grid[i * (n + 1) + q], self.grid[(i + 1) * (n + 1) + q]);
                let mid = scale(add(pa, pb), 0.5);
                let infl = self.influence_at(mid, &wakes);
                let v = infl.iter().zip(&gamma).fold(inflow(j, mid), |s, (u, g)| add(s, scale(*u, *g)));
                let g = gamma[i * n + q];
                let r = libm::hypot(mid[1], mid[2]);
                let e_theta = [0.0, -mid[2] / r, mid[1] / r];
                // Kutta-Joukowski's force split into its part normal to the blade (the pressure's)
                // and its part along the surface (the leading edge's suction); the suction is taken
                // as turned normal to the blade, Polhamus's (1966) leading-edge suction analogy for
                // a thin edge whose flow separates into a vortex.
                let nx = self.normals[i * n + q][0];
                // In the section's own axial and tangential directions (a chord spans up to a radian).
                let force = scale(cross(v, sub(pb, pa)), g);
                let kutta = [force[0], dot(force, e_theta), 0.0];
                let normal_local = [nx, -(1.0 - nx * nx).sqrt(), 0.0];
                let pressure = scale(normal_local, dot(kutta, normal_local));
                strip_pressure = add(strip_pressure, pressure);
                strip_suction = add(strip_suction, sub(kutta, pressure));
                strip_kutta = add(strip_kutta, kutta);
                strip_r = r;
                // The strip's circulation-weighted velocity, in its axial and tangential directions:
                // weighted so that the bound vortices' velocities at one another cancel in pairs, as
                // in the forces (an unweighted mean kept them, and on a narrow chord they dominate).
                strip = add(strip, scale([v[0], dot(v, e_theta), 0.0], g));
                strip_gamma += g;
            }
            // The strip's suction (summed over its chord, where the bound vortices' forces on one
            // another cancel in pairs) turned normal to the blade, along its pressure force.
            let along = dot(strip_pressure, strip_pressure).sqrt();
            let suction = dot(strip_suction, strip_suction).sqrt();
            let f =
                if self.polhamus && along > 0.0 { scale(strip_pressure, 1.0 + suction / along) } else { strip_kutta };
            kt -= zf * f[0] / 4.0;
            kq += zf * f[1] * strip_r / 8.0;
            strip = if strip_gamma.abs() > 1e-12 {
                scale(strip, 1.0 / strip_gamma)
            } else {
                let mid = scale(add(self.grid[i * (n + 1)], self.grid[(i + 1) * (n + 1)]), 0.5);
                let r = libm::hypot(mid[1], mid[2]);
                [j, PI * r, 0.0]
            };
            // Viscous drag along the strip's mean inflow.
            let speed = libm::hypot(strip[0], strip[1]);
            let (d_m, nd) = (self.flow.diameter_m, self.flow.rev_per_s * self.flow.diameter_m);
            let reynolds = speed * nd * self.chord[i] * d_m / 2.0 / self.flow.kinematic_viscosity_m2_s;
            let dr = self.rv[i + 1] - self.rv[i];
            let drag = 0.5 * speed * self.chord[i] * section_drag(reynolds, self.t0_c[i]) * dr;
            kt -= zf * drag * strip[0] / 4.0;
            kq += zf * drag * strip[1] * self.rc[i] / 8.0;
            let w = strip_gamma.abs() * dr;
            num += w * self.rc[i] * strip[0] / strip[1];
            den += w;
        }
        let own = if den > 0.0 { num / den } else { lambda };
        Ok((gamma, kt, kq, own))
    }

    /// The open-water point at advance ratio `j`: the wake's pitch found by the secant method from the
    /// lifting line's, as the lifting line finds its own.
    pub fn solve(&self, j: f64) -> Result<LatticePoint, String> {
        super::check_advance_ratio(j)?;
        let start = self.line.solve(j)?;
        let mut lambda = self.line.wake_pitch(&start).max(MIN_WAKE_PITCH);
        let mut last: Option<(f64, f64)> = None;
        let (mut kt, mut kq, mut converged) = (0.0, 0.0, false);
        for _ in 0..MAX_ALIGNMENTS {
            let (_, t, q, own) = self.frozen_wake(j, lambda)?;
            (kt, kq) = (t, q);
            let miss = own.max(MIN_WAKE_PITCH) - lambda;
            if miss.abs() < WAKE_TOLERANCE {
                converged = true;
                break;
            }
            let secant = last.and_then(|(l0, m0)| {
                let slope = (miss - m0) / (lambda - l0);
                let next = lambda - miss / slope;
                (slope.is_finite() && slope < 0.0 && next > 0.0).then_some(next)
            });
            last = Some((lambda, miss));
            lambda = secant.unwrap_or(lambda + 0.5 * miss).max(MIN_WAKE_PITCH);
        }
        let eta = if kt > 0.0 && kq > 0.0 { j * kt / (2.0 * PI * kq) } else { 0.0 };
        Ok(LatticePoint { j, kt, kq, eta, wake_pitch: lambda, converged })
    }
}

/// The open-water curve of `g` by the vortex lattice at the advance ratios `js`.
pub fn open_water(g: &BladeGeometry, js: &[f64], flow: &Flow) -> Result<Vec<LatticePoint>, String> {
    let lattice = Lattice::new(g, flow)?;
    js.iter().map(|&j| lattice.solve(j)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const P4119: &str = include_str!("../../../data/dtmb4119_geometry.csv");

    /// The 2D lattice of `n` panels with the quarter / three-quarter rule: the lift coefficient of a
    /// plate at `alpha` with camber slope `slope(x)` in a unit stream.
    fn lift_2d(n: usize, alpha: f64, slope: impl Fn(f64) -> f64) -> f64 {
        let mut a = vec![0.0; n * n];
        let mut b = vec![0.0; n];
        for i in 0..n {
            let xc = (i as f64 + 0.75) / n as f64;
            for k in 0..n {
                a[i * n + k] = 1.0 / (2.0 * PI * (xc - (k as f64 + 0.25) / n as f64));
            }
            b[i] = alpha - slope(xc);
        }
        let g = super::super::lifting_line::solve_linear(&mut a, &mut b, n).unwrap();
        2.0 * g.iter().sum::<f64>()
    }

    #[test]
    fn two_dimensional_limits() {
        // The quarter / three-quarter rule lifts a flat plate 2 pi alpha exactly, at any panel count.
        for n in [1, 4, 6, 12] {
            let cl = lift_2d(n, 0.05, |_| 0.0);
            assert!((cl - 2.0 * PI * 0.05).abs() < 1e-12, "N {n}: {cl}");
        }
        // The a = 0.8 mean line: the slope integrates to zero (closed ends), its largest ordinate is
        // the tabulated 0.0679 of C_Li = 1, and at its ideal angle of 1.54 deg the lattice lifts 1
        // (measured: 1.020 with 6 panels, 1.004 with 24: the mean line's slope is log-singular at 0.8 c).
        let steps = 200_000;
        let (mut y, mut y_max) = (0.0f64, 0.0f64);
        for i in 0..steps {
            y += a08_slope((i as f64 + 0.5) / steps as f64) / steps as f64;
            y_max = y_max.max(y);
        }
        assert!(y.abs() < 1e-6 && (y_max - 0.0679).abs() < 1e-4, "y(1) {y}, max {y_max}");
        for (n, tol) in [(CHORDWISE, 0.025), (24, 0.006)] {
            let cl = lift_2d(n, 1.54f64.to_radians(), a08_slope);
            assert!((cl - 1.0).abs() < tol, "N {n}: C_L {cl}");
        }
    }

    #[test]
    fn a_narrow_blade_is_a_lifting_line() {
        // As the chord shrinks the lifting surface becomes the lifting line without lifting-surface
        // corrections. DTMB 4119's chord over 20 / 60 / 200, lattice against line at J 0.5: KT -2.1 /
        // -1.1 / -1.0 %, KQ -2.5 / -1.2 / -0.9 %; at J 0.833: KT -0.8 / +0.4 / +0.7 %, KQ -0.8 / +0.3 /
        // +0.6 % (measured). The last per cent is Wrench's factors against the lattice's Biot-Savart sum.
        for (f, tol) in [(20.0, 0.03), (60.0, 0.015)] {
            let mut g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
            g.rows.iter_mut().for_each(|r| r.c_d /= f);
            let flow = Flow::fresh_water(0.3048, 10.0);
            let lattice = Lattice::new(&g, &flow).unwrap().kutta_joukowski();
            let line = LiftingLine::with_panels(&g, &flow, SPANWISE).unwrap().without_surface_corrections();
            for j in [0.5, 0.833] {
                let (s, l) = (lattice.solve(j).unwrap(), line.solve(j).unwrap());
                assert!(s.converged && l.converged);
                let (dt, dq) = (s.kt / l.kt - 1.0, s.kq / l.kq - 1.0);
                assert!(dt.abs() < tol && dq.abs() < tol, "chord / {f}, J {j}: KT {dt:+.4}, KQ {dq:+.4}");
            }
        }
    }

    #[test]
    fn converged_in_the_lattice() {
        // DTMB 4119 at J 0.5 and 0.833: 6 against 12 chordwise panels, 12 against 24 spanwise (measured:
        // 6 / 8 / 12 / 16 chordwise give KT 0.2631 / 0.2627 / 0.2617 / 0.2609 at J 0.5).
        let g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        let flow = Flow::fresh_water(0.3048, 10.0);
        let base = Lattice::new(&g, &flow).unwrap();
        let fine_n = Lattice::with_panels(&g, &flow, 12, SPANWISE).unwrap();
        let fine_m = Lattice::with_panels(&g, &flow, CHORDWISE, 24).unwrap();
        for j in [0.5, 0.833] {
            let a = base.solve(j).unwrap();
            for (name, f) in [("chordwise", &fine_n), ("spanwise", &fine_m)] {
                let b = f.solve(j).unwrap();
                let (dt, dq) = (a.kt / b.kt - 1.0, a.kq / b.kq - 1.0);
                eprintln!("{name} J {j}: KT {dt:+.4} KQ {dq:+.4}");
                assert!(dt.abs() < 0.02 && dq.abs() < 0.02, "{name} J {j}: KT {dt:+.4}, KQ {dq:+.4}");
            }
        }
        assert!(Lattice::with_panels(&g, &flow, 1, 12).err().unwrap().starts_with("chordwise panels: 1"));
        assert!(base.solve(f64::NAN).unwrap_err().starts_with("j: NaN"));
    }
}
