//! The `power` lesson, "Where the power goes": its definition and its explainer.

use super::facts::*;
use super::*;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "power",
        title: "Where the power goes",
        preset: "startup",
        set: &[("sim.duration_s", "200")],
        story: "The ship starts from rest and speeds up to its ordered speed. Four gas turbines turn generators; the electricity drives two motors; the motors turn the propellers; the propellers push the ship. The power plot shows each stage's power, from the turbines (top) to the useful power that pushes the ship (bottom).",
        controls: vec![
            slider("commands.0.speed_kn", "Ordered speed", "kn", 10.0, 30.0, 1.0),
            slider("ship.drag_coeff", "Hull drag coefficient C_r (a ratio: resistance over \u{bd} \u{3c1} S V\u{b2})", "", 0.0015, 0.006, 0.00025),
        ],
        question: "Once the ship holds its speed, how much of the gas turbines' power ends up pushing the ship through the water?",
        answers: &["almost all of it (more than 90 %)", "about two thirds", "less than a third"],
        plots: &["inventory"],
        view: "train",
        explain,
        change: None,
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    power(b, g.num("commands.0.speed_kn"), end)
}

fn power(b: &mut Book, order: f64, end: f64) -> Explanation {
    // The instant quoted is the run's last row, which the live picture also shows.
    let stages = ["p_turbine_w", "p_generator_w", "p_inverter_w", "p_motor_w", "p_ship_w"];
    let p: Vec<(usize, f64)> = stages.iter().map(|s| b.at(s, end)).collect();
    let v = b.at("ship_speed_kn", end);
    let vo = b.at("speed_cmd_kn", end);
    let held = b.compare(v, vo, 0.02 * vo.1);
    let share = p[4].1 / p[0].1;
    if held == Relation::About {
        b.say(format!("At {} s, the end of the run and the instant the drive-train picture shows, the ship holds its order ({} of {} knots).", f(end, 0), f(v.1, 1), f(vo.1, 0)), &[v.0, vo.0, b.last()]);
    } else {
        b.say(format!("At {} s, the end of the run and the instant the drive-train picture shows, the ship is still at {} knots of its {}: part of the power is still speeding it up.", f(end, 0), f(v.1, 1), f(vo.1, 0)), &[v.0, vo.0, b.last()]);
    }
    b.say(
        format!(
            "The turbines make {} MW and {} MW pushes the ship (its resistance times its speed): {}.",
            f(p[0].1 / 1e6, 1),
            f(p[4].1 / 1e6, 1),
            pct(share)
        ),
        &[p[0].0, p[4].0],
    );
    let names = ["generators", "power electronics", "motors", "propellers"];
    let passed: Vec<f64> = (0..4).map(|i| p[i + 1].1 / p[i].1).collect();
    let worst = (0..4).min_by(|&i, &j| passed[i].total_cmp(&passed[j])).unwrap_or(3);
    b.say(
        format!(
            "Each stage keeps back part of what it gets: the generators pass on {}, the power electronics {}, the motors {}, the propellers {}; the largest loss is the {}'.",
            pct(passed[0]),
            pct(passed[1]),
            pct(passed[2]),
            pct(passed[3]),
            names[worst]
        ),
        &p.iter().map(|x| x.0).collect::<Vec<_>>(),
    );
    // The share decides the answer: above 0.9, about two thirds (0.4 to 0.9), below.
    let right = if share > 0.9 {
        0
    } else if share > 0.4 {
        1
    } else {
        2
    };
    let (to, relation, why) = if order <= 20.0 {
        (
            30.0,
            Relation::More,
            "resistance grows about with the square of speed, so the turbines' power grows about with its cube",
        )
    } else {
        (
            15.0,
            Relation::Less,
            "resistance falls about with the square of speed, so the turbines' power falls about with its cube",
        )
    };
    let next = Next {
        text: format!("Order {} knots: {}.", f(to, 0), why),
        set: vec![("commands.0.speed_kn", value_text(to))],
        promise: Promise {
            measure: Measure::Stat { signals: vec!["p_turbine_w"], stat: Stat::At, from_s: end },
            relation,
            by: 1e6,
        },
    };
    b.done(Some((right, p[4].0)), String::new(), next, end)
}
