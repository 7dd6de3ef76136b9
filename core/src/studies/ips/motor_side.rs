//! Motor side of the Purdue MVDC testbed (thesis ch. 4.1.2, 4.2.2, 4.3.2, 4.4.2): a 50 hp,
//! 460 V, 4-pole induction motor in the synchronous qd frame aligned with the stator voltage
//! (v_ds = 0), a quadratic propeller load, torque-trim control, AMTPA control with a rotor-flux
//! limit, and current hysteresis represented by its equivalent continuous control.
//!
//! Machine parameters: the thesis prints none. The defaults are the maximum-torque-per-ampere
//! reconstruction in core/data/purdue_testbed_params.md (L_m = 30.46 mH, L_ls = L_lr = 1.335 mH,
//! r_r = 0.0530 ohm, r_s = 0.117 ohm), which reproduces Table 4.2.
//!
//! Two places where the thesis' printed equations disagree with the machine physics, and what we
//! use: (1) the torque threshold (4.23) and the flux-limited slip (4.24) are off by a factor of
//! P/2 against T = (3/2)(P/2) lambda_r^2 omega_s / r_r (with 4.22's own convention P = poles); we
//! use T_thres = 3 P omega_s,set lambda_max^2 / (4 r_r) and omega_s = 4 T r_r / (3 P lambda_max^2),
//! which join continuously at the threshold. (2) The equivalent control (4.49-4.51) takes
//! v_qs = (A_m i)_1, whose sign is opposite to the steady state of (4.16) (0 = A_m i + e_1 v_qs); we
//! use v_qs = -(A_m i)_1 with i_qs from the current-magnitude constraint.

use super::numerical_jacobian;
use crate::control::linear::{margins, LinearSystem, Margins};
use crate::numerics::powi;
use nalgebra::{DMatrix, Matrix4, Vector4};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::ops::RangeInclusive;

/// Range of the torque command T* [N m] the steady state accepts (the testbed's motor is rated
/// near 200 N m; beyond this the model's numbers lose meaning).
pub const TORQUE_RANGE_NM: RangeInclusive<f64> = 0.01..=10_000.0;

/// Motor-side parameters (SI; magnitudes are peak qd values, as the thesis' tables are).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MotorSideParams {
    /// Stator resistance r_s \[ohm\]. Reconstruction (reproduces Table 4.2's 411.91 V): 0.117.
    pub r_s: f64,
    /// Rotor resistance r_r \[ohm\]. Reconstruction (slip-power identity): 0.0530.
    pub r_r: f64,
    /// Stator and rotor leakage inductances \[H\]. Reconstruction: 1.335 mH each.
    pub l_ls: f64,
    pub l_lr: f64,
    /// Magnetizing inductance L_m \[H\]. Reconstruction: 30.46 mH.
    pub l_m: f64,
    /// Number of poles P_m [-]: 4 (ch. 4.1).
    pub poles: f64,
    /// Motor and propeller inertia I_p [kg m^2]. Not given; 0.5 (0.4 for a 50 hp rotor plus a
    /// dynamometer coupling).
    pub inertia: f64,
    /// Zero-speed torque coefficient k_q0 [-] of eq. 4.19: 0.05.
    pub kq0: f64,
    /// Water density [kg/m^3].
    pub rho: f64,
    /// Propeller diameter D \[m\]. Not given; 0.29324 so that T* = 100 N m is carried at
    /// omega_r = 377 rad/s, as Table 4.2 reports (eq. 4.31).
    pub diameter: f64,
    /// Maximum rotor flux lambda_r,max [V s]. Not given; 1.261, which puts the torque threshold at
    /// 150 N m: the 100 N m point (rotor flux 1.03 V s) lies below it, the 200 N m point above.
    pub lambda_r_max: f64,
    /// Torque-trim time constant tau \[s\] of eq. 4.21. Not given; 0.05.
    pub trim_tau: f64,
    /// Factor on the machine's r_r, L_r, L_m used by the AMTPA estimates (the primes of
    /// eq. 4.22) [-]; 1 means the estimates are exact.
    pub estimate_factor: f64,
}

