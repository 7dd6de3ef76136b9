//! The `engines` lesson, "How many engines?": its definition and its explainer.

use super::facts::*;
use super::verdict::{by_relation, Change};
use super::*;

/// Mean fuel powers closer than this \[W\] are "about the same" (a fiftieth of one set's 21.5 MW
/// rating at cruise).
const ENGINES_BY_W: f64 = 0.4e6;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "engines",
        title: "How many engines?",
        preset: "startup",
        set: &[
            ("sim.duration_s", "60"),
            ("initial.speed_kn", "15"),
            ("commands.0.speed_kn", "15"),
            ("sea.kind", "random"),
            ("sea.sea_state", "3"),
            ("hull.model", "maneuvering"),
            ("stepping.dt_s", "0.005"),
            ("stepping.integrator", "midpoint"),
        ],
        // The rating and the efficiency at rating are checked against the scenario in
        // tests/lessons.rs.
        story: "The ship cruises into head seas. Four gas turbines can run, each rated 21.5 MW. A gas turbine turns its fuel into shaft power best near full load (37 % of the fuel's energy) and worse and worse below it; the thesis runs all four at every speed. Here you choose how many run: they share the load, and the waves make it swing.",
        controls: vec![
            Control {
                path: "plant.online.sets",
                with_paths: &[],
                label: "Gas turbines running",
                unit: "",
                kind: ControlKind::Toggle {
                    values: &["[1,2,3,4]", "[1,3]", "[1]"],
                    labels: &["all four", "two", "one"],
                    settings: &[&[], &[], &[]],
                },
            },
            speed(10.0, 20.0),
            slider("sea.sea_state", "Sea state (2: smooth, 6: very rough)", "", 2.0, 6.0, 1.0),
        ],
        question: "At cruising speed, which burns less fuel: one gas turbine carrying the whole load, or all four sharing it?",
        answers: &["one carrying the whole load", "four sharing it", "the same: the load is the same"],
        plots: &["fuel", "load"],
        view: "train",
        explain,
        change: Some(Change {
            paths: &["plant.online.sets"],
            names: &["sets running:"],
            what: "the mean fuel power",
            unit: "MW",
            scale: 1e6,
            digits: 2,
            measure: |_| Measure::Mean { signal: "fuel_power_w", from_s: 0.0 },
            by: ENGINES_BY_W,
            // The later choice runs fewer sets: less fuel there is "one carrying the whole load".
            decide: |away, toward, by| Ok(by_relation(away, toward, by, [1, 0, 2])),
            hint: "change the gas turbines running",
            // The runs may compare four sets with two, or two with one: what the answers mean then.
            shown: &["the fewer sets burning less fuel", "the more sets burning less fuel", "about the same fuel either way"],
        }),
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    engines(b, &g.sc, &g.text("plant.online.sets"), end)
}

