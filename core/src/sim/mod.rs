//! The coupled simulation: controllers, commands, fixed-step integration, recording and
//! divergence detection. `Simulation` can be advanced in chunks (the browser reports progress
//! and honours cancel between chunks); `run` does it in one go.

pub mod conditioned;
mod heading_hold;
pub mod health;
pub mod linearize;
mod loops;
pub mod lqg;
pub mod plant;
pub mod propeller_cavitation;
mod record;
pub mod seaway;
mod steady;
pub mod summary;

use crate::control::speed::SpeedController;
use crate::control::DiscretePi;
use crate::numerics::units::{deg_to_rad, kn_to_m_s, m_s_to_kn, rad_s_to_rpm, rad_to_deg};
use crate::plant::generator::FieldController;
use crate::plant::motor::SlipController;
use crate::plant::prime_mover::Governor;
use crate::plant::propeller_losses::{beta_out_of_water, torque_factor, LossParams, Ventilation};
use crate::scenario::{ControllerDesign, HullModelKind, Scenario};
use crate::ship::rudder::Autopilot;
use crate::signals::{Signal, N_SIGNALS};
use plant::{
    drive_step, hull_step, plant_step, slot, Energy, Held, Outputs, Plant, State, ENERGY, ENERGY0, HEADING, NX,
    N_ENERGY, N_SETS, N_SHAFTS, SETS_PER_SHAFT, SURGE, SWAY, X_POS, YAW_RATE, Y_POS,
};
use std::borrow::Cow;
use std::f64::consts::PI;
use std::fmt;

use loops::Controllers;
pub use summary::{Summary, TraceStats};

/// A run that could not start or did not finish.
#[derive(Debug, Clone, PartialEq)]
pub enum SimError {
    /// The scenario cannot be built into a model.
    Setup(String),
    /// The run left the physical range: when, where and what.
    Diverged { time_s: f64, subsystem: String, message: String },
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SimError::Setup(m) => write!(f, "cannot set up the run: {m}"),
            SimError::Diverged { time_s, subsystem, message } => {
                write!(f, "run diverged at t = {time_s:.3} s in {subsystem}: {message}")
            }
        }
    }
}

impl std::error::Error for SimError {}

/// A recorded trace: one column per signal of [`crate::signals::SIGNALS`], in its order.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    pub columns: Vec<Vec<f64>>,
}

impl Trace {
    /// An empty trace with room for `rows` rows.
    pub fn with_capacity(rows: usize) -> Trace {
        Trace { columns: (0..N_SIGNALS).map(|_| Vec::with_capacity(rows)).collect() }
    }

    /// The column of a signal.
    pub fn get(&self, s: Signal) -> &[f64] {
        &self.columns[s.index()]
    }

    /// The column of a signal, by name (None for a name that is not a signal).
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        Signal::from_name(name).map(|s| self.get(s))
    }

    /// Number of recorded rows.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, |c| c.len())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The trace as CSV text with a header row.
    pub fn to_csv(&self) -> String {
        use std::io::Write;
        let mut s = crate::signals::names().collect::<Vec<_>>().join(",").into_bytes();
        s.push(b'\n');
        // Display's text, written in place (no String per number) into one allocation of about
        // 16 bytes a number; a number with the bits of the one above it (a fifth of a trace:
        // zeros, held commands) copies that one's text. In WebAssembly the CSV was a quarter of
        // a head-seas-ss6 run (about 5.9 ms of 21 ms; now about 3.5 ms).
        s.reserve(self.len() * self.columns.len() * 16);
        let mut above: Vec<(u64, usize, usize)> = vec![(0, 0, 0); self.columns.len()];
        for r in 0..self.len() {
            for (i, c) in self.columns.iter().enumerate() {
                if i > 0 {
                    s.push(b',');
                }
                let (bits, at) = (c[r].to_bits(), s.len());
                let (b, from, to) = above[i];
                if r > 0 && b == bits {
                    s.extend_from_within(from..to);
                } else {
                    let _ = write!(s, "{}", c[r]);
                }
                above[i] = (bits, at, s.len());
            }
            s.push(b'\n');
        }
        String::from_utf8(s).unwrap_or_default()
    }
}

/// What a finished run gives back.
#[derive(Debug, Clone, PartialEq)]
pub struct RunResult {
    pub trace: Trace,
    pub summary: Summary,
}

/// Divergence limits: a state outside them means the run has left the physics the model
/// represents (a numerical blow-up or an impossible parameter set), and the run stops with the
/// subsystem named instead of printing nonsense.
pub mod limits {
    /// Turbine speed band, per unit of rated: a real LM2500 trips on overspeed near 1.1; three
    /// times rated is far past anything physical; slightly negative allows numerical noise at rest.
    pub const TURBINE_SPEED_PU: (f64, f64) = (-0.1, 3.0);
    /// Field current \[A\]: about 200 times the 500 A of rated excitation.
    pub const FIELD_CURRENT_A: f64 = 1.0e5;
    /// Bus voltage band, per unit of the set point: three times the set point would have
    /// destroyed the converters long before.
    pub const BUS_VOLTAGE_PU: (f64, f64) = (-0.1, 3.0);
    /// Shaft speed, multiple of the speed controller's largest reference.
    pub const SHAFT_SPEED_OF_MAX_REF: f64 = 3.0;
    /// Ship speed \[m/s\]: 40 m/s is 78 knots, twice a destroyer's top speed.
    pub const SURGE_M_S: f64 = 40.0;
    /// Sway speed \[m/s\] and yaw rate \[rad/s\]: 20 m/s sideways or 29 deg/s of turn are beyond any
    /// ship of this size.
    pub const SWAY_M_S: f64 = 20.0;
    pub const YAW_RATE_RAD_S: f64 = 0.5;
}

