//! Validation of parameters: every problem names the field by its dotted path, its value
//! (shortened) and what is allowed.
//!
//! Each subsystem's `Params::validate(&self, v: &mut Validator)` checks its own fields with
//! [`check_range!`] (the path comes from the field's name, never from a typed string); `Scenario`
//! nests the sections (`v.section("plant.motor", |v| self.plant.motor.validate(v))`) and adds the
//! checks that span sections.

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
        write!(f, "{} = {}: {}", self.path, self.value, self.message)
    }
}

/// Every problem found in a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioError(pub Vec<FieldError>);

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

/// Longest value echoed in a message [characters]; longer values are cut with an ellipsis.
pub const MAX_VALUE_CHARS: usize = 60;

/// A value as text for a message, cut to [`MAX_VALUE_CHARS`].
pub fn shorten(text: &str) -> String {
    if text.chars().count() <= MAX_VALUE_CHARS {
        text.to_string()
    } else {
        let mut s: String = text.chars().take(MAX_VALUE_CHARS).collect();
        s.push_str("...");
        s
    }
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
        if !(v.is_finite() && v >= lo && v <= hi) {
            self.fail(field, v, format!("must be a number from {lo} to {hi}"));
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
        self.errors.push(FieldError { path, value: shorten(&value.to_string()), message: message.into() });
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

#[cfg(test)]
mod tests {
    use super::*;

    struct P {
        mass_kg: f64,
        blades: u32,
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
    fn long_values_are_shortened() {
        let mut v = Validator::new();
        v.fail("name", "x".repeat(100_000), "too long");
        let e = v.finish().unwrap_err();
        assert_eq!(e.0[0].value.chars().count(), MAX_VALUE_CHARS + 3);
    }
}
