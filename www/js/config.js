// Presentation choices only: what the page shows and how. Every number of the model (ratings,
// levels, bands, lengths, gravity) comes from the wasm (signalMeta, pageConstants); units and
// labels of recorded signals come from signalMeta. Nothing here is a physics value.

// Parameters shown in the form, grouped as a naval engineer thinks of them.
// [path, label, unit, help, choices?]. The form adds the preset's value to each help line.
export const FIELDS = [
  ['Ship and hull', [
    ['ship.mass_kg', 'Displaced mass', 'kg', 'Table 5.1.'],
    ['ship.wetted_area_m2', 'Wetted area', 'm²', 'Table 5.1.'],
    ['ship.drag_coeff', 'Drag coefficient C_r', '-', 'Eq. 2.15, Table 5.1.'],
    ['ship.wake_fraction', 'Wake fraction w', '-', 'Eq. 2.12, Table 5.1.'],
    ['ship.thrust_deduction', 'Thrust deduction t', '-', 'Eq. 2.15, Table 5.1.'],
    ['hull.model', 'Hull model', '', 'surge: straight line (ch. 2.3); maneuvering: Abkowitz 3-DOF with rudder (ch. 2.4).', ['surge', 'maneuvering']],
  ]],
  ['Propulsion plant', [
    ['propeller.model', 'Propeller model', '', 'B-series (first quadrant) or four-quadrant B4-70 (needed for braking).', ['b_series', 'four_quadrant']],
    ['propeller.diameter_m', 'Propeller diameter', 'm', 'Table 5.1.'],
    ['propeller.pitch_ratio', 'Pitch ratio P/D', '-', 'Table 5.1.'],
    ['propeller.blades', 'Blades', '-', 'Within the Wageningen B-series range.'],
    ['plant.turbine.inertia_kg_m2', 'Turbine inertia', 'kg m²', 'Table 5.2.'],
    ['plant.motor.rated_power_w', 'Motor rating', 'W', 'Ch. 2.2.2; the base of motor power in per unit.'],
    ['plant.dc_link.capacitance_f', 'Bus capacitance', 'F', 'Table 5.4.'],
    ['plant.dc_link.rectifier', 'Rectifier', '', 'diode: power flows one way; reversible: it can flow back to the turbines.', ['diode', 'reversible']],
    ['plant.dc_link.brake_resistor_ohm', 'Brake resistor', 'Ω', '0 for none.'],
  ]],
  ['Controllers', [
    ['controllers.governor.kp', 'Governor K_p,t', '1/pu', 'Throttle per per-unit speed error.'],
    ['controllers.governor.slew_rate_per_s', 'Throttle slew limit', '1/s', 'Fuel schedule limit.'],
    ['controllers.field.kp', 'Field K_p,v', 'V/V', 'Ch. 5.2.1 baseline.'],
    ['controllers.field.ki', 'Field K_i,v', 'V/(V s)', 'Ch. 5.2.1 baseline.'],
    ['controllers.speed.shaft_ramp_rpm_per_s', 'Shaft ramp', 'rpm/s', '0 for a step.'],
    ['controllers.slip.allow_braking', 'Allow AC braking', '', 'Negative slip: the motor brakes as a generator.', ['false', 'true']],
    ['controllers.autopilot.turn_rate_deg_s', 'Default turn rate', 'deg/s', 'Used when a heading order gives none.'],
  ]],
  ['Sea and seakeeping', [
    ['sea.kind', 'Sea', '', 'calm; random: Bretschneider spectrum (eq. 2.58) of a Table 2.4 sea state; regular: one wave.', ['calm', 'random', 'regular']],
    ['sea.sea_state', 'Sea state', '-', 'Table 2.4 gives each sea state\'s significant height and peak frequency.'],
    ['sea.from_deg', 'Waves from', 'deg', '0 = from north: head seas for a ship heading north.'],
    ['sea.components', 'Wave components N_s', '-', 'Ch. 2.5.4.'],
    ['sea.amplitude_m', 'Regular wave amplitude', 'm', '1 ft = 0.3048 m.'],
    ['sea.omega_rad_s', 'Regular wave frequency', 'rad/s', 'Wave length 2 pi g / omega^2.'],
    ['seakeeping.hub_depth_m', 'Calm-water hub depth h0', 'm', 'Ch. 5.3 and ch. 5.4.1 use different depths.'],
    ['seakeeping.stern_motion', 'Hub depth formula', '', 'consistent: the stern follows long waves; thesis_eq_2_57: the printed sign, which reproduces the thesis figures.', ['consistent', 'thesis_eq_2_57']],
    ['monte_carlo.trials', 'Monte Carlo trials', '-', 'For the Monte Carlo button (ch. 5.4).'],
  ]],
  ['Simulation', [
    ['initial.speed_kn', 'Initial speed', 'kn', '0 starts from idle.'],
    ['sim.duration_s', 'Duration', 's', 'Simulated time.'],
    ['sim.dt_s', 'Time step', 's', 'RK4 step.'],
    ['sim.record_interval_s', 'Record every', 's', 'A whole number of steps.'],
    ['sim.seed', 'Seed', '-', 'Fixes every random number.'],
  ]],
];