impl Default for MotorSideParams {
    fn default() -> Self {
        MotorSideParams {
            r_s: 0.117,
            r_r: 0.0530,
            l_ls: 1.335e-3,
            l_lr: 1.335e-3,
            l_m: 30.46e-3,
            poles: 4.0,
            inertia: 0.5,
            kq0: 0.05,
            rho: 1025.0,
            diameter: 0.29324,
            lambda_r_max: 1.261,
            trim_tau: 0.05,
            estimate_factor: 1.0,
        }
    }
}

/// The motor-side steady state (Table 4.2 quantities, SI).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MotorSteadyState {
    /// Torque command T* and the measured torque T_m0 [N m].
    pub t_star: f64,
    pub t_m0: f64,
    /// Torque reference after the trim, T_m0** [N m].
    pub t_ref0: f64,
    /// Electrical rotor speed omega_r0 [rad/s] and slip omega_s0 [rad/s].
    pub omega_r0: f64,
    pub omega_s0: f64,
    /// Stator and rotor current magnitudes [A peak] and stator voltage magnitude [V peak].
    pub i_s_mag: f64,
    pub i_r_mag: f64,
    pub v_s_mag: f64,
    /// The currents i_qs, i_ds, i_qr, i_dr \[A\] and the stator q voltage \[V\].
    pub currents: [f64; 4],
    pub v_qs: f64,
    /// Whether the flux limit is active (T** above the threshold).
    pub above_threshold: bool,
    /// The torque threshold [N m].
    pub t_threshold: f64,
    /// AMTPA iterations needed.
    pub iterations: u32,
}

impl MotorSideParams {
    fn l_s(&self) -> f64 {
        self.l_ls + self.l_m
    }
    fn l_r(&self) -> f64 {
        self.l_lr + self.l_m
    }
    /// Constant slip of the MTPA region, omega_s,set = r_r'/L_r' [rad/s].
    pub fn slip_set(&self) -> f64 {
        self.r_r / self.l_r()
    }
    /// Torque threshold of the flux limit [N m].
    pub fn torque_threshold(&self) -> f64 {
        let k = self.estimate_factor;
        3.0 * self.poles * self.slip_set() * (self.lambda_r_max * self.lambda_r_max) / (4.0 * self.r_r * k)
    }
    /// AMTPA slip command omega_s*(T**) [rad/s] (eqs. 4.23-4.24, see the module note).
    pub fn slip_command(&self, t_ref: f64) -> f64 {
        if t_ref <= self.torque_threshold() {
            self.slip_set()
        } else {
            4.0 * t_ref * self.r_r * self.estimate_factor / (3.0 * self.poles * (self.lambda_r_max * self.lambda_r_max))
        }
    }
    /// d omega_s* / d T** [rad/s per N m].
    fn slip_slope(&self, t_ref: f64) -> f64 {
        if t_ref <= self.torque_threshold() {
            0.0
        } else {
            4.0 * self.r_r * self.estimate_factor / (3.0 * self.poles * (self.lambda_r_max * self.lambda_r_max))
        }
    }
    /// Theta(omega_s) of eq. 4.49: |i_s|^2 = Theta T** (from eq. 4.22 with the estimates).
    fn theta(&self, ws: f64) -> f64 {
        let k = self.estimate_factor;
        let (rr, lr, lm) = (self.r_r * k, self.l_r() * k, self.l_m * k);
        4.0 * (rr * rr + ws * ws * lr * lr) / (3.0 * self.poles * ws * lm * lm * rr)
    }
    fn dtheta_dws(&self, ws: f64) -> f64 {
        let k = self.estimate_factor;
        let (rr, lr, lm) = (self.r_r * k, self.l_r() * k, self.l_m * k);
        4.0 / (3.0 * self.poles * lm * lm * rr) * (lr * lr - rr * rr / (ws * ws))
    }
    /// Current magnitude command I* (eq. 4.22) [A peak].
    pub fn current_command(&self, t_ref: f64) -> f64 {
        (self.theta(self.slip_command(t_ref)) * t_ref).sqrt()
    }
    /// Propeller torque T_p = k_q0 rho D^5 n^2 (eq. 4.19) at shaft speed `w_rm` [rad/s].
    pub fn propeller_torque(&self, w_rm: f64) -> f64 {
        let n = w_rm / (2.0 * PI);
        self.kq0 * self.rho * powi(self.diameter, 5) * n * n.abs()
    }
    fn mass(&self) -> Matrix4<f64> {
        let (ls, lr, lm) = (self.l_s(), self.l_r(), self.l_m);
        Matrix4::new(ls, 0.0, lm, 0.0, 0.0, ls, 0.0, lm, lm, 0.0, lr, 0.0, 0.0, lm, 0.0, lr)
    }
    /// A_m(omega_e, omega_s) of eq. 4.18.
    fn a_m(&self, we: f64, ws: f64) -> Matrix4<f64> {
        let (ls, lr, lm, rs, rr) = (self.l_s(), self.l_r(), self.l_m, self.r_s, self.r_r);
        Matrix4::new(
            -rs,
            -we * ls,
            0.0,
            -we * lm,
            we * ls,
            -rs,
            we * lm,
            0.0,
            0.0,
            -ws * lm,
            -rr,
            -ws * lr,
            ws * lm,
            0.0,
            ws * lr,
            -rr,
        )
    }
    /// Electromagnetic torque (3P/4) L_m (i_qs i_dr - i_qr i_ds) [N m] (eq. 4.20).
    pub fn torque(&self, i: &[f64]) -> f64 {
        0.75 * self.poles * self.l_m * (i[0] * i[3] - i[2] * i[1])
    }
    fn dtorque_di(&self, i: &[f64]) -> [f64; 4] {
        let k = 0.75 * self.poles * self.l_m;
        [k * i[3], -k * i[2], -k * i[1], k * i[0]]
    }

