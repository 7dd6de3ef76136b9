//! Property-based tests of every entry point (issue 18): mutated scenarios from every preset
//! through `--set`-style overrides, hull CSVs, Monte Carlo partials for merge, and the ch. 4
//! tool's parameters. The property: a clean error or a finite result, within a time bound, never
//! a panic. Seeded (the same cases every run); `AES_FUZZ_CASES` sets the cases per property
//! (default 128, about a second each; `./build.sh fuzz` runs 2000).

use aes_core::checks::check_finite;
use aes_core::scenario::presets::{preset, PRESET_NAMES};
use aes_core::sea::seakeeping::strip::{MassProperties, Ship};
use aes_core::ship::sections::HullOffsets;
use aes_core::studies::montecarlo::MonteCarlo;
use aes_core::studies::study::{self, Study};
use aes_core::Simulation;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::time::{Duration, Instant};

/// Most time one case may take (the bound for a reproducer).
const CASE_BOUND: Duration = Duration::from_secs(10);

fn runner(seed: u8) -> TestRunner {
    let cases = std::env::var("AES_FUZZ_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(128);
    let config = Config { cases, failure_persistence: None, ..Config::default() };
    TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]))
}

/// Values a hostile or careless user types.
fn value_text() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "0",
            "-1",
            "1",
            "1e308",
            "-1e308",
            "1e-300",
            "5e-324",
            "1e999",
            "NaN",
            "inf",
            "\"x\"",
            "true",
            "null",
            "[]",
            "{}",
            "[1,2]",
            "18446744073709551615",
            "-9223372036854775808",
            "0.5",
            "2",
            "1000000",
        ])
        .prop_map(str::to_string),
        any::<f64>().prop_map(|x| x.to_string()),
        (-1.0e4..1.0e4f64).prop_map(|x| x.to_string()),
    ]
}

/// Every leaf path of a JSON value (`plant.motor.rated_power_w`, `commands.0.speed_kn`).
fn leaf_paths(v: &serde_json::Value, prefix: &str, out: &mut Vec<String>) {
    let join = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
    match v {
        serde_json::Value::Object(m) => m.iter().for_each(|(k, x)| leaf_paths(x, &join(k), out)),
        serde_json::Value::Array(a) => {
            a.iter().enumerate().for_each(|(i, x)| leaf_paths(x, &join(&i.to_string()), out))
        }
        _ => out.push(prefix.to_string()),
    }
}

/// A scenario mutated in one to three places either fails with named fields or runs (its first
/// 3000 steps here) to a finite summary.
#[test]
fn mutated_scenarios_fail_cleanly_or_stay_finite() {
    let presets: Vec<_> = PRESET_NAMES.iter().map(|n| preset(n).unwrap()).collect();
    let mut paths = Vec::new();
    leaf_paths(&serde_json::to_value(&presets[0]).unwrap(), "", &mut paths);
    let strategy = (0..presets.len(), prop::collection::vec((prop::sample::select(paths), value_text()), 1..4));
    runner(1)
        .run(&strategy, |(k, sets)| {
            let t0 = Instant::now();
            let mut sc = presets[k].clone();
            for (path, value) in &sets {
                match sc.with_override(path, value) {
                    Ok(s) => sc = s,
                    Err(e) => {
                        prop_assert!(!e.0.is_empty() && e.to_string().len() < 4000, "{e}");
                        return Ok(());
                    }
                }
            }
            if let Ok(mut sim) = Simulation::new(&sc) {
                if sim.advance(3000).is_ok() {
                    let r = sim.finish();
                    prop_assert!(check_finite(&r.summary).is_ok(), "{sets:?}: {:?}", check_finite(&r.summary));
                }
            }
            prop_assert!(t0.elapsed() < CASE_BOUND, "{sets:?} took {:?}", t0.elapsed());
            Ok(())
        })
        .unwrap();
}