export const ORDERS_HELP = 'Orders: [{"t_s": 0, "speed_kn": 25}, {"t_s": 10, "heading_deg": 90, "heading_rate_deg_s": 0.5}]';
export const ORDERS_LABEL = 'Orders as JSON: time [s], speed [kn], heading [deg], heading rate [deg/s]';

// What each study shows, for a class (added to the preset's own description).
export const ABOUT_EXTRA = {
  'startup': 'Watch the power inventory: each stage passes on a little less than it gets (Table 5.6).',
  'acceleration': 'Compare turbine speed and bus voltage with Fig. 5-4; then try the higher field gains.',
  'acceleration-high-gains': 'The bus voltage now recovers faster than the turbine speed (Fig. 5-5).',
  'ac-braking': 'Motor power turns negative: the ship drives the propellers and the brake resistor burns the energy (Fig. 5-7).',
  'ac-braking-unbuffered': 'No resistor: the energy goes back into the turbines, which overspeed with the throttle shut (Fig. 5-8).',
  'turn-45': 'The ship track, rudder and the extra motor power needed to hold speed (Figs. 5-9, 5-10).',
  'turn-90': 'A longer turn at the same rate: similar extra power, for longer.',
  'turn-360': 'A full turn in calm water (Fig. 5-16 without the waves); note the counter-rudder in the steady turn.',
  'quarter-turn-ss3': 'Added resistance slows the ship a little; after the turn the sea is on the beam and the drift force appears (Fig. 5-11).',
  'quarter-turn-ss6': 'The same turn in sea state 6: over 40 times the added resistance of SS3 (it grows with the square of the wave height).',
  'fuel-regular-seas': 'One regular head wave of 1 ft: compare fuel power with calm water; the command line sweeps 1 to 5 ft (Fig. 5-12).',
  'head-seas-ss6': 'h/R against the ventilation band: with the consistent hub depth the propeller stays down; switch the hub depth formula to thesis_eq_2_57 to see the thesis\' ventilation and power swings (Figs. 5-13 to 5-15).',
  'turn-360-ss6': 'Heave and pitch are strong in head seas and weak in following seas (Figs. 5-16 to 5-19).',
  'mc-excess-energy': 'Press Monte Carlo: 100 seas, the envelope of motor power, the excess energy per trial and its histogram (Figs. 5-20 to 5-23).',
  'mc-arrival': 'Press Monte Carlo: arrival times of the first surface effect against Rice\'s prediction (Table 5.8, Fig. 5-24).',
};

// The per-unit signals and the pageConstants entry that is their base, with its unit.
export const PU_BASES = {
  turbine_speed_pu: { constant: 'turbine_rated_speed_rpm', unit: 'rpm' },
  bus_voltage_pu: { constant: 'bus_voltage_ref_v', unit: 'V' },
  im_power_pu: { constant: 'motor_rated_power_w', unit: 'W' },
};

