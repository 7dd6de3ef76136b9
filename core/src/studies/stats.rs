//! Statistics for Monte Carlo studies (thesis ch. 5.4): per-trial seeds that depend on the
//! (master seed, trial index) alone, moments and histograms that merge exactly across shards and
//! threads, Welch periodograms, and the Rice up-crossing rate of a Gaussian process.

use num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Seed of trial `i` of a study with `master` seed: SplitMix64 of both, so the trial's sea does
/// not depend on thread count, order or sharding.
pub fn trial_seed(master: u64, i: u64) -> u64 {
    let mut z = master ^ i.wrapping_add(1).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Count, mean, central moments up to the fourth, extremes; merged with the pairwise formulas of
/// Chan, Golub and LeVeque (1979) and Pebay (2008).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Moments {
    pub n: u64,
    pub mean: f64,
    m2: f64,
    m3: f64,
    m4: f64,
    pub min: f64,
    pub max: f64,
}

impl Default for Moments {
    fn default() -> Self {
        Moments { n: 0, mean: 0.0, m2: 0.0, m3: 0.0, m4: 0.0, min: f64::INFINITY, max: f64::NEG_INFINITY }
    }
}

impl Moments {
    pub fn push(&mut self, x: f64) {
        let mut one = Moments { n: 1, mean: x, min: x, max: x, ..Moments::default() };
        one.m2 = 0.0;
        self.merge(&one);
    }

    /// Combines two sets of moments as if their samples had been pushed into one.
    pub fn merge(&mut self, b: &Moments) {
        if b.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *b;
            return;
        }
        let (na, nb) = (self.n as f64, b.n as f64);
        let n = na + nb;
        let d = b.mean - self.mean;
        let (d2, d3, d4) = (d * d, d * d * d, d * d * d * d);
        let m2 = self.m2 + b.m2 + d2 * na * nb / n;
        let m3 = self.m3 + b.m3 + d3 * na * nb * (na - nb) / (n * n) + 3.0 * d * (na * b.m2 - nb * self.m2) / n;
        let m4 = self.m4
            + b.m4
            + d4 * na * nb * (na * na - na * nb + nb * nb) / (n * n * n)
            + 6.0 * d2 * (na * na * b.m2 + nb * nb * self.m2) / (n * n)
            + 4.0 * d * (na * b.m3 - nb * self.m3) / n;
        self.mean += d * nb / n;
        self.m2 = m2;
        self.m3 = m3;
        self.m4 = m4;
        self.n += b.n;
        self.min = self.min.min(b.min);
        self.max = self.max.max(b.max);
    }

    /// Sample standard deviation (n - 1).
    pub fn std(&self) -> f64 {
        if self.n < 2 {
            0.0
        } else {
            (self.m2 / (self.n as f64 - 1.0)).sqrt()
        }
    }

    /// Skewness (population form, m3 / m2^1.5 sqrt(n)).
    pub fn skewness(&self) -> f64 {
        if self.m2 <= 0.0 {
            0.0
        } else {
            (self.n as f64).sqrt() * self.m3 / libm::pow(self.m2, 1.5)
        }
    }

    /// Kurtosis (not excess; 3 for a Gaussian).
    pub fn kurtosis(&self) -> f64 {
        if self.m2 <= 0.0 {
            0.0
        } else {
            self.n as f64 * self.m4 / (self.m2 * self.m2)
        }
    }
}

/// Moments accumulated exactly: each value is quantised to 2^-`bits` of its unit and its powers
/// summed in 128-bit integers, so any merge order (threads, shards, browser tabs) gives the same
/// bits. `order` 2 keeps mean and variance for values up to 2^(45 - bits) in size; `order` 4 adds
/// skewness and kurtosis for values up to 2^(24 - bits); either way 2^30 samples fit. Larger values
/// are clamped and counted in `clamped`. Sums travel as decimal strings in JSON (JavaScript
/// numbers cannot hold them).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExactMoments {
    pub bits: i32,
    pub order: u8,
    pub n: u64,
    #[serde(with = "i128_strings")]
    pub sums: [i128; 4],
    /// Extremes (JSON null when empty, read back as NaN, which min/max then ignore).
    #[serde(deserialize_with = "null_as_nan")]
    pub min: f64,
    #[serde(deserialize_with = "null_as_nan")]
    pub max: f64,
    pub clamped: u64,
}

fn null_as_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

