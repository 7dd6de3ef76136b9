//! Checks against closed forms, limits and conservation laws (no thesis number involved): energy
//! books, Parseval, Monte Carlo against Rice, the radiation solver and strip theory in their
//! limits, the Wigley hull, the bus stability boundary; and the DTMB 5415's RAO figure.

use crate::rows::row;
use crate::runs::mc;
use crate::runs::thesis_preset as preset;
use crate::svg_plot::{Panel, Plot, Series};
use crate::{Figure, Row, Section, Size, Tolerance};
use aes_core::scenario::SternMotion;

pub(crate) fn analytic(size: Size, st: &aes_core::RunResult) -> Result<Section, String> {
    let mut rows = Vec::new();
    rows.push(row(
        "energy books over the start-up: residual / turbine work",
        "conservation (ch. 5.1)",
        0.0,
        st.summary.energy_j.relative_residual,
        "-",
        Tolerance::Abs(1e-9),
        "RK4 with 1 ms steps closes the books to round-off",
    ));
    let (w, h) = aes_core::sea::waves::sea_state(6).ok_or("no sea state")?;
    let comps = aes_core::sea::waves::SeaSampling::new(h, w, 0.0).sample(1);
    rows.push(row(
        "SS6, 200 components: sum a_i^2 / 2 over H^2/16",
        "Parseval (eq. 2.58)",
        1.0,
        aes_core::sea::waves::m0(&comps) / (h * h / 16.0),
        "-",
        Tolerance::Abs(0.02),
        "the sampled band holds all but the tails of the spectrum",
    ));
    let mut sc = preset("mc-arrival").ok_or("no preset")?;
    sc.seakeeping.stern_motion = SternMotion::Consistent;
    sc.set_hub_depth_m(4.0);
    // Both hubs on the centreline: one process, Rice's (tests/montecarlo.rs).
    sc.ship.hull.shaft_y_m = Some([0.0, 0.0]);
    let s = mc(&sc, size.trials)?;
    let rice = s.rice.as_ref().ok_or("no Rice summary")?;
    let a = &s.arrival_time_s;
    let sd = a.std_censored.unwrap_or(f64::NAN);
    let se = sd / (size.trials as f64).sqrt();
    rows.push(row(
        "mean of min(T, 90 s), D = 4.8 m, h0 = 4 m (Monte Carlo against Rice)",
        "eqs. 5.1-5.3 (where their assumption of rare crossings holds)",
        rice.mean_censored_with_start_s,
        a.mean_censored.unwrap_or(f64::NAN),
        "s",
        Tolerance::Abs(2.0 * se),
        &format!(
            "two Monte Carlo standard errors ({se:.2} s, {} trials); the 'thesis' column is Rice's mean of min(T, \
             90 s) with the trials that start past the level arriving at 0",
            size.trials
        ),
    ));
    rows.extend(seakeeping_limits());
    rows.extend(bus_stability()?);
    Ok(Section {
        finding: String::new(),
        title: "Analytic checks",
        note: String::new(),
        rows,
        figures: vec![rao_figure()?],
    })
}

/// The bus stability map's boundary (issue 44, `studies::stability_map`) against the closed form
/// of a constant-power load behind its LC filter on a stiff bus, P = R_f C_f v_f^2 / L_f: the
/// plant at 20 kn with a 100 F bus, the boundary in ship service power bisected (as the map does
/// between its cells) at three filter capacitances.
fn bus_stability() -> Result<Vec<Row>, String> {
    use aes_core::studies::stability_map::{stiff_bus_check, STIFF_BUS_FILTERS_F};
    STIFF_BUS_FILTERS_F
        .into_iter()
        .map(|c_f| {
            let (closed, b) = stiff_bus_check(c_f)?;
            Ok(row(
                &format!("bus stability boundary, C_f = {} mF on a stiff bus (100 F): ship service power", c_f * 1e3),
                "closed form R_f C_f v_f^2 / L_f (constant-power load behind its filter)",
                closed / 1e6,
                b / 1e6,
                "MW",
                Tolerance::Rel(1e-3),
                "the whole plant linearised (stability_map); the rest is the bus's finite stiffness",
            ))
        })
        .collect()
}

