//! Fuel power of a gas turbine from its shaft power (thesis ch. 5.2.4, Fig. 5-12): thermal
//! efficiency at rated power times a generic part-load curve (core/data/gas_turbine_part_load.csv,
//! from the TransiEnt library; 37 % at rated power as the thesis' ch. 5.1).

const CURVE: &str = include_str!("../../data/gas_turbine_part_load.csv");

/// The part-load curve: (power fraction, efficiency / rated efficiency), increasing fraction.
pub fn part_load_curve() -> Vec<(f64, f64)> {
    crate::numerics::interp::csv_points(CURVE)
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
            return (crate::numerics::interp::point_slope(a, ra, b, rb, f), false);
        }
    }
    (curve[curve.len() - 1].1, false)
}

/// Fuel power \[W\] for shaft power `p` \[W\] of a turbine rated `p_rated` \[W\] with efficiency
/// `eta_rated` at rated power; and whether the curve was extrapolated below 30 % load.
pub fn fuel_power(curve: &[(f64, f64)], p: f64, p_rated: f64, eta_rated: f64) -> (f64, bool) {
    if p <= 0.0 {
        return (0.0, false);
    }
    let (r, ex) = efficiency_ratio(curve, p / p_rated);
    (p / (eta_rated * r), ex)
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
