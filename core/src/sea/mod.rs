//! The sea and the ship in it (thesis ch. 2.5): waves and their spectra, strip-theory seakeeping
//! and its tables, the cache of RAO tables, and the seakeeping criteria of operability.

pub mod conditioning;
pub mod operability;
pub mod rao_cache;
pub mod seakeeping;
pub mod waves;
