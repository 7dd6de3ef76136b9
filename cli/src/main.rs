//! `aes-sim`: the command line of the All Electric Ship simulator. One module per command under
//! `cmd/` (its arguments beside what it does); what they share is in `common`.

// The doc comments of the arguments are clap's --help text, where `[m]` is a unit, not a link:
// escaping it would print the backslashes.
#![allow(rustdoc::broken_intra_doc_links)]

mod cmd;
mod common;
mod study;

use clap::{Parser, Subcommand};
use common::Failure;
use std::fmt::Write as _;
use std::io::Write;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "aes-sim",
    version,
    about = "All Electric Ship simulator (Schmitt, MIT 2010): drive train, hull and power system"
)]
struct Cli {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// List the preset scenarios.
    Presets,
    /// List the trace columns: name, unit and what each is (`--json` for the machine-readable table).
    Signals(cmd::signals::Args),
    /// List every scenario parameter: path, unit, default, allowed values and label (`--json`
    /// for the full declarations: help, source, page group, per-unit base; `--markdown` for the
    /// book's table, docs/reference/parameters.md).
    Params(cmd::params::Args),
    /// List the plant's health checks each run's summary applies (its `warnings`): what, the
    /// threshold and why (`--markdown` for the book's table, docs/reference/health.md).
    Health(cmd::health::Args),
    /// Print a preset scenario as JSON (a starting point for your own).
    Preset(cmd::presets::Args),
    /// Run a scenario file (or `-` for standard input, or `preset:NAME`); prints a JSON summary.
    Run(cmd::run::Args),
    /// Run one of the page's lessons with its controls' values and print what the run shows (the
    /// page's words: verdict, explanation, try this next; `--json` for the facts behind them).
    Lesson(cmd::lesson::Args),
    /// Controller design (thesis ch. 3.1).
    Design {
        #[command(subcommand)]
        command: cmd::design::Cmd,
    },
    /// The IPS performance and stability tool of thesis ch. 4 (Purdue MVDC testbed).
    Ips {
        #[command(subcommand)]
        command: cmd::ips::Cmd,
    },
    /// Is the bus stable at the scenario's operating point (its loads and storage included)? The
    /// plant's eigenvalues there, or `--x PATH=FROM:TO:N --y PATH=FROM:TO:N` for a map of its
    /// spectral abscissa over two parameters with the boundary; JSON.
    StabilityMap(cmd::stability_map::Args),
    /// Sectional added mass and damping of one ship section (thesis ch. 2.5.1: conformal map +
    /// Ursell-Tasai multipoles, deep water); JSON on standard output.
    Section(cmd::section::Args),
    /// Response amplitude operators and mean second-order forces of a hull by strip theory
    /// (thesis ch. 2.5.2-2.5.3); JSON on standard output.
    Rao(cmd::rao::Args),
    /// A Monte Carlo study of a scenario (thesis ch. 5.4); prints the summary JSON.
    Mc(cmd::mc::Args),
    /// The operability polar of the scenario's ship: for each speed and wave heading the
    /// highest sea in which every seakeeping criterion holds (motions, accelerations, slamming,
    /// deck wetness, propeller ventilation and emergence), the criterion that limits it, and the
    /// operable share of a wave scatter diagram; JSON on standard output.
    Operability(cmd::operability::Args),
    /// How often, and how bad: the consequences of a rare propeller surface event (ventilation
    /// onset, emergence, or a level of h/R on one shaft) by conditioned simulation: every
    /// trial's random sea is made to bring the event at a chosen time; the event's rate per hour
    /// and each consequence's quantiles and rates past thresholds, with 95 % intervals; JSON.
    Rare(cmd::rare::Args),
    /// Fuel per nautical mile against ordered speed, over seas of several seeds: where the ship
    /// is most economical in a sea, and how much the sea's realisation moves it; JSON.
    FuelPerMile(cmd::fuel_per_mile::Args),
    /// Merges shards of any study (`aes-sim mc`, `rare`, `operability`, `fuel-per-mile` with
    /// `--trial-range ... --partial`) into the study's summary. Reads one shard at a time: memory
    /// does not grow with their number.
    Merge(cmd::merge::Args),
    /// The standard maneuvers of a scenario's ship (IMO MSC.137(76)): the 35 degree turning circle,
    /// the 10/10 and 20/20 zig-zags, a coasting stop and the hull's static drift and pure yaw
    /// forces, with IMO's verdicts, and the full-astern stopping test through the drive train; JSON (`--markdown` for the booklet's tables).
    Maneuvers(cmd::maneuvers::Args),
    /// The fuel study of ch. 5.2.4 (Fig. 5-12): fuel power of one prime mover in regular head and
    /// bow seas of 1 to 5 ft over wave frequency; JSON rows on standard output.
    Fuel(cmd::fuel::Args),
    /// How many gas turbines should run (thesis ch. 6.1): for speeds 0 to full and sea states 2-6
    /// the online set that burns least fuel while the sea's power swings leave it its reserve;
    /// the table with the fuel saving against all four online (`--json` for everything).
    Schedule(cmd::schedule::Args),
    /// How big a storage the scenario's seaway needs (thesis ch. 5.2.2, 6.1): one run per storage
    /// size (energy x power rating on each bus) beside the run without storage: the turbines' speed
    /// swing, the bus's range, fuel, brake energy and the storage's cycling (`--json` for everything).
    StorageSizing(cmd::storage_sizing::Args),
    /// Measure simulated seconds per wall-clock second on a preset (default: startup), or
    /// `seakeeping`: the time to build the default RAO tables of the DTMB 5415 (and, with
    /// --hull, of that hull beside it, in the same run).
    Bench(cmd::bench::Args),
    /// Open-water KT, 10KQ and efficiency of a propeller from its blade table (a vortex lattice,
    /// thesis ch. 3.2), `--at-j J` for its radial loading (a lifting line); JSON, or `--markdown`.
    Propeller(cmd::propeller::Args),
    /// The validation report: every thesis number we compare with, beside ours, with the
    /// difference, tolerance, verdict and reason (Markdown; docs/validation.md). Exit status 1 when
    /// a row leaves its tolerance.
    Validate(cmd::validate::Args),
}

