//! Standard maneuvers of a scenario's ship, as a trials booklet gives them (IMO resolution
//! MSC.137(76), "Standards for ship manoeuvrability", and its explanatory notes MSC/Circ.1053):
//! the 35 degree turning circle, the 10/10 and 20/20 zig-zags with the initial turning ability, a
//! coasting stop, the full-astern stopping test (`studies::stopping`, through the whole drive
//! train), and a static drift and pure yaw table of the hull's own forces, the way captive
//! model tests are reported.
//!
//! The hull moves under the scenario's maneuvering model with its propellers held at the shaft
//! speed that carries the approach speed in calm water (constant rpm: a trial's engine setting),
//! the thrust following the ship's speed through the propellers' open-water curves; the rudder
//! moves at the steering gear's swing rate. The drive train is not simulated here: these are the
//! hull's and rudders' answers, which the booklet is about.

use crate::numerics::units::{kn_to_m_s, m_s_to_kn};
use crate::numerics::Integrator;
use crate::scenario::Scenario;
use crate::ship::hull::N_SHAFTS;
use crate::ship::maneuvering::ManeuveringForces;
use crate::sim::plant::{Held, HullModel, Plant, State, HEADING, NX, SURGE, SWAY, X_POS, YAW_RATE, Y_POS};
use serde::Serialize;

/// Time step of the maneuvers \[s\] (the hull's slowest motions take tens of seconds).
const DT_S: f64 = 0.1;
/// Longest maneuver \[s\].
const MAX_S: f64 = 1800.0;
/// Hard-over rudder of the turning circle \[deg\] (IMO).
pub const TURNING_RUDDER_DEG: f64 = 35.0;
/// Coasting stops at this speed \[kn\].
const STOPPED_KN: f64 = 5.0;

/// One sample of a maneuver: time \[s\], position \[m\] (north, east), heading \[deg\], speed \[kn\],
/// rudder \[deg\] (positive turns to starboard, as a booklet plots it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    pub t_s: f64,
    pub x_m: f64,
    pub y_m: f64,
    pub heading_deg: f64,
    pub speed_kn: f64,
    pub rudder_deg: f64,
}

/// The turning circle to starboard with 35 degrees of rudder.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Turning {
    pub advance_m: f64,
    pub transfer_m: f64,
    pub tactical_diameter_m: f64,
    pub steady_diameter_m: f64,
    /// Steady speed over the approach speed \[-\].
    pub speed_ratio: f64,
    pub steady_yaw_rate_deg_s: f64,
    pub track: Vec<Sample>,
}

/// A zig-zag (`rudder_deg` / `rudder_deg`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ZigZag {
    pub rudder_deg: f64,
    pub first_overshoot_deg: f64,
    pub second_overshoot_deg: f64,
    /// Distance run from the rudder order until the heading has changed by `rudder_deg` \[m\].
    pub initial_turning_m: f64,
    pub track: Vec<Sample>,
}

/// Coasting from the approach speed with the propellers stopped.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Coasting {
    pub to_kn: f64,
    pub track_reach_m: f64,
    pub time_s: f64,
}

/// A row of the captive table: drift angle \[deg\] or r' = r L / U, and the side force and yaw
/// moment of the hull with its rudders at 0 deg and the propellers at the approach speed's
/// thrust, as Y' = Y / ((1/2) rho L T U^2), N' = N / ((1/2) rho L^2 T U^2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CaptiveRow {
    pub drift_deg: f64,
    pub r_prime: f64,
    pub y_prime: f64,
    pub n_prime: f64,
}

/// One IMO criterion and whether the ship meets it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Criterion {
    pub name: String,
    pub value: f64,
    pub limit: f64,
    pub unit: String,
    pub pass: bool,
}

/// The booklet.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Booklet {
    pub scenario: String,
    pub model: String,
    pub length_m: f64,
    pub approach_kn: f64,
    pub shaft_rpm: f64,
    pub turning: Turning,
    pub zigzag_10: ZigZag,
    pub zigzag_20: ZigZag,
    pub coasting: Coasting,
    /// The full-astern stopping test (the drive train simulated: `studies::stopping`), or None
    /// and why it could not run (Table 2.3's hull holds ahead only).
    pub stopping: Option<crate::studies::stopping::Stopping>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stopping_refused: Option<String>,
    pub static_drift: Vec<CaptiveRow>,
    /// The same static drift of the bare hull and its slope beside Clarke's regression (None
    /// without the hull's own forces).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bare_drift: Option<BareDrift>,
    pub pure_yaw: Vec<CaptiveRow>,
    pub criteria: Vec<Criterion>,
}

