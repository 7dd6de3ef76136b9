//! The scenario's `operability` section: where on the ship motions are judged (points), the
//! seakeeping criteria with their published sources, and the bow's geometry for slamming and
//! deck wetness. The study that evaluates them over speed x heading x sea is
//! `studies::operability`.

use crate::checks::Validator;
use serde::{Deserialize, Serialize};

/// Most points and criteria a scenario may list (a polar evaluates every criterion in every
/// cell: a longer list is no design question, only work).
pub const MAX_POINTS: usize = 20;
pub const MAX_CRITERIA: usize = 50;

crate::choices! {
    /// What a criterion limits. Accelerations are RMS values in units of g (9.81 m/s^2); a
    /// probability is per encounter of the relative motion's oscillation (one zero up-crossing);
    /// a rate is per hour.
    pub enum Quantity {
        RollRmsDeg = "roll_rms_deg", "roll, RMS [deg]",
        PitchRmsDeg = "pitch_rms_deg", "pitch, RMS [deg]",
        HeaveRmsM = "heave_rms_m", "heave at the centre of gravity, RMS [m]",
        VerticalAccelerationRmsG = "vertical_acceleration_rms_g", "vertical acceleration at a point, RMS [g]",
        /// Felt lateral acceleration: the point's sideways acceleration plus the gravity
        /// component g sin(roll) that the roll brings into the deck's plane (what a person or a
        /// loose object on deck feels; NORDFORSK's and STANAG 4154's lateral acceleration).
        LateralAccelerationRmsG = "lateral_acceleration_rms_g", "lateral acceleration at a point, RMS [g]",
        VerticalVelocityRmsMS = "vertical_velocity_rms_m_s", "vertical velocity at a point, RMS [m/s]",
        SlammingProbability = "slamming_probability", "slamming, chance per encounter (Ochi)",
        SlamsPerHour = "slams_per_hour", "slams per hour (Ochi)",
        DeckWetnessProbability = "deck_wetness_probability", "deck wetness at the bow, chance per encounter",
        DeckWetnessPerHour = "deck_wetness_per_hour", "deck wetness at the bow, per hour",
        VentilationPerHour = "ventilation_per_hour", "propeller ventilation onsets per hour, worse shaft (Rice)",
        EmergencePerHour = "emergence_per_hour", "propeller emergence (h/R below 1) per hour, worse shaft (Rice)",
    }
}

impl Quantity {
    /// Whether the quantity is taken at one of the section's points.
    pub fn at_point(self) -> bool {
        matches!(
            self,
            Quantity::VerticalAccelerationRmsG | Quantity::LateralAccelerationRmsG | Quantity::VerticalVelocityRmsMS
        )
    }

    /// The JSON name (the unit is its suffix).
    pub fn name(self) -> &'static str {
        let v = serde_json::to_value(self).unwrap_or_default();
        <Self as crate::params::Param>::choices()
            .iter()
            .find(|(n, _)| v.as_str() == Some(n))
            .map(|(n, _)| *n)
            .unwrap_or("")
    }
}

crate::params! {
    /// A place on the ship whose motions a criterion judges (the bridge, the flight deck).
    /// Coordinates in the offsets' frame: forward of the aft perpendicular, to port of the
    /// centreline, above the baseline.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct MotionPoint {
        pub name: String = "bridge".into() => {
            label: "Point name", help: "The name criteria use to refer to this point.",
        },
        pub x_m: f64 = 104.0 => {
            label: "Point: forward of the aft perpendicular", unit: "m", range: -100.0..=1000.0,
            help: "Longitudinal place of the point.",
        },
        pub y_m: f64 = 0.0 => {
            label: "Point: to port of the centreline", unit: "m", range: -100.0..=100.0,
            help: "Transverse place of the point (negative: to starboard).",
        },
        pub z_m: f64 = 20.0 => {
            label: "Point: above the baseline", unit: "m", range: -50.0..=100.0,
            help: "Height of the point.",
        },
    }
}

crate::params! {
    /// One seakeeping criterion: a quantity and its highest acceptable value.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct Criterion {
        pub quantity: Quantity = Quantity::RollRmsDeg => {
            label: "Criterion: quantity", help: "What the criterion limits (its unit is the name's suffix).",
        },
        pub point: String = String::new() => {
            label: "Criterion: at point",
            help: "For accelerations and velocities: the name of one of operability.points; empty for the others.",
        },
        pub limit: f64 = 4.0 => {
            label: "Criterion: limit", unit: "(the quantity's)", range: 1.0e-9..=1.0e6,
            help: "Highest acceptable value, in the quantity's unit.",
        },
        pub source: String = String::new() => {
            label: "Criterion: source", help: "Where the limit comes from (shown beside it).",
        },
    }
}

