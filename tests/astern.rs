//! Astern orders and the crash stop (issue 56, thesis ch. 5.2.2): the shafts go through zero to
//! astern within the motors' limits, the ship stops dead in the water and goes astern, the
//! energy books close through the reversal, an astern order is held, and storage sized to the
//! brake energy takes it instead of the resistors.

use aes_core::numerics::units::kn_to_m_s;
use aes_core::scenario::presets::preset;
use aes_core::scenario::{Command, Scenario, SeaKind};
use aes_core::sim::health::{bus_high_pu, BUS_LOW_PU};
use aes_core::sim::{run, RunResult};

fn col<'a>(r: &'a RunResult, name: &str) -> &'a [f64] {
    r.trace.column(name).unwrap()
}

/// The way ahead of each recorded row [m/s]: the displacement to the next row along the heading
/// over the recording interval.
fn way_ahead(r: &RunResult) -> Vec<f64> {
    let (t, x, y, psi) = (col(r, "t_s"), col(r, "x_m"), col(r, "y_m"), col(r, "heading_deg"));
    (0..t.len() - 1)
        .map(|i| {
            let h = psi[i].to_radians();
            ((x[i + 1] - x[i]) * libm::cos(h) + (y[i + 1] - y[i]) * libm::sin(h)) / (t[i + 1] - t[i])
        })
        .collect()
}

fn order(t_s: f64, speed_kn: Option<f64>, crash_stop: bool) -> Command {
    Command { t_s, speed_kn, heading_deg: None, heading_rate_deg_s: None, online_sets: None, crash_stop }
}

/// The crash-stop preset started at `kn`.
fn crash_stop_from(kn: f64) -> Scenario {
    let mut s = preset("crash-stop").unwrap();
    s.initial.speed_kn = kn;
    s.commands[0].speed_kn = Some(kn);
    s
}

/// Every recorded value finite (no NaN reached the trace).
fn all_finite(r: &RunResult) -> bool {
    r.trace.to_csv().split([',', '\n']).all(|v| !v.contains("NaN") && !v.contains("inf"))
}

/// A crash stop from 25 kn and from 30 kn: the shafts reverse, the ship is dead in the water within
/// 400 s and then goes astern (its way at the end below -2 m/s), nothing diverges or turns NaN, and
/// the energy books close to 1e-9 of the turbines' work, as a maneuvering run ahead does
/// (tests/maneuvering.rs).
#[test]
fn crash_stop_from_25_and_30_knots_stops_and_goes_astern() {
    for kn in [25.0, 30.0] {
        let r = run(&crash_stop_from(kn)).unwrap();
        assert!(all_finite(&r), "{kn} kn: a value is not finite");
        let t = col(&r, "t_s");
        let ahead = way_ahead(&r);
        let stop = ahead.iter().position(|&u| u <= 0.0).expect("dead in the water");
        let rpm = col(&r, "prop_rpm");
        let lowest_rpm = rpm.iter().copied().fold(f64::INFINITY, f64::min);
        let e = &r.summary.energy_j;
        eprintln!(
            "{kn} kn: dead in the water at t = {:.1} s, way at the end {:.2} m/s, lowest shaft {lowest_rpm:.0} rpm, \
             brake {:.1} MJ, regenerated {:.1} MJ, residual {:e}, warnings {:?}",
            t[stop],
            ahead[ahead.len() - 1],
            e.brake / 1e6,
            e.regenerated / 1e6,
            e.relative_residual,
            r.summary.warnings
        );
        assert!(lowest_rpm < -50.0, "{kn} kn: the shafts did not reverse ({lowest_rpm} rpm)");
        assert!(t[stop] < 400.0, "{kn} kn: still going ahead at {}", t[stop]);
        assert!(ahead[ahead.len() - 1] < -2.0, "{kn} kn: not astern at the end: {}", ahead[ahead.len() - 1]);
        assert!(e.brake > 0.0 && e.regenerated > 0.0, "{e:?}");
        assert!(e.relative_residual.abs() < 1e-9, "{kn} kn: {e:?}");
        // From 30 kn the returned power lifts the turbines past their trip (measured 1.109 pu),
        // and the warnings say it was the stop's braking.
        if kn == 30.0 {
            assert!(r.summary.warnings.iter().any(|w| w.starts_with("during the astern order from t = 10.0 s")));
        }
    }
}

