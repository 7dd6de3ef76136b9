//! The second-order forces' share of the resistance (ch. 2.5.3) and the fuel of one prime mover
//! (ch. 5.1, 5.2.4).

use crate::rows::{calibrated, explained, reference, reference_pct, row, seeded, thesis_f64, thesis_text, Thesis};
use crate::runs::thesis_preset as preset;
use crate::runs::{measure, run, seed_runs};
use crate::{Kind, Section, Tolerance};
use aes_core::scenario::Scenario;
use aes_core::scenario::SternMotion;

/// The second-order forces' share of the resistance (ch. 2.5.3) and the fuel of one prime mover
/// (ch. 5.1, 5.2.4).
pub(crate) fn second_order_and_fuel(base: &aes_core::RunResult) -> Result<Section, String> {
    use aes_core::plant::fuel::{fuel_power, part_load_curve};
    let sig = |r: &aes_core::RunResult, n: &str| r.summary.signals[n];
    let mut rows = Vec::new();
    // Share of the calm-water resistance R_sp (eq. 2.15) at the run's mean speed.
    let share = |r: &aes_core::RunResult, sc: &Scenario| {
        let surge = aes_core::ship::surge::Surge::new(&sc.ship, sc.ship_hull().map_or(0.0, |h| h.mass_kg));
        let u = aes_core::numerics::units::kn_to_m_s(sig(r, "ship_speed_kn").mean);
        (sig(r, "added_resistance_n").mean / surge.resistance(u), surge.resistance(u))
    };
    let sc6 = preset("head-seas-ss6").ok_or("no preset")?;
    let (s6, r6) = share(base, &sc6);
    // The thesis' range, read as its middle +- half its width.
    let (lo_key, hi_key) = ("ch_2_5_3.added_resistance_low", "ch_2_5_3.added_resistance_high");
    let (lo, hi) = (thesis_f64(lo_key), thesis_f64(hi_key));
    let (lo_text, hi_text) = (thesis_text(lo_key), thesis_text(hi_key));
    let middle: Thesis = if lo.is_nan() {
        reference(lo_key)
    } else if hi.is_nan() {
        reference(hi_key)
    } else {
        Thesis::Computed((lo + hi) / 200.0)
    };
    let src = format!("ch. 2.5.3 text (\"can add {lo_text}-{hi_text} % resistance\")");
    let src = src.as_str();
    // The run `base` is: head_seas with nothing as printed and the consistent stern motion.
    let mut sc6_base = sc6.clone();
    sc6_base.set_hub_depth_m(6.0);
    sc6_base.seakeeping.stern_motion = SternMotion::Consistent;
    sc6_base.as_printed = Default::default();
    // Shown, not judged: the thesis' 20-30 % is a general statement, as the SS3 row below says.
    rows.push(
        seeded(
            row(
                "mean second-order force over calm-water resistance, head seas SS6, 25 kn, h0 = 6 m, 80 s (beside the \
             thesis' general figure for rough seas)",
                &format!("{src}; a general statement, not a result for this ship or sea"),
                middle,
                s6,
                "-",
                Tolerance::Abs((hi - lo) / 200.0),
                &format!(
                    "the thesis' range read as {} +- {}; a general figure for rough seas, not a result for this hull: \
                 ours is each realisation's mean added resistance over R_sp at its mean speed (seed 1: {:.0} kN \
                 over {:.0} kN)",
                    (lo + hi) / 200.0,
                    (hi - lo) / 200.0,
                    sig(base, "added_resistance_n").mean / 1e3,
                    r6 / 1e3
                ),
            ),
            measure(&seed_runs(&sc6_base)?, |r| Ok(share(r, &sc6_base).0))?,
        )
        .shown(Kind::Context),
    );
    let mut sc3 = sc6.clone();
    sc3.sea.sea_state = 3;
    sc3.set_hub_depth_m(6.0);
    let ss3 = run(&sc3)?;
    let (s3, _) = share(&ss3, &sc3);
    let s3_seeds = measure(&seed_runs(&sc3)?, |r| Ok(share(r, &sc3).0))?;
    rows.push(seeded(
        explained(
            "mean second-order force over calm-water resistance, head seas SS3, 25 kn, 80 s (beside the thesis' \
             figure for rough seas)",
            &format!("{src}; the thesis gives no number for SS3"),
            middle,
            s3,
            "-",
            &format!(
                "SS3's waves (H 0.9 m, peak {} rad/s, lambda/L about 0.6) are short against the 142 m hull, where the \
             added resistance operator is small, and the force goes as H^2 ((0.9 / 5.0)^2 = 0.03 of SS6's): the \
             {lo_text}-{hi_text} % is for severe seas (Fig. 5-11 shows SS3 and SS6 without numbers)",
                thesis_text("table_2_4.ss3.peak_frequency_rad_s")
            ),
        )
        .shown(Kind::Context),
        s3_seeds,
    ));
    // Fuel: the thermal efficiency the part-load curve gives, and one prime mover at 25 kn.
    let curve = part_load_curve();
    let rated = sc6.plant.turbine.rated_power_w;
    let eta = sc6.seakeeping.turbine_rated_efficiency;
    let thermal = |p: f64| p / fuel_power(&curve, p, rated, eta).0;
    let (rated_key, half_key) = ("ch_5_1.turbine_efficiency_rated", "ch_5_1.turbine_efficiency_half");
    let src = format!(
        "ch. 5.1 text (\"as high as {} % ... about {} % at half the rated power\")",
        thesis_text(rated_key),
        thesis_text(half_key)
    );
    let src = src.as_str();
    rows.push(
        calibrated(
            &format!(
                "gas-turbine thermal efficiency at rated power ({} MW)",
                thesis_text("ch_5_1.turbine_rated_power_mw")
            ),
            src,
            reference_pct(rated_key),
            thermal(rated),
            "-",
            Tolerance::Abs(1e-9),
            "copied (seakeeping.turbine_rated_efficiency)",
        )
        .kind(Kind::Copied),
    );
    rows.push(row(
        "gas-turbine thermal efficiency at half rated power",
        src,
        reference_pct(half_key),
        thermal(0.5 * rated),
        "-",
        Tolerance::Abs(0.01),
        &format!(
            "the generic TransiEnt part-load curve scaled to {} % at rated power (not fitted at half load); \
             \"about\": read to +-1 point",
            thesis_text(rated_key)
        ),
    ));
    let fsc = preset("fuel-regular-seas").ok_or("no preset")?;
    let pts = aes_core::studies::fuel::run(&fsc, &[0.6])?;
    let head5 = pts.iter().find(|r| r.heading == "head" && r.amplitude_ft == 5.0).ok_or("no 5 ft head row")?;
    let head1 = pts.iter().find(|r| r.heading == "head" && r.amplitude_ft == 1.0).ok_or("no 1 ft head row")?;
    let (p1, e1) = (head1.turbine_power_w, head1.turbine_power_w / head1.fuel_power_w);
    rows.push(
        explained(
        "thermal efficiency of one prime mover, 25 kn, 1 ft regular head sea at 0.6 rad/s (beside the rated \
         efficiency)",
        "thesis column: the rated efficiency of ch. 5.1, for scale; ch. 5.2.4 and Fig. 5-12 give no number for \
         this case, only \"the efficiency of each turbine is low\"",
        reference_pct(rated_key),
        e1,
        "-",
        &format!(
            "four turbines share the load: each gives {:.1} MW, {:.0} % of its rating, where the part-load curve is \
             {:.0} % of its rated efficiency; the thesis' reason: \"the lack of an intelligent scheme for prime mover \
             operation\". Fig. 5-12's fuel powers are an image our text of the thesis lacks, so they have no row; ours: {:.1} MW \
             of fuel per prime mover in a 1 ft head sea, {:.1} MW in 5 ft (aes-sim fuel)",
            p1 / 1e6,
            100.0 * p1 / rated,
            100.0 * e1 / eta,
            head1.fuel_power_w / 1e6,
            head5.fuel_power_w / 1e6
        ),
    )
    .shown(Kind::Context),
    );
    // The same case with one, two and four sets online (plant.online; the buses tied with fewer
    // than four): the thermal efficiency of the online sets and their fuel (issue 45).
    use aes_core::studies::schedule::{evaluate, SlowDrift};
    let drift = SlowDrift { mean_n: head1.added_resistance_n, bandwidth_rad_s: 0.0 };
    let speed = fsc.commands.first().and_then(|c| c.speed_kn).unwrap_or(25.0);
    let four = evaluate(&fsc, &[1, 2, 3, 4], speed, &drift);
    let fuel4 = four.fuel_power_w.ok_or("four sets cannot drive the fuel case")?;
    for sets in [vec![1u32], vec![1, 3], vec![1, 2, 3, 4]] {
        let n = sets.len();
        let c = evaluate(&fsc, &sets, speed, &drift);
        let (eff, what) = match (c.turbine_power_w, c.fuel_power_w) {
            (Some(p), Some(f)) => (
                p / f,
                format!(
                    "{n} online: {:.1} MW of shaft power, each set at {:.0} % of its rating; {:.1} MW of fuel power in all, \
                     {:+.1} % against four online (aes-sim schedule's steady state; ch. 5.2.4 runs four)",
                    p / 1e6,
                    100.0 * c.load_pu.unwrap_or(0.0),
                    f / 1e6,
                    100.0 * (f - fuel4) / fuel4
                ),
            ),
            _ => (
                0.0,
                format!(
                    "{n} online cannot drive {speed} kn: the steady state needs more than full throttle ({:.1} MW \
                     rating a set); ours 0 marks it",
                    rated / 1e6
                ),
            ),
        };
        rows.push(
            explained(
                &format!(
                    "thermal efficiency of the online sets, {speed} kn, 1 ft regular head sea at 0.6 rad/s, {n} of 4 \
                     sets online"
                ),
                "thesis column: the rated efficiency of ch. 5.1, for scale; the thesis runs four sets (ch. 6.1 asks \
                 for a schedule)",
                reference_pct(rated_key),
                eff,
                "-",
                &what,
            )
            .shown(Kind::Context),
        );
    }
    Ok(Section {
        finding: String::new(),
        title: "Ch. 2.5.3, 5.1, 5.2.4: second-order forces and fuel",
        note: String::new(),
        rows,
        figures: Vec::new(),
    })
}
