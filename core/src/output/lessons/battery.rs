//! The `battery` lesson, "A battery smooths the waves": its definition and its explainer.

use super::facts::*;
use super::verdict::Change;
use super::*;
use crate::sim::health::{BUS_LOW_PU, TURBINE_OVERSPEED_PU};

/// The `battery` lesson's controls: the storage's energy and power rating on each bus.
const BATTERY_J: &str = "plant.storage.energy_j";
const BATTERY_W: &str = "plant.storage.power_w";

/// Turbine speed swings closer than this \[pu\] are "about the same".
const BATTERY_BY_PU: f64 = 0.002;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "battery",
        title: "A battery smooths the waves",
        preset: "head-seas-ss6",
        // 40 s hold the first runs of ventilation (the turbines' highest speed at 12 s without
        // storage) and keep the test's grid of 15 pairs of runs short.
        set: &[("sim.duration_s", "40")],
        story: "The ship steams at 25 knots into very rough head seas (sea state 6), lightly loaded, so its propellers run near the surface. Each time a propeller draws air its load drops at once, and it comes back when the propeller bites again: swings of many megawatts within seconds. The gas turbines cannot follow that fast, so their speed swings, and the bus voltage with it. A battery on each DC bus, behind a DC-DC converter, can take the fast part of the swings: it charges when the load drops and gives when the load returns.",
        controls: vec![
            Control {
                path: BATTERY_J,
                with_paths: &[],
                label: "Battery energy on each bus",
                unit: "",
                kind: ControlKind::Toggle {
                    values: &["0", "25000000", "50000000", "100000000", "200000000"],
                    labels: &["none", "25 MJ (7 kWh)", "50 MJ (14 kWh)", "100 MJ (28 kWh)", "200 MJ (56 kWh, the study's)"],
                    settings: &[&[], &[], &[], &[], &[]],
                },
            },
            Control {
                path: BATTERY_W,
                with_paths: &[],
                label: "Battery power rating on each bus",
                unit: "",
                kind: ControlKind::Toggle {
                    values: &["2500000", "5000000", "10000000"],
                    labels: &["2.5 MW", "5 MW", "10 MW (the study's)"],
                    settings: &[&[], &[], &[]],
                },
            },
        ],
        question: "Fit a battery on each DC bus. Will the turbines' speed be steadier, and by how much?",
        answers: &["much steadier: the swing almost vanishes", "a little steadier", "no steadier"],
        plots: &["bus", "storage"],
        view: "train",
        explain,
        change: Some(Change {
            paths: &[BATTERY_J],
            names: &["battery:"],
            what: "the turbines' speed swing",
            unit: "pu",
            scale: 1.0,
            digits: 4,
            measure: |_| Measure::Swing { signal: "turbine_speed_pu", from_s: 0.0 },
            by: BATTERY_BY_PU,
            decide: steadier,
            hint: "choose the battery's energy",
            shown: &[],
        }),
    }
}

/// A swing smaller by more than the margin is steadier; under a quarter of the one before, the
/// swing "almost vanishes".
fn steadier(away: f64, toward: f64, by: f64) -> Result<usize, &'static str> {
    Ok(match Relation::of(toward, away, by) {
        Relation::Less if toward < 0.25 * away => 0,
        Relation::Less => 1,
        _ => 2,
    })
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    battery(b, &g.sc, g.num(BATTERY_J), g.num(BATTERY_W), end)
}

