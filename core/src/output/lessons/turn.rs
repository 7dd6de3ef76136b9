//! The `turn` lesson, "A turn costs power": its definition and its explainer.

use super::facts::*;
use super::*;
use crate::signals::Signal;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "turn",
        title: "A turn costs power",
        preset: "turn-90",
        // The largest turn (180 deg) finishes inside the run: turning at 0.8 deg/s (the study's
        // 0.5 would need 420 s; the autopilot holds 0.88 deg/s at the slider's lowest 17 kn).
        set: &[("sim.duration_s", "270"), ("controllers.autopilot.turn_rate_deg_s", "0.8")],
        story: "The ship steams straight at a steady speed; at 10 s the autopilot orders a new heading and the rudder turns the ship. The speed order stays the same all the time.",
        controls: vec![
            slider("commands.1.heading_deg", "Turn to heading", "deg", 15.0, 180.0, 15.0),
            speed(17.0, 30.0),
        ],
        question: "The speed order stays the same through the turn. What do the motors need while the ship turns?",
        answers: &["more power", "the same power", "less power"],
        plots: &["motor", "speed"],
        view: "plan",
        explain,
        change: None,
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    turn(b, &g.sc, g.num("commands.1.heading_deg"), g.num(SPEED_KN), end)
}

fn turn(b: &mut Book, sc: &serde_json::Value, heading: f64, speed: f64, end: f64) -> Explanation {
    let t0 = number(sc, "commands.1.t_s");
    let reached = {
        let t = b.run.trace.get(Signal::TS);
        let h = b.run.trace.get(Signal::HeadingDeg);
        let level = heading - 1.0;
        let r = window(t, t0, end).find(|&i| h[i] >= level).map(|i| t[i]);
        (b.push(Fact::Reaches { signal: "heading_deg", level, from_s: t0, t_s: r }), r)
    };
    match reached.1 {
        Some(tr) => b.say(
            format!(
                "The order came at {} s; the ship was on its new heading, {}\u{b0}, {} s later.",
                f(t0, 0),
                f(heading, 0),
                f(tr - t0, 0)
            ),
            &[reached.0],
        ),
        None => {
            let h = b.at("heading_deg", end);
            b.say(
                format!(
                    "The order came at {} s; when the run ended the ship had turned {}\u{b0} of its {}\u{b0}.",
                    f(t0, 0),
                    f(h.1, 0),
                    f(heading, 0)
                ),
                &[reached.0, h.0],
            )
        }
    }
    let p0 = b.at("im_power_pu", t0);
    let (pi, pmax, tmax) = b.stat(&["im_power_pu"], Stat::Max, t0, end);
    // A change under 1 % of the power at the order is "the same".
    let by = 0.01 * p0.1;
    let rel = b.compare((pi, pmax), p0, by);
    let because = b.last();
    match rel {
        Relation::More => {
            let when = match reached.1 {
                Some(tr) if tmax > tr => format!(
                    "{} s after the ship reached its new heading: stopping a turn costs power too",
                    f(tmax - tr, 0)
                ),
                _ => "while the ship was turning".to_string(),
            };
            b.say(
                format!(
                    "While the ship turns, the rudder is over and the hull moves sideways, so the propellers meet the water at an angle: the motors' power rose from {} pu at the order to {} pu ({} more) at {} s, {when}.",
                    f(p0.1, 3),
                    f(pmax, 3),
                    pct(pmax / p0.1 - 1.0),
                    f(tmax, 0)
                ),
                &[p0.0, pi, because, reached.0],
            )
        }
        _ => b.say(
            format!("The motors' power stayed within 1 % of its {} pu at the order.", f(p0.1, 3)),
            &[p0.0, pi, because],
        ),
    }
    let v0 = b.at("ship_speed_kn", t0);
    let vmin = b.stat(&["ship_speed_kn"], Stat::Min, t0, end);
    let vend = b.at("ship_speed_kn", end);
    let dip = b.compare(v0, (vmin.0, vmin.1), 0.02);
    let dip_i = b.last();
    if dip == Relation::More {
        let back = b.compare(vend, (vmin.0, vmin.1), 0.02);
        let back_i = b.last();
        let after = if back == Relation::More {
            format!(", and the speed controller brought it back to {} knots by the end", f(vend.1, 2))
        } else {
            String::new()
        };
        b.say(
            format!("The ship slowed from {} to {} knots in the turn{after}.", f(v0.1, 2), f(vmin.1, 2)),
            &[v0.0, vmin.0, dip_i, back_i, vend.0],
        );
    } else {
        b.say(format!("The speed held at {} knots.", f(v0.1, 2)), &[v0.0, vmin.0, dip_i]);
    }
    let right = match rel {
        Relation::More => 0,
        Relation::About => 1,
        Relation::Less => 2,
    };
    // The extra power of a turn grows with the speed (measured over the lesson's grid).
    let rise = Measure::Rise { signal: "im_power_pu", from_s: t0 };
    let next = if speed < 30.0 {
        Next {
            text: "Set the speed to 30 knots: the same turn then takes more extra power.".into(),
            set: vec![(SPEED_KN, "30".into())],
            promise: Promise { measure: rise, relation: Relation::More, by: 0.002 },
        }
    } else {
        Next {
            text: "Set the speed to 20 knots: the same turn then takes less extra power.".into(),
            set: vec![(SPEED_KN, "20".into())],
            promise: Promise { measure: rise, relation: Relation::Less, by: 0.002 },
        }
    };
    b.done(Some((right, because)), String::new(), next, tmax)
}
