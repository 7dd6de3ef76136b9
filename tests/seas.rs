//! Thesis ch. 5.2.4 and 5.3: the ship in random and regular seas, the propeller's surface losses,
//! and the coupling into the drive train. Figures are printed for the notes (`--nocapture`).

use aes_core::scenario::presets::preset;
use aes_core::scenario::{SeaKind, SternMotion};
use aes_core::{RunResult, Scenario};
use aes_tests::run;

fn col<'a>(r: &'a RunResult, name: &str) -> &'a [f64] {
    r.trace.column(name).unwrap_or_else(|| panic!("no column {name}"))
}
fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}
fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
}
fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}
fn std(v: &[f64]) -> f64 {
    let m = mean(v);
    (v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / v.len() as f64).sqrt()
}

fn head_seas(seed: u64, stern: SternMotion, duration: f64) -> Scenario {
    let mut s = preset("head-seas-ss6").unwrap();
    // The thesis' depth (the preset's default is a light loading with a shallower hub).
    s.set_hub_depth_m(6.0);
    s.sim.seed = seed;
    s.seakeeping.stern_motion = stern;
    s.sim.duration_s = duration;
    s
}

/// A row's h/R is its hub depth over the radius at the row's time, on both shafts, so that the
/// page never draws the disc out of the water under a label h/R >= 1. (The loss model reads the
/// step's midpoint, half a step earlier: up to 0.004 in h/R apart at 25 kn in SS6.) Tolerance:
/// 4 ulp of the quotient.
#[test]
fn a_rows_h_over_r_is_its_hub_depth_over_the_radius() {
    // The preset's light loading: its hub goes out of the water.
    let s = preset("head-seas-ss6").unwrap();
    let radius = 0.5 * s.propeller.diameter_m;
    let r = run(&s);
    for (hr, hub) in [("h_over_r", "hub_depth_m"), ("h_over_r_stbd", "hub_depth_stbd_m")] {
        let (a, b) = (col(&r, hr), col(&r, hub));
        assert!(min(a) < 1.0, "{hr}: the run does not reach h/R < 1 (min {})", min(a));
        for (i, (x, h)) in a.iter().zip(b).enumerate() {
            let want = h / radius;
            assert!((x - want).abs() <= 4.0 * f64::EPSILON * want.abs().max(1.0), "{hr} row {i}: {x} against {want}");
        }
    }
}

/// Same scenario and seed: bit-identical traces; another seed: another sea.
#[test]
fn same_seed_same_trace() {
    let a = run(&head_seas(3, SternMotion::Consistent, 20.0));
    let b = run(&head_seas(3, SternMotion::Consistent, 20.0));
    assert_eq!(a.trace, b.trace);
    let c = run(&head_seas(4, SternMotion::Consistent, 20.0));
    assert_ne!(col(&a, "h_over_r"), col(&c, "h_over_r"));
}

/// Multi-rate stepping (wave sums every 50 ms, carried between samples by their Taylor series;
/// RAOs looked up every 0.25 s) against summing and looking up at every 2.5 ms step: h/R within
/// 0.01, propeller speed within 0.5 rpm, motor power within 1 % of rated, in a run with
/// ventilation events (eq. 2.57 as printed, so that the losses switch).
#[test]
fn multi_rate_matches_single_rate() {
    let multi = head_seas(2, SternMotion::ThesisEq257, 40.0);
    let mut single = multi.clone();
    single.stepping.sea_sample_s = single.stepping.dt_s;
    single.seakeeping.rao_refresh_s = single.stepping.dt_s;
    single.seakeeping.rao_refresh_speed_m_s = 0.0;
    single.seakeeping.rao_refresh_heading_deg = 0.0;
    let (a, b) = (run(&multi), run(&single));
    let diff = |n: &str| col(&a, n).iter().zip(col(&b, n)).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    let vent = col(&a, "beta_t").iter().filter(|&&b| b < 0.99).count();
    println!(
        "multi vs single rate: h/R {:.2e}, rpm {:.3}, motor power {:.4} pu; {} of {} rows with losses",
        diff("h_over_r"),
        diff("prop_rpm"),
        diff("im_power_pu"),
        vent,
        a.trace.len()
    );
    assert!(vent > 10, "the comparison needs surface losses to happen");
    assert!(diff("h_over_r") < 0.01 && diff("prop_rpm") < 0.5 && diff("im_power_pu") < 0.01);
}

