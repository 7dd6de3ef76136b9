//! `aes-sim merge`: Monte Carlo shards into the study's summary.

use crate::common::{emit_json, read_bounded, shorten, Failure, OutFile};

/// Largest Monte Carlo partial file [bytes].
const MAX_PARTIAL_BYTES: u64 = 512 << 20;

// The command line of `aes-sim merge`.
#[derive(clap::Args)]
pub struct Args {
    /// Partial files.
    #[arg(required_unless_present = "files_from")]
    files: Vec<String>,
    /// Also merge the partial files listed in this file, one path a line (`-`: standard input;
    /// for more shards than a command line holds).
    #[arg(long = "files-from", value_name = "LIST")]
    files_from: Option<String>,
    /// Also write the merged partial to this file.
    #[arg(long)]
    partial: Option<String>,
}

pub fn run(Args { files, files_from, partial }: Args) -> Result<(), Failure> {
    // The output may not be one of the inputs (the shard would be lost): the named partials,
    // the list, and (below) every partial the list names. Written only at the end.
    let inputs: Vec<&str> = files.iter().map(String::as_str).chain(files_from.as_deref()).collect();
    let partial = partial.map(|path| OutFile::check(&path, "--partial", &inputs)).transpose()?;
    // The listed names are read line by line as they are merged (never all at once).
    let listed: Box<dyn Iterator<Item = std::io::Result<String>>> = match files_from.as_deref() {
        None => Box::new(std::iter::empty()),
        Some("-") => Box::new(std::io::stdin().lines()),
        Some(list) => {
            let f =
                std::fs::File::open(list).map_err(|e| format!("--files-from '{}': cannot read: {e}", shorten(list)))?;
            Box::new(std::io::BufRead::lines(std::io::BufReader::new(f)))
        }
    };
    let mut merged = aes_core::studies::montecarlo::Merged::default();
    for f in files.into_iter().map(Ok).chain(listed) {
        let f = f.map_err(|e| format!("--files-from: {e}"))?;
        if f.trim().is_empty() {
            continue;
        }
        if let Some(out) = &partial {
            out.refuse_input(&f)?;
        }
        let text = read_bounded(&f, MAX_PARTIAL_BYTES, "a Monte Carlo partial")?;
        let p =
            aes_core::studies::montecarlo::Partial::from_json(&text).map_err(|e| format!("{}: {e}", shorten(&f)))?;
        merged.add(p).map_err(|e| format!("{}: {e}", shorten(&f)))?;
    }
    let acc = merged.partial()?;
    let summary = aes_core::studies::montecarlo::study_summary(&acc)?;
    // A lost shard leaves a smaller study that looks like a whole one: say which trials
    // are missing (a merge of the shards done so far is still allowed).
    let missing = missing_trials(&summary.ranges, summary.trials_requested);
    if !missing.is_empty() {
        let shown: Vec<String> = missing.iter().take(5).map(|(a, b)| format!("{a}..{b}")).collect();
        eprintln!(
            "aes-sim merge: warning: {} of the study's {} trials merged; missing {}{}",
            summary.trials,
            summary.trials_requested,
            shown.join(", "),
            if missing.len() > 5 { format!(" and {} more ranges", missing.len() - 5) } else { String::new() }
        );
    }
    emit_json(&summary)?;
    if let Some(out) = &partial {
        out.write(serde_json::to_string(&acc).map_err(|e| e.to_string())?.as_bytes())?;
    }
    Ok(())
}

/// The trial ranges of 0..`requested` that `ranges` (the merged shards' ranges) leave out.
fn missing_trials(ranges: &[(u64, u64)], requested: u64) -> Vec<(u64, u64)> {
    let mut sorted = ranges.to_vec();
    sorted.sort_unstable();
    let mut gaps = Vec::new();
    let mut next = 0;
    for (a, b) in sorted {
        if a > next {
            gaps.push((next, a.min(requested)));
        }
        next = next.max(b);
    }
    if next < requested {
        gaps.push((next, requested));
    }
    gaps.retain(|(a, b)| a < b);
    gaps
}
