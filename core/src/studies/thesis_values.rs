//! The thesis' numbers we compare with (core/data/thesis_values.csv), each once, by key: the
//! validation report, the tests and the page (the wasm's `thesisValues`) read them here instead of
//! copying them.
//!
//! ```text
//! thesis_values::value("table_5_8.monte_carlo.mean_s")   // Some(23.67)
//! thesis_values::get("table_5_8.monte_carlo.skewness")   // printed "1.00", unit "-", where, what
//! ```
//!
//! A missing key is `None`, never a panic: the report turns it into a failing row that says
//! "missing reference".

use serde::Serialize;
use std::sync::OnceLock;

/// The file, embedded.
pub const CSV: &str = include_str!("../../data/thesis_values.csv");

/// Where the file lives in the repository (for messages).
pub const PATH: &str = "core/data/thesis_values.csv";

/// Table 5.7's keys at each speed \[kn\]: the generator, power electronics, motor and propeller
/// efficiencies, in that order (the validation report and tests/startup.rs compare with them).
pub const TABLE_5_7: [(f64, [&str; 4]); 3] = [
    (
        20.0,
        [
            "table_5_7.generator.20kn",
            "table_5_7.power_electronics.20kn",
            "table_5_7.motor.20kn",
            "table_5_7.propeller.20kn",
        ],
    ),
    (
        25.0,
        [
            "table_5_7.generator.25kn",
            "table_5_7.power_electronics.25kn",
            "table_5_7.motor.25kn",
            "table_5_7.propeller.25kn",
        ],
    ),
    (
        30.0,
        [
            "table_5_7.generator.30kn",
            "table_5_7.power_electronics.30kn",
            "table_5_7.motor.30kn",
            "table_5_7.propeller.30kn",
        ],
    ),
];

/// The file's header row.
const HEADER: [&str; 6] = ["key", "value", "unit", "where", "what", "note"];

/// One number the thesis prints.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ThesisValue {
    /// The name it is looked up by, e.g. `table_5_8.monte_carlo.mean_s`.
    pub key: String,
    /// The number.
    pub value: f64,
    /// The number as the thesis prints it ("1.00", "16.400").
    pub printed: String,
    /// The printed unit ("-" for none; "%" for a percentage).
    pub unit: String,
    /// The thesis' table, figure or text and its section.
    #[serde(rename = "where")]
    pub source: String,
    /// What the number is.
    pub what: String,
    /// How it is printed, when that needs saying (often empty).
    pub note: String,
}

/// Splits one CSV line into fields: a field may be quoted ("a, b"), with "" for a quote inside.
fn fields(line: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut chars = line.chars().peekable();
    let mut quoted = false;
    let mut was_quoted = false;
    while let Some(c) = chars.next() {
        if quoted {
            match c {
                '"' if chars.peek() == Some(&'"') => {
                    chars.next();
                    cur.push('"');
                }
                '"' => quoted = false,
                _ => cur.push(c),
            }
        } else {
            match c {
                ',' => {
                    out.push(std::mem::take(&mut cur));
                    was_quoted = false;
                }
                '"' if cur.is_empty() && !was_quoted => {
                    quoted = true;
                    was_quoted = true;
                }
                '"' => return Err("a quote inside an unquoted field".into()),
                _ if was_quoted => return Err("text after a closing quote".into()),
                _ => cur.push(c),
            }
        }
    }
    if quoted {
        return Err("an unclosed quote".into());
    }
    out.push(cur);
    Ok(out)
}

