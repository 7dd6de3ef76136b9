//! The command line's one front for every study on the shared pipeline (Monte Carlo, rare
//! events, the operability polar, fuel per mile): the shard flags (`--trial-range`, `--partial`, `--merge`),
//! threads, progress, the estimate said before a long study, and the merge of shard files.

use crate::common::{emit_json, read_bounded, shorten, Failure, OutFile, Threads};
use aes_core::studies::study::{self, Merger, ShardOf, Study};
use std::io::Write;
use std::time::Instant;

/// Largest shard file [bytes].
pub const MAX_SHARD_BYTES: u64 = 512 << 20;

/// The flags every study command shares.
#[derive(clap::Args, Debug)]
pub struct ShardArgs {
    /// Run only items A..B of the study (a shard: its trials, the polar's speeds, the fuel study's
    /// runs); needs --partial.
    #[arg(long = "trial-range", value_name = "A..B", conflicts_with = "merge")]
    pub range: Option<String>,
    /// Write the shard (or with --merge the merged shards) to this file, for `aes-sim merge`.
    #[arg(long)]
    pub partial: Option<String>,
    /// Summarise these shard files (of this same study) instead of running.
    #[arg(long, num_args = 1.., value_name = "FILE")]
    pub merge: Vec<String>,
    /// Worker threads (default: all cores). The numbers do not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// No progress on stderr (by default a bar on a terminal, a line every 10 s otherwise).
    #[arg(long)]
    pub quiet: bool,
    /// Run a study estimated to take longer than an hour on its threads (refused without it).
    #[arg(long)]
    pub allow_long: bool,
}

/// The longest a study runs without `--allow-long`, by its estimate before it starts [s of
/// wall clock on its threads]: an hour, past which a mistyped trial count or run length should
/// be caught before it is spent.
pub const STUDY_BUDGET_S: f64 = 3600.0;

/// Refuses work estimated at `estimate_s` seconds of wall clock on `threads` threads past
/// [`STUDY_BUDGET_S`] unless `allow_long`; `what` says what the work is (in the message).
pub fn check_budget(cmd: &str, what: &str, estimate_s: f64, threads: usize, allow_long: bool) -> Result<(), Failure> {
    if allow_long || estimate_s <= STUDY_BUDGET_S {
        return Ok(());
    }
    Err(format!(
        "{cmd}: {what} is estimated at {} on {threads} thread(s), past the {:.0} h a study may take \
         without --allow-long: give it to run anyway, or ask for less",
        duration_text(estimate_s),
        STUDY_BUDGET_S / 3600.0
    )
    .into())
}

/// A wall-clock duration in minutes, hours or days, as an estimate is read.
fn duration_text(s: f64) -> String {
    if !s.is_finite() {
        "more than can be counted".into()
    } else if s < 2.0 * 3600.0 {
        format!("about {:.0} min", s / 60.0)
    } else if s < 2.0 * 86400.0 {
        format!("about {:.1} h", s / 3600.0)
    } else {
        format!("about {:.0} days", s / 86400.0)
    }
}

