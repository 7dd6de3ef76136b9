//! aes-core: the physics of the All Electric Ship simulator (Schmitt, MIT 2010).
//!
//! One module per physical subsystem, named after it; equation numbers are the thesis' own.
//! Everything is SI inside; no I/O, no threads; the same scenario gives the same numbers on
//! every platform.

pub mod as_printed;
pub mod control;
pub mod controller_study;
pub mod dc_link;
pub mod design;
pub mod fft;
pub mod fuel;
pub mod fuel_study;
pub mod generator;
pub mod hull_sections;
pub mod interp;
pub mod maneuvering;
pub mod montecarlo;
pub mod motor;
pub mod numerics;
pub mod params;
pub mod presentation;
pub mod presets;
pub mod prime_mover;
pub mod propeller;
pub mod propeller_losses;
pub mod rao_cache;
pub mod registry;
pub mod regression;
pub mod rudder;
pub mod scenario;
pub mod scenario_file;
pub mod seakeeping;
pub mod ship_hull;
pub mod signals;
pub mod sim;
pub mod speed_control;
pub mod stability;
pub mod stats;
pub mod surge;
pub mod svg_plot;
pub mod thesis_values;
pub mod units;
pub mod validate;
pub mod validation;
pub mod waves;

pub use scenario::Scenario;
pub use sim::{run, RunResult, SimError, Simulation};
