//! The Wigley hulls in head seas. The Wigley I (L/B 10, B/T 1.6; `Ship::wigley`): heave and
//! pitch RAOs at Fn 0.2 and 0.3 from our strip theory, their convergence in the number of
//! stations, their long-wave limits and resonance. The Wigley III (Journee's model, L 3 m):
//! every point of Journee's (1992) experiments in core/data/journee1992_wigley_iii.csv computed
//! by our strip theory at the same condition and in the report's normalisation
//! ([`journee_wigley_iii`]), and the added resistance's scaling with the beam.
//!
//! Source: J.M.J. Journee, "Experiments and calculations on four Wigley hullforms", Delft
//! University of Technology, Ship Hydromechanics Laboratory, report 909, 1992.

use super::motions::{heave_pitch_system, response};
use super::strip::{MassProperties, RadiationTable, Ship};
use crate::geometry::HullOffsets;
use crate::numerics::complex::cabs;
use std::f64::consts::PI;

/// Journee's (1992) Wigley III measurements (see the file's header for the normalisations).
pub const JOURNEE1992_WIGLEY_III: &str = include_str!("../../../data/journee1992_wigley_iii.csv");

/// Journee's Wigley III model: L 3 m, B 0.3 m, d 0.1875 m (report 909).
pub const WIGLEY_III_L: f64 = 3.0;
pub const WIGLEY_III_B: f64 = 0.3;
pub const WIGLEY_III_D: f64 = 0.1875;
/// Stations of our Wigley III (cosine-spaced) and rows below its waterline.
pub const WIGLEY_III_STATIONS: usize = 31;
pub const WIGLEY_III_ROWS: usize = 24;
/// Our KG \[m\]. Journee's KG 0.17 m leaves the model unstable in roll (GM_T < 0: it was guided in
/// roll), which `Ship::new` refuses. KG enters head-sea heave and pitch only through C55's
/// rho g V (z_B - z_G) and the pitch inertia's z_G^2, and 0.15 m raises those by 0.5 % and
/// 0.2 % over KG 0.17 m while it keeps GM_T positive (+0.0096 m).
pub const WIGLEY_III_KG: f64 = 0.15;
/// Fresh water [kg/m^3] (Journee's tank).
pub const FRESH_WATER_RHO: f64 = 1000.0;

/// One point of Journee's tables beside our value in the same normalisation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JourneePoint {
    /// heave, pitch, a33, b33, x3, x5 or raw_peak (see the CSV's header).
    pub table: &'static str,
    /// Froude number.
    pub fn_: f64,
    /// lambda/L (heave, pitch, x3, x5), omega_e sqrt(L/g) (a33, b33); for raw_peak our
    /// lambda/L at the peak (Journee's is not given).
    pub x: f64,
    pub measured: f64,
    pub ours: f64,
}

/// Heave RAO [m/m] and pitch RAO over the wave slope, pitch / (k zeta_a) [-], in head seas
/// (beta = 180 deg) at Froude number `froude` and wave length ratio `lambda_over_l`.
pub fn heave_pitch(ship: &Ship, table: &RadiationTable, froude: f64, lambda_over_l: f64) -> (f64, f64) {
    let g = ship.g;
    let k = 2.0 * PI / (lambda_over_l * ship.lpp);
    let u = froude * libm::sqrt(g * ship.lpp);
    let r = response(ship, table, libm::sqrt(g * k), u, PI, 1.0);
    (cabs(r.heave), cabs(r.pitch) / r.k)
}

/// A Wigley III-form model of beam `beam` \[m\] (Journee's is 0.3 m) at Journee's length, draft
/// and loading: KG [`WIGLEY_III_KG`], k_yy = k_zz = 0.25 L (k_xx = 0.35 B, our choice: roll
/// plays no part in head seas), mass from the displaced volume in fresh water, g = 9.81.
pub fn wigley_iii_model(beam: f64, stations: usize) -> Result<Ship, String> {
    let (l, d) = (WIGLEY_III_L, WIGLEY_III_D);
    let mass = MassProperties { kg_m: WIGLEY_III_KG, kxx_m: 0.35 * beam, kyy_m: 0.25 * l, kzz_m: 0.25 * l };
    let hull = HullOffsets::wigley_iii(l, beam, d, stations, WIGLEY_III_ROWS);
    Ship::new(&hull, d, mass, None, FRESH_WATER_RHO, crate::sea::waves::G)
}