/// Runs the study `s` as `args` say (whole, one shard, or a merge of shard files): the summary
/// goes to `emit` (whole study or merge), the shard to `--partial`. `cmd` names the command in
/// messages, `file` its scenario argument.
pub fn execute<S: Study>(
    s: S,
    args: &ShardArgs,
    cmd: &'static str,
    file: &str,
    emit: impl FnOnce(&S, &S::Summary) -> Result<(), Failure>,
) -> Result<(), Failure> {
    if !args.merge.is_empty() {
        let out = args.partial.as_deref().map(|p| OutFile::check(p, "--partial", &[file])).transpose()?;
        let merged = merge_files(Merger::new(s), args.merge.iter().cloned().map(Ok), out.as_ref())?;
        return finish(merged, cmd, out.as_ref(), emit);
    }
    let (a, b) = range_of(args, s.items(), S::ITEM)?;
    let out = args.partial.as_deref().map(|p| OutFile::check(p, "--partial", &[file])).transpose()?;
    // At most the machine's parallelism: more threads only cost time and memory.
    let threads = threads(args.threads, cmd);
    // A long study says so up front (the progress then shows the time left as measured), and
    // past the budget it is refused unless asked for.
    if let study::Estimate { item_work: Some(w), seconds: Some(estimate_s), .. } =
        study::estimate(&s, b - a, threads, study::Platform::Native)
    {
        check_budget(
            cmd,
            &format!("{} {}s of {w:.3e} units of work each", b - a, S::ITEM),
            estimate_s,
            threads,
            args.allow_long,
        )?;
        if estimate_s > 60.0 && !args.quiet {
            let _ = writeln!(
                std::io::stderr(),
                "aes-sim {cmd}: {} {}s of {w:.3e} units of work each: roughly {:.0} min on {threads} thread(s) (Ctrl-C stops it)",
                b - a,
                S::ITEM,
                estimate_s / 60.0
            );
        }
    }
    let pool = pool(threads)?;
    // The seakeeping tables first, their parts on every thread (once, shared by every item): a
    // line on stderr if they take more than a second (a fine grid), so a long silence is
    // explained.
    let sc = s.scenario();
    if s.needs_rao_table() {
        let note = SlowNote::start(cmd, args.quiet);
        pool.install(|| sc.rao_table_with(&Threads))?;
        note.finish();
    }
    let t0 = Instant::now();
    let progress = Progress::start(b - a, cmd, S::ITEM, args.quiet);
    let part = pool.install(|| -> Result<S::Part, String> {
        use rayon::prelude::*;
        // What the items share is built once, not per item.
        let shared = s.prepare()?;
        (a..b).into_par_iter().map(|i| progress.tick(s.run(&shared, i))).try_reduce(
            || s.empty(),
            |mut x, y| {
                s.merge(&mut x, &y)?;
                Ok(x)
            },
        )
    });
    progress.finish();
    let part = part?;
    if !args.quiet {
        let _ = writeln!(
            std::io::stderr(),
            "aes-sim {cmd}: {} {}s in {:.2} s on {} threads",
            b - a,
            S::ITEM,
            t0.elapsed().as_secs_f64(),
            pool.current_num_threads()
        );
    }
    let shard = study::shard(&s, vec![(a, b)], part);
    if args.range.is_some() {
        // A shard: no summary, only the file.
        return write_shard::<S>(&shard, out.as_ref());
    }
    finish((s, shard), cmd, out.as_ref(), emit)
}

/// The worker threads every study runs on: the one place a thread pool is built.
pub fn pool(threads: usize) -> Result<rayon::ThreadPool, String> {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| format!("--threads: {e}"))
}

/// The items of `--trial-range` (all `items` without it), checked with the `--partial` it needs:
/// a study command whose set-up is itself work (rare events' run to the event) calls it first.
pub fn range_of(args: &ShardArgs, items: u64, item: &str) -> Result<(u64, u64), String> {
    let Some(r) = &args.range else {
        return Ok((0, items));
    };
    let bad = |why: &str| format!("--trial-range '{}': {why}", shorten(r));
    let (x, y) = r.split_once("..").ok_or_else(|| bad("expected A..B"))?;
    let a: u64 = x.trim().parse().map_err(|_| bad("A is not a whole number"))?;
    let b: u64 = y.trim().parse().map_err(|_| bad("B is not a whole number"))?;
    if !(a < b && b <= items) {
        return Err(format!("--trial-range {a}..{b}: need a < b <= the study's {items} {item}s"));
    }
    if args.partial.is_none() {
        return Err("--trial-range needs --partial FILE (merge the shards with `aes-sim merge`)".into());
    }
    Ok((a, b))
}

