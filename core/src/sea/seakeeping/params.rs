//! The scenario's seakeeping section: the RAO grid, the propeller hub's place, the surface-loss
//! model's parameters and the multi-rate sampling of the seaway.

use crate::checks::Validator;
use crate::plant::propeller_losses::LossParams;
use num_complex::Complex64 as C;
use serde::{Deserialize, Serialize};

/// Declared beside the reflection force it chooses (`reflection`), which `motions` uses without
/// this section.
pub use crate::sea::seakeeping::reflection::ShortWaveForce;

crate::params! {
    /// Ship motions in waves and propeller surface losses (ch. 2.3, 2.5.4). The hull, its loading
    /// and the propellers' place are the ship's (`ship.hull`). The surface-loss model owns its
    /// defaults (ch. 2.3); this section only carries them.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SeakeepingParams {
        pub grid: crate::sea::seakeeping::tables::SeakeepingGrid = Default::default() => {},
        /// Salvesen-Tuck-Faltinsen (1970) as printed keeps the terms of the aft end (superscript
        /// A: the aftmost strip with beam) in every coefficient and exciting force at speed, e.g.
        /// U a22^A, U a24^A and U a44^A in B22, B24 and B44 (Appendix A eqs. 13, 14, 18). A hull
        /// ending in a deep, thin stern (a Wigley hull) keeps sway and roll added mass there
        /// however small its beam, and these terms add roll damping as speed rises
        /// (`aft_end::aft_end_roll_peaks`). Off: every aft-end term is zero, as in codes that
        /// keep end terms only for a transom. Part of the RAO table's cache key.
        pub aft_end_terms: bool = true => {
            label: "Strip theory's aft-end terms",
            source: "STF (1970) as printed: on",
            help: "STF's terms of the aft end at speed (U a44^A in B44 and the rest), which add roll damping as speed rises. Off drops them, as codes that keep end terms only for a transom do (a Wigley hull has none).",
        },
        /// The second-order mean force's short-wave part: the waves the waterline reflects
        /// (`reflection`, the default) or eq. 2.48's F7 (Salvesen 1978), which the thesis' ch. 5
        /// rows keep. Part of the RAO table's cache key.
        pub short_wave_force: ShortWaveForce = ShortWaveForce::Reflection => {
            label: "Short-wave mean force",
            source: "Faltinsen et al. (1980) with Fujii-Takahashi's draft factor; eq. 2.48 as the thesis' option",
            help: "Reflection: only the part of the waterline the waves meet reflects them, by the angle it meets them at. F7 (eq. 2.48) integrates the sections' damping over the whole hull and, in following seas, pushes a slow ship on with several times the force a wall as wide as the ship would feel.",
        },
        /// See `propeller_losses` for why 1.1 starts and 1.3 ends the loop.
        pub ventilation_on_h_over_r: f64 = LossParams::default().ventilation_on => {
            label: "Ventilation starts below h/R", unit: "-", range: -1.0..=5.0, source: "ch. 2.3",
            help: "The propeller draws air when its hub depth over radius falls below this.",
        },
        pub ventilation_off_h_over_r: f64 = LossParams::default().ventilation_off => {
            label: "Ventilation ends above h/R", unit: "-", range: -1.0..=5.0, source: "ch. 2.3",
            help: "...and stops drawing air above this (a hysteresis loop).",
        },
        pub ventilation_loss: f64 = LossParams::default().ventilation_loss => {
            label: "Thrust lost when ventilated", unit: "-", range: 0.0..=1.0, source: "ch. 2.3: 0.7",
            help: "Share of thrust lost when the propeller is fully ventilated.",
        },
        pub recovery_revolutions: f64 = LossParams::default().recovery_revolutions => {
            label: "Revolutions to recover lift", unit: "-", range: 0.01..=100.0, source: "ch. 2.3: about 4 (Wagner effect)",
            help: "Revolutions over which the lift returns after ventilation.",
        },
        pub torque_exponent: f64 = LossParams::default().torque_exponent => {
            label: "Torque loss exponent m", unit: "-", range: 0.1..=2.0, source: "ch. 2.3: 0.85",
            help: "beta_Q = beta_T^m.",
        },
        /// Generic: the two numbers above. Derived (`propeller.model = "geometry"` only): the loop
        /// starts where the blades' own cavitation at 12 o'clock, at the run's calm-water point,
        /// says a low-pressure region reaches the surface, between h/R 1 (the tips at the surface)
        /// and `ventilation_on_h_over_r`; the band is kept. Why not the cavitation depth itself:
        /// `propeller_losses::VentilationOnset`.
        pub ventilation_onset: crate::plant::propeller_losses::VentilationOnset = Default::default() => {
            label: "Ventilation onset", source: "ch. 2.3 (generic); ch. 3.2.2 and our criterion (derived, docs/cavitation.md)",
            help: "Generic: the h/R above. Derived (propeller.model = geometry): from the blades' cavitation at 12 o'clock at the run's speed, between 1 (tips at the surface) and the generic onset.",
        },
        /// Quasi-steady speed and heading, ch. 2.5.4.
        pub rao_refresh_s: f64 = 0.25 => {
            label: "RAO look-up interval", unit: "s", range: 1.0e-5..=10.0, source: "our choice (tests/multirate.rs)",
            help: "RAOs are looked up again at the ship's speed and heading this often; a whole number of time steps, at least the sea sample period.",
        },
        /// A due look-up is skipped while the ship's speed through the water and its heading are
        /// both within these of the last look-up's: it would give nearly the same values (the
        /// table's grid steps are 2.6 m/s and 15 deg). Chosen by measurement (tests/multirate.rs,
        /// `skipped_rao_look_ups_change_little`): with 0.02 m/s and 0.01 deg the propeller speed
        /// moves no more than the 0.25 s look-up interval itself moves it (against a look-up at
        /// every sample; in head seas 0.078 against 0.079 rpm), and the other traces by at most
        /// twice as much (the ship speed in head seas); 0.1 deg moved a quarter turn in SS6 by 0.18
        /// rpm, ten times more. Either at 0 looks up every `rao_refresh_s`, and so does eqs.
        /// 2.55/2.59 as printed (`as_printed.doppler_twice`), whose extra phase would drift with a
        /// stale speed. Head seas at 25 kn: 109 of 320 look-ups (issue 17).
        pub rao_refresh_speed_m_s: f64 = 0.02 => {
            label: "RAO look-up: speed change", unit: "m/s", range: 0.0..=1.0,
            source: "our choice, measured (tests/multirate.rs)",
            help: "A due look-up is skipped while speed and heading changed less than these; 0: never skip.",
        },
        pub rao_refresh_heading_deg: f64 = 0.01 => {
            label: "RAO look-up: heading change", unit: "deg", range: 0.0..=1.0,
            source: "our choice, measured (tests/multirate.rs)",
            help: "See the speed change; 0: never skip.",
        },
        pub second_order_forces: bool = true => {
            label: "Second-order wave forces", source: "eq. 2.60",
            help: "Slowly varying added resistance and drift force in the maneuvering equations.",
        },
        pub surface_losses: bool = true => {
            label: "Propeller surface losses", source: "ch. 2.3",
            help: "Off gives the fully submerged counterpart of a run.",
        },
        pub stern_motion: SternMotion = SternMotion::Consistent => {
            label: "Hub depth formula", group: "sea",
            source: "our choice: the sign consistent with the pitch convention (eq. 2.57 printed otherwise)",
            help: "Consistent: the stern rises with long waves, so the hub depth swings less than the wave. As printed, eq. 2.57 adds the stern motion with the opposite sign: the depth swings by wave plus motion, and surface effects come far more often (the thesis figures).",
        },
        /// Scaled by the part-load curve of `core/data/gas_turbine_part_load.csv`.
        pub turbine_rated_efficiency: f64 = 0.37 => {
            label: "Turbine efficiency at rating", unit: "-", range: 0.05..=0.8, source: "ch. 5.1: about 37 %",
            help: "Thermal efficiency at rated power, for the fuel power (part-load curve beneath).",
        },
    }
}

