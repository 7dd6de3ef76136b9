//! The scenario as a file: reading JSON (bounded in size and depth, no duplicate keys, type
//! errors and unknown names worded from the registry, fields that exclude each other refused),
//! writing it, and `--set` overrides by dotted path.

use crate::scenario::{FieldError, Scenario, ScenarioError};
use std::fmt;

impl Scenario {
    /// Parses a scenario from JSON, naming the field of any type error or unknown field, then
    /// validates every range.
    pub fn from_json(text: &str) -> Result<Scenario, ScenarioError> {
        let value: serde_json::Value = parse_bounded(text)?;
        Scenario::from_value(value)
    }

    /// Like [`Scenario::from_json`], from an already parsed JSON value.
    pub fn from_value(mut value: serde_json::Value) -> Result<Scenario, ScenarioError> {
        // Earlier files and links name some parameters by their old paths: read as they were.
        migrate(&mut value)?;
        // Fields that moved into `ship.hull` (issue 15): say where, not just "unknown field".
        let moved: Vec<FieldError> = MOVED_FIELDS
            .iter()
            .filter_map(|(section, field, to)| {
                let v = value.get(section)?.get(field)?;
                Some(FieldError {
                    path: format!("{section}.{field}"),
                    value: crate::checks::shorten(&v.to_string()),
                    message: format!("this field is gone: {to}"),
                })
            })
            .collect();
        if !moved.is_empty() {
            return Err(ScenarioError(moved));
        }
        // serde would fill a section from an array, field by field in order: refused, so that a
        // scenario means what its names say.
        static SHAPE: std::sync::OnceLock<serde_json::Value> = std::sync::OnceLock::new();
        let shape = SHAPE.get_or_init(|| serde_json::to_value(Scenario::default()).unwrap_or_default());
        let mut arrays = Vec::new();
        arrays_for_objects(&value, shape, "", &mut arrays);
        if !arrays.is_empty() {
            return Err(ScenarioError(arrays));
        }
        let conflicts = crate::scenario::registry::conflicts(&value);
        if !conflicts.is_empty() {
            return Err(ScenarioError(conflicts));
        }
        // From a borrow, so that an error can quote the offending value (serde names only the path).
        let sc: Scenario = serde_path_to_error::deserialize(&value).map_err(|e| {
            let path = dotted(e.path());
            let found = value_at(&value, e.path()).map(|v| crate::checks::shorten(&v.to_string()));
            let message = reader_message(&path, &e.into_inner().to_string());
            ScenarioError(vec![FieldError {
                path: if path.is_empty() { "(top level)".into() } else { crate::checks::shorten(&path) },
                value: found.unwrap_or_default(),
                message,
            }])
        })?;
        sc.validate()?;
        Ok(sc)
    }

