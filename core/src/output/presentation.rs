//! The levels, ratings and per-unit bases a display of a run needs (the page's bands and reference
//! lines), taken from the scenario and the model so that no front end copies a number.

use crate::plant::propeller_losses::{DISK_AT_SURFACE_H_OVER_R, DISK_OUT_H_OVER_R, HUB_AT_SURFACE_H_OVER_R};
use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::health;
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
    /// Ship length of the maneuvering model \[m\] (the hull's Lpp, or Table 5.5's 180 m with
    /// `as_printed.table_5_ship`).
    pub ship_length_m: f64,
    /// Length between perpendiculars of the hull \[m\] (RAO plots against lambda/L).
    pub seakeeping_lpp_m: f64,
    /// Gravity [m/s^2] of the wave dispersion relation.
    pub gravity_m_s2: f64,
    /// Calm-water hub depth h0 \[m\] and the shafts' offsets to port \[m\].
    pub hub_depth_m: f64,
    pub shaft_y_m: [f64; crate::ship::hull::N_SHAFTS],
    /// Propeller radius R \[m\] (the disc drawn at the hub depth).
    pub propeller_radius_m: f64,
    /// Propeller hub aft of the centre of gravity \[m\] (eq. 2.56).
    pub prop_x_aft_m: f64,
    /// When the live views turn a block to its warning colour.
    pub warnings: WarningLevels,
    /// What 1 pu is for every per-unit trace column, in this scenario.
    pub pu_bases: Vec<PuBase>,
}

/// The base of a per-unit signal: `signal` is `value` `unit` per unit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PuBase {
    pub signal: &'static str,
    pub value: f64,
    pub unit: &'static str,
}

/// Levels at which the live drive-train view marks a block: the health checks' thresholds
/// (`sim::health`, where each is declared with its reason), drawn instant by instant; the
/// summary's warnings add how long a level was passed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningLevels {
    /// Turbine speed below which a set is stalled [pu of the governor set point].
    pub turbine_min_running_pu: f64,
    /// Turbine overspeed [pu of the governor set point].
    pub turbine_overspeed_pu: f64,
    /// Bus voltage band [pu of the set point]: below the low level the inverters lose torque,
    /// above the high level the brake chopper is not holding the bus.
    pub bus_voltage_low_pu: f64,
    pub bus_voltage_high_pu: f64,
    /// Motor power limit [pu of rated]: the slip controller holds the motor to its rating.
    pub motor_power_limit_pu: f64,
}

/// The stern-to-stem side profile and waterline of the seakeeping hull, for drawing: positions
/// forward from the aft perpendicular \[m\], heights up from the calm waterline \[m\].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HullProfile {
    pub name: String,
    /// Station positions [m from the AP].
    pub x_m: Vec<f64>,
    /// Lowest point of each station (keel or bottom) and its highest (deck edge) [m, up].
    pub keel_z_m: Vec<f64>,
    pub deck_z_m: Vec<f64>,
    /// Half-breadth at the calm waterline \[m\] (0 where the station is dry).
    pub waterline_half_breadth_m: Vec<f64>,
    /// Centre of gravity [m from the AP], draft \[m\], length between perpendiculars \[m\].
    pub lcg_m: f64,
    pub draft_m: f64,
    pub lpp_m: f64,
}

impl HullProfile {
    /// The scenario's hull (`ship.hull`).
    pub fn of(sc: &Scenario) -> Result<HullProfile, String> {
        let hull = sc.ship_hull()?;
        let offsets = &hull.offsets;
        let t = hull.draft_m;
        let wl = offsets.sections(t).unwrap_or_default();
        let mut p = HullProfile {
            name: match hull.name.as_str() {
                "dtmb5415" => "DTMB 5415".into(),
                "wigley" => "Wigley".into(),
                _ => "custom hull".into(),
            },
            x_m: Vec::new(),
            keel_z_m: Vec::new(),
            deck_z_m: Vec::new(),
            waterline_half_breadth_m: Vec::new(),
            lcg_m: hull.lcg_m,
            draft_m: t,
            lpp_m: hull.lpp_m,
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
        Ok(p)
    }
}

/// The hull panel of the page: the body plan, the appendages and the hydrostatics of the
/// scenario's hull at its loading (positions from the AP and the baseline, metres).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HullSheet {
    pub profile: HullProfile,
    /// Every station's offsets: x from the AP, (z above the baseline, half-breadth) rows.
    pub stations: Vec<StationOffsets>,
    /// Waterline above the baseline \[m\], beam at it \[m\], displaced volume [m^3] and mass \[kg\].
    pub draft_m: f64,
    pub beam_m: f64,
    pub volume_m3: f64,
    pub mass_kg: f64,
    /// Centre of buoyancy forward of the AP \[m\] and above the baseline \[m\]; transverse and
    /// longitudinal metacentric radii \[m\]; centre of gravity above the baseline \[m\]; metacentric
    /// heights \[m\]; waterplane area [m^2].
    pub lcb_m: f64,
    pub kb_m: f64,
    pub bm_t_m: f64,
    pub bm_l_m: f64,
    pub kg_m: f64,
    pub gm_t_m: f64,
    pub gm_l_m: f64,
    pub awp_m2: f64,
    /// Radii of gyration \[m\] and bilge keels (length, breadth \[m\]; none: null).
    pub k_m: [f64; 3],
    pub bilge_keels_m: Option<[f64; 2]>,
    /// Propeller hubs: x from the AP, shafts' offsets to port, height above the baseline,
    /// calm-water depth h0 \[m\]; the propeller's diameter \[m\]; the rudder's x from the AP \[m\].
    pub propeller_x_m: f64,
    pub shaft_y_m: [f64; crate::ship::hull::N_SHAFTS],
    pub hub_above_base_m: f64,
    pub hub_depth_m: f64,
    pub propeller_diameter_m: f64,
    pub rudder_x_m: f64,
    /// Stations strip theory takes only approximately (x from the AP \[m\], why).
    pub approximated_stations: Vec<(f64, String)>,
}