    /// The five-step steady-state procedure of ch. 4.2.2 for torque command `t_star` [N m].
    pub fn steady_state(&self, t_star: f64) -> Result<MotorSteadyState, String> {
        super::check_input("torque command T*", "N m", t_star, &TORQUE_RANGE_NM)?;
        // I: the propeller carries T* at steady state (eq. 4.31).
        let c = self.kq0 * self.rho * powi(self.diameter, 5) / ((2.0 * PI) * (2.0 * PI));
        let w_rm = (t_star / c).sqrt();
        let mut t_ref = t_star;
        for it in 1..=50 {
            // II: AMTPA commands.
            let ws = self.slip_command(t_ref);
            let i_mag = self.current_command(t_ref);
            // III-IV: currents and voltage with v_ds = 0: 0 = A i + e1 v, |i_s| = I*.
            let we = 0.5 * self.poles * w_rm + ws;
            let a = self.a_m(we, ws);
            let inv = a.try_inverse().ok_or("singular motor equations at the operating point")?;
            let unit: Vector4<f64> = -inv * Vector4::new(1.0, 0.0, 0.0, 0.0); // currents per volt
            let v = i_mag / libm::hypot(unit[0], unit[1]);
            let i = unit * v;
            let cur = [i[0], i[1], i[2], i[3]];
            // V: the torque the machine makes; trim the reference if the estimates are off.
            let t_m = self.torque(&cur);
            if (t_m - t_star).abs() < 1e-10 * t_star || it == 50 {
                let steady = MotorSteadyState {
                    t_star,
                    t_m0: t_m,
                    t_ref0: t_ref,
                    omega_r0: 0.5 * self.poles * w_rm,
                    omega_s0: ws,
                    i_s_mag: libm::hypot(i[0], i[1]),
                    i_r_mag: libm::hypot(i[2], i[3]),
                    v_s_mag: v.abs(),
                    currents: cur,
                    v_qs: v,
                    above_threshold: t_ref > self.torque_threshold(),
                    t_threshold: self.torque_threshold(),
                    iterations: it,
                };
                let [i_qs, i_ds, i_qr, i_dr] = steady.currents;
                super::check_steady(
                    "motor-side",
                    &format!("T* = {t_star} N m"),
                    &[
                        ("t_m0", steady.t_m0),
                        ("t_ref0", steady.t_ref0),
                        ("omega_r0", steady.omega_r0),
                        ("omega_s0", steady.omega_s0),
                        ("i_qs", i_qs),
                        ("i_ds", i_ds),
                        ("i_qr", i_qr),
                        ("i_dr", i_dr),
                        ("v_s_mag", steady.v_s_mag),
                        ("t_threshold", steady.t_threshold),
                    ],
                )?;
                return Ok(steady);
            }
            t_ref *= t_star / t_m;
        }
        Err("AMTPA steady state did not converge".into())
    }

