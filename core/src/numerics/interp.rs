//! Linear interpolation, the one module for it: tables on a grid (RAO tables, the seaway's RAO
//! slices), on a uniform grid (the calm-water shaft-speed map), along a curve given by points (the
//! turbine part-load curve, a station's half-breadths), and the two-column tables embedded as CSV.

/// The segment of increasing `grid` holding `x` and the fraction along it: `(j, f)` with
/// x = grid\[j\] + f (grid[j+1] - grid\[j\]); held at the ends (f = 0 below, (n-2, 1) above); a NaN
/// `x` gives the first point.
pub fn bracket(grid: &[f64], x: f64) -> (usize, f64) {
    if grid.len() < 2 || x.is_nan() || x <= grid[0] {
        return (0, 0.0);
    }
    let n = grid.len();
    if x >= grid[n - 1] {
        return (n - 2, 1.0);
    }
    let j = grid.partition_point(|&v| v <= x) - 1;
    (j, (x - grid[j]) / (grid[j + 1] - grid[j]))
}

/// [`bracket`]'s answer found by walking from segment `guess` (the last one found): the same
/// `(j, f)` in a step or two when `x` moves little between calls (the seaway's headings).
pub fn bracket_from(grid: &[f64], x: f64, guess: usize) -> (usize, f64) {
    let n = grid.len();
    if n < 2 || x.is_nan() || x <= grid[0] {
        return (0, 0.0);
    }
    if x >= grid[n - 1] {
        return (n - 2, 1.0);
    }
    // grid[0] < x < grid[n - 1]: the last j with grid[j] <= x, as `bracket`'s partition point.
    let mut j = guess.min(n - 2);
    while grid[j] > x {
        j -= 1;
    }
    while grid[j + 1] <= x {
        j += 1;
    }
    (j, (x - grid[j]) / (grid[j + 1] - grid[j]))
}

/// `y0 + f (y1 - y0)`.
pub fn lerp(y0: f64, y1: f64, f: f64) -> f64 {
    y0 + f * (y1 - y0)
}

/// Values `table[i]` at x = i `step`, at `x` (held at the ends). At least two values.
pub fn uniform(table: &[f64], step: f64, x: f64) -> f64 {
    let s = (x / step).clamp(0.0, (table.len() - 1) as f64);
    let i = (s.floor() as usize).min(table.len() - 2);
    let f = s - i as f64;
    table[i] * (1.0 - f) + table[i + 1] * f
}

/// The straight line through (a, ya) and (b, yb) at `x`, in point-slope form (also outside
/// [a, b]: the caller extrapolates on purpose).
pub fn point_slope(a: f64, ya: f64, b: f64, yb: f64, x: f64) -> f64 {
    ya + (yb - ya) * (x - a) / (b - a)
}

/// The (x, y) points of a two-column CSV table embedded with its source: lines starting with `#`
/// and the header (any line whose columns are not both numbers) are skipped.
pub fn csv_points(text: &str) -> Vec<(f64, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| {
            let (a, b) = l.split_once(',')?;
            Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bracket_and_forms_agree_on_a_line() {
        let g = [0.0, 1.0, 3.0, 7.0];
        let y: Vec<f64> = g.iter().map(|x| 2.0 * x + 1.0).collect();
        for x in [0.0, 0.5, 1.0, 2.5, 6.9, 7.0] {
            let (j, f) = bracket(&g, x);
            assert!((lerp(y[j], y[j + 1], f) - (2.0 * x + 1.0)).abs() < 1e-14, "{x}");
            assert!((point_slope(g[j], y[j], g[j + 1], y[j + 1], x) - (2.0 * x + 1.0)).abs() < 1e-14);
        }
        assert_eq!(bracket(&g, -1.0), (0, 0.0));
        assert_eq!(bracket(&g, 9.0), (2, 1.0));
        // A NaN takes the first point (it used to underflow the index).
        assert_eq!(bracket(&g, f64::NAN), (0, 0.0));
        assert_eq!(bracket_from(&g, f64::NAN, 2), (0, 0.0));
        for x in (0..=90).map(|i| -0.5 + 0.09 * i as f64).chain(g) {
            for guess in 0..5 {
                assert_eq!(bracket_from(&g, x, guess), bracket(&g, x), "{x} from {guess}");
            }
        }
        let t = [0.0, 2.0, 4.0];
        assert_eq!(uniform(&t, 0.5, 0.25), 1.0);
        assert_eq!(uniform(&t, 0.5, 5.0), 4.0);
        assert_eq!(uniform(&t, 0.5, -1.0), 0.0);
    }
}
