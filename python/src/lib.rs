//! aes-python: PyO3 bindings over aes-core for the `aes_sim` Python package. Thin: no physics
//! here. Scenarios cross as JSON text (the public format of the command line and the page), so a
//! scenario file, a Python dict and a preset speak one language and give the same bits; the
//! package's Python half (python/aes_sim/) makes dicts and numpy arrays of what this returns.
//!
//! Every run and study releases the GIL while Rust computes. A study runs on its own thread
//! while the calling thread, every 100 ms, takes the GIL back to call the progress callback
//! and to look for Ctrl-C: either stops the study's remaining items, and the exception is raised.

use aes_core::checks::shorten;
use aes_core::scenario::presets::{preset, PRESET_NAMES};
use aes_core::studies::study::{self, Study};
use aes_core::{Scenario, Simulation};
use pyo3::prelude::*;
use pyo3::types::PyByteArray;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Duration;

pyo3::create_exception!(
    _aes_sim,
    AesSimError,
    pyo3::exceptions::PyException,
    "A scenario, a setting, a run or a study refused; the message is the command line's."
);

/// How often a running study reports progress and looks for Ctrl-C.
const POLL: Duration = Duration::from_millis(100);

fn err(e: impl std::fmt::Display) -> PyErr {
    AesSimError::new_err(e.to_string())
}

/// The command line's message for a preset name it does not know.
fn no_preset(name: &str) -> String {
    format!("no preset named '{}' (try: {})", shorten(name), PRESET_NAMES.join(", "))
}

/// Names of the preset scenarios with their descriptions, in the command line's order.
#[pyfunction]
fn presets() -> Vec<(&'static str, String)> {
    PRESET_NAMES.iter().map(|n| (*n, preset(n).map(|s| s.description).unwrap_or_default())).collect()
}

/// A preset scenario as JSON text (`aes-sim preset NAME`).
#[pyfunction]
fn preset_json(name: &str) -> PyResult<String> {
    preset(name).map(|s| s.to_json()).ok_or_else(|| err(no_preset(name)))
}

/// Every scenario parameter's declaration as JSON (`aes-sim params --json`).
#[pyfunction]
fn params_json() -> PyResult<String> {
    serde_json::to_string(&aes_core::scenario::registry::all()).map_err(err)
}

/// Every trace signal's name, unit, label and description as JSON (`aes-sim signals --json`).
#[pyfunction]
fn signals_json() -> PyResult<String> {
    serde_json::to_string(aes_core::signals::SIGNALS).map_err(err)
}

/// Reads a scenario (JSON text from `source`, named in the error as the command line names a
/// file) and gives it back in its canonical JSON: migrated, checked.
#[pyfunction]
fn scenario_json(text: &str, source: &str) -> PyResult<String> {
    Scenario::from_json(text)
        .map(|s| s.to_json())
        .map_err(|e| err(format!("{}: invalid scenario:\n{e}", shorten(source))))
}

/// A canonical scenario with `sets` (path, value as JSON text) applied all at once, refused as
/// `aes-sim run --set PATH=VALUE` refuses.
#[pyfunction]
fn scenario_set(text: &str, sets: Vec<(String, String)>) -> PyResult<String> {
    let sc = Scenario::from_json(text).map_err(err)?;
    let pairs: Vec<(&str, &str)> = sets.iter().map(|(p, v)| (p.trim(), v.trim())).collect();
    // The command line's words (`Scenario::with_set_flags`, as `aes-sim run --set` says them).
    sc.with_set_flags(&pairs).map(|s| s.to_json()).map_err(err)
}

/// A summary as the command line prints it: every number checked finite, the keys sorted.
fn summary_text<T: serde::Serialize>(x: &T) -> Result<String, String> {
    aes_core::checks::check_finite(x)?;
    let v = serde_json::to_value(x).map_err(|e| e.to_string())?;
    serde_json::to_string(&v).map_err(|e| e.to_string())
}

/// Time steps a run takes between two looks for Ctrl-C (a few hundredths of a second of wall
/// clock: a start-up runs about a million steps a second natively).
const RUN_CHUNK_STEPS: u64 = 50_000;

