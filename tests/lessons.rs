//! Every sentence a lesson shows is true of its own run (issue 43): for each lesson, over a grid
//! of its control values (5 per slider, ends included, each with the others at the lesson's
//! values, and every corner), the lesson's scenario runs natively and each fact of its
//! explanation (core/src/output/lessons.rs) is checked against the run's trace with code of this
//! file's own; the verdict follows the facts; "try this next" is run and must show its promise.

use aes_core::output::lessons::{self, ControlKind, Explanation, Fact, Lesson, Measure, Relation, Stat};
use aes_core::signals::Signal;
use aes_core::sim::{run, RunResult};
use std::collections::BTreeSet;

/// A control's grid: 5 evenly spaced stops of a slider (both ends), every value of a toggle.
fn grid(kind: &ControlKind) -> Vec<String> {
    match kind {
        ControlKind::Toggle { values, .. } => values.iter().map(|v| v.to_string()).collect(),
        ControlKind::Slider { stops, .. } => {
            let n = stops.len() - 1;
            let ks: BTreeSet<usize> = (0..5).map(|i| (i * n + 2) / 4).collect();
            ks.into_iter().map(|k| stops[k].to_string()).collect()
        }
    }
}

fn ends(kind: &ControlKind) -> Vec<String> {
    let g = grid(kind);
    match kind {
        ControlKind::Toggle { .. } => g,
        _ => vec![g[0].clone(), g[g.len() - 1].clone()],
    }
}

/// The value sets of a lesson: each control along its grid (others at the lesson's values), and
/// every corner.
fn cases(l: &Lesson) -> Vec<Vec<(&'static str, String)>> {
    let mut out: BTreeSet<Vec<(&'static str, String)>> = BTreeSet::new();
    for c in &l.controls {
        for v in grid(&c.kind) {
            out.insert(vec![(c.path, v)]);
        }
    }
    let mut corners: Vec<Vec<(&'static str, String)>> = vec![vec![]];
    for c in &l.controls {
        corners = corners
            .into_iter()
            .flat_map(|pre| ends(&c.kind).into_iter().map(move |v| [pre.clone(), vec![(c.path, v)]].concat()))
            .collect();
    }
    out.extend(corners);
    out.into_iter().collect()
}

fn col<'a>(r: &'a RunResult, name: &str) -> &'a [f64] {
    r.trace.get(Signal::from_name(name).unwrap_or_else(|| panic!("no signal {name}")))
}

/// Rows with from <= t <= to (a recorded row every 0.1 s; the bounds are exact row times or the
/// run's ends).
fn rows(r: &RunResult, from: f64, to: f64) -> Vec<usize> {
    let t = col(r, "t_s");
    (0..t.len()).filter(|&i| t[i] >= from - 1e-9 && t[i] <= to + 1e-9).collect()
}

fn value_at(r: &RunResult, name: &str, at: f64) -> f64 {
    let t = col(r, "t_s");
    let i = (0..t.len()).min_by(|&a, &b| (t[a] - at).abs().total_cmp(&(t[b] - at).abs())).unwrap();
    assert!((t[i] - at).abs() <= 0.05 + 1e-9, "no row near {at} s");
    col(r, name)[i]
}

fn extreme(r: &RunResult, names: &[&str], stat: Stat, from: f64, to: f64) -> f64 {
    let vals = names.iter().flat_map(|n| rows(r, from, to).into_iter().map(move |i| col(r, n)[i]));
    match stat {
        Stat::Min => vals.fold(f64::INFINITY, f64::min),
        Stat::Max => vals.fold(f64::NEG_INFINITY, f64::max),
        Stat::At => value_at(r, names[0], from),
    }
}

fn end(r: &RunResult) -> f64 {
    *col(r, "t_s").last().unwrap()
}

fn measure(r: &RunResult, m: &Measure, submerged: f64) -> f64 {
    match m {
        Measure::Stat { signals, stat, from_s } => extreme(r, signals, *stat, *from_s, end(r)),
        Measure::Rise { signal, from_s } => {
            extreme(r, &[signal], Stat::Max, *from_s, end(r)) - value_at(r, signal, *from_s)
        }
        Measure::Onsets => onsets(r, submerged) as f64,
    }
}

fn onsets(r: &RunResult, submerged: f64) -> usize {
    let b = col(r, "beta_t");
    let mut n = 0;
    let mut out = false;
    for &x in b {
        if x < submerged && !out {
            n += 1;
        }
        out = x < submerged;
    }
    n
}

