//! The fuel study of ch. 5.2.4 (Fig. 5-12): steady states in regular seas with the mean added
//! resistance, and the fuel power of one prime mover (`aes-sim fuel`, the page's fuel curves).

use crate::fuel::{fuel_power, part_load_curve};

/// One row of the fuel study (Fig. 5-12).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FuelPoint {
    pub heading: &'static str,
    pub amplitude_ft: f64,
    pub omega_rad_s: f64,
    /// Mean added resistance [N], shaft power and fuel power of one prime mover [W].
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
pub fn run(sc: &crate::Scenario, omegas: &[f64]) -> Result<Vec<FuelPoint>, String> {
    let curve = part_load_curve();
    let speed_kn = sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(25.0);
    let u = crate::units::kn_to_m_s(speed_kn);
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
