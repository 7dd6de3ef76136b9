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
    /// Run on this blade table (CSV with the header r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D):
    /// `propeller.model = "geometry"` with it as `propeller.geometry` (name "custom").
    #[arg(long, value_name = "FILE")]
    propeller_csv: Option<String>,
    /// Blades of `--propeller-csv`'s propeller.
    #[arg(long, default_value_t = 3)]
    blades: u32,
    /// Hub diameter over propeller diameter of `--propeller-csv`'s propeller.
    #[arg(long, default_value_t = 0.2)]
    hub_ratio: f64,
}

pub fn run(Args { file, out, sets, propeller_csv, blades, hub_ratio }: Args) -> Result<(), Failure> {
    // The output is checked before anything is read or computed, and written only at the end.
    let out = out.map(|path| OutFile::check(&path, "--out", &[&file])).transpose()?;
    let mut sc = load(&file, &sets)?;
    if let Some(csv) = propeller_csv {
        use aes_core::plant::{blade::geometry::MAX_CSV_BYTES, propeller_geometry::GeometrySpec};
        let text = crate::common::read_bounded(&csv, MAX_CSV_BYTES as u64, "a blade table")?;
        let spec = GeometrySpec::from_csv(&text, blades, hub_ratio)
            .map_err(|e| format!("--propeller-csv {}: {e}", crate::common::shorten(&csv)))?;
        let json = serde_json::to_string(&spec).map_err(|e| e.to_string())?;
        sc = sc
            .with_overrides(&[("propeller.model", "\"geometry\""), ("propeller.geometry", &json)])
            .map_err(|e| format!("--propeller-csv {}: {e}", crate::common::shorten(&csv)))?;
    }
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
