//! The registry of the scenario's parameters: every declaration of `params!` in scenario order
//! (`aes-sim params`, the wasm's `paramMeta()`), look-ups by dotted path, "did you mean" hints,
//! fields that exclude each other, and the book's table (docs/reference/parameters.md).

use crate::checks::num;
use crate::params::{ParamMeta, Section};

/// Every parameter of the scenario, in the order of its JSON.
pub fn all() -> Vec<ParamMeta> {
    list().to_vec()
}

/// The same list, made once: every scenario read and write consults it (conflicts, excluded
/// fields), and making it serializes the whole default scenario.
fn list() -> &'static [ParamMeta] {
    static LIST: std::sync::OnceLock<Vec<ParamMeta>> = std::sync::OnceLock::new();
    LIST.get_or_init(|| {
        let mut out = Vec::new();
        <crate::Scenario as Section>::describe_fields("", &crate::Scenario::default(), &mut out);
        for m in &mut out {
            m.unused_with = unused_with(&m.path).map(|u| format!("{} = \"{}\"", u.choice, u.value)).collect();
        }
        out
    })
}

/// Fields a choice of model leaves unused: under `choice = value`, the fields `fields` (a path
/// ending in '.' is a whole section) change nothing: they belong to `owner`, and the choice reads
/// `instead`.
pub struct Unused {
    pub choice: &'static str,
    pub value: &'static str,
    pub fields: &'static [&'static str],
    pub owner: &'static str,
    pub instead: &'static str,
}

/// Every such choice (the plant's `HullModel::Own` reads neither the Table 2.3 coefficients nor
/// the `rudder` section's area and slopes; `HullModel::Maneuvering` reads neither the own hull's
/// factors nor the hull's rudders). `tests/registry.rs` runs each field changed under its choice
/// and finds the run unchanged.
pub const UNUSED_WITH: [Unused; 2] = [
    Unused {
        choice: "hull.forces",
        value: "own_hull",
        fields: &[
            "rudder.area_m2",
            "rudder.lift_slope",
            "rudder.drag_slope",
            "hull.abkowitz.",
            "hull.linearization_speed_kn",
            "hull.symmetric_hull",
            "hull.handover_low_kn",
            "hull.handover_high_kn",
        ],
        owner: "the Table 2.3 forces",
        instead: "the hull's own forces take the rudders of ship.hull (rudder_area_m2, rudder_span_m) and the \
                  factors of hull.own",
    },
    Unused {
        choice: "hull.forces",
        value: "table_2_3",
        fields: &["hull.own.", "ship.hull.rudder_area_m2", "ship.hull.rudder_span_m"],
        owner: "the hull's own forces",
        instead: "the Table 2.3 forces take the rudder section's area and slopes",
    },
];

/// The choices under which the field at `path` is unused.
fn unused_with(path: &str) -> impl Iterator<Item = &'static Unused> + '_ {
    UNUSED_WITH
        .iter()
        .filter(move |u| u.fields.iter().any(|f| if f.ends_with('.') { path.starts_with(f) } else { path == *f }))
}

/// The run's warnings for fields set away from their defaults under a choice of model that does
/// not use them, one per choice, in a scenario's JSON: "hull.forces = \"own_hull\": rudder.area_m2
/// = 500.0 set here is not used (...)".
pub fn ignored(root: &serde_json::Value) -> Vec<String> {
    let mut out = Vec::new();
    for u in &UNUSED_WITH {
        if at(root, u.choice).and_then(|v| v.as_str()) != Some(u.value) {
            continue;
        }
        let set: Vec<String> = list()
            .iter()
            .filter(|m| unused_with(&m.path).any(|x| std::ptr::eq(x, u)))
            .filter_map(|m| {
                let v = at(root, &m.path).filter(|v| is_set(m, Some(v)) && **v != m.default)?;
                Some(format!("{} = {}", m.path, crate::checks::shorten(&v.to_string())))
            })
            .collect();
        if !set.is_empty() {
            out.push(format!(
                "{} = \"{}\": {} set here {} not used ({} to {}; {})",
                u.choice,
                u.value,
                set.join(", "),
                if set.len() == 1 { "is" } else { "are" },
                if set.len() == 1 { "it belongs" } else { "they belong" },
                u.owner,
                u.instead
            ));
        }
    }
    out
}

/// The parameter at a dotted path (`commands.3.t_s` finds `commands.N.t_s`; a pair's element
/// `ship.hull.shaft_y_m.1` finds the pair).
pub fn find(path: &str) -> Option<ParamMeta> {
    let all = list();
    let generic = generic(path);
    all.iter()
        .find(|m| m.path == generic || m.path == path)
        .or_else(|| {
            let parent = generic.rsplit_once('.')?.0;
            all.iter().find(|m| m.path == parent && m.kind == "pair")
        })
        .cloned()
}