/// The bow, the bridge and the flight deck of a DDG-51-like destroyer on the DTMB 5415 hull
/// (our estimate from the class's arrangement: the bridge about 0.27 Lpp aft of the FP and 20 m
/// above the keel, 13.9 m above the design waterline; the flight deck near the transom, 9 m
/// above the keel; the bow at the FP on the forecastle deck). Another hull's user names its own.
pub fn default_points() -> Vec<MotionPoint> {
    vec![
        MotionPoint { name: "bow".into(), x_m: 142.0, y_m: 0.0, z_m: 14.0 },
        MotionPoint { name: "bridge".into(), x_m: 104.0, y_m: 0.0, z_m: 20.0 },
        MotionPoint { name: "flight_deck".into(), x_m: 8.0, y_m: 0.0, z_m: 9.0 },
    ]
}

/// NORDFORSK (1987), "Assessment of ship performance in a seaway", its general operability
/// limiting criteria, column "naval vessels" (RMS values; chances per encounter). Checked in a
/// secondary source only (a university course's reproduction of the table); the primary text was
/// not at hand.
const NORDFORSK: &str = "NORDFORSK (1987), naval vessels (RMS; from a reproduction of its table)";
/// Helicopter operations: pitch 3 deg and vertical velocity 2 m/s at the landing spot as
/// significant single amplitudes (2 x RMS for a narrow-banded Gaussian response), as a Naval
/// Postgraduate School ship-design brief (TSSE 2025) lists "standard design limits for helicopter
/// operations". NATO STANAG 4154's own text was not at hand to check it against.
const HELICOPTER: &str = "helicopter operations: 3 deg and 2 m/s significant amplitude, halved to RMS (NPS TSSE design brief; STANAG 4154 not checked)";

/// A criterion of the default list.
fn criterion(quantity: Quantity, point: &str, limit: f64, source: &str) -> Criterion {
    Criterion { quantity, point: point.into(), limit, source: source.into() }
}

/// The default criteria for a naval combatant, each with its source; the propeller's two are
/// ours (see [`VENTILATION_PER_HOUR`]).
pub fn default_criteria() -> Vec<Criterion> {
    vec![
        criterion(Quantity::RollRmsDeg, "", 4.0, NORDFORSK),
        criterion(Quantity::PitchRmsDeg, "", 1.5, HELICOPTER),
        criterion(Quantity::VerticalAccelerationRmsG, "bow", 0.275, NORDFORSK),
        criterion(Quantity::VerticalAccelerationRmsG, "bridge", 0.2, NORDFORSK),
        criterion(Quantity::LateralAccelerationRmsG, "bridge", 0.1, NORDFORSK),
        criterion(Quantity::VerticalVelocityRmsMS, "flight_deck", 1.0, HELICOPTER),
        criterion(Quantity::SlammingProbability, "", 0.03, NORDFORSK),
        criterion(Quantity::DeckWetnessProbability, "", 0.05, NORDFORSK),
        criterion(Quantity::VentilationPerHour, "", VENTILATION_PER_HOUR, VENTILATION_SOURCE),
        criterion(Quantity::EmergencePerHour, "", EMERGENCE_PER_HOUR, EMERGENCE_SOURCE),
    ]
}

/// Ventilation onsets per hour on the worse shaft that we accept: one every ten minutes. Each
/// onset takes 70 % of the thrust within a fraction of a second and the motor's load with it
/// (ch. 2.3); the plant rides through an isolated one (the head-seas study: the bus stays inside
/// its band), but the gas turbines' speed loop needs about 20 s to settle after a load step
/// (the acceleration study), so events much closer than minutes apart pile transient on
/// transient. No published criterion exists for a shaft-line load swing.
pub const VENTILATION_PER_HOUR: f64 = 6.0;
/// Emergences (h/R below 1: the blade tips in the air at the top of their circle) per hour on
/// the worse shaft: one an hour. An emergence is a full ventilation with racing of the shaft,
/// the event propulsion shaft-line guidance treats as to be avoided in normal service.
pub const EMERGENCE_PER_HOUR: f64 = 1.0;
/// The two propeller criteria's sources as a reader of the polar sees them (the reasons above, in
/// words: no published criterion exists for them).
const VENTILATION_SOURCE: &str = "our choice: one onset every ten minutes on the worse shaft, so that the gas \
     turbines' speed loop (about 20 s to settle after a load step) rides through each; no published criterion \
     exists for a shaft-line load swing";
const EMERGENCE_SOURCE: &str =
    "our choice: one an hour on the worse shaft (the tips in the air, the shaft racing: to be avoided in normal service)";

