//! Thesis ch. 2.4 and 5.2: the Abkowitz maneuvering model (Table 2.3's hull forces) and the routine
//! maneuvering studies (acceleration, AC braking, heading changes). Figures are printed with `--nocapture`.

use aes_core::numerics::units::kn_to_m_s;

/// A preset with the thesis' hull forces (Table 2.3), which these tests check.
fn preset(name: &str) -> Option<aes_core::Scenario> {
    let mut s = aes_core::scenario::presets::preset(name)?;
    s.hull.forces = aes_core::ship::maneuvering::ManeuveringForces::Table23;
    Some(s)
}
use aes_core::ship::maneuvering::{Abkowitz, AbkowitzCoefficients};
use aes_tests::{final_value, run};

fn column<'a>(r: &'a aes_core::RunResult, name: &str) -> &'a [f64] {
    r.trace.column(name).unwrap_or_else(|| panic!("no column {name}"))
}

/// Straight ahead at u0 = 22 knots the propellers' thrust balances X0 q = 1.383 MN (Table 2.3,
/// prime system with L = 180 m): the steady state found on load holds for 60 s (the speed unchanged
/// to 1e-9 kn; measured exactly) and its thrust is -X0 (1/2) rho L^2 u0^2 within 1e-12 (measured
/// 3.4e-15).
#[test]
fn straight_ahead_equilibrium_balances_x0() {
    let mut s = preset("turn-45").unwrap();
    // Eq. 2.22's own straight-line polynomial is the thesis' ship's (Table 5.5, L = 180 m).
    s.as_printed.table_5_ship = true;
    s.initial.speed_kn = 22.0;
    s.commands = vec![aes_core::scenario::Command {
        t_s: 0.0,
        speed_kn: Some(22.0),
        heading_deg: None,
        heading_rate_deg_s: None,
        online_sets: None,
        crash_stop: false,
    }];
    s.sim.duration_s = 60.0;
    let r = run(&s);
    let u0 = kn_to_m_s(22.0);
    let x0 = 65.01e-5 * 0.5 * 1025.0 * 180.0 * 180.0 * u0 * u0;
    let thrust = final_value(&r, "thrust_kn") * 1e3;
    println!("thrust {thrust:.0} N, -X0 q = {x0:.0} N, {:.1} rpm", final_value(&r, "prop_rpm"));
    assert!((thrust - x0).abs() < 1e-12 * x0, "thrust {thrust} vs {x0}");
    let kn = r.summary.signals["ship_speed_kn"];
    assert!(kn.max - kn.min < 1e-9, "speed wandered {} .. {}", kn.min, kn.max);
    // And the model's surge mass is Table 2.3's (m - X_udot).
    let a = Abkowitz::new(&AbkowitzCoefficients::default(), true, u0, 180.0, 1025.0);
    assert!((a.m11 / (646.9e-5 * 0.5 * 1025.0 * (180.0 * 180.0 * 180.0)) - 1.0).abs() < 1e-12);
}

/// Ch. 5.2.1, Figs. 5-3 to 5-5: a step order from 25 knots to full ahead. The thesis: the turbines
/// lose about 20 % of their speed and stay away from rated speed for about 20 s with the baseline
/// field gains; the bus voltage follows the turbine speed, a little better with the higher gains.
///
/// Ours (slew limit 0.1 /s): the turbines dip to about 0.84 pu and are back within 1 % in about 8 s.
/// The depth and length of the dip are set by the governor's slew limit, which the thesis does not
/// give (0.05 /s gives a 24 % dip for 10 s, 0.025 /s 30 % for 20 s). Tested: a dip between 5 % and
/// 40 %, recovery within 1 % by 60 s after the order, the bus sagging with the turbines, and the
/// higher field gains holding the bus closer to 1 pu afterwards.
#[test]
fn acceleration_dips_the_turbines_and_the_bus() {
    let mut bus_after = Vec::new();
    for name in ["acceleration", "acceleration-high-gains"] {
        let r = run(&preset(name).unwrap());
        let t = column(&r, "t_s");
        let n = column(&r, "turbine_speed_pu");
        let v = column(&r, "bus_voltage_pu");
        let n_min = n.iter().copied().fold(f64::INFINITY, f64::min);
        let v_min = v.iter().copied().fold(f64::INFINITY, f64::min);
        let last_off = t.iter().zip(n).filter(|(_, &x)| (x - 1.0).abs() > 0.01).map(|(&t, _)| t).fold(0.0, f64::max);
        let mean_bus_after: f64 = {
            let sel: Vec<f64> = t.iter().zip(v).filter(|(&t, _)| t > 30.0).map(|(_, &x)| x).collect();
            sel.iter().sum::<f64>() / sel.len() as f64
        };
        let rpm_max = r.summary.signals["prop_rpm"].max;
        println!(
            "{name}: turbine min {n_min:.3} pu, off rated by >1 % until t = {last_off:.1} s; bus min {v_min:.3} pu, \
             mean after 30 s {mean_bus_after:.4}; propeller up to {rpm_max:.0} rpm; final {:.2} kn",
            final_value(&r, "ship_speed_kn")
        );
        assert!(n_min > 0.6 && n_min < 0.95, "turbine dip {n_min}");
        assert!(last_off < 70.0, "turbines still off rated at {last_off} s");
        assert!(v_min < n_min, "the bus sags at least as much as the turbine speed");
        // The slip limit holds the motors at their rating to the 5 ms sample (measured 1.55e-5 over).
        assert!(r.summary.signals["im_power_pu"].max <= 1.0 + 2e-5);
        bus_after.push(mean_bus_after);
    }
    assert!(
        (bus_after[1] - 1.0).abs() < (bus_after[0] - 1.0).abs(),
        "higher gains should hold the bus closer: {bus_after:?}"
    );
}

