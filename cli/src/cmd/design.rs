//! `aes-sim design`: controller design (ch. 3.1).

use crate::common::{emit, emit_json, read_bounded, shorten, Failure};

/// The LQG/LTR tuning and operating point, as `controllers.lqg_ltr.*` (defaults there: mu 0.01,
/// omega_p 1 rad/s, q 1000, turbine weight 1, 25 knots).
#[derive(clap::Args)]
pub struct TuningArgs {
    /// Kalman filter weight mu (eq. 3.4).
    #[arg(long)]
    mu: Option<f64>,
    /// Pinch frequency omega_p [rad/s].
    #[arg(long)]
    omega_p: Option<f64>,
    /// Recovery gain q (eq. 3.6).
    #[arg(long)]
    q: Option<f64>,
    /// Weight of the turbine-speed error beside the bus voltage's.
    #[arg(long)]
    turbine_weight: Option<f64>,
    /// Ship speed of the operating point [kn].
    #[arg(long)]
    speed_kn: Option<f64>,
}

impl TuningArgs {
    fn any(&self) -> bool {
        [self.mu, self.omega_p, self.q, self.turbine_weight, self.speed_kn].iter().any(Option::is_some)
    }

    /// The defaults with the given values in place.
    fn apply(&self, t: &mut aes_core::control::design::LqgLtrParams) {
        t.mu = self.mu.unwrap_or(t.mu);
        t.omega_p_rad_s = self.omega_p.unwrap_or(t.omega_p_rad_s);
        t.q = self.q.unwrap_or(t.q);
        t.turbine_speed_weight = self.turbine_weight.unwrap_or(t.turbine_speed_weight);
        t.design_speed_kn = self.speed_kn.unwrap_or(t.design_speed_kn);
    }
}

#[derive(clap::Subcommand)]
pub enum Cmd {
    /// LQG/LTR (eqs. 3.2-3.10) for a square plant given as JSON
    /// {"a": [[..]], "b": [[..]], "c": [[..]], "d": [[..]], "mu": 0.005, "omega_p": 3.0, "q": 1000.0}
    /// (FILE or `-`); prints the gains, the compensator, the closed-loop poles and the singular values.
    LqgLtr {
        /// Plant and tuning as JSON, or `-` for standard input (not with --plant).
        file: Option<String>,
        /// `aes`: our own drive train linearised at --speed-kn (throttle and field voltage in,
        /// turbine speed and bus voltage out, per unit), with the tuning below.
        #[arg(long)]
        plant: Option<String>,
        #[command(flatten)]
        tuning: TuningArgs,
    },
    /// PI against LQG/LTR in the acceleration, AC braking and head seas SS6 studies: turbine
    /// dip, bus-voltage excursion, settling, fuel (a Markdown table; --json for JSON).
    Compare {
        #[command(flatten)]
        tuning: TuningArgs,
        /// Print JSON instead of the table.
        #[arg(long)]
        json: bool,
    },
}

/// Largest design input read [bytes] (a 60-state plant in JSON is well under 1 MB).
const MAX_DESIGN_BYTES: u64 = 4 << 20;

pub fn run(command: Cmd) -> Result<(), Failure> {
    match command {
        Cmd::LqgLtr { file, plant, tuning } => {
            let input: aes_core::control::design::lqg_ltr::DesignInput = match (file, plant.as_deref()) {
                (Some(_), None) if tuning.any() => {
                    return Err("--mu, --omega-p, --q, --turbine-weight and --speed-kn go with --plant aes; a FILE \
                                carries its own mu, omega_p and q"
                        .into())
                }
                (Some(file), None) => {
                    let text = read_bounded(&file, MAX_DESIGN_BYTES, "a design input")?;
                    serde_json::from_str(&text).map_err(|e| format!("{file}: {e}"))?
                }
                (None, Some("aes")) => {
                    let mut sc = aes_core::scenario::presets::preset("acceleration").ok_or("no acceleration preset")?;
                    tuning.apply(&mut sc.controllers.lqg_ltr);
                    let d = aes_core::sim::lqg::analyse(&sc)?;
                    return emit_json(&d);
                }
                (None, Some(other)) => {
                    return Err(format!("--plant = {}: the only built-in plant is `aes`", shorten(other)).into())
                }
                (Some(_), Some(_)) => return Err("give a FILE or --plant aes, not both".into()),
                (None, None) => return Err("give a FILE (or `-`) or --plant aes".into()),
            };
            let d = aes_core::control::design::lqg_ltr::design(&input)?;
            emit_json(&d)?;
        }
        Cmd::Compare { tuning, json } => {
            let mut t = aes_core::control::design::LqgLtrParams::default();
            tuning.apply(&mut t);
            let mut v = aes_core::checks::Validator::new();
            v.section("controllers", |v| v.section("lqg_ltr", |v| aes_core::params::Section::check_fields(&t, v)));
            v.finish().map_err(|e| e.to_string())?;
            let rows = aes_core::studies::controller::compare(&t)?;
            if json {
                emit_json(&rows)?;
            } else {
                emit(&aes_core::studies::controller::markdown(&rows))?;
            }
        }
    }
    Ok(())
}