/// A run in progress.
#[derive(Clone)]
pub struct Simulation {
    scenario: Scenario,
    plant: Plant,
    x: State,
    ctl: Controllers,
    out: Outputs,
    t: f64,
    step: u64,
    /// The step and the loops' intervals.
    clock: Clock,
    next_command: usize,
    speed_cmd: f64,
    stored0: f64,
    trace: Trace,
    warnings: Vec<String>,
    /// Headings lost with the rudder hard over, sorted by cause (an ordered turn or the waves).
    heading_hold: heading_hold::HeadingHold,
    /// The seaway (None in calm water), the propellers' ventilation states and the loss model.
    sea: Option<seaway::Seaway>,
    vent: [Ventilation; N_SHAFTS],
    losses: LossParams,
    /// Where the ventilation loop starts and why (`seakeeping.ventilation_onset`), for the summary.
    onset: propeller_cavitation::Onset,
    /// Each propeller's last (beta_T, beta_Q).
    last_beta: [(f64, f64); N_SHAFTS],
    /// Calm-water hub depth \[m\] (the hull's) and each shaft's hub depth over the propeller
    /// radius at the current step's midpoint, the loss model's input \[-\].
    hub0: f64,
    h_over_r: [f64; N_SHAFTS],
    fuel_curve: Vec<(f64, f64)>,
    fuel_extrapolated: bool,
    /// Time of the first surface effect (beta_T < 1 on either shaft) \[s\].
    first_event: Option<f64>,
    /// Multi-rate stepping (`stepping.hull_substeps` > 1).
    multi: MultiRate,
    /// Which turbine-generator sets run, start or stop (`plant.online`, the orders' `online_sets`).
    sets: crate::plant::online::Sets,
    /// The step that opens the stage efficiencies' window, and the books there (at the start
    /// until then).
    window_step: u64,
    window: summary::WindowStart,
}

/// The multi-rate step's bookkeeping: the hull steps once per `substeps` drive-train steps.
#[derive(Debug, Clone, Copy)]
struct MultiRate {
    substeps: u64,
    /// First drive-train step of the present hull step.
    start: u64,
    /// The thrust account before the hull step \[J\] (its slot integrates the thrust \[N s\] over
    /// the drive-train steps).
    thrust_work: f64,
    /// The propellers' inflow over the hull step \[m/s\].
    va: f64,
    /// The hull's mean rate over its last step (surge, sway, yaw rate, x, y, heading), which
    /// carries the hull forward for the controllers and the seaway between its steps.
    rate: [f64; HULL_STATES],
}

/// The hull's states, from [`SURGE`] to [`HEADING`].
const HULL_STATES: usize = HEADING + 1 - SURGE;

impl MultiRate {
    /// The state at drive-train step `step` as the controllers and the seaway read it: the state
    /// itself at a hull step or with one rate (borrowed: no copy), else with the hull carried
    /// forward from its last step by that step's rate.
    fn state_now<'a>(&self, x: &'a State, step: u64, dt: f64) -> Cow<'a, State> {
        if !self.between_hull_steps(step) {
            return Cow::Borrowed(x);
        }
        let mut y = *x;
        let tau = (step - self.start) as f64 * dt;
        for (i, r) in self.rate.iter().enumerate() {
            y[SURGE + i] += r * tau;
        }
        Cow::Owned(y)
    }

    /// Whether drive-train step `step` falls between hull steps (where `state_now` moves the hull).
    fn between_hull_steps(&self, step: u64) -> bool {
        self.substeps > 1 && step % self.substeps != 0
    }
}

/// One clock for every loop of a run, built from `scenario.stepping` (and the run's length and
/// the seaway's refresh): the time step and, in steps, how often each loop samples.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Clock {
    /// Time step \[s\] and the fixed-step method (`stepping.dt_s`, `stepping.integrator`).
    dt: f64,
    method: crate::numerics::Integrator,
    /// Steps of the whole run.
    total_steps: u64,
    /// The controllers' sample in steps, and its length \[s\].
    ctl_every: u64,
    ts: f64,
    /// The recorded rows, the sea's samples and the RAO refresh, in steps.
    rec_every: u64,
    sea_every: u64,
    refresh_every: u64,
    /// Drive-train steps per hull step (1: one step for both).
    hull_substeps: u64,
}

impl Clock {
    fn new(sc: &Scenario) -> Clock {
        let st = &sc.stepping;
        let dt = st.dt_s;
        let every = |interval_s: f64| (interval_s / dt).round().max(1.0) as u64;
        let ctl_every = every(st.controller_sample_s);
        Clock {
            dt,
            method: st.integrator,
            total_steps: (sc.sim.duration_s / dt).round() as u64,
            ctl_every,
            ts: ctl_every as f64 * dt,
            rec_every: every(sc.sim.record_interval_s),
            sea_every: every(st.sea_sample_s),
            refresh_every: every(sc.seakeeping.rao_refresh_s),
            hull_substeps: st.hull_substeps.max(1) as u64,
        }
    }

