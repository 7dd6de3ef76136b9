//! Issue 57: `merge` checks every number of a shard from outside against what the study's items
//! can give, for every kind on the pipeline. A valid shard of each kind has every field of its
//! part changed, one at a time, to a value no item can give (a number far out of range or of
//! the wrong sign, a count or an index far too large, a name that is not the study's, a flag
//! flipped): each is refused, and the refusal names the field (a checked refusal says the
//! field's name or the record holding it; one that does not even read, as a type error, is
//! refused before any check). Every field's pattern (indices aside) is tried at its first,
//! middle and last instance, and then `AES_FUZZ_CASES` random (field, value) pairs (default 128).
//!
//! One thing is not refused and cannot be: the limiting height of a rate criterion that does not
//! limit its cell may be made larger (a response whose zero-crossing rate is just above the limit
//! has a limiting height as large as one likes); it is bounded (finite, non-negative, under the
//! square root of the largest double) and ordered against its value, which the values here
//! (1e308, negative) break.

use aes_core::scenario::presets::preset;
use aes_core::scenario::Scenario;
use aes_core::studies::study::{self, Study};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use serde_json::Value;
use std::collections::BTreeMap;

/// Every leaf of `v` under `prefix`, with its path.
fn leaves(v: &Value, prefix: &str, out: &mut Vec<String>) {
    let join = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
    match v {
        Value::Object(m) => m.iter().for_each(|(k, x)| leaves(x, &join(k), out)),
        Value::Array(a) => a.iter().enumerate().for_each(|(i, x)| leaves(x, &join(&i.to_string()), out)),
        _ => out.push(prefix.to_string()),
    }
}

fn at<'a>(v: &'a mut Value, path: &str) -> &'a mut Value {
    path.split('.').fold(v, |node, part| match node {
        Value::Array(x) => &mut x[part.parse::<usize>().unwrap()],
        x => &mut x[part],
    })
}

/// Values no item gives in place of `x`: kept to its JSON type (a number's wrong sign or an
/// overflow, a count far above the items, a sum of powers far out, another name, a flag flipped).
fn tampers(x: &Value) -> Vec<Value> {
    match x {
        Value::Number(n) if n.is_u64() => {
            let k = n.as_u64().unwrap();
            vec![Value::from(k.saturating_mul(1000).saturating_add(1000)), Value::from(u64::MAX)]
        }
        Value::Number(n) => {
            let f = n.as_f64().unwrap();
            vec![Value::from(1e308), Value::from(-1e308), Value::from(-5.0), Value::from(-(f.abs() + 1.0) * 10.0)]
        }
        // The exact moments' integer sums, written as strings.
        Value::String(s) if s.parse::<i128>().is_ok() => {
            let k: i128 = s.parse().unwrap();
            vec![
                Value::from((k * 1000 + 1_000_000_000_000_000).to_string()),
                Value::from("-1000000000000000000000000000000"),
            ]
        }
        Value::String(_) => vec![Value::from("x")],
        Value::Bool(b) => vec![Value::from(!b)],
        _ => vec![],
    }
}

/// The names a refusal of the field at `path` may give: its non-index components under `part`.
fn names(path: &str) -> Vec<&str> {
    path.split('.').skip(1).filter(|p| p.parse::<usize>().is_err()).collect()
}

/// Shard items `a` of the study `make` gives, with `path` set to `value`: the refusal, or None if
/// it was merged.
fn refusal<S: Study>(make: &impl Fn() -> S, good: &Value, path: &str, value: &Value) -> Option<String> {
    let mut v = good.clone();
    *at(&mut v, path) = value.clone();
    let shard = match study::from_json::<S>(&v.to_string()) {
        Ok(s) => s,
        Err(e) => return Some(format!("(read) {e}")),
    };
    let mut m = study::Merger::new(make());
    m.add(shard).err()
}

fn check_one<S: Study>(make: &impl Fn() -> S, good: &Value, path: &str, value: &Value) -> Result<(), String> {
    match refusal(make, good, path, value) {
        None => Err(format!("{path} = {value}: merged")),
        Some(e) if e.starts_with("(read) ") => Ok(()),
        Some(e) => {
            let named = names(path).iter().any(|n| e.contains(n));
            if !named {
                return Err(format!("{path} = {value}: refused without naming it: {e}"));
            }
            if e.len() > 2000 || e.chars().any(|c| c.is_control()) {
                return Err(format!("{path} = {value}: a message of {} bytes or with control characters", e.len()));
            }
            Ok(())
        }
    }
}

