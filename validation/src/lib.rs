//! The validation report (`aes-sim validate`, docs/validation.md): every thesis number we compare
//! with, beside ours, with the difference, the tolerance we claim, the verdict and the reason for
//! every difference. Generated, never hand-written: a change that moves a number shows in the
//! report's diff, and `aes-sim validate --check` (run by `./build.sh test`) fails when a row leaves
//! its tolerance or the committed report is stale.
//!
//! A crate of its own, outside the physics library: the report reads aes-core's public API, runs
//! its simulations and writes Markdown and SVG as text (no I/O; `aes-sim validate` writes and
//! checks the files). One module per part of the report: chapters 2, 4 and 5 of the thesis, the
//! Monte Carlo studies of ch. 5.4, the analytic checks, the second-order forces and fuel, the model
//! experiments, the peer code and the as-printed switches; `rows` and `runs` hold what they share.

mod analytic;
mod as_printed;
mod blade;
mod chapter_2;
mod chapter_4;
mod chapter_5;
mod experiments;
mod markdown;
mod monte_carlo;
mod own_hull;
mod peer_code;
mod rows;
mod runs;
mod second_order_and_fuel;
mod snnm;
mod stopping;
pub mod svg_plot;

pub use markdown::markdown;

use crate::analytic::analytic;
use crate::as_printed::as_printed;
use crate::blade::propeller_from_geometry;
use crate::chapter_2::table_2_4;
use crate::chapter_4::{table_4_1, table_4_2};
use crate::chapter_5::{chapter_5, table_5_7};
use crate::experiments::wigley_iii_experiments;
use crate::monte_carlo::{excess_energy, table_5_8};
use crate::own_hull::own_hull;
use crate::peer_code::pdstrip_rows;
use crate::rows::within;
use crate::runs::{head_seas, run, startup_to};
use crate::second_order_and_fuel::second_order_and_fuel;
use crate::stopping::stopping;
use crate::svg_plot::{check_well_formed, svg, Plot};
use aes_core::scenario::SternMotion;
use serde::Serialize;

/// How far ours may be from the thesis' number.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Tolerance {
    /// |ours - thesis| <= x.
    Abs(f64),
    /// |ours - thesis| <= x |thesis|.
    Rel(f64),
}

/// What a row says.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Verdict {
    /// Within the tolerance.
    Pass,
    /// Outside the tolerance: the build fails.
    Fail,
    /// Within the tolerance, but not an independent check: the number was copied from the thesis
    /// or a parameter was chosen to give it (the reason says which). Still fails the build when
    /// it leaves its tolerance.
    Calibrated,
    /// A difference whose cause is known and written in the reason (a parameter the thesis does
    /// not print, a definition it leaves open, a thesis number that its own inputs do not give).
    Explained,
    /// A known difference whose cause is still being investigated (no tolerance is claimed; the
    /// reason says what is known).
    Open,
    /// A number shown, not compared: what a switch as printed moves, or ours beside a thesis
    /// number for another case (the reason says which).
    Shown,
}

/// What a row is checked against. The report counts each kind apart, so that no kind inflates
/// another's count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Kind {
    /// A number the thesis prints or states for this case, computed here from the model.
    Thesis,
    /// A thesis number copied into a parameter.
    Copied,
    /// A thesis number a parameter was chosen to give (or one that follows from such a point).
    Fitted,
    /// A closed form, a limit or a conservation law; no thesis number is involved.
    Analytic,
    /// Model experiments (Journee 1992; Jessup 1989; the B-series' regression of its model tests).
    Experiment,
    /// Another code, run by us on the same hull (PDStrip).
    PeerCode,
    /// What a switch as printed moves: the thesis column is the run with the switch as printed.
    AsPrinted,
    /// Ours beside a thesis number given for another case, for scale: no comparison.
    Context,
}

