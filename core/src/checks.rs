//! Validation of parameters: every problem names the field by its dotted path, its value
//! (shortened) and what is allowed.
//!
//! Each section's fields are checked against their declarations (`crate::params`: the path comes
//! from the field's name, never from a typed string); a section's `CrossCheck` adds the checks
//! that relate its fields, and `Scenario`'s the checks that span sections.

use serde::Serialize;
use std::fmt;

/// One problem with a scenario, naming the field, its value and what is allowed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FieldError {
    /// Dotted path of the field, e.g. `plant.motor.pole_pairs` or `commands.2.speed_kn`.
    pub path: String,
    /// The offending value as text (at most [`MAX_VALUE_CHARS`] characters).
    pub value: String,
    /// What is allowed.
    pub message: String,
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}: {}", shorten(&self.path), shorten(&self.value), shorten_message(&self.message))
    }
}

/// Every problem found in a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioError(pub Vec<FieldError>);

impl fmt::Display for ScenarioError {
    /// The first problems, at most [`MAX_ERRORS_SHOWN`] of them and [`MAX_ERRORS_BYTES`] bytes
    /// (the first always), then a line counting the rest: a message stays under 2 kB.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut bytes = 0;
        let mut shown = 0;
        for e in self.0.iter().take(MAX_ERRORS_SHOWN) {
            let line = e.to_string();
            if shown > 0 && bytes + 1 + line.len() > MAX_ERRORS_BYTES {
                break;
            }
            if shown > 0 {
                writeln!(f)?;
            }
            write!(f, "{line}")?;
            bytes += line.len() + usize::from(shown > 0);
            shown += 1;
        }
        if self.0.len() > shown {
            write!(f, "\n... and {} more problems ({} in all)", self.0.len() - shown, self.0.len())?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

/// Longest value echoed in a message \[characters\]; longer values are cut with an ellipsis.
pub const MAX_VALUE_CHARS: usize = 60;

/// Most problems of one scenario a message lists, and most bytes of them (one problem is at most
/// about 530 characters: a path, a value, a message cut to 400); the rest are counted in a last
/// line.
pub const MAX_ERRORS_SHOWN: usize = 20;
pub const MAX_ERRORS_BYTES: usize = 1500;

/// A value as text for a message, its control characters escaped (ESC, BEL, newline: a value
/// or a file name never reaches the terminal raw) and cut to [`MAX_VALUE_CHARS`].
pub fn shorten(text: &str) -> String {
    let text = escape_controls(text, false);
    if text.chars().count() <= MAX_VALUE_CHARS {
        text
    } else {
        let mut s: String = text.chars().take(MAX_VALUE_CHARS).collect();
        s.push_str("...");
        s
    }
}

/// `text` with every control character written as its Rust escape (`\u{1b}`, `\n`); newlines
/// kept as they are when `keep_newlines` (a message of several lines).
pub fn escape_controls(text: &str, keep_newlines: bool) -> String {
    if !text.chars().any(char::is_control) {
        return text.to_string();
    }
    text.chars()
        .map(|c| {
            if c.is_control() && !(keep_newlines && c == '\n') {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// A message from a parser, with every quoted or backticked stretch longer than
/// [`MAX_VALUE_CHARS`] cut (serde echoes the offending string whole: a 4 MB string would give
/// 4 MB of stderr).
pub fn shorten_message(msg: &str) -> String {
    let mut out = String::new();
    let mut quote: Option<(char, String)> = None;
    for ch in msg.chars() {
        match &mut quote {
            Some((q, inner)) if ch == *q => {
                out.push_str(&shorten(inner));
                out.push(ch);
                quote = None;
            }
            Some((_, inner)) => inner.push(ch),
            None => {
                out.push(ch);
                if ch == '"' || ch == '`' {
                    quote = Some((ch, String::new()));
                }
            }
        }
    }
    if let Some((_, inner)) = quote {
        out.push_str(&shorten(&inner));
    }
    shorten_long(&out)
}

/// Any text, control characters but newlines escaped, cut to 400 characters (a message's last
/// guard).
fn shorten_long(text: &str) -> String {
    let text = escape_controls(text, true);
    if text.chars().count() <= 400 {
        text
    } else {
        let mut s: String = text.chars().take(400).collect();
        s.push_str("...");
        s
    }
}

/// A number for a message: as Rust prints it when that is short, else in scientific notation
/// (`1e300`, not 301 digits).
pub fn num(x: f64) -> String {
    let plain = x.to_string();
    if plain.len() <= 24 {
        plain
    } else {
        format!("{x:e}")
    }
}

/// A derived number (a bound worked out from other fields: 0.1 L T is 7.1000000000000005) to four
/// significant digits, without trailing zeros.
pub fn short(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return num(x);
    }
    let digits = (3 - libm::floor(libm::log10(x.abs())) as i32).clamp(0, 12) as usize;
    let text = format!("{x:.digits$}");
    let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
    text.to_string()
}

/// Collects the problems of a scenario; sections nest the paths.
#[derive(Debug, Default)]
pub struct Validator {
    prefix: String,
    errors: Vec<FieldError>,
}

impl Validator {
    pub fn new() -> Validator {
        Validator::default()
    }

    /// Checks a section whose fields sit under `name` (dotted, e.g. `plant.motor`).
    pub fn section(&mut self, name: &str, f: impl FnOnce(&mut Validator)) {
        let saved = self.prefix.len();
        if !self.prefix.is_empty() {
            self.prefix.push('.');
        }
        self.prefix.push_str(name);
        f(self);
        self.prefix.truncate(saved);
    }

    /// The full path of a field of the present section.
    pub fn path(&self, field: &str) -> String {
        if self.prefix.is_empty() {
            field.to_string()
        } else {
            format!("{}.{field}", self.prefix)
        }
    }

    /// A number in [lo, hi] (NaN and infinities fail).
    pub fn range(&mut self, field: &str, v: f64, lo: f64, hi: f64) {
        if lo > hi {
            // A range set by other fields (a hull's draft sets those of KG, the shafts, the hub)
            // can close up: no value of this field helps, and a range "from 3 to 0.4" would
            // read as a typo.
            self.fail(
                field,
                num(v),
                format!(
                    "no value fits: the range the other fields leave it (from {} down to {}) is empty; change those (for a hull: its draft or mass)",
                    num(lo),
                    num(hi)
                ),
            );
        } else if !(v.is_finite() && v >= lo && v <= hi) {
            self.fail(field, num(v), format!("must be a number from {} to {}", num(lo), num(hi)));
        }
    }

    /// A whole number in [lo, hi].
    pub fn range_u(&mut self, field: &str, v: u64, lo: u64, hi: u64) {
        if v < lo || v > hi {
            self.fail(field, v, format!("must be a whole number from {lo} to {hi}"));
        }
    }

    /// A problem with a field of the present section.
    pub fn fail(&mut self, field: &str, value: impl fmt::Display, message: impl Into<String>) {
        let path = self.path(field);
        // A long number (1e300 prints 301 digits) in its exponent form, then cut like any value.
        let text = value.to_string();
        let text = match text.parse::<f64>() {
            Ok(x) if text.len() > 24 => num(x),
            _ => text,
        };
        self.errors.push(FieldError { path, value: shorten(&text), message: message.into() });
    }

    /// Whether nothing has failed so far.
    pub fn is_ok(&self) -> bool {
        self.errors.is_empty()
    }

    pub fn finish(self) -> Result<(), ScenarioError> {
        if self.errors.is_empty() {
            Ok(())
        } else {
            Err(ScenarioError(self.errors))
        }
    }
}

/// `check_range!(v, self.field, lo, hi)`: the field's own name is its path in the present section.
/// Floats use [`Validator::range`]; `check_range!(v, self.field as u64, lo, hi)` whole numbers.
#[macro_export]
macro_rules! check_range {
    ($v:expr, $s:ident . $field:ident as u64, $lo:expr, $hi:expr) => {
        $v.range_u(stringify!($field), $s.$field as u64, $lo, $hi)
    };
    ($v:expr, $s:ident . $field:ident, $lo:expr, $hi:expr) => {
        $v.range(stringify!($field), $s.$field, $lo, $hi)
    };
}

/// Checks that every number in a serializable value is finite: an output must never carry NaN or
/// an infinity (serde_json would print it as `null`, CSV as `NaN`). The error names the first
/// offending number by its path, e.g. `steady_state.t_m0 = NaN is not a finite number`. Undefined
/// statistics are `None` (printed as `null`), never NaN.
pub fn check_finite<T: Serialize + ?Sized>(x: &T) -> Result<(), String> {
    let mut c = FiniteCheck { path: Vec::new() };
    x.serialize(&mut c).map_err(|e| e.0)
}

/// The error of [`check_finite`].
#[derive(Debug)]
pub struct NotFinite(String);

impl fmt::Display for NotFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NotFinite {}

impl serde::ser::Error for NotFinite {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        NotFinite(msg.to_string())
    }
}

struct FiniteCheck {
    path: Vec<String>,
}

impl FiniteCheck {
    fn float(&self, x: f64) -> Result<(), NotFinite> {
        if x.is_finite() {
            Ok(())
        } else {
            let path = if self.path.is_empty() { "(value)".to_string() } else { self.path.join(".") };
            Err(NotFinite(format!("{} = {x} is not a finite number", shorten(&path))))
        }
    }
    fn nested<T: Serialize + ?Sized>(&mut self, key: String, v: &T) -> Result<(), NotFinite> {
        self.path.push(key);
        let r = v.serialize(&mut *self);
        self.path.pop();
        r
    }
}

/// The compound part of [`FiniteCheck`]: counts elements for their paths.
struct Compound<'a> {
    c: &'a mut FiniteCheck,
    index: usize,
    key: Option<String>,
}

macro_rules! ok_scalars {
    ($($f:ident: $t:ty),*) => {
        $(fn $f(self, _: $t) -> Result<(), NotFinite> { Ok(()) })*
    };
}

impl<'a> serde::Serializer for &'a mut FiniteCheck {
    type Ok = ();
    type Error = NotFinite;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;
    ok_scalars!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_i128: i128, serialize_u8: u8, serialize_u16: u16,
        serialize_u32: u32, serialize_u64: u64, serialize_u128: u128, serialize_char: char,
        serialize_str: &str, serialize_bytes: &[u8], serialize_unit_struct: &'static str);
    fn serialize_f32(self, x: f32) -> Result<(), NotFinite> {
        self.float(x as f64)
    }
    fn serialize_f64(self, x: f64) -> Result<(), NotFinite> {
        self.float(x)
    }
    fn serialize_none(self) -> Result<(), NotFinite> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> Result<(), NotFinite> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), NotFinite> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), NotFinite> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> Result<(), NotFinite> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> Result<(), NotFinite> {
        self.nested(variant.to_string(), v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, NotFinite> {
        Ok(Compound { c: self, index: 0, key: None })
    }
}

impl Compound<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), NotFinite> {
        let key = self.index.to_string();
        self.index += 1;
        self.c.nested(key, v)
    }
}

macro_rules! seq_like {
    ($($tr:ident: $f:ident),*) => {
        $(impl serde::ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = NotFinite;
            fn $f<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), NotFinite> {
                self.element(v)
            }
            fn end(self) -> Result<(), NotFinite> {
                Ok(())
            }
        })*
    };
}
seq_like!(SerializeSeq: serialize_element, SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field, SerializeTupleVariant: serialize_field);

