//! The verdict on a prediction about a change: a lesson whose question is about a change keeps
//! the run before as its reference; the run after the change is compared with it on the one
//! number the question is about (its [`Reading`]), and the answer the two runs show is said with
//! both numbers side by side, or "about the same" when they differ by no more than the margin.

use super::facts::{
    col, energy, f, nearest, onsets, stat, submerged, value_text, window, Measure, Relation, Run, Stat, Verdict,
};
use super::{as_text, Control, ControlKind, Lesson};
use crate::signals::Signal;
use serde::Deserialize;

/// The run before a change, as the page keeps it: its controls' values, its reading and the
/// answer the student chose (None: skipped), so the run after can be compared with it.
#[derive(Debug, Clone, Deserialize)]
pub struct Before {
    pub values: serde_json::Map<String, serde_json::Value>,
    pub reading: f64,
    #[serde(default)]
    pub answer: Option<usize>,
}

/// What a lesson's question is about: the controls it changes and the reading that decides it.
#[derive(Debug, Clone)]
pub(super) struct Change {
    /// The controls of the question (moved the same way; any other kept).
    pub paths: &'static [&'static str],
    /// Each path's short name in the verdict ("" for a toggle, whose label says it).
    pub names: &'static [&'static str],
    /// The reading in words (a noun phrase that takes a number after it, e.g. "surface-loss
    /// onsets"), its unit as shown, the scale shown (1e6 for MW) and its digits.
    pub what: &'static str,
    pub unit: &'static str,
    pub scale: f64,
    pub digits: usize,
    /// The reading of a run of this scenario.
    pub measure: fn(&serde_json::Value) -> Measure,
    /// Readings closer than this are "about the same".
    pub by: f64,
    /// The answer that the reading of the run nearer the question's change (`toward`; for a
    /// slider its higher value, for a toggle its later value) against the other's (`away`)
    /// shows, or why the runs cannot tell.
    pub decide: fn(away: f64, toward: f64, by: f64) -> Result<usize, &'static str>,
    /// How to make the question's change, said when another control was moved.
    pub hint: &'static str,
    /// What each answer means for any two settings of the question's controls, where the runs
    /// may compare other settings than the question's two ("fewer sets burn less" for "one
    /// carrying the whole load" when the runs are four sets against two); empty: the answers.
    pub shown: &'static [&'static str],
}

/// The usual decision: more (beyond the margin) is answer `more`, less is `less`, about the same
/// is `same`.
pub(super) fn by_relation(away: f64, toward: f64, by: f64, [more, less, same]: [usize; 3]) -> usize {
    match Relation::of(toward, away, by) {
        Relation::More => more,
        Relation::Less => less,
        Relation::About => same,
    }
}

/// A question answered by the count of surface-loss onsets: more after the change (beyond one,
/// which a small change of depth does by chance) is the first answer, fewer the second, about the
/// same the third (`waves` and `sign`).
pub(super) fn onsets_change(
    paths: &'static [&'static str],
    names: &'static [&'static str],
    hint: &'static str,
) -> Change {
    Change {
        paths,
        names,
        what: "surface-loss onsets",
        unit: "",
        scale: 1.0,
        digits: 0,
        measure: |_| Measure::Onsets,
        by: 1.0,
        decide: |away, toward, by| Ok(by_relation(away, toward, by, [0, 1, 2])),
        hint,
        shown: &[],
    }
}

/// A measure of a run (the same as the promise's; tests/lessons.rs has its own).
pub fn measure(run: &Run, m: &Measure) -> f64 {
    let t = run.trace.get(Signal::TS);
    let end = t.last().copied().unwrap_or(0.0);
    match m {
        Measure::Stat { signals, stat: s, from_s } => stat(run.trace, signals, *s, *from_s, end).0,
        Measure::Rise { signal, from_s } => {
            stat(run.trace, &[signal], Stat::Max, *from_s, end).0 - col(run.trace, signal)[nearest(t, *from_s)]
        }
        Measure::Swing { signal, from_s } => {
            stat(run.trace, &[signal], Stat::Max, *from_s, end).0
                - stat(run.trace, &[signal], Stat::Min, *from_s, end).0
        }
        Measure::Onsets => onsets(run.trace, submerged(&run.scenario.to_value())) as f64,
        Measure::Mean { signal, from_s } => {
            let c = col(run.trace, signal);
            let w = window(t, *from_s, end);
            let n = w.len().max(1) as f64;
            w.map(|i| c[i]).sum::<f64>() / n
        }
        Measure::Energy { signal, from_s } => energy(run.trace, signal, *from_s, end),
    }
}

/// A control's position in its own order (a slider's value, a toggle's index).
fn position(c: &Control, v: &serde_json::Value) -> Option<f64> {
    match &c.kind {
        ControlKind::Slider { .. } => v.as_f64().or_else(|| v.as_str()?.trim().parse().ok()),
        ControlKind::Toggle { values, .. } => values.iter().position(|x| *x == as_text(v)).map(|i| i as f64),
    }
}

