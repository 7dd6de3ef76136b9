//! Chapter 5.4's Monte Carlo studies: the arrival time of Table 5.8 against Rice's prediction and
//! the excess energy (ch. 5.4.1).

use crate::rows::{explained, open, reference, row, thesis_f64, thesis_text};
use crate::runs::thesis_preset as preset;
use crate::runs::{mc, run};
use crate::svg_plot::{Panel, Plot, Series};
use crate::{Figure, Kind, Section, Size, Tolerance};
use aes_core::scenario::Scenario;
use aes_core::scenario::SternMotion;

/// The arrival-time histogram as a density over all `trials` (censored trials count in no bin).
fn arrival_density(a: &aes_core::studies::montecarlo::ArrivalTimes, trials: u64) -> Vec<(f64, f64)> {
    let h = &a.histogram;
    let nb = h.counts.len().max(1);
    let width = (h.hi - h.lo) / nb as f64;
    let mut hist = vec![(h.lo, 0.0)];
    for (i, &c) in h.counts.iter().enumerate() {
        let d = c as f64 / (trials as f64 * width);
        let x = h.lo + i as f64 * width;
        hist.extend([(x, d), (x + width, d)]);
    }
    hist.push((h.hi, 0.0));
    hist
}

pub(crate) fn table_5_8(size: Size) -> Result<Section, String> {
    // The thesis' predicted rate and level (ch. 5.4.2), for the computations and the text.
    let (rate_key, z_key) = ("ch_5_4_2.rate_per_s", "ch_5_4_2.level_z_m");
    let (thesis_rate, thesis_z) = (thesis_f64(rate_key), thesis_f64(z_key));
    let (rate_text, z_text) = (thesis_text(rate_key), thesis_text(z_key));
    let sc = preset("mc-arrival").ok_or("no preset")?;
    let s = mc(&sc, size.trials)?;
    let a = &s.arrival_time_s;
    let rice = s.rice.as_ref().ok_or("no Rice summary")?;
    let radius = 0.5 * sc.propeller.diameter_m;
    let h0 = sc.ship_hull()?.hub_depth_m;
    let on = sc.seakeeping.ventilation_on_h_over_r;
    let sigma = rice.hubs[0].m0.sqrt();
    // Zero-crossing rate of the hub-depth process (eq. 5.3 at Z = 0) [1/s].
    let nu0 = (rice.hubs[0].m2 / rice.hubs[0].m0).sqrt() / (2.0 * std::f64::consts::PI);
    // Our spectrum at the thesis' level, and the standard deviation the thesis' pair (Z, rate)
    // needs at our zero-crossing rate (eq. 5.3 solved for M0).
    let rate_at_thesis_z = aes_core::studies::stats::rice_upcrossing_rate(rice.hubs[0].m0, rice.hubs[0].m2, thesis_z);
    let sigma_implied = thesis_z / libm::sqrt(2.0 * libm::log(nu0 / thesis_rate));
    // Rice (no trials) for the same study in a long-crested sea and with the consistent sign.
    let variant = |f: &dyn Fn(&mut Scenario)| -> Result<aes_core::studies::rice::RiceSummary, String> {
        let mut c = sc.clone();
        f(&mut c);
        aes_core::studies::rice::rice_summary(&c)?.ok_or_else(|| "no Rice summary".to_string())
    };
    let long = variant(&|c| c.sea.spreading = 0.0)?;
    let cons = variant(&|c| c.seakeeping.stern_motion = SternMotion::Consistent)?;
    let rate_at = |r: &aes_core::studies::rice::RiceSummary, z: f64| {
        aes_core::studies::stats::rice_upcrossing_rate(r.hubs[0].m0, r.hubs[0].m2, z)
    };
    // The same study with the hub lowered so that the level lies `z` below the calm hub: the
    // RAOs and so M0, M2 do not depend on the hub's height, only Z does.
    let at_level = |z: f64| -> Result<(f64, aes_core::studies::montecarlo::StudySummary), String> {
        let mut c = sc.clone();
        c.set_hub_depth_m(z + on * radius);
        Ok((z + on * radius, mc(&c, size.trials)?))
    };
    // Where our Rice rate is the thesis' 0.044 1/s, and where the level is 2 sigma deep.
    let z44 = libm::sqrt(2.0 * rice.hubs[0].m0 * libm::log(nu0 / thesis_rate));
    let (h44, s44) = at_level(z44)?;
    let (h2, s2) = at_level(2.0 * sigma)?;
    let (a44, a2) = (&s44.arrival_time_s, &s2.arrival_time_s);
    let r44 = s44.rice.as_ref().ok_or("no Rice summary")?;
    let r2 = s2.rice.as_ref().ok_or("no Rice summary")?;
    let v = |x: Option<f64>| x.unwrap_or(f64::NAN);
    let se2 = v(a2.std_censored) / (size.trials as f64).sqrt();
    let se = v(a.std_censored) / (size.trials as f64).sqrt();
    // Probability that a trial starts with the hub already below the level: Phi(-Z / sigma).
    let below = |z: f64| 0.5 * libm::erfc(z / sigma / std::f64::consts::SQRT_2);
    let src_a = "Table 5.8, analytic row";
    let src_m = format!(
        "Table 5.8, Monte Carlo row ({} trials; ours {})",
        thesis_text("table_5_8.monte_carlo.trials"),
        size.trials
    );
    let why_z = format!(
        "ours is h0 - {on} R = {h0:.2} - {on} x {radius:.2} = {:.2} m: our ventilation loop starts at h/R = {on} \
         (ch. 2.3's two numbers read as a loop, core/src/plant/propeller_losses.rs). The thesis' own recipe, h/R = 1.3 \
         with its h0 = 6 m and R = 2.4 m, gives 2.88 m, and none of the levels it names (h/R 1.3, 1.1, 1.0, 0) \
         gives {z_text} m from h0 = 6 m (2.88, 3.36, 3.60, 6.00 m); {z_text} m is exactly 7.0 - 1.3 x 2.4: the thesis' inputs \
         give its Z only with the hub 1 m deeper than the printed 6 m. Set at Z = {z_text} m (h0 = 7 m, h/R = 1.3) our \
         Rice rate is {rate_at_thesis_z:.4} 1/s (rows above): the level does not close the gap",
        rice.z_m
    );
    let why_rice = format!(
        "the hub-depth spectrum (eq. 5.2 with eq. 2.57's sign as printed; both shafts on the centreline, as eq. 2.57 \
         has them) gives M0 = {:.2} m^2 (sigma {sigma:.2} m) and a zero-crossing rate of {nu0:.4} 1/s. At our Z = \
         {:.2} m that is {:.4} 1/s; at the thesis' Z = {z_text} m it is {rate_at_thesis_z:.4} 1/s ({:.1} s), still {:.2} \
         times the thesis'. At our zero-crossing rate the thesis' pair ({z_text} m, {rate_text} 1/s) needs sigma = \
         {sigma_implied:.2} m (M0 = {:.2} m^2): {:.0} % less than ours with eq. 2.57 as printed, and far more \
         than with the consistent sign (sigma {:.2} m, {:.1e} 1/s at {z_text} m). A long-crested sea raises ours \
         ({:.4} 1/s at {z_text} m). The thesis prints neither M0 nor M2 (its RAOs are its own strip theory), so which \
         of its inputs makes the smaller motion is not shown: open",
        rice.hubs[0].m0,
        rice.z_m,
        rice.rate_per_s,
        1.0 / rate_at_thesis_z,
        rate_at_thesis_z / thesis_rate,
        sigma_implied * sigma_implied,
        100.0 * (1.0 - sigma_implied / sigma),
        cons.hubs[0].m0.sqrt(),
        rate_at(&cons, thesis_z),
        rate_at(&long, thesis_z),
    );
    let why_mc = format!(
        "two causes, one measured, one open. Measured: our level is only {:.2} sigma deep, so {:.0} % of trials \
         start below it and the first passage is no Poisson arrival at Rice's rate (mean of min(T, 90 s) {:.1} +- \
         {se:.1} s against Rice's {:.1} s, which counts the trials that start past the level as arriving at 0; \
         {:.1} s without them); with the hub lowered to put it 2 sigma deep (h0 = {h2:.2} m) the two agree \
         (row below). Open: Rice's rate itself (rows above). At the level where our Rice rate is the thesis' {rate_text} \
         1/s (Z = {:.2} m, {:.2} sigma, h0 = {h44:.2} m) our arrival times have mean {:.2} s, std {:.2} s, skewness \
         {:.2}, kurtosis {:.2}, median {:.2} s, from {} events at {:.4} 1/s ({:.0} % of starts below), against the \
         thesis' {}, {}, {}, {}, {}",
        rice.z_m / sigma,
        100.0 * below(rice.z_m),
        v(a.mean_censored),
        rice.mean_censored_with_start_s,
        rice.mean_censored_s,
        r44.z_m,
        r44.z_m / sigma,
        v(a44.mean),
        v(a44.std),
        v(a44.skewness),
        v(a44.kurtosis),
        v(a44.median),
        a44.events,
        v(a44.rate_per_s),
        100.0 * below(r44.z_m),
        thesis_text("table_5_8.monte_carlo.mean_s"),
        thesis_text("table_5_8.monte_carlo.std_s"),
        thesis_text("table_5_8.monte_carlo.skewness"),
        thesis_text("table_5_8.monte_carlo.kurtosis"),
        thesis_text("table_5_8.monte_carlo.median_s"),
    );
    let mut rows = vec![
        open(
            "mean arrival time (Rice)",
            src_a,
            reference("table_5_8.rice.mean_s"),
            rice.mean_arrival_s,
            "s",
            &why_rice,
        ),
        open("rate of surface effects (Rice)", src_a, reference(rate_key), rice.rate_per_s, "1/s", &why_rice),
        explained("level Z", "ch. 5.4.2 text", reference(z_key), rice.z_m, "m", &why_z),
    ];
    for (name, key, ours, unit) in [
        ("mean", "table_5_8.monte_carlo.mean_s", v(a.mean), "s"),
        ("standard deviation", "table_5_8.monte_carlo.std_s", v(a.std), "s"),
        ("skewness", "table_5_8.monte_carlo.skewness", v(a.skewness), "-"),
        ("kurtosis", "table_5_8.monte_carlo.kurtosis", v(a.kurtosis), "-"),
        ("median", "table_5_8.monte_carlo.median_s", v(a.median), "s"),
    ] {
        rows.push(open(&format!("arrival time {name} (Monte Carlo)"), &src_m, reference(key), ours, unit, &why_mc));
    }
    // Rice's Poisson assumption where it holds: our Monte Carlo against our Rice with the level
    // 2 sigma deep (eq. 2.57's sign, as the study).
    rows.push(
        row(
            "mean of min(T, 90 s), level 2 sigma deep (Monte Carlo against Rice)",
            "eqs. 5.1-5.3 (where their assumption of rare crossings holds)",
            r2.mean_censored_with_start_s,
            v(a2.mean_censored),
            "s",
            Tolerance::Abs(2.0 * se2),
            &format!(
                "the study with the hub at h0 = {h2:.2} m (Z = {:.2} m): {} events, {:.4} 1/s against Rice's {:.4}; \
             tolerance two Monte Carlo standard errors ({se2:.2} s, {} trials); the 'thesis' column is Rice's mean \
             of min(T, 90 s) with the trials that start past the level arriving at 0",
                r2.z_m,
                a2.events,
                v(a2.rate_per_s),
                r2.rate_per_s,
                size.trials
            ),
        )
        .kind(Kind::Analytic),
    );
    let law = |rate: f64| (0..=180).map(|i| i as f64 * 0.5).map(|t| (t, rate * libm::exp(-rate * t))).collect();
    let plot = Plot {
        title: "Arrival time of the first surface effect, SS6 head seas, 25 kn (Table 5.8)".into(),
        x_label: "arrival time [s]".into(),
        x_range: Some((0.0, a.cap_s)),
        panels: vec![Panel::new(
            "probability density [1/s]",
            vec![
                Series::line(&format!("ours, {} trials", size.trials), 0, arrival_density(a, size.trials)),
                Series::dashed(&format!("Rice, our rate {:.3} 1/s", rice.rate_per_s), 2, law(rice.rate_per_s)),
                Series::dashed(&format!("thesis, Rice {rate_text} 1/s"), 1, law(thesis_rate)),
                Series::line(
                    &format!("ours, hub at {h44:.2} m (Rice {rate_text} 1/s)"),
                    3,
                    arrival_density(a44, size.trials),
                ),
            ],
        )],
    };
    let fig = Figure::new(
        "arrival-time",
        &format!(
            "Arrival time of the first surface effect: our Monte Carlo histogram against the exponential law of \
             Rice's rate, ours (level h/R = {on}) and the thesis' (Table 5.8's analytic row), and ours with the hub \
             at {h44:.2} m, where our Rice rate is the thesis'"
        ),
        &plot,
    )?;
    // The opening's paragraph on eq. 2.57 (sections() appends Fig. 5-15's swing).
    let (cons_ours, cons_thesis) = (rate_at(&cons, rice.z_m), rate_at(&cons, thesis_z));
    let finding = format!(
        "**Eq. 2.57's sign decides the thesis' chapters 5.3 and 5.4.** With the sign consistent with the hull's \
         motions (the stern's rise taken from the wave, our default), the thesis' headline case (head seas SS6, \
         25 kn, hub {h0:.1} m deep) has a Rice rate of surface effects of {cons_thesis:.1e} per second and hub at the thesis' \
         level Z = {z_text} m ({cons_ours:.1e} at ours, {:.2} m): one event in {:.0} days of steaming ({:.0} days \
         at ours), so the propellers stay down and the ventilation, emergence and megawatt swings of chapters 5.3-5.4 appear only \
         with eq. 2.57 as printed (the mc-arrival and as-printed studies) or a shallower hub (mc-excess-energy's \
         h0 = 4 m with a 4.8 m propeller, the ballast draughts of the operability polar). With the printed sign our \
         Rice rate is {:.1} times the thesis' ({:.4} against {rate_text} 1/s at our level; {:.2} times at the \
         thesis' level)",
        rice.z_m,
        1.0 / cons_thesis / 86400.0,
        1.0 / cons_ours / 86400.0,
        rice.rate_per_s / thesis_rate,
        rice.rate_per_s,
        rate_at_thesis_z / thesis_rate,
    );
    Ok(Section {
        finding,
        title: "Table 5.8: arrival time of the first surface effect (SS6 head seas, 25 kn, mc-arrival)",
        note: format!("{} trials, {} with an event, censored at {} s.", size.trials, a.events, a.cap_s),
        rows,
        figures: vec![fig],
    })
}

