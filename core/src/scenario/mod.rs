//! The scenario: everything one run needs, as a public JSON format.
//!
//! Defaults are the thesis' values (Tables 2.1, 5.1-5.5). Where the thesis leaves a value open, the
//! chosen value and the reason stand next to the field. Units are in the field names; speeds of
//! rotating machines are given in rpm and ship speeds in knots because that is how engineers state
//! them; the physics converts to SI on load.

pub mod file;
pub mod presets;
pub mod registry;

use crate::checks::Validator;
pub use crate::numerics::Integrator;
use crate::signals::Signal;
use serde::{Deserialize, Serialize};

// Each subsystem owns its parameters (field docs with the thesis source, defaults, ranges); the
// scenario only composes them. Re-exported so that `scenario::X` names every part of the format.
pub use crate::as_printed::AsPrintedParams;
pub use crate::checks::{FieldError, ScenarioError};
pub use crate::control::design::{ControllerDesign, LqgLtrParams};
pub use crate::control::speed::SpeedControlParams;
pub use crate::plant::bus_loads::BusLoadParams;
pub use crate::plant::dc_link::{DcLinkParams, RectifierKind};
pub use crate::plant::generator::{FieldControlParams, GeneratorParams};
pub use crate::plant::load_bank::LoadBankParams;
pub use crate::plant::motor::{MotorParams, SlipControlParams};
pub use crate::plant::online::OnlineParams;
pub use crate::plant::prime_mover::{GovernorParams, TurbineParams};
pub use crate::plant::propeller::{PropellerModelKind, PropellerParams};
pub use crate::plant::storage::{StorageKind, StorageParams};
pub use crate::plant::{BusParts, PlantParams};
pub use crate::sea::conditioning::RareEventParams;
pub use crate::sea::operability::OperabilityParams;
pub use crate::sea::seakeeping::params::{SeakeepingParams, SternMotion};
pub use crate::sea::waves::{SeaKind, SeaParams};
pub use crate::ship::maneuvering::{AbkowitzCoefficients, HullModelKind, HullParams};
pub use crate::ship::rudder::{AutopilotParams, RudderParams};
pub use crate::ship::surge::ShipParams;

crate::params! {
    /// One complete run: ship, plant, propeller, controllers, commands and simulation settings.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct Scenario {
        pub name: String = "custom".into() => {
            label: "Name", source: "our choice", help: "Short name, shown in summaries.",
        },
        pub description: String = String::new() => {
            label: "Description", help: "One or two sentences for the reader: what this run shows.",
        },
        pub ship: ShipParams = ShipParams::default() => {},
        pub hull: HullParams = HullParams::default() => {},
        pub rudder: RudderParams = RudderParams::default() => {},
        pub propeller: PropellerParams = PropellerParams::default() => {},
        pub plant: PlantParams = PlantParams::default() => {},
        pub controllers: ControllerParams = ControllerParams::default() => {},
        /// Time-stamped commands; the latest command whose time has come is in force.
        pub commands: Vec<Command> = vec![Command { t_s: 0.0, speed_kn: Some(25.0), heading_deg: None, heading_rate_deg_s: None, online_sets: None, crash_stop: false }] => {},
        pub initial: InitialConditions = InitialConditions::default() => {},
        pub sim: SimSettings = SimSettings::default() => {},
        pub stepping: SteppingParams = SteppingParams::default() => {},
        /// The sea (calm unless set).
        pub sea: SeaParams = SeaParams::default() => {},
        /// Ship motions in waves and the propeller's surface losses (used when the sea is not calm).
        pub seakeeping: SeakeepingParams = SeakeepingParams::default() => {},
        /// What a Monte Carlo study of this scenario collects (`aes-sim mc`, the page's Monte Carlo
        /// tab); a single run ignores it.
        pub monte_carlo: MonteCarloParams = MonteCarloParams::default() => {},
        /// Where on the ship motions are judged and the seakeeping criteria (`aes-sim
        /// operability`, the page's Operability tab); a single run ignores it.
        pub operability: OperabilityParams = OperabilityParams::default() => {},
        /// A sea conditioned on a propeller surface event, and the rare-event study's window
        /// (`aes-sim rare`); off unless `rare_event.level_h_over_r` is set.
        pub rare_event: RareEventParams = RareEventParams::default() => {},
        /// The thesis' equations as printed where we chose a corrected form (all off by default;
        /// `core/src/as_printed.rs`).
        pub as_printed: AsPrintedParams = AsPrintedParams::default() => {},
    }
}

