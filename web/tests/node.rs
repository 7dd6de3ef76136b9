//! wasm-bindgen tests, run in Node (`./build.sh test`).
#![cfg(target_arch = "wasm32")]

use aes_core::studies::montecarlo::MonteCarlo;
use aes_core::studies::study;
use aes_web::*;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

#[wasm_bindgen_test]
fn presets_are_listed_and_valid() {
    let names = preset_names();
    assert!(names.iter().any(|n| n == "startup"));
    for n in &names {
        let json = preset_json(JsValue::from(n)).unwrap();
        let errs = validate_scenario(JsValue::from(&json)).unwrap();
        assert_eq!(js_sys::Array::from(&errs).length(), 0, "{n}");
    }
}

#[wasm_bindgen_test]
fn bad_scenario_names_the_field() {
    let errs = validate_scenario(JsValue::from(r#"{"ship": {"wetted_area_m2": -1}}"#)).unwrap();
    let arr = js_sys::Array::from(&errs);
    assert_eq!(arr.length(), 1);
    let path = js_sys::Reflect::get(&arr.get(0), &"path".into()).unwrap();
    assert_eq!(path.as_string().unwrap(), "ship.wetted_area_m2");
}

/// A 60 s start-up in wasm, in chunks, gives the same summary as in one go, and moves the ship.
#[wasm_bindgen_test]
fn startup_runs_in_chunks() {
    let mut sc: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("startup")).unwrap()).unwrap();
    sc["sim"]["duration_s"] = serde_json::json!(60.0);
    let json = sc.to_string();
    let mut run = Run::new(JsValue::from(&json)).unwrap();
    let mut progress = 0.0;
    while progress < 1.0 {
        progress = run.advance(5000.0).unwrap();
    }
    let chunked = run.summary_json();
    assert_eq!(chunked, run_summary(JsValue::from(&json)).unwrap());
    let s: serde_json::Value = serde_json::from_str(&chunked).unwrap();
    let kn = s["signals"]["ship_speed_kn"]["final"].as_f64().unwrap();
    assert!(kn > 15.0 && kn < 30.0, "{kn}");
    let rel = s["energy_j"]["relative_residual"].as_f64().unwrap();
    // The books close to round-off, as natively (measured -1.5e-13 for this 60 s run).
    assert!(rel.abs() < 1e-9, "{rel}");
    assert_eq!(run.column(JsValue::from("t_s")).unwrap().length(), 601);
    // The export: the CSV made from the columns the page keeps is the run's own, header and 601 rows.
    let csv = run.trace_csv();
    let flat: Vec<f64> =
        Run::signal_names().iter().flat_map(|n| run.column(JsValue::from(n.as_str())).unwrap().to_vec()).collect();
    assert_eq!(aes_web::trace_csv_of(flat, 601).ok(), Some(csv.clone()));
    assert_eq!(csv.lines().count(), 602);
    assert!(aes_web::trace_csv_of(vec![1.0; 3], 601).is_err());
}

/// The stability tool answers in wasm as natively: Table 4.2's stator current at 100 N m.
#[wasm_bindgen_test]
fn stability_tool_in_wasm() {
    let out = ips_analysis(JsValue::from("motor"), 377.0, 28.5, 45.0, 100.0, false, 0.1, 100.0, 10).unwrap();
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let i = v["steady_state"]["i_s_mag"].as_f64().unwrap();
    // Within 1e-4 as natively (measured 5.5e-5, core's table_4_2).
    let table_4_2 = aes_core::studies::thesis_values::value("table_4_2.steady_state.i_s_mag_a").unwrap();
    assert!((i - table_4_2).abs() < 1e-4 * table_4_2, "{i}");
    assert_eq!(v["bode"]["magnitude_db"].as_array().unwrap().len(), 10);
    assert!(ips_analysis(JsValue::from("rotor"), 0.0, 0.0, 0.0, 0.0, false, 0.1, 1.0, 3).is_err());
}

/// Determinism across platforms: the same scenarios run in wasm give the summaries the native build
/// computed at build time (web/build.rs), bit for bit (every number printed with full precision).
#[wasm_bindgen_test]
fn wasm_matches_native_bit_for_bit() {
    let mut s: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("startup")).unwrap()).unwrap();
    s["sim"]["duration_s"] = serde_json::json!(60.0);
    assert_eq!(
        run_summary(JsValue::from(&s.to_string())).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_startup_60s.json"))
    );
    let mut t: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("turn-90")).unwrap()).unwrap();
    t["sim"]["duration_s"] = serde_json::json!(40.0);
    assert_eq!(
        run_summary(JsValue::from(&t.to_string())).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_turn90_40s.json"))
    );
    // Waves: 200 components, the RAO table built in wasm, ventilation switching (eq. 2.57 as printed).
    let mut h: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("head-seas-ss6")).unwrap()).unwrap();
    h["sim"]["duration_s"] = serde_json::json!(10.0);
    h["seakeeping"]["stern_motion"] = serde_json::json!("thesis_eq_2_57");
    assert_eq!(
        run_summary(JsValue::from(&h.to_string())).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_head_seas_10s.json"))
    );
    // The multi-rate hull step (stepping.hull_substeps = 4) too.
    h["sim"]["hull_substeps"] = serde_json::json!(4);
    assert_eq!(
        run_summary(JsValue::from(&h.to_string())).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_head_seas_10s_multirate.json"))
    );
}

