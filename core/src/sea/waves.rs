//! Random seas (thesis ch. 2.5.4): the Bretschneider spectrum (eq. 2.58) with the sea states of
//! Table 2.4, its sampling into N_s components (uniform strata with one random frequency each,
//! amplitudes sqrt(2 S dw), cos^h spreading about the mean direction by rejection, uniform
//! phases), and the surface elevation by superposition. Everything random comes from one ChaCha8
//! generator seeded by the scenario's seed, so a seed fixes the sea on every platform.
//!
//! Conventions: a component travels towards direction mu (radians, in the same earth frame as the
//! ship's heading psi: x north, y east); z_i(x, y, t) = a_i cos(w_i t - k_i (x cos mu_i + y sin mu_i)
//! + gamma_i) with deep-water wave number k_i = w_i^2 / g.

use crate::checks::Validator;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Gravity [m/s^2].
pub const G: f64 = 9.81;
/// One foot [m].
const FOOT: f64 = 0.3048;

/// Table 2.4: modal frequency omega_n [rad/s] and significant height H_1/3 \[m\] of sea states 2 to 6.
pub fn sea_state(n: u32) -> Option<(f64, f64)> {
    let (w, h_ft) = match n {
        2 => (0.997, 0.984),
        3 => (0.838, 2.952),
        4 => (0.714, 6.232),
        5 => (0.648, 10.824),
        6 => (0.507, 16.400),
        _ => return None,
    };
    Some((w, h_ft * FOOT))
}

/// Eq. 2.58: S(w) = (5/16) w_n^4 / w^5 H^2 exp(-5 w_n^4 / (4 w^4)) [m^2 s].
pub fn bretschneider(omega: f64, h_sig: f64, omega_n: f64) -> f64 {
    if omega <= 0.0 {
        return 0.0;
    }
    let r4 = crate::numerics::powi(omega_n / omega, 4);
    5.0 / 16.0 * r4 / omega * h_sig * h_sig * libm::exp(-1.25 * r4)
}

/// One regular wave component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveComponent {
    /// Amplitude \[m\].
    pub amplitude: f64,
    /// Frequency in the earth frame [rad/s].
    pub omega: f64,
    /// Wave number [1/m].
    pub k: f64,
    /// Direction of travel \[rad\].
    pub direction: f64,
    /// Phase \[rad\].
    pub phase: f64,
}

/// How to sample a Bretschneider sea.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeaSampling {
    pub h_sig: f64,
    pub omega_n: f64,
    /// Mean direction of travel \[rad\].
    pub direction: f64,
    /// Number of components N_s.
    pub components: usize,
    /// Spectrum bounds [rad/s].
    pub omega_min: f64,
    pub omega_max: f64,
    /// Exponent h of the cos^h spreading (0: long-crested, no spreading).
    pub spreading: f64,
}

impl SeaSampling {
    /// Defaults for a sea of modal frequency `omega_n`: 200 components from 0.6 to 4 omega_n (the
    /// band holds 99.5 % of the energy), cos^2 spreading.
    pub fn new(h_sig: f64, omega_n: f64, direction: f64) -> SeaSampling {
        SeaSampling {
            h_sig,
            omega_n,
            direction,
            components: 200,
            omega_min: 0.6 * omega_n,
            omega_max: 4.0 * omega_n,
            spreading: 2.0,
        }
    }

    /// The sampled components for `seed` (ch. 2.5.4).
    pub fn sample(&self, seed: u64) -> Vec<WaveComponent> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let n = self.components.max(1);
        let dw = (self.omega_max - self.omega_min) / n as f64;
        (0..n)
            .map(|i| {
                let w = self.omega_min + (i as f64 + rng.random::<f64>()) * dw;
                let spread = if self.spreading > 0.0 { spreading_sample(&mut rng, self.spreading) } else { 0.0 };
                WaveComponent {
                    amplitude: (2.0 * bretschneider(w, self.h_sig, self.omega_n) * dw).sqrt(),
                    omega: w,
                    k: w * w / G,
                    direction: self.direction + spread,
                    phase: 2.0 * PI * rng.random::<f64>(),
                }
            })
            .collect()
    }
}