/// Reads the file's text: comment lines (`#`) and blank lines skipped, then the header, then one
/// row per number. Refuses a wrong header, a row of the wrong width, an empty or malformed key, a
/// duplicate key, a value that is not a finite number and an empty unit, where or what.
pub fn parse(text: &str) -> Result<Vec<ThesisValue>, String> {
    let mut rows: Vec<ThesisValue> = Vec::new();
    let mut header = false;
    for (i, line) in text.lines().enumerate() {
        let at = |e: String| format!("{PATH} line {}: {e}", i + 1);
        let line = line.trim_end_matches('\r');
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let f = fields(line).map_err(at)?;
        if !header {
            if f != HEADER {
                return Err(at(format!("the header must be {}", HEADER.join(","))));
            }
            header = true;
            continue;
        }
        let [key, printed, unit, source, what, note]: [String; 6] =
            f.try_into().map_err(|f: Vec<String>| at(format!("{} fields, not {}", f.len(), HEADER.len())))?;
        let key_ok = !key.is_empty()
            && key.contains('.')
            && key.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.')
            && !key.starts_with('.')
            && !key.ends_with('.');
        if !key_ok {
            return Err(at(format!("'{key}' is not a key (lower case, digits, '_' and '.')")));
        }
        if rows.iter().any(|r| r.key == key) {
            return Err(at(format!("'{key}' appears twice")));
        }
        let value: f64 = printed.trim().parse().map_err(|_| at(format!("{key}: '{printed}' is not a number")))?;
        if !value.is_finite() || printed.trim() != printed {
            return Err(at(format!("{key}: '{printed}' is not a finite number as printed")));
        }
        for (name, v) in [("unit", &unit), ("where", &source), ("what", &what)] {
            if v.trim().is_empty() {
                return Err(at(format!("{key}: empty {name}")));
            }
        }
        rows.push(ThesisValue { key, value, printed, unit, source, what, note });
    }
    if !header {
        return Err(format!("{PATH}: no header"));
    }
    Ok(rows)
}

/// Every number of the file, in its order, read once; the error when the file does not parse.
pub fn all() -> Result<&'static [ThesisValue], &'static str> {
    static ROWS: OnceLock<Result<Vec<ThesisValue>, String>> = OnceLock::new();
    match ROWS.get_or_init(|| parse(CSV)) {
        Ok(rows) => Ok(rows),
        Err(e) => Err(e),
    }
}

/// The number under `key`, with its unit, where and what; None when the file lacks it (or does
/// not parse).
pub fn get(key: &str) -> Option<&'static ThesisValue> {
    all().ok()?.iter().find(|r| r.key == key)
}

/// The number under `key`.
pub fn value(key: &str) -> Option<f64> {
    get(key).map(|r| r.value)
}

/// The number under `key` as the thesis prints it.
pub fn printed(key: &str) -> Option<&'static str> {
    get(key).map(|r| r.printed.as_str())
}

/// The keys of `keys` the file lacks.
pub fn missing<'a>(keys: &[&'a str]) -> Vec<&'a str> {
    keys.iter().copied().filter(|k| get(k).is_none()).collect()
}

/// Every row as JSON: `[{"key", "value", "printed", "unit", "where", "what", "note"}, ...]` (the
/// page's references); `[]` if the file does not parse (its test fails first).
pub fn to_json() -> String {
    serde_json::to_string(all().unwrap_or(&[])).unwrap_or_else(|_| "[]".into())
}