    /// The scenario as pretty JSON (without the fields that a set field excludes, so that it
    /// reads back).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(&self.to_value()).unwrap_or_default()
    }

    /// The scenario as a JSON value, as `to_json` writes it.
    pub fn to_value(&self) -> serde_json::Value {
        let mut v = serde_json::to_value(self).unwrap_or_default();
        crate::scenario::registry::drop_excluded(&mut v);
        v
    }

    /// Sets one parameter by dotted path (`sim.duration_s`, `commands.0.speed_kn`) to a value
    /// given as text (JSON; bare words are taken as strings), then re-validates.
    pub fn with_override(&self, path: &str, value_text: &str) -> Result<Scenario, ScenarioError> {
        self.with_overrides(&[(path, value_text)])
    }

    /// `with_overrides` for the command line's `--set PATH=VALUE` flags (and the Python package's
    /// `Scenario.set`), refused in the flags' words: every flag's path is named (the error's field
    /// may be another that they move together), the first few of a long list.
    pub fn with_set_flags(&self, sets: &[(&str, &str)]) -> Result<Scenario, String> {
        const NAMED: usize = 4;
        self.with_overrides(sets).map_err(|e| {
            let mut paths: Vec<String> = sets.iter().take(NAMED).map(|(p, _)| crate::checks::shorten(p)).collect();
            if sets.len() > NAMED {
                paths.push(format!("and {} more", sets.len() - NAMED));
            }
            format!("--set {}: {e}", paths.join(", "))
        })
    }

    /// The same for several (path, value) pairs at once, checked together: fields that must
    /// change together (sea.h_sig_m with sea.omega_n_rad_s) can, in either order.
    pub fn with_overrides(&self, sets: &[(&str, &str)]) -> Result<Scenario, ScenarioError> {
        if sets.is_empty() {
            return Ok(self.clone());
        }
        // An old name sets the parameter at its new path.
        let sets: Vec<(&str, &str)> = sets.iter().map(|&(p, v)| (renamed(p), v)).collect();
        let sets = sets.as_slice();
        let mut root = self.to_value();
        // A field set here replaces the ones it excludes in the base (a height of one's own, the
        // sea state); given both here, both stay, and the reader refuses them.
        for (path, _) in sets {
            if let Some(m) = crate::scenario::registry::find(path) {
                for ex in m.excludes {
                    if !sets.iter().any(|(p, _)| p == ex) {
                        if let Some((parent, key)) = ex.rsplit_once('.') {
                            let node = parent.split('.').try_fold(&mut root, |v, k| v.get_mut(k));
                            if let Some(serde_json::Value::Object(map)) = node {
                                map.remove(key);
                            }
                        }
                    }
                }
            }
        }
        for (path, value_text) in sets {
            set_path(&mut root, path, value_text)?;
        }
        Scenario::from_value(root)
    }
}

/// Parameters renamed since earlier scenario files and share links: (old path, new path). The
/// time step, its method and the sample periods were in three sections; they are `stepping`'s.
pub const RENAMED: [(&str, &str); 5] = [
    ("sim.dt_s", "stepping.dt_s"),
    ("sim.integrator", "stepping.integrator"),
    ("sim.hull_substeps", "stepping.hull_substeps"),
    ("controllers.sample_period_s", "stepping.controller_sample_s"),
    ("seakeeping.sample_period_s", "stepping.sea_sample_s"),
];

/// A path with an old name (`sim.dt_s`) as its new one (`stepping.dt_s`); others as they are.
pub fn renamed(path: &str) -> &str {
    RENAMED.iter().find(|(old, _)| *old == path).map_or(path, |(_, new)| new)
}

