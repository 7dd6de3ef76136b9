//! `aes-sim bench`: realtime factor of a preset, the time to build the RAO tables, or the time
//! of a propeller's open-water curve from its blades.

use crate::common::{emit_json, load, read_bounded, shorten, Failure, Threads};
use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
use aes_core::sea::seakeeping::tables::{RaoTable, SeakeepingGrid};
use aes_core::Simulation;
use std::time::Instant;

// The command line of `aes-sim bench`.
#[derive(clap::Args)]
pub struct Args {
    /// Preset to time, `seakeeping` (the RAO tables) or `propeller` (DTMB 4119's open-water curve).
    #[arg(default_value = "startup")]
    name: String,
    /// Repetitions (the best is reported).
    #[arg(long, default_value_t = 3)]
    repeat: u32,
    /// `bench seakeeping`: an embedded hull's name or an offsets CSV to time beside the 5415
    /// (its loading: --set ship.hull.draft_m=..., ship.hull.kg_m=...).
    #[arg(long)]
    hull: Option<String>,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { name, repeat, hull, sets }: Args) -> Result<(), Failure> {
    let most = aes_core::scenario::MAX_BENCH_REPEAT;
    if !(1..=most).contains(&repeat) {
        return Err(format!("--repeat = {repeat}: must be a whole number from 1 to {most}").into());
    }
    // A flag the chosen benchmark does not read would be ignored without a word: refused.
    if name != "seakeeping" && hull.is_some() {
        return Err(format!("--hull is for `bench seakeeping` only, not `bench {}`", shorten(&name)).into());
    }
    if name == "propeller" && !sets.is_empty() {
        return Err("--set: `bench propeller` times DTMB 4119's own blades and takes no parameter".into());
    }
    if name == "seakeeping" && hull.is_none() && !sets.is_empty() {
        return Err("--set: `bench seakeeping` sets only the loading of --hull's hull (give --hull)".into());
    }
    if name == "seakeeping" {
        seakeeping(repeat, hull, sets)
    } else if name == "propeller" {
        propeller(repeat)
    } else {
        preset(name, repeat, sets)
    }
}