/// One scenario to its end (`aes-sim run`): its summary as JSON, its trace as one bytearray of
/// little-endian f64 (the columns of `signals_json`'s order one after another) and its rows. The
/// GIL is released while it steps; between chunks of steps Ctrl-C stops it (the chunks give the
/// same bits as one advance to the end: stepping does not depend on where it pauses).
#[pyfunction]
fn run(py: Python<'_>, text: &str) -> PyResult<(String, Py<PyByteArray>, usize)> {
    let sc = Scenario::from_json(text).map_err(err)?;
    let mut sim = py.detach(|| Simulation::new(&sc)).map_err(err)?;
    while !sim.done() {
        py.detach(|| sim.advance(RUN_CHUNK_STEPS)).map_err(err)?;
        py.check_signals()?;
    }
    let r = py.detach(|| sim.finish());
    let summary = summary_text(&r.summary).map_err(err)?;
    let rows = r.trace.len();
    let n = r.trace.columns.len() * rows * 8;
    let bytes = PyByteArray::new_with(py, n, |buf| {
        for (chunk, x) in buf.chunks_exact_mut(8).zip(r.trace.columns.iter().flatten()) {
            chunk.copy_from_slice(&x.to_le_bytes());
        }
        Ok(())
    })?;
    Ok((summary, bytes.unbind(), rows))
}

/// The command line's Monte Carlo (`aes-sim mc FILE --trials N --seed S`): the scenario with its
/// trial count and master seed replaced when given, through the study pipeline; the summary as
/// JSON.
#[pyfunction]
#[pyo3(signature = (text, trials=None, seed=None, threads=None, progress=None))]
fn monte_carlo(
    py: Python<'_>,
    text: &str,
    trials: Option<u64>,
    seed: Option<u64>,
    threads: Option<usize>,
    progress: Option<Py<PyAny>>,
) -> PyResult<String> {
    let mut sc = Scenario::from_json(text).map_err(err)?;
    if let Some(n) = trials {
        sc.monte_carlo.trials = n;
    }
    if let Some(s) = seed {
        sc.sim.seed = s;
    }
    sc.validate().map_err(|e| err(format!("scenario: {e}")))?;
    let s = aes_core::studies::montecarlo::MonteCarlo::new(sc).map_err(|e| err(format!("scenario: {e}")))?;
    Ok(drive(py, &s, None, threads, progress)?.summary)
}

/// The standard maneuvers booklet of a scenario's ship (`aes-sim maneuvers`, IMO MSC.137(76)) as
/// JSON, tracks included.
#[pyfunction]
fn maneuvers(py: Python<'_>, text: &str) -> PyResult<String> {
    let sc = Scenario::from_json(text).map_err(err)?;
    py.detach(|| summary_text(&aes_core::studies::maneuvers::booklet(&sc)?)).map_err(err)
}

/// How many gas turbines should run, speed by speed and sea state by sea state (`aes-sim
/// schedule`, thesis ch. 6.1): the schedule as JSON (`--json`'s `schedule`).
#[pyfunction]
fn schedule(py: Python<'_>, text: &str) -> PyResult<String> {
    let sc = Scenario::from_json(text).map_err(err)?;
    sc.validate().map_err(err)?;
    py.detach(|| summary_text(&aes_core::studies::schedule::run(&sc)?)).map_err(err)
}

/// One axis of a stability map: a scenario number's path, from, to, number of values.
type AxisArg = (String, f64, f64, usize);

/// The bus's stability (`aes-sim stability-map`): without axes the eigenvalues at the scenario's
/// operating point, with both a map over the two parameters on the study pipeline; as JSON.
#[pyfunction]
#[pyo3(signature = (text, x=None, y=None, threads=None, progress=None))]
fn stability_map(
    py: Python<'_>,
    text: &str,
    x: Option<AxisArg>,
    y: Option<AxisArg>,
    threads: Option<usize>,
    progress: Option<Py<PyAny>>,
) -> PyResult<String> {
    use aes_core::studies::stability_map::{linearize, Axis, StabilityMapSpec, StabilityMapStudy};
    let sc = Scenario::from_json(text).map_err(err)?;
    let axis = |which: &str, (path, lo, hi, n): AxisArg| Axis::checked(&sc, which, path.trim(), lo, hi, n).map_err(err);
    match (x, y) {
        (None, None) => py.detach(|| summary_text(&linearize(&sc)?)).map_err(err),
        (Some(x), Some(y)) => {
            let spec = StabilityMapSpec { x: axis("x", x)?, y: axis("y", y)?, scenario: sc.clone() };
            let s = StabilityMapStudy::new(spec).map_err(err)?;
            Ok(drive(py, &s, None, threads, progress)?.summary)
        }
        _ => Err(err("give both x and y for a map, or neither for the eigenvalues at the point")),
    }
}

