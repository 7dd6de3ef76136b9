//! The parameter registry reaches the page and the book (docs/): the page names no parameter the
//! registry lacks, and the book's scenario table is the registry's.

use aes_core::scenario::registry;
use std::path::Path;

/// Quoted strings in a text that look like scenario parameter paths (`'sea.sea_state'`).
fn quoted_paths(text: &str) -> Vec<String> {
    // The scenario's sections, from the registry itself (a new section is covered as it lands).
    let mut sections: Vec<String> =
        registry::all().iter().map(|m| format!("{}.", m.path.split('.').next().unwrap_or_default())).collect();
    sections.sort();
    sections.dedup();
    let mut out = Vec::new();
    for quote in ['\'', '"', '`'] {
        for (i, piece) in text.split(quote).enumerate() {
            let is_path = i % 2 == 1
                && sections.iter().any(|s| piece.starts_with(s.as_str()))
                && piece.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.')
                && !piece.ends_with('.');
            if is_path {
                out.push(piece.to_string());
            }
        }
    }
    out
}

/// Every parameter path written in www/ (the studies' key fields, compare buttons, links) is
/// declared. A renamed or removed parameter fails here, not in a classroom.
#[test]
fn the_page_names_only_declared_parameters() {
    let www = Path::new(env!("CARGO_MANIFEST_DIR")).join("../www");
    // www/js and its folders (the live views' modules are in www/js/live).
    let (mut files, mut dirs) = (vec![www.join("index.html")], vec![www.join("js")]);
    while let Some(dir) = dirs.pop() {
        for path in std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()) {
            if path.is_dir() {
                dirs.push(path)
            } else {
                files.push(path)
            }
        }
    }
    let mut seen = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for p in quoted_paths(&text) {
            assert!(registry::find(&p).is_some(), "{} names {p}, which no parameter declares", f.display());
            seen += 1;
        }
    }
    // The studies' key fields and compare buttons name over 30.
    assert!(seen > 30, "{seen} paths found: the scan is broken");
}

/// The scanner finds a path and would catch a stale one.
#[test]
fn a_stale_path_is_caught() {
    let found = quoted_paths("params: ['sea.sea_state', 'sea.wave_height_m'], other: 'sea state'");
    assert_eq!(found, ["sea.sea_state", "sea.wave_height_m"]);
    assert!(registry::find("sea.wave_height_m").is_none());
}

/// A page of the book (docs/, relative to it).
fn book_page(page: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs").join(page))
        .unwrap_or_else(|e| panic!("docs/{page}: {e}"))
}

/// A book page's text between its `<!-- NAME:begin -->` and `<!-- NAME:end -->` markers.
fn page_between(page: &str, name: &str) -> String {
    let text = book_page(page);
    let (begin, end) = (format!("<!-- {name}:begin -->\n"), format!("<!-- {name}:end -->"));
    let a = text.find(&begin).unwrap_or_else(|| panic!("docs/{page} has no {name}:begin marker")) + begin.len();
    let b = text[a..].find(&end).unwrap_or_else(|| panic!("docs/{page} has no {name}:end marker")) + a;
    text[a..b].to_string()
}

/// The book's scenario table is `aes-sim params --markdown` (regenerate with `./build.sh docs`).
#[test]
fn the_book_table_is_the_registry() {
    assert!(
        page_between("reference/parameters.md", "params") == registry::markdown_table(),
        "docs/reference/parameters.md is stale: run ./build.sh docs"
    );
}

/// The book's list of health checks is `aes-sim health --markdown` (regenerate with
/// `./build.sh docs`).
#[test]
fn the_book_health_checks_are_cores() {
    assert!(
        page_between("reference/health.md", "health") == aes_core::sim::health::markdown(),
        "docs/reference/health.md is stale: run ./build.sh docs"
    );
}

