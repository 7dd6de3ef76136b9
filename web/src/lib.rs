//! aes-web: wasm-bindgen bindings over aes-core for the browser page. Thin: no physics here.
//!
//! Scenarios cross as JSON text (the same public format as the command line), so that a scenario
//! file, a shared link and a native run all speak one language.

use aes_core::output::lessons;
use aes_core::scenario::presets::{preset, PRESET_NAMES};
use aes_core::studies::{stability_map, study};
use aes_core::{Scenario, Simulation};
use wasm_bindgen::prelude::*;

/// Every error the exports give, through one guard: control characters escaped and long
/// stretches cut (`checks::shorten_message`), so no input comes back whole or raw (a 1 MB axis
/// path with ESC and BEL in it was echoed in full).
fn js_error(msg: &str) -> JsError {
    JsError::new(&aes_core::checks::shorten_message(msg))
}

/// A text argument from JavaScript, refused by name when it is not a string (a number or an
/// object given for a `&str` trapped with "memory access out of bounds", issue 34).
fn text(v: &JsValue, what: &str) -> Result<String, JsError> {
    v.as_string().ok_or_else(|| {
        let kind = v.js_typeof().as_string().unwrap_or_default();
        js_error(&format!("{what}: expected a string, got a value of type {kind}"))
    })
}

/// A count from JavaScript (a number of steps, a trial, passes, workers), refused by name when it
/// is not a whole number from 0 to `max`: the glue of a `u32` argument would turn NaN, infinities
/// and negatives into 0 or wrap them before Rust saw them.
fn whole(x: f64, what: &str, max: u32) -> Result<u32, JsError> {
    if x.is_finite() && x.fract() == 0.0 && (0.0..=max as f64).contains(&x) {
        Ok(x as u32)
    } else {
        let shown = if x.is_finite() { aes_core::checks::num(x) } else { "a value that is not a finite number".into() };
        Err(js_error(&format!("{what} = {shown}: must be a whole number from 0 to {max}")))
    }
}

/// Names of the preset scenarios.
#[wasm_bindgen(js_name = presetNames)]
pub fn preset_names() -> Vec<String> {
    PRESET_NAMES.iter().map(|s| s.to_string()).collect()
}

/// A preset scenario as JSON text.
#[wasm_bindgen(js_name = presetJson)]
pub fn preset_json(name: JsValue) -> Result<String, JsError> {
    let name = text(&name, "the preset's name")?;
    preset(&name)
        .map(|s| s.to_json())
        .ok_or_else(|| js_error(&format!("no preset named '{}'", aes_core::checks::shorten(&name))))
}

/// Checks a scenario; returns every problem as a list of `{path, value, message}` (empty when valid).
#[wasm_bindgen(js_name = validateScenario)]
pub fn validate_scenario(json: JsValue) -> Result<JsValue, JsError> {
    let errors = match Scenario::from_json(&text(&json, "the scenario JSON")?) {
        Ok(_) => Vec::new(),
        Err(e) => e.0,
    };
    serde_wasm_bindgen::to_value(&errors).map_err(|e| js_error(&e.to_string()))
}

/// Every recorded signal's metadata, in trace column order, as JSON:
/// `[{"name", "unit", "label", "description"}, ...]` (the page's axis units and labels).
#[wasm_bindgen(js_name = signalMeta)]
pub fn signal_meta() -> String {
    serde_json::to_string(aes_core::signals::SIGNALS).unwrap_or_default()
}

/// Every scenario parameter's declaration, as JSON: `{"groups": [[id, title], ...], "params":
/// [{"path", "kind", "label", "unit", "help", "source", "default", "min", "max", "choices",
/// "empty", "empty_is", "group", "base", "excludes"}, ...], "renamed": [[old path, new path], ...]}`
/// in scenario order. The page's form is made from it (the parameters with a group, in its
/// groups); links and files of earlier versions are read with `renamed`.
#[wasm_bindgen(js_name = paramMeta)]
pub fn param_meta() -> String {
    serde_json::json!({
        "groups": aes_core::params::FORM_GROUPS,
        "params": aes_core::scenario::registry::all(),
        "renamed": aes_core::scenario::file::RENAMED,
    })
    .to_string()
}

/// The thesis' numbers we compare with (core/data/thesis_values.csv), as JSON: `[{"key", "value",
/// "printed", "unit", "where", "what", "note"}, ...]` in the file's order. The page takes its
/// reference columns from here (Table 5.8, the excess energy); `printed` is the number as the thesis
/// prints it ("1.00").
#[wasm_bindgen(js_name = thesisValues)]
pub fn thesis_values() -> String {
    aes_core::studies::thesis_values::to_json()
}

