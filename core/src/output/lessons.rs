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

use crate::checks::shorten;
use crate::scenario::presets::preset;
use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::health::{BUS_LOW_PU, TURBINE_MIN_RUNNING_PU, TURBINE_OVERSPEED_PU};
use crate::sim::summary::Summary;
use crate::sim::Trace;
use serde::Serialize;

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
}

const SPEED_KN: &str = "initial.speed_kn";
/// The top of the `waves` lesson's hub slider [m] (the hub 3.0 m deep at the 5415's draft).
const HUB_TOP_M: f64 = 3.15;
const ORDER_KN: &[&str] = &["commands.0.speed_kn"];
/// The `battery` lesson's controls: the storage's energy and power rating on each bus.
const BATTERY_J: &str = "plant.storage.energy_j";
const BATTERY_W: &str = "plant.storage.power_w";

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

/// Every lesson, in the order the index lists them.
pub fn lessons() -> Vec<Lesson> {
    vec![
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
        },
        Lesson {
            name: "waves",
            title: "Waves unload the propeller",
            preset: "head-seas-ss6",
            set: &[("sim.duration_s", "60")],
            story: "The ship steams into waves. Each propeller sits under the stern; when a wave trough passes over it, the water above it thins and the propeller can draw air or break the surface, and it loses thrust. h/R (the hub's depth over the propeller's radius) says how deep it is: below 1 its disc breaks the surface.",
            controls: vec![
                slider("sea.sea_state", "Sea state (2: smooth, 6: very rough)", "", 2.0, 6.0, 1.0),
                slider("ship.hull.hub_above_base_m", "Propeller hub above the keel", "m", 0.15, HUB_TOP_M, 0.25),
                speed(10.0, 30.0),
            ],
            question: "Raise the propeller hub (a lighter ship rides higher). Will the propeller draw air more often, less often, or as often?",
            answers: &["more often", "less often", "as often"],
            plots: &["hr", "motor"],
            view: "stern",
        },
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
        },
        Lesson {
            name: "braking",
            title: "Braking: where the ship's energy goes",
            preset: "ac-braking",
            set: &[("sim.duration_s", "90")],
            story: "At 10 s the ship is ordered to slow to 10 knots. The motors brake: the water turns the propellers, the motors work as generators and send the ship's kinetic energy back into the electric bus. A brake resistor can burn it as heat; without one, the rectifiers pass it back towards the generators and the gas turbines.",
            controls: vec![
                Control {
                    path: "plant.dc_link.brake_resistor_ohm",
                    with_paths: &[],
                    label: "Brake resistor",
                    unit: "",
                    kind: ControlKind::Toggle {
                        values: &["1", "0"],
                        labels: &["with a brake resistor", "no brake resistor"],
                        // Without the resistor the rectifiers must pass power back to the
                        // generators (Fig. 5-8's plant): a diode rectifier with nowhere for the
                        // energy to go drives the bus voltage away.
                        settings: &[&[("plant.dc_link.rectifier", "diode")], &[("plant.dc_link.rectifier", "reversible")]],
                    },
                },
                speed(15.0, 30.0),
            ],
            question: "The ship slows from 25 to 10 knots. Without a brake resistor, where does its kinetic energy go?",
            answers: &["back into the gas turbines, which speed up", "it simply disappears", "into the bus, which holds its voltage"],
            plots: &["bus", "brake"],
            view: "train",
        },
        Lesson {
            name: "bus",
            title: "How the bus voltage is held",
            preset: "acceleration",
            set: &[],
            story: "At 10 s the motors are ordered to full power at once. The generators' voltage sags as the turbines slow under the load; a field controller raises the generators' field current to hold the bus voltage. pu means \"per unit\": a fraction of the rated value (1 pu is the rated voltage or speed).",
            controls: vec![
                decades("controllers.field.kp", "Field controller: reaction to the voltage error now (proportional gain)", "V/V", 1e-5, 0.1),
                decades("controllers.field.ki", "Field controller: reaction to the error summed over time (integral gain)", "V/(V s)", 1e-5, 10.0),
            ],
            question: "The motors suddenly take full power. If the generators' field controller reacts more strongly (a larger gain), the bus voltage will...",
            answers: &["dip less and recover sooner", "dip more", "hardly change"],
            plots: &["bus"],
            view: "train",
        },
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
        },
        Lesson {
            name: "sign",
            title: "One sign in one equation",
            preset: "head-seas-ss6",
            set: &[("sim.duration_s", "60")],
            story: "A wave crest lifts the water at the stern, and it lifts the stern too, so the propeller stays at about the same depth under the surface. The thesis this simulator follows prints its depth formula with the stern's motion added the other way round: as if the stern sank whenever the water rose. One sign, and the propeller seems to swing twice as far.",
            controls: vec![
                Control {
                    path: "seakeeping.stern_motion",
                    with_paths: &[],
                    label: "How the stern moves in the depth formula",
                    unit: "",
                    kind: ControlKind::Toggle {
                        values: &["consistent", "thesis_eq_2_57"],
                        labels: &["it rises and falls with the waves", "the other way, as the thesis prints it"],
                        settings: &[&[], &[]],
                    },
                },
                slider("sea.sea_state", "Sea state (2: smooth, 6: very rough)", "", 2.0, 6.0, 1.0),
            ],
            question: "The thesis prints the stern's motion with the other sign. If that were right, the propeller would break the surface...",
            answers: &["more often than with the stern following the waves", "less often", "as often"],
            plots: &["hr"],
            view: "stern",
        },
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
        },
    ]
}

