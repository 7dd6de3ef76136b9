//! Lifting-surface corrections of a lifting line's section lift: over a blade of finite chord the
//! helical inflow is curved, which takes away part of the camber's lift and moves the angle at which
//! the section meets the flow shock-free.
//!
//! The lifting line uses Morgan, Silovic & Denny's (1968) factors ("Propeller lifting-surface
//! corrections", Trans. SNAME 76), from lifting-surface calculations over Z = 4 to 6,
//! A_E/A_0 = 0.35 to 1.15: a blade needs k_c times the camber of a two-dimensional section for the
//! same lift, and its pitch angle exceeds the inflow angle by k_a times that section's ideal angle
//! plus k_t times the blade thickness fraction (the thickness's own effect on the flow). So in
//! analysis a blade of camber f0/c lifts like a section of camber f0/c / k_c about the angle
//! k_a alpha_i(f0/c / k_c) + k_t BTF (the inversion OpenProp's analysis applies, Epps & Kimball
//! 2013). Their tables are `core/data/morgan1968_lifting_surface.csv`, with its source.
//!
//! Eckhardt & Morgan's (1955) older camber factor K_c = K1(lambda_i, A_E/A_0) K2(r/R, A_E/A_0)
//! (Trans. SNAME 63, figs. 12-13; as tabulated in OpenProp v3, Epps, MIT, 2011:
//! SourceCode/EckhardtMorgan1955.m) is kept beside it ([`camber_factor`]): it corrects the camber
//! only, and its factor is larger (1.9 against Morgan's 1.5 at 0.7 R of DTMB 4119).

use std::sync::OnceLock;

/// Factors applied to one section's lift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corrections {
    /// k_c: divides the mean line's camber, so the ideal lift and the 2D ideal angle are those of
    /// f0/c / `camber` \[-\].
    pub camber: f64,
    /// k_a: multiplies that 2D ideal angle \[-\].
    pub ideal_angle: f64,
    /// k_t BTF: the angle the blade's thickness adds to the ideal angle \[rad\].
    pub thickness_angle_rad: f64,
}

impl Corrections {
    /// No correction: the section lifts as in two dimensions.
    pub const NONE: Corrections = Corrections { camber: 1.0, ideal_angle: 1.0, thickness_angle_rad: 0.0 };
}

/// The Morgan 1968 tables' grid: blades, A_E/A_0, pi lambda_i = pi (r/R) tan(beta_i), r/R.
const M_BLADES: [f64; 3] = [4.0, 5.0, 6.0];
const M_EAR: [f64; 5] = [0.35, 0.55, 0.75, 0.95, 1.15];
const M_PLI: [f64; 5] = [0.4, 0.8, 1.2, 1.6, 2.0];
const M_RADIUS: [f64; 7] = [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9];
/// Entries per factor (Z, A_E/A_0, pi lambda_i, r/R).
const M_SIZE: usize = 3 * 5 * 5 * 7;

/// k_c, k_a, k_t on the grid, each indexed [[z][ear][pli][r]] flattened.
struct Morgan {
    kc: Vec<f64>,
    ka: Vec<f64>,
    kt: Vec<f64>,
}

const MORGAN_CSV: &str = include_str!("../../../data/morgan1968_lifting_surface.csv");

/// The tables, parsed once from the data file (a fixed file of the repository: a malformed row is a
/// build defect, which the unit test below catches).
fn morgan() -> &'static Morgan {
    static TABLES: OnceLock<Morgan> = OnceLock::new();
    TABLES.get_or_init(|| {
        let mut m = Morgan { kc: vec![f64::NAN; M_SIZE], ka: vec![f64::NAN; M_SIZE], kt: vec![f64::NAN; M_SIZE] };
        let at = |xs: &[f64], v: f64| xs.iter().position(|&x| (x - v).abs() < 1e-9);
        for line in MORGAN_CSV.lines().filter(|l| !l.starts_with('#') && !l.starts_with("factor")) {
            let cells: Vec<&str> = line.split(',').collect();
            let num: Vec<f64> = cells[1..].iter().filter_map(|c| c.trim().parse().ok()).collect();
            let (Some(z), Some(e), Some(p)) = (at(&M_BLADES, num[0]), at(&M_EAR, num[1]), at(&M_PLI, num[2])) else {
                continue;
            };
            let table = match cells[0] {
                "kc" => &mut m.kc,
                "ka" => &mut m.ka,
                "kt" => &mut m.kt,
                _ => continue,
            };
            let base = ((z * 5 + e) * 5 + p) * 7;
            table[base..base + 7].copy_from_slice(&num[3..10]);
        }
        m
    })
}

/// Position of `x` in the increasing grid `xs`: the lower index and the fraction to the next,
/// held at the grid's ends (never extrapolated).
fn bracket(xs: &[f64], x: f64) -> (usize, f64) {
    let x = x.clamp(xs[0], xs[xs.len() - 1]);
    let k = xs.iter().position(|&v| v >= x).unwrap_or(xs.len() - 1).max(1);
    (k - 1, (x - xs[k - 1]) / (xs[k] - xs[k - 1]))
}