impl crate::params::CrossCheck for SeakeepingParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.ventilation_off_h_over_r < self.ventilation_on_h_over_r {
            v.fail(
                "ventilation_off_h_over_r",
                crate::checks::num(self.ventilation_off_h_over_r),
                format!("must be at least {}", v.path("ventilation_on_h_over_r")),
            );
        }
    }
}

crate::choices! {
    /// How the stern's vertical motion enters the hub depth (eq. 2.57).
    pub enum SternMotion {
        /// h = h0 + eta_s - eta3 - x_p eta5 with STF's bow-down pitch: the stern rises by
        /// eta3 + x_p eta5, and a hull that follows long waves keeps its propeller at h0.
        Consistent = "consistent", "consistent (stern follows long waves)",
        /// Eq. 2.57 as printed, h0 + eta_s - eta3 + x_p eta5: pitch adds to the stern's relative
        /// motion instead of following the wave. Several times larger swings of h/R; with it the
        /// ch. 5.3 runs show the thesis' frequent ventilation at h0 = 6 m.
        ThesisEq257 = "thesis_eq_2_57", "as printed in eq. 2.57",
    }
}

/// Where a propeller hub is: `x_aft` \[m\] aft of the centre of gravity, `y` \[m\] to port of the
/// centreline (STF axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HubPlace {
    pub x_aft: f64,
    pub y: f64,
}