fn battery(b: &mut Book, sc: &serde_json::Value, energy_j: f64, power_w: f64, end: f64) -> Explanation {
    let with = energy_j > 0.0;
    // The turbines' swing over the whole run: their lowest and highest speed.
    let lo = b.stat(&["turbine_speed_pu"], Stat::Min, 0.0, end);
    let hi = b.stat(&["turbine_speed_pu"], Stat::Max, 0.0, end);
    // A swing under 0.01 pu is "held": the words then say so with more digits.
    if b.compare((hi.0, hi.1), (lo.0, lo.1), 0.01) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "The turbines' speed moved between {} and {} pu of its set speed, a swing of {} pu (highest at {} s, the instant the drive-train picture shows).",
                f(lo.1, 3),
                f(hi.1, 3),
                f(hi.1 - lo.1, 3),
                f(hi.2, 1)
            ),
            &[lo.0, hi.0, i],
        );
    } else {
        let i = b.last();
        b.say(
            format!(
                "The turbines' speed held at {} to {} pu of its set speed, a swing of {} pu (highest at {} s, the instant the drive-train picture shows).",
                f(lo.1, 4),
                f(hi.1, 4),
                f(hi.1 - lo.1, 4),
                f(hi.2, 1)
            ),
            &[lo.0, hi.0, i],
        );
    }
    let over = b.push(Fact::Level { name: "turbines' overspeed level [pu]", value: TURBINE_OVERSPEED_PU });
    if b.compare((hi.0, hi.1), (over, TURBINE_OVERSPEED_PU), 0.0) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "That is above the {} pu overspeed level: the turbine blocks of the picture turn red with OVERSPEED.",
                f(TURBINE_OVERSPEED_PU, 1)
            ),
            &[hi.0, over, i],
        );
    }
    let bmin = b.stat(&["bus_voltage_pu"], Stat::Min, 0.0, end);
    let bmax = b.stat(&["bus_voltage_pu"], Stat::Max, 0.0, end);
    let low = b.push(Fact::Level { name: "bus band's lower edge [pu]", value: BUS_LOW_PU });
    if b.compare((bmin.0, bmin.1), (low, BUS_LOW_PU), 0.0) == Relation::Less {
        let i = b.last();
        b.say(
            format!(
                "The bus voltage follows the generators' speed: it went down to {} pu, below its band's lower edge of {} pu, and up to {} pu.",
                f(bmin.1, 3),
                f(BUS_LOW_PU, 1),
                f(bmax.1, 3)
            ),
            &[bmin.0, bmax.0, low, i],
        );
    } else {
        let i = b.last();
        b.say(
            format!(
                "The bus voltage kept between {} and {} pu, above its band's lower edge of {} pu.",
                f(bmin.1, 3),
                f(bmax.1, 3),
                f(BUS_LOW_PU, 1)
            ),
            &[bmin.0, bmax.0, low, i],
        );
    }
    if with {
        let st = &sc["plant"]["storage"];
        let floor = st["soc_min"].as_f64().unwrap_or(f64::NAN);
        let pmin = b.stat(&["storage_power_w"], Stat::Min, 0.0, end);
        let pmax = b.stat(&["storage_power_w"], Stat::Max, 0.0, end);
        let mw = |w: f64| f(w.abs() / 1e6, 1);
        b.say(
            format!(
                "The two batteries took up to {} MW together while charging and gave up to {} MW (the storage plot; each bus's block in the picture shows half).",
                mw(pmin.1.min(0.0)),
                mw(pmax.1.max(0.0))
            ),
            &[pmin.0, pmax.0],
        );
        // At the rating: within 1 % of both converters' rated power, either way.
        let rated =
            b.push(Fact::Level { name: "99 % of the two batteries' power rating [W]", value: 0.99 * 2.0 * power_w });
        let give = b.compare((pmax.0, pmax.1), (rated, 0.99 * 2.0 * power_w), 0.0);
        let gi = b.last();
        let rated_in = b.push(Fact::Level {
            name: "99 % of the two batteries' power rating, charging [W]",
            value: -0.99 * 2.0 * power_w,
        });
        let take = b.compare((pmin.0, pmin.1), (rated_in, -0.99 * 2.0 * power_w), 0.0);
        let ti = b.last();
        if give != Relation::Less || take != Relation::More {
            b.say(
                format!(
                    "At times they were at their rating ({} MW each): the rest of the swing went to the turbines.",
                    value_text(power_w / 1e6)
                ),
                &[pmax.0, rated, gi, pmin.0, rated_in, ti],
            );
        }
        let s0 = b.at("storage_soc", 0.0);
        let smin = b.stat(&["storage_soc"], Stat::Min, 0.0, end);
        let s1 = b.at("storage_soc", end);
        b.say(
            format!(
                "Their charge started at {} %, went down to {} % ({} s in) and ended at {} %.",
                f(100.0 * s0.1, 0),
                f(100.0 * smin.1, 0),
                f(smin.2, 1),
                f(100.0 * s1.1, 0)
            ),
            &[s0.0, smin.0, s1.0],
        );
        // Below this charge the controller gives less and less (its taper, at least a second of its
        // rated power wide, or the reserve it keeps to hand its rating back to the turbines),
        // handing the swings back to the turbines.
        let edge =
            (floor + crate::plant::storage::discharge_edge_j(energy_j, power_w, handover_rate(sc)) / energy_j).min(1.0);
        let lv =
            b.push(Fact::Level { name: "lowest charge where the controller starts to give less [-]", value: edge });
        let fl = b.push(Fact::Level { name: "lowest allowed charge [-]", value: floor });
        if b.compare((smin.0, smin.1), (lv, edge), 0.0) != Relation::More {
            let i = b.last();
            b.say(
                format!(
                    "From {} % of charge down to its lowest allowed charge ({} %) the controller gives less and less, and the turbines take back the swings the battery no longer takes: here the charge went down to {} %, {} its floor.",
                    f(100.0 * edge, 0),
                    f(100.0 * floor, 0),
                    f(100.0 * smin.1, 0),
                    pct_points(smin.1 - floor)
                ),
                &[smin.0, lv, i, fl],
            );
        }
    } else {
        let n = onsets(b.run.trace, submerged(sc));
        let on = b.push(Fact::Onsets { count: n });
        b.say(
            format!(
                "Surface losses started {n} time{} in this run, and there is no battery on the buses: the turbines alone take every swing of the load (the power rating does nothing until you choose an energy).",
                if n == 1 { "" } else { "s" }
            ),
            &[on],
        );
    }
    let measure = Measure::Stat { signals: vec!["turbine_speed_pu"], stat: Stat::Max, from_s: 0.0 };
    // Each promise measured over the lesson's grid (the turbines' highest speed, 40 s runs):
    // none to 200 MJ at 10 MW 1.138 -> 1.001; 2.5 or 5 MW to 10 MW at least 0.007 lower; 25 MJ to
    // 200 MJ at 10 MW 1.008 -> 1.001; 10 MW to 2.5 MW at 50 MJ or more at least 0.026 higher.
    let next = if !with {
        Next {
            text: "Fit the study's battery, 200 MJ at 10 MW on each bus: the turbines' highest speed falls.".into(),
            set: vec![(BATTERY_J, "200000000".into()), (BATTERY_W, "10000000".into())],
            promise: Promise { measure, relation: Relation::Less, by: 0.05 },
        }
    } else if power_w < 10.0e6 {
        Next {
            text: "Raise the power rating to 10 MW: the battery takes more of each swing, and the turbines' highest speed falls.".into(),
            set: vec![(BATTERY_W, "10000000".into())],
            promise: Promise { measure, relation: Relation::Less, by: 0.005 },
        }
    } else if energy_j < 50.0e6 {
        Next {
            text: "Choose 200 MJ: with more energy the battery keeps taking the swings, and the turbines' highest speed falls.".into(),
            set: vec![(BATTERY_J, "200000000".into())],
            promise: Promise { measure, relation: Relation::Less, by: 0.005 },
        }
    } else {
        Next {
            text: "Lower the power rating to 2.5 MW: a battery that cannot pass the swings' megawatts leaves them to the turbines, whose highest speed rises.".into(),
            set: vec![(BATTERY_W, "2500000".into())],
            promise: Promise { measure, relation: Relation::More, by: 0.02 },
        }
    };
    b.done(
        None,
        "One run cannot answer a question about a change: choose another battery and compare the turbines' swing with the faint earlier run.".into(),
        next,
        hi.2,
    )
}
