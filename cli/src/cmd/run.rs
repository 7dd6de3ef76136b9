//! `aes-sim run`: one scenario to its end.

use crate::common::{emit_json, load, Failure, OutFile};
use aes_core::Simulation;

// The command line of `aes-sim run`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario JSON file, `-` for standard input, or `preset:NAME`.
    file: String,
    /// Write the recorded trace as CSV to this file.
    #[arg(long)]
    out: Option<String>,
    /// Override one parameter, e.g. `--set sim.duration_s=60` (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { file, out, sets }: Args) -> Result<(), Failure> {
    // The output is checked before anything is read or computed, and written only at the end.
    let out = out.map(|path| OutFile::check(&path, "--out", &[&file])).transpose()?;
    let sc = load(&file, &sets)?;
    let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
    let write = |trace: &aes_core::sim::Trace| -> Result<(), String> {
        match &out {
            Some(out) => out.write(trace.to_csv().as_bytes()),
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
    Ok(())
}
