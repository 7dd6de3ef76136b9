// Presentation choices only: what the page shows and how. Every number of the model (ratings,
// levels, bands, lengths, gravity) comes from the wasm (signalMeta, pageConstants); units and
// labels of recorded signals come from signalMeta. Nothing here is a physics value.
import { RUDDER_SIGN } from './units.js';

// The scenario form is made from the wasm's paramMeta (labels, units, help, ranges, choices and
// each parameter's group are declared once, in core). Here only where a group goes on the page
// (an element id other than the full form) and which fields get a line the page fills (h0 under
// the hub height).
export const FORM_PLACES = {
  into: { 'hull-loading': 'hull-loading' },
  derived: { 'ship.hull.hub_above_base_m': 'h0' },
};

// The studies as the page offers them: grouped by thesis chapter, each with a human name, what to
// watch, the plots that tell its story first (ids of PLOTS; the others one click away), the
// parameters that matter on top, and one-click comparisons ("compare with ..."): another study,
// or this one with some values changed. `about` replaces the preset's description in the page.
export const CHAPTERS = [
  ['Ch. 5.1 Start-up', ['startup']],
  ['Ch. 5.2.1 Acceleration', ['acceleration', 'acceleration-high-gains', 'acceleration-lqg-ltr']],
  ['Ch. 5.2.2 Braking', ['ac-braking', 'ac-braking-unbuffered']],
  ['Ch. 5.2.3 Turns in calm water', ['turn-45', 'turn-90', 'turn-360']],
  ['Ch. 5.2.4 Turns and fuel in waves', ['quarter-turn-ss3', 'quarter-turn-ss6', 'fuel-regular-seas']],
  ['Ch. 5.3 Head seas and a turn in waves', ['head-seas-ss6', 'head-seas-ss6-storage', 'turn-360-ss6', 'as-printed']],
  ['Ch. 5.4 Monte Carlo', ['mc-excess-energy', 'mc-arrival']],
  ['Any hull (ch. 2.5)', ['wigley-head-seas', 'mc-wigley']],
];

