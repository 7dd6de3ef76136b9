//! The hull's own maneuvering model (core/src/ship/sectional.rs), which every preset sails: its
//! standard maneuvers against IMO MSC.137(76)'s limits and the range destroyers show, its
//! derivatives against the regression they come from and against Table 2.3, and the mean wave
//! force in a seaway against ITTC 2021's SNNM, Gerritsma-Beukelman and eq. 2.48's F7.

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
    if let aes_core::sim::plant::HullModel::Own { model, .. } = &own.hull_model {
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
    rows.extend(mean_wave_force_rows()?);
    Ok(Section {
        finding: String::new(),
        title: "The hull's own maneuvering model (what every preset sails)",
        note: "The booklet is `aes-sim maneuvers preset:turn-360`. IMO's criteria are upper limits: a row passes \
               anywhere from 0 to the limit. The thesis' ch. 5 rows above run Table 2.3's model \
               (hull.forces = \"table_2_3\") and eq. 2.48's short-wave force (seakeeping.short_wave_force = \
               \"salvesen_f7\"). The mean added resistance rows: ours is eq. 2.47's sum with the waterline's \
               reflection (Faltinsen et al. 1980 over the lit waterline, Fujii-Takahashi's draft factor), what \
               every run uses. Against SNNM, a regression of model tests of many hulls: in following and quartering \
               seas all three agree that the force is small where eq. 2.48's F7 pushed the ship on with 0.3-0.6 MN \
               (SNNM -2 to -9 kN at 6 kn, ours -16 to -30 kN); in head seas ours is 6-58 % below SNNM, most at SS4, \
               where short waves carry more of the energy and SNNM's reflection part, for a fine hull at speed, is \
               (0.87/C_B)^(1 + 4 sqrt(Fn)) times 2.25 times Faltinsen's (about 13 at 24 kn), where ours keeps \
               Faltinsen's. Ours has no surge force in beam seas (eq. 2.46 sets the mean force along the waves' \
               travel), SNNM 30-78 kN. The reference is our reading of the published formula, checked for its \
               limits (validation/src/snnm.rs), not against SNNM's authors' numbers."
            .into(),
        rows,
        figures: Vec::new(),
    })
}

/// The mean second-order surge force of our strip theory (eq. 2.47 with the waterline's
/// reflection, what every run uses) against ITTC 2021's SNNM and Gerritsma-Beukelman, in
/// long-crested seas of the sea state's spectrum (the runs' components, seed 1): head seas at 6 to
/// 24 kn in sea states 4 to 6, and the other headings at 6 and 24 kn in sea state 6. Each row's
/// reason gives eq. 2.48's F7 in place of the reflection (the thesis' form) at the same cell.
fn mean_wave_force_rows() -> Result<Vec<Row>, String> {
    use aes_core::sea::seakeeping::params::ShortWaveForce;
    let ours = Ship::dtmb5415();
    let table = ours.radiation_table(&default_omega_grid());
    let mut thesis = ours.clone();
    thesis.short_wave = ShortWaveForce::SalvesenF7;
    let h = snnm_hull(&ours);
    let mut cells = Vec::new();
    for ss in 4..=6u32 {
        for kn in [6.0, 12.0, 18.0, 24.0] {
            cells.push((ss, kn, 180.0));
        }
    }
    for heading in [0.0, 45.0, 90.0, 135.0] {
        for kn in [6.0, 24.0] {
            cells.push((6, kn, heading));
        }
    }
    let mut rows = Vec::new();
    for (ss, kn, heading) in cells {
        let (w, hs) = aes_core::sea::waves::sea_state(ss).ok_or("no sea state")?;
        let comps = aes_core::sea::waves::SeaSampling::new(hs, w, 0.0).sample(1);
        let u = aes_core::numerics::units::kn_to_m_s(kn);
        let beta = f64::to_radians(heading);
        let (mut r_ours, mut r_f7, mut r_snnm, mut r_gb) = (0.0, 0.0, 0.0, 0.0);
        for c in &comps {
            let a2 = c.amplitude * c.amplitude;
            let r = response(&ours, &table, c.omega, u, beta, 1.0);
            r_ours += a2 * r.added_resistance;
            r_gb += a2 * r.added_resistance_gb;
            r_f7 += a2 * response(&thesis, &table, c.omega, u, beta, 1.0).added_resistance;
            r_snnm += a2 * crate::snnm::added_resistance(&h, c.omega, beta, u, ours.rho, ours.g);
        }
        rows.push(
            open(
                &format!("mean added resistance, SS{ss}, {kn} kn, waves at {heading} deg (180 head seas)"),
                "ITTC 2021 SNNM (Liu and Papanikolaou 2020), our reading of the formula",
                r_snnm / 1e3,
                r_ours / 1e3,
                "kN",
                &format!(
                    "eq. 2.48's F7 in place of the reflection: {:.0} kN; Gerritsma-Beukelman: {:.0} kN",
                    r_f7 / 1e3,
                    r_gb / 1e3
                ),
            )
            .kind(Kind::Context),
        );
    }
    Ok(rows)
}

/// What SNNM needs of our hull: its dimensions, block coefficient and pitch radius of gyration, and
/// the lengths of entrance and run from its waterline (to 99 % of the largest beam; the bow's end
/// half a station ahead of the foremost wet station, as the strips close it).
pub(crate) fn snnm_hull(ship: &Ship) -> crate::snnm::SnnmHull {
    let st = &ship.strips;
    let n = st.len();
    let full = 0.99 * st.iter().map(|s| s.beam).fold(0.0, f64::max);
    let bow = st[n - 1].xi + 0.5 * (st[n - 1].xi - st[n - 2].xi);
    let fore = st.iter().rev().find(|s| s.beam >= full).map_or(0.0, |s| s.xi);
    let aft = st.iter().find(|s| s.beam >= full).map_or(0.0, |s| s.xi);
    crate::snnm::SnnmHull {
        lpp: ship.lpp,
        beam: ship.beam,
        draft: ship.draft,
        trim: 0.0,
        cb: ship.volume / (ship.lpp * ship.beam * ship.draft),
        kyy: ship.mass_props.kyy_m / ship.lpp,
        entrance: bow - fore,
        run: aft - st[0].xi,
    }
}
