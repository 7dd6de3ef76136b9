//! The ship (thesis ch. 2.3-2.4): its hull (loading, appendages, the strip-theory ship built from
//! `geometry`'s offsets) and the cache of its RAO tables, the surge model's resistance, the
//! Abkowitz maneuvering model and the rudder.

pub mod crossflow;
pub mod hull;
pub mod hull_forces;
pub mod maneuvering;
pub mod rao_cache;
pub mod rudder;
pub mod sectional;
/// The hull geometry lives below both ship and sea (each reads it); the path other crates use.
pub use crate::geometry as sections;
pub mod surge;
