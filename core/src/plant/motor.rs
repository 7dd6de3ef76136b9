//! Induction motor by its per-phase equivalent circuit (thesis ch. 2.2.2, eqs. 2.5-2.6, Table 2.1)
//! and its volts-per-hertz slip-speed control (ch. 2.2.4).
//!
//! The circuit is solved with admittances written in the slip speed omega_s = s omega_e, so that it
//! stays finite at zero slip and at standstill: the rotor branch R_r/s + j omega_e L_r has the
//! admittance omega_s / (omega_e (R_r + j omega_s L_r)).
//!
//! Eq. 2.5 prints Q_m = 3 eta_m |I_r|^2 R_rm / omega_rm, which is the rotor copper loss over the
//! shaft speed. The power converted to mechanical form is 3 |I_r|^2 R_r (1-s)/s (the
//! "electromechanical resistor" the same section describes), so the torque used here is
//! Q_e = 3 |I_r|^2 R_r / (s omega_e / p) = p P_airgap / omega_e.

use crate::as_printed::AsPrintedParams;
use crate::control::DiscretePi;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Motor constants in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InductionMotor {
    pub r_s: f64,
    pub l_s: f64,
    pub r_r: f64,
    pub l_r: f64,
    pub l_m: f64,
    /// Pole pairs p: omega_r = p omega_rm.
    pub pole_pairs: f64,
    /// Rated phase rms voltage \[V\].
    pub v_rated: f64,
    /// Rated electrical frequency [rad/s].
    pub omega_rated: f64,
    /// Rated shaft power \[W\].
    pub p_rated: f64,
    /// eta_m of eq. 2.5 [-].
    pub eta_m: f64,
    /// Eq. 2.5 as printed: the torque is the rotor copper loss over the shaft speed
    /// (`as_printed.eq_2_5_copper_loss`).
    pub copper_loss_torque: bool,
}

/// The motor's operating point.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct MotorPoint {
    /// Electrical input 3 Re{v_m i_in^*} \[W\] (the inverter's output, Table 5.6).
    pub p_in: f64,
    /// Air-gap power \[W\].
    pub p_airgap: f64,
    /// Stator copper loss \[W\].
    pub p_stator_loss: f64,
    /// Rotor copper loss \[W\].
    pub p_rotor_loss: f64,
    /// Electromagnetic torque Q_e [N m].
    pub torque_em: f64,
    /// Shaft torque Q_m after the eta_m loss [N m] (eq. 2.5).
    pub torque: f64,
    /// Stator current |i_in| [A rms].
    pub i_in: f64,
}

impl InductionMotor {
    pub fn new(p: &MotorParams) -> InductionMotor {
        InductionMotor {
            r_s: p.stator_resistance_ohm,
            l_s: p.stator_inductance_h,
            r_r: p.rotor_resistance_ohm,
            l_r: p.rotor_inductance_h,
            l_m: p.magnetizing_inductance_h,
            pole_pairs: p.pole_pairs as f64,
            v_rated: p.rated_voltage_ll_v / 3f64.sqrt(),
            omega_rated: 2.0 * PI * p.rated_frequency_hz,
            p_rated: p.rated_power_w,
            eta_m: p.efficiency,
            copper_loss_torque: false,
        }
    }

    /// The motor with the switches of `as_printed`: Table 2.1's P read as poles
    /// (`motor_p_is_poles`: half as many pole pairs) and eq. 2.5's torque as printed
    /// (`eq_2_5_copper_loss`).
    pub fn new_as(p: &MotorParams, printed: &AsPrintedParams) -> InductionMotor {
        let mut m = InductionMotor::new(p);
        if printed.motor_p_is_poles {
            m.pole_pairs = p.pole_pairs as f64 / 2.0;
        }
        m.copper_loss_torque = printed.eq_2_5_copper_loss;
        m
    }

    /// Volts-per-hertz law v_m = (omega_e / omega_rated) v_rated, limited by what the inverter can
    /// make, `v_max` [V phase rms].
    pub fn phase_voltage(&self, omega_e: f64, v_max: f64) -> f64 {
        (omega_e.abs() / self.omega_rated * self.v_rated).min(v_max)
    }