crate::params! {
    /// A Monte Carlo study (thesis ch. 5.4): trial i runs the scenario with the sea of seed
    /// `trial_seed(sim.seed, i)`.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct MonteCarloParams {
        pub trials: u64 = 100 => {
            label: "Monte Carlo trials", unit: "-", range: 1.0..=1.0e7, source: "ch. 5.4: 100 trials (189 for the arrival times)", group: "sea",
            help: "For the Monte Carlo button (ch. 5.4): trials, each with its own sea.",
        },
        pub envelope_signals: Vec<String> = vec!["im_power_pu".into(), "h_over_r".into(), "prop_rpm".into()] => {
            label: "Envelope signals", source: "Figs. 5-22 to 5-24",
            help: "Signals whose envelope over trials (mean, +-2 sigma, min, max) is kept.",
        },
        /// Empty when the trials end before `histogram_time_s`.
        pub histogram_signal: String = "im_power_pu".into() => {
            label: "Histogram signal", source: "Fig. 5-21", help: "The trace column whose histogram over trials is kept.",
        },
        pub histogram_time_s: f64 = 40.0 => {
            label: "Histogram time", unit: "s", range: 0.0..=1.0e6, source: "our choice", help: "When the histogram is taken.",
        },
        pub histogram_lo: f64 = 0.0 => {
            label: "Histogram from", unit: "-", range: -1.0e9..=1.0e9, source: "our choice", help: "Lower edge, in the histogram signal's unit.",
        },
        pub histogram_hi: f64 = 1.5 => {
            label: "Histogram to", unit: "-", range: -1.0e9..=1.0e9, source: "our choice", help: "Upper edge, in the histogram signal's unit.",
        },
        pub histogram_bins: u32 = 30 => {
            label: "Histogram bins", unit: "-", range: 1.0..=1000.0, source: "our choice", help: "Number of bins.",
        },
        /// Doubles the cost.
        pub excess_energy: bool = false => {
            label: "Excess energy", source: "ch. 5.4.2",
            help: "Each trial's extra motor energy against the same trial without surface losses (doubles the cost).",
        },
        /// Trials without one run to the end and count as censored at `sim.duration_s`.
        pub stop_at_first_event: bool = false => {
            label: "Stop at the first event", source: "ch. 5.4.3",
            help: "Stop a trial onset_window_s after its first surface effect (beta_T < 1).",
        },
        pub onset_window_s: f64 = 12.0 => {
            label: "Onset window", unit: "s", range: 0.0..=600.0, source: "Fig. 5-25",
            help: "Motor power kept after the onset of the first event.",
        },
        pub keep_traces: u32 = 1 => {
            label: "Traces kept", unit: "-", range: 0.0..=10.0, source: "our choice", help: "Traces of the first trials kept for display.",
        },
        pub periodogram_segment_s: f64 = 25.6 => {
            label: "Periodogram segment", unit: "s", range: 1.0..=1.0e4, source: "our choice: 0.04 Hz resolution",
            help: "Welch segment for the periodogram of motor power.",
        },
    }
}

crate::params! {
    /// Gains of all the control loops.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct ControllerParams {
        pub design: ControllerDesign = ControllerDesign::Pi => {
            label: "Turbine and field control", source: "ch. 2, 5 (PI); ch. 3.1 (LQG/LTR)", group: "controllers",
            help: "Two PI loops per set (ch. 2, 5), or one LQG/LTR controller per set moving throttle and field together (ch. 3.1; tune it in the Controller design tab).",
        },
        pub lqg_ltr: LqgLtrParams = LqgLtrParams::default() => {},
        pub governor: GovernorParams = GovernorParams::default() => {},
        pub field: FieldControlParams = FieldControlParams::default() => {},
        pub slip: SlipControlParams = SlipControlParams::default() => {},
        pub speed: SpeedControlParams = SpeedControlParams::default() => {},
        pub autopilot: AutopilotParams = AutopilotParams::default() => {},
    }
}

crate::params! {
    /// A command; the latest one whose time has come is in force.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Command {
        pub t_s: f64 = 0.0 => {
            label: "Order time", unit: "s", range: 0.0..=1.0e7, help: "When the order takes effect.",
        },
        /// Negative orders go astern, down to [`ASTERN_LIMIT_KN`].
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub speed_kn: Option<f64> = None => {
            label: "Ordered speed", unit: "kn", range: ASTERN_LIMIT_KN..=40.0, empty: "keep the previous order",
            source: "astern to -15 kn, our choice: the hull's astern resistance is its ahead curve mirrored (ASTERN_LIMIT_KN)",
            help: "Ship speed ordered; negative is astern (needs propeller.model four_quadrant or geometry and controllers.slip.allow_braking).",
        },
        /// Full astern at once (the crash stop): the speed order becomes the astern limit and the
        /// shaft reference steps to zero (the motors brake the shafts within their braking
        /// limits), then ramps astern at the shaft ramp. A later speed order ends it.
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        pub crash_stop: bool = false => {
            label: "Crash stop", source: "IMO MSC.137(76) 5.3.4's full-astern stopping test",
            help: "Full astern at once: orders the astern limit; the shaft reference steps to zero, then ramps astern (needs what an astern order needs).",
        },
        /// Not wrapped: 360 means one full turn to starboard.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub heading_deg: Option<f64> = None => {
            label: "Ordered heading", unit: "deg", range: -3600.0..=3600.0, empty: "keep the previous order",
            help: "Clockwise from north, not wrapped (360: a full turn to starboard); needs hull.model maneuvering.",
        },
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub heading_rate_deg_s: Option<f64> = None => {
            label: "Heading rate", unit: "deg/s", range: 0.01..=10.0, empty: "the autopilot's turn_rate_deg_s",
            help: "How fast the heading order moves to the ordered heading.",
        },
        /// Sets not running start (online after `plant.online.startup_time_s`); running sets not
        /// listed stop (after their minimum running time).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub online_sets: Option<Vec<u32>> = None => {
            label: "Ordered online sets", unit: "-", range: 1.0..=4.0, empty: "keep the sets running",
            help: "The turbine-generator sets to run from this order on, by number (1 to 4).",
        },
    }
}

crate::params! {
    /// Where the run starts.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct InitialConditions {
        /// Above 0 the plant starts at the calm-water steady state for that speed (solved on load).
        pub speed_kn: f64 = 0.0 => {
            label: "Initial speed", unit: "kn", range: 0.0..=35.0, source: "ch. 5.1 starts from idle", group: "sim",
            help: "0 starts from idle (turbines at rated speed, bus charged, shafts stopped); above 0, at the calm-water steady state.",
        },
    }
}

