//! The hull's own maneuvering model (core/src/ship/sectional.rs), which every preset sails: its
//! standard maneuvers against IMO MSC.137(76)'s limits and the range destroyers show, its
//! derivatives against the regression they come from and against Table 2.3, and the mean wave
//! force that limits it at low speed, by two methods.

use crate::rows::{explained, open, row};
use crate::{Kind, Row, Section, Tolerance};
use aes_core::scenario::presets::preset;
use aes_core::sea::seakeeping::motions::response;
use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
use aes_core::studies::maneuvers::{booklet, zigzag_10_limits};

/// A limit row: ours within [0, limit] (IMO's criteria are upper bounds).
fn within_limit(quantity: &str, source: &str, limit: f64, ours: f64, unit: &'static str, reason: &str) -> Row {
    row(quantity, source, 0.5 * limit, ours, unit, Tolerance::Abs(0.5 * limit), reason).kind(Kind::Context)
}

pub(crate) fn own_hull() -> Result<Section, String> {
    let sc = preset("turn-360").ok_or("no preset")?;
    let b = booklet(&sc)?;
    let l = b.length_m;
    let u = aes_core::numerics::units::kn_to_m_s(b.approach_kn);
    let mut rows = vec![
        row(
            "35 deg turn at 25 kn: tactical diameter",
            "destroyers: 2.5 to 5 L (IMO MSC.137(76): at most 5 L)",
            3.75,
            b.turning.tactical_diameter_m / l,
            "L",
            Tolerance::Abs(1.25),
            &format!(
                "the hull's own model with the shafts held at the approach rpm ({:.0} rpm), the rudders at 35 deg; \
                 steady diameter {:.2} L at {:.0} % of the approach speed",
                b.shaft_rpm,
                b.turning.steady_diameter_m / l,
                100.0 * b.turning.speed_ratio
            ),
        )
        .kind(Kind::Context),
        within_limit(
            "35 deg turn at 25 kn: advance",
            "IMO MSC.137(76): at most 4.5 L",
            4.5,
            b.turning.advance_m / l,
            "L",
            "from the rudder order to 90 deg of heading change",
        ),
        within_limit(
            "initial turning: track to 10 deg of heading with 10 deg of rudder",
            "IMO MSC.137(76): at most 2.5 L",
            2.5,
            b.zigzag_10.initial_turning_m / l,
            "L",
            "the 10/10 zig-zag's first leg",
        ),
        within_limit(
            "10/10 zig-zag: first overshoot",
            "IMO MSC.137(76): by L/V",
            zigzag_10_limits(l / u).0,
            b.zigzag_10.first_overshoot_deg,
            "deg",
            &format!("L/V = {:.1} s; second overshoot {:.1} deg", l / u, b.zigzag_10.second_overshoot_deg),
        ),
        within_limit(
            "20/20 zig-zag: first overshoot",
            "IMO MSC.137(76): at most 25 deg",
            25.0,
            b.zigzag_20.first_overshoot_deg,
            "deg",
            "the hull's cross-flow drag and the rudders' lift damp the yaw; the 5415's skeg, left out, would damp it more",
        ),
    ];
    // The static drift slope at 0 deg against Clarke's Y_v' (in L T units: times L/T) and Table
    // 2.3's; the hull's own adds the rudders' lift in the slipstream.
    let hull = sc.ship_hull()?;
    let d = aes_core::ship::sectional::clarke_1983(
        l,
        hull.beam_m,
        hull.draft_m,
        hull.hydrostatics.volume / (l * hull.beam_m * hull.draft_m),
    );
    let drift = &b.static_drift;
    let slope = (drift[1].y_prime - drift[0].y_prime) / drift[1].drift_deg.to_radians();
    let clarke = d.yv * l / hull.draft_m;
    let table = aes_core::ship::maneuvering::AbkowitzCoefficients::default().yv * 1e-5 * l / hull.draft_m;
    rows.push(
        explained(
            "static drift at 25 kn: side force slope dY'/dbeta (Y' over 1/2 rho L T U^2)",
            "Clarke et al. (1983), the regression the model takes",
            clarke,
            slope,
            "1/rad",
            &format!(
                "ours adds the rudders' lift in the slipstream and the cross-flow drag's share at 2 deg to the \
                 bare hull's regression value; Table 2.3's Y_v (a kayak's) gives {table:.3} in the same units"
            ),
        )
        .kind(Kind::Context),
    );
    let own = aes_core::sim::plant::Plant::new(&sc)?;
    if let aes_core::sim::plant::Hull::Own { model, .. } = &own.hull {
        rows.push(
            explained(
                "sway added mass Y_vdot' (over 1/2 rho L^3)",
                "Clarke et al. (1983)",
                d.yvdot,
                model.sections_added[0],
                "-",
                "ours integrates the sections' rigid-wall sway added mass (each section's map, checked against \
                 the multipole solver to 0.25 %); the regression is fitted to model tests of whole hulls \
                 with their appendages",
            )
            .kind(Kind::Context),
        );
    }
    rows.push(mean_surge_force_at_low_speed()?);
    Ok(Section {
        finding: String::new(),
        title: "The hull's own maneuvering model (what every preset sails)",
        note: "The booklet is `aes-sim maneuvers preset:turn-360`. IMO's criteria are upper limits: a row passes \
               anywhere from 0 to the limit. The thesis' ch. 5 rows above run Table 2.3's model \
               (hull.forces = \"table_2_3\")."
            .into(),
        rows,
        figures: Vec::new(),
    })
}

/// The mean second-order surge force at 4 kn in sea state 6 following seas (long-crested, the
/// spectrum's components): Salvesen's (eqs. 2.47-2.48, what the runs use) against
/// Gerritsma-Beukelman's radiated-energy estimate, both from our strip theory.
fn mean_surge_force_at_low_speed() -> Result<Row, String> {
    let ship = Ship::dtmb5415();
    let table = ship.radiation_table(&default_omega_grid());
    let (w, h) = aes_core::sea::waves::sea_state(6).ok_or("no sea state")?;
    let comps = aes_core::sea::waves::SeaSampling::new(h, w, 0.0).sample(1);
    let u = aes_core::numerics::units::kn_to_m_s(4.0);
    let (mut salvesen, mut gb) = (0.0, 0.0);
    for c in &comps {
        let r = response(&ship, &table, c.omega, u, 0.0, 1.0);
        salvesen += c.amplitude * c.amplitude * r.added_resistance;
        gb += c.amplitude * c.amplitude * r.added_resistance_gb;
    }
    Ok(open(
        "mean added resistance at 4 kn, SS6 following seas (negative: a push forward)",
        "Gerritsma-Beukelman, our strip theory",
        gb / 1e3,
        salvesen / 1e3,
        "kN",
        "ours is Salvesen's method (eqs. 2.47-2.48), which the runs use; at low speed its F7 term (the sections' \
         diffraction) is three quarters of it and carries a ship ordered to 4-8 kn with waves from astern to 6-14 kn \
         (tests/own_hull.rs). At 25 kn in head seas the two agree within 25 %. A third method (ITTC 2021's SNNM) \
         is still to be compared",
    )
    .kind(Kind::Context))
}