/// The value a fact states, checked against the trace (tolerance: 1e-12 relative, the same rows).
fn check_fact(r: &RunResult, facts: &[Fact], i: usize, submerged: f64, what: &str) -> f64 {
    match &facts[i] {
        Fact::Stat { signals, stat, from_s, to_s, value, t_s } => {
            let own = extreme(r, signals, *stat, *from_s, *to_s);
            assert!(
                (own - value).abs() <= 1e-12 * own.abs().max(1.0),
                "{what}: fact {i} {:?} says {value}, the trace {own}",
                facts[i]
            );
            // The time quoted is a row of the window where one of the signals has that value.
            assert!(*t_s >= from_s - 0.05 && *t_s <= to_s + 0.05, "{what}: fact {i} {:?}", facts[i]);
            assert!(
                signals.iter().any(|s| value_at(r, s, *t_s) == *value),
                "{what}: fact {i} {:?}: no signal at {t_s} s has {value}",
                facts[i]
            );
            *value
        }
        Fact::Reaches { signal, level, from_s, t_s } => {
            let t = col(r, "t_s");
            let c = col(r, signal);
            let own = rows(r, *from_s, end(r)).into_iter().find(|&j| c[j] >= *level).map(|j| t[j]);
            assert_eq!(own, *t_s, "{what}: fact {i} {:?}", facts[i]);
            t_s.unwrap_or(f64::NAN)
        }
        Fact::Onsets { count } => {
            assert_eq!(onsets(r, submerged), *count, "{what}: onsets");
            *count as f64
        }
        Fact::BrakeEnergy { value_j } => {
            // The trapezoid over the 0.1 s rows against the run's own energy book: within 2 % and
            // 0.5 MJ (measured: 123.1 MJ either way in the lesson's default run).
            let t = col(r, "t_s");
            let p = col(r, "brake_power_w");
            let own: f64 = (1..t.len()).map(|j| 0.5 * (p[j] + p[j - 1]) * (t[j] - t[j - 1])).sum();
            assert!(
                (own - value_j).abs() <= 0.02 * own.abs() + 0.5e6,
                "{what}: brake energy {value_j} J, the trace's {own} J"
            );
            *value_j
        }
        Fact::Level { value, .. } => *value,
        Fact::Compare { a, b, by, relation } => {
            let (x, y) = (check_fact(r, facts, *a, submerged, what), check_fact(r, facts, *b, submerged, what));
            assert_eq!(Relation::of(x, y, *by), *relation, "{what}: fact {i}: {x} against {y} by {by}");
            f64::NAN
        }
    }
}

/// Words that state a direction must rest on a comparison that holds that way.
fn check_words(e: &Explanation, what: &str) {
    for (text, ids) in &e.sentences {
        let relations: Vec<Relation> = ids
            .iter()
            .filter_map(|&i| match &e.facts[i] {
                Fact::Compare { relation, .. } => Some(*relation),
                _ => None,
            })
            .collect();
        for (word, rel) in [
            ("rose from", Relation::More),
            ("slowed from", Relation::More),
            ("sped up", Relation::More),
            ("stayed within", Relation::About),
            ("back at", Relation::More),
            ("stalled", Relation::Less),
            ("moved between", Relation::More),
            ("held at", Relation::About),
        ] {
            if text.contains(word) {
                assert!(
                    relations.contains(&rel),
                    "{what}: \"{text}\" says '{word}' without a {rel:?} comparison: {relations:?}"
                );
            }
        }
        if text.contains("still at") && text.contains("below its band") {
            assert!(relations.iter().any(|r| *r != Relation::More), "{what}: \"{text}\"");
        }
    }
}

