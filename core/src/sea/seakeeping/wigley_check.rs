//! The Wigley hull (L/B 10, B/T 1.6; `Ship::wigley`) in head seas: heave and pitch RAOs at Fn 0.2
//! and 0.3 from our strip theory, their convergence in the number of stations, their long-wave
//! limits and resonance, and the comparison with the published experiments of
//! core/data/wigley_journee1992_head_seas.csv (empty until the reference points are found).

use super::strip::{response, RadiationTable, Ship};
use crate::sea::seakeeping::complex::cabs;
use std::f64::consts::PI;

/// Reference points for the Wigley I hull in head seas (see the file's header).
pub const WIGLEY_JOURNEE1992: &str = include_str!("../../../data/wigley_journee1992_head_seas.csv");

/// Heave RAO [m/m] and pitch RAO over the wave slope, pitch / (k zeta_a) [-], in head seas
/// (beta = 180 deg) at Froude number `froude` and wave length ratio `lambda_over_l`, as
/// Journee (1992) plots them.
pub fn heave_pitch(ship: &Ship, table: &RadiationTable, froude: f64, lambda_over_l: f64) -> (f64, f64) {
    let g = ship.g;
    let k = 2.0 * PI / (lambda_over_l * ship.lpp);
    let u = froude * libm::sqrt(g * ship.lpp);
    let r = response(ship, table, libm::sqrt(g * k), u, PI, 1.0);
    (cabs(r.heave), cabs(r.pitch) / r.k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea::seakeeping::strip::{default_omega_grid, natural_periods};
    use crate::ship::sections::HullOffsets;
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

    /// Our heave and pitch against the published points of core/data/wigley_journee1992_head_seas.csv:
    /// within 0.1 plus the point's reading uncertainty (heave / zeta_a and pitch / (k zeta_a)), except
    /// the points whose `exclude` column gives a reason. Ignored while the file has no data rows.
    #[test]
    #[ignore = "core/data/wigley_journee1992_head_seas.csv has no reference points yet (Journee 1992 not found)"]
    fn wigley_against_journee_1992() {
        let (ship, table) = wigley();
        let mut asserted = 0;
        for line in WIGLEY_JOURNEE1992.lines().filter(|l| !l.starts_with('#') && !l.starts_with("fn,")) {
            let f: Vec<&str> = line.split(',').map(str::trim).collect();
            let num = |i: usize| f[i].parse::<f64>().unwrap();
            let (froude, lam, h_ref, p_ref, unc) = (num(0), num(1), num(2), num(3), num(4));
            let (h, p) = heave_pitch(ship, table, froude, lam);
            println!("Fn {froude} lambda/L {lam}: heave {h:.3} vs {h_ref}, pitch {p:.3} vs {p_ref} ({})", f[5]);
            if f.get(6).is_none_or(|s| s.is_empty()) {
                assert!((h - h_ref).abs() <= 0.1 + unc && (p - p_ref).abs() <= 0.1 + unc, "{line}");
                asserted += 1;
            }
        }
        assert!(asserted > 0, "no reference points to assert");
    }

    /// The RAO table's precompute time on the default 40 x 6 x 13 grid, the Wigley hull beside
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
