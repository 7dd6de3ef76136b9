//! The IPS performance and stability tool of thesis ch. 4: time-averaged nonlinear models of a
//! scaled MVDC power system (the Purdue MVDC testbed), split into a generator side (the motor
//! side seen as a current sink) and a motor side (the generator side seen as a DC voltage
//! source); steady states, linearization, state-space models, eigenvalues and Bode plots (the
//! linear models, poles, Bode points and margins are `control::linear`'s).

pub mod generator_side;
pub mod motor_side;
pub mod study;

use crate::control::linear::log_space;
use nalgebra::{DMatrix, DVector};
use std::ops::RangeInclusive;

/// Central-difference Jacobian of f at x (for checking the analytic linearizations).
pub fn numerical_jacobian(f: &dyn Fn(&[f64]) -> Vec<f64>, x: &[f64]) -> DMatrix<f64> {
    let n = x.len();
    let m = f(x).len();
    let mut j = DMatrix::zeros(m, n);
    let mut xp = x.to_vec();
    for k in 0..n {
        let h = 1e-6 * x[k].abs().max(1e-3);
        xp[k] = x[k] + h;
        let fp = f(&xp);
        xp[k] = x[k] - h;
        let fm = f(&xp);
        xp[k] = x[k];
        for i in 0..m {
            j[(i, k)] = (fp[i] - fm[i]) / (2.0 * h);
        }
    }
    j
}

/// One RK4 step of dx/dt = f(t, x).
pub fn rk4(f: &dyn Fn(f64, &[f64]) -> Vec<f64>, t: f64, x: &mut [f64], dt: f64) {
    let mut v = x.to_vec();
    crate::numerics::rk4(&mut v, t, dt, |t, y, dx| *dx = f(t, y));
    x.copy_from_slice(&v);
}

/// One step of the implicit trapezoidal rule for dx/dt = f(t, x), solved by Newton's method with
/// a numerical Jacobian: A-stable, so it integrates the stiff averaged models (the rectifier
/// constraint puts a pole near -7e5 /s on the generator side) at steps set by accuracy alone.
/// Returns false if Newton did not converge.
pub fn trapezoid_step(f: &dyn Fn(f64, &[f64]) -> Vec<f64>, t: f64, x: &mut [f64], dt: f64) -> bool {
    let n = x.len();
    let f0 = f(t, x);
    let mut y: Vec<f64> = (0..n).map(|i| x[i] + dt * f0[i]).collect();
    for _ in 0..20 {
        let fy = f(t + dt, &y);
        let r: Vec<f64> = (0..n).map(|i| y[i] - x[i] - 0.5 * dt * (f0[i] + fy[i])).collect();
        let j = numerical_jacobian(&|z: &[f64]| f(t + dt, z), &y);
        let m = DMatrix::<f64>::identity(n, n) - j * (0.5 * dt);
        let Some(step) = m.lu().solve(&DVector::from_vec(r)) else { return false };
        let mut big = 0.0f64;
        for i in 0..n {
            y[i] -= step[i];
            big = big.max(step[i].abs() / (1.0 + y[i].abs()));
        }
        if big < 1e-12 {
            x.copy_from_slice(&y);
            return true;
        }
    }
    x.copy_from_slice(&y);
    false
}

/// How far `--set` may move a parameter from its default: a factor of [`PARAM_SPAN`] either way
/// (the models are reconstructions of one 50 hp testbed; beyond that their numbers overflow or
/// lose all meaning, e.g. `l_m = 1e-300`).
pub const PARAM_SPAN: f64 = 1.0e3;

/// Reads a parameter set from JSON (or its defaults), applies `path=value` overrides, and checks
/// that every parameter is a finite number within [`PARAM_SPAN`] of its default (of `base`);
/// errors name the field, its value (shortened) and the allowed range.
pub fn load_params<T>(base: &T, overrides: &[(String, String)]) -> Result<T, String>
where
    T: serde::Serialize + serde::de::DeserializeOwned,
{
    use crate::checks::shorten;
    let defaults = serde_json::to_value(base).map_err(|e| e.to_string())?;
    let mut v = defaults.clone();
    for (path, text) in overrides {
        let slot = v
            .as_object_mut()
            .and_then(|m| m.get_mut(path.as_str()))
            .ok_or_else(|| format!("{}: no such parameter", shorten(path)))?;
        let num: f64 = text.parse().map_err(|_| format!("{path} = {}: not a number", shorten(text)))?;
        *slot = serde_json::Number::from_f64(num)
            .map(serde_json::Value::Number)
            .ok_or_else(|| format!("{path} = {}: not a finite number", shorten(text)))?;
    }
    if let (Some(map), Some(def)) = (v.as_object(), defaults.as_object()) {
        for (k, x) in map {
            let x = x.as_f64().unwrap_or(f64::NAN);
            let d = def.get(k).and_then(|d| d.as_f64()).unwrap_or(1.0);
            let (lo, hi) = (d / PARAM_SPAN, (d * PARAM_SPAN).min(1.0e9));
            if !(x.is_finite() && x >= lo && x <= hi) {
                return Err(format!(
                    "{k} = {}: must be a number from {lo:e} to {hi:e} (the default {d} within a factor of {PARAM_SPAN})",
                    crate::checks::num(x)
                ));
            }
        }
    }
    serde_path_to_error::deserialize(v).map_err(|e| format!("{}: {}", e.path(), e.inner()))
}

/// The frequencies a Bode plot may span \[Hz\].
pub const BODE_HZ_RANGE: RangeInclusive<f64> = 1e-6..=1e7;

/// `n` logarithmically spaced Bode frequencies \[Hz\] from `from_hz` to `to_hz`, after checking
/// the range (both in [`BODE_HZ_RANGE`], from below to, 2 to [`MAX_BODE_POINTS`] points).
pub fn bode_frequencies(from_hz: f64, to_hz: f64, points: usize) -> Result<Vec<f64>, String> {
    if !(BODE_HZ_RANGE.contains(&from_hz) && BODE_HZ_RANGE.contains(&to_hz) && to_hz > from_hz) {
        return Err(format!("Bode range from {from_hz} Hz to {to_hz} Hz: need 1e-6 <= from < to <= 1e7 Hz"));
    }
    if !(2..=MAX_BODE_POINTS).contains(&points) {
        return Err(format!("Bode points = {points}: must be a whole number from 2 to {MAX_BODE_POINTS}"));
    }
    Ok(log_space(from_hz, to_hz, points))
}

/// Most points of one Bode plot.
pub const MAX_BODE_POINTS: usize = 10_000;

/// Checks an operating-point input of a steady state: a finite number in `range`, or an error
/// naming it, its value and the range.
pub(crate) fn check_input(name: &str, unit: &str, x: f64, range: &RangeInclusive<f64>) -> Result<(), String> {
    let (lo, hi) = (*range.start(), *range.end());
    if x.is_finite() && range.contains(&x) {
        Ok(())
    } else {
        Err(format!("{name} = {} {unit}: must be a number from {lo} to {hi} {unit}", crate::checks::num(x)))
    }
}

/// Checks that every number of a steady state is finite; the error names the quantity and the
/// inputs that led to it.
pub(crate) fn check_steady(side: &str, inputs: &str, values: &[(&str, f64)]) -> Result<(), String> {
    match values.iter().find(|(_, x)| !x.is_finite()) {
        None => Ok(()),
        Some((name, x)) => Err(format!(
            "the {side} steady state at {inputs} has {name} = {}: the parameters or the operating point are outside what the model can represent",
            crate::checks::num(*x)
        )),
    }
}