    /// Room for the recorded rows of a whole run.
    fn rows(&self) -> usize {
        (self.total_steps / self.rec_every + 2) as usize
    }

    /// The step that opens the stage efficiencies' window (`summary::EFFICIENCY_WINDOW_S`, at
    /// most half the run), on a hull step's boundary so that the hull's books are whole there.
    fn window_step(&self) -> u64 {
        let window = (summary::EFFICIENCY_WINDOW_S / self.dt).round() as u64;
        let from = self.total_steps - window.min(self.total_steps / 2);
        from - from % self.hull_substeps
    }
}

impl Simulation {
    /// Builds the model and its initial state from a validated scenario.
    pub fn new(scenario: &Scenario) -> Result<Simulation, SimError> {
        Self::with_extra_resistance(scenario, 0.0)
    }

    /// The same with a constant added resistance \[N\] in the hull (the fuel study's steady states
    /// in regular seas: the mean second-order force).
    pub fn with_extra_resistance(scenario: &Scenario, extra: f64) -> Result<Simulation, SimError> {
        Ok(Self::prepare(scenario, extra)?.start())
    }

    /// The model, its seaway and its initial state, before the first sample of the sea.
    fn prepare(scenario: &Scenario, extra: f64) -> Result<Simulation, SimError> {
        scenario.validate().map_err(|e| SimError::Setup(e.to_string()))?;
        let mut plant = Plant::new(scenario).map_err(SimError::Setup)?;
        let hub0 = scenario.ship_hull().map_err(SimError::Setup)?.hub_depth_m;
        plant.extra_resistance = extra;
        // The ventilation loop: generic, or derived from the blades at the run's calm point.
        let onset = propeller_cavitation::onset(scenario, &plant).map_err(SimError::Setup)?;
        let clock = Clock::new(scenario);
        let trace = Trace::with_capacity(clock.rows());

        // The speed loop's calm-water map: propellers without surface losses (beta_T = 1), no
        // added resistance.
        let mut calm = plant.clone();
        calm.beta_t = 1.0;
        calm.beta_q = 1.0;
        calm.extra_resistance = 0.0;
        let mut speed = SpeedController::new(&scenario.controllers.speed, |u| calm.equilibrium_shaft_speed(u));
        if scenario.commands.iter().any(|c| c.astern()) {
            speed = speed.with_astern(crate::scenario::ASTERN_LIMIT_KN, |u| calm.equilibrium_shaft_speed_astern(u));
        }

        let mut sim = Simulation {
            scenario: scenario.clone(),
            x: [0.0; NX],
            ctl: Controllers {
                governor: [Governor::new(&scenario.controllers.governor, 0.0); N_SETS],
                field: [FieldController::new(&scenario.field_control(), 0.0, plant.generator.v_f_max); N_SETS],
                lqg: match scenario.controllers.design {
                    ControllerDesign::Pi => None,
                    ControllerDesign::LqgLtr => {
                        Some((lqg::LqgDesign::new(scenario, plant.generator.v_f_max)?, Vec::new()))
                    }
                },
                slip: [SlipController {
                    pi: DiscretePi::new(scenario.controllers.slip.kp, scenario.controllers.slip.ki, 0.0),
                    offset: scenario.controllers.slip.zero_slip_offset_rad_s,
                }; N_SHAFTS],
                peak_slip: [0.0; N_SHAFTS],
                speed,
                allow_braking: scenario.controllers.slip.allow_braking,
                peak_brake_slip: [0.0; N_SHAFTS],
                psi_ref: 0.0,
                psi_target: 0.0,
                heading_rate: 0.0,
                autopilot: Autopilot::new(&scenario.controllers.autopilot, &scenario.rudder),
                held: Held::default(),
                tracked: health::Tracked::default(),
            },
            plant,
            out: Outputs::default(),
            t: 0.0,
            step: 0,
            clock,
            next_command: 0,
            speed_cmd: 0.0,
            stored0: 0.0,
            trace,
            warnings: crate::plant::storage::ignored_without_energy(&scenario.plant.storage)
                .into_iter()
                .chain(crate::scenario::registry::ignored(&scenario.to_value()))
                .collect(),
            heading_hold: heading_hold::HeadingHold::default(),
            sea: seaway::Seaway::new(scenario).map_err(SimError::Setup)?,
            vent: [Ventilation::default(); N_SHAFTS],
            losses: onset.losses,
            onset,
            last_beta: [(1.0, 1.0); N_SHAFTS],
            hub0,
            h_over_r: [2.0 * hub0 / scenario.propeller.diameter_m; N_SHAFTS],
            fuel_curve: crate::plant::fuel::part_load_curve(),
            fuel_extrapolated: false,
            first_event: None,
            multi: MultiRate {
                substeps: clock.hull_substeps,
                start: 0,
                thrust_work: 0.0,
                va: 0.0,
                rate: [0.0; HULL_STATES],
            },
            sets: crate::plant::online::Sets::new(&scenario.plant.online),
            window_step: clock.window_step(),
            window: summary::WindowStart { time_s: 0.0, energy: [0.0; N_ENERGY], stores: Default::default() },
        };
        sim.sync_online();
        sim.initialise()?;
        Ok(sim)
    }

