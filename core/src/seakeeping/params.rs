//! The scenario's seakeeping section: the RAO grid, the propeller hub's place, the surface-loss
//! model's parameters and the multi-rate sampling of the seaway.

use crate::check_range;
use crate::propeller_losses::LossParams;
use crate::validate::Validator;
use num_complex::Complex64 as C;
use serde::{Deserialize, Serialize};

/// Ship motions in waves and propeller surface losses (ch. 2.3, 2.5.4). The seakeeping hull is the
/// DTMB 5415 at 6.15 m draft (`aes-sim rao` takes other hulls).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SeakeepingParams {
    /// The RAO table's grid.
    pub grid: crate::seakeeping::tables::SeakeepingGrid,
    /// Calm-water depth of the propeller hub below the surface, h0 [m] (ch. 5.3: 6.0).
    pub hub_depth_m: f64,
    /// Propellers' distance aft of the centre of gravity [m]: the 5415's LCG is 70.3 m forward of
    /// the aft perpendicular and a destroyer's propellers sit about 0.06 L forward of it, so 62 m.
    pub prop_x_aft_m: f64,
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
            hub_depth_m: 6.0,
            prop_x_aft_m: 62.0,
            ventilation_on_h_over_r: losses.ventilation_on,
            ventilation_off_h_over_r: losses.ventilation_off,
            ventilation_loss: losses.ventilation_loss,
            recovery_revolutions: losses.recovery_revolutions,
            torque_exponent: losses.torque_exponent,
            sample_period_s: 0.05,
            rao_refresh_s: 0.25,
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

impl SternMotion {
    /// Eq. 2.57 in the frequency domain: the hub depth's transfer function per unit wave
    /// amplitude, from the wave at the stern `stern`, heave `heave` [m/m] and pitch `pitch`
    /// [rad/m] (STF: bow down) with the propeller `x_p` [m] aft of the centre of gravity. The
    /// simulator's seaway and the Rice prediction of the Monte Carlo studies both use this one.
    pub fn hub_transfer(self, stern: C, heave: C, pitch: C, x_p: f64) -> C {
        match self {
            // The stern rises by eta3 + x_p eta5, so the hub's depth is h0 + eta_s - eta3 - x_p eta5
            // (a hull following long waves keeps its depth).
            SternMotion::Consistent => stern - heave - pitch * x_p,
            // Eq. 2.57 as printed: + x_p eta5.
            SternMotion::ThesisEq257 => stern - heave + pitch * x_p,
        }
    }
}

/// The wave at a point `x_p` [m] aft of the centre of gravity per unit wave at the centre, for
/// wave number `k` [1/m] and heading beta given by its cosine `cos_beta` (STF: 180 deg head
/// seas): its phase leads by k x_p cos(beta).
pub fn stern_wave(k: f64, x_p: f64, cos_beta: f64) -> C {
    let ph = k * x_p * cos_beta;
    C::new(libm::cos(ph), libm::sin(ph))
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
        check_range!(v, self.hub_depth_m, 0.0, 50.0);
        check_range!(v, self.prop_x_aft_m, 0.0, 300.0);
        check_range!(v, self.ventilation_on_h_over_r, -1.0, 5.0);
        check_range!(v, self.ventilation_off_h_over_r, self.ventilation_on_h_over_r, 5.0);
        check_range!(v, self.ventilation_loss, 0.0, 1.0);
        check_range!(v, self.recovery_revolutions, 0.01, 100.0);
        check_range!(v, self.torque_exponent, 0.1, 2.0);
        check_range!(v, self.sample_period_s, dt_s, 0.5);
        check_range!(v, self.rao_refresh_s, self.sample_period_s, 10.0);
        check_range!(v, self.turbine_rated_efficiency, 0.05, 0.8);
    }
}