/// Issues 31 and 32 in wasm, bit for bit against the native build (web/build.rs): the operability
/// polar of the head-seas study at 2 speeds x 4 headings (its speeds as two parts, joined), and a
/// rare-event study of three conditioned trials (its trial scenario from a run in waves, the
/// trials as two shards).
#[wasm_bindgen_test]
fn operability_and_rare_events_match_native() {
    let mut s: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("head-seas-ss6")).unwrap()).unwrap();
    s["rare_event"]["level_h_over_r"] = serde_json::json!(1.1);
    s["sim"]["duration_s"] = serde_json::json!(165.0);
    let j = JsValue::from(&s.to_string());
    let polar =
        format!(r#"{{"scenario": {s}, "request": {{"speeds_kn": [0, 20], "headings_deg": [0, 90, 180, 225]}}}}"#);
    let (kind, spec) = (JsValue::from("operability"), JsValue::from(&polar));
    let shards = vec![
        bytes(study_range(kind.clone(), spec.clone(), 1, 2)),
        bytes(study_range(kind.clone(), spec.clone(), 0, 1)),
    ];
    assert_eq!(
        study_summary(kind, spec, shards).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_operability.json"))
    );
    let t = rare_scenario(j).unwrap();
    let (kind, spec) = (JsValue::from("rare-events"), JsValue::from(&format!(r#"{{"scenario": {t}, "trials": 3}}"#)));
    let shards = vec![
        bytes(study_range(kind.clone(), spec.clone(), 2, 3)),
        bytes(study_range(kind.clone(), spec.clone(), 0, 2)),
    ];
    assert_eq!(
        study_summary(kind.clone(), spec.clone(), shards).unwrap(),
        include_str!(concat!(env!("OUT_DIR"), "/native_rare.json"))
    );
    // The estimate the page says before a study (issue 46): a rare-event trial's work counts its
    // runs that place the ship, in this browser's time on 2 workers; a polar's speeds are not runs.
    let e: serde_json::Value = serde_json::from_str(&study_estimate(kind, spec, 2.0).unwrap()).unwrap();
    let trial: aes_core::Scenario = aes_core::Scenario::from_json(&t).unwrap();
    let w = aes_core::studies::rare::trial_work(&trial);
    assert_eq!(e["items"], 3);
    assert_eq!(e["item_work"].as_f64(), Some(w));
    let want = 3.0 * w / aes_core::scenario::WORK_PER_S * aes_core::scenario::WASM_SLOWDOWN / 2.0;
    assert!((e["seconds"].as_f64().unwrap() - want).abs() <= 1e-12 * want, "{e}");
    let polar = study_estimate(JsValue::from("operability"), JsValue::from(&polar), 2.0).unwrap();
    assert_eq!(polar, r#"{"items":2}"#);
}

/// A binary shard as the page's workers pass it.
fn bytes(r: Result<Vec<u8>, wasm_bindgen::JsError>) -> js_sys::Uint8Array {
    js_sys::Uint8Array::from(&r.map_err(message).unwrap()[..])
}

/// Monte Carlo trials `a..b` of the scenario `j` through the generic entry.
fn mc_range(j: &str, a: u32, b: u32) -> js_sys::Uint8Array {
    bytes(study_range(JsValue::from("monte-carlo"), JsValue::from(j), a, b))
}

/// The Monte Carlo summary of binary shards through the generic entry.
fn mc_summary(j: &str, shards: Vec<js_sys::Uint8Array>) -> Result<String, wasm_bindgen::JsError> {
    study_summary(JsValue::from("monte-carlo"), JsValue::from(j), shards)
}

/// Monte Carlo in wasm: two ranges merged give the summary of the whole range.
#[wasm_bindgen_test]
fn monte_carlo_in_wasm() {
    let mut s: serde_json::Value =
        serde_json::from_str(&preset_json(JsValue::from("mc-excess-energy")).unwrap()).unwrap();
    s["monte_carlo"]["trials"] = serde_json::json!(3);
    s["monte_carlo"]["histogram_time_s"] = serde_json::json!(4.0);
    s["monte_carlo"]["periodogram_segment_s"] = serde_json::json!(2.0);
    s["sim"]["duration_s"] = serde_json::json!(6.0);
    let j = s.to_string();
    let whole = mc_summary(&j, vec![mc_range(&j, 0, 3)]).unwrap();
    let split = mc_summary(&j, vec![mc_range(&j, 2, 3), mc_range(&j, 0, 2)]).unwrap();
    assert_eq!(whole, split);
    // A table handed over from another worker gives the same numbers as one built here.
    let values = rao_table_values(JsValue::from(&j)).unwrap();
    rao_table_load(JsValue::from(&j), &values).unwrap();
    assert_eq!(mc_summary(&j, vec![mc_range(&j, 0, 3)]).unwrap(), whole);
    assert!(rao_table_load(JsValue::from(&j), &values[1..]).is_err());
    let v: serde_json::Value = serde_json::from_str(&whole).unwrap();
    assert_eq!(v["trials"], 3);
    assert!(study_range(JsValue::from("monte-carlo"), JsValue::from(&j), 2, 9).is_err());
    let r: serde_json::Value =
        serde_json::from_str(&rao_json(JsValue::from(&j), 20.0, 180.0, vec![0.12, 0.6]).unwrap()).unwrap();
    assert!((r["heave"]["amp"][0].as_f64().unwrap() - 1.0).abs() < 0.03);
}

/// The hull panel's numbers in wasm: the Wigley's volume is (4/9) L B T within 0.6 % (the
/// trapezoid over its 19 stations, as natively: -0.55 %), and a broken offsets file is refused
/// with its line named.
#[wasm_bindgen_test]
fn hull_sheet_in_wasm() {
    let j = r#"{"ship": {"hull": {"name": "wigley"}}}"#;
    let h: serde_json::Value = serde_json::from_str(&hull_sheet(JsValue::from(j)).unwrap()).unwrap();
    let exact = 4.0 / 9.0 * 100.0 * 10.0 * 6.25;
    assert!((h["volume_m3"].as_f64().unwrap() / exact - 1.0).abs() < 0.006, "{}", h["volume_m3"]);
    assert!(hull_names().contains(&"wigley".to_string()));
    let bad = r#"{"ship": {"hull": {"name": "custom", "draft_m": 1, "kg_m": 1, "offsets_csv": "station_index,x_m,z_m,half_breadth_m\n0,0,0,x\n"}}}"#;
    assert!(hull_sheet(JsValue::from(bad)).is_err());
    let errs = js_sys::Array::from(&validate_scenario(JsValue::from(bad)).unwrap());
    let e = errs.get(0);
    let msg = js_sys::Reflect::get(&e, &"message".into()).unwrap().as_string().unwrap();
    assert!(msg.contains("line 2"), "{msg}");
}

/// Every preset's golden record (tests/golden/*.json, made natively) recomputed in wasm: summary,
/// trace fingerprint and the Monte Carlo presets' four-trial studies, bit for bit.
#[wasm_bindgen_test]
fn golden_records_in_wasm() {
    // Every preset's record, listed at build time from PRESET_NAMES (web/build.rs).
    let stored: &[(&str, &str)] = &include!(concat!(env!("OUT_DIR"), "/golden_files.rs"));
    assert_eq!(stored.len(), aes_core::scenario::presets::PRESET_NAMES.len(), "a preset without a golden record here");
    let mut failed = Vec::new();
    for &(name, text) in stored {
        let now = aes_core::studies::regression::record(name).unwrap();
        if now != text {
            let (a, b): (serde_json::Value, serde_json::Value) =
                (serde_json::from_str(text).unwrap(), serde_json::from_str(&now).unwrap());
            let mut paths = Vec::new();
            differences(&a, &b, name.to_string(), &mut paths);
            failed.push(paths.into_iter().take(8).collect::<Vec<_>>().join("\n"));
        }
    }
    assert!(failed.is_empty(), "wasm differs from the golden records at:\n{}", failed.join("\n"));
}

/// Paths (with both values) where two JSON documents differ.
fn differences(a: &serde_json::Value, b: &serde_json::Value, path: String, out: &mut Vec<String>) {
    use serde_json::Value;
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for (k, v) in x {
                match y.get(k) {
                    Some(w) => differences(v, w, format!("{path}.{k}"), out),
                    None => out.push(format!("{path}.{k}: missing")),
                }
            }
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            for (i, (v, w)) in x.iter().zip(y).enumerate() {
                differences(v, w, format!("{path}.{i}"), out);
            }
        }
        _ if a != b => out.push(format!("{path}: golden {a}, wasm {b}")),
        _ => {}
    }
}

/// The message of a JsError.
fn message(e: wasm_bindgen::JsError) -> String {
    let v = wasm_bindgen::JsValue::from(e);
    js_sys::Reflect::get(&v, &"message".into()).ok().and_then(|m| m.as_string()).unwrap_or_default()
}

/// Issue 18 through the wasm exports: extreme inputs end at once with a named error (the page's
/// stability worker froze on the first), and nothing non-finite comes back.
#[wasm_bindgen_test]
fn extreme_inputs_end_with_named_errors() {
    let e = ips_analysis(JsValue::from("motor"), 377.0, 28.5, 45.0, 1e300, false, 0.01, 1000.0, 200).unwrap_err();
    assert!(message(e).contains("torque command T* = 1e300 N m"));
    for (omega, vfd, load) in [(1e300, 28.5, 45.0), (377.0, f64::NAN, 45.0), (377.0, 28.5, 1e-300)] {
        assert!(ips_analysis(JsValue::from("generator"), omega, vfd, load, 100.0, true, 0.01, 1000.0, 200).is_err());
    }
    assert!(ips_analysis(JsValue::from("motor"), 377.0, 28.5, 45.0, 100.0, false, 0.0, 1000.0, 200).is_err());
    assert!(ips_analysis(JsValue::from("motor"), 377.0, 28.5, 45.0, 100.0, false, 0.01, 1000.0, 1_000_000).is_err());
    let ok = ips_analysis(JsValue::from("motor"), 377.0, 28.5, 45.0, 10_000.0, true, 1e-6, 1e7, 50).unwrap();
    assert!(!ok.contains("null"), "{ok}");
    // A run recording 2e6 rows is refused before it starts (it took 2.8 GB).
    let big = r#"{"sim": {"duration_s": 20000, "dt_s": 0.01, "record_interval_s": 0.01}}"#;
    assert!(message(Run::new(JsValue::from(big)).err().unwrap()).contains("sim.record_interval_s"));
    let long = r#"{"sim": {"duration_s": 1000000, "dt_s": 0.001}}"#;
    assert!(message(Run::new(JsValue::from(long)).err().unwrap()).contains("sim.duration_s"));
    let errs = js_sys::Array::from(
        &validate_scenario(JsValue::from(r#"{"ship": {"wetted_area_m2": 7e3, "wetted_area_m2": 8e3}}"#)).unwrap(),
    );
    let msg = js_sys::Reflect::get(&errs.get(0), &"message".into()).unwrap().as_string().unwrap();
    assert!(msg.contains("duplicate key ship.wetted_area_m2"), "{msg}");
    // A shard with a reversed range is refused by studySummary.
    let mut sc: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("mc-arrival")).unwrap()).unwrap();
    sc["sim"]["duration_s"] = serde_json::json!(2.0);
    let j = sc.to_string();
    let mut bad = study::from_bytes::<MonteCarlo>(&mc_range(&j, 0, 1).to_vec()).unwrap();
    bad.ranges = vec![(2, 0)];
    let bad = js_sys::Uint8Array::from(&study::to_bytes::<MonteCarlo>(&bad).unwrap()[..]);
    assert!(message(mc_summary(&j, vec![bad]).unwrap_err()).contains("ranges.0 = [2, 0]"));
}

/// What the live views read: rows handed out while a run goes add up to the finished column; the
/// sea picture sums the run's own components; a trial's scenario carries its exact seed.
#[wasm_bindgen_test]
fn live_view_exports() {
    let mut sc: serde_json::Value =
        serde_json::from_str(&preset_json(JsValue::from("head-seas-ss6")).unwrap()).unwrap();
    sc["sim"]["duration_s"] = serde_json::json!(6.0);
    let json = sc.to_string();
    let mut run = Run::new(JsValue::from(&json)).unwrap();
    let mut streamed: Vec<f64> = Vec::new();
    let mut progress = 0.0;
    while progress < 1.0 {
        progress = run.advance(400.0).unwrap();
        streamed.extend(run.column_from(JsValue::from("h_over_r"), streamed.len()).unwrap().to_vec());
    }
    assert_eq!(streamed, run.column(JsValue::from("h_over_r")).unwrap().to_vec());
    assert_eq!(run.rows(), streamed.len());

    let parsed = aes_core::Scenario::from_json(&json).unwrap();
    let comps = aes_core::sim::seaway::wave_components(&parsed);
    let mut sea = Sea::new(JsValue::from(&json)).unwrap();
    assert_eq!(sea.components(), comps.len());
    let (xs, ys) = ([10.0, -62.0], [0.0, 5.0]);
    let got = sea.elevations(3.5, &xs, &ys).unwrap().to_vec();
    for i in 0..2 {
        let want = aes_core::sea::waves::elevation(&comps, xs[i], ys[i], 3.5);
        // The same terms in the same order (measured: equal to the last bit).
        assert!((got[i] - want).abs() <= 1e-12 * (1.0 + want.abs()), "{} vs {want}", got[i]);
    }
    let hull: serde_json::Value = serde_json::from_str(&hull_profile(JsValue::from(&json)).unwrap()).unwrap();
    assert!(hull["x_m"].as_array().unwrap().len() > 20);

    let trial: serde_json::Value = serde_json::from_str(&trial_scenario(JsValue::from(&json), 2.0).unwrap()).unwrap();
    let seed = sc["sim"]["seed"].as_u64().unwrap();
    assert_eq!(trial["sim"]["seed"].as_u64(), Some(aes_core::studies::stats::trial_seed(seed, 2)));
    assert!(trial_scenario(JsValue::from(&json), 1e6).is_err());
}

/// The thesis' numbers reach the page as the file prints them (Table 5.8's "1.00", not 1).
#[wasm_bindgen_test]
fn thesis_values_as_printed() {
    let v: serde_json::Value = serde_json::from_str(&thesis_values()).unwrap();
    let rows = v.as_array().unwrap();
    let row = |key: &str| rows.iter().find(|r| r["key"] == key).unwrap_or_else(|| panic!("{key} missing"));
    let r = row("table_5_8.monte_carlo.skewness");
    assert_eq!((r["printed"].as_str(), r["value"].as_f64(), r["unit"].as_str()), (Some("1.00"), Some(1.0), Some("-")));
    assert_eq!(row("ch_5_4_1.excess_energy_mean_mj")["printed"], "94.1");
    assert_eq!(row("table_5_8.rice.mean_s")["where"], "Table 5.8, analytic row (sec. 5.4.2)");
}

/// Issue 34 through the wasm exports: an argument of the wrong type is refused by name (it
/// trapped with "memory access out of bounds"), a non-finite time for the sea is refused, a
/// loaded RAO table of 1e308 values is refused as a computed one would be, a Monte Carlo study
/// over its memory budget is refused before it starts, and a binary partial with impossible
/// numbers is refused by studySummary as merge refuses it.
#[wasm_bindgen_test]
fn boundary_checks_in_wasm() {
    for v in [JsValue::from(3.0), JsValue::NULL, JsValue::UNDEFINED, js_sys::Object::new().into()] {
        assert!(message(preset_json(v.clone()).unwrap_err()).contains("expected a string"));
        assert!(message(run_summary(v.clone()).unwrap_err()).contains("the scenario JSON: expected a string"));
        assert!(message(Run::new(v.clone()).err().unwrap()).contains("expected a string"));
        assert!(message(study_range("monte-carlo".into(), v.clone(), 0, 1).unwrap_err()).contains("expected a string"));
        assert!(message(Sea::new(v).err().unwrap()).contains("expected a string"));
    }
    let storm = preset_json(JsValue::from("mc-arrival")).unwrap();
    let mut sea = Sea::new(JsValue::from(&storm)).unwrap();
    for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(message(sea.elevations(t, &[0.0], &[0.0]).unwrap_err()).contains("the time must be a finite number"));
    }
    let z = sea.elevations(10.0, &[0.0, 5.0], &[0.0, 5.0]).unwrap().to_vec();
    assert!(z.iter().all(|v| v.is_finite()), "{z:?}");
    for (x, y) in [(f64::NAN, 0.0), (0.0, f64::INFINITY), (1e300, 0.0), (0.0, -1.0e7 - 1.0)] {
        let e = message(sea.elevations(10.0, &[0.0, x], &[0.0, y]).unwrap_err());
        assert!(
            e.contains("point 1 at") && e.contains("within 1e7") && !e.contains("NaN") && !e.contains("inf"),
            "{e}"
        );
    }
    assert!(sea.elevations(10.0, &[1.0e7], &[-1.0e7]).unwrap().to_vec()[0].is_finite());
    let values = rao_table_values(JsValue::from(&storm)).unwrap();
    let huge = vec![1e308; values.len()];
    assert!(message(rao_table_load(JsValue::from(&storm), &huge).unwrap_err()).contains("its digest differs"));
    // Negated transfer functions with the grid kept (a table the next run would have used
    // silently, generator efficiency 1.24): refused.
    let per = aes_core::sea::seakeeping::tables::RaoTable::VALUES_PER_POINT;
    let negated: Vec<f64> = values
        .iter()
        .enumerate()
        .map(|(i, &v)| if i + 1 < values.len() && (3..13).contains(&(i % per)) { -v } else { v })
        .collect();
    assert!(message(rao_table_load(JsValue::from(&storm), &negated).unwrap_err()).contains("its digest differs"));
    rao_table_load(JsValue::from(&storm), &values).unwrap();
    let mut big: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("startup")).unwrap()).unwrap();
    // (Within the run's rows budget of 55 columns: 180,000 rows.)
    big["sim"]["duration_s"] = serde_json::json!(900.0);
    big["sim"]["record_interval_s"] = serde_json::json!(0.005);
    big["monte_carlo"]["trials"] = serde_json::json!(10);
    big["monte_carlo"]["keep_traces"] = serde_json::json!(10);
    big["monte_carlo"]["envelope_signals"] =
        serde_json::json!(Run::signal_names().into_iter().take(20).collect::<Vec<_>>());
    let e = message(study_range("monte-carlo".into(), JsValue::from(&big.to_string()), 0, 1).unwrap_err());
    assert!(e.contains("this study keeps about") && e.contains("at most 64 MB"), "{e}");
    let mut s: serde_json::Value = serde_json::from_str(&storm).unwrap();
    s["monte_carlo"]["trials"] = serde_json::json!(2);
    s["sim"]["duration_s"] = serde_json::json!(2.0);
    let j = s.to_string();
    let mut p = study::from_bytes::<MonteCarlo>(&mc_range(&j, 0, 2).to_vec()).unwrap();
    p.part.envelopes[0].rows[3].sums[1] = -1;
    let bad = js_sys::Uint8Array::from(&study::to_bytes::<MonteCarlo>(&p).unwrap()[..]);
    assert!(message(mc_summary(&j, vec![bad]).unwrap_err()).contains("sum of squares"));
}