impl serde::ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = NotFinite;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, k: &T) -> Result<(), NotFinite> {
        // Keys are strings or numbers in our outputs; their text is the path element.
        self.key =
            Some(serde_json::to_value(k).map(|v| v.as_str().map_or(v.to_string(), str::to_string)).unwrap_or_default());
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), NotFinite> {
        let key = self.key.take().unwrap_or_default();
        self.c.nested(key, v)
    }
    fn end(self) -> Result<(), NotFinite> {
        Ok(())
    }
}

macro_rules! struct_like {
    ($($tr:ident),*) => {
        $(impl serde::ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = NotFinite;
            fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, v: &T) -> Result<(), NotFinite> {
                self.c.nested(key.to_string(), v)
            }
            fn end(self) -> Result<(), NotFinite> {
                Ok(())
            }
        })*
    };
}
struct_like!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;

    struct P {
        mass_kg: f64,
        blades: u32,
    }

    /// A derived bound to four significant digits.
    #[test]
    fn short_numbers() {
        assert_eq!(short(7.1000000000000005), "7.1");
        assert_eq!(short(0.07100000000000001), "0.071");
        assert_eq!(short(-14.200000000000001), "-14.2");
        assert_eq!(short(123456.0), "123456");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(f64::NAN), "NaN");
    }

    /// A range that other fields closed up says so instead of "from 3 to 0.4".
    #[test]
    fn an_empty_range_says_no_value_fits() {
        let mut v = Validator::new();
        v.range("kg_m", 7.5, 3.0, 0.4);
        let e = v.finish().unwrap_err();
        assert!(
            e.0[0].message.starts_with("no value fits: the range the other fields leave it (from 3 down to 0.4)"),
            "{}",
            e.0[0].message
        );
    }

    #[test]
    fn paths_come_from_sections_and_field_names() {
        let p = P { mass_kg: -3.0, blades: 9 };
        let mut v = Validator::new();
        v.section("plant", |v| {
            v.section("motor", |v| {
                check_range!(v, p.mass_kg, 0.0, 1.0);
                check_range!(v, p.blades as u64, 2, 7);
            })
        });
        check_range!(v, p.mass_kg, -5.0, 0.0);
        let e = v.finish().unwrap_err();
        assert_eq!(e.0.len(), 2);
        assert_eq!(e.0[0].path, "plant.motor.mass_kg");
        assert_eq!(e.0[0].value, "-3");
        assert_eq!(e.0[0].message, "must be a number from 0 to 1");
        assert_eq!(e.0[1].path, "plant.motor.blades");
        assert_eq!(e.0[1].message, "must be a whole number from 2 to 7");
    }

    #[test]
    fn non_finite_numbers_are_named_by_path() {
        #[derive(Serialize)]
        struct S {
            a: f64,
            b: Vec<Option<f64>>,
            m: std::collections::BTreeMap<String, (u8, f64)>,
        }
        let mut s = S { a: 1.0, b: vec![Some(2.0), None], m: [("k".to_string(), (1, 3.0))].into() };
        assert_eq!(check_finite(&s), Ok(()));
        s.b[1] = Some(f64::INFINITY);
        assert_eq!(check_finite(&s), Err("b.1 = inf is not a finite number".to_string()));
        s.b[1] = None;
        s.m.insert("x".into(), (0, f64::NAN));
        assert_eq!(check_finite(&s), Err("m.x.1 = NaN is not a finite number".to_string()));
    }

    #[test]
    fn long_values_are_shortened() {
        let mut v = Validator::new();
        v.fail("name", "x".repeat(100_000), "too long");
        let e = v.finish().unwrap_err();
        assert_eq!(e.0[0].value.chars().count(), MAX_VALUE_CHARS + 3);
    }
}