    /// Solves the equivalent circuit for phase voltage `v` [V rms], excitation frequency `omega_e`
    /// and slip speed `omega_s` [rad/s electrical], with the shaft at `omega_rm` [rad/s].
    pub fn operate(&self, v: f64, omega_e: f64, omega_s: f64, omega_rm: f64) -> MotorPoint {
        if omega_e.abs() < 1e-9 || v <= 0.0 {
            return MotorPoint::default();
        }
        // In real arithmetic (the time loop calls this eight times a step; complex divisions cost
        // ten real ones): rotor admittance y_r = g (R_r - j omega_s L_r) with
        // g = omega_s / (omega_e (R_r^2 + omega_s^2 L_r^2)), magnetising -j / (omega_e L_m),
        // Y = y_m + y_r; with D = 1 + (R_s + j omega_e L_s) Y the air-gap voltage is v / D and the
        // stator current v Y / D.
        let x_r = omega_s * self.l_r;
        let g = omega_s / (omega_e * (self.r_r * self.r_r + x_r * x_r));
        let (y_re, y_im) = (g * self.r_r, -g * x_r - 1.0 / (omega_e * self.l_m));
        let x_s = omega_e * self.l_s;
        let (d_re, d_im) = (1.0 + self.r_s * y_re - x_s * y_im, self.r_s * y_im + x_s * y_re);
        let inv_d2 = 1.0 / (d_re * d_re + d_im * d_im);
        let v2_inv = v * v * inv_d2;
        let p_airgap = 3.0 * v2_inv * y_re;
        let i_in_sq = v2_inv * (y_re * y_re + y_im * y_im);
        let i_in_re = v * (y_re * d_re + y_im * d_im) * inv_d2;
        let torque_em = if self.copper_loss_torque {
            // Eq. 2.5 as printed: 3 |I_r|^2 R_r / omega_rm, the shaft speed kept at 1 rad/s or more.
            let w = if omega_rm.abs() < 1.0 { 1f64.copysign(omega_rm) } else { omega_rm };
            p_airgap * omega_s / omega_e / w
        } else {
            self.pole_pairs * p_airgap / omega_e
        };
        // eta_m takes its loss out of whatever flows through the shaft, in either direction.
        let torque = if torque_em * omega_rm >= 0.0 { self.eta_m * torque_em } else { torque_em / self.eta_m };
        MotorPoint {
            p_in: 3.0 * v * i_in_re,
            p_airgap,
            p_stator_loss: 3.0 * self.r_s * i_in_sq,
            p_rotor_loss: p_airgap * omega_s / omega_e,
            torque_em,
            torque,
            i_in: i_in_sq.sqrt(),
        }
    }

    /// The operating point under volts-per-hertz control: omega_e = omega_r + omega_s.
    pub fn operate_vhz(&self, omega_rm: f64, omega_s: f64, v_max: f64) -> MotorPoint {
        let omega_e = self.pole_pairs * omega_rm + omega_s;
        self.operate(self.phase_voltage(omega_e, v_max), omega_e, omega_s, omega_rm)
    }

    fn shaft_torque(&self, omega_rm: f64, omega_s: f64, v_max: f64) -> f64 {
        self.operate_vhz(omega_rm, omega_s, v_max).torque
    }

    /// The slip speed of peak motoring torque at shaft speed `omega_rm` with the inverter limit
    /// `v_max` (the dynamic saturation of ch. 2.2.4), by Newton's method on dQ/domega_s with central
    /// differences, started from `guess` (the previous sample's answer). Falls back to a golden
    /// section search when Newton does not settle.
    pub fn peak_torque_slip(&self, omega_rm: f64, v_max: f64, guess: f64) -> f64 {
        self.peak_slip_dir(omega_rm, v_max, guess, 1.0)
    }

