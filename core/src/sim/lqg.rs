//! The LQG/LTR compensator of thesis ch. 3.1 running in the simulator in place of the governor and
//! exciter PIs (`controllers.design = "lqg_ltr"`). It is designed when the run is built, on the
//! drive train linearised at `controllers.lqg_ltr.design_speed_kn` (sim::linearize), and each
//! turbine-generator set runs its own copy on its own turbine speed and its shaft's bus voltage
//! (the design model is the sets' common mode).
//!
//! Discretisation and anti-windup. Eq. 3.7 is an observer of the integrator-augmented plant with
//! the regulator's output as its input: x_k' = (A_ - K_f C_) x_k - B_ du + K_f e, du = K_c x_k,
//! and the plant input is u = integral of du (eq. 3.2). The observer is discretised by zero-order
//! hold for the controller's sample period (exact for the held samples). The integrator is the
//! actuator position itself, so anti-windup is the observer rule (Astrom and Wittenmark, ch. 9):
//! the commanded u is clamped to the actuator's range and slew (throttle 0 to 1 at the governor's
//! slew limit, field voltage 0 to the ceiling) and the observer is fed the du that was actually
//! applied, so its estimate stays consistent with the real plant input instead of winding up.
//! Unsaturated, this is eq. 3.7 sampled: the actuator steps by du T at each sample while the
//! observer's hold takes du constant over it, half a sample apart (0.7 degrees of phase at the
//! 4.7 rad/s crossover with the 5 ms sample).

use super::linearize::{drive_train, DriveTrainModel};
use super::SimError;
use crate::control::design::discrete::zero_order_hold;
use crate::control::design::lqg_ltr::{compensator, design, Design, DesignInput};
use crate::control::design::state_space::StateSpace;
use crate::control::design::ControllerDesign;
use crate::scenario::{Command, Scenario};
use crate::sea::waves::SeaParams;
use nalgebra::DMatrix;

/// The discretised design, shared by every set.
#[derive(Debug, Clone, PartialEq)]
pub struct LqgDesign {
    /// Compensator order (plant states + 2 integrators).
    n: usize,
    /// Observer transition, row-major n x n.
    phi: Vec<f64>,
    /// Input matrices of the error e and of the applied du, row-major n x 2 each.
    gam_e: Vec<f64>,
    gam_u: Vec<f64>,
    /// Regulator gain K_c, row-major 2 x n.
    k_c: Vec<f64>,
    /// Weight of the turbine-speed error (`turbine_speed_weight`).
    w_weight: f64,
    /// Per-unit bases of the outputs and of the field voltage [rad/s], [V], [V].
    w_ref: f64,
    v_ref: f64,
    v_f_base: f64,
    /// Actuator limits: throttle slew [1/s], field voltage ceiling [V].
    slew: f64,
    v_f_max: f64,
}

fn flat(m: &DMatrix<f64>) -> Vec<f64> {
    (0..m.nrows()).flat_map(|i| (0..m.ncols()).map(move |j| m[(i, j)])).collect()
}

impl LqgDesign {
    /// Designs the compensator for the scenario's plant and discretises it for the controller's
    /// sample period.
    pub fn new(sc: &Scenario, v_f_max: f64) -> Result<LqgDesign, SimError> {
        let p = &sc.controllers.lqg_ltr;
        let (model, weighted) = design_model(sc)?;
        let k = compensator(&weighted, p.mu, p.omega_p_rad_s, p.q).map_err(|e| setup(sc, "the design", e))?;
        let a_obs = &k.a_aug - &k.k_f * &k.c_aug;
        let m = k.b_aug.ncols();
        let mut inputs = DMatrix::zeros(a_obs.nrows(), 2 * m);
        inputs.view_mut((0, 0), (a_obs.nrows(), m)).copy_from(&k.k_f);
        inputs.view_mut((0, m), (a_obs.nrows(), m)).copy_from(&(-&k.b_aug));
        let (phi, gam) = zero_order_hold(&a_obs, &inputs, sc.stepping.controller_sample_s)
            .map_err(|e| setup(sc, "the discretisation", e))?;
        let n = phi.nrows();
        Ok(LqgDesign {
            n,
            phi: flat(&phi),
            gam_e: flat(&gam.columns(0, m).into_owned()),
            gam_u: flat(&gam.columns(m, m).into_owned()),
            k_c: flat(&k.k_c),
            w_weight: p.turbine_speed_weight,
            w_ref: model.turbine_speed_base,
            v_ref: model.bus_voltage_base,
            v_f_base: model.held0.field_voltage[0],
            slew: sc.controllers.governor.slew_rate_per_s,
            v_f_max,
        })
    }
}

fn setup(sc: &Scenario, what: &str, e: String) -> SimError {
    SimError::Setup(format!(
        "controllers.lqg_ltr: {what} at design_speed_kn = {} failed: {e}",
        sc.controllers.lqg_ltr.design_speed_kn
    ))
}