/// The summary to `emit` first (it is printed even when the shard cannot be written), then the
/// shard to its file; a study that cannot be summarised in part (a polar lacking speeds, rare
/// events lacking trials) still has its merged shard written before the error.
fn finish<S: Study>(
    (s, shard): (S, ShardOf<S>),
    cmd: &'static str,
    out: Option<&OutFile>,
    emit: impl FnOnce(&S, &S::Summary) -> Result<(), Failure>,
) -> Result<(), Failure> {
    warn_missing::<S>(&shard, s.items(), cmd);
    match s.summary(&shard.part, &shard.ranges) {
        Ok(summary) => {
            emit(&s, &summary)?;
            write_shard::<S>(&shard, out)
        }
        Err(e) => {
            write_shard::<S>(&shard, out)?;
            Err(e.into())
        }
    }
}

/// The worker threads of `--threads` (0 or none: every core; more than the machine has: capped,
/// with a line on stderr). At most the machine's parallelism: more threads only cost time and
/// memory.
pub fn threads(arg: Option<usize>, cmd: &str) -> usize {
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    match arg {
        None | Some(0) => cores,
        Some(t) if t > cores => {
            let _ = writeln!(
                std::io::stderr(),
                "aes-sim {cmd}: --threads {t} capped at {cores}, this machine's available parallelism"
            );
            cores
        }
        Some(t) => t,
    }
}

fn write_shard<S: Study>(shard: &ShardOf<S>, out: Option<&OutFile>) -> Result<(), Failure> {
    if let Some(out) = out {
        out.write(serde_json::to_string(shard).map_err(|e| e.to_string())?.as_bytes())?;
    }
    Ok(())
}

/// A lost shard leaves a smaller study that looks like a whole one: says on stderr which items
/// are missing (a merge of the shards done so far is still allowed where the study can be
/// summarised in part).
fn warn_missing<S: Study>(shard: &ShardOf<S>, items: u64, cmd: &str) {
    let missing = study::missing(&shard.ranges, items);
    if missing.is_empty() {
        return;
    }
    let shown: Vec<String> = missing.iter().take(5).map(|(a, b)| format!("{a}..{b}")).collect();
    eprintln!(
        "aes-sim {cmd}: warning: {} of the study's {items} {}s merged; missing {}{}",
        study::count(&shard.ranges),
        S::ITEM,
        shown.join(", "),
        if missing.len() > 5 { format!(" and {} more ranges", missing.len() - 5) } else { String::new() }
    );
}

/// Reads shard files one at a time and merges them into `m` (memory does not grow with their
/// number). `out`, when given, may be none of them.
pub fn merge_files<S: Study>(
    mut m: Merger<S>,
    files: impl Iterator<Item = std::io::Result<String>>,
    out: Option<&OutFile>,
) -> Result<(S, ShardOf<S>), Failure> {
    for f in files {
        let f = f.map_err(|e| format!("--files-from: {e}"))?;
        if f.trim().is_empty() {
            continue;
        }
        if let Some(out) = out {
            out.refuse_input(&f)?;
        }
        let text = read_bounded(&f, MAX_SHARD_BYTES, "a shard")?;
        let s = study::from_json::<S>(&text).map_err(|e| format!("{}: {e}", shorten(&f)))?;
        m.add(s).map_err(|e| format!("{}: {e}", shorten(&f)))?;
    }
    Ok(m.finish()?)
}

/// Merges shard files of any kind of study (the first file's kind and definition) and prints
/// the summary as the study's own command does: `aes-sim merge`.
pub fn merge_any(
    first: String,
    rest: impl Iterator<Item = std::io::Result<String>>,
    out: Option<OutFile>,
) -> Result<(), Failure> {
    struct Visit<I> {
        first: String,
        text: String,
        rest: I,
        out: Option<OutFile>,
    }
    impl<I: Iterator<Item = std::io::Result<String>>> study::Visit for Visit<I> {
        type Out = Result<(), Failure>;
        fn visit<S: Study>(self) -> Result<(), Failure> {
            let shard = study::from_json::<S>(&self.text).map_err(|e| format!("{}: {e}", shorten(&self.first)))?;
            let s = S::new(shard.spec.clone()).map_err(|e| format!("{}: {e}", shorten(&self.first)))?;
            let mut m = Merger::new(s);
            m.add(shard).map_err(|e| format!("{}: {e}", shorten(&self.first)))?;
            let merged = merge_files(m, self.rest, self.out.as_ref())?;
            finish(merged, "merge", self.out.as_ref(), |_, summary| emit_json(summary))
        }
    }
    if let Some(out) = &out {
        out.refuse_input(&first)?;
    }
    let text = read_bounded(&first, MAX_SHARD_BYTES, "a shard")?;
    let kind = study::kind_of(&text).map_err(|e| format!("{}: {e}", shorten(&first)))?;
    study::dispatch(&kind, Visit { first: first.clone(), text, rest, out })
        .map_err(|e| format!("{}: {e}", shorten(&first)))?
}

