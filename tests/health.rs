//! The plant's health checks (core/src/sim/health.rs) and the settling times of the summary
//! (core/src/sim/summary.rs) on the runs that showed why they are needed (issue 29): a stalled
//! plant, a propeller out of the water, and healthy runs that must stay silent.

use aes_core::scenario::presets::preset;
use aes_core::signals::Signal;
use aes_core::sim::{health, run, RunResult};

fn run_preset(name: &str, edit: impl FnOnce(&mut aes_core::scenario::Scenario)) -> RunResult {
    let mut sc = preset(name).unwrap();
    edit(&mut sc);
    run(&sc).unwrap()
}

fn has(r: &RunResult, words: &str) -> bool {
    r.summary.warnings.iter().any(|w| w.contains(words))
}

/// The acceleration with field K_p,v = 5 stalls (turbines 0.13-0.155 pu, bus 0.35-0.41 pu for
/// about 100 s): the summary says so, and neither the turbine speed nor the bus voltage is given
/// a settling time (they end far from their 1 pu). The preset itself settles both.
#[test]
fn a_stalled_plant_is_named_and_does_not_settle() {
    let r = run_preset("acceleration", |sc| sc.controllers.field.kp = 5.0);
    let s = &r.summary.signals;
    assert!(s["turbine_speed_pu"].final_ < health::TURBINE_MIN_RUNNING_PU, "{:?}", s["turbine_speed_pu"]);
    assert!(has(&r, "turbines stalled"), "{:#?}", r.summary.warnings);
    assert!(has(&r, "bus voltage outside its band"), "{:#?}", r.summary.warnings);
    assert!(has(&r, "at the slip limit (mostly below rated power"), "{:#?}", r.summary.warnings);
    assert_eq!(s["turbine_speed_pu"].settling_time_s, None);
    assert_eq!(s["bus_voltage_pu"].settling_time_s, None);

    let ok = run_preset("acceleration", |_| {});
    assert!(!has(&ok, "turbines stalled"), "{:#?}", ok.summary.warnings);
    // The turbines dip to 0.69 pu and are back within 2 % after about 20 s.
    let ts = ok.summary.signals["turbine_speed_pu"].settling_time_s.unwrap();
    assert!((10.0..40.0).contains(&ts), "{ts}");
}

/// With the hub raised to h0 = 0.15 m in the head-seas study the propellers' discs break the
/// surface all run (h/R about 0.06 at rest); the summary says so, and the trace agrees that
/// surface losses hold from the first row on (the page counts that row as an onset).
#[test]
fn a_propeller_out_of_the_water_is_named() {
    let r = run_preset("head-seas-ss6", |sc| {
        sc.set_hub_depth_m(0.15);
    });
    assert!(has(&r, "both propellers out of the water"), "{:#?}", r.summary.warnings);
    let beta = r.trace.get(Signal::BetaT);
    assert!(beta[0] < 1.0, "beta_T at t = 0: {}", beta[0]);
    let h = &r.summary.signals["h_over_r"];
    assert!(h.mean < 0.5, "{h:?}");
}

/// Runs that stay within every limit add no health warning: the start-up, a calm turn and the
/// quarter turn in sea state 6 (their warnings, if any, are about orders outside the model).
#[test]
fn healthy_runs_stay_silent() {
    for name in ["startup", "turn-90", "quarter-turn-ss6"] {
        let r = run_preset(name, |_| {});
        let health: Vec<_> = r.summary.warnings.iter().filter(|w| !w.contains("trusted from")).collect();
        assert!(health.is_empty(), "{name}: {health:#?}");
    }
}

/// A turbine speed that stays at 1.000 has nothing to settle (it never leaves the 2 % band): no
/// settling time, where the old definition (2 % of its own tiny range) printed one.
#[test]
fn a_flat_signal_has_no_settling_time() {
    let r = run_preset("turn-90", |_| {});
    let t = &r.summary.signals["turbine_speed_pu"];
    assert!(t.max - t.min < 0.01, "{t:?}");
    assert_eq!(t.settling_time_s, None);
    // The heading is ordered to 90 degrees and gets there.
    assert!(r.summary.signals["heading_deg"].settling_time_s.is_some());
}

