//! The scenario's seakeeping section: the RAO grid, the propeller hub's place, the surface-loss
//! model's parameters and the multi-rate sampling of the seaway.

use crate::check_range;
use crate::propeller_losses::LossParams;
use crate::validate::Validator;
use num_complex::Complex64 as C;
use serde::{Deserialize, Serialize};

/// Ship motions in waves and propeller surface losses (ch. 2.3, 2.5.4). The hull, its loading and
/// the propellers' place are the ship's (`ship.hull`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SeakeepingParams {
    /// The RAO table's grid.
    pub grid: crate::seakeeping::tables::SeakeepingGrid,
    /// Ventilation starts below this h/R and ends above `ventilation_off_h_over_r` (ch. 2.3; see
    /// `propeller_losses` for why 1.1 starts and 1.3 ends the loop).
    pub ventilation_on_h_over_r: f64,
    pub ventilation_off_h_over_r: f64,
    /// Thrust lost when fully ventilated [-] (ch. 2.3: 0.7).
    pub ventilation_loss: f64,
    /// Revolutions over which the lift returns (Wagner effect) [-] (ch. 2.3: about 4).
    pub recovery_revolutions: f64,
    /// beta_Q = beta_T^m (ch. 2.3: m = 0.85).
    pub torque_exponent: f64,
    /// Wave kinematics are summed every `sample_period_s` and carried between samples by a
    /// second-order Taylor series; RAOs are looked up again every `rao_refresh_s` (quasi-steady
    /// speed and heading, ch. 2.5.4) [s].
    pub sample_period_s: f64,
    pub rao_refresh_s: f64,
    /// A due look-up is skipped while the ship's speed through the water and its heading are
    /// both within these of the last look-up's: it would give nearly the same values (the
    /// table's grid steps are 3.6 m/s and 15 deg). Chosen by measurement (tests/multirate.rs,
    /// `skipped_rao_look_ups_change_little`): with 0.02 m/s and 0.01 deg the propeller speed
    /// moves less than the 0.25 s look-up interval itself moves it (against a look-up at every
    /// sample), and the other traces about as much; 0.1 deg moved a quarter turn in SS6 by 0.18
    /// rpm, ten times more. Either at 0 looks up every `rao_refresh_s`, and so does eqs.
    /// 2.55/2.59 as printed (`as_printed.doppler_twice`), whose extra phase would drift with a
    /// stale speed. Head seas at 25 kn: 110 of 320 look-ups (issue 17). Speed [m/s].
    pub rao_refresh_speed_m_s: f64,
    /// Heading [deg] (see `rao_refresh_speed_m_s`).
    pub rao_refresh_heading_deg: f64,
    /// Second-order slowly varying forces in the maneuvering equations (eq. 2.60).
    pub second_order_forces: bool,
    /// Propeller surface losses (ch. 2.3); off gives the fully submerged counterpart of a run.
    pub surface_losses: bool,
    /// Sign of the pitch term in the hub depth (eq. 2.57): "consistent" or "thesis_eq_2_57".
    pub stern_motion: SternMotion,
    /// Fuel: turbine thermal efficiency at rated power [-] (ch. 5.1: about 37 %), scaled by the
    /// part-load curve of `core/data/gas_turbine_part_load.csv`.
    pub turbine_rated_efficiency: f64,
}

impl Default for SeakeepingParams {
    fn default() -> Self {
        // The surface-loss model owns its defaults (ch. 2.3); this section only carries them.
        let losses = LossParams::default();
        SeakeepingParams {
            grid: Default::default(),
            ventilation_on_h_over_r: losses.ventilation_on,
            ventilation_off_h_over_r: losses.ventilation_off,
            ventilation_loss: losses.ventilation_loss,
            recovery_revolutions: losses.recovery_revolutions,
            torque_exponent: losses.torque_exponent,
            sample_period_s: 0.05,
            rao_refresh_s: 0.25,
            rao_refresh_speed_m_s: 0.02,
            rao_refresh_heading_deg: 0.01,
            second_order_forces: true,
            surface_losses: true,
            stern_motion: SternMotion::Consistent,
            turbine_rated_efficiency: 0.37,
        }
    }
}

/// How the stern's vertical motion enters the hub depth (eq. 2.57).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SternMotion {
    /// h = h0 + eta_s - eta3 - x_p eta5 with STF's bow-down pitch: the stern rises by
    /// eta3 + x_p eta5, and a hull that follows long waves keeps its propeller at h0.
    Consistent,
    /// Eq. 2.57 as printed, h0 + eta_s - eta3 + x_p eta5: pitch adds to the stern's relative
    /// motion instead of following the wave. Several times larger swings of h/R; with it the
    /// ch. 5.3 runs show the thesis' frequent ventilation at h0 = 6 m.
    #[serde(rename = "thesis_eq_2_57")]
    ThesisEq257,
}

/// Where a propeller hub is: `x_aft` [m] aft of the centre of gravity, `y` [m] to port of the
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

    /// The phase of `hub_wave` [rad].
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

    /// Checks the section for a run with time step `dt_s` [s].
    pub fn validate(&self, v: &mut Validator, dt_s: f64) {
        if let Err(e) = self.grid.validate() {
            // The grid names its own field: "seakeeping.grid.<field> = <value> <message>".
            let (path, rest) = e.split_once(" = ").unwrap_or(("seakeeping.grid", e.as_str()));
            let (value, msg) = rest.split_once(' ').unwrap_or((rest, ""));
            let field = path.strip_prefix("seakeeping.").unwrap_or(path);
            v.fail(field, value, msg);
        }
        check_range!(v, self.ventilation_on_h_over_r, -1.0, 5.0);
        check_range!(v, self.ventilation_off_h_over_r, self.ventilation_on_h_over_r, 5.0);
        check_range!(v, self.ventilation_loss, 0.0, 1.0);
        check_range!(v, self.recovery_revolutions, 0.01, 100.0);
        check_range!(v, self.torque_exponent, 0.1, 2.0);
        check_range!(v, self.sample_period_s, dt_s, 0.5);
        check_range!(v, self.rao_refresh_s, self.sample_period_s, 10.0);
        check_range!(v, self.rao_refresh_speed_m_s, 0.0, 1.0);
        check_range!(v, self.rao_refresh_heading_deg, 0.0, 1.0);
        check_range!(v, self.turbine_rated_efficiency, 0.05, 0.8);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::seakeeping::complex::cabs;
    use crate::seakeeping::strip::{default_omega_grid, response, Ship};

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
        let k = w * w / crate::waves::G;
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