/// Physics of eq. 2.57: in long regular head waves a hull follows the surface, so the hub keeps
/// its depth (the wave at the stern and the stern's own motion cancel, within 10 % of the wave
/// amplitude); eq. 2.57 as printed adds the pitch instead and the hub swings ten times as much.
/// The stern wave itself has the ordered 1 m amplitude within 1e-5 m (measured 6.7e-7).
#[test]
fn long_waves_leave_the_hub_depth_alone() {
    let mut swings = Vec::new();
    for stern in [SternMotion::Consistent, SternMotion::ThesisEq257] {
        let mut s = preset("fuel-regular-seas").unwrap();
        s.sea.kind = SeaKind::Regular;
        s.sea.amplitude_m = 1.0;
        s.sea.omega_rad_s = 0.25; // lambda = 986 m, 7 ship lengths
        s.seakeeping.stern_motion = stern;
        s.sim.duration_s = 60.0;
        let r = run(&s);
        let h = col(&r, "hub_depth_m");
        let wave = col(&r, "wave_stern_m");
        let swing = 0.5 * (max(h) - min(h));
        println!("{stern:?}: hub depth swing {swing:.3} m, stern wave {:.3} m", 0.5 * (max(wave) - min(wave)));
        assert!((0.5 * (max(wave) - min(wave)) - 1.0).abs() < 1e-5);
        swings.push(swing);
    }
    assert!(swings[0] < 0.1 && swings[1] > 10.0 * swings[0], "{swings:?}");
}

/// Ch. 5.3.1, head seas SS6 at 25 knots, 80 s, five seeds. With the consistent hub depth the
/// stern's relative motion is smaller than the wave at the stern (the ship follows the long waves
/// of SS6) and h/R stays above the ventilation onset at h0 = 6 m; with eq. 2.57 as printed the
/// thesis' picture returns: ventilation in most runs, occasional emergence, a propeller speed swing
/// of tens of rpm (thesis: 50) and a motor power swing of tens of percent (thesis: 25 %).
#[test]
fn head_seas_ss6_over_seeds() {
    let calm = {
        let mut s = head_seas(1, SternMotion::Consistent, 30.0);
        s.sea.kind = SeaKind::Calm;
        let r = run(&s);
        *col(&r, "im_power_pu").last().unwrap()
    };
    let mut vent_runs = 0;
    for seed in 1..=5 {
        for stern in [SternMotion::Consistent, SternMotion::ThesisEq257] {
            let r = run(&head_seas(seed, stern, 80.0));
            let (h, rpm, p, wave) =
                (col(&r, "h_over_r"), col(&r, "prop_rpm"), col(&r, "im_power_pu"), col(&r, "wave_stern_m"));
            let rel: Vec<f64> = col(&r, "hub_depth_m").iter().map(|d| d - 6.0).collect();
            let losses = col(&r, "beta_t").iter().filter(|&&b| b < 0.99).count() as f64 / h.len() as f64;
            println!(
                "seed {seed} {stern:?}: h/R {:.2}..{:.2}, losses {:.0} % of the time, rpm swing {:.0}, power {:.2}..{:.2} of \
                 calm ({:.0} % swing), relative motion std {:.2} m vs stern wave {:.2} m, energy residual {:.1e}",
                min(h),
                max(h),
                100.0 * losses,
                max(rpm) - min(rpm),
                min(p) / calm,
                max(p) / calm,
                100.0 * (max(p) - min(p)) / calm,
                std(&rel),
                std(wave),
                r.summary.energy_j.relative_residual
            );
            match stern {
                SternMotion::Consistent => {
                    assert!(std(&rel) < std(wave));
                    assert!(min(h) > 1.3, "seed {seed}: h/R {}", min(h));
                }
                SternMotion::ThesisEq257 => {
                    vent_runs += usize::from(losses > 0.0);
                    assert!((15.0..=100.0).contains(&(max(rpm) - min(rpm))), "rpm swing {}", max(rpm) - min(rpm));
                }
            }
            // The books close to the step's error: the side force's and yaw moment's work in sway
            // and yaw is booked with the ship's (measured 8.7e-11 to 1.6e-7 over these ten runs,
            // printed above, the larger with eq. 2.57 as printed; before that booking -2.4e-6 to
            // -5.8e-5, the sway and yaw work that no account held).
            assert!(
                r.summary.energy_j.relative_residual.abs() < 3e-7,
                "energy residual {}",
                r.summary.energy_j.relative_residual
            );
        }
    }
    assert!(vent_runs >= 4, "{vent_runs} of 5 runs ventilated with eq. 2.57 as printed");
}

