//! `aes-sim ips`: the IPS performance and stability tool of ch. 4.

use crate::common::{emit_json, shorten, Failure};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Side {
    Generator,
    Motor,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Loop {
    Open,
    Closed,
}

#[derive(clap::Args)]
pub struct IpsPoint {
    /// Which side: the generator (motor seen as a current sink) or the motor (generator seen as a
    /// DC source).
    #[arg(long, value_enum)]
    side: Side,
    /// Generator side: electrical speed set point [rad/s].
    #[arg(long, default_value_t = 377.0)]
    omega: f64,
    /// Generator side: field voltage [V].
    #[arg(long, default_value_t = 28.5)]
    vfd: f64,
    /// Generator side: current sink I [A].
    #[arg(long, default_value_t = 45.0)]
    load: f64,
    /// Motor side: torque command T* [N m].
    #[arg(long, default_value_t = 100.0)]
    torque: f64,
    /// Override a parameter of the side, e.g. `--set l_md=0.014` (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
}

#[derive(clap::Subcommand)]
pub enum Cmd {
    /// Steady state (Tables 4.1 and 4.2 quantities, SI).
    Steady(IpsPoint),
    /// State-space matrices and eigenvalues at the steady state.
    Linear {
        #[command(flatten)]
        point: IpsPoint,
        /// Open loop (eqs. 4.39-4.47) or closed loop (eq. 4.48; eqs. 4.49-4.53).
        #[arg(long = "loop", value_enum, default_value = "open")]
        loop_kind: Loop,
    },
    /// Bode magnitude and phase of the linear model.
    Bode {
        #[command(flatten)]
        point: IpsPoint,
        #[arg(long = "loop", value_enum, default_value = "open")]
        loop_kind: Loop,
        /// Lowest frequency [Hz].
        #[arg(long, default_value_t = 0.01)]
        from: f64,
        /// Highest frequency [Hz].
        #[arg(long, default_value_t = 1000.0)]
        to: f64,
        /// Number of points.
        #[arg(long, default_value_t = 200)]
        points: usize,
    },
}

pub fn run(command: Cmd) -> Result<(), Failure> {
    let out = ips(command)?;
    emit_json(&out)?;
    Ok(())
}

fn ips(cmd: Cmd) -> Result<serde_json::Value, String> {
    use aes_core::stability::{
        bode_frequencies, generator_side::GeneratorSideParams, load_params, motor_side::MotorSideParams,
    };
    let (point, loop_kind, bode) = match cmd {
        Cmd::Steady(p) => (p, None, None),
        Cmd::Linear { point, loop_kind } => (point, Some(loop_kind), None),
        Cmd::Bode { point, loop_kind, from, to, points } => {
            let hz = bode_frequencies(from, to, points).map_err(|e| format!("--from/--to/--points: {e}"))?;
            (point, Some(loop_kind), Some(hz))
        }
    };
    let overrides: Vec<(String, String)> = point
        .sets
        .iter()
        .map(|s| {
            s.split_once('=')
                .map(|(a, b)| (a.trim().to_string(), b.trim().to_string()))
                .ok_or_else(|| format!("--set '{}': expected NAME=VALUE", shorten(s)))
        })
        .collect::<Result<_, _>>()?;
    let (steady, sys, margins) = match point.side {
        Side::Generator => {
            let p = load_params(&GeneratorSideParams::default(), &overrides)?;
            let s = p.steady_state(point.omega, point.vfd, point.load)?;
            let steady = serde_json::json!({
                "omega_rad_s": s.omega, "v_fd": s.v_fd, "i_load": s.i_load,
                "v_gs_mag": s.v_gs_mag, "i_gs_mag": s.i_gs_mag, "i_fd": s.i_fd,
                "v_rect_v": s.v_rect_v, "v_dc": s.v_dc, "i_dc": s.i_dc, "cos_phi": s.cos_phi,
                "parameters": p,
            });
            let sys = loop_kind.map(|l| if l == Loop::Open { p.open_loop(&s) } else { p.closed_loop(&s) });
            let margins = (loop_kind == Some(Loop::Closed)).then(|| p.droop_margins(&s));
            aes_core::validate::check_finite(&s)?;
            (steady, sys, margins)
        }
        Side::Motor => {
            let p = load_params(&MotorSideParams::default(), &overrides)?;
            let s = p.steady_state(point.torque)?;
            let steady = serde_json::json!({
                "t_star": s.t_star, "t_m0": s.t_m0, "t_ref0": s.t_ref0, "omega_r0": s.omega_r0,
                "omega_s0": s.omega_s0, "i_s_mag": s.i_s_mag, "i_r_mag": s.i_r_mag, "v_s_mag": s.v_s_mag,
                "above_threshold": s.above_threshold, "t_threshold": s.t_threshold, "parameters": p,
            });
            let sys = loop_kind.map(|l| if l == Loop::Open { p.open_loop(&s) } else { p.closed_loop(&s) });
            let margins = (loop_kind == Some(Loop::Closed)).then(|| p.trim_margins(&s));
            aes_core::validate::check_finite(&s)?;
            (steady, sys, margins)
        }
    };
    let mut out = serde_json::json!({ "steady_state": steady });
    if let Some(m) = margins {
        aes_core::validate::check_finite(&m).map_err(|e| format!("margins: {e}"))?;
        out["margins"] = serde_json::to_value(m).map_err(|e| e.to_string())?;
    }
    if let Some(sys) = &sys {
        out["linear"] = sys.to_json_value()?;
    }
    if let (Some(sys), Some(hz)) = (&sys, bode) {
        let omegas: Vec<f64> = hz.iter().map(|f| 2.0 * std::f64::consts::PI * f).collect();
        let pts = sys.bode(&omegas)?;
        out["bode"] = serde_json::json!({
            "frequency_hz": hz,
            "magnitude_db": pts.iter().map(|p| p.magnitude_db).collect::<Vec<_>>(),
            "phase_deg": pts.iter().map(|p| p.phase_deg).collect::<Vec<_>>(),
        });
    }
    Ok(out)
}
