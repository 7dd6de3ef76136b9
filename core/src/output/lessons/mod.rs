//! The lessons of the page (a few controls on one study, a question, an explanation): their
//! definitions and the claims each run supports. One owner for both the page (through the wasm)
//! and the native test that checks every claim against the run's own trace over a grid of
//! control values (tests/lessons.rs).
//!
//! A claim is data ([`Fact`]): a statistic of named signals over a named window, a count of
//! surface-loss onsets, an energy, or a comparison of two of them. The sentences are written from
//! the facts, and a sentence is only chosen when its fact holds (a rise is called a rise only
//! when the window's peak exceeds its start by the stated margin). "Try this next" names the
//! values to set and the effect promised ([`Promise`]), which the test checks by running them.
//!
//! One file per lesson holds its definition and its explainer, registered by one line in
//! [`lessons`]; `facts` holds the fact language. A lesson carries its own explainer, so a run is
//! always explained by the lesson it ran, and an unknown name is refused ([`lesson`]).

use crate::checks::shorten;
use crate::scenario::presets::preset;
use crate::scenario::Scenario;
use serde::Serialize;

mod battery;
mod braking;
mod bus;
mod engines;
mod facts;
mod power;
mod sign;
mod stopping;
mod turn;
mod verdict;
mod waves;

use facts::Book;
pub use facts::{energy, onsets, stat, Explanation, Fact, Measure, Next, Promise, Relation, Run, Stat};
pub use facts::{Reading, Verdict};
pub use verdict::{measure, Before};

/// A control of a lesson.
#[derive(Debug, Clone, Serialize)]
pub struct Control {
    /// The scenario path the control sets (a link's key; a maneuver order is `commands.N.*` with
    /// its index).
    pub path: &'static str,
    /// Paths set to the same value (the ordered speed with the initial speed, so the ship starts
    /// steady instead of settling to its order while the story happens).
    pub with_paths: &'static [&'static str],
    /// Plain words.
    pub label: &'static str,
    /// Shown after the value ("" for none; a ratio says so in `label`).
    pub unit: &'static str,
    #[serde(flatten)]
    pub kind: ControlKind,
}

#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ControlKind {
    /// A slider over `stops`, its values in order (the thumb's positions: the label shows the
    /// stop under the thumb). `log`: the stops are equal steps in decades.
    Slider { stops: Vec<f64>, log: bool },
    /// One of `values` (each with its label and the settings that go with it).
    Toggle {
        values: &'static [&'static str],
        labels: &'static [&'static str],
        settings: &'static [&'static [(&'static str, &'static str)]],
    },
}

/// A lesson.
#[derive(Debug, Clone, Serialize)]
pub struct Lesson {
    pub name: &'static str,
    pub title: &'static str,
    pub preset: &'static str,
    /// Settings of the lesson over its preset (the run's length).
    pub set: &'static [(&'static str, &'static str)],
    /// What the lesson is about, in plain words, before anything runs.
    pub story: &'static str,
    pub controls: Vec<Control>,
    pub question: &'static str,
    pub answers: &'static [&'static str],
    /// Plot ids of the page (www/js/config.js PLOTS) and its live view.
    pub plots: &'static [&'static str],
    pub view: &'static str,
    /// What a finished run shows (the lesson's own file writes it).
    #[serde(skip)]
    explain: Explainer,
    /// The change the question is about and the reading that decides it (None: one run answers).
    #[serde(skip)]
    change: Option<verdict::Change>,
}

/// Writes a lesson's explanation of a run into the book.
type Explainer = fn(&mut Book, &Given) -> Explanation;

/// What an explainer is given besides the run: the controls' values and the run's scenario.
struct Given<'a> {
    values: &'a serde_json::Map<String, serde_json::Value>,
    /// The lesson's own values (a "back to" names them, never a number typed twice).
    defaults: serde_json::Map<String, serde_json::Value>,
    sc: serde_json::Value,
}