    /// The first step's part of `new` that the sea takes part in: the first sample, the stored
    /// energy, the commands of t = 0 and the first recorded row.
    fn start(mut self) -> Simulation {
        self.sea_step();
        self.stored0 = self.plant.stored_energy(&self.x);
        self.open_window();
        self.apply_commands();
        self.refresh_outputs();
        self.record();
        self
    }

    /// Initial state: idle (u0 = 0) or the calm-water steady state at the initial speed.
    fn initialise(&mut self) -> Result<(), SimError> {
        let sc = &self.scenario;
        let st = steady::calm_water(&self.plant, sc)?;
        for k in 0..N_SETS {
            self.x[slot::turbine_speed(k)] = st.turbine_speed;
            self.x[slot::field_current(k)] = st.field_current;
            self.ctl.governor[k] = Governor::new(&sc.controllers.governor, st.throttle);
            self.ctl.field[k] =
                FieldController::new(&sc.field_control(), st.field_voltage, self.plant.generator.v_f_max);
            self.ctl.held.throttle[k] = st.throttle;
            self.ctl.held.field_voltage[k] = st.field_voltage;
        }
        if let Some((d, sets)) = &mut self.ctl.lqg {
            *sets = vec![lqg::LqgSet::new(d, st.throttle, st.field_voltage); N_SETS];
        }
        for s in 0..N_SHAFTS {
            self.x[slot::bus_voltage(s)] = st.bus_voltage;
            self.x[slot::shaft_speed(s)] = st.shaft_speed;
            self.ctl.slip[s].pi.integral = st.slip;
            self.ctl.held.slip[s] = st.slip;
        }
        self.ctl.peak_slip = [st.peak_slip; N_SHAFTS];
        if self.plant.bus.any() {
            self.start_bus_parts(st.shaft_speed, st.ship_speed, st.bus_voltage)?;
        }
        self.x[SURGE] = st.ship_speed;
        self.ctl.speed.start(st.shaft_speed, st.ship_speed);
        Ok(())
    }

    /// The bus's parts at the steady state (`BusPart::start`: the ship service filter at rest, the
    /// storage at its charge set point with the bus's load as its low-passed load).
    fn start_bus_parts(&mut self, w_rm: f64, u0: f64, v_bus: f64) -> Result<(), SimError> {
        let p = &self.plant;
        let p_inv = if u0 > 0.0 {
            let v_max = p.dc_link.max_phase_voltage(v_bus);
            p.motor.operate_vhz(w_rm, self.ctl.held.slip[0], v_max).p_in
        } else {
            0.0
        };
        if let Some(l) = &p.bus.loads {
            self.ctl.held.bus = l.demand(0.0);
        }
        let p_load = p.bus.steady_load_w(v_bus, p_inv).map_err(SimError::Setup)?;
        p.bus.start(v_bus, p_load, &mut self.x[plant::slots(plant::Block::BusParts)]);
        Ok(())
    }

    /// Takes every command whose time has come.
    fn apply_commands(&mut self) {
        let cmds = &self.scenario.commands;
        let mut ordered = false;
        while self.next_command < cmds.len() && cmds[self.next_command].t_s <= self.t + 0.5 * self.clock.dt {
            let cmd = &cmds[self.next_command];
            if cmd.crash_stop {
                self.speed_cmd = kn_to_m_s(crate::scenario::ASTERN_LIMIT_KN);
            }
            self.ctl.speed.full_astern = cmd.crash_stop || (self.ctl.speed.full_astern && cmd.speed_kn.is_none());
            if let Some(kn) = cmd.speed_kn.filter(|_| !cmd.crash_stop) {
                self.speed_cmd = kn_to_m_s(kn);
                let h = &self.scenario.hull;
                if h.model == HullModelKind::Maneuvering
                    && h.forces == crate::ship::maneuvering::ManeuveringForces::Table23
                    && kn > 0.0
                    && (kn < h.handover_low_kn || kn > 32.0)
                {
                    self.warnings.push(format!(
                        "commands.{}.speed_kn = {kn}: the maneuvering model is trusted from {} to about 32 knots \
                         (fitted at 11 and {} knots); below {} knots surge follows the surge model",
                        self.next_command, h.handover_low_kn, h.linearization_speed_kn, h.handover_low_kn
                    ));
                }
            }
            if let Some(deg) = cmd.heading_deg {
                self.ctl.psi_target = deg_to_rad(deg);
                let rate = cmd.heading_rate_deg_s.unwrap_or(self.scenario.controllers.autopilot.turn_rate_deg_s);
                self.ctl.heading_rate = deg_to_rad(rate);
                let limit = rad_to_deg(self.max_turn_rate());
                if rate > limit {
                    self.warnings.push(format!(
                        "commands.{}: a turn at {rate} deg/s is faster than the autopilot holds for this hull at \
                         {:.1} knots ({limit:.2} deg/s, controllers.autopilot.max_turn_rate_nondim); it turns at that",
                        self.next_command,
                        m_s_to_kn(speed_through_water(&self.x))
                    ));
                }
            }
            if let Some(sets) = &cmd.online_sets {
                let wanted = crate::plant::online::mask(sets);
                let notes = self.sets.order(&wanted, self.t);
                self.warnings.extend(notes.into_iter().map(|n| format!("commands.{}: {n}", self.next_command)));
                ordered = true;
            }
            self.next_command += 1;
        }
        let moved = self.sets.advance(self.t);
        if ordered || moved {
            self.sync_online();
        }
    }

