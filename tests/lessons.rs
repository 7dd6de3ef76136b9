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
        Measure::Swing { signal, from_s } => {
            extreme(r, &[signal], Stat::Max, *from_s, end(r)) - extreme(r, &[signal], Stat::Min, *from_s, end(r))
        }
        Measure::Mean { signal, from_s } => {
            let rows = rows(r, *from_s, end(r));
            rows.iter().map(|&i| col(r, signal)[i]).sum::<f64>() / rows.len() as f64
        }
        Measure::Energy { signal, from_s } => energy(r, signal, *from_s, end(r)),
    }
}

/// The time integral of a power column over the rows in [from, to] [J], by the trapezoid rule.
fn energy(r: &RunResult, name: &str, from: f64, to: f64) -> f64 {
    let (t, p) = (col(r, "t_s"), col(r, name));
    let rows = rows(r, from, to);
    rows.windows(2).map(|w| 0.5 * (p[w[0]] + p[w[1]]) * (t[w[1]] - t[w[0]])).sum()
}

/// A question about a change: its controls, its margin, its decision (see `question`).
type Question = (&'static [&'static str], f64, fn(f64, f64, f64) -> Option<usize>);

/// The question each lesson about a change asks, as this test reads it: the controls of the
/// change, the margin of "about the same", and the answer a pair of readings shows (`away`: the
/// run lower in the control's order, `toward`: the higher; None: the runs cannot tell).
fn question(name: &str) -> Option<Question> {
    fn rel(away: f64, toward: f64, by: f64) -> Relation {
        Relation::of(toward, away, by)
    }
    Some(match name {
        // Raising the hub: more onsets is "more often".
        "waves" => (&["ship.hull.hub_above_base_m"], 1.0, |a, t, by| Some([0, 1, 2][rel(a, t, by) as usize])),
        // The printed sign: more onsets is "more often".
        "sign" => (&["seakeeping.stern_motion"], 1.0, |a, t, by| Some([0, 1, 2][rel(a, t, by) as usize])),
        // No resistor: the turbines speed up more is "back into the turbines"; else no answer.
        "braking" => {
            (&["plant.dc_link.brake_resistor_ohm"], 0.005, |a, t, by| (rel(a, t, by) == Relation::More).then_some(0))
        }
        // A larger gain: a higher lowest voltage is "dip less".
        "bus" => (&["controllers.field.kp", "controllers.field.ki"], 0.005, |a, t, by| {
            Some([0, 1, 2][rel(a, t, by) as usize])
        }),
        // Fewer sets: less fuel is "one carrying the whole load".
        "engines" => (&["plant.online.sets"], 0.4e6, |a, t, by| Some([1, 0, 2][rel(a, t, by) as usize])),
        // More battery: a swing smaller by the margin is steadier, under a quarter "almost vanishes".
        "battery" => (&["plant.storage.energy_j"], 0.002, |a, t, by| {
            Some(match rel(a, t, by) {
                Relation::Less if t < 0.25 * a => 0,
                Relation::Less => 1,
                _ => 2,
            })
        }),
        // More storage: less brake energy is "it falls", more "it rises", else "about the same".
        "stopping" => (&["plant.storage.energy_j"], 1.0e6, |a, t, by| Some([2, 0, 1][rel(a, t, by) as usize])),
        _ => return None,
    })
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
        Fact::Energy { signal, from_s, to_s, value_j } => {
            let own = energy(r, signal, *from_s, *to_s);
            assert!(
                (own - value_j).abs() <= 1e-9 * own.abs().max(1.0),
                "{what}: fact {i} {:?} says {value_j} J, the trace {own} J",
                facts[i]
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
        // The plant's health check quoted whole is the run summary's own sentence (its numbers
        // are the health module's, checked by its tests): the words before it are the lesson's.
        let text = &text.split("the plant's health check: ").next().unwrap_or_default().to_string();
        let relations: Vec<Relation> = ids
            .iter()
            .filter_map(|&i| match &e.facts[i] {
                Fact::Compare { relation, .. } => Some(*relation),
                _ => None,
            })
            .collect();
        for (word, rels) in WORDS {
            if text.contains(word) {
                assert!(
                    rels.iter().any(|r| relations.contains(r)),
                    "{what}: \"{text}\" says '{word}' without a {rels:?} comparison: {relations:?}"
                );
            }
        }
        // At the rating: giving at it (not below) or taking at it (not above its negative).
        if text.contains("were at their rating") {
            assert!(
                relations.len() == 2 && (relations[0] != Relation::Less || relations[1] != Relation::More),
                "{what}: \"{text}\": {relations:?}"
            );
        }
        if text.contains("still at") && text.contains("below its band") {
            assert!(relations.iter().any(|r| *r != Relation::More), "{what}: \"{text}\"");
        }
        for (word, need) in STATED {
            if text.contains(word) {
                let has = ids.iter().any(|&i| match (&e.facts[i], need) {
                    (Fact::Stat { stat, .. }, Some(s)) => stat == s,
                    (Fact::Onsets { .. }, None) => true,
                    _ => false,
                });
                assert!(has, "{what}: \"{text}\" says '{word}' without a {need:?} fact");
            }
        }
        // Every word of quantity is one of the phrases checked above, or plain words listed as such.
        let mut rest = format!(" {} ", text.to_lowercase());
        // The longest phrase first ("stalled (below" before "stalled").
        let mut phrases: Vec<&str> =
            WORDS.iter().map(|(w, _)| *w).chain(STATED.iter().map(|(w, _)| *w)).chain(PLAIN.iter().copied()).collect();
        phrases.sort_by_key(|p| std::cmp::Reverse(p.len()));
        for p in phrases {
            rest = rest.replace(&p.to_lowercase(), " ");
        }
        let left: Vec<&str> =
            rest.split(|c: char| !c.is_alphanumeric() && c != '\'').filter(|w| QUANTITY.contains(w)).collect();
        assert!(left.is_empty(), "{what}: \"{text}\" says {left:?}, words of quantity no fact checks");
    }
}

/// Words of quantity: a sentence may say one only inside a phrase this file checks.
const QUANTITY: &[&str] = &[
    "about", "little", "much", "most", "almost", "nearly", "hardly", "same", "back", "still", "held", "hold", "holds",
    "stayed", "stay", "stays", "within", "rose", "rise", "rises", "fell", "fall", "falls", "sped", "slowed", "stalled",
    "above", "below", "between", "reserve", "largest", "higher", "lower", "steadier", "there", "never", "far", "near",
    "nearer", "more", "less", "up", "down", "under", "over", "only", "least", "swing", "twice", "half",
];

/// Phrases of quantity that rest on a comparison of the sentence's facts, one of these ways.
const WORDS: &[(&str, &[Relation])] = &[
    ("rose from", &[Relation::More]),
    ("% more)", &[Relation::More]),
    ("slowed from", &[Relation::More]),
    ("sped up", &[Relation::More]),
    ("stayed within", &[Relation::About]),
    ("back at", &[Relation::More]),
    ("stalled", &[Relation::Less]),
    ("moved between", &[Relation::More]),
    ("held at", &[Relation::About]),
    ("hardly change", &[Relation::About]),
    ("holds its order", &[Relation::About]),
    ("is still at", &[Relation::More, Relation::Less]),
    ("still speeding it up", &[Relation::More, Relation::Less]),
    ("that is below", &[Relation::Less]),
    ("stalled (below", &[Relation::Less]),
    ("kept between", &[Relation::More, Relation::About]),
    ("brought it back to", &[Relation::More]),
    ("has not brought it back", &[Relation::Less, Relation::About]),
    ("inside its band (above", &[Relation::More]),
    ("that is above", &[Relation::More]),
    ("below its band", &[Relation::Less]),
    ("above its band", &[Relation::About, Relation::More]),
    ("power in reserve", &[Relation::Less]),
    ("little is left in reserve", &[Relation::More, Relation::About]),
    ("reaches the rating", &[Relation::More, Relation::About]),
    ("gives less and less", &[Relation::Less, Relation::About]),
    ("points below", &[Relation::Less, Relation::About]),
    ("points above", &[Relation::Less, Relation::About]),
    ("point below", &[Relation::Less, Relation::About]),
    ("point above", &[Relation::Less, Relation::About]),
    ("after which it went astern", &[Relation::Less]),
    ("still had way ahead", &[Relation::About]),
    ("inside its band (up to", &[Relation::Less, Relation::About]),
    ("above its band's top", &[Relation::More]),
    ("above the 1.1 pu overspeed level", &[Relation::More]),
];

/// Phrases that state a statistic of the trace (Some: that statistic among the sentence's facts;
/// None: a count of onsets).
const STATED: &[(&str, Option<Stat>)] = &[
    ("went down to", Some(Stat::Min)),
    ("dipped to", Some(Stat::Min)),
    ("slowed to", Some(Stat::Min)),
    ("took up to", Some(Stat::Min)),
    ("gave up to", Some(Stat::Max)),
    ("and up to", Some(Stat::Max)),
    ("rose to", Some(Stat::Max)),
    ("fell to", Some(Stat::Min)),
    ("its highest", Some(Stat::Max)),
    ("highest", Some(Stat::Max)),
    ("lowest", Some(Stat::Min)),
    ("ran from", Some(Stat::Max)),
    ("returned up to", Some(Stat::Min)),
    ("a swing of", Some(Stat::Max)),
    ("the largest loss is", Some(Stat::At)),
    ("surface losses started", None),
    ("never lost thrust", None),
];

/// Words of quantity that say no amount of this run (the physics told, a level named, a place).
const PLAIN: &[&str] = &[
    "falls with its speed",
    "were at their rating",
    "each bus's block in the picture shows half",
    "for more than the turbines could give",
    "there is no battery",
    "take every swing of the load",
    "keeps back part of what it gets",
    "'s lower edge",
    "to make up for it",
    "the rudder is over",
    "extends the curve down",
    "flowed back through",
    "rise and fall with the waves",
    "over the run",
    "down to its lowest allowed charge",
    "take back the swings",
    "the rest of the swing",
    "takes more of each swing",
    "make it bigger",
    "a bigger storage does not help",
];

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
    let verdict = check_verdict(l, &o, &r, &e, &o2, &r2, submerged, &what);
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
    format!("{what}: right {:?}, next {:?}: {now:.3} -> {then:.3}; verdict {verdict:?}", e.right, e.next.set)
}

