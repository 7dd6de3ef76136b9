//! The `braking` lesson, "Braking: where the ship's energy goes": its definition and its explainer.

use super::facts::*;
use super::verdict::Change;
use super::*;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "braking",
        title: "Braking: where the ship's energy goes",
        preset: "ac-braking",
        set: &[("sim.duration_s", "90")],
        story: "At 10 s the ship is ordered to slow to 10 knots. The motors brake: the water turns the propellers, the motors work as generators and send the ship's kinetic energy back into the electric bus. A brake resistor can burn it as heat; without one, the rectifiers pass it back towards the generators and the gas turbines.",
        controls: vec![
            Control {
                path: "plant.dc_link.brake_resistor_ohm",
                with_paths: &[],
                label: "Brake resistor",
                unit: "",
                kind: ControlKind::Toggle {
                    values: &["1", "0"],
                    labels: &["with a brake resistor", "no brake resistor"],
                    // Without the resistor the rectifiers must pass power back to the
                    // generators (Fig. 5-8's plant): a diode rectifier with nowhere for the
                    // energy to go drives the bus voltage away.
                    settings: &[&[("plant.dc_link.rectifier", "diode")], &[("plant.dc_link.rectifier", "reversible")]],
                },
            },
            speed(15.0, 30.0),
        ],
        question: "The ship slows from 25 to 10 knots. Without a brake resistor, where does its kinetic energy go?",
        answers: &["back into the gas turbines, which speed up", "it simply disappears", "into the bus, which holds its voltage"],
        plots: &["bus", "brake"],
        view: "train",
        explain,
        change: Some(Change {
            paths: &["plant.dc_link.brake_resistor_ohm"],
            names: &[""],
            what: "the turbines' rise in speed after the order",
            unit: "pu",
            scale: 1.0,
            digits: 3,
            measure: |sc| Measure::Rise { signal: "turbine_speed_pu", from_s: number(sc, "commands.1.t_s") },
            by: 0.005,
            decide: |away, toward, by| match Relation::of(toward, away, by) {
                Relation::More => Ok(0),
                _ => Err("Without the resistor the turbines sped up no more than with it: from this speed there is little energy to return; start from a higher speed."),
            },
            hint: "switch the brake resistor off",
            shown: &[],
        }),
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    braking(b, &g.sc, g.text("plant.dc_link.brake_resistor_ohm") == "1", g.num(SPEED_KN), end)
}

fn braking(b: &mut Book, sc: &serde_json::Value, resistor: bool, speed: f64, end: f64) -> Explanation {
    let t0 = number(sc, "commands.1.t_s");
    let to = number(sc, "commands.1.speed_kn");
    let v0 = b.at("ship_speed_kn", t0);
    b.say(
        format!("At {} s the order slows the ship from {} to {} knots: the water drives the propellers and the motors brake as generators, sending the ship's energy into the bus.", f(t0, 0), f(v0.1, 1), f(to, 0)),
        &[v0.0],
    );
    let n0 = b.at("turbine_speed_pu", t0);
    let (ni, nmax, tmax) = b.stat(&["turbine_speed_pu"], Stat::Max, t0, end);
    let bus = b.stat(&["bus_voltage_pu"], Stat::Max, t0, end);
    let rose = b.compare((ni, nmax), n0, 0.01);
    let because = b.last();
    let e = b.run.summary.energy_j.brake;
    let ei = b.push(Fact::BrakeEnergy { value_j: e });
    let (right, note) = if resistor {
        b.say(
            format!("The brake resistor burnt {} MJ as heat; the turbines reached {} pu of their speed and the bus {} pu of its voltage.", f(e / 1e6, 1), f(nmax, 3), f(bus.1, 3)),
            &[ei, ni, bus.0],
        );
        (None, "This run burnt the energy in the brake resistor, so it does not answer the question yet: switch the resistor off.".to_string())
    } else if rose == Relation::More {
        let pmin = b.stat(&["p_turbine_w"], Stat::Min, t0, end);
        b.say(
            format!("With no resistor the energy flowed back through the rectifiers: the turbines sped up from {} to {} pu of their speed ({} s in) while their power fell to {} MW, and the bus rose to {} pu.", f(n0.1, 3), f(nmax, 3), f(tmax, 0), f(pmin.1 / 1e6, 1), f(bus.1, 3)),
            &[n0.0, ni, because, pmin.0, bus.0],
        );
        (Some((0, because)), String::new())
    } else {
        b.say(format!("With no resistor the turbines stayed within 1 % of their speed (highest {} pu): from this speed there is little energy to return.", f(nmax, 3)), &[n0.0, ni, because]);
        (None, "From this speed the run shows too little to answer: order a higher speed.".to_string())
    };
    let measure = Measure::Stat { signals: vec!["turbine_speed_pu"], stat: Stat::Max, from_s: t0 };
    let next = if resistor {
        Next {
            text: "Switch the resistor off: with nowhere else to go, the energy speeds up the turbines.".into(),
            set: vec![("plant.dc_link.brake_resistor_ohm", "0".into())],
            promise: Promise { measure, relation: Relation::More, by: 0.005 },
        }
    } else if speed < 30.0 {
        Next {
            text: "Start from 30 knots: more energy to stop, and the turbines speed up more.".into(),
            set: vec![(SPEED_KN, "30".into())],
            promise: Promise { measure, relation: Relation::More, by: 0.005 },
        }
    } else {
        Next {
            text: "Switch the resistor on: it takes the energy, and the turbines stay near their speed.".into(),
            set: vec![("plant.dc_link.brake_resistor_ohm", "1".into())],
            promise: Promise { measure, relation: Relation::Less, by: 0.005 },
        }
    };
    let at = if resistor { b.stat(&["brake_power_w"], Stat::Max, t0, end).2 } else { tmax };
    b.done(right, note, next, at)
}
