//! The scenario's parameters, declared once.
//!
//! Every section of the scenario is written with [`params!`]: one line per field gives its type,
//! default and a [`Decl`] (label, unit, allowed range or choices, one-line help, source of the
//! default, the page's form group, the per-unit base). From that one declaration come the struct
//! and its `Default`, the range checks and their messages, the wording of the reader's type
//! errors, `aes-sim params`, the wasm's `paramMeta()` (the page's form) and the README's scenario
//! table. Choices are enums written with [`choices!`], which give each value its label.
//!
//! Checks that relate fields (a hull's draft bounds its KG; the record interval is a whole number
//! of steps) are the section's [`CrossCheck`], written by hand beside the physics.
//!
//! To add a parameter: one line in its section's `params!`, then read it where the model needs it.

use crate::validate::{num, Validator};
use serde::Serialize;
use std::ops::RangeInclusive;

/// What a parameter's declaration says beside its name, type and default.
#[derive(Debug, Clone)]
pub struct Decl {
    /// Short name a student understands ("Sea state", "Bus capacitance").
    pub label: &'static str,
    /// Unit as the page shows it ("m", "kg m²", "-" for a pure number, "" for a choice or switch).
    pub unit: &'static str,
    /// One line: what it does.
    pub help: &'static str,
    /// Where the default comes from: a thesis table or equation, or "our choice: ...".
    pub source: &'static str,
    /// Allowed values of a number (both ends included); unbounded: any finite number.
    pub range: RangeInclusive<f64>,
    /// The part of `range` the page's control offers (a slider's ends, a number box's limits),
    /// where the model is of interest; the command line accepts all of `range`. Unbounded: the
    /// page offers all of `range`.
    pub span: RangeInclusive<f64>,
    /// What leaving it unset means (an optional field left out, or a number at 0 where 0 means
    /// "not set"), e.g. "the hull's own value"; empty: it is always set.
    pub empty: &'static str,
    /// Values of a text field with their labels (a choice of names that is not an enum).
    pub choices: &'static [(&'static str, &'static str)],
    /// The page's form group it is shown in ([`FORM_GROUPS`]); empty: the JSON editor only.
    pub group: &'static str,
    /// For a per-unit value: what 1 pu is.
    pub base: &'static str,
    /// Fields that may not be given together with this one (dotted paths).
    pub excludes: &'static [&'static str],
}

impl Decl {
    /// A declaration that says nothing (the start of every field's declaration).
    pub const NONE: Decl = Decl {
        label: "",
        unit: "",
        help: "",
        source: "",
        range: f64::NEG_INFINITY..=f64::INFINITY,
        span: f64::NEG_INFINITY..=f64::INFINITY,
        empty: "",
        choices: &[],
        group: "",
        base: "",
        excludes: &[],
    };

    fn bounded(&self) -> Option<(f64, f64)> {
        let (lo, hi) = (*self.range.start(), *self.range.end());
        (lo.is_finite() || hi.is_finite()).then_some((lo, hi))
    }
}

/// The page's form groups: (id, title), in the order the form shows them.
pub const FORM_GROUPS: [(&str, &str); 6] = [
    ("hull-loading", "Hull loading and propeller hub"),
    ("ship", "Ship: resistance and maneuvering"),
    ("plant", "Propulsion plant"),
    ("controllers", "Controllers"),
    ("sea", "Sea and seakeeping"),
    ("sim", "Simulation"),
];

/// One value of a choice.
#[derive(Debug, Clone, Serialize)]
pub struct Choice {
    pub value: &'static str,
    pub label: &'static str,
}