/// Moves every field of `root` (a scenario, or the part of one that a link carries) that has an
/// old name to its new path; refuses a field given under both names.
pub fn migrate(root: &mut serde_json::Value) -> Result<(), ScenarioError> {
    let mut errors = Vec::new();
    for (old, new) in RENAMED {
        let (old_parent, old_key) = old.rsplit_once('.').unwrap_or(("", old));
        let Some(serde_json::Value::Object(map)) = old_parent.split('.').try_fold(&mut *root, |v, k| v.get_mut(k))
        else {
            continue;
        };
        let Some(value) = map.remove(old_key) else { continue };
        let (new_parent, new_key) = new.rsplit_once('.').unwrap_or(("", new));
        let serde_json::Value::Object(top) = &mut *root else { continue };
        let section = top.entry(new_parent.to_string()).or_insert_with(|| serde_json::json!({}));
        match section {
            serde_json::Value::Object(sec) if !sec.contains_key(new_key) => {
                sec.insert(new_key.to_string(), value);
            }
            serde_json::Value::Object(_) => errors.push(FieldError {
                path: old.to_string(),
                value: crate::checks::shorten(&value.to_string()),
                message: format!("is the old name of {new}, which is given too: give {new} only"),
            }),
            // A `stepping` that is no object: the reader names it.
            _ => {}
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(ScenarioError(errors))
    }
}

/// Where `input` has an array for a section that `schema` (the default scenario's JSON) has as an
/// object: one error each, named by path (the root is "scenario").
fn arrays_for_objects(input: &serde_json::Value, schema: &serde_json::Value, path: &str, out: &mut Vec<FieldError>) {
    let serde_json::Value::Object(fields) = schema else { return };
    match input {
        serde_json::Value::Array(_) => out.push(FieldError {
            path: if path.is_empty() { "scenario".into() } else { path.into() },
            value: crate::checks::shorten(&input.to_string()),
            message: "must be a JSON object of named fields ({...}), not an array".into(),
        }),
        serde_json::Value::Object(map) => {
            for (k, v) in map {
                if let Some(sub) = fields.get(k) {
                    let p = if path.is_empty() { k.clone() } else { format!("{path}.{k}") };
                    arrays_for_objects(v, sub, &p, out);
                }
            }
        }
        _ => {}
    }
}

/// Writes `value_text` (JSON, or else a string) at dotted `path` of a scenario's JSON.
fn set_path(root: &mut serde_json::Value, path: &str, value_text: &str) -> Result<(), ScenarioError> {
    if path.is_empty() {
        return Err(one_error(
            "(empty path)",
            value_text,
            &"a setting needs a parameter's path before its '=' (`aes-sim params` lists them)",
        ));
    }
    let new_value: serde_json::Value =
        serde_json::from_str(value_text).unwrap_or_else(|_| serde_json::Value::String(value_text.to_string()));
    // A path the registry declares may pass through an optional section that is unset here
    // (ship.hull.bilge_keels): the section is made, and the reader then asks for what it lacks.
    let declared = crate::scenario::registry::find(path).is_some();
    let mut node = root;
    let parts: Vec<&str> = path.split('.').collect();
    for (i, part) in parts.iter().enumerate() {
        let last = i + 1 == parts.len();
        let here = parts[..=i].join(".");
        if declared && node.is_null() {
            *node = serde_json::Value::Object(serde_json::Map::new());
        }
        node = match node {
            serde_json::Value::Object(map) => {
                if !map.contains_key(*part) {
                    if last || declared {
                        // Optional fields (e.g. commands.N.heading_deg) are absent when unset.
                        map.insert(part.to_string(), serde_json::Value::Null);
                    } else if crate::scenario::registry::find(&here)
                        .is_some_and(|m| !["section", "pair", "list"].contains(&m.kind))
                    {
                        // An unset optional value, not a section: named as the deepest real path.
                        return Err(one_error(
                            path,
                            value_text,
                            &format!(
                                "{here} is a single value, not a section: it has no field {}",
                                parts[i + 1..].join(".")
                            ),
                        ));
                    } else {
                        return Err(unknown_path(&here, value_text));
                    }
                }
                map.get_mut(*part).ok_or_else(|| unknown_path(&here, value_text))?
            }
            serde_json::Value::Array(items) => {
                let idx: usize = part.parse().map_err(|_| unknown_path(&here, value_text))?;
                let len = items.len();
                items.get_mut(idx).ok_or_else(|| {
                    one_error(&here, value_text, &format!("index out of range (0 to {})", len.saturating_sub(1)))
                })?
            }
            // A value, not a section: the deepest real path is the one before this part.
            _ => {
                let parent = parts[..i].join(".");
                return Err(one_error(
                    path,
                    value_text,
                    &format!("{parent} is a single value, not a section: it has no field {}", parts[i..].join(".")),
                ));
            }
        };
    }
    *node = new_value;
    Ok(())
}

/// Fields of earlier scenario files that the hull now owns: (section, field, where it went).
const MOVED_FIELDS: [(&str, &str, &str); 6] = [
    ("ship", "mass_kg", "the mass is the hull's displacement (ship.hull.draft_m, or ship.hull.mass_kg to set it)"),
    ("ship", "added_mass_kg", "give ship.added_mass_fraction (of the hull's displacement)"),
    ("ship", "length_m", "the length is the hull's Lpp (ship.hull; as_printed.table_5_ship for the thesis' 180 m)"),
    ("seakeeping", "hub_depth_m", "the hubs' place is the hull's: ship.hull.hub_above_base_m (h0 = draft - it)"),
    ("seakeeping", "prop_x_aft_m", "the propellers' place is the hull's: ship.hull.propeller_x_m (from the AP)"),
    ("rudder", "x_p_m", "the rudder's place is the hull's: ship.hull.rudder_x_m (from the AP)"),
];

/// A deserializer's error path as the dotted path the checks use (`commands.1.speed_kn`).
fn dotted(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let parts: Vec<String> = path
        .iter()
        .filter_map(|s| match s {
            Segment::Map { key } => Some(key.clone()),
            Segment::Seq { index } => Some(index.to_string()),
            Segment::Enum { variant } => Some(variant.clone()),
            Segment::Unknown => None,
        })
        .collect();
    parts.join(".")
}

/// The reader's error in the registry's words: what the field at `path` accepts (its label and
/// range or choices), or, for a name that is no parameter, the closest one. serde's own wording
/// ("invalid type: floating point `2.5`, expected u32") never reaches a user.
fn reader_message(path: &str, serde_says: &str) -> String {
    if serde_says.starts_with("unknown field") {
        let (parent, _) = path.rsplit_once('.').unwrap_or(("", path));
        let near = crate::scenario::registry::closest(path);
        let hint = near.map(|n| format!("; did you mean {n}?")).unwrap_or_default();
        let section = if parent.is_empty() { "the scenario".to_string() } else { parent.to_string() };
        return format!("no such parameter in {section}{hint} (`aes-sim params` lists them all)");
    }
    if serde_says.starts_with("missing field") {
        if let Some(m) =
            serde_says.split('`').nth(1).and_then(|f| crate::scenario::registry::find(&format!("{path}.{f}")))
        {
            return format!("needs {} ({}), which {}", m.path, m.label, m.expects());
        }
    }
    if serde_says.starts_with("duplicate key") || serde_says.starts_with("nesting deeper") {
        return crate::checks::shorten_message(serde_says);
    }
    // The field, or the choice or pair that a deeper path ({"midpoint": 5}) sits in.
    let mut at = Some(path);
    while let Some(p) = at {
        if let Some(m) = crate::scenario::registry::find(p).filter(|m| m.kind != "section" && m.kind != "list") {
            return m.message();
        }
        at = p.rsplit_once('.').map(|(parent, _)| parent);
    }
    match crate::scenario::registry::find(path) {
        _ if path == "commands" => "must be a list of orders, e.g. [{\"t_s\": 0, \"speed_kn\": 25}]".into(),
        _ if path.is_empty() => "a scenario must be a JSON object of named sections ({...})".into(),
        _ => "must be a JSON object of named fields ({...})".into(),
    }
}

/// The value at a deserializer's error path in the JSON it read, if it is there.
fn value_at<'a>(root: &'a serde_json::Value, path: &serde_path_to_error::Path) -> Option<&'a serde_json::Value> {
    use serde_path_to_error::Segment;
    path.iter().try_fold(root, |node, segment| match segment {
        Segment::Map { key } => node.get(key.as_str()),
        Segment::Seq { index } => node.get(*index),
        // An enum's variant given as a map key ({"midpoint": ...}): the value under it.
        Segment::Enum { variant } => node.get(variant.as_str()).or(Some(node)),
        Segment::Unknown => None,
    })
}

