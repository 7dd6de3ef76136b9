//! The `sign` lesson, "One sign in one equation": its definition and its explainer.

use super::facts::*;
use super::verdict::onsets_change;
use super::*;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "sign",
        title: "One sign in one equation",
        preset: "head-seas-ss6",
        set: &[("sim.duration_s", "60")],
        story: "A wave crest lifts the water at the stern, and it lifts the stern too: the propeller's depth is the water's rise less the stern's. The thesis this simulator follows prints its depth formula with the stern's motion added the other way round: as if the stern sank whenever the water rose.",
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
        change: Some(onsets_change(&["seakeeping.stern_motion"], &["stern:"], "switch how the stern moves in the depth formula")),
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
    // The range the plot shows, in numbers: no word for how far it swings but its own ends.
    let hi = b.stat(&HR[..1], Stat::Max, 0.0, end);
    let how = if printed {
        "This run uses the printed sign: the stern's motion is added to the wave's instead of taken from it"
    } else {
        "This run lets the stern rise and fall with the waves: its motion is taken from the wave's"
    };
    b.say(format!("{how}; the port shaft's h/R ran from {} to {}.", f(low.1, 2), f(hi.1, 2)), &[low.0, hi.0]);
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
