//! The runs the sections share: a scenario run with its name in the error, the ch. 5.3 head-seas
//! run, the start-up to a speed, a run over seeds, a Monte Carlo study, and a trace column as points.

use aes_core::scenario::Scenario;
use aes_core::scenario::SternMotion;
use aes_core::studies::montecarlo::run_study;

/// A preset as the thesis ran it: with the maneuvering model's hull forces of Table 2.3
/// (`hull.forces = "table_2_3"`), which the thesis' ch. 5 rows compare; the presets themselves sail
/// the hull's own model.
pub(crate) fn thesis_preset(name: &str) -> Option<Scenario> {
    let mut sc = aes_core::scenario::presets::preset(name)?;
    sc.hull.forces = aes_core::ship::maneuvering::ManeuveringForces::Table23;
    sc.seakeeping.short_wave_force = aes_core::sea::seakeeping::params::ShortWaveForce::SalvesenF7;
    Some(sc)
}

/// A trace column as (t, y) points, y scaled.
pub(crate) fn points(r: &aes_core::RunResult, name: &str, scale: f64) -> Result<Vec<(f64, f64)>, String> {
    let t = r.trace.column("t_s").ok_or("no t_s")?;
    let y = r.trace.column(name).ok_or_else(|| format!("no column {name}"))?;
    Ok(t.iter().zip(y).map(|(&t, &y)| (t, y * scale)).collect())
}

/// The seeds a row that depends on the random sea is run with (each a whole realisation of the
/// sea: its phases and directions).
pub(crate) const SEEDS: std::ops::RangeInclusive<u64> = 1..=10;

/// `sc` run with each of [`SEEDS`].
pub(crate) fn seed_runs(sc: &Scenario) -> Result<Vec<aes_core::RunResult>, String> {
    SEEDS
        .map(|seed| {
            let mut c = sc.clone();
            c.sim.seed = seed;
            run(&c)
        })
        .collect()
}

/// Each run measured with `f`.
pub(crate) fn measure(
    runs: &[aes_core::RunResult],
    f: impl Fn(&aes_core::RunResult) -> Result<f64, String>,
) -> Result<Vec<f64>, String> {
    runs.iter().map(f).collect()
}

pub(crate) fn run(sc: &Scenario) -> Result<aes_core::RunResult, String> {
    aes_core::run(sc).map_err(|e| format!("{}: {e}", sc.name))
}

/// The ch. 5.3 run (head seas SS6, 25 kn, 80 s) at the thesis' depth h0 = 6 m, with these
/// as-printed switches and this stern motion.
pub(crate) fn head_seas(
    ap: aes_core::as_printed::AsPrintedParams,
    stern: SternMotion,
) -> Result<aes_core::RunResult, String> {
    let mut sc = thesis_preset("head-seas-ss6").ok_or("no preset")?;
    sc.set_hub_depth_m(6.0);
    sc.as_printed = ap;
    sc.seakeeping.stern_motion = stern;
    run(&sc)
}

/// Table 2.3's maneuvering model on the hull's ship, or with `as_printed.table_5_ship` on the
/// thesis' (L = 180 m): its straight-line resistance and surge mass.
pub(crate) fn table_2_3_model(
    ap: &aes_core::as_printed::AsPrintedParams,
) -> Result<aes_core::ship::maneuvering::Abkowitz, String> {
    let hull = Scenario::default().ship_hull()?;
    let b = hull.rigid_body(ap);
    let h = aes_core::scenario::HullParams::default();
    let u0 = aes_core::numerics::units::kn_to_m_s(h.linearization_speed_kn);
    Ok(aes_core::ship::maneuvering::Abkowitz::new(&h.abkowitz, h.symmetric_hull, u0, b.length_m, 1025.0))
}

/// Table 2.3's straight-line resistance at 25 kn on the thesis' ship over the hull's (eq. 2.15's,
/// Table 5.1's): the factor between the thesis' two resistances.
pub(crate) fn table_5_resistance_ratio() -> Result<f64, String> {
    use aes_core::as_printed::AsPrintedParams;
    let u25 = aes_core::numerics::units::kn_to_m_s(25.0);
    let t5 = table_2_3_model(&AsPrintedParams { table_5_ship: true, ..Default::default() })?;
    let own = table_2_3_model(&AsPrintedParams::default())?;
    Ok(t5.forces(u25, 0.0, 0.0).x / own.forces(u25, 0.0, 0.0).x)
}

/// The start-up ordered to `kn`, run 400 s to settle (Table 5.7's runs).
pub(crate) fn startup_to(kn: f64) -> Scenario {
    aes_core::scenario::presets::startup_to(kn, 400.0)
}

pub(crate) fn mc(sc: &Scenario, trials: u64) -> Result<aes_core::studies::montecarlo::StudySummary, String> {
    let mut sc = sc.clone();
    sc.monte_carlo.trials = trials;
    run_study(&sc)
}