/// What [`drive`] gives: the summary as JSON (when the study was whole) and the shard as JSON.
struct Outcome {
    summary: String,
    shard: String,
}

/// Any study on the pipeline by its kind (`study.KINDS`) and its definition as JSON (the `spec`
/// of its shards): whole, or items `a..b` as a shard for `merge`.
#[pyfunction]
#[pyo3(signature = (kind, spec, range=None, threads=None, progress=None))]
fn run_study(
    py: Python<'_>,
    kind: &str,
    spec: &str,
    range: Option<(u64, u64)>,
    threads: Option<usize>,
    progress: Option<Py<PyAny>>,
) -> PyResult<(String, String)> {
    struct Visit<'a, 'py> {
        py: Python<'py>,
        spec: &'a str,
        range: Option<(u64, u64)>,
        threads: Option<usize>,
        progress: Option<Py<PyAny>>,
    }
    impl study::Visit for Visit<'_, '_> {
        type Out = PyResult<(String, String)>;
        fn visit<S: Study>(self) -> Self::Out {
            let spec = S::spec_from_json(self.spec).map_err(|e| err(format!("spec: {e}")))?;
            let s = S::new(spec).map_err(|e| err(format!("spec: {e}")))?;
            let o = drive(self.py, &s, self.range, self.threads, self.progress)?;
            Ok((o.summary, o.shard))
        }
    }
    study::dispatch(kind, Visit { py, spec, range, threads, progress }).map_err(err)?
}

/// Merges shards (JSON texts) of one study, of any kind (the first's), and summarises them as
/// `aes-sim merge` does: the summary and the merged shard, as JSON.
#[pyfunction]
fn merge(py: Python<'_>, shards: Vec<String>) -> PyResult<(String, String)> {
    struct Visit<'a> {
        shards: &'a [String],
    }
    impl study::Visit for Visit<'_> {
        type Out = Result<(String, String), String>;
        fn visit<S: Study>(self) -> Self::Out {
            let mut m: Option<study::Merger<S>> = None;
            for (k, text) in self.shards.iter().enumerate() {
                let at = |e: String| format!("shard {k}: {e}");
                let shard = study::from_json::<S>(text).map_err(at)?;
                let m = match &mut m {
                    Some(m) => m,
                    None => m.insert(study::Merger::new(S::new(shard.spec.clone()).map_err(at)?)),
                };
                m.add(shard).map_err(at)?;
            }
            let (s, shard) = m.ok_or("no shards given")?.finish()?;
            let summary = summary_text(&s.summary(&shard.part, &shard.ranges)?)?;
            Ok((summary, serde_json::to_string(&shard).map_err(|e| e.to_string())?))
        }
    }
    let first = shards.first().ok_or_else(|| err("no shards given"))?;
    let kind = study::kind_of(first).map_err(|e| err(format!("shard 0: {e}")))?;
    py.detach(|| study::dispatch(&kind, Visit { shards: &shards })).map_err(err)?.map_err(err)
}

/// The worker threads: `None` or 0 every core, at most the machine's parallelism (as the command
/// line's `--threads`).
fn threads_of(arg: Option<usize>) -> usize {
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    match arg {
        None | Some(0) => cores,
        Some(t) => t.min(cores),
    }
}

/// Why a study stopped early: the items left are skipped with this (its text never reaches the
/// user: the Python exception that stopped the study is raised instead).
const STOPPED: &str = "stopped from Python";

