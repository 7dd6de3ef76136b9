//! `aes-sim fuel`: the fuel study of ch. 5.2.4 (Fig. 5-12).

use crate::common::{emit_json, load, Failure};

// The command line of `aes-sim fuel`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (default: the fuel-regular-seas preset); its first ordered speed is used.
    #[arg(default_value = "preset:fuel-regular-seas")]
    file: String,
    /// Wave frequencies [rad/s], comma separated (default 0.3 to 1.5 in steps of 0.1).
    #[arg(long, value_delimiter = ',')]
    omega: Vec<f64>,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { file, omega, sets }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    let rows = aes_core::studies::fuel::run(&sc, &omega)?;
    let extrapolated = rows.iter().any(|r| r.extrapolated);
    let out = serde_json::json!({
        "speed_kn": sc.commands.first().and_then(|c| c.speed_kn),
        "turbine_rated_efficiency": sc.seakeeping.turbine_rated_efficiency,
        "note": if extrapolated { "some turbine loads are below 30 % of rated, where the part-load curve has no data: extrapolated linearly" } else { "" },
        "rows": rows,
    });
    aes_core::checks::check_finite(&rows)?;
    emit_json(&out)?;
    Ok(())
}