/// Hull offsets with hostile numbers parse with an error naming the line, or give finite RAOs.
#[test]
fn hull_csvs_fail_cleanly_or_give_finite_raos() {
    let num = prop_oneof![
        3 => 0.0..20.0f64,
        1 => prop::sample::select(vec![0.0, -1.0, 1e300, -1e300, 1e-300, 5e-324, 1e4, f64::NAN]),
    ];
    let station = (prop::collection::vec((num.clone(), num.clone()), 2..6), num.clone());
    let strategy = prop::collection::vec(station, 3..7);
    runner(2)
        .run(&strategy, |stations| {
            let t0 = Instant::now();
            let mut text = String::from("station_index,x_m,z_m,half_breadth_m\n");
            for (i, (rows, x)) in stations.iter().enumerate() {
                for (z, hb) in rows {
                    text.push_str(&format!("{i},{},{z},{hb}\n", x + 10.0 * i as f64));
                }
            }
            if let Ok(h) = HullOffsets::parse(&text) {
                let mass = MassProperties { kg_m: 3.0, kxx_m: 2.0, kyy_m: 10.0, kzz_m: 10.0 };
                if let Ok(ship) = Ship::new(&h, 2.0, mass, None, 1025.0, 9.81) {
                    if let Ok(v) = aes_core::sea::seakeeping::tables::rao_json(&ship, 5.0, 3.0, &[0.5, 1.0], 1.0) {
                        prop_assert!(!v.to_string().contains("null"), "{text}");
                    }
                }
            }
            prop_assert!(t0.elapsed() < CASE_BOUND, "took {:?}", t0.elapsed());
            Ok(())
        })
        .unwrap();
}

/// Shard `a` of a study with one or two values changed (any leaf of its JSON, from the hostile
/// list): refused by name, or it merges with shard `b` and summarises finitely.
fn mutated_shards_are_refused_or_finite<S: Study>(make: impl Fn() -> S, a: (u64, u64), b: (u64, u64), seed: u8) {
    let first = study::run_range(&make(), a.0, a.1).unwrap();
    let second = study::run_range(&make(), b.0, b.1).unwrap();
    let good = serde_json::to_value(&first).unwrap();
    let mut paths = Vec::new();
    leaf_paths(&good, "", &mut paths);
    let strategy = prop::collection::vec((prop::sample::select(paths), value_text()), 1..3);
    runner(seed)
        .run(&strategy, |changes| {
            let t0 = Instant::now();
            let mut v = good.clone();
            for (path, value) in &changes {
                let mut node = &mut v;
                for part in path.split('.') {
                    node = match node {
                        serde_json::Value::Array(x) => &mut x[part.parse::<usize>().unwrap()],
                        x => &mut x[part],
                    };
                }
                *node = serde_json::from_str(value).unwrap_or(serde_json::Value::String(value.clone()));
            }
            match study::from_json::<S>(&v.to_string()) {
                Err(e) => prop_assert!(e.len() < 2000, "{} bytes", e.len()),
                Ok(p) => {
                    let mut m = study::Merger::new(make());
                    match m.add(p).and_then(|()| m.add(second.clone())) {
                        Err(e) => prop_assert!(e.len() < 2000, "{} bytes", e.len()),
                        Ok(()) => {
                            let (study, merged) = m.finish().unwrap();
                            if let Ok(s) = study.summary(&merged.part, &merged.ranges) {
                                prop_assert!(check_finite(&s).is_ok(), "{changes:?}: {:?}", check_finite(&s));
                            }
                        }
                    }
                }
            }
            prop_assert!(t0.elapsed() < CASE_BOUND, "took {:?}", t0.elapsed());
            Ok(())
        })
        .unwrap();
}

/// A Monte Carlo partial with one value changed is refused by name, or merges and summarises
/// finitely.
#[test]
fn mutated_partials_fail_cleanly_or_merge_finitely() {
    let sc = preset("mc-arrival").unwrap().with_override("sim.duration_s", "2").unwrap();
    let sc = sc.with_override("monte_carlo.trials", "4").unwrap();
    mutated_shards_are_refused_or_finite(|| MonteCarlo::new(sc.clone()).unwrap(), (0, 2), (2, 4), 3);
}

/// Issue 46: a rare-event shard with values changed (a seed, a weight, a consequence, the ship's
/// place, the study's key) is refused naming it, in under 2 kB, or merges into a finite summary.
#[test]
fn mutated_rare_event_shards_fail_cleanly_or_merge_finitely() {
    use aes_core::studies::rare::{RareEvents, RareSpec};
    let sc = preset("head-seas-ss6").unwrap();
    let mut sc =
        sc.with_override("rare_event.time_s", "20").unwrap().with_override("rare_event.window_s", "5").unwrap();
    // Ventilation, as `aes-sim rare` sets it by default.
    sc = sc.with_override("rare_event.level_h_over_r", "1.1").unwrap();
    let spec = RareSpec::new(&sc, 4).unwrap();
    mutated_shards_are_refused_or_finite(|| RareEvents::new(spec.clone()).unwrap(), (0, 2), (2, 4), 11);
}