/// A line on stderr when building the seakeeping tables takes more than a second ("... (done
/// in N s)" when it ends); nothing for a quick build or when quiet.
struct SlowNote {
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl SlowNote {
    fn start(cmd: &'static str, quiet: bool) -> SlowNote {
        use std::sync::atomic::{AtomicBool, Ordering};
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let thread = (!quiet).then(|| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                let what = format!("aes-sim {cmd}: building the seakeeping (RAO) tables");
                let t0 = Instant::now();
                while !stop.load(Ordering::Relaxed) && t0.elapsed().as_secs_f64() < 1.0 {
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                }
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                let _ = writeln!(std::io::stderr(), "{what} ...");
                while !stop.load(Ordering::Relaxed) {
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                }
                let _ = writeln!(std::io::stderr(), "{what}: done in {:.1} s", t0.elapsed().as_secs_f64());
            })
        });
        SlowNote { stop, thread }
    }

    fn finish(mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

/// Progress of a long study on stderr: on a terminal a bar redrawn in place (done, rate, time
/// left); otherwise (a scheduler's log) a plain line every 10 s; nothing when quiet.
struct Progress {
    done: std::sync::Arc<std::sync::atomic::AtomicU64>,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Progress {
    fn start(total: u64, cmd: &'static str, item: &'static str, quiet: bool) -> Progress {
        use std::io::IsTerminal;
        use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
        use std::sync::Arc;
        let (done, stop) = (Arc::new(AtomicU64::new(0)), Arc::new(AtomicBool::new(false)));
        let thread = (!quiet).then(|| {
            let (done, stop) = (done.clone(), stop.clone());
            let tty = std::io::stderr().is_terminal();
            std::thread::spawn(move || {
                let t0 = Instant::now();
                let every = if tty { 0.25 } else { 10.0 };
                let mut last = 0.0;
                let line = |n: u64, bar: bool| {
                    let s = t0.elapsed().as_secs_f64();
                    let rate = n as f64 / s.max(1e-9);
                    let left = if n > 0 { format!("{:.0} s left", (total - n) as f64 / rate) } else { "".into() };
                    let text = format!("{n}/{total} {item}s, {rate:.1}/s, {left}");
                    if bar {
                        let w = 30;
                        let k = (w as u64 * n / total.max(1)) as usize;
                        format!("\raes-sim {cmd} [{}{}] {text}\x1b[K", "#".repeat(k), ".".repeat(w - k))
                    } else {
                        format!("aes-sim {cmd}: {text}\n")
                    }
                };
                while !stop.load(Ordering::Relaxed) {
                    // Woken early by finish(): a short run does not wait for the next tick.
                    std::thread::park_timeout(std::time::Duration::from_millis(100));
                    let s = t0.elapsed().as_secs_f64();
                    if s - last >= every {
                        last = s;
                        let _ = write!(std::io::stderr(), "{}", line(done.load(Ordering::Relaxed), tty));
                    }
                }
                if tty {
                    let _ = writeln!(std::io::stderr(), "{}", line(done.load(Ordering::Relaxed), true));
                }
            })
        });
        Progress { done, stop, thread }
    }

    /// Counts one finished item and passes its result on.
    fn tick<T>(&self, r: T) -> T {
        self.done.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        r
    }

    fn finish(mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}
