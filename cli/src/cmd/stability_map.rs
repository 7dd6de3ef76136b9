//! `aes-sim stability-map`: is the bus stable at the scenario's operating point, and where over
//! two parameters does it stop being (`aes_core::studies::stability_map`); JSON on standard
//! output.

use crate::common::{emit_json, load, Failure};
use aes_core::scenario::Scenario;
use aes_core::studies::stability_map::{linearize, map, Axis};

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

pub fn run(Args { file, sets, x, y }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    match (x, y) {
        (None, None) => emit_json(&linearize(&sc)?),
        (Some(x), Some(y)) => emit_json(&map(&sc, &axis(&sc, "--x", &x)?, &axis(&sc, "--y", &y)?)?),
        _ => Err("give both --x and --y for a map, or neither for the eigenvalues at the point".to_string().into()),
    }
}
