//! The IPS tool of ch. 4 as one study: a side, an operating point and what to compute in
//! ([`IpsRequest`]); the steady state, the linear model with its poles, the loop's margins and
//! the Bode plot out ([`IpsResponse`]). `aes-sim ips` and the page's `ipsAnalysis` both call
//! [`run`]; the operating point's defaults, ranges, labels and units are declared once, in
//! [`OperatingPoint`] ([`meta`] lists them: `ipsMeta()` for the page, the command line's help
//! and defaults).

use super::generator_side::{GeneratorSideParams, LOAD_RANGE_A, OMEGA_RANGE_RAD_S, V_FD_RANGE_V};
use super::motor_side::{MotorSideParams, TORQUE_RANGE_NM};
use super::{bode_frequencies, load_params, BODE_HZ_RANGE, MAX_BODE_POINTS};
use crate::checks::{check_finite, num};
use crate::control::linear::{LinearReport, LinearSystem, Margins};
use crate::params::{ParamMeta, Section};
use serde::{Deserialize, Serialize};

crate::params! {
    /// The operating point of the ch. 4 tool and the frequencies of its Bode plot. The ranges are
    /// what the steady states accept (they check them, with their own messages); a slider's span
    /// is the part a student explores.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct OperatingPoint {
        pub omega_rad_s: f64 = 377.0 => {
            label: "Speed set point ω*", unit: "rad/s", range: OMEGA_RANGE_RAD_S,
            source: "ch. 4.2.1, Table 4.1: 377 rad/s (60 Hz)",
            help: "Generator side: the electrical speed the turbine's speed control holds.",
        },
        pub v_fd_v: f64 = 28.5 => {
            label: "Field voltage v_fd", unit: "V", range: V_FD_RANGE_V, span: 1.0..=200.0,
            source: "ch. 4.2.1, Table 4.1",
            help: "Generator side: the synchronous machine's field voltage.",
        },
        pub load_a: f64 = 45.0 => {
            label: "Current sink I", unit: "A", range: LOAD_RANGE_A, span: 5.0..=48.0,
            source: "ch. 4.2.1, Table 4.1",
            help: "Generator side: the current the motor side draws from the bus.",
        },
        pub torque_nm: f64 = 100.0 => {
            label: "Torque command T*", unit: "N m", range: TORQUE_RANGE_NM, span: 20.0..=250.0,
            source: "ch. 4.2.2, Table 4.2 and Fig. 4-8 (200 N m in Fig. 4-9)",
            help: "Motor side: the torque the motor's control is ordered to make.",
        },
        pub from_hz: f64 = 0.01 => {
            label: "Bode plot from", unit: "Hz", range: BODE_HZ_RANGE,
            source: "our choice: below the slowest mode of Figs. 4-7 to 4-12",
            help: "Lowest frequency of the Bode plot.",
        },
        pub to_hz: f64 = 1000.0 => {
            label: "Bode plot to", unit: "Hz", range: BODE_HZ_RANGE,
            source: "our choice: above the fastest mode of Figs. 4-7 to 4-12",
            help: "Highest frequency of the Bode plot, above the lowest.",
        },
        pub points: usize = 200 => {
            label: "Bode plot points", unit: "-", range: 2.0..=MAX_BODE_POINTS as f64,
            source: "our choice: 40 a decade",
            help: "Number of frequencies, spaced logarithmically.",
        },
    }
}

impl crate::params::CrossCheck for OperatingPoint {
    fn cross_check(&self, v: &mut crate::checks::Validator) {
        if self.to_hz <= self.from_hz {
            v.fail("to_hz", num(self.to_hz), format!("must be above {}", v.path("from_hz")));
        }
    }
}

/// Which side of the testbed is studied.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// The induction motor with its propeller and torque control, fed by the generator side seen
    /// as a DC source.
    #[default]
    Motor,
    /// The synchronous generator with its rectifier, DC filter and droop control, loaded by the
    /// motor side seen as a current sink.
    Generator,
}

impl Side {
    /// The side of a name ("motor", "generator"), or an error naming what was given.
    pub fn from_name(name: &str) -> Result<Side, String> {
        match name {
            "motor" => Ok(Side::Motor),
            "generator" => Ok(Side::Generator),
            other => Err(format!("side = '{}': use 'generator' or 'motor'", crate::checks::shorten(other))),
        }
    }
}

