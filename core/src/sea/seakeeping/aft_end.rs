//! STF's aft-end terms and the roll damping they add at speed (docs/model.md, "Roll, sway and yaw at
//! speed"). Salvesen-Tuck-Faltinsen (1970) keep, at forward speed, terms of the aftmost strip with
//! beam (superscript A) in every coefficient and exciting force: U a22^A, U a24^A and U a44^A in
//! B22, B24 and B44 (Appendix A eqs. 13, 14, 18) and the terms that go with them. A hull ending in
//! a deep, thin stern, such as the Wigley hull, keeps sway and roll added mass there however small
//! its beam, so these terms act as lift at the stern and damp roll more as speed rises. Codes that
//! drop end terms when there is no transom show no such effect: `seakeeping.aft_end_terms` off
//! (`Ship::aft_end_terms`).
//!
//! [`aft_end_roll_peaks`] measures it on the embedded Wigley hull (`Ship::wigley`: L 100 m, B 10 m,
//! T 6.25 m, KG 4.5 m, GM_T 0.78 m, kxx 0.35 B, no bilge keels) with the viscous roll damping off,
//! so only the strips' potential damping is left: the beam-sea roll peak at Fn 0 and Fn 0.2, with
//! and without the aft-end terms.

use super::motions::response;
use super::strip::{default_omega_grid, RadiationTable, Ship};
use crate::numerics::complex::cabs;
use std::f64::consts::PI;

/// Froude numbers of the comparison: at rest and Fn 0.2.
pub const FROUDE: [f64; 2] = [0.0, 0.2];

/// The beam-sea roll peak at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollPeak {
    /// Froude number U / sqrt(g L).
    pub froude: f64,
    /// Largest roll amplitude per wave slope, |eta4| / (k zeta_a) [-].
    pub roll_per_slope: f64,
    /// Wave frequency of the peak [rad/s] (in beam seas also the encounter frequency).
    pub omega_rad_s: f64,
}

/// The roll peaks at Fn 0 and 0.2 ([`FROUDE`]) with STF's aft-end terms (`with_terms`) and
/// without them (`without_terms`), viscous roll damping off.
#[derive(Debug, Clone, PartialEq)]
pub struct AftEndRoll {
    /// The hull and its loading, for the report.
    pub hull: String,
    /// Transverse metacentric height \[m\].
    pub gm_t_m: f64,
    pub with_terms: [RollPeak; 2],
    pub without_terms: [RollPeak; 2],
}

impl AftEndRoll {
    /// The peak's change from Fn 0 to Fn 0.2 [%] (negative: it falls), with the aft-end terms.
    pub fn change_with_terms_pct(&self) -> f64 {
        change_pct(&self.with_terms)
    }

    /// The same without them.
    pub fn change_without_terms_pct(&self) -> f64 {
        change_pct(&self.without_terms)
    }
}

fn change_pct(p: &[RollPeak; 2]) -> f64 {
    100.0 * (p[1].roll_per_slope / p[0].roll_per_slope - 1.0)
}

/// [`roll_peaks`] of the embedded Wigley hull at its own loading (`Ship::wigley`).
pub fn aft_end_roll_peaks() -> Result<AftEndRoll, String> {
    let ship = Ship::wigley();
    let hull = format!(
        "Wigley hull (L {} m, B {} m, T {} m), KG {} m, kxx {} m, no bilge keels",
        ship.lpp, ship.beam, ship.draft, ship.mass_props.kg_m, ship.mass_props.kxx_m
    );
    roll_peaks(&ship, &hull)
}