/// Ours over seeds, for a row whose number depends on the random sea.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Spread {
    /// The seeds, in order.
    pub seeds: Vec<u64>,
    /// Ours for each seed.
    pub values: Vec<f64>,
    /// How many seeds fall within the row's tolerance (None without one).
    pub within: Option<usize>,
}

impl Spread {
    pub(crate) fn sorted(&self) -> Vec<f64> {
        let mut v = self.values.clone();
        v.sort_by(f64::total_cmp);
        v
    }

    /// The median of the seeds' values (the mean of the middle two for an even count).
    pub fn median(&self) -> f64 {
        let v = self.sorted();
        match v.len() {
            0 => f64::NAN,
            n if n % 2 == 1 => v[n / 2],
            n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
        }
    }

    /// The smallest and largest value.
    pub fn range(&self) -> (f64, f64) {
        let v = self.sorted();
        (v.first().copied().unwrap_or(f64::NAN), v.last().copied().unwrap_or(f64::NAN))
    }
}

/// One compared number.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub quantity: String,
    /// Where the thesis prints it.
    pub source: String,
    pub thesis: f64,
    pub ours: f64,
    pub unit: &'static str,
    /// None for an open difference.
    pub tolerance: Option<Tolerance>,
    pub verdict: Verdict,
    /// Why ours differs, or what the agreement rests on.
    pub reason: String,
    pub kind: Kind,
    /// For a number that depends on the random sea: ours over seeds (`ours` is their median and
    /// the verdict is the median's).
    pub spread: Option<Spread>,
    /// A pass that rests on an input chosen for it (the thesis does not give it): what and why.
    pub chosen_input: Option<String>,
    /// An explained difference whose explanation gives a number of its own: the thesis' number
    /// reproduced by the model with the explanation's change. The row fails when it leaves its
    /// tolerance, so an explanation can be wrong.
    pub explanation: Option<Explanation>,
}

/// The number an explanation gives, against the thesis' (see [`Row::explanation`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Explanation {
    /// What was changed, e.g. "1.6 times Table 5.1's resistance".
    pub change: String,
    pub value: f64,
    pub tolerance: Tolerance,
}

impl Row {
    /// The same row, of another kind.
    pub(crate) fn kind(self, kind: Kind) -> Row {
        Row { kind, ..self }
    }

    /// The same row, shown and not compared (an as-printed switch, or another case's number).
    pub(crate) fn shown(self, kind: Kind) -> Row {
        // Only a number that could not be had fails (a missing reference, a NaN of ours).
        let broken = self.thesis.is_nan() || !self.ours.is_finite();
        let verdict = if broken { Verdict::Fail } else { Verdict::Shown };
        let spread = self.spread.map(|sp| Spread { within: None, ..sp });
        Row { kind, verdict, tolerance: None, spread, ..self }
    }

    /// The same row, noting the chosen input its verdict rests on.
    pub(crate) fn chosen(self, input: String) -> Row {
        Row { chosen_input: Some(input), ..self }
    }

    /// The same explained row, with the number its explanation gives: it fails when that number
    /// is not within `tolerance` of the thesis'. An explanation that does not bring the number
    /// nearer the thesis' than ours is no reproduction: the row then says so and claims none.
    pub(crate) fn because(self, change: String, value: f64, tolerance: Tolerance) -> Row {
        if (value - self.thesis).abs() >= (self.ours - self.thesis).abs() {
            let reason = format!(
                "{}; {change} gives {value:.4}, no nearer the thesis' number than ours, so it is not claimed here",
                self.reason
            );
            return Row { reason, ..self };
        }
        let holds = within(tolerance, self.thesis, value);
        let verdict = if holds || self.verdict == Verdict::Fail { self.verdict } else { Verdict::Fail };
        Row { verdict, explanation: Some(Explanation { change, value, tolerance }), ..self }
    }
}

/// A titled group of rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Section {
    pub title: &'static str,
    pub note: String,
    pub rows: Vec<Row>,
    /// Drawn from the runs the rows use; shown below the rows.
    pub figures: Vec<Figure>,
    /// What the report's opening says of this section (empty for most).
    pub finding: String,
}