/// Runs items `range` of study `s` (all without it) as the command line's `execute` does: the
/// seakeeping tables first on every thread, what the items share built once, the items on a
/// rayon pool merged with the study's associative merge (the same bits on any number of
/// threads). The GIL is released while it runs; the calling thread polls for progress and
/// Ctrl-C ([`POLL`]).
fn drive<S: Study>(
    py: Python<'_>,
    s: &S,
    range: Option<(u64, u64)>,
    threads: Option<usize>,
    progress: Option<Py<PyAny>>,
) -> PyResult<Outcome> {
    let (a, b) = range.unwrap_or((0, s.items()));
    study::check_range(s, a, b).map_err(|e| err(format!("range {a}..{b}: {e}")))?;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads_of(threads)).build().map_err(err)?;
    let (done, stop) = (AtomicU64::new(0), AtomicBool::new(false));
    let work = || -> Result<Outcome, String> {
        if s.needs_rao_table() {
            pool.install(|| s.scenario().rao_table_with(&Threads))?;
        }
        let part = pool.install(|| -> Result<S::Part, String> {
            use rayon::prelude::*;
            let shared = s.prepare()?;
            (a..b)
                .into_par_iter()
                .map(|i| {
                    if stop.load(Ordering::Relaxed) {
                        return Err(STOPPED.to_string());
                    }
                    let r = s.run(&shared, i);
                    done.fetch_add(1, Ordering::Relaxed);
                    r
                })
                .try_reduce(
                    || s.empty(),
                    |mut x, y| {
                        s.merge(&mut x, &y)?;
                        Ok(x)
                    },
                )
        })?;
        let shard = study::shard(s, vec![(a, b)], part);
        let summary =
            if range.is_none() { summary_text(&s.summary(&shard.part, &shard.ranges)?)? } else { String::new() };
        Ok(Outcome { summary, shard: serde_json::to_string(&shard).map_err(|e| e.to_string())? })
    };
    let mut raised: Option<PyErr> = None;
    let caller = std::thread::current();
    let outcome = std::thread::scope(|scope| {
        // The caller is woken when the study ends: a short study does not wait for the next poll.
        let worker = scope.spawn(|| {
            let r = work();
            caller.unpark();
            r
        });
        loop {
            let finished = py.detach(|| {
                std::thread::park_timeout(POLL);
                worker.is_finished()
            });
            if raised.is_none() {
                let total = b - a;
                let called = match &progress {
                    Some(f) => f.call1(py, (done.load(Ordering::Relaxed), total)).map(drop),
                    None => Ok(()),
                };
                if let Err(e) = called.and_then(|()| py.check_signals()) {
                    stop.store(true, Ordering::Relaxed);
                    raised = Some(e);
                }
            }
            if finished {
                break;
            }
        }
        worker.join()
    });
    if let Some(e) = raised {
        return Err(e);
    }
    match outcome {
        Ok(r) => r.map_err(err),
        Err(_) => Err(err("the study's thread panicked")),
    }
}

/// The independent parts of a seakeeping table on the study's rayon threads.
struct Threads;

impl aes_core::sea::seakeeping::tables::ForEach for Threads {
    fn for_each(&self, n: usize, f: &(dyn Fn(usize) + Sync)) {
        use rayon::prelude::*;
        (0..n).into_par_iter().for_each(f)
    }
}

/// The native half of the `aes_sim` package.
#[pymodule]
fn _aes_sim(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("AesSimError", m.py().get_type::<AesSimError>())?;
    m.add("KINDS", study::KINDS.to_vec())?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(preset_json, m)?)?;
    m.add_function(wrap_pyfunction!(params_json, m)?)?;
    m.add_function(wrap_pyfunction!(signals_json, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_json, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_set, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(monte_carlo, m)?)?;
    m.add_function(wrap_pyfunction!(run_study, m)?)?;
    m.add_function(wrap_pyfunction!(merge, m)?)?;
    m.add_function(wrap_pyfunction!(maneuvers, m)?)?;
    m.add_function(wrap_pyfunction!(schedule, m)?)?;
    m.add_function(wrap_pyfunction!(stability_map, m)?)?;
    Ok(())
}
