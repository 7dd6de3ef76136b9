//! Rice's prediction of the first propeller surface effect (thesis ch. 5.4, eqs. 5.1-5.3): the
//! hub-depth response spectrum S_y = |H_p|^2 S(omega) D(mu) over the spreading, with H_p the hub
//! transfer function of the run (eq. 5.2 with the run's `stern_motion` sign) at the ordered speed;
//! its moments in the encounter frequency, and the up-crossing rate of eq. 5.3 of the level
//! Z = h0 - h_on R at which ventilation starts, per hub and for the union of the two hubs (their
//! joint statistics). The Monte Carlo summary sets it beside the trials' arrival times.

use crate::scenario::{Scenario, SeaKind};
use crate::sea::seakeeping::params::HubPlace;
use crate::ship::hull::N_SHAFTS;
use crate::studies::stats::rice_upcrossing_rate;
use serde::Serialize;
use serde_json::Value;
use std::f64::consts::PI;

/// Rice's prediction (eqs. 5.1-5.3) for the study's sea, speed and hubs (see [`RiceSummary`]).
pub fn rice(sc: &Scenario) -> Result<Value, String> {
    serde_json::to_value(rice_summary(sc)?).map_err(|e| e.to_string())
}

/// Rice's prediction, None unless the sea is random: for each hub its own spectrum's moments and
/// up-crossing rate, and for the event the trials count, the first surface effect on either
/// shaft, the rate at which either hub crosses (the union from the two hubs' joint statistics).
pub fn rice_summary(sc: &Scenario) -> Result<Option<RiceSummary>, String> {
    if sc.sea.kind != SeaKind::Random {
        return Ok(None);
    }
    let k = &sc.seakeeping;
    let hull = sc.ship_hull()?;
    let table = sc.rao_table()?;
    let hubs = hull.shaft_y_m.map(|y| HubPlace { x_aft: hull.prop_x_aft_m, y });
    let (h, wn) = sc.sea.spectrum();
    let (w_lo, w_hi) = sc.sea.band();
    let u = crate::numerics::units::kn_to_m_s(sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(25.0));
    let psi = 0.0;
    let mu0 = (sc.sea.from_deg + 180.0).to_radians();
    let (nw, nd) = (400usize, 61usize);
    let dw = (w_hi - w_lo) / nw as f64;
    // Spreading density cos^h on (-pi/2, pi/2), normalised numerically (midpoint rule).
    let dd = PI / nd as f64;
    let spread: Vec<(f64, f64)> = (0..nd)
        .map(|j| {
            let d = -PI / 2.0 + (j as f64 + 0.5) * dd;
            (d, if sc.sea.spreading > 0.0 { libm::pow(libm::cos(d), sc.sea.spreading) } else { 0.0 })
        })
        .collect();
    let norm: f64 = spread.iter().map(|(_, w)| w * dd).sum();
    let dirs: Vec<(f64, f64)> = if sc.sea.spreading > 0.0 {
        spread.iter().map(|&(d, w)| (d, w * dd / norm)).collect()
    } else {
        vec![(0.0, 1.0)]
    };
    // Each hub's moments, and the cross terms: cov(y1, y2) = sum Re(H1 H2*) S and
    // cov(y1', y2) = -sum omega_e Im(H1 H2*) S, omega_e the signed encounter frequency (the rate
    // of the component's phase in the seaway: omega - k U cos beta).
    let (mut m0, mut m2, mut c, mut d) = ([0.0; N_SHAFTS], [0.0; N_SHAFTS], 0.0, 0.0);
    for i in 0..nw {
        let w = w_lo + (i as f64 + 0.5) * dw;
        let s = crate::sea::waves::bretschneider(w, h, wn);
        let kw = w * w / crate::sea::waves::G;
        for &(dir, wt) in &dirs {
            let beta = psi - (mu0 + dir);
            let r = table.interpolate(w, u, beta);
            let (cos_beta, sin_beta) = (libm::cos(beta), libm::sin(beta));
            let hp = hubs.map(|at| {
                let wave = k.stern_motion.hub_wave(kw, at, cos_beta, sin_beta);
                k.stern_motion.hub_transfer(wave, r.heave, r.roll, r.pitch, at)
            });
            let we = w - kw * u * cos_beta;
            for j in 0..N_SHAFTS {
                let sy = hp[j].norm_sqr() * s * wt * dw;
                m0[j] += sy;
                m2[j] += sy * we * we;
            }
            let cross = hp[0] * hp[1].conj();
            c += cross.re * s * wt * dw;
            d -= we * cross.im * s * wt * dw;
        }
    }
    let radius = 0.5 * sc.propeller.diameter_m;
    let z = hull.hub_depth_m - k.ventilation_on_h_over_r * radius;
    let cap = sc.sim.duration_s;
    let censored = |rate: f64| (1.0 - libm::exp(-rate * cap)) / rate;
    let pair = crate::studies::stats::GaussianPair { m0, m2, c, d };
    let per_hub: [RiceHub; N_SHAFTS] = std::array::from_fn(|j| {
        let rate = rice_upcrossing_rate(m0[j], m2[j], z);
        RiceHub {
            shaft: ["port", "starboard"][j],
            y_m: hubs[j].y,
            m0: m0[j],
            m2: m2[j],
            rate_per_s: rate,
            mean_arrival_s: 1.0 / rate,
            mean_censored_s: censored(rate),
        }
    });
    // The hub depth drops below the level when its motion y rises above Z: the union of the
    // two up-crossings (the signs of y and y' flip together, the joint statistics do not).
    let rate = pair.union_upcrossing_rate(z);
    let p0 = pair.either_above(z);
    let sum_bound = per_hub[0].rate_per_s + per_hub[1].rate_per_s;
    Ok(Some(RiceSummary {
        z_m: z,
        threshold_h_over_r: k.ventilation_on_h_over_r,
        event: "the first surface effect on either shaft (what the trials count)",
        method: "union of the two hubs' up-crossings from their joint Gaussian statistics (Rice's formula with the \
                 other hub below the level), Poisson arrivals at that rate; sum_bound_rate_per_s is the upper \
                 bound by the sum of the two hubs' rates",
        rate_per_s: rate,
        mean_arrival_s: 1.0 / rate,
        mean_censored_s: censored(rate),
        cap_s: cap,
        sum_bound_rate_per_s: sum_bound,
        sum_bound_mean_censored_s: censored(sum_bound),
        hub_correlation: pair.correlation(),
        start_past_level_probability: p0,
        mean_censored_with_start_s: (1.0 - p0) * censored(rate),
        hubs: per_hub,
    }))
}

