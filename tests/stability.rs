//! Thesis ch. 4: the IPS stability tool. Steady states against Tables 4.1 and 4.2, and the linear
//! models' Bode plots against small sinusoidal perturbations of the nonlinear averaged models
//! (the counterpart of the stars on Figs. 4-7 to 4-9 and 4-12).

use aes_core::control::linear::{fourier_gain, BodePoint, LinearSystem};
use aes_core::studies::ips::motor_side::MotorSideParams;
use aes_core::studies::ips::{rk4, trapezoid_step};

#[allow(clippy::too_many_arguments)]
/// Simulates dx/dt = f(t, x) from `x0` with input amplitude `amp` at `omega` (RK4, or the implicit
/// trapezoidal rule for stiff models), discards `settle_s`, and returns the gain and phase of
/// output `y` over the following whole periods.
fn simulated_point(
    f: &dyn Fn(f64, &[f64]) -> Vec<f64>,
    y: &dyn Fn(&[f64]) -> f64,
    x0: &[f64],
    omega: f64,
    amp: f64,
    settle_s: f64,
    dt: f64,
    implicit: bool,
) -> BodePoint {
    let period = 2.0 * std::f64::consts::PI / omega;
    let periods = (2.0 / period).ceil().max(4.0);
    let steps_settle = (settle_s / period).ceil() * period / dt;
    let steps_measure = periods * period / dt;
    let (n_settle, n_meas) = (steps_settle.round() as usize, steps_measure.round() as usize);
    let dt_settle = (settle_s / period).ceil() * period / n_settle as f64;
    let dt_meas = periods * period / n_meas as f64;
    let mut x = x0.to_vec();
    let y0 = y(x0);
    let mut t = 0.0;
    let step = |t: f64, x: &mut [f64], h: f64| {
        if implicit {
            assert!(trapezoid_step(f, t, x, h), "Newton failed at t = {t}");
        } else {
            rk4(f, t, x, h);
        }
    };
    for _ in 0..n_settle {
        step(t, &mut x, dt_settle);
        t += dt_settle;
    }
    let (mut ts, mut ys) = (vec![t], vec![y(&x) - y0]);
    for _ in 0..n_meas {
        step(t, &mut x, dt_meas);
        t += dt_meas;
        ts.push(t);
        ys.push(y(&x) - y0);
    }
    fourier_gain(&ts, &ys, omega, amp)
}

fn compare(name: &str, sys: &LinearSystem, sim: &BodePoint) {
    let lin = sys.bode(&[sim.omega_rad_s]).unwrap()[0];
    let mut dphase = (lin.phase_deg - sim.phase_deg) % 360.0;
    if dphase > 180.0 {
        dphase -= 360.0;
    }
    if dphase < -180.0 {
        dphase += 360.0;
    }
    println!(
        "{name} at {:.2} rad/s: linear {:.2} dB {:.1} deg, nonlinear {:.2} dB {:.1} deg",
        sim.omega_rad_s, lin.magnitude_db, lin.phase_deg, sim.magnitude_db, sim.phase_deg
    );
    // Measured at most 2.3e-3 dB and 4.9e-3 deg (motor open loop at 100 rad/s; the gaps are the
    // perturbations' nonlinearity and the integration steps): asserted at 0.01 dB and 0.01 deg.
    let dgain = lin.magnitude_db - sim.magnitude_db;
    assert!(dgain.abs() < 0.01, "{name}: gain off by {dgain} dB");
    assert!(dphase.abs() < 0.01, "{name}: phase off by {dphase} deg");
}

/// Fig. 4-8 (T* = 100 N m, five states) and Fig. 4-9 (200 N m, six states): open loop, stator
/// voltage in, stator current magnitude out, at 1, 10 and 100 rad/s; perturbation 0.5 % of v_qs0.
#[test]
fn motor_open_loop_bode_matches_nonlinear_model() {
    let p = MotorSideParams::default();
    for t_star in [100.0, 200.0] {
        let ss = p.steady_state(t_star).unwrap();
        let sys = p.open_loop(&ss);
        assert!(sys.is_stable().unwrap(), "{t_star} N m open loop poles {:?}", sys.poles().unwrap());
        assert_eq!(sys.a.nrows(), if t_star > 150.0 { 6 } else { 5 });
        let x0 = p.steady_vector(&ss, ss.above_threshold);
        let amp = 0.005 * ss.v_qs;
        for omega in [1.0, 10.0, 100.0] {
            let f = |t: f64, x: &[f64]| p.open_loop_rhs(x, ss.v_qs + amp * libm::sin(omega * t), ss.t_ref0, ss.t_star);
            let y = |x: &[f64]| libm::hypot(x[0], x[1]);
            let sim = simulated_point(&f, &y, &x0, omega, amp, 6.0, 2e-4, false);
            compare(&format!("motor open loop {t_star} N m"), &sys, &sim);
        }
    }
}

