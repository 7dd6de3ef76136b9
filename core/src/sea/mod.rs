//! The sea and the ship in it (thesis ch. 2.5): waves and their spectra, strip-theory seakeeping
//! and its tables, and the seakeeping criteria of operability. It reads the hull's offsets from
//! `geometry`; the hull assembled for it, and the cache of its tables, are `ship`'s.

pub mod conditioning;
pub mod operability;
pub mod seakeeping;
pub mod waves;
