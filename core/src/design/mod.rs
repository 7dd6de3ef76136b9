//! Controller design (thesis ch. 3.1): LQG with loop transfer recovery for any linear plant
//! (A, B, C, D), the Riccati equations it rests on, the loop and closed-loop analysis of
//! eqs. 3.2-3.10 (`aes-sim design lqg-ltr`), modal model reduction, stability margins, and the
//! discretisation that runs a design in the simulator.

pub mod discrete;
pub mod lqg_ltr;
pub mod margins;
pub mod reduction;
pub mod riccati;

use crate::check_range;
use crate::validate::Validator;
use serde::{Deserialize, Serialize};

/// Which controller runs the gas turbines' throttles and the generators' field voltages.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControllerDesign {
    /// Two single-loop PIs per set: the governor on turbine speed and the exciter on bus voltage
    /// (thesis ch. 2.1-2.2, as in ch. 5).
    #[default]
    Pi,
    /// One two-input, two-output LQG/LTR compensator per set (ch. 3.1), designed on the drive
    /// train linearised at `controllers.lqg_ltr.design_speed_kn`.
    LqgLtr,
}

/// Tuning of the LQG/LTR design for our drive train (ch. 3.1.3).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LqgLtrParams {
    /// Kalman filter weight N = mu I (eq. 3.4) [-]. Kappos' F100 design: 5e-3. Ours: 0.01 puts the
    /// Kalman target's crossovers at 5.2 and 0.54 rad/s at 25 knots, within what the actuators give
    /// (the field circuit's 1 s time constant, the throttle's 0.1 /s slew) and near the PI loops'
    /// 2 rad/s. A larger mu (0.1) slows the speed loop until the turbine nearly stalls in the
    /// acceleration study (0.15 pu).
    pub mu: f64,
    /// Pinch frequency omega_p of the target loop's singular values [rad/s] (Gamma =
    /// [Re{G(j omega_p)^-1}; 0]). Kappos: 3. Ours: 1, between the two crossovers.
    pub omega_p_rad_s: f64,
    /// Recovery gain q of Q = q^2 C'C (eq. 3.6) [-]. Kappos: 1000, and ours: it recovers the
    /// target's crossovers to 4.6 and 0.51 rad/s (q = 100: 3.8 and 0.49) with margins at the
    /// plant input of 20 dB / 57 degrees on the field voltage and 40 dB / 63 degrees on the
    /// throttle (q = 100: 13.5 dB / 46 degrees); the fastest compensator pole, -216 rad/s, is
    /// well inside what the 5 ms sample holds (zero-order hold is exact for any speed).
    pub q: f64,
    /// Weight of the turbine-speed error beside the bus-voltage error [-]: the design's first
    /// output is w (omega_t / omega_t* - 1), the second V_bus / V* - 1. Not in the thesis (whose
    /// F100 outputs are scaled by the designer); 1 weighs a per-unit of each alike. Larger values
    /// keep the turbines nearer their set speed and let the bus sag more.
    pub turbine_speed_weight: f64,
    /// Ship speed of the operating point the plant is linearised at [kn]. Not in the thesis; 25,
    /// the speed every ch. 5 study starts from.
    pub design_speed_kn: f64,
}

impl Default for LqgLtrParams {
    fn default() -> Self {
        LqgLtrParams { mu: 0.01, omega_p_rad_s: 1.0, q: 1000.0, turbine_speed_weight: 1.0, design_speed_kn: 25.0 }
    }
}

impl LqgLtrParams {
    pub fn validate(&self, v: &mut Validator) {
        check_range!(v, self.mu, 1.0e-6, 1.0e3);
        check_range!(v, self.omega_p_rad_s, 0.0, 100.0);
        check_range!(v, self.q, 1.0e-2, 1.0e5);
        check_range!(v, self.turbine_speed_weight, 0.01, 100.0);
        check_range!(v, self.design_speed_kn, 5.0, 32.0);
    }
}