/// The lesson of that name.
pub fn lesson(name: &str) -> Option<Lesson> {
    lessons().into_iter().find(|l| l.name == name)
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
                    _ => Err(format!(
                        "{}: {} is outside this lesson's range, {} to {}{}",
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
            Some((_, text)) => c.accept(text).unwrap_or_else(|e| {
                refused.push(e);
                own
            }),
            None => own,
        };
        sets.extend(c.sets(&v));
        values.insert(c.path.to_string(), v);
    }
    let pairs: Vec<(&str, &str)> = sets.iter().map(|(p, v)| (*p, v.as_str())).collect();
    let scenario = base.with_overrides(&pairs).map_err(|e| format!("lesson {}: {e}", l.name))?;
    Ok(Opened { scenario, values, defaults, refused })
}

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
    /// `value` is the `stat` of `signals` over [from_s, to_s] (every signal the plot shows).
    /// `t_s`: the time of that value (the row's time for `At`).
    Stat { signals: Vec<&'static str>, stat: Stat, from_s: f64, to_s: f64, value: f64, t_s: f64 },
    /// The first time at or after `from_s` that `signal` reaches `level` from below (None: never).
    Reaches { signal: &'static str, level: f64, from_s: f64, t_s: Option<f64> },
    /// Surface-loss onsets (beta_T leaves its submerged value) in the run.
    Onsets { count: usize },
    /// Energy \[J\] burnt in the brake resistor (the time integral of its power).
    BrakeEnergy { value_j: f64 },
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
}

/// The run a lesson explains.
pub struct Run<'a> {
    pub scenario: &'a Scenario,
    pub trace: &'a Trace,
    pub summary: &'a Summary,
}

/// Rows of `t` in [from, to].
fn window(t: &[f64], from: f64, to: f64) -> std::ops::Range<usize> {
    let a = t.partition_point(|&x| x < from - 1e-9);
    let b = t.partition_point(|&x| x <= to + 1e-9);
    a..b.max(a)
}

fn nearest(t: &[f64], at: f64) -> usize {
    let i = t.partition_point(|&x| x < at);
    if i >= t.len() {
        t.len().saturating_sub(1)
    } else if i > 0 && at - t[i - 1] < t[i] - at {
        i - 1
    } else {
        i
    }
}

fn col<'a>(trace: &'a Trace, name: &str) -> &'a [f64] {
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

/// Surface-loss onsets: rows where beta_T drops below its submerged value (the page's markers).
pub fn onsets(trace: &Trace, submerged: f64) -> usize {
    let b = trace.get(Signal::BetaT);
    (0..b.len()).filter(|&i| b[i] < submerged && (i == 0 || b[i - 1] >= submerged)).count()
}