crate::params! {
    /// The run: how long, what is recorded, the seed.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SimSettings {
        pub duration_s: f64 = 300.0 => {
            label: "Duration", unit: "s", range: 0.0..=1.0e6, source: "our choice", group: "sim",
            help: "Simulated time.",
        },
        pub record_interval_s: f64 = 0.1 => {
            label: "Record every", unit: "s", range: 1.0e-4..=1.0e4, source: "our choice", group: "sim",
            help: "Interval between recorded trace rows; a whole number of steps.",
        },
        /// The calm-water drive train uses none.
        pub seed: u64 = 0 => {
            label: "Seed", unit: "-", source: "our choice", group: "sim",
            help: "Fixes every random number: the same seed gives the same sea.",
        },
    }
}

crate::params! {
    /// How time is stepped, in one place: the fixed step and its method, the controllers' and the
    /// sea's sample periods and the hull's multi-rate step (each a whole number of steps).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SteppingParams {
        /// The DC link's time constant is about 4.5 ms (4.25 ms at 3 kn, 4.71 ms at 32 kn: the
        /// fastest mode of the drive train linearised, every other one 0.9 s or slower), so 1 ms by
        /// default; 5 ms in the presets in waves.
        pub dt_s: f64 = 0.001 => {
            label: "Time step", unit: "s", range: 1.0e-5..=0.01, group: "sim",
            source: "our choice: a quarter of the DC link's 4.5 ms time constant",
            help: "Fixed step (1 ms; 5 ms in waves, the controllers' sample period); the record interval must be a whole number of steps.",
        },
        /// "midpoint" is second order, two evaluations of the plant a step instead of four; the
        /// presets in waves use it, where holding the sea's inputs over a step costs more accuracy
        /// than the method (tests/multirate.rs). The midpoint rule is stable for the DC link at
        /// steps up to 2 time constants (RK4: 2.8).
        pub integrator: Integrator = Integrator::Rk4 => {
            label: "Integration method", group: "sim", source: "our choice: RK4; midpoint in waves (tests/multirate.rs)",
            help: "RK4 evaluates the plant four times a step, the midpoint rule twice (second order). In waves at 5 ms both agree with 1 ms RK4 steps to 0.035 rpm: holding the sea over a step costs more than the method.",
        },
        /// Not given in the thesis (which calls the governor "discrete").
        pub controller_sample_s: f64 = 0.005 => {
            label: "Controller sample period", unit: "s", range: 1.0e-4..=1.0,
            source: "our choice: 5 ms (not given in the thesis)",
            help: "The discrete controllers sample this often; a whole number of time steps.",
        },
        /// Wave kinematics are summed every `sea_sample_s` and carried between samples by a
        /// second-order Taylor series.
        pub sea_sample_s: f64 = 0.05 => {
            label: "Sea sample period", unit: "s", range: 1.0e-5..=0.5,
            source: "our choice: 20 Hz, measured against every step (tests/multirate.rs)",
            help: "How often the wave sums are made; a whole number of time steps.",
        },
        /// The hull (surge, sway, yaw, position, heading) takes one step of this many `dt_s` (by
        /// `integrator`) under the drive train's mean thrust over them, while the drive train takes
        /// its `dt_s` steps with the hull held. 1: one step of the whole plant every `dt_s`.
        /// `sim.record_interval_s` must be a whole number of hull steps.
        #[serde(skip_serializing_if = "is_one")]
        pub hull_substeps: u32 = 1 => {
            label: "Hull sub-steps", unit: "-", range: 1.0..=100.0, source: "our choice: single rate (tests/multirate.rs)",
            help: "Multi-rate: the hull steps once per this many time steps under the mean thrust.",
        },
    }
}

/// Longest step with `stepping.integrator = midpoint` \[s\] (see `SteppingParams`' checks).
pub const MIDPOINT_MAX_DT_S: f64 = 0.008;

fn is_one(n: &u32) -> bool {
    *n == 1
}

/// How many recorded values (rows times trace columns) a run may hold; beyond it the run is
/// refused before it starts. 1e7 values are 80 MB of columns and about 200 MB of CSV, which a
/// browser tab still holds (the page keeps both); the presets record at most 2.4e5.
pub const MAX_RECORDED_VALUES: f64 = 1.0e7;
/// How many recorded rows a run may hold (the values budget over the trace's columns).
pub const MAX_RECORDED_ROWS: f64 = MAX_RECORDED_VALUES / crate::signals::N_SIGNALS as f64;
/// How many time steps a run may take.
pub const MAX_STEPS: f64 = 1.0e9;
/// The simulator's state size (`plant::layout::NX`). A run's work counts only the states it uses
/// ([`Scenario::active_states`]): 33 without the bus's parts, as before they came.
pub const STATE_SIZE: usize = crate::plant::layout::NX;
/// Budget of simulated work: time steps times the work of one step in state variables (the state
/// size, plus in waves the wave components summed per step). 2e9 is about 40 s natively
/// ([`WORK_PER_S`]) and a minute in a browser; the presets need at most 1.7e7.
pub const MAX_WORK: f64 = 2.0e9;
/// Work done natively in a second on one core, roughly: for an estimate before a long study,
/// never for a result. Measured on one core of the development machine: 7.3e7 for the start-up
/// preset (calm water), 5.6e7 for Monte Carlo trials of head-seas-ss6, 6.6e7 for its rare-event
/// trials; the lower end is taken, since machines of one kind differ 2-3 times and a study that
/// ends early surprises no one.
pub const WORK_PER_S: f64 = 5.0e7;
/// How many times slower the same work runs in WebAssembly than natively (1.4 in Node for the
/// start-up preset, `node scripts/bench-wasm.mjs startup`; a browser's engine is about the same):
/// for the estimate the page says before a long study, never for a result.
pub const WASM_SLOWDOWN: f64 = 1.4;
/// How many times `aes-sim bench` may repeat its runs (each within [`MAX_WORK`]).
pub const MAX_BENCH_REPEAT: u32 = 100;
/// How many commands a scenario may hold.
pub const MAX_COMMANDS: usize = crate::params::MAX_LIST_ITEMS;
/// How many signals a Monte Carlo study may keep envelopes of.
pub const MAX_ENVELOPE_SIGNALS: usize = 20;

