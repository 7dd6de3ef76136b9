//! Multi-rate stepping (`stepping.hull_substeps`): the hull steps once per several drive-train
//! steps under their mean thrust. Against the single-rate run of the same preset the recorded
//! propeller speed, motor power, hub depth and ship speed agree within the tolerances below, and
//! the energy accounts close as tightly.

/// The preset; W1 (head seas SS6) and the as-printed run with the thesis' hull forces (Table 2.3),
/// and eq. 2.48's short-wave force (the thesis'): the realisation the step tolerances below were
/// measured on. With the hull's own forces W1's
/// seed 1 meets a harder sequence of ventilations: the 5 ms midpoint run's governor settles 0.1 of
/// throttle from the 1 ms run's after the ventilation at 72-73 s (bus 0.087 pu apart at 80 s).
fn preset(name: &str) -> Option<aes_core::Scenario> {
    let mut sc = aes_core::scenario::presets::preset(name)?;
    if name == "head-seas-ss6" || name == "as-printed" {
        sc.hull.forces = aes_core::ship::maneuvering::ManeuveringForces::Table23;
        sc.seakeeping.short_wave_force = aes_core::sea::seakeeping::params::ShortWaveForce::SalvesenF7;
    }
    Some(sc)
}
use aes_core::scenario::Integrator;
use aes_core::RunResult;
use aes_tests::run;

fn col<'a>(r: &'a RunResult, name: &str) -> &'a [f64] {
    r.trace.column(name).unwrap_or_else(|| panic!("no column {name}"))
}
fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}
fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}
fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

/// Differences of one run from a reference run of the same scenario (a multi-rate run from the
/// single-rate one, or a longer step from 1 ms steps), recorded at the same times.
pub struct Diff {
    rpm_max: f64,
    rpm_mean: f64,
    motor_power_mean_rel: f64,
    motor_power_max_of_peak: f64,
    min_h_over_r: f64,
    speed_kn_max: f64,
    bus_pu_max: f64,
    h_over_r_max: f64,
    residual_reference: f64,
    residual_run: f64,
}

/// The preset with every due RAO look-up made: the look-up skipped after small moves
/// (`skipped_rao_look_ups_change_little`) would decide differently in two runs of different
/// steps and add its own difference to the method's.
fn every_look_up(name: &str) -> aes_core::Scenario {
    let mut sc = preset(name).unwrap();
    sc.seakeeping.rao_refresh_speed_m_s = 0.0;
    sc.seakeeping.rao_refresh_heading_deg = 0.0;
    sc
}

fn compare(name: &str, hull_step_s: f64) -> Diff {
    let mut single = every_look_up(name);
    if name == "head-seas-ss6" {
        // W1 as defined in issue 17: 2.5 ms steps (the preset ships with 5 ms: `wave_presets_step_of_5_ms_matches_1_ms`).
        single.stepping.dt_s = 0.0025;
        single.stepping.integrator = Integrator::Rk4;
    }
    let mut multi = single.clone();
    multi.stepping.hull_substeps = (hull_step_s / single.stepping.dt_s).round() as u32;
    let d = differences(&single, &multi);
    println!(
        "{name}, hull step {hull_step_s} s ({} substeps): rpm max {:.2e} mean {:.2e}; motor power mean {:.2e}, \
         max {:.2e} of peak; min h/R {:.2e}; ship speed max {:.2e} kn; energy residual {:.2e} single, {:.2e} multi",
        multi.stepping.hull_substeps,
        d.rpm_max,
        d.rpm_mean,
        d.motor_power_mean_rel,
        d.motor_power_max_of_peak,
        d.min_h_over_r,
        d.speed_kn_max,
        d.residual_reference,
        d.residual_run
    );
    d
}

impl std::fmt::Display for Diff {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "rpm max {:.3e} mean {:.3e}; motor power mean {:.3e}, max {:.3e} of peak; min h/R {:.3e}, h/R max \
             {:.3e}; bus max {:.3e} pu; ship speed max {:.3e} kn; residual {:.3e} (reference {:.3e})",
            self.rpm_max,
            self.rpm_mean,
            self.motor_power_mean_rel,
            self.motor_power_max_of_peak,
            self.min_h_over_r,
            self.h_over_r_max,
            self.bus_pu_max,
            self.speed_kn_max,
            self.residual_run,
            self.residual_reference
        )
    }
}

