//! The blades' cavitation in a run on `propeller.model = "geometry"` (thesis ch. 3.2.2): the
//! ship's calm-water self-propulsion point at a speed, the ventilation onset derived from it
//! (`seakeeping.ventilation_onset = "derived"`), and the calm-water cavitation-inception speed.
//!
//! The speed-to-rpm relation is the plant's own: at ship speed u the shaft turns at the speed at
//! which both propellers carry the hull's straight-line resistance (`Plant::equilibrium_shaft_speed`,
//! the speed loop's calm-water map), and J is the propellers' advance ratio there (wake included).

use super::plant::Plant;
use crate::numerics::units::kn_to_m_s;
use crate::plant::blade::cavitation::{check_point, PointCavitation, PropellerBuckets, Water};
use crate::plant::blade::{analyse, BladeGeometry, Flow, ADVANCE_RATIO};
use crate::plant::propeller_losses::{derived_ventilation_on, LossParams, VentilationOnset};
use crate::scenario::{PropellerModelKind, Scenario};
use std::f64::consts::PI;

/// The slowest ship speed the inception search looks at \[kn\]: below it the shaft barely turns.
const SLOWEST_KN: f64 = 0.5;
/// The fastest \[kn\]: the speed orders' upper bound (`commands.speed_kn`).
const FASTEST_KN: f64 = 40.0;
/// The inception speed's fixed point stops when a step moves it less than this \[kn\].
const SPEED_TOL_KN: f64 = 1e-4;

/// A calm-water self-propulsion point.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CalmPoint {
    /// Ship speed \[kn\].
    pub ship_speed_kn: f64,
    /// Shaft speed n \[rev/s\].
    pub rev_per_s: f64,
    /// The propellers' advance ratio J \[-\].
    pub j: f64,
}

/// The steady self-propulsion point of `plant` at `ship_speed_kn` \[kn\].
pub fn calm_point(plant: &Plant, ship_speed_kn: f64) -> CalmPoint {
    let u = kn_to_m_s(ship_speed_kn);
    let w = plant.equilibrium_shaft_speed(u);
    CalmPoint { ship_speed_kn, rev_per_s: w / (2.0 * PI), j: plant.propeller_load(w, u).advance_ratio }
}

/// The blades of the scenario's geometry model (None with another model).
pub fn blades(sc: &Scenario) -> Result<Option<BladeGeometry>, String> {
    match (&sc.propeller.geometry, sc.propeller.model) {
        (Some(spec), PropellerModelKind::Geometry) => {
            spec.resolve(&sc.propeller.b_series_of()).map(Some).map_err(|(f, e)| format!("propeller.geometry.{f}: {e}"))
        }
        _ => Ok(None),
    }
}

/// The cavitation check of `g` (diameter `diameter_m` \[m\]) at the calm point `p` with the hub
/// `hub_depth_m` \[m\] deep: the lifting line's section loads in sea water on the sections' buckets.
pub fn check_at(g: &BladeGeometry, diameter_m: f64, p: CalmPoint, hub_depth_m: f64) -> Result<PointCavitation, String> {
    if !(p.rev_per_s > 0.0 && ADVANCE_RATIO.contains(&p.j)) {
        return Err(format!(
            "the shaft does not turn ahead within the analysed range at {:.2} kn (n {:.3} rev/s, J {:.3})",
            p.ship_speed_kn, p.rev_per_s, p.j
        ));
    }
    let flow = Flow::sea_water(diameter_m, p.rev_per_s);
    let a = analyse(g, p.j, &flow)?;
    let b = PropellerBuckets::cached(g, diameter_m)?;
    Ok(check_point(&b, &Water::of(&flow), &a, p.rev_per_s, hub_depth_m))
}

/// The ventilation onset a run uses and where it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Onset {
    pub kind: VentilationOnset,
    /// The loss model's parameters with it.
    pub losses: LossParams,
    /// With `derived`: the calm point it was found at (the run's fastest ordered speed) and the
    /// blades' cavitation onset h/R there \[-\].
    pub at: Option<CalmPoint>,
    pub cavitation_h_over_r: Option<f64>,
}

