//! `aes-sim validate`: the validation report (docs/validation.md).

use crate::common::{emit, read_bounded, Failure};

// The command line of `aes-sim validate`.
#[derive(clap::Args)]
pub struct Args {
    /// Monte Carlo trials per study (docs/validation.md is made with the default).
    #[arg(long, default_value_t = 200)]
    trials: u64,
    /// Write the report to this file instead of standard output.
    #[arg(long)]
    out: Option<String>,
    /// Compare the report with this file and fail if it differs (a stale committed report).
    #[arg(long)]
    check: Option<String>,
}

pub fn run(Args { trials, out, check }: Args) -> Result<(), Failure> {
    if !(1..=100_000).contains(&trials) {
        return Err(format!("--trials = {trials}: must be a whole number from 1 to 100000").into());
    }
    let size = aes_core::studies::validation_report::Size { trials };
    let sections = aes_core::studies::validation_report::sections(size)?;
    let text = aes_core::studies::validation_report::markdown(&sections, size);
    let failed: Vec<String> = sections
        .iter()
        .flat_map(|s| &s.rows)
        .filter(|r| r.verdict == aes_core::studies::validation_report::Verdict::Fail)
        .map(|r| format!("{}: ours {} against {} ({})", r.quantity, r.ours, r.thesis, r.source))
        .collect();
    if let Some(path) = check {
        let old = read_bounded(&path, 8 << 20, "a validation report")?;
        if let Some((i, (a, b))) = old.lines().zip(text.lines()).enumerate().find(|(_, (a, b))| a != b) {
            return Err(format!(
                "{path} is stale (run ./build.sh validate and commit it); line {}:\n  committed: {a}\n  now:       {b}",
                i + 1
            )
            .into());
        }
        if old.lines().count() != text.lines().count() {
            return Err(format!(
                "{path} is stale (run ./build.sh validate and commit it): the number of lines differs"
            )
            .into());
        }
        check_figures(&path, &sections)?;
    } else if let Some(path) = out {
        std::fs::write(&path, &text).map_err(|e| format!("{path}: {e}"))?;
        write_figures(&path, &sections)?;
    } else {
        emit(&text)?;
    }
    if !failed.is_empty() {
        return Err(format!("{} row(s) outside their tolerance:\n{}", failed.len(), failed.join("\n")).into());
    }
    Ok(())
}

fn figure_dir(report: &str) -> std::path::PathBuf {
    std::path::Path::new(report)
        .parent()
        .unwrap_or(std::path::Path::new(""))
        .join(aes_core::studies::validation_report::FIGURE_DIR)
}

/// Writes the report's figures beside it, and removes figures it no longer makes.
fn write_figures(report: &str, sections: &[aes_core::studies::validation_report::Section]) -> Result<(), String> {
    let dir = figure_dir(report);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let made: Vec<String> = sections.iter().flat_map(|s| &s.figures).map(|f| format!("{}.svg", f.name)).collect();
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        std::fs::write(&p, &f.svg).map_err(|e| format!("{}: {e}", p.display()))?;
    }
    for name in stray_figures(&dir, &made)? {
        let p = dir.join(&name);
        std::fs::remove_file(&p).map_err(|e| format!("{}: {e}", p.display()))?;
    }
    Ok(())
}

/// SVG files in `dir` the report does not make.
fn stray_figures(dir: &std::path::Path, made: &[String]) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let name = e.map_err(|e| e.to_string())?.file_name().to_string_lossy().into_owned();
        if name.ends_with(".svg") && !made.contains(&name) {
            out.push(name);
        }
    }
    out.sort();
    Ok(out)
}

/// Fails when a committed figure differs from the one the report makes now, is missing, or is
/// one the report no longer makes.
fn check_figures(report: &str, sections: &[aes_core::studies::validation_report::Section]) -> Result<(), String> {
    let dir = figure_dir(report);
    let mut made = Vec::new();
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        let shown = p.display().to_string();
        let old = read_bounded(&shown, 8 << 20, "a validation figure")
            .map_err(|e| format!("{e} (run ./build.sh validate and commit the figures)"))?;
        if old != f.svg {
            return Err(format!("{shown} is stale (run ./build.sh validate and commit it)"));
        }
        made.push(format!("{}.svg", f.name));
    }
    let stray = stray_figures(&dir, &made)?;
    if !stray.is_empty() {
        return Err(format!("{}: figures the report no longer makes: {}", dir.display(), stray.join(", ")));
    }
    Ok(())
}