/// The DTMB 5415's heave and pitch RAOs in head seas against wavelength, at rest and at Fn 0.28,
/// with Appendix A as printed, and the long-wave limit the rows above check.
fn rao_figure() -> Result<Figure, String> {
    use aes_core::as_printed::AsPrintedParams;
    use aes_core::sea::seakeeping::complex::cabs;
    use aes_core::sea::seakeeping::motions::response_as;
    use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
    let ship = Ship::dtmb5415();
    let table = ship.radiation_table(&default_omega_grid());
    let g = aes_core::sea::waves::G;
    let fn028 = 0.28 * libm::sqrt(g * ship.lpp);
    let printed = AsPrintedParams::default().with("appendix_a_typos", true).unwrap_or_default();
    let corrected = AsPrintedParams::default();
    // lambda / L from 0.4 to 3.
    let ratios: Vec<f64> = (0..=52).map(|i| 0.4 + 0.05 * i as f64).collect();
    type Curve = Vec<(f64, f64)>;
    let curve = |u: f64, ap: &AsPrintedParams| -> (Curve, Curve) {
        ratios
            .iter()
            .map(|&r| {
                let w = libm::sqrt(2.0 * core::f64::consts::PI * g / (r * ship.lpp));
                let x = response_as(&ship, &table, w, u, core::f64::consts::PI, 1.0, ap);
                ((r, cabs(x.heave)), (r, cabs(x.pitch) / x.k))
            })
            .unzip()
    };
    let (h0, p0) = curve(0.0, &corrected);
    let (h1, p1) = curve(fn028, &corrected);
    let (h2, p2) = curve(fn028, &printed);
    let limit = |y| Series::level("long-wave limit", 5, y, 0.4, 3.0);
    let plot = Plot {
        title: "DTMB 5415 heave and pitch RAOs, head seas".into(),
        x_label: "wavelength / ship length lambda/L [-]".into(),
        x_range: Some((0.4, 3.0)),
        panels: vec![
            Panel::new(
                "heave / wave amplitude [m/m]",
                vec![
                    Series::line("ours, at rest", 0, h0),
                    Series::line("ours, Fn 0.28", 2, h1),
                    Series::dashed("Fn 0.28, App. A as printed", 3, h2),
                    limit(1.0),
                ],
            ),
            Panel::new(
                "pitch / wave slope [-]",
                vec![
                    Series::line("ours, at rest", 0, p0),
                    Series::line("ours, Fn 0.28", 2, p1),
                    Series::dashed("Fn 0.28, App. A as printed", 3, p2),
                    limit(1.0),
                ],
            ),
        ],
    };
    Figure::new(
        "rao-dtmb5415",
        "DTMB 5415 in head seas: heave and pitch per unit wave (amplitude, slope) against wavelength; both tend to \
         the hull following the surface in long waves (the rows above); Appendix A's typos as printed make the heave \
         resonate at speed",
        &plot,
    )
}

/// Closed-form limits of the radiation solver (the semicircle) and of the strip theory (long
/// waves on the DTMB 5415), with the tolerances of their unit tests.
fn seakeeping_limits() -> Vec<Row> {
    use aes_core::sea::seakeeping::conformal::section_map;
    use aes_core::sea::seakeeping::motions::response;
    use aes_core::sea::seakeeping::radiation::coefficients;
    use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
    let (rho, g) = (1025.0, 9.81);
    let norm = rho * core::f64::consts::PI / 2.0;
    let mut rows = Vec::new();
    if let Some(circle) = section_map(1.0, 1.0, core::f64::consts::PI / 4.0) {
        let at = |ka: f64| coefficients(&circle, libm::sqrt(ka * g), rho, g);
        let hi = at(40.0);
        let lo = at(1e-4);
        let w = libm::sqrt(1e-4 * g);
        let src = "Ursell (1949): semicircle of radius a";
        rows.push(row(
            "semicircle heave added mass at Ka = 40 / (rho pi a^2 / 2)",
            src,
            1.0,
            hi.a33 / norm,
            "-",
            Tolerance::Abs(0.02),
            "the infinite-frequency limit, approached as 1/Ka",
        ));
        rows.push(row(
            "semicircle sway added mass at Ka = 1e-4 / (rho pi a^2 / 2)",
            src,
            1.0,
            lo.a22 / norm,
            "-",
            Tolerance::Abs(1e-3),
            "the zero-frequency limit",
        ));
        rows.push(row(
            "semicircle heave damping at Ka = 1e-4 / (4 rho omega a^2)",
            src,
            1.0,
            lo.b33 / (4.0 * rho * w),
            "-",
            Tolerance::Abs(5e-3),
            "the section radiates the flux it displaces",
        ));
        let ks: Vec<f64> = (1..=40).map(|i| 0.05 * i as f64).collect();
        let amin = ks.iter().map(|&k| at(k).a33 / norm).fold(f64::INFINITY, f64::min);
        rows.push(row(
            "semicircle heave added mass minimum (Ka 0.05 to 2)",
            "Ursell (1949), Vugts (1968)",
            0.6,
            amin,
            "-",
            Tolerance::Abs(0.05),
            "read off the published curves",
        ));
    }
    let ship = Ship::dtmb5415();
    let table = ship.radiation_table(&default_omega_grid());
    let fn028 = 0.28 * libm::sqrt(g * 142.0);
    for (u, name) in [(0.0, "at rest"), (fn028, "Fn 0.28")] {
        let r = response(&ship, &table, 0.12, u, core::f64::consts::PI, 1.0);
        let src = "long waves (lambda/L = 27): the hull follows the surface";
        rows.push(row(
            &format!("DTMB 5415 heave RAO, head seas, {name}"),
            src,
            1.0,
            aes_core::sea::seakeeping::complex::cabs(r.heave),
            "m/m",
            Tolerance::Abs(3e-3),
            "",
        ));
        rows.push(row(
            &format!("DTMB 5415 pitch RAO / k, head seas, {name}"),
            src,
            1.0,
            aes_core::sea::seakeeping::complex::cabs(r.pitch) / r.k,
            "-",
            Tolerance::Abs(0.02),
            "the hull's length against the wave",
        ));
    }
    let r = response(&ship, &table, 0.12, 0.0, core::f64::consts::PI / 2.0, 1.0);
    let src = "long waves, beam seas, at rest: the hull moves with the water";
    rows.push(row(
        "DTMB 5415 sway RAO",
        src,
        1.0,
        aes_core::sea::seakeeping::complex::cabs(r.sway),
        "m/m",
        Tolerance::Abs(0.01),
        "at the waterline above G",
    ));
    rows.push(row(
        "DTMB 5415 heave RAO",
        src,
        1.0,
        aes_core::sea::seakeeping::complex::cabs(r.heave),
        "m/m",
        Tolerance::Abs(1e-3),
        "",
    ));
    rows.extend(wigley_rows());
    rows
}