/// One parameter as `aes-sim params --json` and the page's `paramMeta()` list it.
#[derive(Debug, Clone, Serialize)]
pub struct ParamMeta {
    /// Dotted path in the scenario (`plant.motor.rated_power_w`; a command's fields are
    /// `commands.N.t_s`).
    pub path: String,
    /// "number", "integer", "switch", "choice", "text", "signal list", "pair" or "offsets".
    pub kind: &'static str,
    pub label: &'static str,
    pub unit: &'static str,
    pub help: &'static str,
    pub source: &'static str,
    /// The default as JSON (null: unset, see `empty`).
    pub default: serde_json::Value,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    /// The page control's [from, to] (`Decl::span`), inside [min, max].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub span: Option<[f64; 2]>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub choices: Vec<Choice>,
    #[serde(skip_serializing_if = "str::is_empty")]
    pub empty: &'static str,
    /// The value that means `empty`: null (left out) for an optional field, 0 for a number
    /// whose 0 means "not set".
    #[serde(skip_serializing_if = "str::is_empty")]
    pub empty_is: &'static str,
    #[serde(skip_serializing_if = "str::is_empty")]
    pub group: &'static str,
    #[serde(skip_serializing_if = "str::is_empty")]
    pub base: &'static str,
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub excludes: &'static [&'static str],
}

impl ParamMeta {
    fn new<T: Param>(
        path: &str,
        d: &Decl,
        default: serde_json::Value,
        choices: &[(&'static str, &'static str)],
    ) -> Self {
        let kind = T::KIND;
        let range = if matches!(kind, "number" | "integer" | "pair") { d.bounded() } else { None };
        ParamMeta {
            path: path.to_string(),
            kind,
            label: d.label,
            unit: d.unit,
            help: d.help,
            source: d.source,
            default,
            min: range.map(|r| r.0).filter(|x| x.is_finite()),
            max: range.map(|r| r.1).filter(|x| x.is_finite()),
            span: (d.span.start().is_finite() && d.span.end().is_finite()).then(|| [*d.span.start(), *d.span.end()]),
            choices: choices.iter().map(|&(value, label)| Choice { value, label }).collect(),
            empty: d.empty,
            empty_is: if d.empty.is_empty() { "" } else { T::EMPTY_IS },
            group: d.group,
            base: d.base,
            excludes: d.excludes,
        }
    }

    /// What the field accepts, in words: "must be a whole number from 2 to 6" (the range
    /// checks' and the reader's type errors' common wording).
    pub fn expects(&self) -> String {
        let unit = match self.unit {
            "" | "-" => String::new(),
            u => format!(" {u}"),
        };
        let range = match (self.min, self.max) {
            (Some(lo), Some(hi)) => format!(" from {} to {}{unit}", num(lo), num(hi)),
            (Some(lo), None) => format!(" of at least {}{unit}", num(lo)),
            (None, Some(hi)) => format!(" of at most {}{unit}", num(hi)),
            (None, None) => unit.clone(),
        };
        let empty = match self.empty_is {
            "" => String::new(),
            "0" => format!(", or 0 ({})", self.empty),
            _ => format!(", or left out ({})", self.empty),
        };
        let listed =
            |c: &[Choice]| c.iter().map(|c| format!("\"{}\" ({})", c.value, c.label)).collect::<Vec<_>>().join(", ");
        match self.kind {
            "number" => format!("must be a number{range}{empty}"),
            "integer" => format!("must be a whole number{range}{empty}"),
            "switch" => "must be true or false".into(),
            "choice" => format!("must be one of {}", listed(&self.choices)),
            "text" if !self.choices.is_empty() => format!("must be one of {}", listed(&self.choices)),
            "text" => "must be text in double quotes".into(),
            "signal list" => "must be a list of trace column names (see `aes-sim signals`)".into(),
            "pair" => format!("must be two numbers [port, starboard]{range}{empty}"),
            "offsets" => "must be the offsets as CSV text (station_index,x_m,z_m,half_breadth_m)".into(),
            _ => "must be an object of named fields ({...})".into(),
        }
    }

    /// The message of a value outside what is allowed: "Sea state must be a whole number from
    /// 2 to 6".
    pub fn message(&self) -> String {
        format!("{} {}", self.label, self.expects())
    }
}

/// A type a parameter can have: how it is listed and checked.
pub trait Param: Serialize + Sized {
    /// The kind of [`ParamMeta::kind`].
    const KIND: &'static str;
    /// The value that means "not set" where a declaration says what that means (`empty`).
    const EMPTY_IS: &'static str = "null";
    /// The values of a choice with their labels.
    fn choices() -> &'static [(&'static str, &'static str)] {
        &[]
    }
    /// Appends this field's listing (a section appends its fields').
    fn describe(path: &str, d: &Decl, default: &Self, out: &mut Vec<ParamMeta>) {
        let choices = if d.choices.is_empty() { Self::choices() } else { d.choices };
        out.push(ParamMeta::new::<Self>(path, d, serde_json::to_value(default).unwrap_or_default(), choices));
    }
    /// Checks the value against its declaration (a section checks its fields).
    fn check(&self, field: &str, d: &Decl, v: &mut Validator);
}