/// The browser's binary partials with bytes overwritten in their moment rows (issue 34: 127 of
/// 1,500 such were accepted): refused, or every row's numbers are possible, a mean within
/// [min, max] and a std no larger than values in [min, max] allow ((max - min) / 2 times
/// sqrt(n / (n - 1)), plus 1e-6 of it and a grid step for the rounding).
#[test]
fn corrupted_binary_partials_are_refused_or_possible() {
    let sc = preset("mc-arrival").unwrap().with_override("sim.duration_s", "2").unwrap();
    let sc = sc.with_override("monte_carlo.trials", "4").unwrap();
    let mc = || MonteCarlo::new(sc.clone()).unwrap();
    let good = study::run_range(&mc(), 0, 3).unwrap();
    let bytes = study::to_bytes::<MonteCarlo>(&good).unwrap();
    // The shard's envelope, then the part's own head: the moment rows follow.
    let part = 16 + u64::from_le_bytes(bytes[8..16].try_into().unwrap()) as usize;
    let head = part + 16 + u64::from_le_bytes(bytes[part + 8..part + 16].try_into().unwrap()) as usize;
    let body = bytes.len() - head;
    assert!(body > 1000, "the case has moment rows to damage: {body} bytes");
    let strategy = prop::collection::vec((0..body, any::<u8>()), 1..6);
    runner(5)
        .run(&strategy, |changes| {
            let mut b = bytes.clone();
            for &(at, v) in &changes {
                b[head + at] = v;
            }
            let mut m = study::Merger::new(mc());
            if study::from_bytes::<MonteCarlo>(&b).and_then(|p| m.add(p)).is_ok() {
                let (study, p) = m.finish().unwrap();
                let s = study.summary(&p.part, &p.ranges).unwrap();
                prop_assert!(check_finite(&s).is_ok(), "{changes:?}");
                for (name, r) in &s.envelopes {
                    for i in 0..r.n.len() {
                        if let (Some(mean), Some(lo), Some(hi)) = (r.mean[i], r.min[i], r.max[i]) {
                            prop_assert!(
                                lo <= mean && mean <= hi,
                                "{changes:?}: {name}.{i} mean {mean} in [{lo}, {hi}]"
                            );
                            if let (Some(std), true) = (r.std[i], r.n[i] >= 2) {
                                let n = r.n[i] as f64;
                                let most = (hi - lo) / 2.0 * (n / (n - 1.0)).sqrt();
                                prop_assert!(
                                    std <= most * (1.0 + 1e-6) + 1.0 / 65536.0,
                                    "{changes:?}: {name}.{i} std {std} beyond {most}"
                                );
                            }
                        }
                    }
                }
            }
            Ok(())
        })
        .unwrap();
}

/// The ch. 4 tool at any operating point and parameter: an error, or finite poles and Bode.
#[test]
fn ips_parameters_fail_cleanly_or_stay_finite() {
    use aes_core::studies::ips::{generator_side::GeneratorSideParams, load_params, motor_side::MotorSideParams};
    let x = prop_oneof![
        (1e-3..1e4f64),
        prop::sample::select(vec![0.0, -1.0, 1e100, 1e300, 1e-300, 5e-324, f64::NAN, f64::INFINITY]),
    ];
    let names = vec!["r_s", "l_m", "kq0", "inertia", "trim_tau", "l_md", "r_fd", "x_co", "estimate_factor"];
    let strategy =
        (any::<bool>(), x.clone(), x.clone(), x.clone(), prop::sample::select(names), value_text(), any::<bool>());
    runner(4)
        .run(&strategy, |(motor, a, b, c, name, value, closed)| {
            let t0 = Instant::now();
            let sets = vec![(name.to_string(), value.clone())];
            let sys = if motor {
                load_params(&MotorSideParams::default(), &sets).and_then(|p| {
                    let s = p.steady_state(a)?;
                    check_finite(&s)?;
                    Ok(if closed { p.closed_loop(&s) } else { p.open_loop(&s) })
                })
            } else {
                load_params(&GeneratorSideParams::default(), &sets).and_then(|p| {
                    let s = p.steady_state(a, b, c)?;
                    check_finite(&s)?;
                    Ok(if closed { p.closed_loop(&s) } else { p.open_loop(&s) })
                })
            };
            if let Ok(sys) = sys {
                if let Ok(p) = sys.poles() {
                    prop_assert!(check_finite(&p).is_ok());
                }
                if let Ok(pts) = sys.bode(&[0.1, 10.0, 1000.0]) {
                    prop_assert!(check_finite(&pts).is_ok());
                }
            }
            prop_assert!(t0.elapsed() < CASE_BOUND, "took {:?}", t0.elapsed());
            Ok(())
        })
        .unwrap();
}

