//! Wave scatter diagrams: how often each (H_1/3, T_z) class occurs in an ocean. The default is
//! the North Atlantic of IACS Recommendation No. 34 (core/data/iacs_rec34_north_atlantic.csv,
//! source lines in the file); users load their own CSV of the same layout.
//!
//! Each class is taken as a Bretschneider sea (eq. 2.58) of the class centres: modal frequency
//! omega_n = 2 pi (T_z / T_p) / T_z with T_z / T_p = 0.7104 ([`super::tz_over_tp`]). The ship is
//! operable in a class when its H_1/3 is at most the lowest limiting height of the criteria at
//! that spectral shape.

use std::f64::consts::PI;

/// The IACS Rec. 34 North Atlantic diagram, embedded.
pub const NORTH_ATLANTIC_CSV: &str = include_str!("../../../data/iacs_rec34_north_atlantic.csv");

/// Largest scatter file \[bytes\], most H_1/3 and T_z classes.
pub const MAX_SCATTER_BYTES: usize = 256 << 10;
pub const MAX_CLASSES: usize = 100;
/// Largest occurrence of one class: a diagram counts observations (IACS Rec. 34's add up to
/// 100,000) or their shares; 1e12 per class keeps every total finite (at most 1e16).
pub const MAX_OCCURRENCE: f64 = 1.0e12;

/// A scatter diagram: class centres and occurrences.
#[derive(Debug, Clone, PartialEq)]
pub struct Scatter {
    pub name: String,
    pub source: String,
    /// H_1/3 class centres \[m\] (rows) and T_z class centres \[s\] (columns).
    pub hs_m: Vec<f64>,
    pub tz_s: Vec<f64>,
    /// [row][column] occurrences.
    pub counts: Vec<Vec<f64>>,
}

impl Scatter {
    /// The embedded North Atlantic diagram.
    pub fn north_atlantic() -> Scatter {
        // The embedded file is checked by the tests; a failure here would be a build defect.
        Scatter::parse(NORTH_ATLANTIC_CSV, "IACS Rec. 34 North Atlantic").unwrap_or_else(|_| Scatter {
            name: String::new(),
            source: String::new(),
            hs_m: vec![],
            tz_s: vec![],
            counts: vec![],
        })
    }

