//! Model experiments: Journee's (1992) Wigley III in head waves against our strip theory.

use crate::rows::{explained, open, row};
use crate::{Kind, Row, Section, Tolerance, Verdict};

/// Journee's (1992) model experiments on the Wigley III hull in head waves
/// (core/data/journee1992_wigley_iii.csv) against our strip theory at the same conditions and in
/// the same normalisations, split so that a difference can be placed: radiation (A33, B33),
/// excitation on the restrained model (X3, X5), motions, added resistance.
pub(crate) fn wigley_iii_experiments() -> Result<Section, String> {
    use aes_core::sea::seakeeping::motions::response;
    use aes_core::sea::seakeeping::wigley_check::{
        journee_points, model_omega_grid, raw_peak, wigley_iii_model, JourneePoint, WIGLEY_III_B, WIGLEY_III_L,
        WIGLEY_III_STATIONS,
    };
    let ship = wigley_iii_model(WIGLEY_III_B, WIGLEY_III_STATIONS)?;
    let table = ship.radiation_table(&model_omega_grid(ship.lpp, ship.g));
    let points = journee_points(&ship, &table)?;
    let src = "Journee 1992, Delft report 909 (Wigley III, head waves)";
    // Short waves at rest (lambda/L < 1): the heave force passes through zero near 0.75 and the
    // motions are small differences of large terms, for heave and pitch alike.
    let short = |p: &JourneePoint| p.fn_ == 0.0 && p.x < 1.0 && (p.table == "heave" || p.table == "pitch");
    // The range of ours over measured, in per cent, of the points of a table that are judged.
    let range = |table: &str, at_rest: Option<bool>| -> (f64, f64) {
        points
            .iter()
            .filter(|p| p.table == table && !short(p) && at_rest.is_none_or(|r| (p.fn_ == 0.0) == r))
            .map(|p| 100.0 * (p.ours / p.measured - 1.0))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)))
    };
    let pct = |(a, b): (f64, f64)| format!("{a:+.0} % to {b:+.0} %");
    let a33 = format!(
        "{} at every frequency: with no transom STF's speed terms leave A33 at its zero-speed value, while at \
         tau = omega_e U / g of 0.7-1.3 the measured added mass changes with speed (waves swept along the hull, \
         sinkage, trim and the bow wave, none of them in strip theory)",
        pct(range("a33", None))
    );
    let b33 = format!(
        "{}, falling with frequency: 2-D strips overestimate the damping at low frequency, where the radiated \
         waves of neighbouring strips interfere along a hull they are as long as",
        pct(range("b33", None))
    );
    let x3 = format!("{}: Froude-Krylov plus STF's diffraction", pct(range("x3", None)));
    let x5 = format!(
        "{}: STF's speed term U/(i omega_e) in the diffraction moment raises it (X3 has none); the data have no \
         restrained moment at rest to confirm it",
        pct(range("x5", None))
    );
    let heave = format!(
        "{} at rest in long waves, {} at speed; our Fn 0.3 resonance (lambda/L about 1.1) lies below Journee's \
         shortest wave there, 1.25",
        pct(range("heave", Some(true))),
        pct(range("heave", Some(false)))
    );
    let pitch = format!(
        "{} at rest in long waves, while heave is high: the data have no excitation at rest to place it (the \
         assumed k_yy = 0.25 L and the ends' 3-D relief are candidates); no pitch at speed was measured",
        pct(range("pitch", Some(true)))
    );
    let short_why = "short waves at rest (lambda/L < 1): the heave force passes through zero near lambda/L = 0.75 \
                     (both find the minimum there) and the motions are small differences of large terms, so a per \
                     cent means little; the measured pitch 0.51 at lambda/L 0.5, between 0.12 and 0.14, looks like \
                     a reading error of the transcription";
    let raw = "open: above Fn 0.2 the peak follows our heave-pitch resonance, lightly damped in strip theory, and \
               grows with speed where Journee's stays near 20-28; at Fn 0.2 it is low, which the resonance does \
               not explain. See the note on beam";
    let mut rows = Vec::new();
    for p in &points {
        let at = match p.table {
            "a33" | "b33" => format!("omega_e sqrt(L/g) = {}", p.x),
            "raw_peak" => format!("peak over lambda/L (ours at {:.2})", p.x),
            _ => format!("lambda/L = {}", p.x),
        };
        let what = match p.table {
            "heave" => "heave z_a / zeta_a",
            "pitch" => "pitch theta_a L / (2 pi zeta_a)",
            "a33" => "radiation: heave added mass A33 / (rho V)",
            "b33" => "radiation: heave damping B33 / (rho V) sqrt(L/g)",
            "x3" => "excitation: heave force |X3| / (C33 zeta_a), restrained",
            "x5" => "excitation: pitch moment |X5| / (k C55 zeta_a), restrained",
            _ => "added resistance R_aw / (rho g zeta_a^2 B^2 / L), eq. 2.47 + the waterline's reflection",
        };
        let quantity = format!("{what}, Fn {}, {at}", p.fn_);
        // Each tolerance is what the code reaches, rounded up: a change that makes the agreement
        // worse fails the build.
        let judged = |tol: f64, why: &str| row(&quantity, src, p.measured, p.ours, "-", Tolerance::Rel(tol), why);
        let r = match p.table {
            _ if short(p) => explained(&quantity, src, p.measured, p.ours, "-", short_why),
            "a33" => judged(0.12, &a33),
            "b33" => judged(0.14, &b33),
            "x3" => judged(0.065, &x3),
            "x5" => judged(0.125, &x5),
            "heave" => judged(0.10, &heave),
            "pitch" => judged(0.14, &pitch),
            _ => open(&quantity, src, p.measured, p.ours, "-", raw),
        };
        rows.push(r.kind(Kind::Experiment));
    }
    // Salvesen's added resistance against beam: Wigley III forms of 1.5 and 2 times the beam at
    // the same length, draft and loading, at Fn 0.3.
    let fr = 0.3;
    let beam_study = |b_over_l: f64| -> Result<(f64, f64, f64), String> {
        let s = wigley_iii_model(b_over_l * WIGLEY_III_L, WIGLEY_III_STATIONS)?;
        let t = s.radiation_table(&model_omega_grid(s.lpp, s.g));
        let (peak, lam) = raw_peak(&s, &t, fr);
        let u = fr * libm::sqrt(s.g * s.lpp);
        let omega = libm::sqrt(s.g * 2.0 * std::f64::consts::PI / (lam * s.lpp));
        let r = response(&s, &t, omega, u, std::f64::consts::PI, 1.0);
        Ok((peak, lam, r.added_resistance / r.added_resistance_gb))
    };
    // Eq. 2.48's F7 in place of the reflection (the thesis' form), at Journee's three speeds.
    let f7_peaks: Vec<f64> = {
        let mut s = wigley_iii_model(WIGLEY_III_B, WIGLEY_III_STATIONS)?;
        s.short_wave = aes_core::sea::seakeeping::params::ShortWaveForce::SalvesenF7;
        let t = s.radiation_table(&model_omega_grid(s.lpp, s.g));
        [0.2, 0.3, 0.4].iter().map(|&f| raw_peak(&s, &t, f).0).collect()
    };
    let (p10, l10, g10) = beam_study(0.1)?;
    let (p15, _, g15) = beam_study(0.15)?;
    let (p20, l20, g20) = beam_study(0.2)?;
    let expo = libm::log(p20 * 4.0 / p10) / libm::log(2.0);
    let judged: Vec<&Row> = rows.iter().filter(|r| r.tolerance.is_some()).collect();
    let claims = judged.iter().filter_map(|r| match r.tolerance {
        Some(Tolerance::Rel(x)) => Some(100.0 * x),
        _ => None,
    });
    let (tmin, tmax) = claims.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    let note = format!(
        "Our strip theory at Journee's model scale (L {} m, B {} m, d 0.1875 m, the (1 + 0.2 xi^2) form, {} \
         stations, fresh water; KG 0.15 m where Journee's 0.17 m gives a negative GM_T, which reaches head-sea \
         heave and pitch only through C55, +0.5 %). Measured values as transcribed in the data file (its header \
         gives the reading uncertainty). Each tolerance is what our code reaches, rounded up, so that a change \
         for the worse fails. The added resistance is eq. 2.47's sum with the waterline's reflection as \
         its short-wave part (what every run uses); with eq. 2.48's F7 instead the peaks are {:.1}, {:.1} and \
         {:.1} at Fn 0.2, 0.3 and 0.4: the motions make the peak, not the short-wave term. Beam: on Wigley III forms at the same length, draft and loading, our \
         nondimensional peak at Fn {fr} falls from {p10:.1} (B/L 0.10, at lambda/L {l10:.2}) to {p15:.1} (0.15) \
         and {p20:.1} (0.20, at {l20:.2}): the dimensional peak grows as B^{expo:.2}, not B^2, because at a \
         fixed draft the damping grows faster than the mass and restoring and our resonance flattens. Ours \
         over Gerritsma-Beukelman at the peak stays {g10:.2}, {g15:.2}, {g20:.2}: both formulas scale alike on \
         the same motions, so neither mis-scales with beam on its own; whether our motions' dependence on beam \
         is right needs measurements on a wider hull (Journee's Wigley II and IV, L/B 5), which our data file \
         does not hold.",
        WIGLEY_III_L, WIGLEY_III_B, WIGLEY_III_STATIONS, f7_peaks[0], f7_peaks[1], f7_peaks[2]
    );
    let misses: Vec<f64> =
        points.iter().filter(|p| p.table == "raw_peak").map(|p| 100.0 * (p.ours / p.measured - 1.0)).collect();
    let (lo, hi) = misses.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
    let passed = judged.iter().filter(|r| r.verdict == Verdict::Pass).count();
    let finding = format!(
        "**Seakeeping against measurements.** On Journee's Wigley III model experiments our strip theory's \
         radiation, excitation and motions pass {passed} of the {} points where a tolerance is claimed, within \
         {tmin:.1}-{tmax:.0} % (each kind's tolerance is what the code reaches); of the other {}, short waves at \
         rest are explained, and the added-resistance peaks miss by {lo:+.0} % to {hi:+.0} % (open).",
        judged.len(),
        rows.len() - judged.len()
    );
    Ok(Section {
        finding,
        title: "Wigley III against Journee's model experiments (1992)",
        note,
        rows,
        figures: Vec::new(),
    })
}
