//! The `stopping` lesson, "Stopping a destroyer: where does the energy go?" (issue 56): the crash
//! stop of the `crash-stop` preset with a storage of a chosen size on each bus; its definition and
//! its explainer. The question is how the brake resistors' energy changes with the storage.

use super::facts::*;
use super::verdict::{by_relation, Change};
use super::*;
use crate::sim::health::{bus_high_pu, BUS_LOW_PU, TURBINE_OVERSPEED_PU};
use crate::studies::stopping::IMO_TRACK_REACH_L;

/// The control: the storage's energy on each bus \[J\], and the power rating each storage is
/// given with it (`crash-stop-storage`'s, 20 MW: it takes the motors' returned power but its
/// first peak); without storage the preset's own rating, so that no rating is set for nothing.
const STORAGE_J: &str = "plant.storage.energy_j";
const RATING: &[(&str, &str)] = &[("plant.storage.power_w", "20000000")];
const NO_RATING: &[(&str, &str)] = &[("plant.storage.power_w", "10000000")];

/// Brake energies closer than this \[J\] are "about the same".
const BRAKE_BY_J: f64 = 1.0e6;

/// The order's time in the preset (`commands.1`, the crash stop) \[s\].
const ORDER: &str = "commands.1.t_s";

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "stopping",
        title: "Stopping a destroyer: where does the energy go?",
        preset: "crash-stop",
        // 120 s hold the stop (dead in the water some 48 s after the order at 10 s) and the
        // first minute astern; rows every 0.02 s sum the brake resistors' first spike of power to
        // 0.3 % of the run's own energy book (every 0.1 s: 3 %).
        set: &[("sim.duration_s", "120"), ("sim.record_interval_s", "0.02")],
        story: "The destroyer steams ahead (25 knots to start). At 10 s the bridge orders full astern at once: a crash stop. The motors reverse the shafts, but the water still drives the propellers ahead, so the motors work as generators and send the ship's kinetic energy into the two DC buses. The diode rectifiers cannot pass it back to the gas turbines: brake resistors burn it as heat, unless a storage on each bus (a battery behind a DC-DC converter, rated 20 MW) takes it. Once the ship is dead in the water the motors draw power again to drive it astern.",
        controls: vec![Control {
            path: STORAGE_J,
            with_paths: &[],
            label: "Storage energy on each bus",
            unit: "",
            kind: ControlKind::Toggle {
                values: &["0", "50000000", "100000000", "150000000", "200000000"],
                labels: &["none", "50 MJ", "100 MJ", "150 MJ (crash-stop-storage's)", "200 MJ"],
                settings: &[NO_RATING, RATING, RATING, RATING, RATING],
            },
        }, speed(15.0, 30.0)],
        question: "Fit a storage on each DC bus and make it bigger. What happens to the energy the brake resistors burn in the crash stop?",
        answers: &[
            "it falls: the storage takes what the resistors burnt",
            "it stays about the same: the resistors still burn it",
            "it rises",
        ],
        plots: &["brake", "storage", "bus"],
        view: "train",
        explain,
        change: Some(Change {
            paths: &[STORAGE_J],
            names: &["storage:"],
            what: "the brake resistors' energy after the order",
            unit: "MJ",
            scale: 1.0e6,
            digits: 1,
            measure: |sc| Measure::Energy { signal: "brake_power_w", from_s: number(sc, ORDER) },
            by: BRAKE_BY_J,
            decide: |away, toward, by| Ok(by_relation(away, toward, by, [2, 0, 1])),
            hint: "choose the storage's energy",
            shown: &[],
        }),
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    let t0 = number(&g.sc, ORDER);
    let length_m = b.run.scenario.ship_hull().map(|h| h.rigid_body(&b.run.scenario.as_printed).length_m);
    stopping(b, &g.sc, g.num(STORAGE_J), t0, length_m.unwrap_or(f64::NAN), end)
}

fn mj(x: f64) -> String {
    f(x / 1e6, 1)
}