/// The differences of run `b` from run `a` (the reference), recorded at the same times.
pub fn differences(a: &aes_core::Scenario, b: &aes_core::Scenario) -> Diff {
    let (a, b) = (run(a), run(b));
    assert_eq!(a.trace.len(), b.trace.len());
    let (pa, pb) = (col(&a, "p_motor_w"), col(&b, "p_motor_w"));
    let peak = pa.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
    Diff {
        rpm_max: max_diff(col(&a, "prop_rpm"), col(&b, "prop_rpm")),
        rpm_mean: (mean(col(&a, "prop_rpm")) - mean(col(&b, "prop_rpm"))).abs(),
        motor_power_mean_rel: ((mean(pa) - mean(pb)) / mean(pa)).abs(),
        motor_power_max_of_peak: max_diff(pa, pb) / peak,
        min_h_over_r: (min(col(&a, "h_over_r")) - min(col(&b, "h_over_r"))).abs(),
        speed_kn_max: max_diff(col(&a, "ship_speed_kn"), col(&b, "ship_speed_kn")),
        bus_pu_max: max_diff(col(&a, "bus_voltage_pu"), col(&b, "bus_voltage_pu")),
        h_over_r_max: max_diff(col(&a, "h_over_r"), col(&b, "h_over_r")),
        residual_reference: a.summary.energy_j.relative_residual,
        residual_run: b.summary.energy_j.relative_residual,
    }
}

/// W1 (head seas SS6, 2.5 ms steps) with the hull stepping every 5 ms (2 substeps, the
/// controller sample) and every 10 ms (4 substeps; the controllers and the seaway read the hull
/// carried forward by its last step's rate in between). Measured at 5 / 10 ms: rpm 2.1e-3 /
/// 0.041 at most (mean 2.2e-4 / 2.1e-4), mean motor power 4.4e-6 / 6.1e-5, largest 5.2e-5 /
/// 1.8e-3 of the peak, min h/R 3.5e-6 / 2.6e-6, ship speed 3.6e-4 / 2.3e-3 kn, the energy
/// residual -5.65e-5 / -5.74e-5 against -5.65e-5 (the seaway's work). (On the RAO table linear in
/// frequency, another realisation: rpm 0.035 / 0.038, ship speed 7e-4 / 4.8e-3 kn; at 20 ms the
/// rpm peaks differed by 0.12, ship speed by 6e-3 kn.)
#[test]
fn head_seas_multi_rate_matches_single_rate() {
    for step in [0.005, 0.01] {
        let d = compare("head-seas-ss6", step);
        assert!(d.rpm_max < 0.05, "rpm {}", d.rpm_max);
        assert!(d.rpm_mean < 5e-4, "rpm mean {}", d.rpm_mean);
        assert!(d.motor_power_mean_rel < 1.2e-4, "motor power {}", d.motor_power_mean_rel);
        assert!(d.motor_power_max_of_peak < 3e-3, "motor power {} of peak", d.motor_power_max_of_peak);
        assert!(d.min_h_over_r < 1e-5, "min h/R {}", d.min_h_over_r);
        assert!(d.speed_kn_max < 4e-3, "ship speed {} kn", d.speed_kn_max);
        assert!((d.residual_run - d.residual_reference).abs() < 2e-6, "{} vs {}", d.residual_run, d.residual_reference);
    }
}

/// Calm-water acceleration (maneuvering model, 1 ms steps) with hull steps of 5 and 10 ms: measured rpm
/// 2.7e-3 and 5.4e-3 at most, mean motor power 1.2e-6 and 2.4e-6, ship speed 8.8e-5 and 1.8e-4
/// kn; the energy residual unchanged (-2.47e-11).
#[test]
fn acceleration_multi_rate_matches_single_rate() {
    for step in [0.005, 0.01] {
        let d = compare("acceleration", step);
        assert!(d.rpm_max < 0.05, "rpm {}", d.rpm_max);
        assert!(d.rpm_mean < 0.01, "rpm mean {}", d.rpm_mean);
        assert!(d.motor_power_mean_rel < 2e-3, "motor power {}", d.motor_power_mean_rel);
        assert!(d.speed_kn_max < 0.01, "ship speed {} kn", d.speed_kn_max);
        assert!(d.residual_run.abs() < 1e-9, "residual {}", d.residual_run);
    }
}

