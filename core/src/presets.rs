//! Named scenarios, one per study of thesis ch. 5 as they are implemented.

use crate::scenario::{Command, HullModelKind, PropellerModelKind, RectifierKind, Scenario};

/// Names of all presets, in the order of the thesis.
pub const PRESET_NAMES: &[&str] = &[
    "startup",
    "acceleration",
    "acceleration-high-gains",
    "ac-braking",
    "ac-braking-unbuffered",
    "turn-45",
    "turn-90",
    "turn-360",
];

/// The preset of that name.
pub fn preset(name: &str) -> Option<Scenario> {
    Some(match name {
        "startup" => startup(),
        "acceleration" => acceleration(false),
        "acceleration-high-gains" => acceleration(true),
        "ac-braking" => ac_braking(true),
        "ac-braking-unbuffered" => ac_braking(false),
        "turn-45" => turn("turn-45", 45.0, None),
        "turn-90" => turn("turn-90", 90.0, None),
        "turn-360" => turn("turn-360", 360.0, Some(1.0)),
        _ => return None,
    })
}

fn speed(t_s: f64, kn: f64) -> Command {
    Command { t_s, speed_kn: Some(kn), heading_deg: None, heading_rate_deg_s: None }
}

/// Ch. 5.1: idle to 25 knots in calm water with the surge model (Figs. 5-1, 5-2, Tables 5.6-5.7).
pub fn startup() -> Scenario {
    let mut s = Scenario {
        name: "startup".into(),
        description: "Start-up from idle to 25 knots in calm water (thesis ch. 5.1, Figs. 5-1 and 5-2): \
                      power flows turbine -> generator -> inverter -> motor -> ship, each stage losing a little."
            .into(),
        commands: vec![speed(0.0, 25.0)],
        ..Scenario::default()
    };
    s.sim.duration_s = 400.0;
    s
}

/// The maneuvering model, steady at 25 knots.
fn at_speed_maneuvering(name: &str, description: &str) -> Scenario {
    let mut s = Scenario { name: name.into(), description: description.into(), ..Scenario::default() };
    s.hull.model = HullModelKind::Maneuvering;
    s.initial.speed_kn = 25.0;
    s.commands = vec![speed(0.0, 25.0)];
    s
}

/// Ch. 5.2.1: 25 knots to full ahead by a step command (Figs. 5-3 to 5-5).
pub fn acceleration(high_gains: bool) -> Scenario {
    let (name, gains) = if high_gains {
        ("acceleration-high-gains", "higher field gains Kp,v = 0.0003, Ki,v = 0.001 (Fig. 5-5)")
    } else {
        ("acceleration", "the baseline field gains Kp,v = 0.0001, Ki,v = 0.0005 (Figs. 5-3, 5-4)")
    };
    let mut s = at_speed_maneuvering(
        name,
        &format!(
            "Acceleration from 25 knots to full ahead by a step order (thesis ch. 5.2.1) with {gains}: the motors \
             pull hard, the turbines slow down and the bus voltage sags with them until the throttle catches up."
        ),
    );
    s.commands.push(speed(10.0, 40.0));
    s.controllers.speed.shaft_ramp_rpm_per_s = 0.0;
    if high_gains {
        s.controllers.field.kp = 0.0003;
        s.controllers.field.ki = 0.001;
    }
    s.sim.duration_s = 120.0;
    s
}

/// Ch. 5.2.2: AC braking from 25 knots, with a brake resistor (ideal power management, Fig. 5-7)
/// or with the energy flowing back to the turbines (Fig. 5-8).
pub fn ac_braking(ideal: bool) -> Scenario {
    let mut s = if ideal {
        at_speed_maneuvering(
            "ac-braking",
            "AC braking from 25 knots (thesis ch. 5.2.2, Figs. 5-6, 5-7): the motors run as generators with negative \
             slip, the ship's kinetic energy flows back into the DC buses and a brake resistor burns it; the turbines \
             idle.",
        )
    } else {
        at_speed_maneuvering(
            "ac-braking-unbuffered",
            "AC braking from 25 knots without a brake resistor (thesis ch. 5.2.2, Fig. 5-8): the returned energy \
             flows back through reversible rectifiers into the generators and the turbines overspeed with the \
             throttle closed.",
        )
    };
    s.propeller.model = PropellerModelKind::FourQuadrant;
    s.controllers.slip.allow_braking = true;
    if ideal {
        s.plant.dc_link.brake_resistor_ohm = 1.0;
    } else {
        s.plant.dc_link.rectifier = RectifierKind::Reversible;
    }
    s.controllers.speed.shaft_ramp_rpm_per_s = 10.0;
    // Water brakes take over at low speed (ch. 5.2.2): AC braking orders 10 knots.
    s.commands.push(speed(10.0, 10.0));
    s.sim.duration_s = 120.0;
    s
}

/// Ch. 5.2.3: heading changes at 25 knots (Figs. 5-9, 5-10, 5-16 in calm water).
pub fn turn(name: &str, heading_deg: f64, rate_deg_s: Option<f64>) -> Scenario {
    let what = if heading_deg >= 360.0 {
        "A full turn at 25 knots (thesis Fig. 5-16 in calm water), ordered as a heading ramp at the fastest rate the \
         autopilot holds for this hull"
            .to_string()
    } else {
        format!("A {heading_deg:.0} degree heading change at 25 knots (thesis ch. 5.2.3, Figs. 5-9 and 5-10)")
    };
    let mut s = at_speed_maneuvering(
        name,
        &format!("{what}: the hull turns less streamlined, the propellers see an altered inflow, and the motors need more power to hold speed."),
    );
    s.commands.push(Command {
        t_s: 10.0,
        speed_kn: None,
        heading_deg: Some(heading_deg),
        heading_rate_deg_s: rate_deg_s,
    });
    s.sim.duration_s = if heading_deg >= 360.0 { 500.0 } else { 300.0 };
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
            assert!(!s.description.is_empty());
        }
        assert!(preset("nope").is_none());
    }
}