mod i128_strings {
    use serde::{Deserialize, Deserializer, Serializer};
    pub fn serialize<S: Serializer>(v: &[i128; 4], s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        let mut seq = s.serialize_seq(Some(4))?;
        for x in v {
            seq.serialize_element(&x.to_string())?;
        }
        seq.end()
    }
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<[i128; 4], D::Error> {
        let v: Vec<String> = Vec::deserialize(d)?;
        if v.len() != 4 {
            return Err(serde::de::Error::custom("expected four sums"));
        }
        let mut out = [0i128; 4];
        for (o, s) in out.iter_mut().zip(&v) {
            *o = s.parse().map_err(|_| serde::de::Error::custom(format!("not an integer: {s}")))?;
        }
        Ok(out)
    }
}

impl ExactMoments {
    pub fn new(bits: i32, order: u8) -> ExactMoments {
        ExactMoments { bits, order, n: 0, sums: [0; 4], min: f64::INFINITY, max: f64::NEG_INFINITY, clamped: 0 }
    }

    fn scale(&self) -> f64 {
        libm::ldexp(1.0, self.bits)
    }

    /// Largest quantised magnitude that keeps the sums in range.
    fn limit(&self) -> f64 {
        libm::ldexp(1.0, if self.order > 2 { 24 } else { 45 })
    }

    pub fn push(&mut self, x: f64) {
        if !x.is_finite() {
            self.clamped += 1;
            return;
        }
        let lim = self.limit();
        let qf = libm::round(x * self.scale());
        if qf.abs() > lim {
            self.clamped += 1;
        }
        let q = qf.clamp(-lim, lim) as i128;
        let mut p = q;
        for k in 0..self.order.min(4) as usize {
            self.sums[k] += p;
            p *= q;
        }
        self.n += 1;
        self.min = self.min.min(x);
        self.max = self.max.max(x);
    }

    /// Adds another accumulator of the same quantum and order.
    pub fn merge(&mut self, b: &ExactMoments) -> Result<(), String> {
        if b.bits != self.bits || b.order != self.order {
            return Err("exact moments with different quanta cannot be merged".into());
        }
        let mut sums = self.sums;
        for (s, x) in sums.iter_mut().zip(b.sums) {
            *s = s.checked_add(x).ok_or("exact moments overflow: more samples than the sums can hold")?;
        }
        let n = self.n.checked_add(b.n).ok_or("exact moments: the sample count overflows")?;
        let clamped = self.clamped.checked_add(b.clamped).ok_or("exact moments: the clamped count overflows")?;
        self.sums = sums;
        self.n = n;
        self.min = self.min.min(b.min);
        self.max = self.max.max(b.max);
        self.clamped = clamped;
        Ok(())
    }

