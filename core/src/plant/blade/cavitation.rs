//! Cavitation of a propeller's blade sections (thesis ch. 3.2.2): each section's -Cp_min from its
//! own shape (a panel solution of its a = 0.8 + NACA 66 section) against the local cavitation
//! number with the blade at 12 o'clock, which radii cavitate, the hub depth h/R at which the first
//! section does, and the shaft speed of inception at a fixed advance ratio.
//!
//! Steady and two-dimensional: no blade-rate pressure fluctuation in the wake, no viscous effect on
//! inception (a real section incepts at somewhat less than -Cp_min), no tip-vortex cavitation.

use super::geometry::BladeGeometry;
use super::panel::{Bucket, MinPressure, Panels, PANELS_PER_SIDE};
use super::section_shape::section;

/// The water and the air above it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Water {
    /// Atmospheric pressure at the surface \[Pa\]: 101 325 (ISO 2533 standard atmosphere).
    pub p_atm_pa: f64,
    /// Vapour pressure \[Pa\]: 1 705 for sea water at 15 deg C (ITTC 7.5-02-01-03, 2011).
    pub p_vapour_pa: f64,
    /// Density \[kg/m^3\]: 1 025.9 for sea water at 15 deg C, salinity 35 g/kg (same source).
    pub rho_kg_m3: f64,
    /// Gravity \[m/s^2\]: 9.80665 (standard).
    pub g_m_s2: f64,
}

impl Default for Water {
    fn default() -> Self {
        Water { p_atm_pa: 101_325.0, p_vapour_pa: 1_705.0, rho_kg_m3: 1_025.9, g_m_s2: 9.80665 }
    }
}

impl Water {
    /// The water of a lifting-line flow: its density, with the vapour pressure at 15 deg C
    /// (1 705 Pa for fresh and sea water alike to the precision of ITTC 7.5-02-01-03's table).
    pub fn of(flow: &super::Flow) -> Water {
        Water { rho_kg_m3: flow.density_kg_m3, ..Water::default() }
    }
}

/// The flow at one blade section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionFlow {
    /// Radius over tip radius \[-\].
    pub r_r: f64,
    /// Chord \[m\].
    pub chord_m: f64,
    /// Angle of attack from the nose-tail line \[rad\], positive loading the back.
    pub alpha_rad: f64,
    /// Total inflow speed V* at the section \[m/s\] (axial and tangential, induced included).
    pub v_star_m_s: f64,
}

impl From<&super::SectionLoad> for SectionFlow {
    /// The lifting line's load at a section, as the cavitation check reads it: the 2D section at
    /// the angle where it meets the flow as the blade does (the same distance from its ideal angle
    /// as the blade from Morgan's corrected one; the bucket is about the ideal angle).
    fn from(l: &super::SectionLoad) -> SectionFlow {
        SectionFlow { r_r: l.r_r, chord_m: l.chord_m, alpha_rad: l.alpha_2d_rad, v_star_m_s: l.v_star_m_s }
    }
}

/// Local cavitation number of a section at radius `r_m` \[m\] with the blade at 12 o'clock and
/// the hub `hub_depth_m` \[m\] below the surface: (p_atm + rho g (h - r) - p_v) / (0.5 rho V*^2).
pub fn sigma_local(w: &Water, hub_depth_m: f64, r_m: f64, v_star_m_s: f64) -> f64 {
    (w.p_atm_pa + w.rho_kg_m3 * w.g_m_s2 * (hub_depth_m - r_m) - w.p_vapour_pa)
        / (0.5 * w.rho_kg_m3 * v_star_m_s * v_star_m_s)
}

/// One section's state: its -Cp_min on each side, sigma, and the margin sigma - (-Cp_min).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionCavitation {
    /// Radius over tip radius \[-\].
    pub r_r: f64,
    /// Local cavitation number \[-\].
    pub sigma: f64,
    /// -Cp_min on the back and the face \[-\].
    pub min_cp: MinPressure,
    /// sigma - max(-Cp_min): negative where the section cavitates \[-\].
    pub margin: f64,
    /// Whether a 2D section describes this radius (inside the outermost row with a chord);
    /// outboard of it the tip vortex rules, and the margin only carries the tip's angles.
    pub sectioned: bool,
    /// The bucket at this sigma: the angles of attack \[rad\] between which neither side
    /// cavitates (face cavitation below the first, back cavitation above the second); None when
    /// sigma is below the bucket's bottom.
    pub bucket_rad: Option<(f64, f64)>,
}

