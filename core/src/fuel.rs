//! Fuel power of a gas turbine from its shaft power (thesis ch. 5.2.4, Fig. 5-12): thermal
//! efficiency at rated power times a generic part-load curve (core/data/gas_turbine_part_load.csv,
//! from the TransiEnt library; 37 % at rated power as the thesis' ch. 5.1).

const CURVE: &str = include_str!("../data/gas_turbine_part_load.csv");

/// The part-load curve: (power fraction, efficiency / rated efficiency), increasing fraction.
pub fn part_load_curve() -> Vec<(f64, f64)> {
    CURVE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("power"))
        .filter_map(|l| {
            let (a, b) = l.split_once(',')?;
            Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
        })
        .collect()
}

/// Efficiency ratio at power fraction `f`: linear interpolation; below the curve's first point
/// (30 % load, where the data ends) the first segment is extended down to 5 % load and held
/// there, and `extrapolated` says so; above rated power the ratio stays 1.
pub fn efficiency_ratio(curve: &[(f64, f64)], f: f64) -> (f64, bool) {
    let (f0, r0) = curve[0];
    if f < f0 {
        let (f1, r1) = curve[1];
        let fe = f.max(0.05);
        return (r0 + (r1 - r0) / (f1 - f0) * (fe - f0), true);
    }
    for w in curve.windows(2) {
        let ((a, ra), (b, rb)) = (w[0], w[1]);
        if f <= b {
            return (ra + (rb - ra) * (f - a) / (b - a), false);
        }
    }
    (curve[curve.len() - 1].1, false)
}

/// Fuel power [W] for shaft power `p` [W] of a turbine rated `p_rated` [W] with efficiency
/// `eta_rated` at rated power; and whether the curve was extrapolated below 30 % load.
pub fn fuel_power(curve: &[(f64, f64)], p: f64, p_rated: f64, eta_rated: f64) -> (f64, bool) {
    if p <= 0.0 {
        return (0.0, false);
    }
    let (r, ex) = efficiency_ratio(curve, p / p_rated);
    (p / (eta_rated * r), ex)
}

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
pub fn fuel_study(sc: &crate::Scenario, omegas: &[f64]) -> Result<Vec<FuelPoint>, String> {
    let curve = part_load_curve();
    let speed_kn = sc.commands.first().and_then(|c| c.speed_kn).unwrap_or(25.0);
    let u = crate::units::kn_to_m_s(speed_kn);
    let table = crate::seakeeping::cache::rao_table(&sc.seakeeping.grid)?;
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

    /// The thesis' anchors (ch. 5.1): 37 % near rated power and about 28 % at half power (the
    /// generic curve gives 0.776 x 37 % = 28.7 %, within 1 point).
    #[test]
    fn anchors() {
        let c = part_load_curve();
        assert_eq!(c.len(), 8);
        let (fuel, ex) = fuel_power(&c, 21.5e6, 21.5e6, 0.37);
        assert!(!ex && (21.5e6 / fuel - 0.37).abs() < 1e-12);
        let (fuel, _) = fuel_power(&c, 10.75e6, 21.5e6, 0.37);
        assert!((10.75e6 / fuel - 0.28).abs() < 0.01);
        assert!(efficiency_ratio(&c, 0.1).1);
    }
}