    /// Checks that the counts and sums could come from `n` values between `min` and `max`
    /// (quantised as [`ExactMoments::push`] does): no sums without samples, every power sum
    /// within n times the extremes' powers, S2 at least S1^2 / n (Cauchy-Schwarz) and the
    /// variance at most (max - min)^2 / 4 (Popoviciu), S4 at least S2^2 / n, no sums above the
    /// order kept. The bounds are exact on the integers; the f64 comparisons allow 1e-9 of the
    /// magnitudes and one quantum for rounding. The error says what is impossible.
    pub fn check_consistent(&self) -> Result<(), String> {
        let order = self.order.min(4) as usize;
        if let Some(k) = (order..4).find(|&k| self.sums[k] != 0) {
            return Err(format!("sum {} = {}: this accumulator keeps {} sums", k + 1, self.sums[k], order));
        }
        if self.n == 0 {
            if self.sums.iter().any(|&s| s != 0) || self.min.is_finite() || self.max.is_finite() {
                return Err("n = 0 beside non-zero sums or finite extremes".to_string());
            }
            return Ok(());
        }
        if !(self.min.is_finite() && self.max.is_finite() && self.min <= self.max) {
            return Err(format!("min = {}, max = {}: need finite min <= max", self.min, self.max));
        }
        let lim = self.limit();
        let q = |x: f64| libm::round(x * self.scale()).clamp(-lim, lim);
        let (lo, hi) = (q(self.min), q(self.max));
        let n = self.n as f64;
        let s: Vec<f64> = self.sums.iter().map(|&v| v as f64).collect();
        let slack = |bound: f64| 1e-9 * bound.abs() + 1.0;
        let big = lo.abs().max(hi.abs());
        let mut bad = Vec::new();
        // The extremes are two of the samples (one when n = 1): the sum holds min and max and
        // n - 2 values between them, so it lies in [max + (n - 1) min, min + (n - 1) max].
        let (s_lo, s_hi) = (hi + (n - 1.0) * lo, lo + (n - 1.0) * hi);
        if s[0] < s_lo - slack(s_lo) || s[0] > s_hi + slack(s_hi) {
            bad.push("the sum lies outside [max + (n - 1) min, min + (n - 1) max], the sums of n values whose extremes are min and max");
        }
        if order >= 2 {
            let top = n * big * big;
            if s[1] < 0.0 || s[1] > top + slack(top) {
                bad.push("the sum of squares lies outside [0, n max(|min|, |max|)^2]");
            }
            let mean = s[0] / n;
            let var = s[1] / n - mean * mean;
            let spread = (hi - lo) * (hi - lo) / 4.0;
            let tol = slack(s[1] / n);
            if var < -tol {
                bad.push("the sum of squares is below the square of the sum over n");
            } else if var > spread + tol {
                bad.push("the variance exceeds (max - min)^2 / 4, the most values in [min, max] can have");
            }
        }
        if order >= 3 {
            let top = n * big * big * big;
            if s[2].abs() > top + slack(top) {
                bad.push("the sum of cubes exceeds n max(|min|, |max|)^3");
            }
        }
        if order >= 4 {
            let top = n * big * big * big * big;
            if s[3] < 0.0 || s[3] > top + slack(top) {
                bad.push("the sum of fourth powers lies outside [0, n max(|min|, |max|)^4]");
            } else if s[3] * n < s[1] * s[1] - slack(s[1] * s[1]) {
                bad.push("the sum of fourth powers is below the square of the sum of squares over n");
            }
        }
        match bad.first() {
            None => Ok(()),
            Some(why) => Err(format!(
                "n = {}, min = {}, max = {}, sums = [{}, {}, {}, {}]: {why}",
                self.n,
                crate::checks::num(self.min),
                crate::checks::num(self.max),
                self.sums[0],
                self.sums[1],
                self.sums[2],
                self.sums[3]
            )),
        }
    }

    /// Raw moment E\[x^k\] (k = 1..4).
    fn raw(&self, k: usize) -> f64 {
        self.sums[k - 1] as f64 / self.n.max(1) as f64 / libm::pow(self.scale(), k as f64)
    }

    /// The mean; within \[min, max\], which the values' quantisation to the grid could leave by
    /// a grid step (a mean above the largest value, measured 5e-6 rpm over 60 trials).
    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            f64::NAN
        } else {
            self.raw(1).clamp(self.min, self.max)
        }
    }

    /// The sample standard deviation where it is defined (two values or more), else None.
    pub fn std_defined(&self) -> Option<f64> {
        (self.n >= 2).then(|| self.std())
    }

    /// The skewness where it is defined (three values or more, not all equal, third and fourth
    /// moments kept), else None.
    pub fn skewness_defined(&self) -> Option<f64> {
        let (mu2, _, _) = self.central();
        (self.n >= 3 && mu2 > 0.0 && self.order >= 4).then(|| self.skewness())
    }

    /// The kurtosis where it is defined (four values or more, not all equal), else None.
    pub fn kurtosis_defined(&self) -> Option<f64> {
        let (mu2, _, _) = self.central();
        (self.n >= 4 && mu2 > 0.0 && self.order >= 4).then(|| self.kurtosis())
    }

    /// Sample standard deviation (n - 1).
    pub fn std(&self) -> f64 {
        if self.n < 2 {
            return 0.0;
        }
        let m = self.raw(1);
        let var = (self.raw(2) - m * m).max(0.0);
        (var * self.n as f64 / (self.n - 1) as f64).sqrt()
    }

    /// Central moments mu_2, mu_3, mu_4 (population).
    fn central(&self) -> (f64, f64, f64) {
        let (m, r2, r3, r4) = (self.raw(1), self.raw(2), self.raw(3), self.raw(4));
        let mu2 = (r2 - m * m).max(0.0);
        let mu3 = r3 - 3.0 * m * r2 + 2.0 * m * m * m;
        let mu4 = r4 - 4.0 * m * r3 + 6.0 * m * m * r2 - 3.0 * m * m * m * m;
        (mu2, mu3, mu4)
    }

    /// Skewness mu3 / mu2^1.5 (0 for fewer than 3 samples or order 2).
    pub fn skewness(&self) -> f64 {
        let (mu2, mu3, _) = self.central();
        if self.n < 3 || mu2 <= 0.0 || self.order < 4 {
            0.0
        } else {
            mu3 / libm::pow(mu2, 1.5)
        }
    }

    /// Kurtosis mu4 / mu2^2 (3 for a normal distribution, 9 for the exponential).
    pub fn kurtosis(&self) -> f64 {
        let (mu2, _, mu4) = self.central();
        if self.n < 4 || mu2 <= 0.0 || self.order < 4 {
            0.0
        } else {
            mu4 / (mu2 * mu2)
        }
    }
}