    /// Open-loop dynamics. `x` = [i_qs, i_ds, i_qr, i_dr, omega_rm] (five states, T** fixed at
    /// `t_ref`) or with T** as sixth state; `v_qs` the input; `t_star` the (constant) command.
    pub fn open_loop_rhs(&self, x: &[f64], v_qs: f64, t_ref_fixed: f64, t_star: f64) -> Vec<f64> {
        let six = x.len() == 6;
        let t_ref = if six { x[5] } else { t_ref_fixed };
        let ws = self.slip_command(t_ref);
        let we = 0.5 * self.poles * x[4] + ws;
        let i = Vector4::new(x[0], x[1], x[2], x[3]);
        let m_inv = self.mass().try_inverse().unwrap_or_else(Matrix4::zeros);
        let di = m_inv * (self.a_m(we, ws) * i + Vector4::new(v_qs, 0.0, 0.0, 0.0)); // eq. 4.16
        let t_m = self.torque(&x[..4]);
        let mut out = vec![di[0], di[1], di[2], di[3], (t_m - self.propeller_torque(x[4])) / self.inertia]; // eq. 4.20
        if six {
            out.push((t_star - t_m) / self.trim_tau); // eq. 4.21 with T* constant
        }
        out
    }

    /// The equivalent control of the current hysteresis (eq. 4.49, see the module note): the stator
    /// voltage that holds |i_s|^2 = Theta T** at the present state.
    pub fn equivalent_voltage(&self, x: &[f64], sign_qs: f64) -> f64 {
        let ws = self.slip_command(x[5]);
        let we = 0.5 * self.poles * x[4] + ws;
        let s = (self.theta(ws) * x[5] - x[1] * x[1]).max(0.0).sqrt();
        self.r_s * sign_qs * s + we * (self.l_s() * x[1] + self.l_m * x[3])
    }

    /// Closed-loop dynamics: the six-state model with the equivalent control, input T*.
    pub fn closed_loop_rhs(&self, x: &[f64], t_star: f64, sign_qs: f64) -> Vec<f64> {
        let v = self.equivalent_voltage(x, sign_qs);
        self.open_loop_rhs(x, v, 0.0, t_star)
    }

    /// Analytic Jacobian of the open-loop dynamics with respect to the state (eqs. 4.34-4.36,
    /// 4.38) and the input v_qs, at state `x`.
    fn open_loop_jacobian(&self, x: &[f64], t_ref_fixed: f64) -> (DMatrix<f64>, DMatrix<f64>) {
        let n = x.len();
        let six = n == 6;
        let t_ref = if six { x[5] } else { t_ref_fixed };
        let ws = self.slip_command(t_ref);
        let we = 0.5 * self.poles * x[4] + ws;
        let m_inv = self.mass().try_inverse().unwrap_or_else(Matrix4::zeros);
        let ma = m_inv * self.a_m(we, ws);
        let (ls, lr, lm) = (self.l_s(), self.l_r(), self.l_m);
        // d(A i)/d omega_e and d(A i)/d omega_s.
        let d_we = Vector4::new(-(ls * x[1] + lm * x[3]), ls * x[0] + lm * x[2], 0.0, 0.0);
        let d_ws = Vector4::new(0.0, 0.0, -(lm * x[1] + lr * x[3]), lm * x[0] + lr * x[2]);
        let col_w = m_inv * d_we * (0.5 * self.poles);
        let mut j = DMatrix::zeros(n, n);
        for r in 0..4 {
            for c in 0..4 {
                j[(r, c)] = ma[(r, c)];
            }
            j[(r, 4)] = col_w[r];
        }
        let dt = self.dtorque_di(x);
        let c2 = 2.0 * self.kq0 * self.rho * powi(self.diameter, 5) / ((2.0 * PI) * (2.0 * PI));
        for c in 0..4 {
            j[(4, c)] = dt[c] / self.inertia;
        }
        j[(4, 4)] = -c2 * x[4].abs() / self.inertia; // eq. 4.35
        if six {
            let col_s = m_inv * (d_we + d_ws) * self.slip_slope(t_ref); // eq. 4.38 through omega_e and omega_s
            for r in 0..4 {
                j[(r, 5)] = col_s[r];
            }
            for c in 0..4 {
                j[(5, c)] = -dt[c] / self.trim_tau; // eq. 4.36
            }
        }
        let mut b = DMatrix::zeros(n, 1);
        for r in 0..4 {
            b[(r, 0)] = m_inv[(r, 0)];
        }
        (j, b)
    }

