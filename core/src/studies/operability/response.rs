//! Frequency-domain statistics of the ship's responses in a short-crested sea: response spectra
//! from the RAO table (ch. 2.5.2-2.5.4) and the Bretschneider spectrum (eq. 2.58) with cos^h
//! spreading, and from them RMS values and the spectral moments that give crossing rates.
//!
//! A response y with transfer function H(omega, beta) per unit wave amplitude has, in the sea
//! S(omega) D(theta), the spectral moments in encounter frequency
//! m_n = sum_omega sum_theta S(omega) D(theta) |H(omega, beta + theta)|^2 |omega_e|^n d omega,
//! omega_e = omega - k U cos(beta + theta): m0 its variance, m2 the variance of its rate, m4 of its
//! second derivative. The sum runs over the band the time-domain sampler draws from, 0.6 to 4
//! times the modal frequency unless the scenario gives one (`waves::SeaSampling`), so the RMS here
//! is the standard deviation of the simulator's own sea.
//!
//! The speed's transfer functions are computed once per heading of a lattice and reused by every
//! mean heading and every sea: a sea changes only the weights S(omega) d omega, a mean heading only
//! which lattice headings its spreading sums.

use crate::sea::seakeeping::params::{HubPlace, SternMotion};
use crate::sea::seakeeping::tables::RaoTable;
use crate::sea::waves::{bretschneider, G};
use crate::ship::hull::N_SHAFTS;
use num_complex::Complex64 as C;
use std::collections::HashMap;
use std::f64::consts::PI;

/// The responses summed, by channel: heave, pitch, roll at the centre of gravity; the relative
/// motion (water up, relative to the hull) at the forward perpendicular and at the slamming
/// station; each hub's relative motion (its depth's swing, eq. 2.57); then per point its
/// vertical displacement and its felt lateral acceleration.
pub const HEAVE: usize = 0;
pub const PITCH: usize = 1;
pub const ROLL: usize = 2;
pub const BOW: usize = 3;
pub const SLAM: usize = 4;
pub const HUB: [usize; N_SHAFTS] = [5, 6];
const FIXED: usize = 7;

/// Channel of point p's vertical displacement.
pub fn point_vertical(p: usize) -> usize {
    FIXED + 2 * p
}
/// Channel of point p's felt lateral acceleration (already an acceleration: its m0 is used).
pub fn point_lateral(p: usize) -> usize {
    FIXED + 2 * p + 1
}

/// Where the responses are taken, in STF axes with the RAOs' origin, on the calm waterline above
/// the centre of gravity: x forward, y to port, z up \[m\].
#[derive(Debug, Clone, PartialEq)]
pub struct Places {
    pub points: Vec<[f64; 3]>,
    /// The forward perpendicular and the slamming station, on the centreline: x \[m\].
    pub fp_x: f64,
    pub slam_x: f64,
    pub hubs: [HubPlace; N_SHAFTS],
    pub stern_motion: SternMotion,
}

impl Places {
    pub fn channels(&self) -> usize {
        FIXED + 2 * self.points.len()
    }