/// A deviation from the mean direction with density proportional to cos^h on (-pi/2, pi/2), by
/// rejection from the uniform distribution.
fn spreading_sample(rng: &mut ChaCha8Rng, h: f64) -> f64 {
    loop {
        let d = (rng.random::<f64>() - 0.5) * PI;
        if rng.random::<f64>() <= libm::pow(libm::cos(d), h) {
            return d;
        }
    }
}

/// Zeroth spectral moment of a set of components, m0 = sum a^2 / 2 [m^2].
pub fn m0(components: &[WaveComponent]) -> f64 {
    components.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum()
}

impl WaveComponent {
    /// Phase omega t - k (x cos mu + y sin mu) + phase at (x, y) \[m\] and time `t` \[s\], with the
    /// direction's cosine and sine `cos_mu`, `sin_mu` given (the seaway keeps them).
    pub fn phase_at(&self, cos_mu: f64, sin_mu: f64, x: f64, y: f64, t: f64) -> f64 {
        let along = x * cos_mu + y * sin_mu;
        self.omega * t - self.k * along + self.phase
    }
}

/// Surface elevation at (x, y) \[m\] and time t \[s\] by superposition.
pub fn elevation(components: &[WaveComponent], x: f64, y: f64, t: f64) -> f64 {
    components
        .iter()
        .map(|c| c.amplitude * libm::cos(c.phase_at(libm::cos(c.direction), libm::sin(c.direction), x, y, t)))
        .sum()
}

/// Surface elevation at many points (`xs[i]`, `ys[i]`) \[m\] at time t \[s\] into `out`: the sum of
/// [`elevation`] with each component's direction taken once (a picture of the sea, not the step).
pub fn elevations(components: &[WaveComponent], xs: &[f64], ys: &[f64], t: f64, out: &mut [f64]) {
    out.iter_mut().for_each(|e| *e = 0.0);
    for c in components {
        let (cm, sm) = (libm::cos(c.direction), libm::sin(c.direction));
        for ((e, &x), &y) in out.iter_mut().zip(xs).zip(ys) {
            *e += c.amplitude * libm::cos(c.phase_at(cm, sm, x, y, t));
        }
    }
}

/// Slowly varying second-order force (eq. 2.60) with Newman's approximation
/// F_add(w_i, w_j) = sqrt(F_i F_j) sign(F_i), which turns the double sum over component pairs into
/// the squared magnitude of one single sum:
/// sum_i sum_j a_i a_j sqrt(F_i F_j) cos(theta_i - theta_j) = |sum_i a_i sqrt(F_i) e^(i theta_i)|^2,
/// O(N_s) per step instead of O(N_s^2). `f_unit[i]` is the mean force per amplitude squared of
/// component i (N/m^2, one sign for the whole set) and `theta[i]` its instantaneous phase
/// (encounter frequency times time plus phase and position lag).
pub fn slow_drift_newman(amplitudes: &[f64], f_unit: &[f64], theta: &[f64]) -> f64 {
    let sign = newman_sign(f_unit.iter().sum::<f64>());
    let (mut c, mut s) = (0.0, 0.0);
    for i in 0..amplitudes.len() {
        let w = newman_weight(amplitudes[i], f_unit[i], sign);
        c += w * libm::cos(theta[i]);
        s += w * libm::sin(theta[i]);
    }
    newman_force(sign, c, s)
}