export const STUDIES = {
  'startup': { title: 'Start-up from idle to 25 knots', plots: ['inventory', 'bus', 'speed', 'rpm', 'motor'], params: ['ship.drag_coeff', 'controllers.governor.kp', 'sim.duration_s'],
    watch: 'The power inventory: each stage passes on a little less than it gets, turbine to generator to motor to ship. The table of efficiencies under the summary gives the numbers of Tables 5.6 and 5.7.' },
  'acceleration': { title: 'Acceleration: step to full ahead', plots: ['bus', 'speed', 'rpm', 'motor'], params: ['controllers.field.kp', 'controllers.field.ki', 'controllers.speed.shaft_ramp_rpm_per_s'],
    watch: 'Turbine speed and bus voltage dip when the motors take the load (Fig. 5-4). Then compare with higher field gains: the voltage recovers faster.',
    compare: [{ label: 'higher field gains', preset: 'acceleration-high-gains' }, { label: 'the LQG/LTR controller (ch. 3.1)', preset: 'acceleration-lqg-ltr' }] },
  'acceleration-high-gains': { title: 'Acceleration with higher field gains', plots: ['bus', 'speed', 'rpm', 'motor'], params: ['controllers.field.kp', 'controllers.field.ki'],
    watch: 'The bus voltage now recovers faster than the turbine speed (Fig. 5-5).',
    compare: [{ label: 'the normal gains', preset: 'acceleration' }] },
  'acceleration-lqg-ltr': { title: 'Acceleration with the LQG/LTR controller (ch. 3.1)', plots: ['bus', 'speed', 'rpm', 'motor'], params: ['controllers.lqg_ltr.q', 'controllers.lqg_ltr.mu', 'controllers.lqg_ltr.turbine_speed_weight'],
    watch: 'One multivariable controller per set moves throttle and field together. The step from 0.34 to 1 pu of motor power is more than the turbines can follow: set the turbine-speed weight to 1 and the controller holds the bus with the turbines\' kinetic energy until they stall; at the preset\'s 10 it ends much like the PI loops. On the thesis\' own ship (as_printed.table_5_ship with hull.forces = "table_2_3", in the JSON editor) the step is smaller and equal weights hold the bus within 5 %.',
    compare: [{ label: 'the PI loops', preset: 'acceleration' }, { label: 'equal weights', set: { 'controllers.lqg_ltr.turbine_speed_weight': 1 } }] },
  'ac-braking': { title: 'Slowing down 25 to 10 knots by AC braking, with a brake resistor', plots: ['motor', 'brake', 'bus', 'speed', 'rpm'], params: ['plant.dc_link.brake_resistor_ohm', 'plant.dc_link.rectifier', 'controllers.slip.allow_braking'],
    watch: 'Motor power turns negative: the water drives the propellers, the motors brake as generators and the resistor burns the energy (Fig. 5-7).',
    compare: [{ label: 'no brake resistor', preset: 'ac-braking-unbuffered' }] },
  'ac-braking-unbuffered': { title: 'Slowing down 25 to 10 knots by AC braking, without a brake resistor', plots: ['bus', 'motor', 'speed', 'rpm'], params: ['plant.dc_link.rectifier', 'controllers.governor.kp'],
    watch: 'No resistor: the braking energy flows back into the turbines, which overspeed with the throttle shut (Fig. 5-8).',
    compare: [{ label: 'the brake resistor', preset: 'ac-braking' }] },
  'crash-stop': { title: 'Crash stop from 25 knots: full astern at once', plots: ['motor', 'brake', 'bus', 'speed', 'rpm'], params: ['plant.dc_link.brake_resistor_ohm', 'controllers.speed.shaft_ramp_rpm_per_s', 'plant.storage.energy_j'],
    watch: 'The shafts go through zero to astern. While the motors brake them their power is negative and the brake resistors burn what the buses cannot hold; then the motors take power again to drive the ship astern. The ship speed (through the water, unsigned) falls to zero about 48 s after the order and rises again as the ship goes astern.',
    compare: [{ label: 'with storage', preset: 'crash-stop-storage' }] },
  'crash-stop-storage': { title: 'Crash stop from 25 knots with storage on the buses', plots: ['motor', 'brake', 'bus', 'speed', 'rpm'], params: ['plant.storage.energy_j', 'plant.storage.power_w', 'plant.dc_link.brake_resistor_ohm'],
    watch: 'The storage takes the returned energy: the brake resistors burn far less than without it, and the bus stays lower.',
    compare: [{ label: 'without storage', preset: 'crash-stop' }] },
  'turn-45': { title: 'A 45° turn at 25 knots', plots: ['track', 'rudder', 'motor', 'speed'], params: ['controllers.autopilot.turn_rate_deg_s', 'initial.speed_kn'],
    watch: 'The rudder (right axis, a few degrees) against the heading (left axis), and the extra motor power needed to hold speed in the turn (Figs. 5-9, 5-10).',
    compare: [{ label: 'a 90° turn', preset: 'turn-90' }] },
  'turn-90': { title: 'A 90° turn at 25 knots', plots: ['track', 'rudder', 'motor', 'speed'], params: ['controllers.autopilot.turn_rate_deg_s', 'initial.speed_kn'],
    watch: 'A longer turn at the same rate: similar extra power, for longer.', compare: [{ label: 'a 45° turn', preset: 'turn-45' }] },
  'turn-360': { title: 'A full turn in calm water', plots: ['track', 'rudder', 'motor', 'speed'], params: ['controllers.autopilot.turn_rate_deg_s', 'initial.speed_kn'],
    watch: 'In the steady turn the rudder settles at a small counter angle; speed drops and motor power rises to hold it (Fig. 5-16 without waves).',
    compare: [{ label: 'the same turn in sea state 6', preset: 'turn-360-ss6' }] },
  'quarter-turn-ss3': { title: 'A quarter turn in sea state 3', plots: ['track', 'force', 'speed', 'motor', 'rudder'], params: ['sea.sea_state', 'sea.from_deg', 'sim.seed'],
    watch: 'Added resistance slows the ship a little; after the turn the sea is on the beam and the drift force appears (Fig. 5-11).',
    compare: [{ label: 'sea state 6', preset: 'quarter-turn-ss6' }] },
  'quarter-turn-ss6': { title: 'A quarter turn in sea state 6', plots: ['track', 'force', 'speed', 'motor', 'rudder'], params: ['sea.sea_state', 'sea.from_deg', 'sim.seed'],
    watch: 'About 27 times the mean added resistance of sea state 3 (213 kN against 8 kN over the run): nearly the square of the ratio of wave heights, (5.0 m / 0.9 m)^2 = 31.',
    compare: [{ label: 'sea state 3', preset: 'quarter-turn-ss3' }] },
  'fuel-regular-seas': { title: 'Fuel in one regular head wave', plots: ['fuel', 'speed', 'motor', 'heave', 'pitch'], params: ['sea.amplitude_m', 'sea.omega_rad_s'],
    watch: 'One regular head wave of 1 ft: fuel power against calm water. After the run the page sweeps wave frequencies and heights (Fig. 5-12, below the run\'s plots).',
    compare: [{ label: 'calm water', set: { 'sea.kind': 'calm' } }] },
  'head-seas-ss6': { title: 'Head seas, sea state 6: ventilation', plots: ['hr', 'beta', 'motor', 'rpm', 'bus'], params: ['ship.hull.hub_above_base_m', 'seakeeping.stern_motion', 'sea.sea_state', 'sim.seed'],
    watch: 'h/R against the shaded ventilation band: each time it dips below 1.1 the propeller draws air (orange markers), thrust and torque drop (beta), the propeller races and the motor power falls. Below 1 the disc breaks the surface. Each event is a sudden load rejection for the plant: the turbines overspeed (up to 14 % with seed 1) and dip as much when the propeller bites again, the bus voltage follows them (0.83 to 1.14 pu), then both ring for tens of seconds (bus plot), far beyond the 0.2 % (turbines) and 2 % (bus) they move in these seas when the propellers stay down.',
    compare: [{ label: 'eq. 2.57 as printed', set: { 'seakeeping.stern_motion': 'thesis_eq_2_57' } }, { label: 'fully loaded (the hull\'s own hub height)', set: { 'ship.hull.hub_above_base_m': null } }, { label: 'with storage', preset: 'head-seas-ss6-storage' }],
    note: 'The sign of eq. 2.57: as printed, the stern\'s own motion is added to the wave instead of taken from it, so the hub depth swings by wave plus motion and surface effects come several times as often; with the consistent sign the stern rides the long waves of SS6 and a fully loaded ship (h0 = 6 m) keeps its propellers down.' },
  'head-seas-ss6-storage': { title: 'Head seas, sea state 6, with storage on each bus', plots: ['bus', 'storage', 'motor', 'hr'], params: ['plant.storage.energy_j', 'plant.storage.power_w', 'plant.storage.corner_hz', 'sim.seed'],
    watch: 'The same ventilation as without storage (h/R, motor power), but the batteries take the fast part of the load: the turbine speed stays between 0.997 and 1.002 pu and the bus voltage between 0.98 and 1.00 pu (bus plot), while the storage power swings from 20 MW charging to 8 MW giving (both buses, storage plot). The charge (the drive-train picture\'s storage blocks) starts at 55 %, rises to 60 %, then falls to 22 %, near its 20 % floor, as the waves\' added resistance builds the mean load. Make the storage smaller and watch the turbines take the swings back.',
    compare: [{ label: 'without storage', preset: 'head-seas-ss6' }, { label: 'a smaller storage (100 MJ, 5 MW)', set: { 'plant.storage.energy_j': 1e8, 'plant.storage.power_w': 5e6 } }] },
  'as-printed': { title: 'The thesis as printed: head seas SS6', plots: ['heave', 'hr', 'motor', 'rpm', 'bus'], params: ['seakeeping.stern_motion', 'ship.hull.hub_above_base_m', 'sim.seed'],
    watch: 'Heave first: with Appendix A\'s eq. 5 as printed the destroyer heaves by about 16 m in SS6, and the propellers leave the water (h/R far below the band) again and again; the motor power drops to nothing each time, and near the end the turbines overspeed and then stall (the warnings above the summary). Compare with the corrected equations, and with eq. 2.57\'s sign alone, which gives the thesis\' ch. 5.3 picture of ventilation and swings of tens of rpm. The bus starts at its set point, 9.7 kV (E_a line to line).',
    compare: [{ label: 'corrected, same depth', set: { 'as_printed.doppler_twice': false, 'as_printed.appendix_a_typos': false, 'as_printed.eq_2_47_conjugate': false, 'as_printed.ea_line_to_line': false, 'seakeeping.stern_motion': 'consistent' } }, { label: 'eq. 2.57 as printed only', set: { 'as_printed.doppler_twice': false, 'as_printed.appendix_a_typos': false, 'as_printed.eq_2_47_conjugate': false, 'as_printed.ea_line_to_line': false } }],
    note: 'Every inconsistency of the thesis we settled is a switch in the scenario\'s as_printed section (JSON editor); this preset turns on all that let the run start at 25 knots, plus seakeeping.stern_motion. The two motor switches (Table 2.1\'s P read as poles, eq. 2.5\'s copper-loss torque) are off: with either the motor cannot carry the propeller at 25 knots. docs/validation.md, section "As printed", says what each switch moves.' },
  'turn-360-ss6': { title: 'A full turn in sea state 6', plots: ['track', 'heave', 'pitch', 'hr', 'motor'], params: ['sea.sea_state', 'sea.from_deg', 'sim.seed'],
    watch: 'Heave and pitch are strong in head seas and weak in following seas (Figs. 5-16 to 5-19). The arrow on the track shows where the waves come from.',
    compare: [{ label: 'calm water', preset: 'turn-360' }] },
  'mc-excess-energy': { title: 'Monte Carlo: excess energy', plots: ['motor', 'hr', 'speed'], params: ['monte_carlo.trials', 'ship.hull.hub_above_base_m', 'seakeeping.stern_motion'],
    about: 'Monte Carlo over random seas of 80 s at 25 knots in head seas SS6, with a 4.8 m propeller only 4 m deep (thesis ch. 5.4.1, Figs. 5-20 to 5-23): the energy one motor draws over the run against the same sea without surface losses and against calm water, and how its power spreads over the trials. The summary says which way each difference goes and how it stands beside the thesis\' figure.',
    watch: 'Press Monte Carlo (Run shows one trial): the envelope of motor power, the excess energy per trial and its histograms (Figs. 5-20 to 5-23).' },
  'mc-arrival': { title: 'Monte Carlo: when the first surface effect arrives', plots: ['hr', 'motor', 'beta'], params: ['monte_carlo.trials', 'ship.hull.hub_above_base_m', 'seakeeping.stern_motion'],
    about: 'Monte Carlo at 25 knots in head seas SS6 with a 4.8 m propeller 6 m deep, each trial stopped 12 s after its first surface effect or at 90 s (thesis ch. 5.4.2, Table 5.8, Figs. 5-24 and 5-25): the arrival times against Rice\'s up-crossing rate. Uses the hub depth of eq. 2.57 as printed, as the thesis did; with the consistent sign (seakeeping.stern_motion) such events are far rarer: switch it and press Monte Carlo to see Rice\'s rate for each.',
    watch: 'Press Monte Carlo (Run shows one trial): the arrival times of the first surface effect against Rice\'s prediction (Table 5.8, Fig. 5-24).' },
};
STUDIES['wigley-head-seas'] = { title: 'The Wigley hull in head seas', plots: ['heave', 'pitch', 'hr', 'motor', 'rpm'], params: ['ship.hull.hub_above_base_m', 'sea.sea_state', 'sim.seed'],
  watch: 'The same plant on the Wigley hull, the classic seakeeping test hull (L 100 m): at 20 knots the energetic waves of sea state 5 meet it near its heave and pitch resonance, so it heaves and pitches far more than the destroyer would. The hull panel under the plots draws its body plan and gives its hydrostatics; the hull picker above Run loads offsets of your own.',
  compare: [{ label: 'the destroyer (DTMB 5415)', set: { 'ship.hull.name': 'dtmb5415' } }] };