/// How far the study goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Analysis {
    /// The steady state only (Tables 4.1 and 4.2).
    Steady,
    /// And the linear model at it: matrices, poles; with the loop closed, its margins.
    Linear,
    /// And the linear model's Bode plot.
    #[default]
    Bode,
}

/// What the IPS tool is asked.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct IpsRequest {
    pub side: Side,
    pub analysis: Analysis,
    /// The closed-loop model (eq. 4.48; eqs. 4.49-4.53) instead of the open loop (eqs. 4.39-4.47).
    pub closed: bool,
    pub point: OperatingPoint,
    /// Parameters of the side changed from their defaults, name and value as text
    /// (`aes-sim ips --set l_md=0.014`); each within a factor of [`super::PARAM_SPAN`].
    pub overrides: Vec<(String, String)>,
}

/// The generator side's steady state (Table 4.1 quantities, SI, peak qd magnitudes) and the
/// parameters it was found with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GeneratorReport {
    pub omega_rad_s: f64,
    pub v_fd: f64,
    pub i_load: f64,
    pub v_gs_mag: f64,
    pub i_gs_mag: f64,
    pub i_fd: f64,
    /// Rectifier output voltage, Table 4.1's v~_dc \[V\].
    pub v_rect_v: f64,
    /// Bus voltage after the DC filter, the thesis' v_dc of eqs. 4.12-4.13 \[V\].
    pub v_dc: f64,
    pub i_dc: f64,
    pub cos_phi: f64,
    pub parameters: GeneratorSideParams,
}

/// The motor side's steady state (Table 4.2 quantities, SI) and the parameters it was found with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MotorReport {
    pub t_star: f64,
    pub t_m0: f64,
    pub t_ref0: f64,
    pub omega_r0: f64,
    pub omega_s0: f64,
    pub i_s_mag: f64,
    pub i_r_mag: f64,
    pub v_s_mag: f64,
    /// Whether the rotor-flux limit is active (T** above the threshold, eqs. 4.23-4.24).
    pub above_threshold: bool,
    pub t_threshold: f64,
    pub parameters: MotorSideParams,
}

/// The steady state of the side studied.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum SteadyReport {
    Generator(GeneratorReport),
    Motor(MotorReport),
}

/// A Bode plot: frequencies \[Hz\], magnitude \[dB\] and phase \[deg\] (principal value).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodeReport {
    pub frequency_hz: Vec<f64>,
    pub magnitude_db: Vec<f64>,
    pub phase_deg: Vec<f64>,
}

/// What the IPS tool answers: the JSON of `aes-sim ips` and of the page's `ipsAnalysis`, keys as
/// docs/studies/ips-stability.md lists them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IpsResponse {
    pub steady_state: SteadyReport,
    /// With the linear analysis or the Bode plot.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub linear: Option<LinearReport>,
    /// With the loop closed: the gain and phase margins of the loop (droop PI times the
    /// generator; torque trim times the motor).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub margins: Option<Margins>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bode: Option<BodeReport>,
}

/// Why the study gave no answer.
#[derive(Debug, Clone, PartialEq)]
pub enum IpsError {
    /// The Bode plot's frequencies or number of points.
    Bode(String),
    /// The side's parameters, the operating point, or the model at it.
    Model(String),
}

impl std::fmt::Display for IpsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            IpsError::Bode(e) | IpsError::Model(e) => f.write_str(e),
        }
    }
}

impl std::error::Error for IpsError {}

/// Every declaration of [`OperatingPoint`], by field name (`ipsMeta()`).
pub fn meta() -> Vec<ParamMeta> {
    let mut out = Vec::new();
    OperatingPoint::describe_fields("", &OperatingPoint::default(), &mut out);
    out
}

