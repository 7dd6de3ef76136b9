//! A propeller from its blade geometry (thesis ch. 3.2 and 6.1): the radial table of a blade, and
//! (beside it) the analyses that turn a geometry into open-water thrust, torque and cavitation.
//!
//! The open-water analysis is a moderately loaded lifting line ([`lifting_line`]): helical
//! horseshoe vortices on the key blade and its Z-1 images, Wrench's induction factors
//! ([`induction`]), a hub image, section lift from the mean line ([`mean_line`], [`section_lift`],
//! [`lifting_surface`]) and a Reynolds-number-dependent section drag ([`friction`]).

pub mod cavitation;
pub mod friction;
pub mod geometry;
pub mod induction;
pub mod lifting_line;
pub mod lifting_surface;
pub mod mean_line;
pub mod panel;
pub mod section_lift;
pub mod section_shape;
pub mod vortex_lattice;

pub use geometry::{BladeGeometry, MeanLine, Row, Thickness};

use crate::checks::shorten;
use serde::{Deserialize, Serialize};

/// What the section Reynolds numbers need: the propeller's size, speed and water.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Flow {
    /// Propeller diameter D \[m\].
    pub diameter_m: f64,
    /// Shaft speed n \[rev/s\].
    pub rev_per_s: f64,
    /// Kinematic viscosity of the water nu \[m^2/s\].
    pub kinematic_viscosity_m2_s: f64,
    /// Density of the water rho \[kg/m^3\].
    pub density_kg_m3: f64,
}

impl Flow {
    /// Sea water at 15 degC (nu = 1.1892e-6 m^2/s, rho = 1026.0 kg/m^3, near the ITTC 2011 sea water table).
    pub fn sea_water(diameter_m: f64, rev_per_s: f64) -> Flow {
        Flow { diameter_m, rev_per_s, kinematic_viscosity_m2_s: 1.1892e-6, density_kg_m3: 1026.0 }
    }

    /// Fresh water at 15 degC (ITTC 2011 tables: nu = 1.1386e-6 m^2/s, rho = 999.1 kg/m^3), a model basin's.
    pub fn fresh_water(diameter_m: f64, rev_per_s: f64) -> Flow {
        Flow { diameter_m, rev_per_s, kinematic_viscosity_m2_s: 1.1386e-6, density_kg_m3: 999.1 }
    }

    /// Refuses a flow no test has, naming the field.
    pub fn check(&self) -> Result<(), String> {
        let fields = [
            ("diameter_m", self.diameter_m, 0.05, 20.0),
            ("rev_per_s", self.rev_per_s, 0.1, 200.0),
            ("kinematic_viscosity_m2_s", self.kinematic_viscosity_m2_s, 1e-7, 1e-4),
            ("density_kg_m3", self.density_kg_m3, 500.0, 2000.0),
        ];
        for (name, v, lo, hi) in fields {
            if !(v.is_finite() && (lo..=hi).contains(&v)) {
                return Err(format!("{name}: {} is outside {lo}..={hi}", shorten(&v.to_string())));
            }
        }
        Ok(())
    }
}

/// The advance ratios an analysis accepts \[-\]: from bollard pull (0) to well past zero thrust.
pub const ADVANCE_RATIO: std::ops::RangeInclusive<f64> = 0.0..=2.5;

/// Refuses an advance ratio outside [`ADVANCE_RATIO`], naming it.
pub fn check_advance_ratio(j: f64) -> Result<(), String> {
    if j.is_finite() && ADVANCE_RATIO.contains(&j) {
        return Ok(());
    }
    Err(format!("j: {} is outside {}..={}", shorten(&j.to_string()), ADVANCE_RATIO.start(), ADVANCE_RATIO.end()))
}

/// The loading of one control point of the key blade.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SectionLoad {
    /// Radius over tip radius r/R \[-\].
    pub r_r: f64,
    /// Chord c \[m\].
    pub chord_m: f64,
    /// Non-dimensional circulation G = Gamma / (pi D^2 n) \[-\] (Gamma over n D times the circumference of
    /// the tip circle; G is finite at bollard pull, where Gamma / (2 pi R V_s) is not).
    pub circulation: f64,
    /// Hydrodynamic pitch angle of the total inflow beta_i \[rad\].
    pub beta_i_rad: f64,
    /// Angle of attack from the section's nose-tail line (geometric pitch angle minus beta_i) \[rad\].
    pub alpha_rad: f64,
    /// The angle from the nose-tail line at which the section's own 2D shape meets the flow as the
    /// blade does: `alpha_rad` less the blade's ideal angle (Morgan's lifting-surface corrections)
    /// plus the section's own; the cavitation buckets are read at it \[rad\].
    #[serde(default)]
    pub alpha_2d_rad: f64,
    /// Total inflow speed at the section V* \[m/s\].
    pub v_star_m_s: f64,
    /// Section lift coefficient \[-\].
    pub cl: f64,
    /// Section drag coefficient \[-\].
    pub cd: f64,
    /// Chord Reynolds number V* c / nu \[-\].
    pub reynolds: f64,
}

/// The open-water point of a propeller at one advance ratio.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Analysis {
    /// Advance ratio J = V_A / (n D) \[-\].
    pub j: f64,
    /// Thrust coefficient KT = T / (rho n^2 D^4) \[-\]; negative past zero thrust.
    pub kt: f64,
    /// Torque coefficient KQ = Q / (rho n^2 D^5) \[-\].
    pub kq: f64,
    /// Open-water efficiency J KT / (2 pi KQ) \[-\]; 0 where KT or KQ is not positive.
    pub eta: f64,
    /// Whether the circulation and the wake pitch converged (to 1e-9 of the largest circulation).
    pub converged: bool,
    /// The control points, root to tip.
    pub sections: Vec<SectionLoad>,
}

/// The open-water point of `g` at advance ratio `j` (thesis ch. 3.2): a moderately loaded lifting line.
pub fn analyse(g: &BladeGeometry, j: f64, flow: &Flow) -> Result<Analysis, String> {
    lifting_line::LiftingLine::new(g, flow)?.solve(j)
}

/// The open-water curve of `g` at the advance ratios `js` (each point solved from the previous one's
/// circulation, so a curve costs less than its points one by one).
pub fn open_water(g: &BladeGeometry, js: &[f64], flow: &Flow) -> Result<Vec<Analysis>, String> {
    let ll = lifting_line::LiftingLine::new(g, flow)?;
    let mut out: Vec<Analysis> = Vec::with_capacity(js.len());
    for &j in js {
        let a = ll.solve_from(j, out.last())?;
        out.push(a);
    }
    Ok(out)
}
