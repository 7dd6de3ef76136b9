//! `aes-sim`: the command line of the All Electric Ship simulator.

use aes_core::presets::{preset, PRESET_NAMES};
use aes_core::seakeeping::strip::{default_omega_grid, Ship};
use aes_core::seakeeping::tables::{rao_json, section_json, FormChoice, RaoTable, SeakeepingGrid};
use aes_core::{Scenario, Simulation};
use clap::{Parser, Subcommand};
use std::io::{Read, Write};
use std::process::ExitCode;
use std::time::Instant;

/// How a command ends other than with success.
enum Failure {
    /// A message for stderr; exit status 1.
    Msg(String),
    /// Standard output was closed by its reader (`aes-sim ... | head`): a normal end, exit 0.
    PipeClosed,
}

impl From<String> for Failure {
    fn from(s: String) -> Failure {
        Failure::Msg(s)
    }
}

impl From<&str> for Failure {
    fn from(s: &str) -> Failure {
        Failure::Msg(s.to_string())
    }
}

/// Writes text to standard output; a closed pipe ends the command quietly (exit 0).
fn emit(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    let r = out.write_all(text.as_bytes()).and_then(|()| out.write_all(b"\n")).and_then(|()| out.flush());
    match r {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(Failure::PipeClosed),
        Err(e) => Err(Failure::Msg(format!("cannot write to standard output: {e}"))),
    }
}