/// Fails `field` with the declaration's wording.
fn refuse<T: Param>(field: &str, d: &Decl, value: impl std::fmt::Display, v: &mut Validator) {
    let meta = ParamMeta::new::<T>(field, d, serde_json::Value::Null, T::choices());
    v.fail(field, value, meta.message());
}

fn in_range(x: f64, d: &Decl) -> bool {
    x.is_finite() && d.range.contains(&x)
}

impl Param for f64 {
    const KIND: &'static str = "number";
    const EMPTY_IS: &'static str = "0";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        let unset = !d.empty.is_empty() && *self == 0.0;
        if !unset && !in_range(*self, d) {
            refuse::<f64>(field, d, num(*self), v);
        }
    }
}

impl Param for Option<f64> {
    const KIND: &'static str = "number";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if let Some(x) = self.filter(|x| !in_range(*x, d)) {
            refuse::<Self>(field, d, num(x), v);
        }
    }
}

macro_rules! whole_number {
    ($($t:ty),*) => {$(
        impl Param for $t {
            const KIND: &'static str = "integer";
            fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
                if !in_range(*self as f64, d) {
                    refuse::<$t>(field, d, *self, v);
                }
            }
        }
    )*};
}
whole_number!(u32, u64, usize);

impl Param for bool {
    const KIND: &'static str = "switch";
    fn check(&self, _: &str, _: &Decl, _: &mut Validator) {}
}

impl Param for String {
    const KIND: &'static str = "text";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if !d.choices.is_empty() && !d.choices.iter().any(|(c, _)| c == self) {
            let meta = ParamMeta::new::<Self>(field, d, serde_json::Value::Null, d.choices);
            v.fail(field, format!("\"{}\"", crate::validate::shorten(self)), meta.message());
        }
    }
}

/// A list of trace columns (checked by the section, which knows the signals).
impl Param for Vec<String> {
    const KIND: &'static str = "signal list";
    fn check(&self, _: &str, _: &Decl, _: &mut Validator) {}
}

/// A value per shaft: port, starboard.
impl Param for Option<[f64; 2]> {
    const KIND: &'static str = "pair";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if let Some(pair) = self {
            for (i, x) in pair.iter().enumerate() {
                if !in_range(*x, d) {
                    refuse::<Self>(&format!("{field}.{i}"), d, num(*x), v);
                }
            }
        }
    }
}

/// A section that may be left out (its fields are listed under its path).
impl<T: Section> Param for Option<T> {
    const KIND: &'static str = "section";
    fn describe(path: &str, _: &Decl, default: &Self, out: &mut Vec<ParamMeta>) {
        T::describe_fields(path, default.as_ref().unwrap_or(&T::default()), out);
    }
    fn check(&self, field: &str, _: &Decl, v: &mut Validator) {
        if let Some(s) = self {
            v.section(field, |v| s.check_fields(v));
        }
    }
}

/// A list of records (the commands): the fields of one are listed under `path.N`.
impl<T: Section> Param for Vec<T> {
    const KIND: &'static str = "list";
    fn describe(path: &str, _: &Decl, _: &Self, out: &mut Vec<ParamMeta>) {
        T::describe_fields(&format!("{path}.N"), &T::default(), out);
    }
    fn check(&self, field: &str, _: &Decl, v: &mut Validator) {
        for (i, s) in self.iter().enumerate().take(crate::scenario::MAX_COMMANDS) {
            v.section(&format!("{field}.{i}"), |v| s.check_fields(v));
        }
    }
}

/// A section of the scenario written with [`params!`].
pub trait Section: Param + Default {
    /// Appends the listing of every field under `prefix`.
    fn describe_fields(prefix: &str, default: &Self, out: &mut Vec<ParamMeta>);
    /// Checks every field against its declaration, then the section's [`CrossCheck`].
    fn check_fields(&self, v: &mut Validator);
}