impl crate::params::CrossCheck for ControllerParams {}
impl crate::params::CrossCheck for PlantParams {}
impl crate::params::CrossCheck for InitialConditions {}

/// Fastest ordered speed astern \[kn\] (negative). Our choice, not the motors' limit: on eq.
/// 2.15's resistance, which is the ahead curve mirrored (the thesis knows no other), the motors'
/// rated power would drive the ship at 31.6 kn astern (tests/astern.rs), which no warship does;
/// neither that mirrored hull nor the rudders in reversed flow are checked against astern data,
/// so orders stop at half the ahead top speed (a shaft then takes 4.1 MW).
pub const ASTERN_LIMIT_KN: f64 = -15.0;

impl Command {
    /// Whether this order takes the ship astern (a negative speed or a crash stop).
    pub fn astern(&self) -> bool {
        self.crash_stop || self.speed_kn.is_some_and(|kn| kn < 0.0)
    }
}

impl crate::params::CrossCheck for Command {
    fn cross_check(&self, v: &mut Validator) {
        if let Some(sets) = &self.online_sets {
            crate::plant::online::check_set_list(sets, "online_sets", v);
        }
    }
}

impl crate::params::CrossCheck for MonteCarloParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.envelope_signals.len() > MAX_ENVELOPE_SIGNALS {
            v.fail(
                "envelope_signals",
                format!("{} signals", self.envelope_signals.len()),
                format!("at most {MAX_ENVELOPE_SIGNALS}"),
            );
        }
        for (i, n) in self.envelope_signals.iter().enumerate().take(MAX_ENVELOPE_SIGNALS) {
            if Signal::from_name(n).is_none() {
                v.fail(&format!("envelope_signals.{i}"), n, "is not a trace column (see `aes-sim signals`)");
            }
        }
        if Signal::from_name(&self.histogram_signal).is_none() {
            v.fail("histogram_signal", &self.histogram_signal, "is not a trace column (see `aes-sim signals`)");
        }
        if self.histogram_hi < self.histogram_lo {
            v.fail(
                "histogram_hi",
                crate::checks::num(self.histogram_hi),
                format!("must be at least {}", v.path("histogram_lo")),
            );
        }
    }
}

impl crate::params::CrossCheck for SimSettings {}

impl crate::params::CrossCheck for SteppingParams {
    fn cross_check(&self, v: &mut Validator) {
        // The midpoint rule's stability bound: 2 time constants of the DC link (4.25 ms at the
        // least, at 3 kn), 8.5 ms; RK4's 2.8, 11.8 ms, lies beyond the range above.
        if self.integrator == Integrator::Midpoint && self.dt_s > MIDPOINT_MAX_DT_S {
            v.fail(
                "dt_s",
                self.dt_s,
                format!(
                    "must be at most {MIDPOINT_MAX_DT_S} s with stepping.integrator = midpoint (stable for the DC \
                     link's 4.25 ms time constant up to 2 of them; rk4 allows up to 0.01 s)"
                ),
            );
        }
        if !(self.dt_s.is_finite() && self.dt_s > 0.0) {
            return;
        }
        for (field, period) in [("controller_sample_s", self.controller_sample_s), ("sea_sample_s", self.sea_sample_s)]
        {
            if !whole_multiple(period, self.dt_s) {
                v.fail(field, period, format!("must be a whole number (1 or more) of stepping.dt_s = {}", self.dt_s));
            }
        }
    }
}

/// The checks that span sections.
impl crate::params::CrossCheck for Scenario {
    fn cross_check(&self, v: &mut Validator) {
        self.validate_commands(v);
        if self.sea.kind != SeaKind::Calm && self.hull.model != HullModelKind::Maneuvering {
            v.fail(
                "sea.kind",
                format!("{:?}", self.sea.kind).to_lowercase(),
                "waves need hull.model = \"maneuvering\"",
            );
        }
        if self.as_printed.table_5_ship
            && self.hull.model == HullModelKind::Maneuvering
            && self.hull.forces == crate::ship::maneuvering::ManeuveringForces::OwnHull
        {
            v.fail(
                "as_printed.table_5_ship",
                "true",
                "Tables 5.1 and 5.5's ship (L 180 m) goes with the thesis' hull forces: hull.forces = \"table_2_3\"",
            );
        }
        if self.seakeeping.ventilation_onset == crate::plant::propeller_losses::VentilationOnset::Derived
            && self.propeller.model != PropellerModelKind::Geometry
        {
            v.fail(
                "seakeeping.ventilation_onset",
                "derived",
                format!(
                    "needs propeller.model = \"geometry\" (the onset comes from the blades' sections); propeller.model \
                     is {}",
                    serde_json::to_string(&self.propeller.model).unwrap_or_default()
                ),
            );
        }
        self.validate_steps(v);
        self.validate_work(v);
        self.validate_bus_steps(v);
    }
}

/// Longest step for the ship service filter, as a fraction of its period over 2 pi: 1/(omega dt)
/// of at least 5 (RK4 follows the filter's resonance to 1e-5 of its damping at it).
pub const FILTER_STEP_PER_RAD: f64 = 0.2;

