//! Runs a short start-up, a turn, a run in head seas, a small operability polar, a rare-event
//! study and DTMB 4119's open-water curve (the propeller panel's) natively at build time and stores
//! their results, so the wasm tests can check that the browser computes the same numbers bit for bit; and lists the golden record of every preset
//! (tests/golden/NAME.json, from the preset list itself) for the wasm golden test. Any failure
//! stops the build with its message: an empty file would only fail the comparison later, unexplained.
use aes_core::studies::operability::{study::OperabilityPolar, study::PolarStudySpec, PolarRequest};
use aes_core::studies::rare::{RareEvents, RareSpec};
use aes_core::studies::study::{run_all, Study};

/// A result, or the build stops naming what failed.
fn must<T, E: std::fmt::Display>(what: &str, r: Result<T, E>) -> T {
    r.unwrap_or_else(|e| panic!("web/build.rs: {what}: {e}"))
}

/// A run's summary as JSON.
fn run(what: &str, sc: &aes_core::Scenario) -> String {
    must(what, aes_core::run(sc)).summary.to_json_value().to_string()
}

/// A study's summary as the wasm's `studySummary` gives it (through a Value: keys sorted).
fn summary<S: Study>(what: &str, spec: S::Spec) -> String {
    let s = must(what, S::new(spec));
    must(what, serde_json::to_value(must(what, run_all(&s)))).to_string()
}

fn main() {
    let preset = |name: &str| must(name, aes_core::scenario::presets::preset(name).ok_or("no such preset"));
    let mut s = aes_core::scenario::presets::startup();
    s.sim.duration_s = 60.0;
    let startup = run("startup, 60 s", &s);
    let mut m = preset("turn-90");
    m.sim.duration_s = 40.0;
    let turn = run("turn-90, 40 s", &m);
    let mut h = preset("head-seas-ss6");
    h.sim.duration_s = 10.0;
    h.seakeeping.stern_motion = aes_core::scenario::SternMotion::ThesisEq257;
    let seas = run("head-seas-ss6, 10 s", &h);
    // The same with the multi-rate hull step (stepping.hull_substeps = 4: 10 ms).
    h.stepping.hull_substeps = 4;
    let multirate = run("head-seas-ss6, 10 s, multi-rate", &h);
    // Issue 31 and 32: a small operability polar and a rare-event study of three trials.
    let mut r = preset("head-seas-ss6");
    r.rare_event.level_h_over_r = 1.1;
    r.sim.duration_s = 165.0;
    let rare = summary::<RareEvents>("rare events", must("rare events", RareSpec::new(&r, 3)));
    let request = PolarRequest {
        speeds_kn: Some(vec![0.0, 20.0]),
        headings_deg: Some(vec![0.0, 90.0, 180.0, 225.0]),
        ..Default::default()
    };
    let polar = summary::<OperabilityPolar>("operability", PolarStudySpec { scenario: r, request });
    // Issue 54: DTMB 4119's open water over the propeller panel's 25 J in head-seas-ss6's design
    // flow, as [[J, KT, KQ], ...].
    let p = preset("head-seas-ss6");
    let spec = aes_core::plant::propeller_geometry::GeometrySpec { name: "dtmb4119".into(), ..Default::default() };
    let g = must(
        "DTMB 4119",
        spec.resolve(&p.propeller.b_series_of()).map_err(|(f, e)| format!("propeller.geometry.{f}: {e}")),
    );
    let js: Vec<f64> = (0..25).map(|k| 1.2 * k as f64 / 24.0).collect();
    let ow = must(
        "DTMB 4119's open water",
        aes_core::plant::blade::vortex_lattice::open_water(&g, &js, &p.propeller_design_flow()),
    );
    let curve = serde_json::to_string(&ow.iter().map(|a| [a.j, a.kt, a.kq]).collect::<Vec<_>>()).unwrap_or_default();
    let out = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into());
    let write = |name: &str, text: &str| must(name, std::fs::write(format!("{out}/{name}"), text));
    write("native_rare.json", &rare);
    write("native_propeller_4119.json", &curve);
    write("native_operability.json", &polar);
    write("native_head_seas_10s.json", &seas);
    write("native_head_seas_10s_multirate.json", &multirate);
    write("native_startup_60s.json", &startup);
    write("native_turn90_40s.json", &turn);
    let golden = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/golden");
    let list: Vec<String> = aes_core::scenario::presets::PRESET_NAMES
        .iter()
        .map(|n| format!("({n:?}, include_str!({:?}))", golden.join(format!("{n}.json")).display().to_string()))
        .collect();
    write("golden_files.rs", &format!("[{}]", list.join(",\n")));
    println!("cargo:rerun-if-changed=../core/src");
    println!("cargo:rerun-if-changed=../tests/golden");
}