impl Given<'_> {
    /// A control's number (a number, or text that reads as one; NaN when absent).
    fn num(&self, p: &str) -> f64 {
        self.values.get(p).and_then(|v| v.as_f64().or_else(|| v.as_str()?.parse().ok())).unwrap_or(f64::NAN)
    }
    /// A control's choice ("" when absent).
    fn text(&self, p: &str) -> String {
        self.values.get(p).and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
    }
}

const SPEED_KN: &str = "initial.speed_kn";
const ORDER_KN: &[&str] = &["commands.0.speed_kn"];

fn slider(path: &'static str, label: &'static str, unit: &'static str, lo: f64, hi: f64, step: f64) -> Control {
    // Rounded to a millionth so that 0.15 + 10 x 0.25 reads 2.65.
    let n = libm::round((hi - lo) / step) as usize;
    let stops = (0..=n).map(|k| libm::round((lo + step * k as f64) * 1e6) / 1e6).collect();
    Control { path, with_paths: &[], label, unit, kind: ControlKind::Slider { stops, log: false } }
}

/// A slider in decades from `lo` to `hi` in the 1-2-5 steps of a meter's ranges (1e-4, 2e-4,
/// 5e-4, 1e-3 ...): a gain's effect shows on a log scale, and every stop reads short.
fn decades(path: &'static str, label: &'static str, unit: &'static str, lo: f64, hi: f64) -> Control {
    let first = libm::floor(libm::log10(lo)) as i32;
    let last = libm::ceil(libm::log10(hi)) as i32;
    let stops = (first..=last)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| format!("{m}e{e}").parse::<f64>().unwrap_or(f64::NAN)))
        .filter(|x| *x >= lo * (1.0 - 1e-9) && *x <= hi * (1.0 + 1e-9))
        .collect();
    Control { path, with_paths: &[], label, unit, kind: ControlKind::Slider { stops, log: true } }
}

fn speed(lo: f64, hi: f64) -> Control {
    Control { with_paths: ORDER_KN, ..slider(SPEED_KN, "Ship speed (start and order)", "kn", lo, hi, 1.0) }
}

/// Every lesson, in the order the index lists them: one line per lesson, whose file holds it.
pub fn lessons() -> Vec<Lesson> {
    vec![
        power::lesson(),
        waves::lesson(),
        turn::lesson(),
        braking::lesson(),
        bus::lesson(),
        engines::lesson(),
        sign::lesson(),
        battery::lesson(),
        stopping::lesson(),
    ]
}

/// The lesson of that name; another name is refused with the names there are.
pub fn lesson(name: &str) -> Result<Lesson, String> {
    let all = lessons();
    let names: Vec<&str> = all.iter().map(|l| l.name).collect();
    let refused = format!("no lesson named '{}' (try: {})", shorten(name), names.join(", "));
    all.into_iter().find(|l| l.name == name).ok_or(refused)
}

/// A lesson's scenario for the given control values (text, as a link carries them): a value
/// outside the control's span, or not one of its values, is refused with a message and the
/// lesson's own value is used.
#[derive(Debug, Clone, Serialize)]
pub struct Opened {
    #[serde(skip)]
    pub scenario: Scenario,
    /// The values used, by control path (numbers as JSON numbers, choices as text).
    pub values: serde_json::Map<String, serde_json::Value>,
    /// The values used when no link sets them.
    pub defaults: serde_json::Map<String, serde_json::Value>,
    /// One sentence per refused value.
    pub refused: Vec<String>,
    /// One sentence per value moved to the slider's nearest stop (a link's 100 deg between stops
    /// 90 and 105 is run as 105 deg, and the page says so).
    pub snapped: Vec<String>,
}

/// The value at a dotted path of a scenario's JSON.
fn at_path<'a>(v: &'a serde_json::Value, path: &str) -> Option<&'a serde_json::Value> {
    path.split('.').try_fold(v, |v, k| match v {
        serde_json::Value::Array(a) => a.get(k.parse::<usize>().ok()?),
        _ => v.get(k),
    })
}