/// Ch. 5.3.2: the full turn in SS6 starting in head seas. The thesis: "in following seas at 25
/// knots, the ship is excited very little in heave and pitch", and head seas threaten the
/// propeller most. Heave and pitch: standard deviations in following seas under 0.7 of those in
/// head seas. h/R: with eq. 2.57 as printed the head-seas swings are 1.3 times the following-seas
/// ones or more; with the consistent hub depth they come out alike (printed, not asserted: in
/// following seas the encounter frequency is low, the hull no longer rides the short waves and
/// the stern's relative motion is the short waves' own height).
#[test]
fn turn_360_in_ss6() {
    for stern in [SternMotion::Consistent, SternMotion::ThesisEq257] {
        let mut s = preset("turn-360-ss6").unwrap();
        s.seakeeping.stern_motion = stern;
        let r = run(&s);
        let hd = col(&r, "heading_deg");
        let pick = |name: &str, centre: f64| -> Vec<f64> {
            hd.iter()
                .zip(col(&r, name))
                .filter(|(d, _)| !(45.0..=315.0).contains(&(*d - centre).rem_euclid(360.0)))
                .map(|(_, v)| *v)
                .collect()
        };
        let ratio = |name: &str| std(&pick(name, 180.0)) / std(&pick(name, 0.0));
        let p = col(&r, "im_power_pu");
        println!(
            "turn in SS6, {stern:?}: following/head std ratios heave {:.2}, pitch {:.2}, h/R {:.2}; motor power {:.2}..{:.2} pu (straight {:.2}), propeller {:.0}..{:.0} rpm",
            ratio("heave_m"),
            ratio("pitch_deg"),
            ratio("h_over_r"),
            min(p),
            max(p),
            mean(&p[..100]),
            min(col(&r, "prop_rpm")),
            max(col(&r, "prop_rpm"))
        );
        assert!(pick("heave_m", 180.0).len() > 100 && pick("heave_m", 0.0).len() > 100);
        assert!(ratio("heave_m") < 0.7 && ratio("pitch_deg") < 0.7);
        if stern == SternMotion::ThesisEq257 {
            assert!(ratio("h_over_r") < 1.0 / 1.3);
        }
    }
}

/// Ch. 5.2.4, Fig. 5-11: a quarter turn in SS3 and SS6. Added resistance grows with the sea
/// (SS6 over five times SS3 before the turn); once the sea is on the port beam the drift force
/// pushes to starboard.
#[test]
fn quarter_turns_show_added_resistance_and_drift() {
    let r3 = run(&preset("quarter-turn-ss3").unwrap());
    let r6 = run(&preset("quarter-turn-ss6").unwrap());
    let before = |r: &RunResult, n: &str| mean(&col(r, n)[..200]);
    let after = |r: &RunResult, n: &str| {
        let c = col(r, n);
        mean(&c[c.len() - 1000..])
    };
    println!(
        "added resistance before the turn: SS3 {:.0} kN, SS6 {:.0} kN; drift force after: SS3 {:.0} kN, SS6 {:.0} kN; \
         speed after: SS3 {:.2} kn, SS6 {:.2} kn",
        before(&r3, "added_resistance_n") / 1e3,
        before(&r6, "added_resistance_n") / 1e3,
        after(&r3, "drift_force_n") / 1e3,
        after(&r6, "drift_force_n") / 1e3,
        after(&r3, "ship_speed_kn"),
        after(&r6, "ship_speed_kn")
    );
    assert!(before(&r6, "added_resistance_n") > 5.0 * before(&r3, "added_resistance_n"));
    assert!(before(&r3, "added_resistance_n") > 0.0);
    assert!(after(&r6, "drift_force_n") > 0.0 && after(&r3, "drift_force_n") > 0.0);
}

/// Ch. 5.2.4, Fig. 5-12: fuel power of one prime mover rises with wave amplitude, most where the
/// added resistance peaks; head seas cost more than bow seas there.
#[test]
fn fuel_in_regular_seas() {
    let sc = preset("fuel-regular-seas").unwrap();
    let rows = aes_core::studies::fuel::run(&sc, &[0.6]).unwrap();
    let head: Vec<f64> = rows.iter().filter(|r| r.heading == "head").map(|r| r.fuel_power_w).collect();
    let bow: Vec<f64> = rows.iter().filter(|r| r.heading == "bow").map(|r| r.fuel_power_w).collect();
    println!("fuel power at 0.6 rad/s, 1-5 ft: head {head:?}, bow {bow:?}");
    assert!(head.windows(2).all(|w| w[1] > w[0]) && bow.windows(2).all(|w| w[1] > w[0]));
    assert!(head[4] > bow[4]);
    assert_eq!(rows.len(), 10);
}

/// The RAO table handed from one web worker to another (`RaoTable::values`, `from_values`)
/// interpolates to the same bits as the table it came from; a wrong length is refused.
#[test]
fn rao_table_values_round_trip() {
    use aes_core::sea::seakeeping::tables::{RaoTable, SeakeepingGrid};
    let grid = SeakeepingGrid::default();
    let t = aes_core::Scenario::default().rao_table().unwrap();
    let v = t.values();
    let back = RaoTable::from_values(&grid, &v).unwrap();
    assert_eq!(back.values(), v);
    for &(w, u, b) in &[(0.4, 12.86, 3.1), (0.9, 5.0, 1.0), (1.7, 15.0, 4.0)] {
        assert_eq!(format!("{:?}", back.interpolate(w, u, b)), format!("{:?}", t.interpolate(w, u, b)));
    }
    assert!(RaoTable::from_values(&grid, &v[1..]).is_err());
}