fn stopping(b: &mut Book, sc: &serde_json::Value, energy_j: f64, t0: f64, length_m: f64, end: f64) -> Explanation {
    let v0 = b.at("ship_speed_kn", t0);
    let back = b.stat(&["p_inverter_w"], Stat::Min, t0, end);
    b.say(
        format!(
            "At {} s full astern is ordered at {} knots: the motors brake as generators and returned up to {} MW to the buses ({} s, as pictured).",
            f(t0, 0),
            f(v0.1, 1),
            f(-back.1 / 1e6, 1),
            f(back.2, 1)
        ),
        &[v0.0, back.0],
    );
    // Dead in the water where the ship is furthest along its course (north: it starts heading
    // north, and the twin-screw stop keeps it straight), as the booklet's stopping test finds it.
    let x0 = b.at("x_m", t0);
    let far = b.stat(&["x_m"], Stat::Max, t0, end);
    let x1 = b.at("x_m", end);
    let l = b.push(Fact::Level { name: "ship length [m]", value: length_m });
    let imo = b.push(Fact::Level { name: "IMO's track reach limit [ship lengths]", value: IMO_TRACK_REACH_L });
    let reach = far.1 - x0.1;
    if b.compare((x1.0, x1.1), (far.0, far.1), 1.0) == Relation::Less {
        let i = b.last();
        b.say(
            format!(
                "The ship was dead in the water {} s later, {} m on ({} ship lengths; IMO's limit for merchant ships: {}), after which it went astern.",
                f(far.2 - t0, 1),
                f(reach, 0),
                f(reach / length_m, 2),
                f(IMO_TRACK_REACH_L, 0)
            ),
            &[x0.0, far.0, l, imo, x1.0, i],
        );
    } else {
        let i = b.last();
        b.say(
            format!("The ship still had way ahead at the end of the run, {} m on from the order.", f(x1.1 - x0.1, 0)),
            &[x0.0, far.0, x1.0, i],
        );
    }
    let brake = b.energy("brake_power_w", t0, end);
    b.say(format!("The brake resistors burnt {} MJ as heat by the end ({} s).", mj(brake.1), f(end, 0)), &[brake.0]);
    if energy_j > 0.0 {
        storage(b, sc, energy_j, (t0, far.2), end);
    } else {
        b.say(
            "With no storage, the resistors burn what the diode rectifiers cannot pass to the turbines.".into(),
            &[brake.0],
        );
    }
    bus(b, t0, end);
    let measure = Measure::Energy { signal: "brake_power_w", from_s: t0 };
    // Each promise measured over the lesson's grid (brake energy after the order, 0.02 s rows):
    // without storage 18.9 MJ at 15 kn, 85.6 at 25 and 210.8 at 30; a storage of 50 MJ or more
    // takes at least 18.9 MJ of it at every speed (at 15 kn all; at 30 kn 150 MJ leaves 108.0).
    let next = if energy_j <= 0.0 {
        Next {
            text: "Fit 150 MJ on each bus: the storage takes the returned energy, and the resistors burn less.".into(),
            set: vec![(STORAGE_J, "150000000".into())],
            promise: Promise { measure, relation: Relation::Less, by: 10.0e6 },
        }
    } else {
        Next {
            text: "Take the storage off: the resistors burn the ship's energy again.".into(),
            set: vec![(STORAGE_J, "0".into())],
            promise: Promise { measure, relation: Relation::More, by: 10.0e6 },
        }
    };
    b.done(
        None,
        "One run cannot answer a question about a change: choose another storage and compare the brake energy with the run before.".into(),
        next,
        back.2,
    )
}