fn real_main(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Cmd::Presets => cmd::presets::list(),
        Cmd::Signals(a) => cmd::signals::run(a),
        Cmd::Params(a) => cmd::params::run(a),
        Cmd::Health(a) => cmd::health::run(a),
        Cmd::Preset(a) => cmd::presets::print(a),
        Cmd::Run(a) => cmd::run::run(a),
        Cmd::Lesson(a) => cmd::lesson::run(a),
        Cmd::Design { command } => cmd::design::run(command),
        Cmd::Ips { command } => cmd::ips::run(command),
        Cmd::StabilityMap(a) => cmd::stability_map::run(a),
        Cmd::Section(a) => cmd::section::run(a),
        Cmd::Rao(a) => cmd::rao::run(a),
        Cmd::Mc(a) => cmd::mc::run(a),
        Cmd::Operability(a) => cmd::operability::run(a),
        Cmd::Rare(a) => cmd::rare::run(a),
        Cmd::Merge(a) => cmd::merge::run(a),
        Cmd::FuelPerMile(a) => cmd::fuel_per_mile::run(a),
        Cmd::Fuel(a) => cmd::fuel::run(a),
        Cmd::Schedule(a) => cmd::schedule::run(a),
        Cmd::StorageSizing(a) => cmd::storage_sizing::run(a),
        Cmd::Maneuvers(a) => cmd::maneuvers::run(a),
        Cmd::Validate(a) => cmd::validate::run(a),
        Cmd::Bench(a) => cmd::bench::run(a),
        Cmd::Propeller(a) => cmd::propeller::run(a),
    }
}

/// Whether the kernel's list of this CPU's features lacks AVX2 (false when it cannot be read). Not
/// `is_x86_feature_detected!`: in a build for AVX2 that answers yes without asking the CPU.
#[cfg(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2"))]
#[inline(never)]
fn cpu_lacks_avx2() -> bool {
    std::fs::read_to_string("/proc/cpuinfo").is_ok_and(|info| flags_lack_avx2(&info))
}

/// Whether the first `flags` line of a /proc/cpuinfo text lacks the word avx2 (false without one).
#[cfg_attr(not(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2")), allow(dead_code))]
fn flags_lack_avx2(cpuinfo: &str) -> bool {
    cpuinfo
        .lines()
        .find(|l| l.starts_with("flags"))
        .is_some_and(|flags| !flags.split_whitespace().skip(2).any(|f| f == "avx2"))
}

/// Exit status: 0 on success and when standard output is closed by its reader (`| head`);
/// 1 with a message on stderr for every error; 2 for a command line clap refuses.
fn main() -> ExitCode {
    // .cargo/config.toml builds for AVX2: say so on a CPU without it rather than die of an
    // illegal instruction somewhere in a run.
    #[cfg(all(target_os = "linux", target_arch = "x86_64", target_feature = "avx2"))]
    if cpu_lacks_avx2() {
        let _ = writeln!(
            std::io::stderr(),
            "aes-sim: this build needs a CPU with AVX2 (x86_64 from about 2013 on); on an older one \
             remove the rustflags of .cargo/config.toml and build again"
        );
        return ExitCode::FAILURE;
    }
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_end(&e),
    };
    match real_main(cli) {
        Ok(()) | Err(Failure::PipeClosed) => ExitCode::SUCCESS,
        Err(Failure::Msg(e)) => {
            // The last guard: no control character of a value or a file name reaches the terminal,
            // and no message is longer than a screen.
            let _ = writeln!(std::io::stderr(), "aes-sim: {}", bounded(&aes_core::checks::escape_controls(&e, true)));
            ExitCode::FAILURE
        }
    }
}