impl SectionCavitation {
    /// Whether the section cavitates.
    pub fn cavitates(&self) -> bool {
        self.margin < 0.0
    }
}

/// The cavitation buckets of a propeller's sections, built once (a panel solution per row).
#[derive(Debug, Clone)]
pub struct PropellerBuckets {
    /// r/R of each bucket (the rows with a chord; a zero tip chord has no section).
    pub r_r: Vec<f64>,
    /// The buckets, root to tip.
    pub buckets: Vec<Bucket>,
    /// Tip radius \[m\].
    pub radius_m: f64,
}

impl PropellerBuckets {
    /// The buckets of `geometry` at diameter `diameter_m` \[m\].
    pub fn new(geometry: &BladeGeometry, diameter_m: f64) -> Result<PropellerBuckets, String> {
        geometry.check()?;
        if !(diameter_m.is_finite() && diameter_m > 0.0) {
            return Err(format!("diameter_m: {diameter_m} must be a positive length"));
        }
        let mut r_r = Vec::new();
        let mut buckets = Vec::new();
        for (i, row) in geometry.rows.iter().enumerate().filter(|(_, r)| r.c_d > 0.0) {
            let s = section(row.f0_c, row.t0_c, PANELS_PER_SIDE);
            let p = Panels::new(&s.points, s.nose).map_err(|e| format!("row {} (r/R {}): {e}", i + 1, row.r_r))?;
            r_r.push(row.r_r);
            buckets.push(Bucket::new(&p));
        }
        Ok(PropellerBuckets { r_r, buckets, radius_m: 0.5 * diameter_m })
    }

    /// The buckets of `geometry` at `diameter_m`, remembered (a run's summary, its Monte Carlo
    /// trials and the page's repeated runs build them once: about 20 ms a section).
    pub fn cached(geometry: &BladeGeometry, diameter_m: f64) -> Result<std::sync::Arc<PropellerBuckets>, String> {
        use std::sync::{Arc, Mutex, OnceLock};
        type Cache = Mutex<Vec<((BladeGeometry, u64), Arc<PropellerBuckets>)>>;
        static CACHE: OnceLock<Cache> = OnceLock::new();
        const MAX: usize = 8;
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        let key = (geometry.clone(), diameter_m.to_bits());
        if let Ok(c) = cache.lock() {
            if let Some((_, b)) = c.iter().find(|(k, _)| *k == key) {
                return Ok(b.clone());
            }
        }
        let b = Arc::new(PropellerBuckets::new(geometry, diameter_m)?);
        if let Ok(mut c) = cache.lock() {
            if c.len() >= MAX {
                c.remove(0);
            }
            c.push((key, b.clone()));
        }
        Ok(b)
    }

    /// The bucket nearest `r_r` (the flows are given at the table's radii).
    fn bucket(&self, r_r: f64) -> &Bucket {
        let k = (0..self.r_r.len())
            .min_by(|&a, &b| (self.r_r[a] - r_r).abs().total_cmp(&(self.r_r[b] - r_r).abs()))
            .unwrap_or(0);
        &self.buckets[k]
    }

    /// Whether a 2D section describes the flow at `r_r`: inside the outermost row with a chord.
    /// Outboard of it the tip vortex rules (it cavitates first, which a section cannot tell), so
    /// the onset and inception are taken from the sections inside it.
    fn sectioned(&self, r_r: f64) -> bool {
        r_r <= self.r_r.last().copied().unwrap_or(0.0) + 1e-9
    }