    /// The magnitude of the negative slip of peak generating (braking) torque.
    pub fn peak_braking_slip(&self, omega_rm: f64, v_max: f64, guess: f64) -> f64 {
        self.peak_slip_dir(omega_rm, v_max, guess, -1.0)
    }

    /// The peak of `dir` Q(`dir` x) over x > 0 found by a scan and a golden section around its
    /// best point, so the global one (`dir` = 1: motoring, -1: braking). Near and through zero
    /// shaft speed the volts-per-hertz torque curve has two humps (the field reverses where
    /// omega_e = 0, x = p |omega_rm|), and the warm-started Newton of [`Self::peak_torque_slip`]
    /// may settle on the lesser one, leaving a reversing shaft with a third of its braking torque;
    /// runs that go astern use this instead.
    pub fn peak_slip_scan(&self, omega_rm: f64, v_max: f64, dir: f64) -> f64 {
        let q = |x: f64| dir * self.shaft_torque(omega_rm, dir * x, v_max);
        const N: usize = 24;
        let (lo, hi) = (1e-3, 20.0 * self.r_r / (self.l_s + self.l_r));
        let ratio = libm::pow(hi / lo, 1.0 / (N - 1) as f64);
        // On the stack: this runs at every controller sample of a run that goes astern.
        let mut xs = [0.0; N];
        let mut x = lo / ratio;
        for v in xs.iter_mut() {
            x *= ratio;
            *v = x;
        }
        let best = (0..N).max_by(|&a, &b| q(xs[a]).total_cmp(&q(xs[b]))).unwrap_or(0);
        golden_max(q, xs[best.saturating_sub(1)], xs[(best + 1).min(N - 1)], 40)
    }

    /// Peak of dir * Q(dir * x) over x > 0.
    fn peak_slip_dir(&self, omega_rm: f64, v_max: f64, guess: f64, dir: f64) -> f64 {
        let q = |x: f64| dir * self.shaft_torque(omega_rm, dir * x, v_max);
        let mut x = if guess > 0.0 { guess } else { self.r_r / (self.l_s + self.l_r) };
        for _ in 0..12 {
            let h = 1e-4 * x.max(1e-3);
            let (qm, q0, qp) = (q(x - h), q(x), q(x + h));
            let d1 = (qp - qm) / (2.0 * h);
            let d2 = (qp - 2.0 * q0 + qm) / (h * h);
            if d2 >= 0.0 || !d1.is_finite() || !d2.is_finite() {
                break;
            }
            let next = (x - d1 / d2).clamp(0.5 * x, 2.0 * x);
            if (next - x).abs() < 1e-9 * x.max(1.0) {
                return next;
            }
            x = next;
        }
        // Golden section on a generous bracket.
        golden_max(q, 1e-6, 20.0 * self.r_r / (self.l_s + self.l_r), 80)
    }

    /// Whether slip `omega_s` [rad/s] lies below both upper limits of the slip controller at
    /// shaft speed `omega_rm`: below the peak-torque slip (the torque still rises there) and
    /// below the slip of power `p_max`. A quick test (two circuit evaluations) that lets the
    /// caller skip the solvers; false whenever in doubt.
    pub fn below_slip_limits(&self, omega_rm: f64, v_max: f64, omega_s: f64, p_max: f64) -> bool {
        if !(omega_s > 0.0 && omega_rm > 0.0) {
            return false;
        }
        let q = self.shaft_torque(omega_rm, omega_s, v_max);
        // The torque curve has one maximum: if it is higher 0.1 % further on, the peak lies
        // beyond (by far more than the peak solver's 1e-9). The margin on the power keeps the
        // answer clear of the power solver's tolerance (1e-10).
        let q_up = self.shaft_torque(omega_rm, omega_s * 1.001, v_max);
        q_up > q && q * omega_rm < p_max * (1.0 - 1e-6)
    }

    /// The slip speed in [0, `omega_s_peak`] at which the shaft power Q_m omega_rm equals `p_max`,
    /// or `omega_s_peak` if even the peak torque stays below it.
    pub fn power_limited_slip(&self, omega_rm: f64, v_max: f64, omega_s_peak: f64, p_max: f64) -> f64 {
        if omega_rm <= 0.0 {
            return omega_s_peak;
        }
        self.slip_for_torque(omega_rm, v_max, omega_s_peak, p_max / omega_rm)
    }