/// The value at a dotted path of a scenario's JSON.
fn at<'a>(root: &'a serde_json::Value, path: &str) -> Option<&'a serde_json::Value> {
    path.split('.').try_fold(root, |v, k| v.get(k))
}

/// Whether a declared field is given a value that is not its "unset" (null, or 0 where 0 means
/// unset).
fn is_set(m: &ParamMeta, v: Option<&serde_json::Value>) -> bool {
    match v {
        None | Some(serde_json::Value::Null) => false,
        Some(x) => !(m.empty_is == "0" && x.as_f64() == Some(0.0)),
    }
}

/// Fields given together that exclude each other (`sea.h_sig_m` with `sea.sea_state`), in a
/// scenario's JSON as read: one error each, at the excluded field. Refused, never resolved
/// silently.
pub fn conflicts(root: &serde_json::Value) -> Vec<crate::checks::FieldError> {
    let mut out: Vec<crate::checks::FieldError> = Vec::new();
    for m in list().iter().filter(|m| !m.excludes.is_empty() && is_set(m, at(root, &m.path))) {
        for ex in m.excludes {
            let Some(v) = at(root, ex) else { continue };
            if out.iter().any(|e| e.path == *ex) {
                continue;
            }
            let label = find(ex).map(|e| e.label).unwrap_or("");
            out.push(crate::checks::FieldError {
                path: ex.to_string(),
                value: crate::checks::shorten(&v.to_string()),
                message: format!("{label} cannot be given together with {} ({}): leave one out", m.path, m.label),
            });
        }
    }
    out
}

/// Takes out of a scenario's JSON the fields that a set field excludes (what the scenario writes:
/// a sea of its own height and frequency carries no sea state), so that it reads back.
pub fn drop_excluded(root: &mut serde_json::Value) {
    let drop: Vec<&'static str> =
        list().iter().filter(|m| is_set(m, at(root, &m.path))).flat_map(|m| m.excludes.iter().copied()).collect();
    for ex in drop {
        if let Some((parent, key)) = ex.rsplit_once('.') {
            if let Some(serde_json::Value::Object(map)) = parent.split('.').try_fold(&mut *root, |v, k| v.get_mut(k)) {
                map.remove(key);
            }
        }
    }
}

/// The parameter whose path is nearest to `path` by edit distance (at most 3 edits), for "did you
/// mean" hints.
pub fn closest(path: &str) -> Option<String> {
    let generic = generic(path);
    let (parent, name) = generic.rsplit_once('.').unwrap_or(("", generic.as_str()));
    list()
        .iter()
        .filter_map(|m| {
            let (p, n) = m.path.rsplit_once('.').unwrap_or(("", m.path.as_str()));
            (p == parent).then(|| (edit_distance(n, name), m.path.clone()))
        })
        .filter(|(d, _)| *d <= 3)
        .min_by_key(|(d, _)| *d)
        .map(|(_, p)| p)
}

/// A path with its list indices as `N` (`commands.3.t_s` is `commands.N.t_s`).
fn generic(path: &str) -> String {
    path.split('.')
        .enumerate()
        .map(|(i, p)| if i > 0 && !p.is_empty() && p.chars().all(|c| c.is_ascii_digit()) { "N" } else { p })
        .collect::<Vec<_>>()
        .join(".")
}

