//! The scenario's propeller blade geometry (`propeller.geometry`): a named geometry (the ship's
//! B-series equivalent, DTMB 4119) or a table of one's own, resolved into a checked
//! [`BladeGeometry`] at the scenario's diameter.

use crate::checks::Validator;
use crate::plant::blade::{BladeGeometry, MeanLine, Row, Thickness};
use serde::{Deserialize, Serialize};

/// DTMB 4119's table (Epps & Kimball 2013, Table 3; core/data, with its source lines).
const DTMB_4119_CSV: &str = include_str!("../../data/dtmb4119_geometry.csv");
/// DTMB 4119: three blades, hub 0.2 D (same source).
const DTMB_4119_BLADES: u32 = 3;
const DTMB_4119_HUB: f64 = 0.2;

/// The B4-70 geometry derived from the B-series tables (core/data/b4_70_geometry.csv, with how
/// it was derived): chord, the 4-blade root pitch reduction, thickness and camber per radius.
const B4_70_CSV: &str = include_str!("../../data/b4_70_geometry.csv");
/// Blade area ratio and blades of that table.
const B4_70_AREA: f64 = 0.70;
const B4_70_BLADES: f64 = 4.0;
/// Wageningen B-series hub diameter over D for four or more blades (Kuiper 1992, 0.167 D).
const B_SERIES_HUB: f64 = 0.167;
/// The B-series' Br per radius r/R = 0.2..1.0 (Carlton, Marine Propellers and Propulsion, table
/// of the series' thickness t/D = Ar - Z Br): with it the table's four-blade t/D gives Ar, and
/// any Z its own t/D. Ar - 4 Br reproduces core/data/b4_70_geometry.csv's t_D at every radius.
const B_SERIES_BR: [f64; 9] = [0.0040, 0.0035, 0.0030, 0.0025, 0.0020, 0.0015, 0.0010, 0.0005, 0.0];

/// The named geometries (`propeller.geometry.name`).
pub const GEOMETRY_NAMES: [(&str, &str); 3] = [
    ("b_series", "the ship's B-series equivalent (its Z, P/D, Ae/A0)"),
    ("dtmb4119", "DTMB 4119 (3 blades) at the ship's diameter"),
    ("custom", "a table of one's own (rows)"),
];

crate::params! {
    /// One row of a blade table, root to tip (the columns of core/data/dtmb4119_geometry.csv).
    #[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct GeometryRow {
        pub r_r: f64 = 1.0 => {
            label: "Radius r/R", unit: "-", range: 0.05..=1.0, help: "Radius over tip radius; the last row is the tip.",
        },
        pub c_d: f64 = 0.0 => {
            label: "Chord c/D", unit: "-", range: 0.0..=1.5, help: "Chord over diameter; 0 only at the tip.",
        },
        pub p_d: f64 = 1.0 => {
            label: "Pitch P/D", unit: "-", range: 0.2..=3.0, help: "Local pitch over diameter.",
        },
        pub f0_c: f64 = 0.0 => {
            label: "Camber f0/c", unit: "-", range: -0.1..=0.15, help: "Maximum camber of the mean line over chord.",
        },
        pub t0_c: f64 = 0.0 => {
            label: "Thickness t0/c", unit: "-", range: 0.0..=0.4, help: "Maximum thickness over chord.",
        },
        pub skew_deg: f64 = 0.0 => {
            label: "Skew", unit: "deg", range: -90.0..=90.0, help: "Skew angle of the section.",
        },
        pub rake_d: f64 = 0.0 => {
            label: "Rake", unit: "-", range: -0.5..=0.5, help: "Rake over diameter.",
        },
    }
}

impl crate::params::CrossCheck for GeometryRow {}