STUDIES['mc-wigley'] = { title: 'Monte Carlo on the Wigley hull', plots: ['motor', 'hr', 'rpm'], params: ['monte_carlo.trials', 'ship.hull.hub_above_base_m', 'sim.seed'],
  watch: 'Press Monte Carlo (Run shows one trial): how motor power, hub depth and shaft speed spread over random seas on a hull other than the thesis\' destroyer.' };
// What the page calls a study it has no entry for (a new preset): its name.
export const studyTitle = (name) => (STUDIES[name] && STUDIES[name].title) || name;

// Plots of a run. Each series is a trace column: its label and unit come from signalMeta (label
// overrides a meta label only to add a sign convention). `prefix` shows W as MW, N as kN.
// The axis label and the unit in the title are built from the series' units; series of different
// units go on a left and a right axis, and so does a series with `axis: 'right'` (a small angle
// beside a large one). `sea`: only in waves. `hOverR`: the ventilation band and the levels of
// pageConstants. `events`: markers where surface losses start. `only`: drawn when it holds.
// `key`: a line under the plot saying what its numbers mean. `asked`: drawn only where a study or
// lesson lists it (the turbine load alone; the Lab has it in the power inventory).
// Colours: distinct and >= 3:1 against white. A run's own lines are solid, told apart by colour
// and width (a dash means the kept run: runplots.js); a reference (order) is grey and thin; on a
// plot of several, the first is widest, so that a later one drawn over it leaves it in view.
const REF = { color: '#6b6b6b', width: 1.2 };
export const PLOTS = [
  { id: 'speed', title: 'Ship speed', series: [{ signal: 'ship_speed_kn', color: '#0b5cad', width: 2.4 }, { signal: 'speed_cmd_kn', ...REF }] },
  { id: 'rpm', title: 'Propeller speed', events: true, series: [{ signal: 'prop_rpm', color: '#0b5cad', width: 2.4 }, { signal: 'prop_rpm_ref', ...REF }] },
  { id: 'bus', title: 'Bus voltage and turbine speed', series: [{ signal: 'bus_voltage_pu', color: '#b03a2e', width: 2.6 }, { signal: 'turbine_speed_pu', color: '#1e7b3c', width: 1.4 }] },
  { id: 'motor', title: 'Motor power', events: true, series: [{ signal: 'im_power_pu', color: '#6c3483' }] },
  { id: 'inventory', title: 'Power inventory', prefix: 'M', series: [{ signal: 'p_turbine_w', color: '#1e7b3c', width: 4.2 }, { signal: 'p_generator_w', color: '#b9770e', width: 3.2 }, { signal: 'p_inverter_w', color: '#0b5cad', width: 2.3 }, { signal: 'p_motor_w', color: '#6c3483', width: 1.5 }, { signal: 'p_ship_w', color: '#1b1b1b', width: 1.2 }] },
  { id: 'rudder', title: 'Heading and rudder', key: RUDDER_SIGN, series: [{ signal: 'heading_deg', color: '#0b5cad', width: 2.4 }, { signal: 'heading_ref_deg', ...REF }, { signal: 'rudder_deg', label: 'rudder (+ to port)', axisName: 'rudder', color: '#a04000', axis: 'right' }] },
  { id: 'hr', title: 'Hub depth over propeller radius', yLabel: 'h/R [-]', sea: true, hOverR: true, events: true, series: [{ signal: 'h_over_r', label: 'h/R port', color: '#0b5cad', width: 2.6 }, { signal: 'h_over_r_stbd', label: 'h/R starboard', color: '#1b1b1b', width: 1.2 }] },
  { id: 'beta', title: 'Thrust and torque kept under surface losses', sea: true, events: true, series: [{ signal: 'beta_t', color: '#b03a2e', width: 2.6 }, { signal: 'beta_q', color: '#6c3483', width: 1.4 }] },
  { id: 'wave', title: 'Wave at the stern and hub depth', sea: true, series: [{ signal: 'wave_stern_m', color: '#0b5cad', width: 2.6 }, { signal: 'hub_depth_m', color: '#1b1b1b', width: 1.4 }] },
  { id: 'heave', title: 'Heave', sea: true, series: [{ signal: 'heave_m', label: 'heave (up)', color: '#117a65' }] },
  { id: 'pitch', title: 'Pitch and roll', sea: true, series: [{ signal: 'pitch_deg', label: 'pitch (bow down)', color: '#a04000', width: 2.6 }, { signal: 'roll_deg', label: 'roll (starboard down)', color: '#5b2c6f', width: 1.4 }] },
  { id: 'force', title: 'Second-order wave force', sea: true, prefix: 'k', key: 'The slowly varying force of wave groups (Newman\'s approximation of the mean drift force, Salvesen\'s method): it peaks when a group passes, at any time, the start too. Below zero is physics: waves from abaft the beam push the ship on (negative added resistance), as in a turn out of head seas.', series: [{ signal: 'added_resistance_n', color: '#b03a2e', width: 2.6 }, { signal: 'drift_force_n', label: 'drift force (to starboard)', color: '#0b5cad', width: 1.4 }] },
  { id: 'fuel', title: 'Fuel power, the turbines online', prefix: 'M', series: [{ signal: 'fuel_power_w', color: '#6e2c00' }] },
  { id: 'load', title: 'Turbine load, the turbines online', prefix: 'M', asked: true, series: [{ signal: 'p_turbine_w', color: '#1e7b3c' }] },
  { id: 'storage', title: 'Storage power, both buses (negative: charging)', prefix: 'M', series: [{ signal: 'storage_power_w', color: '#117a65' }], only: (c) => c.storage_power_w.some((v) => v !== 0) },
  { id: 'brake', title: 'Brake resistor power', prefix: 'M', series: [{ signal: 'brake_power_w', color: '#b03a2e' }], only: (c) => c.brake_power_w.some((v) => v > 0) },
];
// Plots shown when a study names none.
export const DEFAULT_PLOTS = ['speed', 'rpm', 'bus', 'motor', 'track'];
// Key figures of the comparison of a kept run with the new one: a statistic of a signal's summary
// ('swing' is max - min) or an energy of the summary, named by `text` ({} is the signal's label);
// units from signalMeta (a statistic in seconds, `_s`, is in s), with an optional metric prefix.
// `better`: which way is better for the plant ('higher' or 'lower'); without it the difference is
// shown neutral (a figure whose good direction depends on the study, like the final speed).
// `none`: the words for a statistic the summary leaves undefined (null): a settling time exists
// only for a signal that left its order's band and came back to stay (core's summary.rs).
export const KEY_FIGURES = [
  { text: 'peak {}', signal: 'im_power_pu', stat: 'max' },
  { text: 'lowest {}', signal: 'im_power_pu', stat: 'min' },
  { text: 'lowest {} (dip)', signal: 'bus_voltage_pu', stat: 'min', better: 'higher' },
  { text: 'lowest {} (dip)', signal: 'turbine_speed_pu', stat: 'min', better: 'higher' },
  { text: 'highest {}', signal: 'turbine_speed_pu', stat: 'max', better: 'lower' },
  { text: 'peak {}', signal: 'fuel_power_w', stat: 'max', prefix: 'M', better: 'lower' },
  { text: 'final {}', signal: 'ship_speed_kn', stat: 'final' },
  { text: '{} settles after', signal: 'ship_speed_kn', stat: 'settling_time_s', better: 'lower', none: 'no settling time' },
  { text: '{} settles after', signal: 'bus_voltage_pu', stat: 'settling_time_s', better: 'lower', none: 'no settling time' },
  { text: '{} settles after', signal: 'turbine_speed_pu', stat: 'settling_time_s', better: 'lower', none: 'no settling time' },
  { text: '{} swing', signal: 'prop_rpm', stat: 'swing', better: 'lower' },
  { text: 'lowest {}', signal: 'h_over_r', stat: 'min', better: 'higher' },
  { text: 'mean {}', signal: 'fuel_power_w', stat: 'mean', prefix: 'M', better: 'lower' },
  { text: 'turbine energy', energy: 'turbine', prefix: 'M' },
  { text: 'energy burnt in the brake', energy: 'brake', prefix: 'M' },
];


