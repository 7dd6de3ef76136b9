//! What the commands share: how a command fails, printing, reading bounded input, loading a
//! scenario.

use aes_core::scenario::presets::{preset, PRESET_NAMES};
use aes_core::Scenario;
use std::io::{Read, Write};

/// How a command ends other than with success.
pub enum Failure {
    /// A message for stderr; exit status 1.
    Msg(String),
    /// Standard output was closed by its reader (`aes-sim ... | head`): a normal end, exit 0.
    PipeClosed,
}

impl From<String> for Failure {
    fn from(s: String) -> Failure {
        Failure::Msg(s)
    }
}

impl From<&str> for Failure {
    fn from(s: &str) -> Failure {
        Failure::Msg(s.to_string())
    }
}

/// Writes text to standard output; a closed pipe ends the command quietly (exit 0).
pub fn emit(text: &str) -> Result<(), Failure> {
    // Every human-readable output passes here: a scenario's name or a file's text never reaches
    // the terminal raw (ESC, BEL, CR), as errors and JSON already escape them; newlines and tabs
    // are the output's own layout.
    let text: String =
        if text.chars().any(|c| c.is_control() && c != '\n' && c != '\t') {
            text.chars()
                .map(|c| {
                    if c.is_control() && c != '\n' && c != '\t' {
                        c.escape_default().to_string()
                    } else {
                        c.to_string()
                    }
                })
                .collect()
        } else {
            text.to_string()
        };
    let mut out = std::io::stdout().lock();
    let r = out.write_all(text.as_bytes()).and_then(|()| out.write_all(b"\n")).and_then(|()| out.flush());
    match r {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(Failure::PipeClosed),
        Err(e) => Err(Failure::Msg(format!("cannot write to standard output: {e}"))),
    }
}

