//! The ship in random or regular seas, quasi-steady (thesis ch. 2.5.4): wave components from the
//! seeded sampler, motions by superposition of the RAO table (eqs. 2.55, 2.59), the wave at the
//! stern and the hub's depth (eqs. 2.56-2.57), and the slowly varying second-order forces
//! (eq. 2.60, Newman's approximation, O(N_s) per sample).
//!
//! Phase of component i at the ship's centre of gravity (x, y): theta_i = omega0_i t -
//! k_i (x cos mu_i + y sin mu_i) + gamma_i, with mu_i its direction of travel. Eqs. 2.55 and 2.59
//! write the encounter frequency in front of t as well as the moving position in the phase, which
//! counts the Doppler shift twice; with the position in the phase, the wave frequency is the
//! right one (the encounter frequency is theta's rate, omega0 - k (x' cos mu + y' sin mu)).
//!
//! Multi-rate: the sums run every `sample_period_s`; the hub depth between samples follows the
//! second-order Taylor series of its own sum (the derivatives come with the sum at no extra
//! transcendental cost). RAOs, the stern's phase offsets and the drift-force weights are looked up
//! again every `rao_refresh_s` at the ship's speed and heading then.

use crate::interp::bracket;
use crate::scenario::{Scenario, SeaKind};
use crate::seakeeping::cache::rao_table;
use crate::seakeeping::params::{stern_wave, SternMotion};
use crate::waves::{newman_force, newman_sign, newman_weight, SeaSampling, WaveComponent, G};
use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// The wave components of a scenario's sea (eqs. 2.55, 2.58: the seeded sample of the spectrum,
/// or the one regular wave); none in calm water. The seaway and the page's wave picture share it.
pub fn wave_components(sc: &Scenario) -> Vec<WaveComponent> {
    let sea = &sc.sea;
    if sea.kind == SeaKind::Calm {
        return Vec::new();
    }
    // Direction of travel: opposite to where the waves come from.
    let mu = (sea.from_deg + 180.0).to_radians();
    match sea.kind {
        SeaKind::Regular => vec![WaveComponent {
            amplitude: sea.amplitude_m,
            omega: sea.omega_rad_s,
            k: sea.omega_rad_s * sea.omega_rad_s / G,
            direction: mu,
            phase: 0.0,
        }],
        _ => {
            let (h, wn) = sea.spectrum();
            let mut s = SeaSampling::new(h, wn, mu);
            s.components = sea.components as usize;
            if sea.omega_min_rad_s > 0.0 && sea.omega_max_rad_s > 0.0 {
                s.omega_min = sea.omega_min_rad_s;
                s.omega_max = sea.omega_max_rad_s;
            }
            s.spreading = sea.spreading;
            s.sample(sc.sim.seed)
        }
    }
}

/// One component with its RAO slice at its own frequency: [speed][heading] of
/// (heave, pitch, roll, sway, yaw; F_add).
struct Component {
    wave: WaveComponent,
    cos_mu: f64,
    sin_mu: f64,
    slice: Vec<([C; 5], f64)>,
}

/// What one sample gives.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SeaSample {
    pub t: f64,
    /// Hub depth below the surface [m] and its first two time derivatives.
    pub hub: f64,
    pub hub_rate: f64,
    pub hub_accel: f64,
    /// Wave elevation at the stern [m].
    pub wave_stern: f64,
    /// Heave [m, up], pitch [rad, bow down], roll [rad, starboard down], sway [m, to starboard],
    /// yaw [rad, bow to starboard]: the first-order motions about the maneuvering track.
    pub heave: f64,
    pub pitch: f64,
    pub roll: f64,
    pub sway: f64,
    pub yaw: f64,
    /// Slowly varying second-order force in ship axes [N]: forward and to starboard.
    pub fx: f64,
    pub fy: f64,
}