// The h/R plot: the ventilation hysteresis band, the region where the disc is at or above the
// surface, and the levels of pageConstants (solid, labelled). Colours >= 3:1 on white.
export const LEVEL_COLORS = ['#b03a2e', '#7b241c', '#4a0f0a'];
export const BAND_FILL = 'rgba(211, 84, 0, 0.28)';
export const BAND_EDGE = '#a04000';
export const SURFACE_FILL = 'rgba(176, 58, 46, 0.12)';
// Vertical markers where surface losses start (beta_T leaves 1 in the trace).
export const EVENT_COLOR = '#a04000';
// A kept run is drawn in this muted style under the new one.
export const KEPT_STYLE = { color: '#8a8a8a', dash: [5, 4], width: 1.5 };

// The ship track: a mark and heading arrow every TRACK_MARK_S of simulated time; the picture
// spans at least TRACK_MIN_SPAN_M (a short run is not blown up to fill it).
export const TRACK_MARK_S = 60;
export const TRACK_MIN_SPAN_M = 200;

// Rows of the summary table (labels and units from signalMeta).
export const SUMMARY_ROWS = ['ship_speed_kn', 'prop_rpm', 'turbine_speed_pu', 'bus_voltage_pu', 'im_power_pu', 'thrust_kn'];

// After a run in waves: RAOs over wave length / Lpp, in head and bow seas.
export const RAO = { lambdaFrom: 0.3, lambdaStep: 0.045, points: 60, headings: [[180, 'head'], [135, 'bow']] };
// After a run in a regular sea: the fuel study (Fig. 5-12; its wave frequencies come from the wasm).
export const FUEL_COLORS = ['#1f618d', '#117a65', '#a04000', '#6c3483', '#1b1b1b'];