/// The encounter-frequency grid for a model of length `lpp`: 64 points, geometric in
/// omega sqrt(L/g) from 0.3 to 12 (the default grid of `strip` is for ships of about 100 m and
/// stops at 4 rad/s, which a 3 m model passes at omega sqrt(L/g) = 2.2).
pub fn model_omega_grid(lpp: f64, g: f64) -> Vec<f64> {
    let s = libm::sqrt(g / lpp);
    let (lo, hi, n) = (0.3f64, 12.0f64, 64);
    (0..n).map(|i| s * lo * libm::pow(hi / lo, i as f64 / (n - 1) as f64)).collect()
}

/// Deep-water wave frequency [rad/s] whose head-sea encounter frequency at speed `u` is `we`:
/// omega_e = omega0 + omega0^2 U / g.
fn head_sea_omega0(we: f64, u: f64, g: f64) -> f64 {
    if u <= 0.0 {
        return we;
    }
    let c = u / g;
    (libm::sqrt(1.0 + 4.0 * c * we) - 1.0) / (2.0 * c)
}

/// Our value of one of Journee's quantities for `ship` in head seas at Froude number `froude`
/// and abscissa `x`, in the report's normalisation (the CSV's header): heave z_a/zeta_a and
/// pitch theta_a L/(2 pi zeta_a) from `response`; A33/(rho V) and B33/(rho V) sqrt(L/g) at
/// omega_e = x sqrt(g/L) (STF with the speed terms); |X3|/(C33 zeta_a) and |X5|/(k C55 zeta_a)
/// on the restrained ship (Froude-Krylov plus diffraction, C33 and C55 those of our equations of
/// motion). `raw_peak` is not a point: see [`raw_peak`].
pub fn journee_quantity(ship: &Ship, table: &RadiationTable, name: &str, froude: f64, x: f64) -> Result<f64, String> {
    let (g, l) = (ship.g, ship.lpp);
    let u = froude * libm::sqrt(g * l);
    let omega0_of_lambda = |lam: f64| libm::sqrt(g * 2.0 * PI / (lam * l));
    let rv = ship.rho * ship.volume;
    Ok(match name {
        "heave" => cabs(response(ship, table, omega0_of_lambda(x), u, PI, 1.0).heave),
        "pitch" => cabs(response(ship, table, omega0_of_lambda(x), u, PI, 1.0).pitch) * l / (2.0 * PI),
        "a33" | "b33" => {
            let we = x * libm::sqrt(g / l);
            let s = heave_pitch_system(ship, table, head_sea_omega0(we, u, g), u, PI);
            if name == "a33" {
                s.a33 / rv
            } else {
                s.b33 / rv * libm::sqrt(l / g)
            }
        }
        "x3" | "x5" => {
            let w0 = omega0_of_lambda(x);
            let s = heave_pitch_system(ship, table, w0, u, PI);
            if name == "x3" {
                cabs(s.x3_fk + s.x3_d) / s.c33
            } else {
                cabs(s.x5_fk + s.x5_d) / (w0 * w0 / g * s.c55)
            }
        }
        _ => return Err(format!("unknown quantity '{name}'")),
    })
}

/// The peak over lambda/L = 0.3 to 3 (steps of 0.005) of the added resistance in head seas by
/// Salvesen's (1978) method (eqs. 2.47-2.48), R_aw / (rho g zeta_a^2 B^2 / L) with B the ship's
/// beam, and the lambda/L where it is reached.
pub fn raw_peak(ship: &Ship, table: &RadiationTable, froude: f64) -> (f64, f64) {
    let (g, l) = (ship.g, ship.lpp);
    let u = froude * libm::sqrt(g * l);
    let norm = ship.rho * g * ship.beam * ship.beam / l;
    (0..=540)
        .map(|i| {
            let lam = 0.3 + 0.005 * i as f64;
            let r = response(ship, table, libm::sqrt(g * 2.0 * PI / (lam * l)), u, PI, 1.0);
            (r.added_resistance / norm, lam)
        })
        .fold((f64::NEG_INFINITY, 0.0), |a, b| if b.0 > a.0 { b } else { a })
}

