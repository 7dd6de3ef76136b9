//! The ship's hull: one definition that every study uses (thesis ch. 2 intro: the seakeeping
//! model "allows for the input of an arbitrary hull shape"). The scenario's `ship.hull` names an
//! embedded hull or carries offsets, with the loading (draft or mass, KG, radii of gyration) and
//! the appendages (bilge keels, propeller hubs, rudder). From it come the one length Lpp of the
//! maneuvering prime system, the displaced mass of the surge and maneuvering models, the
//! propellers' and rudder's levers, and the strip-theory hull of the RAO tables.
//!
//! Positions are from the aft perpendicular (x forward), the centreline (y to port, STF) and the
//! baseline (z up), as in the offsets. A field left out (null) takes the embedded hull's own
//! value, or for offsets of one's own the rule in its doc comment.
//!
//! Thesis Tables 5.1 and 5.5 give L = 180 m, x_p = 75 m and m = 7e6 kg; the DTMB 5415, the
//! DDG-51's public hull form and our seakeeping hull, has Lpp = 142 m and displaces 8.64e6 kg at
//! its 6.15 m design draft. The default is the 5415 throughout: Table 2.3's (X_udot - m)' scaled
//! by L = 142 m gives m - X_udot = 9.5e6 kg, the 5415's mass plus 10 % added mass, while L = 180 m
//! gives 19.3e6 kg, 2.75 times Table 5.1's mass. `as_printed.table_5_ship` runs the thesis'
//! numbers instead (core/src/as_printed.rs).

use crate::as_printed::AsPrintedParams;
use crate::checks::{num, short, Validator};
use crate::geometry::{HullOffsets, Hydrostatics};
use crate::sea::seakeeping::strip::{BilgeKeels, MassProperties, Ship};
use serde::{Deserialize, Serialize};
use std::sync::{Arc, Mutex, OnceLock};

/// Shafts of the ship (port, starboard): the geometry's.
pub use crate::geometry::N_SHAFTS;

/// Resolved hulls (and strip-ship checks) remembered, the oldest dropped first.
const MEMO_SIZE: usize = 8;

/// The embedded hulls' names (`ship.hull.name`), then "custom" for offsets of one's own.
pub const HULL_NAMES: [&str; 3] = ["dtmb5415", "wigley", "custom"];

