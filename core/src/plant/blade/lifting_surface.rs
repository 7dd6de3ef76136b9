//! Lifting-surface corrections of a lifting line's section lift: over a blade of finite chord the
//! helical inflow is curved, which takes away part of the camber's lift. The correction is Eckhardt
//! & Morgan's (1955) camber factor K_c = K1(lambda_i, A_E/A_0) K2(r/R, A_E/A_0) (Eckhardt & Morgan,
//! "A propeller design method", Trans. SNAME 63, 1955, figs. 12-13): a lifting surface needs K_c
//! times the camber a two-dimensional section needs for the same lift, so a blade of camber f0/c
//! lifts like a section of camber f0/c / K_c. Morgan, Silovic & Denny's (1968) factors, which add an
//! ideal-angle and a thickness correction, were not found in a public copy; their camber factor
//! is of the same size (1.3 to 2 at A_E/A_0 = 0.6).
//!
//! The tables below are the paper's curves read at its grid points, as tabulated in OpenProp v3
//! (Epps, MIT, 2011: SourceCode/EckhardtMorgan1955.m), the public copy checked here.

/// Factors applied to one section's lift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corrections {
    /// Divides the mean line's camber: ideal lift and ideal angle are those of f0/c / `camber` \[-\].
    pub camber: f64,
}

impl Corrections {
    /// No correction: the section lifts as in two dimensions.
    pub const NONE: Corrections = Corrections { camber: 1.0 };
}

/// Expanded area ratios of both tables' columns \[-\].
const EAR: [f64; 9] = [0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2];
/// Hydrodynamic pitch lambda_i = (r/R) tan(beta_i) of K1's rows \[-\].
const LAMBDA_I: [f64; 5] = [0.2, 0.3, 0.4, 0.5, 0.6];
/// r/R of K2's rows \[-\].
const RADIUS: [f64; 9] = [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95];

/// K1(lambda_i, A_E/A_0): the loading factor (1 at lambda_i = 0.4).
#[rustfmt::skip]
const K1: [[f64; 9]; 5] = [
    [0.8613, 0.8601, 0.8532, 0.8413, 0.8250, 0.8048, 0.7815, 0.7555, 0.7275],
    [0.9394, 0.9378, 0.9355, 0.9320, 0.9270, 0.9198, 0.9099, 0.8970, 0.8805],
    [1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000, 1.0000],
    [1.0496, 1.0528, 1.0555, 1.0584, 1.0623, 1.0677, 1.0756, 1.0865, 1.1012],
    [1.0890, 1.0911, 1.0950, 1.1014, 1.1106, 1.1231, 1.1393, 1.1597, 1.1847],
];

/// K2(r/R, A_E/A_0): the camber factor at lambda_i = 0.4.
#[rustfmt::skip]
const K2: [[f64; 9]; 9] = [
    [1.0024, 0.9991, 1.0019, 0.9991, 0.9981, 1.0164, 1.0734, 1.1834, 1.3490],
    [1.1223, 1.1208, 1.1316, 1.1510, 1.1811, 1.2289, 1.3074, 1.4346, 1.6342],
    [1.3046, 1.3094, 1.3330, 1.3705, 1.4217, 1.4911, 1.5879, 1.7261, 1.9240],
    [1.4905, 1.5127, 1.5464, 1.5914, 1.6513, 1.7331, 1.8477, 2.0093, 2.2361],
    [1.6753, 1.7035, 1.7519, 1.8146, 1.8924, 1.9930, 2.1308, 2.3266, 2.6085],
    [1.7843, 1.8412, 1.9044, 1.9861, 2.0975, 2.2491, 2.4505, 2.7107, 3.0376],
    [1.7947, 1.8736, 1.9764, 2.1051, 2.2669, 2.4737, 2.7425, 3.0954, 3.5592],
    [1.8086, 1.8681, 1.9989, 2.1637, 2.3536, 2.5880, 2.9146, 3.4094, 4.1768],
    [1.7912, 1.8781, 2.0037, 2.1848, 2.4084, 2.6694, 3.0065, 3.5400, 4.5083],
];

/// Bilinear interpolation in a table over (`rows`, [`EAR`]), held at its edges (not extrapolated).
fn lookup<const R: usize>(table: &[[f64; 9]; R], rows: &[f64; R], row: f64, ear: f64) -> f64 {
    let at = |xs: &[f64], x: f64| -> (usize, f64) {
        let x = x.clamp(xs[0], xs[xs.len() - 1]);
        let k = xs.iter().position(|&v| v >= x).unwrap_or(xs.len() - 1).max(1);
        (k - 1, (x - xs[k - 1]) / (xs[k] - xs[k - 1]))
    };
    let (i, s) = at(rows, row);
    let (j, t) = at(&EAR, ear);
    let v = |i: usize, j: usize| table[i][j];
    (1.0 - s) * ((1.0 - t) * v(i, j) + t * v(i, j + 1)) + s * ((1.0 - t) * v(i + 1, j) + t * v(i + 1, j + 1))
}

/// Eckhardt & Morgan's camber factor K_c = K1 K2 at radius `r_r`, hydrodynamic pitch angle
/// tan(beta_i) `tan_beta_i`, expanded area ratio `ear` (each held inside the paper's range).
pub fn camber_factor(ear: f64, r_r: f64, tan_beta_i: f64) -> f64 {
    lookup(&K1, &LAMBDA_I, r_r * tan_beta_i, ear) * lookup(&K2, &RADIUS, r_r, ear)
}

/// The expanded blade area ratio A_E / A_0 = Z integral(c dr) / (pi R^2) of a geometry \[-\].
pub fn expanded_area_ratio(g: &super::BladeGeometry) -> f64 {
    let area: f64 = g.rows.windows(2).map(|w| 0.5 * (w[0].c_d + w[1].c_d) * (w[1].r_r - w[0].r_r)).sum();
    2.0 * g.blades as f64 * area / std::f64::consts::PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_at_its_grid_and_between() {
        // At lambda_i = 0.4, K1 = 1 and K_c is K2's entry.
        assert!((camber_factor(0.6, 0.7, 0.4 / 0.7) - 1.9044).abs() < 1e-12);
        // Halfway between two columns and two rows: the mean of four entries.
        let mid = camber_factor(0.65, 0.55, 0.4 / 0.55);
        assert!((mid - (1.5464 + 1.5914 + 1.7519 + 1.8146) / 4.0).abs() < 1e-12);
        // Outside the table: held at its edge, never extrapolated.
        assert_eq!(camber_factor(2.0, 0.99, 0.4 / 0.99), camber_factor(1.2, 0.95, 0.4 / 0.95));
    }
}
