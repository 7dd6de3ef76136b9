//! `aes-sim validate`: the validation report (docs/validation.md).

use crate::common::{emit, read_bounded, shorten, Failure, OutFile};
use aes_validation::{self as report, MAX_TRIALS};

// The command line of `aes-sim validate`.
#[derive(clap::Args)]
pub struct Args {
    /// Monte Carlo trials per study (docs/validation.md is made with the default).
    #[arg(long, default_value_t = 200)]
    trials: u64,
    /// Write the report to this file instead of standard output (nothing else is written).
    #[arg(long)]
    out: Option<String>,
    /// Also write the report's figures (NAME.svg) into this folder, made if missing; the
    /// report links them as validation/NAME.svg, so give the folder `validation` beside it.
    /// Only the report's own figures are written; nothing is deleted.
    #[arg(long, value_name = "DIR")]
    figures: Option<String>,
    /// Compare the report with this file and fail if it differs (a stale committed report), and
    /// its figures with those in the folder validation/ beside it.
    #[arg(long)]
    check: Option<String>,
}

pub fn run(Args { trials, out, figures, check }: Args) -> Result<(), Failure> {
    if !(1..=MAX_TRIALS).contains(&trials) {
        return Err(format!("--trials = {trials}: must be a whole number from 1 to {MAX_TRIALS}").into());
    }
    if check.is_some() && (out.is_some() || figures.is_some()) {
        return Err("--check compares, --out and --figures write: give one or the other".into());
    }
    // Every output is checked before the report is computed.
    let inputs: Vec<&str> = check.as_deref().into_iter().collect();
    let out = out.map(|path| OutFile::check(&path, "--out", &inputs)).transpose()?;
    let figures = figures.map(|dir| check_figure_dir(&dir)).transpose()?;
    let size = report::Size { trials };
    let sections = report::sections(size)?;
    let text = report::markdown(&sections, size);
    let failed: Vec<String> = sections
        .iter()
        .flat_map(|s| &s.rows)
        .filter(|r| r.verdict == report::Verdict::Fail)
        .map(|r| format!("{}: ours {} against {} ({})", r.quantity, r.ours, r.thesis, r.source))
        .collect();
    if let Some(path) = check {
        let shown = shorten(&path);
        let old = read_bounded(&path, 8 << 20, "a validation report")?;
        if let Some((i, (a, b))) = old.lines().zip(text.lines()).enumerate().find(|(_, (a, b))| a != b) {
            return Err(format!(
                "{shown} is stale (run ./build.sh validate and commit it); line {}:\n  committed: {}\n  now:       {}",
                i + 1,
                aes_core::checks::shorten_message(a),
                aes_core::checks::shorten_message(b)
            )
            .into());
        }
        if old.lines().count() != text.lines().count() {
            return Err(format!(
                "{shown} is stale (run ./build.sh validate and commit it): the number of lines differs"
            )
            .into());
        }
        check_figures(&path, &sections)?;
    } else if out.is_some() || figures.is_some() {
        if let Some(out) = &out {
            out.write(text.as_bytes())?;
        }
        if let Some(dir) = &figures {
            write_figures(dir, &sections)?;
        }
    } else {
        emit(&text)?;
    }
    if !failed.is_empty() {
        return Err(format!("{} row(s) outside their tolerance:\n{}", failed.len(), failed.join("\n")).into());
    }
    Ok(())
}

/// The figures beside a report (docs/validation.md -> docs/validation/), where --check reads them.
fn figure_dir(report: &str) -> std::path::PathBuf {
    std::path::Path::new(report).parent().unwrap_or(std::path::Path::new("")).join(report::FIGURE_DIR)
}

/// Checks before the report is computed that `dir` is a folder, or can be made one.
fn check_figure_dir(dir: &str) -> Result<std::path::PathBuf, String> {
    let p = std::path::PathBuf::from(dir);
    if p.exists() && !p.is_dir() {
        return Err(format!("--figures '{}': not a folder", shorten(dir)));
    }
    std::fs::create_dir_all(&p).map_err(|e| format!("--figures '{}': cannot make the folder: {e}", shorten(dir)))?;
    Ok(p)
}

/// Writes the report's figures into `dir`, each through a temporary file; nothing else there is
/// touched (a figure the report no longer makes is named by --check, for its owner to remove).
fn write_figures(dir: &std::path::Path, sections: &[report::Section]) -> Result<(), String> {
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        OutFile::check(&p.to_string_lossy(), "--figures", &[])?.write(f.svg.as_bytes())?;
    }
    Ok(())
}

/// SVG files in `dir` the report does not make.
fn stray_figures(dir: &std::path::Path, made: &[String]) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", shorten(&dir.to_string_lossy())))? {
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
fn check_figures(report: &str, sections: &[report::Section]) -> Result<(), String> {
    let dir = figure_dir(report);
    let mut made = Vec::new();
    for f in sections.iter().flat_map(|s| &s.figures) {
        let p = dir.join(format!("{}.svg", f.name));
        let shown = shorten(&p.to_string_lossy());
        let old = read_bounded(&p.to_string_lossy(), 8 << 20, "a validation figure")
            .map_err(|e| format!("{e} (run ./build.sh validate and commit the figures)"))?;
        if old != f.svg {
            return Err(format!("{shown} is stale (run ./build.sh validate and commit it)"));
        }
        made.push(format!("{}.svg", f.name));
    }
    let stray = stray_figures(&dir, &made)?;
    if !stray.is_empty() {
        return Err(format!(
            "{}: figures the report no longer makes: {} (remove them)",
            shorten(&dir.to_string_lossy()),
            stray.iter().take(5).map(|s| shorten(s)).collect::<Vec<_>>().join(", ")
        ));
    }
    Ok(())
}