/// Prints a value as pretty JSON after checking that every number in it is finite (the error
/// names the first that is not, by its path).
pub fn emit_json<T: serde::Serialize + ?Sized>(x: &T) -> Result<(), Failure> {
    aes_core::checks::check_finite(x)?;
    // Through a Value, whose keys are sorted: the output keeps its established form.
    let v = serde_json::to_value(x).map_err(|e| e.to_string())?;
    emit(&serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
}

/// Reads a file (or standard input for `-`) as UTF-8, stopping at `limit` bytes: a larger or
/// endless input (`/dev/zero`) is refused after reading `limit + 1` bytes, never read whole.
pub fn read_bounded(file: &str, limit: u64, what: &str) -> Result<String, String> {
    let mut buf = Vec::new();
    let r = if file == "-" {
        std::io::stdin().lock().take(limit + 1).read_to_end(&mut buf)
    } else {
        std::fs::File::open(file).and_then(|f| f.take(limit + 1).read_to_end(&mut buf))
    };
    let name = if file == "-" { "standard input".to_string() } else { format!("'{}'", shorten(file)) };
    r.map_err(|e| format!("cannot read {name}: {e}"))?;
    if buf.len() as u64 > limit {
        return Err(format!("{name}: larger than {limit} bytes, the limit for {what}"));
    }
    String::from_utf8(buf).map_err(|e| format!("{name}: not UTF-8 text (byte {})", e.utf8_error().valid_up_to()))
}

/// An output file named on the command line, checked before the computation and written only
/// on success: to a temporary file in the same folder, renamed into place, so a failed or
/// interrupted command leaves what was there before untouched.
pub struct OutFile {
    path: std::path::PathBuf,
    flag: &'static str,
    /// A device or a pipe (`/dev/null`, `/dev/stdout`, a fifo): written to directly, there is
    /// nothing to replace.
    direct: bool,
}

impl OutFile {
    /// Checks `path` (given as `flag`) before anything is computed: not one of the command's
    /// `inputs` (files, `-` and `preset:` names are skipped), not a folder, in a folder where a
    /// file can be made now. Nothing that exists is touched.
    pub fn check(path: &str, flag: &'static str, inputs: &[&str]) -> Result<OutFile, String> {
        let name = || format!("{flag} '{}'", shorten(path));
        let p = std::path::PathBuf::from(path);
        if path.is_empty() || p.file_name().is_none() || p.is_dir() {
            return Err(format!("{}: not a file name", name()));
        }
        let direct = std::fs::metadata(&p).is_ok_and(|m| !m.is_file());
        let out = OutFile { path: p, flag, direct };
        for input in inputs {
            out.refuse_input(input)?;
        }
        if direct {
            return Ok(out);
        }
        let (probe, _) = out.create_temp().map_err(|e| format!("{}: cannot write in its folder: {e}", name()))?;
        let _ = std::fs::remove_file(&probe);
        Ok(out)
    }

    /// Refuses an `input` of the command (a file name; `-` and `preset:` names are not files)
    /// that is this output file, under whatever name.
    pub fn refuse_input(&self, input: &str) -> Result<(), String> {
        if input == "-" || input.starts_with("preset:") {
            return Ok(());
        }
        match (std::fs::canonicalize(&self.path), std::fs::canonicalize(input)) {
            (Ok(out), Ok(i)) if out == i => Err(format!(
                "{} '{}': is also an input of this command ('{}'); writing it would destroy it: name another file",
                self.flag,
                shorten(&self.path.to_string_lossy()),
                shorten(input)
            )),
            _ => Ok(()),
        }
    }

    /// A new temporary file beside the file, for the text being written: hidden, named with this
    /// process's id and 64 unpredictable bits ([`random_token`]), so nobody can plant a link at
    /// its name beforehand; created new (a name already taken, a symbolic link included, is
    /// never opened: another is drawn, up to 8 times).
    fn create_temp(&self) -> std::io::Result<(std::path::PathBuf, std::fs::File)> {
        let file = self.path.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default();
        let mut taken = None;
        for _ in 0..8 {
            let tmp =
                self.path.with_file_name(format!(".{file}.{}.{:016x}.aes-sim-tmp", std::process::id(), random_token()));
            match create_new(&tmp) {
                Ok(f) => return Ok((tmp, f)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => taken = Some(e),
                Err(e) => return Err(e),
            }
        }
        Err(taken.unwrap_or_else(|| std::io::Error::other("no free temporary name")))
    }

    /// Writes `bytes` whole to a new temporary file, syncs it to the disk, then renames it over
    /// the file; on an error the temporary file is removed and the file is as it was.
    pub fn write(&self, bytes: &[u8]) -> Result<(), String> {
        let failed =
            |e: std::io::Error| format!("{} '{}': cannot write: {e}", self.flag, shorten(&self.path.to_string_lossy()));
        if self.direct {
            return std::fs::write(&self.path, bytes).map_err(failed);
        }
        let (tmp, mut f) = self.create_temp().map_err(failed)?;
        #[cfg(unix)]
        on_signal::writing(Some(&tmp));
        let r = f.write_all(bytes).and_then(|()| f.sync_all()).and_then(|()| std::fs::rename(&tmp, &self.path));
        #[cfg(unix)]
        on_signal::writing(None);
        r.map_err(|e| {
            // Only the file this process created is removed.
            let _ = std::fs::remove_file(&tmp);
            failed(e)
        })
    }
}

/// The temporary file being written is removed when SIGINT, SIGTERM, SIGHUP or SIGQUIT stops the
/// command (Ctrl-C, a scheduler's kill, a closed terminal, Ctrl-\\); the signal then ends the
/// command as it would have.
#[cfg(unix)]
mod on_signal {
    use std::sync::atomic::{AtomicPtr, Ordering};

    /// The temporary file being written, as a C string (null: none). A name once stored is never
    /// freed (one small string a write): the handler may read it at any moment.
    static WRITING: AtomicPtr<libc::c_char> = AtomicPtr::new(std::ptr::null_mut());
    static INSTALLED: std::sync::Once = std::sync::Once::new();

    extern "C" fn remove_and_stop(sig: libc::c_int) {
        let path = WRITING.load(Ordering::SeqCst);
        // SAFETY: unlink, signal and raise are async-signal-safe; `path` is null or a string
        // that is never freed.
        unsafe {
            if !path.is_null() {
                libc::unlink(path);
            }
            libc::signal(sig, libc::SIG_DFL);
            libc::raise(sig);
        }
    }

    /// Marks `path` as the temporary file being written (None: none now). The handler is
    /// installed at the first call, for SIGINT, SIGTERM, SIGHUP and SIGQUIT, unless the signal was ignored (a
    /// command started with `nohup`, or in the background by a script, stays deaf to it).
    pub fn writing(path: Option<&std::path::Path>) {
        INSTALLED.call_once(|| {
            for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP, libc::SIGQUIT] {
                // SAFETY: the handler only calls async-signal-safe functions.
                unsafe {
                    let before = libc::signal(sig, remove_and_stop as *const () as libc::sighandler_t);
                    if before == libc::SIG_IGN {
                        libc::signal(sig, libc::SIG_IGN);
                    }
                }
            }
        });
        use std::os::unix::ffi::OsStrExt;
        let name = path
            .and_then(|p| std::ffi::CString::new(p.as_os_str().as_bytes()).ok())
            .map_or(std::ptr::null_mut(), std::ffi::CString::into_raw);
        WRITING.store(name, Ordering::SeqCst);
    }
}

/// Opens `path` for writing as a new file: refused when anything is at that name already
/// (O_EXCL), and a symbolic link there is never followed (O_NOFOLLOW).
fn create_new(path: &std::path::Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NOFOLLOW);
    }
    options.open(path)
}