    /// Hands the sets' breakers to the plant: which sets deliver, and the bus tie closed while
    /// any is offline (on closing the two buses meet at their mean voltage: the charge of two
    /// equal capacitors shared).
    fn sync_online(&mut self) {
        let h = &mut self.ctl.held;
        h.online = self.sets.online();
        let tied = !self.sets.all_online();
        if tied && !h.tied {
            let mean = (0..N_SHAFTS).map(|s| self.x[slot::bus_voltage(s)]).sum::<f64>() / N_SHAFTS as f64;
            for s in 0..N_SHAFTS {
                self.x[slot::bus_voltage(s)] = mean;
            }
        }
        h.tied = tied;
    }

    /// Fastest turn the autopilot orders at the present speed \[rad/s\].
    fn max_turn_rate(&self) -> f64 {
        self.max_turn_rate_at(&self.x)
    }

    /// The same at state `x`.
    fn max_turn_rate_at(&self, x: &State) -> f64 {
        let l = self.plant.hull_length;
        self.scenario.controllers.autopilot.max_turn_rate_nondim * speed_through_water(x).max(1.0) / l
    }

    /// One sample of every discrete controller, loop by loop (`loops`).
    fn control(&mut self) {
        let (ts, t_now) = (self.clock.ts, self.t);
        let now = self.multi.state_now(&self.x, self.step, self.clock.dt);
        let x: &State = &now;
        let max_turn_rate = self.max_turn_rate_at(x);
        let (p, c) = (&self.plant, &mut self.ctl);
        let shaft_ref = c.speed_loop(x, self.speed_cmd, ts);
        c.set_loops(p, x, ts);
        c.track_overload(p, x, t_now, ts);
        c.slip_loops(p, x, shaft_ref, t_now, ts);
        if p.hull_model.turns() {
            let ref_before = c.psi_ref;
            let lag = c.heading_loop(x, max_turn_rate, ts);
            let rudder = c.held.rudder;
            let sample = heading_hold::Sample {
                ramping: c.psi_ref != ref_before,
                saturated: lag.is_some(),
                err: lag.unwrap_or(0.0),
                // Positive rudder turns the bow to port (a negative moment); M_add is positive
                // bow to starboard, so it opposes a positive rudder when positive.
                wave_against: if rudder >= 0.0 { c.held.sea.wave_mz } else { -c.held.sea.wave_mz },
                rudder_max: heading_hold::rudder_moment_at_limit(p, x, self.out.thrust, c.autopilot.max_angle),
                speed: speed_through_water(x),
            };
            self.heading_hold.observe(&sample);
        }
    }

    fn refresh_outputs(&mut self) {
        let mut dx = [0.0; NX];
        self.plant.evaluate(&self.x, &self.ctl.held, &mut self.out, &mut dx);
    }

    /// Checks the state after a step; names the subsystem that left its range.
    fn check(&self) -> Result<(), SimError> {
        let p = &self.plant;
        let bad = |sub: String, msg: String| Err(SimError::Diverged { time_s: self.t, subsystem: sub, message: msg });
        for k in 0..N_SETS {
            let w = self.x[slot::turbine_speed(k)];
            let (lo, hi) = limits::TURBINE_SPEED_PU;
            if !w.is_finite() || w < lo * p.turbine.rated_speed || w > hi * p.turbine.rated_speed {
                return bad(
                    format!("gas turbine {} (shaft {})", k + 1, k / SETS_PER_SHAFT + 1),
                    format!("speed {:.0} rpm outside {} % to {} % of rated", rad_s_to_rpm(w), lo * 100.0, hi * 100.0),
                );
            }
            let i_f = self.x[slot::field_current(k)];
            if !i_f.is_finite() || i_f.abs() > limits::FIELD_CURRENT_A {
                return bad(format!("generator {} field", k + 1), format!("field current {i_f:.3e} A"));
            }
        }
        let v_ref = self.scenario.bus_voltage_ref_v();
        for s in 0..N_SHAFTS {
            let v = self.x[slot::bus_voltage(s)];
            let (lo, hi) = limits::BUS_VOLTAGE_PU;
            if !v.is_finite() || v < lo * v_ref || v > hi * v_ref {
                return bad(
                    format!("DC bus {}", s + 1),
                    format!("voltage {v:.0} V outside {} % to {} % of the set point", lo * 100.0, hi * 100.0),
                );
            }
            let w = self.x[slot::shaft_speed(s)];
            if !w.is_finite() || w.abs() > limits::SHAFT_SPEED_OF_MAX_REF * self.ctl.speed.max_shaft_speed.max(1.0) {
                return bad(format!("propeller shaft {}", s + 1), format!("speed {:.0} rpm", rad_s_to_rpm(w)));
            }
        }
        let u = self.x[SURGE];
        if !u.is_finite() || u.abs() > limits::SURGE_M_S {
            return bad("ship surge".into(), format!("speed {:.1} knots", m_s_to_kn(u)));
        }
        let (v, r) = (self.x[SWAY], self.x[YAW_RATE]);
        if !v.is_finite() || v.abs() > limits::SWAY_M_S || !r.is_finite() || r.abs() > limits::YAW_RATE_RAD_S {
            return bad("hull sway-yaw".into(), format!("sway {v:.2} m/s, yaw rate {:.2} deg/s", rad_to_deg(r)));
        }
        if !self.x[X_POS].is_finite() || !self.x[Y_POS].is_finite() || !self.x[HEADING].is_finite() {
            return bad("ship position".into(), "non-finite position or heading".into());
        }
        if self.x[plant::slots(plant::Block::BusParts)].iter().any(|v| !v.is_finite()) {
            return bad("bus loads and storage".into(), "non-finite filter or storage state".into());
        }
        if self.x[ENERGY].iter().any(|v| !v.is_finite()) {
            return bad("energy accounts".into(), "non-finite energy".into());
        }
        Ok(())
    }