/// A histogram with fixed bins, so shards add up exactly.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Histogram {
    pub lo: f64,
    pub hi: f64,
    pub counts: Vec<u64>,
    pub below: u64,
    pub above: u64,
}

impl Histogram {
    pub fn new(lo: f64, hi: f64, bins: usize) -> Histogram {
        Histogram { lo, hi, counts: vec![0; bins.max(1)], below: 0, above: 0 }
    }

    pub fn push(&mut self, x: f64) {
        if x < self.lo || x.is_nan() {
            self.below += 1;
        } else if x >= self.hi {
            self.above += 1;
        } else {
            let bins = self.counts.len();
            let k = ((x - self.lo) / (self.hi - self.lo) * bins as f64) as usize;
            self.counts[k.min(bins - 1)] += 1;
        }
    }

    /// Adds another histogram with the same bins; refuses different bins.
    pub fn merge(&mut self, b: &Histogram) -> Result<(), String> {
        if b.lo != self.lo || b.hi != self.hi || b.counts.len() != self.counts.len() {
            return Err("histograms with different bins cannot be merged".into());
        }
        let overflow = || "histograms: a count overflows".to_string();
        let counts: Vec<u64> = self
            .counts
            .iter()
            .zip(&b.counts)
            .map(|(a, c)| a.checked_add(*c).ok_or_else(overflow))
            .collect::<Result<_, _>>()?;
        let below = self.below.checked_add(b.below).ok_or_else(overflow)?;
        let above = self.above.checked_add(b.above).ok_or_else(overflow)?;
        self.counts = counts;
        self.below = below;
        self.above = above;
        Ok(())
    }

    /// Number of samples counted, inside the bins and outside.
    pub fn total(&self) -> u64 {
        self.below.saturating_add(self.above).saturating_add(self.counts.iter().fold(0u64, |a, c| a.saturating_add(*c)))
    }

    /// The median by linear interpolation inside the bin where the cumulative count crosses half
    /// (counts below the range included, above it too).
    pub fn median(&self) -> f64 {
        let total = self.below + self.above + self.counts.iter().sum::<u64>();
        if total == 0 {
            return f64::NAN;
        }
        let half = total as f64 / 2.0;
        let mut cum = self.below as f64;
        if cum >= half {
            return self.lo;
        }
        let w = (self.hi - self.lo) / self.counts.len() as f64;
        for (k, &c) in self.counts.iter().enumerate() {
            if cum + c as f64 >= half && c > 0 {
                return self.lo + w * (k as f64 + (half - cum) / c as f64);
            }
            cum += c as f64;
        }
        self.hi
    }

    /// Centre of the fullest bin (the mode of Table 5.8).
    pub fn mode(&self) -> f64 {
        let k = self.counts.iter().enumerate().max_by_key(|(_, c)| **c).map_or(0, |(k, _)| k);
        self.lo + (k as f64 + 0.5) * (self.hi - self.lo) / self.counts.len() as f64
    }