    /// Braking side: the magnitude of the negative slip in [0, `peak`] at which the power the shaft
    /// returns, -Q_m omega_rm, equals `p_max`, or `peak` if the braking torque never gets there.
    pub fn power_limited_braking_slip(&self, omega_rm: f64, v_max: f64, peak: f64, p_max: f64) -> f64 {
        if omega_rm <= 0.0 {
            return peak;
        }
        let f = |x: f64| -self.shaft_torque(omega_rm, -x, v_max) * omega_rm - p_max;
        if f(peak) <= 0.0 {
            return peak;
        }
        crate::numerics::bisect(f, 0.0, peak, 60)
    }

    /// The slip speed in [0, `omega_s_peak`] at which the shaft torque equals `q_target` [N m]
    /// (regula falsi, Illinois variant; torque rises monotonically there). Returns the end of the
    /// interval when the target lies outside it.
    pub fn slip_for_torque(&self, omega_rm: f64, v_max: f64, omega_s_peak: f64, q_target: f64) -> f64 {
        let f = |ws: f64| self.shaft_torque(omega_rm, ws, v_max) - q_target;
        let (mut a, mut b) = (0.0, omega_s_peak);
        let (mut fa, mut fb) = (f(a), f(b));
        if fb <= 0.0 {
            return omega_s_peak;
        }
        if fa >= 0.0 {
            return 0.0;
        }
        let tol = 1e-10 * q_target.abs().max(1.0);
        let mut side = 0;
        for _ in 0..100 {
            let c = (a * fb - b * fa) / (fb - fa);
            let fc = f(c);
            if fc.abs() < tol || (b - a) < 1e-13 {
                return c;
            }
            if fc > 0.0 {
                b = c;
                fb = fc;
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                a = c;
                fa = fc;
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        0.5 * (a + b)
    }
}

/// The maximum of `q` between `a` and `b` by `iterations` steps of the golden section (one maximum
/// there assumed): the middle of the last bracket.
fn golden_max(q: impl Fn(f64) -> f64, a: f64, b: f64, iterations: usize) -> f64 {
    let (mut a, mut b) = (a, b);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (q(c), q(d));
    for _ in 0..iterations {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = q(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = q(d);
        }
    }
    0.5 * (a + b)
}

/// Discrete PI on electrical rotor speed error giving the slip speed command, saturated to
/// [-lower, upper] with conditional integration. `lower` is 0 unless the drive may brake (AC
/// braking needs a path for the returned energy, which diode rectifiers alone do not offer).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipController {
    /// PI on the electrical rotor speed error; its integrator carries the slip [rad/s].
    pub pi: DiscretePi,
    /// Width of the skipped band around zero slip [rad/s] (ch. 5.2.2's offset; 0 for none).
    pub offset: f64,
}

impl SlipController {
    /// One sample: returns the slip speed [rad/s] to hold until the next.
    pub fn update(&mut self, err: f64, lower: f64, upper: f64, ts: f64) -> f64 {
        let mut out = self.pi.update(err, -lower, upper, ts);
        // Keep the integrator inside the band the output can reach (no stored wind-up).
        self.pi.integral = self.pi.integral.clamp(-lower, upper);
        if self.offset > 0.0 && out.abs() < self.offset {
            out = if out >= 0.0 { self.offset.min(upper) } else { -self.offset.min(lower) };
        }
        out
    }
}

crate::params! {
    /// 38 MW induction motor (eqs. 2.5-2.6, Table 2.1).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct MotorParams {
        pub stator_resistance_ohm: f64 = 2.2e-3 => {
            label: "Motor stator resistance R_sm", unit: "Ω", range: 0.0..=10.0, source: "Table 2.1",
            help: "Per phase, in the equivalent circuit (eq. 2.5).",
        },
        pub stator_inductance_h: f64 = 0.198e-3 => {
            label: "Motor stator leakage L_sm", unit: "H", range: 0.0..=1.0, source: "Table 2.1",
            help: "Stator leakage inductance per phase.",
        },
        pub rotor_resistance_ohm: f64 = 3.4e-3 => {
            label: "Motor rotor resistance R_rm", unit: "Ω", range: 1.0e-6..=10.0, source: "Table 2.1",
            help: "Referred to the stator; sets the slip at a given torque.",
        },
        pub rotor_inductance_h: f64 = 0.330e-3 => {
            label: "Motor rotor leakage L_rm", unit: "H", range: 0.0..=1.0, source: "Table 2.1",
            help: "Rotor leakage inductance, referred to the stator.",
        },
        pub magnetizing_inductance_h: f64 = 11.74e-3 => {
            label: "Magnetizing inductance L_m", unit: "H", range: 1.0e-5..=10.0, source: "Table 2.1",
            help: "The motor's magnetizing branch.",
        },
        /// Table 2.1 gives P = 12 and calls it pole pairs, while ch. 2.2.2 writes omega_r =
        /// (P_m/2) omega_rm as if P were poles. Twelve pole pairs make a 300 rpm machine at 60 Hz
        /// whose peak torque (1.34 MN m) delivers 38 MW there; twelve poles would make a 600 rpm
        /// machine, which contradicts the 300 rpm rating of ch. 5. So: 12 pole pairs.
        pub pole_pairs: u32 = 12 => {
            label: "Motor pole pairs", unit: "-", range: 1.0..=64.0,
            source: "Table 2.1 (read as pole pairs: a 300 rpm machine, as ch. 5 rates it)",
            help: "With the frequency, the motor's synchronous speed.",
        },
        pub rated_voltage_ll_v: f64 = 4160.0 => {
            label: "Motor rated voltage", unit: "V", range: 100.0..=1.0e5, source: "Table 2.1",
            help: "Line-to-line rms; the base of motor voltage in per unit.",
        },
        pub rated_frequency_hz: f64 = 60.0 => {
            label: "Motor rated frequency", unit: "Hz", range: 1.0..=1000.0, source: "Table 2.1",
            help: "Electrical frequency at rated speed.",
        },
        /// The slip saturation keeps the motor under it.
        pub rated_power_w: f64 = 38.0e6 => {
            label: "Motor rating", unit: "W", range: 1.0e3..=1.0e9, source: "ch. 2.2.2", group: "plant",
            help: "Rated shaft power; the base of motor power in per unit.",
        },
        /// 0.2 % mechanical loss, usual for large low-speed machines; applied so that the loss is
        /// positive in both motoring and generating.
        pub efficiency: f64 = 0.998 => {
            label: "Motor efficiency eta_m", unit: "-", range: 0.5..=1.0,
            source: "our choice: 0.2 % friction and windage, usual for large slow machines",
            help: "Friction, windage and stray loss of eq. 2.5.",
        },
    }
}

