//! The shape of a blade section: the NACA a = 0.8 mean line (Abbott & von Doenhoff 1959, ch. 6.4)
//! and the NACA 66 (DTRC modified) thickness form (Brockett 1966), combined into upper and lower
//! surface coordinates for a section of given f0/c and t0/c, in chords.

use crate::numerics::interp::csv_points;

/// Chordwise extent of the uniform load of the a = 0.8 mean line \[-\].
const A: f64 = 0.8;

/// The NACA 66 (DTRC modified) thickness form, T/T0 against x/c, with its source.
const THICKNESS_66: &str = include_str!("../../../data/naca66_dtrc_thickness.csv");

/// Leading-edge radius of the NACA 66 (DTRC modified) form over chord, per (t0/c)^2 (Brockett 1966).
pub const LE_RADIUS_PER_T2: f64 = 0.448;

/// The a = 0.8 mean line for a design lift coefficient C_Li = 1 at `x` = x/c in \[0, 1\]: ordinate
/// y_c/c and slope dy_c/dx (Abbott & von Doenhoff 1959, eq. 4.26 of ch. 4.4 and ch. 6.4, with
/// the general-a constants g and h). Scale both by C_Li.
pub fn a08_mean_line(x: f64) -> (f64, f64) {
    let x = x.clamp(0.0, 1.0);
    let k = 1.0 / (2.0 * std::f64::consts::PI * (A + 1.0));
    let (g, h) = a08_g_h();
    // x ln x and its kin vanish at their zeros; write them so 0 ln 0 is 0, not NaN.
    let xlnx = |u: f64| if u <= 0.0 { 0.0 } else { u * libm::log(u) };
    let (am, om) = ((A - x).abs(), 1.0 - x);
    let y = k
        * ((0.5 * am * xlnx(am) - 0.5 * om * xlnx(om) + 0.25 * om * om - 0.25 * am * am) / (1.0 - A) - xlnx(x) + g
            - h * x);
    // dy/dx: (a - x) ln|a - x| is continuous (zero) at x = a; ln x diverges at the nose, held at
    // x = 1e-12 (the slope there only tilts the thickness, which is zero at the nose).
    let alnx = if am == 0.0 { 0.0 } else { (A - x) * libm::log(am) };
    let slope = k * ((xlnx(om) - alnx) / (1.0 - A) - libm::log(x.max(1e-12)) - 1.0 - h);
    (y, slope)
}

/// The constants g and h of the a-series mean line (Abbott & von Doenhoff 1959, ch. 4.4).
fn a08_g_h() -> (f64, f64) {
    let g = -(A * A * (0.5 * libm::log(A) - 0.25) + 0.25) / (1.0 - A);
    let om = 1.0 - A;
    let h = (0.5 * om * om * libm::log(om) - 0.25 * om * om) / om + g;
    (g, h)
}

/// Ideal angle of attack of the a = 0.8 mean line per unit C_Li \[rad\]: -C_Li h / (2 pi (a + 1)),
/// 1.54 deg in Abbott & von Doenhoff's table for C_Li = 1.
pub fn a08_ideal_angle_per_cli() -> f64 {
    -a08_g_h().1 / (2.0 * std::f64::consts::PI * (A + 1.0))
}

/// Maximum camber f0/c of the a = 0.8 mean line per unit C_Li \[-\] (0.0679 in Abbott & von
/// Doenhoff's table): y_c at the zero of the slope, found by bisection.
pub fn a08_camber_per_cli() -> f64 {
    let x = crate::numerics::bisect(|x| a08_mean_line(x).1, 0.2, 0.7, 60);
    a08_mean_line(x).0
}

/// The NACA 66 (DTRC modified) thickness T/T0 at `x` = x/c in \[0, 1\].
///
/// The table is interpolated as T/T0 / sqrt(x) (smooth and monotone, unlike T/T0 at a round nose)
/// by a monotone cubic (Fritsch & Carlson 1980), with the nose value 2 sqrt(2 * 0.448) from the
/// leading-edge radius, so the section has its published round nose between the table's stations.
pub fn naca66_thickness(x: f64) -> f64 {
    let x = x.clamp(0.0, 1.0);
    let t = thickness_table();
    let g = pchip(&t.0, &t.1, x);
    g * x.sqrt()
}

/// The thickness form with its blunt base (0.0666 t0) closed by subtracting 0.0666 x^4: a sharp
/// trailing edge where the Kutta condition holds. The potential flow past a blunt base is singular
/// at its corners and the panel solution's lift then depends on the panel size (the lift slope of
/// a 4 % section fell from 1.09 to 1.02 x 2 pi as the panels were halved three times); closed,
/// it converges. The change is under 0.3 % of t0 ahead of x = 0.45, where the suction peaks are.
pub fn closed_thickness(x: f64) -> f64 {
    let base = csv_points(THICKNESS_66).last().map_or(0.0, |p| p.1);
    naca66_thickness(x) - base * x * x * x * x
}