fn one_error(path: &str, value: &str, msg: &dyn fmt::Display) -> ScenarioError {
    use crate::checks::{shorten, shorten_message};
    ScenarioError(vec![FieldError {
        path: shorten(path),
        value: shorten(value),
        message: shorten_message(&msg.to_string()),
    }])
}

fn unknown_path(path: &str, value: &str) -> ScenarioError {
    one_error(path, value, &"no such parameter (see `aes-sim preset startup` for the names)")
}

/// Largest scenario text accepted \[bytes\].
pub const MAX_SCENARIO_BYTES: usize = 4 << 20;
/// Deepest nesting accepted in a scenario file.
pub const MAX_SCENARIO_DEPTH: usize = 32;

/// Parses JSON after bounding its size and nesting, so hostile input cannot exhaust memory or stack,
/// and refuses duplicate keys (serde_json keeps the last one silently, which hides typos). Errors
/// name the location: the dotted path, and serde_json's line and column.
pub fn parse_bounded(text: &str) -> Result<serde_json::Value, ScenarioError> {
    if text.len() > MAX_SCENARIO_BYTES {
        return Err(one_error(
            "(file)",
            &format!("{} bytes", text.len()),
            &format!("a scenario may be at most {MAX_SCENARIO_BYTES} bytes"),
        ));
    }
    use serde::de::DeserializeSeed;
    let mut de = serde_json::Deserializer::from_str(text);
    let value = Strict { path: String::new(), depth: 0 }
        .deserialize(&mut de)
        .and_then(|v| de.end().map(|()| v))
        .map_err(|e| one_error("(file)", "", &format!("not valid JSON: {e}")))?;
    Ok(value)
}

