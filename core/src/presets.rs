//! Named scenarios, one per study of thesis ch. 5 as they are implemented.

use crate::scenario::{Command, Scenario};

/// Names of all presets, in the order of the thesis.
pub const PRESET_NAMES: &[&str] = &["startup"];

/// The preset of that name.
pub fn preset(name: &str) -> Option<Scenario> {
    match name {
        "startup" => Some(startup()),
        _ => None,
    }
}

/// Ch. 5.1: idle to 25 knots in calm water with the surge model (Figs. 5-1, 5-2, Tables 5.6-5.7).
pub fn startup() -> Scenario {
    let mut s = Scenario {
        name: "startup".into(),
        description: "Start-up from idle to 25 knots in calm water (thesis ch. 5.1, Figs. 5-1 and 5-2): \
                      power flows turbine -> generator -> inverter -> motor -> ship, each stage losing a little."
            .into(),
        commands: vec![Command { t_s: 0.0, speed_kn: Some(25.0), heading_deg: None, heading_rate_deg_s: None }],
        ..Scenario::default()
    };
    s.sim.duration_s = 400.0;
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_is_valid() {
        for n in PRESET_NAMES {
            let s = preset(n).unwrap();
            s.validate().unwrap();
            assert_eq!(&s.name, n);
        }
        assert!(preset("nope").is_none());
    }
}
