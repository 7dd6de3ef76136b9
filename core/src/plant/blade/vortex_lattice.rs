//! A steady vortex-lattice lifting surface of a propeller in open water: the blade's chord resolved,
//! where the lifting line ([`super::lifting_line`]) carries it only through Morgan's (1968)
//! lifting-surface factors. It is the run's model of KT and KQ (`propeller.model = "geometry"`);
//! a curve tabulates the wake's influence over the wake pitches once, so 25 points of DTMB 4119
//! cost about 37 ms.
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
use super::induction::{polyline, segment};
use super::lifting_line::{interp, LiftingLine};
use super::mean_line::TABLE_CAMBER_RATIO;
use super::{BladeGeometry, Flow};
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
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
/// The wake table's Chebyshev points: at least this many, and this many more per e-fold of the
/// pitches it spans; a curve widens the lifting line's range of pitches by this factor either way.
const TABLE_NODES_MIN: u32 = 3;
const TABLE_NODES_PER_E_FOLD: f64 = 5.0;
const TABLE_MARGIN: f64 = 1.25;

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
    /// At each field point ([`Lattice::field_points`]), each horseshoe's velocity through its
    /// vortices on the blades ([`Lattice::blade_influence`]): they do not depend on the wake.
    blade_at: Vec<Vec<V3>>,
    /// The wake table the last curve used, kept while later curves' pitches fall inside it.
    table: RefCell<Option<WakeTable>>,
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
        let mut lattice = Lattice {
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
            blade_at: Vec::new(),
            table: RefCell::new(None),
        };
        lattice.blade_at = lattice.field_points().into_iter().map(|p| lattice.blade_influence(p)).collect();
        Ok(lattice)
    }

    /// The same lattice with Kutta-Joukowski's forces as they are (the suction kept along the chord).
    #[cfg(test)]
    fn kutta_joukowski(mut self) -> Self {
        self.polhamus = false;
        self
    }

    /// The wake helix of the trailer leaving the trailing edge at vortex radius index `k` of blade
    /// `b`, at radius `radius` (its own, or its hub image's), pitch `lambda`: `SEGMENTS_PER_TURN`
    /// straight segments a turn over the first turn, where the blade is near, half as many after.
    fn helix(&self, k: usize, b: usize, radius: f64, lambda: f64) -> Vec<V3> {
        let te = self.grid[k * (self.n + 1) + self.n];
        let theta0 = libm::atan2(te[2], te[1]) + 2.0 * PI * b as f64 / self.blades as f64;
        let end = 2.0 * PI * (WAKE_LENGTH / (2.0 * PI * lambda)).min(MAX_TURNS);
        let (fine, coarse) = (2.0 * PI / SEGMENTS_PER_TURN as f64, 4.0 * PI / SEGMENTS_PER_TURN as f64);
        let mut out = Vec::new();
        let mut psi = 0.0;
        loop {
            let theta = theta0 + psi;
            out.push([te[0] + lambda * psi, radius * libm::cos(theta), radius * libm::sin(theta)]);
            if psi >= end {
                break out;
            }
            psi = (psi + if psi < 2.0 * PI - 1e-9 { fine } else { coarse }).min(end);
        }
    }

    /// The points the velocity is wanted at: the control points, then the bound vortices' midpoints.
    fn field_points(&self) -> Vec<V3> {
        let (n, m) = (self.n, self.m);
        let mids = (0..m * n).map(|e| {
            let (i, q) = (e / n, e % n);
            scale(add(self.grid[i * (n + 1) + q], self.grid[(i + 1) * (n + 1) + q]), 0.5)
        });
        self.cps.iter().copied().chain(mids).collect()
    }

    /// The velocity each horseshoe of unit circulation (on all Z blades) induces at `p` through its
    /// vortices on the blade (bound, and legs to the trailing edge; not the wake's): [i * N + q].
    fn blade_influence(&self, p: V3) -> Vec<V3> {
        let (n, m) = (self.n, self.m);
        let mut bound = vec![[0.0; 3]; m * n];
        // legs[k * N + q]: from the bound point q at vortex radius k along the blade to the trailing edge.
        let mut legs = vec![[0.0; 3]; (m + 1) * n];
        for b in 0..self.blades as usize {
            let angle = 2.0 * PI * b as f64 / self.blades as f64;
            let at = |k: usize, q: usize| rotate(self.grid[k * (n + 1) + q], angle);
            for k in 0..=m {
                let mut tail = [0.0; 3];
                for q in (0..n).rev() {
                    tail = add(tail, segment(at(k, q), at(k, q + 1), p));
                    legs[k * n + q] = add(legs[k * n + q], tail);
                }
                if k < m {
                    for q in 0..n {
                        bound[k * n + q] = add(bound[k * n + q], segment(at(k, q), at(k + 1, q), p));
                    }
                }
            }
        }
        // Horseshoe (i, q): in along the blade at radius i, bound outward, out at radius i + 1.
        (0..m * n).map(|e| add(bound[e], sub(legs[e + n], legs[e]))).collect()
    }

    /// The velocity the wake's trailers of unit circulation leaving vortex radius k (on all Z blades,
    /// less their hub images) induce at each of `points`, wake pitch `lambda`: [point * (M + 1) + k].
    fn wake_influence(&self, points: &[V3], lambda: f64) -> Vec<V3> {
        let (m, z) = (self.m, self.blades as usize);
        let hub2 = self.hub * self.hub;
        let wakes: Vec<(Vec<V3>, Vec<V3>)> = (0..z)
            .flat_map(|b| {
                (0..=m)
                    .map(move |k| (self.helix(k, b, self.rv[k], lambda), self.helix(k, b, hub2 / self.rv[k], lambda)))
            })
            .collect();
        let mut out = Vec::with_capacity(points.len() * (m + 1));
        for &p in points {
            let mut trail = vec![[0.0; 3]; m + 1];
            for (e, (own, image)) in wakes.iter().enumerate() {
                trail[e % (m + 1)] = add(trail[e % (m + 1)], sub(polyline(own, p), polyline(image, p)));
            }
            out.extend(trail);
        }
        out
    }

    /// The wake's influence tabulated over wake pitches `lo` to `hi`: an open-water curve's points
    /// then cost a linear solve per wake pitch tried instead of a Biot-Savart sum over the helices.
    pub fn wake_table(&self, lo: f64, hi: f64) -> WakeTable {
        let (lo, hi) = (lo.max(MIN_WAKE_PITCH), hi.max(lo * 1.01));
        let (a, b) = (libm::log(lo), libm::log(hi));
        let span = b - a;
        let count = (TABLE_NODES_MIN as f64 + TABLE_NODES_PER_E_FOLD * span).ceil() as usize;
        // Chebyshev-Lobatto points in ln(lambda), with their barycentric weights.
        let nodes: Vec<f64> =
            (0..count).map(|i| a + 0.5 * span * (1.0 - libm::cos(PI * i as f64 / (count - 1) as f64))).collect();
        let points = self.field_points();
        let values = nodes.iter().map(|&x| self.wake_influence(&points, libm::exp(x))).collect();
        WakeTable { lo, hi, nodes, values }
    }

    /// The wake's influence at all field points at pitch `lambda`: from `table` where it covers it.
    fn wake_at(&self, lambda: f64, table: Option<&WakeTable>) -> Vec<V3> {
        match table {
            Some(t) if lambda >= t.lo && lambda <= t.hi => t.at(lambda),
            _ => self.wake_influence(&self.field_points(), lambda),
        }
    }

    /// Circulation, thrust, torque and the wake's own pitch for a wake frozen at `lambda`, whose
    /// influence at the field points is `wake` ([`Lattice::wake_influence`]'s layout).
    fn frozen_wake(&self, j: f64, lambda: f64, wake: &[V3]) -> Result<(Vec<f64>, f64, f64, f64), String> {
        let (n, m, z) = (self.n, self.m, self.blades as usize);
        let size = m * n;
        // The velocity at field point `p` of the horseshoes with circulation `gamma`, and of each alone.
        let horseshoe = |p: usize, e: usize| {
            let w = &wake[p * (m + 1)..(p + 1) * (m + 1)];
            add(self.blade_at[p][e], sub(w[e / n + 1], w[e / n]))
        };
        let induced = |p: usize, gamma: &[f64]| -> V3 {
            let w = &wake[p * (m + 1)..(p + 1) * (m + 1)];
            let mut v = self.blade_at[p].iter().zip(gamma).fold([0.0; 3], |s, (u, g)| add(s, scale(*u, *g)));
            for (e, &g) in gamma.iter().enumerate() {
                v = add(v, scale(sub(w[e / n + 1], w[e / n]), g));
            }
            v
        };
        let mut a = nalgebra::DMatrix::zeros(size, size);
        for row in 0..size {
            for col in 0..size {
                a[(row, col)] = dot(horseshoe(row, col), self.normals[row]);
            }
        }
        let lu = a.lu();
        // V* in the camber's condition is the total inflow: solve with the undisturbed speed, then
        // twice more with the speed the solution gives (the matrix is the same).
        let mut gamma = vec![0.0; size];
        for pass in 0..3 {
            let rhs = nalgebra::DVector::from_iterator(
                size,
                self.cps.iter().enumerate().map(|(row, &p)| {
                    let mut v = inflow(j, p);
                    if pass > 0 {
                        v = add(v, induced(row, &gamma));
                    }
                    -dot(inflow(j, p), self.normals[row]) - dot(v, v).sqrt() * self.camber_slope[row]
                }),
            );
            let x = lu.solve(&rhs).ok_or("the vortex lattice's matrix is singular")?;
            if x.iter().any(|v| !v.is_finite()) {
                return Err("the vortex lattice's matrix is singular".into());
            }
            gamma = x.iter().copied().collect();
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
                let v = add(inflow(j, mid), induced(size + i * n + q, &gamma));
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
                // By the circulation's size: near zero thrust the chord's loading changes sign, and
                // a signed weight's sum there can be near zero while the velocities are not.
                strip = add(strip, scale([v[0], dot(v, e_theta), 0.0], g.abs()));
                strip_gamma += g.abs();
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

    /// The open-water point at advance ratio `j` (the wake's influence summed afresh for each
    /// pitch tried).
    pub fn solve(&self, j: f64) -> Result<LatticePoint, String> {
        self.solve_with(j, None, None)
    }

    /// The open-water point at advance ratio `j`: the wake's pitch found by the secant method, from
    /// `start` (a neighbouring point's) or else the lifting line's, the wake's influence from `table`
    /// where it covers the pitch.
    fn solve_with(&self, j: f64, table: Option<&WakeTable>, start: Option<f64>) -> Result<LatticePoint, String> {
        super::check_advance_ratio(j)?;
        let mut lambda = match start {
            Some(l) => l,
            None => self.line.wake_pitch(&self.line.solve(j)?),
        }
        .max(MIN_WAKE_PITCH);
        let mut last: Option<(f64, f64)> = None;
        let (mut kt, mut kq, mut converged) = (0.0, 0.0, false);
        for _ in 0..MAX_ALIGNMENTS {
            let (_, t, q, own) = self.frozen_wake(j, lambda, &self.wake_at(lambda, table))?;
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

    /// The open-water curve at the advance ratios `js`: the wake's influence tabulated over the
    /// pitches the lifting line finds at the smallest and largest J, widened by `TABLE_MARGIN` either
    /// way (the table is kept for later curves inside it), each point started from its neighbour's
    /// pitch. Measured on DTMB 4119 at 25 J from 0 to 1.2: within 4e-4 of [`Lattice::solve`]'s KT
    /// and KQ, a tenth of the time.
    pub fn curve(&self, js: &[f64]) -> Result<Vec<LatticePoint>, String> {
        for &j in js {
            super::check_advance_ratio(j)?;
        }
        if js.is_empty() {
            return Ok(Vec::new());
        }
        let (lo, hi) = js.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &j| (a.min(j), b.max(j)));
        let pitch = |j: f64| -> Result<f64, String> { Ok(self.line.wake_pitch(&self.line.solve(j)?)) };
        let (lo, hi) = (pitch(lo)? / TABLE_MARGIN, pitch(hi)? * TABLE_MARGIN);
        let mut kept = self.table.borrow_mut();
        let covered = kept.as_ref().is_some_and(|t| t.lo <= lo.max(MIN_WAKE_PITCH) && t.hi >= hi);
        if !covered {
            let (lo, hi) = kept.as_ref().map_or((lo, hi), |t| (t.lo.min(lo), t.hi.max(hi)));
            *kept = Some(self.wake_table(lo, hi));
        }
        let table = kept.as_ref();
        let mut start = None;
        let mut out = Vec::with_capacity(js.len());
        for &j in js {
            let p = self.solve_with(j, table, start)?;
            start = p.converged.then_some(p.wake_pitch);
            out.push(p);
        }
        Ok(out)
    }
}

/// The wake's influence at a lattice's field points, tabulated on Chebyshev-Lobatto points in
/// ln(lambda_w) and interpolated by the barycentric formula (Berrut & Trefethen 2004, "Barycentric
/// Lagrange interpolation", SIAM Review 46(3)).
pub struct WakeTable {
    lo: f64,
    hi: f64,
    nodes: Vec<f64>,
    values: Vec<Vec<V3>>,
}

impl WakeTable {
    fn at(&self, lambda: f64) -> Vec<V3> {
        let x = libm::log(lambda);
        let last = self.nodes.len() - 1;
        if let Some(i) = self.nodes.iter().position(|&u| u == x) {
            return self.values[i].clone();
        }
        let w: Vec<f64> = (0..=last)
            .map(|i| {
                let half = if i == 0 || i == last { 0.5 } else { 1.0 };
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                sign * half / (x - self.nodes[i])
            })
            .collect();
        let total: f64 = w.iter().sum();
        let mut out = vec![[0.0; 3]; self.values[0].len()];
        for (wi, vals) in w.iter().zip(&self.values) {
            for (o, v) in out.iter_mut().zip(vals) {
                *o = add(*o, scale(*v, wi / total));
            }
        }
        out
    }
}

/// The open-water curve of `g` by the vortex lattice at the advance ratios `js`.
pub fn open_water(g: &BladeGeometry, js: &[f64], flow: &Flow) -> Result<Vec<LatticePoint>, String> {
    Lattice::new(g, flow)?.curve(js)
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

    #[test]
    fn a_curve_is_its_points() {
        // A curve's points through the tabulated wake against each point solved on its own (the
        // wake summed afresh for every pitch): measured within 3.8e-4 of KT and KQ (relative, KT held
        // at 0.01 and KQ at 0.001 near zero thrust) at 25 J from 0 to 1.2; held 5e-4.
        let g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        let lattice = Lattice::new(&g, &Flow::fresh_water(0.3048, 10.0)).unwrap();
        let js: Vec<f64> = (0..25).map(|k| 1.2 * k as f64 / 24.0).collect();
        let curve = lattice.curve(&js).unwrap();
        for (k, a) in curve.iter().enumerate().filter(|(k, _)| k % 4 == 0) {
            let b = lattice.solve(js[k]).unwrap();
            let (dt, dq) = ((a.kt - b.kt) / b.kt.abs().max(0.01), (a.kq - b.kq) / b.kq.abs().max(0.001));
            assert!(
                a.converged && b.converged && dt.abs() < 5e-4 && dq.abs() < 5e-4,
                "J {}: KT {dt:+.2e}, KQ {dq:+.2e}",
                a.j
            );
        }
        // A later curve inside the kept table reuses it: the same numbers to the pitch's tolerance
        // (its first point starts from the lifting line's pitch, not its neighbour's).
        let again = lattice.curve(&js[8..12]).unwrap();
        assert!((again[0].kt / curve[8].kt - 1.0).abs() < 1e-6, "{:?} against {:?}", again[0], curve[8]);
        assert!(lattice.curve(&[]).unwrap().is_empty());
    }
}
