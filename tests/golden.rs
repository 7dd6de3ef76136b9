//! Golden baselines: the summary and a fingerprint of the trace of every preset, stored under
//! `tests/golden/` and compared exactly (every number with its full bits, via serde_json's
//! float round trip). A change of the physics, however small, shows here and in review.
//!
//! A deliberate change regenerates them with one command (`./build.sh golden`, i.e.
//! `UPDATE_GOLDEN=1 cargo test --release -p aes-tests --test golden`); the diff of the JSON files
//! then shows which numbers moved and by how much.
//!
//! The long presets run in full (the whole suite takes a few seconds natively); the two Monte
//! Carlo presets store one trial's run and a four-trial study shortened to 20 s.

use aes_core::montecarlo::{run_range, summary};
use aes_core::presets::{preset, PRESET_NAMES};
use std::path::PathBuf;

/// FNV-1a over the bits of every trace value, column by column: equal only if every recorded
/// number is identical.
fn fingerprint(columns: &[Vec<f64>]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for col in columns {
        for v in col {
            for b in v.to_bits().to_le_bytes() {
                h ^= b as u64;
                h = h.wrapping_mul(0x0000_0100_0000_01b3);
            }
        }
    }
    format!("{h:016x}")
}

/// The golden record of one preset as pretty JSON.
fn record(name: &str) -> String {
    let sc = preset(name).unwrap_or_else(|| panic!("no preset {name}"));
    let r = aes_core::run(&sc).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut v = serde_json::json!({
        "preset": name,
        "trace_rows": r.trace.len(),
        "trace_fingerprint": fingerprint(&r.trace.columns),
        "summary": r.summary.to_json_value(),
    });
    if sc.monte_carlo.excess_energy || sc.monte_carlo.stop_at_first_event || name.starts_with("mc-") {
        let mut m = sc.clone();
        m.monte_carlo.trials = 4;
        m.sim.duration_s = 20.0;
        m.monte_carlo.histogram_time_s = 10.0;
        m.monte_carlo.periodogram_segment_s = 5.0;
        let p = run_range(&m, 0, 4).unwrap_or_else(|e| panic!("{name} Monte Carlo: {e}"));
        v["monte_carlo_4_trials_20s"] = summary(&p).unwrap_or_else(|e| panic!("{name} Monte Carlo summary: {e}"));
    }
    let mut s = serde_json::to_string_pretty(&v).expect("golden record serialises");
    s.push('\n');
    s
}

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("golden").join(format!("{name}.json"))
}

#[test]
fn every_preset_matches_its_golden_record() {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let mut failed = Vec::new();
    for name in PRESET_NAMES {
        let now = record(name);
        let p = path(name);
        if update {
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(&p, &now).unwrap();
            continue;
        }
        let stored = std::fs::read_to_string(&p)
            .unwrap_or_else(|_| panic!("{} is missing: run ./build.sh golden and review the diff", p.display()));
        if stored != now {
            // Name the first differing line so the failure says what moved.
            let line = stored
                .lines()
                .zip(now.lines())
                .find(|(a, b)| a != b)
                .map(|(a, b)| format!("stored `{}`, now `{}`", a.trim(), b.trim()))
                .unwrap_or_else(|| "different length".into());
            failed.push(format!("{name}: {line}"));
        }
    }
    assert!(
        failed.is_empty(),
        "golden records differ (a deliberate physics change: ./build.sh golden, then review the diff):\n{}",
        failed.join("\n")
    );
}
