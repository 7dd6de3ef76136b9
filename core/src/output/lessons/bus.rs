//! The `bus` lesson, "How the bus voltage is held": its definition and its explainer.

use super::facts::*;
use super::verdict::{by_relation, Change};
use super::*;
use crate::sim::health::{BUS_LOW_PU, TURBINE_MIN_RUNNING_PU};

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "bus",
        title: "How the bus voltage is held",
        preset: "acceleration",
        set: &[],
        story: "At 10 s the motors are ordered to full power at once. The generators' voltage sags as the turbines slow under the load; a field controller raises the generators' field current to hold the bus voltage. pu means \"per unit\": a fraction of the rated value (1 pu is the rated voltage or speed).",
        controls: vec![
            decades("controllers.field.kp", "Field controller: reaction to the voltage error now (proportional gain)", "V/V", 1e-5, 0.1),
            decades("controllers.field.ki", "Field controller: reaction to the error summed over time (integral gain)", "V/(V s)", 1e-5, 10.0),
        ],
        question: "The motors suddenly take full power. If the generators' field controller reacts more strongly (a larger gain), the bus voltage will...",
        answers: &["dip less and recover sooner", "dip more", "hardly change"],
        plots: &["bus"],
        view: "train",
        explain,
        change: Some(Change {
            paths: &["controllers.field.kp", "controllers.field.ki"],
            names: &["Kp", "Ki"],
            what: "the lowest bus voltage after the order",
            unit: "pu",
            scale: 1.0,
            digits: 3,
            measure: |sc| Measure::Stat { signals: vec!["bus_voltage_pu"], stat: Stat::Min, from_s: number(sc, "commands.1.t_s") },
            // Half a percent of the rated voltage: the bus band's scale is a tenth.
            by: 0.005,
            // A higher lowest voltage is a smaller dip.
            decide: |away, toward, by| Ok(by_relation(away, toward, by, [0, 1, 2])),
            hint: "raise a gain of the field controller",
            shown: &[],
        }),
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    let own = |p: &str| g.defaults.get(p).and_then(|v| v.as_f64()).unwrap_or(f64::NAN);
    bus(b, &g.sc, (own("controllers.field.kp"), own("controllers.field.ki")), end)
}

/// `own`: the lesson's own gains (Kp, Ki), which "back to" names.
fn bus(b: &mut Book, sc: &serde_json::Value, own: (f64, f64), end: f64) -> Explanation {
    let t0 = number(sc, "commands.1.t_s");
    let (bi, bmin, tmin) = b.stat(&["bus_voltage_pu"], Stat::Min, t0, end);
    let tu = b.stat(&["turbine_speed_pu"], Stat::Min, t0, end);
    b.say(
        format!("At {} s the motors take full power. The bus dipped to {} pu ({} s in) and the turbines slowed to {} pu: a generator's voltage falls with its speed, and the field controller raises its field current to make up for it.", f(t0, 0), f(bmin, 3), f(tmin, 1), f(tu.1, 3)),
        &[bi, tu.0],
    );
    // What the controller did by the dip: the field voltage then against before the order. A small
    // gain barely moves it, so the dip is the turbines' slowing alone (the reason a small change
    // of gain "hardly changes" the dip).
    let f0 = b.at("field_voltage_v", t0);
    let fmin = b.at("field_voltage_v", tmin);
    let rose = b.compare(fmin, f0, 0.0);
    let cmp_f = b.last();
    let said = if rose == Relation::More {
        format!(
            "By the dip the controller had raised the field voltage from {} V to {} V ({} more) while the bus was {} low.",
            f(f0.1, 1),
            f(fmin.1, 1),
            pct(fmin.1 / f0.1 - 1.0),
            pct(1.0 - bmin)
        )
    } else {
        format!(
            "By the dip the controller had not raised the field voltage ({} V before the order, {} V then) while the bus was {} low.",
            f(f0.1, 1),
            f(fmin.1, 1),
            pct(1.0 - bmin)
        )
    };
    b.say(said, &[f0.0, fmin.0, cmp_f, bi]);
    let bend = b.at("bus_voltage_pu", end);
    let low = b.push(Fact::Level { name: "bus band's lower edge [pu]", value: BUS_LOW_PU });
    let back = Relation::of(bend.1, BUS_LOW_PU, 0.0);
    let cmp = b.push(Fact::Compare { a: bend.0, b: low, by: 0.0, relation: back });
    if back == Relation::More {
        b.say(
            format!(
                "By the end the bus was back at {} pu, inside its band (above {} pu).",
                f(bend.1, 3),
                f(BUS_LOW_PU, 1)
            ),
            &[bend.0, cmp],
        );
    } else {
        b.say(
            format!(
                "At the end the bus is still at {} pu, below its band's {} pu: the controller has not brought it back.",
                f(bend.1, 3),
                f(BUS_LOW_PU, 1)
            ),
            &[bend.0, cmp],
        );
    }
    if let Some(w) = b.run.summary.warnings.iter().find(|w| w.starts_with("bus voltage")) {
        b.say(format!("The red LOW on the bus blocks is the plant's health check: {w}."), &[bi]);
    }
    let run_level = b.push(Fact::Level { name: "turbines' minimum running speed [pu]", value: TURBINE_MIN_RUNNING_PU });
    let stalled = Relation::of(tu.1, TURBINE_MIN_RUNNING_PU, 0.0) == Relation::Less;
    let cmp = b.push(Fact::Compare {
        a: tu.0,
        b: run_level,
        by: 0.0,
        relation: Relation::of(tu.1, TURBINE_MIN_RUNNING_PU, 0.0),
    });
    if stalled {
        b.say(format!("The turbines stalled (below {} pu of their speed): the controller asked the generators for more than the turbines could give.", f(TURBINE_MIN_RUNNING_PU, 1)), &[tu.0, cmp]);
    }
    let turb = Measure::Stat { signals: vec!["turbine_speed_pu"], stat: Stat::Min, from_s: t0 };
    let next = if stalled {
        let (kp, ki) = (value_text(own.0), value_text(own.1));
        Next {
            text: format!("Set the gains back to the lesson's own, proportional {kp} and integral {ki}: the turbines keep running."),
            set: vec![("controllers.field.kp", kp), ("controllers.field.ki", ki)],
            promise: Promise { measure: turb, relation: Relation::More, by: 0.1 },
        }
    } else if back != Relation::More {
        let ki = value_text(own.1);
        Next {
            text: format!("Set the integral gain to the lesson's own {ki}: summing the error over time brings the bus back by the end."),
            set: vec![("controllers.field.ki", ki)],
            promise: Promise {
                measure: Measure::Stat { signals: vec!["bus_voltage_pu"], stat: Stat::At, from_s: end },
                relation: Relation::More,
                by: 0.02,
            },
        }
    } else {
        Next {
            text: "Set the proportional gain to 0.1: a controller can hold the voltage only by stalling its turbines."
                .into(),
            set: vec![("controllers.field.kp", "0.1".into())],
            promise: Promise { measure: turb, relation: Relation::Less, by: 0.1 },
        }
    };
    b.done(None, "One run cannot answer a question about a change: move a gain and compare the new run with the faint earlier one.".into(), next, tmin)
}