/// The run after "try this next" against the case's run as the run before: the reading of each
/// is the test's own measure of its trace, and the verdict's answer is the test's reading of the
/// question (only when the change is the question's alone); the verdict's words carry both
/// numbers. Returns the answer the verdict shows.
#[allow(clippy::too_many_arguments)]
fn check_verdict(
    l: &Lesson,
    o: &lessons::Opened,
    r: &RunResult,
    e: &Explanation,
    o2: &lessons::Opened,
    r2: &RunResult,
    submerged: f64,
    what: &str,
) -> Option<usize> {
    let Some((paths, by, decide)) = question(l.name) else {
        assert!(e.reading.is_none() && e.verdict.is_none(), "{what}: a reading in a lesson one run answers");
        return None;
    };
    let reading = e.reading.as_ref().unwrap_or_else(|| panic!("{what}: no reading"));
    let own = measure(r, &reading.measure, submerged);
    assert!(
        (own - reading.value).abs() <= 1e-12 * own.abs().max(1.0),
        "{what}: reading {} against {own}",
        reading.value
    );
    // The answer cycles over the answers with the case, so every verdict wording is met.
    let answer = Some(what.len() % l.answers.len());
    let before = lessons::Before { values: o.values.clone(), reading: reading.value, answer };
    let e2 = lessons::explain_after(
        l,
        &o2.values,
        &lessons::Run { scenario: &o2.scenario, trace: &r2.trace, summary: &r2.summary },
        Some(&before),
    );
    let now = measure(r2, &e2.reading.as_ref().unwrap().measure, submerged);
    let moved: Vec<&str> =
        l.controls.iter().filter(|c| o.values[c.path] != o2.values[c.path]).map(|c| c.path).collect();
    let Some(v) = e2.verdict else {
        assert!(moved.is_empty(), "{what}: no verdict after {moved:?} moved");
        return None;
    };
    assert!(
        v.before == reading.value && (v.now - now).abs() <= 1e-12 * now.abs().max(1.0),
        "{what}: {v:?}, measured {now}"
    );
    assert_eq!(v.by, by, "{what}: the margin");
    assert!(v.text.contains(" before (") && v.text.contains(" now ("), "{what}: {}", v.text);
    let ours = moved.iter().all(|p| paths.contains(p));
    // The question's change alone, all its controls moved the same way.
    let pos = |o: &lessons::Opened, p: &str| {
        let c = l.controls.iter().find(|c| c.path == p).unwrap();
        match &c.kind {
            ControlKind::Toggle { values, .. } => values.iter().position(|x| o.values[p] == *x).unwrap() as f64,
            _ => o.values[p].as_f64().unwrap(),
        }
    };
    let ways: BTreeSet<bool> = moved.iter().map(|p| pos(o2, p) > pos(o, p)).collect();
    if !ours || ways.len() != 1 {
        assert_eq!(v.right, None, "{what}: a verdict on a change that is not the question's: {}", v.text);
        return None;
    }
    let up = *ways.iter().next().unwrap();
    let (away, toward) = if up { (v.before, v.now) } else { (v.now, v.before) };
    let right = decide(away, toward, by);
    assert_eq!(v.right, right, "{what}: {away} -> {toward}: {}", v.text);
    assert_eq!(v.agrees, right.map(|k| Some(k) == answer), "{what}");
    match right {
        // A lesson whose runs may compare other settings than its question's two says what the
        // answer means for them ("the fewer sets burning less fuel, as your prediction ... says").
        Some(k) if Some(k) == answer => assert!(
            v.text.contains("agree with your prediction")
                || v.text.contains(&format!("as your prediction \"{}\" says", l.answers[k])),
            "{what}: {}",
            v.text
        ),
        Some(k) => assert!(
            v.text.contains(&format!("The runs show \"{}\"", l.answers[k]))
                || v.text.contains(&format!("the way of \"{}\", not", l.answers[k])),
            "{what}: {}",
            v.text
        ),
        None => {}
    }
    if Relation::of(toward, away, by) == Relation::About {
        assert!(v.text.contains("about the same"), "{what}: {}", v.text);
    }
    right
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
    // Every lesson about a change met its question's change and gave an answer somewhere on its grid.
    for l in lessons::lessons().iter().filter(|l| question(l.name).is_some()) {
        let met = lines.iter().flatten().any(|x| x.starts_with(&format!("{} ", l.name)) && x.contains("verdict Some("));
        assert!(met, "{}: no verdict with an answer over the grid", l.name);
    }
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

/// The numbers the stopping lesson's story states (a constant text) are its scenario's: the
/// approach speed it starts at, the crash stop's time, the diode rectifiers and the storages' rating; and a
/// storage of each size is the only change from the preset.
#[test]
fn the_stopping_story_states_the_scenarios_speed_order_and_rating() {
    let l = lessons::lesson("stopping").unwrap();
    let none = lessons::open(&l, &[]).unwrap();
    let sc = &none.scenario;
    assert_eq!(sc.plant.storage.energy_j, 0.0, "the lesson opens without storage");
    // "none" sets the rating back to the preset's own (a run after a storage keeps no rating).
    let own = aes_core::scenario::presets::preset("crash-stop").unwrap().plant.storage.power_w;
    assert_eq!(sc.plant.storage.power_w, own);
    let order = sc.commands.iter().find(|c| c.crash_stop).expect("the crash stop");
    for words in [
        format!("steams ahead ({} knots to start)", sc.initial.speed_kn),
        format!("At {} s the bridge orders full astern", order.t_s),
        "The diode rectifiers".to_string(),
    ] {
        assert!(l.story.contains(&words), "{words}: {}", l.story);
    }
    assert_eq!(sc.plant.dc_link.rectifier, aes_core::scenario::RectifierKind::Diode);
    let with = lessons::open(&l, &[("plant.storage.energy_j", "150000000")]).unwrap();
    let rated = with.scenario.plant.storage.power_w;
    assert!(l.story.contains(&format!("rated {} MW", rated / 1e6)), "{rated}: {}", l.story);
    let preset = aes_core::scenario::presets::preset("crash-stop-storage").unwrap();
    assert_eq!(
        (with.scenario.plant.storage.energy_j, rated),
        (preset.plant.storage.energy_j, preset.plant.storage.power_w)
    );
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

/// A study's "What to watch" (www/js/config.js) as the page shows it.
fn watch_text(study: &str) -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../www/js/config.js");
    let js = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let from = js.find(&format!("'{study}': {{")).unwrap_or_else(|| panic!("no study {study} in config.js"));
    let rest = &js[from..];
    let at = rest.find("watch: '").unwrap() + "watch: '".len();
    let mut out = String::new();
    let mut chars = rest[at..].chars();
    while let Some(c) = chars.next() {
        match c {
            '\\' => out.extend(chars.next()),
            '\'' => break,
            c => out.push(c),
        }
    }
    out
}

/// Every number the two head-seas studies' "What to watch" quote is their own run's, as printed
/// (rounded to the digits written); a number no row of this test checks fails it.
#[test]
fn the_head_seas_watch_texts_quote_their_own_runs() {
    use aes_core::scenario::presets::preset;
    for (study, quoted) in [
        (
            "head-seas-ss6-storage",
            &[
                ("stays between {} and", "turbine_speed_pu", "min", 3, 1.0),
                ("and {} pu and the bus", "turbine_speed_pu", "max", 3, 1.0),
                ("voltage between {} and", "bus_voltage_pu", "min", 2, 1.0),
                ("and {} pu (bus plot)", "bus_voltage_pu", "max", 2, 1.0),
                ("from {} MW charging", "storage_power_w", "-min", 0, 1e-6),
                ("to {} MW giving", "storage_power_w", "max", 0, 1e-6),
                ("starts at {} %", "storage_soc", "first", 0, 100.0),
                ("rises to {} %", "storage_soc", "max", 0, 100.0),
                ("falls to {} %", "storage_soc", "min", 0, 100.0),
                ("its {} % floor", "soc_min", "level", 0, 100.0),
            ][..],
        ),
        (
            "head-seas-ss6",
            &[
                ("(up to {} % with seed 1)", "turbine_speed_pu", "max-1", 0, 100.0),
                ("({} to", "bus_voltage_pu", "min", 2, 1.0),
                ("to {} pu)", "bus_voltage_pu", "max", 2, 1.0),
            ][..],
        ),
    ] {
        let text = watch_text(study);
        let sc = preset(study).unwrap();
        let r = run(&sc).unwrap();
        let mut said = Vec::new();
        for (phrase, signal, how, digits, scale) in quoted {
            let x = match *how {
                "level" => sc.plant.storage.soc_min,
                "first" => col(&r, signal)[0],
                "max-1" => extreme(&r, &[signal], Stat::Max, 0.0, end(&r)) - 1.0,
                "-min" => -extreme(&r, &[signal], Stat::Min, 0.0, end(&r)),
                "min" => extreme(&r, &[signal], Stat::Min, 0.0, end(&r)),
                _ => extreme(&r, &[signal], Stat::Max, 0.0, end(&r)),
            };
            let number = format!("{:.*}", *digits, x * scale);
            let words = phrase.replace("{}", &number);
            assert!(text.contains(&words), "{study}: the run gives \"{words}\"; the text says: {text}");
            said.push(number);
        }
        // Every number of the text is one of these, or a level named (h/R 1 and 1.1, seed 1), or
        // the swing with the propellers down (0.2 % and 2 %: another run, checked in
        // the_quarter_turn_and_crash_stop_watch_texts_quote_their_own_runs).
        let mut numbers: Vec<String> = Vec::new();
        let mut cur = String::new();
        for c in text.chars().chain(std::iter::once(' ')) {
            if c.is_ascii_digit() || (c == '.' && !cur.is_empty()) {
                cur.push(c);
            } else if !cur.is_empty() {
                numbers.push(cur.trim_end_matches('.').to_string());
                cur.clear();
            }
        }
        for n in numbers {
            let known = said.contains(&n) || ["1", "1.1", "0.2", "2"].contains(&n.as_str());
            assert!(known, "{study}: the text quotes {n}, which no row of this test checks: {text}");
        }
    }
}

/// The numbers in the other studies' "What to watch" that a run can give: the quarter turn in
/// sea state 6 (its mean added resistance against sea state 3's, and their ratio) and the crash
/// stop (the time from the order to the lowest ship speed), the thesis as printed (its heave and
/// its bus) and head-seas-ss6's swings with the
/// propellers kept down, each as its own preset's run prints
/// it. The wave heights of the quarter turn's text are the sea states' (Table 2.4), said beside
/// their square.
#[test]
fn the_quarter_turn_and_crash_stop_watch_texts_quote_their_own_runs() {
    use aes_core::scenario::presets::preset;
    let mean = |r: &RunResult, s: &str| col(r, s).iter().sum::<f64>() / col(r, s).len() as f64;
    let ss3 = run(&preset("quarter-turn-ss3").unwrap()).unwrap();
    let ss6 = run(&preset("quarter-turn-ss6").unwrap()).unwrap();
    let (m3, m6) = (mean(&ss3, "added_resistance_n"), mean(&ss6, "added_resistance_n"));
    let text = watch_text("quarter-turn-ss6");
    let words = format!(
        "About {:.0} times the mean added resistance of sea state 3 ({:.0} kN against {:.0} kN over the run)",
        m6 / m3,
        m6 / 1e3,
        m3 / 1e3
    );
    assert!(text.contains(&words), "the runs give \"{words}\"; the text says: {text}");
    let sq = |a: f64, b: f64| format!("({a:.1} m / {b:.1} m)^2 = {:.0}", (a / b) * (a / b));
    let heights = sq(aes_core::sea::waves::sea_state(6).unwrap().1, aes_core::sea::waves::sea_state(3).unwrap().1);
    assert!(text.contains(&heights), "the sea states give \"{heights}\"; the text says: {text}");

    // head-seas-ss6's swings "when the propellers stay down": its own run without surface losses,
    // the turbines' and the bus's highest less lowest over the run.
    let mut calm = preset("head-seas-ss6").unwrap();
    calm.seakeeping.surface_losses = false;
    let r = run(&calm).unwrap();
    let swing =
        |s: &str| 100.0 * (extreme(&r, &[s], Stat::Max, 0.0, end(&r)) - extreme(&r, &[s], Stat::Min, 0.0, end(&r)));
    let words = format!(
        "far beyond the {:.1} % (turbines) and {:.0} % (bus) they move in these seas when the propellers stay down",
        swing("turbine_speed_pu"),
        swing("bus_voltage_pu")
    );
    let text = watch_text("head-seas-ss6");
    assert!(text.contains(&words), "the run gives \"{words}\"; the text says: {text}");

    // The thesis as printed: the largest heave and the bus's set point, where the run starts.
    let r = run(&preset("as-printed").unwrap()).unwrap();
    let heave = col(&r, "heave_m").iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let text = watch_text("as-printed");
    for words in [
        format!("heaves by about {heave:.0} m in SS6"),
        format!("The bus starts at its set point, {:.1} kV", col(&r, "bus_voltage_v")[0] / 1e3),
    ] {
        assert!(text.contains(&words), "the run gives \"{words}\"; the text says: {text}");
    }

    let sc = preset("crash-stop").unwrap();
    let order = sc.commands.iter().find(|c| c.crash_stop).expect("the crash stop's order").t_s;
    let r = run(&sc).unwrap();
    let v = col(&r, "ship_speed_kn");
    let lowest = (0..v.len()).min_by(|&a, &b| v[a].total_cmp(&v[b])).unwrap();
    let words = format!("falls to zero about {:.0} s after the order", col(&r, "t_s")[lowest] - order);
    let text = watch_text("crash-stop");
    assert!(text.contains(&words), "the run gives \"{words}\"; the text says: {text}");
}

/// acceleration-lqg-ltr's "What to watch": the step of motor power it quotes (before the order,
/// against both motors' rating) and, on the thesis' own ship with equal weights, the bus held
/// within 5 %.
#[test]
fn the_lqg_watch_text_quotes_its_own_runs() {
    use aes_core::scenario::presets::preset;
    let sc = preset("acceleration-lqg-ltr").unwrap();
    let order = sc.commands[1].t_s;
    let r = run(&sc).unwrap();
    let before = value_at(&r, "p_motor_w", order) / (2.0 * sc.plant.motor.rated_power_w);
    let text = watch_text("acceleration-lqg-ltr");
    let words = format!("The step from {before:.2} to 1 pu of motor power");
    assert!(text.contains(&words), "the run gives \"{words}\"; the text says: {text}");
    let mut own = sc.clone();
    own.as_printed.table_5_ship = true;
    own.hull.forces = aes_core::ship::maneuvering::ManeuveringForces::Table23;
    own.controllers.lqg_ltr.turbine_speed_weight = 1.0;
    let r = run(&own).unwrap();
    let dip = 1.0 - extreme(&r, &["bus_voltage_pu"], Stat::Min, order, end(&r));
    assert!(text.contains("equal weights hold the bus within 5 %"), "{text}");
    assert!((0.0..0.05).contains(&dip), "the thesis' ship with equal weights dips {dip}");
}
