//! Shared helpers of the thesis-reproduction tests.

use aes_core::{RunResult, Scenario};

/// The start-up preset ordered to `speed_kn` and run for `duration_s` (core's, which the
/// validation report runs too).
pub use aes_core::scenario::presets::startup_to;

/// Runs a scenario, failing the test with the simulator's message if it does not finish.
pub fn run(s: &Scenario) -> RunResult {
    aes_core::run(s).unwrap_or_else(|e| panic!("{}: {e}", s.name))
}

/// Final value of a recorded signal.
pub fn final_value(r: &RunResult, name: &str) -> f64 {
    r.summary.signals.get(name).unwrap_or_else(|| panic!("no signal {name}")).final_
}