/// A control's value as the verdict says it ("hub 2.65 m", "no brake resistor").
fn said(c: &Control, name: &str, v: &serde_json::Value) -> String {
    match &c.kind {
        ControlKind::Toggle { values, labels, .. } => {
            let t = as_text(v);
            let label = values.iter().position(|x| *x == t).map_or(t.clone(), |i| labels[i].to_string());
            if name.is_empty() {
                label
            } else {
                format!("{name} {label}")
            }
        }
        ControlKind::Slider { .. } => {
            let x = position(c, v).unwrap_or(f64::NAN);
            let unit = if c.unit.is_empty() { String::new() } else { format!(" {}", c.unit) };
            if name.is_empty() {
                format!("{}{unit}", value_text(x))
            } else {
                format!("{name} {}{unit}", value_text(x))
            }
        }
    }
}

/// A control's label as a name inside a sentence: the words before its first parenthesis or colon,
/// first letter lower-cased ("Sea state (2: smooth ...)" -> "sea state"); a control that moved
/// besides the question's own is said by this name, never by an empty one.
fn short_label(c: &Control) -> String {
    let cut = c.label.find(['(', ':']).unwrap_or(c.label.len());
    let words = c.label[..cut].trim();
    let mut chars = words.chars();
    match chars.next() {
        Some(first) => first.to_lowercase().chain(chars).collect(),
        None => c.path.to_string(),
    }
}

/// Values equal as a control reads them (1e-9 relative for numbers).
fn same(c: &Control, a: Option<&serde_json::Value>, b: Option<&serde_json::Value>) -> bool {
    match (a.and_then(|a| position(c, a)), b.and_then(|b| position(c, b))) {
        (Some(x), Some(y)) => (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1e-12),
        _ => a == b,
    }
}

/// The verdict of lesson `l` on the change from `before` to the run now (`values`, `reading`),
/// or None when the lesson's question is not about a change or nothing changed.
pub(super) fn verdict(
    l: &Lesson,
    before: &Before,
    values: &serde_json::Map<String, serde_json::Value>,
    reading: f64,
) -> Option<Verdict> {
    let ch = l.change.as_ref()?;
    let moved: Vec<&Control> =
        l.controls.iter().filter(|c| !same(c, before.values.get(c.path), values.get(c.path))).collect();
    if moved.is_empty() {
        return None;
    }
    let num = |x: f64| {
        let unit = if ch.unit.is_empty() { String::new() } else { format!(" {}", ch.unit) };
        format!("{}{unit}", f(x / ch.scale, ch.digits))
    };
    let ours: Vec<(&Control, &str)> = ch
        .paths
        .iter()
        .zip(ch.names)
        .filter_map(|(p, n)| l.controls.iter().find(|c| c.path == *p).map(|c| (c, *n)))
        .collect();
    let context = |vals: &serde_json::Map<String, serde_json::Value>| {
        let parts: Vec<String> = ours
            .iter()
            .filter(|(c, _)| moved.iter().any(|m| m.path == c.path))
            .map(|(c, n)| said(c, n, vals.get(c.path).unwrap_or(&serde_json::Value::Null)))
            .collect();
        parts.join(", ")
    };
    let others: Vec<String> = moved.iter().filter(|m| !ch.paths.contains(&m.path)).map(|m| short_label(m)).collect();
    // The question's controls that moved, and which way (up the control's order or down).
    let ways: Vec<f64> = ours
        .iter()
        .filter_map(|(c, _)| {
            let (a, b) = (before.values.get(c.path).and_then(|v| position(c, v))?, position(c, values.get(c.path)?)?);
            (a != b).then_some(if b > a { 1.0 } else { -1.0 })
        })
        .collect();
    let predicted = before.answer.and_then(|i| l.answers.get(i)).map(|a| format!("You predicted: {a}. "));
    let predicted = predicted.unwrap_or_default();
    let relation_now = Relation::of(reading, before.reading, ch.by);
    let numbers = |ctx_before: String, ctx_now: String| {
        format!(
            "{}: {} before ({ctx_before}), {} now ({ctx_now}).",
            capital(ch.what),
            num(before.reading),
            num(reading)
        )
    };
    let mut v = Verdict {
        text: String::new(),
        before: before.reading,
        now: reading,
        by: ch.by,
        relation: relation_now,
        right: None,
        answer: before.answer,
        agrees: None,
    };
    if !others.is_empty() || ways.is_empty() || ways.iter().any(|w| *w != ways[0]) {
        let why = if ways.is_empty() {
            format!("This change is not the one the question is about ({}).", ch.hint)
        } else if !others.is_empty() {
            format!(
                "The two runs differ in more than the question's change ({} moved too), so they cannot answer it: change one thing at a time.",
                others.join("; ")
            )
        } else {
            "One of the question's controls went up and another down: move them the same way.".to_string()
        };
        let ctx = |vals: &serde_json::Map<String, serde_json::Value>| {
            let parts: Vec<String> = moved
                .iter()
                .map(|c| {
                    // A toggle's choice names itself ("no brake resistor"); a slider's number needs its name.
                    let name = match c.kind {
                        ControlKind::Slider { .. } => short_label(c),
                        ControlKind::Toggle { .. } => String::new(),
                    };
                    said(c, &name, vals.get(c.path).unwrap_or(&serde_json::Value::Null))
                })
                .collect();
            parts.join(", ")
        };
        v.text = format!("{predicted}{why} {}", numbers(ctx(&before.values), ctx(values)));
        return Some(v);
    }
    // The run nearer the question's change is the later one in the control's order.
    let (away, toward) = if ways[0] > 0.0 { (before.reading, reading) } else { (reading, before.reading) };
    let nums = numbers(context(&before.values), context(values));
    let about = if Relation::of(toward, away, ch.by) == Relation::About {
        format!(" They differ by no more than {}: about the same.", num(ch.by))
    } else {
        String::new()
    };
    match (ch.decide)(away, toward, ch.by) {
        Ok(right) => {
            v.right = Some(right);
            v.agrees = before.answer.map(|a| a == right);
            let shows = l.answers[right];
            let end = match (ch.shown.get(right), before.answer) {
                (None, Some(a)) if a == right => format!("The runs agree with your prediction: {shows}."),
                (None, Some(a)) => format!("The runs show \"{shows}\", not \"{}\".", l.answers[a]),
                (None, None) => format!("The runs show: {shows}."),
                (Some(general), Some(a)) if a == right => {
                    format!("The runs show {general}, as your prediction \"{shows}\" says.")
                }
                (Some(general), Some(a)) => {
                    format!("The runs show {general}, the way of \"{shows}\", not \"{}\".", l.answers[a])
                }
                (Some(general), None) => format!("The runs show {general}, the way of \"{shows}\"."),
            };
            v.text = format!("{predicted}{nums}{about} {end}");
        }
        Err(why) => v.text = format!("{predicted}{nums}{about} {why}"),
    }
    Some(v)
}

