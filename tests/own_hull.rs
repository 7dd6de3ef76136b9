//! The hull's own maneuvering model (core/src/ship/sectional.rs): the ship sails at every speed
//! and heading a polar click can ask for, keeps its speed order or says why not, drifts at rest,
//! and its standard maneuvers are a destroyer's.

use aes_core::scenario::presets::preset;
use aes_core::studies::maneuvers::booklet;
use aes_tests::run;

/// The head-seas preset set as the operability polar's click sets a cell: order and initial speed
/// `kn`, waves at relative heading `heading_deg` (180: head seas), sea state `ss`, 200 s.
fn cell(kn: f64, heading_deg: f64, ss: u32) -> aes_core::Scenario {
    let mut s = preset("head-seas-ss6").unwrap();
    s.name = format!("{kn} kn, waves at {heading_deg} deg, SS{ss}");
    s.sea.sea_state = ss;
    s.sea.from_deg = (180.0 - heading_deg).rem_euclid(360.0);
    s.initial.speed_kn = kn;
    s.commands[0].speed_kn = Some(kn);
    s.sim.duration_s = 200.0;
    s
}

/// The mean of a column over the run's last minute.
fn last_minute(r: &aes_core::RunResult, name: &str) -> f64 {
    let t = r.trace.column("t_s").unwrap();
    let y = r.trace.column(name).unwrap();
    let end = t[t.len() - 1];
    let sel: Vec<f64> = t.iter().zip(y).filter(|(&t, _)| t >= end - 60.0).map(|(_, &y)| y).collect();
    sel.iter().sum::<f64>() / sel.len() as f64
}

