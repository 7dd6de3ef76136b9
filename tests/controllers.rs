//! Thesis ch. 3.1 applied to our plant (ch. 3.1.3): the LQG/LTR controller running in the
//! simulator in place of the governor and field PIs, against the PI loops of ch. 5.2.

use aes_core::scenario::presets::{acceleration, acceleration_lqg_ltr, preset};
use aes_core::scenario::ControllerDesign;
use aes_tests::run;

fn stats(r: &aes_core::RunResult, name: &str) -> aes_core::sim::TraceStats {
    r.summary.signals[name]
}

/// The study of issue 16 on the thesis' own ship (Tables 5.1/5.5, `as_printed.table_5_ship`):
/// there the kayak's resistance at L = 180 m puts the 25-knot motors near 0.8 pu, so the step to
/// full ahead is small, and the compensator is tuned with equal weights (turbine speed weight 1).
fn on_table_5_ship(mut sc: aes_core::Scenario) -> aes_core::Scenario {
    sc.as_printed.table_5_ship = true;
    sc.hull.forces = aes_core::ship::maneuvering::ManeuveringForces::Table23;
    sc.controllers.lqg_ltr.turbine_speed_weight = 1.0;
    sc
}

/// At its steady state the compensator keeps the plant there: the observer starts at rest with no
/// error, so nothing moves beyond the calm-water solve's own residual (within 1e-9 per unit over
/// 20 s; measured 0 for the bus voltage and 0 for the turbine speed).
#[test]
fn lqg_holds_the_steady_state() {
    let mut sc = acceleration_lqg_ltr();
    sc.commands.truncate(1);
    sc.sim.duration_s = 20.0;
    let r = run(&sc);
    for name in ["turbine_speed_pu", "bus_voltage_pu"] {
        let s = stats(&r, name);
        assert!(s.max - s.min < 1e-9, "{name}: {} to {}", s.min, s.max);
    }
}

/// The test, on the thesis' ship (`on_table_5_ship`): in the acceleration study LQG/LTR holds the bus far better than the PI
/// field loop (dip measured 4.4 % against 23.9 %; asserted below a third) at equal peak fuel power
/// (both 239.3 MW: the throttles reach full fuel at their slew limit either way; within 1e-5,
/// measured LQG 1.9e-6 higher, from the turbine's speed at full fuel), and the
/// turbines pay with a deeper dip (0.734 against 0.825 pu; asserted: the LQG dip is deeper and
/// stays above 0.7).
#[test]
fn lqg_holds_the_bus_better_in_the_acceleration() {
    let (pi, lqg) = (run(&on_table_5_ship(acceleration(false))), run(&on_table_5_ship(acceleration_lqg_ltr())));
    let dip = |r: &aes_core::RunResult| 1.0 - stats(r, "bus_voltage_pu").min;
    assert!(dip(&lqg) < dip(&pi) / 3.0, "bus dip LQG {} PI {}", dip(&lqg), dip(&pi));
    let peak = |r: &aes_core::RunResult| stats(r, "fuel_power_w").max;
    assert!(peak(&lqg) <= peak(&pi) * (1.0 + 1e-5), "peak fuel LQG {} PI {}", peak(&lqg), peak(&pi));
    let (t_pi, t_lqg) = (stats(&pi, "turbine_speed_pu").min, stats(&lqg, "turbine_speed_pu").min);
    assert!(t_lqg < t_pi && t_lqg > 0.7, "turbine min LQG {t_lqg} PI {t_pi}");
}

/// On the hull's own ship (Lpp 142 m, eq. 2.15's resistance) the 25-knot motors run at 0.4 pu and
/// the step to full ahead is 0.6 pu: with equal weights the compensator holds the bus by taking the
/// turbines' kinetic energy until they stall (measured 0.14 pu, asserted below 0.3, never back);
/// the preset's weight of 10 keeps them turning (measured 0.69 pu, asserted above 0.6) and back at
/// their set point within 1e-3 at the end, like the PIs (0.69 pu).
#[test]
fn equal_weights_stall_the_turbines_in_the_big_step_and_the_presets_weight_does_not() {
    let mut equal = acceleration_lqg_ltr();
    equal.controllers.lqg_ltr.turbine_speed_weight = 1.0;
    let t = stats(&run(&equal), "turbine_speed_pu");
    assert!(t.min < 0.3 && t.final_ < 0.3, "equal weights: turbines {} .. final {}", t.min, t.final_);
    let t = stats(&run(&acceleration_lqg_ltr()), "turbine_speed_pu");
    assert!(t.min > 0.6 && (t.final_ - 1.0).abs() < 1e-3, "weight 10: turbines {} .. final {}", t.min, t.final_);
}

/// Anti-windup: the throttle sits at full fuel for seconds in the acceleration, and the
/// compensator comes out of it without the overshoot of a wound-up integrator: turbine speed at
/// most 3 % over its set point (measured 1.4 %), bus voltage at most 1 % over (measured 0.33 %),
/// and both back within 1e-3 of their set points at the end (measured 3e-5 and 2e-6).
#[test]
fn lqg_comes_out_of_saturation_cleanly() {
    let r = run(&on_table_5_ship(acceleration_lqg_ltr()));
    assert_eq!(stats(&r, "throttle").max, 1.0);
    let (t, v) = (stats(&r, "turbine_speed_pu"), stats(&r, "bus_voltage_pu"));
    assert!(t.max < 1.03 && v.max < 1.01, "overshoot: turbine {} bus {}", t.max, v.max);
    assert!((t.final_ - 1.0).abs() < 1e-3 && (v.final_ - 1.0).abs() < 1e-3, "final {} {}", t.final_, v.final_);
}

/// AC braking: the brake chopper holds the bus above its set point for about a hundred seconds
/// with the field at 0 V. The compensator stops integrating the bus error while the field sits at
/// that limit, so the turbine ends at its set point: within 1e-3 (measured 3.3e-4; without the
/// rule it ended at 0.971 pu). A bad tuning is refused with the field named.
#[test]
fn lqg_in_braking_ends_at_speed_and_bad_tuning_is_named() {
    let mut sc = preset("ac-braking").unwrap();
    sc.controllers.design = ControllerDesign::LqgLtr;
    let r = run(&sc);
    assert_eq!(stats(&r, "field_voltage_v").min, 0.0);
    let t = stats(&r, "turbine_speed_pu");
    assert!((t.final_ - 1.0).abs() < 1e-3, "turbine ends at {}", t.final_);
    sc.controllers.lqg_ltr.mu = -1.0;
    let e = aes_core::Simulation::new(&sc).err().unwrap().to_string();
    assert!(e.contains("controllers.lqg_ltr.mu"), "{e}");
}