/// The run's fastest ordered speed \[kn\] (its initial speed and every speed order): where the
/// blades are loaded most, so their cavitation reaches deepest.
pub fn fastest_order_kn(sc: &Scenario) -> f64 {
    sc.commands.iter().filter_map(|c| c.speed_kn).fold(sc.initial.speed_kn, f64::max)
}

/// The loss model's parameters for a run of `sc` on `plant`: the generic loop, or with
/// `seakeeping.ventilation_onset = "derived"` the loop starting at
/// `propeller_losses::derived_ventilation_on` of the blades' cavitation onset at the run's fastest
/// ordered speed (the scenario's checks refuse "derived" without the geometry model).
pub fn onset(sc: &Scenario, plant: &Plant) -> Result<Onset, String> {
    let generic = sc.seakeeping.loss_params();
    let kind = sc.seakeeping.ventilation_onset;
    let plain = Onset { kind, losses: generic, at: None, cavitation_h_over_r: None };
    if kind == VentilationOnset::Generic {
        return Ok(plain);
    }
    let Some(g) = blades(sc)? else {
        return Err("seakeeping.ventilation_onset = \"derived\" needs propeller.model = \"geometry\"".into());
    };
    let u = fastest_order_kn(sc);
    if u <= 0.0 {
        // Never ordered ahead: no operating point to derive from; the generic loop stays.
        return Ok(plain);
    }
    let p = calm_point(plant, u);
    let hub = sc.ship_hull()?.hub_depth_m;
    let c = check_at(&g, sc.propeller.diameter_m, p, hub)
        .map_err(|e| format!("seakeeping.ventilation_onset = \"derived\": {e}"))?;
    let on = derived_ventilation_on(c.onset_h_over_r, generic.ventilation_on);
    Ok(Onset { kind, losses: generic.starting_at(on), at: Some(p), cavitation_h_over_r: Some(c.onset_h_over_r) })
}

/// The calm-water cavitation inception of a ship.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Inception {
    /// The calm point where the first sectioned radius reaches -Cp_min = sigma.
    pub at: CalmPoint,
    /// The hub depth it was found at \[m\].
    pub hub_depth_m: f64,
    /// The radius r/R that cavitates first \[-\].
    pub first_r_r: Option<f64>,
}

/// The lowest ship speed at which a section of `g` at 12 o'clock cavitates in calm water, the
/// shaft at `plant`'s self-propulsion speed and the hub `hub_depth_m` \[m\] deep; None when none
/// does up to 40 kn.
///
/// Along the calm-water line J changes little (the resistance and the thrust both go nearly as
/// u^2), so each section's V* goes as the shaft speed and its -Cp_min stays: the inception shaft
/// speed at the present point (`PropellerBuckets::inception_hz`) gives the next guess of the ship
/// speed, u_next = u n_i / n, repeated until it moves less than 1e-4 kn (a fixed point; the test
/// checks the margins on both sides of it).
pub fn calm_inception(
    g: &BladeGeometry,
    diameter_m: f64,
    plant: &Plant,
    hub_depth_m: f64,
) -> Result<Option<Inception>, String> {
    // Remembered: a run's summary, its Monte Carlo trials and the page's repeated runs ask again.
    // The search is deterministic, and depends on the plant only through the calm points it
    // visits; an entry is reused when the same blades, diameter and depth give the same points
    // (bit for bit) at the speeds it visited.
    type Entry = ((BladeGeometry, u64, u64), Vec<CalmPoint>, Option<Inception>);
    static CACHE: std::sync::OnceLock<std::sync::Mutex<Vec<Entry>>> = std::sync::OnceLock::new();
    const MAX: usize = 8;
    let cache = CACHE.get_or_init(Default::default);
    let key = (g.clone(), diameter_m.to_bits(), hub_depth_m.to_bits());
    let same = |visited: &[CalmPoint]| visited.iter().all(|p| calm_point(plant, p.ship_speed_kn) == *p);
    if let Ok(c) = cache.lock() {
        if let Some((_, _, r)) = c.iter().find(|(k, v, _)| *k == key && same(v)) {
            return Ok(*r);
        }
    }
    let mut visited = Vec::new();
    let r = search_inception(g, diameter_m, plant, hub_depth_m, &mut visited)?;
    if let Ok(mut c) = cache.lock() {
        if c.len() >= MAX {
            c.remove(0);
        }
        c.push((key, visited, r));
    }
    Ok(r)
}