/// Prints a value as pretty JSON after checking that every number in it is finite (the error
/// names the first that is not, by its path).
fn emit_json<T: serde::Serialize + ?Sized>(x: &T) -> Result<(), Failure> {
    aes_core::validate::check_finite(x)?;
    // Through a Value, whose keys are sorted: the output keeps its established form.
    let v = serde_json::to_value(x).map_err(|e| e.to_string())?;
    emit(&serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
}

/// Largest Monte Carlo partial file [bytes].
const MAX_PARTIAL_BYTES: u64 = 512 << 20;

/// Reads a file (or standard input for `-`) as UTF-8, stopping at `limit` bytes: a larger or
/// endless input (`/dev/zero`) is refused after reading `limit + 1` bytes, never read whole.
fn read_bounded(file: &str, limit: u64, what: &str) -> Result<String, String> {
    let mut buf = Vec::new();
    let r = if file == "-" {
        std::io::stdin().lock().take(limit + 1).read_to_end(&mut buf)
    } else {
        std::fs::File::open(file).and_then(|f| f.take(limit + 1).read_to_end(&mut buf))
    };
    let name = if file == "-" { "standard input".to_string() } else { format!("'{}'", shorten(file)) };
    r.map_err(|e| format!("cannot read {name}: {e}"))?;
    if buf.len() as u64 > limit {
        return Err(format!("{name}: larger than {limit} bytes, the limit for {what}"));
    }
    String::from_utf8(buf).map_err(|e| format!("{name}: not UTF-8 text (byte {})", e.utf8_error().valid_up_to()))
}

/// Checks before a long computation that `path` can be written (created or truncated now, so a
/// bad directory or permission is found before the run, not after).
fn check_writable(path: &str, flag: &str) -> Result<(), String> {
    std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(true)
        .open(path)
        .map(|_| ())
        .map_err(|e| format!("{flag} '{}': cannot write: {e}", shorten(path)))
}

fn shorten(s: &str) -> String {
    aes_core::validate::shorten(s)
}

#[derive(Parser)]
#[command(
    name = "aes-sim",
    version,
    about = "All Electric Ship simulator (Schmitt, MIT 2010): drive train, hull and power system"
)]
struct Cli {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// List the preset scenarios.
    Presets,
    /// List the trace columns: name, unit and what each is (`--json` for the machine-readable table).
    Signals {
        #[arg(long)]
        json: bool,
    },
    /// List every scenario parameter: path, unit, default, allowed values and label (`--json`
    /// for the full declarations: help, source, page group, per-unit base; `--markdown` for the
    /// README's table).
    Params {
        #[arg(long, conflicts_with = "markdown")]
        json: bool,
        #[arg(long)]
        markdown: bool,
    },
    /// Print a preset scenario as JSON (a starting point for your own).
    Preset {
        /// Preset name (see `aes-sim presets`).
        name: String,
    },
    /// Run a scenario file (or `-` for standard input, or `preset:NAME`); prints a JSON summary.
    Run {
        /// Scenario JSON file, `-` for standard input, or `preset:NAME`.
        file: String,
        /// Write the recorded trace as CSV to this file.
        #[arg(long)]
        out: Option<String>,
        /// Override one parameter, e.g. `--set sim.duration_s=60` (repeatable).
        #[arg(long = "set", value_name = "PATH=VALUE")]
        sets: Vec<String>,
    },
    /// Controller design (thesis ch. 3.1).
    Design {
        #[command(subcommand)]
        command: DesignCmd,
    },
    /// The IPS performance and stability tool of thesis ch. 4 (Purdue MVDC testbed).
    Ips {
        #[command(subcommand)]
        command: IpsCmd,
    },
    /// Sectional added mass and damping of one ship section (thesis ch. 2.5.1: conformal map +
    /// Ursell-Tasai multipoles, deep water); JSON on standard output.
    Section {
        /// Beam at the waterline [m].
        #[arg(long)]
        beam: f64,
        /// Draft [m].
        #[arg(long)]
        draft: f64,
        /// Area coefficient A / (B T).
        #[arg(long = "area-coeff")]
        area_coeff: f64,
        /// Conformal form: auto (Lewis, or bulb where Lewis cannot), lewis, bulb.
        #[arg(long, default_value = "auto")]
        form: String,
        /// Frequencies [rad/s], comma separated.
        #[arg(long, value_delimiter = ',', required = true)]
        omega: Vec<f64>,
    },
    /// Response amplitude operators and mean second-order forces of a hull by strip theory
    /// (thesis ch. 2.5.2-2.5.3); JSON on standard output.
    Rao {
        /// The hull: an embedded one by name (dtmb5415, wigley) or an offsets CSV file (the long
        /// format of dtmb5415_offsets.csv). Default: the hull of --scenario, else the DTMB 5415.
        #[arg(long)]
        hull: Option<String>,
        /// Take the hull and its loading from this scenario's `ship.hull` (file, `-` or
        /// `preset:NAME`): the RAOs its runs use.
        #[arg(long)]
        scenario: Option<String>,
        /// Waterline above the baseline [m] (default: the hull's design draft).
        #[arg(long)]
        draft: Option<f64>,
        /// Displaced mass [kg], instead of --draft: the draft is solved for it.
        #[arg(long)]
        mass: Option<f64>,
        /// Centre of gravity above the baseline [m] (needed for an offsets file).
        #[arg(long)]
        kg: Option<f64>,
        /// Radii of gyration [m]: roll, pitch, yaw (defaults: the hull's; for an offsets file
        /// 0.37 B, 0.25 Lpp, 0.25 Lpp).
        #[arg(long)]
        kxx: Option<f64>,
        #[arg(long)]
        kyy: Option<f64>,
        #[arg(long)]
        kzz: Option<f64>,
        /// Ship speed [kn].
        #[arg(long = "speed-kn")]
        speed_kn: f64,
        /// Wave heading [deg]: 180 head seas, 90 waves from starboard, 0 following seas.
        #[arg(long = "heading-deg")]
        heading_deg: f64,
        /// Wave frequencies [rad/s], comma separated.
        #[arg(long, value_delimiter = ',', required = true)]
        omega: Vec<f64>,
        /// Wave amplitude at which the nonlinear roll damping is linearised [m].
        #[arg(long = "roll-wave-amplitude", default_value_t = 1.0)]
        roll_wave_amplitude: f64,
    },
    /// A Monte Carlo study of a scenario (thesis ch. 5.4); prints the summary JSON.
    Mc {
        /// Scenario JSON file, `-` or `preset:NAME` (its `monte_carlo` section says what to collect).
        file: String,
        /// Number of trials (default: the scenario's monte_carlo.trials).
        #[arg(long)]
        trials: Option<u64>,
        /// Master seed (default: the scenario's sim.seed); trial i uses a seed made from it and i.
        #[arg(long)]
        seed: Option<u64>,
        /// Worker threads (default: all cores). The summary does not depend on it.
        #[arg(long)]
        threads: Option<usize>,
        /// Run only trials A..B of the study (a shard).
        #[arg(long = "trial-range", value_name = "A..B")]
        trial_range: Option<String>,
        /// Write the shard's partial statistics to this file (for `aes-sim merge`).
        #[arg(long)]
        partial: Option<String>,
        /// Override one parameter (repeatable).
        #[arg(long = "set", value_name = "PATH=VALUE")]
        sets: Vec<String>,
        /// No progress on stderr (by default a bar on a terminal, a line every 10 s otherwise).
        #[arg(long)]
        quiet: bool,
    },
    /// Merges Monte Carlo shards (`aes-sim mc ... --partial`) into the study's summary. Reads one
    /// shard at a time: memory does not grow with their number.
    Merge {
        /// Partial files.
        #[arg(required_unless_present = "files_from")]
        files: Vec<String>,
        /// Also merge the partial files listed in this file, one path a line (`-`: standard input;
        /// for more shards than a command line holds).
        #[arg(long = "files-from", value_name = "LIST")]
        files_from: Option<String>,
        /// Also write the merged partial to this file.
        #[arg(long)]
        partial: Option<String>,
    },
    /// The fuel study of ch. 5.2.4 (Fig. 5-12): fuel power of one prime mover in regular head and
    /// bow seas of 1 to 5 ft over wave frequency; JSON rows on standard output.
    Fuel {
        /// Scenario (default: the fuel-regular-seas preset); its first ordered speed is used.
        #[arg(default_value = "preset:fuel-regular-seas")]
        file: String,
        /// Wave frequencies [rad/s], comma separated (default 0.3 to 1.5 in steps of 0.1).
        #[arg(long, value_delimiter = ',')]
        omega: Vec<f64>,
        /// Override one parameter (repeatable).
        #[arg(long = "set", value_name = "PATH=VALUE")]
        sets: Vec<String>,
    },
    /// Measure simulated seconds per wall-clock second on a preset (default: startup), or
    /// `seakeeping`: the time to build the default RAO tables of the DTMB 5415 (and, with
    /// --hull, of that hull beside it, in the same run).
    Bench {
        /// Preset to time.
        #[arg(default_value = "startup")]
        name: String,
        /// Repetitions (the best is reported).
        #[arg(long, default_value_t = 3)]
        repeat: u32,
        /// `bench seakeeping`: an embedded hull's name or an offsets CSV to time beside the 5415
        /// (its loading: --set ship.hull.draft_m=..., ship.hull.kg_m=...).
        #[arg(long)]
        hull: Option<String>,
        /// Override one parameter (repeatable).
        #[arg(long = "set", value_name = "PATH=VALUE")]
        sets: Vec<String>,
    },
    /// The validation report: every thesis number we compare with, beside ours, with the
    /// difference, tolerance, verdict and reason (Markdown; docs/validation.md). Exit status 1 when
    /// a row leaves its tolerance.
    Validate {
        /// Monte Carlo trials per study (docs/validation.md is made with the default).
        #[arg(long, default_value_t = 200)]
        trials: u64,
        /// Write the report to this file instead of standard output.
        #[arg(long)]
        out: Option<String>,
        /// Compare the report with this file and fail if it differs (a stale committed report).
        #[arg(long)]
        check: Option<String>,
    },
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Side {
    Generator,
    Motor,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Loop {
    Open,
    Closed,
}

#[derive(clap::Args)]
struct IpsPoint {
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

/// The LQG/LTR tuning and operating point, as `controllers.lqg_ltr.*` (defaults there: mu 0.01,
/// omega_p 1 rad/s, q 1000, turbine weight 1, 25 knots).
#[derive(clap::Args)]
struct TuningArgs {
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
    fn apply(&self, t: &mut aes_core::design::LqgLtrParams) {
        t.mu = self.mu.unwrap_or(t.mu);
        t.omega_p_rad_s = self.omega_p.unwrap_or(t.omega_p_rad_s);
        t.q = self.q.unwrap_or(t.q);
        t.turbine_speed_weight = self.turbine_weight.unwrap_or(t.turbine_speed_weight);
        t.design_speed_kn = self.speed_kn.unwrap_or(t.design_speed_kn);
    }
}

#[derive(Subcommand)]
enum DesignCmd {
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

#[derive(Subcommand)]
enum IpsCmd {
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

fn ips(cmd: IpsCmd) -> Result<serde_json::Value, String> {
    use aes_core::stability::{
        bode_frequencies, generator_side::GeneratorSideParams, load_params, motor_side::MotorSideParams,
    };
    let (point, loop_kind, bode) = match cmd {
        IpsCmd::Steady(p) => (p, None, None),
        IpsCmd::Linear { point, loop_kind } => (point, Some(loop_kind), None),
        IpsCmd::Bode { point, loop_kind, from, to, points } => {
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

fn load(file: &str, sets: &[String]) -> Result<Scenario, String> {
    let mut sc = if let Some(name) = file.strip_prefix("preset:") {
        preset(name).ok_or_else(|| format!("no preset named '{}' (try: {})", shorten(name), PRESET_NAMES.join(", ")))?
    } else {
        let text = read_bounded(file, aes_core::scenario_file::MAX_SCENARIO_BYTES as u64, "a scenario")?;
        Scenario::from_json(&text).map_err(|e| format!("{}: invalid scenario:\n{e}", shorten(file)))?
    };
    let mut pairs = Vec::with_capacity(sets.len());
    for s in sets {
        let (path, value) = s
            .split_once('=')
            .ok_or_else(|| format!("--set '{}': expected PATH=VALUE, e.g. sim.duration_s=60", shorten(s)))?;
        pairs.push((path.trim(), value.trim()));
    }
    // All at once: fields that change together (a significant height with its peak frequency)
    // are checked together. An error names its field.
    if !pairs.is_empty() {
        let what = if pairs.len() == 1 { format!("--set {}", shorten(pairs[0].0)) } else { "--set".to_string() };
        sc = sc.with_overrides(&pairs).map_err(|e| format!("{what}: {e}"))?;
    }
    Ok(sc)
}

fn real_main() -> Result<(), Failure> {
    let cli = Cli::parse();
    match cli.command {
        Cmd::Presets => {
            let mut text = String::new();
            for n in PRESET_NAMES {
                let d = preset(n).map(|s| s.description).unwrap_or_default();
                text.push_str(&format!("{n:<12} {d}\n"));
            }
            emit(text.trim_end())?;
        }
        Cmd::Signals { json } => {
            if json {
                emit_json(aes_core::signals::SIGNALS)?;
            } else {
                let mut text = String::new();
                for s in aes_core::signals::SIGNALS {
                    text.push_str(&format!("{:<20} {:<6} {}\n", s.name, s.unit, s.description));
                }
                emit(text.trim_end())?;
            }
        }
        Cmd::Params { json, markdown } => {
            let all = aes_core::registry::all();
            if json {
                emit_json(&all)?;
            } else if markdown {
                emit(aes_core::registry::markdown_table().trim_end())?;
            } else {
                let mut text = String::new();
                for m in &all {
                    let default = match &m.default {
                        serde_json::Value::Null => "-".to_string(),
                        v => shorten(&v.to_string()),
                    };
                    let range = match (m.min, m.max) {
                        (Some(lo), Some(hi)) => {
                            format!("{} .. {}", aes_core::validate::num(lo), aes_core::validate::num(hi))
                        }
                        _ if !m.choices.is_empty() => m.choices.iter().map(|c| c.value).collect::<Vec<_>>().join(" | "),
                        _ => m.kind.to_string(),
                    };
                    text.push_str(&format!(
                        "{:<44} {:<10} {:<14} {:<28} {}\n",
                        m.path, m.unit, default, range, m.label
                    ));
                }
                emit(text.trim_end())?;
            }
        }
        Cmd::Preset { name } => {
            let sc = preset(&name)
                .ok_or_else(|| format!("no preset named '{}' (try: {})", shorten(&name), PRESET_NAMES.join(", ")))?;
            emit(&sc.to_json())?;
        }
        Cmd::Run { file, out, sets } => {
            let sc = load(&file, &sets)?;
            if let Some(path) = &out {
                check_writable(path, "--out")?;
            }
            let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
            let write = |trace: &aes_core::sim::Trace| -> Result<(), String> {
                match &out {
                    Some(path) => std::fs::write(path, trace.to_csv())
                        .map_err(|e| format!("cannot write the trace to '{}': {e}", shorten(path))),
                    None => Ok(()),
                }
            };
            if let Err(e) = sim.advance(u64::MAX) {
                // Keep what led up to the failure: it is what the user needs to see.
                let hint = match write(sim.trace()) {
                    Ok(()) if out.is_some() => " (the trace up to the failure was written)".to_string(),
                    Ok(()) => String::new(),
                    Err(w) => format!(" ({w})"),
                };
                return Err(format!("{e}{hint}").into());
            }
            let result = sim.finish();
            // The summary is printed even when the trace cannot be written: a computed run is never lost.
            let written = write(&result.trace);
            emit_json(&result.summary)?;
            written?;
        }
        Cmd::Design { command: DesignCmd::LqgLtr { file, plant, tuning } } => {
            let input: aes_core::design::lqg_ltr::DesignInput = match (file, plant.as_deref()) {
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
                    let mut sc = aes_core::presets::preset("acceleration").ok_or("no acceleration preset")?;
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
            let d = aes_core::design::lqg_ltr::design(&input)?;
            emit_json(&d)?;
        }
        Cmd::Design { command: DesignCmd::Compare { tuning, json } } => {
            let mut t = aes_core::design::LqgLtrParams::default();
            tuning.apply(&mut t);
            let mut v = aes_core::validate::Validator::new();
            v.section("controllers", |v| v.section("lqg_ltr", |v| aes_core::params::Section::check_fields(&t, v)));
            v.finish().map_err(|e| e.to_string())?;
            let rows = aes_core::controller_study::compare(&t)?;
            if json {
                emit_json(&rows)?;
            } else {
                emit(&aes_core::controller_study::markdown(&rows))?;
            }
        }
        Cmd::Ips { command } => {
            let out = ips(command)?;
            emit_json(&out)?;
        }
        Cmd::Section { beam, draft, area_coeff, form, omega } => {
            let form = match form.as_str() {
                "auto" => FormChoice::Auto,
                "lewis" => FormChoice::Lewis,
                "bulb" => FormChoice::Bulb,
                other => return Err(format!("--form '{other}': expected auto, lewis or bulb").into()),
            };
            let v = section_json(beam, draft, area_coeff, form, &omega, 1025.0, 9.81)?;
            emit_json(&v)?;
        }
        Cmd::Rao {
            hull,
            scenario,
            draft,
            mass,
            kg,
            kxx,
            kyy,
            kzz,
            speed_kn,
            heading_deg,
            omega,
            roll_wave_amplitude,
        } => {
            if !(roll_wave_amplitude.is_finite() && (0.01..=20.0).contains(&roll_wave_amplitude)) {
                return Err(format!("--roll-wave-amplitude = {roll_wave_amplitude} is outside [0.01, 20]").into());
            }
            let mut ship = match &scenario {
                Some(path) => load(path, &[])?.ship,
                None => aes_core::scenario::ShipParams::default(),
            };
            let spec = &mut ship.hull;
            if let Some(h) = &hull {
                if aes_core::ship_hull::HULL_NAMES.contains(&h.as_str()) && h != "custom" {
                    *spec = aes_core::ship_hull::HullSpec { name: h.clone(), ..Default::default() };
                } else {
                    let text = read_bounded(h, aes_core::hull_sections::MAX_HULL_BYTES as u64, "a hull offsets file")?;
                    *spec = aes_core::ship_hull::HullSpec {
                        name: "custom".into(),
                        offsets_csv: text,
                        ..Default::default()
                    };
                }
            }
            if draft.is_some() || mass.is_some() {
                spec.draft_m = draft;
                spec.mass_kg = mass;
            }
            for (field, v) in
                [(&mut spec.kg_m, kg), (&mut spec.kxx_m, kxx), (&mut spec.kyy_m, kyy), (&mut spec.kzz_m, kzz)]
            {
                if v.is_some() {
                    *field = v;
                }
            }
            // The hull section's own checks, with the flags' names for its fields.
            let mut v = aes_core::validate::Validator::new();
            v.section("hull", |v| ship.hull.validate(v, ship.water_density_kg_m3));
            v.finish().map_err(|e| {
                let e = e.to_string();
                format!("{e}\n(--draft, --mass, --kg, --kxx, --kyy, --kzz set hull.draft_m, mass_kg, kg_m, kxx_m, kyy_m, kzz_m)")
            })?;
            let resolved = ship.hull.resolve(ship.water_density_kg_m3).map_err(|(f, e)| format!("hull.{f}: {e}"))?;
            let strips = resolved.strip_ship()?;
            let v = rao_json(
                &strips,
                speed_kn * aes_core::units::KNOT_M_S,
                heading_deg.to_radians(),
                &omega,
                roll_wave_amplitude,
            )?;
            emit_json(&v)?;
        }
        Cmd::Mc { file, trials, seed, threads, trial_range, partial, sets, quiet } => {
            let mut sc = load(&file, &sets)?;
            if let Some(n) = trials {
                sc.monte_carlo.trials = n;
            }
            if let Some(s) = seed {
                sc.sim.seed = s;
            }
            sc.validate().map_err(|e| format!("{}: {e}", shorten(&file)))?;
            let n = sc.monte_carlo.trials;
            let (a, b) = match &trial_range {
                None => (0, n),
                Some(r) => {
                    let (x, y) = r.split_once("..").ok_or_else(|| format!("--trial-range '{r}': expected A..B"))?;
                    let a: u64 =
                        x.trim().parse().map_err(|_| format!("--trial-range '{r}': A is not a whole number"))?;
                    let b: u64 =
                        y.trim().parse().map_err(|_| format!("--trial-range '{r}': B is not a whole number"))?;
                    if a >= b || b > n {
                        return Err(format!("--trial-range {a}..{b}: must satisfy 0 <= A < B <= trials = {n}").into());
                    }
                    (a, b)
                }
            };
            if trial_range.is_some() && partial.is_none() {
                return Err("--trial-range needs --partial FILE (merge the shards with `aes-sim merge`)".into());
            }
            if let Some(path) = &partial {
                check_writable(path, "--partial")?;
            }
            // At most the machine's parallelism: more threads only cost time and memory.
            let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
            let threads = match threads {
                None | Some(0) => cores,
                Some(n) if n > cores => {
                    let _ = writeln!(
                        std::io::stderr(),
                        "aes-sim mc: --threads {n} capped at {cores}, this machine's available parallelism"
                    );
                    cores
                }
                Some(n) => n,
            };
            // The seakeeping tables first (once, shared by every trial): a line on stderr if they
            // take more than a second (a fine grid), so a long silence is explained.
            if sc.sea.kind != aes_core::scenario::SeaKind::Calm {
                let note = SlowNote::start("aes-sim mc: building the seakeeping (RAO) tables", quiet);
                sc.rao_table()?;
                note.finish();
            }
            // What the trials share is built once, not per trial.
            let trials = aes_core::montecarlo::Trials::new(&sc);
            let pool =
                rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| format!("--threads: {e}"))?;
            let t0 = Instant::now();
            let progress = Progress::start(b - a, "aes-sim mc", quiet);
            let result = pool.install(|| {
                use rayon::prelude::*;
                (a..b).into_par_iter().map(|i| progress.tick(trials.run(i))).try_reduce(
                    || aes_core::montecarlo::Partial::empty(&sc),
                    |mut x, y| {
                        x.merge(&y)?;
                        Ok(x)
                    },
                )
            });
            progress.finish();
            let result = result?;
            if !quiet {
                let _ = writeln!(
                    std::io::stderr(),
                    "aes-sim mc: {} trials in {:.2} s on {} threads",
                    b - a,
                    t0.elapsed().as_secs_f64(),
                    pool.current_num_threads()
                );
            }
            // The summary first: it is printed even when the partial cannot be written.
            if trial_range.is_none() {
                emit_json(&aes_core::montecarlo::study_summary(&result)?)?;
            }
            if let Some(path) = &partial {
                let text = serde_json::to_string(&result).map_err(|e| e.to_string())?;
                std::fs::write(path, text).map_err(|e| format!("cannot write '{}': {e}", shorten(path)))?;
            }
        }
        Cmd::Merge { files, files_from, partial } => {
            if let Some(path) = &partial {
                check_writable(path, "--partial")?;
            }
            // The listed names are read line by line as they are merged (never all at once).
            let listed: Box<dyn Iterator<Item = std::io::Result<String>>> = match files_from.as_deref() {
                None => Box::new(std::iter::empty()),
                Some("-") => Box::new(std::io::stdin().lines()),
                Some(list) => {
                    let f = std::fs::File::open(list)
                        .map_err(|e| format!("--files-from '{}': cannot read: {e}", shorten(list)))?;
                    Box::new(std::io::BufRead::lines(std::io::BufReader::new(f)))
                }
            };
            let mut acc: Option<aes_core::montecarlo::Partial> = None;
            for f in files.into_iter().map(Ok).chain(listed) {
                let f = f.map_err(|e| format!("--files-from: {e}"))?;
                if f.trim().is_empty() {
                    continue;
                }
                let text = read_bounded(&f, MAX_PARTIAL_BYTES, "a Monte Carlo partial")?;
                let p = aes_core::montecarlo::Partial::from_json(&text).map_err(|e| format!("{}: {e}", shorten(&f)))?;
                match acc.as_mut() {
                    None => acc = Some(p),
                    Some(a) => a.merge(&p).map_err(|e| format!("{}: {e}", shorten(&f)))?,
                }
            }
            let acc = acc.ok_or("no partials given")?;
            let summary = aes_core::montecarlo::study_summary(&acc)?;
            // A lost shard leaves a smaller study that looks like a whole one: say which trials
            // are missing (a merge of the shards done so far is still allowed).
            let missing = missing_trials(&summary.ranges, summary.trials_requested);
            if !missing.is_empty() {
                let shown: Vec<String> = missing.iter().take(5).map(|(a, b)| format!("{a}..{b}")).collect();
                eprintln!(
                    "aes-sim merge: warning: {} of the study's {} trials merged; missing {}{}",
                    summary.trials,
                    summary.trials_requested,
                    shown.join(", "),
                    if missing.len() > 5 { format!(" and {} more ranges", missing.len() - 5) } else { String::new() }
                );
            }
            emit_json(&summary)?;
            if let Some(path) = &partial {
                let text = serde_json::to_string(&acc).map_err(|e| e.to_string())?;
                std::fs::write(path, text).map_err(|e| format!("cannot write '{}': {e}", shorten(path)))?;
            }
        }
        Cmd::Fuel { file, omega, sets } => {
            let sc = load(&file, &sets)?;
            let omegas = if omega.is_empty() { (3..=15).map(|i| i as f64 / 10.0).collect() } else { omega };
            for &w in &omegas {
                if !(w.is_finite() && (0.1..=5.0).contains(&w)) {
                    return Err(format!("--omega {w}: must be from 0.1 to 5 rad/s").into());
                }
            }
            let rows = aes_core::fuel_study::run(&sc, &omegas)?;
            let extrapolated = rows.iter().any(|r| r.extrapolated);
            let out = serde_json::json!({
                "speed_kn": sc.commands.first().and_then(|c| c.speed_kn),
                "turbine_rated_efficiency": sc.seakeeping.turbine_rated_efficiency,
                "note": if extrapolated { "some turbine loads are below 30 % of rated, where the part-load curve has no data: extrapolated linearly" } else { "" },
                "rows": rows,
            });
            aes_core::validate::check_finite(&rows)?;
            emit_json(&out)?;
        }
        Cmd::Validate { trials, out, check } => {
            if !(1..=100_000).contains(&trials) {
                return Err(format!("--trials = {trials}: must be a whole number from 1 to 100000").into());
            }
            let size = aes_core::validation::Size { trials };
            let sections = aes_core::validation::sections(size)?;
            let text = aes_core::validation::markdown(&sections, size);
            let failed: Vec<String> = sections
                .iter()
                .flat_map(|s| &s.rows)
                .filter(|r| r.verdict == aes_core::validation::Verdict::Fail)
                .map(|r| format!("{}: ours {} against {} ({})", r.quantity, r.ours, r.thesis, r.source))
                .collect();
            if let Some(path) = check {
                let old = read_bounded(&path, 8 << 20, "a validation report")?;
                if let Some((i, (a, b))) = old.lines().zip(text.lines()).enumerate().find(|(_, (a, b))| a != b) {
                    return Err(format!(
                        "{path} is stale (run ./build.sh validate and commit it); line {}:\n  committed: {a}\n  now:       {b}",
                        i + 1
                    )
                    .into());
                }
                if old.lines().count() != text.lines().count() {
                    return Err(format!(
                        "{path} is stale (run ./build.sh validate and commit it): the number of lines differs"
                    )
                    .into());
                }
                check_figures(&path, &sections)?;
            } else if let Some(path) = out {
                std::fs::write(&path, &text).map_err(|e| format!("{path}: {e}"))?;
                write_figures(&path, &sections)?;
            } else {
                emit(&text)?;
            }
            if !failed.is_empty() {
                return Err(format!("{} row(s) outside their tolerance:\n{}", failed.len(), failed.join("\n")).into());
            }
        }
        Cmd::Bench { name, repeat, hull, sets } if name == "seakeeping" => {
            let grid = SeakeepingGrid::default();
            // The other hull's resolved definition (the scenario's `ship.hull` with --hull and --set).
            let other = match &hull {
                None => None,
                Some(h) => {
                    let spec = if aes_core::ship_hull::HULL_NAMES.contains(&h.as_str()) && h != "custom" {
                        aes_core::ship_hull::HullSpec { name: h.clone(), ..Default::default() }
                    } else {
                        let text =
                            read_bounded(h, aes_core::hull_sections::MAX_HULL_BYTES as u64, "a hull offsets file")?;
                        aes_core::ship_hull::HullSpec { name: "custom".into(), offsets_csv: text, ..Default::default() }
                    };
                    // Every --set ship.hull.FIELD=VALUE at once (a custom hull is whole only with all).
                    let mut v = serde_json::to_value(&spec).map_err(|e| e.to_string())?;
                    for s in &sets {
                        let (p, val) =
                            s.split_once('=').ok_or_else(|| format!("--set '{}': expected PATH=VALUE", shorten(s)))?;
                        let field = p.trim().strip_prefix("ship.hull.").ok_or_else(|| {
                            format!("--set '{}': bench seakeeping takes ship.hull.FIELD=VALUE only", shorten(s))
                        })?;
                        v[field] = serde_json::from_str(val.trim())
                            .unwrap_or_else(|_| serde_json::Value::String(val.trim().to_string()));
                    }
                    let spec: aes_core::ship_hull::HullSpec =
                        serde_json::from_value(v).map_err(|e| format!("ship.hull: {}", shorten(&e.to_string())))?;
                    let mut check = aes_core::validate::Validator::new();
                    check.section("ship.hull", |c| spec.validate(c, 1025.0));
                    check.finish().map_err(|e| e.to_string())?;
                    let hull = spec.resolve(1025.0).map_err(|(f, e)| format!("ship.hull.{f}: {e}"))?;
                    Some(hull.strip_ship()?)
                }
            };
            let five = Ship::dtmb5415();
            // Best of `repeat`, the two hulls alternating so that both see the same machine.
            let time = |ship: &Ship| {
                let t0 = Instant::now();
                let rad = ship.radiation_table(&default_omega_grid());
                let t1 = Instant::now();
                std::hint::black_box(RaoTable::from_radiation(ship, &rad, &grid));
                ((t1 - t0).as_secs_f64(), t1.elapsed().as_secs_f64())
            };
            let (mut best, mut best_other) = ((f64::INFINITY, f64::INFINITY), (f64::INFINITY, f64::INFINITY));
            for _ in 0..repeat.max(1) {
                let t = time(&five);
                best = (best.0.min(t.0), best.1.min(t.1));
                if let Some(o) = &other {
                    let t = time(o);
                    best_other = (best_other.0.min(t.0), best_other.1.min(t.1));
                }
            }
            let mut out = serde_json::json!({
                "workload": format!("DTMB 5415: sectional coefficients of {} strips at 48 encounter frequencies, then RAOs and drift on the 40 x 6 x 13 grid", five.strips.len()),
                "sections_s": best.0,
                "rao_grid_s": best.1,
                "total_s": best.0 + best.1,
            });
            if let Some(o) = &other {
                out["hull"] = serde_json::json!({
                    "strips": o.strips.len(),
                    "sections_s": best_other.0,
                    "rao_grid_s": best_other.1,
                    "total_s": best_other.0 + best_other.1,
                    // Issue 15's measure: this hull's table build over the 5415's, same run.
                    "over_dtmb5415": (best_other.0 + best_other.1) / (best.0 + best.1),
                });
            }
            emit_json(&out)?;
        }
        Cmd::Bench { name, repeat, sets, .. } => {
            let sc = load(&format!("preset:{name}"), &sets)?;
            let mut best = f64::INFINITY;
            let mut steps = 0;
            for _ in 0..repeat.max(1) {
                let t0 = Instant::now();
                let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
                sim.advance(u64::MAX).map_err(|e| e.to_string())?;
                let r = sim.finish();
                best = best.min(t0.elapsed().as_secs_f64());
                steps = r.summary.steps;
            }
            let sim_s = sc.sim.duration_s;
            // Where a run's time goes: the same run with a clock read at the end of each part of
            // every step (the repetition with the least in all), less the clock's own cost.
            let lap_s = clock_lap_s();
            let mut parts: Option<(f64, [f64; 4], f64)> = None;
            for _ in 0..repeat.max(1) {
                let t0 = Instant::now();
                let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
                let setup = t0.elapsed().as_secs_f64();
                let mut probe = LapProbe { last: Instant::now(), spent: [0.0; 4], laps: 0 };
                sim.advance_probed(u64::MAX, &mut probe).map_err(|e| e.to_string())?;
                let per_part = probe.laps as f64 / 4.0;
                let spent = probe.spent.map(|t| (t - per_part * lap_s).max(0.0));
                let t1 = Instant::now();
                std::hint::black_box(sim.finish());
                let finish = t1.elapsed().as_secs_f64();
                let total = setup + spent.iter().sum::<f64>() + finish;
                if parts.is_none_or(|(s, p, f)| total < s + p.iter().sum::<f64>() + f) {
                    parts = Some((setup, spent, finish));
                }
            }
            // The irreducible part in waves: the bare superposition of the wave components (one sum
            // per sample period, as the run does it).
            let mut wave_sums_s = None;
            for _ in 0..repeat.max(1) {
                if let Some(mut sea) = aes_core::sim::seaway::Seaway::new(&sc)? {
                    let n = (sim_s / sc.stepping.sea_sample_s).round() as u64;
                    sea.refresh(12.86, 0.0);
                    let t0 = Instant::now();
                    let mut acc = 0.0;
                    for i in 0..n {
                        let t = i as f64 * sc.stepping.sea_sample_s;
                        acc += sea.sample(t, 12.86 * t, 0.0, 12.86, 0.0).hub[0];
                    }
                    std::hint::black_box(acc);
                    let s = t0.elapsed().as_secs_f64();
                    wave_sums_s = Some(wave_sums_s.map_or(s, |b: f64| b.min(s)));
                }
            }
            let parts = parts.map(|(setup, [ctl, sea, plant, rest], finish)| {
                serde_json::json!({
                    // Simulation::new: the plant, the steady state, the seaway's components (and,
                    // in the first repetition, the RAO table, which a process builds once).
                    "setup_s": setup,
                    "controllers_s": ctl,
                    // The RAO look-ups, the wave sums, the hub depth and the propellers' ventilation.
                    "sea_s": sea,
                    "plant_s": plant,
                    // The checks, the commands and the recorded rows.
                    "rest_s": rest,
                    // The summary of the trace.
                    "finish_s": finish,
                    // The clock's own cost, taken off each part once a step.
                    "clock_lap_s": lap_s,
                    // Issue 17's target 2, the whole trial within 2x of the bare sums, leaves one
                    // sums' time for everything else: the plant and the controllers alone take this.
                    "plant_and_controllers_over_wave_sums": wave_sums_s.map(|w| (plant + ctl) / w),
                })
            });
            let out = serde_json::json!({
                "parts": parts,
                "wave_sums_s": wave_sums_s,
                // Issue 17's measure: the full model's time over the bare wave kernel's, same steps.
                "full_over_wave_sums": wave_sums_s.map(|w| best / w),
                "wave_components": if wave_sums_s.is_some() { Some(sc.sea.components) } else { None },
                "preset": name,
                "simulated_s": sim_s,
                "steps": steps,
                "wall_s": best,
                "realtime_factor": sim_s / best,
                "ns_per_step": best * 1e9 / steps.max(1) as f64,
            });
            emit_json(&out)?;
        }
    }
    Ok(())
}

/// A line on stderr when a step takes more than a second ("... (done in N s)" when it ends);
/// nothing for a quick step or when quiet.
struct SlowNote {
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl SlowNote {
    fn start(what: &'static str, quiet: bool) -> SlowNote {
        use std::sync::atomic::{AtomicBool, Ordering};
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let thread = (!quiet).then(|| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                let t0 = Instant::now();
                while !stop.load(Ordering::Relaxed) && t0.elapsed().as_secs_f64() < 1.0 {
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                }
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                let _ = writeln!(std::io::stderr(), "{what} ...");
                while !stop.load(Ordering::Relaxed) {
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                }
                let _ = writeln!(std::io::stderr(), "{what}: done in {:.1} s", t0.elapsed().as_secs_f64());
            })
        });
        SlowNote { stop, thread }
    }

    fn finish(mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

/// The trial ranges of 0..`requested` that `ranges` (the merged shards' ranges) leave out.
fn missing_trials(ranges: &[(u64, u64)], requested: u64) -> Vec<(u64, u64)> {
    let mut sorted = ranges.to_vec();
    sorted.sort_unstable();
    let mut gaps = Vec::new();
    let mut next = 0;
    for (a, b) in sorted {
        if a > next {
            gaps.push((next, a.min(requested)));
        }
        next = next.max(b);
    }
    if next < requested {
        gaps.push((next, requested));
    }
    gaps.retain(|(a, b)| a < b);
    gaps
}

/// `aes-sim bench`'s probe: the time since the last part's end, added to the part that ends now.
struct LapProbe {
    last: Instant,
    /// Seconds per part ([`StepPart`] order).
    spent: [f64; 4],
    laps: u64,
}

impl aes_core::sim::StepProbe for LapProbe {
    #[inline(always)]
    fn done(&mut self, part: aes_core::sim::StepPart) {
        let now = Instant::now();
        self.spent[part as usize] += (now - self.last).as_secs_f64();
        self.last = now;
        self.laps += 1;
    }
}

/// The clock's own cost in one lap of [`LapProbe`] with nothing between two reads [s] (the
/// least of a few batches).
fn clock_lap_s() -> f64 {
    use aes_core::sim::StepProbe;
    const N: u64 = 20_000;
    (0..5)
        .map(|_| {
            let mut p = LapProbe { last: Instant::now(), spent: [0.0; 4], laps: 0 };
            let t0 = Instant::now();
            for _ in 0..N {
                p.done(std::hint::black_box(aes_core::sim::StepPart::Rest));
            }
            t0.elapsed().as_secs_f64() / N as f64
        })
        .fold(f64::INFINITY, f64::min)
}

/// Progress of a long command on stderr: on a terminal a bar redrawn in place (done, rate, time
/// left); otherwise (a scheduler's log) a plain line every 10 s; nothing when quiet.
struct Progress {
    done: std::sync::Arc<std::sync::atomic::AtomicU64>,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Progress {
    fn start(total: u64, label: &'static str, quiet: bool) -> Progress {
        use std::io::IsTerminal;
        use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
        use std::sync::Arc;
        let (done, stop) = (Arc::new(AtomicU64::new(0)), Arc::new(AtomicBool::new(false)));
        let thread = (!quiet).then(|| {
            let (done, stop) = (done.clone(), stop.clone());
            let tty = std::io::stderr().is_terminal();
            std::thread::spawn(move || {
                let t0 = Instant::now();
                let every = if tty { 0.25 } else { 10.0 };
                let mut last = 0.0;
                let line = |n: u64, bar: bool| {
                    let s = t0.elapsed().as_secs_f64();
                    let rate = n as f64 / s.max(1e-9);
                    let left = if n > 0 { format!("{:.0} s left", (total - n) as f64 / rate) } else { "".into() };
                    let text = format!("{n}/{total} trials, {rate:.1}/s, {left}");
                    if bar {
                        let w = 30;
                        let k = (w as u64 * n / total.max(1)) as usize;
                        format!("\r{label} [{}{}] {text}\x1b[K", "#".repeat(k), ".".repeat(w - k))
                    } else {
                        format!("{label}: {text}\n")
                    }
                };
                while !stop.load(Ordering::Relaxed) {
                    // Woken early by finish(): a short run does not wait for the next tick.
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                    let s = t0.elapsed().as_secs_f64();
                    if s - last >= every {
                        last = s;
                        let _ = write!(std::io::stderr(), "{}", line(done.load(Ordering::Relaxed), tty));
                    }
                }
                if tty {
                    let _ = writeln!(std::io::stderr(), "{}", line(done.load(Ordering::Relaxed), true));
                }
            })
        });
        Progress { done, stop, thread }
    }

    /// Counts one finished piece of work and passes its result on.
    fn tick<T>(&self, r: T) -> T {
        self.done.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        r
    }

    fn finish(mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

/// Exit status: 0 on success and when standard output is closed by its reader (`| head`);
/// 1 with a message on stderr for every error; 2 for a command line clap refuses.
/// The directory of a validation report's figures: docs/validation.md -> docs/validation/.
fn figure_dir(report: &str) -> std::path::PathBuf {
    std::path::Path::new(report).parent().unwrap_or(std::path::Path::new("")).join(aes_core::validation::FIGURE_DIR)
}

/// Writes the report's figures beside it, and removes figures it no longer makes.
fn write_figures(report: &str, sections: &[aes_core::validation::Section]) -> Result<(), String> {
    let dir = figure_dir(report);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let made: Vec<String> = sections.iter().flat_map(|s| &s.figures).map(|f| format!("{}.svg", f.name)).collect();
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        std::fs::write(&p, &f.svg).map_err(|e| format!("{}: {e}", p.display()))?;
    }
    for name in stray_figures(&dir, &made)? {
        let p = dir.join(&name);
        std::fs::remove_file(&p).map_err(|e| format!("{}: {e}", p.display()))?;
    }
    Ok(())
}

/// SVG files in `dir` the report does not make.
fn stray_figures(dir: &std::path::Path, made: &[String]) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let name = e.map_err(|e| e.to_string())?.file_name().to_string_lossy().into_owned();
        if name.ends_with(".svg") && !made.contains(&name) {
            out.push(name);
        }
    }
    out.sort();
    Ok(out)
}

/// Fails when a committed figure differs from the one the report makes now, is missing, or is
/// one the report no longer makes.
fn check_figures(report: &str, sections: &[aes_core::validation::Section]) -> Result<(), String> {
    let dir = figure_dir(report);
    let mut made = Vec::new();
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        let shown = p.display().to_string();
        let old = read_bounded(&shown, 8 << 20, "a validation figure")
            .map_err(|e| format!("{e} (run ./build.sh validate and commit the figures)"))?;
        if old != f.svg {
            return Err(format!("{shown} is stale (run ./build.sh validate and commit it)"));
        }
        made.push(format!("{}.svg", f.name));
    }
    let stray = stray_figures(&dir, &made)?;
    if !stray.is_empty() {
        return Err(format!("{}: figures the report no longer makes: {}", dir.display(), stray.join(", ")));
    }
    Ok(())
}

/// Whether the kernel's list of this CPU's features lacks AVX2 (false when it cannot be read). Not
/// `is_x86_feature_detected!`: in a build for AVX2 that answers yes without asking the CPU.
#[cfg(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2"))]
#[inline(never)]
fn cpu_lacks_avx2() -> bool {
    std::fs::read_to_string("/proc/cpuinfo").is_ok_and(|info| flags_lack_avx2(&info))
}

/// Whether the first `flags` line of a /proc/cpuinfo text lacks the word avx2 (false without one).
#[cfg_attr(not(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2")), allow(dead_code))]
fn flags_lack_avx2(cpuinfo: &str) -> bool {
    cpuinfo
        .lines()
        .find(|l| l.starts_with("flags"))
        .is_some_and(|flags| !flags.split_whitespace().skip(2).any(|f| f == "avx2"))
}

fn main() -> ExitCode {
    // .cargo/config.toml builds for AVX2: say so on a CPU without it rather than die of an
    // illegal instruction somewhere in a run.
    #[cfg(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2"))]
    if cpu_lacks_avx2() {
        let _ = writeln!(
            std::io::stderr(),
            "aes-sim: this build needs a CPU with AVX2 (x86_64 from about 2013 on); on an older one \
             remove the rustflags of .cargo/config.toml and build again"
        );
        return ExitCode::FAILURE;
    }
    match real_main() {
        Ok(()) | Err(Failure::PipeClosed) => ExitCode::SUCCESS,
        Err(Failure::Msg(e)) => {
            let _ = writeln!(std::io::stderr(), "aes-sim: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    /// The AVX2 check reads the kernel's flags: a word, not a prefix (avx512f is not avx2).
    #[test]
    fn avx2_is_read_from_the_flags_line() {
        let has = "processor\t: 0\nflags\t\t: fpu sse2 avx avx2 fma\nbugs\t\t: none\n";
        let lacks = "processor\t: 0\nflags\t\t: fpu sse2 avx avx512f\n";
        assert!(!super::flags_lack_avx2(has));
        assert!(super::flags_lack_avx2(lacks));
        assert!(!super::flags_lack_avx2("no flags here"));
        // A test binary built for AVX2 runs only on a CPU with it: the real flags must say so.
        if let (true, Ok(info)) = (cfg!(target_feature = "avx2"), std::fs::read_to_string("/proc/cpuinfo")) {
            assert!(!super::flags_lack_avx2(&info));
        }
    }
}