    /// Parses the layout of the embedded file: lines starting with # are comments (the first is
    /// kept as the source); a header `Hs_m\Tz_s,T1,T2,...` of T_z class centres \[s\]; then one row
    /// per H_1/3 class, `Hs,count1,count2,...`. Errors name the line.
    pub fn parse(text: &str, name: &str) -> Result<Scatter, String> {
        if text.len() > MAX_SCATTER_BYTES {
            return Err(format!("{} bytes: a scatter diagram may be at most {MAX_SCATTER_BYTES} bytes", text.len()));
        }
        let mut source = String::new();
        let mut tz: Option<Vec<f64>> = None;
        let (mut hs, mut counts) = (Vec::new(), Vec::new());
        let number = |s: &str, line: usize, what: &str| -> Result<f64, String> {
            let t = s.trim();
            t.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("line {line}: {what} \"{}\" is not a number", crate::checks::shorten(t)))
        };
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let l = raw.trim();
            if l.is_empty() {
                continue;
            }
            if let Some(c) = l.strip_prefix('#') {
                if source.is_empty() {
                    source = c.trim().to_string();
                }
                continue;
            }
            let mut cells = l.split(',');
            let first = cells.next().unwrap_or("");
            match &tz {
                None => {
                    let t: Vec<f64> = cells.map(|c| number(c, line, "T_z class centre")).collect::<Result<_, _>>()?;
                    if t.is_empty() || t.len() > MAX_CLASSES {
                        return Err(format!("line {line}: give 1 to {MAX_CLASSES} T_z classes (got {})", t.len()));
                    }
                    if let Some(bad) = t.iter().find(|&&x| !(0.5..=40.0).contains(&x)) {
                        return Err(format!(
                            "line {line}: T_z = {} s is outside 0.5 to 40 s",
                            crate::checks::num(*bad)
                        ));
                    }
                    if t.windows(2).any(|w| w[1] <= w[0]) {
                        return Err(format!("line {line}: T_z classes must increase"));
                    }
                    tz = Some(t);
                }
                Some(t) => {
                    let h = number(first, line, "H_1/3 class centre")?;
                    if !(0.0..=30.0).contains(&h) {
                        return Err(format!("line {line}: H_1/3 = {} m is outside 0 to 30 m", crate::checks::num(h)));
                    }
                    let row: Vec<f64> = cells.map(|c| number(c, line, "occurrence")).collect::<Result<_, _>>()?;
                    if row.len() != t.len() {
                        return Err(format!("line {line}: {} occurrences for {} T_z classes", row.len(), t.len()));
                    }
                    if let Some(&bad) = row.iter().find(|&&x| !(0.0..=MAX_OCCURRENCE).contains(&x)) {
                        return Err(format!(
                            "line {line}: occurrence = {} is outside 0 to {MAX_OCCURRENCE:e}",
                            crate::checks::num(bad)
                        ));
                    }
                    if hs.len() >= MAX_CLASSES {
                        return Err(format!("line {line}: at most {MAX_CLASSES} H_1/3 classes"));
                    }
                    hs.push(h);
                    counts.push(row);
                }
            }
        }
        let tz = tz.ok_or("no header line of T_z classes (Hs_m\\Tz_s,T1,T2,...)")?;
        let total: f64 = counts.iter().flatten().sum();
        if hs.is_empty() || !(total > 0.0 && total.is_finite()) {
            return Err("no occurrences: give at least one H_1/3 row with a positive count".into());
        }
        Ok(Scatter { name: name.to_string(), source, hs_m: hs, tz_s: tz, counts })
    }

    /// The modal frequency [rad/s] of each T_z class.
    pub fn omega_n(&self) -> Vec<f64> {
        let r = super::tz_over_tp();
        self.tz_s.iter().map(|t| 2.0 * PI * r / t).collect()
    }

    /// The modal frequencies of the T_z classes that occur (the spectral shapes to judge).
    pub fn shapes(&self) -> Vec<f64> {
        let w = self.omega_n();
        (0..self.tz_s.len()).filter(|&j| self.counts.iter().any(|r| r[j] > 0.0)).map(|j| w[j]).collect()
    }

    /// The share of occurrences in which the ship is operable, given the limiting H_1/3 at each
    /// of [`Self::shapes`] (in that order).
    pub fn operable_share(&self, limit_at_shape: &[f64]) -> f64 {
        let (mut ok, mut total) = (0.0, 0.0);
        let mut k = 0;
        for j in 0..self.tz_s.len() {
            if !self.counts.iter().any(|r| r[j] > 0.0) {
                continue;
            }
            let lim = limit_at_shape.get(k).copied().unwrap_or(0.0);
            k += 1;
            for (i, row) in self.counts.iter().enumerate() {
                total += row[j];
                if self.hs_m[i] <= lim {
                    ok += row[j];
                }
            }
        }
        if total > 0.0 {
            ok / total
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The embedded diagram reads whole: 17 H_1/3 rows, 18 T_z columns, 99 999.8 occurrences (the
    /// file's own total), its rows summing to the whole numbers the file states within 0.5 (the entries are rounded to 0.1); Bretschneider's T_z / T_p is 0.7104.
    #[test]
    fn the_north_atlantic_reads_whole() {
        let s = Scatter::north_atlantic();
        assert_eq!((s.hs_m.len(), s.tz_s.len()), (17, 18));
        let total: f64 = s.counts.iter().flatten().sum();
        assert!((total - 99_999.8).abs() < 1e-6, "{total}");
        let rows = [
            3050.0, 22575.0, 23810.0, 19128.0, 13289.0, 8328.0, 4806.0, 2586.0, 1309.0, 626.0, 285.0, 124.0, 51.0,
            21.0, 8.0, 3.0, 1.0,
        ];
        for (row, want) in s.counts.iter().zip(rows) {
            let sum: f64 = row.iter().sum();
            assert!((sum - want).abs() <= 0.5 + 1e-9, "{sum} against {want}");
        }
        assert!(s.source.starts_with("IACS Recommendation No. 34"));
        assert_eq!(s.shapes().len(), 16);
        assert!((super::super::tz_over_tp() - 0.7104).abs() < 5e-5);
        // All operable below an infinite limit, none below zero.
        assert_eq!(s.operable_share(&[f64::INFINITY; 16]), 1.0);
        assert_eq!(s.operable_share(&[0.0; 16]), 0.0);
    }

    #[test]
    fn bad_files_name_the_line() {
        for (text, want) in [
            ("Hs_m\\Tz_s,5,6\n1,2\n", "line 2: 1 occurrences for 2 T_z classes"),
            ("Hs_m\\Tz_s,5,x\n", "line 1: T_z class centre \"x\" is not a number"),
            ("Hs_m\\Tz_s,6,5\n", "line 1: T_z classes must increase"),
            ("Hs_m\\Tz_s,5,6\n1,-2,3\n", "line 2: occurrence = -2 is outside 0 to 1e12"),
            // Counts whose total overflows were taken for no occurrences at all.
            ("Hs_m\\Tz_s,5,6\n1,1e308,1e308\n", "line 2: occurrence = 1e308 is outside 0 to 1e12"),
            ("Hs_m\\Tz_s,5,6\n1,0,0\n", "no occurrences"),
            ("# only a comment\n", "no header line"),
        ] {
            let e = Scatter::parse(text, "mine").unwrap_err();
            assert!(e.contains(want), "{e}");
        }
    }
}