/// Morgan, Silovic & Denny's (1968) k_c, k_a and k_t BTF at radius `r_r` with inflow
/// tan(beta_i) `tan_beta_i`, for `blades` blades of expanded area ratio `ear` and blade thickness
/// fraction `btf` (t0/D extrapolated to the shaft axis). Multilinear in the four table axes, held
/// at the tables' edges: Z below 4 (DTMB 4119's 3) takes the Z = 4 table, r/R inside 0.3 the 0.3
/// row and outside 0.9 the 0.9 row.
pub fn morgan_1968(blades: u32, ear: f64, btf: f64, r_r: f64, tan_beta_i: f64) -> Corrections {
    let t = morgan();
    let axes = [
        bracket(&M_BLADES, blades as f64),
        bracket(&M_EAR, ear),
        bracket(&M_PLI, std::f64::consts::PI * r_r * tan_beta_i),
        bracket(&M_RADIUS, r_r),
    ];
    let (mut kc, mut ka, mut kt) = (0.0, 0.0, 0.0);
    for corner in 0..16usize {
        let mut w = 1.0;
        let mut idx = [0usize; 4];
        for (a, &(i, f)) in axes.iter().enumerate() {
            let up = (corner >> a) & 1 == 1;
            idx[a] = i + usize::from(up);
            w *= if up { f } else { 1.0 - f };
        }
        if w == 0.0 {
            continue;
        }
        let k = ((idx[0] * 5 + idx[1]) * 5 + idx[2]) * 7 + idx[3];
        kc += w * t.kc[k];
        ka += w * t.ka[k];
        kt += w * t.kt[k];
    }
    Corrections { camber: kc, ideal_angle: ka, thickness_angle_rad: kt * btf }
}

/// Blade thickness fraction: the maximum thickness t0/D extrapolated to the shaft axis, from a
/// least-squares line through the rows that carry a chord (Morgan et al. 1968's thickness measure).
pub fn blade_thickness_fraction(g: &super::BladeGeometry) -> f64 {
    let pts: Vec<(f64, f64)> = g.rows.iter().filter(|r| r.c_d > 0.0).map(|r| (r.r_r, r.t0_c * r.c_d)).collect();
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) =
        pts.iter().fold((0.0, 0.0), |(a, b), p| (a + (p.0 - mx) * (p.1 - my), b + (p.0 - mx) * (p.0 - mx)));
    (my - sxy / sxx * mx).max(0.0)
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
    let (i, s) = bracket(rows, row);
    let (j, t) = bracket(&EAR, ear);
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

    #[test]
    fn morgan_1968_at_its_grid_and_between() {
        // Every entry of the three tables was read (no NaN left), and the factors are of their size.
        let t = morgan();
        assert!(t.kc.iter().chain(&t.ka).chain(&t.kt).all(|v| v.is_finite()));
        // At grid points the table's entries: Z 4, A_E/A_0 0.55, pi lambda_i 1.2, r/R 0.7.
        let tan = |pli: f64, r: f64| pli / (std::f64::consts::PI * r);
        let k = morgan_1968(4, 0.55, 1.0, 0.7, tan(1.2, 0.7));
        assert!((k.camber - 1.355).abs() < 1e-12 && (k.ideal_angle - 1.477).abs() < 1e-12, "{k:?}");
        assert!((k.thickness_angle_rad - 0.097).abs() < 1e-12);
        // Z 5, A_E/A_0 0.75, pi lambda_i 0.8, r/R 0.3; the thickness angle scales with BTF.
        let k = morgan_1968(5, 0.75, 0.05, 0.3, tan(0.8, 0.3));
        assert!((k.camber - 1.490).abs() < 1e-12 && (k.thickness_angle_rad - 0.05 * 0.783).abs() < 1e-12);
        // Halfway in r/R and in A_E/A_0: the mean of four entries.
        let k = morgan_1968(4, 0.65, 1.0, 0.75, tan(1.2, 0.75));
        assert!((k.camber - (1.355 + 1.517 + 1.573 + 1.803) / 4.0).abs() < 1e-12, "{}", k.camber);
        // Held at the edges: 3 blades take Z = 4, the hub takes r/R 0.3.
        let (a, b) = (morgan_1968(3, 0.6, 0.08, 0.2, 1.5), morgan_1968(4, 0.6, 0.08, 0.3, 1.0));
        assert!((a.camber - b.camber).abs() < 1e-12 && (a.thickness_angle_rad - b.thickness_angle_rad).abs() < 1e-12);
    }

    #[test]
    fn blade_thickness_fraction_of_a_linear_blade() {
        // t0/D = 0.05 - 0.04 r/R exactly: the axis value 0.05 comes back.
        let text = "r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D\n0.2,0.2,1,0.02,0.21,0,0\n0.5,0.3,1,0.02,0.1,0,0\n0.8,0.2,1,0.02,0.09,0,0\n1.0,0.0,1,0.02,0.05,0,0\n";
        let g = super::super::BladeGeometry::from_csv(text, 4, 0.2).unwrap();
        assert!((blade_thickness_fraction(&g) - 0.05).abs() < 1e-12, "{}", blade_thickness_fraction(&g));
    }
}