/// An astern order from rest reaches its speed and holds it within max(1 kn, 20 %) over the last
/// minute, in calm water and in sea state 4 from ahead.
#[test]
fn an_astern_order_is_held_in_calm_water_and_in_head_seas() {
    for (sea_state, order_kn) in [(0, -10.0), (4, -10.0), (0, -15.0)] {
        let mut s = preset("crash-stop").unwrap();
        s.initial.speed_kn = 0.0;
        s.commands = vec![order(0.0, Some(order_kn), false)];
        s.sim.duration_s = 400.0;
        if sea_state > 0 {
            s.sea.kind = SeaKind::Random;
            s.sea.sea_state = sea_state;
            s.sim.seed = 1;
            s.stepping.dt_s = 0.005;
            s.stepping.integrator = aes_core::numerics::Integrator::Midpoint;
        }
        let r = run(&s).unwrap();
        assert!(all_finite(&r));
        let ahead = way_ahead(&r);
        let t = col(&r, "t_s");
        let from = t.partition_point(|&x| x < t[t.len() - 1] - 60.0);
        let mean = ahead[from..].iter().sum::<f64>() / (ahead.len() - from) as f64;
        let want = kn_to_m_s(order_kn);
        let band = kn_to_m_s(1.0).max(0.2 * want.abs());
        eprintln!(
            "SS{sea_state}, {order_kn} kn: mean way over the last minute {:.2} kn, heading at the end {:.1} deg, \
             warnings {:?}",
            mean / kn_to_m_s(1.0),
            col(&r, "heading_deg")[t.len() - 1],
            r.summary.warnings
        );
        assert!((mean - want).abs() <= band, "SS{sea_state}: {mean} m/s against {want}");
    }
}

/// With a storage sized to the brake energy on each bus the resistors burn less and the bus stays
/// within its band (the top of the chopper's band) through the stop.
#[test]
fn storage_takes_the_crash_stops_energy() {
    let without = run(&preset("crash-stop").unwrap()).unwrap();
    let sc = preset("crash-stop-storage").unwrap();
    let with = run(&sc).unwrap();
    let top = |r: &RunResult| col(r, "bus_voltage_pu").iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (b0, b1) = (without.summary.energy_j.brake, with.summary.energy_j.brake);
    eprintln!(
        "brake {:.1} -> {:.1} MJ, storage took {:.1} MJ, top of the bus {:.3} -> {:.3} pu (band to {:.3}), \
         residual {:e}",
        b0 / 1e6,
        b1 / 1e6,
        -with.summary.energy_j.storage_to_bus / 1e6,
        top(&without),
        top(&with),
        bus_high_pu(&sc),
        with.summary.energy_j.relative_residual
    );
    assert!(b1 < 0.5 * b0, "brake energy {b0} -> {b1}");
    assert!(top(&with) <= bus_high_pu(&sc), "bus {}", top(&with));
    assert!(with.summary.energy_j.relative_residual.abs() < 1e-9);
}

/// Storage of any size from 50 to 200 MJ a bus keeps the bus inside its band, the bottom too,
/// through the crash stop: the storage carries part of the rising astern load and reaches its
/// floor, and hands that power back at a quarter of what the turbines' fuel schedule can take up
/// (`plant::storage::HANDOVER_SHARE`). With the 1 s taper alone the bus fell to 0.751 pu at
/// 150 MJ and 0.694 pu at 200 MJ; now its lowest is 0.918-0.929 pu (measured), asserted at the
/// band's 0.9 pu.
#[test]
fn storage_of_any_size_keeps_the_bus_in_its_band() {
    for energy_j in [50e6, 100e6, 150e6, 200e6] {
        let mut sc = preset("crash-stop-storage").unwrap();
        sc.plant.storage.energy_j = energy_j;
        let r = run(&sc).unwrap();
        let v = col(&r, "bus_voltage_pu");
        let (lo, hi) = v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
        let floor = col(&r, "storage_soc").iter().copied().fold(f64::INFINITY, f64::min);
        eprintln!("{:.0} MJ: bus {lo:.3} to {hi:.3} pu, lowest charge {floor:.3}", energy_j / 1e6);
        assert!(lo >= BUS_LOW_PU && hi <= bus_high_pu(&sc), "{energy_j} J: bus {lo} to {hi} pu");
        assert!(r.summary.warnings.is_empty(), "{energy_j} J: {:?}", r.summary.warnings);
    }
}

