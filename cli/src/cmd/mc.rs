//! `aes-sim mc`: a Monte Carlo study, whole or one shard of it (ch. 5.4).

use crate::common::{emit_json, load, shorten, Failure, OutFile};
use std::io::Write;
use std::time::Instant;

// The command line of `aes-sim mc`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario JSON file, `-` or `preset:NAME` (its `monte_carlo` section says what to collect).
    file: String,
    /// Number of trials (default: the scenario's monte_carlo.trials).
    #[arg(long)]
    trials: Option<u64>,
    /// Master seed (default: the scenario's sim.seed); trial i uses a seed made from it and i.
    #[arg(long)]
    seed: Option<u64>,
    /// Worker threads (default: all cores). The summary does not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    /// Run only trials A..B of the study (a shard).
    #[arg(long = "trial-range", value_name = "A..B")]
    trial_range: Option<String>,
    /// Write the shard's partial statistics to this file (for `aes-sim merge`).
    #[arg(long)]
    partial: Option<String>,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
    /// No progress on stderr (by default a bar on a terminal, a line every 10 s otherwise).
    #[arg(long)]
    quiet: bool,
}

pub fn run(Args { file, trials, seed, threads, trial_range, partial, sets, quiet }: Args) -> Result<(), Failure> {
    let mut sc = load(&file, &sets)?;
    if let Some(n) = trials {
        sc.monte_carlo.trials = n;
    }
    if let Some(s) = seed {
        sc.sim.seed = s;
    }
    sc.validate().map_err(|e| format!("{}: {e}", shorten(&file)))?;
    // What the study keeps and the work it asks for, before anything runs.
    aes_core::studies::montecarlo::check_study(&sc).map_err(|e| format!("{}: {e}", shorten(&file)))?;
    let n = sc.monte_carlo.trials;
    let (a, b) = match &trial_range {
        None => (0, n),
        Some(r) => {
            let (x, y) = r.split_once("..").ok_or_else(|| format!("--trial-range '{r}': expected A..B"))?;
            let a: u64 = x.trim().parse().map_err(|_| format!("--trial-range '{r}': A is not a whole number"))?;
            let b: u64 = y.trim().parse().map_err(|_| format!("--trial-range '{r}': B is not a whole number"))?;
            aes_core::studies::montecarlo::check_shard(&sc, a, b)
                .map_err(|e| format!("--trial-range {a}..{b}: {e}"))?;
            (a, b)
        }
    };
    if trial_range.is_some() && partial.is_none() {
        return Err("--trial-range needs --partial FILE (merge the shards with `aes-sim merge`)".into());
    }
    let partial = partial.map(|path| OutFile::check(&path, "--partial", &[&file])).transpose()?;
    // At most the machine's parallelism: more threads only cost time and memory.
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let threads = match threads {
        None | Some(0) => cores,
        Some(n) if n > cores => {
            let _ = writeln!(
                std::io::stderr(),
                "aes-sim mc: --threads {n} capped at {cores}, this machine's available parallelism"
            );
            cores
        }
        Some(n) => n,
    };
    // A long study says so up front (the progress then shows the time left as measured).
    let estimate_s = (b - a) as f64 * sc.work() / aes_core::scenario::WORK_PER_S / threads as f64;
    if estimate_s > 60.0 && !quiet {
        let _ = writeln!(
            std::io::stderr(),
            "aes-sim mc: {} trials of {:.3e} units of work each: roughly {:.0} min on {threads} thread(s) (Ctrl-C stops it)",
            b - a,
            sc.work(),
            estimate_s / 60.0
        );
    }
    // The seakeeping tables first (once, shared by every trial): a line on stderr if they
    // take more than a second (a fine grid), so a long silence is explained.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| format!("--threads: {e}"))?;
    if sc.sea.kind != aes_core::scenario::SeaKind::Calm {
        let note = SlowNote::start("aes-sim mc: building the seakeeping (RAO) tables", quiet);
        pool.install(|| sc.rao_table_with(&crate::common::Threads))?;
        note.finish();
    }
    // What the trials share is built once, not per trial.
    let trials = aes_core::studies::montecarlo::Trials::new(&sc);
    let t0 = Instant::now();
    let progress = Progress::start(b - a, "aes-sim mc", quiet);
    let result = pool.install(|| {
        use rayon::prelude::*;
        (a..b).into_par_iter().map(|i| progress.tick(trials.run(i))).try_reduce(
            || aes_core::studies::montecarlo::Partial::empty(&sc),
            |mut x, y| {
                x.merge(&y)?;
                Ok(x)
            },
        )
    });
    progress.finish();
    let result = result?;
    if !quiet {
        let _ = writeln!(
            std::io::stderr(),
            "aes-sim mc: {} trials in {:.2} s on {} threads",
            b - a,
            t0.elapsed().as_secs_f64(),
            pool.current_num_threads()
        );
    }
    // The summary first: it is printed even when the partial cannot be written.
    if trial_range.is_none() {
        emit_json(&aes_core::studies::montecarlo::study_summary(&result)?)?;
    }
    if let Some(out) = &partial {
        out.write(serde_json::to_string(&result).map_err(|e| e.to_string())?.as_bytes())?;
    }
    Ok(())
}

/// A line on stderr when a step takes more than a second ("... (done in N s)" when it ends);
/// nothing for a quick step or when quiet.
struct SlowNote {
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl SlowNote {
    fn start(what: &'static str, quiet: bool) -> SlowNote {
        use std::sync::atomic::{AtomicBool, Ordering};
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let thread = (!quiet).then(|| {
            let stop = stop.clone();
            std::thread::spawn(move || {
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

/// Progress of a long command on stderr: on a terminal a bar redrawn in place (done, rate, time
/// left); otherwise (a scheduler's log) a plain line every 10 s; nothing when quiet.
struct Progress {
    done: std::sync::Arc<std::sync::atomic::AtomicU64>,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Progress {
    fn start(total: u64, label: &'static str, quiet: bool) -> Progress {
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
                    let text = format!("{n}/{total} trials, {rate:.1}/s, {left}");
                    if bar {
                        let w = 30;
                        let k = (w as u64 * n / total.max(1)) as usize;
                        format!("\r{label} [{}{}] {text}\x1b[K", "#".repeat(k), ".".repeat(w - k))
                    } else {
                        format!("{label}: {text}\n")
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

    /// Counts one finished piece of work and passes its result on.
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
