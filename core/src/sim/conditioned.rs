//! A random sea conditioned on a propeller hub reaching a chosen depth at a chosen time (issue
//! 32; the scenario's `rare_event` section).
//!
//! The seaway is linear in the wave components: with complex coefficients c_i = A_i + i B_i
//! (amplitude and phase of component i), the hub's depth swing at the ship's place is
//! r(t) = sum_i Re(c_i H_i e^{i theta_i(t)}), H_i the hub's transfer function (eq. 2.57 with the
//! RAOs at the ship's speed and heading) and theta_i the phase without the component's own. When
//! A_i and B_i are independent Gaussian variables of variance S(omega_i) d omega (a Gaussian sea:
//! the thesis' amplitudes sqrt(2 S d omega) times Rayleigh factors), r and its rate are Gaussian,
//! and the sea given r(t0) = r* and r'(t0) = v* is exactly the unconditioned sea corrected along
//! the two directions the constraints span (r and r' are uncorrelated at one instant):
//! c_i += s_i^2 (dr/dc_i) (r* - r(t0)) / m0 + s_i^2 (dr'/dc_i) (v* - r'(t0)) / m2.
//! With v* drawn from the speeds of crossings of the process (Rice: a Rayleigh law of scale
//! sqrt(m2)), the conditioned seas are the seas of events picked at random among all events
//! (Slepian's model); with no random part and v* = 0, the conditional mean: the most likely
//! wave group that makes the event (Lindgren; Taylor's NewWave). The full nonlinear model then
//! runs through the sea as in any trial.
//!
//! The ship is taken at the place, heading and speed `rare_event.ship_x_m`, `ship_y_m`,
//! `ship_heading_deg` and `ship_speed_kn` say (by default its ordered speed from the start, as Rice's prediction
//! takes it; the rare-event study sets them from a run in waves, since the ship slows there).

use crate::scenario::Scenario;
use crate::sea::conditioning::Shape;
use crate::sea::seakeeping::params::HubPlace;
use crate::sea::waves::WaveComponent;
use num_complex::Complex64 as C;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

/// Streams of the Gaussian sea's extra draws, apart from the sampler's (frequencies, directions,
/// phases): the Rayleigh factors, and the crossing speed.
const RAYLEIGH_STREAM: u64 = 0x0005_EA0F_6A05;
const CROSSING_STREAM: u64 = 0x0005_EA0F_C205;

/// Farthest level from the calm hub depth a sea is conditioned on [standard deviations].
pub const MAX_SIGMAS: f64 = 8.0;

/// The thesis' sea (amplitudes sqrt(2 S d omega), uniform phases) made Gaussian: each amplitude
/// times sqrt(-ln U), U uniform from its own stream of `seed` (|c|^2 / a^2 is then exponential
/// of mean 1, and c Gaussian of variance a^2 / 2 per part).
pub fn make_gaussian(components: &mut [WaveComponent], seed: u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ RAYLEIGH_STREAM);
    for c in components {
        let u: f64 = 1.0 - rng.random::<f64>(); // in (0, 1]
        c.amplitude *= libm::sqrt(-libm::log(u));
    }
}

/// What conditioning a sea gives besides its components.
#[derive(Debug, Clone, PartialEq)]
pub struct Conditioned {
    pub components: Vec<WaveComponent>,
    /// This sea's hub process: variance [m^2] and rate variance [m^2/s^2] (the discrete sum of
    /// this seed's components), and its rate of crossings of the level [1/s] (Rice for this
    /// seed's spectrum: the weight of the trial among seeds, whose spectra differ a little).
    pub m0: f64,
    pub m2: f64,
    pub crossing_rate_per_s: f64,
    /// The level of the hub's depth swing r = h - h0 \[m\] and the rate imposed at the event [m/s].
    pub level_m: f64,
    pub rate_m_s: f64,
}