/// Astern orders are refused, naming the field, where the model cannot go astern: the B-series
/// propeller and a drive that may not brake.
#[test]
fn astern_orders_need_a_four_quadrant_propeller_and_braking() {
    let mut s = preset("turn-360").unwrap();
    s.commands.push(order(20.0, Some(-5.0), false));
    let e = s.validate().unwrap_err().to_string();
    assert!(e.contains("commands.2.speed_kn") && e.contains("four_quadrant") && e.contains("allow_braking"), "{e}");
    let mut c = preset("turn-360").unwrap();
    c.commands.push(order(20.0, None, true));
    let e = c.validate().unwrap_err().to_string();
    assert!(e.contains("commands.2.crash_stop"), "{e}");
    let mut too_fast = preset("crash-stop").unwrap();
    too_fast.commands[1] = order(10.0, Some(-16.0), false);
    let e = too_fast.validate().unwrap_err().to_string();
    assert!(e.contains("commands.1.speed_kn") && e.contains("-15"), "{e}");
}

/// The astern limit (commands' -15 kn) lies well within what the motors' rated power reaches
/// astern: on the calm-water map a shaft takes 4.1 MW at -15 kn, and the rating is reached at
/// 31.6 kn astern on eq. 2.15's mirrored resistance (asserted 28 to 35 kn), which is why the limit
/// is a choice about the hull model's astern validity, not the motors' (scenario::ASTERN_LIMIT_KN).
#[test]
fn the_astern_limit_is_within_the_motors_power() {
    use aes_core::sim::plant::Plant;
    let sc = preset("crash-stop").unwrap();
    let p = Plant::new(&sc).unwrap();
    let shaft_power = |kn: f64| {
        let u = kn_to_m_s(kn);
        let w = p.equilibrium_shaft_speed_astern(u);
        p.propeller_load(w, u).torque_nm * w
    };
    let rated = sc.plant.motor.rated_power_w;
    let limit = aes_core::scenario::ASTERN_LIMIT_KN;
    assert!(shaft_power(limit) < rated, "{} W at {limit} kn", shaft_power(limit));
    let reach = aes_core::numerics::bisect(|kn| shaft_power(kn) - rated, -40.0, 0.0, 60);
    eprintln!("astern: {:.1} MW a shaft at {limit} kn; rated power reached at {reach:.1} kn", shaft_power(limit) / 1e6);
    assert!((-35.0..=-28.0).contains(&reach), "{reach}");
}

/// The booklet of turn-360 has the full-astern stopping test with IMO's verdict (measured from
/// 25 kn: track reach 326 m, 2.29 L, head reach the same, no lateral deviation on the symmetric
/// twin-screw ship, dead in the water 48 s after the order), and the bare hull's static drift
/// beside Clarke's regression: its linear side force is Clarke's Y'_v (the hull's own model takes
/// it), so at 2 deg the bare hull's slope is Clarke's plus the cross-flow drag's start (measured
/// 1.14 times; asserted 1.0 to 1.3) and the rudders add more (measured 1.33 times).
#[test]
fn the_booklet_has_the_stopping_test_and_the_bare_hull() {
    let b = aes_core::studies::maneuvers::booklet(&preset("turn-360").unwrap()).unwrap();
    let st = b.stopping.as_ref().expect("the stopping test ran");
    eprintln!(
        "track reach {:.0} m ({:.2} L), head reach {:.0} m, lateral {:.1} m, {:.0} s, bus {:.3} pu, brake {:.0} MJ, \
         regenerated peak {:.1} MW; adjustments {:?}",
        st.track_reach_m,
        st.track_reach_l,
        st.head_reach_m,
        st.lateral_deviation_m,
        st.time_to_dead_s,
        st.peak_bus_voltage_pu,
        st.brake_energy_j / 1e6,
        st.peak_regenerated_w / 1e6,
        st.adjustments
    );
    assert!(st.track_reach_l > 1.0 && st.track_reach_l < 15.0 && st.imo_pass, "{}", st.track_reach_l);
    assert!(st.head_reach_m <= st.track_reach_m + 1e-9 && st.time_to_dead_s > 20.0);
    assert!(st.brake_energy_j > 0.0 && st.peak_regenerated_w > 0.0 && st.peak_bus_voltage_pu > 1.0);
    let c = b.criteria.iter().find(|c| c.name.starts_with("stopping ability")).expect("IMO's stopping criterion");
    assert!(c.pass && c.limit == 15.0 && c.value == st.track_reach_l);
    let bare = b.bare_drift.as_ref().expect("the hull's own forces give the bare hull");
    let (rb, ra) =
        (bare.slope_bare_per_rad / bare.slope_clarke_per_rad, bare.slope_appended_per_rad / bare.slope_clarke_per_rad);
    eprintln!("bare {rb:.3}, appended {ra:.3} times Clarke's {:.3}", bare.slope_clarke_per_rad);
    assert!((1.0..=1.3).contains(&rb) && ra > rb, "{rb} {ra}");
}