/// `aes-sim bench seakeeping`: the time to build the DTMB 5415's RAO tables (and another hull's).
fn seakeeping(repeat: u32, hull: Option<String>, sets: Vec<String>) -> Result<(), Failure> {
    let grid = SeakeepingGrid::default();
    // The other hull's resolved definition (the scenario's `ship.hull` with --hull and --set).
    let other = match &hull {
        None => None,
        Some(h) => {
            let spec = if aes_core::ship::hull::HULL_NAMES.contains(&h.as_str()) && h != "custom" {
                aes_core::ship::hull::HullSpec { name: h.clone(), ..Default::default() }
            } else {
                let text = read_bounded(h, aes_core::ship::sections::MAX_HULL_BYTES as u64, "a hull offsets file")?;
                aes_core::ship::hull::HullSpec { name: "custom".into(), offsets_csv: text, ..Default::default() }
            };
            // Every --set ship.hull.FIELD=VALUE at once (a custom hull is whole only with all).
            let mut v = serde_json::to_value(&spec).map_err(|e| e.to_string())?;
            for s in &sets {
                let (p, val) =
                    s.split_once('=').ok_or_else(|| format!("--set '{}': expected PATH=VALUE", shorten(s)))?;
                let field = p.trim().strip_prefix("ship.hull.").ok_or_else(|| {
                    format!("--set '{}': bench seakeeping takes ship.hull.FIELD=VALUE only", shorten(s))
                })?;
                v[field] = serde_json::from_str(val.trim())
                    .unwrap_or_else(|_| serde_json::Value::String(val.trim().to_string()));
            }
            let spec: aes_core::ship::hull::HullSpec =
                serde_json::from_value(v).map_err(|e| format!("ship.hull: {}", shorten(&e.to_string())))?;
            let mut check = aes_core::checks::Validator::new();
            check.section("ship.hull", |c| spec.validate(c, 1025.0));
            check.finish().map_err(|e| e.to_string())?;
            let hull = spec.resolve(1025.0).map_err(|(f, e)| format!("ship.hull.{f}: {e}"))?;
            Some(hull.strip_ship()?)
        }
    };
    let five = Ship::dtmb5415();
    // Best of `repeat`, the two hulls alternating so that both see the same machine.
    let time = |ship: &Ship| {
        let t0 = Instant::now();
        let rad = ship.radiation_table(&default_omega_grid());
        let t1 = Instant::now();
        std::hint::black_box(RaoTable::from_radiation(ship, &rad, &grid));
        ((t1 - t0).as_secs_f64(), t1.elapsed().as_secs_f64())
    };
    let (mut best, mut best_other) = ((f64::INFINITY, f64::INFINITY), (f64::INFINITY, f64::INFINITY));
    for _ in 0..repeat.max(1) {
        let t = time(&five);
        best = (best.0.min(t.0), best.1.min(t.1));
        if let Some(o) = &other {
            let t = time(o);
            best_other = (best_other.0.min(t.0), best_other.1.min(t.1));
        }
    }
    // Issue 31: the same table built part by part on all threads (the command line's way), and
    // the default operability polar on it, side by side with the one-thread build above.
    let printed = aes_core::scenario::AsPrintedParams::default();
    let (mut parallel, mut polar) = (f64::INFINITY, f64::INFINITY);
    let mut same_bits = true;
    let serial = RaoTable::compute_as(&five, &grid, &printed)?.values();
    let sc = aes_core::Scenario::default();
    sc.rao_table_with(&Threads)?;
    let scatter = aes_core::studies::operability::scatter::Scatter::north_atlantic();
    for _ in 0..repeat.max(1) {
        let t0 = Instant::now();
        let t = RaoTable::compute_with(&five, &grid, &printed, &Threads)?;
        parallel = parallel.min(t0.elapsed().as_secs_f64());
        same_bits &= t.values() == serial;
        let t0 = Instant::now();
        let setup = aes_core::studies::operability::PolarSetup::new(
            &sc,
            aes_core::studies::operability::PolarSpec::default(),
            Some(&scatter),
        )?;
        let rows: Vec<_> = {
            use rayon::prelude::*;
            (0..setup.spec.speeds_kn.len()).into_par_iter().map(|j| setup.speed(j, Some(&scatter))).collect()
        };
        std::hint::black_box(aes_core::studies::operability::assemble(&sc, &setup, rows, Some(&scatter))?);
        polar = polar.min(t0.elapsed().as_secs_f64());
    }
    let one_thread = best.0 + best.1;
    let mut out = serde_json::json!({
        "workload": format!("DTMB 5415: sectional coefficients of {} strips at 48 encounter frequencies, then RAOs and drift on the default 40 x 8 x 13 grid", five.strips.len()),
        "sections_s": best.0,
        "rao_grid_s": best.1,
        "total_s": one_thread,
        "threads": rayon::current_num_threads(),
        "table_on_all_threads_s": parallel,
        "table_speed_up": one_thread / parallel,
        "table_same_bits": same_bits,
        "operability_polar": "the default polar (11 speeds x 24 headings x sea states 2-6, and the IACS North Atlantic scatter diagram) on the built table, all threads",
        "operability_polar_s": polar,
        "polar_over_one_table_build": polar / one_thread,
    });
    if let Some(o) = &other {
        out["hull"] = serde_json::json!({
            "strips": o.strips.len(),
            "sections_s": best_other.0,
            "rao_grid_s": best_other.1,
            "total_s": best_other.0 + best_other.1,
            // Issue 15's measure: this hull's table build over the 5415's, same run.
            "over_dtmb5415": (best_other.0 + best_other.1) / (best.0 + best.1),
        });
    }
    emit_json(&out)?;
    Ok(())
}