/// A JSON value read with a depth limit and no duplicate keys; `path` is where it sits.
struct Strict {
    path: String,
    depth: usize,
}

impl Strict {
    fn child(&self, key: &str) -> Strict {
        let path = if self.path.is_empty() { key.to_string() } else { format!("{}.{key}", self.path) };
        Strict { path, depth: self.depth + 1 }
    }
    fn enter<E: serde::de::Error>(&self) -> Result<(), E> {
        if self.depth >= MAX_SCENARIO_DEPTH {
            let at = if self.path.is_empty() { "(top level)" } else { self.path.as_str() };
            return Err(E::custom(format!(
                "nesting deeper than {MAX_SCENARIO_DEPTH} levels at {}",
                crate::checks::shorten(at)
            )));
        }
        Ok(())
    }
}

impl<'de> serde::de::DeserializeSeed<'de> for Strict {
    type Value = serde_json::Value;
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<serde_json::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> serde::de::Visitor<'de> for Strict {
    type Value = serde_json::Value;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, b: bool) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::Bool(b))
    }
    fn visit_i64<E>(self, x: i64) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::Number(x.into()))
    }
    fn visit_u64<E>(self, x: u64) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::Number(x.into()))
    }
    fn visit_f64<E>(self, x: f64) -> Result<serde_json::Value, E> {
        // As serde_json's own Value does.
        Ok(serde_json::Number::from_f64(x).map_or(serde_json::Value::Null, serde_json::Value::Number))
    }
    fn visit_str<E>(self, x: &str) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::String(x.to_string()))
    }
    fn visit_string<E>(self, x: String) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::String(x))
    }
    fn visit_unit<E>(self) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::Null)
    }
    fn visit_none<E>(self) -> Result<serde_json::Value, E> {
        Ok(serde_json::Value::Null)
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<serde_json::Value, A::Error> {
        self.enter()?;
        let mut items = Vec::new();
        while let Some(v) = seq.next_element_seed(self.child(&items.len().to_string()))? {
            items.push(v);
        }
        Ok(serde_json::Value::Array(items))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<serde_json::Value, A::Error> {
        self.enter()?;
        let mut out = serde_json::Map::new();
        while let Some(key) = map.next_key::<String>()? {
            let child = self.child(&key);
            if out.contains_key(&key) {
                return Err(serde::de::Error::custom(format!(
                    "duplicate key {} (each key may appear once)",
                    crate::checks::shorten(&child.path)
                )));
            }
            let v = map.next_value_seed(child)?;
            out.insert(key, v);
        }
        Ok(serde_json::Value::Object(out))
    }
}