fn table_name(s: &str) -> Result<&'static str, String> {
    ["heave", "pitch", "a33", "b33", "x3", "x5", "raw_peak"]
        .into_iter()
        .find(|&n| n == s)
        .ok_or_else(|| format!("unknown table '{s}'"))
}

/// Every point of Journee's (1992) Wigley III tables (core/data/journee1992_wigley_iii.csv)
/// beside our strip theory's value at the same condition and in the same normalisation, in the
/// file's order, on Journee's model ([`wigley_iii_model`] with B 0.3 m).
pub fn journee_wigley_iii() -> Result<Vec<JourneePoint>, String> {
    let ship = wigley_iii_model(WIGLEY_III_B, WIGLEY_III_STATIONS)?;
    let table = ship.radiation_table(&model_omega_grid(ship.lpp, ship.g));
    journee_points(&ship, &table)
}

/// [`journee_wigley_iii`] for a given ship and radiation table.
pub fn journee_points(ship: &Ship, table: &RadiationTable) -> Result<Vec<JourneePoint>, String> {
    let mut out = Vec::new();
    let mut header = false;
    for (k, line) in JOURNEE1992_WIGLEY_III.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if !header {
            if line != "table,fn,x_name,x,value" {
                return Err(format!("line {}: unexpected header '{line}'", k + 1));
            }
            header = true;
            continue;
        }
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() != 5 {
            return Err(format!("line {}: expected 5 fields", k + 1));
        }
        let num = |s: &str| s.parse::<f64>().map_err(|_| format!("line {}: '{s}' is not a number", k + 1));
        let table_n = table_name(f[0])?;
        let (froude, measured) = (num(f[1])?, num(f[4])?);
        let (x, ours) = if table_n == "raw_peak" {
            let (peak, lam) = raw_peak(ship, table, froude);
            (lam, peak)
        } else {
            let x = num(f[3])?;
            (x, journee_quantity(ship, table, table_n, froude, x)?)
        };
        out.push(JourneePoint { table: table_n, fn_: froude, x, measured, ours });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea::seakeeping::motions::natural_periods;
    use crate::sea::seakeeping::strip::default_omega_grid;
    use std::sync::OnceLock;

    fn wigley() -> &'static (Ship, RadiationTable) {
        static H: OnceLock<(Ship, RadiationTable)> = OnceLock::new();
        H.get_or_init(|| {
            let s = Ship::wigley();
            let t = s.radiation_table(&default_omega_grid());
            (s, t)
        })
    }

    fn lambdas() -> impl Iterator<Item = f64> {
        (0..=20).map(|i| 0.5 + 0.1 * i as f64)
    }

    /// Tripling the stations (19 to 61, cosine-spaced) moves heave and pitch / (k zeta_a) at
    /// Fn 0.2 and 0.3, lambda/L 0.5 to 2.5, by under 0.5 % of the curve's peak (measured in the
    /// output; 21 and 31 stations move them by under 0.3 %, 15 stations by up to 0.7 %).
    #[test]
    fn wigley_raos_converged_in_stations() {
        let (ship, table) = wigley();
        let fine = Ship::new(
            &HullOffsets::wigley_sized(100.0, 10.0, 6.25, 61, 24),
            6.25,
            ship.mass_props,
            None,
            ship.rho,
            ship.g,
        )
        .unwrap();
        let tf = fine.radiation_table(&default_omega_grid());
        for froude in [0.2, 0.3] {
            let a: Vec<(f64, f64)> = lambdas().map(|l| heave_pitch(ship, table, froude, l)).collect();
            let b: Vec<(f64, f64)> = lambdas().map(|l| heave_pitch(&fine, &tf, froude, l)).collect();
            let peak_h = a.iter().map(|x| x.0).fold(0.0, f64::max);
            let peak_p = a.iter().map(|x| x.1).fold(0.0, f64::max);
            let dh = a.iter().zip(&b).map(|(x, y)| (x.0 - y.0).abs()).fold(0.0, f64::max) / peak_h;
            let dp = a.iter().zip(&b).map(|(x, y)| (x.1 - y.1).abs()).fold(0.0, f64::max) / peak_p;
            println!(
                "Fn {froude}: 19 vs 61 stations, heave {:.3} %, pitch {:.3} % of the peak",
                100.0 * dh,
                100.0 * dp
            );
            assert!(dh < 5e-3 && dp < 5e-3, "Fn {froude}: {dh} {dp}");
        }
    }

    /// Long head waves (lambda/L = 20): heave -> 1 and pitch / (k zeta_a) -> 1 at Fn 0.2 and 0.3
    /// (within 0.005 and 0.01; measured heave 1.0012 and 1.0029, pitch 1.0048 and 1.0039).
    #[test]
    fn wigley_long_wave_limits() {
        let (ship, table) = wigley();
        for froude in [0.2, 0.3] {
            let (h, p) = heave_pitch(ship, table, froude, 20.0);
            println!("Fn {froude}, lambda/L 20: heave {h:.4}, pitch/(k zeta) {p:.4}");
            assert!((h - 1.0).abs() < 0.005 && (p - 1.0).abs() < 0.01, "Fn {froude}: {h} {p}");
        }
    }

    /// At Fn 0.3 the heave peak sits where the encounter frequency meets the heave natural
    /// frequency from the computed added mass (within 5 %), and strip theory's lightly damped
    /// resonance makes it the largest heave of the speeds: over 1.5 at Fn 0.3, under 1 at Fn 0.2.
    #[test]
    fn wigley_heave_resonance_at_fn_03() {
        let (ship, table) = wigley();
        let (t3, _) = natural_periods(ship, table);
        let w3 = 2.0 * PI / t3;
        let fine: Vec<f64> = (0..=200).map(|i| 0.5 + 0.01 * i as f64).collect();
        let peak = |froude: f64| {
            fine.iter()
                .map(|&l| (l, heave_pitch(ship, table, froude, l)))
                .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
                .unwrap()
        };
        let (l3, (h3, p3)) = peak(0.3);
        let (l2, (h2, p2)) = peak(0.2);
        let k = 2.0 * PI / (l3 * ship.lpp);
        let we = libm::sqrt(ship.g * k) + k * 0.3 * libm::sqrt(ship.g * ship.lpp);
        println!("T3 {t3:.2} s (omega {w3:.3}); Fn 0.3 heave peak {h3:.3} (pitch {p3:.3}) at lambda/L {l3:.2}, omega_e {we:.3}; Fn 0.2 peak {h2:.3} (pitch {p2:.3}) at {l2:.2}");
        assert!((we / w3 - 1.0).abs() < 0.05, "{we} vs {w3}");
        assert!(h3 > 1.5 && h2 < 1.0);
    }

    /// Journee's Wigley III model and its radiation table on the model's grid.
    fn wigley_iii() -> &'static (Ship, RadiationTable) {
        static H: OnceLock<(Ship, RadiationTable)> = OnceLock::new();
        H.get_or_init(|| {
            let s = wigley_iii_model(WIGLEY_III_B, WIGLEY_III_STATIONS).unwrap();
            let t = s.radiation_table(&model_omega_grid(s.lpp, s.g));
            (s, t)
        })
    }

    /// The Wigley III's hydrostatics against Journee's (1992) volume 0.078 m^3 and CB 0.4622 (the
    /// closed form of the hull formula: CB = (2/3)(1/2)(2 - 2/3 + 0.4/3 - 0.08) = 0.46222, V =
    /// 0.078000 m^3): the trapezoid over 31 cosine-spaced stations gives V 0.077824 m^3 and
    /// CB 0.46118 (-0.23 %; tolerance 0.3 %), 61 stations -0.09 % (tolerance 0.12 %); KB 5d/8
    /// within 0.05 %. Journee's KG 0.17 m is above KM_T = 0.1596 m (GM_T -0.010 m): our KG
    /// 0.15 m gives GM_T +0.0096 m.
    #[test]
    fn wigley_iii_hydrostatics_against_journee() {
        let (l, b, d) = (WIGLEY_III_L, WIGLEY_III_B, WIGLEY_III_D);
        let cb_exact: f64 = (2.0 / 3.0) * 0.5 * (2.0 - 2.0 / 3.0 + 0.4 / 3.0 - 0.08);
        assert!((cb_exact - 0.4622).abs() < 5e-5 && (cb_exact * l * b * d - 0.078).abs() < 5e-5);
        for (n, tol) in [(WIGLEY_III_STATIONS, 3e-3), (61, 1.2e-3)] {
            let h = HullOffsets::wigley_iii(l, b, d, n, WIGLEY_III_ROWS).hydrostatics(d).unwrap();
            let cb = h.volume / (l * b * d);
            println!(
                "{n} stations: V {:.6} m^3 ({:+.3} % of 0.078), CB {cb:.5} ({:+.3} % of 0.4622), KB {:.5} m, Awp {:.5} m^2, KM_T {:.4} m",
                h.volume,
                100.0 * (h.volume / 0.078 - 1.0),
                100.0 * (cb / 0.4622 - 1.0),
                h.kb,
                h.awp,
                h.kb + h.bmt
            );
            assert!((h.volume / 0.078 - 1.0).abs() < tol && (cb / 0.4622 - 1.0).abs() < tol, "{n}: {h:?}");
            assert!((h.kb / (5.0 * d / 8.0) - 1.0).abs() < 5e-4, "KB {}", h.kb);
            assert!(h.kb + h.bmt < 0.17 && h.kb + h.bmt > WIGLEY_III_KG);
        }
        let (ship, _) = wigley_iii();
        assert!(ship.gm_t > 0.0 && (ship.mass - FRESH_WATER_RHO * ship.volume).abs() < 1e-9);
    }

    /// The accessor `heave_pitch_system` is the system `response` solves: its coefficients and
    /// excitation give `response`'s heave and pitch to 1e-9 (Fn 0, 0.3; lambda/L 0.6 to 2; with
    /// and without STF's aft-end terms).
    #[test]
    fn heave_pitch_system_is_the_one_response_solves() {
        let (with_end, table) = wigley_iii();
        let mut without_end = with_end.clone();
        without_end.aft_end_terms = false;
        for (ship, froude) in [(with_end, 0.0), (with_end, 0.3), (&without_end, 0.3)] {
            let (g, l) = (ship.g, ship.lpp);
            let u = froude * libm::sqrt(g * l);
            for lam in [0.6, 1.0, 1.3, 2.0] {
                let w0 = libm::sqrt(g * 2.0 * PI / (lam * l));
                let r = response(ship, table, w0, u, PI, 1.0);
                let s = heave_pitch_system(ship, table, w0, u, PI);
                let we = s.omega_e;
                let z = |m: f64, b: f64, c: f64| num_complex::Complex64::new(c - we * we * m, we * b);
                let (m11, m12) = (z(s.mass + s.a33, s.b33, s.c33), z(s.a35, s.b35, s.c35));
                let (m21, m22) = (z(s.a53, s.b53, s.c35), z(s.i55 + s.a55, s.b55, s.c55));
                let (f3, f5) = (s.x3_fk + s.x3_d, s.x5_fk + s.x5_d);
                let det = m11 * m22 - m12 * m21;
                let (h, p) = ((f3 * m22 - m12 * f5) / det, (m11 * f5 - m21 * f3) / det);
                assert!((we - r.omega_e).abs() < 1e-12 * we);
                assert!(cabs(h - r.heave) < 1e-9 * cabs(r.heave), "Fn {froude} {lam}: {h} vs {}", r.heave);
                assert!(cabs(p - r.pitch) < 1e-9 * cabs(r.pitch), "Fn {froude} {lam}: {p} vs {}", r.pitch);
            }
        }
    }

    /// Every Journee (1992) Wigley III point against ours (printed as a table), asserting the
    /// agreement reached (difference = ours / measured - 1):
    ///
    /// - A33 (Fn 0.3, omega_e sqrt(L/g) 2.22 to 4.45; measured 0.707 to 0.421): ours 6.7 to 10.8 %
    ///   low at every point (asserted: -12 % to -5 %).
    /// - B33 (measured 1.963 to 1.518): +13.1 % at 2.22 falling to -4.0 % at 4.45 (asserted: within
    ///   14 %, and the difference falls with frequency).
    /// - X3 (Fn 0.3, lambda/L 1.25 to 2; measured 0.345 to 0.577): -4.7 % to +5.8 % (within 6.5 %).
    /// - X5 (measured 0.444 to 0.658): ours 7.0 to 11.6 % high at every point (+5 % to +12.5 %).
    ///   Our zero-speed X5 is 0.459, 0.558, 0.682 at lambda/L 1.25, 1.5, 2 (printed), within
    ///   2.2 to 3.6 % of the Fn 0.3 measurements: the excess is STF's speed term U/(i omega_e) in the
    ///   pitch diffraction moment.
    /// - Heave, Fn 0.2 and 0.3 (lambda/L 1.25 to 2; measured 0.71 to 1.28): +0.3 to +9.2 % (within
    ///   10 %); heave, Fn 0, lambda/L 1 to 2 (measured 0.29 to 0.74): -1.1 to +9.5 % (within 10 %).
    /// - Pitch theta_a L / (2 pi zeta_a), Fn 0, lambda/L 0.75 to 2 (measured 0.33 to 0.63): +3.6 to
    ///   -13.1 % (within 14 %).
    ///
    /// Printed, not compared: heave at Fn 0 for lambda/L under 1 (measured 0.04 to 0.22, around
    /// the zero of the heave excitation near lambda/L 0.75 and the heave resonance near 0.5: ours
    /// differ by up to 0.10 (0.117 against 0.22 at 0.64); asserted only that ours, like the
    /// measurements, has its minimum at 0.75 among 0.64, 0.75 and 0.857), pitch at Fn 0 under
    /// lambda/L 0.75 (measured 0.12, 0.51, 0.14, 0.21 at 0.417 to 0.64: the 0.51 at 0.5 stands alone
    /// between 0.12 and 0.14 and looks like a reading error; ours 0.21, 0.17, 0.07, 0.16), and the
    /// added-resistance peaks (measured 22.2, 20.2, 27.7 at Fn 0.2, 0.3, 0.4; ours 17.9, 30.0,
    /// 40.9: -19 %, +48 %, +48 %), where only the physically required is asserted: positive and
    /// finite, within a factor 2 of the measured, peaking at lambda/L 0.8 to 1.5 and moving to
    /// longer waves with speed. Our Fn 0.3 heave peaks at 1.69 at lambda/L 1.09, shorter than
    /// Journee's first point (1.25). STF's aft-end terms move no point by over 0.01 %.
    #[test]
    fn wigley_iii_against_journee_1992() {
        let (ship, table) = wigley_iii();
        let pts = journee_points(ship, table).unwrap();
        assert_eq!(pts.len(), 50);
        let d = |p: &JourneePoint| p.ours / p.measured - 1.0;
        for p in &pts {
            println!(
                "{:8} Fn {:.1} x {:6.3}: measured {:7.3}, ours {:7.3} ({:+6.1} %)",
                p.table,
                p.fn_,
                p.x,
                p.measured,
                p.ours,
                100.0 * d(p)
            );
            assert!(p.ours.is_finite() && p.ours > 0.0, "{p:?}");
        }
        let of = |t: &'static str| pts.iter().filter(move |p| p.table == t);
        let check = |name: &str, pts: Vec<&JourneePoint>, lo: f64, hi: f64| {
            assert!(!pts.is_empty(), "{name}");
            for p in pts {
                assert!((lo..=hi).contains(&d(p)), "{name}: {p:?} differs by {:+.1} %", 100.0 * d(p));
            }
        };
        check("A33", of("a33").collect(), -0.12, -0.05);
        check("B33", of("b33").collect(), -0.14, 0.14);
        let b33: Vec<f64> = of("b33").map(d).collect();
        assert!(b33.windows(2).all(|w| w[1] < w[0]), "{b33:?}");
        check("X3", of("x3").collect(), -0.065, 0.065);
        check("X5", of("x5").collect(), 0.05, 0.125);
        check("heave, Fn 0.2 and 0.3", of("heave").filter(|p| p.fn_ > 0.0).collect(), -0.1, 0.1);
        check("heave, Fn 0, lambda/L >= 1", of("heave").filter(|p| p.fn_ == 0.0 && p.x >= 1.0).collect(), -0.1, 0.1);
        check("pitch, Fn 0, lambda/L >= 0.75", of("pitch").filter(|p| p.x >= 0.75).collect(), -0.14, 0.14);
        // Short waves at zero speed: the heave excitation's zero near lambda/L 0.75.
        let h0 = |x: f64| of("heave").find(|p| p.fn_ == 0.0 && p.x == x).unwrap().ours;
        assert!(h0(0.75) < h0(0.64) && h0(0.75) < h0(0.857));
        // Added resistance: the right order and place only.
        let raw: Vec<&JourneePoint> = of("raw_peak").collect();
        assert_eq!(raw.len(), 3);
        for p in &raw {
            assert!((0.5..=2.0).contains(&(p.ours / p.measured)) && (0.8..=1.5).contains(&p.x), "{p:?}");
        }
        assert!(raw[0].x < raw[1].x && raw[1].x < raw[2].x);
        // STF's aft-end terms (on by default; the Wigley has no transom, its aftmost strip a
        // small beam): what turning them off moves.
        let mut no_end = ship.clone();
        no_end.aft_end_terms = false;
        let off = journee_points(&no_end, table).unwrap();
        let moved = pts.iter().zip(&off).map(|(a, b)| (b.ours / a.ours - 1.0).abs()).fold(0.0, f64::max);
        println!("without the aft-end terms the points move by at most {:.2} %", 100.0 * moved);
        // Our Fn 0.3 heave peak (Journee's points start at lambda/L 1.25).
        let (lam, h) = (0..=100)
            .map(|i| 0.9 + 0.005 * i as f64)
            .map(|l| (l, heave_pitch(ship, table, 0.3, l).0))
            .fold((0.0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
        println!("ours: Fn 0.3 heave peak {h:.3} at lambda/L {lam:.3}");
        // Zero-speed pitch moment in long waves, for the pitch deficit: Froude-Krylov and total.
        for lam in [1.25, 1.5, 2.0] {
            let w0 = libm::sqrt(ship.g * 2.0 * PI / (lam * ship.lpp));
            let s = heave_pitch_system(ship, table, w0, 0.0, PI);
            let kc = w0 * w0 / ship.g * s.c55;
            println!(
                "Fn 0, lambda/L {lam}: |X5|/(k C55) Froude-Krylov {:.3}, with diffraction {:.3}; |X3|/C33 {:.3}, {:.3}",
                cabs(s.x5_fk) / kc,
                cabs(s.x5_fk + s.x5_d) / kc,
                cabs(s.x3_fk) / s.c33,
                cabs(s.x3_fk + s.x3_d) / s.c33
            );
        }
    }

    /// Peak over lambda/L 0.3 to 3 of the added resistance by Gerritsma and Beukelman (the
    /// radiated-energy method `response` also gives), R_aw / (rho g zeta_a^2 B^2 / L).
    fn raw_peak_gb(ship: &Ship, table: &RadiationTable, froude: f64) -> f64 {
        let (g, l) = (ship.g, ship.lpp);
        let u = froude * libm::sqrt(g * l);
        (0..=540)
            .map(|i| {
                let w0 = libm::sqrt(g * 2.0 * PI / ((0.3 + 0.005 * i as f64) * l));
                response(ship, table, w0, u, PI, 1.0).added_resistance_gb
            })
            .fold(f64::NEG_INFINITY, f64::max)
            / (ship.rho * g * ship.beam * ship.beam / l)
    }

    /// Salvesen's added resistance against the beam: the Wigley III form at B/L 0.10 (Journee's),
    /// 0.15 and 0.20, same L, draft and loading. Measured in the output, nondimensional peak
    /// R_aw / (rho g zeta_a^2 B^2 / L) at Fn 0.2 / 0.3 / 0.4:
    ///
    /// - B/L 0.10: 17.9 / 30.0 / 40.9 at lambda/L 0.91 / 1.07 / 1.24 (heave there 0.81 / 1.67 / 2.53)
    /// - B/L 0.15: 10.4 / 15.4 / 19.8 at 0.99 / 1.14 / 1.31 (heave 0.76 / 1.30 / 1.85)
    /// - B/L 0.20:  7.2 /  9.8 / 12.1 at 1.06 / 1.22 / 1.39 (heave 0.73 / 1.13 / 1.53)
    ///
    /// The dimensional peak grows as B^0.2 to B^0.7 (not B^2), so the nondimensional one falls
    /// with the beam, most at the higher speeds, and the peak moves to longer waves. Gerritsma and
    /// Beukelman's radiated energy (an independent formula on the same motions) falls alike: the
    /// ratio Salvesen / GB is 0.77 / 0.62 / 0.55 at every beam (within 2 %). The beam dependence is
    /// the motions' (a wider hull at the same draft is more damped: damping grows as B^2, mass and
    /// restoring as B, so the heave-pitch resonance flattens), not a B^1 scaling of Salvesen's
    /// formula. Asserted: the nondimensional peak falls with the beam at each speed, the
    /// dimensional exponent lies in 0 to 1, and the Salvesen / GB ratio varies by under 3 % with
    /// the beam.
    #[test]
    fn salvesen_added_resistance_against_beam() {
        let mut rows = Vec::new();
        for bl in [0.10, 0.15, 0.20] {
            let b = bl * WIGLEY_III_L;
            let mut s = wigley_iii_model(b, WIGLEY_III_STATIONS).unwrap();
            s.short_wave = crate::sea::seakeeping::reflection::ShortWaveForce::SalvesenF7;
            let t = s.radiation_table(&model_omega_grid(s.lpp, s.g));
            let row: Vec<(f64, f64, f64, f64)> = [0.2, 0.3, 0.4]
                .into_iter()
                .map(|fr| {
                    let (peak, lam) = raw_peak(&s, &t, fr);
                    let (h, _) = heave_pitch(&s, &t, fr, lam);
                    (peak, lam, h, peak / raw_peak_gb(&s, &t, fr))
                })
                .collect();
            rows.push((b, row));
        }
        for (b, row) in &rows {
            for (fr, (peak, lam, h, ratio)) in [0.2, 0.3, 0.4].iter().zip(row) {
                println!(
                    "B/L {:.2} Fn {fr}: Salvesen peak {peak:.2} at lambda/L {lam:.3} (heave {h:.3}), Salvesen/GB {ratio:.3}, dimensional {:.1} N/m^2",
                    b / WIGLEY_III_L,
                    peak * FRESH_WATER_RHO * 9.81 * b * b / WIGLEY_III_L
                );
            }
        }
        for (j, fr) in [0.2, 0.3, 0.4].into_iter().enumerate() {
            let (b0, r0) = (rows[0].0, rows[0].1[j]);
            for (b, r) in rows.iter().skip(1).map(|(b, r)| (*b, r[j])) {
                let expo = libm::log(r.0 * b * b / (r0.0 * b0 * b0)) / libm::log(b / b0);
                println!("Fn {fr}: dimensional peak ~ B^{expo:.2} from B/L 0.10 to {:.2}", b / WIGLEY_III_L);
                assert!(r.0 < r0.0 && r.1 > r0.1, "{r:?} vs {r0:?}");
                assert!((0.0..1.0).contains(&expo), "{expo}");
                assert!((r.3 / r0.3 - 1.0).abs() < 0.03, "Salvesen/GB {} vs {}", r.3, r0.3);
            }
        }
    }

    /// The RAO table's precompute time on the default 40 x 8 x 13 grid, the Wigley hull beside
    /// the DTMB 5415, in one run (`cargo test --release -p aes-core --lib table_time -- --ignored
    /// --nocapture`).
    #[test]
    #[ignore = "a timing, printed"]
    fn wigley_table_time_against_dtmb5415() {
        use crate::sea::seakeeping::tables::{RaoTable, SeakeepingGrid};
        let grid = SeakeepingGrid::default();
        let (wig, dtmb) = (Ship::wigley(), Ship::dtmb5415());
        let time = |s: &Ship| {
            let t0 = std::time::Instant::now();
            RaoTable::compute(s, &grid).unwrap();
            t0.elapsed().as_secs_f64()
        };
        // Twice each, alternating, to see the spread.
        let (d1, w1, d2, w2) = (time(&dtmb), time(&wig), time(&dtmb), time(&wig));
        println!(
            "RaoTable::compute, default grid: DTMB 5415 ({} strips) {d1:.2} / {d2:.2} s, Wigley ({} strips) {w1:.2} / {w2:.2} s, ratio {:.2}",
            dtmb.strips.len(),
            wig.strips.len(),
            (w1 + w2) / (d1 + d2)
        );
    }
}