// Monte Carlo in the page: trial limit, at most this many workers, the periodogram's upper
// frequency on the plot, and the signal of the onset plot (the study's motor power, ch. 5.4.3).
export const MC = { maxTrials: 100000, maxWorkers: 4, periodogramMaxHz: 1.0, onsetSignal: 'im_power_pu',
  // The thesis' reference numbers are not copied here: these are their keys in the thesis' numbers
  // (core/data/thesis_values.csv, sent by the worker with 'ready'). Table 5.8: each statistic with
  // its analytic (Rice) and Monte Carlo cells; ch. 5.4.1: the excess energy's mean and spread.
  table58: [
    ['mean', 'table_5_8.rice.mean_s', 'table_5_8.monte_carlo.mean_s'],
    ['std', 'table_5_8.rice.std_s', 'table_5_8.monte_carlo.std_s'],
    ['skewness', 'table_5_8.rice.skewness', 'table_5_8.monte_carlo.skewness'],
    ['kurtosis', 'table_5_8.rice.kurtosis', 'table_5_8.monte_carlo.kurtosis'],
    ['median', 'table_5_8.rice.median_s', 'table_5_8.monte_carlo.median_s'],
    ['mode', 'table_5_8.rice.mode_s', 'table_5_8.monte_carlo.mode_s']],
  calmWater: ['ch_5_4_1.excess_energy_mean_mj', 'ch_5_4_1.excess_energy_std_mj'],
  // The studies that are the thesis' own (its numbers are shown beside them only).
  thesisStudies: { table58: ['mc-arrival'], calmWater: ['mc-excess-energy'] },
  // The fixed part of the Rice note; montecarlo.js adds what the numbers it compares say.
  riceNote: 'Rice\'s rate counts up-crossings of a stationary Gaussian response and treats them as rare, independent events, so that arrival times are exponential: that holds for a level many standard deviations away; nearer, crossings come in clusters on wave groups.',
  // The fixed part of the excess-energy note; montecarlo.js adds what the numbers say (their sign,
  // and how ours stands beside the thesis').
  excessNote: 'Two excess energies of one motor over the run: against the same sea with surface losses switched off (the submerged counterpart: what ventilation and emergence alone change), and against calm water (which adds the added resistance of the waves and the speed control\'s work in them; the thesis\' figure is of this kind, though it does not print its reference).' };