/// The beam-sea roll peaks of `ship` (described by `hull`) at Fn 0 and 0.2 with and without STF's
/// aft-end terms, its viscous roll damping off.
pub fn roll_peaks(ship: &Ship, hull: &str) -> Result<AftEndRoll, String> {
    let mut ship = ship.clone();
    ship.viscous_roll_damping = false;
    let table = ship.radiation_table(&default_omega_grid());
    let mut peaks = |terms: bool| -> Result<[RollPeak; 2], String> {
        ship.aft_end_terms = terms;
        let mut out = [RollPeak { froude: 0.0, roll_per_slope: 0.0, omega_rad_s: 0.0 }; 2];
        for (p, froude) in out.iter_mut().zip(FROUDE) {
            let u = froude * libm::sqrt(ship.g * ship.lpp);
            let (roll_per_slope, omega_rad_s) = beam_sea_roll_peak(&ship, &table, u);
            if !(roll_per_slope.is_finite() && roll_per_slope > 0.0) {
                return Err(format!("no roll peak at Fn {froude}: {roll_per_slope}"));
            }
            *p = RollPeak { froude, roll_per_slope, omega_rad_s };
        }
        Ok(out)
    };
    let with_terms = peaks(true)?;
    let without_terms = peaks(false)?;
    Ok(AftEndRoll { hull: hull.to_string(), gm_t_m: ship.gm_t, with_terms, without_terms })
}