fn number(v: &serde_json::Value, path: &str) -> f64 {
    at_path(v, path).and_then(|x| x.as_f64()).unwrap_or(f64::NAN)
}

impl Control {
    /// A value (text) if the control allows it.
    fn accept(&self, text: &str) -> Result<serde_json::Value, String> {
        match &self.kind {
            ControlKind::Toggle { values, labels, .. } => values
                .iter()
                .position(|v| *v == text)
                .map(|i| serde_json::Value::from(values[i]))
                .ok_or_else(|| format!("{}: \"{}\" is not one of {}", self.label, shorten(text), labels.join(", "))),
            ControlKind::Slider { stops, log } => {
                let (lo, hi) = (stops[0], stops[stops.len() - 1]);
                match text.trim().parse::<f64>() {
                    // A value inside the span moves to the nearest stop (the thumb shows it).
                    Ok(x) if x.is_finite() && x >= lo * (1.0 - 1e-9) && x <= hi * (1.0 + 1e-9) => {
                        let d = |s: f64| if *log { (libm::log(s) - libm::log(x)).abs() } else { (s - x).abs() };
                        let best = stops.iter().copied().min_by(|a, b| d(*a).total_cmp(&d(*b))).unwrap_or(lo);
                        Ok(serde_json::Value::from(best))
                    }
                    // Text that is no number is told as such, not as a number out of range.
                    Ok(x) if !x.is_nan() => Err(format!(
                        "{}: {} is outside this lesson's range, {} to {}{}",
                        self.label,
                        shorten(text),
                        lo,
                        hi,
                        unit_after(self.unit)
                    )),
                    _ => Err(format!(
                        "{}: \"{}\" is not a number; this lesson's range is {} to {}{}",
                        self.label,
                        shorten(text),
                        lo,
                        hi,
                        unit_after(self.unit)
                    )),
                }
            }
        }
    }

    /// The (path, value text) pairs that a value sets.
    fn sets(&self, value: &serde_json::Value) -> Vec<(&'static str, String)> {
        let text = as_text(value);
        let mut out: Vec<(&'static str, String)> =
            std::iter::once(self.path).chain(self.with_paths.iter().copied()).map(|p| (p, text.clone())).collect();
        if let ControlKind::Toggle { values, settings, .. } = &self.kind {
            if let Some(i) = values.iter().position(|v| *v == text) {
                out.extend(settings.get(i).copied().unwrap_or_default().iter().map(|(p, v)| (*p, v.to_string())));
            }
        }
        out
    }
}

/// A JSON value as a link writes it (a whole number without its ".0").
/// The rate at which the scenario `sc`'s storage hands its power back near its floor \[W/s\]
/// (`plant::storage::handover_rate_w_per_s` with its turbines' rating and governor slew).
fn handover_rate(sc: &serde_json::Value) -> f64 {
    crate::plant::storage::handover_rate_w_per_s(
        crate::plant::layout::SETS_PER_SHAFT as f64,
        number(sc, "plant.turbine.rated_power_w"),
        number(sc, "controllers.governor.slew_rate_per_s"),
    )
}

fn as_text(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::String(s) => s.clone(),
        serde_json::Value::Number(n) => match n.as_f64() {
            Some(x) if x.fract() == 0.0 && x.abs() < 1e15 => format!("{}", x as i64),
            _ => n.to_string(),
        },
        v => v.to_string(),
    }
}