/// Builds an explanation fact by fact.
struct Book<'a> {
    run: &'a Run<'a>,
    end: f64,
    facts: Vec<Fact>,
    sentences: Vec<(String, Vec<usize>)>,
}

impl<'a> Book<'a> {
    fn new(run: &'a Run<'a>) -> Book<'a> {
        let end = run.trace.get(Signal::TS).last().copied().unwrap_or(0.0);
        Book { run, end, facts: Vec::new(), sentences: Vec::new() }
    }
    fn push(&mut self, f: Fact) -> usize {
        self.facts.push(f);
        self.facts.len() - 1
    }
    /// A statistic over [from, to]: (fact index, value, time of the value).
    fn stat(&mut self, signals: &[&'static str], s: Stat, from: f64, to: f64) -> (usize, f64, f64) {
        let (value, t) = stat(self.run.trace, signals, s, from, to);
        let to = if s == Stat::At { from } else { to };
        (self.push(Fact::Stat { signals: signals.to_vec(), stat: s, from_s: from, to_s: to, value, t_s: t }), value, t)
    }
    fn at(&mut self, signal: &'static str, t: f64) -> (usize, f64) {
        let (i, v, _) = self.stat(&[signal], Stat::At, t, t);
        (i, v)
    }
    fn compare(&mut self, a: (usize, f64), b: (usize, f64), by: f64) -> Relation {
        let relation = Relation::of(a.1, b.1, by);
        self.push(Fact::Compare { a: a.0, b: b.0, by, relation });
        relation
    }
    fn say(&mut self, text: String, facts: &[usize]) {
        self.sentences.push((text, facts.to_vec()));
    }
    fn last(&self) -> usize {
        self.facts.len() - 1
    }
    fn done(&mut self, right: Option<(usize, usize)>, verdict_note: String, next: Next, at_s: f64) -> Explanation {
        Explanation {
            sentences: std::mem::take(&mut self.sentences),
            facts: std::mem::take(&mut self.facts),
            right: right.map(|r| r.0),
            right_because: right.map(|r| r.1),
            verdict_note,
            next,
            at_s,
        }
    }
}

fn f(x: f64, d: usize) -> String {
    format!("{x:.d$}")
}
fn pct(x: f64) -> String {
    format!("{:.0} %", 100.0 * x)
}
fn value_text(x: f64) -> String {
    let s = format!("{}", (x * 1e6).round() / 1e6);
    s.trim_end_matches(".0").to_string()
}

const HR: &[&str] = &["h_over_r", "h_over_r_stbd"];