/// The calm-water start-up from idle with hull steps of 5, 10 and 20 ms: the energy books close
/// within 1e-9 (measured 2.5e-14, 4.8e-14, 2.0e-15: the thrust's work is booked at the hull's
/// speed in the hull's own step), rpm within 3.5e-3, 7e-3, 1.4e-2, ship speed within 4.3e-4,
/// 8.3e-4, 1.7e-3 kn.
#[test]
fn startup_multi_rate_closes_energy() {
    for step in [0.005, 0.01, 0.02] {
        let d = compare("startup", step);
        assert!(d.residual_run.abs() < 1e-9, "residual {}", d.residual_run);
        assert!(d.rpm_max < 0.05, "rpm {}", d.rpm_max);
        assert!(d.speed_kn_max < 0.01, "ship speed {} kn", d.speed_kn_max);
    }
}

/// The runs in waves step at 5 ms by the midpoint rule (`presets::sea_step`). Against 1 ms RK4
/// steps, head seas SS6 (W1) and the as-printed SS6 run (hub depth of eq. 2.57 as printed: the
/// propeller ventilates and emerges, the hardest case for a fixed step) are compared by RK4 at
/// 2.5 and 5 ms, by the midpoint rule at 5 ms (as shipped) and at 5 ms with the hull at 10 ms (2
/// substeps). Measured: see the printed lines; the shipped step asserted as below.
#[test]
fn wave_presets_step_of_5_ms_matches_1_ms() {
    use Integrator::{Midpoint, Rk4};
    for name in ["head-seas-ss6", "as-printed"] {
        let mut shipped = every_look_up(name);
        if name == "as-printed" {
            // Its first 60 s: at 69 s seed 1's turbines stall (0.31 pu, the bus at 0.33 pu) and
            // from there every fixed step parts from the 1 ms run, RK4 at 2.5 ms by 0.5 pu of bus.
            shipped.sim.duration_s = 60.0;
        }
        assert_eq!((shipped.stepping.dt_s, shipped.stepping.integrator), (0.005, Midpoint));
        let mut reference = shipped.clone();
        reference.stepping.dt_s = 0.001;
        reference.stepping.integrator = Rk4;
        reference.stepping.hull_substeps = 1;
        for (dt, method, sub) in [(0.0025, Rk4, 1), (0.005, Rk4, 1), (0.005, Midpoint, 1), (0.005, Midpoint, 2)] {
            let mut c = shipped.clone();
            c.stepping.dt_s = dt;
            c.stepping.integrator = method;
            c.stepping.hull_substeps = sub;
            let d = differences(&reference, &c);
            println!("{name} at {dt} s x {sub}, {method:?}: {d}");
            let w1 = name == "head-seas-ss6";
            let tol = |a: f64, b: f64| if w1 { a } else { b };
            if (dt, method, sub) == (0.005, Midpoint, 2) {
                // The shipped method with the hull at 10 ms. Measured (W1 / as printed's first 60
                // s): rpm max 0.062 / 0.142, mean 6.3e-4 / 1.0e-2, mean motor power 1.1e-4 /
                // 3.3e-4, largest difference 2.9e-3 / 3.2e-3 of the peak, min h/R 8.9e-7 / 1.0e-2,
                // bus 3.0e-3 / 2.6e-2 pu, ship speed 3.2e-3 / 2.7e-3 kn, residual 7.7e-8 / 4.4e-7
                // from the 1 ms run's. As printed, h/R's minimum lies on the last row (60 s), still
                // falling, where the 1 ms run is 0.04 m further along (the ship speeds 2.7e-3 kn
                // apart after the ventilations): the phase of a heave of 8 m moves the hub by 2 cm.
                assert!(d.rpm_max < tol(0.09, 0.15), "{name} x 2: rpm {}", d.rpm_max);
                assert!(d.motor_power_mean_rel < tol(1.5e-4, 4e-4), "{name} x 2: power {}", d.motor_power_mean_rel);
                assert!(
                    d.motor_power_max_of_peak < tol(6e-3, 5e-3),
                    "{name} x 2: {} of peak",
                    d.motor_power_max_of_peak
                );
                assert!(d.min_h_over_r < tol(2e-6, 1.5e-2), "{name} x 2: min h/R {}", d.min_h_over_r);
                assert!(d.speed_kn_max < tol(5e-3, 4e-3), "{name} x 2: ship speed {} kn", d.speed_kn_max);
                let residual = (d.residual_run - d.residual_reference).abs();
                assert!(residual < tol(1.5e-7, 7e-7), "{name} x 2: residual {residual}");
            }
            if (dt, method, sub) != (0.005, Midpoint, 1) {
                continue;
            }
            // The shipped step. Measured (W1 / as printed's first 60 s): rpm max 0.042 / 0.142, rpm
            // mean 2.7e-3 / 1.0e-2, mean motor power 4.6e-5 / 3.0e-4, largest motor power
            // difference 2.0e-3 / 3.2e-3 of the peak, min h/R 8.2e-6 / 1.0e-2 (as above), bus
            // voltage 1.5e-2 / 3.2e-2 pu, ship speed 1.1e-3 / 2.7e-3 kn, energy residual 7.7e-8 /
            // 4.4e-7 from the 1 ms run's (4.9e-7 / 4.8e-7 before the side force's work was booked); RK4 at 5 ms gives the same but for the bus, 2.5e-3 /
            // 1.5e-2 pu. The bus: in W1, as both shafts recover from ventilating at 72-73 s, the
            // midpoint run's throttle steps 0.01 away from the 1 ms run's and holds 0.0075 above it
            // from 74.5 to 78 s (0.505 against 0.497), so the turbines run 1.4 % faster at 78 s and
            // the bus with them. (Measured on the RAO table linear in frequency, with other
            // realisations: bus 4.0e-3 / 2.7e-3 pu.) The as-printed run's propeller emerges: a
            // ventilation switch a step later moves the trace after it.
            assert!(d.rpm_max < tol(0.05, 0.2), "{name}: rpm {}", d.rpm_max);
            assert!(d.rpm_mean < tol(4e-3, 1.2e-2), "{name}: rpm mean {}", d.rpm_mean);
            assert!(d.motor_power_mean_rel < tol(6e-5, 4e-4), "{name}: motor power {}", d.motor_power_mean_rel);
            assert!(d.motor_power_max_of_peak < tol(2.5e-3, 5e-3), "{name}: {} of peak", d.motor_power_max_of_peak);
            assert!(d.min_h_over_r < tol(2e-5, 1.5e-2), "{name}: min h/R {}", d.min_h_over_r);
            assert!(d.bus_pu_max < tol(2e-2, 4e-2), "{name}: bus {} pu", d.bus_pu_max);
            assert!(d.speed_kn_max < tol(2e-3, 3e-3), "{name}: ship speed {} kn", d.speed_kn_max);
            let residual = (d.residual_run - d.residual_reference).abs();
            assert!(residual < tol(1.5e-7, 6e-7), "{name}: residual {residual}");
        }
    }
}