/// The thickness table as (x, T/T0 / sqrt(x)), the nose value from the leading-edge radius.
fn thickness_table() -> &'static (Vec<f64>, Vec<f64>) {
    static TABLE: std::sync::OnceLock<(Vec<f64>, Vec<f64>)> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let pts = csv_points(THICKNESS_66);
        let xs: Vec<f64> = pts.iter().map(|p| p.0).collect();
        let gs = pts
            .iter()
            .map(|&(x, t)| if x == 0.0 { 2.0 * (2.0 * LE_RADIUS_PER_T2).sqrt() } else { t / x.sqrt() })
            .collect();
        (xs, gs)
    })
}

/// Monotone piecewise-cubic Hermite interpolation (Fritsch & Carlson 1980) of (xs, ys) at `x`.
fn pchip(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    let (j, _) = crate::numerics::interp::bracket(xs, x);
    let d = |i: usize| (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i]);
    // End slopes one-sided; interior slopes the weighted harmonic mean, zero at an extremum.
    let slope = |i: usize| -> f64 {
        if i == 0 {
            d(0)
        } else if i == n - 1 {
            d(n - 2)
        } else {
            let (d0, d1) = (d(i - 1), d(i));
            if d0 * d1 <= 0.0 {
                0.0
            } else {
                let (h0, h1) = (xs[i] - xs[i - 1], xs[i + 1] - xs[i]);
                let (w1, w2) = (2.0 * h1 + h0, h1 + 2.0 * h0);
                (w1 + w2) / (w1 / d0 + w2 / d1)
            }
        }
    };
    let h = xs[j + 1] - xs[j];
    let t = ((x - xs[j]) / h).clamp(0.0, 1.0);
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * ys[j]
        + (t3 - 2.0 * t2 + t) * h * slope(j)
        + (-2.0 * t3 + 3.0 * t2) * ys[j + 1]
        + (t3 - t2) * h * slope(j + 1)
}

/// A section's outline in chords: the nose at (0, 0), the nose-tail line along x.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Points of the closed outline, clockwise: lower surface from the trailing edge to the nose,
    /// then the upper surface back to the trailing edge; the nose is `points[nose]`.
    pub points: Vec<[f64; 2]>,
    /// Index of the nose point.
    pub nose: usize,
}

/// The a = 0.8 + NACA 66 (DTRC modified) section of maximum camber `f0_c` and thickness `t0_c`,
/// with `panels_per_side` panels on each surface.
///
/// The thickness is laid off normal to the mean line (Abbott & von Doenhoff 1959, eq. 6.1):
/// x = x_c -/+ y_t sin(theta), y = y_c +/- y_t cos(theta). The points are spaced evenly in
/// (cosine-spacing angle + turning of the surface's tangent): about a third of them go round the
/// nose whatever its radius, which a thin tip section (nose radius 4e-4 c) needs for its suction
/// peak, and the cosine spacing keeps panels shorter than the section is thick near the thin tail
/// (constant-strength panels facing each other closer than their length lose the lift).
pub fn section(f0_c: f64, t0_c: f64, panels_per_side: usize) -> Section {
    let cli = f0_c / a08_camber_per_cli();
    let dense = 2000;
    let thick: Vec<f64> = (0..=dense)
        .map(|k| t0_c * closed_thickness(0.5 * (1.0 - libm::cos(std::f64::consts::PI * k as f64 / dense as f64))))
        .collect();
    let surface = |upper: bool| -> Vec<[f64; 2]> {
        (0..=dense)
            .map(|k| {
                let x = 0.5 * (1.0 - libm::cos(std::f64::consts::PI * k as f64 / dense as f64));
                let (yc, dyc) = a08_mean_line(x);
                let (yc, dyc) = (cli * yc, cli * dyc);
                let yt = 0.5 * t0_c * closed_thickness(x);
                let th = libm::atan(dyc);
                let s = if upper { 1.0 } else { -1.0 };
                [x - s * yt * libm::sin(th), yc + s * yt * libm::cos(th)]
            })
            .collect()
    };
    let upper = resample(&surface(true), &thick, panels_per_side);
    let mut points: Vec<[f64; 2]> = resample(&surface(false), &thick, panels_per_side).into_iter().rev().collect();
    points.extend_from_slice(&upper[1..]);
    Section { points, nose: panels_per_side }
}

/// `n + 1` points along a dense polyline from its first point to its last (the dense points at
/// x = (1 - cos theta) / 2, theta evenly spaced), evenly spaced in theta + turning angle \[rad\].
/// Weight of (arc length / local thickness) in the spacing measure \[-\].
const THIN_WEIGHT: f64 = 0.03;

