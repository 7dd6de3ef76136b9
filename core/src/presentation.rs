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
    /// Propeller radius R [m] (the disc drawn at the hub depth).
    pub propeller_radius_m: f64,
    /// Propeller hub aft of the centre of gravity [m] (eq. 2.56).
    pub prop_x_aft_m: f64,
    /// When the live views turn a block to its warning colour.
    pub warnings: WarningLevels,
}

/// Levels at which the live drive-train view marks a block (display levels, not model limits:
/// the model runs on past them and says so in the trace).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningLevels {
    /// Turbine overspeed [pu of the governor set point]: an LM2500 trips near 1.1 (the same
    /// figure as `sim::limits`' note); our display level.
    pub turbine_overspeed_pu: f64,
    /// Bus voltage band [pu of the set point]: below the low level the inverters lose torque
    /// ("dynamic saturation", ch. 2.2.3; 0.9 is our display choice); above the high level the
    /// brake chopper starts (`plant.dc_link.brake_on_pu`).
    pub bus_voltage_low_pu: f64,
    pub bus_voltage_high_pu: f64,
    /// Motor power limit [pu of rated]: the slip controller holds the motor to its rating.
    pub motor_power_limit_pu: f64,
}

/// The stern-to-stem side profile and waterline of the seakeeping hull, for drawing: positions
/// forward from the aft perpendicular [m], heights up from the calm waterline [m].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HullProfile {
    pub name: &'static str,
    /// Station positions [m from the AP].
    pub x_m: Vec<f64>,
    /// Lowest point of each station (keel or bottom) and its highest (deck edge) [m, up].
    pub keel_z_m: Vec<f64>,
    pub deck_z_m: Vec<f64>,
    /// Half-breadth at the calm waterline [m] (0 where the station is dry).
    pub waterline_half_breadth_m: Vec<f64>,
    /// Centre of gravity [m from the AP], draft [m], length between perpendiculars [m].
    pub lcg_m: f64,
    pub draft_m: f64,
    pub lpp_m: f64,
}

impl HullProfile {
    /// The hull runs in waves use (the DTMB 5415, until scenarios carry their own hull).
    pub fn of(_sc: &Scenario) -> HullProfile {
        let ship = crate::seakeeping::cache::dtmb5415();
        let offsets = crate::hull_sections::HullOffsets::dtmb5415();
        let t = ship.draft;
        let wl = offsets.sections(t).unwrap_or_default();
        let mut p = HullProfile {
            name: "DTMB 5415",
            x_m: Vec::new(),
            keel_z_m: Vec::new(),
            deck_z_m: Vec::new(),
            waterline_half_breadth_m: Vec::new(),
            lcg_m: ship.lcg,
            draft_m: t,
            lpp_m: ship.lpp,
        };
        for (i, s) in offsets.stations.iter().enumerate() {
            // The hull closes at the last row without breadth below the first with breadth (the
            // keel, or a transom's lower edge); its top is the highest row with breadth.
            let Some(first) = s.half_breadth.iter().position(|&b| b > 0.0) else { continue };
            let Some(top) = s.half_breadth.iter().rposition(|&b| b > 0.0) else { continue };
            let (lo, hi) = (s.z[first.saturating_sub(1)], s.z[top]);
            p.x_m.push(s.x);
            p.keel_z_m.push(lo - t);
            p.deck_z_m.push(hi - t);
            p.waterline_half_breadth_m.push(wl.get(i).map_or(0.0, |sec| 0.5 * sec.beam));
        }
        p
    }
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
            bus_voltage_ref_v: sc.bus_voltage_ref_v(),
            turbine_rated_speed_rpm: sc.plant.turbine.rated_speed_rpm,
            ship_length_m: sc.ship.length_m,
            seakeeping_lpp_m: crate::seakeeping::cache::dtmb5415().lpp,
            gravity_m_s2: crate::waves::G,
            hub_depth_m: k.hub_depth_m,
            propeller_radius_m: 0.5 * sc.propeller.diameter_m,
            prop_x_aft_m: k.prop_x_aft_m,
            warnings: WarningLevels {
                turbine_overspeed_pu: 1.1,
                bus_voltage_low_pu: 0.9,
                bus_voltage_high_pu: sc.plant.dc_link.brake_on_pu,
                motor_power_limit_pu: 1.0,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_profile_spans_the_ship_and_the_waterline_is_between_keel_and_deck() {
        let p = HullProfile::of(&Scenario::default());
        assert!(p.x_m.len() > 20, "{} stations", p.x_m.len());
        assert!(p.x_m[0] < 1.0 && *p.x_m.last().unwrap() > 140.0);
        for i in 0..p.x_m.len() {
            assert!(p.keel_z_m[i] < p.deck_z_m[i]);
            assert!(p.deck_z_m[i] > 0.0, "station at {} m is below the waterline", p.x_m[i]);
        }
        // Midship: the keel at the draft, the beam of the waterline 19.06 m (within the offsets).
        let mid = p.x_m.iter().position(|&x| (x - 71.0).abs() < 4.0).unwrap();
        assert!((p.keel_z_m[mid] + p.draft_m).abs() < 0.05, "{}", p.keel_z_m[mid]);
        assert!((2.0 * p.waterline_half_breadth_m[mid] - 19.06).abs() < 0.5);
    }
}