/// The hull step must divide the record interval, and 0 substeps is refused.
#[test]
fn hull_substeps_validated() {
    let mut s = preset("head-seas-ss6").unwrap();
    s.stepping.hull_substeps = 3; // 7.5 ms does not divide 0.1 s
    assert!(s.validate().unwrap_err().to_string().contains("sim.record_interval_s"));
    s.stepping.hull_substeps = 0;
    assert!(s.validate().unwrap_err().to_string().contains("stepping.hull_substeps"));
}

/// The RAO look-up skipped while speed and heading stay within `seakeeping.rao_refresh_speed_m_s`
/// and `rao_refresh_heading_deg` of the last one (0.02 m/s, 0.01 deg), in head seas (the preset at
/// its 5 ms steps, the ship slowing 1 m/s) and in a quarter turn in SS6, against a look-up every
/// 0.25 s (`rao_refresh_s`). Yardstick: what that interval itself costs, against a look-up at every
/// sample (0.05 s). Measured (head seas / quarter turn), skipping: 109 of 320 / 1081 of 1200
/// look-ups, rpm max 0.078 / 0.0031 (mean 5.0e-4 / 5.4e-4), motor power 3.5e-3 / 1.0e-4 of peak,
/// h/R 1.9e-3 / 3.2e-3, bus 1.6e-2 / 6e-6 pu, ship speed 1.4e-3 / 4.9e-4 kn; the interval's own:
/// rpm max 0.079 / 0.011, motor power 3.1e-3 / 3.2e-4 of peak, h/R 1.9e-3 / 1.2e-2, bus 1.5e-2 /
/// 1.4e-5 pu, ship speed 7.8e-4 / 1.2e-3 kn. In head seas the largest differences, of either, come
/// from the governor's throttle settling apart after the ventilation at 72-73 s (see
/// `wave_presets_step_of_5_ms_matches_1_ms`); before the RAO table became cubic in frequency
/// (another realisation of seed 1's run) skipping measured rpm max 0.017 and bus 2.7e-3 pu. (With
/// 0.1 deg the quarter turn moved by 0.18 rpm and 0.045 kn.) The as-printed run (eqs. 2.55/2.59's
/// doubled Doppler shift) never skips: the same bits as every look-up. The quarter turn sails the
/// hull's own maneuvering model (the numbers above are Table 2.3's): skipping 132 of 1200
/// look-ups it measured rpm max 7.3e-3 (mean 8.5e-4), motor power 2.1e-4 of peak, h/R 4.1e-3, bus
/// 1.2e-5 pu, ship speed 1.1e-3 kn, against the interval's own rpm 0.031, motor power 8.2e-4 of
/// peak, h/R 1.0e-2, bus 3.8e-5 pu, ship speed 3.5e-3 kn.
#[test]
fn skipped_rao_look_ups_change_little() {
    use aes_core::sim::Simulation;
    let printed = preset("as-printed").unwrap();
    assert!(printed.as_printed.doppler_twice);
    assert_eq!(run(&printed).trace, run(&every_look_up("as-printed")).trace, "as printed: a look-up skipped");
    for name in ["head-seas-ss6", "quarter-turn-ss6"] {
        let shipped = preset(name).unwrap();
        let every = every_look_up(name);
        let mut each_sample = every.clone();
        each_sample.seakeeping.rao_refresh_s = each_sample.stepping.sea_sample_s;
        let look_ups = |sc: &aes_core::Scenario| {
            let mut sim = Simulation::new(sc).unwrap();
            sim.advance(u64::MAX).unwrap();
            sim.seaway().unwrap().look_ups()
        };
        let (n_every, n_shipped) = (look_ups(&every), look_ups(&shipped));
        let d = differences(&every, &shipped);
        let interval = differences(&each_sample, &every);
        println!("{name}: {n_shipped} of {n_every} look-ups; {d}\n  the 0.25 s interval's own: {interval}");
        assert!(d.rpm_max < interval.rpm_max, "{name}: rpm {} against the interval's {}", d.rpm_max, interval.rpm_max);
        let w1 = name == "head-seas-ss6";
        let tol = |a: f64, b: f64| if w1 { a } else { b };
        assert!(d.rpm_max < tol(0.09, 1e-2), "{name}: rpm {}", d.rpm_max);
        assert!(d.rpm_mean < tol(1e-3, 1.2e-3), "{name}: rpm mean {}", d.rpm_mean);
        assert!(d.motor_power_max_of_peak < tol(4e-3, 3e-4), "{name}: {} of peak", d.motor_power_max_of_peak);
        assert!(d.h_over_r_max < tol(3e-3, 5e-3), "{name}: h/R {}", d.h_over_r_max);
        assert!(d.bus_pu_max < tol(2e-2, 2e-5), "{name}: bus {} pu", d.bus_pu_max);
        assert!(d.speed_kn_max < tol(1.5e-3, 1.5e-3), "{name}: ship speed {} kn", d.speed_kn_max);
        let skipped_share = 1.0 - n_shipped as f64 / n_every as f64;
        assert!(skipped_share > tol(0.6, 0.05), "{name}: {n_shipped} of {n_every} look-ups");
    }
}
