//! `aes-sim health`: the plant's health checks every run's summary applies (its `warnings`).

use crate::common::{emit, Failure};

// The command line of `aes-sim health`.
#[derive(clap::Args)]
pub struct Args {
    /// The book's table, docs/reference/health.md (Markdown).
    #[arg(long)]
    markdown: bool,
}

pub fn run(Args { markdown }: Args) -> Result<(), Failure> {
    if markdown {
        emit(aes_core::sim::health::markdown().trim_end())?;
    } else {
        let mut text = String::new();
        for c in aes_core::sim::health::checks() {
            text.push_str(&format!("{}\n  warns when: {}\n  why: {}\n", c.name, c.threshold, c.reason));
        }
        emit(text.trim_end())?;
    }
    Ok(())
}
