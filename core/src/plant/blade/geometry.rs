//! The blade of a propeller as a radial table (r/R, c/D, P/D, f0/c, t0/c, skew, rake), its section
//! forms, and the refusals a bad table gets: every error names the row and the column.

use crate::checks::shorten;
use serde::{Deserialize, Serialize};

/// The CSV header of a blade table, in this order (the header of DTMB 4119's published table).
pub const COLUMNS: [&str; 7] = ["r_R", "c_D", "P_D", "f0_c", "t0_c", "skew_deg", "rake_D"];

/// A blade table's text is refused above this size \[bytes\] (a real table is under 2 kB).
pub const MAX_CSV_BYTES: usize = 64 * 1024;
/// Rows of a blade table.
pub const MIN_ROWS: usize = 4;
pub const MAX_ROWS: usize = 40;
/// Blades Z.
pub const BLADES: std::ops::RangeInclusive<u32> = 2..=7;
/// Hub diameter over propeller diameter.
pub const HUB_RATIO: std::ops::RangeInclusive<f64> = 0.05..=0.5;

/// One row of the radial table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// Radius over tip radius r/R \[-\].
    pub r_r: f64,
    /// Chord over diameter c/D \[-\] (0 only at the tip).
    pub c_d: f64,
    /// Local pitch over diameter P/D \[-\].
    pub p_d: f64,
    /// Maximum camber of the mean line over chord f0/c \[-\].
    pub f0_c: f64,
    /// Maximum thickness over chord t0/c \[-\].
    pub t0_c: f64,
    /// Skew angle \[deg\].
    pub skew_deg: f64,
    /// Rake over diameter \[-\].
    pub rake_d: f64,
}

/// The allowed range of each column, in [`COLUMNS`]' order: a wider table is refused, not clamped.
pub const RANGES: [(f64, f64); 7] = [
    (0.05, 1.0),   // r/R: from inside the smallest hub to the tip
    (0.0, 1.5),    // c/D: 0 only at the tip (checked apart); wide-bladed screws stay under 0.6
    (0.2, 3.0),    // P/D: from a slow tug to a fast racing screw
    (-0.1, 0.15),  // f0/c: a thin section's mean line; past 0.1 it is no propeller section
    (0.0, 0.4),    // t0/c: a root section is at most about 0.3 thick
    (-90.0, 90.0), // skew: a blade cannot sweep past the radial line at a right angle
    (-0.5, 0.5),   // rake/D: beyond half a diameter the blade is no longer a disc
];

impl Row {
    /// The row's values in [`COLUMNS`]' order.
    pub fn values(&self) -> [f64; 7] {
        [self.r_r, self.c_d, self.p_d, self.f0_c, self.t0_c, self.skew_deg, self.rake_d]
    }

    fn from_values(v: [f64; 7]) -> Row {
        Row { r_r: v[0], c_d: v[1], p_d: v[2], f0_c: v[3], t0_c: v[4], skew_deg: v[5], rake_d: v[6] }
    }
}

/// The section's mean line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MeanLine {
    /// NACA a = 0.8 mean line (Abbott & von Doenhoff 1959, ch. 6.4), the usual propeller mean line.
    #[default]
    NacaA08,
}

/// The section's thickness form.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Thickness {
    /// NACA 66 (DTRC modified) thickness form (Brockett 1966).
    #[default]
    Naca66Mod,
}

/// The blade geometry of a propeller; its diameter is the scenario's `propeller.diameter_m`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BladeGeometry {
    /// Number of blades Z \[-\].
    pub blades: u32,
    /// Hub diameter over propeller diameter \[-\].
    pub hub_ratio: f64,
    #[serde(default)]
    pub meanline: MeanLine,
    #[serde(default)]
    pub thickness: Thickness,
    /// The radial table, root to tip.
    pub rows: Vec<Row>,
}

impl BladeGeometry {
    /// A geometry from a CSV table with the header [`COLUMNS`] (comment lines start with '#').
    pub fn from_csv(text: &str, blades: u32, hub_ratio: f64) -> Result<BladeGeometry, String> {
        let g = BladeGeometry {
            blades,
            hub_ratio,
            meanline: MeanLine::default(),
            thickness: Thickness::default(),
            rows: parse_rows(text)?,
        };
        g.check()?;
        Ok(g)
    }

    /// Refuses a geometry no propeller has, naming the row (1 = root) and the column.
    pub fn check(&self) -> Result<(), String> {
        if !BLADES.contains(&self.blades) {
            return Err(format!("blades: {} is outside {}..={}", self.blades, BLADES.start(), BLADES.end()));
        }
        if !(HUB_RATIO.contains(&self.hub_ratio)) {
            return Err(format!(
                "hub_ratio: {} is outside {}..={}",
                shorten(&self.hub_ratio.to_string()),
                HUB_RATIO.start(),
                HUB_RATIO.end()
            ));
        }
        let n = self.rows.len();
        if !(MIN_ROWS..=MAX_ROWS).contains(&n) {
            return Err(format!("the blade table has {n} rows; it needs {MIN_ROWS} to {MAX_ROWS}, root to tip"));
        }
        for (i, row) in self.rows.iter().enumerate() {
            let at = |col: usize| format!("row {} ({}), column {}", i + 1, row_name(row), COLUMNS[col]);
            for (col, (&v, &(lo, hi))) in row.values().iter().zip(RANGES.iter()).enumerate() {
                if !v.is_finite() {
                    return Err(format!("{}: {v} is not a number", at(col)));
                }
                if !(lo..=hi).contains(&v) {
                    return Err(format!("{}: {} is outside {lo}..={hi}", at(col), shorten(&v.to_string())));
                }
            }
            let tip = i + 1 == n;
            if !tip && row.c_d <= 0.0 {
                return Err(format!("{}: a chord of {} inside the blade (only the tip may have none)", at(1), row.c_d));
            }
            if !tip && row.t0_c <= 0.0 {
                return Err(format!("{}: a thickness of {} inside the blade", at(4), row.t0_c));
            }
            if i > 0 && row.r_r <= self.rows[i - 1].r_r {
                return Err(format!(
                    "{}: {} does not follow {} (radii go root to tip, increasing)",
                    at(0),
                    row.r_r,
                    self.rows[i - 1].r_r
                ));
            }
        }
        let root = self.rows[0].r_r;
        if root + 1e-9 < self.hub_ratio {
            return Err(format!("row 1, column r_R: {root} is inside the hub (hub_ratio {})", self.hub_ratio));
        }
        let tip = self.rows[n - 1].r_r;
        if tip != 1.0 {
            return Err(format!("row {n}, column r_R: {tip}; the last row is the tip, r/R = 1"));
        }
        Ok(())
    }
}

