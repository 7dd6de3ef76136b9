//! A propeller from its blade geometry (thesis ch. 3.2 and 6.1): the radial table of a blade, and
//! (beside it) the analyses that turn a geometry into open-water thrust, torque and cavitation.

pub mod cavitation;
pub mod geometry;
pub mod panel;
pub mod section_shape;

pub use geometry::{BladeGeometry, MeanLine, Row, Thickness};