pub(crate) fn excess_energy(size: Size) -> Result<Section, String> {
    let sc = preset("mc-excess-energy").ok_or("no preset")?;
    let s = mc(&sc, size.trials)?;
    let e = s.excess_energy_mj.as_ref().ok_or("no excess energy")?;
    let mean = e.vs_calm_water.mean.unwrap_or(f64::NAN);
    let std = e.vs_calm_water.std.unwrap_or(f64::NAN);
    let h = &e.vs_calm_water.histogram;
    let n = h.counts.iter().sum::<u64>() + h.below + h.above;
    let se = std / (n.max(1) as f64).sqrt();
    // The thesis' window: one motor over the whole run (its 94.1 MJ and 1.18 MW agree over 80 s).
    let dur = sc.sim.duration_s;
    let (mean_key, std_key) = ("ch_5_4_1.excess_energy_mean_mj", "ch_5_4_1.excess_energy_std_mj");
    let (mean_text, power_text) = (thesis_text(mean_key), thesis_text("ch_5_4_1.excess_power_mw"));
    let sub = e.mean.unwrap_or(f64::NAN);
    let sub_std = e.std.unwrap_or(f64::NAN);
    let calm_mw = {
        let mut calm = sc.clone();
        calm.sea.kind = aes_core::sea::waves::SeaKind::Calm;
        calm.sim.duration_s = 1.0;
        let r = run(&calm)?;
        r.summary.signals["im_power_pu"].final_ * sc.plant.motor.rated_power_w / 1e6
    };
    Ok(Section {
        finding: String::new(),
        figures: Vec::new(),
        title: "Ch. 5.4.1: excess energy of one motor over the 80 s run (mc-excess-energy)",
        note: format!(
            "{} trials; ours against calm water, the definition that matches the thesis' in kind.",
            size.trials
        ),
        rows: vec![
            open(
                "mean excess energy",
                "ch. 5.4.1 text",
                reference(mean_key),
                mean,
                "MJ",
                &format!(
                    "ours {mean:.0} +- {se:.0} (standard error). The window is the thesis': one motor over the \
                     whole {dur:.0} s run, which its own {mean_text} MJ and \"{power_text} MW\" confirm ({mean_text} MJ / {} s = {:.2} \
                     MW); ours is {:.2} MW over calm water's {calm_mw:.1} MW. The reference is what differs: \
                     against the same sea without surface losses (what \"due to propeller emergence\" names) ours \
                     is {sub:.1} +- {sub_std:.1} MJ, since an emerging propeller sheds load and the motor draws \
                     less; only against calm water, which counts the added resistance and the speed control's \
                     work in the waves, is it positive. The thesis' reference is not printed and neither of ours \
                     gives {:.0} MJ: open",
                    thesis_text("ch_5_4_1.duration_s"),
                    thesis_f64(mean_key) / thesis_f64("ch_5_4_1.duration_s"),
                    mean / dur,
                    thesis_f64(mean_key),
                ),
            ),
            open(
                "standard deviation of the excess energy",
                "ch. 5.4.1 text",
                reference(std_key),
                std,
                "MJ",
                &format!("as above; against the same sea without surface losses the spread is {sub_std:.1} MJ"),
            ),
        ],
    })
}