/// The sign of Newman's force for a set whose mean force sum_i a_i^2 F_i is `mean` (one sign
/// for the whole set; a component of the other sign is dropped).
pub fn newman_sign(mean: f64) -> f64 {
    if mean < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Component weight a sqrt(sign F) of Newman's single sum.
pub fn newman_weight(amplitude: f64, f_unit: f64, sign: f64) -> f64 {
    amplitude * (sign * f_unit).max(0.0).sqrt()
}

/// Newman's force from the single sums c = sum w_i cos(theta_i), s = sum w_i sin(theta_i).
pub fn newman_force(sign: f64, c: f64, s: f64) -> f64 {
    sign * (c * c + s * s)
}

/// The same force by the direct double sum (the O(N_s^2) reference of the tests), with a free
/// choice of the pair transfer function `pair(i, j)`.
pub fn slow_drift_direct(amplitudes: &[f64], theta: &[f64], pair: &dyn Fn(usize, usize) -> f64) -> f64 {
    let n = amplitudes.len();
    let mut total = 0.0;
    for i in 0..n {
        for j in 0..n {
            total += amplitudes[i] * amplitudes[j] * pair(i, j) * libm::cos(theta[i] - theta[j]);
        }
    }
    total
}

#[cfg(test)]
mod drift_tests {
    use super::*;

    /// Newman's factorised sum equals the direct double sum with the same pair function to 1e-10,
    /// and its mean over time equals sum a_i^2 F_i (the first term of eq. 2.60).
    #[test]
    fn newman_factorisation_matches_double_sum() {
        let (wn, h) = sea_state(6).unwrap();
        let comps = SeaSampling::new(h, wn, 0.0).sample(11);
        let a: Vec<f64> = comps.iter().map(|c| c.amplitude).collect();
        // A smooth added-resistance curve per amplitude squared [N/m^2].
        let f: Vec<f64> = comps
            .iter()
            .map(|c| -2.0e4 * (c.omega / wn) * (c.omega / wn) * libm::exp(-(c.omega / wn - 1.0) * (c.omega / wn - 1.0)))
            .collect();
        let mut mean = 0.0;
        let steps = 4000;
        for k in 0..steps {
            let t = k as f64 * 0.5;
            let theta: Vec<f64> = comps.iter().map(|c| c.omega * t + c.phase).collect();
            let fast = slow_drift_newman(&a, &f, &theta);
            if k % 400 == 0 {
                let direct = slow_drift_direct(&a, &theta, &|i, j| -(f[i] * f[j]).sqrt());
                assert!((fast - direct).abs() < 1e-10 * direct.abs().max(1.0), "{fast} vs {direct}");
            }
            mean += fast / steps as f64;
        }
        let first_term: f64 = a.iter().zip(&f).map(|(a, f)| a * a * f).sum();
        assert!((mean / first_term - 1.0).abs() < 0.1, "time mean {mean} vs {first_term}");
    }
}

crate::params! {
    /// The sea (thesis ch. 2.5.4). Directions are where the waves come FROM, in the earth frame of
    /// the ship's heading (0 = north): a ship heading 0 deg in waves from 0 deg meets head seas.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SeaParams {
        pub kind: SeaKind = SeaKind::Calm => {
            label: "Sea", source: "ch. 2.5.4 (random), ch. 5.2.4 (regular)", group: "sea",
            help: "Random: Bretschneider spectrum (eq. 2.58) of a Table 2.4 sea state.",
        },
        /// Used unless `h_sig_m` and `omega_n_rad_s` are set; given with them, refused. Left out of
        /// the JSON when they are set.
        pub sea_state: u32 = 6 => {
            label: "Sea state", unit: "-", range: 2.0..=6.0, source: "Table 2.4 (the ch. 5 studies use 6)", group: "sea",
            help: "Table 2.4 gives each sea state's significant height and peak frequency.",
        },
        pub h_sig_m: f64 = 0.0 => {
            label: "Significant wave height H_1/3", unit: "m", range: 0.01..=20.0, empty: "the sea state's",
            excludes: &["sea.sea_state"],
            help: "With omega_n_rad_s, a spectrum of one's own instead of the sea state's.",
        },
        pub omega_n_rad_s: f64 = 0.0 => {
            label: "Modal frequency omega_n", unit: "rad/s", range: 0.2..=3.0, empty: "the sea state's",
            excludes: &["sea.sea_state"],
            help: "Peak frequency of the spectrum of one's own (with h_sig_m).",
        },
        pub from_deg: f64 = 0.0 => {
            label: "Waves from", unit: "deg", range: -3600.0..=3600.0, source: "head seas for a ship heading north", group: "sea",
            help: "0 = from north: head seas for a ship heading north.",
        },
        pub components: u32 = 200 => {
            label: "Wave components N_s", unit: "-", range: 1.0..=2000.0, source: "ch. 2.5.4 (100 to 500)", group: "sea",
            help: "Regular waves summed to make the random sea.",
        },
        /// 0: 0.6 and 4 times the modal frequency, 99.5 % of the energy.
        pub omega_min_rad_s: f64 = 0.0 => {
            label: "Lowest wave frequency", unit: "rad/s", range: 0.05..=5.0, empty: "0.6 times the modal frequency",
            help: "Lower bound of the sampled spectrum.",
        },
        pub omega_max_rad_s: f64 = 0.0 => {
            label: "Highest wave frequency", unit: "rad/s", range: 0.06..=6.0, empty: "4 times the modal frequency",
            help: "Upper bound of the sampled spectrum.",
        },
        /// Each amplitude sqrt(2 S d omega) times a Rayleigh factor: the sum of the components is
        /// then a Gaussian process for any number of them (the sea a conditioned sea is made
        /// from, `rare_event`; always on there).
        pub gaussian: bool = false => {
            label: "Gaussian sea (random amplitudes)", source: "our choice: off, the thesis' fixed amplitudes (ch. 2.5.4)",
            help: "Random Rayleigh amplitudes instead of sqrt(2 S dw): a Gaussian sea for any number of components.",
        },
        pub spreading: f64 = 2.0 => {
            label: "Directional spreading", unit: "-", range: 0.0..=100.0, source: "our choice: cos² spreading, usual for wind seas",
            help: "Exponent h of cos^h about the mean direction; 0: long-crested.",
        },
        pub amplitude_m: f64 = 0.6096 => {
            label: "Regular wave amplitude", unit: "m", range: 0.0..=10.0, source: "our choice: 2 ft, within Fig. 5-12's 1 to 5 ft", group: "sea",
            help: "1 ft = 0.3048 m.",
        },
        pub omega_rad_s: f64 = 0.6 => {
            label: "Regular wave frequency", unit: "rad/s", range: 0.1..=5.0, source: "our choice, within Fig. 5-12's sweep", group: "sea",
            help: "Wave length 2 pi g / omega^2.",
        },
    }
}

