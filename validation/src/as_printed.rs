//! What each switch of `as_printed` (and `seakeeping.stern_motion`) moves: the thesis' printed
//! inconsistencies, each run as printed beside the corrected run.

use crate::rows::{explained, thesis_f64, thesis_text};
use crate::runs::thesis_preset as preset;
use crate::runs::{head_seas, points, run, startup_to, table_2_3_model};
use crate::svg_plot::{Panel, Plot, Series};
use crate::{Figure, Section};
use aes_core::scenario::SternMotion;

/// Surface-effect onsets in a run: the times beta_T falls below 1 from 1.
fn onsets(r: &aes_core::RunResult) -> Result<f64, String> {
    let b = r.trace.column("beta_t").ok_or("no beta_t")?;
    Ok(b.windows(2).filter(|w| w[0] >= 1.0 && w[1] < 1.0).count() as f64)
}

/// What each switch of `as_printed` (and `seakeeping.stern_motion`) moves: the thesis column is
/// the run or computation with the switch as printed, ours the corrected one.
pub(crate) fn as_printed(base: &aes_core::RunResult) -> Result<Section, String> {
    use aes_core::as_printed::AsPrintedParams;
    use aes_core::sea::seakeeping::complex::cabs;
    use aes_core::sea::seakeeping::motions::response_as;
    use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
    let sig = |r: &aes_core::RunResult, n: &str| r.summary.signals[n];
    let mut rows = Vec::new();
    // The ch. 5.3 run at the thesis' depth, corrected (`base`) and with one switch as printed.
    let one = |name: &str| AsPrintedParams::default().with(name, true).unwrap_or_default();
    let hs = "head seas SS6, 25 kn, h0 = 6 m, 80 s";
    let swing = |r: &aes_core::RunResult, n: &str| sig(r, n).max - sig(r, n).min;
    // Every row: (quantity, switch as printed, corrected, unit, reason).
    let mut add = |q: String, switch: &str, printed: f64, ours: f64, unit: &'static str, why: &str| {
        rows.push(explained(&q, &format!("{switch} as printed"), printed, ours, unit, why));
    };

    // Eq. 2.57's sign (seakeeping.stern_motion).
    let st = head_seas(AsPrintedParams::default(), SternMotion::ThesisEq257)?;
    let why = "as printed the pitch term adds the stern's motion to the wave instead of following it: the hub \
               depth swings several times as far, the propellers ventilate and break the surface, the thesis' ch. \
               5.3 picture";
    let sw = "seakeeping.stern_motion";
    add(format!("shaft speed swing, {hs}"), sw, swing(&st, "prop_rpm"), swing(base, "prop_rpm"), "rpm", why);
    add(format!("h/R minimum, {hs}"), sw, sig(&st, "h_over_r").min, sig(base, "h_over_r").min, "-", why);
    add(format!("surface-effect onsets, {hs}"), sw, onsets(&st)?, onsets(base)?, "-", why);

    // The Doppler shift counted twice (eqs. 2.55, 2.59).
    let d = head_seas(one("doppler_twice"), SternMotion::Consistent)?;
    let k = 0.36 / aes_core::sea::waves::G;
    let u = 25.0 * aes_core::numerics::units::KNOT_M_S;
    let why = "the phase turns at omega0 + 2 k U instead of the encounter frequency omega0 + k U: the motions and \
               the hub depth come faster and the second-order force's slow part changes with them";
    let sw = "as_printed.doppler_twice";
    add(
        "encounter frequency of a 0.6 rad/s head wave at 25 kn (from the formulas; the seaway's phase rate is \
         tested against them in sim/seaway.rs)"
            .into(),
        sw,
        0.6 + 2.0 * k * u,
        0.6 + k * u,
        "rad/s",
        why,
    );
    add(format!("shaft speed swing, {hs}"), sw, swing(&d, "prop_rpm"), swing(base, "prop_rpm"), "rpm", why);
    add(format!("h/R minimum, {hs}"), sw, sig(&d, "h_over_r").min, sig(base, "h_over_r").min, "-", why);
    add(
        format!("mean second-order force backwards, {hs}"),
        sw,
        sig(&d, "added_resistance_n").mean / 1e3,
        sig(base, "added_resistance_n").mean / 1e3,
        "kN",
        why,
    );

    // Strip theory: Appendix A's typos and eq. 2.47's conjugate.
    let ship = Ship::dtmb5415();
    let rad = ship.radiation_table(&default_omega_grid());
    let fn028 = 0.28 * libm::sqrt(9.81 * ship.lpp);
    let peak_heave = |ap: &AsPrintedParams| -> f64 {
        (0..=30)
            .map(|i| cabs(response_as(&ship, &rad, 0.3 + 0.03 * i as f64, fn028, std::f64::consts::PI, 1.0, ap).heave))
            .fold(0.0, f64::max)
    };
    let a = head_seas(one("appendix_a_typos"), SternMotion::Consistent)?;
    let why = "eq. 5's -(U^2/omega^2) B33^0 is U times STF's term (and not an added mass): at speed it swamps the \
               heave-pitch coupling; at rest both typos vanish. The thesis says its heave and pitch compare well with \
               other programs (ch. 2.5.2) and that only a small fraction of the propeller emerges in this run (ch. \
               5.3.1), so its code had STF's terms";
    let sw = "as_printed.appendix_a_typos";
    add(
        "largest heave RAO, Fn 0.28, head seas, 0.3-1.2 rad/s".into(),
        sw,
        peak_heave(&one("appendix_a_typos")),
        peak_heave(&AsPrintedParams::default()),
        "m/m",
        why,
    );
    add(format!("largest heave, {hs}"), sw, sig(&a, "heave_m").max, sig(base, "heave_m").max, "m", why);
    add(format!("h/R minimum, {hs}"), sw, sig(&a, "h_over_r").min, sig(base, "h_over_r").min, "-", why);
    add(format!("surface-effect onsets, {hs}"), sw, onsets(&a)?, onsets(base)?, "-", why);

    let norm = 1025.0 * 9.81 * ship.beam * ship.beam / ship.lpp;
    let sigma = |ap: &AsPrintedParams| {
        response_as(&ship, &rad, 0.3, fn028, std::f64::consts::PI, 2.5, ap).added_resistance / norm
    };
    let c = head_seas(one("eq_2_47_conjugate"), SternMotion::Consistent)?;
    let why = "with the conjugate on F^I only the diffraction term's real part changes and the mean force does not \
               vanish in long waves (Gerritsma-Beukelman: 0.01 at lambda/L = 4.8)";
    let sw = "as_printed.eq_2_47_conjugate";
    add(
        "added resistance coefficient sigma_aw, lambda/L = 4.8, Fn 0.28".into(),
        sw,
        sigma(&one("eq_2_47_conjugate")),
        sigma(&AsPrintedParams::default()),
        "-",
        why,
    );
    add(
        format!("mean second-order force backwards, {hs}"),
        sw,
        sig(&c, "added_resistance_n").mean / 1e3,
        sig(base, "added_resistance_n").mean / 1e3,
        "kN",
        why,
    );
    add(format!("mean motor power, {hs}"), sw, sig(&c, "im_power_pu").mean, sig(base, "im_power_pu").mean, "pu", why);

    // The plant: start-ups to 25 kn in calm water.
    let startup = |name: &str| -> Result<aes_core::RunResult, String> {
        let mut sc = startup_to(25.0);
        sc.as_printed = one(name);
        run(&sc)
    };
    let s0 = startup("none")?;
    let su = "start-up to 25 kn, end";
    let e = startup("ea_line_to_line")?;
    let why = format!(
        "E_a read as the line-to-line emf in eq. 2.8: the rated 4160 V drive the bridge, so the bus and its set \
         point are sqrt(3) times higher and the currents and their losses smaller; the thesis' power-electronics \
         efficiency ({} at 25 kn, Table 5.7) fits this reading",
        thesis_text("table_5_7.power_electronics.25kn")
    );
    let why = why.as_str();
    let sw = "as_printed.ea_line_to_line";
    add(format!("bus voltage, {su}"), sw, sig(&e, "bus_voltage_v").final_, sig(&s0, "bus_voltage_v").final_, "V", why);
    add(
        format!("field current, {su}"),
        sw,
        sig(&e, "field_current_a").final_,
        sig(&s0, "field_current_a").final_,
        "A",
        why,
    );
    add(
        format!("power electronics efficiency, {su}"),
        sw,
        e.summary.efficiency.all()?[1],
        s0.summary.efficiency.all()?[1],
        "-",
        why,
    );
    let m = startup("motor_p_is_poles")?;
    let why = "P = 12 read as poles: 6 pole pairs make a 600 rpm machine whose volts per hertz give a third of its \
               voltage at 200 rpm; it works at its peak-torque slip, and cannot carry the propeller at 25 kn from the \
               start (peak 654 kN m against 944 kN m: the head-seas run refuses to start)";
    let sw = "as_printed.motor_p_is_poles";
    add(
        format!("motor efficiency, {su}"),
        sw,
        m.summary.efficiency.all()?[2],
        s0.summary.efficiency.all()?[2],
        "-",
        why,
    );
    add(
        format!("slip speed, {su}"),
        sw,
        sig(&m, "slip_speed_rad_s").final_,
        sig(&s0, "slip_speed_rad_s").final_,
        "rad/s",
        why,
    );
    add(format!("shaft speed, {su}"), sw, sig(&m, "prop_rpm").final_, sig(&s0, "prop_rpm").final_, "rpm", why);
    let q = startup("eq_2_5_copper_loss")?;
    let why =
        "the rotor copper loss over the shaft speed is s/(1-s) of the torque: the motor starves the shaft and the \
               ship stops accelerating at half its speed; the energy books no longer close (the air-gap power's \
               (1 - s) part is counted nowhere: residual -9 % of the turbine work)";
    let sw = "as_printed.eq_2_5_copper_loss";
    add(format!("ship speed, {su}"), sw, sig(&q, "ship_speed_kn").final_, sig(&s0, "ship_speed_kn").final_, "kn", why);
    add(format!("shaft speed, {su}"), sw, sig(&q, "prop_rpm").final_, sig(&s0, "prop_rpm").final_, "rpm", why);
    add(
        format!("motor efficiency, {su}"),
        sw,
        q.summary.efficiency.all()?[2],
        s0.summary.efficiency.all()?[2],
        "-",
        why,
    );

    // The preset with every switch that lets the run start.
    let all = run(&preset("as-printed").ok_or("no preset")?)?;
    // Where the turbines overspeed and where they then stall (below the health check's minimum
    // running speed), from the run.
    use aes_core::sim::health::TURBINE_MIN_RUNNING_PU as STALL_PU;
    let (t, w) =
        (all.trace.column("t_s").ok_or("no t_s")?, all.trace.column("turbine_speed_pu").ok_or("no turbine speed")?);
    let top = (0..w.len()).fold(0, |b, i| if w[i] > w[b] { i } else { b });
    let stall =
        (top..w.len()).find(|&i| w[i] < STALL_PU).map_or("never".to_string(), |i| format!("from {:.0} s", t[i]));
    let why = &format!(
        "every switch that lets the run start at 25 kn, and eq. 2.57's sign: Appendix A's typos dominate (the hub \
         leaves the water by radii where the thesis sees only a small fraction of the disk emerge, and the turbines \
         overspeed to {:.2} pu at {:.0} s, then fall below {STALL_PU} pu {stall}: a stalled plant, not the \
         thesis'); eq. 2.57's sign alone gives the thesis' ch. 5.3 picture",
        w[top], t[top]
    );
    let sw = "preset as-printed: every switch";
    add(format!("shaft speed swing, {hs}"), sw, swing(&all, "prop_rpm"), swing(base, "prop_rpm"), "rpm", why);
    add(format!("largest heave, {hs}"), sw, sig(&all, "heave_m").max, sig(base, "heave_m").max, "m", why);
    add(format!("h/R minimum, {hs}"), sw, sig(&all, "h_over_r").min, sig(base, "h_over_r").min, "-", why);
    add(format!("surface-effect onsets, {hs}"), sw, onsets(&all)?, onsets(base)?, "-", why);
    add(format!("motor power swing, {hs}"), sw, swing(&all, "im_power_pu"), swing(base, "im_power_pu"), "pu", why);
    let end = base.summary.final_time_s;
    let both = |name: &str, scale: f64| -> Result<Vec<Series>, String> {
        Ok(vec![
            Series::line("corrected", 0, points(base, name, scale)?),
            Series::dashed("eq. 2.57 as printed", 3, points(&st, name, scale)?),
        ])
    };
    let mut hr = both("h_over_r", 1.0)?;
    hr.push(Series::level("ventilation starts, h/R 1.1", 5, 1.1, 0.0, end));
    // Tables 5.1/5.5's ship against the hull's (as_printed.table_5_ship).
    {
        let sw = "as_printed.table_5_ship";
        let why = "Tables 5.1/5.5 give L = 180 m, x_p = 75 m and m = 7e6 kg; the hull (DTMB 5415) has Lpp = 142 m, \
                   its rudder 67 m aft of G and 8.6e6 kg. Table 2.3 scaled by 142 m gives the 5415's mass plus 10 % \
                   and Table 5.1's resistance at 25 kn; scaled by 180 m, 2.75 times the mass and 1.6 times the \
                   resistance";
        let t5 = AsPrintedParams { table_5_ship: true, ..Default::default() };
        let (a5, a0) = (table_2_3_model(&t5)?, table_2_3_model(&AsPrintedParams::default())?);
        add("maneuvering surge mass m - X_udot".into(), sw, a5.m11 / 1e3, a0.m11 / 1e3, "t", why);
        let u25 = aes_core::numerics::units::kn_to_m_s(25.0);
        add(
            "Table 2.3's straight-line resistance at 25 kn (eq. 2.15, which the hull's ship takes: 1469 kN)".into(),
            sw,
            -a5.forces(u25, 0.0, 0.0).x / 1e3,
            -a0.forces(u25, 0.0, 0.0).x / 1e3,
            "kN",
            why,
        );
        let t360 = |ap: AsPrintedParams| -> Result<f64, String> {
            let mut sc = preset("turn-360").ok_or("no preset")?;
            sc.as_printed = ap;
            let l = sc.ship_hull()?.rigid_body(&ap).length_m;
            let r = run(&sc)?;
            Ok((sig(&r, "y_m").max - sig(&r, "y_m").min) / 2.0 / l)
        };
        add("radius of the 360 deg turn".into(), sw, t360(t5)?, t360(AsPrintedParams::default())?, "L", why);
    }
    let plot = Plot {
        title: "Head seas SS6, 25 kn, h0 = 6 m (ch. 5.3.1, Fig. 5-15)".into(),
        x_label: "time [s]".into(),
        x_range: Some((0.0, end)),
        panels: vec![
            Panel::new("hub depth / radius h/R [-]", hr),
            Panel::new("propeller speed [rpm]", both("prop_rpm", 1.0)?),
            Panel::new("motor power [pu]", both("im_power_pu", 1.0)?),
        ],
    };
    let fig = Figure::new(
        "head-seas-ss6",
        &format!(
            "Head seas SS6 at 25 kn, one realisation: with eq. 2.57 as printed the hub leaves the water and the shaft \
             speed swings by tens of rpm (the thesis' Fig. 5-15: about {} rpm and {} pu); corrected, the hub stays \
             below the ventilation level",
            thesis_text("ch_5_3_1.prop_rpm_swing"),
            thesis_f64("ch_5_3_1.im_power_swing") / 100.0
        ),
        &plot,
    )?;
    Ok(Section {
        finding: String::new(),
        figures: vec![fig],
        title: "As printed: what each switch moves",
        note: "Every inconsistency of the thesis we settled is a switch of the scenario's `as_printed` section \
               (default: corrected), besides `seakeeping.stern_motion` for eq. 2.57. Here the thesis column is the \
               run or computation with one switch as printed, ours the corrected one; the rest of the scenario is \
               the same, the runs in waves included: both columns sail seed 1's sea, so a row shows what the switch \
               moves in one realisation (a sensitivity, not a comparison; no verdict). Not switches: the ventilation hysteresis read literally (no loop: the state would chatter \
               every step), eqs. 2.34-2.35's section map, and ch. 4's sign fixes (a stability study, not a run)."
            .into(),
        rows,
    })
}
