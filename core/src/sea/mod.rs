//! The sea and the ship in it (thesis ch. 2.5): waves and their spectra, strip-theory seakeeping
//! and its tables, and the cache of RAO tables.

pub mod rao_cache;
pub mod seakeeping;
pub mod waves;
