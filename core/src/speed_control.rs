//! The ship-speed loop (ours; the thesis orders shaft speed directly): a calm-water map from
//! ordered ship speed to shaft speed, trimmed by a PI on the speed error, then a ramp limit.

use crate::check_range;
use crate::validate::Validator;
use serde::{Deserialize, Serialize};
/// Outer ship-speed loop: a calm-water rpm map trimmed by a PI on ship speed error.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SpeedControlParams {
    /// Proportional trim [rpm per knot of ship speed error]. Our design; 4. The calm-water map has
    /// about 8 rpm per knot, so the loop gain is 0.5 and the 30 s surge lag closes near 20 s.
    pub kp_rpm_per_kn: f64,
    /// Integral trim [rpm per knot second]. Our design; 0.2 (a 40 s integral time: it removes the
    /// steady error that waves, turns or fouling leave on the calm-water map).
    pub ki_rpm_per_kn_s: f64,
    /// Largest trim as a fraction of the mapped shaft speed [-]. Our design; 0.4 (a tight turn at
    /// 25 knots needs about a quarter more shaft speed than the straight-line map).
    pub trim_limit: f64,
    /// Rate limit of the shaft speed reference [rpm/s]. Our design; 5 rpm/s keeps the turbines'
    /// load rise within their slew limit. 0 means no limit (a true step command).
    pub shaft_ramp_rpm_per_s: f64,
    /// Largest shaft speed reference [rpm]. Our design; 320 (the motor is rated near 300 rpm and
    /// ch. 5.2.1 shows it overrunning that at full ahead).
    pub max_shaft_rpm: f64,
}

impl Default for SpeedControlParams {
    fn default() -> Self {
        SpeedControlParams {
            kp_rpm_per_kn: 4.0,
            ki_rpm_per_kn_s: 0.2,
            trim_limit: 0.4,
            shaft_ramp_rpm_per_s: 5.0,
            max_shaft_rpm: 320.0,
        }
    }
}

impl SpeedControlParams {
    pub fn validate(&self, v: &mut Validator) {
        check_range!(v, self.kp_rpm_per_kn, 0.0, 100.0);
        check_range!(v, self.ki_rpm_per_kn_s, 0.0, 100.0);
        check_range!(v, self.trim_limit, 0.0, 1.0);
        check_range!(v, self.shaft_ramp_rpm_per_s, 0.0, 1.0e4);
        check_range!(v, self.max_shaft_rpm, 1.0, 2000.0);
    }
}