fn whole_multiple(a: f64, b: f64) -> bool {
    let r = a / b;
    (r - r.round()).abs() < 1e-6 && r.round() >= 1.0
}

impl Scenario {
    /// Checks every field against its declaration and the checks that span fields; returns all
    /// problems at once.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        let mut v = Validator::new();
        crate::params::Section::check_fields(self, &mut v);
        v.finish()
    }

    /// The ship's hull, resolved (`ship.hull`); the error names the field.
    pub fn ship_hull(&self) -> Result<crate::ship::hull::ShipHull, String> {
        self.ship.hull.resolve(self.ship.water_density_kg_m3).map_err(|(f, e)| format!("ship.hull.{f}: {e}"))
    }

    /// Puts the propeller hubs at calm-water depth `h0` \[m\] below this loading's waterline
    /// (`ship.hull.hub_above_base_m` = draft - h0; ch. 5.3 and 5.4 vary h0).
    pub fn set_hub_depth_m(&mut self, h0: f64) {
        if let Ok(h) = self.ship_hull() {
            self.ship.hull.hub_above_base_m = Some(h.draft_m - h0);
        }
    }

    /// The RAO table of this scenario's hull, grid and strip-theory switches (`as_printed`'s,
    /// `seakeeping.aft_end_terms` and `short_wave_force`; built once, shared).
    pub fn rao_table(&self) -> Result<std::sync::Arc<crate::sea::seakeeping::tables::RaoTable>, String> {
        self.rao_table_with(&crate::sea::seakeeping::tables::Serial)
    }

    /// [`Self::rao_table`] with the build's parts run by `each` (side by side on the command
    /// line's threads; the same table to the bit).
    pub fn rao_table_with(
        &self,
        each: &dyn crate::sea::seakeeping::tables::ForEach,
    ) -> Result<std::sync::Arc<crate::sea::seakeeping::tables::RaoTable>, String> {
        crate::ship::rao_cache::rao_table_with(&self.table_spec(&self.ship_hull()?), each)
    }

    /// Whether this scenario's RAO table is built and kept (nothing is built; false when the
    /// hull cannot be made).
    pub fn rao_table_is_cached(&self) -> bool {
        self.ship_hull().is_ok_and(|h| crate::ship::rao_cache::is_cached(&self.table_spec(&h)))
    }

    /// The RAO table's values and their digest, for another web worker ([`Self::insert_rao_table`]).
    pub fn rao_table_values(&self) -> Result<Vec<f64>, String> {
        crate::ship::rao_cache::rao_table_values(
            &self.table_spec(&self.ship_hull()?),
            &crate::sea::seakeeping::tables::Serial,
        )
    }

    /// Takes the table another web worker built ([`Self::rao_table_values`]) if it is this
    /// scenario's.
    pub fn insert_rao_table(&self, values_and_digest: &[f64]) -> Result<(), String> {
        crate::ship::rao_cache::insert_rao_table(&self.table_spec(&self.ship_hull()?), values_and_digest)
    }

    fn table_spec<'a>(&'a self, hull: &'a crate::ship::hull::ShipHull) -> crate::ship::rao_cache::TableSpec<'a> {
        let sk = &self.seakeeping;
        crate::ship::rao_cache::TableSpec {
            hull,
            grid: &sk.grid,
            printed: &self.as_printed,
            aft_end_terms: sk.aft_end_terms,
            short_wave: sk.short_wave_force,
        }
    }

    /// The bus voltage set point the field control holds \[V\]: `controllers.field.bus_voltage_ref_v`,
    /// read as sqrt(3) times itself with `as_printed.ea_line_to_line` (eq. 2.8's E_a taken as the
    /// line-to-line emf puts the bus at sqrt(3) times the phase reading's voltage).
    pub fn bus_voltage_ref_v(&self) -> f64 {
        if self.as_printed.ea_line_to_line {
            self.controllers.field.bus_voltage_ref_v * self.as_printed.emf_reading()
        } else {
            self.controllers.field.bus_voltage_ref_v
        }
    }

    /// The flow the scenario's table is analysed in: sea water, the propeller's diameter, and the
    /// motor's synchronous speed f / p (300 rpm for the thesis' direct-drive motor, its ch. 5 rating).
    /// A stated shaft speed rather than the ordered speed's rpm, because the table is built before
    /// the run and the rpm there would need the run; the speed only sets the sections' Reynolds
    /// numbers (drag), which change slowly with it.
    pub fn propeller_design_flow(&self) -> crate::plant::blade::Flow {
        let m = &self.plant.motor;
        crate::plant::blade::Flow::sea_water(
            self.propeller.diameter_m,
            m.rated_frequency_hz / m.pole_pairs.max(1) as f64,
        )
    }

    /// The field control's parameters with the set point of `bus_voltage_ref_v`.
    pub fn field_control(&self) -> FieldControlParams {
        FieldControlParams { bus_voltage_ref_v: self.bus_voltage_ref_v(), ..self.controllers.field.clone() }
    }

    /// The bus's parts against the step: the ship service filter's resonance and the storage's
    /// current loop must be resolved.
    fn validate_bus_steps(&self, v: &mut Validator) {
        let dt = self.stepping.dt_s;
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        let l = &self.plant.loads;
        if l.has_ship_service() {
            let w = 1.0 / (l.filter_inductance_h * l.filter_capacitance_f).sqrt();
            // The integrator is blamed when it is the problem, the step only when it is too long.
            if self.stepping.integrator != Integrator::Rk4 {
                v.fail(
                    "stepping.integrator",
                    "midpoint",
                    format!(
                        "must be rk4 with a ship service load (plant.loads.ship_service_w > 0): its filter \
                         resonates at {:.1} Hz, an undamped oscillation the midpoint rule makes grow",
                        w / (2.0 * std::f64::consts::PI)
                    ),
                );
            } else if w * dt > FILTER_STEP_PER_RAD {
                v.fail(
                    "stepping.dt_s",
                    dt,
                    format!(
                        "must be at most {:.2e} s with stepping.integrator = rk4 for the ship service filter \
                         (plant.loads: resonance {:.1} Hz; the step must be at most {FILTER_STEP_PER_RAD} / omega)",
                        FILTER_STEP_PER_RAD / w,
                        w / (2.0 * std::f64::consts::PI)
                    ),
                );
            }
        }
        let st = &self.plant.storage;
        if st.energy_j > 0.0 && dt > st.current_time_constant_s {
            v.fail(
                "plant.storage.current_time_constant_s",
                st.current_time_constant_s,
                format!("must be at least stepping.dt_s = {dt} s (the step must resolve the current loop)"),
            );
        }
    }

    /// The state variables a run advances: the plant's, less the states and energy accounts of
    /// the bus parts it lacks.
    pub fn active_states(&self) -> usize {
        let absent = BusParts::present(&self.plant).into_iter().zip(BusParts::STATES.iter().zip(BusParts::ACCOUNTS));
        absent
            .filter(|(present, _)| !present)
            .map(|(_, (states, accounts))| crate::ship::hull::N_SHAFTS * states.len() + accounts.len())
            .fold(STATE_SIZE, |n, k| n - k)
    }

    /// The work a run asks for: time steps times the state variables advanced per step (plus, in
    /// waves, the wave components summed per step).
    pub fn work(&self) -> f64 {
        let steps = self.sim.duration_s / self.stepping.dt_s;
        let mut per_step = self.active_states() as f64;
        if self.sea.kind != SeaKind::Calm {
            per_step += self.sea.components as f64 * self.stepping.dt_s / self.stepping.sea_sample_s;
        }
        steps * per_step
    }

    /// The run against its step: whole numbers of steps, and the budgets of steps and rows.
    fn validate_steps(&self, v: &mut Validator) {
        let (sim, st) = (&self.sim, &self.stepping);
        let dt = st.dt_s;
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if !whole_multiple(sim.record_interval_s, dt) {
            v.fail(
                "sim.record_interval_s",
                sim.record_interval_s,
                format!("must be a whole number (1 or more) of stepping.dt_s = {dt}"),
            );
        } else if (1..=100).contains(&st.hull_substeps)
            && !whole_multiple(sim.record_interval_s, st.hull_substeps as f64 * dt)
        {
            v.fail(
                "sim.record_interval_s",
                sim.record_interval_s,
                format!(
                    "must be a whole number of hull steps, stepping.hull_substeps x stepping.dt_s = {} x {dt}",
                    st.hull_substeps
                ),
            );
        }
        if !whole_multiple(self.seakeeping.rao_refresh_s, dt) {
            v.fail(
                "seakeeping.rao_refresh_s",
                self.seakeeping.rao_refresh_s,
                format!("must be a whole number (1 or more) of stepping.dt_s = {dt}"),
            );
        }
        if self.seakeeping.rao_refresh_s < st.sea_sample_s {
            v.fail(
                "seakeeping.rao_refresh_s",
                crate::checks::num(self.seakeeping.rao_refresh_s),
                "must be at least stepping.sea_sample_s",
            );
        }
        let steps = sim.duration_s / dt;
        if steps > MAX_STEPS {
            v.fail(
                "sim.duration_s",
                sim.duration_s,
                format!(
                    "with stepping.dt_s = {} this is {steps:.3e} steps; at most {MAX_STEPS:e}",
                    crate::checks::num(dt)
                ),
            );
        }
        let rows = sim.duration_s / sim.record_interval_s;
        if rows > MAX_RECORDED_ROWS {
            v.fail(
                "sim.record_interval_s",
                sim.record_interval_s,
                format!(
                    "with sim.duration_s = {} this records {rows:.3e} rows of {} columns; at most {:.0} rows ({MAX_RECORDED_VALUES:e} values): raise the interval or shorten the run",
                    crate::checks::num(sim.duration_s),
                    crate::signals::N_SIGNALS,
                    MAX_RECORDED_ROWS.floor()
                ),
            );
        }
    }

    fn validate_work(&self, v: &mut Validator) {
        if !(self.stepping.dt_s.is_finite() && self.stepping.dt_s > 0.0 && self.stepping.sea_sample_s > 0.0) {
            return;
        }
        let work = self.work();
        if work > MAX_WORK {
            v.section("sim", |v| {
                v.fail(
                    "duration_s",
                    self.sim.duration_s,
                    format!(
                        "with stepping.dt_s = {} this is {:.3e} steps and {work:.3e} units of work (steps times state size); at most {MAX_WORK:e}: shorten the run or raise stepping.dt_s",
                        crate::checks::num(self.stepping.dt_s),
                        self.sim.duration_s / self.stepping.dt_s
                    ),
                )
            });
        }
    }

    fn validate_commands(&self, v: &mut Validator) {
        if self.commands.len() > MAX_COMMANDS {
            v.fail("commands", format!("{} commands", self.commands.len()), format!("at most {MAX_COMMANDS}"));
        }
        let mut last_t = f64::NEG_INFINITY;
        for (i, cmd) in self.commands.iter().enumerate().take(MAX_COMMANDS) {
            v.section(&format!("commands.{i}"), |v| {
                if cmd.t_s < last_t {
                    v.fail("t_s", cmd.t_s, "commands must be in time order");
                }
                last_t = cmd.t_s;
                if let (Some(hd), false) = (cmd.heading_deg, self.hull.model == HullModelKind::Maneuvering) {
                    v.fail(
                        "heading_deg",
                        hd,
                        "heading commands need hull.model = \"maneuvering\" (the surge model only goes straight)",
                    );
                }
            });
        }
        self.validate_astern(v);
        if self.commands.first().and_then(|c| c.speed_kn).is_none()
            && !self.commands.first().is_some_and(|c| c.crash_stop)
        {
            v.fail(
                "commands.0.speed_kn",
                "missing",
                "the first command must order a ship speed (-15 to 40 knots) or a crash stop",
            );
        }
    }
}