crate::params! {
    /// Volts-per-hertz slip-speed PI on rotor speed error (ch. 2.2.4).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SlipControlParams {
        /// Near zero slip the motor torque is 430 kN m per rad/s of slip, so the shaft speed loop
        /// closes near 2 rad/s with K_i below.
        pub kp: f64 = 0.1 => {
            label: "Slip K_p", unit: "-", range: 0.0..=100.0,
            source: "our choice: the shaft loop closes near 2 rad/s (not given in the thesis)",
            help: "Slip speed per electrical rotor speed error.",
        },
        pub ki: f64 = 0.1 => {
            label: "Slip K_i", unit: "1/s", range: 0.0..=100.0, source: "our choice, with K_p",
            help: "Slip speed per electrical rotor angle error.",
        },
        /// Only meaningful with a path for the returned power (brake resistor or reversible
        /// rectifier).
        pub allow_braking: bool = false => {
            label: "Allow AC braking", source: "ch. 5.2.2", group: "controllers",
            help: "Negative slip: the motor brakes as a generator.",
        },
        /// The thesis needed it because its circuit is singular at zero slip; ours (written in
        /// admittances) is regular there, so the default is 0; set it to reproduce the thesis'
        /// scheme.
        pub zero_slip_offset_rad_s: f64 = 0.0 => {
            label: "Zero-slip offset", unit: "rad/s", range: 0.0..=1.0,
            source: "ch. 5.2.2 needs one; our circuit is regular at zero slip, so 0",
            help: "The slip command skips the band (-offset, offset) (ch. 5.2.2).",
        },
    }
}