/// The hull moving at a fixed shaft speed.
struct Trial {
    plant: Plant,
    omega: f64,
    u0: f64,
    rate: f64,
}

impl Trial {
    fn thrust(&self, x: &State) -> f64 {
        let inflow = self.plant.inflow(x[SURGE], x[SWAY], x[YAW_RATE]);
        N_SHAFTS as f64 * self.plant.propeller_load(self.omega, inflow.speed).thrust_n
    }

    /// Runs from straight running at the approach speed; `order(t, heading change \[deg\],
    /// speed \[m/s\])` gives the rudder order [rad, positive to starboard] or None to stop.
    fn run(&self, propelled: bool, mut order: impl FnMut(f64, f64, f64) -> Option<f64>) -> Vec<Sample> {
        let mut x: State = [0.0; NX];
        x[SURGE] = self.u0;
        let mut h = Held {
            throttle: [0.0; crate::sim::plant::N_SETS],
            field_voltage: [0.0; crate::sim::plant::N_SETS],
            slip: [0.0; N_SHAFTS],
            rudder: 0.0,
            ..Held::default()
        };
        let mut out = Vec::new();
        let mut t = 0.0;
        while t <= MAX_S {
            let speed = libm::hypot(x[SURGE], x[SWAY]);
            let change = x[HEADING].to_degrees();
            out.push(Sample {
                t_s: t,
                x_m: x[X_POS],
                y_m: x[Y_POS],
                heading_deg: change,
                speed_kn: m_s_to_kn(speed),
                rudder_deg: -h.rudder.to_degrees(),
            });
            let Some(want) = order(t, change, speed) else { break };
            // Our rudder turns to port when positive.
            let step = self.rate * DT_S;
            h.rudder += (-want - h.rudder).clamp(-step, step);
            let psi0 = x[HEADING];
            let heading = (psi0, libm::sin(psi0), libm::cos(psi0));
            Integrator::Rk4.step(&mut x, t, DT_S, |_, y, dx| {
                let thrust = if propelled { self.thrust(y) } else { 0.0 };
                self.plant.hull_derivatives(y, &h, thrust, heading, dx);
            });
            if !x.iter().all(|v| v.is_finite()) {
                break;
            }
            t += DT_S;
        }
        out
    }
}

/// The turning circle from a track: advance and transfer at 90 degrees of heading change,
/// tactical diameter at 180, steady diameter and speed from the last full turn.
fn turning(track: Vec<Sample>, u0_kn: f64) -> Result<Turning, String> {
    let at = |deg: f64| track.iter().position(|s| s.heading_deg >= deg);
    let (Some(i90), Some(i180)) = (at(90.0), at(180.0)) else {
        return Err("the ship did not turn through 180 degrees with 35 degrees of rudder".into());
    };
    let last = track[track.len() - 1];
    let (rate, speed) = {
        let k = track.iter().position(|s| s.t_s >= last.t_s - 60.0).unwrap_or(0);
        let a = track[k];
        ((last.heading_deg - a.heading_deg) / (last.t_s - a.t_s), 0.5 * (a.speed_kn + last.speed_kn))
    };
    Ok(Turning {
        advance_m: track[i90].x_m,
        transfer_m: track[i90].y_m,
        tactical_diameter_m: track[i180].y_m,
        steady_diameter_m: 2.0 * kn_to_m_s(speed) / rate.to_radians(),
        speed_ratio: speed / u0_kn,
        steady_yaw_rate_deg_s: rate,
        track,
    })
}