/// The model's levels and ratings the page draws (bands, reference lines, per-unit bases), for a
/// scenario, as JSON. The page copies none of these numbers.
#[wasm_bindgen(js_name = pageConstants)]
pub fn page_constants(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let c = aes_core::output::presentation::PageConstants::of(&sc).map_err(|e| js_error(&e))?;
    serde_json::to_string(&c).map_err(|e| js_error(&e.to_string()))
}

/// The signal of a column name, or an error naming it (cut to 40 characters).
fn signal(name: &str) -> Result<aes_core::signals::Signal, JsError> {
    aes_core::signals::Signal::from_name(name)
        .ok_or_else(|| js_error(&format!("no signal named '{}'", name.chars().take(40).collect::<String>())))
}

/// A run that stopped, in words for the page: why nothing new is drawn and what to try.
fn stopped(e: &aes_core::SimError) -> String {
    match e {
        aes_core::SimError::Diverged { .. } => format!(
            "{e}. The run stopped: its numbers left the range the model holds, so there is nothing new to draw. \
             What to try: a speed nearer the study's own, a calmer sea or a shorter run; Reset brings the study's values back."
        ),
        _ => e.to_string(),
    }
}

/// A finished run's trace as CSV from its columns, `rows` values each, one after another in the
/// order of `signalNames` (what the page kept of a run: its export needs no second run).
#[wasm_bindgen(js_name = traceCsvOf)]
pub fn trace_csv_of(data: Vec<f64>, rows: usize) -> Result<String, JsError> {
    let n = aes_core::signals::N_SIGNALS;
    if rows == 0 || data.len() != n * rows {
        return Err(js_error(&format!("the trace's columns: {} values for {n} columns of {rows} rows", data.len())));
    }
    Ok(aes_core::sim::Trace { columns: data.chunks(rows).map(|c| c.to_vec()).collect() }.to_csv())
}

/// A run in progress, advanced in chunks so a worker can report progress and honour cancel.
#[wasm_bindgen]
pub struct Run {
    sim: Option<Simulation>,
    summary_json: String,
    columns: Vec<Vec<f64>>,
    /// The scenario and summary of the finished run (a lesson's explanation reads them).
    scenario: Scenario,
    summary: Option<aes_core::sim::summary::Summary>,
}

#[wasm_bindgen]
impl Run {
    /// Builds a run from scenario JSON; the error names every bad field.
    #[wasm_bindgen(constructor)]
    pub fn new(json: JsValue) -> Result<Run, JsError> {
        let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
        let sim = Simulation::new(&sc).map_err(|e| js_error(&e.to_string()))?;
        Ok(Run { sim: Some(sim), summary_json: String::new(), columns: Vec::new(), scenario: sc, summary: None })
    }

    /// Advances by at most `steps` time steps; returns the fraction done (1 when finished).
    pub fn advance(&mut self, steps: f64) -> Result<f64, JsError> {
        let steps = whole(steps, "advance: steps", u32::MAX)?;
        let Some(sim) = self.sim.as_mut() else {
            return Ok(1.0);
        };
        sim.advance(steps as u64).map_err(|e| js_error(&stopped(&e)))?;
        if sim.done() {
            if let Some(sim) = self.sim.take() {
                let r = sim.finish();
                aes_core::checks::check_finite(&r.summary).map_err(|e| js_error(&e))?;
                self.summary_json = serde_json::to_string(&r.summary.to_json_value()).unwrap_or_default();
                self.columns = r.trace.columns;
                self.summary = Some(r.summary);
            }
            return Ok(1.0);
        }
        Ok(sim.progress())
    }

    /// Summary JSON (after the run has finished; empty before).
    #[wasm_bindgen(js_name = summaryJson)]
    pub fn summary_json(&self) -> String {
        self.summary_json.clone()
    }

    /// The trace as CSV (after the run has finished; made when asked: the text of every number
    /// costs a browser a fifth of a run in waves, and only an export wants it).
    #[wasm_bindgen(js_name = traceCsv)]
    pub fn trace_csv(&self) -> String {
        aes_core::sim::Trace { columns: self.columns.clone() }.to_csv()
    }

    /// Names of the trace columns.
    #[wasm_bindgen(js_name = signalNames)]
    pub fn signal_names() -> Vec<String> {
        aes_core::signals::names().map(|s| s.to_string()).collect()
    }