crate::params! {
    /// `propeller.geometry`: the blades `propeller.model = "geometry"` analyses. Its diameter is
    /// `propeller.diameter_m`; sections are NACA a = 0.8 mean lines with the NACA 66 (DTRC
    /// modified) thickness form.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct GeometrySpec {
        pub name: String = "b_series".into() => {
            label: "Blade geometry", choices: &GEOMETRY_NAMES,
            source: "B-series: derived from the series' tables (core/data/b4_70_geometry.csv); DTMB 4119: Epps & Kimball 2013",
            help: "A named geometry, or \"custom\" with its rows (the command line's --propeller-csv fills them).",
        },
        /// Custom: needs it. Named geometries: their own (B-series: `propeller.blades`; 4119: 3).
        #[serde(skip_serializing_if = "Option::is_none")]
        pub blades: Option<u32> = None => {
            label: "Blades of the geometry", unit: "-", range: 2.0..=7.0, empty: "the named geometry's own",
            help: "Number of blades Z of a custom table.",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub hub_ratio: Option<f64> = None => {
            label: "Hub ratio", unit: "-", range: 0.05..=0.5, empty: "the named geometry's own (B-series 0.167, 4119 0.2)",
            help: "Hub diameter over propeller diameter of a custom table.",
        },
        #[serde(skip_serializing_if = "Vec::is_empty")]
        pub rows: Vec<GeometryRow> = Vec::new() => {},
    }
}

impl crate::params::CrossCheck for GeometrySpec {}

impl From<&GeometryRow> for Row {
    fn from(r: &GeometryRow) -> Row {
        Row { r_r: r.r_r, c_d: r.c_d, p_d: r.p_d, f0_c: r.f0_c, t0_c: r.t0_c, skew_deg: r.skew_deg, rake_d: r.rake_d }
    }
}

impl From<&Row> for GeometryRow {
    fn from(r: &Row) -> GeometryRow {
        GeometryRow {
            r_r: r.r_r,
            c_d: r.c_d,
            p_d: r.p_d,
            f0_c: r.f0_c,
            t0_c: r.t0_c,
            skew_deg: r.skew_deg,
            rake_d: r.rake_d,
        }
    }
}

/// The scenario's B-series propeller, of which a geometry named "b_series" is the equivalent
/// (kept apart from the propeller's parameters so that this module does not read them back).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BSeriesOf {
    /// Blades Z \[-\].
    pub blades: u32,
    /// Pitch ratio P/D \[-\].
    pub pitch_ratio: f64,
    /// Expanded blade area ratio Ae/A0 \[-\].
    pub blade_area_ratio: f64,
}

impl GeometrySpec {
    /// A custom geometry from a CSV blade table (the header of core/data/dtmb4119_geometry.csv).
    pub fn from_csv(text: &str, blades: u32, hub_ratio: f64) -> Result<GeometrySpec, String> {
        let g = BladeGeometry::from_csv(text, blades, hub_ratio)?;
        Ok(GeometrySpec {
            name: "custom".into(),
            blades: Some(blades),
            hub_ratio: Some(hub_ratio),
            rows: g.rows.iter().map(GeometryRow::from).collect(),
        })
    }

