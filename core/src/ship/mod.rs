//! The ship (thesis ch. 2.3-2.4): its hull (offsets, loading, appendages) and sections, the surge
//! model's resistance, the Abkowitz maneuvering model and the rudder.

pub mod crossflow;
pub mod hull;
pub mod hull_forces;
pub mod maneuvering;
pub mod rudder;
pub mod sectional;
pub mod sections;
pub mod surge;
