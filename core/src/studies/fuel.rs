//! The fuel study of ch. 5.2.4 (Fig. 5-12): steady states in regular seas with the mean added
//! resistance, and the fuel power of one prime mover (`aes-sim fuel`, the page's fuel curves).

use crate::plant::fuel::{fuel_power, part_load_curve};
use std::ops::RangeInclusive;

/// Wave frequencies the study takes \[rad/s\] (the RAO table's span and more), and how many at once
/// (each is ten steady states).
pub const OMEGA_RANGE_RAD_S: RangeInclusive<f64> = 0.1..=5.0;
pub const MAX_OMEGAS: usize = 200;

/// Fig. 5-12's wave frequencies: 0.3 to 1.5 rad/s in steps of 0.1.
pub fn fig_5_12_omegas() -> Vec<f64> {
    (3..=15).map(|i| i as f64 / 10.0).collect()
}

/// Checks the wave frequencies of a study: 1 to [`MAX_OMEGAS`], each in [`OMEGA_RANGE_RAD_S`].
pub fn check_omegas(omegas: &[f64]) -> Result<(), String> {
    let (lo, hi) = (*OMEGA_RANGE_RAD_S.start(), *OMEGA_RANGE_RAD_S.end());
    if omegas.is_empty() || omegas.len() > MAX_OMEGAS {
        return Err(format!("fuel study: {} wave frequencies: give 1 to {MAX_OMEGAS}", omegas.len()));
    }
    match omegas.iter().find(|w| !OMEGA_RANGE_RAD_S.contains(w)) {
        Some(w) => {
            Err(format!("fuel study: wave frequency {} rad/s: must be from {lo} to {hi} rad/s", crate::checks::num(*w)))
        }
        None => Ok(()),
    }
}

/// One row of the fuel study (Fig. 5-12).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FuelPoint {
    pub heading: &'static str,
    pub amplitude_ft: f64,
    pub omega_rad_s: f64,
    /// Mean added resistance \[N\], shaft power and fuel power of one prime mover \[W\].
    pub added_resistance_n: f64,
    pub turbine_power_w: f64,
    pub fuel_power_w: f64,
    pub extrapolated: bool,
}

/// The fuel study of ch. 5.2.4 (Fig. 5-12): for regular seas of 1 to 5 ft amplitude over wave
/// frequency `omegas`, in head seas (180 deg) and bow seas (135 deg), the steady state at the
/// scenario's first ordered speed with the mean added resistance alpha^2 R_aw(omega, U, beta) of the
/// RAO table, and the shaft and fuel power of one prime mover. Quasi-static: the wave-frequency
/// load swings average out over a turbine's response; the mean added resistance is what costs fuel.
/// The frequencies are checked first ([`check_omegas`]); none given: Fig. 5-12's.
pub fn run(sc: &crate::Scenario, omegas: &[f64]) -> Result<Vec<FuelPoint>, String> {
    // None given: Fig. 5-12's (what the page and `aes-sim fuel` without --omega ask for).
    let fig = fig_5_12_omegas();
    let omegas = if omegas.is_empty() { fig.as_slice() } else { omegas };
    check_omegas(omegas)?;
    let curve = part_load_curve();
    let speed_kn = sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(25.0);
    let u = crate::numerics::units::kn_to_m_s(speed_kn);
    let table = sc.rao_table()?;
    let mut calm = sc.clone();
    calm.sea.kind = crate::scenario::SeaKind::Calm;
    calm.initial.speed_kn = speed_kn;
    let eta = sc.seakeeping.turbine_rated_efficiency;
    let rated = sc.plant.turbine.rated_power_w;
    let mut out = Vec::new();
    for (name, beta_deg) in [("head", 180.0f64), ("bow", 135.0)] {
        for amp_ft in [1.0, 2.0, 3.0, 4.0, 5.0] {
            let a = amp_ft * 0.3048;
            for &w in omegas {
                let r = table.interpolate(w, u, beta_deg.to_radians());
                let added = -r.fx * a * a;
                let mut sim = crate::Simulation::with_extra_resistance(&calm, added).map_err(|e| e.to_string())?;
                let p = sim.turbine_power();
                let p1 = p[0];
                let (fuel, ex) = fuel_power(&curve, p1, rated, eta);
                out.push(FuelPoint {
                    heading: name,
                    amplitude_ft: amp_ft,
                    omega_rad_s: w,
                    added_resistance_n: added,
                    turbine_power_w: p1,
                    fuel_power_w: fuel,
                    extrapolated: ex,
                });
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The frequencies both the command line and the page may ask for, and Fig. 5-12's among them.
    #[test]
    fn frequencies_are_checked() {
        assert!(check_omegas(&fig_5_12_omegas()).is_ok());
        assert_eq!(fig_5_12_omegas().len(), 13);
        assert!(check_omegas(&[0.1, 5.0]).is_ok());
        assert!(check_omegas(&[]).unwrap_err().contains("0 wave frequencies"));
        assert!(check_omegas(&vec![1.0; MAX_OMEGAS + 1]).is_err());
        for bad in [0.09, 5.01, f64::NAN, f64::INFINITY] {
            let e = check_omegas(&[1.0, bad]).unwrap_err();
            assert!(e.contains("must be from 0.1 to 5 rad/s"), "{bad}: {e}");
        }
    }
}