/// `aes-sim bench propeller`: DTMB 4119's open-water curve at 25 advance ratios by the vortex
/// lattice (what `aes-sim propeller` computes by default; issue 54's target is under 50 ms
/// natively), and beside it the lifting line's curve, the sections' cavitation buckets, the
/// margins at the 25 points, and a run's first-quadrant table. Best of `repeat` each.
fn propeller(repeat: u32) -> Result<(), Failure> {
    use aes_core::plant::blade::{self, cavitation};
    let spec = aes_core::plant::propeller_geometry::GeometrySpec { name: "dtmb4119".into(), ..Default::default() };
    let g = spec
        .resolve(&aes_core::plant::propeller::PropellerParams::default().b_series_of())
        .map_err(|(f, e)| format!("propeller.geometry.{f}: {e}"))?;
    let flow = blade::Flow::fresh_water(0.3048, 10.0);
    let js: Vec<f64> = (0..25).map(|k| 1.2 * k as f64 / 24.0).collect();
    let best = |f: &mut dyn FnMut() -> Result<(), String>| -> Result<f64, String> {
        let mut b = f64::INFINITY;
        for _ in 0..repeat {
            let t0 = Instant::now();
            f()?;
            b = b.min(t0.elapsed().as_secs_f64());
        }
        Ok(b)
    };
    let lattice_s = best(&mut || {
        std::hint::black_box(blade::vortex_lattice::open_water(&g, &js, &flow)?);
        Ok(())
    })?;
    let mut curve = Vec::new();
    let curve_s = best(&mut || {
        curve = blade::open_water(&g, &js, &flow)?;
        Ok(())
    })?;
    let mut buckets = None;
    let buckets_s = best(&mut || {
        buckets = Some(cavitation::PropellerBuckets::new(&g, flow.diameter_m)?);
        Ok(())
    })?;
    let b = buckets.ok_or("no buckets")?;
    let w = cavitation::Water::of(&flow);
    let margins_s = best(&mut || {
        for a in &curve {
            std::hint::black_box(cavitation::check_point(&b, &w, a, flow.rev_per_s, 1.0));
        }
        Ok(())
    })?;
    let table_s = best(&mut || {
        let curves = aes_core::plant::propeller_table::lattice_curves(&g, blade::Flow::sea_water(4.5, 5.0))?;
        std::hint::black_box(aes_core::plant::propeller_table::GeometryPropeller::build(&g, &curves)?);
        Ok(())
    })?;
    emit_json(&serde_json::json!({
        "workload": "DTMB 4119 (D 0.3048 m, 10 rev/s, fresh water): the vortex lattice at 25 advance ratios, J 0 to 1.2",
        "open_water_25_j_s": lattice_s,
        // The lifting line at the same 25 (its sections give the cavitation margins).
        "lifting_line_25_j_s": curve_s,
        "converged": curve.iter().filter(|a| a.converged).count(),
        // Only with --depth-m (or a scenario): a panel solution per section.
        "cavitation_buckets_s": buckets_s,
        "buckets": b.buckets.len(),
        "margins_25_j_s": margins_s,
        // A run on the geometry model builds this once per geometry and flow (the lattice's).
        "run_table_s": table_s,
        "repeat": repeat,
    }))?;
    Ok(())
}

