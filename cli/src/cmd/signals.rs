//! `aes-sim signals`: the trace columns.

use crate::common::{emit, emit_json, Failure};

// The command line of `aes-sim signals`.
#[derive(clap::Args)]
pub struct Args {
    #[arg(long)]
    json: bool,
}

pub fn run(Args { json }: Args) -> Result<(), Failure> {
    if json {
        emit_json(aes_core::signals::SIGNALS)?;
    } else {
        let mut text = String::new();
        for s in aes_core::signals::SIGNALS {
            text.push_str(&format!("{:<20} {:<6} {}\n", s.name, s.unit, s.description));
        }
        emit(text.trim_end())?;
    }
    Ok(())
}