fn check_case(l: &Lesson, set: &[(&'static str, String)]) -> String {
    let given: Vec<(&str, &str)> = set.iter().map(|(p, v)| (*p, v.as_str())).collect();
    let what = format!("{} {:?}", l.name, given);
    let o = lessons::open(l, &given).unwrap();
    assert!(o.refused.is_empty(), "{what}: refused {:?}", o.refused);
    let r = run(&o.scenario).unwrap_or_else(|e| panic!("{what}: {e}"));
    let submerged = o.scenario.to_value()["propeller"]["beta_t"].as_f64().unwrap_or(1.0);
    let e =
        lessons::explain(l, &o.values, &lessons::Run { scenario: &o.scenario, trace: &r.trace, summary: &r.summary });
    for i in 0..e.facts.len() {
        check_fact(&r, &e.facts, i, submerged, &what);
    }
    check_words(&e, &what);
    for (_, ids) in &e.sentences {
        assert!(ids.iter().all(|&i| i < e.facts.len()), "{what}");
    }
    // Every line the plot shows: a lesson that plots h/R quotes both shafts.
    if l.plots.contains(&"hr") {
        for s in ["h_over_r", "h_over_r_stbd"] {
            assert!(
                e.facts.iter().any(|f| matches!(f, Fact::Stat { signals, stat: Stat::Min, .. } if signals == &vec![s])),
                "{what}: no lowest {s}"
            );
        }
    }
    // The verdict follows the run.
    let t_end = end(&r);
    match l.name {
        "power" => {
            let share = value_at(&r, "p_ship_w", t_end) / value_at(&r, "p_turbine_w", t_end);
            let right = if share > 0.9 {
                0
            } else if share > 0.4 {
                1
            } else {
                2
            };
            assert_eq!(e.right, Some(right), "{what}: share {share}");
            assert_eq!(e.at_s, t_end, "{what}: the picture shows the instant the words quote");
        }
        "turn" => {
            let t0 = o.scenario.commands[1].t_s;
            let p0 = value_at(&r, "im_power_pu", t0);
            let pmax = extreme(&r, &["im_power_pu"], Stat::Max, t0, t_end);
            let right = match Relation::of(pmax, p0, 0.01 * p0) {
                Relation::More => 0,
                Relation::About => 1,
                Relation::Less => 2,
            };
            assert_eq!(e.right, Some(right), "{what}");
            // The window is the turn's: nothing before the order is quoted.
            for f in &e.facts {
                if let Fact::Stat { from_s, .. } = f {
                    assert!(*from_s >= t0, "{what}: {f:?} starts before the order");
                }
            }
        }
        "braking" => {
            let resistor = o.values["plant.dc_link.brake_resistor_ohm"] == "1";
            let t0 = o.scenario.commands[1].t_s;
            let rise = extreme(&r, &["turbine_speed_pu"], Stat::Max, t0, t_end) - value_at(&r, "turbine_speed_pu", t0);
            if resistor {
                assert_eq!(
                    e.right, None,
                    "{what}: a run with the resistor does not show where the energy goes without it"
                );
                assert!(r.summary.energy_j.brake > 1e6, "{what}: {}", r.summary.energy_j.brake);
            } else {
                assert_eq!(e.right, (rise > 0.01).then_some(0), "{what}: rise {rise}");
                assert_eq!(r.summary.energy_j.brake, 0.0, "{what}");
            }
        }
        _ => assert_eq!(e.right, None, "{what}"),
    }
    // "Try this next" keeps its promise in the lesson's own run.
    let mut next_set: Vec<(&str, &str)> =
        given.iter().filter(|(p, _)| !e.next.set.iter().any(|(q, _)| q == p)).copied().collect();
    next_set.extend(e.next.set.iter().map(|(p, v)| (*p, v.as_str())));
    let o2 = lessons::open(l, &next_set).unwrap();
    assert!(o2.refused.is_empty(), "{what}: next {:?} refused {:?}", e.next.set, o2.refused);
    let r2 = run(&o2.scenario).unwrap();
    let p = &e.next.promise;
    let (now, then) = (measure(&r, &p.measure, submerged), measure(&r2, &p.measure, submerged));
    assert_eq!(
        Relation::of(then, now, p.by),
        p.relation,
        "{what}: try next {:?} promised {:?} by {}: {now} -> {then}",
        e.next.set,
        p.relation,
        p.by
    );
    format!("{what}: right {:?}, next {:?}: {now:.3} -> {then:.3}", e.right, e.next.set)
}

#[test]
fn every_claim_of_every_lesson_holds_over_its_grid() {
    let all: Vec<(Lesson, Vec<(&'static str, String)>)> =
        lessons::lessons().into_iter().flat_map(|l| cases(&l).into_iter().map(move |c| (l.clone(), c))).collect();
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get()).min(4);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let lines = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((l, c)) = all.get(i) else { break };
                let line = std::panic::catch_unwind(|| check_case(l, c)).map_err(|e| {
                    e.downcast_ref::<String>()
                        .cloned()
                        .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_default()
                });
                lines.lock().unwrap().push(line);
            });
        }
    });
    let lines = lines.into_inner().unwrap();
    let failed: Vec<&String> = lines.iter().filter_map(|l| l.as_ref().err()).collect();
    assert!(
        failed.is_empty(),
        "{} of {} cases failed:\n{}",
        failed.len(),
        lines.len(),
        failed.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n")
    );
    // Each lesson's grid: 5 values per slider, both toggle values, every corner.
    assert!(lines.len() >= 60, "{}", lines.len());
    for l in lessons::lessons() {
        let o = lessons::open(&l, &[]).unwrap();
        for c in &l.controls {
            // The lesson's own value is a stop of its slider (the thumb can show it).
            if let ControlKind::Slider { stops, .. } = &c.kind {
                let v = o.defaults[c.path].as_f64().unwrap();
                assert!(
                    stops.iter().any(|s| (s - v).abs() <= 1e-9 * v.abs().max(1e-12)),
                    "{} {}: {v} not in {stops:?}",
                    l.name,
                    c.path
                );
            }
            assert!(
                grid(&c.kind).len() >= if matches!(c.kind, ControlKind::Toggle { .. }) { 2 } else { 5 },
                "{} {}",
                l.name,
                c.path
            );
        }
    }
}

