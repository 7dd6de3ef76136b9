//! `aes-sim fuel-per-mile`: fuel per nautical mile against ordered speed, over seas of several
//! seeds (core's studies::fuel_per_mile), whole or one shard of it.

use crate::common::{emit_json, load, shorten, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::studies::fuel_per_mile::{FuelPerMileSpec, FuelPerMileStudy};
use aes_core::studies::study::Study;

// The command line of `aes-sim fuel-per-mile`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (file, `-` or `preset:NAME`): its sea, ship, plant and run length.
    #[arg(default_value = "preset:head-seas-ss6")]
    file: String,
    /// Ordered speeds [kn], comma separated.
    #[arg(long, value_delimiter = ',', default_value = "12,15,18,21,24,27")]
    speeds: Vec<f64>,
    /// Seas (seeds) per speed.
    #[arg(long, default_value_t = 3)]
    seeds: u64,
    /// Start of the measurement [s] (after the speed has settled; default: half the run).
    #[arg(long)]
    from: Option<f64>,
    #[command(flatten)]
    shards: ShardArgs,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { file, speeds, seeds, from, shards, sets }: Args) -> Result<(), Failure> {
    let scenario = load(&file, &sets)?;
    let from_s = from.unwrap_or(0.5 * scenario.sim.duration_s);
    let spec = FuelPerMileSpec { scenario, speeds_kn: speeds, seeds, from_s };
    let study = FuelPerMileStudy::new(spec).map_err(|e| format!("{}: {e}", shorten(&file)))?;
    execute(study, &shards, "fuel-per-mile", &file, |_, summary| emit_json(summary))
}