/// The plant the design is made for: the drive train linearised in calm water at
/// `controllers.lqg_ltr.design_speed_kn` (the PI loops holding the steady state, which does not
/// depend on which controller holds it), and the same with its turbine-speed output weighted by
/// `turbine_speed_weight`.
pub fn design_model(sc: &Scenario) -> Result<(DriveTrainModel, StateSpace), SimError> {
    let p = &sc.controllers.lqg_ltr;
    let mut op = sc.clone();
    op.controllers.design = ControllerDesign::Pi;
    op.sea = SeaParams::default();
    op.initial.speed_kn = p.design_speed_kn;
    op.commands = vec![Command {
        t_s: 0.0,
        speed_kn: Some(p.design_speed_kn),
        heading_deg: None,
        heading_rate_deg_s: None,
        online_sets: None,
        crash_stop: false,
    }];
    // Only the steady state is needed: no long trace.
    op.sim.duration_s = op.stepping.dt_s.max(op.stepping.controller_sample_s);
    let model = drive_train(&op).map_err(|e| setup(sc, "the linearisation", e.to_string()))?;
    let mut weighted = model.system.clone();
    weighted.c.row_mut(0).scale_mut(p.turbine_speed_weight);
    weighted.d.row_mut(0).scale_mut(p.turbine_speed_weight);
    Ok((model, weighted))
}

/// The design and its analysis (singular values, poles, margins) for the scenario's tuning, as
/// `aes-sim design lqg-ltr --plant aes` and the page's design tab show it.
pub fn analyse(sc: &Scenario) -> Result<Design, String> {
    sc.validate().map_err(|e| e.to_string())?;
    let p = &sc.controllers.lqg_ltr;
    let (_, weighted) = design_model(sc).map_err(|e| e.to_string())?;
    design(&DesignInput::from_plant(&weighted, p.mu, p.omega_p_rad_s, p.q))
}

/// One set's compensator state.
#[derive(Debug, Clone, PartialEq)]
pub struct LqgSet {
    /// Observer state x_k.
    x: Vec<f64>,
    /// Plant input deviation from `base`: throttle [fraction], field voltage [per unit of the
    /// design point's].
    u: [f64; 2],
    /// Actuator positions the deviations are measured from: throttle, field voltage [V].
    base: [f64; 2],
    /// The next observer state, built here and swapped in (no allocation in the sample).
    next: Vec<f64>,
}

impl LqgSet {
    /// At rest at the run's initial steady state (throttle, field voltage \[V\]).
    pub fn new(d: &LqgDesign, throttle0: f64, v_f0: f64) -> LqgSet {
        LqgSet { x: vec![0.0; d.n], u: [0.0; 2], base: [throttle0, v_f0], next: vec![0.0; d.n] }
    }

    /// One sample of period `ts` \[s\] with turbine speed `omega_t` [rad/s] and bus voltage
    /// `v_bus` \[V\]; returns the throttle and field voltage \[V\] to hold.
    pub fn update(&mut self, d: &LqgDesign, omega_t: f64, v_bus: f64, ts: f64) -> (f64, f64) {
        let e = [d.w_weight * (d.w_ref - omega_t) / d.w_ref, (d.v_ref - v_bus) / d.v_ref];
        let n = d.n;
        let mut du = [0.0; 2];
        for (r, du_r) in du.iter_mut().enumerate() {
            *du_r = (0..n).map(|j| d.k_c[r * n + j] * self.x[j]).sum();
        }
        // The actuators: throttle within [0, 1] and its slew, field voltage within [0, ceiling].
        let th_prev = self.base[0] + self.u[0];
        let th_cmd = (self.base[0] + self.u[0] + du[0] * ts).clamp(0.0, 1.0);
        let step = d.slew * ts;
        let throttle = th_prev + (th_cmd - th_prev).clamp(-step, step);
        let v_f = (self.base[1] + d.v_f_base * (self.u[1] + du[1] * ts)).clamp(0.0, d.v_f_max);
        let applied = [throttle - self.base[0], (v_f - self.base[1]) / d.v_f_base];
        // A field held at a limit by the bus error (at 0 V while the brake chopper holds the bus
        // above its set point in AC braking, for a hundred seconds) cannot act on it: the
        // compensator stops integrating the bus error, so the throttle loop settles the turbine
        // at its own set point instead of trading speed for bus voltage (conditional integration
        // at the output; without it the braking study ended 2.9 % under speed). Not applied to
        // the throttle: its limits are met only for seconds, which the observer rule handles, and
        // there it made the braking study's turbine speed worse (0.991 against 0.999 pu).
        let mut e = e;
        if (v_f <= 0.0 && e[1] < 0.0) || (v_f >= d.v_f_max && e[1] > 0.0) {
            e[1] = 0.0;
        }
        let du_applied = [(applied[0] - self.u[0]) / ts, (applied[1] - self.u[1]) / ts];
        for (i, x_i) in self.next.iter_mut().enumerate() {
            let mut acc = 0.0;
            for j in 0..n {
                acc += d.phi[i * n + j] * self.x[j];
            }
            for c in 0..2 {
                acc += d.gam_e[i * 2 + c] * e[c] + d.gam_u[i * 2 + c] * du_applied[c];
            }
            *x_i = acc;
        }
        std::mem::swap(&mut self.x, &mut self.next);
        self.u = applied;
        (throttle, v_f)
    }
}
