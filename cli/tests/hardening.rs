//! The reproducers of issue 18, one test per class: each must end within 10 s with a clean error
//! (exit 1, a message naming the field or the limit) or a finite result, and never panic.

use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Most time a reproducer may take [s] (the issue's bound).
const BOUND: Duration = Duration::from_secs(10);

struct Outcome {
    code: Option<i32>,
    out: String,
    err: String,
}

/// Runs aes-sim with `args` and `stdin`, killing it at [`BOUND`]; fails the test on a timeout or
/// a panic (exit 101).
fn run(args: &[&str], stdin: &[u8]) -> Outcome {
    let t0 = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_aes-sim"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start aes-sim");
    let mut input = child.stdin.take().expect("stdin");
    let data = stdin.to_vec();
    // A writer thread: the command may stop reading early (that is the point of bounded reads).
    let feeder = std::thread::spawn(move || {
        let _ = input.write_all(&data);
    });
    let out = child.stdout.take().expect("stdout");
    let err = child.stderr.take().expect("stderr");
    let read_out = std::thread::spawn(move || std::io::read_to_string(out).unwrap_or_default());
    let read_err = std::thread::spawn(move || std::io::read_to_string(err).unwrap_or_default());
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if t0.elapsed() > BOUND {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?} did not end within {BOUND:?}");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let _ = feeder.join();
    let o = Outcome {
        code: status.code(),
        out: read_out.join().unwrap_or_default(),
        err: read_err.join().unwrap_or_default(),
    };
    assert_ne!(o.code, Some(101), "{args:?} panicked: {}", o.err);
    assert!(!o.err.contains("panicked"), "{args:?}: {}", o.err);
    o
}

/// A clean error: exit status 1 and a message containing `want`, at most 2000 bytes of it.
fn refused(args: &[&str], stdin: &[u8], want: &str) {
    let o = run(args, stdin);
    assert_eq!(o.code, Some(1), "{args:?}: {}", o.err);
    assert!(o.err.contains(want), "{args:?}: expected '{want}' in: {}", o.err);
    assert!(o.err.len() < 2000, "{args:?}: {} bytes of stderr", o.err.len());
}

/// Every number in a JSON text is finite: no `null` where serde_json printed NaN or infinity is
/// possible to tell apart, so the outputs are parsed and every null's path must be an allowed one.
fn finite_json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {}", &text[..text.len().min(300)]))
}

#[test]
fn class1_ips_extremes_end_with_a_named_error() {
    refused(&["ips", "linear", "--side", "motor", "--torque=1e100"], b"", "torque command T* = 1e100 N m");
    refused(&["ips", "bode", "--side", "motor", "--torque=1e100"], b"", "torque command T*");
    refused(&["ips", "linear", "--side", "motor", "--set", "l_m=1e-300"], b"", "l_m = 1e-300: must be a number");
    refused(&["ips", "bode", "--side", "generator", "--omega", "1e300"], b"", "omega = 1e300 rad/s");
    // The edges of the accepted ranges give finite results.
    for args in [
        &["ips", "bode", "--side", "motor", "--torque=10000", "--loop", "closed"][..],
        &["ips", "linear", "--side", "motor", "--torque=0.01"][..],
        &["ips", "bode", "--side", "generator", "--load", "0.01", "--vfd", "1000"][..],
    ] {
        let o = run(args, b"");
        if o.code == Some(0) {
            finite_json(&o.out);
            assert!(!o.out.contains("null"), "{args:?}: {}", o.out);
        } else {
            assert_eq!(o.code, Some(1), "{args:?}: {}", o.err);
        }
    }
}

