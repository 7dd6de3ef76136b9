//! The `sign` lesson, "One sign in one equation": its definition and its explainer.

use super::facts::*;
use super::*;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "sign",
        title: "One sign in one equation",
        preset: "head-seas-ss6",
        set: &[("sim.duration_s", "60")],
        story: "A wave crest lifts the water at the stern, and it lifts the stern too, so the propeller stays at about the same depth under the surface. The thesis this simulator follows prints its depth formula with the stern's motion added the other way round: as if the stern sank whenever the water rose. One sign, and the propeller seems to swing twice as far.",
        controls: vec![
            Control {
                path: "seakeeping.stern_motion",
                with_paths: &[],
                label: "How the stern moves in the depth formula",
                unit: "",
                kind: ControlKind::Toggle {
                    values: &["consistent", "thesis_eq_2_57"],
                    labels: &["it rises and falls with the waves", "the other way, as the thesis prints it"],
                    settings: &[&[], &[]],
                },
            },
            slider("sea.sea_state", "Sea state (2: smooth, 6: very rough)", "", 2.0, 6.0, 1.0),
        ],
        question: "The thesis prints the stern's motion with the other sign. If that were right, the propeller would break the surface...",
        answers: &["more often than with the stern following the waves", "less often", "as often"],
        plots: &["hr"],
        view: "stern",
        explain,
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    sign(b, &g.sc, g.text("seakeeping.stern_motion") == "thesis_eq_2_57", g.num("sea.sea_state"), end)
}

fn sign(b: &mut Book, sc: &serde_json::Value, printed: bool, sea: f64, end: f64) -> Explanation {
    let low = depth(b, sc, end);
    // In low seas the stern hardly moves and the two formulas differ by about 0.02 in h/R.
    let (by, much) =
        if sea <= 3.0 { (0.01, " a little (the stern hardly moves in these low waves)") } else { (0.05, "") };
    let (to, words, relation) = if printed {
        (
            "consistent",
            format!("Switch to the stern rising and falling with the waves: the lowest h/R rises{much}."),
            Relation::More,
        )
    } else {
        ("thesis_eq_2_57", format!("Switch to the thesis' printed sign: the lowest h/R falls{much}."), Relation::Less)
    };
    b.say(
        if printed { "This run uses the printed sign: the stern's motion adds to the wave's instead of cancelling it, so the hub seems to swing more." } else { "This run lets the stern follow the waves: its motion cancels much of the wave's, so the hub stays at about the same depth." }.into(),
        &[],
    );
    let next = Next {
        text: words,
        set: vec![("seakeeping.stern_motion", to.into())],
        promise: Promise {
            measure: Measure::Stat { signals: HR.to_vec(), stat: Stat::Min, from_s: 0.0 },
            relation,
            by,
        },
    };
    b.done(None, "One run cannot answer a question about a change: switch the formula and compare the new run with the faint earlier one.".into(), next, low.2)
}