impl crate::params::CrossCheck for MotorParams {}
impl crate::params::CrossCheck for SlipControlParams {}

#[cfg(test)]
mod tests {
    use super::*;
    use num_complex::Complex64;

    fn motor() -> InductionMotor {
        InductionMotor::new(&MotorParams::default())
    }

    /// Power flows through the circuit without loss or gain: p_in = stator loss + air gap,
    /// air gap = rotor loss + Q_e omega_rm.
    #[test]
    fn circuit_conserves_power() {
        let m = motor();
        for &(rpm, ws) in &[(200.0, 2.0), (290.0, 5.0), (10.0, 6.0), (150.0, -3.0)] {
            let w_rm = rpm * 2.0 * PI / 60.0;
            let op = m.operate_vhz(w_rm, ws, 1e9);
            let r1 = op.p_in - (op.p_stator_loss + op.p_airgap);
            let r2 = op.p_airgap - (op.p_rotor_loss + op.torque_em * w_rm);
            assert!(r1.abs() < 1e-6 * op.p_in.abs().max(1.0), "{rpm} {ws}: {r1}");
            assert!(r2.abs() < 1e-6 * op.p_airgap.abs().max(1.0), "{rpm} {ws}: {r2}");
        }
        assert_eq!(m.operate_vhz(0.0, 0.0, 1e9), MotorPoint::default());
    }