/// Every field of shard `a` of the study tampered: each refused by name. Returns how many
/// changes were tried.
fn every_field_refused<S: Study>(make: impl Fn() -> S, a: (u64, u64), seed: u8) -> usize {
    let s = study::run_range(&make(), a.0, a.1).unwrap();
    let good = serde_json::to_value(&s).unwrap();
    assert!(refusal(&make, &good, "version", &good["version"].clone()).is_none(), "the valid shard merges");
    let mut paths = Vec::new();
    leaves(&good["part"], "part", &mut paths);
    let mut by_pattern: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for p in &paths {
        let pattern: Vec<&str> = p.split('.').map(|c| if c.parse::<usize>().is_ok() { "*" } else { c }).collect();
        by_pattern.entry(pattern.join(".")).or_default().push(p.clone());
    }
    let mut failures = Vec::new();
    let mut tried = 0;
    for list in by_pattern.values() {
        let picks = [0, list.len() / 2, list.len() - 1];
        for &k in picks.iter().take(if list.len() > 2 { 3 } else { list.len() }) {
            let path = &list[k];
            let mut g = good.clone();
            for value in tampers(at(&mut g, path)) {
                tried += 1;
                if let Err(e) = check_one(&make, &good, path, &value) {
                    failures.push(e);
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} of {tried} changes not refused by name:\n{}", failures.len(), failures.join("\n"));
    let cases = std::env::var("AES_FUZZ_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(128);
    let mut runner = TestRunner::new_with_rng(
        Config { cases, failure_persistence: None, ..Config::default() },
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    );
    runner
        .run(&(prop::sample::select(paths), 0usize..4), |(path, which)| {
            let mut g = good.clone();
            let t = tampers(at(&mut g, &path));
            if let Some(value) = t.get(which % t.len().max(1)) {
                prop_assert!(
                    check_one(&make, &good, &path, value).is_ok(),
                    "{:?}",
                    check_one(&make, &good, &path, value)
                );
            }
            Ok(())
        })
        .unwrap();
    tried
}

/// Operability: 2 speeds x 3 headings x 2 seas, the default criteria (motions, accelerations,
/// chances, rates) and the North Atlantic scatter diagram.
#[test]
fn every_field_of_an_operability_shard_is_checked() {
    use aes_core::studies::operability::study::{OperabilityPolar, PolarStudySpec};
    use aes_core::studies::operability::PolarRequest;
    let request = PolarRequest {
        speeds_kn: Some(vec![0.0, 18.0]),
        headings_deg: Some(vec![0.0, 90.0, 180.0]),
        sea_states: Some(vec![4, 6]),
        ..Default::default()
    };
    let spec = PolarStudySpec { scenario: Scenario::default(), request };
    let n = every_field_refused(|| OperabilityPolar::new(spec.clone()).unwrap(), (1, 2), 21);
    assert!(n > 40, "{n} changes");
}

/// Fuel per mile: two speeds in SS6 head seas, two seeds each (a shard of both of one speed).
#[test]
fn every_field_of_a_fuel_per_mile_shard_is_checked() {
    use aes_core::studies::fuel_per_mile::{FuelPerMileSpec, FuelPerMileStudy};
    let mut sc = preset("head-seas-ss6").unwrap();
    sc.sim.duration_s = 30.0;
    let spec = FuelPerMileSpec { scenario: sc, speeds_kn: vec![15.0, 25.0], seeds: 2, from_s: 15.0 };
    let n = every_field_refused(|| FuelPerMileStudy::new(spec.clone()).unwrap(), (1, 3), 22);
    assert!(n > 20, "{n} changes");
}

/// Monte Carlo: two trials of the arrival study (envelopes, histograms, onset, periodogram,
/// kept traces).
#[test]
fn every_field_of_a_monte_carlo_shard_is_checked() {
    use aes_core::studies::montecarlo::MonteCarlo;
    for (k, sc) in [mc_excess(), mc_arrival()].into_iter().enumerate() {
        let n = every_field_refused(|| MonteCarlo::new(sc.clone()).unwrap(), (0, 2), 23 + k as u8);
        assert!(n > 60, "{n} changes");
    }
}

/// Four trials of 45 s of the excess-energy study (a histogram at 40 s, excess energies, the
/// periodogram), two traces kept.
fn mc_excess() -> Scenario {
    let mut sc = preset("mc-excess-energy").unwrap();
    sc.sim.duration_s = 45.0;
    sc.monte_carlo.trials = 4;
    sc.monte_carlo.keep_traces = 2;
    sc
}

/// Four trials of 30 s of the arrival study (arrivals, onsets, censored trials).
fn mc_arrival() -> Scenario {
    let mut sc = preset("mc-arrival").unwrap();
    sc.sim.duration_s = 30.0;
    sc.monte_carlo.trials = 4;
    sc
}

/// The campaign's own examples, each merged before: the shard edited as the issue did, refused
/// naming the field.
fn refused_as<S: Study>(make: impl Fn() -> S, a: (u64, u64), edit: impl Fn(&mut Value), field: &str) {
    let s = study::run_range(&make(), a.0, a.1).unwrap();
    let mut v = serde_json::to_value(&s).unwrap();
    edit(&mut v);
    let shard = study::from_json::<S>(&v.to_string()).unwrap();
    let e = study::Merger::new(make()).add(shard).unwrap_err();
    assert!(e.contains(field), "{field}: {e}");
}

fn cell(v: &mut Value) -> &mut Value {
    &mut v["part"][0]["cells"][0]
}

#[test]
fn the_campaigns_tampered_shards_are_refused() {
    use aes_core::studies::fuel_per_mile::{FuelPerMileSpec, FuelPerMileStudy};
    use aes_core::studies::montecarlo::MonteCarlo;
    use aes_core::studies::operability::study::{OperabilityPolar, PolarStudySpec};
    use aes_core::studies::operability::PolarRequest;
    // Operability: -1,562 deg of roll; a limiting height of 1e308 m, of -5 m, of 99 m with no
    // sea passed.
    let request = PolarRequest {
        speeds_kn: Some(vec![18.0]),
        headings_deg: Some(vec![90.0]),
        sea_states: Some(vec![4, 6]),
        ..Default::default()
    };
    let spec = PolarStudySpec { scenario: Scenario::default(), request };
    let polar = || OperabilityPolar::new(spec.clone()).unwrap();
    refused_as(polar, (0, 1), |v| cell(v)["values"][0][0] = (-1562.0).into(), "values.0.0 = -1562");
    for (h, passed) in [(1e308, None), (-5.0, None), (99.0, Some(0))] {
        refused_as(
            polar,
            (0, 1),
            |v| {
                cell(v)["limiting_hs_m"] = h.into();
                if let Some(p) = passed {
                    cell(v)["seas_passed"] = Value::from(p);
                }
            },
            "limiting_hs_m",
        );
    }
    // Fuel per mile: a mean speed of 947 kn for a 20 kn order; 370,000 kg per nautical mile.
    let mut sc = preset("head-seas-ss6").unwrap();
    sc.sim.duration_s = 30.0;
    let spec = FuelPerMileSpec { scenario: sc, speeds_kn: vec![20.0], seeds: 1, from_s: 15.0 };
    let fuel = || FuelPerMileStudy::new(spec.clone()).unwrap();
    refused_as(fuel, (0, 1), |v| v["part"][0]["speed_kn"]["max"] = 947.0.into(), "0.speed_kn");
    refused_as(
        fuel,
        (0, 1),
        |v| {
            let m = &mut v["part"][0]["kg_per_nmi"];
            let q = (370_000.0f64 * 65536.0) as i128;
            m["min"] = 370_000.0.into();
            m["max"] = 370_000.0.into();
            m["sums"] = serde_json::json!([q.to_string(), (q * q).to_string(), "0", "0"]);
        },
        "0.kg_per_nmi",
    );
    // Monte Carlo: the motor power histogram's counts moved to its top bin (a median far above
    // the largest value); a kept trace with h/R 5,162; its time column reversed.
    let mc = || MonteCarlo::new(mc_excess()).unwrap();
    refused_as(
        mc,
        (0, 2),
        |v| {
            let h = &mut v["part"]["at_time_hist"]["counts"];
            let n: u64 = h.as_array().unwrap().iter().map(|c| c.as_u64().unwrap()).sum();
            let len = h.as_array().unwrap().len();
            *h = Value::from((0..len).map(|k| if k == len - 1 { n } else { 0 }).collect::<Vec<u64>>());
        },
        "at_time_hist: counts.29",
    );
    let mc = || MonteCarlo::new(mc_arrival()).unwrap();
    refused_as(
        mc,
        (0, 2),
        |v| v["part"]["traces"][0]["columns"][1][1][3] = 5162.0.into(),
        "traces: trial 0: columns.h_over_r.3",
    );
    refused_as(
        mc,
        (0, 2),
        |v| {
            let t = v["part"]["traces"][0]["t_s"].as_array_mut().unwrap();
            t.reverse();
        },
        "traces: trial 0: t_s.0",
    );
}