/// The bus stability map (issue 44) in wasm: its axes refuse bad input with the field, its value
/// and what is allowed, the study its grid, and the map's rows computed in shards of the
/// "stability-map" study are the native map bit for bit.
#[wasm_bindgen_test]
fn stability_map_refuses_bad_input_by_name() {
    use aes_core::scenario::Scenario;
    use aes_core::studies::stability_map;
    let mut sc: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("startup")).unwrap()).unwrap();
    let at_rest = JsValue::from(sc.to_string());
    assert!(message(stability_point(at_rest).unwrap_err()).contains("initial.speed_kn = 0"));
    sc["initial"]["speed_kn"] = serde_json::json!(25.0);
    let json = sc.to_string();
    let (p, c) = ("plant.loads.ship_service_w", "plant.loads.filter_capacitance_f");
    let axis = |which: &str, path: JsValue, from: f64, to: f64, n: f64| {
        stability_axis(JsValue::from(&json), JsValue::from(which), path, from, to, n)
    };
    let refused = |r: Result<String, wasm_bindgen::JsError>, want: &str| {
        let m = message(r.unwrap_err());
        assert!(m.contains(want), "{m} lacks {want}");
    };
    refused(
        axis("x axis", p.into(), 0.0, 16e6, 500.0),
        "x axis: 500 values of plant.loads.ship_service_w: a whole number from 2 to 200",
    );
    refused(axis("x axis", p.into(), 0.0, 16e6, 2.5), "x axis: 2.5 values");
    refused(
        axis("x axis", p.into(), f64::NAN, 16e6, 5.0),
        "x axis: from a value that is not a finite number to 16000000",
    );
    refused(
        axis("y axis", c.into(), 0.007, 5.0, 3.0),
        "y axis: plant.loads.filter_capacitance_f = 5: Ship service filter C must be a number from",
    );
    refused(axis("y axis", "plant.loads.filter_capacitance".into(), 0.007, 0.015, 3.0), "no such parameter");
    refused(axis("x axis", 1.0.into(), 0.0, 16e6, 5.0), "x axis: the parameter's path must be a string");
    // The grid is the study's to refuse: the spec of two checked axes, as the page puts it together.
    let spec = |x: &str, y: &str| format!(r#"{{"scenario":{json},"x":{x},"y":{y}}}"#);
    let kind = || JsValue::from("stability-map");
    let x = axis("x axis", p.into(), 0.0, 16e6, 5.0).unwrap();
    let same = axis("y axis", p.into(), 1e6, 2e6, 3.0).unwrap();
    let many =
        (axis("x axis", p.into(), 0.0, 16e6, 200.0).unwrap(), axis("y axis", c.into(), 0.007, 0.015, 200.0).unwrap());
    refused(
        study_range(kind(), JsValue::from(spec(&x, &same)), 0, 1).map(|_| String::new()),
        "both axes are plant.loads.ship_service_w",
    );
    refused(study_range(kind(), JsValue::from(spec(&many.0, &many.1)), 0, 1).map(|_| String::new()), "at most 10000");
    // Rows 0..1 and 1..3 as two shards summarised are the native map of the same axes.
    let y = axis("y axis", c.into(), 0.007, 0.015, 3.0).unwrap();
    let s = spec(&x, &y);
    let shards =
        vec![bytes(study_range(kind(), JsValue::from(&s), 1, 3)), bytes(study_range(kind(), JsValue::from(&s), 0, 1))];
    let page: serde_json::Value =
        serde_json::from_str(&study_summary(kind(), JsValue::from(&s), shards).unwrap()).unwrap();
    let scenario = Scenario::from_json(&json).unwrap();
    let native = stability_map::map(
        &scenario,
        &stability_map::Axis::checked(&scenario, "x axis", p, 0.0, 16e6, 5).unwrap(),
        &stability_map::Axis::checked(&scenario, "y axis", c, 0.007, 0.015, 3).unwrap(),
    )
    .unwrap();
    assert_eq!(page, serde_json::to_value(&native).unwrap());
}