/// Ch. 5.2.2, Figs. 5-6 and 5-7: AC braking with a brake resistor. The ship's kinetic energy comes
/// back through the propellers and motors; the books (turbine work, ship work, losses including the
/// resistor, change of stored energy) close within 1e-9 of the turbine work (measured 4.0e-12); the
/// turbines idle near rated speed while the resistor takes what the motors return.
#[test]
fn ac_braking_with_brake_resistor() {
    let r = run(&preset("ac-braking").unwrap());
    let e = r.summary.energy_j;
    println!(
        "regenerated {:.1} MJ per plant, brake resistor {:.1} MJ per plant, ship kinetic energy change {:.0} MJ, \
         residual {:.2e}",
        e.regenerated / 2e6,
        e.brake / 2e6,
        e.stored_change / 1e6,
        e.relative_residual
    );
    assert!(e.relative_residual.abs() < 1e-9);
    assert!(e.regenerated > 0.0);
    // The resistor takes the regenerated energy (the generators add a little at the start, before
    // the bus reaches the chopper's threshold): within 1 % (measured 0.71 %).
    assert!((e.brake - e.regenerated).abs() < 0.01 * e.regenerated, "{} vs {}", e.brake, e.regenerated);
    // The sudden loss of load makes the turbines overshoot while the throttle closes at its slew
    // limit (about +5 %, Fig. 5-7's "acceptably controlled" response); then they settle (to 1e-4
    // pu by the end; measured 2.5e-5: the ship, at 8.8 kn, is still slowing and the chopper still
    // working).
    let n = r.summary.signals["turbine_speed_pu"];
    println!("turbines {:.4} .. {:.4} pu, final {:.4}", n.min, n.max, n.final_);
    assert!(n.max < 1.06 && n.min > 0.98, "turbines {} .. {}", n.min, n.max);
    assert!((n.final_ - 1.0).abs() < 1e-4, "final {}", n.final_);
    let t = column(&r, "t_s");
    let throttle = column(&r, "throttle");
    let idle = t.iter().zip(throttle).filter(|(&t, _)| t > 40.0).all(|(_, &f)| f < 0.05);
    assert!(idle, "turbines should idle while braking");
    assert!(r.summary.signals["bus_voltage_pu"].max < 1.16);
    assert!(final_value(&r, "ship_speed_kn") < 15.0);
}

/// Fig. 5-8: without the resistor the returned energy reaches the turbines through reversible
/// rectifiers and they overspeed with the throttle closed.
#[test]
fn ac_braking_unbuffered_overspeeds_the_turbines() {
    let r = run(&preset("ac-braking-unbuffered").unwrap());
    let n = r.summary.signals["turbine_speed_pu"];
    let th = r.summary.signals["throttle"];
    println!(
        "turbines up to {:.3} pu, throttle down to {:.3}, bus up to {:.3} pu",
        n.max, th.min, r.summary.signals["bus_voltage_pu"].max
    );
    assert!(n.max > 1.1, "turbine overspeed {}", n.max);
    assert_eq!(th.min, 0.0);
    // The books close within 1e-9 (measured 5.5e-13).
    assert!(r.summary.energy_j.relative_residual.abs() < 1e-9);
    assert_eq!(r.summary.energy_j.brake, 0.0);
}