/// Strings quoted in `text` (with ', " or `) that have the form of a key of this file: the
/// prefixes `table_` and `ch_` followed by a digit, lower case, digits, '_' and '.'. The tests
/// use it to check that every key a source file names exists. (Every piece between two quote
/// characters is tried, so an apostrophe or an escaped quote in the text loses no key.)
pub fn quoted_keys(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for quote in ['\'', '"', '`'] {
        for piece in text.split(quote) {
            let prefixed = ["table_", "ch_"]
                .iter()
                .any(|p| piece.strip_prefix(p).is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_digit())));
            let is_key = prefixed
                && piece.contains('.')
                && piece.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.')
                && !piece.ends_with('.');
            if is_key && !out.contains(&piece.to_string()) {
                out.push(piece.to_string());
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_file_parses_with_unique_keys() {
        let rows = all().unwrap();
        assert!(rows.len() >= 60, "{} rows", rows.len());
        for (i, r) in rows.iter().enumerate() {
            assert!(rows[..i].iter().all(|q| q.key != r.key), "{} twice", r.key);
        }
    }

    /// A few numbers as the thesis prints them (shared/spec/thesis.md).
    #[test]
    fn values_are_the_printed_ones() {
        for (key, v, printed, unit) in [
            ("table_5_8.monte_carlo.mean_s", 23.67, "23.67", "s"),
            ("table_5_8.monte_carlo.skewness", 1.0, "1.00", "-"),
            ("table_5_8.monte_carlo.mode_s", 0.0217, "0.0217", "s"),
            ("table_5_8.rice.kurtosis", 9.0, "9", "-"),
            ("ch_5_4_2.rate_per_s", 0.044, "0.044", "1/s"),
            ("ch_5_4_2.level_z_m", 3.88, "3.88", "m"),
            ("ch_5_4_1.excess_energy_mean_mj", 94.1, "94.1", "MJ"),
            ("ch_5_4_1.excess_energy_std_mj", 33.3, "33.3", "MJ"),
            ("table_4_1.steady_state.v_rect_v", 743.17, "743.17", "V"),
            ("table_4_2.steady_state.v_s_mag_v", 411.91, "411.91", "V"),
            ("table_5_7.propeller.25kn", 0.703, "0.703", "-"),
            ("table_2_4.ss6.significant_height_ft", 16.4, "16.400", "ft"),
            ("ch_5_3_2.im_power_turn", 160.0, "160", "%"),
        ] {
            let r = get(key).unwrap_or_else(|| panic!("{key} missing"));
            assert_eq!((r.value, r.printed.as_str(), r.unit.as_str()), (v, printed, unit), "{key}");
        }
        assert_eq!(get("table_5_8.monte_carlo.mean_s").unwrap().source, "Table 5.8, Monte Carlo row (sec. 5.4.2)");
    }

    /// Table 5.7's keys are in the file, each once (the validation report's other keys are
    /// checked in aes-validation).
    #[test]
    fn table_5_7_keys_exist() {
        let keys: Vec<&str> = TABLE_5_7.iter().flat_map(|(_, k)| *k).collect();
        assert_eq!(keys.len(), 12);
        assert_eq!(missing(&keys), Vec::<&str>::new());
        for (i, k) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(k), "{k} twice");
        }
    }

    #[test]
    fn a_missing_key_is_none() {
        assert_eq!(get("table_9_9.nothing"), None);
        assert_eq!(value("table_9_9.nothing"), None);
        assert_eq!(missing(&["table_9_9.nothing", "table_5_8.rice.mean_s"]), ["table_9_9.nothing"]);
    }

    #[test]
    fn bad_files_are_refused() {
        let head = "# c\nkey,value,unit,where,what,note\n";
        for (body, says) in [
            ("a.b,1,s,w,x,\na.b,2,s,w,x,\n", "twice"),
            ("a.b,one,s,w,x,\n", "not a number"),
            ("a.b,NaN,s,w,x,\n", "finite"),
            ("a.b,1,s,w,x\n", "5 fields"),
            ("A.b,1,s,w,x,\n", "not a key"),
            ("ab,1,s,w,x,\n", "not a key"),
            ("a.b,1,,w,x,\n", "empty unit"),
            ("a.b,1,s,\"w, v,x,\n", "unclosed"),
            ("a.b,1,s,\"w\"v,x,\n", "after a closing quote"),
        ] {
            let e = parse(&format!("{head}{body}")).unwrap_err();
            assert!(e.contains(says), "{body}: {e}");
        }
        assert!(parse("key,value\n").unwrap_err().contains("header"));
        let ok = parse(&format!("{head}a.b,1.50,s,\"Table 1, row \"\"x\"\"\",y,\n")).unwrap();
        assert_eq!((ok[0].value, ok[0].printed.as_str(), ok[0].source.as_str()), (1.5, "1.50", "Table 1, row \"x\""));
    }

    #[test]
    fn json_carries_every_row() {
        let v: serde_json::Value = serde_json::from_str(&to_json()).unwrap();
        let rows = v.as_array().unwrap();
        assert_eq!(rows.len(), all().unwrap().len());
        let r = rows.iter().find(|r| r["key"] == "table_5_8.monte_carlo.skewness").unwrap();
        assert_eq!((r["printed"].as_str(), r["value"].as_f64()), (Some("1.00"), Some(1.0)));
        assert_eq!(r["where"], "Table 5.8, Monte Carlo row (sec. 5.4.2)");
    }
}