    /// What the finished run shows as lesson `name` with the controls' `values` (JSON, as
    /// `lessonOpen` gives them), and with `before` (JSON `{values, reading, answer}` of the run
    /// before, or `null`) the verdict on the prediction: `aes_core::output::lessons::explain_after`
    /// as JSON.
    #[wasm_bindgen(js_name = lessonExplain)]
    pub fn lesson_explain(&self, name: JsValue, values: JsValue, before: JsValue) -> Result<String, JsError> {
        let l = lessons::lesson(&text(&name, "the lesson's name")?).map_err(|e| js_error(&e))?;
        let values: serde_json::Map<String, serde_json::Value> =
            serde_json::from_str(&text(&values, "the lesson's values")?).map_err(|e| js_error(&e.to_string()))?;
        let before: Option<lessons::Before> = match before.as_string() {
            Some(t) => serde_json::from_str(&t).map_err(|e| js_error(&format!("the run before: {e}")))?,
            None => None,
        };
        lessons::check_values(&l, &values).map_err(|e| js_error(&format!("the lesson's values: {e}")))?;
        let summary = self.summary.as_ref().ok_or_else(|| js_error("the run has not finished"))?;
        let trace = aes_core::sim::Trace { columns: self.columns.clone() };
        let run = lessons::Run { scenario: &self.scenario, trace: &trace, summary };
        let e = lessons::explain_checked(&l, &values, &run, before.as_ref()).map_err(|e| js_error(&e))?;
        Ok(serde_json::to_string(&e).unwrap_or_default())
    }

    /// One trace column as a Float64Array (after the run has finished).
    pub fn column(&self, name: JsValue) -> Result<js_sys::Float64Array, JsError> {
        let s = signal(&text(&name, "the signal's name")?)?;
        let col = self.columns.get(s.index()).ok_or_else(|| js_error("the run has not finished"))?;
        Ok(js_sys::Float64Array::from(col.as_slice()))
    }
}

#[wasm_bindgen]
impl Run {
    /// Rows recorded so far (during the run and after it).
    pub fn rows(&self) -> usize {
        match &self.sim {
            Some(sim) => sim.trace().len(),
            None => self.columns.first().map_or(0, |c| c.len()),
        }
    }

    /// Rows `from..` of one trace column recorded so far (the page follows a run as it goes).
    #[wasm_bindgen(js_name = columnFrom)]
    pub fn column_from(&self, name: JsValue, from: usize) -> Result<js_sys::Float64Array, JsError> {
        let s = signal(&text(&name, "the signal's name")?)?;
        let col = match &self.sim {
            Some(sim) => sim.trace().get(s),
            None => self.columns.get(s.index()).map(|c| c.as_slice()).unwrap_or_default(),
        };
        Ok(js_sys::Float64Array::from(col.get(from.min(col.len())..).unwrap_or_default()))
    }
}

/// The lessons (`aes_core::output::lessons::lessons`) as JSON: name, title, preset, story,
/// controls (path, label, unit, kind: slider with its stops or toggle with its values), question,
/// answers, plots, view.
#[wasm_bindgen(js_name = lessonMeta)]
pub fn lesson_meta() -> String {
    serde_json::to_string(&lessons::lessons()).unwrap_or_default()
}

/// Lesson `name` opened with a link's `values` (JSON object, path to text): `{scenario` (JSON
/// text), `values`, `defaults`, `refused` (a sentence per value refused; the lesson's own used)}.
#[wasm_bindgen(js_name = lessonOpen)]
pub fn lesson_open(name: JsValue, values: JsValue) -> Result<String, JsError> {
    let l = lessons::lesson(&text(&name, "the lesson's name")?).map_err(|e| js_error(&e))?;
    let given: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(&text(&values, "the lesson's values")?).map_err(|e| js_error(&e.to_string()))?;
    let given: Vec<(String, String)> =
        given.into_iter().map(|(k, v)| (k, v.as_str().map(str::to_string).unwrap_or_else(|| v.to_string()))).collect();
    let pairs: Vec<(&str, &str)> = given.iter().map(|(k, v)| (k.as_str(), v.as_str())).collect();
    let o = lessons::open(&l, &pairs).map_err(|e| js_error(&e))?;
    let mut v = serde_json::to_value(&o).map_err(|e| js_error(&e.to_string()))?;
    v["scenario"] = serde_json::Value::from(o.scenario.to_json());
    Ok(v.to_string())
}

/// Runs a scenario to the end and returns its summary JSON.
#[wasm_bindgen(js_name = runSummary)]
pub fn run_summary(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let r = aes_core::run(&sc).map_err(|e| js_error(&e.to_string()))?;
    Ok(serde_json::to_string(&r.summary.to_json_value()).unwrap_or_default())
}