/// A zig-zag of `deg` / `deg` from a run that reverses the rudder at each heading check.
fn zigzag(trial: &Trial, deg: f64) -> ZigZag {
    let mut sign = 1.0;
    let mut reversals = 0;
    let track = trial.run(true, |_, change, _| {
        if sign * change >= deg {
            sign = -sign;
            reversals += 1;
        }
        (reversals < 4).then_some(sign * deg.to_radians())
    });
    // The overshoots are the extremes of heading between the checks.
    let first_check = track.iter().position(|s| s.heading_deg >= deg).unwrap_or(track.len() - 1);
    let second_check = track[first_check..].iter().position(|s| s.heading_deg <= -deg).map(|i| i + first_check);
    let first =
        track[first_check..second_check.unwrap_or(track.len())].iter().map(|s| s.heading_deg).fold(f64::MIN, f64::max);
    let second = second_check
        .map(|j| {
            let end = track[j..].iter().position(|s| s.heading_deg >= deg).map(|i| i + j).unwrap_or(track.len());
            -track[j..end].iter().map(|s| s.heading_deg).fold(f64::MAX, f64::min)
        })
        .unwrap_or(f64::NAN);
    let run =
        |i: usize| track[..=i].windows(2).map(|w| libm::hypot(w[1].x_m - w[0].x_m, w[1].y_m - w[0].y_m)).sum::<f64>();
    ZigZag {
        rudder_deg: deg,
        first_overshoot_deg: first - deg,
        second_overshoot_deg: second - deg,
        initial_turning_m: run(first_check),
        track,
    }
}

/// A maneuver's track that stayed physical, or a refusal naming the maneuver, the hull forces and
/// the range they hold: at a fixed shaft speed (or none) a ship cannot gain speed in a turn, a
/// zig-zag or a coast, so a speed past its approach speed by half (or any number that is not
/// finite) is the hull model diverging, and no verdict may be given on its numbers.
fn held_physical(sc: &Scenario, name: &str, track: &[Sample], approach_kn: f64) -> Result<(), String> {
    let limit_kn = 1.5 * approach_kn;
    let bad = track.iter().find(|s| {
        ![s.t_s, s.x_m, s.y_m, s.heading_deg, s.speed_kn].iter().all(|v| v.is_finite()) || s.speed_kn > limit_kn
    });
    // The run stops before the first state that is not finite, after the speed has run away.
    let Some(s) = bad.copied() else {
        return Ok(());
    };
    let forces = serde_json::to_value(sc.hull.forces).ok().and_then(|v| v.as_str().map(str::to_string));
    let forces = forces.unwrap_or_default();
    let range = <ManeuveringForces as crate::params::Param>::choices()
        .iter()
        .find(|(n, _)| *n == forces)
        .map_or(String::new(), |(_, label)| format!(" ({label})"));
    let speed = match s.speed_kn {
        v if !v.is_finite() => "not a number".to_string(),
        v if v < 1e6 => format!("{v:.1} kn"),
        v => format!("{v:.2e} kn"),
    };
    Err(format!(
        "the {name} diverged under hull.forces = \"{forces}\"{range}: at t = {:.1} s the speed was {speed}, \
         past 1.5 times the approach speed of {approach_kn} kn, which a ship at a fixed shaft speed cannot reach; \
         these hull forces do not hold this maneuver, so the booklet judges none of its numbers (hull.forces = \
         \"own_hull\" holds it)",
        s.t_s
    ))
}

/// IMO's first-overshoot limit of the 10/10 zig-zag for L/V \[s\]: 10 deg below 10 s, 20 deg above
/// 30 s, 5 + (L/V)/2 between; and the second overshoot's: 25, 40, 17.5 + 0.75 L/V.
pub fn zigzag_10_limits(l_over_v_s: f64) -> (f64, f64) {
    let a = l_over_v_s.clamp(10.0, 30.0);
    (5.0 + 0.5 * a, 17.5 + 0.75 * a)
}