    /// Checks that every count lies where the values `x` counts can be: a bin holds values only
    /// if it meets [min, max] of `x`, `below` only a value under `lo` (or one not finite), `above`
    /// only one from `hi` up (or an infinite one). So the median and mode read from the bins lie
    /// within the accumulator's extremes. Room of 1e-9 of the range for the bin's rounding.
    pub fn check_within(&self, x: &ExactMoments) -> Result<(), String> {
        use crate::checks::num;
        let n = self.counts.len();
        let (lo, hi) = (self.lo, self.hi);
        let w = (hi - lo) / n as f64;
        let slack = 1e-9 * (hi - lo).abs().max(1.0);
        let extremes = || format!("the values' min = {}, max = {}", num(x.min), num(x.max));
        let finite = x.n > 0;
        if self.below > 0 && x.clamped == 0 && !(finite && x.min < lo + slack) {
            return Err(format!("below = {}: values under {} counted, but {}", self.below, num(lo), extremes()));
        }
        if self.above > 0 && x.clamped == 0 && !(finite && x.max >= hi - slack) {
            return Err(format!("above = {}: values from {} up counted, but {}", self.above, num(hi), extremes()));
        }
        for (k, &c) in self.counts.iter().enumerate() {
            let (a, b) = (lo + w * k as f64, lo + w * (k + 1) as f64);
            if c > 0 && !(finite && x.max >= a - slack && x.min <= b + slack) {
                return Err(format!(
                    "counts.{k} = {c}: bin [{}, {}) lies outside {} of the values it counts",
                    num(a),
                    num(b),
                    extremes()
                ));
            }
        }
        Ok(())
    }
}

/// One-sided power spectral density by Welch's method: Hann windows of `segment` samples with
/// 50 % overlap, mean removed per segment. Returns (frequencies \[Hz\], PSD \[unit^2/Hz\]); its
/// integral over frequency is the signal's variance (Parseval).
pub fn welch(signal: &[f64], dt: f64, segment: usize) -> (Vec<f64>, Vec<f64>) {
    let seg = segment.min(signal.len()).max(2);
    let step = (seg / 2).max(1);
    let window: Vec<f64> = (0..seg).map(|i| 0.5 - 0.5 * libm::cos(2.0 * PI * i as f64 / seg as f64)).collect();
    let wsum2: f64 = window.iter().map(|w| w * w).sum();
    let fft = crate::numerics::fft::Fft::new(seg);
    let n_out = seg / 2 + 1;
    let mut psd = vec![0.0; n_out];
    let mut count = 0usize;
    let mut buf = vec![Complex64::new(0.0, 0.0); seg];
    let mut start = 0;
    while start + seg <= signal.len() {
        let part = &signal[start..start + seg];
        let mean = part.iter().sum::<f64>() / seg as f64;
        for i in 0..seg {
            buf[i] = Complex64::new((part[i] - mean) * window[i], 0.0);
        }
        fft.forward(&mut buf);
        for (k, p) in psd.iter_mut().enumerate() {
            let two = if k == 0 || (seg % 2 == 0 && k == seg / 2) { 1.0 } else { 2.0 };
            *p += two * buf[k].norm_sqr() * dt / wsum2;
        }
        count += 1;
        start += step;
    }
    for p in psd.iter_mut() {
        *p /= count.max(1) as f64;
    }
    let freqs = (0..n_out).map(|k| k as f64 / (seg as f64 * dt)).collect();
    (freqs, psd)
}

/// Rice's mean rate of up-crossings of level `z` by a zero-mean Gaussian process with spectral
/// moments m0 and m2 \[1/s\]: (1 / 2 pi) sqrt(m2 / m0) exp(-z^2 / (2 m0)).
pub fn rice_upcrossing_rate(m0: f64, m2: f64, z: f64) -> f64 {
    (m2 / m0).sqrt() / (2.0 * PI) * libm::exp(-z * z / (2.0 * m0))
}

/// The joint second-order statistics of two stationary zero-mean Gaussian processes y1, y2 and
/// their rates: variances `m0`, variances of the rates `m2`, cov(y1, y2) = `c`, and
/// cov(y1', y2) = `d` (then cov(y1, y2') = -d and cov(y_j, y_j') = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussianPair {
    pub m0: [f64; 2],
    pub m2: [f64; 2],
    pub c: f64,
    pub d: f64,
}

/// Standard normal distribution function (libm's erfc).
fn normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x / std::f64::consts::SQRT_2)
}

impl GaussianPair {
    /// The correlation of y1 and y2.
    pub fn correlation(&self) -> f64 {
        self.c / (self.m0[0] * self.m0[1]).sqrt()
    }