/// The "offset discontinuity" of ch. 5.2.2 is not needed by our circuit (regular at zero slip);
/// switching it on with a small band changes the braking energy by under 2 % (measured 1.1 %, over
/// the 110 s from 25 to 8.8 knots).
#[test]
fn zero_slip_offset_changes_little() {
    let base = run(&preset("ac-braking").unwrap()).summary.energy_j.regenerated;
    let mut s = preset("ac-braking").unwrap();
    s.controllers.slip.zero_slip_offset_rad_s = 0.05;
    let with = run(&s).summary.energy_j.regenerated;
    println!("regenerated {base:.4e} J without offset, {with:.4e} J with");
    assert!((with - base).abs() < 0.02 * base, "{with} vs {base}");
}

fn turn_figures(name: &str) -> (f64, f64, f64) {
    let r = run(&preset(name).unwrap());
    let p = column(&r, "p_motor_w");
    let eta = column(&r, "prop_efficiency");
    let p_rise = p.iter().copied().fold(0.0, f64::max) / p[0] - 1.0;
    let eta_drop = 1.0 - eta.iter().copied().fold(f64::INFINITY, f64::min) / eta[0];
    (p_rise, eta_drop, final_value(&r, "heading_deg"))
}

/// Ch. 5.2.3, Fig. 5-10: heading changes need more motor power to hold speed (thesis: about 6 % for
/// 45 degrees and 15 % for 90 degrees) and lower the propeller efficiency. Ours: +6 % for both at
/// the autopilot's default 0.5 deg/s turn: the peak depends on the rate of turn, not on the angle,
/// and the thesis does not give its turn rate. Tested: a rise of 2 % to 30 %, a fall in efficiency,
/// and the new heading reached within 2 degrees.
#[test]
fn heading_changes_cost_power() {
    for (name, target) in [("turn-45", 45.0), ("turn-90", 90.0)] {
        let (rise, drop, heading) = turn_figures(name);
        println!(
            "{name}: motor power +{:.1} %, propeller efficiency -{:.2} %, final heading {heading:.2}",
            100.0 * rise,
            100.0 * drop
        );
        assert!(rise > 0.02 && rise < 0.3, "{name}: {rise}");
        assert!(drop > 0.0);
        assert!((heading - target).abs() < 2.0, "{name}: heading {heading}");
    }
}

/// Fig. 5-16 in calm water: a full turn at 25 knots. The thesis: radius about three ship lengths,
/// about 255 rpm to hold 25 knots. Ours, ordered at the preset's 1 deg/s (r' = 0.19 on the hull's
/// L = 142 m): radius 737 m (5.2 L; 4.1 of the 180 m the check below divides by), 2.4 deg of
/// rudder, 205 rpm and 9 % more motor power. Tested: the turn completes, the radius (U / r over
/// the steady part) is 2 to 6 times 180 m and the speed stays within 2 % of 25 knots.
#[test]
fn full_turn() {
    let r = run(&preset("turn-360").unwrap());
    let t = column(&r, "t_s");
    let yaw = column(&r, "yaw_rate_deg_s");
    let kn = column(&r, "ship_speed_kn");
    let rpm = column(&r, "prop_rpm");
    let sel: Vec<usize> = (0..t.len()).filter(|&i| t[i] >= 150.0 && t[i] <= 300.0).collect();
    let mean = |c: &[f64]| sel.iter().map(|&i| c[i]).sum::<f64>() / sel.len() as f64;
    let radius = kn_to_m_s(mean(kn)) / mean(yaw).to_radians();
    println!("full turn: radius {radius:.0} m = {:.2} L, {:.1} rpm, {:.2} kn", radius / 180.0, mean(rpm), mean(kn));
    assert!(radius > 2.0 * 180.0 && radius < 6.0 * 180.0);
    assert!(r.summary.signals["ship_speed_kn"].min > 24.5);
    assert!((final_value(&r, "heading_deg") - 360.0).abs() < 6.0);
    assert!(r.summary.warnings.is_empty(), "{:?}", r.summary.warnings);
}