/// The booklet of `sc` at its first ordered speed (or its initial speed).
pub fn booklet(sc: &Scenario) -> Result<Booklet, String> {
    if sc.hull.model == crate::ship::maneuvering::HullModelKind::Surge {
        // Named by the field and a study that turns, so the reader knows what would make it run.
        return Err("hull.model: \"surge\" goes straight only; the maneuvers need hull.model = \"maneuvering\" \
             (or a study that turns, such as turn-360)"
            .into());
    }
    let plant = Plant::new(sc)?;
    let approach_kn = sc.commands.iter().find_map(|c| c.speed_kn).unwrap_or(sc.initial.speed_kn);
    if !(3.0..=40.0).contains(&approach_kn) {
        return Err(format!("the approach speed {approach_kn} kn (the first speed order) must be 3 to 40 kn"));
    }
    let u0 = kn_to_m_s(approach_kn);
    let omega = plant.equilibrium_shaft_speed(u0);
    let l = plant.hull_length;
    let trial = Trial { plant, omega, u0, rate: sc.rudder.swing_rate_rad_s };
    let hard = TURNING_RUDDER_DEG.to_radians();
    let track = trial.run(true, |_, change, _| (change < 540.0).then_some(hard));
    let held = |name: &str, track: &[Sample]| held_physical(sc, name, track, approach_kn);
    held("turning circle", &track)?;
    let turning = turning(track, approach_kn)?;
    let zigzag_10 = zigzag(&trial, 10.0);
    held("10/10 zig-zag", &zigzag_10.track)?;
    let zigzag_20 = zigzag(&trial, 20.0);
    held("20/20 zig-zag", &zigzag_20.track)?;
    for z in [&zigzag_10, &zigzag_20] {
        if !(z.first_overshoot_deg.is_finite() && z.second_overshoot_deg.is_finite()) {
            return Err(format!(
                "the {0}/{0} zig-zag did not reach its heading checks within {MAX_S} s, so it has no overshoots to judge",
                z.rudder_deg
            ));
        }
    }
    let coast = trial.run(false, |_, _, speed| (m_s_to_kn(speed) > STOPPED_KN).then_some(0.0));
    held("coasting stop", &coast)?;
    let end = coast[coast.len() - 1];
    let coasting = Coasting { to_kn: STOPPED_KN, track_reach_m: end.x_m, time_s: end.t_s };
    let (static_drift, pure_yaw) = captive(&trial, sc)?;
    let stopping = crate::studies::stopping::stopping_test(sc, approach_kn, l);
    let l_over_v = l / u0;
    let (first_limit, second_limit) = zigzag_10_limits(l_over_v);
    let crit = |name: &str, value: f64, limit: f64, unit: &str| Criterion {
        name: name.into(),
        value,
        limit,
        unit: unit.into(),
        pass: value <= limit,
    };
    let mut criteria = vec![
        crit("turning ability: advance", turning.advance_m / l, 4.5, "L"),
        crit("turning ability: tactical diameter", turning.tactical_diameter_m / l, 5.0, "L"),
        crit(
            "initial turning ability: track to 10 deg of heading with 10 deg rudder",
            zigzag_10.initial_turning_m / l,
            2.5,
            "L",
        ),
        crit("yaw checking: 10/10 first overshoot", zigzag_10.first_overshoot_deg, first_limit, "deg"),
        crit("yaw checking: 10/10 second overshoot", zigzag_10.second_overshoot_deg, second_limit, "deg"),
        crit("yaw checking: 20/20 first overshoot", zigzag_20.first_overshoot_deg, 25.0, "deg"),
    ];
    criteria.extend(stopping.as_ref().ok().map(|s| {
        use crate::studies::stopping::{IMO_TRACK_REACH_ALLOWED_L, IMO_TRACK_REACH_L};
        let name = format!(
            "stopping ability: track reach in the full-astern test (naval ship: a reference; up to \
             {IMO_TRACK_REACH_ALLOWED_L} L may be allowed)"
        );
        crit(&name, s.track_reach_l, IMO_TRACK_REACH_L, "L")
    }));
    let (stopping, stopping_refused) = match stopping {
        Ok(s) => (Some(s), None),
        Err(e) => (None, Some(e)),
    };
    Ok(Booklet {
        scenario: sc.name.clone(),
        model: format!("{:?}", sc.hull.forces),
        length_m: l,
        approach_kn,
        shaft_rpm: omega * 60.0 / (2.0 * std::f64::consts::PI),
        turning,
        zigzag_10,
        zigzag_20,
        coasting,
        stopping,
        stopping_refused,
        bare_drift: bare_drift(&trial, sc)?,
        static_drift,
        pure_yaw,
        criteria,
    })
}

/// Static drift as captive tests of a bare hull report it: the rows with the rudders and
/// propellers off, and the side force's slope at small drift (its 2 deg point, Y' per rad in the
/// table's normalisation) of the bare hull, of the appended ship and of Clarke et al.'s (1983)
/// bare-hull regression, Y'_v = -pi (T/L)^2 (1 + 0.40 C_B B/T) over (1/2) rho L^2 U^2, times L/T.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BareDrift {
    pub rows: Vec<CaptiveRow>,
    pub slope_bare_per_rad: f64,
    pub slope_appended_per_rad: f64,
    pub slope_clarke_per_rad: f64,
}