/// The sets running: the load they carry against their rating, the fuel they burn and the share
/// of its energy that becomes shaft power (below the part-load data's lowest load the figure rests
/// on the curve's extension, and the words say so); the swing of the load and the rating. One run
/// shows one choice: the verdict waits for the comparison, "try this next" runs the other.
fn engines(b: &mut Book, sc: &serde_json::Value, sets: &str, end: f64) -> Explanation {
    let n = serde_json::from_str::<Vec<u32>>(sets).map_or(4, |v| v.len().max(1));
    let rated = number(sc, "plant.turbine.rated_power_w");
    let rating = n as f64 * rated;
    let p = b.at("p_turbine_w", end);
    let g = b.at("p_generator_w", end);
    let fuel = b.at("fuel_power_w", end);
    let ri = b.push(Fact::Level { name: "rating of the sets running [W]", value: rating });
    let (who, give, its, burn, lose) = match n {
        1 => ("the one set running", "gives", "its", "burns", "its generator loses {} MW and passes"),
        2 => ("the two sets running", "give", "their", "burn", "their two generators lose {} MW and pass"),
        3 => ("the three sets running", "give", "their", "burn", "their three generators lose {} MW and pass"),
        _ => ("all four sets running", "give", "their", "burn", "their four generators lose {} MW and pass"),
    };
    b.say(
        format!(
            "At {} s, the end of the run, {who} {give} {} MW of shaft power, {} of {its} {} MW rating, and {burn} {} MW of fuel power: {} of the fuel's energy becomes shaft power.",
            f(end, 0),
            f(p.1 / 1e6, 1),
            pct(p.1 / rating),
            f(rating / 1e6, 1),
            f(fuel.1 / 1e6, 1),
            pct(p.1 / fuel.1)
        ),
        &[p.0, fuel.0, ri],
    );
    b.say(
        format!("Of the shaft power, {} on {} MW.", lose.replace("{}", &f((p.1 - g.1) / 1e6, 2)), f(g.1 / 1e6, 1)),
        &[p.0, g.0],
    );
    // Below the curve's first point (30 % load) the data end: the fuel is the curve's extension.
    let first = crate::plant::fuel::part_load_curve().first().map_or(0.3, |c| c.0);
    let li = b.push(Fact::Level { name: "lowest load of the part-load data [W]", value: first * rating });
    if b.compare(p, (li, first * rating), 0.0) == Relation::Less {
        let i = b.last();
        b.say(
            format!(
                "That is below {} of the rating, where the part-load data end: the simulator extends the curve down, so the fuel figure is an estimate.",
                pct(first)
            ),
            &[p.0, li, i],
        );
    }
    let lo = b.stat(&["p_turbine_w"], Stat::Min, 0.0, end);
    let hi = b.stat(&["p_turbine_w"], Stat::Max, 0.0, end);
    // A swing under 0.1 MW is "held".
    if b.compare((hi.0, hi.1), (lo.0, lo.1), 0.1e6) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "Over the run the load moved between {} MW ({} s) and {} MW ({} s) as groups of waves added resistance and the speed controller answered.",
                f(lo.1 / 1e6, 1),
                f(lo.2, 0),
                f(hi.1 / 1e6, 1),
                f(hi.2, 0)
            ),
            &[lo.0, hi.0, i],
        );
    } else {
        let i = b.last();
        b.say(format!("The load held at {} MW: these waves hardly change it.", f(hi.1 / 1e6, 1)), &[lo.0, hi.0, i]);
    }
    if b.compare((hi.0, hi.1), (ri, rating), 0.0) == Relation::Less {
        let i = b.last();
        // Within a tenth of the rating the reserve is a group of waves away (20 kn in SS6 on one
        // set: 98 %), which "power in reserve" would hide.
        let near_w = 0.9 * rating;
        let near = b.push(Fact::Level { name: "nine tenths of the rating of the sets running [W]", value: near_w });
        let text = if b.compare((hi.0, hi.1), (near, near_w), 0.0) == Relation::Less {
            "they have power in reserve."
        } else {
            "little is left in reserve; a larger group of waves could overload them."
        };
        let j = b.last();
        b.say(
            format!("Its highest is {} of the rating of the sets running: {text}", pct(hi.1 / rating)),
            &[hi.0, ri, i, near, j],
        );
    } else {
        let i = b.last();
        b.say(
            format!(
                "Its highest reaches the rating of the sets running ({} of it): too few sets for this sea and speed.",
                pct(hi.1 / rating)
            ),
            &[hi.0, ri, i],
        );
    }
    let measure = Measure::Stat { signals: vec!["fuel_power_w"], stat: Stat::At, from_s: end };
    let next = if n < 4 {
        Next {
            text: "Run all four: each then carries a quarter of the load, where it turns less of its fuel into shaft power, so together they burn more.".into(),
            set: vec![("plant.online.sets", "[1,2,3,4]".into())],
            promise: Promise { measure, relation: Relation::More, by: 1e6 },
        }
    } else {
        Next {
            text: "Run one: it carries the whole load, nearer its rating, where it turns more of its fuel into shaft power, so it burns less than the four together.".into(),
            set: vec![("plant.online.sets", "[1]".into())],
            promise: Promise { measure, relation: Relation::Less, by: 1e6 },
        }
    };
    let note = "One run shows one choice: change the gas turbines running and compare the fuel with the faint line of this run.".to_string();
    b.done(None, note, next, end)
}