impl SternMotion {
    /// Eq. 2.57 in the frequency domain, generalised to a hub off the centreline: the hub depth's
    /// transfer function per unit wave amplitude, from the wave at the hub `wave` (`hub_wave`),
    /// heave `heave` [m/m], roll `roll` (STF: port side up) and pitch `pitch` [rad/m] (STF: bow
    /// down). The simulator's seaway and the Rice prediction of the Monte Carlo studies both use
    /// this one.
    pub fn hub_transfer(self, wave: C, heave: C, roll: C, pitch: C, at: HubPlace) -> C {
        match self {
            // The hub rises by eta3 + y eta4 + x_p eta5 (small rotations about G), so its depth is
            // h0 + eta_s - eta3 - y eta4 - x_p eta5: a hull following long waves keeps its depth,
            // and in oblique seas the two shafts of a twin-screw ship differ by 2 y eta4 and by
            // the wave's phase across the beam.
            SternMotion::Consistent => wave - heave - roll * at.y - pitch * at.x_aft,
            // Eq. 2.57 as printed, on the centreline: + x_p eta5 and no roll.
            SternMotion::ThesisEq257 => wave - heave + pitch * at.x_aft,
        }
    }

    /// The wave at the hub per unit wave at the centre of gravity, for wave number `k` [1/m] and
    /// heading beta given by its cosine and sine (STF: 180 deg head seas, 90 deg waves from
    /// starboard): the phase leads by k (x_p cos beta - y sin beta). Eq. 2.57 as printed takes the
    /// wave on the centreline.
    pub fn hub_wave(self, k: f64, at: HubPlace, cos_beta: f64, sin_beta: f64) -> C {
        let ph = self.hub_phase(k, at, cos_beta, sin_beta);
        C::new(libm::cos(ph), libm::sin(ph))
    }

    /// The phase of `hub_wave` \[rad\].
    pub fn hub_phase(self, k: f64, at: HubPlace, cos_beta: f64, sin_beta: f64) -> f64 {
        let y = match self {
            SternMotion::Consistent => at.y,
            SternMotion::ThesisEq257 => 0.0,
        };
        k * (at.x_aft * cos_beta - y * sin_beta)
    }
}

impl SeakeepingParams {
    /// The propeller surface-loss model's parameters.
    pub fn loss_params(&self) -> LossParams {
        LossParams {
            ventilation_on: self.ventilation_on_h_over_r,
            ventilation_off: self.ventilation_off_h_over_r,
            ventilation_loss: self.ventilation_loss,
            recovery_revolutions: self.recovery_revolutions,
            torque_exponent: self.torque_exponent,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::complex::cabs;
    use crate::sea::seakeeping::motions::response;
    use crate::sea::seakeeping::strip::{default_omega_grid, Ship};

    /// Eq. 2.57 off the centreline: in long waves the ship follows the surface, so each hub keeps
    /// its depth whatever the heading. DTMB 5415 at rest, omega 0.1 rad/s (lambda/L = 43), hubs
    /// 62 m aft and 5 m to either side, headings 90-150 deg. The two hubs' difference,
    /// (wave at port - wave at starboard) - 2 y eta4, holds only the new terms (the wave's phase
    /// across the beam and the roll): measured at most 3.7e-4 m/m, asserted 5e-4; with the roll
    /// term's sign turned it is 1.0e-2 to 2.1e-2 (asserted above 5e-3: a sign error fails). Each
    /// hub alone: measured at most 1.25e-3, asserted 2e-3. (At 0.2 rad/s the roll is already 12 %
    /// above the wave slope, near its resonance, and the difference 5e-3.)
    #[test]
    fn both_hubs_keep_their_depth_in_long_oblique_waves() {
        let ship = Ship::dtmb5415();
        let rad = ship.radiation_table(&default_omega_grid());
        let w = 0.1;
        let k = w * w / crate::sea::waves::G;
        let m = SternMotion::Consistent;
        for beta_deg in [90.0f64, 120.0, 150.0] {
            let beta = beta_deg.to_radians();
            let r = response(&ship, &rad, w, 0.0, beta, 1.0);
            let (cb, sb) = (libm::cos(beta), libm::sin(beta));
            let hub = |y: f64| {
                let at = HubPlace { x_aft: 62.0, y };
                m.hub_transfer(m.hub_wave(k, at, cb, sb), r.heave, r.roll, r.pitch, at)
            };
            let (port, stbd) = (hub(5.0), hub(-5.0));
            let diff = cabs(port - stbd);
            // The same with the roll term's sign turned: what a sign error would give.
            let wrong = cabs(port - stbd + r.roll * 20.0);
            println!("beta {beta_deg}: |port - starboard| {diff:.2e}, with the roll sign turned {wrong:.2e}");
            assert!(diff < 5e-4, "beta {beta_deg}: {diff}");
            assert!(wrong > 10.0 * 5e-4, "beta {beta_deg}: {wrong}");
            assert!(cabs(port) < 2e-3 && cabs(stbd) < 2e-3, "beta {beta_deg}: {} {}", cabs(port), cabs(stbd));
        }
    }
}
