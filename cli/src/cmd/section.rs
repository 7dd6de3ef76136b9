//! `aes-sim section`: sectional added mass and damping (ch. 2.5.1).

use crate::common::{emit_json, Failure};
use aes_core::sea::seakeeping::tables::{section_json, FormChoice};

// The command line of `aes-sim section`.
#[derive(clap::Args)]
pub struct Args {
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
}

pub fn run(Args { beam, draft, area_coeff, form, omega }: Args) -> Result<(), Failure> {
    let form = match form.as_str() {
        "auto" => FormChoice::Auto,
        "lewis" => FormChoice::Lewis,
        "bulb" => FormChoice::Bulb,
        other => return Err(format!("--form '{other}': expected auto, lewis or bulb").into()),
    };
    let v = section_json(beam, draft, area_coeff, form, &omega, 1025.0, 9.81)?;
    emit_json(&v)?;
    Ok(())
}