/// The Wigley hull (L 100 m, B 10 m, T 6.25 m, generated in code): hydrostatics against the closed
/// forms, heave and pitch in long head waves, and the Fn 0.3 heave resonance. Measurements are
/// compared on the Wigley III model ([`wigley_iii_experiments`]).
fn wigley_rows() -> Vec<Row> {
    use aes_core::sea::seakeeping::motions::natural_periods;
    use aes_core::sea::seakeeping::strip::{default_omega_grid, Ship};
    use aes_core::sea::seakeeping::wigley_check::heave_pitch;
    use aes_core::ship::sections::HullOffsets;
    let (l, b, t) = (100.0, 10.0, 6.25);
    let mut rows = Vec::new();
    let Ok(h) = HullOffsets::wigley().hydrostatics(t) else { return rows };
    let src = "closed form of y = (B/2)(1 - xi^2)(1 - (d/T)^2)";
    let why = "trapezoid over 19 cosine-spaced stations";
    for (name, exact, ours, unit, tol) in [
        ("volume, (4/9) L B T", 4.0 / 9.0 * l * b * t, h.volume, "m^3", 6e-3),
        ("waterplane area, (2/3) L B", 2.0 / 3.0 * l * b, h.awp, "m^2", 6e-3),
        ("KB, 5T/8", 5.0 * t / 8.0, h.kb, "m", 5e-4),
        ("BM_T, 3 B^2 / (35 T)", 3.0 * b * b / (35.0 * t), h.bmt, "m", 1e-3),
    ] {
        rows.push(row(&format!("Wigley hull {name}"), src, exact, ours, unit, Tolerance::Rel(tol), why));
    }
    let ship = Ship::wigley();
    let table = ship.radiation_table(&default_omega_grid());
    for froude in [0.2, 0.3] {
        let (hv, p) = heave_pitch(&ship, &table, froude, 20.0);
        let src = "long waves (lambda/L = 20): the hull follows the surface";
        rows.push(row(
            &format!("Wigley heave RAO, head seas, Fn {froude}"),
            src,
            1.0,
            hv,
            "m/m",
            Tolerance::Abs(0.005),
            "",
        ));
        rows.push(row(
            &format!("Wigley pitch RAO / k, head seas, Fn {froude}"),
            src,
            1.0,
            p,
            "-",
            Tolerance::Abs(0.01),
            "",
        ));
    }
    let (t3, _) = natural_periods(&ship, &table);
    let u = 0.3 * libm::sqrt(ship.g * l);
    let peak = (0..=200)
        .map(|i| 0.5 + 0.01 * i as f64)
        .max_by(|&a, &c| heave_pitch(&ship, &table, 0.3, a).0.total_cmp(&heave_pitch(&ship, &table, 0.3, c).0))
        .unwrap_or(1.0);
    let k = 2.0 * core::f64::consts::PI / (peak * l);
    rows.push(row(
        "Wigley heave peak encounter frequency, head seas, Fn 0.3",
        "heave natural frequency from the computed added mass",
        2.0 * core::f64::consts::PI / t3,
        libm::sqrt(ship.g * k) + k * u,
        "rad/s",
        Tolerance::Rel(0.05),
        "resonance; the peak heave is 1.82 m/m at lambda/L 1.09 (strip theory, lightly damped)",
    ));
    rows
}