crate::params! {
    /// Where on the ship the motions are judged, and the criteria (`aes-sim operability`, the
    /// page's Operability tab; a single run ignores it).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct OperabilityParams {
        pub points: Vec<MotionPoint> = default_points() => {
            label: "Points judged", help: "Places on the ship whose accelerations criteria limit.",
        },
        pub criteria: Vec<Criterion> = default_criteria() => {
            label: "Criteria", help: "The seakeeping criteria every cell of the polar is judged by.",
        },
        /// The DTMB 5415 offsets stop 3.1 m above the design waterline (9.2 m above the base),
        /// below the forecastle deck, so they cannot give it.
        pub bow_freeboard_m: f64 = 8.0 => {
            label: "Freeboard at the forward perpendicular", unit: "m", range: 0.1..=50.0,
            source: "our estimate for the DDG-51's forecastle deck over the design waterline",
            help: "Height of the deck edge at the bow above the calm waterline: deck wetness when the relative motion exceeds it.",
        },
        pub slam_station_from_fp: f64 = 0.1 => {
            label: "Slamming station aft of the FP", unit: "-", range: 0.0..=0.5,
            source: "our choice: 10 % of Lpp aft of the FP, where bottom slamming is worst (Ochi's own station not checked)",
            help: "Where slamming is judged, as a share of Lpp aft of the forward perpendicular.",
        },
        pub slam_velocity_coefficient: f64 = 0.093 => {
            label: "Slamming threshold velocity coefficient", unit: "-", range: 0.0..=1.0,
            source: "Ochi (1964): 12 ft/s for a 520 ft ship, Froude-scaled",
            help: "The bow's re-entry must be faster than this times sqrt(g Lpp) to slam.",
        },
        pub spreading_step_deg: f64 = 5.0 => {
            label: "Spreading quadrature step", unit: "deg", range: 1.0..=45.0,
            source: "our choice: the spreading summed over 36 directions",
            help: "Step of the sum over wave directions about the mean heading.",
        },
    }
}

impl crate::params::CrossCheck for MotionPoint {}
impl crate::params::CrossCheck for Criterion {}

impl crate::params::CrossCheck for OperabilityParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.points.len() > MAX_POINTS {
            v.fail("points", self.points.len(), format!("at most {MAX_POINTS} points"));
        }
        if self.criteria.len() > MAX_CRITERIA {
            v.fail("criteria", self.criteria.len(), format!("at most {MAX_CRITERIA} criteria"));
        }
        for (i, p) in self.points.iter().enumerate().take(MAX_POINTS) {
            if p.name.trim().is_empty() {
                v.fail(&format!("points.{i}.name"), "\"\"", "a point needs a name");
            } else if self.points[..i].iter().any(|q| q.name == p.name) {
                v.fail(
                    &format!("points.{i}.name"),
                    format!("\"{}\"", crate::checks::shorten(&p.name)),
                    "names a point twice",
                );
            }
        }
        for (i, c) in self.criteria.iter().enumerate().take(MAX_CRITERIA) {
            let names = || self.points.iter().map(|p| format!("\"{}\"", p.name)).collect::<Vec<_>>().join(", ");
            if c.quantity.at_point() {
                if !self.points.iter().any(|p| p.name == c.point) {
                    v.fail(
                        &format!("criteria.{i}.point"),
                        format!("\"{}\"", crate::checks::shorten(&c.point)),
                        format!("{} is taken at a point: one of {}", c.quantity.name(), names()),
                    );
                }
            } else if !c.point.is_empty() {
                v.fail(
                    &format!("criteria.{i}.point"),
                    format!("\"{}\"", crate::checks::shorten(&c.point)),
                    format!("{} is not taken at a point: leave it empty", c.quantity.name()),
                );
            }
            let probability = matches!(c.quantity, Quantity::SlammingProbability | Quantity::DeckWetnessProbability);
            if probability && c.limit >= 1.0 {
                v.fail(&format!("criteria.{i}.limit"), crate::checks::num(c.limit), "a chance must be below 1");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Section;

    #[test]
    fn the_defaults_pass_and_bad_criteria_name_their_field() {
        let d = OperabilityParams::default();
        let mut v = Validator::new();
        v.section("operability", |v| d.check_fields(v));
        assert!(v.finish().is_ok());
        let mut bad = d.clone();
        bad.criteria[3].point = "mast".into();
        bad.criteria[0].point = "bridge".into();
        bad.criteria[6].limit = 2.0;
        bad.points[2].name = "bridge".into();
        let mut v = Validator::new();
        v.section("operability", |v| bad.check_fields(v));
        let e = v.finish().unwrap_err().to_string();
        for want in [
            "operability.criteria.3.point = \"mast\": vertical_acceleration_rms_g is taken at a point: one of \"bow\", \"bridge\", \"bridge\"",
            "operability.criteria.0.point = \"bridge\": roll_rms_deg is not taken at a point",
            "operability.criteria.6.limit = 2: a chance must be below 1",
            "operability.points.2.name = \"bridge\": names a point twice",
        ] {
            assert!(e.contains(want), "{want}\n in {e}");
        }
    }
}