/// The IPS tool of ch. 4: the steady state of the side at the operating point (which checks its
/// inputs against [`OperatingPoint`]'s ranges), and as far as asked the linear model (open or
/// closed loop) with its poles, the closed loop's margins and the Bode plot. Every number of the
/// answer is finite, or it is an error naming what is not.
pub fn run(r: &IpsRequest) -> Result<IpsResponse, IpsError> {
    let model = IpsError::Model;
    let p = &r.point;
    let bode_hz = match r.analysis {
        Analysis::Bode => Some(bode_frequencies(p.from_hz, p.to_hz, p.points).map_err(IpsError::Bode)?),
        _ => None,
    };
    let linear = r.analysis != Analysis::Steady;
    let (steady_state, sys, margins): (SteadyReport, Option<LinearSystem>, Option<Margins>) = match r.side {
        Side::Generator => {
            let params = load_params(&GeneratorSideParams::default(), &r.overrides).map_err(model)?;
            let s = params.steady_state(p.omega_rad_s, p.v_fd_v, p.load_a).map_err(model)?;
            check_finite(&s).map_err(model)?;
            let sys = linear.then(|| if r.closed { params.closed_loop(&s) } else { params.open_loop(&s) });
            let margins = (linear && r.closed).then(|| params.droop_margins(&s));
            let report = GeneratorReport {
                omega_rad_s: s.omega,
                v_fd: s.v_fd,
                i_load: s.i_load,
                v_gs_mag: s.v_gs_mag,
                i_gs_mag: s.i_gs_mag,
                i_fd: s.i_fd,
                v_rect_v: s.v_rect_v,
                v_dc: s.v_dc,
                i_dc: s.i_dc,
                cos_phi: s.cos_phi,
                parameters: params,
            };
            (SteadyReport::Generator(report), sys, margins)
        }
        Side::Motor => {
            let params = load_params(&MotorSideParams::default(), &r.overrides).map_err(model)?;
            let s = params.steady_state(p.torque_nm).map_err(model)?;
            check_finite(&s).map_err(model)?;
            let sys = linear.then(|| if r.closed { params.closed_loop(&s) } else { params.open_loop(&s) });
            let margins = (linear && r.closed).then(|| params.trim_margins(&s));
            let report = MotorReport {
                t_star: s.t_star,
                t_m0: s.t_m0,
                t_ref0: s.t_ref0,
                omega_r0: s.omega_r0,
                omega_s0: s.omega_s0,
                i_s_mag: s.i_s_mag,
                i_r_mag: s.i_r_mag,
                v_s_mag: s.v_s_mag,
                above_threshold: s.above_threshold,
                t_threshold: s.t_threshold,
                parameters: params,
            };
            (SteadyReport::Motor(report), sys, margins)
        }
    };
    if let Some(m) = &margins {
        check_finite(m).map_err(|e| model(format!("margins: {e}")))?;
    }
    let linear = sys.as_ref().map(LinearSystem::report).transpose().map_err(model)?;
    let bode = match (&sys, bode_hz) {
        (Some(sys), Some(hz)) => {
            let omegas: Vec<f64> = hz.iter().map(|f| 2.0 * std::f64::consts::PI * f).collect();
            let pts = sys.bode(&omegas).map_err(model)?;
            Some(BodeReport {
                frequency_hz: hz,
                magnitude_db: pts.iter().map(|p| p.magnitude_db).collect(),
                phase_deg: pts.iter().map(|p| p.phase_deg).collect(),
            })
        }
        _ => None,
    };
    let out = IpsResponse { steady_state, linear, margins, bode };
    check_finite(&out).map_err(model)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request(side: Side, analysis: Analysis, closed: bool) -> IpsRequest {
        IpsRequest { side, analysis, closed, ..Default::default() }
    }

    /// The declarations are complete, each default inside its range and each slider's span, each
    /// span inside its range.
    #[test]
    fn operating_point_declarations_are_complete() {
        let meta = meta();
        let names: Vec<&str> = meta.iter().map(|m| m.path.as_str()).collect();
        assert_eq!(names, ["omega_rad_s", "v_fd_v", "load_a", "torque_nm", "from_hz", "to_hz", "points"]);
        for m in &meta {
            assert!(!m.label.is_empty() && !m.unit.is_empty() && m.help.ends_with('.'), "{}", m.path);
            assert!(!m.source.is_empty(), "{}", m.path);
            let (lo, hi) = (m.min.unwrap(), m.max.unwrap());
            let x = m.default.as_f64().unwrap();
            assert!(lo <= x && x <= hi, "{}: default {x} outside [{lo}, {hi}]", m.path);
            if let Some([a, b]) = m.span {
                assert!(lo <= a && a < b && b <= hi && a <= x && x <= b, "{}: span [{a}, {b}]", m.path);
            }
        }
        let sliders: Vec<&str> = meta.iter().filter(|m| m.span.is_some()).map(|m| m.path.as_str()).collect();
        assert_eq!(sliders, ["v_fd_v", "load_a", "torque_nm"]);
    }

    /// The declared ranges are the ones the study enforces: a number outside is refused by the
    /// steady state or the Bode check, naming the input and the range, and by the registry's
    /// check; the defaults are accepted.
    #[test]
    fn declared_ranges_are_the_ones_enforced() {
        for m in meta() {
            let (lo, hi) = (m.min.unwrap(), m.max.unwrap());
            for outside in [lo - 1.0, 2.0 * hi] {
                let mut r = request(Side::Motor, Analysis::Bode, false);
                let x = outside;
                match m.path.as_str() {
                    "omega_rad_s" => (r.side, r.point.omega_rad_s) = (Side::Generator, x),
                    "v_fd_v" => (r.side, r.point.v_fd_v) = (Side::Generator, x),
                    "load_a" => (r.side, r.point.load_a) = (Side::Generator, x),
                    "torque_nm" => r.point.torque_nm = x,
                    "from_hz" => r.point.from_hz = x,
                    "to_hz" => r.point.to_hz = x,
                    "points" => r.point.points = x.max(0.0) as usize,
                    p => panic!("{p} not tried"),
                }
                let mut v = crate::checks::Validator::new();
                r.point.check_fields(&mut v);
                assert!(v.finish().is_err(), "{} = {x}: the registry accepts it", m.path);
                let e = run(&r).unwrap_err();
                let text = e.to_string();
                match m.path.as_str() {
                    "from_hz" | "to_hz" | "points" => assert!(matches!(e, IpsError::Bode(_)), "{}: {e}", m.path),
                    _ => assert!(
                        text.contains(&format!("must be a number from {lo} to {hi}")),
                        "{} = {}: {text}",
                        m.path,
                        num(x)
                    ),
                }
            }
        }
        let mut v = crate::checks::Validator::new();
        OperatingPoint::default().check_fields(&mut v);
        assert!(v.finish().is_ok());
        for side in [Side::Motor, Side::Generator] {
            for closed in [false, true] {
                run(&request(side, Analysis::Bode, closed)).unwrap();
            }
        }
    }

    /// Table 4.1 and 4.2 through the study, and what each analysis adds to the answer.
    #[test]
    fn the_study_answers_as_far_as_asked() {
        let g = run(&request(Side::Generator, Analysis::Steady, false)).unwrap();
        let SteadyReport::Generator(s) = &g.steady_state else { panic!("not the generator") };
        assert!((s.v_rect_v - 743.17).abs() < 0.2, "{}", s.v_rect_v);
        assert!(g.linear.is_none() && g.margins.is_none() && g.bode.is_none());
        let m = run(&request(Side::Motor, Analysis::Linear, true)).unwrap();
        let SteadyReport::Motor(s) = &m.steady_state else { panic!("not the motor") };
        assert!((s.i_s_mag - 47.80).abs() < 1e-4 * 47.80, "{}", s.i_s_mag);
        assert_eq!(m.linear.as_ref().unwrap().poles.len(), 6);
        assert!(m.margins.is_some() && m.bode.is_none());
        let b = run(&request(Side::Motor, Analysis::Bode, false)).unwrap();
        let bode = b.bode.unwrap();
        assert_eq!(bode.frequency_hz.len(), OperatingPoint::default().points);
        assert!(b.margins.is_none() && b.linear.unwrap().stable);
        // The JSON keys of `aes-sim ips` (docs/studies/ips-stability.md) and of the page.
        let v = serde_json::to_value(run(&request(Side::Generator, Analysis::Bode, true)).unwrap()).unwrap();
        for key in ["v_gs_mag", "i_gs_mag", "i_fd", "v_rect_v", "v_dc", "i_dc", "cos_phi", "parameters"] {
            assert!(!v["steady_state"][key].is_null(), "{key}");
        }
        for key in ["states", "a", "b", "c", "d", "poles", "stable"] {
            assert!(!v["linear"][key].is_null(), "{key}");
        }
        assert!(v["margins"].is_object() && v["bode"]["phase_deg"].is_array());
        assert_eq!(Side::from_name("generator"), Ok(Side::Generator));
        assert!(Side::from_name("rotor").unwrap_err().contains("'rotor'"));
        let over = IpsRequest { overrides: vec![("nope".into(), "1".into())], ..Default::default() };
        assert_eq!(run(&over).unwrap_err(), IpsError::Model("nope: no such parameter".into()));
    }
}