    /// The checked geometry this section names for the propeller `p` (its B-series Z, P/D and
    /// Ae/A0 for the B-series equivalent). Errors are (field, message), the field under
    /// `propeller.geometry`; a bad table's message names its row and column.
    pub fn resolve(&self, p: &BSeriesOf) -> Result<BladeGeometry, (String, String)> {
        let named = |field: &str| -> Result<(), (String, String)> {
            if field == "rows" && !self.rows.is_empty() || field == "blades" && self.blades.is_some() {
                return Err((field.into(), format!("is for name = \"custom\"; \"{}\" has its own", self.name)));
            }
            Ok(())
        };
        let g = match self.name.as_str() {
            "b_series" => {
                named("rows")?;
                named("blades")?;
                b_series_equivalent(p.blades, p.pitch_ratio, p.blade_area_ratio, self.hub_ratio.unwrap_or(B_SERIES_HUB))
                    .map_err(|e| ("name".to_string(), e))?
            }
            "dtmb4119" => {
                named("rows")?;
                named("blades")?;
                let hub = self.hub_ratio.unwrap_or(DTMB_4119_HUB);
                BladeGeometry::from_csv(DTMB_4119_CSV, DTMB_4119_BLADES, hub).map_err(|e| ("name".to_string(), e))?
            }
            "custom" => {
                if self.rows.is_empty() {
                    return Err(("rows".into(), "a custom geometry needs its rows, root to tip".into()));
                }
                let Some(blades) = self.blades else {
                    return Err(("blades".into(), "a custom geometry needs its number of blades".into()));
                };
                BladeGeometry {
                    blades,
                    hub_ratio: self.hub_ratio.unwrap_or(B_SERIES_HUB),
                    meanline: MeanLine::default(),
                    thickness: Thickness::default(),
                    rows: self.rows.iter().map(Row::from).collect(),
                }
            }
            other => {
                let names: Vec<&str> = GEOMETRY_NAMES.iter().map(|(n, _)| *n).collect();
                return Err((
                    "name".into(),
                    format!("\"{}\" must be one of {}", crate::checks::shorten(other), names.join(", ")),
                ));
            }
        };
        g.check().map_err(|e| ("rows".to_string(), e))?;
        Ok(g)
    }

    /// Checks the section for the propeller `p` (called by `propeller`'s cross check).
    pub fn validate(&self, p: &BSeriesOf, v: &mut Validator) {
        if let Err((field, msg)) = self.resolve(p) {
            v.fail(&field, "", msg);
        }
    }
}

/// The Wageningen B-series geometry of `blades` Z, pitch ratio P/D and blade area ratio Ae/A0,
/// from the B4-70 table: chords scale with Ae/A0 / Z (the series' chord factor c Z / (D Ae/A0)
/// is one function of r/R), the root pitch reduction belongs to the four-bladed series only
/// (the others have constant pitch), thickness is t/D = Ar - Z Br, and camber scales with the
/// section's thickness (the series' section ordinates are fractions of it).
pub fn b_series_equivalent(
    blades: u32,
    pitch_ratio: f64,
    area_ratio: f64,
    hub_ratio: f64,
) -> Result<BladeGeometry, String> {
    let z = blades as f64;
    let b4 = crate::plant::blade::geometry::parse_rows(B4_70_CSV).map_err(|e| format!("b4_70_geometry.csv: {e}"))?;
    if b4.len() != B_SERIES_BR.len() {
        return Err(format!("b4_70_geometry.csv: {} rows; the series' tables have {}", b4.len(), B_SERIES_BR.len()));
    }
    let mut rows = Vec::new();
    for (i, r4) in b4.iter().enumerate() {
        let c_d = r4.c_d * B4_70_BLADES / B4_70_AREA * area_ratio / z;
        // The tip (chord 0) carries no section: thickness and camber 0 there.
        let tip = c_d <= 0.0;
        let t4_d = r4.t0_c * r4.c_d;
        let t_d = t4_d + (B4_70_BLADES - z) * B_SERIES_BR[i];
        let t0_c = if tip { 0.0 } else { t_d / c_d };
        let f0_c = if tip { 0.0 } else { r4.f0_c * t0_c / r4.t0_c };
        let p_d = pitch_ratio * if blades == 4 { r4.p_d } else { 1.0 };
        rows.push(Row { r_r: r4.r_r, c_d, p_d, f0_c, t0_c, skew_deg: 0.0, rake_d: 0.0 });
    }
    let g = BladeGeometry { blades, hub_ratio, meanline: MeanLine::default(), thickness: Thickness::default(), rows };
    g.check()?;
    Ok(g)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// B4-70 P/D 1 reproduces the table it is derived from (chord and pitch to 1e-12, t/D to 1e-4),
    /// and its expanded area ratio (`area_ratio`: hub to an elliptic tip) is 0.70 within 3 %.
    #[test]
    fn b4_70_round_trip_and_area() {
        let g = b_series_equivalent(4, 1.0, 0.70, B_SERIES_HUB).unwrap();
        assert!((g.rows[0].c_d - 0.2908).abs() < 1e-12 && (g.rows[0].p_d - 0.822).abs() < 1e-12);
        // t/D = 0.0240 at r/R 0.5; the table gives t/c to four figures.
        assert!((g.rows[3].t0_c * g.rows[3].c_d - 0.0240).abs() < 1e-4);
        let area = crate::plant::propeller_table::area_ratio;
        let a = area(&g);
        assert!((a - 0.70).abs() < 0.03 * 0.70, "Ae/A0 = {a}");
        let g5 = b_series_equivalent(5, 1.0, 0.75, B_SERIES_HUB).unwrap();
        let a5 = area(&g5);
        assert!((a5 / a - 0.75 / 0.70).abs() < 1e-9, "Ae/A0 scales: {a5} vs {a}");
        assert!(g5.rows.iter().all(|r| r.p_d == 1.0), "five blades: constant pitch");
    }

    #[test]
    fn named_and_custom_resolve_or_are_refused_by_name() {
        let p = crate::plant::propeller::PropellerParams::default().b_series_of();
        let g = GeometrySpec { name: "dtmb4119".into(), ..GeometrySpec::default() }.resolve(&p).unwrap();
        assert_eq!((g.blades, g.rows.len()), (3, 10));
        let custom = GeometrySpec::from_csv(DTMB_4119_CSV, 3, 0.2).unwrap();
        assert_eq!(custom.resolve(&p).unwrap(), g);
        let mut bad = custom.clone();
        bad.rows[3].c_d = 0.0;
        let (field, msg) = bad.resolve(&p).unwrap_err();
        assert_eq!(field, "rows");
        assert!(msg.starts_with("row 4 (r/R 0.5), column c_D: a chord of 0"), "{msg}");
        let (field, _) = GeometrySpec { name: "custom".into(), ..GeometrySpec::default() }.resolve(&p).unwrap_err();
        assert_eq!(field, "rows");
        let (field, _) = GeometrySpec { name: "x".into(), ..GeometrySpec::default() }.resolve(&p).unwrap_err();
        assert_eq!(field, "name");
    }
}