/// The numbers the engines lesson's story states (a constant text) are the scenario's.
#[test]
fn the_engines_story_states_the_scenarios_rating_and_efficiency() {
    let l = lessons::lesson("engines").unwrap();
    let o = lessons::open(&l, &[]).unwrap();
    let rated = o.scenario.plant.turbine.rated_power_w;
    let eta = o.scenario.seakeeping.turbine_rated_efficiency;
    assert!(l.story.contains(&format!("each rated {} MW", rated / 1e6)), "{rated}: {}", l.story);
    assert!(l.story.contains(&format!("({:.0} % of the fuel's energy)", 100.0 * eta)), "{eta}: {}", l.story);
    assert_eq!(o.scenario.plant.online.sets, vec![1, 2, 3, 4], "the lesson's own value is all four");
    let one = lessons::open(&l, &[("plant.online.sets", "[1]")]).unwrap();
    assert!(one.refused.is_empty(), "{:?}", one.refused);
    assert_eq!(one.scenario.plant.online.sets, vec![1]);
}

#[test]
fn a_link_value_outside_a_control_is_refused_with_its_range_and_the_default_used() {
    let l = lessons::lesson("waves").unwrap();
    let o = lessons::open(&l, &[("sea.sea_state", "9"), ("ship.hull.hub_above_base_m", "1.15")]).unwrap();
    assert_eq!(o.refused.len(), 1, "{:?}", o.refused);
    assert!(o.refused[0].contains("9 is outside this lesson's range, 2 to 6"), "{}", o.refused[0]);
    assert_eq!(o.values["sea.sea_state"], o.defaults["sea.sea_state"]);
    assert_eq!(o.scenario.sea.sea_state, 6);
    assert_eq!(o.values["ship.hull.hub_above_base_m"], 1.15);
    let b = lessons::lesson("braking").unwrap();
    let o = lessons::open(&b, &[("plant.dc_link.brake_resistor_ohm", "5")]).unwrap();
    assert_eq!(o.refused.len(), 1);
    assert_eq!(o.values["plant.dc_link.brake_resistor_ohm"], "1");
}

/// A link's text that is no number is called that (with the range), not "outside the range"; a
/// value between two stops is moved to the nearest and said, and a stop itself is not.
#[test]
fn a_link_value_that_is_no_number_is_said_so_and_a_snapped_value_is_said() {
    let l = lessons::lesson("turn").unwrap();
    let o = lessons::open(&l, &[("commands.1.heading_deg", "abc")]).unwrap();
    assert_eq!(o.refused.len(), 1, "{:?}", o.refused);
    assert!(o.refused[0].contains("\"abc\" is not a number; this lesson's range is 15 to 180 deg"), "{}", o.refused[0]);
    assert!(!o.refused[0].contains("outside"), "{}", o.refused[0]);
    let o = lessons::open(&l, &[("commands.1.heading_deg", "NaN")]).unwrap();
    assert!(o.refused[0].contains("is not a number"), "{}", o.refused[0]);
    let o = lessons::open(&l, &[("commands.1.heading_deg", "100")]).unwrap();
    assert!(o.refused.is_empty(), "{:?}", o.refused);
    assert_eq!(o.values["commands.1.heading_deg"], 105.0);
    assert_eq!(o.snapped.len(), 1, "{:?}", o.snapped);
    assert!(
        o.snapped[0].contains("100 deg lies between this lesson's stops; the nearest, 105 deg, is used"),
        "{}",
        o.snapped[0]
    );
    let o = lessons::open(&l, &[("commands.1.heading_deg", "105")]).unwrap();
    assert!(o.snapped.is_empty() && o.refused.is_empty(), "{:?} {:?}", o.snapped, o.refused);
}