/// The IPS stability tool (thesis ch. 4) for the page's stability tab: `aes_core::studies::ips::study`,
/// as `aes-sim ips bode` runs it. `side` is "generator" or "motor"; the operating point is omega
/// [rad/s], v_fd \[V\] and I \[A\] (generator) or T* [N m] (motor); `closed` picks the closed-loop
/// model; Bode from `from_hz` to `to_hz` in `points` points. Returns the JSON of `aes-sim ips bode`:
/// `steady_state`, `linear` (matrices, `poles`, `stable`), `margins` (closed loop) and `bode`.
#[wasm_bindgen(js_name = ipsAnalysis)]
#[allow(clippy::too_many_arguments)]
pub fn ips_analysis(
    side: JsValue,
    omega: f64,
    v_fd: f64,
    i_load: f64,
    torque: f64,
    closed: bool,
    from_hz: f64,
    to_hz: f64,
    points: u32,
) -> Result<String, JsError> {
    use aes_core::studies::ips::study::{self, Analysis, IpsRequest, OperatingPoint, Side};
    let request = IpsRequest {
        side: Side::from_name(&text(&side, "side")?).map_err(|e| js_error(&e))?,
        analysis: Analysis::Bode,
        closed,
        point: OperatingPoint {
            omega_rad_s: omega,
            v_fd_v: v_fd,
            load_a: i_load,
            torque_nm: torque,
            from_hz,
            to_hz,
            points: points as usize,
        },
        overrides: Vec::new(),
    };
    let r = study::run(&request).map_err(|e| js_error(&e.to_string()))?;
    serde_json::to_string(&r).map_err(|e| js_error(&e.to_string()))
}

/// The declarations of the IPS tool's operating point and Bode range, as JSON: `[{"path",
/// "kind", "label", "unit", "help", "source", "default", "min", "max", "span"}, ...]` (the paths
/// are `aes_core::studies::ips::study::OperatingPoint`'s fields; `span` is a slider's [from, to]).
/// The stability tab's sliders, their ranges and the synchronous speed come from it.
#[wasm_bindgen(js_name = ipsMeta)]
pub fn ips_meta() -> String {
    serde_json::to_string(&aes_core::studies::ips::study::meta()).unwrap_or_default()
}

/// Is the bus stable at a scenario's operating point (`aes-sim stability-map FILE`): the plant
/// with its bus loads and storage linearised at `initial.speed_kn` (`stability_map::linearize`),
/// as JSON: `states`, `eigenvalues` [[re, im] 1/s], `spectral_abscissa` [1/s], `least_damped_hz`.
#[wasm_bindgen(js_name = stabilityPoint)]
pub fn stability_point(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let m = aes_core::studies::stability_map::linearize(&sc).map_err(|e| js_error(&e))?;
    aes_core::checks::check_finite(&m).map_err(|e| js_error(&e))?;
    serde_json::to_string(&m).map_err(|e| js_error(&e.to_string()))
}

/// One axis of a stability map (`aes-sim stability-map --x PATH=FROM:TO:N`) from the page's
/// numbers, checked as the command checks it (`n` a whole number from 2 to `MAX_AXIS_VALUES`,
/// both ends a value the scenario takes at `path`, named with `which`, e.g. "x axis"), as the
/// JSON of `stability_map::Axis`: the page puts two of them and the scenario into the spec of the
/// "stability-map" study (`studyRange`, `studySummary`), so its values are the command's.
#[wasm_bindgen(js_name = stabilityAxis)]
pub fn stability_axis(
    json: JsValue,
    which: JsValue,
    path: JsValue,
    from: f64,
    to: f64,
    n: f64,
) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    // Text by a check of its own: a `&str` argument given a boolean or number trapped in the glue.
    let which = text(&which, "stabilityAxis: the axis's name")?;
    let which = which.as_str();
    let path = path.as_string().ok_or_else(|| js_error(&format!("{which}: the parameter's path must be a string")))?;
    let max = stability_map::MAX_AXIS_VALUES;
    if !(n.fract() == 0.0 && (2.0..=max as f64).contains(&n)) {
        let shown = if n.is_finite() { aes_core::checks::num(n) } else { "a value that is not a finite number".into() };
        return Err(js_error(&format!("{which}: {shown} values of {path}: a whole number from 2 to {max}")));
    }
    let axis = stability_map::Axis::checked(&sc, which, &path, from, to, n as usize).map_err(|e| js_error(&e))?;
    serde_json::to_string(&axis).map_err(|e| js_error(&e.to_string()))
}

/// The LQG/LTR design (thesis ch. 3.1) for a scenario's drive train and `controllers.lqg_ltr`
/// tuning, with its singular values, closed-loop poles and input margins, as JSON (the format of
/// `aes-sim design lqg-ltr --plant aes`).
#[wasm_bindgen(js_name = designLqgLtr)]
pub fn design_lqg_ltr(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let d = aes_core::sim::lqg::analyse(&sc).map_err(|e| js_error(&e))?;
    aes_core::checks::check_finite(&d).map_err(|e| js_error(&e))?;
    serde_json::to_string(&d).map_err(|e| js_error(&e.to_string()))
}

/// The histogram bins trial `i` of a Monte Carlo study falls in (`at_time`, `excess`,
/// `excess_vs_calm`, `arrival`: a bin index or null), as JSON: the page finds a trial to replay
/// from a histogram bar with it.
#[wasm_bindgen(js_name = trialBins)]
pub fn trial_bins(json: JsValue, i: u32) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    if i as u64 >= sc.monte_carlo.trials {
        return Err(js_error(&format!("trial {i}: the study has {} trials", sc.monte_carlo.trials)));
    }
    let b = aes_core::studies::montecarlo::trial_bins(&sc, i as u64).map_err(|e| js_error(&e))?;
    serde_json::to_string(&b).map_err(|e| js_error(&e.to_string()))
}

