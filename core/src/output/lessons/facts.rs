//! The fact language of the lessons: a claim is data ([`Fact`]) measured from the run's trace,
//! and the sentences are written from the facts ([`Book`]); the words and sentences the
//! explainers share.

use super::number;
use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::summary::Summary;
use crate::sim::Trace;
use serde::Serialize;

/// A statistic of a window of a trace.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stat {
    /// The smallest value of any of the signals in the window.
    Min,
    /// The largest.
    Max,
    /// The value (of the one signal) at the row nearest the window's start.
    At,
}

/// How two numbers compare: `More` when a exceeds b by more than `by`, `Less` when b exceeds a by
/// more than `by`, `About` otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    More,
    Less,
    About,
}

impl Relation {
    pub fn of(a: f64, b: f64, by: f64) -> Relation {
        if a - b > by {
            Relation::More
        } else if b - a > by {
            Relation::Less
        } else {
            Relation::About
        }
    }
}

/// One claim an explanation makes, in the terms a test can check against the trace.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "fact", rename_all = "snake_case")]
pub enum Fact {
    /// `value` is the `stat` of `signals` over \[from_s, to_s\] (every signal the plot shows).
    /// `t_s`: the time of that value (the row's time for `At`).
    Stat { signals: Vec<&'static str>, stat: Stat, from_s: f64, to_s: f64, value: f64, t_s: f64 },
    /// The first time at or after `from_s` that `signal` reaches `level` from below (None: never).
    Reaches { signal: &'static str, level: f64, from_s: f64, t_s: Option<f64> },
    /// Surface-loss onsets (beta_T leaves its submerged value) in the run.
    Onsets { count: usize },
    /// Energy \[J\] burnt in the brake resistor (the time integral of its power).
    BrakeEnergy { value_j: f64 },
    /// The time integral \[J\] of the power `signal` \[W\] over \[from_s, to_s\], by the trapezoid
    /// rule over the recorded rows ([`energy`]).
    Energy { signal: &'static str, from_s: f64, to_s: f64, value_j: f64 },
    /// A level of the model (`sim::health`'s thresholds), named.
    Level { name: &'static str, value: f64 },
    /// Facts `a` and `b` (indices, each a Stat, BrakeEnergy or Level) compare as `relation`.
    Compare { a: usize, b: usize, by: f64, relation: Relation },
}

/// What "try this next" promises: `measure` of the run with `set` stands in `relation` to the same
/// measure of this run (by more than `by`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Promise {
    pub measure: Measure,
    pub relation: Relation,
    pub by: f64,
}

/// A number of a run that a promise compares.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "measure", rename_all = "snake_case")]
pub enum Measure {
    Stat {
        signals: Vec<&'static str>,
        stat: Stat,
        from_s: f64,
    },
    /// How far `signal` rises at or after `from_s` above its value at `from_s`.
    Rise {
        signal: &'static str,
        from_s: f64,
    },
    Onsets,
    /// How far `signal` moves at or after `from_s` (its highest less its lowest).
    Swing {
        signal: &'static str,
        from_s: f64,
    },
    /// The mean of `signal`'s rows at or after `from_s`.
    Mean {
        signal: &'static str,
        from_s: f64,
    },
    /// The time integral of the power `signal` at or after `from_s` \[J\] ([`energy`]).
    Energy {
        signal: &'static str,
        from_s: f64,
    },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Next {
    pub text: String,
    /// Control values to set (path, value as the link carries it).
    pub set: Vec<(&'static str, String)>,
    pub promise: Promise,
}

/// What a run of a lesson shows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Explanation {
    /// Sentences in order, each with the indices of the facts it states.
    pub sentences: Vec<(String, Vec<usize>)>,
    pub facts: Vec<Fact>,
    /// The answer the run shows to be right, when one run settles the question, with the fact
    /// that decides it; otherwise None and `verdict_note` says why.
    pub right: Option<usize>,
    pub right_because: Option<usize>,
    pub verdict_note: String,
    pub next: Next,
    /// The instant the live picture shows (the one the words quote).
    pub at_s: f64,
    /// The number the question is about, in this run (a lesson about a change).
    pub reading: Option<Reading>,
    /// The verdict on the prediction against the run before (given one that differs).
    pub verdict: Option<Verdict>,
}

/// The run a lesson explains.
pub struct Run<'a> {
    pub scenario: &'a Scenario,
    pub trace: &'a Trace,
    pub summary: &'a Summary,
}

/// Rows of `t` in \[from, to\].
pub(super) fn window(t: &[f64], from: f64, to: f64) -> std::ops::Range<usize> {
    let a = t.partition_point(|&x| x < from - 1e-9);
    let b = t.partition_point(|&x| x <= to + 1e-9);
    a..b.max(a)
}

pub(super) fn nearest(t: &[f64], at: f64) -> usize {
    let i = t.partition_point(|&x| x < at);
    if i >= t.len() {
        t.len().saturating_sub(1)
    } else if i > 0 && at - t[i - 1] < t[i] - at {
        i - 1
    } else {
        i
    }
}

pub(super) fn col<'a>(trace: &'a Trace, name: &str) -> &'a [f64] {
    Signal::from_name(name).map(|s| trace.get(s)).unwrap_or_default()
}

/// The statistic of a window (shared with the promise's measure; the test has its own).
pub fn stat(trace: &Trace, signals: &[&str], stat: Stat, from: f64, to: f64) -> (f64, f64) {
    let t = trace.get(Signal::TS);
    if stat == Stat::At {
        let i = nearest(t, from);
        return (col(trace, signals[0]).get(i).copied().unwrap_or(f64::NAN), t.get(i).copied().unwrap_or(from));
    }
    let mut best = (if stat == Stat::Min { f64::INFINITY } else { f64::NEG_INFINITY }, from);
    for name in signals {
        let c = col(trace, name);
        for i in window(t, from, to) {
            let better = if stat == Stat::Min { c[i] < best.0 } else { c[i] > best.0 };
            if better {
                best = (c[i], t[i]);
            }
        }
    }
    best
}

/// The time integral of the power `signal` \[W\] over the rows in \[from, to\] \[J\]: the trapezoid
/// rule, exact for a power that is linear between rows (a lesson that quotes a short spike of
/// power records its rows densely).
pub fn energy(trace: &Trace, signal: &str, from: f64, to: f64) -> f64 {
    let t = trace.get(Signal::TS);
    let c = col(trace, signal);
    let w = window(t, from, to);
    (w.start + 1..w.end).map(|i| 0.5 * (c[i] + c[i - 1]) * (t[i] - t[i - 1])).sum()
}

/// Surface-loss onsets: rows where beta_T drops below its submerged value (the page's markers).
pub fn onsets(trace: &Trace, submerged: f64) -> usize {
    let b = trace.get(Signal::BetaT);
    (0..b.len()).filter(|&i| b[i] < submerged && (i == 0 || b[i - 1] >= submerged)).count()
}

/// Builds an explanation fact by fact.
pub(super) struct Book<'a> {
    pub(super) run: &'a Run<'a>,
    pub(super) end: f64,
    pub(super) facts: Vec<Fact>,
    pub(super) sentences: Vec<(String, Vec<usize>)>,
}