/// The largest roll per wave slope in beam seas (waves from starboard) at speed `u` [m/s] and its
/// wave frequency [rad/s]: a scan of 0.2-2 rad/s in steps of 0.005, refined by golden section
/// to 1e-9 rad/s. The roll damping is linearised at a wave amplitude of 1 m (nothing to linearise
/// with the viscous damping off).
pub fn beam_sea_roll_peak(ship: &Ship, table: &RadiationTable, u: f64) -> (f64, f64) {
    let per_slope = |w: f64| {
        let r = response(ship, table, w, u, 0.5 * PI, 1.0);
        cabs(r.roll) / r.k
    };
    let step = 0.005;
    let (mut best, mut at) = (f64::NEG_INFINITY, 0.2);
    for i in 0..=360 {
        let w = 0.2 + step * i as f64;
        let a = per_slope(w);
        if a > best {
            (best, at) = (a, w);
        }
    }
    let (mut lo, mut hi) = (at - step, at + step);
    let r = 0.5 * (libm::sqrt(5.0) - 1.0);
    let (mut c, mut d) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut fc, mut fd) = (per_slope(c), per_slope(d));
    while hi - lo > 1e-9 {
        if fc > fd {
            (hi, d, fd) = (d, c, fc);
            c = hi - r * (hi - lo);
            fc = per_slope(c);
        } else {
            (lo, c, fc) = (c, d, fd);
            d = lo + r * (hi - lo);
            fd = per_slope(d);
        }
    }
    let w = 0.5 * (lo + hi);
    let a = per_slope(w);
    if a >= best {
        (a, w)
    } else {
        (best, at)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn print(r: &AftEndRoll) {
        println!("{} (GM_T {:.3} m), viscous roll damping off:", r.hull, r.gm_t_m);
        for (name, p) in [("with the aft-end terms", &r.with_terms), ("without them", &r.without_terms)] {
            println!(
                "  {name}: Fn {} {:.3} at {:.4} rad/s, Fn {} {:.3} at {:.4} rad/s: {:+.2} %",
                p[0].froude,
                p[0].roll_per_slope,
                p[0].omega_rad_s,
                p[1].froude,
                p[1].roll_per_slope,
                p[1].omega_rad_s,
                change_pct(p)
            );
        }
    }

    /// The embedded Wigley hull (KG 4.5 m, GM_T 0.78 m), viscous roll damping off, beam seas.
    /// Measured: with STF's aft-end terms the roll peak per wave slope is 36.08 at 0.707 rad/s at
    /// Fn 0 and 17.05 at 0.706 rad/s at Fn 0.2, a fall of 52.7 %; without them 36.08 and 36.11
    /// (+0.10 %). Asserted: a fall of 52.7 % +- 1 point with the terms, under 0.5 % of change
    /// without them, and the two alike at rest (the terms carry U: bit for bit the same).
    #[test]
    fn aft_end_terms_damp_wigley_roll_at_speed() {
        let r = aft_end_roll_peaks().unwrap();
        print(&r);
        let (on, off) = (r.change_with_terms_pct(), r.change_without_terms_pct());
        assert!((on + 52.7).abs() < 1.0, "with the aft-end terms: {on} %");
        assert!(off.abs() < 0.5, "without the aft-end terms: {off} %");
        assert_eq!(r.with_terms[0], r.without_terms[0]);
        assert!((r.with_terms[0].roll_per_slope - 36.08).abs() < 0.05, "{:?}", r.with_terms[0]);
        assert!((r.with_terms[1].roll_per_slope - 17.05).abs() < 0.05, "{:?}", r.with_terms[1]);
        // The peak stays at the roll's natural frequency: the terms damp, they do not stiffen.
        assert!((r.with_terms[1].omega_rad_s / r.with_terms[0].omega_rad_s - 1.0).abs() < 0.01);
    }

    /// The more potential damping, the less the aft-end terms move the peak: the Wigley hull at
    /// KG 3.5 m (GM_T 1.78 m, roll natural frequency 1.04 rad/s, where the strips radiate more)
    /// measured 8.83 at Fn 0 and 7.91 at Fn 0.2 with the terms (-10.4 %), -0.12 % without them.
    /// Asserted: -10.4 % +- 1 point, and under 0.5 % without.
    #[test]
    fn aft_end_terms_matter_less_for_a_stiffer_wigley() {
        let mut ship = Ship::wigley();
        let mass = crate::sea::seakeeping::strip::MassProperties { kg_m: 3.5, ..ship.mass_props };
        ship = Ship::new(&crate::geometry::HullOffsets::wigley(), ship.draft, mass, None, ship.rho, ship.g).unwrap();
        let r = roll_peaks(&ship, "Wigley hull at KG 3.5 m").unwrap();
        print(&r);
        let (on, off) = (r.change_with_terms_pct(), r.change_without_terms_pct());
        assert!((on + 10.4).abs() < 1.0, "with the aft-end terms: {on} %");
        assert!(off.abs() < 0.5, "without the aft-end terms: {off} %");
    }

    /// `seakeeping.aft_end_terms` reaches the scenario's RAO table and its cache key: on a small
    /// grid of the Wigley hull the tables with and without the terms are two tables, alike at rest
    /// bit for bit and apart in beam-sea roll at speed (viscous damping on, as in a run: at
    /// 0.7 rad/s and 12 kn measured 0.1221 rad/m with the terms and 0.1314 without; asserted 5 %
    /// apart).
    #[test]
    fn scenario_switch_reaches_the_rao_table() {
        let mut sc = crate::Scenario::default();
        sc.ship.hull = crate::ship::hull::HullSpec { name: "wigley".into(), ..Default::default() };
        sc.seakeeping.grid = crate::sea::seakeeping::tables::SeakeepingGrid {
            omega_min: 0.6,
            omega_max: 0.8,
            n_omega: 3,
            speed_max_kn: 12.0,
            n_speed: 2,
            n_heading: 3,
            ..Default::default()
        };
        let on = sc.rao_table().unwrap();
        sc.seakeeping.aft_end_terms = false;
        let off = sc.rao_table().unwrap();
        assert!(!std::sync::Arc::ptr_eq(&on, &off));
        let u = 12.0 * crate::numerics::units::KNOT_M_S;
        assert_eq!(on.interpolate(0.7, 0.0, 0.5 * PI), off.interpolate(0.7, 0.0, 0.5 * PI));
        let (a, b) = (cabs(on.interpolate(0.7, u, 0.5 * PI).roll), cabs(off.interpolate(0.7, u, 0.5 * PI).roll));
        println!("beam-sea roll at 0.7 rad/s, 12 kn: with the aft-end terms {a:.4}, without {b:.4} rad/m");
        assert!(b > 1.05 * a, "{a} vs {b}");
    }
}