// Stability tab: presentation only. The operating point's defaults, ranges, labels and units, the
// synchronous speed and the Bode range come from the wasm (ipsMeta); here the controls' steps (by
// declaration path), the pole map's radius (faster poles are listed, not drawn) and the debounce.
export const IPS = { steps: { torque_nm: 1, load_a: 0.5, v_fd_v: 'any' }, poleMapMax: 2000, debounceMs: 60 };

// The bus stability map on the stability tab (issue 44): presentation only. The pairs of
// parameters a student picks from (checked with `aes-sim stability-map` on the start-up study at
// 25 kn: each map's boundary crosses it inside these ranges, from 0 W: no ship service load, the
// presets' own value, so the study's point is on the map), each axis's default range [SI] and
// number of values; the unit each parameter's SI unit is shown in (a power of ten: MW, mF); the
// map's height [px] (less on a phone) and its colours (diverging: stable blue, unstable red).
// The labels, units and allowed ranges are the registry's (paramMeta); every number drawn is the
// wasm's (the "stability-map" study, stabilityPoint).
export const BUSMAP = {
  pairs: [
    { id: 'filter', x: ['plant.loads.ship_service_w', 0, 16e6, 41], y: ['plant.loads.filter_capacitance_f', 0.007, 0.015, 17] },
    { id: 'bus', x: ['plant.loads.ship_service_w', 0, 20e6, 41], y: ['plant.dc_link.capacitance_f', 0.005, 0.1, 20] },
    { id: 'resistance', x: ['plant.loads.ship_service_w', 0, 20e6, 41], y: ['plant.loads.filter_resistance_ohm', 0.02, 0.12, 21] },
  ],
  shown: { W: ['MW', 6], F: ['mF', -3] },
  heightPx: 420, phoneHeightPx: 340, phoneBelowPx: 600,
  // The colour scale is symmetric-logarithmic: |a| below linear1PerS is drawn on a linear scale.
  linear1PerS: 0.01,
  colors: { stable: [33, 102, 172], zero: [247, 247, 247], unstable: [178, 24, 43], failed: '#9a9a9a' },
};