crate::params! {
    /// The `ship.hull` section of the scenario. Its ranges depend on the hull (a draft bounds KG,
    /// the length the appendages' places): `HullSpec::validate` checks them once it resolves.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct HullSpec {
        pub name: String = "dtmb5415".into() => {
            label: "Hull", source: "our choice: the DTMB 5415, the destroyer the thesis' ship resembles",
            choices: &[("dtmb5415", "DTMB 5415 (destroyer, 142 m)"), ("wigley", "Wigley (test hull)"), ("custom", "custom offsets")],
            help: "An embedded hull, or \"custom\" with offsets_csv.",
        },
        /// Offsets of a custom hull in the long format `station_index,x_m,z_m,half_breadth_m` (what
        /// `aes-sim rao --hull` reads), x forward from the aft perpendicular, z above the baseline.
        #[serde(skip_serializing_if = "String::is_empty")]
        pub offsets_csv: String = String::new() => {
            label: "Custom hull offsets", empty: "an embedded hull",
            help: "CSV lines station_index,x_m,z_m,half_breadth_m (x from the AP, z above the baseline).",
        },
        /// Neither this nor `mass_kg`: the embedded hull's design draft (5415: 6.15 m, Wigley:
        /// 6.25 m).
        #[serde(skip_serializing_if = "Option::is_none")]
        pub draft_m: Option<f64> = None => {
            label: "Draft T", unit: "m", empty: "the hull's own", group: "hull-loading",
            source: "the embedded hull's design draft (5415: 6.15 m, Wigley: 6.25 m)",
            help: "Calm waterline above the baseline, even keel. Give the draft or the mass.",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub mass_kg: Option<f64> = None => {
            label: "Displaced mass", unit: "kg", empty: "from the draft", group: "hull-loading",
            excludes: &["ship.hull.draft_m"],
            help: "Instead of the draft: the draft is solved so that the hull displaces this mass.",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub kg_m: Option<f64> = None => {
            label: "Centre of gravity KG", unit: "m", empty: "the hull's own", group: "hull-loading",
            source: "5415: 7.555 m (SIMMAN 2014); Wigley: 4.5 m (our choice)",
            help: "Above the baseline; a custom hull needs it.",
        },
        /// Custom offsets: 0.37 B, 0.25 Lpp, 0.25 Lpp (the 5415's ratios, typical of slender ships).
        #[serde(skip_serializing_if = "Option::is_none")]
        pub kxx_m: Option<f64> = None => {
            label: "Roll radius of gyration k_xx", unit: "m", empty: "the hull's own (custom: 0.37 B)", group: "hull-loading",
            source: "SIMMAN 2014 ratios", help: "About the centre of gravity.",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub kyy_m: Option<f64> = None => {
            label: "Pitch radius of gyration k_yy", unit: "m", empty: "the hull's own (custom: 0.25 Lpp)", group: "hull-loading",
            source: "SIMMAN 2014 ratios", help: "About the centre of gravity.",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub kzz_m: Option<f64> = None => {
            label: "Yaw radius of gyration k_zz", unit: "m", empty: "the hull's own (custom: 0.25 Lpp)", group: "hull-loading",
            source: "SIMMAN 2014 ratios", help: "About the centre of gravity.",
        },
        /// Length 0: none. Custom offsets and the Wigley: none.
        #[serde(skip_serializing_if = "Option::is_none")]
        pub bilge_keels: Option<BilgeKeels> = None => {},
        #[serde(skip_serializing_if = "Option::is_none")]
        pub propeller_x_m: Option<f64> = None => {
            label: "Propellers from the AP", unit: "m", empty: "the hull's own (custom: 0.058 Lpp)",
            source: "5415: 8.3 m (our choice)", help: "Propeller hubs' distance forward of the aft perpendicular.",
        },
        /// Port positive, starboard negative.
        #[serde(skip_serializing_if = "Option::is_none")]
        pub shaft_y_m: Option<[f64; N_SHAFTS]> = None => {
            label: "Shaft offsets", unit: "m", empty: "the hull's own (custom: +-0.26 B)",
            source: "5415: +-5.0 m (our choice)", help: "Lateral offsets of the port and starboard shafts, to port.",
        },
        /// Custom: 0.024 T (the 5415's 0.15 m at 6.15 m).
        #[serde(skip_serializing_if = "Option::is_none")]
        pub hub_above_base_m: Option<f64> = None => {
            label: "Propeller hub above the baseline", unit: "m", empty: "the hull's own (custom: 0.024 T)", group: "hull-loading",
            source: "5415: 0.15 m, h0 = 6.0 m (ch. 5.3)",
            help: "The calm-water hub depth is h0 = draft - hub height (ch. 5.3 and 5.4 vary h0).",
        },
        #[serde(skip_serializing_if = "Option::is_none")]
        pub rudder_x_m: Option<f64> = None => {
            label: "Rudder from the AP", unit: "m", empty: "the hull's own (custom: 0.022 Lpp)",
            source: "5415: 3.1 m (our choice)", help: "Rudders' distance forward of the aft perpendicular (its lever in eq. 2.19).",
        },
        /// Custom: the rule of thumb A = T L (1 + 25 (B/L)^2) / 100 for all rudders (Det Norske
        /// Veritas' minimum), shared by the two.
        #[serde(skip_serializing_if = "Option::is_none")]
        pub rudder_area_m2: Option<f64> = None => {
            label: "Rudder area (each)", unit: "m²", empty: "the hull's own (custom: DNV's minimum)",
            source: "5415: 15.4 m² each, twin spade rudders (SIMMAN 2014's 5415M at full scale)",
            help: "Lateral area of each of the two rudders (the hull's own maneuvering model).",
        },
        /// Custom: 0.7 T.
        #[serde(skip_serializing_if = "Option::is_none")]
        pub rudder_span_m: Option<f64> = None => {
            label: "Rudder span", unit: "m", empty: "the hull's own (custom: 0.7 T)",
            source: "5415: 4.0 m (our estimate: geometric aspect ratio 1.04)",
            help: "Height of each rudder; with the area it sets the aspect ratio and so the lift slope.",
        },
    }
}

impl crate::params::CrossCheck for HullSpec {}

/// An embedded hull's own loading and appendages.
struct Embedded {
    offsets: fn() -> HullOffsets,
    draft_m: f64,
    kg_m: f64,
    /// Radii of gyration [m].
    k_m: [f64; 3],
    bilge_keels: Option<BilgeKeels>,
    propeller_x_m: f64,
    shaft_y_m: [f64; N_SHAFTS],
    hub_above_base_m: f64,
    rudder_x_m: f64,
    rudder_area_m2: f64,
    rudder_span_m: f64,
}

/// The DTMB 5415 at its design draft with the SIMMAN 2014 mass properties (KG 7.555 m,
/// kxx = 0.37 B, kyy = kzz = 0.25 Lpp) and our appendages: bilge keels of 0.25 Lpp by 0.6 m over
/// the middle body (b/B = 0.031, destroyer practice); propellers 8.3 m (0.058 Lpp) forward of
/// the AP, 62 m aft of the centre of gravity, on shafts 5.0 m (0.26 B) either side, their hubs
/// 0.15 m above the baseline (h0 = 6.0 m, ch. 5.3); rudders one propeller diameter behind, 3.1 m
/// forward of the AP.
fn dtmb5415() -> Embedded {
    Embedded {
        offsets: HullOffsets::dtmb5415,
        draft_m: 6.15,
        kg_m: 7.555,
        k_m: [0.37 * 19.06, 0.25 * 142.0, 0.25 * 142.0],
        bilge_keels: Some(BilgeKeels { length_m: 0.25 * 142.0, breadth_m: 0.6 }),
        propeller_x_m: 8.3,
        shaft_y_m: [5.0, -5.0],
        hub_above_base_m: 0.15,
        rudder_x_m: 3.1,
        rudder_area_m2: 15.4,
        rudder_span_m: 4.0,
    }
}

/// The Wigley hull (y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2), Journee 1992's Wigley I, L/B = 10,
/// B/T = 1.6) at L 100 m, B 10 m, T 6.25 m (`HullOffsets::wigley`), without bilge keels. Mass
/// properties are our choice (Journee 1992's values could not be found here): kyy = kzz = 0.25 L
/// (the usual assumption for Wigley seakeeping tests), kxx = 0.35 B, KG = 4.5 m = 0.72 T, which
/// gives GM_T 0.78 m (the hull's KM_T is 5T/8 + 3B^2/(35T) = 5.28 m). A test hull has no
/// appendages of its own: the 5415's rules place them (propellers 0.058 L forward of the AP on
/// shafts +-0.26 B, hubs 0.15 m above the base, the rudder 0.022 L forward of the AP).
fn wigley() -> Embedded {
    Embedded {
        offsets: HullOffsets::wigley,
        draft_m: 6.25,
        kg_m: 4.5,
        k_m: [0.35 * 10.0, 0.25 * 100.0, 0.25 * 100.0],
        bilge_keels: None,
        propeller_x_m: 5.8,
        shaft_y_m: [2.6, -2.6],
        hub_above_base_m: 0.15,
        rudder_x_m: 2.2,
        rudder_area_m2: rule_rudder_area(100.0, 10.0, 6.25),
        rudder_span_m: 0.7 * 6.25,
    }
}

/// What a custom hull must be given (an embedded one has its own loading).
const NEEDS_LOADING: &str = "a custom hull needs its draft_m or mass_kg";
const NEEDS_KG: &str = "a custom hull needs its centre of gravity above the baseline";

fn embedded(name: &str) -> Option<Embedded> {
    match name {
        "dtmb5415" => Some(dtmb5415()),
        "wigley" => Some(wigley()),
        _ => None,
    }
}

/// The hull of a run: geometry, loading and appendages resolved, SI throughout.
#[derive(Debug, Clone, PartialEq)]
pub struct ShipHull {
    /// Name of the embedded hull or "custom".
    pub name: String,
    pub offsets: HullOffsets,
    /// Waterline above the baseline \[m\] and the hydrostatics there.
    pub draft_m: f64,
    pub hydrostatics: Hydrostatics,
    /// Length between perpendiculars: the offsets' span \[m\]. The one length of every model.
    pub lpp_m: f64,
    /// Largest waterline breadth \[m\].
    pub beam_m: f64,
    /// Displaced mass rho V \[kg\].
    pub mass_kg: f64,
    pub mass_props: MassProperties,
    pub bilge_keels: Option<BilgeKeels>,
    /// Centre of gravity (= centre of buoyancy) forward of the AP \[m\].
    pub lcg_m: f64,
    /// Propellers aft of the centre of gravity \[m\], shafts' offsets to port \[m\], calm-water hub
    /// depth below the waterline \[m\].
    pub prop_x_aft_m: f64,
    pub shaft_y_m: [f64; N_SHAFTS],
    pub hub_depth_m: f64,
    /// Rudder aft of the centre of gravity \[m\] (x_p of eqs. 2.19, 2.26-2.27).
    pub rudder_x_aft_m: f64,
    /// Each rudder's lateral area [m^2] and span \[m\] (the hull's own maneuvering model).
    pub rudder_area_m2: f64,
    pub rudder_span_m: f64,
    pub rho: f64,
    /// Every input of `strip_ship` as text, made once (the RAO cache's key; a custom hull's
    /// offsets make it long, and clones share it).
    table_key: Arc<str>,
}

/// Bisection steps for the draft of a given mass (the interval halves 60 times: far below a
/// micrometre on any ship).
const DRAFT_BISECTIONS: u32 = 60;

impl HullSpec {
    /// The offsets this section names (parsed for custom hulls; errors name the line).
    pub fn offsets(&self) -> Result<HullOffsets, (String, String)> {
        match (embedded(&self.name), self.name.as_str()) {
            (Some(e), _) => {
                if !self.offsets_csv.is_empty() {
                    return Err((
                        "offsets_csv".into(),
                        format!("offsets are for name = \"custom\"; \"{}\" is an embedded hull", self.name),
                    ));
                }
                Ok((e.offsets)())
            }
            (None, "custom") => {
                if self.offsets_csv.trim().is_empty() {
                    return Err(("offsets_csv".into(), "a custom hull needs its offsets (long CSV format)".into()));
                }
                HullOffsets::parse(&self.offsets_csv).map_err(|e| ("offsets_csv".into(), e))
            }
            _ => Err(("name".into(), format!("must be one of {}", HULL_NAMES.join(", ")))),
        }
    }

    /// Resolves the section with water density `rho` [kg/m^3]. Errors are (field, message).
    ///
    /// Memoised: a run resolves its hull several times (validation, plant, seaway, RAO table)
    /// and a Monte Carlo study once per trial; resolving is deterministic, so a remembered hull
    /// is the same to the bit.
    pub fn resolve(&self, rho: f64) -> Result<ShipHull, (String, String)> {
        type Memo = Mutex<Vec<((HullSpec, u64), ShipHull)>>;
        static RESOLVED: OnceLock<Memo> = OnceLock::new();
        let memo = RESOLVED.get_or_init(|| Mutex::new(Vec::new()));
        if let Ok(m) = memo.lock() {
            if let Some((_, h)) = m.iter().find(|((spec, r), _)| *r == rho.to_bits() && spec == self) {
                return Ok(h.clone());
            }
        }
        let h = self.resolve_uncached(rho)?;
        if let Ok(mut m) = memo.lock() {
            if m.len() >= MEMO_SIZE {
                drop(m.remove(0));
            }
            m.push(((self.clone(), rho.to_bits()), h.clone()));
        }
        Ok(h)
    }

    fn resolve_uncached(&self, rho: f64) -> Result<ShipHull, (String, String)> {
        let offsets = self.offsets()?;
        let emb = embedded(&self.name);
        let xs = offsets.stations.iter().map(|s| s.x);
        let (x_min, x_max) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
        let lpp = x_max - x_min;
        let top = offsets.stations.iter().map(|s| *s.z.last().unwrap_or(&0.0)).fold(f64::INFINITY, f64::min);
        let bottom = offsets.stations.iter().map(|s| s.z[0]).fold(f64::INFINITY, f64::min);
        let draft = match (self.draft_m, self.mass_kg, &emb) {
            (Some(_), Some(_), _) => {
                return Err(("mass_kg".into(), "give the draft or the mass, not both".into()));
            }
            (Some(t), None, _) => {
                // Above the baseline (the keel, z = 0; a sonar dome may reach below it) and the
                // lowest offset.
                if !(t > bottom.max(0.0) && t <= top) {
                    return Err((
                        "draft_m".into(),
                        format!(
                            "must be above the baseline and the lowest offset (more than {} m) and within every \
                             station's data (up to {top} m)",
                            bottom.max(0.0)
                        ),
                    ));
                }
                t
            }
            (None, Some(m), _) => draft_for_mass(&offsets, m, rho, bottom, top)?,
            (None, None, Some(e)) => e.draft_m,
            (None, None, None) => {
                return Err(("draft_m".into(), NEEDS_LOADING.into()));
            }
        };
        let hs = offsets.hydrostatics(draft).map_err(|e| ("draft_m".to_string(), e))?;
        if hs.volume.is_nan() || hs.volume <= 0.0 {
            return Err(("draft_m".into(), format!("the hull displaces nothing at {draft} m")));
        }
        let secs = offsets.sections(draft).map_err(|e| ("draft_m".to_string(), e))?;
        let beam = secs.iter().map(|s| s.beam).fold(0.0, f64::max);
        let pick = |own: Option<f64>, e: Option<f64>, custom: f64| own.or(e).unwrap_or(custom);
        let kg = match (self.kg_m, &emb) {
            (Some(k), _) => k,
            (None, Some(e)) => e.kg_m,
            (None, None) => return Err(("kg_m".into(), NEEDS_KG.into())),
        };
        let ek = emb.as_ref().map(|e| e.k_m);
        let mass_props = MassProperties {
            kg_m: kg,
            kxx_m: pick(self.kxx_m, ek.map(|k| k[0]), 0.37 * beam),
            kyy_m: pick(self.kyy_m, ek.map(|k| k[1]), 0.25 * lpp),
            kzz_m: pick(self.kzz_m, ek.map(|k| k[2]), 0.25 * lpp),
        };
        let bilge_keels = match self.bilge_keels {
            Some(b) if b.length_m == 0.0 || b.breadth_m == 0.0 => None,
            Some(b) => Some(b),
            None => emb.as_ref().and_then(|e| e.bilge_keels),
        };
        let prop_x = pick(self.propeller_x_m, emb.as_ref().map(|e| e.propeller_x_m), x_min + 0.058 * lpp);
        let shaft_y = self.shaft_y_m.or(emb.as_ref().map(|e| e.shaft_y_m)).unwrap_or([0.26 * beam, -0.26 * beam]);
        let hub_z = pick(self.hub_above_base_m, emb.as_ref().map(|e| e.hub_above_base_m), 0.024 * draft);
        let rudder_x = pick(self.rudder_x_m, emb.as_ref().map(|e| e.rudder_x_m), x_min + 0.022 * lpp);
        let rudder_area =
            pick(self.rudder_area_m2, emb.as_ref().map(|e| e.rudder_area_m2), rule_rudder_area(lpp, beam, draft));
        let rudder_span = pick(self.rudder_span_m, emb.as_ref().map(|e| e.rudder_span_m), 0.7 * draft);
        let hull = ShipHull {
            name: self.name.clone(),
            draft_m: draft,
            lpp_m: lpp,
            beam_m: beam,
            mass_kg: rho * hs.volume,
            mass_props,
            bilge_keels,
            lcg_m: hs.lcb,
            prop_x_aft_m: hs.lcb - prop_x,
            shaft_y_m: shaft_y,
            hub_depth_m: draft - hub_z,
            rudder_x_aft_m: hs.lcb - rudder_x,
            rudder_area_m2: rudder_area,
            rudder_span_m: rudder_span,
            hydrostatics: hs,
            offsets,
            rho,
            table_key: Arc::from(""),
        };
        Ok(ShipHull { table_key: hull.key_text().into(), ..hull })
    }

    /// Checks the section (with water density `rho`): the hull must resolve, float upright and
    /// carry its appendages within reach of the hull.
    pub fn validate(&self, v: &mut Validator, rho: f64) {
        // A custom hull names every value it lacks at once (the loading has no defaults to fall
        // back on), rather than one per try; a file that does not parse is named first, below.
        if embedded(&self.name).is_none() && self.offsets().is_ok() {
            let lacks_loading = self.draft_m.is_none() && self.mass_kg.is_none();
            if lacks_loading {
                v.fail("draft_m", "null", NEEDS_LOADING);
            }
            if self.kg_m.is_none() {
                v.fail("kg_m", "null", NEEDS_KG);
            }
            if lacks_loading || self.kg_m.is_none() {
                return;
            }
        }
        let h = match self.resolve(rho) {
            Ok(h) => h,
            Err((field, msg)) => {
                let value = match field.as_str() {
                    "name" => self.name.clone(),
                    "offsets_csv" => format!("({} bytes)", self.offsets_csv.len()),
                    "draft_m" => self.draft_m.map(num).unwrap_or_else(|| "null".into()),
                    "mass_kg" => self.mass_kg.map(num).unwrap_or_else(|| "null".into()),
                    "kg_m" => "null".into(),
                    _ => String::new(),
                };
                v.fail(&field, value, msg);
                return;
            }
        };
        let (l, b, t) = (h.lpp_m, h.beam_m, h.draft_m);
        let mp = &h.mass_props;
        v.range("kg_m", mp.kg_m, -t, 3.0 * t.max(b));
        v.range("kxx_m", mp.kxx_m, 0.01 * b, 2.0 * b);
        v.range("kyy_m", mp.kyy_m, 0.01 * l, l);
        v.range("kzz_m", mp.kzz_m, 0.01 * l, l);
        if let Some(bk) = self.bilge_keels {
            v.range("bilge_keels.length_m", bk.length_m, 0.0, l);
            v.range("bilge_keels.breadth_m", bk.breadth_m, 0.0, 0.2 * b);
        }
        let x0 = h.offsets.stations.first().map(|s| s.x).unwrap_or(0.0);
        v.range("propeller_x_m", h.lcg_m - h.prop_x_aft_m, x0 - 0.1 * l, x0 + 0.5 * l);
        v.range("rudder_x_m", h.lcg_m - h.rudder_x_aft_m, x0 - 0.1 * l, x0 + 0.5 * l);
        for (i, y) in h.shaft_y_m.iter().enumerate() {
            v.range(&format!("shaft_y_m.{i}"), *y, -b, b);
        }
        // The propeller's and rudders' ranges scale with the draft. A part the user left to the
        // hull's own (the 5415's 4 m rudder span) that a draft of the user's no longer fits is the
        // draft's fault, and the draft is named; a part the user set is checked as usual.
        let loading = match (self.draft_m, self.mass_kg) {
            (Some(d), _) => Some(("draft_m", d)),
            (None, Some(m)) => Some(("mass_kg", m)),
            (None, None) => None,
        };
        let mut misfits = Vec::new();
        for (field, own, value, lo, hi) in [
            ("hub_above_base_m", self.hub_above_base_m, t - h.hub_depth_m, -t, t),
            ("rudder_area_m2", self.rudder_area_m2, h.rudder_area_m2, 0.001 * l * t, 0.1 * l * t),
            ("rudder_span_m", self.rudder_span_m, h.rudder_span_m, 0.1 * t, 2.0 * t),
        ] {
            if own.is_none() && loading.is_some() && !(value >= lo && value <= hi) {
                misfits.push(format!("{field} = {} outside {} to {}", short(value), short(lo), short(hi)));
            } else {
                v.range(field, value, lo, hi);
            }
        }
        if let (Some((field, value)), false) = (loading, misfits.is_empty()) {
            v.fail(
                field,
                num(value),
                format!(
                    "at a draft of {} m the hull's own propeller and rudders do not fit ({}); give a deeper \
                     loading or set those fields too",
                    short(t),
                    misfits.join(", ")
                ),
            );
        }
        if v.is_ok() {
            if let Err(e) = h.strip_ship_check() {
                v.fail("offsets_csv", format!("{} stations", h.offsets.stations.len()), e);
            }
        }
    }
}

/// Each of two rudders' area [m^2] by Det Norske Veritas' minimum for all rudders of a ship of
/// length `l`, beam `b` and draft `t` [m]: T L (1 + 25 (B/L)^2) / 100 (the 5415 by it: 6.3 m^2
/// each; a destroyer carries more, 15.4).
fn rule_rudder_area(l: f64, b: f64, t: f64) -> f64 {
    0.5 * t * l * (1.0 + 25.0 * (b / l) * (b / l)) / 100.0
}

/// The draft at which `offsets` displace `mass` [kg] in water of density `rho`, by bisection
/// between the lowest offset and the lowest station top.
fn draft_for_mass(offsets: &HullOffsets, mass: f64, rho: f64, bottom: f64, top: f64) -> Result<f64, (String, String)> {
    let vol = |t: f64| offsets.hydrostatics(t).map(|h| h.volume).unwrap_or(0.0);
    let v_max = vol(top);
    if !(mass.is_finite() && mass > 0.0 && mass <= rho * v_max) {
        return Err((
            "mass_kg".into(),
            format!(
                "must be from 0 to {} kg, what the hull displaces at the top of its offsets ({top} m)",
                num(rho * v_max)
            ),
        ));
    }
    let (mut lo, mut hi) = (bottom, top);
    for _ in 0..DRAFT_BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if rho * vol(mid) < mass {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The length, mass and rudder lever the maneuvering and surge models use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    /// L of the prime system (ch. 2.4) \[m\].
    pub length_m: f64,
    /// Displaced mass m \[kg\].
    pub mass_kg: f64,
    /// Rudder aft of the centre of gravity, x_p of eqs. 2.19, 2.26-2.27 \[m\].
    pub rudder_x_aft_m: f64,
}

/// Tables 5.1 and 5.5: L = 180 m, m = 7e6 kg, x_p = 75 m (`as_printed.table_5_ship`).
pub const TABLE_5_SHIP: RigidBody = RigidBody { length_m: 180.0, mass_kg: 7.0e6, rudder_x_aft_m: 75.0 };

impl ShipHull {
    /// The hull's length, mass and rudder lever, or with `printed.table_5_ship` the thesis'.
    pub fn rigid_body(&self, printed: &AsPrintedParams) -> RigidBody {
        if printed.table_5_ship {
            TABLE_5_SHIP
        } else {
            RigidBody { length_m: self.lpp_m, mass_kg: self.mass_kg, rudder_x_aft_m: self.rudder_x_aft_m }
        }
    }

    /// The strip-theory hull (thesis ch. 2.5.1-2.5.2). Errors name the stations the radiation
    /// solver cannot represent.
    pub fn strip_ship(&self) -> Result<Ship, String> {
        Ship::new(&self.offsets, self.draft_m, self.mass_props, self.bilge_keels, self.rho, crate::sea::waves::G)
    }

    /// Whether `strip_ship` builds, memoised by `table_key` (validation asks once per run, and
    /// building the strips maps every section).
    fn strip_ship_check(&self) -> Result<(), String> {
        type Memo = Mutex<Vec<(Arc<str>, Result<(), String>)>>;
        static CHECKED: OnceLock<Memo> = OnceLock::new();
        let memo = CHECKED.get_or_init(|| Mutex::new(Vec::new()));
        let key = self.table_key();
        if let Ok(m) = memo.lock() {
            if let Some((_, r)) = m.iter().find(|(k, _)| *k == key) {
                return r.clone();
            }
        }
        let r = self.strip_ship().map(|_| ());
        if let Ok(mut m) = memo.lock() {
            if m.len() >= MEMO_SIZE {
                drop(m.remove(0));
            }
            m.push((key, r.clone()));
        }
        r
    }

    /// What makes the RAO table: every input of `strip_ship`, as text (the cache's key).
    pub fn table_key(&self) -> Arc<str> {
        self.table_key.clone()
    }

    fn key_text(&self) -> String {
        let bk = self.bilge_keels.map(|b| (b.length_m.to_bits(), b.breadth_m.to_bits()));
        let mp = &self.mass_props;
        let geometry = if self.name == "custom" { format!("{:?}", self.offsets) } else { self.name.clone() };
        format!(
            "{geometry}|{:x}|{:x}|{:x}|{:x}|{:x}|{bk:?}|{:x}",
            self.draft_m.to_bits(),
            mp.kg_m.to_bits(),
            mp.kxx_m.to_bits(),
            mp.kyy_m.to_bits(),
            mp.kzz_m.to_bits(),
            self.rho.to_bits()
        )
    }
}

/// The embedded hulls as strip theory sees them (the comparisons with published results).
impl Ship {
    /// An embedded hull (`ship_hull`: "dtmb5415", "wigley") at its own design loading in water
    /// of 1025 kg/m^3.
    pub fn embedded(name: &str) -> Ship {
        crate::ship::hull::HullSpec { name: name.into(), ..Default::default() }
            .resolve(1025.0)
            .map_err(|(f, e)| format!("{f}: {e}"))
            .and_then(|h| h.strip_ship())
            .expect("the embedded hulls are valid")
    }

    /// The DTMB 5415 at its design draft 6.15 m with the SIMMAN 2014 mass properties and bilge
    /// keels (`ship_hull`).
    pub fn dtmb5415() -> Ship {
        Ship::embedded("dtmb5415")
    }

    /// The Wigley hull of [`HullOffsets::wigley`] (L 100 m, B 10 m, T 6.25 m) at its draft
    /// (`ship_hull`).
    pub fn wigley() -> Ship {
        Ship::embedded("wigley")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::DTMB5415_OFFSETS;
    use crate::numerics::complex::cabs;
    use crate::scenario::Scenario;

    fn resolve(spec: &HullSpec) -> Result<ShipHull, (String, String)> {
        spec.resolve(1025.0)
    }

    /// The memo gives what resolving afresh gives, and a changed spec or density is resolved anew
    /// (never a remembered hull of another spec).
    #[test]
    fn memoised_resolve_is_the_fresh_one() {
        let spec = HullSpec::default();
        let fresh = spec.resolve_uncached(1025.0).unwrap();
        assert_eq!(resolve(&spec).unwrap(), fresh);
        assert_eq!(resolve(&spec).unwrap(), fresh);
        let mut deeper = spec.clone();
        deeper.hub_above_base_m = Some(1.0);
        assert_eq!(resolve(&deeper).unwrap(), deeper.resolve_uncached(1025.0).unwrap());
        assert_ne!(resolve(&deeper).unwrap().hub_depth_m, fresh.hub_depth_m);
        assert_eq!(spec.resolve(1000.0).unwrap(), spec.resolve_uncached(1000.0).unwrap());
        assert_ne!(spec.resolve(1000.0).unwrap().mass_kg, fresh.mass_kg);
        assert_eq!(fresh.strip_ship_check(), Ok(()));
    }

    /// The default hull is the 5415 at 6.15 m: Lpp 142 m, 8.6e6 kg (published 8424 m^3, this
    /// mesh 8386.5 m^3 to 0.5 %), the propellers 62 m aft of G (8.3 m forward of the AP) and
    /// 6.0 m deep, the rudder 67 m aft of G.
    #[test]
    fn the_default_hull_is_the_5415_at_its_design_draft() {
        let h = resolve(&HullSpec::default()).unwrap();
        assert_eq!(h.lpp_m, 142.0);
        assert!((h.hydrostatics.volume - 8386.5).abs() < 0.005 * 8386.5, "{}", h.hydrostatics.volume);
        assert!((h.mass_kg / 8.6e6 - 1.0).abs() < 0.005, "{}", h.mass_kg);
        assert!((h.prop_x_aft_m - 62.0).abs() < 0.1, "{}", h.prop_x_aft_m);
        assert!((h.hub_depth_m - 6.0).abs() < 1e-12 && (h.rudder_x_aft_m - 67.2).abs() < 0.1);
        // Table 2.3's (X_udot - m)' at this length: m - X_udot = 9.5e6 kg, the mass plus 10 %.
        let m11 = 646.9e-5 * 0.5 * 1025.0 * 142.0 * 142.0 * 142.0;
        assert!((m11 / h.mass_kg - 1.1).abs() < 0.02, "{}", m11 / h.mass_kg);
    }

    /// A custom hull with the 5415's own offsets and loading gives the embedded hull's RAOs bit
    /// for bit; the scenario's RAO table at a grid point is strip theory's response there, the
    /// numbers `aes-sim rao --hull` prints (it builds the same `ShipHull::strip_ship`).
    #[test]
    fn a_custom_hull_and_the_rao_command_give_the_runs_raos() {
        let custom = HullSpec {
            name: "custom".into(),
            offsets_csv: DTMB5415_OFFSETS.into(),
            draft_m: Some(6.15),
            kg_m: Some(7.555),
            kxx_m: Some(0.37 * 19.06),
            kyy_m: Some(0.25 * 142.0),
            kzz_m: Some(0.25 * 142.0),
            bilge_keels: Some(BilgeKeels { length_m: 0.25 * 142.0, breadth_m: 0.6 }),
            ..Default::default()
        };
        let (a, b) = (resolve(&custom).unwrap().strip_ship().unwrap(), Ship::dtmb5415());
        let rad = a.radiation_table(&crate::sea::seakeeping::strip::default_omega_grid());
        let rad_b = b.radiation_table(&crate::sea::seakeeping::strip::default_omega_grid());
        let mut sc = Scenario::default();
        sc.ship.hull = custom;
        let table = sc.rao_table().unwrap();
        let grid = sc.seakeeping.grid;
        let (w, u, beta) = (grid.omegas()[17], grid.speeds()[4], grid.headings()[9]);
        let ra = crate::sea::seakeeping::motions::response(&a, &rad, w, u, beta, grid.roll_wave_amplitude_m);
        let rb = crate::sea::seakeeping::motions::response(&b, &rad_b, w, u, beta, grid.roll_wave_amplitude_m);
        assert_eq!(format!("{ra:?}"), format!("{rb:?}"));
        let t = table.interpolate(w, u, beta);
        for (x, y) in [(t.heave, ra.heave), (t.pitch, ra.pitch), (t.roll, ra.roll)] {
            assert!(cabs(x - y) <= 1e-12 * cabs(y).max(1e-9), "{x} {y}");
        }
    }

    /// A mass instead of a draft: the 5415 floats at Table 5.1's 7e6 kg with rho V = m to 1e-9.
    #[test]
    fn the_draft_of_a_given_mass() {
        let h = resolve(&HullSpec { mass_kg: Some(7.0e6), ..Default::default() }).unwrap();
        assert!((h.mass_kg / 7.0e6 - 1.0).abs() < 1e-9, "{}", h.mass_kg);
        assert!(h.draft_m > 5.0 && h.draft_m < 6.15, "{}", h.draft_m);
    }

    /// Bad hulls name the field, the value and what is allowed; nothing panics.
    #[test]
    fn bad_hulls_name_the_field() {
        let check = |spec: HullSpec| {
            let mut v = Validator::new();
            v.section("ship.hull", |v| spec.validate(v, 1025.0));
            v.finish().unwrap_err().to_string()
        };
        let e = check(HullSpec { name: "titanic".into(), ..Default::default() });
        assert!(e.contains("ship.hull.name = titanic") && e.contains("dtmb5415, wigley, custom"), "{e}");
        let e = check(HullSpec { name: "custom".into(), ..Default::default() });
        assert!(e.contains("ship.hull.offsets_csv") && e.contains("needs its offsets"), "{e}");
        let bad = DTMB5415_OFFSETS.replacen("0,0.0000,-2.750,0.000", "0,0.0000,-2.750,abc", 1);
        let e = check(HullSpec { name: "custom".into(), offsets_csv: bad, ..Default::default() });
        assert!(
            e.contains("ship.hull.offsets_csv") && e.contains("'abc' is not a number") && e.contains("line "),
            "{e}"
        );
        let e = check(HullSpec {
            name: "custom".into(),
            offsets_csv: DTMB5415_OFFSETS.into(),
            draft_m: Some(6.15),
            ..Default::default()
        });
        assert!(e.contains("ship.hull.kg_m"), "{e}");
        // Both missing values at once, not one per try.
        let e = check(HullSpec { name: "custom".into(), offsets_csv: DTMB5415_OFFSETS.into(), ..Default::default() });
        assert!(e.contains("ship.hull.draft_m") && e.contains("ship.hull.kg_m"), "{e}");
        let e = check(HullSpec { draft_m: Some(40.0), ..Default::default() });
        assert!(e.contains("ship.hull.draft_m = 40") && e.contains("up to 9.225"), "{e}");
        let e = check(HullSpec { draft_m: Some(6.15), mass_kg: Some(7e6), ..Default::default() });
        assert!(e.contains("ship.hull.mass_kg") && e.contains("not both"), "{e}");
        let e = check(HullSpec { mass_kg: Some(1e12), ..Default::default() });
        assert!(e.contains("ship.hull.mass_kg") && e.contains("must be from 0 to"), "{e}");
        // KG above the metacentre: the strip-theory hull refuses it and says why.
        let e = check(HullSpec { kg_m: Some(12.0), ..Default::default() });
        assert!(e.contains("GM_T") && e.contains("unstable"), "{e}");
        let e = check(HullSpec { shaft_y_m: Some([30.0, -5.0]), ..Default::default() });
        assert!(e.contains("ship.hull.shaft_y_m.0 = 30"), "{e}");
    }

    /// A draft of the user's that the hull's own propeller and rudders no longer fit is blamed on
    /// the draft (one error, naming the parts); a draft at or below the keel is refused as such;
    /// parts the user set with the shallow draft are checked as themselves.
    #[test]
    fn a_shallow_draft_is_blamed_on_the_draft() {
        let check = |spec: HullSpec| {
            let mut v = Validator::new();
            v.section("ship.hull", |v| spec.validate(v, 1025.0));
            v.finish().map_err(|e| e.to_string())
        };
        let e = check(HullSpec { draft_m: Some(0.0), ..Default::default() }).unwrap_err();
        assert!(e.starts_with("ship.hull.draft_m = 0: must be above the baseline"), "{e}");
        let e = check(HullSpec { draft_m: Some(-1.0), ..Default::default() }).unwrap_err();
        assert!(e.starts_with("ship.hull.draft_m = -1: must be above the baseline"), "{e}");
        let e = check(HullSpec { draft_m: Some(0.5), ..Default::default() }).unwrap_err();
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(
            e.starts_with(
                "ship.hull.draft_m = 0.5: at a draft of 0.5 m the hull's own propeller and rudders do not fit"
            ) && e.contains("rudder_area_m2 = 15.4 outside 0.071 to 7.1")
                && e.contains("rudder_span_m = 4 outside 0.05 to 1"),
            "{e}"
        );
        let e = check(HullSpec { draft_m: Some(0.5), rudder_span_m: Some(8.0), ..Default::default() }).unwrap_err();
        assert!(e.contains("ship.hull.rudder_span_m = 8: must be a number from 0.05 to 1"), "{e}");
        check(HullSpec { draft_m: Some(2.5), ..Default::default() }).unwrap();
    }

    /// `as_printed.table_5_ship` gives Tables 5.1/5.5's L, m and x_p; off, the hull's.
    #[test]
    fn the_rigid_body_of_the_hull_or_of_table_5() {
        let h = resolve(&HullSpec::default()).unwrap();
        let on = AsPrintedParams { table_5_ship: true, ..Default::default() };
        assert_eq!(h.rigid_body(&on), TABLE_5_SHIP);
        let off = h.rigid_body(&AsPrintedParams::default());
        assert_eq!((off.length_m, off.mass_kg, off.rudder_x_aft_m), (142.0, h.mass_kg, h.rudder_x_aft_m));
    }
}

#[cfg(test)]
mod approximated_tests {
    use super::*;

    /// Sections no Lewis or bulb form takes are kept as the nearest Lewis form and named with the
    /// reason (the hull panel and `HullSheet` list them): a deep spike (B/T 0.12, sigma 0.5) and a
    /// wide flat V (B/T 16) are; boxes are not (the bulb form takes them); the embedded hulls need
    /// no approximation at any station.
    #[test]
    fn stations_the_maps_cannot_take_are_named() {
        let hull = |rows: &[(f64, f64)], t: f64| {
            let mut csv = String::from("station_index,x_m,z_m,half_breadth_m\n");
            for i in 0..11 {
                for (z, hb) in rows {
                    csv.push_str(&format!("{i},{},{z},{hb}\n", 10.0 * i as f64));
                }
            }
            let spec = HullSpec {
                name: "custom".into(),
                offsets_csv: csv,
                draft_m: Some(t),
                kg_m: Some(0.1 * t),
                ..Default::default()
            };
            spec.resolve(1025.0).unwrap().strip_ship().unwrap().approximated
        };
        let spike = hull(&[(0.0, 0.0), (8.0, 0.5), (12.0, 0.75)], 8.0);
        assert_eq!(spike.len(), 11);
        assert!(spike[3].0 == 30.0 && spike[3].1.contains("area coefficient 0.500 at B/T = 0.12"), "{spike:?}");
        assert_eq!(hull(&[(0.0, 0.0), (1.0, 8.0), (2.0, 16.0)], 1.0).len(), 11);
        assert!(hull(&[(0.0, 0.0), (0.001, 8.0), (4.0, 8.0)], 2.0).is_empty());
        assert!(hull(&[(0.0, 0.0), (0.001, 1.0), (12.0, 1.0)], 8.0).is_empty());
        for name in ["dtmb5415", "wigley"] {
            assert!(Ship::embedded(name).approximated.is_empty(), "{name}");
        }
    }
}
