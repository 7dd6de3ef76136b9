//! The levels, ratings and per-unit bases a display of a run needs (the page's bands and reference
//! lines), taken from the scenario and the model so that no front end copies a number.

use crate::propeller_losses::{DISK_AT_SURFACE_H_OVER_R, DISK_OUT_H_OVER_R, HUB_AT_SURFACE_H_OVER_R};
use crate::scenario::Scenario;
use serde::Serialize;

/// A horizontal level on a plot of one signal.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Level {
    pub value: f64,
    pub label: String,
}

/// A band between two levels on a plot of one signal.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Band {
    pub from: f64,
    pub to: f64,
    pub label: String,
}

/// What a display needs besides the trace.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PageConstants {
    /// Ventilation hysteresis on h/R (ch. 2.3): starts below `from`, ends above `to`.
    pub h_over_r_bands: Vec<Band>,
    /// Levels of eq. 2.14 on h/R.
    pub h_over_r_levels: Vec<Level>,
    /// Per-unit bases and ratings.
    pub motor_rated_power_w: f64,
    pub bus_voltage_ref_v: f64,
    pub turbine_rated_speed_rpm: f64,
    /// Ship length of the maneuvering model [m].
    pub ship_length_m: f64,
    /// Length between perpendiculars of the seakeeping hull [m] (RAO plots against lambda/L).
    pub seakeeping_lpp_m: f64,
    /// Gravity [m/s^2] of the wave dispersion relation.
    pub gravity_m_s2: f64,
    /// Calm-water hub depth h0 [m].
    pub hub_depth_m: f64,
}

impl PageConstants {
    pub fn of(sc: &Scenario) -> PageConstants {
        let k = &sc.seakeeping;
        PageConstants {
            h_over_r_bands: vec![Band {
                from: k.ventilation_on_h_over_r,
                to: k.ventilation_off_h_over_r,
                label: format!(
                    "ventilation: starts below {}, ends above {}",
                    k.ventilation_on_h_over_r, k.ventilation_off_h_over_r
                ),
            }],
            h_over_r_levels: vec![
                Level { value: DISK_AT_SURFACE_H_OVER_R, label: "disk reaches the surface".into() },
                Level { value: HUB_AT_SURFACE_H_OVER_R, label: "hub at the surface".into() },
                Level { value: DISK_OUT_H_OVER_R, label: "disk out of the water".into() },
            ],
            motor_rated_power_w: sc.plant.motor.rated_power_w,
            bus_voltage_ref_v: sc.controllers.field.bus_voltage_ref_v,
            turbine_rated_speed_rpm: sc.plant.turbine.rated_speed_rpm,
            ship_length_m: sc.ship.length_m,
            seakeeping_lpp_m: crate::seakeeping::cache::dtmb5415().lpp,
            gravity_m_s2: crate::waves::G,
            hub_depth_m: k.hub_depth_m,
        }
    }
}