/// Explains a finished run of lesson `l` (`values`: the controls' values, as `open` gives them).
pub fn explain(l: &Lesson, values: &serde_json::Map<String, serde_json::Value>, run: &Run) -> Explanation {
    let num = |p: &str| values.get(p).and_then(|v| v.as_f64().or_else(|| v.as_str()?.parse().ok())).unwrap_or(f64::NAN);
    let text = |p: &str| values.get(p).and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default();
    let sc = run.scenario.to_value();
    let mut b = Book::new(run);
    let end = b.end;
    match l.name {
        "power" => power(&mut b, num("commands.0.speed_kn"), end),
        "waves" => waves(&mut b, &sc, num("sea.sea_state"), num("ship.hull.hub_above_base_m"), end),
        "turn" => turn(&mut b, &sc, num("commands.1.heading_deg"), num(SPEED_KN), end),
        "braking" => braking(&mut b, &sc, text("plant.dc_link.brake_resistor_ohm") == "1", num(SPEED_KN), end),
        "bus" => bus(&mut b, &sc, num("controllers.field.kp"), num("controllers.field.ki"), end),
        "engines" => engines(&mut b, &sc, &text("plant.online.sets"), end),
        "battery" => battery(&mut b, &sc, num(BATTERY_J), num(BATTERY_W), end),
        _ => sign(&mut b, &sc, text("seakeeping.stern_motion") == "thesis_eq_2_57", num("sea.sea_state"), end),
    }
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
            "Each stage keeps back a little: the generators pass on {}, the power electronics {}, the motors {}, the propellers {}; the largest loss is the {}'.",
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

fn submerged(sc: &serde_json::Value) -> f64 {
    let x = number(sc, "propeller.beta_t");
    if x.is_finite() {
        x
    } else {
        1.0
    }
}

/// The lowest h/R on both shafts and the surface-loss onsets: the sentences `waves` and `sign`
/// share. Returns (fact of the lowest h/R, its time).
fn depth(b: &mut Book, sc: &serde_json::Value, end: f64) -> (usize, f64, f64) {
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

fn waves(b: &mut Book, sc: &serde_json::Value, sea: f64, hub: f64, end: f64) -> Explanation {
    let low = depth(b, sc, end);
    let m_lo = b.stat(&["im_power_pu"], Stat::Min, 0.0, end);
    let m_hi = b.stat(&["im_power_pu"], Stat::Max, 0.0, end);
    let rating = f(number(sc, "plant.motor.rated_power_w") / 1e6, 0);
    // A swing under 0.01 pu is "held": the words then say so instead of quoting equal numbers.
    if b.compare((m_hi.0, m_hi.1), (m_lo.0, m_lo.1), 0.01) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "The motors' power moved between {} and {} pu of their {rating} MW rating as the waves changed the propellers' load.",
                f(m_lo.1, 2),
                f(m_hi.1, 2)
            ),
            &[m_lo.0, m_hi.0, i],
        );
    } else {
        let i = b.last();
        b.say(format!("The motors' power held at {} pu of their {rating} MW rating: these waves hardly change the propellers' load.", f(m_hi.1, 2)), &[m_lo.0, m_hi.0, i]);
    }
    // The lesson's question is the hub's height: half a metre up (down from the top of its
    // span) moves the whole h/R line by about 0.5 m over the propeller's radius.
    let (to, relation, words) = if hub + 0.5 <= HUB_TOP_M {
        (hub + 0.5, Relation::Less, "Raise the hub to {} m (a lighter ship): the whole h/R line moves down, and the propellers come nearer the surface.")
    } else {
        (
            hub - 0.5,
            Relation::More,
            "Lower the hub to {} m (a heavier ship): the whole h/R line moves up, and the propellers stay deeper.",
        )
    };
    let next = Next {
        text: words.replace("{}", &value_text(to)),
        set: vec![("ship.hull.hub_above_base_m", value_text(to))],
        promise: Promise {
            measure: Measure::Stat { signals: HR.to_vec(), stat: Stat::Min, from_s: 0.0 },
            relation,
            by: 0.1,
        },
    };
    let _ = sea;
    b.done(None, "One run cannot answer a question about a change: move the hub and compare the new run with the faint earlier one.".into(), next, low.2)
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
                    "While the ship turns, the rudder is over and the hull moves a little sideways, so the propellers meet the water at an angle: the motors' power rose from {} pu at the order to {} pu ({} more) at {} s, {when}.",
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

