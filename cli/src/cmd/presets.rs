//! `aes-sim presets` and `aes-sim preset`: the preset scenarios.

use crate::common::{emit, shorten, Failure};
use aes_core::scenario::presets::{preset, PRESET_NAMES};

// The command line of `aes-sim preset`.
#[derive(clap::Args)]
pub struct Args {
    /// Preset name (see `aes-sim presets`).
    name: String,
}

/// `aes-sim presets`: their names and descriptions.
pub fn list() -> Result<(), Failure> {
    let mut text = String::new();
    for n in PRESET_NAMES {
        let d = preset(n).map(|s| s.description).unwrap_or_default();
        text.push_str(&format!("{n:<12} {d}\n"));
    }
    emit(text.trim_end())?;
    Ok(())
}

/// `aes-sim preset NAME`: one as JSON.
pub fn print(Args { name }: Args) -> Result<(), Failure> {
    let sc = preset(&name)
        .ok_or_else(|| format!("no preset named '{}' (try: {})", shorten(&name), PRESET_NAMES.join(", ")))?;
    emit(&sc.to_json())?;
    Ok(())
}