/// One station of the body plan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StationOffsets {
    pub x_m: f64,
    pub z_m: Vec<f64>,
    pub half_breadth_m: Vec<f64>,
}

impl HullSheet {
    pub fn of(sc: &Scenario) -> Result<HullSheet, String> {
        let h = sc.ship_hull()?;
        let hs = &h.hydrostatics;
        let mp = &h.mass_props;
        Ok(HullSheet {
            profile: HullProfile::of(sc)?,
            stations: h
                .offsets
                .stations
                .iter()
                .map(|s| StationOffsets { x_m: s.x, z_m: s.z.clone(), half_breadth_m: s.half_breadth.clone() })
                .collect(),
            draft_m: h.draft_m,
            beam_m: h.beam_m,
            volume_m3: hs.volume,
            mass_kg: h.mass_kg,
            lcb_m: hs.lcb,
            kb_m: hs.kb,
            bm_t_m: hs.bmt,
            bm_l_m: hs.bml,
            kg_m: mp.kg_m,
            gm_t_m: hs.kb + hs.bmt - mp.kg_m,
            gm_l_m: hs.kb + hs.bml - mp.kg_m,
            awp_m2: hs.awp,
            k_m: [mp.kxx_m, mp.kyy_m, mp.kzz_m],
            bilge_keels_m: h.bilge_keels.map(|b| [b.length_m, b.breadth_m]),
            propeller_x_m: h.lcg_m - h.prop_x_aft_m,
            shaft_y_m: h.shaft_y_m,
            hub_above_base_m: h.draft_m - h.hub_depth_m,
            hub_depth_m: h.hub_depth_m,
            propeller_diameter_m: sc.propeller.diameter_m,
            rudder_x_m: h.lcg_m - h.rudder_x_aft_m,
            approximated_stations: h.strip_ship()?.approximated,
        })
    }
}

impl PageConstants {
    pub fn of(sc: &Scenario) -> Result<PageConstants, String> {
        let k = &sc.seakeeping;
        let hull = sc.ship_hull()?;
        Ok(PageConstants {
            h_over_r_bands: vec![Band {
                from: k.ventilation_on_h_over_r,
                to: k.ventilation_off_h_over_r,
                label: format!(
                    "ventilation: starts below {}, ends above {}",
                    k.ventilation_on_h_over_r, k.ventilation_off_h_over_r
                ),
            }],
            h_over_r_levels: vec![
                Level { value: DISK_AT_SURFACE_H_OVER_R, label: "disc reaches the surface".into() },
                Level { value: HUB_AT_SURFACE_H_OVER_R, label: "hub at the surface".into() },
                Level { value: DISK_OUT_H_OVER_R, label: "disc out of the water".into() },
            ],
            motor_rated_power_w: sc.plant.motor.rated_power_w,
            bus_voltage_ref_v: sc.bus_voltage_ref_v(),
            turbine_rated_speed_rpm: sc.plant.turbine.rated_speed_rpm,
            ship_length_m: hull.rigid_body(&sc.as_printed).length_m,
            seakeeping_lpp_m: hull.lpp_m,
            gravity_m_s2: crate::sea::waves::G,
            hub_depth_m: hull.hub_depth_m,
            shaft_y_m: hull.shaft_y_m,
            propeller_radius_m: 0.5 * sc.propeller.diameter_m,
            prop_x_aft_m: hull.prop_x_aft_m,
            warnings: WarningLevels {
                turbine_min_running_pu: health::TURBINE_MIN_RUNNING_PU,
                turbine_overspeed_pu: health::TURBINE_OVERSPEED_PU,
                bus_voltage_low_pu: health::BUS_LOW_PU,
                bus_voltage_high_pu: health::bus_high_pu(sc),
                motor_power_limit_pu: 1.0,
            },
            pu_bases: vec![
                PuBase { signal: Signal::TurbineSpeedPu.name(), value: sc.plant.turbine.rated_speed_rpm, unit: "rpm" },
                PuBase { signal: Signal::BusVoltagePu.name(), value: sc.bus_voltage_ref_v(), unit: "V" },
                PuBase {
                    signal: Signal::MotorVoltagePu.name(),
                    value: crate::plant::motor::InductionMotor::new(&sc.plant.motor).v_rated,
                    unit: "V",
                },
                PuBase { signal: Signal::ImPowerPu.name(), value: sc.plant.motor.rated_power_w, unit: "W" },
                PuBase { signal: Signal::FilterVoltagePu.name(), value: sc.bus_voltage_ref_v(), unit: "V" },
                PuBase { signal: Signal::FilterRipplePu.name(), value: sc.bus_voltage_ref_v(), unit: "V" },
            ],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every per-unit trace column has its base, and only those.
    #[test]
    fn every_per_unit_signal_has_a_base() {
        let c = PageConstants::of(&Scenario::default()).unwrap();
        let pu: Vec<&str> = crate::signals::SIGNALS.iter().filter(|s| s.unit == "pu").map(|s| s.name).collect();
        let based: Vec<&str> = c.pu_bases.iter().map(|b| b.signal).collect();
        assert_eq!(pu, based);
        // The motor's rated phase voltage: 4160 V line to line (Table 2.1).
        assert!((c.pu_bases[2].value - 4160.0 / 3f64.sqrt()).abs() < 1e-9);
    }

    #[test]
    fn the_hull_profile_spans_the_ship_and_the_waterline_is_between_keel_and_deck() {
        let p = HullProfile::of(&Scenario::default()).unwrap();
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