// The controller design tab (ch. 3.1): the plant is the acceleration study's; poles faster than
// poleMapMax [1/s] are listed, not drawn (the compensator's fastest are near -216 /s).
// The sliders' spans (in decades for mu and q) within the declared ranges, and their steps.
export const DESIGN = { basePreset: 'acceleration', poleMapMax: 40, debounceMs: 120,
  spans: { mu: [-4, 0], q: [0, 4], omega_p_rad_s: [0, 10] },
  steps: { mu: 0.1, q: 0.1, omega_p_rad_s: 0.1, design_speed_kn: 1 } };

// Progress reports while running: at most one per this many milliseconds; steps per chunk.
export const RUN_CHUNK_STEPS = 4000; // small enough that the live views follow a run (about 20 ms a chunk)
export const PROGRESS_EVERY_MS = 100;

export const STORE_KEY = 'aes-sim/edits/v1';

// The study shown first, and when a link cannot be used.
export const DEFAULT_PRESET = 'startup';

// Live views (drive train, stern, plan view) and their playback: presentation choices only; the
// warning levels, radius, hull and sea come from the wasm (pageConstants, hullProfile, Sea).
export const LIVE = {
  speeds: [0.25, 0.5, 1, 2, 5, 10, 20, 50], // playback, times real time
  defaultSpeed: 2,
  textEveryMs: 250, // the text alternative follows the playback at most this often
  // Arrows of the drive train: width at a link's rated power, and how fast the dashes move
  // (pixels per second of wall time at rated power and 1x).
  arrowMaxPx: 16, dashPxPerS: 60,
  // Below this canvas width [px] the drive train runs top to bottom.
  trainVerticalBelowPx: 560,
  // Stern view window [m]: aft of the AP, forward of it, above and below the calm waterline.
  stern: { aftM: 14, foreM: 38, upM: 8, downM: 10 },
  // Plan view: half the span shown [m] as a multiple of Lpp, the wave picture's grid (cells
  // across), and how much track is drawn behind the ship [s].
  plan: { spanOfLpp: 0.75, grid: 36, trackS: 600 },
  colors: {
    block: '#ffffff', blockEdge: '#4a4a4a', warn: '#fde2e1', warnEdge: '#b03a2e', text: '#1b1b1b', muted: '#4a4a4a',
    flow: '#0b5cad', back: '#a04000', hull: '#5d6d7e', hullEdge: '#1b1b1b', water: '#2e86c1', sky: '#f4f8fb',
    disc: '#1b1b1b', discOut: '#b03a2e', gauge: '#1e7b3c', track: '#ffffff', ship: '#f8f9f9', rudder: '#a04000', waveArrow: '#0e6251',
    crest: [214, 234, 248], trough: [21, 67, 96],
  },
};

