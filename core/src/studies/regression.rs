//! Regression records: the summary and a fingerprint of the trace of every preset, as stored
//! under `tests/golden/` and compared exactly natively (tests/golden.rs) and in WebAssembly
//! (web/tests/node.rs). Every number is written with its full bits (serde_json's float round
//! trip), so any change of the physics, however small, shows.
//!
//! The long presets run in full; the two Monte Carlo presets store one trial's run and a
//! four-trial study shortened to 20 s.

use crate::scenario::presets::preset;
use crate::studies::montecarlo::run_study;

/// FNV-1a over the bits of every value of a column: equal only if every recorded number is
/// identical.
pub fn fingerprint(column: &[f64]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for v in column {
        for b in v.to_bits().to_le_bytes() {
            h ^= b as u64;
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    format!("{h:016x}")
}

/// The golden record of one preset as pretty JSON.
pub fn record(name: &str) -> Result<String, String> {
    let sc = preset(name).ok_or_else(|| format!("no preset {name}"))?;
    let r = crate::run(&sc).map_err(|e| format!("{name}: {e}"))?;
    let mut v = serde_json::json!({
        "preset": name,
        "trace_rows": r.trace.len(),
        // One fingerprint per signal, so a review sees which columns moved (and a new signal
        // adds one line).
        "trace_fingerprints": crate::signals::SIGNALS
            .iter()
            .zip(&r.trace.columns)
            .map(|(s, c)| (s.name.to_string(), serde_json::Value::String(fingerprint(c))))
            .collect::<serde_json::Map<_, _>>(),
        "summary": r.summary.to_json_value(),
    });
    if sc.monte_carlo.excess_energy || sc.monte_carlo.stop_at_first_event || name.starts_with("mc-") {
        let mut m = sc.clone();
        m.monte_carlo.trials = 4;
        m.sim.duration_s = 20.0;
        m.monte_carlo.histogram_time_s = 10.0;
        m.monte_carlo.periodogram_segment_s = 5.0;
        let s = run_study(&m).map_err(|e| format!("{name} Monte Carlo: {e}"))?;
        v["monte_carlo_4_trials_20s"] =
            serde_json::to_value(s).map_err(|e| format!("{name} Monte Carlo summary: {e}"))?;
    }
    let mut s = serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?;
    s.push('\n');
    Ok(s)
}