/// The sea of `components` (Gaussian, of the scenario's seed) conditioned as `sc.rare_event` says.
/// `nominal` are the components' amplitudes before the Rayleigh factors (sqrt(2 S d omega)).
pub fn condition(sc: &Scenario, components: &[WaveComponent], nominal: &[f64]) -> Result<Conditioned, String> {
    let ev = &sc.rare_event;
    let hull = sc.ship_hull()?;
    let table = sc.rao_table()?;
    let k = &sc.seakeeping;
    let s = ev.shaft.index();
    let at = HubPlace { x_aft: hull.prop_x_aft_m, y: hull.shaft_y_m[s] };
    let ordered = sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(0.0);
    let u = crate::numerics::units::kn_to_m_s(if ev.ship_speed_kn > 0.0 { ev.ship_speed_kn } else { ordered });
    let t0 = ev.time_s;
    let psi = ev.ship_heading_deg.to_radians();
    let (x0, y0) = if ev.ship_x_m != 0.0 {
        (ev.ship_x_m, ev.ship_y_m)
    } else {
        let run = crate::numerics::units::kn_to_m_s(ordered) * t0;
        (run * libm::cos(psi), run * libm::sin(psi))
    };
    let radius = 0.5 * sc.propeller.diameter_m;
    let level = ev.level_h_over_r * radius - hull.hub_depth_m;
    // Per component: variance of each part, and d r / d(A, B), d r' / d(A, B) at t0.
    let n = components.len();
    let (mut var, mut ua, mut ub, mut wa, mut wb) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut m0, mut m2, mut r0, mut r1) = (0.0, 0.0, 0.0, 0.0);
    for (i, c) in components.iter().enumerate() {
        let beta = psi - c.direction;
        let (cb, sb) = (libm::cos(beta), libm::sin(beta));
        let rao = table.interpolate(c.omega, u, beta);
        let h =
            k.stern_motion.hub_transfer(k.stern_motion.hub_wave(c.k, at, cb, sb), rao.heave, rao.roll, rao.pitch, at);
        let theta = c.omega * t0 - c.k * (x0 * libm::cos(c.direction) + y0 * libm::sin(c.direction));
        let p = h * C::new(libm::cos(theta), libm::sin(theta));
        let we = c.omega - c.k * u * cb;
        var[i] = 0.5 * nominal[i] * nominal[i];
        (ua[i], ub[i], wa[i], wb[i]) = (p.re, -p.im, -we * p.im, -we * p.re);
        m0 += var[i] * p.norm_sqr();
        m2 += var[i] * we * we * p.norm_sqr();
        let (a, b) = (c.amplitude * libm::cos(c.phase), c.amplitude * libm::sin(c.phase));
        r0 += a * ua[i] + b * ub[i];
        r1 += a * wa[i] + b * wb[i];
    }
    if !(m0 > 0.0 && m2 > 0.0) {
        return Err(
            "rare_event: the hub does not move in this sea (no wave reaches it): nothing to condition on".into()
        );
    }
    // Beyond a few standard deviations the sea would need waves no linear model holds, and the
    // event's rate underflows.
    let sigmas = level.abs() / libm::sqrt(m0);
    if sigmas > MAX_SIGMAS {
        return Err(format!(
            "rare_event.level_h_over_r = {}: the level is {sigmas:.1} standard deviations of the hub's depth swing ({:.2} m) from its calm depth; at most {MAX_SIGMAS}",
            crate::checks::num(ev.level_h_over_r),
            libm::sqrt(m0)
        ));
    }
    let (rate, random) = match ev.shape {
        Shape::Sampled => {
            let mut rng = ChaCha8Rng::seed_from_u64(sc.sim.seed ^ CROSSING_STREAM);
            let v: f64 = 1.0 - rng.random::<f64>();
            // A down-crossing of the depth (the hub rising towards the surface): r' < 0.
            (-libm::sqrt(m2) * libm::sqrt(-2.0 * libm::log(v)), true)
        }
        Shape::MostLikely => (0.0, false),
    };
    let (r0, r1) = if random { (r0, r1) } else { (0.0, 0.0) };
    let (fa, fb) = ((level - r0) / m0, (rate - r1) / m2);
    let out = components
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let (a0, b0) =
                if random { (c.amplitude * libm::cos(c.phase), c.amplitude * libm::sin(c.phase)) } else { (0.0, 0.0) };
            let a = a0 + var[i] * (ua[i] * fa + wa[i] * fb);
            let b = b0 + var[i] * (ub[i] * fa + wb[i] * fb);
            WaveComponent { amplitude: libm::sqrt(a * a + b * b), phase: libm::atan2(b, a), ..*c }
        })
        .collect();
    let crossing_rate_per_s = libm::sqrt(m2 / m0) / (2.0 * PI) * libm::exp(-level * level / (2.0 * m0));
    Ok(Conditioned { components: out, m0, m2, crossing_rate_per_s, level_m: level, rate_m_s: rate })
}