    fn record(&mut self) {
        let o = &self.out;
        let x = &self.x;
        let sea = match &self.sea {
            Some(s) => {
                let mut l = s.last;
                l.hub = l.hub_at(self.t);
                l
            }
            None => seaway::SeaSample::calm(self.hub0),
        };
        let mut fuel = 0.0;
        let eta = self.scenario.seakeeping.turbine_rated_efficiency;
        for k in 0..N_SETS {
            let (f, ex) = crate::plant::fuel::fuel_power(
                &self.fuel_curve,
                o.turbine_torque[k] * x[slot::turbine_speed(k)],
                self.scenario.plant.turbine.rated_power_w,
                eta,
            );
            fuel += f;
            self.fuel_extrapolated |= ex;
        }
        let rec = record::Recording {
            t: self.t,
            plant: &self.plant,
            x,
            out: o,
            ctl: &self.ctl,
            speed_cmd: self.speed_cmd,
            v_ref: self.scenario.bus_voltage_ref_v(),
            sea,
            // At the row's time, like `sea.hub`: the row's h/R is its hub depth over the radius.
            // The loss model's h/R (`self.h_over_r`) is the step's midpoint, half a step earlier
            // (up to 0.004 apart at 25 kn in SS6), which let the page draw the disc out of the
            // water under a label h/R >= 1.
            h_over_r: sea.hub.map(|h| h / (0.5 * self.plant.prop_diameter)),
            p_turbine: (0..N_SETS).map(|k| o.turbine_torque[k] * x[slot::turbine_speed(k)]).sum(),
            p_motor: (0..N_SHAFTS).map(|s| o.motor[s].torque * x[slot::shaft_speed(s)]).sum(),
            fuel,
        };
        let row = record::row(&rec);
        for (col, v) in self.trace.columns.iter_mut().zip(row) {
            col.push(v);
        }
    }

    /// Simulated time now \[s\].
    pub fn time(&self) -> f64 {
        self.t
    }

    /// Fraction of the run done, 0 to 1.
    pub fn progress(&self) -> f64 {
        if self.clock.total_steps == 0 {
            1.0
        } else {
            self.step as f64 / self.clock.total_steps as f64
        }
    }

    /// Whether the run has reached its duration.
    pub fn done(&self) -> bool {
        self.step >= self.clock.total_steps
    }

    /// The seaway's part of a step: RAO refresh and wave sums when due, then the hub depth at
    /// the middle of the step and the propellers' surface losses held over it.
    fn sea_step(&mut self) {
        let now = self.multi.state_now(&self.x, self.step, self.clock.dt);
        let x: &State = &now;
        let Some(sea) = self.sea.as_mut() else { return };
        if self.step % self.clock.refresh_every == 0 {
            let k = &self.scenario.seakeeping;
            sea.refresh_if_moved(
                speed_through_water(x),
                x[HEADING],
                k.rao_refresh_speed_m_s,
                k.rao_refresh_heading_deg.to_radians(),
            );
        }
        if self.step % self.clock.sea_every == 0 {
            let (sp, cp) = (libm::sin(x[HEADING]), libm::cos(x[HEADING]));
            let xd = x[SURGE] * cp - x[SWAY] * sp;
            let yd = x[SURGE] * sp + x[SWAY] * cp;
            let s = sea.sample(self.t, x[X_POS], x[Y_POS], xd, yd);
            self.ctl.held.sea.wave_fx = s.fx;
            self.ctl.held.sea.wave_fy = s.fy;
            self.ctl.held.sea.wave_mz = s.mz;
        }
        let hub = sea.last.hub_at(self.t + 0.5 * self.clock.dt);
        let radius = 0.5 * self.plant.prop_diameter;
        self.h_over_r = hub.map(|h| h / radius);
        if !self.scenario.seakeeping.surface_losses {
            return;
        }
        for s in 0..N_SHAFTS {
            let h_r = self.h_over_r[s];
            let n_hz = x[slot::shaft_speed(s)] / (2.0 * PI);
            let tv = self.vent[s].step(&self.losses, h_r, n_hz, self.clock.dt);
            // Eq. 2.13's beta_T = beta_TA beta_TV, beta_Q = beta_T^m; beta_T holds for many steps
            // while a propeller is ventilated (0.3): then beta_Q is the last one, without pow.
            let bt = beta_out_of_water(h_r) * tv;
            let bq = if bt == self.last_beta[s].0 { self.last_beta[s].1 } else { torque_factor(&self.losses, bt) };
            self.last_beta[s] = (bt, bq);
            self.ctl.held.sea.beta_t[s] = bt;
            self.ctl.held.sea.beta_q[s] = bq;
            if bt < 1.0 && self.first_event.is_none() {
                self.first_event = Some(self.t);
            }
        }
    }