impl Scenario {
    /// Astern orders need a propeller model for every quadrant, a hull model that holds astern and
    /// a drive that may brake (the shafts go through zero against the windmilling propeller).
    fn validate_astern(&self, v: &mut Validator) {
        let Some((i, cmd)) = self.commands.iter().enumerate().take(MAX_COMMANDS).find(|(_, c)| c.astern()) else {
            return;
        };
        let (field, value) = match cmd.speed_kn {
            Some(kn) if !cmd.crash_stop => (format!("commands.{i}.speed_kn"), crate::checks::num(kn)),
            _ => (format!("commands.{i}.crash_stop"), "true".to_string()),
        };
        if self.propeller.model == crate::plant::propeller::PropellerModelKind::BSeries {
            v.fail(
                &field,
                &value,
                "an astern order needs propeller.model = \"four_quadrant\" or \"geometry\" (the B-series \
                 polynomials hold ahead only)",
            );
        }
        if !self.controllers.slip.allow_braking {
            v.fail(
                &field,
                &value,
                "an astern order needs controllers.slip.allow_braking = true (without braking the windmilling \
                 propellers hold the shafts ahead)",
            );
        }
        if self.hull.model == HullModelKind::Maneuvering
            && self.hull.forces == crate::ship::maneuvering::ManeuveringForces::Table23
        {
            v.fail(
                &field,
                &value,
                "an astern order needs hull.forces = \"own_hull\" (Table 2.3's polynomials were fitted ahead)",
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_round_trip() {
        let s = Scenario::default();
        s.validate().unwrap();
        let back = Scenario::from_json(&s.to_json()).unwrap();
        assert_eq!(back, s);
    }

    #[test]
    fn unknown_field_is_named() {
        let e = Scenario::from_json(r#"{"ship": {"mass_kgg": 1}}"#).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("mass_kgg"), "{text}");
        let e = Scenario::from_json(r#"{"sea": {"sea_stat": 4}}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "sea.sea_stat = 4: no such parameter in sea; did you mean sea.sea_state? (`aes-sim params` lists them all)"
        );
    }

    #[test]
    fn wrong_type_is_named_with_path() {
        let e = Scenario::from_json(r#"{"plant": {"motor": {"pole_pairs": "twelve"}}}"#).unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("plant.motor.pole_pairs", "\"twelve\""));
        assert_eq!(e.0[0].message, "Motor pole pairs must be a whole number from 1 to 64");
        // The issue's example: a fraction where a whole number belongs, in words, no serde.
        let e = Scenario::from_json(r#"{"sea": {"sea_state": 2.5}}"#).unwrap_err();
        assert_eq!(e.to_string(), "sea.sea_state = 2.5: Sea state must be a whole number from 2 to 6");
        let e = Scenario::from_json(r#"{"ship": {"wetted_area_m2": "big"}}"#).unwrap_err();
        assert_eq!(e.0[0].message, "Wetted area must be a number from 1 to 100000 m²");
        // An unknown choice: the value quoted and the choices listed.
        let e = Scenario::from_json(r#"{"stepping": {"integrator": "euler"}}"#).unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("stepping.integrator", "\"euler\""));
        assert_eq!(
            e.0[0].message,
            "Integration method must be one of \"rk4\" (RK4 (fourth order)), \"midpoint\" (midpoint rule (second order))"
        );
        let e = Scenario::from_json(r#"{"stepping": {"integrator": {"midpoint": 5}}}"#).unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("stepping.integrator.midpoint", "5"));
        let e = Scenario::from_json(r#"{"commands": [{"t_s": 0}, {"t_s": 5, "speed_kn": [1]}]}"#).unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("commands.1.speed_kn", "[1]"));
        assert!(e.0[0].message.starts_with("Ordered speed must be a number from -15 to 40 kn"), "{}", e.0[0].message);
    }

    #[test]
    fn out_of_range_names_field_value_and_range() {
        let mut s = Scenario::default();
        s.ship.wetted_area_m2 = -5.0;
        s.stepping.dt_s = f64::NAN;
        s.seakeeping.rao_refresh_speed_m_s = -0.1;
        s.seakeeping.rao_refresh_heading_deg = f64::NAN;
        let e = s.validate().unwrap_err();
        let paths: Vec<_> = e.0.iter().map(|f| f.path.as_str()).collect();
        assert!(paths.contains(&"ship.wetted_area_m2"));
        assert!(paths.contains(&"stepping.dt_s"));
        assert!(paths.contains(&"seakeeping.rao_refresh_speed_m_s"), "{paths:?}");
        assert!(paths.contains(&"seakeeping.rao_refresh_heading_deg"), "{paths:?}");
        let m = e.0.iter().find(|f| f.path == "ship.wetted_area_m2").unwrap();
        assert_eq!(m.value, "-5");
        assert!(m.message.contains("from 1 to 100000"), "{}", m.message);
    }

    /// The midpoint rule is refused a step beyond its stability bound for the DC link; RK4 keeps
    /// the range up to 0.01 s.
    #[test]
    fn midpoint_step_is_bounded() {
        let mut s = Scenario::default();
        s.stepping.integrator = Integrator::Midpoint;
        s.stepping.dt_s = 0.01;
        s.sim.record_interval_s = 0.1;
        let e = s.validate().unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("stepping.dt_s", "0.01"), "{e}");
        assert!(e.0[0].message.contains("at most 0.008 s with stepping.integrator = midpoint"), "{e}");
        s.stepping.dt_s = 0.005;
        s.validate().unwrap();
        s.stepping.integrator = Integrator::Rk4;
        s.stepping.dt_s = 0.01;
        s.stepping.controller_sample_s = 0.01;
        s.validate().unwrap();
    }

    /// With a ship service filter the integrator is blamed when it is the problem (a step well
    /// inside the filter's bound with the midpoint rule), the step only when it is too long.
    #[test]
    fn ship_service_filter_blames_what_is_wrong() {
        let mut s = Scenario::default();
        s.plant.loads.ship_service_w = 1e6;
        s.stepping.integrator = Integrator::Midpoint;
        s.stepping.dt_s = 1e-4;
        s.stepping.controller_sample_s = 1e-3;
        s.stepping.sea_sample_s = 1e-3;
        let e = s.validate().unwrap_err();
        assert_eq!(e.0.len(), 1, "{e}");
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("stepping.integrator", "midpoint"), "{e}");
        assert!(e.0[0].message.starts_with("must be rk4 with a ship service load"), "{e}");
        s.stepping.integrator = Integrator::Rk4;
        s.validate().unwrap();
        s.stepping.dt_s = 5e-3;
        s.stepping.controller_sample_s = 5e-3;
        s.stepping.sea_sample_s = 5e-3;
        let e = s.validate().unwrap_err();
        assert_eq!((e.0[0].path.as_str(), e.0[0].value.as_str()), ("stepping.dt_s", "0.005"), "{e}");
        assert!(e.0[0].message.starts_with("must be at most 1.26e-3 s"), "{e}");
    }

    #[test]
    fn override_by_path() {
        let s = Scenario::default();
        let t = s.with_override("commands.0.speed_kn", "20").unwrap();
        assert_eq!(t.commands[0].speed_kn, Some(20.0));
        let t = s.with_override("sim.duration_s", "12.5").unwrap();
        assert_eq!(t.sim.duration_s, 12.5);
        assert!(s.with_override("sim.nope", "1").unwrap_err().0[0].path == "sim.nope");
        assert!(s.with_override("commands.7.speed_kn", "1").is_err());
        assert!(s.with_override("ship.wetted_area_m2", "abc").is_err());
    }

    #[test]
    fn hostile_input_is_bounded() {
        let deep = "[".repeat(10_000);
        assert!(Scenario::from_json(&deep).is_err());
        assert!(Scenario::from_json("{\"name\": 1e999}").is_err());
        assert!(Scenario::from_json("").is_err());
    }

    #[test]
    fn the_work_budget_uses_the_plant_state_size() {
        // Without the bus's parts a run's work is what it was before they came (33 states);
        // each part adds its states and energy accounts: the loads 2 a bus and 3, the storage 3
        // a bus and 2, the load bank none and 1.
        let mut sc = Scenario::default();
        assert_eq!(sc.active_states(), 33);
        sc.plant.loads.pulse_power_w = 1.0e6;
        assert_eq!(sc.active_states(), 33 + 2 * 2 + 3);
        sc.plant.load_bank.resistance_ohm = 10.0;
        assert_eq!(sc.active_states(), 33 + 2 * 2 + 3 + 1);
        sc.plant.storage.energy_j = 1.0e8;
        assert_eq!(sc.active_states(), STATE_SIZE);
        assert_eq!(STATE_SIZE, 49);
    }

    /// The issue's reproducers: 1e9 steps, 2e6 recorded rows, duplicate keys, deep nesting.
    #[test]
    fn budgets_and_strict_json() {
        let e = Scenario::from_json(r#"{"sim":{"duration_s":1e6,"dt_s":0.001}}"#).unwrap_err();
        assert!(e.0.iter().any(|f| f.path == "sim.duration_s" && f.message.contains("2e9")), "{e}");
        let e = Scenario::from_json(r#"{"sim":{"duration_s":20000,"record_interval_s":0.01}}"#).unwrap_err();
        assert!(e.0.iter().any(|f| f.path == "sim.record_interval_s" && f.message.contains("1e7 values")), "{e}");
        let e = Scenario::from_json(r#"{"ship":{"wetted_area_m2":5e3,"wetted_area_m2":5.1e3}}"#).unwrap_err();
        assert!(e.to_string().contains("duplicate key ship.wetted_area_m2"), "{e}");
        let e = Scenario::from_json(&format!("{{\"commands\":{}", "[".repeat(100))).unwrap_err();
        assert!(e.to_string().contains("nesting deeper than 32 levels at commands.0.0."), "{e}");
        // Parsing with the checks gives serde_json's own value.
        let text = Scenario::default().to_json();
        assert_eq!(
            crate::scenario::file::parse_bounded(&text).unwrap(),
            serde_json::from_str::<serde_json::Value>(&text).unwrap()
        );
    }

    #[test]
    fn record_interval_must_be_whole_steps() {
        let mut s = Scenario::default();
        s.sim.record_interval_s = 0.0015;
        assert!(s.validate().is_err());
    }
}