/// `calm_inception`'s fixed point, noting the calm points it visits in `visited`.
fn search_inception(
    g: &BladeGeometry,
    diameter_m: f64,
    plant: &Plant,
    hub_depth_m: f64,
    visited: &mut Vec<CalmPoint>,
) -> Result<Option<Inception>, String> {
    let b = PropellerBuckets::cached(g, diameter_m)?;
    let mut u = 15.0;
    for _ in 0..40 {
        let p = calm_point(plant, u);
        visited.push(p);
        let flow = Flow::sea_water(diameter_m, p.rev_per_s);
        let a = analyse(g, p.j, &flow)?;
        let flows: Vec<_> = a.sections.iter().map(crate::plant::blade::cavitation::SectionFlow::from).collect();
        let Some(n_i) = b.inception_hz(&Water::of(&flow), &flows, hub_depth_m, p.rev_per_s) else {
            return Ok(None);
        };
        // Held within twice the speed range: a propeller that incepts beyond it stops there.
        let next = (u * n_i / p.rev_per_s).clamp(SLOWEST_KN, 2.0 * FASTEST_KN);
        if (next - u).abs() < SPEED_TOL_KN {
            if next > FASTEST_KN {
                return Ok(None);
            }
            let at = calm_point(plant, next);
            visited.push(at);
            let c = check_at(g, diameter_m, at, hub_depth_m)?;
            let first =
                c.sections.iter().filter(|s| s.sectioned).min_by(|x, y| x.margin.total_cmp(&y.margin)).map(|s| s.r_r);
            return Ok(Some(Inception { at, hub_depth_m, first_r_r: first }));
        }
        u = next;
    }
    Err(format!("the calm-water inception speed did not settle (last {u:.3} kn)"))
}

/// `calm_inception` of the scenario's geometry at its calm-water hub depth (None with another
/// propeller model or no inception up to 40 kn).
pub fn scenario_inception(sc: &Scenario, plant: &Plant) -> Result<Option<Inception>, String> {
    let Some(g) = blades(sc)? else { return Ok(None) };
    calm_inception(&g, sc.propeller.diameter_m, plant, sc.ship_hull()?.hub_depth_m)
}