impl crate::params::CrossCheck for SeaParams {
    fn cross_check(&self, v: &mut Validator) {
        // A spectrum of one's own needs both its height and its frequency.
        for (a, b, x, y) in [
            ("h_sig_m", "omega_n_rad_s", self.h_sig_m, self.omega_n_rad_s),
            ("omega_min_rad_s", "omega_max_rad_s", self.omega_min_rad_s, self.omega_max_rad_s),
        ] {
            if (x == 0.0) != (y == 0.0) {
                let (missing, given) = if x == 0.0 { (a, b) } else { (b, a) };
                v.fail(missing, 0, format!("must be set too when {} is", v.path(given)));
            }
        }
        if self.omega_min_rad_s != 0.0
            && self.omega_max_rad_s != 0.0
            && self.omega_max_rad_s < self.omega_min_rad_s + 0.01
        {
            {
                v.fail(
                    "omega_max_rad_s",
                    crate::checks::num(self.omega_max_rad_s),
                    format!("must be above {} by 0.01 or more", v.path("omega_min_rad_s")),
                );
            }
        }
    }
}

impl SeaParams {
    /// The band of wave frequencies [rad/s] the random sea is sampled over and its statistics
    /// integrated over: the scenario's bounds, or 0.6 and 4 times the modal frequency
    /// ([`SeaSampling::new`]'s default).
    pub fn band(&self) -> (f64, f64) {
        if self.omega_min_rad_s > 0.0 && self.omega_max_rad_s > 0.0 {
            (self.omega_min_rad_s, self.omega_max_rad_s)
        } else {
            let d = SeaSampling::new(1.0, self.spectrum().1, 0.0);
            (d.omega_min, d.omega_max)
        }
    }

    /// (H_1/3 \[m\], modal frequency [rad/s]) of the random sea.
    pub fn spectrum(&self) -> (f64, f64) {
        if self.h_sig_m > 0.0 && self.omega_n_rad_s > 0.0 {
            (self.h_sig_m, self.omega_n_rad_s)
        } else {
            let (w, h) = crate::sea::waves::sea_state(self.sea_state).unwrap_or((0.507, 5.0));
            (h, w)
        }
    }
}