    /// The rate at which the pair enters the set {y1 > z or y2 > z} \[1/s\]: the up-crossings of z
    /// by y1 while y2 < z plus those of y2 while y1 < z (Rice's formula for the union of the two
    /// levels, from the trivariate normal of (y_j, y_j', y_k)). It lies between the larger of the
    /// two single rates and their sum; for two identical processes it is their common rate, for
    /// independent ones each rate times the other's probability of being below z.
    pub fn union_upcrossing_rate(&self, z: f64) -> f64 {
        if self.correlation() >= 1.0 - 1e-12 && self.m0[0] == self.m0[1] && self.m2[0] == self.m2[1] {
            // One process twice: its own rate (exactly: no quadrature).
            return rice_upcrossing_rate(self.m0[0], self.m2[0], z);
        }
        self.upcrossing_while_other_below(0, z) + self.upcrossing_while_other_below(1, z)
    }

    /// The probability that y1 > z or y2 > z at any one time: 1 - P(y1 <= z, y2 <= z), the
    /// bivariate normal integrated over y1 by the midpoint rule (4000 points over -10 to z/sigma1
    /// standard deviations).
    pub fn either_above(&self, z: f64) -> f64 {
        let (s1, s2) = (self.m0[0].sqrt(), self.m0[1].sqrt());
        let rho = self.correlation().min(1.0);
        let sd = (s2 * s2 * (1.0 - rho * rho)).max(1e-18 * self.m0[1]).sqrt();
        let (lo, n) = (-10.0 * s1, 4000);
        let dx = (z - lo) / n as f64;
        let mut both_below = 0.0;
        for i in 0..n {
            let x = lo + (i as f64 + 0.5) * dx;
            let px = libm::exp(-x * x / (2.0 * self.m0[0])) / (2.0 * PI * self.m0[0]).sqrt();
            both_below += px * normal_cdf((z - self.c / self.m0[0] * x) / sd) * dx;
        }
        1.0 - both_below
    }

    /// The rate of up-crossings of z by y_j while the other is below z \[1/s\]:
    /// p(y_j = z) int_0^inf v p(y_j' = v | y_j = z) P(y_k < z | y_j = z, y_j' = v) dv, the integral
    /// by the midpoint rule over 0 to 10 standard deviations of y_j' (4000 points).
    fn upcrossing_while_other_below(&self, j: usize, z: f64) -> f64 {
        let k = 1 - j;
        let (m0, m2) = (self.m0[j], self.m2[j]);
        // cov(y_j', y_k): d for j = 0, -d for j = 1.
        let d = if j == 0 { self.d } else { -self.d };
        let density = libm::exp(-z * z / (2.0 * m0)) / (2.0 * PI * m0).sqrt();
        // y_k given y_j = z and y_j' = v: mean c z / m0 + d v / m2, variance m0_k - c^2/m0 - d^2/m2
        // (floored: two hubs that move nearly alike).
        let var = (self.m0[k] - self.c * self.c / m0 - d * d / m2).max(1e-18 * self.m0[k]);
        let sd = var.sqrt();
        let sv = m2.sqrt();
        let n = 4000;
        let dv = 10.0 * sv / n as f64;
        let mut sum = 0.0;
        for i in 0..n {
            let v = (i as f64 + 0.5) * dv;
            let pv = libm::exp(-v * v / (2.0 * m2)) / (2.0 * PI * m2).sqrt();
            let mean = self.c * z / m0 + d * v / m2;
            sum += v * pv * normal_cdf((z - mean) / sd) * dv;
        }
        density * sum
    }
}

#[cfg(test)]
mod union_tests {
    use super::*;

    /// The union rate's two limits: identical processes give their one rate; independent ones
    /// (c = d = 0) give each rate times the other's probability of being below the level, to 1e-6
    /// relative (the midpoint rule's error, measured 2.6e-7), which lies below the sum of the rates.
    #[test]
    fn union_rate_between_its_limits() {
        let (m0, m2, z) = (0.5, 0.4, 1.2);
        let one = rice_upcrossing_rate(m0, m2, z);
        let same = GaussianPair { m0: [m0, m0], m2: [m2, m2], c: m0, d: 0.0 };
        assert_eq!(same.union_upcrossing_rate(z), one);
        // Nearly the same (correlation 1 - 1e-9): the quadrature gives the one rate too.
        let near = GaussianPair { c: m0 * (1.0 - 1e-9), ..same };
        assert!((near.union_upcrossing_rate(z) / one - 1.0).abs() < 1e-3, "{}", near.union_upcrossing_rate(z) / one);
        let (m0b, m2b) = (0.7, 0.3);
        let two = rice_upcrossing_rate(m0b, m2b, z);
        let free = GaussianPair { m0: [m0, m0b], m2: [m2, m2b], c: 0.0, d: 0.0 };
        let below = |m: f64| 1.0 - 0.5 * libm::erfc(z / (2.0 * m).sqrt());
        let expect = one * below(m0b) + two * below(m0);
        let got = free.union_upcrossing_rate(z);
        assert!((got / expect - 1.0).abs() < 1e-6, "{got} against {expect}");
        assert!(got < one + two && got > one.max(two));
    }
}