/// The scenario of Monte Carlo trial `i` as JSON text: the study's scenario sailing the sea of
/// seed `trial_seed(sim.seed, i)`, which reproduces the trial as a single run. Text, because the
/// seed uses all 64 bits and a JavaScript number keeps 53.
#[wasm_bindgen(js_name = trialScenario)]
pub fn trial_scenario(json: JsValue, i: f64) -> Result<String, JsError> {
    let i = whole(i, "trialScenario: trial", u32::MAX)?;
    let mut sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    if i as u64 >= sc.monte_carlo.trials {
        return Err(js_error(&format!(
            "trial {i}: the study has trials 0 to {}",
            sc.monte_carlo.trials.saturating_sub(1)
        )));
    }
    sc.sim.seed = aes_core::studies::stats::trial_seed(sc.sim.seed, i as u64);
    Ok(sc.to_json())
}

/// Items `a..b` of a study on the shared pipeline (`kind`: one of `studyKinds()`; `spec`: the
/// study's definition as JSON, e.g. a scenario for "monte-carlo"), run one after another in this
/// worker; returns the shard in binary form (`study::to_bytes`: the envelope as JSON, the part
/// packed), to be merged with the other workers' by `studySummary`.
#[wasm_bindgen(js_name = studyRange)]
pub fn study_range(kind: JsValue, spec: JsValue, a: u32, b: u32) -> Result<Vec<u8>, JsError> {
    struct Range(String, u64, u64);
    impl study::Visit for Range {
        type Out = Result<Vec<u8>, String>;
        fn visit<S: study::Study>(self) -> Result<Vec<u8>, String> {
            let s = S::new(spec_of::<S>(&self.0)?)?;
            study::to_bytes::<S>(&study::run_range(&s, self.1, self.2)?)
        }
    }
    let kind = text(&kind, "the study kind")?;
    let spec = text(&spec, "the study JSON")?;
    study::dispatch(&kind, Range(spec, a as u64, b as u64)).and_then(|r| r).map_err(|e| js_error(&e))
}

/// The summary JSON of a study (as its `aes-sim` command prints it, keys sorted) from the binary
/// shards of `studyRange`: each is checked and merged; the result does not depend on how the
/// items were split or in which order the shards come.
#[wasm_bindgen(js_name = studySummary)]
pub fn study_summary(kind: JsValue, spec: JsValue, shards: Vec<js_sys::Uint8Array>) -> Result<String, JsError> {
    struct Summary(String, Vec<js_sys::Uint8Array>);
    impl study::Visit for Summary {
        type Out = Result<String, String>;
        fn visit<S: study::Study>(self) -> Result<String, String> {
            let mut m = study::Merger::new(S::new(spec_of::<S>(&self.0)?)?);
            for b in &self.1 {
                m.add(study::from_bytes::<S>(&b.to_vec())?)?;
            }
            let (s, shard) = m.finish()?;
            let summary = s.summary(&shard.part, &shard.ranges)?;
            aes_core::checks::check_finite(&summary)?;
            // Through a Value, whose keys are sorted, as `aes-sim` prints it.
            Ok(serde_json::to_value(&summary).map_err(|e| e.to_string())?.to_string())
        }
    }
    let kind = text(&kind, "the study kind")?;
    let spec = text(&spec, "the study JSON")?;
    study::dispatch(&kind, Summary(spec, shards)).and_then(|r| r).map_err(|e| js_error(&e))
}

/// The estimate of a study on the shared pipeline before it starts, as JSON: `{"items",
/// "item_work", "seconds"}`, `seconds` the wall clock its items take in this browser on
/// `workers` workers (`study::wall_estimate_s`), or `{"items"}` alone for a study whose items
/// are not runs. The page asks before a long Compute.
#[wasm_bindgen(js_name = studyEstimate)]
pub fn study_estimate(kind: JsValue, spec: JsValue, workers: f64) -> Result<String, JsError> {
    let workers = whole(workers, "studyEstimate: workers", 1024)?;
    struct Ask(String, usize);
    impl study::Visit for Ask {
        type Out = Result<String, String>;
        fn visit<S: study::Study>(self) -> Result<String, String> {
            let s = S::new(spec_of::<S>(&self.0)?)?;
            let e = study::estimate(&s, s.items(), self.1, study::Platform::Wasm);
            aes_core::checks::check_finite(&e)?;
            serde_json::to_string(&e).map_err(|e| e.to_string())
        }
    }
    let kind = text(&kind, "the study kind")?;
    let spec = text(&spec, "the study JSON")?;
    study::dispatch(&kind, Ask(spec, workers.max(1) as usize)).and_then(|r| r).map_err(|e| js_error(&e))
}