fn braking(b: &mut Book, sc: &serde_json::Value, resistor: bool, speed: f64, end: f64) -> Explanation {
    let t0 = number(sc, "commands.1.t_s");
    let to = number(sc, "commands.1.speed_kn");
    let v0 = b.at("ship_speed_kn", t0);
    b.say(
        format!("At {} s the order slows the ship from {} to {} knots: the water drives the propellers and the motors brake as generators, sending the ship's energy into the bus.", f(t0, 0), f(v0.1, 1), f(to, 0)),
        &[v0.0],
    );
    let n0 = b.at("turbine_speed_pu", t0);
    let (ni, nmax, tmax) = b.stat(&["turbine_speed_pu"], Stat::Max, t0, end);
    let bus = b.stat(&["bus_voltage_pu"], Stat::Max, t0, end);
    let rose = b.compare((ni, nmax), n0, 0.01);
    let because = b.last();
    let e = b.run.summary.energy_j.brake;
    let ei = b.push(Fact::BrakeEnergy { value_j: e });
    let (right, note) = if resistor {
        b.say(
            format!("The brake resistor burnt {} MJ as heat; the turbines reached {} pu of their speed and the bus {} pu of its voltage.", f(e / 1e6, 1), f(nmax, 3), f(bus.1, 3)),
            &[ei, ni, bus.0],
        );
        (None, "This run burnt the energy in the brake resistor, so it does not answer the question yet: switch the resistor off.".to_string())
    } else if rose == Relation::More {
        let pmin = b.stat(&["p_turbine_w"], Stat::Min, t0, end);
        b.say(
            format!("With no resistor the energy flowed back through the rectifiers: the turbines sped up from {} to {} pu of their speed ({} s in) while their power fell to {} MW, and the bus rose to {} pu.", f(n0.1, 3), f(nmax, 3), f(tmax, 0), f(pmin.1 / 1e6, 1), f(bus.1, 3)),
            &[n0.0, ni, because, pmin.0, bus.0],
        );
        (Some((0, because)), String::new())
    } else {
        b.say(format!("With no resistor the turbines stayed within 1 % of their speed (highest {} pu): from this speed there is little energy to return.", f(nmax, 3)), &[n0.0, ni, because]);
        (None, "From this speed the run shows too little to answer: order a higher speed.".to_string())
    };
    let measure = Measure::Stat { signals: vec!["turbine_speed_pu"], stat: Stat::Max, from_s: t0 };
    let next = if resistor {
        Next {
            text: "Switch the resistor off: with nowhere else to go, the energy speeds up the turbines.".into(),
            set: vec![("plant.dc_link.brake_resistor_ohm", "0".into())],
            promise: Promise { measure, relation: Relation::More, by: 0.005 },
        }
    } else if speed < 30.0 {
        Next {
            text: "Start from 30 knots: more energy to stop, and the turbines speed up more.".into(),
            set: vec![(SPEED_KN, "30".into())],
            promise: Promise { measure, relation: Relation::More, by: 0.005 },
        }
    } else {
        Next {
            text: "Switch the resistor on: it takes the energy, and the turbines stay near their speed.".into(),
            set: vec![("plant.dc_link.brake_resistor_ohm", "1".into())],
            promise: Promise { measure, relation: Relation::Less, by: 0.005 },
        }
    };
    let at = if resistor { b.stat(&["brake_power_w"], Stat::Max, t0, end).2 } else { tmax };
    b.done(right, note, next, at)
}

