//! `aes-sim mc`: a Monte Carlo study, whole or one shard of it (ch. 5.4).

use crate::common::{emit_json, load, shorten, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::studies::montecarlo::MonteCarlo;
use aes_core::studies::study::Study;

// The command line of `aes-sim mc`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario JSON file, `-` or `preset:NAME` (its `monte_carlo` section says what to collect).
    file: String,
    /// Number of trials (default: the scenario's monte_carlo.trials).
    #[arg(long)]
    trials: Option<u64>,
    /// Master seed (default: the scenario's sim.seed); trial i uses a seed made from it and i.
    #[arg(long)]
    seed: Option<u64>,
    #[command(flatten)]
    shards: ShardArgs,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { file, trials, seed, shards, sets }: Args) -> Result<(), Failure> {
    let mut sc = load(&file, &sets)?;
    if let Some(n) = trials {
        sc.monte_carlo.trials = n;
    }
    if let Some(s) = seed {
        sc.sim.seed = s;
    }
    sc.validate().map_err(|e| format!("{}: {e}", shorten(&file)))?;
    // What the study keeps and the work it asks for, before anything runs.
    let study = MonteCarlo::new(sc).map_err(|e| format!("{}: {e}", shorten(&file)))?;
    execute(study, &shards, "mc", &file, |_, summary| emit_json(summary))
}