/// A study's definition from JSON ([`study::Study::spec_from_json`]).
fn spec_of<S: study::Study>(text: &str) -> Result<S::Spec, String> {
    S::spec_from_json(text).map_err(|e| format!("the {} study: {e}", S::KIND))
}

/// The RAO table of a scenario's seakeeping grid as flat numbers and their digest (built here
/// once, or taken from this worker's cache): the page builds it in one worker and hands it to the
/// Monte Carlo workers (`raoTableLoad`, which takes it only as this scenario's table), so no worker
/// builds it again.
#[wasm_bindgen(js_name = raoTableValues)]
pub fn rao_table_values(json: JsValue) -> Result<Vec<f64>, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    sc.rao_table_values().map_err(|e| js_error(&e))
}

/// The scenario every trial of a rare-event study runs (`rare_event` set, the ship's place at
/// the event from a run in waves; `aes-sim rare`'s `replay_sets`), as JSON: the page runs it
/// with `rare_event.shape = "most_likely"` to show the most likely wave group, or with a trial's
/// seed to replay that trial.
#[wasm_bindgen(js_name = rareScenario)]
pub fn rare_scenario(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let t = aes_core::studies::rare::trial_scenario(&sc).map_err(|e| js_error(&e))?;
    Ok(t.to_json())
}

/// The scenario with the ship placed at the event (`rare_event.ship_*`) by `passes` runs to it in
/// the scenario's own conditioned sea: the most likely wave group (`rare_event.shape =
/// "most_likely"`) slows the ship less than a random sea, so its place is found in it.
#[wasm_bindgen(js_name = rarePlace)]
pub fn rare_place(json: JsValue, passes: f64) -> Result<String, JsError> {
    let passes = whole(passes, "rarePlace: passes", 5)?;
    let mut sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    if passes > 5 {
        return Err(js_error("rarePlace: at most 5 passes"));
    }
    aes_core::studies::rare::place_ship(&mut sc, passes as usize).map_err(|e| js_error(&e))?;
    Ok(sc.to_json())
}

/// Puts the table of `raoTableValues` (from another worker) into this worker's cache.
#[wasm_bindgen(js_name = raoTableLoad)]
pub fn rao_table_load(json: JsValue, values: &[f64]) -> Result<(), JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    sc.insert_rao_table(values).map_err(|e| js_error(&e))
}

/// RAOs of a scenario's hull (`aes-sim rao`'s JSON) at `speed_kn` and `heading_deg` over
/// `omegas` [rad/s].
#[wasm_bindgen(js_name = raoJson)]
pub fn rao_json(json: JsValue, speed_kn: f64, heading_deg: f64, omegas: Vec<f64>) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    if omegas.is_empty() || omegas.len() > 400 || omegas.iter().any(|w| !(w.is_finite() && (0.05..=10.0).contains(w))) {
        return Err(js_error("RAOs: 1 to 400 frequencies from 0.05 to 10 rad/s"));
    }
    if !(speed_kn.is_finite() && (0.0..=40.0).contains(&speed_kn) && heading_deg.is_finite()) {
        return Err(js_error("RAOs: speed 0 to 40 kn and a finite heading"));
    }
    let mut ship = sc.ship_hull().and_then(|h| h.strip_ship()).map_err(|e| js_error(&e))?;
    ship.aft_end_terms = sc.seakeeping.aft_end_terms;
    ship.short_wave = sc.seakeeping.short_wave_force;
    let v = aes_core::sea::seakeeping::tables::rao_json(
        &ship,
        speed_kn * aes_core::numerics::units::KNOT_M_S,
        heading_deg.to_radians(),
        &omegas,
        1.0,
    )
    .map_err(|e| js_error(&e))?;
    Ok(v.to_string())
}

/// The fuel study of ch. 5.2.4 (Fig. 5-12) from a scenario: JSON rows as `aes-sim fuel` prints (no
/// frequencies: Fig. 5-12's).
#[wasm_bindgen(js_name = fuelStudy)]
pub fn fuel_study(json: JsValue, omegas: Vec<f64>) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let rows = aes_core::studies::fuel::run(&sc, &omegas).map_err(|e| js_error(&e))?;
    serde_json::to_string(&rows).map_err(|e| js_error(&e.to_string()))
}

/// The turbine schedule of a scenario's plant (`aes-sim schedule --json`'s `schedule`): for each
/// speed and sea state 2-6 the online sets that burn least fuel with the reserve.
#[wasm_bindgen(js_name = turbineSchedule)]
pub fn turbine_schedule(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let s = aes_core::studies::schedule::run(&sc).map_err(|e| js_error(&e))?;
    serde_json::to_string(&s).map_err(|e| js_error(&e.to_string()))
}