/// Fig. 4-12: closed loop with the equivalent control, torque command in, torque out, at 100 N m,
/// below the trim bandwidth (1 / tau = 20 rad/s): 1, 5 and 10 rad/s; perturbation 1 N m.
#[test]
fn motor_closed_loop_bode_matches_nonlinear_model() {
    let p = MotorSideParams::default();
    let ss = p.steady_state(100.0).unwrap();
    let sys = p.closed_loop(&ss);
    println!("closed loop poles {:?}", sys.poles().unwrap());
    assert!(sys.is_stable().unwrap());
    let x0 = p.steady_vector(&ss, true);
    let sign = ss.currents[0].signum();
    for omega in [1.0, 5.0, 10.0] {
        let f = |t: f64, x: &[f64]| p.closed_loop_rhs(x, ss.t_star + libm::sin(omega * t), sign);
        let y = |x: &[f64]| p.torque(&x[..4]);
        let sim = simulated_point(&f, &y, &x0, omega, 1.0, 6.0, 2e-4, false);
        compare("motor closed loop 100 N m", &sys, &sim);
    }
}

/// Fig. 4-7: generator side, field voltage in, droop feedback (v_dc + K_d i_dc) out, open loop,
/// at the baseline point; perturbation 1 % of v_fd0. And the closed droop loop (eq. 4.48): voltage
/// set point in, bus voltage out, below its bandwidth.
#[test]
fn generator_bode_matches_nonlinear_model() {
    use aes_core::studies::ips::generator_side::GeneratorSideParams;
    let p = GeneratorSideParams::default();
    let ss = p.steady_state(377.0, 28.5, 45.0).unwrap();
    let ol = p.open_loop(&ss);
    println!("generator open-loop poles {:?}", ol.poles().unwrap().iter().map(|q| (q.re, q.im)).collect::<Vec<_>>());
    assert!(ol.is_stable().unwrap());
    let amp = 0.01 * ss.v_fd;
    let dt = 2e-4;
    for omega in [1.0, 10.0, 100.0] {
        let f = |t: f64, x: &[f64]| p.rhs(x, ss.v_fd + amp * libm::sin(omega * t), ss.omega, ss.i_load);
        let y = |x: &[f64]| x[10] + p.k_d * x[7];
        let sim = simulated_point(&f, &y, &ss.x, omega, amp, 3.0, dt, true);
        compare("generator open loop", &ol, &sim);
    }
    let cl = p.closed_loop(&ss);
    println!("generator closed-loop poles {:?}", cl.poles().unwrap().iter().map(|q| (q.re, q.im)).collect::<Vec<_>>());
    assert!(cl.is_stable().unwrap());
    let (x0, v_star) = p.closed_loop_equilibrium(&ss);
    for omega in [1.0, 5.0] {
        let f = |t: f64, x: &[f64]| p.closed_loop_rhs(x, v_star + libm::sin(omega * t), &ss, 10.0 * ss.v_fd);
        let y = |x: &[f64]| x[10];
        let sim = simulated_point(&f, &y, &x0, omega, 1.0, 3.0, dt, true);
        compare("generator closed loop", &cl, &sim);
    }
}

/// Stability margins where a loop is closed: the droop loop and the torque-trim loop are stable
/// with positive gain and phase margins, consistent with their closed-loop poles.
#[test]
fn margins_agree_with_closed_loop_poles() {
    use aes_core::studies::ips::generator_side::GeneratorSideParams;
    let g = GeneratorSideParams::default();
    let ss = g.steady_state(377.0, 28.5, 45.0).unwrap();
    let m = g.droop_margins(&ss);
    println!("droop loop: {m:?}");
    assert!(g.closed_loop(&ss).is_stable().unwrap());
    assert!(m.phase_margin_deg.unwrap() > 0.0);
    if let Some(gm) = m.gain_margin_db {
        assert!(gm > 0.0);
    }
    let p = MotorSideParams::default();
    let ss = p.steady_state(100.0).unwrap();
    let m = p.trim_margins(&ss);
    println!("torque-trim loop: {m:?}");
    assert!(p.closed_loop(&ss).is_stable().unwrap());
    assert!(m.phase_margin_deg.unwrap() > 0.0);
    // A trim ten times faster: the margins and the closed-loop poles agree on stability.
    let mut fast = p.clone();
    fast.trim_tau = p.trim_tau / 10.0;
    let mf = fast.trim_margins(&ss);
    let stable = fast.closed_loop(&ss).is_stable().unwrap();
    println!("tau / 10: {mf:?}, closed loop stable: {stable}");
    assert_eq!(stable, mf.phase_margin_deg.unwrap() > 0.0 && mf.gain_margin_db.is_none_or(|g| g > 0.0));
}