/// The command line's page states issue 34's limits as core's constants hold them (a changed
/// constant fails here until docs/cli.md says so).
#[test]
fn the_book_states_the_limits_as_core_holds_them() {
    use aes_core::sea::seakeeping::tables;
    use aes_core::studies::montecarlo;
    let text = book_page("cli.md").split_whitespace().collect::<Vec<_>>().join(" ");
    let thousands = |n: u64| {
        let s = n.to_string();
        let mut out = String::new();
        for (i, c) in s.chars().enumerate() {
            if i > 0 && (s.len() - i) % 3 == 0 {
                out.push(',');
            }
            out.push(c);
        }
        out
    };
    for want in [
        format!("problems are listed up to {}", aes_core::checks::MAX_ERRORS_SHOWN),
        format!("cut to {} characters", aes_core::checks::MAX_VALUE_CHARS),
        format!("at most {} MB", montecarlo::MAX_STUDY_BYTES / 1e6),
        format!("at most {:e}", montecarlo::MAX_STUDY_WORK),
        format!("grid has at most {} points", thousands(tables::MAX_RAO_POINTS as u64)),
        format!("at most {:.1e} units of work", tables::MAX_RAO_WORK),
        format!(
            "RAO parts within {:e} and mean forces within {:e}",
            tables::MAX_RAO_MAGNITUDE,
            tables::MAX_DRIFT_MAGNITUDE
        ),
        format!("takes at most {} frequencies", aes_core::studies::fuel::MAX_OMEGAS),
        format!("`bench --repeat` 1 to {}", aes_core::scenario::MAX_BENCH_REPEAT),
        format!("`validate --trials` 1 to {}", thousands(aes_validation::MAX_TRIALS)),
    ] {
        assert!(text.contains(&want), "docs/cli.md does not say: {want}");
    }
}

/// Scenario files written before the time step, its method and the sample periods moved into
/// `stepping` (two presets as `aes-sim preset` printed them then) read as those presets do now,
/// but for what the presets changed since: the head-seas description, and the RAO grid's default
/// speeds (6 then, 8 now; a file keeps the grid it names); an old name given beside its new one
/// is refused; `--set` takes the old name too.
#[test]
fn scenario_files_of_the_old_format_read_as_before() {
    use aes_core::scenario::presets::preset;
    use aes_core::Scenario;
    for (name, old) in [
        ("head-seas-ss6", include_str!("data/head-seas-ss6.v1.json")),
        ("startup", include_str!("data/startup.v1.json")),
    ] {
        assert!(old.contains("\"sample_period_s\"") && !old.contains("\"stepping\""), "{name}: not the old format");
        let mut read = Scenario::from_json(old).unwrap();
        let now = preset(name).unwrap();
        assert_eq!(read.seakeeping.grid.n_speed, 6, "{name}: the file's grid");
        read.seakeeping.grid.n_speed = now.seakeeping.grid.n_speed;
        read.description.clone_from(&now.description);
        assert_eq!(read, now, "{name}");
    }
    let e = Scenario::from_json(r#"{"sim": {"dt_s": 0.002}, "stepping": {"dt_s": 0.001}}"#).unwrap_err();
    assert_eq!(
        e.to_string(),
        "sim.dt_s = 0.002: is the old name of stepping.dt_s, which is given too: give stepping.dt_s only"
    );
    let s = preset("startup").unwrap().with_override("sim.dt_s", "0.0025").unwrap();
    assert_eq!(s.stepping.dt_s, 0.0025);
}

/// Every key of the thesis' numbers (core/data/thesis_values.csv) that the page, the tests, the
/// command line's tests and the wasm's tests name exists: a renamed or removed key fails here, before a slow test or a
/// browser meets it. (The validation report's keys are checked in aes-validation, Table 5.7's
/// in aes-core's thesis_values.)
#[test]
fn the_page_and_the_tests_name_only_known_thesis_values() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for (dir, ext) in [("www/js", "js"), ("tests", "rs"), ("cli/tests", "rs"), ("web/tests", "rs")] {
        for e in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = e.unwrap().path();
            if path.extension().is_some_and(|x| x == ext) && !path.ends_with("registry.rs") {
                files.push(path);
            }
        }
    }
    let mut seen = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for key in aes_core::studies::thesis_values::quoted_keys(&text) {
            assert!(
                aes_core::studies::thesis_values::get(&key).is_some(),
                "{} names {key}, which {} lacks",
                f.display(),
                aes_core::studies::thesis_values::PATH
            );
            seen += 1;
        }
    }
    // Table 5.8 and the excess energy on the page, Tables 4.1 and 4.2 and Fig. 5-1 in the tests.
    assert!(seen >= 25, "{seen} keys found: the scan is broken");
}

/// The scanner finds a key and would catch a stale one.
#[test]
fn a_stale_thesis_key_is_caught() {
    let found = aes_core::studies::thesis_values::quoted_keys(
        "const k = ['table_5_8.rice.mean_s', 'table_5_8.rice.average_s', 'table 5.8'];",
    );
    assert_eq!(found, ["table_5_8.rice.mean_s", "table_5_8.rice.average_s"]);
    assert!(aes_core::studies::thesis_values::get("table_5_8.rice.average_s").is_none());
}