/// 64 bits no other user can predict, for a temporary file's name: std's `RandomState`, whose
/// keys come from the operating system's random source (getrandom on Linux), hashing the time,
/// the process id and a count of the names drawn so far.
fn random_token() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    static DRAWN: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
    h.write_u128(now);
    h.write_u32(std::process::id());
    h.write_u64(DRAWN.fetch_add(1, std::sync::atomic::Ordering::Relaxed));
    h.finish()
}

/// A user's text cut short for a message.
pub fn shorten(s: &str) -> String {
    aes_core::checks::shorten(s)
}

/// The scenario of a command: a file, `-` (standard input) or `preset:NAME`, with its `--set`
/// overrides applied all at once.
pub fn load(file: &str, sets: &[String]) -> Result<Scenario, String> {
    let mut sc = if let Some(name) = file.strip_prefix("preset:") {
        preset(name).ok_or_else(|| format!("no preset named '{}' (try: {})", shorten(name), PRESET_NAMES.join(", ")))?
    } else {
        let text = read_bounded(file, aes_core::scenario::file::MAX_SCENARIO_BYTES as u64, "a scenario")?;
        Scenario::from_json(&text).map_err(|e| format!("{}: invalid scenario:\n{e}", shorten(file)))?
    };
    let mut pairs = Vec::with_capacity(sets.len());
    for s in sets {
        let (path, value) = s
            .split_once('=')
            .ok_or_else(|| format!("--set '{}': expected PATH=VALUE, e.g. sim.duration_s=60", shorten(s)))?;
        pairs.push((path.trim(), value.trim()));
    }
    // All at once: fields that change together (a significant height with its peak frequency)
    // are checked together. An error names its field.
    if !pairs.is_empty() {
        sc = sc.with_set_flags(&pairs)?;
    }
    Ok(sc)
}

/// Runs the independent parts of a core computation (an RAO table's strips and rows) on rayon's
/// threads: the same parts as one after another, so the same bits.
pub struct Threads;

impl aes_core::sea::seakeeping::tables::ForEach for Threads {
    fn for_each(&self, n: usize, f: &(dyn Fn(usize) + Sync)) {
        use rayon::prelude::*;
        (0..n).into_par_iter().for_each(f)
    }
}