    /// One drive-train step of the multi-rate scheme, and the hull's step when it ends one: the
    /// drive train steps with the hull held and the propellers' inflow fixed; the hull then
    /// steps over all of them under their mean thrust (the thrust's impulse integrated in the
    /// thrust account's slot), and the thrust's work is booked at the hull's speed, so the
    /// energy accounts close as with one step.
    fn multi_rate_step(&mut self) {
        let thrust_slot = ENERGY0 + Energy::Thrust as usize;
        let m = &mut self.multi;
        if self.step % m.substeps == 0 {
            m.start = self.step;
            m.thrust_work = self.x[thrust_slot];
            self.x[thrust_slot] = 0.0;
            m.va = self.plant.inflow(self.x[SURGE], self.x[SWAY], self.x[YAW_RATE]).speed;
        }
        drive_step(&self.plant, &mut self.x, &self.ctl.held, m.va, self.clock.dt, self.clock.method);
        let done = self.step + 1;
        if done % m.substeps == 0 || done == self.clock.total_steps {
            let span = (done - m.start) as f64 * self.clock.dt;
            let thrust = self.x[thrust_slot] / span;
            self.x[thrust_slot] = m.thrust_work;
            let before = self.x;
            hull_step(&self.plant, &mut self.x, &self.ctl.held, thrust, span, self.clock.method);
            for (i, r) in m.rate.iter_mut().enumerate() {
                *r = (self.x[SURGE + i] - before[SURGE + i]) / span;
            }
        }
    }

    /// Advances by at most `max_steps` time steps (stopping at the end of the run).
    pub fn advance(&mut self, max_steps: u64) -> Result<(), SimError> {
        self.advance_probed(max_steps, &mut NoProbe)
    }

    /// The same, telling `probe` where each part of every step ends (`aes-sim bench`'s account
    /// of where a run's time goes); the run is the same, bit for bit.
    #[inline(always)]
    pub fn advance_probed(&mut self, max_steps: u64, probe: &mut impl StepProbe) -> Result<(), SimError> {
        let end = (self.step + max_steps).min(self.clock.total_steps);
        while self.step < end {
            if self.step % self.clock.ctl_every == 0 {
                self.control();
            }
            probe.done(StepPart::Controllers);
            if self.sea.is_some() && self.step > 0 {
                self.sea_step();
            }
            probe.done(StepPart::Sea);
            if let Some(l) = &self.plant.bus.loads {
                // The loads' profile at the step's middle, held over it.
                self.ctl.held.bus = l.demand(self.t + 0.5 * self.clock.dt);
            }
            if self.multi.substeps == 1 {
                plant_step(&self.plant, &mut self.x, &self.ctl.held, self.clock.dt, self.clock.method);
            } else {
                self.multi_rate_step();
            }
            probe.done(StepPart::Plant);
            if self.sea.is_some() && !self.x[HEADING].is_finite() {
                return Err(SimError::Diverged {
                    time_s: self.t,
                    subsystem: "seaway".into(),
                    message: "non-finite ship state in waves".into(),
                });
            }
            self.step += 1;
            self.t = self.step as f64 * self.clock.dt;
            self.check()?;
            if self.step == self.window_step {
                self.open_window();
            }
            self.apply_commands();
            if self.step % self.clock.rec_every == 0 {
                self.refresh_outputs();
                self.record();
            }
            probe.done(StepPart::Rest);
        }
        Ok(())
    }

    /// The seaway (None in calm water).
    pub fn seaway(&self) -> Option<&seaway::Seaway> {
        self.sea.as_ref()
    }

    /// The trace recorded so far (also after a failed step: what led up to the failure).
    pub fn trace(&self) -> &Trace {
        &self.trace
    }

    /// The state vector now (for tests and analysis). With `stepping.hull_substeps` > 1 between hull
    /// steps the hull's states are those of its last step and the thrust account's slot holds
    /// the thrust's impulse since then \[N s\].
    pub fn state(&self) -> &State {
        &self.x
    }

    /// The inputs held over the present step (controller outputs and the sea's).
    pub fn held(&self) -> &Held {
        &self.ctl.held
    }

    /// The model constants.
    pub fn plant(&self) -> &Plant {
        &self.plant
    }

    /// Time of the first surface effect (beta_T < 1) so far \[s\].
    pub fn first_surface_event(&self) -> Option<f64> {
        self.first_event
    }

    /// Record interval in steps and time step \[s\].
    pub fn record_every(&self) -> u64 {
        self.clock.rec_every
    }

    /// Shaft power of each gas turbine now \[W\].
    pub fn turbine_power(&mut self) -> [f64; N_SETS] {
        self.refresh_outputs();
        std::array::from_fn(|k| self.out.turbine_torque[k] * self.x[slot::turbine_speed(k)])
    }