/// The stability tab's controls and their steps name inputs the IPS tool declares (the page
/// takes their labels, ranges and values from `ipsMeta()`), and index.html writes no number for
/// them.
#[test]
fn the_stability_tab_takes_its_inputs_from_the_declarations() {
    let declared: Vec<String> = aes_core::studies::ips::study::meta().into_iter().map(|m| m.path).collect();
    let www = Path::new(env!("CARGO_MANIFEST_DIR")).join("../www");
    let read = |f: &str| std::fs::read_to_string(www.join(f)).unwrap();
    let mut named = 0;
    for (file, start) in [("js/stability.js", "const CONTROLS = {"), ("js/config.js", "steps: {")] {
        let text = read(file);
        let body = text.split(start).nth(1).and_then(|b| b.split('}').next()).expect(start);
        for key in body.split(',').filter_map(|kv| kv.split(':').next()).map(str::trim) {
            assert!(declared.iter().any(|d| d == key), "{file} names {key}, which the IPS tool does not declare");
            named += 1;
        }
    }
    assert_eq!(named, 6, "the scan is broken");
    let html = read("index.html");
    for id in ["ips-torque", "ips-load", "ips-vfd"] {
        let tag = html.split(&format!("id=\"{id}\"")).nth(1).and_then(|t| t.split('>').next()).expect(id);
        assert!(!tag.chars().any(|c| c.is_ascii_digit()), "index.html: #{id} carries a number: {tag}");
        for text in html.split(&format!("for=\"{id}\">")).skip(1).filter_map(|t| t.split('<').next()) {
            assert!(!text.chars().any(|c| c.is_ascii_digit()), "index.html: #{id}'s label or output says {text}");
        }
    }
}

/// Every field a model choice leaves unused (`registry::UNUSED_WITH`) changes nothing in a turn
/// run under that choice, bit for bit, and the run's warnings name it; a field the choice does
/// use (its own rudder area) does change the run, so the comparison can fail.
#[test]
fn fields_a_model_leaves_unused_change_nothing_and_are_named() {
    use aes_core::sim::run;
    let all = registry::all();
    for u in &registry::UNUSED_WITH {
        let mut base = aes_core::scenario::presets::preset("turn-90").unwrap();
        base.sim.duration_s = 40.0;
        let base = base.with_override(u.choice, u.value).unwrap();
        let reference = run(&base).unwrap();
        let yaw = reference.trace.get(aes_core::signals::Signal::YawRateDegS);
        assert!(yaw.iter().any(|r| r.abs() > 0.1), "{}: the ship does not turn", u.value);
        assert!(reference.summary.warnings.iter().all(|w| !w.contains("not used")), "{:?}", reference.summary.warnings);
        // Each plain field, and the first field of each section.
        let paths = u.fields.iter().map(|f| match f.strip_suffix('.') {
            Some(_) => all.iter().find(|m| m.path.starts_with(f)).unwrap().path.clone(),
            None => f.to_string(),
        });
        for path in paths {
            let m = registry::find(&path).unwrap();
            let value = match &m.default {
                serde_json::Value::Bool(b) => (!b).to_string(),
                serde_json::Value::Number(x) => (0.9 * x.as_f64().unwrap()).to_string(),
                _ => "3.0".to_string(),
            };
            let changed = base.with_override(&path, &value).unwrap();
            let r = run(&changed).unwrap();
            assert_eq!(r.trace.columns, reference.trace.columns, "{path} = {value} changed the run");
            let w = r.summary.warnings.join("\n");
            assert!(
                w.contains(&format!("{} = \"{}\": ", u.choice, u.value)) && w.contains(&format!("{path} = ")),
                "{path}: {w}"
            );
            assert!(m.unused_with.contains(&format!("{} = \"{}\"", u.choice, u.value)), "{path}");
        }
    }
    // The own hull's rudders do move the run under the own hull's forces.
    let mut sc = aes_core::scenario::presets::preset("turn-90").unwrap();
    sc.sim.duration_s = 40.0;
    let used = sc.with_override("ship.hull.rudder_area_m2", "3.0").unwrap();
    assert_ne!(run(&used).unwrap().trace.columns, run(&sc).unwrap().trace.columns);
}