#[cfg(test)]
mod scenario_tests {
    /// The scenario's checks name the field: a geometry model without a geometry, a bad row (by
    /// row and column), and a registry range of one cell.
    #[test]
    fn the_scenario_refuses_by_name() {
        let sc = crate::scenario::presets::preset("startup").unwrap();
        let err = |pairs: &[(&str, &str)]| sc.with_overrides(pairs).unwrap_err().to_string();
        let e = err(&[("propeller.model", "\"geometry\"")]);
        assert!(e.contains("propeller.geometry") && e.contains("needs a blade geometry"), "{e}");
        let rows = r#"{"name":"custom","blades":3,"rows":[{"r_r":0.2,"c_d":0.3,"p_d":1.0,"t0_c":0.1},
            {"r_r":0.5,"c_d":0.0,"p_d":1.0,"t0_c":0.1},{"r_r":0.8,"c_d":0.3,"p_d":1.0,"t0_c":0.1},
            {"r_r":1.0,"c_d":0.0,"p_d":1.0}]}"#;
        let e = err(&[("propeller.model", "\"geometry\""), ("propeller.geometry", rows)]);
        assert!(e.contains("propeller.geometry.rows") && e.contains("row 2 (r/R 0.5), column c_D"), "{e}");
        let e = err(&[("propeller.geometry", &rows.replace("\"p_d\":1.0,\"t0_c\":0.1}", "\"p_d\":10,\"t0_c\":0.1}"))]);
        assert!(e.contains("propeller.geometry.rows.0.p_d") && e.contains("from 0.2 to 3"), "{e}");
        let ok =
            sc.with_overrides(&[("propeller.model", "\"geometry\""), ("propeller.geometry", r#"{"name":"dtmb4119"}"#)]);
        assert!(ok.is_ok(), "{ok:?}");
    }
}