#[cfg(test)]
mod exact_tests {
    use super::*;

    /// Exact moments: any merge order gives the same bits, and the statistics agree with the
    /// floating-point Moments to 1e-9 (quantum 2^-24 of the unit).
    #[test]
    fn order_independent_and_accurate() {
        let xs: Vec<f64> = (0..1000).map(|i| libm::exp(libm::sin(i as f64 * 0.37) * 3.0) + 0.001 * i as f64).collect();
        let mut a = ExactMoments::new(12, 4);
        xs.iter().for_each(|&x| a.push(x));
        let (mut b1, mut b2) = (ExactMoments::new(12, 4), ExactMoments::new(12, 4));
        xs.iter().rev().take(400).for_each(|&x| b2.push(x));
        xs.iter().take(600).for_each(|&x| b1.push(x));
        b2.merge(&b1).unwrap();
        assert_eq!(a, b2);
        assert_eq!(a.clamped, 0);
        let mut m = Moments::default();
        xs.iter().for_each(|&x| m.push(x));
        // Quantum 2^-12 = 2.4e-4: the mean within 1e-5, the shape statistics within 1e-4.
        assert!((a.mean() - m.mean).abs() < 1e-5 && (a.std() - m.std()).abs() < 1e-5);
        assert!((a.skewness() - m.skewness()).abs() < 1e-4 && (a.kurtosis() - m.kurtosis()).abs() < 1e-4);
        assert!(a.skewness() > 1.0);
        assert!(ExactMoments::new(12, 4).merge(&ExactMoments::new(16, 2)).is_err());
        let json = serde_json::to_string(&a).unwrap();
        assert_eq!(serde_json::from_str::<ExactMoments>(&json).unwrap(), a);
        // An empty accumulator goes through JSON (its infinite extremes become null) and merges.
        let mut e: ExactMoments =
            serde_json::from_str(&serde_json::to_string(&ExactMoments::new(12, 4)).unwrap()).unwrap();
        e.merge(&a).unwrap();
        assert_eq!((e.min, e.max, e.n), (a.min, a.max, a.n));
    }