fn resample(dense: &[[f64; 2]], thick: &[f64], n: usize) -> Vec<[f64; 2]> {
    let mut measure = vec![0.0; dense.len()];
    let mut last_angle = None;
    for i in 1..dense.len() {
        let (dx, dy) = (dense[i][0] - dense[i - 1][0], dense[i][1] - dense[i - 1][1]);
        let ds = (dx * dx + dy * dy).sqrt();
        let angle = libm::atan2(dy, dx);
        let turn = last_angle.map_or(0.0, |a: f64| {
            let d = angle - a;
            libm::atan2(libm::sin(d), libm::cos(d)).abs()
        });
        last_angle = Some(angle);
        let thin = THIN_WEIGHT * ds / thick[i].max(thick[i - 1]).max(1e-4);
        measure[i] = measure[i - 1] + std::f64::consts::PI / (dense.len() - 1) as f64 + turn + thin;
    }
    let total = measure[dense.len() - 1];
    (0..=n)
        .map(|k| {
            let m = total * k as f64 / n as f64;
            let (j, f) = crate::numerics::interp::bracket(&measure, m);
            let lerp = crate::numerics::interp::lerp;
            [lerp(dense[j][0], dense[j + 1][0], f), lerp(dense[j][1], dense[j + 1][1], f)]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Abbott & von Doenhoff's table for the a = 0.8 mean line at C_Li = 1: alpha_i = 1.54 deg,
    /// maximum camber 0.0679 c; measured 1.5394 deg and 0.06790 (tolerances: the table's last digit).
    #[test]
    fn a08_constants_match_the_published_table() {
        let ai = a08_ideal_angle_per_cli().to_degrees();
        assert!((ai - 1.54).abs() < 0.005, "ideal angle {ai} deg");
        let f0 = a08_camber_per_cli();
        assert!((f0 - 0.0679).abs() < 0.00005, "camber {f0}");
        // Ends: zero ordinate at nose and tail; the slope is continuous across x = a.
        assert!(a08_mean_line(0.0).0.abs() < 1e-15 && a08_mean_line(1.0).0.abs() < 1e-15);
        let (l, r) = (a08_mean_line(0.8 - 1e-7).1, a08_mean_line(0.8 + 1e-7).1);
        assert!((l - r).abs() < 1e-5, "slope jump at x = a: {l} vs {r}");
        // The slope is the ordinate's derivative (central difference, to 1e-6).
        for x in [0.05, 0.3, 0.6, 0.79, 0.9] {
            let fd = (a08_mean_line(x + 1e-6).0 - a08_mean_line(x - 1e-6).0) / 2e-6;
            assert!((fd - a08_mean_line(x).1).abs() < 1e-6, "x {x}: {fd} vs {}", a08_mean_line(x).1);
        }
    }

    /// The interpolated thickness passes through the table, has its maximum 1 at x = 0.45, its
    /// area is OpenProp's 0.7207 t0 c (to 0.3 %), and the nose has the published radius: near the
    /// nose T/2 = sqrt(2 r x) to 3 % at x = 1e-4.
    #[test]
    fn thickness_form_is_the_table_with_its_round_nose() {
        for (x, t) in csv_points(THICKNESS_66) {
            assert!((naca66_thickness(x) - t).abs() < 1e-12, "x {x}");
        }
        let n = 20000;
        let area: f64 = (0..n).map(|k| naca66_thickness((k as f64 + 0.5) / n as f64)).sum::<f64>() / n as f64;
        assert!((area - 0.7207).abs() < 0.003 * 0.7207, "area {area}");
        let x: f64 = 1e-4;
        let circle = 2.0 * (2.0 * LE_RADIUS_PER_T2 * x).sqrt();
        assert!((naca66_thickness(x) / circle - 1.0).abs() < 0.03, "{} vs {circle}", naca66_thickness(x));
        let tmax = (0..=1000).map(|k| naca66_thickness(k as f64 / 1000.0)).fold(0.0, f64::max);
        assert!((tmax - 1.0).abs() < 0.002, "max {tmax}");
    }

    /// The section's outline: closed at the nose, camber and thickness where they belong (mid-chord
    /// mean of the surfaces = f0 to 1 %, their gap t0 to 1 %).
    #[test]
    fn section_outline_has_its_camber_and_thickness() {
        let s = section(0.02, 0.06, 80);
        assert_eq!(s.points.len(), 161);
        assert!(s.points[s.nose][0].abs() < 1e-15 && s.points[s.nose][1].abs() < 1e-15, "nose");
        let at = |upper: bool, x: f64| -> f64 {
            let pts: Vec<[f64; 2]> =
                if upper { s.points[s.nose..].to_vec() } else { s.points[..=s.nose].iter().rev().copied().collect() };
            let xs: Vec<f64> = pts.iter().map(|p| p[0]).collect();
            let (j, f) = crate::numerics::interp::bracket(&xs, x);
            crate::numerics::interp::lerp(pts[j][1], pts[j + 1][1], f)
        };
        let xm = 0.45;
        let camber = 0.5 * (at(true, xm) + at(false, xm));
        let thick = at(true, xm) - at(false, xm);
        let yc = 0.02 / a08_camber_per_cli() * a08_mean_line(xm).0;
        assert!((camber - yc).abs() < 0.01 * 0.02, "camber {camber} vs {yc}");
        assert!((thick - 0.06).abs() < 0.01 * 0.06, "thickness {thick}");
    }
}
