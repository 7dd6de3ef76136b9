//! The rows' builders: the thesis column (a printed number by its key, or one computed here), a
//! compared, calibrated, open or explained row, and a row over seeds.

use crate::runs::SEEDS;
use crate::{Kind, Row, Spread, Tolerance, Verdict};
use aes_core::studies::thesis_values;

/// The thesis column of a row: a number the thesis prints, by its key in
/// core/data/thesis_values.csv ([`reference`], [`reference_pct`]), or one computed here (a closed
/// form, Rice's prediction, a run with a switch as printed).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Thesis {
    /// The printed number over `divisor` (100 for a percentage compared as a fraction).
    Printed {
        key: &'static str,
        divisor: f64,
    },
    Computed(f64),
}

impl From<f64> for Thesis {
    fn from(x: f64) -> Self {
        Thesis::Computed(x)
    }
}

/// A number the thesis prints, as printed.
pub(crate) fn reference(key: &'static str) -> Thesis {
    Thesis::Printed { key, divisor: 1.0 }
}

/// A percentage the thesis prints, as a fraction.
pub(crate) fn reference_pct(key: &'static str) -> Thesis {
    Thesis::Printed { key, divisor: 100.0 }
}

/// Why a key gives no number.
fn missing_why(key: &str) -> String {
    match thesis_values::all() {
        Ok(_) => format!("missing reference: {key} is not in {}", thesis_values::PATH),
        Err(e) => format!("missing reference: {key} ({e})"),
    }
}

impl Thesis {
    pub(crate) fn resolve(self) -> Result<f64, String> {
        match self {
            Thesis::Computed(x) => Ok(x),
            Thesis::Printed { key, divisor } => {
                thesis_values::value(key).map(|v| v / divisor).ok_or_else(|| missing_why(key))
            }
        }
    }
}

/// A thesis number for a computation or a plot: NaN when the file lacks it (the row that compares
/// with the same key then says "missing reference").
pub(crate) fn thesis_f64(key: &str) -> f64 {
    thesis_values::value(key).unwrap_or(f64::NAN)
}

/// A thesis number as printed, for the report's text.
pub(crate) fn thesis_text(key: &str) -> String {
    thesis_values::printed(key).map_or_else(|| format!("[{}]", missing_why(key)), str::to_string)
}

/// A row before its thesis number is resolved: failing, with no thesis number, tolerance or
/// reason (a row whose thesis number is missing stays so, with the reason that says so).
fn unjudged(quantity: &str, source: &str, ours: f64, unit: &'static str) -> Row {
    Row {
        quantity: quantity.into(),
        source: source.into(),
        thesis: f64::NAN,
        ours,
        unit,
        tolerance: None,
        verdict: Verdict::Fail,
        reason: String::new(),
        kind: Kind::Thesis,
        spread: None,
        chosen_input: None,
        explanation: None,
    }
}

pub(crate) fn row(
    quantity: &str,
    source: &str,
    thesis: impl Into<Thesis>,
    ours: f64,
    unit: &'static str,
    tol: Tolerance,
    reason: &str,
) -> Row {
    let r = unjudged(quantity, source, ours, unit);
    let thesis = match thesis.into().resolve() {
        Ok(x) => x,
        Err(why) => return Row { reason: why, ..r },
    };
    let ok = within(tol, thesis, ours);
    let verdict = if ok && ours.is_finite() { Verdict::Pass } else { Verdict::Fail };
    Row { thesis, tolerance: Some(tol), verdict, reason: reason.into(), ..r }
}

/// Whether `ours` is within `tol` of `thesis` (a NaN never is).
pub(crate) fn within(tol: Tolerance, thesis: f64, ours: f64) -> bool {
    ours.is_finite()
        && match tol {
            Tolerance::Abs(x) => (ours - thesis).abs() <= x,
            Tolerance::Rel(x) => (ours - thesis).abs() <= x * thesis.abs(),
        }
}

/// A row whose number depends on the random sea, from its values over [`SEEDS`]: ours is their
/// median, and a compared row is judged on the distribution: the thesis shows one realisation,
/// which passes when it lies within the middle 80 % of ours (from the second smallest to the
/// second largest of ten seeds). The spread also counts the seeds within the row's tolerance.
pub(crate) fn seeded(r: Row, values: Vec<f64>) -> Row {
    let sp = Spread {
        seeds: SEEDS.collect(),
        within: r.tolerance.map(|t| values.iter().filter(|&&v| within(t, r.thesis, v)).count()),
        values,
    };
    let ours = sp.median();
    let sorted = sp.sorted();
    let typical = sorted.len() >= 5 && (sorted[1]..=sorted[sorted.len() - 2]).contains(&r.thesis);
    let verdict = match r.verdict {
        Verdict::Pass | Verdict::Fail if !r.thesis.is_nan() => {
            if typical && ours.is_finite() {
                Verdict::Pass
            } else {
                Verdict::Fail
            }
        }
        v => v,
    };
    Row { ours, verdict, spread: Some(sp), ..r }
}

pub(crate) fn open(
    quantity: &str,
    source: &str,
    thesis: impl Into<Thesis>,
    ours: f64,
    unit: &'static str,
    reason: &str,
) -> Row {
    let r = unjudged(quantity, source, ours, unit);
    match thesis.into().resolve() {
        Ok(thesis) => Row { thesis, verdict: Verdict::Open, reason: reason.into(), ..r },
        Err(why) => Row { reason: why, ..r },
    }
}

/// A row checked like [`row`] whose agreement is by construction (see [`Verdict::Calibrated`]).
pub(crate) fn calibrated(
    quantity: &str,
    source: &str,
    thesis: impl Into<Thesis>,
    ours: f64,
    unit: &'static str,
    tol: Tolerance,
    reason: &str,
) -> Row {
    let r = row(quantity, source, thesis, ours, unit, tol, reason);
    Row { verdict: if r.verdict == Verdict::Pass { Verdict::Calibrated } else { r.verdict }, kind: Kind::Fitted, ..r }
}

pub(crate) fn explained(
    quantity: &str,
    source: &str,
    thesis: impl Into<Thesis>,
    ours: f64,
    unit: &'static str,
    reason: &str,
) -> Row {
    let r = open(quantity, source, thesis, ours, unit, reason);
    Row { verdict: if r.verdict == Verdict::Open { Verdict::Explained } else { r.verdict }, ..r }
}
