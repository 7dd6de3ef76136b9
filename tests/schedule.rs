//! The turbine schedule (issue 45, core/src/studies/schedule.rs): the exhaustive check of all 15
//! online sets at a few cells, and the frequency-domain reserve against the time domain.

use aes_core::numerics::units::kn_to_m_s;
use aes_core::scenario::presets::preset;
use aes_core::scenario::{Scenario, SeaKind};
use aes_core::signals::Signal;
use aes_core::studies::schedule::{self, chance_in, slow_drift, upcrossing_rate};

/// Up-crossings of `level` in a column.
fn upcrossings(col: &[f64], level: f64) -> usize {
    col.windows(2).filter(|w| w[0] < level && w[1] >= level).count()
}

/// At four cells (a calm cruise, the reserve deciding, sets below their minimum load, the reserve
/// unmet) every one of the 15 online sets is solved on its own, and the schedule's choice is the
/// least fuel among those that keep the reserve; sets of the same count burn the same (the tied
/// buses), to 1e-9.
#[test]
fn all_fifteen_online_sets_agree_with_the_schedule() {
    let sc = preset("startup").unwrap();
    let s = schedule::run(&sc).unwrap();
    for (v, ss) in [(15.0, 3), (21.0, 4), (15.0, 6), (25.0, 6)] {
        let cell = s.cell(v, ss).unwrap();
        let (all, best) = schedule::exhaustive(&sc, v, ss).unwrap();
        assert_eq!(all.len(), 15);
        let (f, b) = (cell.fuel_power_w.unwrap(), best.unwrap());
        assert!((f - b).abs() <= 1e-9 * f, "{v} kn SS{ss}: schedule {f} W, exhaustive {b} W");
        for a in &all {
            let same = cell.options.iter().find(|o| o.count == a.count).unwrap();
            if let (Some(x), Some(y)) = (a.fuel_power_w, same.fuel_power_w) {
                assert!((x - y).abs() <= 1e-9 * y, "{v} kn SS{ss}: sets {} {x} W against {} {y} W", a.sets, same.sets);
            }
        }
    }
    // 15 kn in SS3: one set (37 % less fuel than four); SS6: the reserve needs two.
    assert_eq!(s.cell(15.0, 3).unwrap().count, Some(1));
    assert_eq!(s.cell(15.0, 6).unwrap().count, Some(2));
}

/// The run of the check: head seas, long-crested, at `speed_kn` in sea state `ss` with the
/// thesis' hub depth, `duration_s` long.
fn head_seas(speed_kn: f64, ss: u32, duration_s: f64) -> Scenario {
    let mut sc = preset("head-seas-ss6").unwrap();
    sc.set_hub_depth_m(6.0);
    sc.sea.kind = SeaKind::Random;
    sc.sea.sea_state = ss;
    sc.sea.spreading = 0.0;
    sc.initial.speed_kn = speed_kn;
    sc.commands[0].speed_kn = Some(speed_kn);
    sc.sim.duration_s = duration_s;
    sc
}

/// The fast estimate against the time domain at two cells (15 kn in SS5 and SS6, 1200 s each):
/// the run's slowly varying added resistance has the predicted mean and crosses twice its mean
/// about as often as Rice's rate for Newman's force says, and the turbines' power crosses the
/// level the quasi-static estimate gives for that force no more often than predicted (the
/// estimate is an upper bound: the ship's mass and the speed loop filter the slow force).
#[test]
fn the_reserve_estimate_against_the_time_domain() {
    for ss in [5, 6] {
        let sc = head_seas(15.0, ss, 1200.0);
        let r = aes_core::sim::run(&sc).unwrap();
        let table = sc.rao_table().unwrap();
        let d = slow_drift(&sc, &table, kn_to_m_s(15.0), ss);
        let t = r.trace.get(Signal::TS);
        let from = t.partition_point(|&x| x < 60.0);
        let span = t[t.len() - 1] - t[from];
        let f = &r.trace.get(Signal::AddedResistanceN)[from..];
        let mean = f.iter().sum::<f64>() / f.len() as f64;
        let level = 2.0 * d.mean_n;
        let n_f = upcrossings(f, level);
        let expect = upcrossing_rate(&d, level) * span;
        let p = &r.trace.get(Signal::PTurbineW)[from..];
        let p_mean = p.iter().sum::<f64>() / p.len() as f64;
        let four = schedule::evaluate(&sc, &[1, 2, 3, 4], 15.0, &d);
        let (p_fast, c) = (four.turbine_power_w.unwrap(), four.sensitivity_w_per_n.unwrap());
        let mut n_p = Vec::new();
        for x in [2.0, 3.0] {
            let level_p = p_fast + c * (x - 1.0) * d.mean_n;
            n_p.push((upcrossings(p, level_p), upcrossing_rate(&d, x * d.mean_n) * span));
        }
        println!(
            "SS{ss}: mean force {mean:.0} N (predicted {:.0}), crossings of {level:.0} N: {n_f} (predicted {expect:.1}); \
             mean power {p_mean:.0} W (predicted {p_fast:.0}), crossings of the power at 2 and 3 times the mean force \
             (time domain, predicted): {n_p:?}",
            d.mean_n
        );
        assert!((mean / d.mean_n - 1.0).abs() < 0.1, "SS{ss}: mean force {mean} against {}", d.mean_n);
        assert!((n_f as f64 - expect).abs() <= 3.0 * expect.sqrt() + 1.0, "SS{ss}: {n_f} crossings against {expect}");
        assert!((p_mean / p_fast - 1.0).abs() < 0.05, "SS{ss}: mean power {p_mean} against {p_fast}");
        for (n, e) in n_p {
            assert!(n as f64 <= e + 3.0 * e.sqrt() + 1.0, "SS{ss}: power crossings {n} above the bound {e}");
        }
    }
    // The chance in a window from the rate.
    assert!((chance_in(1.0 / 3600.0, 3600.0) - (1.0 - libm::exp(-1.0))).abs() < 1e-15);
}

/// A run at a schedule cell with the schedule's set: 15 kn in SS6 head seas on two sets (sets 1
/// and 3, one per shaft's bus, the buses tied) for 1200 s holds its speed, and its turbines stay
/// below the two sets' rating (measured peak 0.245 of it) with no overload warning, as the reserve
/// predicts (a chance below 1e-3 per hour).
#[test]
fn a_schedule_cell_run_in_the_time_domain() {
    let sc0 = preset("startup").unwrap();
    let s = schedule::run(&sc0).unwrap();
    let cell = s.cell(15.0, 6).unwrap();
    let n = cell.count.unwrap();
    let mut sc = head_seas(15.0, 6, 1200.0);
    sc.plant.online.sets = if n == 2 { vec![1, 3] } else { (1..=n as u32).collect() };
    let r = aes_core::sim::run(&sc).unwrap();
    let p = r.trace.get(Signal::PTurbineW);
    let top = p.iter().copied().fold(0.0, f64::max) / (n as f64 * sc.plant.turbine.rated_power_w);
    let speed = r.summary.signals["ship_speed_kn"].mean;
    println!(
        "{n} sets at 15 kn SS6: peak power {top:.3} of their rating, mean speed {speed:.2} kn, warnings {:?}",
        r.summary.warnings
    );
    assert!(top < 1.0, "peak {top}");
    assert!((speed - 15.0).abs() < 0.5, "mean speed {speed}");
    assert!(!r.summary.warnings.iter().any(|w| w.contains("overloaded")), "{:?}", r.summary.warnings);
}