    /// Each section's state with the hub `hub_depth_m` \[m\] deep.
    pub fn sections(&self, w: &Water, flows: &[SectionFlow], hub_depth_m: f64) -> Vec<SectionCavitation> {
        flows
            .iter()
            .map(|f| {
                let b = self.bucket(f.r_r);
                let sigma = sigma_local(w, hub_depth_m, f.r_r * self.radius_m, f.v_star_m_s);
                let min_cp = b.at(f.alpha_rad);
                SectionCavitation {
                    r_r: f.r_r,
                    sigma,
                    min_cp,
                    margin: sigma - min_cp.both(),
                    sectioned: self.sectioned(f.r_r),
                    bucket_rad: bucket_edges(b, sigma),
                }
            })
            .collect()
    }

    /// The hub depth over tip radius h/R at which the first section at 12 o'clock reaches
    /// -Cp_min = sigma_local: h = r + (0.5 rho V*^2 (-Cp_min) - p_atm + p_v) / (rho g), the largest
    /// over the sections. Shallower, a section cavitates; a value below 1 says the blade does not
    /// cavitate while the disk is under water.
    pub fn onset_h_over_r(&self, w: &Water, flows: &[SectionFlow]) -> f64 {
        flows
            .iter()
            .filter(|f| self.sectioned(f.r_r))
            .map(|f| {
                let cp = self.bucket(f.r_r).at(f.alpha_rad).both();
                let q = 0.5 * w.rho_kg_m3 * f.v_star_m_s * f.v_star_m_s;
                (f.r_r * self.radius_m + (q * cp - w.p_atm_pa + w.p_vapour_pa) / (w.rho_kg_m3 * w.g_m_s2))
                    / self.radius_m
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// The shaft speed \[rev/s\] at which the first section cavitates, the hub `hub_depth_m` \[m\]
    /// deep, along a line of fixed advance ratio: `flows` were found at `n_ref_hz`, and at a fixed
    /// J every V* scales with n while the angles stay. Per section
    /// n = n_ref sqrt((p_atm + rho g (h - r) - p_v) / (0.5 rho V*_ref^2 (-Cp_min))); the least.
    /// None when no section has suction (-Cp_min <= 0 everywhere).
    pub fn inception_hz(&self, w: &Water, flows: &[SectionFlow], hub_depth_m: f64, n_ref_hz: f64) -> Option<f64> {
        flows
            .iter()
            .filter(|f| self.sectioned(f.r_r))
            .filter_map(|f| {
                let cp = self.bucket(f.r_r).at(f.alpha_rad).both();
                let sigma_ref = sigma_local(w, hub_depth_m, f.r_r * self.radius_m, f.v_star_m_s);
                (cp > 0.0 && sigma_ref > 0.0).then(|| n_ref_hz * (sigma_ref / cp).sqrt())
            })
            .min_by(f64::total_cmp)
    }
}

/// The cavitation check of one open-water point: which radii cavitate with the hub at a depth.
#[derive(Debug, Clone, PartialEq)]
pub struct PointCavitation {
    /// Advance ratio J and shaft speed n \[rev/s\] of the point.
    pub j: f64,
    pub rev_per_s: f64,
    /// Hub depth below the calm surface \[m\].
    pub hub_depth_m: f64,
    /// Each control point of the lifting line, root to tip.
    pub sections: Vec<SectionCavitation>,
    /// The sectioned radii r/R that cavitate (the tip's points are not among them).
    pub cavitating_r_r: Vec<f64>,
    /// The least margin over the sectioned radii \[-\]: negative when one cavitates.
    pub worst_margin: f64,
    /// The hub depth over tip radius h/R at which the first sectioned radius cavitates \[-\].
    pub onset_h_over_r: f64,
}

/// The cavitation check of the lifting line's `analysis` (at `rev_per_s` \[rev/s\]) on `buckets`,
/// the blade at 12 o'clock and the hub `hub_depth_m` \[m\] deep, in `water`.
pub fn check_point(
    buckets: &PropellerBuckets,
    water: &Water,
    analysis: &super::Analysis,
    rev_per_s: f64,
    hub_depth_m: f64,
) -> PointCavitation {
    let flows: Vec<SectionFlow> = analysis.sections.iter().map(SectionFlow::from).collect();
    let sections = buckets.sections(water, &flows, hub_depth_m);
    let inside = || sections.iter().filter(|c| c.sectioned);
    PointCavitation {
        j: analysis.j,
        rev_per_s,
        hub_depth_m,
        cavitating_r_r: inside().filter(|c| c.cavitates()).map(|c| c.r_r).collect(),
        worst_margin: inside().map(|c| c.margin).fold(f64::INFINITY, f64::min),
        onset_h_over_r: buckets.onset_h_over_r(water, &flows),
        sections,
    }
}

/// The angles \[rad\] between which -Cp_min on both sides stays below `sigma`, walking out from
/// the bucket's bottom; None when the bottom is above sigma.
fn bucket_edges(b: &Bucket, sigma: f64) -> Option<(f64, f64)> {
    let (bottom, cp) = b.bottom();
    if cp > sigma {
        return None;
    }
    let k0 = ((bottom - b.alpha0) / b.step).round() as usize;
    let n = b.suction.len();
    let both = |k: usize| b.suction[k].max(b.pressure[k]);
    let mut lo = k0;
    while lo > 0 && both(lo - 1) <= sigma {
        lo -= 1;
    }
    let mut hi = k0;
    while hi + 1 < n && both(hi + 1) <= sigma {
        hi += 1;
    }
    Some((b.alpha0 + b.step * lo as f64, b.alpha0 + b.step * hi as f64))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::blade::section_shape::{a08_camber_per_cli, a08_ideal_angle_per_cli};

    const P4119: &str = include_str!("../../../data/dtmb4119_geometry.csv");

    /// sigma by hand: hub 6 m deep, r 1 m, V* 20 m/s:
    /// (101325 + 1025.9 * 9.80665 * 5 - 1705) / (0.5 * 1025.9 * 400) = 149923.2 / 205180 = 0.730691.
    #[test]
    fn local_cavitation_number_by_hand() {
        let s = sigma_local(&Water::default(), 6.0, 1.0, 20.0);
        assert!((s - 0.730_691).abs() < 1e-6, "{s}");
    }

    /// DTMB 4119 scaled to D = 4.5 m (the thesis' propeller diameter), 180 rpm, J = 0.833 (its
    /// design point), hub 6 m deep (the thesis' h0). Stand-in inflow, labelled as such until the
    /// lifting line's section loads replace it: V* = sqrt(V_A^2 + (2 pi n r)^2) without induced
    /// velocities, and each section at its own mean line's ideal angle plus 1 deg (a section a
    /// little above its design lift). Measured: sigma falls from 1.53 at r/R 0.2 to 0.15 at 0.95,
    /// -Cp_min (back) is 0.53 at 0.5 and 1.56 at 0.95, so r/R 0.5 to 0.95 cavitate (margin -0.02
    /// at 0.5, -1.40 at 0.95) and 0.2 to 0.4 do not (+0.74 to +0.11); onset at h/R 58 (deep: this
    /// inflow has no induced velocity, so V* and the angles are too high); inception at 56.6 rpm
    /// with the hub 6 m deep.
    #[test]
    fn dtmb_4119_names_the_radii_that_cavitate() {
        let g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        let d = 4.5;
        let b = PropellerBuckets::new(&g, d).unwrap();
        let n = 3.0;
        let va = 0.833 * n * d;
        let flows: Vec<SectionFlow> = g
            .rows
            .iter()
            .filter(|r| r.c_d > 0.0)
            .map(|r| {
                let vt = 2.0 * std::f64::consts::PI * n * r.r_r * 0.5 * d;
                let ai = r.f0_c / a08_camber_per_cli() * a08_ideal_angle_per_cli();
                SectionFlow {
                    r_r: r.r_r,
                    chord_m: r.c_d * d,
                    alpha_rad: ai + 1f64.to_radians(),
                    v_star_m_s: (va * va + vt * vt).sqrt(),
                }
            })
            .collect();
        let w = Water::default();
        let s = b.sections(&w, &flows, 6.0);
        let cavitating: Vec<f64> = s.iter().filter(|c| c.cavitates()).map(|c| c.r_r).collect();
        assert_eq!(cavitating, [0.5, 0.6, 0.7, 0.8, 0.9, 0.95]);
        // The bucket narrows outward as sigma falls; it is gone (None) where the bottom exceeds sigma.
        let width = |c: &SectionCavitation| c.bucket_rad.map_or(0.0, |(lo, hi)| hi - lo);
        assert!(s.windows(2).all(|p| width(&p[1]) <= width(&p[0])));
        assert!(s[0].bucket_rad.is_some() && s[8].bucket_rad.is_none());
        let onset = b.onset_h_over_r(&w, &flows);
        assert!((onset - 58.3).abs() < 0.5, "onset h/R {onset}");
        let inc = b.inception_hz(&w, &flows, 6.0, n).unwrap();
        assert!((inc * 60.0 - 56.6).abs() < 0.5, "inception {} rpm", inc * 60.0);
        // At the onset depth the worst margin is zero; deeper none cavitates, shallower some do.
        let worst = |h: f64| b.sections(&w, &flows, h).iter().map(|c| c.margin).fold(f64::INFINITY, f64::min);
        assert!(worst(onset * 0.5 * d).abs() < 1e-9, "margin at onset {}", worst(onset * 0.5 * d));
        assert!(worst(onset * 0.5 * d + 0.1) > 0.0 && worst(onset * 0.5 * d - 0.1) < 0.0);
        // At the inception speed (same J) the worst margin is zero.
        let scaled: Vec<SectionFlow> =
            flows.iter().map(|f| SectionFlow { v_star_m_s: f.v_star_m_s * inc / n, ..*f }).collect();
        let at_inc = b.sections(&w, &scaled, 6.0).iter().map(|c| c.margin).fold(f64::INFINITY, f64::min);
        assert!(at_inc.abs() < 1e-9, "margin at inception {at_inc}");
    }

    /// The same propeller and point with the lifting line's own section loads (branch prop54's
    /// `analyse`, induced velocities and Morgan's 1968 corrections included, each section at its
    /// equivalent 2D angle; its KT is still 10 % high at this J). Measured: r/R 0.20 to 0.57 keep a
    /// margin (+0.71 to +0.05), r/R 0.63 to 0.94 cavitate lightly (-0.02 to -0.07), and the three
    /// outermost control points (r/R 0.970, 0.989, 0.999: margins -0.15, -1.7 and -29) carry the
    /// tip's large angles onto the r/R 0.95 section's bucket. A 2D section does not describe the
    /// tip (its vortex cavitates first), so the onset is taken from the sectioned radii
    /// (r/R <= 0.95), h/R 5.22.
    #[test]
    fn dtmb_4119_with_the_lifting_lines_loads() {
        let g = BladeGeometry::from_csv(P4119, 3, 0.2).unwrap();
        let d = 4.5;
        let a = crate::plant::blade::analyse(&g, 0.833, &crate::plant::blade::Flow::sea_water(d, 3.0)).unwrap();
        let flows: Vec<SectionFlow> = a.sections.iter().map(SectionFlow::from).collect();
        let b = PropellerBuckets::new(&g, d).unwrap();
        let w = Water::default();
        let s = b.sections(&w, &flows, 6.0);
        assert!(!s.is_empty() && s.iter().all(|c| c.margin.is_finite()));
        let onset = b.onset_h_over_r(&w, &flows);
        // Measured: h/R 5.22 (hub 11.7 m): shallower than that the sections from r/R 0.63 out
        // cavitate, as they do at 6 m; at the onset depth the worst sectioned margin is zero.
        assert!(onset.is_finite() && onset > 6.0 / (0.5 * d), "onset h/R {onset}");
        let inside: Vec<SectionFlow> = flows.iter().copied().filter(|f| f.r_r <= 0.95 + 1e-9).collect();
        let at_onset = b.sections(&w, &inside, onset * 0.5 * d).iter().map(|c| c.margin).fold(f64::INFINITY, f64::min);
        assert!(at_onset.abs() < 1e-9, "worst margin at the onset depth {at_onset}");
        for c in &s {
            if c.r_r < 0.6 {
                assert!(c.margin > 0.0, "r/R {} margin {}", c.r_r, c.margin);
            } else if c.r_r <= 0.95 {
                assert!((-0.1..0.0).contains(&c.margin), "r/R {} margin {}", c.r_r, c.margin);
            }
        }
    }
}