impl<'a> Book<'a> {
    pub(super) fn new(run: &'a Run<'a>) -> Book<'a> {
        let end = run.trace.get(Signal::TS).last().copied().unwrap_or(0.0);
        Book { run, end, facts: Vec::new(), sentences: Vec::new() }
    }
    pub(super) fn push(&mut self, f: Fact) -> usize {
        self.facts.push(f);
        self.facts.len() - 1
    }
    /// A statistic over \[from, to\]: (fact index, value, time of the value).
    pub(super) fn stat(&mut self, signals: &[&'static str], s: Stat, from: f64, to: f64) -> (usize, f64, f64) {
        let (value, t) = stat(self.run.trace, signals, s, from, to);
        let to = if s == Stat::At { from } else { to };
        (self.push(Fact::Stat { signals: signals.to_vec(), stat: s, from_s: from, to_s: to, value, t_s: t }), value, t)
    }
    /// The energy of a power signal over \[from, to\]: (fact index, value \[J\]).
    pub(super) fn energy(&mut self, signal: &'static str, from: f64, to: f64) -> (usize, f64) {
        let value_j = energy(self.run.trace, signal, from, to);
        (self.push(Fact::Energy { signal, from_s: from, to_s: to, value_j }), value_j)
    }
    pub(super) fn at(&mut self, signal: &'static str, t: f64) -> (usize, f64) {
        let (i, v, _) = self.stat(&[signal], Stat::At, t, t);
        (i, v)
    }
    pub(super) fn compare(&mut self, a: (usize, f64), b: (usize, f64), by: f64) -> Relation {
        let relation = Relation::of(a.1, b.1, by);
        self.push(Fact::Compare { a: a.0, b: b.0, by, relation });
        relation
    }
    pub(super) fn say(&mut self, text: String, facts: &[usize]) {
        self.sentences.push((text, facts.to_vec()));
    }
    pub(super) fn last(&self) -> usize {
        self.facts.len() - 1
    }
    pub(super) fn done(
        &mut self,
        right: Option<(usize, usize)>,
        verdict_note: String,
        next: Next,
        at_s: f64,
    ) -> Explanation {
        Explanation {
            sentences: std::mem::take(&mut self.sentences),
            facts: std::mem::take(&mut self.facts),
            right: right.map(|r| r.0),
            right_because: right.map(|r| r.1),
            verdict_note,
            next,
            at_s,
            reading: None,
            verdict: None,
        }
    }
}

