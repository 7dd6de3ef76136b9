//! The `waves` lesson, "Waves unload the propeller": its definition and its explainer.

use super::facts::*;
use super::verdict::onsets_change;
use super::*;

/// The top of the `waves` lesson's hub slider \[m\] (the hub 3.0 m deep at the 5415's draft).
const HUB_TOP_M: f64 = 3.15;

pub(super) fn lesson() -> Lesson {
    Lesson {
        name: "waves",
        title: "Waves unload the propeller",
        preset: "head-seas-ss6",
        set: &[("sim.duration_s", "60")],
        story: "The ship steams into waves. Each propeller sits under the stern; when a wave trough passes over it, the water above it thins and the propeller can draw air or break the surface, and it loses thrust. h/R (the hub's depth over the propeller's radius) says how deep it is: below 1 its disc breaks the surface.",
        controls: vec![
            slider("sea.sea_state", "Sea state (2: smooth, 6: very rough)", "", 2.0, 6.0, 1.0),
            slider("ship.hull.hub_above_base_m", "Propeller hub above the keel", "m", 0.15, HUB_TOP_M, 0.25),
            speed(10.0, 30.0),
        ],
        question: "Raise the propeller hub (a lighter ship rides higher). Will the propeller draw air more often, less often, or as often?",
        answers: &["more often", "less often", "as often"],
        plots: &["hr", "motor"],
        view: "stern",
        explain,
        change: Some(onsets_change(&["ship.hull.hub_above_base_m"], &["hub"], "move the propeller hub's height")),
    }
}

fn explain(b: &mut Book, g: &Given) -> Explanation {
    let end = b.end;
    waves(b, &g.sc, g.num("sea.sea_state"), g.num("ship.hull.hub_above_base_m"), end)
}

fn waves(b: &mut Book, sc: &serde_json::Value, sea: f64, hub: f64, end: f64) -> Explanation {
    let low = depth(b, sc, end);
    let m_lo = b.stat(&["im_power_pu"], Stat::Min, 0.0, end);
    let m_hi = b.stat(&["im_power_pu"], Stat::Max, 0.0, end);
    let rating = f(number(sc, "plant.motor.rated_power_w") / 1e6, 0);
    // A swing under 0.01 pu is "held": the words then say so instead of quoting equal numbers.
    if b.compare((m_hi.0, m_hi.1), (m_lo.0, m_lo.1), 0.01) == Relation::More {
        let i = b.last();
        b.say(
            format!(
                "The motors' power moved between {} and {} pu of their {rating} MW rating as the waves changed the propellers' load.",
                f(m_lo.1, 2),
                f(m_hi.1, 2)
            ),
            &[m_lo.0, m_hi.0, i],
        );
    } else {
        let i = b.last();
        b.say(format!("The motors' power held at {} pu of their {rating} MW rating: these waves hardly change the propellers' load.", f(m_hi.1, 2)), &[m_lo.0, m_hi.0, i]);
    }
    // The lesson's question is the hub's height: half a metre up (down from the top of its
    // span) moves the whole h/R line by about 0.5 m over the propeller's radius.
    let (to, relation, words) = if hub + 0.5 <= HUB_TOP_M {
        (hub + 0.5, Relation::Less, "Raise the hub to {} m (a lighter ship): the whole h/R line moves down, and the propellers come nearer the surface.")
    } else {
        (
            hub - 0.5,
            Relation::More,
            "Lower the hub to {} m (a heavier ship): the whole h/R line moves up, and the propellers stay deeper.",
        )
    };
    let next = Next {
        text: words.replace("{}", &value_text(to)),
        set: vec![("ship.hull.hub_above_base_m", value_text(to))],
        promise: Promise {
            measure: Measure::Stat { signals: HR.to_vec(), stat: Stat::Min, from_s: 0.0 },
            relation,
            by: 0.1,
        },
    };
    let _ = sea;
    b.done(None, "One run cannot answer a question about a change: move the hub and compare the new run with the faint earlier one.".into(), next, low.2)
}
