//! Seakeeping in the frequency domain (thesis ch. 2.5.1-2.5.3, Appendix A): conformal maps of the
//! hull sections, 2-D radiation by multipoles, Salvesen-Tuck-Faltinsen strip theory, roll damping,
//! second-order mean forces, and the tables the time-domain simulation interpolates.

pub mod aft_end;
/// Moved to numerics (control reads it too); the path other crates use.
pub use crate::numerics::complex;
pub mod conformal;
pub mod motions;
pub mod params;
pub mod radiation;
pub mod reflection;
pub mod roll_damping;
pub mod strip;
pub mod tables;
pub mod wigley_check;