/// A figure of the report: `FIGURE_DIR/{name}.svg` beside the report, made by [`crate::svg_plot`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Figure {
    /// The file's stem.
    pub name: &'static str,
    pub caption: String,
    pub svg: String,
}

/// Where the figures go, relative to the report (docs/validation.md -> docs/validation/).
pub const FIGURE_DIR: &str = "validation";

impl Figure {
    pub(crate) fn new(name: &'static str, caption: &str, plot: &Plot) -> Result<Figure, String> {
        // Every figure the report makes is checked as the writer's tests check theirs.
        let text = svg(plot)?;
        check_well_formed(&text).map_err(|e| format!("figure {name}: {e}"))?;
        Ok(Figure { name, caption: caption.into(), svg: text })
    }

    /// The file's path relative to the report.
    pub fn path(&self) -> String {
        format!("{FIGURE_DIR}/{}.svg", self.name)
    }
}

/// Most Monte Carlo trials per study a report may ask for (200, the default, take seconds;
/// 10,000 about 6 minutes).
pub const MAX_TRIALS: u64 = 10_000;

/// How large a run of the report is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Size {
    /// Monte Carlo trials of each study (the thesis: 189 for Table 5.8, 100 for the excess energy).
    pub trials: u64,
}

impl Default for Size {
    /// What CI runs: 200 trials (the report says so beside every Monte Carlo row).
    fn default() -> Self {
        Size { trials: 200 }
    }
}

