//! Runs a short start-up, a turn, a run in head seas, a small operability polar and a rare-event study natively at build time and stores their summaries, so the wasm tests can check
//! that the browser computes the same numbers bit for bit; and lists the golden record of every preset
//! (tests/golden/NAME.json, from the preset list itself) for the wasm golden test.
fn main() {
    let mut s = aes_core::scenario::presets::startup();
    s.sim.duration_s = 60.0;
    let summary = aes_core::run(&s).map(|r| r.summary.to_json_value().to_string()).unwrap_or_default();
    let mut m = aes_core::scenario::presets::preset("turn-90").unwrap_or_default();
    m.sim.duration_s = 40.0;
    let turn = aes_core::run(&m).map(|r| r.summary.to_json_value().to_string()).unwrap_or_default();
    let mut h = aes_core::scenario::presets::preset("head-seas-ss6").unwrap_or_default();
    h.sim.duration_s = 10.0;
    h.seakeeping.stern_motion = aes_core::scenario::SternMotion::ThesisEq257;
    let seas = aes_core::run(&h).map(|r| r.summary.to_json_value().to_string()).unwrap_or_default();
    // The same with the multi-rate hull step (stepping.hull_substeps = 4: 10 ms).
    h.stepping.hull_substeps = 4;
    let multirate = aes_core::run(&h).map(|r| r.summary.to_json_value().to_string()).unwrap_or_default();
    // Issue 31 and 32: a small operability polar and a rare-event study of three trials.
    let mut r = aes_core::scenario::presets::preset("head-seas-ss6").unwrap_or_default();
    r.rare_event.level_h_over_r = 1.1;
    r.sim.duration_s = 165.0;
    let rare = aes_core::studies::rare::trial_scenario(&r)
        .and_then(|t| {
            let p = aes_core::studies::rare::run_range(&t, 0, 3)?;
            aes_core::studies::rare::summary(&t, &p, &Default::default())
        })
        .map(|s| serde_json::to_string(&s).unwrap_or_default())
        .unwrap_or_default();
    let spec = aes_core::studies::operability::PolarSpec {
        speeds_kn: vec![0.0, 20.0],
        headings_deg: vec![0.0, 90.0, 180.0, 225.0],
        ..Default::default()
    };
    let scatter = aes_core::studies::operability::scatter::Scatter::north_atlantic();
    let polar = aes_core::studies::operability::polar(&r, spec, Some(&scatter))
        .map(|p| serde_json::to_string(&p).unwrap_or_default())
        .unwrap_or_default();
    let out = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into());
    let _ = std::fs::write(format!("{out}/native_rare.json"), rare);
    let _ = std::fs::write(format!("{out}/native_operability.json"), polar);
    let _ = std::fs::write(format!("{out}/native_head_seas_10s.json"), seas);
    let _ = std::fs::write(format!("{out}/native_head_seas_10s_multirate.json"), multirate);
    let _ = std::fs::write(format!("{out}/native_startup_60s.json"), summary);
    let _ = std::fs::write(format!("{out}/native_turn90_40s.json"), turn);
    let golden = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/golden");
    let list: Vec<String> = aes_core::scenario::presets::PRESET_NAMES
        .iter()
        .map(|n| format!("({n:?}, include_str!({:?}))", golden.join(format!("{n}.json")).display().to_string()))
        .collect();
    let _ = std::fs::write(format!("{out}/golden_files.rs"), format!("[{}]", list.join(",\n")));
    println!("cargo:rerun-if-changed=../core/src");
    println!("cargo:rerun-if-changed=../tests/golden");
}