fn row_name(row: &Row) -> String {
    if row.r_r.is_finite() {
        format!("r/R {}", row.r_r)
    } else {
        "r/R not a number".into()
    }
}

/// The rows of a CSV blade table, header checked, every cell a number; ranges are [`BladeGeometry::check`]'s.
pub fn parse_rows(text: &str) -> Result<Vec<Row>, String> {
    if text.len() > MAX_CSV_BYTES {
        return Err(format!(
            "the blade table is {} bytes; a table of at most {MAX_ROWS} rows is under {} kB",
            text.len(),
            MAX_CSV_BYTES / 1024
        ));
    }
    let mut lines =
        text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((hline, header)) = lines.next() else {
        return Err(format!("the blade table is empty; it needs the header {}", COLUMNS.join(",")));
    };
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    if names != COLUMNS {
        return Err(format!("line {hline}: the header is '{}'; it must be {}", shorten(header), COLUMNS.join(",")));
    }
    let mut rows = Vec::new();
    for (line, text) in lines {
        if rows.len() == MAX_ROWS {
            return Err(format!("line {line}: more than {MAX_ROWS} rows"));
        }
        let cells: Vec<&str> = text.split(',').map(str::trim).collect();
        if cells.len() != COLUMNS.len() {
            return Err(format!(
                "line {line} (row {}): {} cells; it needs {}",
                rows.len() + 1,
                cells.len(),
                COLUMNS.len()
            ));
        }
        let mut v = [0.0; 7];
        for (col, cell) in cells.iter().enumerate() {
            let x: f64 = cell.parse().map_err(|_| {
                format!(
                    "line {line} (row {}), column {}: '{}' is not a number",
                    rows.len() + 1,
                    COLUMNS[col],
                    shorten(cell)
                )
            })?;
            if !x.is_finite() {
                return Err(format!(
                    "line {line} (row {}), column {}: {cell} is not a number",
                    rows.len() + 1,
                    COLUMNS[col]
                ));
            }
            v[col] = x;
        }
        rows.push(Row::from_values(v));
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    const P4119: &str = include_str!("../../../data/dtmb4119_geometry.csv");

    #[test]
    fn dtmb_4119_loads() {
        let g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        assert_eq!(g.rows.len(), 10);
        assert_eq!(g.rows[5].c_d, 0.4622);
        assert_eq!(g.rows[9].r_r, 1.0);
    }

    fn refused(edit: impl Fn(&mut BladeGeometry)) -> String {
        let mut g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        edit(&mut g);
        g.check().unwrap_err()
    }

    #[test]
    fn bad_geometry_is_refused_by_row_and_column() {
        assert!(refused(|g| g.rows[3].c_d = 0.0).starts_with("row 4 (r/R 0.5), column c_D: a chord of 0 inside"));
        assert!(refused(|g| g.rows[2].p_d = 10.0).contains("row 3 (r/R 0.4), column P_D: 10 is outside 0.2..=3"));
        assert!(refused(|g| g.blades = 1).starts_with("blades: 1 is outside 2..=7"));
        assert!(refused(|g| g.rows.swap(2, 3)).contains("row 4 (r/R 0.4), column r_R: 0.4 does not follow 0.5"));
        assert!(refused(|g| g.rows[4].f0_c = f64::NAN).contains("row 5 (r/R 0.6), column f0_c: NaN is not a number"));
        assert!(refused(|g| g.rows[9].r_r = 0.99).contains("the last row is the tip"));
        assert!(refused(|g| g.hub_ratio = 0.3).contains("inside the hub"));
    }

    #[test]
    fn bad_csv_is_refused_by_line_and_column() {
        let big = "#".repeat(5 << 20);
        assert!(parse_rows(&big).unwrap_err().contains("5242880 bytes"));
        let nan = P4119.replace("0.50,0.4392", "0.50,abc");
        assert!(parse_rows(&nan).unwrap_err().contains("(row 4), column c_D: 'abc' is not a number"));
        let short = P4119.replace("0.60,0.4610,1.088,", "0.60,");
        assert!(parse_rows(&short).unwrap_err().contains("(row 5): 5 cells; it needs 7"));
        assert!(parse_rows("r_R,c_D\n").unwrap_err().contains("must be r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D"));
        assert!(parse_rows("").unwrap_err().contains("empty"));
    }
}
