//! The parameter registry reaches the page and the README: the page names no parameter the
//! registry lacks, and the README's scenario table is the registry's.

use aes_core::params;
use std::path::Path;

/// Quoted strings in a text that look like scenario parameter paths (`'sea.sea_state'`).
fn quoted_paths(text: &str) -> Vec<String> {
    const SECTIONS: [&str; 13] = [
        "ship.",
        "hull.",
        "rudder.",
        "propeller.",
        "plant.",
        "controllers.",
        "commands.",
        "initial.",
        "sim.",
        "sea.",
        "seakeeping.",
        "monte_carlo.",
        "as_printed.",
    ];
    let mut out = Vec::new();
    for quote in ['\'', '"', '`'] {
        for (i, piece) in text.split(quote).enumerate() {
            let is_path = i % 2 == 1
                && SECTIONS.iter().any(|s| piece.starts_with(s))
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
    let mut files: Vec<_> = std::fs::read_dir(www.join("js")).unwrap().map(|e| e.unwrap().path()).collect();
    files.push(www.join("index.html"));
    let mut seen = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for p in quoted_paths(&text) {
            assert!(params::find(&p).is_some(), "{} names {p}, which no parameter declares", f.display());
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
    assert!(params::find("sea.wave_height_m").is_none());
}

/// The README's scenario table is `aes-sim params --markdown` (regenerate with `./build.sh docs`).
#[test]
fn the_readme_table_is_the_registry() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../README.md")).unwrap();
    let (begin, end) = ("<!-- params:begin -->\n", "<!-- params:end -->");
    let a = readme.find(begin).expect("README has no params:begin marker") + begin.len();
    let b = readme[a..].find(end).expect("README has no params:end marker") + a;
    assert!(readme[a..b] == params::markdown_table(), "README's scenario table is stale: run ./build.sh docs");
}

/// The stability tab's controls and their steps name inputs the IPS tool declares (the page
/// takes their labels, ranges and values from `ipsMeta()`), and index.html writes no number for
/// them.
#[test]
fn the_stability_tab_takes_its_inputs_from_the_declarations() {
    let declared: Vec<String> = aes_core::stability::study::meta().into_iter().map(|m| m.path).collect();
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
