//! aes-core: the physics of the All Electric Ship simulator (Schmitt, MIT 2010).
//!
//! In folders named for the architecture (plant, ship, sea, control, scenario, sim, studies,
//! numerics, output), one module per physical subsystem, named after it; equation numbers are the
//! thesis' own.
//! Everything is SI inside; no I/O, no threads; the same scenario gives the same numbers on
//! every platform.

pub mod as_printed;
pub mod checks;
pub mod control;
pub mod geometry;
pub mod numerics;
pub mod output;
pub mod params;
pub mod plant;
pub mod scenario;
pub mod sea;
pub mod ship;
pub mod signals;
pub mod sim;
pub mod studies;

pub use scenario::Scenario;
pub use sim::{run, RunResult, SimError, Simulation};