/// Rice's prediction (eqs. 5.1-5.3) of the first surface effect on either shaft: the level Z \[m\]
/// the hubs' motion must rise above (h/R below `threshold_h_over_r`), the rate \[1/s\] of the
/// union of the two hubs' up-crossings, its mean arrival 1/rate \[s\] and the mean of
/// min(arrival, cap) an exponential arrival gives censored at the run's duration \[s\]; the upper
/// bound by the sum of the two rates; and each hub's own prediction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RiceSummary {
    pub z_m: f64,
    pub threshold_h_over_r: f64,
    /// What the rate predicts, and how.
    pub event: &'static str,
    pub method: &'static str,
    pub rate_per_s: f64,
    pub mean_arrival_s: f64,
    pub mean_censored_s: f64,
    pub cap_s: f64,
    pub sum_bound_rate_per_s: f64,
    pub sum_bound_mean_censored_s: f64,
    /// Correlation of the two hubs' depths (1: they move alike).
    pub hub_correlation: f64,
    /// Probability that a trial starts with either hub already past the level (its first event
    /// at t = 0, which Poisson arrivals from t = 0 do not count).
    pub start_past_level_probability: f64,
    /// The mean of min(arrival, cap) with those trials' arrivals at 0 and the others' exponential
    /// at `rate_per_s`: (1 - p0) `mean_censored_s` \[s\]; what the trials' `mean_censored` estimates.
    pub mean_censored_with_start_s: f64,
    pub hubs: [RiceHub; N_SHAFTS],
}

/// Rice's prediction for one hub alone: its offset to port \[m\], its depth spectrum's moments
/// M0 \[m^2\] and M2 \[m^2/s^2\] (in the encounter frequency), the up-crossing rate of eq. 5.3 \[1/s\],
/// 1/rate and the censored mean \[s\].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RiceHub {
    pub shaft: &'static str,
    pub y_m: f64,
    pub m0: f64,
    pub m2: f64,
    pub rate_per_s: f64,
    pub mean_arrival_s: f64,
    pub mean_censored_s: f64,
}