/// [`BareDrift`] of the trial's hull (None without the hull's own forces).
fn bare_drift(trial: &Trial, sc: &Scenario) -> Result<Option<BareDrift>, String> {
    let HullModel::Own { model, .. } = &trial.plant.hull_model else {
        return Ok(None);
    };
    let hull = sc.ship_hull()?;
    let (l, t, u) = (model.length, hull.draft_m, trial.u0);
    let q = 0.5 * hull.rho * l * t * u * u;
    let row = |drift_deg: f64| {
        let b = drift_deg.to_radians();
        let f = model.forces(u * libm::cos(b), u * libm::sin(b), 0.0);
        CaptiveRow { drift_deg, r_prime: 0.0, y_prime: f.y / q, n_prime: f.n / (q * l) }
    };
    let rows: Vec<CaptiveRow> = (0..=6).map(|i| row(2.0 * i as f64)).collect();
    let (appended, _) = captive(trial, sc)?;
    let two = 2f64.to_radians();
    Ok(Some(BareDrift {
        slope_bare_per_rad: rows[1].y_prime / two,
        slope_appended_per_rad: appended.get(1).map_or(f64::NAN, |r| r.y_prime / two),
        slope_clarke_per_rad: model.derivatives.yv * l / t,
        rows,
    }))
}

/// The static drift (0 to 12 deg) and pure yaw (r' 0 to 0.6) tables at the approach speed.
fn captive(trial: &Trial, sc: &Scenario) -> Result<(Vec<CaptiveRow>, Vec<CaptiveRow>), String> {
    let HullModel::Own { model, .. } = &trial.plant.hull_model else {
        return Ok((Vec::new(), Vec::new()));
    };
    let hull = sc.ship_hull()?;
    let (l, t, u) = (model.length, hull.draft_m, trial.u0);
    let q = 0.5 * hull.rho * l * t * u * u;
    let mut straight: State = [0.0; NX];
    straight[SURGE] = u;
    let each = trial.thrust(&straight) / N_SHAFTS as f64;
    let row = |drift_deg: f64, r_prime: f64| {
        let b = drift_deg.to_radians();
        // Drift to starboard: the water meets the hull from starboard, v > 0.
        let (uu, v, r) = (u * libm::cos(b), u * libm::sin(b), r_prime * u / l);
        let f = model.forces(uu, v, r);
        let (_, yr, nr) = model.rudders.forces(hull.rho, v, r, trial.plant.surge.advance_speed(uu), each, 0.0);
        // The captive force is the water's: without the rigid body's m u r.
        let y = f.y + model.mass * uu * r + yr;
        CaptiveRow { drift_deg, r_prime, y_prime: y / q, n_prime: (f.n + nr) / (q * l) }
    };
    Ok(((0..=6).map(|i| row(2.0 * i as f64, 0.0)).collect(), (0..=6).map(|i| row(0.0, 0.1 * i as f64)).collect()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The refusal of a straight-line hull names the field and a study that turns, and that study
    /// does give a booklet (the advice is one the reader can follow).
    #[test]
    fn a_diverging_maneuver_is_refused_naming_it_and_the_hull_forces() {
        // Table 2.3's polynomials as printed run away in the turning circle (the advance was
        // -2e21 m and judged "pass" against IMO's 4.5 L before this refusal).
        let sc = crate::scenario::presets::preset("as-printed").unwrap();
        let e = booklet(&sc).unwrap_err();
        for words in ["the turning circle diverged", "hull.forces = \"table_2_3\"", "Table 2.3", "judges none"] {
            assert!(e.contains(words), "{words:?} not in {e}");
        }
        assert!(!e.contains("NaN") && !e.contains("inf"), "{e}");
    }

    #[test]
    fn a_surge_hull_is_refused_naming_the_field_and_a_study_that_runs() {
        let sc = crate::scenario::presets::preset("startup").expect("startup");
        let e = booklet(&sc).expect_err("the surge model cannot turn");
        assert!(e.contains("hull.model = \"maneuvering\"") && e.contains("turn-360"), "{e}");
        let turn = crate::scenario::presets::preset("turn-360").expect("turn-360");
        assert!(booklet(&turn).is_ok(), "the study the message names must run");
        let mut switched = sc.clone();
        switched.hull.model = crate::ship::maneuvering::HullModelKind::Maneuvering;
        assert!(booklet(&switched).is_ok(), "the field the message names must make it run");
    }
}