/// Every section of the report.
pub fn sections(size: Size) -> Result<Vec<Section>, String> {
    // The 25-knot start-up serves three sections: run it once.
    let st25 = run(&startup_to(25.0))?;
    // The corrected ch. 5.3 run at the thesis' depth serves two.
    let hs_base = head_seas(Default::default(), SternMotion::Consistent)?;
    // Chapter 5 hands its part of the eq. 2.57 paragraph (Fig. 5-15's swing) to Table 5.8's.
    let mut ch5 = chapter_5(&st25)?;
    let mut t58 = table_5_8(size)?;
    t58.finding.push_str(&std::mem::take(&mut ch5.finding));
    let analytic = analytic(size, &st25)?;
    let analytic = Section { rows: analytic.rows.into_iter().map(|r| r.kind(Kind::Analytic)).collect(), ..analytic };
    let printed = as_printed(&hs_base)?;
    let printed = Section { rows: printed.rows.into_iter().map(|r| r.shown(Kind::AsPrinted)).collect(), ..printed };
    Ok(vec![
        table_2_4()?,
        table_4_1()?,
        table_4_2()?,
        table_5_7(&st25)?,
        ch5,
        t58,
        own_hull()?,
        excess_energy(size)?,
        analytic,
        second_order_and_fuel(&hs_base)?,
        wigley_iii_experiments()?,
        propeller_from_geometry()?,
        stopping()?,
        pdstrip_rows()?,
        printed,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rows::{
        calibrated, explained, open, reference, reference_pct, row, seeded, thesis_f64, thesis_text, Thesis,
    };
    use crate::runs::SEEDS;
    use aes_core::studies::thesis_values::{missing, quoted_keys, TABLE_5_7};

    /// Every key the report names is in the thesis' numbers (core/data/thesis_values.csv), its
    /// tests' keys of a missing reference aside (each file is read up to its tests), and so are
    /// Table 5.7's, which it takes from core.
    #[test]
    fn every_key_the_report_uses_exists() {
        let mut keys: Vec<String> = TABLE_5_7.iter().flat_map(|(_, k)| k.map(String::from)).collect();
        for source in SOURCES {
            for key in quoted_keys(source.split("#[cfg(test)]").next().unwrap_or(source)) {
                if !keys.contains(&key) {
                    keys.push(key);
                }
            }
        }
        assert!(keys.len() >= 60, "only {} keys found in the report's sources", keys.len());
        let refs: Vec<&str> = keys.iter().map(String::as_str).collect();
        assert_eq!(missing(&refs), Vec::<&str>::new());
    }

    /// The report's source files, every module of this crate that makes rows or text.
    const SOURCES: [&str; 14] = [
        include_str!("lib.rs"),
        include_str!("analytic.rs"),
        include_str!("as_printed.rs"),
        include_str!("chapter_2.rs"),
        include_str!("chapter_4.rs"),
        include_str!("chapter_5.rs"),
        include_str!("experiments.rs"),
        include_str!("markdown.rs"),
        include_str!("monte_carlo.rs"),
        include_str!("own_hull.rs"),
        include_str!("peer_code.rs"),
        include_str!("rows.rs"),
        include_str!("runs.rs"),
        include_str!("second_order_and_fuel.rs"),
    ];

    /// A key the data file lacks makes a failing row that says so, whatever kind of row it is,
    /// and the report still renders.
    #[test]
    fn a_missing_reference_fails_its_row_and_says_so() {
        let key = "table_9_9.nothing";
        let rows = [
            row("q", "s", reference(key), 1.0, "-", Tolerance::Abs(1.0), ""),
            calibrated("q", "s", reference_pct(key), 1.0, "-", Tolerance::Abs(1.0), ""),
            open("q", "s", reference(key), 1.0, "-", ""),
            explained("q", "s", reference(key), 1.0, "-", ""),
        ];
        for r in &rows {
            assert_eq!(r.verdict, Verdict::Fail, "{r:?}");
            assert!(r.thesis.is_nan() && r.reason.starts_with("missing reference: table_9_9.nothing"), "{r:?}");
        }
        assert!(thesis_f64(key).is_nan());
        assert!(thesis_text(key).contains("missing reference"));
        let sec = Section {
            finding: String::new(),
            title: "t",
            note: String::new(),
            rows: rows.to_vec(),
            figures: Vec::new(),
        };
        let md = markdown(&[sec], Size::default());
        assert!(md.contains("| q | - - | s | 1 |") && md.contains("missing reference"), "{md}");
    }

    /// The opening counts each kind of row apart: an as-printed row or a calibration never adds to
    /// the thesis comparisons' passes, and a failing row is counted under its own kind.
    #[test]
    fn the_opening_counts_each_kind_apart() {
        let pass = row("a", "s", 1.0, 1.0, "-", Tolerance::Abs(0.1), "");
        let rows = vec![
            pass.clone(),
            pass.clone().chosen("a rate".into()),
            row("b", "s", 1.0, 2.0, "-", Tolerance::Abs(0.1), "").kind(Kind::Analytic),
            explained("c", "s", 1.0, 3.0, "-", "").shown(Kind::AsPrinted),
            calibrated("d", "s", 1.0, 1.0, "-", Tolerance::Abs(0.1), "").kind(Kind::Copied),
            pass.kind(Kind::Experiment),
        ];
        let sec = Section { finding: "A finding.".into(), title: "t", note: String::new(), rows, figures: Vec::new() };
        let md = markdown(&[sec], Size::default());
        assert!(md.contains("A finding."), "{md}");
        assert!(md.contains("Of 6 rows, 2 compare our model with a number the thesis gives for the same case; 2 of those pass independently (1 of them only at an input chosen for it"), "{md}");
        assert!(md.contains("| 2 | 2 pass, 0 fail, 0 explained, 0 open |"), "{md}");
        assert!(
            md.contains("(closed forms, limits, energy books) | 1 | 0 pass, 1 fail, 0 explained, 0 open |"),
            "{md}"
        );
        assert!(md.contains("(a sensitivity, not a comparison) | 1 | 1 shown |"), "{md}");
        assert!(md.contains("a thesis number copied into a parameter | 1 | 1 within |"), "{md}");
        assert!(md.contains("(Journee 1992, Wigley III; Jessup 1989, DTMB 4119; the B-series) | 1 | 1 pass"), "{md}");
        assert!(md.contains("1 row(s) fail"), "{md}");
        assert!(md.contains("| pass, at a chosen input | chosen input: a rate |"), "{md}");
    }

    /// A row over seeds takes the median as ours and is judged by where the thesis' one
    /// realisation falls among the seeds (within the middle 80 %: the second smallest to the
    /// second largest of ten); the spread counts the seeds within the tolerance and the table shows
    /// the range.
    #[test]
    fn a_row_over_seeds_is_judged_by_where_the_thesis_falls() {
        let values: Vec<f64> = SEEDS.map(|s| s as f64).collect();
        let r = seeded(row("q", "s", 5.0, 0.0, "-", Tolerance::Abs(1.0), ""), values.clone());
        assert_eq!((r.ours, r.verdict), (5.5, Verdict::Pass));
        assert_eq!(r.spread.as_ref().and_then(|s| s.within), Some(3));
        assert_eq!(r.spread.as_ref().map(Spread::range), Some((1.0, 10.0)));
        let edge = seeded(row("q", "s", 9.0, 9.0, "-", Tolerance::Abs(1.0), ""), values.clone());
        assert_eq!(edge.verdict, Verdict::Pass);
        let far = seeded(row("q", "s", 9.5, 9.0, "-", Tolerance::Abs(1.0), ""), values.clone());
        assert_eq!((far.verdict, far.spread.as_ref().and_then(|s| s.within)), (Verdict::Fail, Some(2)));
        let o = seeded(open("q", "s", 9.0, 0.0, "-", ""), values);
        assert_eq!((o.verdict, o.spread.as_ref().and_then(|s| s.within)), (Verdict::Open, None));
        let sec =
            Section { finding: String::new(), title: "t", note: String::new(), rows: vec![r], figures: Vec::new() };
        let md = markdown(&[sec], Size::default());
        assert!(
            md.contains("| 5.5 (median; 1 to 10 over 10 seeds) |") && md.contains("| pass (3 of 10 seeds within) |"),
            "{md}"
        );
    }

    /// An explanation's own number is checked: within its tolerance the row stays explained and
    /// says so, outside it fails, and one that lands no nearer the thesis' number than ours is not
    /// claimed.
    #[test]
    fn an_explanation_can_fail() {
        let base = || explained("q", "s", 10.0, 7.0, "-", "why");
        let held = base().because("a change".into(), 9.9, Tolerance::Abs(0.2));
        assert_eq!((held.verdict, held.explanation.is_some()), (Verdict::Explained, true));
        let wrong = base().because("a change".into(), 9.5, Tolerance::Abs(0.2));
        assert_eq!(wrong.verdict, Verdict::Fail);
        let farther = base().because("a change".into(), 13.5, Tolerance::Abs(0.2));
        assert_eq!((farther.verdict, farther.explanation.is_none()), (Verdict::Explained, true));
        assert!(farther.reason.contains("no nearer"), "{}", farther.reason);
    }

    /// A key the file has gives its printed number (a percentage as a fraction), and the row
    /// compares with it.
    #[test]
    fn references_resolve_to_the_printed_numbers() {
        assert_eq!(reference("table_5_8.monte_carlo.mean_s").resolve(), Ok(23.67));
        assert_eq!(reference_pct("ch_5_3_2.im_power_turn").resolve(), Ok(1.6));
        assert_eq!(reference_pct("ch_5_2_1.turbine_speed_loss").resolve(), Ok(0.20));
        assert_eq!(Thesis::from(0.5).resolve(), Ok(0.5));
        assert_eq!(thesis_text("table_5_8.monte_carlo.skewness"), "1.00");
        let r = row("q", "s", reference("table_4_1.steady_state.v_rect_v"), 743.2, "V", Tolerance::Abs(0.1), "");
        assert_eq!((r.thesis, r.verdict), (743.17, Verdict::Pass));
    }
}