/// Longest message on stderr [bytes]; a longer one is cut (each part of a message is cut much
/// shorter where it is made: this is the last guard).
const MAX_MESSAGE_BYTES: usize = 1800;

/// `text` cut to [`MAX_MESSAGE_BYTES`] at a character's boundary, saying so.
fn bounded(text: &str) -> String {
    if text.len() <= MAX_MESSAGE_BYTES {
        return text.to_string();
    }
    let mut end = MAX_MESSAGE_BYTES;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    let mut s = text[..end].to_string();
    let _ = write!(s, "... (cut here: {} bytes in all)", text.len());
    s
}

/// A command line clap refuses, with its exit status (2), or help and version (0, on standard
/// output as clap prints them). clap echoes an offending value whole: here each value it echoes
/// is cut to 60 characters with its control characters escaped (a raw newline included), as
/// every other message of the command.
fn clap_end(e: &clap::Error) -> ExitCode {
    let code = u8::try_from(e.exit_code()).unwrap_or(2);
    if !e.use_stderr() {
        let _ = e.print();
        return ExitCode::from(code);
    }
    let _ = write!(std::io::stderr(), "{}", clap_message(e));
    ExitCode::from(code)
}

/// clap's message for `e` without styles, each value of its context shortened and escaped, then
/// any control character left escaped (clap's own line breaks kept) and the whole bounded.
fn clap_message(e: &clap::Error) -> String {
    use clap::error::ContextValue;
    let mut values: Vec<&str> = e
        .context()
        .flat_map(|(_, v)| match v {
            ContextValue::String(s) => vec![s.as_str()],
            ContextValue::Strings(v) => v.iter().map(String::as_str).collect(),
            _ => Vec::new(),
        })
        .collect();
    // The longest first: a value inside another is replaced after it.
    values.sort_by_key(|v| std::cmp::Reverse(v.len()));
    let mut text = e.render().to_string();
    for v in values {
        let short = aes_core::checks::shorten(v);
        if !v.is_empty() && short != v {
            text = text.replace(v, &short);
        }
    }
    let end = if text.ends_with('\n') { "\n" } else { "" };
    format!("{}{end}", bounded(aes_core::checks::escape_controls(text.trim_end_matches('\n'), true).as_str()))
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    /// clap's echo of a 5,000-character value with a raw newline: the value cut to 60 characters,
    /// the newline escaped, clap's own lines and exit status kept.
    #[test]
    fn clap_values_are_cut_and_escaped() {
        let long = format!("1\n{}", "x".repeat(5000));
        let e = super::Cli::try_parse_from(["aes-sim", "operability", "--speeds", &long]).err().unwrap();
        let text = super::clap_message(&e);
        let shown = format!("1\\n{}...", "x".repeat(57));
        assert_eq!(
            text.lines().next().unwrap(),
            format!("error: invalid value '{shown}' for '--speeds <SPEEDS>': invalid float literal")
        );
        assert!(text.len() < 400 && text.ends_with("For more information, try '--help'.\n"), "{text}");
        assert_eq!(e.exit_code(), 2);
        // A message past the bound is cut at a character's boundary.
        let cut = super::bounded(&"\u{e9}".repeat(2000));
        assert!(cut.ends_with("... (cut here: 4000 bytes in all)") && cut.len() < 1900, "{}", cut.len());
    }

    /// The AVX2 check reads the kernel's flags: a word, not a prefix (avx512f is not avx2).
    #[test]
    fn avx2_is_read_from_the_flags_line() {
        let has = "processor\t: 0\nflags\t\t: fpu sse2 avx avx2 fma\nbugs\t\t: none\n";
        let lacks = "processor\t: 0\nflags\t\t: fpu sse2 avx avx512f\n";
        assert!(!super::flags_lack_avx2(has));
        assert!(super::flags_lack_avx2(lacks));
        assert!(!super::flags_lack_avx2("no flags here"));
        // A test binary built for AVX2 runs only on a CPU with it: the real flags must say so.
        if let (true, Ok(info)) = (cfg!(target_feature = "avx2"), std::fs::read_to_string("/proc/cpuinfo")) {
            assert!(!super::flags_lack_avx2(&info));
        }
    }
}