    /// Every channel's transfer function at wave frequency `w` [rad/s], speed `u` [m/s] and
    /// heading `beta` [rad, 180 deg head seas]: |H|^2 into `out`, and the signed encounter
    /// frequency returned.
    pub fn transfer(&self, table: &RaoTable, w: f64, u: f64, beta: f64, out: &mut [f64]) -> f64 {
        let mut r = table.interpolate(w, u, beta);
        // Above the table's top frequency (waves under 15 m long on the default grid) the hull
        // does not follow the waves: its motions are taken as nil rather than held at the edge,
        // which made a short sea's accelerations twice too large.
        if w > table.grid.omega_max {
            r.heave = C::new(0.0, 0.0);
            r.pitch = r.heave;
            r.roll = r.heave;
            r.sway = r.heave;
            r.yaw = r.heave;
        }
        let k = w * w / G;
        let (cb, sb) = (libm::cos(beta), libm::sin(beta));
        let we = w - k * u * cb;
        out[HEAVE] = r.heave.norm_sqr();
        out[PITCH] = r.pitch.norm_sqr();
        out[ROLL] = r.roll.norm_sqr();
        // Relative motion at a place on the hull: eq. 2.57's transfer with the place as "hub"
        // (x_aft negative forward of G): wave there minus the hull's vertical motion there.
        let rel = |x_aft: f64, y: f64, m: SternMotion| {
            let at = HubPlace { x_aft, y };
            m.hub_transfer(m.hub_wave(k, at, cb, sb), r.heave, r.roll, r.pitch, at)
        };
        out[BOW] = rel(-self.fp_x, 0.0, SternMotion::Consistent).norm_sqr();
        out[SLAM] = rel(-self.slam_x, 0.0, SternMotion::Consistent).norm_sqr();
        for (s, at) in self.hubs.iter().enumerate() {
            out[HUB[s]] = rel(at.x_aft, at.y, self.stern_motion).norm_sqr();
        }
        let w2 = C::new(-we * we, 0.0);
        for (p, &[x, y, z]) in self.points.iter().enumerate() {
            // Small rotations about G (STF: roll port side up, pitch bow down, yaw bow to port):
            // vertical eta3 + y eta4 - x eta5, sideways eta2 - z eta4 + x eta6. The felt lateral
            // acceleration adds g eta4, gravity's component in the heeled deck.
            let vertical = r.heave + r.roll * y - r.pitch * x;
            let sideways = r.sway - r.roll * z + r.yaw * x;
            out[point_vertical(p)] = vertical.norm_sqr();
            out[point_lateral(p)] = (w2 * sideways + r.roll * G).norm_sqr();
        }
        we
    }
}

/// A Bretschneider sea (eq. 2.58): significant height \[m\], modal frequency [rad/s] and the band
/// summed [rad/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sea {
    pub h_sig_m: f64,
    pub omega_n: f64,
    pub band: (f64, f64),
}

impl Sea {
    /// The sea of the time-domain sampler's default band, 0.6 to 4 omega_n.
    pub fn new(h_sig_m: f64, omega_n: f64) -> Sea {
        Sea { h_sig_m, omega_n, band: (0.6 * omega_n, 4.0 * omega_n) }
    }
}

/// Directions of the spreading sum: offsets from the mean \[rad\] and normalised weights of cos^h
/// on (-90, 90) deg, by the midpoint rule on `step` \[rad\] (the same offsets for every mean
/// heading, so mean headings a whole number of steps apart share their transfer functions); one
/// direction of weight 1 for a long-crested sea (h = 0).
pub fn spreading(h: f64, step: f64) -> Vec<(f64, f64)> {
    if h <= 0.0 {
        return vec![(0.0, 1.0)];
    }
    let n = libm::ceil(PI / step - 1e-9).max(1.0) as usize;
    let d = PI / n as f64;
    let dirs: Vec<(f64, f64)> = (0..n)
        .map(|j| {
            // Midpoints: offsets (j + 1/2) pi / n - pi / 2, the same for every mean heading.
            let th = -PI / 2.0 + (j as f64 + 0.5) * d;
            (th, libm::pow(libm::cos(th), h))
        })
        .collect();
    let total: f64 = dirs.iter().map(|(_, w)| w).sum();
    dirs.into_iter().map(|(t, w)| (t, w / total)).collect()
}

/// Spectral moments m0, m2, m4 of every channel.
#[derive(Debug, Clone, PartialEq)]
pub struct Moments(pub Vec<[f64; 3]>);

impl Moments {
    /// The moments of a sea `factor` times as high (every moment scales with H^2).
    pub fn scaled(&self, factor: f64) -> Moments {
        Moments(self.0.iter().map(|m| m.map(|x| x * factor * factor)).collect())
    }
    pub fn rms(&self, c: usize) -> f64 {
        self.0[c][0].max(0.0).sqrt()
    }
}