pub(super) fn f(x: f64, d: usize) -> String {
    format!("{x:.d$}")
}
pub(super) fn pct(x: f64) -> String {
    format!("{:.0} %", 100.0 * x)
}
/// A difference of charge in percentage points ("8 points above").
pub(super) fn pct_points(d: f64) -> String {
    let n = libm::round(100.0 * d.abs());
    let w = if d >= 0.0 { "above" } else { "below" };
    format!("{n:.0} point{} {w}", if n == 1.0 { "" } else { "s" })
}
pub(super) fn value_text(x: f64) -> String {
    let s = format!("{}", (x * 1e6).round() / 1e6);
    s.trim_end_matches(".0").to_string()
}

pub(super) const HR: &[&str] = &["h_over_r", "h_over_r_stbd"];

pub(super) fn submerged(sc: &serde_json::Value) -> f64 {
    let x = number(sc, "propeller.beta_t");
    if x.is_finite() {
        x
    } else {
        1.0
    }
}

/// The lowest h/R on both shafts and the surface-loss onsets: the sentences `waves` and `sign`
/// share. Returns (fact of the lowest h/R, its time).
pub(super) fn depth(b: &mut Book, sc: &serde_json::Value, end: f64) -> (usize, f64, f64) {
    let port = b.stat(&HR[..1], Stat::Min, 0.0, end);
    let stbd = b.stat(&HR[1..], Stat::Min, 0.0, end);
    let n = onsets(b.run.trace, submerged(sc));
    let on = b.push(Fact::Onsets { count: n });
    // The stern picture draws the port propeller: it shows the port shaft's lowest moment.
    b.say(
        format!(
            "h/R went down to {} on the port shaft ({} s in: the stern picture shows the port propeller then) and to {} on the starboard shaft.",
            f(port.1, 2),
            f(port.2, 1),
            f(stbd.1, 2)
        ),
        &[port.0, stbd.0],
    );
    if n == 0 {
        b.say("The propellers never lost thrust to the surface in this run.".into(), &[on]);
    } else {
        b.say(format!("Surface losses started {n} time{}: each time a propeller draws air or breaks the surface it loses thrust, its load drops and its motor races.", if n == 1 { "" } else { "s" }), &[on]);
    }
    port
}

/// The number a lesson's question is about, measured in one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reading {
    pub measure: Measure,
    pub value: f64,
}

/// The verdict on a prediction, from the run before and the run now.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// What the page and `aes-sim lesson` say.
    pub text: String,
    /// The reading before and now (the question's measure, SI or pu).
    pub before: f64,
    pub now: f64,
    /// Readings within `by` of each other are "about the same".
    pub by: f64,
    /// The run nearer the question's change against the other (More: its reading is larger).
    pub relation: Relation,
    /// The answer the two runs show (None: the change is not the question's, or the runs cannot
    /// tell; the text says why).
    pub right: Option<usize>,
    /// The student's answer (None: skipped) and whether the runs agree with it.
    pub answer: Option<usize>,
    pub agrees: Option<bool>,
}