impl SeaSample {
    /// Hub depth at time `t` by the Taylor series about the sample.
    pub fn hub_at(&self, t: f64) -> f64 {
        let d = t - self.t;
        self.hub + d * (self.hub_rate + 0.5 * d * self.hub_accel)
    }
}

/// The seaway acting on the ship.
pub struct Seaway {
    comps: Vec<Component>,
    speeds: Vec<f64>,
    headings: Vec<f64>,
    hub0: f64,
    x_p: f64,
    second_order: bool,
    /// How the stern motion enters the hub depth (eq. 2.57).
    stern_motion: SternMotion,
    /// Per component, refreshed: hub transfer, heave, pitch, roll, stern factor, sway, yaw (the
    /// lateral modes signed for the side the waves come from and turned to starboard-positive
    /// axes); Newman weights for x and y with their signs.
    h: Vec<[C; 7]>,
    wx: Vec<f64>,
    wy: Vec<f64>,
    sign_x: f64,
    sign_y: f64,
    pub last: SeaSample,
}

impl Seaway {
    /// The seaway of `sc` (None in calm water).
    pub fn new(sc: &Scenario) -> Result<Option<Seaway>, String> {
        if sc.sea.kind == SeaKind::Calm {
            return Ok(None);
        }
        let waves = wave_components(sc);
        let k = &sc.seakeeping;
        let table = rao_table(&k.grid)?;
        let (speeds, headings) = (k.grid.speeds(), k.grid.headings());
        let comps = waves
            .into_iter()
            .map(|w| {
                let mut slice = Vec::with_capacity(speeds.len() * headings.len());
                for &u in &speeds {
                    for &b in &headings {
                        let r = table.interpolate(w.omega, u, b);
                        // F_add along the waves' travel = fx cos b + fy sin b of the table.
                        let fadd = r.fx * libm::cos(b) + r.fy * libm::sin(b);
                        slice.push(([r.heave, r.pitch, r.roll, r.sway, r.yaw], fadd));
                    }
                }
                Component { cos_mu: libm::cos(w.direction), sin_mu: libm::sin(w.direction), wave: w, slice }
            })
            .collect::<Vec<_>>();
        let n = comps.len();
        Ok(Some(Seaway {
            comps,
            speeds,
            headings,
            hub0: k.hub_depth_m,
            x_p: k.prop_x_aft_m,
            second_order: k.second_order_forces,
            stern_motion: k.stern_motion,
            h: vec![[C::new(0.0, 0.0); 7]; n],
            wx: vec![0.0; n],
            wy: vec![0.0; n],
            sign_x: 1.0,
            sign_y: 1.0,
            last: SeaSample { hub: k.hub_depth_m, ..Default::default() },
        }))
    }

    /// The wave components (for analysis and tests).
    pub fn components(&self) -> Vec<WaveComponent> {
        self.comps.iter().map(|c| c.wave).collect()
    }

