//! Golden baselines: the summary and a fingerprint of the trace of every preset, stored under
//! `tests/golden/` and compared exactly (every number with its full bits, via serde_json's
//! float round trip). A change of the physics, however small, shows here and in review.
//!
//! A deliberate change regenerates them with one command (`./build.sh golden`, i.e.
//! `UPDATE_GOLDEN=1 cargo test --release -p aes-tests --test golden`); the diff of the JSON files
//! then shows which numbers moved and by how much.
//! The records are made by `aes_core::studies::regression::record`; the wasm tests compare the same.

use aes_core::scenario::presets::PRESET_NAMES;
use aes_core::studies::regression::record;
use std::path::PathBuf;

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("golden").join(format!("{name}.json"))
}

#[test]
fn every_preset_matches_its_golden_record() {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let mut failed = Vec::new();
    for name in PRESET_NAMES {
        let now = record(name).unwrap_or_else(|e| panic!("{e}"));
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

/// Every stage efficiency in the records is a fraction (0 to 1) or `null` with its reason in
/// `not_given`: in the records made with the final time's ratio of powers, head-seas-ss6 gave a
/// generator efficiency of 1.81, mc-excess-energy 1.42, ac-braking a propeller 1.26 and
/// head-seas-ss6-storage power electronics 1.05 (a rotor or the ship giving up stored energy).
#[test]
fn every_stage_efficiency_is_a_fraction_or_says_why() {
    for name in PRESET_NAMES {
        let text = std::fs::read_to_string(path(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        let v: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let eff = &v["summary"]["efficiency"];
        let not_given = eff["not_given"].as_array().unwrap_or_else(|| panic!("{name}: no not_given list"));
        let mut missing = 0;
        for stage in ["generator", "power_electronics", "motor", "propeller"] {
            match eff[stage].as_f64() {
                Some(x) => assert!((0.0..=1.0).contains(&x), "{name}: {stage} efficiency {x}"),
                None => {
                    assert!(eff[stage].is_null(), "{name}: {stage} = {}", eff[stage]);
                    missing += 1;
                }
            }
        }
        assert_eq!(missing, not_given.len(), "{name}: {missing} stages not given, {} reasons", not_given.len());
        let (from, to) = (eff["from_s"].as_f64().unwrap(), eff["to_s"].as_f64().unwrap());
        assert!(
            from < to && to - from <= aes_core::sim::summary::EFFICIENCY_WINDOW_S + 1e-9,
            "{name}: window {from}..{to}"
        );
    }
}