/// Speeds in the summary and the command line \[kn\], for the message of a point.
pub fn describe(p: &CalmPoint) -> String {
    format!("{:.2} kn ({:.1} rpm, J {:.3})", p.ship_speed_kn, 60.0 * p.rev_per_s, p.j)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::presets::preset;

    /// head-seas-ss6 on DTMB 4119's blades (geometry model), at `speed_kn`.
    fn on_4119(speed_kn: f64) -> Scenario {
        let mut sc = preset("head-seas-ss6").unwrap();
        sc.propeller.model = PropellerModelKind::Geometry;
        sc.propeller.geometry =
            Some(crate::plant::propeller_geometry::GeometrySpec { name: "dtmb4119".into(), ..Default::default() });
        sc.initial.speed_kn = speed_kn;
        for c in sc.commands.iter_mut().filter(|c| c.speed_kn.is_some()) {
            c.speed_kn = Some(speed_kn);
        }
        sc
    }

    /// Ventilation onsets of the port shaft: rows where beta_T falls below 0.5 (a ventilated
    /// propeller keeps 0.3 of its thrust) from above it.
    fn onsets(r: &crate::sim::RunResult) -> usize {
        let b = r.trace.get(crate::signals::Signal::BetaT);
        b.windows(2).filter(|w| w[0] >= 0.5 && w[1] < 0.5).count()
    }

    /// The derived onset in a run. At 25 kn DTMB 4119's sections cavitate far deeper than the
    /// generic onset (h/R about 6.6), so the derived loop is the generic one and the run is the
    /// same to the bit. At 12 kn they do not cavitate while the disc is under water (onset below
    /// h/R 1), so ventilation waits for the tips at the surface (h/R 1.0, off at 1.2): the
    /// loss model's threshold falls from 1.1 to 1.0 and the ventilation onsets become fewer.
    /// The summary states the derived value beside the generic one. A derived onset without the
    /// geometry model is refused by name.
    #[test]
    fn head_seas_with_the_derived_onset() {
        for (kn, expect_generic) in [(25.0, true), (12.0, false)] {
            let generic = on_4119(kn);
            let mut derived = generic.clone();
            derived.seakeeping.ventilation_onset = VentilationOnset::Derived;
            let (a, b) = (crate::sim::run(&generic).unwrap(), crate::sim::run(&derived).unwrap());
            let note = b.summary.propeller.clone().unwrap();
            let h = note.derived_from_cavitation_h_over_r.unwrap();
            println!(
                "{kn} kn: cavitation onset h/R {h:.3} at {:?}; ventilation on {:.3} (generic {:.3}); onsets {} -> {}",
                note.derived_at,
                note.ventilation_on_h_over_r,
                note.generic_ventilation_on_h_over_r,
                onsets(&a),
                onsets(&b)
            );
            assert_eq!(note.ventilation_on_h_over_r, derived_ventilation_on(h, 1.1));
            assert_eq!(a.summary.propeller.as_ref().unwrap().ventilation_on_h_over_r, 1.1);
            assert!(note.note.contains("derived h/R"), "{}", note.note);
            if expect_generic {
                assert!(h > 1.1, "{h}");
                assert_eq!(a.trace.to_csv(), b.trace.to_csv(), "same loop, same run");
            } else {
                assert!(h < 1.0, "{h}");
                assert_eq!(note.ventilation_on_h_over_r, 1.0);
                assert!(onsets(&b) < onsets(&a), "{} vs {}", onsets(&b), onsets(&a));
            }
        }
        let mut bad = preset("head-seas-ss6").unwrap();
        bad.seakeeping.ventilation_onset = VentilationOnset::Derived;
        let e = bad.validate().unwrap_err().to_string();
        assert!(
            e.contains("seakeeping.ventilation_onset") && e.contains("needs propeller.model = \"geometry\""),
            "{e}"
        );
    }

    /// The calm-water inception speed of DTMB 4119 (4.5 m) on the thesis' ship: at the found
    /// speed the worst sectioned margin is zero (to 1e-3: the fixed point stops at 1e-4 kn),
    /// 0.2 kn slower no section cavitates and 0.2 kn faster one does; a deeper hub incepts at a
    /// higher speed (monotone), and it stays within the speed range.
    #[test]
    fn calm_water_inception_is_bounded_and_monotone() {
        let sc = on_4119(25.0);
        let plant = Plant::new(&sc).unwrap();
        let g = blades(&sc).unwrap().unwrap();
        let d = sc.propeller.diameter_m;
        let mut last = 0.0;
        for hub in [3.5, 6.0, 9.0] {
            let t = std::time::Instant::now();
            let i = calm_inception(&g, d, &plant, hub).unwrap().unwrap();
            let worst = |kn: f64| check_at(&g, d, calm_point(&plant, kn), hub).unwrap().worst_margin;
            let u = i.at.ship_speed_kn;
            println!(
                "hub {hub} m: inception {} first at r/R {:?} ({:?}); margins {:+.4} / {:+.4} / {:+.4}",
                describe(&i.at),
                i.first_r_r,
                t.elapsed(),
                worst(u - 0.2),
                worst(u),
                worst(u + 0.2)
            );
            assert!(worst(u).abs() < 1e-3, "{}", worst(u));
            assert!(worst(u - 0.2) > 0.0 && worst(u + 0.2) < 0.0);
            assert!(u > last && u < FASTEST_KN, "{u} after {last}");
            last = u;
        }
        // Remembered for the same plant; another speed-to-rpm relation (more resistance, so more
        // rpm at each speed) is not given the remembered answer: it incepts slower.
        let again = calm_inception(&g, d, &plant, 3.5).unwrap().unwrap();
        let mut heavier = plant.clone();
        heavier.extra_resistance = 2.0e5;
        let other = calm_inception(&g, d, &heavier, 3.5).unwrap().unwrap();
        assert_eq!(again, calm_inception(&g, d, &plant, 3.5).unwrap().unwrap());
        assert!(other.at.ship_speed_kn < again.at.ship_speed_kn, "{other:?} vs {again:?}");
    }
}