/// Every cell of 7 speeds (4 to 28 kn) x 7 headings (0 to 180 deg) x sea states 4 to 6 runs its
/// 200 s (the Table 2.3 hull diverged in 16 of 40 such cells at 6 and 12 kn) and holds its order
/// within max(2 kn, 20 %) over the last minute. Measured: all 147 hold it. With eq. 2.48's F7 as
/// the surge force's short-wave part, 11 did not (4 and 8 kn with the waves from astern or the
/// quarter, carried to 6-14 kn by about 0.4 MN forward at 4 kn in SS6); the waterline's
/// reflection gives 35 kN there (`seakeeping::reflection`). Asserted: no cell stops, every cell
/// within the band; a cell outside it must say why in its warnings (it would fail here all the
/// same).
#[test]
fn every_polar_cell_sails() {
    let mut cells = Vec::new();
    for ss in 4..=6 {
        for kn in [4.0, 8.0, 12.0, 16.0, 20.0, 24.0, 28.0] {
            for h in [0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0] {
                cells.push((kn, h, ss));
            }
        }
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get()).min(4);
    let results: Vec<(f64, f64, u32, f64, Vec<String>)> = std::thread::scope(|scope| {
        let chunks: Vec<_> = cells.chunks(cells.len().div_ceil(threads)).collect();
        let handles: Vec<_> = chunks
            .into_iter()
            .map(|chunk| {
                scope.spawn(move || {
                    chunk
                        .iter()
                        .map(|&(kn, h, ss)| {
                            let r = run(&cell(kn, h, ss));
                            assert!(r.summary.final_time_s >= 200.0 - 1e-9, "{kn} kn {h} deg SS{ss} stopped");
                            (kn, h, ss, last_minute(&r, "ship_speed_kn"), r.summary.warnings)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let mut held = 0;
    for (kn, h, ss, got, warnings) in &results {
        if (got - kn).abs() <= 2.0f64.max(0.2 * kn) {
            held += 1;
            continue;
        }
        println!("{kn} kn, {h} deg, SS{ss}: {got:.1} kn; {warnings:?}");
        assert!(
            warnings.iter().any(|w| w.starts_with("speed order not held")),
            "{kn} kn, {h} deg, SS{ss}: {got:.2} kn and no warning says why: {warnings:?}"
        );
    }
    println!("{held} of {} cells hold their order", results.len());
    assert_eq!(held, results.len(), "{held} of {}", results.len());
}

/// Stopped in sea state 6 with the waves on the beam, for 600 s: the ship drifts and turns as a
/// ship does, without diverging. Measured: yaw rate at most 0.55 deg/s (no clamp exists: the
/// cross-flow drag of its sections damps it), 230 m from where it started, mostly sideways (drift
/// angle 35-90 deg), at about 1 kn: the mean second-order force turns the bow towards the waves
/// and pushes the ship astern, and the speed loop, which reads the speed through the water signed
/// by the surge, drives the shafts ahead (25-50 rpm) against it; it read |U| before and stopped
/// them, and the ship went 2 km astern at up to 15 kn. Asserted: the run completes, the yaw rate
/// under 1 deg/s, the ship 50 to 600 m from where it started (1 kn for 600 s is 310 m).
#[test]
fn stopped_in_a_beam_sea_drifts() {
    let mut s = cell(0.0, 90.0, 6);
    s.sim.duration_s = 600.0;
    let r = run(&s);
    assert!(r.summary.final_time_s >= 600.0 - 1e-9);
    let yaw = r.summary.signals["yaw_rate_deg_s"];
    let (x, y) = (r.summary.signals["x_m"].final_, r.summary.signals["y_m"].final_);
    println!("yaw rate {:.3} .. {:.3} deg/s, ended at ({x:.0}, {y:.0}) m", yaw.min, yaw.max);
    assert!(yaw.max.abs().max(yaw.min.abs()) < 1.0);
    assert!((50.0..600.0).contains(&libm::hypot(x, y)), "moved {} m", libm::hypot(x, y));
}

/// The booklet of turn-360 (25 kn): IMO MSC.137(76)'s criteria met and a destroyer's turning
/// circle. Measured: advance 2.58 L, tactical diameter 2.91 L, steady diameter 2.70 L at 63 % of
/// the approach speed, 10/10 overshoots 3.6 and 3.9 deg, 20/20 9.0 deg. Asserted: every criterion
/// passes, tactical diameter 2.5 to 5 L, advance below it plus a length, and the turn slows the
/// ship to 50-80 % of its speed.
#[test]
fn turn_360_booklet_is_a_destroyers() {
    let b = booklet(&preset("turn-360").unwrap()).unwrap();
    let l = b.length_m;
    for c in &b.criteria {
        assert!(c.pass, "{}: {} against {}", c.name, c.value, c.limit);
    }
    let td = b.turning.tactical_diameter_m / l;
    assert!((2.5..=5.0).contains(&td), "tactical diameter {td} L");
    assert!(b.turning.advance_m / l < td + 1.0);
    assert!((0.5..=0.8).contains(&b.turning.speed_ratio), "{}", b.turning.speed_ratio);
    // The static drift table: the side force grows with drift, against it.
    let y: Vec<f64> = b.static_drift.iter().map(|r| r.y_prime).collect();
    assert!(y[0].abs() < 1e-12 && y.windows(2).all(|w| w[1] < w[0]), "{y:?}");
}

/// The steady turn does not depend on the approach speed much at a fixed rudder (the turning
/// circle of a displacement ship is nearly speed independent): tactical diameters at 12, 18 and
/// 30 kn within 5 % of one another (measured 2.91-2.92 L).
#[test]
fn turning_circle_is_speed_independent() {
    let td: Vec<f64> = [12.0, 18.0, 30.0]
        .iter()
        .map(|&kn| {
            let mut s = preset("turn-360").unwrap();
            s.initial.speed_kn = kn;
            s.commands[0].speed_kn = Some(kn);
            let b = booklet(&s).unwrap();
            b.turning.tactical_diameter_m / b.length_m
        })
        .collect();
    let (lo, hi) = td.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi / lo < 1.05, "{td:?}");
}