// Plots of a run. Each series is a trace column: its label and unit come from signalMeta (label
// overrides a meta label only to add a sign convention). `prefix` shows W as MW, N as kN.
// The axis label and the unit in the title are built from the series' units; series of different
// units go on a left and a right axis. `sea`: only in waves. `hOverR`: adds the ventilation band
// and the levels of pageConstants. `only`: drawn when it holds for the columns.
export const PLOTS = [
  { title: 'Ship speed', series: [{ signal: 'ship_speed_kn', color: '#0b5cad' }, { signal: 'speed_cmd_kn', color: '#999' }] },
  { title: 'Propeller speed', series: [{ signal: 'prop_rpm', color: '#0b5cad' }, { signal: 'prop_rpm_ref', color: '#999' }] },
  { title: 'Bus voltage and turbine speed', series: [{ signal: 'bus_voltage_pu', color: '#c0392b' }, { signal: 'turbine_speed_pu', color: '#27ae60' }] },
  { title: 'Motor power', series: [{ signal: 'im_power_pu', color: '#8e44ad' }] },
  { title: 'Power inventory', prefix: 'M', series: [{ signal: 'p_turbine_w', color: '#27ae60' }, { signal: 'p_generator_w', color: '#16a085' }, { signal: 'p_inverter_w', color: '#2980b9' }, { signal: 'p_motor_w', color: '#8e44ad' }, { signal: 'p_ship_w', color: '#2c3e50' }] },
  { title: 'Rudder and heading', series: [{ signal: 'rudder_deg', color: '#d35400' }, { signal: 'heading_deg', color: '#0b5cad' }, { signal: 'heading_ref_deg', color: '#999' }] },
  { title: 'Hub depth over propeller radius h/R', sea: true, hOverR: true, series: [{ signal: 'h_over_r', color: '#0b5cad' }] },
  { title: 'Propeller surface losses beta_T, beta_Q', sea: true, series: [{ signal: 'beta_t', color: '#c0392b' }, { signal: 'beta_q', color: '#8e44ad' }] },
  { title: 'Wave at the stern and hub depth', sea: true, series: [{ signal: 'wave_stern_m', color: '#2980b9' }, { signal: 'hub_depth_m', color: '#2c3e50' }] },
  { title: 'Heave', sea: true, series: [{ signal: 'heave_m', label: 'heave (up)', color: '#16a085' }] },
  { title: 'Pitch and roll', sea: true, series: [{ signal: 'pitch_deg', label: 'pitch (bow down)', color: '#d35400' }, { signal: 'roll_deg', label: 'roll (starboard down)', color: '#7f8c8d' }] },
  { title: 'Second-order wave force', sea: true, prefix: 'k', series: [{ signal: 'added_resistance_n', color: '#c0392b' }, { signal: 'drift_force_n', label: 'drift force (to starboard)', color: '#2980b9' }] },
  { title: 'Fuel power, four turbines', prefix: 'M', series: [{ signal: 'fuel_power_w', color: '#6e2c00' }] },
  { title: 'Brake resistor power', prefix: 'M', series: [{ signal: 'brake_power_w', color: '#c0392b' }], only: (c) => c.brake_power_w.some((v) => v > 0) },
];
// Colours of the h/R levels (in pageConstants order) and of the ventilation band.
export const LEVEL_COLORS = ['#c0392b', '#922b21', '#7b241c'];
export const BAND_COLOR = '#e67e22';
export const BAND_FILL = 'rgba(230, 126, 34, 0.15)';

// The ship track: a mark and heading arrow every TRACK_MARK_S of simulated time; the picture
// spans at least TRACK_MIN_SPAN_M (a short run is not blown up to fill it).
export const TRACK_MARK_S = 60;
export const TRACK_MIN_SPAN_M = 200;

// Rows of the summary table (labels and units from signalMeta).
export const SUMMARY_ROWS = ['ship_speed_kn', 'prop_rpm', 'turbine_speed_pu', 'bus_voltage_pu', 'im_power_pu', 'thrust_kn'];

// After a run in waves: RAOs over wave length / Lpp, in head and bow seas.
export const RAO = { lambdaFrom: 0.3, lambdaStep: 0.045, points: 60, headings: [[180, 'head'], [135, 'bow']] };
// After a run in a regular sea: the fuel study (Fig. 5-12) at these wave frequencies [rad/s].
export const FUEL_OMEGAS = Array.from({ length: 13 }, (_, i) => 0.3 + 0.1 * i);
export const FUEL_COLORS = ['#aed6f1', '#5dade2', '#2e86c1', '#1f618d', '#154360'];

// Monte Carlo in the page: trial limit, at most this many workers, the periodogram's upper
// frequency on the plot, and the signal of the onset plot (the study's motor power, ch. 5.4.3).
export const MC = { maxTrials: 100000, maxWorkers: 4, periodogramMaxHz: 1.0, onsetSignal: 'im_power_pu',
  calmWaterNote: 'thesis: 94.1 ± 33.3' };

// Stability tab: the Bode range and the pole map's radius (faster poles are listed, not drawn).
// The testbed's synchronous speed is an operating-point input like the sliders.
export const IPS = { omegaRadS: 377, fromHz: 0.01, toHz: 1000, points: 300, poleMapMax: 2000, debounceMs: 60 };

// Progress reports while running: at most one per this many milliseconds; steps per chunk.
export const RUN_CHUNK_STEPS = 20000;
export const PROGRESS_EVERY_MS = 100;

export const STORE_KEY = 'aes-sim/edits/v1';

// The study shown first, and when a link cannot be used.
export const DEFAULT_PRESET = 'startup';
