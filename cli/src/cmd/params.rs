//! `aes-sim params`: every scenario parameter's declaration.

use crate::common::{emit, emit_json, shorten, Failure};

// The command line of `aes-sim params`.
#[derive(clap::Args)]
pub struct Args {
    #[arg(long, conflicts_with = "markdown")]
    json: bool,
    #[arg(long)]
    markdown: bool,
}

pub fn run(Args { json, markdown }: Args) -> Result<(), Failure> {
    let all = aes_core::scenario::registry::all();
    if json {
        emit_json(&all)?;
    } else if markdown {
        emit(aes_core::scenario::registry::markdown_table().trim_end())?;
    } else {
        let mut text = String::new();
        for m in &all {
            let default = match &m.default {
                serde_json::Value::Null => "-".to_string(),
                v => shorten(&v.to_string()),
            };
            let range = match (m.min, m.max) {
                (Some(lo), Some(hi)) => {
                    format!("{} .. {}", aes_core::checks::num(lo), aes_core::checks::num(hi))
                }
                _ if !m.choices.is_empty() => m.choices.iter().map(|c| c.value).collect::<Vec<_>>().join(" | "),
                _ => m.kind.to_string(),
            };
            let unused = if m.unused_with.is_empty() {
                String::new()
            } else {
                format!(" (not used with {})", m.unused_with.join(" or "))
            };
            text.push_str(&format!(
                "{:<44} {:<10} {:<14} {:<28} {}{unused}\n",
                m.path, m.unit, default, range, m.label
            ));
        }
        emit(text.trim_end())?;
    }
    Ok(())
}
