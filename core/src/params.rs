//! The scenario's parameters, declared once.
//!
//! Every section of the scenario is written with [`params!`](crate::params!): one line per field gives its type,
//! default and a [`Decl`] (label, unit, allowed range or choices, one-line help, source of the
//! default, the page's form group, the per-unit base). From that one declaration come the struct
//! and its `Default`, the range checks and their messages, the wording of the reader's type
//! errors, `aes-sim params`, the wasm's `paramMeta()` (the page's form) and the book's scenario
//! table. Choices are enums written with [`choices!`](crate::choices!), which give each value its label.
//!
//! Checks that relate fields (a hull's draft bounds its KG; the record interval is a whole number
//! of steps) are the section's [`CrossCheck`], written by hand beside the physics.
//!
//! To add a parameter: one line in its section's `params!`, then read it where the model needs it.
//! The whole scenario's list, look-ups by path and the checks on raw JSON are `crate::scenario::registry`'s.

use crate::checks::{num, Validator};
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
    /// "number", "integer", "switch", "choice", "text", "signal list", "pair", "set list" or "offsets".
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
    /// The model choices under which the field is not used, as `path = "value"`
    /// (`registry::UNUSED_WITH` owns them); set away from its default there, a run warns.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub unused_with: Vec<String>,
}

impl ParamMeta {
    fn new<T: Param>(
        path: &str,
        d: &Decl,
        default: serde_json::Value,
        choices: &[(&'static str, &'static str)],
    ) -> Self {
        let kind = T::KIND;
        let range = if matches!(kind, "number" | "integer" | "pair" | "set list") { d.bounded() } else { None };
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
            unused_with: Vec::new(),
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
            "set list" => format!("must be a list of set numbers{range}{empty}"),
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

/// A whole number that may be left out (its declaration says what that means).
impl Param for Option<u32> {
    const KIND: &'static str = "integer";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if let Some(x) = self.filter(|x| !in_range(*x as f64, d)) {
            refuse::<Self>(field, d, x, v);
        }
    }
}

impl Param for bool {
    const KIND: &'static str = "switch";
    fn check(&self, _: &str, _: &Decl, _: &mut Validator) {}
}

impl Param for String {
    const KIND: &'static str = "text";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if !d.choices.is_empty() && !d.choices.iter().any(|(c, _)| c == self) {
            let meta = ParamMeta::new::<Self>(field, d, serde_json::Value::Null, d.choices);
            v.fail(field, format!("\"{}\"", crate::checks::shorten(self)), meta.message());
        }
    }
}

/// A list of trace columns (checked by the section, which knows the signals).
impl Param for Vec<String> {
    const KIND: &'static str = "signal list";
    fn check(&self, _: &str, _: &Decl, _: &mut Validator) {}
}

/// A list of numbered items (the online turbine-generator sets): each number within the range.
impl Param for Vec<u32> {
    const KIND: &'static str = "set list";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        for (i, x) in self.iter().enumerate().take(MAX_LIST_ITEMS) {
            if !in_range(*x as f64, d) {
                refuse::<Self>(&format!("{field}.{i}"), d, x, v);
            }
        }
    }
}

/// The same, optional (an order that leaves it out keeps what is running).
impl Param for Option<Vec<u32>> {
    const KIND: &'static str = "set list";
    fn check(&self, field: &str, d: &Decl, v: &mut Validator) {
        if let Some(list) = self {
            list.check(field, d, v);
        }
    }
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
        for (i, s) in self.iter().enumerate().take(MAX_LIST_ITEMS) {
            v.section(&format!("{field}.{i}"), |v| s.check_fields(v));
        }
    }
}

/// How many items of a list are checked (a longer list is refused by its section, which says so).
pub const MAX_LIST_ITEMS: usize = 10_000;

/// A section of the scenario written with [`params!`](crate::params!).
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
/// section is written `=> {}`: its own fields carry the declarations.
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
            fn check(&self, field: &str, _: &$crate::params::Decl, v: &mut $crate::checks::Validator) {
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
            fn check_fields(&self, v: &mut $crate::checks::Validator) {
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
            fn check(&self, _: &str, _: &$crate::params::Decl, _: &mut $crate::checks::Validator) {}
        }
    };
}