#[test]
fn class2_closed_pipe_is_a_normal_end() {
    // `| head -c 1`: the reader closes after one byte; the command ends with status 0, quietly.
    for args in [
        &["run", "preset:startup", "--set", "sim.duration_s=2"][..],
        &["ips", "bode", "--side", "generator"][..],
        &["signals"][..],
        &["preset", "turn-360"][..],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_aes-sim"))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start");
        let mut out = child.stdout.take().expect("stdout");
        let mut one = [0u8; 1];
        std::io::Read::read_exact(&mut out, &mut one).expect("one byte");
        drop(out);
        let o = child.wait_with_output().expect("wait");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn class3_endless_and_huge_inputs_are_refused_quickly() {
    let t0 = Instant::now();
    refused(&["run", "/dev/zero"], b"", "larger than 4194304 bytes, the limit for a scenario");
    // Measured: 7 ms; the issue asks for under a second.
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    refused(&["run", "-"], &vec![b' '; 5 << 20], "standard input: larger than 4194304 bytes");
    refused(&["rao", "--hull", "/dev/zero", "--speed-kn", "10", "--heading-deg", "180", "--omega", "0.5"], b"", "hull");
    refused(&["mc", "/dev/zero"], b"", "the limit for a scenario");
    refused(&["fuel", "/dev/zero"], b"", "the limit for a scenario");
    refused(
        &["run", "-"],
        br#"{"sim":{"duration_s":1e6,"dt_s":0.001}}"#,
        "sim.duration_s = 1000000: with stepping.dt_s = 0.001",
    );
    refused(
        &["run", "-"],
        br#"{"sim":{"duration_s":200000,"dt_s":0.01,"record_interval_s":0.01}}"#,
        "sim.record_interval_s = 0.01",
    );
    // Hull files: too many stations or rows.
    let mut many = String::from("station_index,x_m,z_m,half_breadth_m\n");
    for i in 0..3000 {
        for k in 0..4 {
            many.push_str(&format!("{i},{},{},{}\n", i as f64 * 0.1, k as f64, 1.0));
        }
    }
    let dir = std::env::temp_dir().join(format!("aes-harden-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hull = dir.join("many.csv");
    std::fs::write(&hull, &many).unwrap();
    let h = hull.to_str().unwrap();
    refused(
        &["rao", "--hull", h, "--speed-kn", "10", "--heading-deg", "180", "--omega", "0.5"],
        b"",
        "more than 200 stations",
    );
    // Threads are capped at the machine's parallelism (a note on stderr, then the study).
    let o = run(&["mc", "preset:mc-arrival", "--trials", "2", "--threads", "100000", "--set", "sim.duration_s=2"], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert!(o.err.contains("capped at"), "{}", o.err);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn class4_no_nan_reaches_an_output() {
    refused(
        &["run", "preset:startup", "--set", "seakeeping.turbine_rated_efficiency=0"],
        b"",
        "turbine_rated_efficiency = 0",
    );
    refused(
        &["run", "preset:startup", "--set", "ship.hull.hub_above_base_m=1e308"],
        b"",
        "ship.hull.hub_above_base_m = 1e308",
    );
    refused(&["ips", "steady", "--side", "motor", "--set", "kq0=5e-324"], b"", "kq0 = 5e-324");
    refused(&["ips", "steady", "--side", "motor", "--torque=1e300"], b"", "torque command T* = 1e300");
    refused(
        &["section", "--beam", "2", "--draft", "1", "--area-coeff", "0.7854", "--omega", "1e-200"],
        b"",
        "omega = 1e-200",
    );
    let dir = std::env::temp_dir().join(format!("aes-harden4-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut text = aes_core::ship::sections::DTMB5415_OFFSETS.to_string();
    let line = text.lines().filter(|l| l.starts_with(|c: char| c.is_ascii_digit())).nth(10).unwrap().to_string();
    let mut f: Vec<&str> = line.split(',').collect();
    f[3] = "1e300";
    text = text.replacen(&line, &f.join(","), 1);
    let hull = dir.join("wide.csv");
    std::fs::write(&hull, text).unwrap();
    refused(
        &["rao", "--hull", hull.to_str().unwrap(), "--speed-kn", "10", "--heading-deg", "180", "--omega", "0.5"],
        b"",
        "half_breadth_m = 1e300",
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// One shard of a 4-trial, 2-second study as JSON.
fn partial_text(dir: &std::path::Path, range: &str) -> serde_json::Value {
    let path = dir.join(format!("p{}.json", range.replace("..", "_")));
    let o = run(
        &[
            "mc",
            "preset:mc-arrival",
            "--trials",
            "4",
            "--set",
            "sim.duration_s=2",
            "--trial-range",
            range,
            "--partial",
            path.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(o.code, Some(0), "{}", o.err);
    serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

/// A change to a partial's JSON.
type Mutation = Box<dyn Fn(&mut serde_json::Value)>;

#[test]
fn class5_merge_refuses_impossible_partials() {
    let dir = std::env::temp_dir().join(format!("aes-harden5-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = partial_text(&dir, "0..2");
    let other = partial_text(&dir, "2..4");
    let write = |name: &str, v: &serde_json::Value| {
        let p = dir.join(name);
        std::fs::write(&p, v.to_string()).unwrap();
        p.to_str().unwrap().to_string()
    };
    let g = write("good.json", &good);
    let o2 = write("other.json", &other);
    let o = run(&["merge", &g, &o2], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert_eq!(finite_json(&o.out)["trials"], 4);
    let cases: Vec<(&str, Mutation, &str)> = vec![
        ("reversed", Box::new(|v| v["ranges"] = serde_json::json!([[2, 0]])), "ranges.0 = [2, 0]"),
        (
            "censored",
            Box::new(|v| v["part"]["censored"] = serde_json::json!(u64::MAX)),
            "censored = 18446744073709551615",
        ),
        (
            "n",
            Box::new(|v| v["part"]["exposure"]["n"] = serde_json::json!(u64::MAX)),
            "exposure: n = 18446744073709551615",
        ),
        ("format", Box::new(|v| v["format"] = serde_json::json!("something else")), "format = 'something else'"),
        ("version", Box::new(|v| v["version"] = serde_json::json!(99)), "version 99"),
        (
            "bits",
            Box::new(|v| v["part"]["arrival"]["bits"] = serde_json::json!(2_000_000_000)),
            "arrival: bits = 2000000000",
        ),
        (
            "interval",
            Box::new(|v| v["part"]["record_interval_s"] = serde_json::json!(1e-300)),
            "record_interval_s = 1e-300",
        ),
        ("kind", Box::new(|v| v["kind"] = serde_json::json!("rare-events")), "not a rare-events shard"),
        ("unknown", Box::new(|v| v["censored"] = serde_json::json!(0)), "unknown field `censored`"),
    ];
    for (name, change, want) in cases {
        let mut bad = good.clone();
        change(&mut bad);
        let b = write(&format!("{name}.json"), &bad);
        // Alone (the first or only file is checked too) and after a good file.
        refused(&["merge", &b], b"", want);
        refused(&["merge", &o2, &b], b"", if name == "kind" { "a shard of another kind of study" } else { want });
    }
    // A shard's definition is checked alone; after a good shard, its key no longer fits it.
    let mut bad = good.clone();
    bad["spec"]["ship"]["hull"]["hub_above_base_m"] = serde_json::json!(1e308);
    let b = write("scenario.json", &bad);
    refused(&["merge", &b], b"", "its scenario is not valid: ship.hull.hub_above_base_m");
    refused(&["merge", &o2, &b], b"", "not the key of its own definition");
    // Overlapping shards.
    refused(&["merge", &g, &g], b"", "overlap");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn class6_messages_name_the_field_briefly() {
    let long = "x".repeat(100_000);
    let o = run(
        &["run", "preset:startup", "--set", &format!("name=1{long}"), "--set", &format!("ship.mass_kg={long}")],
        b"",
    );
    assert_eq!(o.code, Some(1));
    assert!(o.err.len() < 1000, "{} bytes", o.err.len());
    let big = format!(r#"{{"name": "{}", "ship": {{"mass_kg": "{}"}}}}"#, "y".repeat(3 << 20), "z".repeat(10_000));
    let o = run(&["run", "-"], big.as_bytes());
    assert_eq!(o.code, Some(1));
    assert!(o.err.len() < 1000, "{} bytes of stderr", o.err.len());
    refused(&["run", "preset:turn-45", "--set", "plant.motor.rated_voltage_ll_v=498"], b"", "the motor cannot carry");
    refused(&["ips", "steady", "--side", "generator", "--load", "500", "--vfd", "1"], b"", "load current I = 500 A");
    refused(&["run", "-"], br#"{"ship": {"mass_kg": 7e6, "mass_kg": 8e6}}"#, "duplicate key ship.mass_kg");
    let deep = format!(r#"{{"commands": {}}}"#, "[".repeat(64));
    refused(&["run", "-"], deep.as_bytes(), "nesting deeper than 32 levels at commands.0");
    // A huge number is quoted in its exponent form wherever it appears (it printed 301 digits).
    let o = run(&["run", "-"], br#"{"sim": {"duration_s": 1e300}}"#);
    assert_eq!(o.code, Some(1));
    assert!(o.err.contains("with sim.duration_s = 1e300 this records") && !o.err.contains("0000000000"), "{}", o.err);
}

#[test]
fn class7_unwritable_out_is_found_first_and_the_summary_kept() {
    let t0 = Instant::now();
    refused(
        &["run", "preset:startup", "--out", "/nonexistent-dir/trace.csv"],
        b"",
        "--out '/nonexistent-dir/trace.csv'",
    );
    // Found before the 400 s run (which takes about 0.2 s): well under that here.
    assert!(t0.elapsed() < Duration::from_secs(2));
    refused(&["mc", "preset:mc-arrival", "--partial", "/nonexistent-dir/p.json"], b"", "--partial");
}

/// A fresh folder for one test's files.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("aes-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Issue 34: nothing a user made is lost. An output is written only when the command succeeds
/// (through a temporary file renamed into place), never when it is also an input, and `validate`
/// writes only the file --out names.
#[test]
fn class8_no_output_destroys_what_was_there() {
    let dir = scratch("harden8");
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    // A run that fails at set-up leaves the old trace as it was.
    let old = path("old.csv");
    std::fs::write(&old, "my own data\n").unwrap();
    refused(
        &["run", "preset:turn-45", "--set", "plant.motor.rated_voltage_ll_v=498", "--out", &old],
        b"",
        "the motor cannot carry",
    );
    assert_eq!(std::fs::read_to_string(&old).unwrap(), "my own data\n");
    // A successful run replaces it whole, and leaves no temporary file behind.
    let o = run(&["run", "preset:startup", "--set", "sim.duration_s=1", "--out", &old], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert!(std::fs::read_to_string(&old).unwrap().starts_with("t_s,"));
    // A device is written to as before (nothing to replace there).
    let o = run(&["run", "preset:startup", "--set", "sim.duration_s=1", "--out", "/dev/null"], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    // An output that is an input is refused before anything is read or written.
    let a = partial_text(&dir, "0..2");
    let b = partial_text(&dir, "2..4");
    let (pa, pb) = (path("p0_2.json"), path("p2_4.json"));
    let before = std::fs::read(&pa).unwrap();
    refused(&["merge", &pa, &pb, "--partial", &pa], b"", "is also an input of this command");
    // Under another name of the same file too.
    let other_name = format!("{}/./p0_2.json", dir.to_str().unwrap());
    refused(&["merge", &pa, &pb, "--partial", &other_name], b"", "is also an input");
    let list = path("list.txt");
    std::fs::write(&list, format!("{pa}\n{pb}\n")).unwrap();
    refused(&["merge", "--files-from", &list, "--partial", &list], b"", "is also an input");
    // A shard the list names is an input as well.
    refused(&["merge", "--files-from", &list, "--partial", &pb], b"", "is also an input");
    assert_eq!(std::fs::read(&pa).unwrap(), before);
    assert_eq!(std::fs::read_to_string(&list).unwrap(), format!("{pa}\n{pb}\n"));
    assert_eq!(serde_json::from_slice::<serde_json::Value>(&std::fs::read(&pb).unwrap()).unwrap(), b);
    assert_eq!(serde_json::from_slice::<serde_json::Value>(&before).unwrap(), a);
    let merged = path("merged.json");
    let o = run(&["merge", "--files-from", &list, "--partial", &merged], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    let leftovers: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains("aes-sim-tmp"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 34: `validate --out DIR/report.md` writes DIR/report.md and nothing else: a user's own
/// figures in DIR/validation/ stay, and no figure lands there. A bad --out is found before the
/// report is computed (about 13 s with one trial; refused here within a second).
#[test]
fn class8_validate_writes_only_where_out_says() {
    let dir = scratch("harden8v");
    let t0 = Instant::now();
    refused(&["validate", "--out", dir.join("missing/report.md").to_str().unwrap()], b"", "--out '");
    refused(&["validate", "--out", dir.to_str().unwrap()], b"", "not a file name");
    let long = format!("{}/{}/r.md", dir.to_str().unwrap(), "d".repeat(120_000));
    refused(&["validate", "--out", &long], b"", "cannot write in its folder");
    let file = dir.join("a-file");
    std::fs::write(&file, "mine").unwrap();
    refused(&["validate", "--figures", file.to_str().unwrap()], b"", "not a folder");
    refused(&["validate", "--check", "docs/validation.md", "--out", "x.md"], b"", "give one or the other");
    refused(&["validate", "--check", file.to_str().unwrap(), "--figures", "x"], b"", "give one or the other");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "mine");
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    std::fs::create_dir_all(dir.join("validation")).unwrap();
    std::fs::write(dir.join("validation/own.svg"), "<svg/>").unwrap();
    let report = dir.join("report.md");
    // Rows may leave their tolerance with one trial (exit 1): the report is written either way.
    let o = Command::new(env!("CARGO_BIN_EXE_aes-sim"))
        .args(["validate", "--trials", "1", "--out", report.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::read_to_string(&report).unwrap().contains("validation/"));
    let mut names: Vec<String> = std::fs::read_dir(dir.join("validation"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["own.svg"]);
    assert_eq!(std::fs::read_to_string(dir.join("validation/own.svg")).unwrap(), "<svg/>");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 34: control characters of values and file names are escaped before they reach the
/// terminal, and a scenario with thousands of problems lists the first few and counts the rest.
#[test]
fn class9_messages_are_escaped_and_bounded() {
    let o = run(&["run", "bad\u{1b}[2J\u{7}\nname.json"], b"");
    assert_eq!(o.code, Some(1));
    assert!(!o.err.contains('\u{1b}') && !o.err.contains('\u{7}'), "{:?}", o.err);
    assert!(o.err.contains("bad\\u{1b}[2J\\u{7}\\nname.json"), "{:?}", o.err);
    let o = run(&["run", "preset:startup", "--set", "name=a\u{1b}]0;owned\u{7}"], b"");
    assert!(!o.err.contains('\u{1b}') && !o.out.contains('\u{1b}'), "{:?}", o.err);
    let commands: Vec<String> = (0..10_000).map(|i| format!(r#"{{"t_s": {i}, "speed_kn": 1e9}}"#)).collect();
    let sc = format!(r#"{{"commands": [{}]}}"#, commands.join(","));
    let o = run(&["run", "-"], sc.as_bytes());
    assert_eq!(o.code, Some(1));
    assert!(o.err.len() < 5000, "{} bytes of stderr", o.err.len());
    assert!(o.err.contains("more problems (10000 in all)"), "{}", &o.err[o.err.len().saturating_sub(300)..]);
}

/// Issue 34: every study's size is bounded before it starts, with a message saying what to
/// reduce: the issue's 7.6 GB Monte Carlo study (refused within a second, measured 10 ms),
/// 1e7 trials of a 90 s run, `bench --repeat 4294967295`, 30,000 fuel frequencies (the cap is
/// fuel::MAX_OMEGAS = 200), `validate --trials 100000`.
#[test]
fn class10_studies_are_bounded_before_they_start() {
    let dir = scratch("harden10");
    let signals: Vec<String> = run(&["signals", "--json"], b"")
        .out
        .split("\"name\": \"")
        .skip(1)
        .take(20)
        .map(|s| format!("\"{}\"", &s[..s.find('"').unwrap()]))
        .collect();
    assert_eq!(signals.len(), 20);
    let sc = format!(
        r#"{{"sim":{{"duration_s":900,"record_interval_s":0.005}},"monte_carlo":{{"trials":10,"keep_traces":10,"envelope_signals":[{}]}}}}"#,
        signals.join(",")
    );
    let t0 = Instant::now();
    refused(&["mc", "-"], sc.as_bytes(), "this study keeps about 735 MB");
    refused(&["mc", "-"], sc.as_bytes(), "at most 64 MB: record less often (sim.record_interval_s = 0.005)");
    let shard = dir.join("shard.json");
    refused(
        &["mc", "-", "--trial-range", "0..1", "--partial", shard.to_str().unwrap()],
        sc.as_bytes(),
        "at most 64 MB",
    );
    assert!(!shard.exists());
    assert!(t0.elapsed() < Duration::from_secs(2), "{:?}", t0.elapsed());
    refused(&["mc", "preset:mc-arrival", "--trials", "10000000"], b"", "monte_carlo.trials = 10000000: with");
    refused(&["bench", "--repeat", "4294967295"], b"", "--repeat = 4294967295: must be a whole number from 1 to 100");
    refused(&["bench", "--repeat", "0"], b"", "from 1 to 100");
    // One argument holds at most 128 kB: 30,000 frequencies (the issue gave 120,000).
    let omegas = vec!["1"; 30_000].join(",");
    refused(&["fuel", "--omega", &omegas], b"", "30000 wave frequencies: give 1 to 200");
    refused(&["validate", "--trials", "100000"], b"", "--trials = 100000: must be a whole number from 1 to 10000");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46, case 1: `merge --files-from` reads its list a line at a time, each line at most
/// 4,096 bytes (a shard file's name) and the list at most 64 MB: an endless line is refused after
/// reading 4,097 bytes (it was read whole, 4.2 GB, then an abort).
#[test]
fn class11_merge_lists_are_bounded() {
    let t0 = Instant::now();
    let o = run(&["merge", "--files-from", "/dev/zero"], b"");
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert_eq!(
        o.err,
        "aes-sim: --files-from: line 1 of '/dev/zero' is longer than 4096 bytes, the limit for a shard file's name\n"
    );
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    // From standard input, after a first name that is not a shard: the list is read as merged,
    // the first error ends it.
    let mut list = b"\n\n".to_vec();
    list.extend(vec![b'a'; 5 << 20]);
    let o = run(&["merge", "--files-from", "-"], &list);
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert_eq!(
        o.err,
        "aes-sim: --files-from: line 3 of standard input is longer than 4096 bytes, the limit for a shard file's name\n"
    );
    refused(
        &["merge", "--files-from", "-"],
        b"a\xff.json\n",
        "--files-from: line 1 of standard input is not UTF-8 text (byte 2)",
    );
}

/// Issue 46, case 6: `operability` checks its speeds, headings, seas and work before it builds
/// the RAO table. With the finest grid allowed (400 x 20 x 25 = 200,000 points, 5.8e6 units of
/// work: measured 10 s on one core) each bad list is refused within 2 s (it took the table's time
/// first; the work limit was checked only after the table).
#[test]
fn class12_operability_checks_its_lists_before_the_table() {
    let fine = [
        "--set",
        "seakeeping.grid.n_omega=400",
        "--set",
        "seakeeping.grid.n_speed=20",
        "--set",
        "seakeeping.grid.n_heading=25",
    ];
    let speeds: Vec<String> = (0..100).map(|i| format!("{}", i as f64 * 0.3)).collect();
    let headings: Vec<String> = (0..360).map(|i| i.to_string()).collect();
    let (speeds, headings) = (speeds.join(","), headings.join(","));
    let t0 = Instant::now();
    for (args, want) in [
        (
            vec!["--speeds", "99"],
            "aes-sim: speeds: 99 kn is outside 0 to 35 kn (seakeeping.grid.speed_max_kn, the RAO table's top speed)\n",
        ),
        (vec!["--headings", "400"], "aes-sim: headings: 400 deg is outside -360 to 360 deg\n"),
        (vec!["--seas", "30:10"], "aes-sim: seas: H_1/3 = 30 m is outside 0 to 20 m\n"),
        (vec!["--speeds", &speeds, "--headings", &headings], "aes-sim: the polar asks for up to "),
    ] {
        let all: Vec<&str> = ["operability"].into_iter().chain(fine).chain(args.iter().copied()).collect();
        let o = run(&all, b"");
        assert_eq!(o.code, Some(1), "{args:?}: {}", o.err);
        assert!(o.err.starts_with(want), "{args:?}: {}", o.err);
        assert!(o.err.len() < 2000, "{args:?}: {} bytes", o.err.len());
    }
    assert!(t0.elapsed() < Duration::from_secs(2), "{:?}", t0.elapsed());
}

/// Issue 46, case 7: the temporary file of an output is created new, under a name nobody can
/// predict, never through a symbolic link: links planted while the command runs, at the name it
/// used to use (`.NAME.PID.aes-sim-tmp`) and at a guess of the new one, stay as they were, and so
/// does the file they point to; the output is written whole.
#[cfg(unix)]
#[test]
fn class13_temporary_files_never_follow_a_link() {
    let dir = scratch("harden13");
    let target = dir.join("someone-elses.txt");
    std::fs::write(&target, "not yours\n").unwrap();
    let out = dir.join("trace.csv");
    let child = Command::new(env!("CARGO_BIN_EXE_aes-sim"))
        .args(["run", "preset:startup", "--set", "sim.duration_s=400", "--out", out.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start aes-sim");
    let pid = child.id();
    let planted = [format!(".trace.csv.{pid}.aes-sim-tmp"), format!(".trace.csv.{pid}.0000000000000000.aes-sim-tmp")];
    for name in &planted {
        std::os::unix::fs::symlink(&target, dir.join(name)).unwrap();
    }
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "not yours\n");
    assert!(std::fs::read_to_string(&out).unwrap().starts_with("t_s,"));
    for name in &planted {
        assert_eq!(std::fs::read_link(dir.join(name)).unwrap(), target, "{name}");
    }
    let mut names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    let mut want = vec![planted[0].clone(), planted[1].clone(), "someone-elses.txt".into(), "trace.csv".into()];
    want.sort();
    assert_eq!(names, want);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46, case 8: every message stays under 2 kB with its control characters escaped: an
/// operability section with 20 problems (9 kB before) lists the first few and counts the rest;
/// clap's echo of a 5,000-character value with a raw newline is cut and escaped (exit status 2,
/// clap's); a scatter diagram whose counts add up past the largest number is refused by its
/// field (it said "no occurrences").
#[test]
fn class14_every_message_is_short_and_escaped() {
    let points: Vec<String> = (0..20)
        .map(|i| format!(r#"{{"name": "point {i} {}", "x_m": 100, "y_m": 0, "z_m": 20}}"#, "p".repeat(50)))
        .collect();
    let criteria: Vec<String> = (0..20)
        .map(|_| r#"{"quantity": "vertical_acceleration_rms_g", "point": "nowhere", "limit": 0.2}"#.to_string())
        .collect();
    let sc =
        format!(r#"{{"operability": {{"points": [{}], "criteria": [{}]}}}}"#, points.join(","), criteria.join(","));
    let o = run(&["operability", "-"], sc.as_bytes());
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert!(o.err.len() < 2000, "{} bytes of stderr", o.err.len());
    assert!(
        o.err.contains(
            "operability.criteria.0.point = \"nowhere\": vertical_acceleration_rms_g is taken at a point: one of"
        ),
        "{}",
        o.err
    );
    assert!(o.err.ends_with(" more problems (20 in all)\n"), "{}", o.err);
    let long = format!("1\n{}", "x".repeat(5000));
    let o = run(&["operability", "--speeds", &long], b"");
    assert_eq!(o.code, Some(2), "{}", o.err);
    let shown = format!("1\\n{}...", "x".repeat(57));
    assert_eq!(
        o.err.lines().next().unwrap(),
        format!("error: invalid value '{shown}' for '--speeds <SPEEDS>': invalid float literal")
    );
    assert!(o.err.len() < 2000 && !o.err.contains("1\nx"), "{}", o.err);
    let dir = scratch("harden14");
    let scatter = dir.join("scatter.csv");
    std::fs::write(&scatter, "Hs_m\\Tz_s,5,6\n1,1e308,1e308\n").unwrap();
    let s = scatter.to_str().unwrap();
    let o = run(&["operability", "--scatter", s], b"");
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert_eq!(o.err, format!("aes-sim: --scatter {s}: line 2: occurrence = 1e308 is outside 0 to 1e12\n"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46, case 7 and issue 57, case 7: a command stopped by SIGTERM, SIGHUP or SIGQUIT while it writes its output removes its
/// temporary file (and ends by the signal as before). The trace of a 2,000 s run recorded every
/// 0.01 s (200,000 rows) takes long enough to write that the temporary file is seen and the
/// signal sent before the rename.
#[cfg(unix)]
#[test]
fn class15_a_stopped_write_leaves_no_temporary_file() {
    // SIGTERM 15, SIGHUP 1 (a closed terminal: it left 25-102 MB behind), SIGQUIT 3 on Linux.
    for (name, number) in [("TERM", 15), ("HUP", 1), ("QUIT", 3)] {
        // A signal this test was started with ignored (SIGHUP under nohup) the command inherits and
        // keeps ignored, as a command started so should: it then finishes its write.
        if ignored(number) {
            eprintln!("SIG{name} is ignored in this process (nohup?): its case is not checked");
            continue;
        }
        stopped_write_leaves_no_temporary_file(name, number);
    }
}

/// Whether `signal` is ignored in this process (read without changing it).
#[cfg(unix)]
fn ignored(signal: i32) -> bool {
    // SAFETY: sigaction with no new action only reads the present one into `old`.
    unsafe {
        let mut old: libc::sigaction = std::mem::zeroed();
        libc::sigaction(signal, std::ptr::null(), &mut old) == 0 && old.sa_sigaction == libc::SIG_IGN
    }
}

#[cfg(unix)]
fn stopped_write_leaves_no_temporary_file(name: &str, number: i32) {
    use std::os::unix::process::ExitStatusExt;
    let dir = scratch(&format!("harden15-{name}"));
    let out = dir.join("trace.csv");
    let temporary = |dir: &std::path::Path| {
        std::fs::read_dir(dir)
            .unwrap()
            .filter_map(|e| e.ok())
            .any(|e| e.file_name().to_string_lossy().ends_with(".aes-sim-tmp"))
    };
    // Being written: not the empty file made when --out is checked at the start.
    let writing = |dir: &std::path::Path| {
        std::fs::read_dir(dir).unwrap().filter_map(|e| e.ok()).any(|e| {
            e.file_name().to_string_lossy().ends_with(".aes-sim-tmp") && e.metadata().is_ok_and(|m| m.len() > 0)
        })
    };
    let mut child = Command::new(env!("CARGO_BIN_EXE_aes-sim"))
        .args(["run", "preset:startup", "--set", "sim.duration_s=1800", "--set", "sim.record_interval_s=0.01"])
        .args(["--out", out.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("start aes-sim");
    let t0 = Instant::now();
    while !writing(&dir) && t0.elapsed() < BOUND && child.try_wait().unwrap().is_none() {
        std::thread::sleep(Duration::from_micros(200));
    }
    let seen = writing(&dir);
    let killed = Command::new("kill").args([&format!("-{name}"), &child.id().to_string()]).status().unwrap();
    let status = child.wait().unwrap();
    assert!(seen && killed.success(), "SIG{name}: the temporary file was not seen before the command ended");
    assert_eq!(status.signal(), Some(number), "SIG{name}: {status:?}");
    assert!(!temporary(&dir), "SIG{name}: a temporary file is left");
    assert!(!out.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46, case 10: a study estimated past an hour on its threads is refused before any work
/// unless `--allow-long` is given, with the estimate in the message (a 900 s Monte Carlo run
/// 100,000 times: about 2.6 h on 2 threads by the estimate, an upper bound: the arrival study's
/// trials end at their arrival, 20 of them in 0.43 s; refused within a second, measured 18 ms).
/// A rare-event trial's work counts its runs to the event that place the ship as well as its own
/// run: 100,000 trials of head-seas-ss6, which take about 80 min on 2 threads (20 trials
/// measured, 1.1 s; 100 trials on one thread 7.5 s), are estimated at about 82 min and refused
/// (counting the trial's run alone, 44 min, they were let through).
/// With the flag it would run its 4 h, which a test cannot wait for; within the budget a study
/// runs as before.
#[test]
fn class16_a_long_study_is_refused_unless_allowed() {
    let long = [
        "mc",
        "preset:mc-arrival",
        "--set",
        "monte_carlo.trials=100000",
        "--set",
        "sim.duration_s=900",
        "--threads",
        "2",
    ];
    let t0 = Instant::now();
    let o = run(&long, b"");
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert!(
        o.err.starts_with("aes-sim: mc: 100000 trials of ")
            && o.err.contains(
                "is estimated at about 2.6 h on 2 thread(s), past the 1 h a study may take without --allow-long"
            ),
        "{}",
        o.err
    );
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    // Rare events judge the brute-force runs with the trials, before the run that places the
    // ship (10,000 hours of sea: about 73 min on 2 threads by the estimate).
    let t0 = Instant::now();
    let o = run(&["rare", "preset:head-seas-ss6", "--brute-force", "10000", "--threads", "2", "--quiet"], b"");
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert!(
        o.err.starts_with("aes-sim: rare: 200 trials and 30000 brute-force runs of 1365 s is estimated at about ")
            && o.err.contains("without --allow-long"),
        "{}",
        o.err
    );
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    let t0 = Instant::now();
    let o = run(&["rare", "preset:head-seas-ss6", "--trials", "100000", "--threads", "2", "--quiet"], b"");
    assert_eq!(o.code, Some(1), "{}", o.err);
    assert!(
        o.err.starts_with("aes-sim: rare: 100000 trials of ")
            && o.err.contains("is estimated at about 82 min on 2 thread(s), past the 1 h a study may take"),
        "{}",
        o.err
    );
    assert!(t0.elapsed() < Duration::from_secs(2), "{:?}", t0.elapsed());
    // Within the budget nothing changes: 2 trials of the preset run as before.
    let o = run(&["mc", "preset:mc-arrival", "--set", "monte_carlo.trials=2", "--quiet"], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
}

/// The short rare-event study of issue 46's shard tests: 4 trials with the event at 20 s and a
/// 5 s window (about half a second natively).
const RARE: [&str; 8] =
    ["rare", "--trials", "4", "--set", "rare_event.time_s=20", "--set", "rare_event.window_s=5", "--quiet"];

/// Issue 46 (2, 3): a rare-event shard from outside is checked number by number against what a
/// trial of its study can give, by `rare --merge` and by `aes-sim merge` alike (the one check of
/// the shared pipeline): the refusal names the file, the trial and the field with its value in
/// short and what is allowed, in under 1 kB, whatever the shard holds.
#[test]
fn class17_rare_merge_refuses_what_no_trial_gives() {
    let dir = scratch("harden11");
    let shard = dir.join("all.json");
    let s = shard.to_str().unwrap();
    let o = run(&[&RARE[..], &["--trial-range", "0..4", "--partial", s]].concat(), b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    let good: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&shard).unwrap()).unwrap();
    let merged = run(&[&RARE[..], &["--merge", s]].concat(), b"");
    assert_eq!(merged.code, Some(0), "{}", merged.err);
    assert_eq!(run(&["merge", s], b"").out, merged.out);
    let trial1 = |v: &mut serde_json::Value, field: &str, x: serde_json::Value| v["part"][1][field] = x;
    let value1 = |v: &mut serde_json::Value, k: usize, x: f64| v["part"][1]["values"][k] = serde_json::json!(x);
    let cases: Vec<(&str, Mutation, &str)> = vec![
        (
            "negative-weight",
            Box::new(move |v| trial1(v, "crossing_rate_per_s", serde_json::json!(-0.5))),
            "trial 1: crossing_rate_per_s = -0.5: a trial's weight is its sea's crossing rate, above 0 and at most ",
        ),
        ("zero-weight", Box::new(move |v| trial1(v, "crossing_rate_per_s", serde_json::json!(0))), "crossing_rate_per_s = 0: "),
        ("huge-weight", Box::new(move |v| trial1(v, "crossing_rate_per_s", serde_json::json!(1e308))), "crossing_rate_per_s = 1e308: "),
        (
            "bus",
            Box::new(move |v| value1(v, 0, -5.0)),
            "trial 1: values.min_bus_voltage_pu = -5: must be from -0.1 to 3 pu (the run stops when a bus leaves this band",
        ),
        ("turbine", Box::new(move |v| value1(v, 1, 1e308)), "values.peak_turbine_speed_pu = 1e308: must be from -0.1 to 3 pu"),
        ("swing", Box::new(move |v| value1(v, 2, -1e6)), "values.shaft_speed_swing_rpm = -1000000: must be from 0 to 1920 rpm"),
        ("drop", Box::new(move |v| value1(v, 3, 1e308)), "values.motor_power_drop_mw = 1e308: must be from -7600 to 7600 MW"),
        ("brake", Box::new(move |v| value1(v, 4, -1e9)), "values.brake_energy_mj = -1000000000: must be from 0 to 0 MJ"),
        ("h-over-r", Box::new(move |v| trial1(v, "h_over_r_at_event", serde_json::json!(1e308))), "h_over_r_at_event = 1e308: "),
        (
            "seed",
            Box::new(move |v| trial1(v, "seed", serde_json::json!(12345))),
            "trial 1: seed = 12345: trial 1's seed is ",
        ),
        (
            "place",
            Box::new(move |v| trial1(v, "ship_x_m", serde_json::json!(1e308))),
            "trial 1: ship_x_m = 1e308: must be from -10000000 to 10000000 (rare_event.ship_x_m's range: the trial's replay sets it)",
        ),
        (
            "reach",
            Box::new(move |v| trial1(v, "ship_y_m", serde_json::json!(9e6))),
            "m from the start, at most 896 m (the fastest a run allows for the event's time)",
        ),
        ("speed", Box::new(move |v| trial1(v, "ship_speed_kn", serde_json::json!(0))), "ship_speed_kn = 0: must be from 0.01 to 40"),
        (
            "copies",
            Box::new(|v| {
                let copy = v["part"][1].clone();
                v["part"].as_array_mut().unwrap().push(copy);
            }),
            "5 records for the 4 trials of its ranges",
        ),
        ("unknown", Box::new(move |v| trial1(v, "note", serde_json::json!(1))), "unknown field `note`"),
        // The issue's 1 MB string where a number belongs and 100 kB study key.
        (
            "long-string",
            Box::new(move |v| trial1(v, "ship_x_m", serde_json::json!("y".repeat(1 << 20)))),
            "invalid type: string \"yyyy",
        ),
        ("long-key", Box::new(|v| v["key"] = serde_json::json!("k".repeat(100_000))), "not the key of its own definition"),
        ("kind", Box::new(|v| v["kind"] = serde_json::json!("monte-carlo")), "kind = 'monte-carlo'"),
    ];
    for (name, change, want) in cases {
        let mut bad = good.clone();
        change(&mut bad);
        let path = dir.join(format!("{name}.json"));
        std::fs::write(&path, bad.to_string()).unwrap();
        let p = path.to_str().unwrap();
        for args in [[&RARE[..], &["--merge", p]].concat(), vec!["merge", p]] {
            let o = run(&args, b"");
            assert_eq!(o.code, Some(1), "{name}: {}", o.err);
            // `aes-sim merge` reads the kind first and dispatches on it.
            let want =
                if name == "kind" && args[0] == "merge" { "not a monte-carlo shard: invalid type" } else { want };
            assert!(o.err.contains(want), "{name}: expected '{want}' in: {}", o.err);
            assert!(o.err.contains(&format!("{name}.json: ")), "{name}: the file is not named: {}", o.err);
            assert!(o.err.len() < 1000, "{name}: {} bytes of stderr", o.err.len());
            assert!(o.out.is_empty(), "{name}: printed a summary");
        }
    }
    // More trials than a study runs: its definition is refused as a run's would be.
    let mut bad = good.clone();
    bad["spec"]["trials"] = serde_json::json!(170_000);
    let path = dir.join("trials.json");
    std::fs::write(&path, bad.to_string()).unwrap();
    refused(&["merge", path.to_str().unwrap()], b"", "trials.json: trials = 170000: must be from 2 to 100000");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46 (4): `rare`'s flags are checked before any work (the issue found a bad
/// `--brute-force` refused only after the conditioned study; refused here within a second, as are
/// the shard flags),
/// and `--merge` with `--brute-force` or `--trial-range` is refused by the argument parser
/// naming both flags (exit 2). `--merge` with `--partial` is no conflict: it writes the merged
/// shard, as for every study.
#[test]
fn class18_rare_flags_are_checked_before_work() {
    let t0 = Instant::now();
    for bad in ["NaN", "inf", "-1", "0", "0.09", "10001", "1e308"] {
        let want = format!("--brute-force {}: from 0.1 to 10000 hours", aes_core::checks::num(bad.parse().unwrap()));
        refused(&["rare", &format!("--brute-force={bad}")], b"", &want);
    }
    assert!(t0.elapsed() < Duration::from_secs(2), "{:?}", t0.elapsed());
    let dir = scratch("harden12");
    // The shard flags too, before the run to a late event that places the ship (measured 3.6 s
    // before they were checked first, 30 ms after).
    let late = ["rare", "--set", "rare_event.time_s=18000", "--trial-range"];
    let t0 = Instant::now();
    refused(
        &[&late[..], &["5..2", "--partial", "x.json"]].concat(),
        b"",
        "--trial-range 5..2: need a < b <= the study's 200 trials",
    );
    refused(&[&late[..], &["0..2"]].concat(), b"", "--trial-range needs --partial FILE");
    let nowhere = dir.join("missing/x.json");
    refused(
        &[&late[..], &["0..2", "--partial", nowhere.to_str().unwrap()]].concat(),
        b"",
        "cannot write in its folder",
    );
    assert!(t0.elapsed() < Duration::from_secs(1), "{:?}", t0.elapsed());
    let shard = dir.join("all.json");
    let s = shard.to_str().unwrap();
    let o = run(&[&RARE[..], &["--trial-range", "0..4", "--partial", s]].concat(), b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    for (extra, other) in [
        (&["--brute-force", "1"][..], "'--brute-force <HOURS>'"),
        (&["--trial-range", "0..2"][..], "'--trial-range <A..B>'"),
        (&["--trial-range", "0..2", "--partial", "x.json"][..], "'--trial-range <A..B>'"),
    ] {
        let o = run(&[&RARE[..], &["--merge", s], extra].concat(), b"");
        assert_eq!(o.code, Some(2), "{extra:?}: {}", o.err);
        assert!(o.err.contains(&format!("the argument '--merge <FILE>...' cannot be used with {other}")), "{}", o.err);
        assert!(o.out.is_empty());
    }
    let again = dir.join("again.json");
    let o = run(&[&RARE[..], &["--merge", s, "--partial", again.to_str().unwrap()]].concat(), b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(&shard).unwrap());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 46 (5): a 95 % interval needs two trials (one has no spread: it gave an interval of zero
/// width), and the comparison with brute force gives a ratio only where it is defined: where it
/// is not (brute force counted no event past a threshold, so its interval has no width to
/// scale) the field is left out and `undefined` says why; nothing in the output is `null`.
#[test]
fn class19_rare_intervals_are_never_falsely_narrow() {
    refused(
        &["rare", "--trials", "1"],
        b"",
        "trials = 1: must be from 2 to 100000 (the event's 95 % interval is the spread of the trials' seas' rates: fewer than 2 trials have none)",
    );
    let mut args = RARE.to_vec();
    args[2] = "2";
    args.extend(["--threshold", "min_bus_voltage_pu=-1", "--brute-force", "0.1"]);
    let o = run(&args, b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert!(!o.out.contains("null"), "{}", o.out);
    let v = finite_json(&o.out);
    let rows = v["brute_force"]["compare"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    // The event: brute force counts many at the preset's ballast depth; both ratios are there.
    let key = "brute_force_seconds_for_the_same_width_over_conditioned";
    assert!(rows[0][key].as_f64().unwrap() > 0.0 && rows[0]["joint_standard_errors"].is_f64(), "{}", rows[0]);
    assert!(rows[0].get("undefined").is_none(), "{}", rows[0]);
    // No bus falls below -1 pu: brute force's interval is [0, 0].
    assert_eq!(rows[1]["rate"], "min_bus_voltage_pu past -1");
    assert_eq!(rows[1]["brute_force_per_hour"], serde_json::json!([0.0, 0.0, 0.0]));
    assert!(rows[1].get(key).is_none(), "{}", rows[1]);
    assert_eq!(
        rows[1]["undefined"][key],
        "the brute-force interval has zero width (no event past it was counted): it has no width to scale"
    );
}

/// Issue 57's closing fuzz run: flags that the chosen form of a command would not read were
/// ignored with exit status 0. `lesson` without a NAME printed the list and dropped `--value`,
/// `--before`, `--answer` and `--json`; `bench propeller` dropped `--set` and `--hull`, a preset's
/// bench dropped `--hull`, and `bench seakeeping` dropped `--set` without `--hull`. Each is refused
/// by name now.
#[test]
fn class20_a_flag_the_command_would_not_read_is_refused() {
    let names: Vec<&str> = aes_core::output::lessons::lessons().iter().map(|l| l.name).collect();
    let names = format!("(one of {})", names.join(", "));
    refused(&["lesson", "--value", "sea.sea_state=4"], b"", &format!("--value needs a lesson NAME first {names}"));
    refused(&["lesson", "--before", "default"], b"", "--before needs a lesson NAME first");
    refused(&["lesson", "--answer", "1"], b"", "--answer needs a lesson NAME first");
    refused(&["lesson", "--json"], b"", "--json needs a lesson NAME first");
    let o = run(&["lesson"], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
    assert!(o.out.contains("battery"), "{}", o.out);
    refused(
        &["bench", "propeller", "--repeat", "1", "--set", "sim.duration_s=5"],
        b"",
        "--set: `bench propeller` times DTMB 4119's own blades and takes no parameter",
    );
    refused(
        &["bench", "propeller", "--hull", "wigley"],
        b"",
        "--hull is for `bench seakeeping` only, not `bench propeller`",
    );
    refused(
        &["bench", "startup", "--hull", "wigley"],
        b"",
        "--hull is for `bench seakeeping` only, not `bench startup`",
    );
    refused(
        &["bench", "seakeeping", "--set", "ship.hull.draft_m=5"],
        b"",
        "--set: `bench seakeeping` sets only the loading of --hull's hull (give --hull)",
    );
    // `ips`: the motor side read none of the generator's numbers (an infinite field voltage passed).
    refused(
        &["ips", "steady", "--side", "motor", "--vfd", "inf"],
        b"",
        "--vfd is for --side generator; --side motor does not read it",
    );
    refused(
        &["ips", "bode", "--side", "motor", "--omega", "400", "--points", "20"],
        b"",
        "--omega is for --side generator",
    );
    refused(
        &["ips", "linear", "--side", "generator", "--torque", "5"],
        b"",
        "--torque is for --side motor; --side generator does not read it",
    );
    let o = run(&["ips", "steady", "--side", "motor", "--torque", "80", "--vfd", "28.5"], b"");
    assert_eq!(o.code, Some(0), "{}", o.err);
}