    /// Gradient of the equivalent voltage with respect to the six states (eqs. 4.50-4.53).
    fn equivalent_voltage_gradient(&self, x: &[f64], sign_qs: f64) -> [f64; 6] {
        let ws = self.slip_command(x[5]);
        let dws = self.slip_slope(x[5]);
        let we = 0.5 * self.poles * x[4] + ws;
        let th = self.theta(ws);
        let s = (th * x[5] - x[1] * x[1]).max(1e-300).sqrt();
        let flux_d = self.l_s() * x[1] + self.l_m * x[3];
        [
            0.0,
            -self.r_s * sign_qs * x[1] / s + we * self.l_s(),
            0.0,
            we * self.l_m,
            0.5 * self.poles * flux_d,
            self.r_s * sign_qs * (th + x[5] * self.dtheta_dws(ws) * dws) / (2.0 * s) + dws * flux_d,
        ]
    }

    /// State vector at the steady state (five or six states).
    pub fn steady_vector(&self, steady: &MotorSteadyState, six: bool) -> Vec<f64> {
        let mut x = steady.currents.to_vec();
        x.push(2.0 * steady.omega_r0 / self.poles);
        if six {
            x.push(steady.t_ref0);
        }
        x
    }

    /// Open-loop linear model (eqs. 4.43-4.47): input stator voltage v_qs, output stator current
    /// magnitude. Five states below the torque threshold, six (with T**) above it.
    pub fn open_loop(&self, steady: &MotorSteadyState) -> LinearSystem {
        let six = steady.above_threshold;
        let x = self.steady_vector(steady, six);
        let (a, b) = self.open_loop_jacobian(&x, steady.t_ref0);
        let n = x.len();
        let mut c = DMatrix::zeros(1, n);
        c[(0, 0)] = x[0] / steady.i_s_mag;
        c[(0, 1)] = x[1] / steady.i_s_mag;
        let mut states = vec!["i_qs", "i_ds", "i_qr", "i_dr", "omega_rm"];
        if six {
            states.push("t_ref");
        }
        LinearSystem { a, b, c, d: DMatrix::zeros(1, 1), states }
    }

    /// Closed-loop linear model (ch. 4.4.2): the six-state model with the equivalent control
    /// substituted; input torque command T*, output measured torque T_m.
    pub fn closed_loop(&self, steady: &MotorSteadyState) -> LinearSystem {
        let x = self.steady_vector(steady, true);
        let sign = steady.currents[0].signum();
        let (mut a, b_v) = self.open_loop_jacobian(&x, steady.t_ref0);
        let g = self.equivalent_voltage_gradient(&x, sign);
        for r in 0..6 {
            for c in 0..6 {
                a[(r, c)] += b_v[(r, 0)] * g[c];
            }
        }
        let mut b = DMatrix::zeros(6, 1);
        b[(5, 0)] = 1.0 / self.trim_tau;
        let dt = self.dtorque_di(&x);
        let c = DMatrix::from_row_slice(1, 6, &[dt[0], dt[1], dt[2], dt[3], 0.0, 0.0]);
        LinearSystem {
            a,
            b,
            c,
            d: DMatrix::zeros(1, 1),
            states: vec!["i_qs", "i_ds", "i_qr", "i_dr", "omega_rm", "t_ref"],
        }
    }