/// `aes-sim bench PRESET`: simulated seconds per wall-clock second, and where the time goes.
fn preset(name: String, repeat: u32, sets: Vec<String>) -> Result<(), Failure> {
    let sc = load(&format!("preset:{name}"), &sets)?;
    let mut best = f64::INFINITY;
    let mut steps = 0;
    for _ in 0..repeat.max(1) {
        let t0 = Instant::now();
        let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
        sim.advance(u64::MAX).map_err(|e| e.to_string())?;
        let r = sim.finish();
        best = best.min(t0.elapsed().as_secs_f64());
        steps = r.summary.steps;
    }
    let sim_s = sc.sim.duration_s;
    // Where a run's time goes: the same run with a clock read at the end of each part of
    // every step (the repetition with the least in all), less the clock's own cost.
    let lap_s = clock_lap_s();
    let mut parts: Option<(f64, [f64; 4], f64)> = None;
    for _ in 0..repeat.max(1) {
        let t0 = Instant::now();
        let mut sim = Simulation::new(&sc).map_err(|e| e.to_string())?;
        let setup = t0.elapsed().as_secs_f64();
        let mut probe = LapProbe { last: Instant::now(), spent: [0.0; 4], laps: 0 };
        sim.advance_probed(u64::MAX, &mut probe).map_err(|e| e.to_string())?;
        let per_part = probe.laps as f64 / 4.0;
        let spent = probe.spent.map(|t| (t - per_part * lap_s).max(0.0));
        let t1 = Instant::now();
        std::hint::black_box(sim.finish());
        let finish = t1.elapsed().as_secs_f64();
        let total = setup + spent.iter().sum::<f64>() + finish;
        if parts.is_none_or(|(s, p, f)| total < s + p.iter().sum::<f64>() + f) {
            parts = Some((setup, spent, finish));
        }
    }
    // The irreducible part in waves: the bare superposition of the wave components (one sum
    // per sample period, as the run does it).
    let mut wave_sums_s = None;
    for _ in 0..repeat.max(1) {
        if let Some(mut sea) = aes_core::sim::seaway::Seaway::new(&sc)? {
            let n = (sim_s / sc.stepping.sea_sample_s).round() as u64;
            sea.refresh(12.86, 0.0);
            let t0 = Instant::now();
            let mut acc = 0.0;
            for i in 0..n {
                let t = i as f64 * sc.stepping.sea_sample_s;
                acc += sea.sample(t, 12.86 * t, 0.0, 12.86, 0.0).hub[0];
            }
            std::hint::black_box(acc);
            let s = t0.elapsed().as_secs_f64();
            wave_sums_s = Some(wave_sums_s.map_or(s, |b: f64| b.min(s)));
        }
    }
    let parts = parts.map(|(setup, [ctl, sea, plant, rest], finish)| {
        serde_json::json!({
            // Simulation::new: the plant, the steady state, the seaway's components (and,
            // in the first repetition, the RAO table, which a process builds once).
            "setup_s": setup,
            "controllers_s": ctl,
            // The RAO look-ups, the wave sums, the hub depth and the propellers' ventilation.
            "sea_s": sea,
            "plant_s": plant,
            // The checks, the commands and the recorded rows.
            "rest_s": rest,
            // The summary of the trace.
            "finish_s": finish,
            // The clock's own cost, taken off each part once a step.
            "clock_lap_s": lap_s,
            // Issue 17's target 2, the whole trial within 2x of the bare sums, leaves one
            // sums' time for everything else: the plant and the controllers alone take this.
            "plant_and_controllers_over_wave_sums": wave_sums_s.map(|w| (plant + ctl) / w),
        })
    });
    let out = serde_json::json!({
        "parts": parts,
        "wave_sums_s": wave_sums_s,
        // Issue 17's measure: the full model's time over the bare wave kernel's, same steps.
        "full_over_wave_sums": wave_sums_s.map(|w| best / w),
        "wave_components": if wave_sums_s.is_some() { Some(sc.sea.components) } else { None },
        "preset": name,
        "simulated_s": sim_s,
        "steps": steps,
        "wall_s": best,
        "realtime_factor": sim_s / best,
        "ns_per_step": best * 1e9 / steps.max(1) as f64,
    });
    emit_json(&out)?;
    Ok(())
}

/// `aes-sim bench`'s probe: the time since the last part's end, added to the part that ends now.
struct LapProbe {
    last: Instant,
    /// Seconds per part ([`StepPart`] order).
    spent: [f64; 4],
    laps: u64,
}

impl aes_core::sim::StepProbe for LapProbe {
    #[inline(always)]
    fn done(&mut self, part: aes_core::sim::StepPart) {
        let now = Instant::now();
        self.spent[part as usize] += (now - self.last).as_secs_f64();
        self.last = now;
        self.laps += 1;
    }
}

/// The clock's own cost in one lap of [`LapProbe`] with nothing between two reads [s] (the
/// least of a few batches).
fn clock_lap_s() -> f64 {
    use aes_core::sim::StepProbe;
    const N: u64 = 20_000;
    (0..5)
        .map(|_| {
            let mut p = LapProbe { last: Instant::now(), spent: [0.0; 4], laps: 0 };
            let t0 = Instant::now();
            for _ in 0..N {
                p.done(std::hint::black_box(aes_core::sim::StepPart::Rest));
            }
            t0.elapsed().as_secs_f64() / N as f64
        })
        .fold(f64::INFINITY, f64::min)
}