/// Ch. 5.3.2: the radius of the full turn is the heading ramp's, R = U / (ramp rate) = L / r', not
/// the hull's: the autopilot holds the Table 2.3 hull on the ramp even where its spiral curve has
/// no steady turn (r' above 0.11). Measured: 3.05 L at r' = 1/3 (the thesis' three lengths) and
/// 2.00 L at r' = 1/2. Tested: R r' / L within 5 % of 1 at both, the turn completed.
#[test]
fn radius_follows_the_ramp() {
    let base = preset("turn-360").unwrap();
    let len = base.ship_hull().unwrap().rigid_body(&base.as_printed).length_m;
    let u = kn_to_m_s(base.initial.speed_kn);
    for rp in [1.0 / 3.0, 0.5] {
        let mut s = base.clone();
        s.controllers.autopilot.max_turn_rate_nondim = 1.0;
        s.commands[1].heading_rate_deg_s = Some((rp * u / len).to_degrees());
        let r = run(&s);
        let y = r.summary.signals["y_m"];
        let radius = (y.max - y.min) / 2.0 / len;
        println!("r' = {rp:.3}: radius {radius:.3} L");
        assert!((radius * rp - 1.0).abs() < 0.05, "r' = {rp}: {radius} L");
        assert!((final_value(&r, "heading_deg") - 360.0).abs() < 6.0);
    }
}

/// Orders outside what the model trusts are run with a warning, not refused.
#[test]
fn questionable_orders_warn() {
    let mut s = preset("turn-90").unwrap();
    s.commands[1].heading_rate_deg_s = Some(5.0);
    s.sim.duration_s = 60.0;
    let r = run(&s);
    assert!(
        r.summary.warnings.iter().any(|w| w.contains("faster than the autopilot holds")),
        "{:?}",
        r.summary.warnings
    );
    let r = run(&preset("ac-braking").unwrap());
    assert!(r.summary.warnings.iter().any(|w| w.contains("trusted from")), "{:?}", r.summary.warnings);
}

/// On the hull's own ship the maneuvering model's straight-line resistance is eq. 2.15's (Table
/// 5.1) at every speed: the 22-knot steady state's thrust is R_sp(u0) within 1e-9 (the shaft
/// speed solve's tolerance), and the same shaft speed as the surge model's to 1e-9.
#[test]
fn one_resistance_at_every_speed() {
    let s = preset("turn-45").unwrap();
    let p = aes_core::sim::plant::Plant::new(&s).unwrap();
    let mut surge = s.clone();
    surge.hull.model = aes_core::scenario::HullModelKind::Surge;
    let q = aes_core::sim::plant::Plant::new(&surge).unwrap();
    for kn in [5.0, 12.0, 17.5, 19.0, 22.0, 25.0, 30.0] {
        let u = kn_to_m_s(kn);
        assert_eq!(p.straight_resistance(u), q.straight_resistance(u));
        let (a, b) = (p.equilibrium_shaft_speed(u), q.equilibrium_shaft_speed(u));
        assert!((a - b).abs() < 1e-9 * b, "{kn} kn: {a} vs {b}");
    }
}

/// The hand-over from the surge model (below 17 knots) to the Abkowitz model (above 21 knots) is
/// smooth: the straight-line resistance and the calm-water shaft speed rise monotonically from 1 to
/// 35 knots, and the resistance coefficient R/u^2 and the shaft speed per knot w/u change by less
/// than 3 % between neighbouring 0.1-knot points (no kink at the hand-over).
#[test]
fn handover_is_smooth_and_monotone() {
    let mut s = preset("turn-45").unwrap();
    // The hand-over exists with eq. 2.22's straight-line polynomial (the thesis' ship); the hull's
    // own ship takes eq. 2.15 at every speed (test `one_resistance_at_every_speed`).
    s.as_printed.table_5_ship = true;
    let p = aes_core::sim::plant::Plant::new(&s).unwrap();
    let mut last: Option<(f64, f64)> = None;
    for i in 10..=350 {
        let u = kn_to_m_s(i as f64 * 0.1);
        let (r, w) = (p.straight_resistance(u), p.equilibrium_shaft_speed(u));
        if let Some((r0, w0)) = last {
            assert!(r > r0 && w > w0, "not monotone at {} kn", i as f64 * 0.1);
            let u0 = kn_to_m_s((i - 1) as f64 * 0.1);
            let (cr, cw) = ((r / (u * u)) / (r0 / (u0 * u0)), (w / u) / (w0 / u0));
            assert!((cr - 1.0).abs() < 0.03 && (cw - 1.0).abs() < 0.03, "step at {} kn: {cr} {cw}", i as f64 * 0.1);
        }
        last = Some((r, w));
    }
}