/// The standard maneuvers booklet of a scenario's ship (`aes-sim maneuvers`' JSON, tracks included).
#[wasm_bindgen(js_name = maneuversBooklet)]
pub fn maneuvers_booklet(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let b = aes_core::studies::maneuvers::booklet(&sc).map_err(|e| js_error(&e))?;
    serde_json::to_string(&b).map_err(|e| js_error(&e.to_string()))
}

/// The side profile and waterline of the hull a run in waves uses, as JSON (the live stern and
/// plan views draw it; positions from the aft perpendicular, heights from the calm waterline).
#[wasm_bindgen(js_name = hullProfile)]
pub fn hull_profile(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let p = aes_core::output::presentation::HullProfile::of(&sc).map_err(|e| js_error(&e))?;
    serde_json::to_string(&p).map_err(|e| js_error(&e.to_string()))
}

/// The hull panel of a scenario's hull as JSON: body plan (every station's offsets), profile,
/// appendages and hydrostatics at its loading (`presentation::HullSheet`).
#[wasm_bindgen(js_name = hullSheet)]
pub fn hull_sheet(json: JsValue) -> Result<String, JsError> {
    let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let p = aes_core::output::presentation::HullSheet::of(&sc).map_err(|e| js_error(&e))?;
    serde_json::to_string(&p).map_err(|e| js_error(&e.to_string()))
}

/// The embedded hulls' names, then "custom" (offsets of one's own).
#[wasm_bindgen(js_name = hullNames)]
pub fn hull_names() -> Vec<String> {
    aes_core::ship::hull::HULL_NAMES.iter().map(|s| s.to_string()).collect()
}

/// The advance ratios of the propeller panel's curves: `aes-sim propeller`'s default `--j
/// 0:1.2:25`, so the page and the command line give the same points.
const PANEL_J: (f64, f64, usize) = (0.0, 1.2, 25);

/// A custom blade geometry (`propeller.geometry` with name "custom") from a CSV table with the
/// header of core/data/dtmb4119_geometry.csv, as JSON; a bad table is refused with the core's
/// message naming the row and column.
#[wasm_bindgen(js_name = propellerGeometryCsv)]
pub fn propeller_geometry_csv(text: JsValue, blades: f64, hub_ratio: f64) -> Result<String, JsError> {
    let text = self::text(&text, "the blade table")?;
    // A number from a form field: whole, then the core's range check names its range.
    if !(blades.is_finite() && blades.fract() == 0.0 && blades >= 0.0) {
        return Err(js_error(&format!(
            "blades: {} is not a whole number of blades",
            aes_core::checks::shorten(&blades.to_string())
        )));
    }
    let blades = blades.min(u32::MAX as f64) as u32;
    let spec = aes_core::plant::propeller_geometry::GeometrySpec::from_csv(&text, blades, hub_ratio)
        .map_err(|e| js_error(&e))?;
    serde_json::to_string(&spec).map_err(|e| js_error(&e.to_string()))
}

/// The propeller panel of a scenario as JSON: the blades of its `propeller.geometry` (the ship's
/// B-series equivalent without one) with the expanded outline (`rows`: r_r, c_d, p_d, skew_deg,
/// `leading_d` and `trailing_d`: the edges' chordwise positions over D, half a chord either side
/// of the mid-chord, which skew moves along the arc by (r/R)(D/2) times the skew angle),
/// `pitch_07` and `area_ratio` (Ae/A0 from the chords); `open_water` (j, kt, kq, eta, converged:
/// the vortex lattice, the run's model, in the flow the run's table is built in, `flow`) over J = 0 to 1.2 in 25
/// points as `aes-sim propeller` gives them; `series` (blades, pitch_ratio, area_ratio, held and
/// its `rows` j, kt, kq, eta: the B-series polynomial of the same Z, P/D at 0.7 R and Ae/A0);
/// and `runs_it` (whether the scenario's `propeller.model` is "geometry").
#[wasm_bindgen(js_name = propellerCurves)]
pub fn propeller_curves(json: JsValue) -> Result<String, JsError> {
    use aes_core::plant::{blade, propeller_table as table};
    let mut sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
    let runs_it = sc.propeller.model == aes_core::scenario::PropellerModelKind::Geometry;
    let spec = sc.propeller.geometry.clone().unwrap_or_default();
    sc.propeller.geometry = Some(spec.clone());
    let g = spec
        .resolve(&sc.propeller.b_series_of())
        .map_err(|(f, e)| js_error(&format!("propeller.geometry.{f}: {e}")))?;
    let flow = sc.propeller_design_flow();
    let (from, to, n) = PANEL_J;
    let js: Vec<f64> = (0..n).map(|k| from + (to - from) * k as f64 / (n - 1) as f64).collect();
    let curve = blade::vortex_lattice::open_water(&g, &js, &flow).map_err(|e| js_error(&e))?;
    let e = table::series_equivalent(&g);
    let series = aes_core::plant::propeller::OpenWater::b_series(e.pitch_ratio, e.area_ratio, e.blades)
        .map_err(|e| js_error(&e))?;
    let rows: Vec<_> = g
        .rows
        .iter()
        .map(|r| {
            let mid = 0.5 * r.r_r * r.skew_deg.to_radians();
            serde_json::json!({
                "r_r": r.r_r, "c_d": r.c_d, "p_d": r.p_d, "skew_deg": r.skew_deg,
                "leading_d": mid - 0.5 * r.c_d, "trailing_d": mid + 0.5 * r.c_d,
            })
        })
        .collect();
    let out = serde_json::json!({
        "name": spec.name,
        "runs_it": runs_it,
        "blades": g.blades,
        "hub_ratio": g.hub_ratio,
        "pitch_07": table::pitch_at_07(&g),
        "area_ratio": table::area_ratio(&g),
        "flow": flow,
        "rows": rows,
        "open_water": curve.iter().map(|p| serde_json::json!({"j": p.j, "kt": p.kt, "kq": p.kq, "eta": p.eta, "converged": p.converged})).collect::<Vec<_>>(),
        "series": {
            "blades": e.blades, "pitch_ratio": e.pitch_ratio, "area_ratio": e.area_ratio, "held": e.held,
            "rows": js.iter().map(|&j| serde_json::json!({"j": j, "kt": series.kt(j), "kq": series.kq(j), "eta": series.efficiency(j)})).collect::<Vec<_>>(),
        },
    });
    aes_core::checks::check_finite(&out).map_err(|e| js_error(&e))?;
    Ok(out.to_string())
}