    /// The real-arithmetic circuit equals the complex one it replaced (the reference, written
    /// as the circuit reads): measured 4e-16 relative, asserted 1e-13.
    #[test]
    fn real_circuit_matches_complex_reference() {
        let m = motor();
        let j = Complex64::new(0.0, 1.0);
        for &(v, we, ws) in &[(2400.0, 377.0, 3.0), (1200.0, 180.0, -2.0), (2400.0, 300.0, 0.0), (100.0, 5.0, 6.0)] {
            let y_m = 1.0 / (j * (we * m.l_m));
            let y_r = ws / (we * Complex64::new(m.r_r, ws * m.l_r));
            let z_par = 1.0 / (y_m + y_r);
            let i_in = v / (Complex64::new(m.r_s, we * m.l_s) + z_par);
            let p_airgap = 3.0 * (i_in * z_par).norm_sqr() * y_r.re;
            let op = m.operate(v, we, ws, (we - ws) / m.pole_pairs);
            let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1.0);
            assert!(rel(op.p_in, 3.0 * v * i_in.re) < 1e-13, "{v} {we} {ws}");
            assert!(rel(op.p_airgap, p_airgap) < 1e-13 && rel(op.i_in, i_in.norm_sqr().sqrt()) < 1e-13);
        }
    }

    /// At rated frequency the peak-torque slip and torque agree with the Thevenin formulas
    /// s_max = R_r / sqrt(R_th^2 + (X_th + X_r)^2), T_max = 3 p V_th^2 / (2 omega_e (R_th + sqrt(...)))
    /// (e.g. Chapman, Electric Machinery Fundamentals, ch. 6) when the voltage is held fixed.
    #[test]
    fn peak_torque_matches_thevenin() {
        let m = motor();
        let we = m.omega_rated;
        let j = Complex64::new(0.0, 1.0);
        let z_s = Complex64::new(m.r_s, we * m.l_s);
        let z_m = j * we * m.l_m;
        let z_th = z_s * z_m / (z_s + z_m);
        let v_th = {
            let v = m.v_rated * z_m / (z_s + z_m);
            libm::hypot(v.re, v.im)
        };
        let root = libm::hypot(z_th.re, z_th.im + we * m.l_r);
        let s_max = m.r_r / root;
        let t_max = 3.0 * m.pole_pairs * v_th * v_th / (2.0 * we * (z_th.re + root));
        // Fixed voltage at fixed omega_e: sweep slip directly.
        let mut best = (0.0, 0.0);
        for i in 1..20000 {
            let s = i as f64 * 1e-5;
            let op = m.operate(m.v_rated, we, s * we, (1.0 - s) * we / m.pole_pairs);
            if op.torque_em > best.1 {
                best = (s, op.torque_em);
            }
        }
        assert!((best.0 - s_max).abs() < 2e-5, "{} vs {}", best.0, s_max);
        assert!((best.1 - t_max).abs() / t_max < 1e-6, "{} vs {}", best.1, t_max);
        // Table 2.1 is a 38 MW machine: peak torque near 300 rpm carries more than 38 MW.
        assert!(t_max * 2.0 * PI * 300.0 / 60.0 > 38e6, "T_max = {t_max}");
    }

    /// The inline solver finds the true maximum of the V/Hz torque curve (checked by sweeping).
    #[test]
    fn peak_slip_solver_finds_maximum() {
        let m = motor();
        for &(rpm, vmax) in &[(250.0, 1e9), (300.0, 2300.0), (20.0, 1e9), (100.0, 1e9)] {
            let w_rm = rpm * 2.0 * PI / 60.0;
            let ws = m.peak_torque_slip(w_rm, vmax, 0.0);
            let q = m.operate_vhz(w_rm, ws, vmax).torque;
            for i in 1..4000 {
                let other = i as f64 * 0.01;
                assert!(m.operate_vhz(w_rm, other, vmax).torque <= q * (1.0 + 1e-9), "{rpm}: {other} beats {ws}");
            }
            // Warm start from a neighbour converges to the same point.
            let ws2 = m.peak_torque_slip(w_rm, vmax, ws * 1.3);
            assert!((ws2 - ws).abs() < 1e-6 * ws, "{ws2} vs {ws}");
        }
    }

    /// Whenever the quick test says a slip lies below the controller's upper limits, the solvers
    /// agree (a sweep over shaft speed, inverter limit and slip, including near the limits).
    #[test]
    fn quick_limit_test_agrees_with_the_solvers() {
        let m = motor();
        let mut said_below = 0;
        for rpm in [30.0, 120.0, 250.0, 300.0, 320.0] {
            for vmax in [1e9, 2400.0, 1800.0] {
                let w_rm = rpm * 2.0 * PI / 60.0;
                let peak = m.peak_torque_slip(w_rm, vmax, 0.0);
                let limit = m.power_limited_slip(w_rm, vmax, peak, m.p_rated);
                for i in 1..400 {
                    let ws = i as f64 * 0.01 * peak;
                    if m.below_slip_limits(w_rm, vmax, ws, m.p_rated) {
                        said_below += 1;
                        assert!(ws < limit && ws < peak, "{rpm} rpm, v_max {vmax}: {ws} vs {limit}, {peak}");
                    }
                }
            }
        }
        assert!(said_below > 1000, "{said_below}");
    }

    #[test]
    fn power_limit_slip_gives_rated_power() {
        let m = motor();
        let w_rm = 300.0 * 2.0 * PI / 60.0;
        let peak = m.peak_torque_slip(w_rm, 1e9, 0.0);
        let ws = m.power_limited_slip(w_rm, 1e9, peak, m.p_rated);
        let p = m.operate_vhz(w_rm, ws, 1e9).torque * w_rm;
        assert!((p - m.p_rated).abs() < 1e-6 * m.p_rated, "P = {p}");
        // At low speed the peak torque is below rated power: the peak slip is returned.
        let w_low = 50.0 * 2.0 * PI / 60.0;
        let peak_low = m.peak_torque_slip(w_low, 1e9, 0.0);
        assert_eq!(m.power_limited_slip(w_low, 1e9, peak_low, m.p_rated), peak_low);
    }
}