/// The response statistics of one ship at one speed over headings and seas: the transfer
/// functions on frequency `nodes` at each lattice heading, computed on first use.
pub struct SpeedResponses<'a> {
    table: &'a RaoTable,
    places: &'a Places,
    u: f64,
    /// Frequency nodes [rad/s] and their widths.
    nodes: Vec<f64>,
    widths: Vec<f64>,
    /// Per lattice heading (milli-degrees in [0, 360000)): per node, the channels' |H|^2 and the
    /// encounter frequency last.
    lattice: HashMap<i64, Vec<f64>>,
}

impl<'a> SpeedResponses<'a> {
    /// Midpoint nodes of width `dw` covering [lo, hi].
    pub fn new(table: &'a RaoTable, places: &'a Places, u: f64, lo: f64, hi: f64, n: usize) -> Self {
        let dw = (hi - lo) / n as f64;
        let nodes = (0..n).map(|i| lo + (i as f64 + 0.5) * dw).collect();
        SpeedResponses { table, places, u, nodes, widths: vec![dw; n], lattice: HashMap::new() }
    }

    fn at_heading(&mut self, beta: f64) -> &Vec<f64> {
        let key = libm::round(beta.to_degrees().rem_euclid(360.0) * 1000.0) as i64 % 360_000;
        let (table, places, u, nodes) = (self.table, self.places, self.u, &self.nodes);
        self.lattice.entry(key).or_insert_with(|| {
            let nc = places.channels();
            let mut v = vec![0.0; nodes.len() * (nc + 1)];
            for (i, &w) in nodes.iter().enumerate() {
                let row = &mut v[i * (nc + 1)..(i + 1) * (nc + 1)];
                row[nc] = places.transfer(table, w, u, beta, &mut row[..nc]);
            }
            v
        })
    }

    /// Per node and channel the spread sum of |H|^2 |omega_e|^n for n = 0, 2, 4 about the mean
    /// heading `beta` \[rad\] with `dirs` ([`spreading`]).
    pub fn directional(&mut self, beta: f64, dirs: &[(f64, f64)]) -> Directional {
        let nc = self.places.channels();
        let mut g = vec![[0.0; 3]; self.nodes.len() * nc];
        for &(th, wt) in dirs {
            let h = self.at_heading(beta + th);
            for (i, row) in h.chunks_exact(nc + 1).enumerate() {
                let we2 = row[nc] * row[nc];
                for (c, &h2) in row[..nc].iter().enumerate() {
                    let x = wt * h2;
                    let m = &mut g[i * nc + c];
                    m[0] += x;
                    m[1] += x * we2;
                    m[2] += x * we2 * we2;
                }
            }
        }
        Directional { nodes: self.nodes.clone(), widths: self.widths.clone(), channels: nc, g }
    }
}

/// The spread transfer sums of one speed and mean heading on the frequency nodes.
#[derive(Debug, Clone)]
pub struct Directional {
    nodes: Vec<f64>,
    widths: Vec<f64>,
    channels: usize,
    g: Vec<[f64; 3]>,
}

impl Directional {
    /// The moments in `sea` (nodes outside its band do not count).
    pub fn moments(&self, sea: &Sea) -> Moments {
        let mut m = vec![[0.0; 3]; self.channels];
        for (i, (&w, &dw)) in self.nodes.iter().zip(&self.widths).enumerate() {
            if w < sea.band.0 || w > sea.band.1 {
                continue;
            }
            let s = bretschneider(w, sea.h_sig_m, sea.omega_n) * dw;
            for (c, acc) in m.iter_mut().enumerate() {
                let x = self.g[i * self.channels + c];
                for n in 0..3 {
                    acc[n] += s * x[n];
                }
            }
        }
        Moments(m)
    }
}

/// Mean zero up-crossing rate (1/2 pi) sqrt(m2 / m0) [1/s]; 0 in calm water.
pub fn zero_crossing_rate(m: &[f64; 3]) -> f64 {
    if m[0] > 0.0 {
        (m[1] / m[0]).sqrt() / (2.0 * PI)
    } else {
        0.0
    }
}
