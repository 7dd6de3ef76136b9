//! Unit conversions. Everything inside the physics is SI; knots, rpm and degrees
//! appear only at the edges (scenario files, traces, summaries).

use std::f64::consts::PI;

/// One international knot in m/s.
pub const KNOT_M_S: f64 = 1852.0 / 3600.0;

/// Knots to metres per second.
pub fn kn_to_m_s(kn: f64) -> f64 {
    kn * KNOT_M_S
}

/// Metres per second to knots.
pub fn m_s_to_kn(v: f64) -> f64 {
    v / KNOT_M_S
}

/// Revolutions per minute to rad/s.
pub fn rpm_to_rad_s(rpm: f64) -> f64 {
    rpm * 2.0 * PI / 60.0
}

/// rad/s to revolutions per minute.
pub fn rad_s_to_rpm(w: f64) -> f64 {
    w * 60.0 / (2.0 * PI)
}

/// Degrees to radians.
pub fn deg_to_rad(d: f64) -> f64 {
    d * PI / 180.0
}

/// Radians to degrees.
pub fn rad_to_deg(r: f64) -> f64 {
    r * 180.0 / PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips() {
        assert!((m_s_to_kn(kn_to_m_s(25.0)) - 25.0).abs() < 1e-12);
        assert!((rad_s_to_rpm(rpm_to_rad_s(3600.0)) - 3600.0).abs() < 1e-9);
        // 60 Hz = 3600 rpm = 376.99 rad/s.
        assert!((rpm_to_rad_s(3600.0) - 120.0 * PI).abs() < 1e-9);
        assert!((kn_to_m_s(25.0) - 12.8611).abs() < 1e-4);
        assert!((rad_to_deg(deg_to_rad(45.0)) - 45.0).abs() < 1e-12);
    }
}