/// The propeller panel (issue 54): DTMB 4119's KT and KQ over the command line's 25 J are the
/// native vortex lattice's in the run's design flow, bit for bit (web/build.rs computed them
/// natively); the outline is the table's chords about the mid-chord (no skew: symmetric), P/D at
/// 0.7 R is the table's 1.084, the efficiency is J KT / (2 pi KQ), and the B-series beside it has the
/// same Z, P/D and Ae/A0. A bad table is refused naming its row and column, a fractional blade
/// count by name.
#[wasm_bindgen_test]
fn propeller_curves_are_the_native_vortex_lattice() {
    let native: Vec<[f64; 3]> =
        serde_json::from_str(include_str!(concat!(env!("OUT_DIR"), "/native_propeller_4119.json"))).unwrap();
    let mut sc: serde_json::Value =
        serde_json::from_str(&preset_json(JsValue::from("head-seas-ss6")).unwrap()).unwrap();
    sc["propeller"]["model"] = serde_json::json!("geometry");
    sc["propeller"]["geometry"] = serde_json::json!({"name": "dtmb4119"});
    let out: serde_json::Value =
        serde_json::from_str(&propeller_curves(JsValue::from(sc.to_string())).map_err(message).unwrap()).unwrap();
    assert_eq!(out["runs_it"], true);
    assert_eq!((out["name"].as_str(), out["blades"].as_u64()), (Some("dtmb4119"), Some(3)));
    let ow = out["open_water"].as_array().unwrap();
    assert_eq!(ow.len(), 25);
    for (p, n) in ow.iter().zip(&native) {
        let (j, kt, kq) = (p["j"].as_f64().unwrap(), p["kt"].as_f64().unwrap(), p["kq"].as_f64().unwrap());
        assert_eq!(
            [j.to_bits(), kt.to_bits(), kq.to_bits()],
            [n[0].to_bits(), n[1].to_bits(), n[2].to_bits()],
            "J = {j}"
        );
        let eta = p["eta"].as_f64().unwrap();
        let want = if kt > 0.0 && kq > 0.0 { j * kt / (2.0 * std::f64::consts::PI * kq) } else { 0.0 };
        assert!((eta - want).abs() <= 1e-12, "J = {j}: eta {eta} against {want}");
    }
    assert!((out["pitch_07"].as_f64().unwrap() - 1.084).abs() < 1e-12);
    let rows = out["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 10);
    for r in rows {
        let (le, te, c) =
            (r["leading_d"].as_f64().unwrap(), r["trailing_d"].as_f64().unwrap(), r["c_d"].as_f64().unwrap());
        assert!((te - le - c).abs() < 1e-12 && (le + te).abs() < 1e-12, "{r}");
    }
    let s = &out["series"];
    assert_eq!((s["blades"].as_u64(), s["held"].as_bool()), (Some(3), Some(false)));
    assert_eq!(s["pitch_ratio"], out["pitch_07"]);
    assert_eq!(s["area_ratio"], out["area_ratio"]);
    let ow_b = aes_core::plant::propeller::OpenWater::b_series(
        s["pitch_ratio"].as_f64().unwrap(),
        s["area_ratio"].as_f64().unwrap(),
        3,
    )
    .unwrap();
    let at = &s["rows"][14]; // J = 0.7
    let j = at["j"].as_f64().unwrap();
    assert!((j - 0.7).abs() < 1e-12);
    assert_eq!(at["kt"].as_f64().unwrap().to_bits(), ow_b.kt(j).to_bits());

    let table = "r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D\n0.2,0.3,1.0,0.02,0.2,0,0\n0.5,0.0,1.0,0.02,0.1,0,0\n\
                 0.8,0.3,1.0,0.02,0.05,0,0\n1.0,0.0,1.0,0.0,0.03,0,0\n";
    let e = message(propeller_geometry_csv(JsValue::from(table), 3.0, 0.2).unwrap_err());
    assert!(e.contains("row 2 (r/R 0.5), column c_D"), "{e}");
    let good = propeller_geometry_csv(JsValue::from(table.replace("0.5,0.0,", "0.5,0.4,")), 3.0, 0.2)
        .map_err(message)
        .unwrap();
    assert!(good.contains("\"custom\""), "{good}");
    let e = message(propeller_geometry_csv(JsValue::from(table), 2.5, 0.2).unwrap_err());
    assert!(e.starts_with("blades: 2.5 is not a whole number"), "{e}");
}

/// Issue 57 at the wasm boundary: a 1 MB axis path with ESC and BEL comes back cut and escaped;
/// an elevation at t = 1e308 s (it was NaN) is refused naming the time; a lesson's explanation
/// from values lacking its control (it wrote "Lower the hub to NaN m") is refused naming it.
#[wasm_bindgen_test]
fn the_boundary_shortens_escapes_and_refuses_what_is_not_finite() {
    let mut sc: serde_json::Value = serde_json::from_str(&preset_json(JsValue::from("startup")).unwrap()).unwrap();
    sc["initial"]["speed_kn"] = serde_json::json!(25.0);
    let json = sc.to_string();
    let path = format!("plant.\u{1b}[31m\u{7}{}", "x".repeat(1 << 20));
    let m = message(
        stability_axis(JsValue::from(&json), JsValue::from("x axis"), JsValue::from(&path), 0.0, 1.0, 3.0).unwrap_err(),
    );
    assert!(m.len() < 2000 && !m.chars().any(|c| c.is_control()), "{} bytes: {}", m.len(), &m[..m.len().min(200)]);
    assert!(m.contains("\\u{1b}"), "{}", &m[..m.len().min(200)]);
    let waves = preset_json(JsValue::from("head-seas-ss6")).unwrap();
    let mut sea = Sea::new(JsValue::from(waves)).unwrap();
    for t in [1e308, -1e308, 1.0e8] {
        let m = message(sea.elevations(t, &[0.0], &[0.0]).unwrap_err());
        assert!(m.starts_with("elevations: t = ") && m.contains("within 1e7"), "{m}");
    }
    assert!(sea.elevations(1.0e7, &[0.0], &[0.0]).unwrap().to_vec()[0].is_finite());
    let opened: serde_json::Value =
        serde_json::from_str(&lesson_open(JsValue::from("waves"), JsValue::from("{}")).unwrap()).unwrap();
    let run = Run::new(JsValue::from(opened["scenario"].as_str().unwrap())).unwrap();
    let mut values = opened["values"].clone();
    values.as_object_mut().unwrap().remove("ship.hull.hub_above_base_m");
    let m = message(
        run.lesson_explain(JsValue::from("waves"), JsValue::from(values.to_string()), JsValue::NULL).unwrap_err(),
    );
    assert!(m.contains("ship.hull.hub_above_base_m: missing"), "{m}");
}

/// The closing fuzz run's wasm findings (issue 57): an axis name that is not a string is refused
/// by name (it trapped with "memory access out of bounds" in the glue), and a count given NaN, an
/// infinity, a negative or a fraction is refused naming the count (the glue made it 0 before).
#[wasm_bindgen_test]
fn counts_and_names_that_are_not_what_they_say_are_refused() {
    let json = preset_json(JsValue::from("startup")).unwrap();
    let m = message(
        stability_axis(
            JsValue::from(&json),
            JsValue::from(true),
            JsValue::from("plant.loads.ship_service_w"),
            1.0,
            2.0,
            2.0,
        )
        .unwrap_err(),
    );
    assert!(m.starts_with("stabilityAxis: the axis's name: expected a string"), "{m}");
    let mut run = Run::new(JsValue::from(&json)).unwrap();
    for bad in [f64::NAN, f64::NEG_INFINITY, -1.0, 2.5] {
        let m = message(run.advance(bad).unwrap_err());
        assert!(m.starts_with("advance: steps = ") && m.contains("must be a whole number from 0 to"), "{m}");
        let m = message(trial_scenario(JsValue::from(&json), bad).unwrap_err());
        assert!(m.starts_with("trialScenario: trial = "), "{m}");
        let m = message(rare_place(JsValue::from(&json), bad).unwrap_err());
        assert!(m.starts_with("rarePlace: passes = "), "{m}");
        let m = message(study_estimate(JsValue::from("monte-carlo"), JsValue::from("{}"), bad).unwrap_err());
        assert!(m.starts_with("studyEstimate: workers = "), "{m}");
    }
    assert!(run.advance(10.0).is_ok());
}
