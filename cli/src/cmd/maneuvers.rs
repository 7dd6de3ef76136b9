//! `aes-sim maneuvers`: the standard maneuvers booklet (IMO MSC.137(76)) of a scenario's ship.

use crate::common::{emit, emit_json, load, Failure};
use aes_core::studies::maneuvers::{booklet, Booklet};

// The command line of `aes-sim maneuvers`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (file, `-` or `preset:NAME`); its first speed order is the approach speed.
    #[arg(default_value = "preset:turn-360")]
    file: String,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
    /// The booklet as Markdown tables instead of JSON.
    #[arg(long)]
    markdown: bool,
    /// Leave the tracks (every 0.1 s of each maneuver) out of the JSON.
    #[arg(long)]
    no_tracks: bool,
}

pub fn run(Args { file, sets, markdown, no_tracks }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    let mut b = booklet(&sc)?;
    if markdown {
        return emit(to_markdown(&b).trim_end_matches('\n'));
    }
    if no_tracks {
        b.turning.track.clear();
        b.zigzag_10.track.clear();
        b.zigzag_20.track.clear();
        if let Some(st) = &mut b.stopping {
            st.track.clear();
        }
    }
    aes_core::checks::check_finite(&b)?;
    emit_json(&b)?;
    Ok(())
}

/// The booklet as a newcomer reads it: the maneuvers in metres and ship lengths, IMO's verdicts,
/// the captive tables.
pub fn to_markdown(b: &Booklet) -> String {
    let l = b.length_m;
    let t = &b.turning;
    let mut s = format!(
        "Maneuvers of `{}` ({} forces, L = {:.1} m) from {:.1} kn with the shafts held at {:.0} rpm.\n\n",
        crate::common::shorten(&b.scenario),
        b.model,
        l,
        b.approach_kn,
        b.shaft_rpm
    );
    s += "| maneuver | value | in ship lengths |\n|---|---|---|\n";
    for (name, m) in [
        ("advance (35 deg turn)", t.advance_m),
        ("transfer", t.transfer_m),
        ("tactical diameter", t.tactical_diameter_m),
        ("steady turning diameter", t.steady_diameter_m),
        ("coasting to 5 kn, track reach", b.coasting.track_reach_m),
    ] {
        s += &format!("| {name} | {m:.0} m | {:.2} L |\n", m / l);
    }
    s += &format!("| speed in the steady turn | {:.0} % of the approach speed | |\n", 100.0 * t.speed_ratio);
    s += &format!(
        "| 10/10 zig-zag overshoots | {:.1} deg, {:.1} deg | |\n",
        b.zigzag_10.first_overshoot_deg, b.zigzag_10.second_overshoot_deg
    );
    s += &format!(
        "| 20/20 zig-zag overshoots | {:.1} deg, {:.1} deg | |\n\n",
        b.zigzag_20.first_overshoot_deg, b.zigzag_20.second_overshoot_deg
    );
    s += &stopping_markdown(b);
    s += "| IMO MSC.137(76) criterion | ours | limit | verdict |\n|---|---|---|---|\n";
    for c in &b.criteria {
        s += &format!(
            "| {} | {:.2} {} | {:.2} {} | {} |\n",
            c.name,
            c.value,
            c.unit,
            c.limit,
            c.unit,
            if c.pass { "pass" } else { "fail" }
        );
    }
    if !b.static_drift.is_empty() {
        s += "\nStatic drift and pure yaw at the approach speed (rudders at 0 deg, propellers at the approach thrust): Y' = Y / (1/2 rho L T U^2), N' = N / (1/2 rho L^2 T U^2).\n\n| drift [deg] | r' | Y' | N' |\n|---|---|---|---|\n";
        for r in b.static_drift.iter().chain(&b.pure_yaw) {
            s += &format!("| {:.0} | {:.1} | {:.5} | {:.5} |\n", r.drift_deg, r.r_prime, r.y_prime, r.n_prime);
        }
        if let Some(bare) = &b.bare_drift {
            s += &format!(
                "\nStatic drift of the bare hull (rudders and propellers off), as captive tests of a bare hull report it; \
                 the side force's slope at 2 deg: bare hull {:.3}, with its rudders {:.3}, Clarke et al. (1983)'s \
                 bare-hull regression {:.3} per rad.\n\n| drift [deg] | Y' | N' |\n|---|---|---|\n",
                bare.slope_bare_per_rad, bare.slope_appended_per_rad, bare.slope_clarke_per_rad
            );
            for r in &bare.rows {
                s += &format!("| {:.0} | {:.5} | {:.5} |\n", r.drift_deg, r.y_prime, r.n_prime);
            }
        }
    }
    s
}

/// The full-astern stopping test: the track in metres and ship lengths, and where the energy went.
fn stopping_markdown(b: &Booklet) -> String {
    let Some(st) = &b.stopping else {
        return format!("Full-astern stopping test: not run ({}).\n\n", b.stopping_refused.as_deref().unwrap_or("-"));
    };
    let l = b.length_m;
    let mut s = format!(
        "Full-astern stopping test from {:.1} kn (crash stop: full astern at once, the whole drive train \
         simulated; IMO's 15 L is for merchant ships, a reference for this naval ship):\n\n",
        st.approach_kn
    );
    s += "| stopping test | value | in ship lengths |\n|---|---|---|\n";
    for (name, m) in [
        ("track reach", st.track_reach_m),
        ("head reach", st.head_reach_m),
        ("lateral deviation (+ starboard)", st.lateral_deviation_m),
    ] {
        s += &format!("| {name} | {m:.0} m | {:.2} L |\n", m / l);
    }
    s += &format!("| time to dead in the water | {:.0} s | |\n", st.time_to_dead_s);
    s += &format!("| peak bus voltage | {:.3} pu ({:.0} V) | |\n", st.peak_bus_voltage_pu, st.peak_bus_voltage_v);
    s += &format!("| peak power the motors return | {:.1} MW | |\n", st.peak_regenerated_w / 1e6);
    s += &format!("| brake energy until dead in the water | {:.0} MJ | |\n", st.brake_energy_j / 1e6);
    s += &format!("| energy the storages took | {:.0} MJ | |\n\n", st.storage_taken_j / 1e6);
    for a in &st.adjustments {
        s += &format!("The test set {a}.\n");
    }
    for w in &st.warnings {
        s += &format!("During the stop: {w}\n");
    }
    if !st.adjustments.is_empty() || !st.warnings.is_empty() {
        s += "\n";
    }
    s
}