fn capital(s: &str) -> String {
    let mut c = s.chars();
    c.next().map(|x| x.to_uppercase().chain(c).collect()).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::lessons::{lessons, open};

    /// Another value of control `c` than `v`: the next stop or choice (the previous one at the end).
    fn other(c: &Control, v: &serde_json::Value) -> serde_json::Value {
        match &c.kind {
            ControlKind::Slider { stops, .. } => {
                let x = position(c, v).unwrap();
                let i = stops.iter().position(|s| (s - x).abs() <= 1e-9 * s.abs().max(1e-12)).unwrap_or(0);
                let j = if i + 1 < stops.len() { i + 1 } else { i - 1 };
                serde_json::json!(stops[j])
            }
            ControlKind::Toggle { values, .. } => {
                let i = position(c, v).unwrap() as usize;
                serde_json::json!(values[(i + 1) % values.len()])
            }
        }
    }

    /// Every control of every change lesson, moved alone or beside the question's own: the verdict
    /// names each value it prints (it printed "5 before ( 6), 7 now ( 5)" for a control that was
    /// not the question's), and never says NaN.
    #[test]
    fn a_verdict_names_every_value_it_says() {
        let mut checked = 0;
        for l in lessons().iter().filter(|l| l.change.is_some()) {
            let defaults = open(l, &[]).unwrap().defaults;
            let question = l.change.as_ref().unwrap().paths[0];
            for c in &l.controls {
                let mut now = defaults.clone();
                now.insert(c.path.to_string(), other(c, &defaults[c.path]));
                if c.path != question {
                    // Beside the question's change: the "more than one change" sentence.
                    let q = l.controls.iter().find(|k| k.path == question).unwrap();
                    now.insert(q.path.to_string(), other(q, &defaults[q.path]));
                }
                let before = Before { values: defaults.clone(), reading: 5.0, answer: Some(0) };
                let v = verdict(l, &before, &now, 7.0).expect("a moved control gives a verdict");
                for bad in ["( ", "(, ", " , ", "NaN", "()"] {
                    assert!(!v.text.contains(bad), "lesson {} moving {}: {bad:?} in {:?}", l.name, c.path, v.text);
                }
                if l.name == "waves" && c.path == "sea.sea_state" {
                    assert!(v.text.contains("(sea state moved too)"), "{}", v.text);
                    assert!(
                        v.text.contains("5 before (sea state 6, propeller hub above the keel 2.65 m)"),
                        "{}",
                        v.text
                    );
                }
                checked += 1;
            }
        }
        assert!(checked >= 8, "only {checked} controls checked");
    }
}
