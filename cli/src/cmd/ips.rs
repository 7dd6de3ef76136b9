//! `aes-sim ips`: the IPS performance and stability tool of ch. 4 (`aes_core::studies::ips::study`,
//! which the page's Stability tab calls too). The flags' defaults and help come from the
//! operating point's declarations there.

use crate::common::{emit_json, shorten, Failure};
use aes_core::studies::ips::study::{self, Analysis, IpsError, IpsRequest, OperatingPoint};

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

/// The declared operating point (the flags' defaults).
fn declared() -> OperatingPoint {
    OperatingPoint::default()
}

/// A flag's help from its input's declaration: what it is, label, unit and allowed range.
fn help(field: &str) -> String {
    let Some(m) = study::meta().into_iter().find(|m| m.path == field) else { return String::new() };
    let unit = if m.unit == "-" { String::new() } else { format!(" [{}]", m.unit) };
    let range = match (m.min, m.max) {
        (Some(lo), Some(hi)) => format!(", {} to {}", aes_core::checks::num(lo), aes_core::checks::num(hi)),
        _ => String::new(),
    };
    format!("{} ({}{unit}{range})", m.help.trim_end_matches('.'), m.label)
}

#[derive(clap::Args)]
pub struct IpsPoint {
    /// Which side: the generator (motor seen as a current sink) or the motor (generator seen as a
    /// DC source).
    #[arg(long, value_enum)]
    side: Side,
    #[arg(long, default_value_t = declared().omega_rad_s, help = help("omega_rad_s"))]
    omega: f64,
    #[arg(long, default_value_t = declared().v_fd_v, help = help("v_fd_v"))]
    vfd: f64,
    #[arg(long, default_value_t = declared().load_a, help = help("load_a"))]
    load: f64,
    #[arg(long, default_value_t = declared().torque_nm, help = help("torque_nm"))]
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
        #[arg(long, default_value_t = declared().from_hz, help = help("from_hz"))]
        from: f64,
        #[arg(long, default_value_t = declared().to_hz, help = help("to_hz"))]
        to: f64,
        #[arg(long, default_value_t = declared().points, help = help("points"))]
        points: usize,
    },
}

pub fn run(command: Cmd) -> Result<(), Failure> {
    let d = declared();
    let (p, loop_kind, analysis, (from_hz, to_hz, points)) = match command {
        Cmd::Steady(p) => (p, Loop::Open, Analysis::Steady, (d.from_hz, d.to_hz, d.points)),
        Cmd::Linear { point, loop_kind } => (point, loop_kind, Analysis::Linear, (d.from_hz, d.to_hz, d.points)),
        Cmd::Bode { point, loop_kind, from, to, points } => (point, loop_kind, Analysis::Bode, (from, to, points)),
    };
    // A number the chosen side does not read would be ignored without a word: refused by name (a
    // value equal to the default is what leaving the flag out gives).
    let (unread, this, other): (&[(&str, f64, f64)], _, _) = match p.side {
        Side::Motor => (
            &[("--omega", p.omega, d.omega_rad_s), ("--vfd", p.vfd, d.v_fd_v), ("--load", p.load, d.load_a)],
            "motor",
            "generator",
        ),
        Side::Generator => (&[("--torque", p.torque, d.torque_nm)], "generator", "motor"),
    };
    if let Some((flag, ..)) = unread.iter().find(|(_, v, dflt)| v.to_bits() != dflt.to_bits()) {
        return Err(format!("{flag} is for --side {other}; --side {this} does not read it").into());
    }
    let overrides: Vec<(String, String)> = p
        .sets
        .iter()
        .map(|s| {
            s.split_once('=')
                .map(|(a, b)| (a.trim().to_string(), b.trim().to_string()))
                .ok_or_else(|| format!("--set '{}': expected NAME=VALUE", shorten(s)))
        })
        .collect::<Result<_, _>>()?;
    let request = IpsRequest {
        side: match p.side {
            Side::Generator => study::Side::Generator,
            Side::Motor => study::Side::Motor,
        },
        analysis,
        closed: loop_kind == Loop::Closed,
        point: OperatingPoint {
            omega_rad_s: p.omega,
            v_fd_v: p.vfd,
            load_a: p.load,
            torque_nm: p.torque,
            from_hz,
            to_hz,
            points,
        },
        overrides,
    };
    let out = study::run(&request).map_err(|e| match e {
        IpsError::Bode(e) => format!("--from/--to/--points: {e}"),
        IpsError::Model(e) => e,
    })?;
    emit_json(&out)
}