/// A set started by an order delivers nothing until its start-up time has passed, then takes its
/// share of the load (issue 45): 12 kn on set 1 alone, set 3 ordered on at 5 s with a 10 s
/// start-up. Before 15 s set 3 gives exactly 0 W; 10 s after it closed its breaker it carries
/// half the load (measured 0.500 at 25 s: the two sets are alike).
#[test]
fn a_started_set_delivers_only_after_its_startup_time() {
    use aes_core::scenario::Command;
    let mut sc = preset("startup").unwrap();
    sc.initial.speed_kn = 12.0;
    sc.plant.online.sets = vec![1];
    sc.plant.online.startup_time_s = 10.0;
    sc.commands = vec![
        Command {
            t_s: 0.0,
            speed_kn: Some(12.0),
            heading_deg: None,
            heading_rate_deg_s: None,
            online_sets: None,
            crash_stop: false,
        },
        Command {
            t_s: 5.0,
            speed_kn: None,
            heading_deg: None,
            heading_rate_deg_s: None,
            online_sets: Some(vec![1, 3]),
            crash_stop: false,
        },
    ];
    sc.sim.duration_s = 25.0;
    let mut sim = aes_core::sim::Simulation::new(&sc).unwrap();
    let steps_per_s = (1.0 / sc.stepping.dt_s).round() as u64;
    let at = |sim: &mut aes_core::sim::Simulation, t: f64| {
        let n = (t * steps_per_s as f64).round() as u64 - (sim.time() * steps_per_s as f64).round() as u64;
        sim.advance(n).unwrap();
        sim.turbine_power()
    };
    let p = at(&mut sim, 1.0);
    assert!(p[0] > 2.0e6 && p[1] == 0.0 && p[2] == 0.0 && p[3] == 0.0, "{p:?}");
    let p = at(&mut sim, 14.99);
    assert_eq!(p[2], 0.0, "set 3 before its start-up time: {p:?}");
    let p = at(&mut sim, 25.0);
    let share = p[2] / (p[0] + p[2]);
    println!("set 3's share at 25 s: {share:.3} ({p:?})");
    assert!((share - 0.5).abs() < 0.02, "set 3's share after start-up {share:.3}: {p:?}");
    assert_eq!((p[1], p[3]), (0.0, 0.0));
    let r = sim.finish();
    assert!(!has(&r, "overloaded"), "{:#?}", r.summary.warnings);
}

/// One set online at 15 kn ordered to 27 kn: it runs past its rating and the summary says so in
/// words, naming the remedy.
#[test]
fn an_overloaded_online_set_is_named() {
    let r = run_preset("startup", |sc| {
        sc.initial.speed_kn = 15.0;
        sc.plant.online.sets = vec![2];
        sc.commands[0].speed_kn = Some(27.0);
        sc.sim.duration_s = 60.0;
    });
    assert!(has(&r, "set 2 overloaded"), "{:#?}", r.summary.warnings);
    assert!(has(&r, "start another"), "{:#?}", r.summary.warnings);
}

fn run_with(name: &str, sets: &[(&str, &str)]) -> RunResult {
    run(&preset(name).unwrap().with_overrides(sets).unwrap()).unwrap()
}

/// Issue 55: the operability polar's 3 kn cell in sea state 6 with the waves at 45 degrees
/// (quartering, from 135 for a ship heading north) holds no turn order, yet its heading drifts to
/// 81 degrees with the rudder at its limit: the waves' yaw moment (about 3.5 MN m on average)
/// beats the rudders' full angle (about 3 MN m at 2.7 kn). The warning names the waves with
/// both moments, not an ordered turn. A 3 deg/s turn at 25 kn with the autopilot allowed r' = 1
/// in calm water still names the ordered turn. Tolerance: the words; the moments to 0.1 MN m as printed.
#[test]
fn a_heading_lost_to_the_waves_is_not_blamed_on_a_turn() {
    let r = run_with(
        "startup",
        &[
            ("commands.0.speed_kn", "3"),
            ("initial.speed_kn", "3"),
            ("sea.kind", "random"),
            ("sea.sea_state", "6"),
            ("sea.from_deg", "135"),
            ("hull.model", "maneuvering"),
        ],
    );
    assert!(
        has(&r, "no turn ordered: the rudders cannot hold the heading against the waves"),
        "{:#?}",
        r.summary.warnings
    );
    assert!(has(&r, "MN m") && !has(&r, "ordered turn is faster"), "{:#?}", r.summary.warnings);
    let heading = &r.summary.signals["heading_deg"];
    assert!(heading.max > 60.0, "{heading:?}");

    let turn = run_with(
        "turn-90",
        &[
            ("commands.1.heading_rate_deg_s", "3"),
            ("controllers.autopilot.max_turn_rate_nondim", "1"),
            ("sim.duration_s", "120"),
        ],
    );
    assert!(has(&turn, "the ordered turn is faster than full rudder can give"), "{:#?}", turn.summary.warnings);
    assert!(!has(&turn, "against the waves"), "{:#?}", turn.summary.warnings);
}