/// A run's sea surface for pictures: the same seeded wave components the run sails in
/// (`sim::seaway::wave_components`), summed at points the page asks for.
#[wasm_bindgen]
pub struct Sea {
    comps: Vec<aes_core::sea::waves::WaveComponent>,
    out: Vec<f64>,
}

/// How far from the origin [m] the sea's elevation is given: five days at 40 kn, where the
/// shortest waves' phase (k x, some 1e7 rad) is still good to 1e-9 rad.
const MAX_SEA_POINT_M: f64 = 1.0e7;
/// Latest time [s] the sea's elevation is given: 115 days, where the fastest components' phase
/// (omega t, some 5e7 rad) is still good to 1e-8 rad (at 1e308 s it overflowed to NaN).
const MAX_SEA_TIME_S: f64 = 1.0e7;

#[wasm_bindgen]
impl Sea {
    /// The sea of a scenario (no components in calm water).
    #[wasm_bindgen(constructor)]
    pub fn new(json: JsValue) -> Result<Sea, JsError> {
        let sc = Scenario::from_json(&text(&json, "the scenario JSON")?).map_err(|e| js_error(&e.to_string()))?;
        Ok(Sea { comps: aes_core::sim::seaway::wave_components(&sc), out: Vec::new() })
    }

    /// Number of wave components.
    #[wasm_bindgen(getter)]
    pub fn components(&self) -> usize {
        self.comps.len()
    }

    /// Surface elevation [m, up] at the points (xs\[i\] north, ys\[i\] east) \[m\] at time t \[s\]
    /// (eq. 2.55's superposition; at most 20,000 points a call).
    pub fn elevations(&mut self, t: f64, xs: &[f64], ys: &[f64]) -> Result<js_sys::Float64Array, JsError> {
        if t.is_nan() || t.abs() > MAX_SEA_TIME_S {
            let shown = if t.is_finite() { aes_core::checks::num(t) } else { "a value that is not finite".into() };
            return Err(js_error(&format!(
                "elevations: t = {shown}: the time must be a finite number of seconds within {MAX_SEA_TIME_S:e}"
            )));
        }
        if xs.len() != ys.len() || xs.len() > 20_000 {
            return Err(js_error("elevations: xs and ys of equal length, at most 20000 points"));
        }
        // Far out the wave phases k x lose their digits (at 1e300 m nothing of them is left).
        if let Some(i) = (0..xs.len()).find(|&i| !(xs[i].abs() <= MAX_SEA_POINT_M && ys[i].abs() <= MAX_SEA_POINT_M)) {
            let coord =
                |x: f64| if x.is_finite() { aes_core::checks::num(x) } else { "a value that is not finite".into() };
            return Err(js_error(&format!(
                "elevations: point {i} at ({}, {}) m: each coordinate must be a finite number of metres within {MAX_SEA_POINT_M:e}",
                coord(xs[i]),
                coord(ys[i])
            )));
        }
        self.out.resize(xs.len(), 0.0);
        aes_core::sea::waves::elevations(&self.comps, xs, ys, t, &mut self.out);
        if let Some(i) = self.out.iter().position(|z| !z.is_finite()) {
            return Err(js_error(&format!("elevations: point {i}: the elevation is not a finite number")));
        }
        Ok(js_sys::Float64Array::from(self.out.as_slice()))
    }
}
