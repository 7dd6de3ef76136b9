//! `aes-sim merge`: shards of any study (Monte Carlo, rare events, the operability polar, fuel per
//! mile) into the study's summary, as the study's own command prints it.

use crate::common::{Failure, OutFile};

// The command line of `aes-sim merge`.
#[derive(clap::Args)]
pub struct Args {
    /// Shard files (`--partial` of `aes-sim mc`, `rare`, `operability` or `fuel-per-mile`), all of
    /// one study.
    #[arg(required_unless_present = "files_from")]
    files: Vec<String>,
    /// Also merge the shard files listed in this file, one path a line (`-`: standard input;
    /// for more shards than a command line holds).
    #[arg(long = "files-from", value_name = "LIST")]
    files_from: Option<String>,
    /// Also write the merged shard to this file.
    #[arg(long)]
    partial: Option<String>,
}

pub fn run(Args { files, files_from, partial }: Args) -> Result<(), Failure> {
    // The output may not be one of the inputs (the shard would be lost): the named shards, the
    // list, and (as they are read) every shard the list names. Written only at the end.
    let inputs: Vec<&str> = files.iter().map(String::as_str).chain(files_from.as_deref()).collect();
    let partial = partial.map(|path| OutFile::check(&path, "--partial", &inputs)).transpose()?;
    // The listed names are read line by line as they are merged (never all at once).
    let listed: Box<dyn Iterator<Item = std::io::Result<String>>> = match files_from.as_deref() {
        None => Box::new(std::iter::empty()),
        Some("-") => Box::new(std::io::stdin().lines()),
        Some(list) => {
            let f = std::fs::File::open(list)
                .map_err(|e| format!("--files-from '{}': cannot read: {e}", crate::common::shorten(list)))?;
            Box::new(std::io::BufRead::lines(std::io::BufReader::new(f)))
        }
    };
    let mut all = files.into_iter().map(Ok).chain(listed).filter(|f| !matches!(f, Ok(f) if f.trim().is_empty()));
    let first = match all.next() {
        None => return Err("no shards given".into()),
        Some(f) => f.map_err(|e| format!("--files-from: {e}"))?,
    };
    crate::study::merge_any(first, all, partial)
}