    /// Books the energies and stores now as the start of the stage efficiencies' window.
    fn open_window(&mut self) {
        let energy = self.x[ENERGY].try_into().unwrap_or([0.0; N_ENERGY]);
        self.window = summary::WindowStart { time_s: self.t, energy, stores: self.plant.stage_stores(&self.x) };
    }

    /// Ends the run: the trace and its summary.
    pub fn finish(mut self) -> RunResult {
        self.refresh_outputs();
        let energy: [f64; N_ENERGY] = self.x[ENERGY].try_into().unwrap_or([0.0; N_ENERGY]);
        let stored_change = self.plant.stored_energy(&self.x) - self.stored0;
        let lost = self.heading_hold.warnings(self.sea.is_some());
        self.warnings.extend(lost);
        let health = health::assess(&self.scenario, &self.trace, &self.ctl.tracked);
        self.warnings.extend(health);
        let summary = Summary::build(
            &self.scenario,
            &self.trace,
            self.t,
            self.step,
            summary::Books {
                energy: &energy,
                stored_change,
                window: &self.window,
                stores: self.plant.stage_stores(&self.x),
            },
            std::mem::take(&mut self.warnings),
        );
        let summary =
            Summary { propeller: summary::GeometryNote::of(&self.scenario, &self.trace, &self.onset), ..summary };
        RunResult { trace: self.trace, summary }
    }
}

/// The parts of a time step, as a [`StepProbe`] is told of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepPart {
    /// The controllers' sample, when one is due.
    Controllers = 0,
    /// The seaway: RAO look-ups and wave sums when due, the hub depth, the propellers'
    /// ventilation.
    Sea,
    /// The plant's step (the integrator's stages; in the multi-rate scheme the drive train's step
    /// and the hull's when due).
    Plant,
    /// The checks, the commands and the recorded rows.
    Rest,
}

/// Told at the end of each part of every step ([`Simulation::advance_probed`]): a benchmark reads
/// its clock there (core keeps no clock: the browser's wasm has none).
pub trait StepProbe {
    fn done(&mut self, part: StepPart);
}

/// The probe of a plain run: nothing (inlined away).
struct NoProbe;

impl StepProbe for NoProbe {
    #[inline(always)]
    fn done(&mut self, _: StepPart) {}
}

/// A scenario's run built up to its start without its sea (the plant, the calm-water speed map,
/// the steady state, the controllers): runs of the same scenario in the seas of other seeds (a
/// Monte Carlo study's trials) start from a copy of it instead of building all of it again.
#[derive(Clone)]
pub struct Prototype {
    sim: Simulation,
}

impl Prototype {
    /// The run of `scenario` (with any seed) up to its start; the errors `Simulation::new` gives.
    pub fn new(scenario: &Scenario) -> Result<Prototype, SimError> {
        // Built with its own sea, so that a scenario whose seaway cannot be made fails here as in
        // `new`; nothing before the first sample depends on the sea, and the trials bring theirs.
        let mut sim = Simulation::prepare(scenario, 0.0)?;
        sim.sea = None;
        Ok(Prototype { sim })
    }

    /// The run in the sea of `seed`: the same, bit for bit, as `Simulation::new` of the scenario
    /// with that seed.
    pub fn with_seed(&self, seed: u64) -> Result<Simulation, SimError> {
        let mut sim = self.sim.clone();
        sim.scenario.sim.seed = seed;
        sim.sea = seaway::Seaway::new(&sim.scenario).map_err(SimError::Setup)?;
        // A clone keeps the rows' length, not their room.
        sim.trace = Trace::with_capacity(sim.clock.rows());
        Ok(sim.start())
    }
}

/// Runs a scenario to its end.
pub fn run(scenario: &Scenario) -> Result<RunResult, SimError> {
    let mut sim = Simulation::new(scenario)?;
    sim.advance(u64::MAX)?;
    Ok(sim.finish())
}

/// Speed through the water sqrt(u^2 + v^2) \[m/s\]; written out (not `hypot`, which calls the
/// platform's libm) so native and wasm runs agree to the bit.
pub(crate) fn speed_through_water(x: &State) -> f64 {
    (x[SURGE] * x[SURGE] + x[SWAY] * x[SWAY]).sqrt()
}

#[cfg(test)]
mod csv_tests {
    use super::*;

    /// The CSV is Display's text of every number, byte for byte, also where a number repeats the
    /// one above it (its text copied), for zeros of both signs, NaN and infinities.
    #[test]
    fn to_csv_writes_display_text() {
        let edge = [0.0, -0.0, f64::NAN, f64::INFINITY, -f64::INFINITY, 1e300, 5e-324, 0.1 + 0.2, 1.0];
        let columns: Vec<Vec<f64>> = (0..N_SIGNALS)
            .map(|i| {
                (0..40)
                    .map(|r| {
                        if (r + i) % 3 == 0 {
                            edge[(r / 3 + i) % edge.len()]
                        } else {
                            (r / 2) as f64 * 0.37 - i as f64
                        }
                    })
                    .collect()
            })
            .collect();
        let trace = Trace { columns };
        let mut want = crate::signals::names().collect::<Vec<_>>().join(",");
        want.push('\n');
        for r in 0..trace.len() {
            let row: Vec<String> = trace.columns.iter().map(|c| format!("{}", c[r])).collect();
            want.push_str(&row.join(","));
            want.push('\n');
        }
        assert_eq!(trace.to_csv(), want);
    }
}