    /// Looks the RAOs up again at speed `u` [m/s] and heading `psi` [rad].
    pub fn refresh(&mut self, u: f64, psi: f64) {
        let (j0, fj) = bracket(&self.speeds, u);
        let nh = self.headings.len();
        let (mut sx, mut sy) = (0.0, 0.0);
        for (i, c) in self.comps.iter().enumerate() {
            // beta = psi - mu (STF: 180 deg head seas), folded into [0, pi]; beyond pi the waves
            // come from port and roll and the side force change sign.
            let beta = (psi - c.wave.direction).rem_euclid(2.0 * PI);
            let (bf, side) = if beta > PI { (2.0 * PI - beta, -1.0) } else { (beta, 1.0) };
            let (k0, fk) = bracket(&self.headings, bf);
            let mut acc = [C::new(0.0, 0.0); 5];
            let mut fadd = 0.0;
            for (dj, wj) in [(0, 1.0 - fj), (1, fj)] {
                for (dk, wk) in [(0, 1.0 - fk), (1, fk)] {
                    let w = wj * wk;
                    if w == 0.0 {
                        continue;
                    }
                    let j = (j0 + dj).min(self.speeds.len() - 1);
                    let k = (k0 + dk).min(nh - 1);
                    let (h, f) = &c.slice[j * nh + k];
                    for (a, v) in acc.iter_mut().zip(h) {
                        *a += v * w;
                    }
                    fadd += w * f;
                }
            }
            let (h3, h5, h4) = (acc[0], acc[1], acc[2] * side);
            let stern = stern_wave(c.wave.k, self.x_p, beta);
            let hub = self.stern_motion.hub_transfer(stern, h3, h5, self.x_p);
            // STF's sway is to port and its yaw bow to port: both flip for starboard-positive axes.
            self.h[i] = [hub, h3, h5, h4, stern, -acc[3] * side, -acc[4] * side];
            // Mean force components per amplitude squared, ship axes (x forward, y starboard):
            // STF's y is to port.
            let a2 = c.wave.amplitude * c.wave.amplitude;
            self.wx[i] = libm::cos(beta) * fadd;
            self.wy[i] = -libm::sin(beta) * fadd;
            sx += a2 * self.wx[i];
            sy += a2 * self.wy[i];
        }
        // Newman: one sign per direction for the whole set (the components' own signs agree for a
        // sea from one side; where they do not, the weaker side is dropped).
        self.sign_x = newman_sign(sx);
        self.sign_y = newman_sign(sy);
        for (i, c) in self.comps.iter().enumerate() {
            self.wx[i] = newman_weight(c.wave.amplitude, self.wx[i], self.sign_x);
            self.wy[i] = newman_weight(c.wave.amplitude, self.wy[i], self.sign_y);
        }
    }

    /// Sums the components at time `t` [s] with the ship at (x, y) [m] moving at (xd, yd) [m/s].
    pub fn sample(&mut self, t: f64, x: f64, y: f64, xd: f64, yd: f64) -> SeaSample {
        let mut s = SeaSample { t, hub: self.hub0, ..Default::default() };
        let (mut cx, mut sx, mut cy, mut sy) = (0.0, 0.0, 0.0, 0.0);
        for (i, c) in self.comps.iter().enumerate() {
            let w = &c.wave;
            let theta = w.phase_at(c.cos_mu, c.sin_mu, x, y, t);
            let rate = w.omega - w.k * (xd * c.cos_mu + yd * c.sin_mu);
            let (sn, cs) = (libm::sin(theta), libm::cos(theta));
            let h = &self.h[i];
            let a = w.amplitude;
            // Re{H e^{i theta}} and its time derivatives.
            let re = |z: C| z.re * cs - z.im * sn;
            let im = |z: C| z.re * sn + z.im * cs;
            let hub = re(h[0]);
            s.hub += a * hub;
            s.hub_rate -= a * rate * im(h[0]);
            s.hub_accel -= a * rate * rate * hub;
            s.heave += a * re(h[1]);
            s.pitch += a * re(h[2]);
            s.roll += a * re(h[3]);
            s.wave_stern += a * re(h[4]);
            s.sway += a * re(h[5]);
            s.yaw += a * re(h[6]);
            cx += self.wx[i] * cs;
            sx += self.wx[i] * sn;
            cy += self.wy[i] * cs;
            sy += self.wy[i] * sn;
        }
        if self.second_order {
            s.fx = newman_force(self.sign_x, cx, sx);
            s.fy = newman_force(self.sign_y, cy, sy);
        }
        self.last = s;
        s
    }

    /// Mean second-order force per the first term of eq. 2.60, sum a_i^2 F_i, ship axes [N]
    /// (for tests: the time average of `fx`, `fy`).
    pub fn mean_force(&self) -> (f64, f64) {
        let fx: f64 = self.wx.iter().map(|w| w * w).sum::<f64>() * self.sign_x;
        let fy: f64 = self.wy.iter().map(|w| w * w).sum::<f64>() * self.sign_y;
        (fx, fy)
    }
}