// The hull panel and picker (issue 15; the hulls' names and labels come from hullNames() and the
// registry's ship.hull.name choices): the longest share link the page writes (a custom hull's offsets past it go
// into a scenario file instead), and the drawing's colours (>= 3:1 on white).
export const HULL = {
  maxLinkChars: 8000,
  // Body plan and profile: the drawing keeps 1:1 scale unless its height would be under this many
  // pixels; then heights are stretched by a whole factor, said on the axis.
  minDrawPx: 150,
  colors: { hull: '#1f3a5f', fill: 'rgba(93, 109, 126, 0.18)', water: '#0b5cad', waterFill: 'rgba(46, 134, 193, 0.12)', prop: '#b03a2e', rudder: '#a04000', axis: '#4a4a4a', grid: '#d5d8dc', text: '#1b1b1b' },
};

// The propeller panel (issue 54; every number from the wasm's propellerCurves): the outline's
// tallest drawing [px], the largest blade table read [bytes] (the core refuses past 64 kB, in its
// words), and the colours (>= 3:1 on white; the B-series lines lighter, thinner and dashed).
export const PROPELLER = {
  outlineMaxPx: 300,
  maxFileBytes: 4 << 20,
  colors: { blade: '#1f3a5f', bladeFill: 'rgba(31, 58, 95, 0.14)', section: '#6b6b6b', hub: 'rgba(93, 109, 126, 0.25)', text: '#1b1b1b',
    kt: '#0b5cad', kq: '#b03a2e', eta: '#1e7b3c', ktSeries: '#6f97c8', kqSeries: '#cf6e63', etaSeries: '#4f9a66', pitch: '#1f3a5f' },
};

// The operability tab (issue 31): the grid the page asks the polar for (the command line's
// defaults: `aes-sim operability` with no options gives the same cells), speeds above the scenario's
// RAO table (seakeeping.grid.speed_max_kn) left out; the polar's seas, criteria, scatter diagram
// and every number come from the wasm (the study pipeline's studyRange and studySummary). At most this many
// workers; the colour scale's steps [m] and colours (dark: limited in low seas; light: in high seas,
// monotonic in lightness so the scale reads in grey too); the colour of cells that pass every
// listed sea, drawn hatched as well.
export const OPERABILITY = {
  speedsKn: Array.from({ length: 11 }, (_, i) => 3 * i),
  headingsDeg: Array.from({ length: 24 }, (_, i) => 15 * i),
  seaStates: [2, 3, 4, 5, 6],
  maxWorkers: 4,
  // The colour bins: the smallest step that covers the limits that occur in at most maxBins colours.
  steps: [0.05, 0.1, 0.25, 0.5, 1, 2], maxBins: 10,
  ramp: ['#67001f', '#b2182b', '#d6604d', '#f4a582', '#fddbc7', '#fff7bc'],
  beyond: { fill: '#d9f0d3', hatch: '#1b7837' },
  edge: 'rgba(0, 0, 0, 0.28)',
  headingTicksDeg: 30, // degrees marked around the polar
  kept: 6, // polars kept for Back and Forward
};

// Before a study on the worker pool (issue 46): one estimated at more than this many seconds on
// its workers (core's study::estimate, for this browser) is started only when the user says so.
export const LONG_STUDY = { askAboveS: 60 };

// Rare events (issue 32): the page's defaults and limits, and presentation only; the event's level
// (seakeeping.ventilation_on_h_over_r, or 1 for emergence), the trials, their consequences and
// every number come from the wasm (rareScenario, and the study pipeline's studyRange, studySummary). The unit of a
// consequence is its name's suffix; `short` names its histogram's axis. Thresholds: the rate per
// hour past each (null: none asked until one is typed).
export const RARE = {
  trials: 200, maxTrials: 1000, h0Min: 3, h0Max: 7, maxWorkers: 4, kept: 6,
  placePasses: 2, // runs to the event that place the ship in the most likely wave group
  units: { pu: 'pu', rpm: 'rpm', mw: 'MW', mj: 'MJ' },
  short: { min_bus_voltage_pu: 'lowest bus voltage', peak_turbine_speed_pu: 'highest turbine speed', shaft_speed_swing_rpm: 'shaft speed swing', motor_power_drop_mw: 'motor power drop', brake_energy_mj: 'brake energy' },
  thresholds: { min_bus_voltage_pu: 0.9, peak_turbine_speed_pu: 1.1, shaft_speed_swing_rpm: null, motor_power_drop_mw: 10, brake_energy_mj: null },
  // The quantiles drawn on each histogram: the summary's key, label, colour and dash (>= 3:1 on white).
  quantiles: [['q05', '5 %', '#117a65', [6, 3]], ['q50', '50 %', '#b03a2e', []], ['q95', '95 %', '#6c3483', [6, 3]], ['q99', '99 %', '#1b1b1b', [2, 3]]],
};