crate::choices! {
    /// Which sea.
    pub enum SeaKind {
        Calm = "calm", "calm water",
        /// Bretschneider spectrum (eq. 2.58) sampled into components (ch. 2.5.4).
        Random = "random", "random sea of a sea state",
        /// One regular wave (ch. 5.2.4).
        Regular = "regular", "one regular wave",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spectrum's area is H^2/16 (so 4 sqrt(m0) = H_1/3), by quadrature, to 0.1 %.
    #[test]
    fn spectrum_area() {
        let (wn, h) = sea_state(6).unwrap();
        let n = 200_000;
        let (a, b) = (0.05, 20.0);
        let dw = (b - a) / n as f64;
        let area: f64 = (0..n).map(|i| bretschneider(a + (i as f64 + 0.5) * dw, h, wn) * dw).sum();
        assert!((area / (h * h / 16.0) - 1.0).abs() < 1e-3, "{area}");
        // Peak at the modal frequency.
        assert!(bretschneider(wn, h, wn) > bretschneider(0.95 * wn, h, wn));
        assert!(bretschneider(wn, h, wn) > bretschneider(1.05 * wn, h, wn));
        assert!((h - 16.4 * 0.3048).abs() < 1e-12);
    }

    /// Over 200 seeds, 4 sqrt(m0) of the sampled components is H_1/3 within 3 % (mean), for every
    /// sea state of Table 2.4.
    #[test]
    fn sampled_height_matches() {
        for ss in 2..=6 {
            let (wn, h) = sea_state(ss).unwrap();
            let s = SeaSampling::new(h, wn, 0.0);
            let mean: f64 = (0..200).map(|seed| 4.0 * m0(&s.sample(seed)).sqrt()).sum::<f64>() / 200.0;
            assert!((mean / h - 1.0).abs() < 0.03, "SS{ss}: {mean} vs {h}");
        }
    }

    /// The elevation time series at a point has the spectrum's variance: over 20 seeds and 3600 s
    /// each, the mean sample variance is m0 within 3 %.
    #[test]
    fn elevation_variance() {
        let (wn, h) = sea_state(6).unwrap();
        let s = SeaSampling::new(h, wn, 0.3);
        let mut ratio = 0.0;
        for seed in 0..20 {
            let comps = s.sample(seed);
            let n = 7200;
            let z: Vec<f64> = (0..n).map(|i| elevation(&comps, 50.0, -20.0, i as f64 * 0.5)).collect();
            let mean = z.iter().sum::<f64>() / n as f64;
            let var = z.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n as f64;
            ratio += var / m0(&comps) / 20.0;
        }
        assert!((ratio - 1.0).abs() < 0.03, "variance / m0 = {ratio}");
    }

    /// The spreading sampler matches its density: for cos^h, E[cos^2] = (h + 1) / (h + 2) and the
    /// mean is zero; 100 000 draws, tolerance 0.5 % (about 10 standard errors).
    #[test]
    fn spreading_density() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for h in [2.0, 4.0, 10.0] {
            let n = 100_000;
            let draws: Vec<f64> = (0..n).map(|_| spreading_sample(&mut rng, h)).collect();
            let c2 = draws.iter().map(|d| libm::cos(*d) * libm::cos(*d)).sum::<f64>() / n as f64;
            let mean = draws.iter().sum::<f64>() / n as f64;
            assert!((c2 - (h + 1.0) / (h + 2.0)).abs() < 0.005, "h = {h}: E[cos^2] = {c2}");
            assert!(mean.abs() < 0.01, "h = {h}: mean {mean}");
        }
    }

    /// A seed fixes the sea; another seed gives another one.
    #[test]
    fn seeded() {
        let s = SeaSampling::new(5.0, 0.5, 0.0);
        assert_eq!(s.sample(42), s.sample(42));
        assert_ne!(s.sample(42), s.sample(43));
    }

    #[test]
    fn elevations_at_many_points_agree_with_the_single_point_sum() {
        let comps = SeaSampling::new(5.0, 0.5, 0.3).sample(7);
        let (xs, ys) = ([0.0, 120.0, -40.0], [0.0, -15.0, 300.0]);
        let mut out = [0.0; 3];
        elevations(&comps, &xs, &ys, 12.5, &mut out);
        for i in 0..3 {
            // Same terms in the same order: equal to rounding of the last bit.
            let one = elevation(&comps, xs[i], ys[i], 12.5);
            assert!((out[i] - one).abs() <= 1e-12 * (1.0 + one.abs()), "{} vs {one}", out[i]);
        }
    }
}