fn bus(b: &mut Book, sc: &serde_json::Value, kp: f64, ki: f64, end: f64) -> Explanation {
    let t0 = number(sc, "commands.1.t_s");
    let (bi, bmin, tmin) = b.stat(&["bus_voltage_pu"], Stat::Min, t0, end);
    let tu = b.stat(&["turbine_speed_pu"], Stat::Min, t0, end);
    b.say(
        format!("At {} s the motors take full power. The bus dipped to {} pu ({} s in) and the turbines slowed to {} pu: a generator's voltage falls with its speed, and the field controller raises its field current to make up for it.", f(t0, 0), f(bmin, 3), f(tmin, 1), f(tu.1, 3)),
        &[bi, tu.0],
    );
    let bend = b.at("bus_voltage_pu", end);
    let low = b.push(Fact::Level { name: "bus band's lower edge [pu]", value: BUS_LOW_PU });
    let back = Relation::of(bend.1, BUS_LOW_PU, 0.0);
    let cmp = b.push(Fact::Compare { a: bend.0, b: low, by: 0.0, relation: back });
    if back == Relation::More {
        b.say(
            format!(
                "By the end the bus was back at {} pu, inside its band (above {} pu).",
                f(bend.1, 3),
                f(BUS_LOW_PU, 1)
            ),
            &[bend.0, cmp],
        );
    } else {
        b.say(
            format!(
                "At the end the bus is still at {} pu, below its band's {} pu: the controller has not brought it back.",
                f(bend.1, 3),
                f(BUS_LOW_PU, 1)
            ),
            &[bend.0, cmp],
        );
    }
    if let Some(w) = b.run.summary.warnings.iter().find(|w| w.starts_with("bus voltage")) {
        b.say(format!("The red LOW on the bus blocks is the plant's health check: {w}."), &[bi]);
    }
    let run_level = b.push(Fact::Level { name: "turbines' minimum running speed [pu]", value: TURBINE_MIN_RUNNING_PU });
    let stalled = Relation::of(tu.1, TURBINE_MIN_RUNNING_PU, 0.0) == Relation::Less;
    let cmp = b.push(Fact::Compare {
        a: tu.0,
        b: run_level,
        by: 0.0,
        relation: Relation::of(tu.1, TURBINE_MIN_RUNNING_PU, 0.0),
    });
    if stalled {
        b.say(format!("The turbines stalled (below {} pu of their speed): the controller asked the generators for more than the turbines could give.", f(TURBINE_MIN_RUNNING_PU, 1)), &[tu.0, cmp]);
    }
    let turb = Measure::Stat { signals: vec!["turbine_speed_pu"], stat: Stat::Min, from_s: t0 };
    let next = if stalled {
        Next {
            text: "Set both gains back to 0.0001: the turbines keep running.".into(),
            set: vec![("controllers.field.kp", "0.0001".into()), ("controllers.field.ki", "0.0001".into())],
            promise: Promise { measure: turb, relation: Relation::More, by: 0.1 },
        }
    } else if back != Relation::More {
        Next {
            text: "Set the integral gain to 0.0005: summing the error over time brings the bus back by the end.".into(),
            set: vec![("controllers.field.ki", "0.0005".into())],
            promise: Promise {
                measure: Measure::Stat { signals: vec!["bus_voltage_pu"], stat: Stat::At, from_s: end },
                relation: Relation::More,
                by: 0.02,
            },
        }
    } else {
        Next {
            text: "Set the proportional gain to 0.1: a controller can hold the voltage only by stalling its turbines."
                .into(),
            set: vec![("controllers.field.kp", "0.1".into())],
            promise: Promise { measure: turb, relation: Relation::Less, by: 0.1 },
        }
    };
    let _ = (kp, ki);
    b.done(None, "One run cannot answer a question about a change: move a gain and compare the new run with the faint earlier one.".into(), next, tmin)
}

fn sign(b: &mut Book, sc: &serde_json::Value, printed: bool, sea: f64, end: f64) -> Explanation {
    let low = depth(b, sc, end);
    // In low seas the stern hardly moves and the two formulas differ by about 0.02 in h/R.
    let (by, much) =
        if sea <= 3.0 { (0.01, " a little (the stern hardly moves in these low waves)") } else { (0.05, "") };
    let (to, words, relation) = if printed {
        (
            "consistent",
            format!("Switch to the stern rising and falling with the waves: the lowest h/R rises{much}."),
            Relation::More,
        )
    } else {
        ("thesis_eq_2_57", format!("Switch to the thesis' printed sign: the lowest h/R falls{much}."), Relation::Less)
    };
    b.say(
        if printed { "This run uses the printed sign: the stern's motion adds to the wave's instead of cancelling it, so the hub seems to swing more." } else { "This run lets the stern follow the waves: its motion cancels much of the wave's, so the hub stays at about the same depth." }.into(),
        &[],
    );
    let next = Next {
        text: words,
        set: vec![("seakeeping.stern_motion", to.into())],
        promise: Promise {
            measure: Measure::Stat { signals: HR.to_vec(), stat: Stat::Min, from_s: 0.0 },
            relation,
            by,
        },
    };
    b.done(None, "One run cannot answer a question about a change: switch the formula and compare the new run with the faint earlier one.".into(), next, low.2)
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
        // rated power wide), handing the swings back to the turbines.
        let edge = (floor + crate::plant::storage::taper_j(energy_j, power_w) / energy_j).min(1.0);
        let lv =
            b.push(Fact::Level { name: "lowest charge where the controller starts to give less [-]", value: edge });
        if b.compare((smin.0, smin.1), (lv, edge), 0.0) != Relation::More {
            let i = b.last();
            b.say(
                format!(
                    "Below {} % the controller gives less and less, down to nothing at its lowest allowed charge ({} %), and the turbines take back the swings the battery no longer takes: here the charge got down there.",
                    f(100.0 * edge, 0),
                    f(100.0 * floor, 0)
                ),
                &[smin.0, lv, i],
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