/// The checks of a section that relate its fields, written beside the physics. The default
/// checks nothing beyond the declarations.
pub trait CrossCheck {
    fn cross_check(&self, _v: &mut Validator) {}
}

/// Joins a prefix and a field name with a dot.
pub fn join(prefix: &str, field: &str) -> String {
    if prefix.is_empty() {
        field.to_string()
    } else {
        format!("{prefix}.{field}")
    }
}

/// Declares a section of the scenario: a struct whose every field has a type, a default and a
/// [`Decl`] (written as `{ label: "...", unit: "...", range: lo..=hi, ... }`; keys left out say
/// nothing). Attributes before a field (serde's, docs) are kept. A field whose type is another
/// section is written `=> section`.
#[macro_export]
macro_rules! params {
    (
        $(#[$sattr:meta])*
        pub struct $name:ident {
            $(
                $(#[$fattr:meta])*
                pub $field:ident : $ty:ty = $default:expr => { $($key:ident : $val:expr),* $(,)? }
            ),* $(,)?
        }
    ) => {
        $(#[$sattr])*
        pub struct $name {
            $(
                $(#[$fattr])*
                pub $field: $ty,
            )*
        }

        impl Default for $name {
            fn default() -> Self {
                $name { $($field: $default,)* }
            }
        }

        impl $crate::params::Param for $name {
            const KIND: &'static str = "section";
            fn describe(path: &str, _: &$crate::params::Decl, default: &Self, out: &mut Vec<$crate::params::ParamMeta>) {
                <Self as $crate::params::Section>::describe_fields(path, default, out);
            }
            fn check(&self, field: &str, _: &$crate::params::Decl, v: &mut $crate::validate::Validator) {
                v.section(field, |v| <Self as $crate::params::Section>::check_fields(self, v));
            }
        }

        impl $crate::params::Section for $name {
            fn describe_fields(prefix: &str, default: &Self, out: &mut Vec<$crate::params::ParamMeta>) {
                $(
                    <$ty as $crate::params::Param>::describe(
                        &$crate::params::join(prefix, stringify!($field)),
                        &$crate::params::Decl { $($key: $val,)* ..$crate::params::Decl::NONE },
                        &default.$field,
                        out,
                    );
                )*
            }
            fn check_fields(&self, v: &mut $crate::validate::Validator) {
                $(
                    $crate::params::Param::check(
                        &self.$field,
                        stringify!($field),
                        &$crate::params::Decl { $($key: $val,)* ..$crate::params::Decl::NONE },
                        v,
                    );
                )*
                $crate::params::CrossCheck::cross_check(self, v);
            }
        }
    };
}

/// Declares a choice: an enum whose every value has its JSON name and a label
/// (`Rk4 = "rk4", "RK4 (fourth order)"`). The first value is the default.
#[macro_export]
macro_rules! choices {
    (
        $(#[$eattr:meta])*
        pub enum $name:ident {
            $(#[$fattr:meta])* $first:ident = $first_json:literal, $first_label:literal
            $(, $(#[$vattr:meta])* $variant:ident = $json:literal, $label:literal)* $(,)?
        }
    ) => {
        $(#[$eattr])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
        pub enum $name {
            $(#[$fattr])*
            #[default]
            #[serde(rename = $first_json)]
            $first,
            $(
                $(#[$vattr])*
                #[serde(rename = $json)]
                $variant,
            )*
        }

        impl $crate::params::Param for $name {
            const KIND: &'static str = "choice";
            fn choices() -> &'static [(&'static str, &'static str)] {
                &[($first_json, $first_label) $(, ($json, $label))*]
            }
            fn check(&self, _: &str, _: &$crate::params::Decl, _: &mut $crate::validate::Validator) {}
        }
    };
}

/// Every parameter of the scenario, in the order of its JSON.
pub fn all() -> Vec<ParamMeta> {
    let mut out = Vec::new();
    let d = crate::Scenario::default();
    <crate::Scenario as Section>::describe_fields("", &d, &mut out);
    out
}

/// The parameter at a dotted path (`commands.3.t_s` finds `commands.N.t_s`; a pair's element
/// `ship.hull.shaft_y_m.1` finds the pair).
pub fn find(path: &str) -> Option<ParamMeta> {
    static ALL: std::sync::OnceLock<Vec<ParamMeta>> = std::sync::OnceLock::new();
    let all = ALL.get_or_init(all);
    let generic = generic(path);
    all.iter()
        .find(|m| m.path == generic || m.path == path)
        .or_else(|| {
            let parent = generic.rsplit_once('.')?.0;
            all.iter().find(|m| m.path == parent && m.kind == "pair")
        })
        .cloned()
}

/// The parameter whose path is nearest to `path` by edit distance (at most 3 edits), for "did you
/// mean" hints.
pub fn closest(path: &str) -> Option<String> {
    let generic = generic(path);
    let (parent, name) = generic.rsplit_once('.').unwrap_or(("", generic.as_str()));
    all()
        .into_iter()
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

/// The README's scenario table: every parameter with its unit, default, allowed values and
/// label, section by section.
pub fn markdown_table() -> String {
    let mut s = String::from("| parameter | unit | default | allowed | what it is |\n|---|---|---|---|---|\n");
    for m in all() {
        let default = match &m.default {
            serde_json::Value::Null => format!("({})", m.empty),
            serde_json::Value::String(t) if t.len() > 24 => "(text)".into(),
            serde_json::Value::String(t) => format!("`\"{t}\"`"),
            v => format!("`{}`", crate::validate::shorten(&v.to_string())),
        };
        let allowed = match m.kind {
            "choice" | "text" if !m.choices.is_empty() => {
                m.choices.iter().map(|c| format!("`{}`", c.value)).collect::<Vec<_>>().join(", ")
            }
            "number" | "integer" | "pair" => match (m.min, m.max) {
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
        let what = if m.source.is_empty() { m.label.to_string() } else { format!("{} ({})", m.label, m.source) };
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
    use crate::Scenario;

    /// Every leaf of the default scenario's JSON is declared, and every declaration is a leaf
    /// of it (or an optional field left out): no parameter escapes the registry.
    #[test]
    fn the_registry_lists_every_field_once() {
        let json = serde_json::to_value(Scenario::default()).unwrap();
        let mut leaves = Vec::new();
        fn walk(v: &serde_json::Value, p: &str, out: &mut Vec<String>) {
            match v {
                serde_json::Value::Object(m) if p != "commands.N" || !m.is_empty() => {
                    for (k, x) in m {
                        walk(x, &join(p, k), out)
                    }
                }
                serde_json::Value::Array(items) if p == "commands" => walk(&items[0], "commands.N", out),
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
            // hull's offsets, a single-rate run's sub-steps.
            let left_out = m.default.is_null()
                || m.path.starts_with("ship.hull.bilge_keels")
                || ["ship.hull.offsets_csv", "sim.hull_substeps"].contains(&m.path.as_str());
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
        let mut checked = 0;
        for m in all() {
            let (Some(lo), Some(hi)) = (m.min, m.max) else { continue };
            if !matches!(m.kind, "number" | "integer") || m.path.starts_with("commands") {
                continue;
            }
            let outside = if m.kind == "integer" { hi + 1.0 } else { hi + (hi - lo).abs().max(1.0) };
            let e = base.with_override(&m.path, &num(outside)).unwrap_err();
            assert!(e.0.iter().any(|f| f.path == m.path && f.message == m.message()), "{} = {outside}: {e}", m.path);
            checked += 1;
        }
        assert!(checked > 120, "{checked}");
        let e = base.with_override("commands.0.speed_kn", "41").unwrap_err();
        assert_eq!(
            e.to_string(),
            "commands.0.speed_kn = 41: Ordered speed must be a number from 0 to 40 kn, or left out (keep the previous order)"
        );
        // An order's 0 is not "unset": a heading rate of 0 is refused.
        let e = base.with_override("commands.0.heading_rate_deg_s", "0").unwrap_err();
        assert_eq!(e.0[0].path, "commands.0.heading_rate_deg_s", "{e}");
        let e = base.with_override("plant.dc_link.brake_resistor_ohm", "0.001").unwrap_err();
        assert_eq!(e.0[0].message, "Brake resistor must be a number from 0.01 to 10000 Ω, or 0 (none)");
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
