//! `aes-sim`: the command line of the All Electric Ship simulator.

use aes_core::presets::{preset, PRESET_NAMES};
use aes_core::{Scenario, Simulation};
use clap::{Parser, Subcommand};
use std::io::Read;
use std::process::ExitCode;
use std::time::Instant;

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
    /// Measure simulated seconds per wall-clock second on a preset (default: startup).
    Bench {
        /// Preset to time.
        #[arg(default_value = "startup")]
        name: String,
        /// Repetitions (the best is reported).
        #[arg(long, default_value_t = 3)]
        repeat: u32,
        /// Override one parameter (repeatable).
        #[arg(long = "set", value_name = "PATH=VALUE")]
        sets: Vec<String>,
    },
}

fn load(file: &str, sets: &[String]) -> Result<Scenario, String> {
    let mut sc = if let Some(name) = file.strip_prefix("preset:") {
        preset(name).ok_or_else(|| format!("no preset named '{name}' (try: {})", PRESET_NAMES.join(", ")))?
    } else {
        let text = if file == "-" {
            let mut s = String::new();
            std::io::stdin().read_to_string(&mut s).map_err(|e| format!("cannot read standard input: {e}"))?;
            s
        } else {
            std::fs::read_to_string(file).map_err(|e| format!("cannot read '{file}': {e}"))?
        };
        Scenario::from_json(&text).map_err(|e| format!("{file}: invalid scenario:\n{e}"))?
    };
    for s in sets {
        let (path, value) =
            s.split_once('=').ok_or_else(|| format!("--set '{s}': expected PATH=VALUE, e.g. sim.duration_s=60"))?;
        sc = sc.with_override(path.trim(), value.trim()).map_err(|e| format!("--set {s}: {e}"))?;
    }
    Ok(sc)
}

fn real_main() -> Result<(), String> {
    let cli = Cli::parse();
    match cli.command {
        Cmd::Presets => {
            for n in PRESET_NAMES {
                let d = preset(n).map(|s| s.description).unwrap_or_default();
                println!("{n:<12} {d}");
            }
        }
        Cmd::Preset { name } => {
            let sc =
                preset(&name).ok_or_else(|| format!("no preset named '{name}' (try: {})", PRESET_NAMES.join(", ")))?;
            println!("{}", sc.to_json());
        }
        Cmd::Run { file, out, sets } => {
            let sc = load(&file, &sets)?;
            let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
            let write = |trace: &aes_core::sim::Trace| -> Result<(), String> {
                match &out {
                    Some(path) => {
                        std::fs::write(path, trace.to_csv()).map_err(|e| format!("cannot write '{path}': {e}"))
                    }
                    None => Ok(()),
                }
            };
            if let Err(e) = sim.advance(u64::MAX) {
                // Keep what led up to the failure: it is what the user needs to see.
                write(sim.trace())?;
                let hint = if out.is_some() { " (the trace up to the failure was written)" } else { "" };
                return Err(format!("{e}{hint}"));
            }
            let result = sim.finish();
            write(&result.trace)?;
            let json = serde_json::to_string_pretty(&result.summary.to_json_value()).map_err(|e| e.to_string())?;
            println!("{json}");
        }
        Cmd::Bench { name, repeat, sets } => {
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
            let out = serde_json::json!({
                "preset": name,
                "simulated_s": sim_s,
                "steps": steps,
                "wall_s": best,
                "realtime_factor": sim_s / best,
                "ns_per_step": best * 1e9 / steps.max(1) as f64,
            });
            println!("{}", serde_json::to_string_pretty(&out).map_err(|e| e.to_string())?);
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    match real_main() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("aes-sim: {e}");
            ExitCode::FAILURE
        }
    }
}