    #[test]
    fn histogram_median() {
        let mut h = Histogram::new(0.0, 10.0, 10);
        for x in [1.5, 2.5, 3.5, 4.5] {
            h.push(x);
        }
        assert!((h.median() - 3.0).abs() < 1e-12);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The defined statistics: a spread needs two values, skewness three and kurtosis four (and
    /// values not all equal); the mean stays within the values although each is quantised to
    /// 2^-16 (160.903055906... rounds up to ...061 on the grid: the mean was above the largest).
    #[test]
    fn statistics_are_none_where_undefined_and_the_mean_stays_within_the_values() {
        let mut x = ExactMoments::new(16, 4);
        assert_eq!(x.std_defined(), None);
        let v = 160.903_055_906_900_42;
        x.push(v);
        assert_eq!((x.std_defined(), x.skewness_defined(), x.kurtosis_defined()), (None, None, None));
        assert_eq!(x.mean(), v);
        x.push(v);
        x.push(v);
        assert_eq!(x.std_defined(), Some(0.0));
        assert_eq!((x.skewness_defined(), x.kurtosis_defined()), (None, None));
        x.push(v + 1.0);
        assert!(x.std_defined().unwrap() > 0.0 && x.skewness_defined().is_some() && x.kurtosis_defined().is_some());
        assert!(x.mean() >= v && x.mean() <= v + 1.0);
    }

    fn sample(n: usize, seed: u64) -> Vec<f64> {
        let mut r = ChaCha8Rng::seed_from_u64(seed);
        // A skewed variable: the exponential distribution (skewness 2, kurtosis 9).
        (0..n).map(|_| -libm::log(1.0 - r.random::<f64>())).collect()
    }

    /// Merged shards give the single-pass moments to 1e-10 (relative), in any order, and the
    /// exponential distribution's skewness 2 and kurtosis 9 within sampling error (1e6 draws).
    #[test]
    fn moments_merge_exactly() {
        let x = sample(1_000_000, 1);
        let mut one = Moments::default();
        x.iter().for_each(|v| one.push(*v));
        let mut shards: Vec<Moments> = x
            .chunks(77_777)
            .map(|c| {
                let mut m = Moments::default();
                c.iter().for_each(|v| m.push(*v));
                m
            })
            .collect();
        shards.reverse();
        let mut merged = Moments::default();
        shards.iter().for_each(|m| merged.merge(m));
        for (a, b) in [
            (one.mean, merged.mean),
            (one.std(), merged.std()),
            (one.skewness(), merged.skewness()),
            (one.kurtosis(), merged.kurtosis()),
        ] {
            assert!((a - b).abs() < 1e-10 * a.abs(), "{a} vs {b}");
        }
        assert_eq!((one.min, one.max, one.n), (merged.min, merged.max, merged.n));
        assert!((one.mean - 1.0).abs() < 0.005 && (one.std() - 1.0).abs() < 0.005);
        assert!((one.skewness() - 2.0).abs() < 0.05, "skewness {}", one.skewness());
        assert!((one.kurtosis() - 9.0).abs() < 0.5, "kurtosis {}", one.kurtosis());
    }

    #[test]
    fn histograms_merge_exactly() {
        let x = sample(10_000, 2);
        let mut one = Histogram::new(0.0, 5.0, 50);
        x.iter().for_each(|v| one.push(*v));
        let mut a = Histogram::new(0.0, 5.0, 50);
        let mut b = Histogram::new(0.0, 5.0, 50);
        x[..3000].iter().for_each(|v| a.push(*v));
        x[3000..].iter().for_each(|v| b.push(*v));
        a.merge(&b).unwrap();
        assert_eq!(a, one);
        assert_eq!(one.counts.iter().sum::<u64>() + one.above + one.below, 10_000);
        assert!(one.mode() < 0.2, "exponential mode near 0: {}", one.mode());
        assert!(a.merge(&Histogram::new(0.0, 4.0, 50)).is_err());
    }

    /// Welch's periodogram integrates to the variance (Parseval) within 2 %, for a sum of sines
    /// plus noise, and finds the sine's frequency.
    #[test]
    fn welch_parseval() {
        let mut r = ChaCha8Rng::seed_from_u64(3);
        let dt = 0.05;
        let x: Vec<f64> = (0..20_000)
            .map(|i| {
                let t = i as f64 * dt;
                3.0 * libm::sin(2.0 * PI * 0.8 * t) + libm::sin(2.0 * PI * 2.3 * t + 1.0) + (r.random::<f64>() - 0.5)
            })
            .collect();
        let mean = x.iter().sum::<f64>() / x.len() as f64;
        let var = x.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / x.len() as f64;
        let (f, p) = welch(&x, dt, 1024);
        let df = f[1] - f[0];
        let area: f64 = p.iter().sum::<f64>() * df;
        assert!((area / var - 1.0).abs() < 0.02, "Parseval: {area} vs {var}");
        let peak = p.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)).unwrap().0;
        assert!((f[peak] - 0.8).abs() < 2.0 * df, "peak at {} Hz", f[peak]);
    }

    /// Rice's rate: at z = 0 it is the zero-crossing rate (1/2 pi) sqrt(m2/m0); for a single sine of
    /// frequency w it is w / 2 pi; it falls with the level as exp(-z^2 / 2 m0).
    #[test]
    fn rice_rate() {
        let w: f64 = 0.7;
        let (a, m0) = (2.0, 2.0);
        let m2 = w * w * a * a / 2.0;
        assert!((rice_upcrossing_rate(m0, m2, 0.0) - w / (2.0 * PI)).abs() < 1e-15);
        assert!(
            (rice_upcrossing_rate(m0, m2, 2.0) / rice_upcrossing_rate(m0, m2, 0.0) - libm::exp(-1.0)).abs() < 1e-15
        );
    }

    #[test]
    fn trial_seeds_are_distinct_and_fixed() {
        let s: std::collections::HashSet<u64> = (0..100_000).map(|i| trial_seed(42, i)).collect();
        assert_eq!(s.len(), 100_000);
        assert_eq!(trial_seed(42, 7), trial_seed(42, 7));
        assert_ne!(trial_seed(42, 7), trial_seed(43, 7));
    }
}