fn unit_after(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

/// Opens a lesson with the values a link gives (path, text).
pub fn open(l: &Lesson, given: &[(&str, &str)]) -> Result<Opened, String> {
    let base = preset(l.preset).ok_or_else(|| format!("lesson {}: no preset {}", l.name, l.preset))?;
    let base = base.with_overrides(l.set).map_err(|e| format!("lesson {}: {e}", l.name))?;
    let root = base.to_value();
    let mut defaults = serde_json::Map::new();
    let mut values = serde_json::Map::new();
    let mut refused = Vec::new();
    let mut snapped = Vec::new();
    let mut sets: Vec<(&str, String)> = Vec::new();
    for c in &l.controls {
        let own = at_path(&root, c.path).cloned().unwrap_or(serde_json::Value::Null);
        // A toggle's study value is one of its values (the resistor's 1 ohm); any other is its first.
        let own = match &c.kind {
            ControlKind::Toggle { values, .. } => {
                let t = as_text(&own);
                serde_json::Value::from(*values.iter().find(|v| **v == t).unwrap_or(&values[0]))
            }
            _ => own,
        };
        // A slider's study value moves to its stop, so the thumb and the label agree.
        let own = c.accept(&as_text(&own)).unwrap_or(own);
        defaults.insert(c.path.to_string(), own.clone());
        let v = match given.iter().find(|(p, _)| *p == c.path) {
            Some((_, text)) => match c.accept(text) {
                Ok(v) => {
                    let asked = text.trim().parse::<f64>().ok();
                    if let (Some(x), Some(used)) = (asked, v.as_f64()) {
                        if (used - x).abs() > 1e-9 * x.abs().max(1.0) {
                            snapped.push(format!(
                                "{}: {}{} lies between this lesson's stops; the nearest, {}{}, is used",
                                c.label,
                                shorten(text),
                                unit_after(c.unit),
                                as_text(&v),
                                unit_after(c.unit)
                            ));
                        }
                    }
                    v
                }
                Err(e) => {
                    refused.push(e);
                    own
                }
            },
            None => own,
        };
        sets.extend(c.sets(&v));
        values.insert(c.path.to_string(), v);
    }
    let pairs: Vec<(&str, &str)> = sets.iter().map(|(p, v)| (*p, v.as_str())).collect();
    let scenario = base.with_overrides(&pairs).map_err(|e| format!("lesson {}: {e}", l.name))?;
    Ok(Opened { scenario, values, defaults, refused, snapped })
}

/// Checks the controls' values an explanation is written from (as `open` gives them): every
/// control of the lesson there with a value it takes, and nothing else; the error names the
/// first that is not (an explanation from a missing value read "Lower the hub to NaN m").
pub fn check_values(l: &Lesson, values: &serde_json::Map<String, serde_json::Value>) -> Result<(), String> {
    let paths: Vec<&str> = l.controls.iter().map(|c| c.path).collect();
    if let Some(k) = values.keys().find(|k| !paths.contains(&k.as_str())) {
        return Err(format!("{}: not a control of lesson {} (its controls: {})", shorten(k), l.name, paths.join(", ")));
    }
    for c in &l.controls {
        let v = values.get(c.path).ok_or_else(|| {
            format!("{}: missing: lesson {}'s explanation is written from each of its controls' values", c.path, l.name)
        })?;
        c.accept(&as_text(v)).map_err(|e| format!("{}: {e}", c.path))?;
    }
    Ok(())
}

/// Explains a finished run of lesson `l` (`values`: the controls' values, as `open` gives them)
/// by the lesson's own explainer.
pub fn explain(l: &Lesson, values: &serde_json::Map<String, serde_json::Value>, run: &Run) -> Explanation {
    explain_after(l, values, run, None)
}

/// Explains a run as [`explain`] does, with its reading (the number the question is about) and,
/// given the run before (its values, reading and the student's answer), the verdict on the
/// prediction.
pub fn explain_after(
    l: &Lesson,
    values: &serde_json::Map<String, serde_json::Value>,
    run: &Run,
    before: Option<&Before>,
) -> Explanation {
    let defaults = open(l, &[]).map(|o| o.defaults).unwrap_or_default();
    let given = Given { values, defaults, sc: run.scenario.to_value() };
    let mut e = (l.explain)(&mut Book::new(run), &given);
    if let Some(ch) = &l.change {
        let m = (ch.measure)(&given.sc);
        let value = measure(run, &m);
        e.verdict = before.and_then(|b| verdict::verdict(l, b, values, value));
        e.reading = Some(Reading { measure: m, value });
    }
    e
}

/// [`explain_after`] for a run from outside (the page's worker): refused, naming the lesson, when
/// the run does not give the lesson's facts (a run of another scenario, too short to reach the
/// lesson's order: its facts came out infinite or NaN, and the words read "the bus dipped to inf
/// pu"). A lesson's own run always gives them (tests/lessons.rs).
pub fn explain_checked(
    l: &Lesson,
    values: &serde_json::Map<String, serde_json::Value>,
    run: &Run,
    before: Option<&Before>,
) -> Result<Explanation, String> {
    let e = explain_after(l, values, run, before);
    // Every text of it (sentences, the verdict's words, "try this next") without a number that
    // is not one.
    fn words_hold(v: &serde_json::Value) -> bool {
        match v {
            serde_json::Value::String(s) => s
                .split(|c: char| c.is_whitespace() || matches!(c, '(' | ')' | ',' | ':' | ';' | '"'))
                .all(|w| !matches!(w.trim_end_matches('.'), "NaN" | "inf" | "-inf")),
            serde_json::Value::Array(a) => a.iter().all(words_hold),
            serde_json::Value::Object(m) => m.values().all(words_hold),
            _ => true,
        }
    }
    let words_hold = serde_json::to_value(&e).is_ok_and(|v| words_hold(&v));
    match crate::checks::check_finite(&e) {
        Ok(()) if words_hold => Ok(e),
        _ => Err(format!(
            "lesson {}: this run does not give the lesson's facts (a number of them is not finite): explain the \
             lesson's own run, as it opens",
            l.name
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closing fuzz run (issue 57): the bus lesson explaining a run of another scenario (a turn
    /// ended before the lesson's order: "the bus dipped to inf pu") is refused naming the lesson;
    /// its own run is explained.
    #[test]
    fn an_explanation_of_another_run_is_refused() {
        let l = lesson("bus").unwrap();
        let opened = open(&l, &[]).unwrap();
        let explain = |sc: &Scenario| {
            let r = crate::sim::run(sc).unwrap();
            let run = Run { scenario: sc, trace: &r.trace, summary: &r.summary };
            explain_checked(&l, &opened.values, &run, None).map(|e| e.sentences.len())
        };
        assert!(explain(&opened.scenario).unwrap() > 0);
        let mut turn = crate::scenario::presets::preset("turn-45").unwrap();
        turn.sim.duration_s = 5.0;
        let e = explain(&turn).unwrap_err();
        assert!(e.starts_with("lesson bus: this run does not give the lesson's facts"), "{e}");
    }

    /// Issue 57: an explanation is written only from the lesson's own values: the values `open`
    /// gives pass; one lacking the hub control, one with it not a number, one of another lesson's
    /// control are refused naming the control (the page wrote "Lower the hub to NaN m").
    #[test]
    fn an_explanation_needs_every_control_of_its_lesson() {
        let l = lesson("waves").unwrap();
        let opened = open(&l, &[]).unwrap();
        check_values(&l, &opened.values).unwrap();
        let hub = "ship.hull.hub_above_base_m";
        let mut lacking = opened.values.clone();
        lacking.remove(hub);
        let e = check_values(&l, &lacking).unwrap_err();
        assert!(e.starts_with(&format!("{hub}: missing")), "{e}");
        let mut nan = opened.values.clone();
        nan.insert(hub.into(), "NaN".into());
        assert!(check_values(&l, &nan).unwrap_err().starts_with(hub));
        let mut other = opened.values.clone();
        other.insert("plant.storage.energy_j".into(), 1.0.into());
        let e = check_values(&l, &other).unwrap_err();
        assert!(e.starts_with("plant.storage.energy_j: not a control of lesson waves"), "{e}");
    }
}
