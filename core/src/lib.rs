//! aes-core: the physics of the All Electric Ship simulator (Schmitt, MIT 2010).
//!
//! One module per physical subsystem, named after it; equation numbers are the thesis' own.
//! Everything is SI inside; no I/O, no threads; the same scenario gives the same numbers on
//! every platform.

pub mod checks;
pub mod control;
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

// The modules' earlier paths (until every use names the new ones).
pub use scenario::as_printed;
pub use studies::controller as controller_study;
pub use plant::dc_link;
pub use control::design;
pub use numerics::fft;
pub use plant::fuel;
pub use studies::fuel as fuel_study;
pub use plant::generator;
pub use ship::sections as hull_sections;
pub use numerics::interp;
pub use ship::maneuvering;
pub use studies::montecarlo;
pub use plant::motor;
pub use output::presentation;
pub use scenario::presets;
pub use plant::prime_mover;
pub use plant::propeller;
pub use plant::propeller_losses;
pub use sea::rao_cache;
pub use scenario::registry;
pub use studies::regression;
pub use ship::rudder;
pub use scenario::file as scenario_file;
pub use sea::seakeeping;
pub use ship::hull as ship_hull;
pub use control::speed as speed_control;
pub use studies::ips as stability;
pub use studies::stats;
pub use ship::surge;
pub use output::svg_plot;
pub use studies::thesis_values;
pub use numerics::units;
pub use checks as validate;
pub use studies::validation_report as validation;
pub use sea::waves;

pub use scenario::Scenario;
pub use sim::{run, RunResult, SimError, Simulation};