/// Levenshtein distance of two short names.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// The book's scenario table (docs/reference/parameters.md): every parameter with its unit, default, allowed values and
/// label, section by section.
pub fn markdown_table() -> String {
    let mut s = String::from("| parameter | unit | default | allowed | what it is |\n|---|---|---|---|---|\n");
    for m in all() {
        let default = match &m.default {
            serde_json::Value::Null => format!("({})", m.empty),
            serde_json::Value::String(t) if t.len() > 24 => "(text)".into(),
            serde_json::Value::String(t) => format!("`\"{t}\"`"),
            v => format!("`{}`", crate::checks::shorten(&v.to_string())),
        };
        let allowed = match m.kind {
            "choice" | "text" if !m.choices.is_empty() => {
                m.choices.iter().map(|c| format!("`{}`", c.value)).collect::<Vec<_>>().join(", ")
            }
            "number" | "integer" | "pair" | "set list" => match (m.min, m.max) {
                (Some(lo), Some(hi)) => format!("{} to {}", num(lo), num(hi)),
                (Some(lo), None) => format!("from {}", num(lo)),
                (None, Some(hi)) => format!("to {}", num(hi)),
                _ if m.path.starts_with("ship.hull.") => "checked against the hull".into(),
                _ => "any".into(),
            },
            "switch" => "true, false".into(),
            k => k.into(),
        };
        let unit = if m.unit.is_empty() { "" } else { m.unit };
        let mut what = if m.source.is_empty() { m.label.to_string() } else { format!("{} ({})", m.label, m.source) };
        if !m.unused_with.is_empty() {
            what.push_str(&format!("; not used with {}", m.unused_with.join(" or ")));
        }
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            m.path,
            unit,
            default,
            allowed,
            what.replace('|', "\\|")
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{join, FORM_GROUPS};
    use crate::Scenario;

    /// Every leaf of the default scenario's JSON is declared, and every declaration is a leaf
    /// of it (or an optional field left out): no parameter escapes the registry.
    #[test]
    fn the_registry_lists_every_field_once() {
        let json = serde_json::to_value(Scenario::default()).unwrap();
        let mut leaves = Vec::new();
        fn walk(v: &serde_json::Value, p: &str, out: &mut Vec<String>) {
            match v {
                serde_json::Value::Object(m) if !p.ends_with(".N") || !m.is_empty() => {
                    for (k, x) in m {
                        walk(x, &join(p, k), out)
                    }
                }
                // A list of records (the commands, operability's points and criteria).
                serde_json::Value::Array(items) if items.first().is_some_and(|x| x.is_object()) => {
                    walk(&items[0], &format!("{p}.N"), out)
                }
                _ => out.push(p.to_string()),
            }
        }
        walk(&json, "", &mut leaves);
        let all = all();
        let paths: Vec<&str> = all.iter().map(|m| m.path.as_str()).collect();
        for leaf in &leaves {
            assert!(paths.contains(&leaf.as_str()), "{leaf} is not declared");
        }
        for m in &all {
            let listed = leaves.contains(&m.path);
            // Left out of the JSON at their defaults: optional fields, the bilge keels, a custom
            // hull's offsets, a single-rate run's sub-steps, an order that is no crash stop.
            let left_out = m.default.is_null()
                || m.path.starts_with("ship.hull.bilge_keels")
                || ["ship.hull.offsets_csv", "stepping.hull_substeps", "commands.N.crash_stop"]
                    .contains(&m.path.as_str())
                || m.path.starts_with("propeller.geometry.");
            assert!(listed || left_out, "{} is not in the scenario", m.path);
            assert_eq!(paths.iter().filter(|p| **p == m.path).count(), 1, "{} twice", m.path);
        }
        assert!(all.len() > 190, "{} parameters", all.len());
    }

    /// Every declaration has a label and a help line; a number has a unit ("-" for none) and a
    /// default inside its range; a choice's default is one of its choices.
    #[test]
    fn every_declaration_is_complete() {
        for m in all() {
            assert!(!m.label.is_empty() && !m.help.is_empty(), "{}: label or help missing", m.path);
            assert!(m.help.ends_with('.') || m.help.ends_with("..."), "{}: help is a sentence", m.path);
            if matches!(m.kind, "number" | "integer" | "pair") {
                assert!(!m.unit.is_empty(), "{}: no unit", m.path);
                if let Some(x) = m.default.as_f64() {
                    let unset = !m.empty.is_empty() && x == 0.0;
                    assert!(
                        unset || (m.min.unwrap_or(f64::MIN) <= x && x <= m.max.unwrap_or(f64::MAX)),
                        "{}: default {x} outside its range",
                        m.path
                    );
                }
            }
            if m.kind == "choice" {
                let d = m.default.as_str().unwrap();
                assert!(m.choices.iter().any(|c| c.value == d), "{}: default {d} is no choice", m.path);
            }
            if !m.group.is_empty() {
                assert!(FORM_GROUPS.iter().any(|(id, _)| *id == m.group), "{}: no form group {}", m.path, m.group);
            }
        }
    }

    /// A unit in a name (`_kn`, `_rpm`, `_m2`) and the declared unit agree.
    #[test]
    fn units_agree_with_names() {
        let suffixes = [
            ("_kg_m2", "kg m²"),
            ("_kg_m3", "kg/m³"),
            ("_rad_s", "rad/s"),
            ("_m_s", "m/s"),
            ("_deg_s", "deg/s"),
            ("_rpm_per_s", "rpm/s"),
            ("_rpm_per_kn_s", "rpm/(kn s)"),
            ("_rpm_per_kn", "rpm/kn"),
            ("_per_s", "1/s"),
            ("_nm_s", "N m s/rad"),
            ("_m2", "m²"),
            ("_kg", "kg"),
            ("_kn", "kn"),
            ("_rpm", "rpm"),
            ("_deg", "deg"),
            ("_hz", "Hz"),
            ("_ohm", "Ω"),
            ("_pu", "pu"),
            ("_nm", "N m"),
            ("_w", "W"),
            ("_v", "V"),
            ("_f", "F"),
            ("_h", "H"),
            ("_s", "s"),
            ("_m", "m"),
        ];
        for m in all() {
            let name = m.path.rsplit('.').next().unwrap();
            // Table 2.3's coefficients are named for their symbols (xudot_minus_m).
            if m.path.starts_with("hull.abkowitz.") {
                continue;
            }
            if let Some((_, unit)) = suffixes.iter().find(|(s, _)| name.ends_with(s)) {
                assert_eq!(m.unit, *unit, "{}", m.path);
            }
        }
    }

    /// Each bounded number refused just outside its range, with the declaration's message at its
    /// own path; the same value inside the range accepted by that field.
    #[test]
    fn ranges_are_enforced_with_their_messages() {
        let base = Scenario::default();
        // The blade geometry is an optional section: its fields are checked where it is given.
        let mut with_blades = Scenario::default();
        with_blades.propeller.geometry = Some(
            crate::plant::propeller_geometry::GeometrySpec::from_csv(
                include_str!("../../data/dtmb4119_geometry.csv"),
                3,
                0.2,
            )
            .unwrap(),
        );
        let mut checked = 0;
        for m in all() {
            let (Some(lo), Some(hi)) = (m.min, m.max) else { continue };
            if !matches!(m.kind, "number" | "integer") || m.path.starts_with("commands") {
                continue;
            }
            let outside = if m.kind == "integer" { hi + 1.0 } else { hi + (hi - lo).abs().max(1.0) };
            // A list's field at its first item.
            let path = m.path.replace(".N.", ".0.");
            let base = if path.starts_with("propeller.geometry.") { &with_blades } else { &base };
            let e = base.with_override(&path, &num(outside)).unwrap_err();
            assert!(e.0.iter().any(|f| f.path == path && f.message == m.message()), "{path} = {outside}: {e}");
            checked += 1;
        }
        assert!(checked > 120, "{checked}");
        let e = base.with_override("commands.0.speed_kn", "41").unwrap_err();
        assert_eq!(
            e.to_string(),
            "commands.0.speed_kn = 41: Ordered speed must be a number from -15 to 40 kn, or left out (keep the previous order)"
        );
        // An order's 0 is not "unset": a heading rate of 0 is refused.
        let e = base.with_override("commands.0.heading_rate_deg_s", "0").unwrap_err();
        assert_eq!(e.0[0].path, "commands.0.heading_rate_deg_s", "{e}");
        let e = base.with_override("plant.dc_link.brake_resistor_ohm", "0.001").unwrap_err();
        assert_eq!(e.0[0].message, "Brake resistor must be a number from 0.01 to 10000 Ω, or 0 (none)");
    }

    /// A sea state given with a height of one's own is refused; the scenario written with a
    /// height of its own leaves the sea state out and reads back as it was.
    #[test]
    fn fields_that_exclude_each_other_are_refused_and_never_written_together() {
        let e = Scenario::from_json(r#"{"sea": {"sea_state": 4, "h_sig_m": 3, "omega_n_rad_s": 0.8}}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "sea.sea_state = 4: Sea state cannot be given together with sea.h_sig_m (Significant wave height H_1/3): leave one out"
        );
        // Either alone is fine, and 0 (unset) excludes nothing.
        Scenario::from_json(r#"{"sea": {"h_sig_m": 3, "omega_n_rad_s": 0.8}}"#).unwrap();
        Scenario::from_json(r#"{"sea": {"sea_state": 4, "h_sig_m": 0, "omega_n_rad_s": 0}}"#).unwrap();
        let own = Scenario::default().with_overrides(&[("sea.h_sig_m", "3"), ("sea.omega_n_rad_s", "0.8")]).unwrap();
        let text = own.to_json();
        assert!(!text.contains("sea_state"), "{text}");
        assert_eq!(Scenario::from_json(&text).unwrap(), own);
        // Setting the sea state again over a scenario with a spectrum of its own is refused.
        assert!(own.with_override("sea.sea_state", "5").is_err());
    }

    #[test]
    fn paths_with_indices_find_their_declaration() {
        assert_eq!(find("commands.7.heading_deg").unwrap().path, "commands.N.heading_deg");
        assert_eq!(find("ship.hull.shaft_y_m.1").unwrap().path, "ship.hull.shaft_y_m");
        assert!(find("ship.nope").is_none());
        assert_eq!(closest("plant.motor.rated_powr_w").as_deref(), Some("plant.motor.rated_power_w"));
        assert_eq!(closest("sim.zzzzzzzzzz"), None);
    }
}