    /// Margins of the torque-trim loop: L(s) = G(s) / (tau s), G the path from the torque
    /// reference T** to the measured torque with the equivalent control in place.
    pub fn trim_margins(&self, steady: &MotorSteadyState) -> Margins {
        let cl = self.closed_loop(steady);
        // The plant: the first five rows of the closed loop, T** (state 6) as its input.
        let a = cl.a.view((0, 0), (5, 5)).into_owned();
        let b = cl.a.view((0, 5), (5, 1)).into_owned();
        let c = cl.c.view((0, 0), (1, 5)).into_owned();
        let plant = LinearSystem { a, b, c, d: DMatrix::zeros(1, 1), states: vec![] };
        let tau = self.trim_tau;
        margins(&|w: f64| plant.response(w) / num_complex::Complex64::new(0.0, tau * w), 1e-3, 1e6)
    }

    /// Numerical Jacobians of the nonlinear open-loop and closed-loop dynamics at the steady state
    /// (for checking the analytic linearizations).
    pub fn numerical_open_loop(&self, steady: &MotorSteadyState) -> DMatrix<f64> {
        let x = self.steady_vector(steady, steady.above_threshold);
        numerical_jacobian(&|x: &[f64]| self.open_loop_rhs(x, steady.v_qs, steady.t_ref0, steady.t_star), &x)
    }

    pub fn numerical_closed_loop(&self, steady: &MotorSteadyState) -> DMatrix<f64> {
        let x = self.steady_vector(steady, true);
        let sign = steady.currents[0].signum();
        numerical_jacobian(&|x: &[f64]| self.closed_loop_rhs(x, steady.t_star, sign), &x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Table 4.2 (T* = 100 N m), the thesis' "steady-state solution" column, within 1e-4
    /// relative (measured: omega_r0 8.4e-5, |i_s| 5.5e-5, omega_s0 4.3e-5, |i_r| 3.9e-5, |v_s|
    /// 3.8e-5; T_m0 is the torque command, to round-off).
    #[test]
    fn table_4_2() {
        let p = MotorSideParams::default();
        let s = p.steady_state(100.0).unwrap();
        let check = |name: &str, got: f64, want: f64| {
            assert!((got - want).abs() <= 1e-4 * want.abs(), "{name}: {got} vs {want}");
        };
        check("T_m0", s.t_m0, 100.0);
        check("omega_r0", s.omega_r0, 377.0);
        check("omega_s0", s.omega_s0, 1.667);
        check("|i_s|", s.i_s_mag, 47.80);
        check("|i_r|", s.i_r_mag, 32.38);
        check("|v_s|", s.v_s_mag, 411.91);
        assert!(!s.above_threshold);
        assert_eq!(s.iterations, 1);
        let s2 = p.steady_state(200.0).unwrap();
        assert!(s2.above_threshold && s2.omega_s0 > s.omega_s0);
    }

    /// Analytic linearization against a numerical Jacobian of the nonlinear model, relative 1e-8
    /// (measured at most 1.0e-9), below (five states) and above (six states) the torque threshold,
    /// open and closed loop.
    #[test]
    fn analytic_matches_numerical_jacobian() {
        let p = MotorSideParams::default();
        for t in [100.0, 200.0] {
            let s = p.steady_state(t).unwrap();
            for (name, a, n) in [
                ("open", p.open_loop(&s).a, p.numerical_open_loop(&s)),
                ("closed", p.closed_loop(&s).a, p.numerical_closed_loop(&s)),
            ] {
                let scale = n.abs().max();
                let err = (&a - &n).abs().max();
                assert!(err <= 1e-8 * scale, "{name} loop at {t} N m: max error {err:e} of {scale:e}");
            }
        }
    }
}