/// What the storages took and gave: their charge until its highest before the ship is dead in
/// the water (`stop`: the order's time and that), then its lowest while the motors drive the
/// shafts astern, beside the controller's taper above its floor.
fn storage(b: &mut Book, sc: &serde_json::Value, energy_j: f64, (t0, dead): (f64, f64), end: f64) {
    let s0 = b.at("storage_soc", t0);
    let top = b.stat(&["storage_soc"], Stat::Max, t0, dead);
    let took = b.energy("storage_power_w", t0, top.2);
    if b.compare((top.0, top.1), s0, 0.0) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "The two storages took {} MJ from the buses until their charge was highest: it rose from {} % to {} % ({} s).",
                mj(-took.1),
                f(100.0 * s0.1, 0),
                f(100.0 * top.1, 0),
                f(top.2, 1)
            ),
            &[took.0, s0.0, top.0, i],
        );
    } else {
        b.say(
            format!(
                "The two storages took no charge: it started at {} % and its highest was {} %.",
                f(100.0 * s0.1, 0),
                f(100.0 * top.1, 0)
            ),
            &[s0.0, top.0],
        );
    }
    let st = &sc["plant"]["storage"];
    let floor = st["soc_min"].as_f64().unwrap_or(f64::NAN);
    let power_w = st["power_w"].as_f64().unwrap_or(f64::NAN);
    let low = b.stat(&["storage_soc"], Stat::Min, top.2, end);
    // Below this charge the controller gives less and less (its taper above the floor).
    let edge =
        (floor + crate::plant::storage::discharge_edge_j(energy_j, power_w, handover_rate(sc)) / energy_j).min(1.0);
    let lv = b.push(Fact::Level { name: "lowest charge where the controller starts to give less [-]", value: edge });
    let fl = b.push(Fact::Level { name: "lowest allowed charge [-]", value: floor });
    let gave = b.energy("storage_power_w", top.2, low.2);
    let zero = b.push(Fact::Level { name: "no energy [J]", value: 0.0 });
    let given = b.compare(gave, (zero, 0.0), 0.0) == Relation::More;
    let gi = b.last();
    if b.compare((low.0, low.1), (lv, edge), 0.0) != Relation::More && given {
        let i = b.last();
        b.say(
            format!(
                "Then, as the motors drove the shafts astern, the storages gave the buses {} MJ and their charge went down to {} % ({} s), {} its floor ({} %), where the controller gives less and less and the turbines take the motors' whole load.",
                mj(gave.1),
                f(100.0 * low.1, 0),
                f(low.2, 1),
                pct_points(low.1 - floor),
                f(100.0 * floor, 0)
            ),
            &[gave.0, zero, gi, low.0, lv, i, fl],
        );
    } else {
        b.say(format!("After that their lowest charge was {} % ({} s).", f(100.0 * low.1, 0), f(low.2, 1)), &[low.0]);
    }
}

/// The bus against its band after the order, and the turbines' speed (the bus plot's other line).
fn bus(b: &mut Book, t0: f64, end: f64) {
    let high = bus_high_pu(b.run.scenario);
    let peak = b.stat(&["bus_voltage_pu"], Stat::Max, t0, end);
    let hl = b.push(Fact::Level { name: "top of the bus's band [pu]", value: high });
    let where_ = if b.compare((peak.0, peak.1), (hl, high), 0.0) == Relation::More {
        format!("above its band's top of {} pu", f(high, 2))
    } else {
        format!("inside its band (up to {} pu)", f(high, 2))
    };
    let mut ids = vec![peak.0, hl, b.last()];
    let lowest = b.stat(&["bus_voltage_pu"], Stat::Min, t0, end);
    let ll = b.push(Fact::Level { name: "bus band's lower edge [pu]", value: BUS_LOW_PU });
    let below = b.compare((lowest.0, lowest.1), (ll, BUS_LOW_PU), 0.0) == Relation::Less;
    ids.extend([lowest.0, ll, b.last()]);
    let (v, t, edge) = (f(lowest.1, 3), f(lowest.2, 1), f(BUS_LOW_PU, 1));
    let then = if below {
        // The instant's motor power: what the buses were feeding when they sagged.
        let p = b.at("p_inverter_w", lowest.2);
        ids.push(p.0);
        format!(
            "it went down to {v} pu at {t} s, below its band's lower edge of {edge} pu, while the motors took {} MW",
            f(p.1 / 1e6, 1)
        )
    } else {
        format!("its lowest was {v} pu ({t} s), above its band's lower edge of {edge} pu")
    };
    b.say(format!("The bus voltage rose to {} pu ({} s), {where_}; {then}.", f(peak.1, 3), f(peak.2, 1)), &ids);
    let lo = b.stat(&["turbine_speed_pu"], Stat::Min, t0, end);
    let hi = b.stat(&["turbine_speed_pu"], Stat::Max, t0, end);
    let over = b.push(Fact::Level { name: "turbines' overspeed level [pu]", value: TURBINE_OVERSPEED_PU });
    let above = b.compare((hi.0, hi.1), (over, TURBINE_OVERSPEED_PU), 0.0) == Relation::More;
    let oi = b.last();
    let tail = if above {
        format!(": that is above the {} pu overspeed level", f(TURBINE_OVERSPEED_PU, 1))
    } else {
        String::new()
    };
    b.compare((hi.0, hi.1), (lo.0, lo.1), 0.0);
    let mi = b.last();
    b.say(
        format!("The turbines' speed moved between {} and {} pu{tail}.", f(lo.1, 3), f(hi.1, 3)),
        &[lo.0, hi.0, mi, over, oi],
    );
}