/// The operability polar's request (issue 46): speeds, headings, sea states, seas and a scatter
/// diagram's text, each from a hostile list, on the start-up ship with a coarse RAO grid. The
/// property: refused with a message under 2 kB, or a polar whose every number is finite, never a
/// panic, within the case bound.
#[test]
fn operability_requests_fail_cleanly_or_stay_finite() {
    use aes_core::studies::operability::study::{OperabilityPolar, PolarStudySpec};
    let mut sc = preset("startup").unwrap();
    for (k, v) in
        [("seakeeping.grid.n_omega", "12"), ("seakeeping.grid.n_speed", "3"), ("seakeeping.grid.n_heading", "5")]
    {
        sc = sc.with_override(k, v).unwrap();
    }
    // Mostly values a request may hold, a quarter of them hostile, so that polars are built too.
    let hostile = || {
        value_text().prop_map(|t| serde_json::from_str::<serde_json::Value>(&t).unwrap_or(serde_json::Value::String(t)))
    };
    let fine = |lo: f64, hi: f64| (lo..hi).prop_map(|x| serde_json::json!(x));
    let list = move |lo: f64, hi: f64| prop::collection::vec(prop_oneof![3 => fine(lo, hi), 1 => hostile()], 0..4);
    let states =
        prop::collection::vec(prop_oneof![3 => (2u32..=6).prop_map(|x| serde_json::json!(x)), 1 => hostile()], 0..4);
    let seas = prop::collection::vec(
        (prop_oneof![3 => fine(0.5, 10.0), 1 => hostile()], prop_oneof![3 => fine(0.3, 1.5), 1 => hostile()]),
        0..3,
    );
    let scatter = prop::sample::select(vec![
        "",
        "",
        "",
        "hs_m,tp_s,occurrences\n1,8,10\n",
        "hs_m,tp_s,occurrences\n1e308,8,1e308\n2,9,1e308\n",
        "hs_m,tp_s,occurrences\nNaN,8,1\n",
        "hs_m,tp_s\n1,8\n",
        "x\n\u{0}\u{7}\n",
    ]);
    let strategy = (list(0.0, 30.0), list(0.0, 360.0), states, seas, scatter);
    let (tried, built) = (std::sync::atomic::AtomicUsize::new(0), std::sync::atomic::AtomicUsize::new(0));
    runner(7)
        .run(&strategy, |(speeds, headings, states, seas, csv)| {
            let t0 = Instant::now();
            // An empty list stands for a field left out (the default list).
            let mut request = serde_json::json!({});
            for (k, v) in [("speeds_kn", speeds), ("headings_deg", headings), ("sea_states", states)] {
                if !v.is_empty() {
                    request[k] = serde_json::Value::Array(v);
                }
            }
            if !seas.is_empty() {
                request["seas"] =
                    serde_json::Value::Array(seas.iter().map(|(a, b)| serde_json::json!([a, b])).collect());
            }
            if !csv.is_empty() {
                request["scatter_csv"] = serde_json::Value::String(csv.to_string());
            }
            let spec = serde_json::json!({ "scenario": serde_json::to_value(&sc).unwrap(), "request": request });
            let made = serde_json::from_value::<PolarStudySpec>(spec)
                .map_err(|e| e.to_string())
                .and_then(OperabilityPolar::new);
            tried.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            match made {
                Err(e) => prop_assert!(e.len() < 2000, "{} bytes: {}", e.len(), &e[..200.min(e.len())]),
                Ok(polar) => {
                    let n = polar.items();
                    if let Ok(shard) = study::run_range(&polar, 0, n) {
                        if let Ok(s) = polar.summary(&shard.part, &shard.ranges) {
                            prop_assert!(check_finite(&s).is_ok(), "{:?}", check_finite(&s));
                            built.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        }
                    }
                }
            }
            prop_assert!(t0.elapsed() < CASE_BOUND, "took {:?}", t0.elapsed());
            Ok(())
        })
        .unwrap();
    let (tried, built) = (tried.into_inner(), built.into_inner());
    println!("{built} of {tried} requests gave a polar");
    // The property is tested on polars too, not only on refusals.
    assert!(tried < 50 || built > 0, "{built} of {tried}");
}
