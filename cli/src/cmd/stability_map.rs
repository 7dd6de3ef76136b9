//! `aes-sim stability-map`: is the bus stable at the scenario's operating point, and where over
//! two parameters does it stop being (`aes_core::studies::stability_map`); JSON on standard
//! output. A map is a study on the shared pipeline (its rows the items: `--trial-range`,
//! `--partial`, `--merge`, `aes-sim merge`).

use crate::common::{emit_json, load, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::scenario::Scenario;
use aes_core::studies::stability_map::{linearize, Axis, StabilityMapSpec, StabilityMapStudy};
use aes_core::studies::study::Study;

// The command line of `aes-sim stability-map`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario JSON file, `-` for standard input, or `preset:NAME`; linearised at its
    /// `initial.speed_kn` (above 0).
    file: String,
    /// Override one parameter, e.g. `--set plant.loads.ship_service_w=2e6` (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
    /// The map's x axis: a scenario number and its values, `PATH=FROM:TO:N`, e.g.
    /// `plant.loads.ship_service_w=1e6:2e7:20`. Without --x and --y: the eigenvalues at the point.
    #[arg(long, value_name = "PATH=FROM:TO:N")]
    x: Option<String>,
    /// The map's y axis, as --x, e.g. `plant.loads.filter_capacitance_f=0.005:0.04:8`.
    #[arg(long, value_name = "PATH=FROM:TO:N")]
    y: Option<String>,
    #[command(flatten)]
    shards: ShardArgs,
}

fn axis(sc: &Scenario, flag: &str, text: &str) -> Result<Axis, String> {
    let bad = || format!("{flag} {text}: expected PATH=FROM:TO:N, e.g. plant.loads.ship_service_w=1e6:2e7:20");
    let (path, range) = text.split_once('=').ok_or_else(bad)?;
    let parts: Vec<&str> = range.split(':').collect();
    let [lo, hi, n] = parts.as_slice() else { return Err(bad()) };
    let (lo, hi): (f64, f64) = (lo.trim().parse().map_err(|_| bad())?, hi.trim().parse().map_err(|_| bad())?);
    let n: usize = n.trim().parse().map_err(|_| bad())?;
    Axis::checked(sc, flag, path.trim(), lo, hi, n)
}

pub fn run(Args { file, sets, x, y, shards }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    match (x, y) {
        (None, None) if shards.range.is_none() && shards.partial.is_none() && shards.merge.is_empty() => {
            emit_json(&linearize(&sc)?)
        }
        (None, None) => Err("--trial-range, --partial and --merge are for a map: give --x and --y".to_string().into()),
        (Some(x), Some(y)) => {
            let (x, y) = (axis(&sc, "--x", &x)?, axis(&sc, "--y", &y)?);
            let study = StabilityMapStudy::new(StabilityMapSpec { scenario: sc, x, y })?;
            execute(study, &shards, "stability-map", &file, |_, m| emit_json(m))
        }
        _ => Err("give both --x and --y for a map, or neither for the eigenvalues at the point".to_string().into()),
    }
}
