// The page: scenario form, runs in a web worker, plots, share links, exports, stability tab.
import uPlot from './vendor/uPlot.esm.js';

const $ = (id) => document.getElementById(id);
const LINK_VERSION = 1;
const MAX_LINK_CHARS = 16000;
const MAX_LINK_DEPTH = 12;
const STORE_KEY = 'aes-sim/edits/v1';

// Parameters shown in the form, grouped as a naval engineer thinks of them. [path, label, unit, help]
const FIELDS = [
  ['Ship and hull', [
    ['ship.mass_kg', 'Displaced mass', 'kg', 'Table 5.1: 7e6.'],
    ['ship.wetted_area_m2', 'Wetted area', 'm²', 'Table 5.1: 5200.'],
    ['ship.drag_coeff', 'Drag coefficient C_r', '-', 'Eq. 2.15, Table 5.1: 3e-3.'],
    ['ship.wake_fraction', 'Wake fraction w', '-', 'Eq. 2.12, Table 5.1: 0.1.'],
    ['ship.thrust_deduction', 'Thrust deduction t', '-', 'Eq. 2.15, Table 5.1: 0.1.'],
    ['hull.model', 'Hull model', '', 'surge: straight line (ch. 2.3); maneuvering: Abkowitz 3-DOF with rudder (ch. 2.4).', ['surge', 'maneuvering']],
  ]],
  ['Propulsion plant', [
    ['propeller.model', 'Propeller model', '', 'B-series (first quadrant) or four-quadrant B4-70 (needed for braking).', ['b_series', 'four_quadrant']],
    ['propeller.diameter_m', 'Propeller diameter', 'm', 'Table 5.1: 4.5.'],
    ['propeller.pitch_ratio', 'Pitch ratio P/D', '-', 'Table 5.1: 1.0.'],
    ['propeller.blades', 'Blades', '-', 'B-series range 2 to 7.'],
    ['plant.turbine.inertia_kg_m2', 'Turbine inertia', 'kg m²', 'Table 5.2: 400.'],
    ['plant.motor.rated_power_w', 'Motor rating', 'W', '38 MW (ch. 2.2.2).'],
    ['plant.dc_link.capacitance_f', 'Bus capacitance', 'F', 'Table 5.4: 0.037.'],
    ['plant.dc_link.rectifier', 'Rectifier', '', 'diode: power flows one way; reversible: it can flow back to the turbines.', ['diode', 'reversible']],
    ['plant.dc_link.brake_resistor_ohm', 'Brake resistor', 'Ω', '0 for none.'],
  ]],
  ['Controllers', [
    ['controllers.governor.kp', 'Governor K_p,t', '1/pu', 'Throttle per per-unit speed error.'],
    ['controllers.governor.slew_rate_per_s', 'Throttle slew limit', '1/s', 'Fuel schedule limit.'],
    ['controllers.field.kp', 'Field K_p,v', 'V/V', 'Ch. 5.2.1 baseline 1e-4.'],
    ['controllers.field.ki', 'Field K_i,v', 'V/(V s)', 'Ch. 5.2.1 baseline 5e-4.'],
    ['controllers.speed.shaft_ramp_rpm_per_s', 'Shaft ramp', 'rpm/s', '0 for a step.'],
    ['controllers.slip.allow_braking', 'Allow AC braking', '', 'Negative slip: the motor brakes as a generator.', ['false', 'true']],
    ['controllers.autopilot.turn_rate_deg_s', 'Default turn rate', 'deg/s', 'Used when a heading order gives none.'],
  ]],
  ['Sea and seakeeping', [
    ['sea.kind', 'Sea', '', 'calm; random: Bretschneider spectrum (eq. 2.58) of a Table 2.4 sea state; regular: one wave.', ['calm', 'random', 'regular']],
    ['sea.sea_state', 'Sea state', '-', 'Table 2.4: 2 to 6 (SS6: H1/3 5 m, peak 0.507 rad/s).'],
    ['sea.from_deg', 'Waves from', 'deg', '0 = from north: head seas for a ship heading north.'],
    ['sea.components', 'Wave components N_s', '-', 'Ch. 2.5.4: 100 to 500.'],
    ['sea.amplitude_m', 'Regular wave amplitude', 'm', '1 ft = 0.3048 m.'],
    ['sea.omega_rad_s', 'Regular wave frequency', 'rad/s', 'Wave length 2 pi g / omega^2.'],
    ['seakeeping.hub_depth_m', 'Calm-water hub depth h0', 'm', 'Ch. 5.3: 6 m; ch. 5.4.1: 4 m.'],
    ['seakeeping.stern_motion', 'Hub depth formula', '', 'consistent: the stern follows long waves; thesis_eq_2_57: the printed sign, which reproduces the thesis figures.', ['consistent', 'thesis_eq_2_57']],
    ['monte_carlo.trials', 'Monte Carlo trials', '-', 'For the Monte Carlo button (ch. 5.4).'],
  ]],
  ['Simulation', [
    ['initial.speed_kn', 'Initial speed', 'kn', '0 starts from idle.'],
    ['sim.duration_s', 'Duration', 's', 'Simulated time.'],
    ['sim.dt_s', 'Time step', 's', 'RK4 step, 1 ms.'],
    ['sim.record_interval_s', 'Record every', 's', 'A whole number of steps.'],
    ['sim.seed', 'Seed', '-', 'Fixes every random number.'],
  ]],
];

// What each study shows, for a class.
const ABOUT_EXTRA = {
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

const PLOTS = [
  { title: 'Ship speed [kn]', series: [['ship_speed_kn', 'speed', '#0b5cad'], ['speed_cmd_kn', 'ordered', '#999']] },
  { title: 'Propeller speed [rpm]', series: [['prop_rpm', 'propeller', '#0b5cad'], ['prop_rpm_ref', 'reference', '#999']] },
  { title: 'Bus voltage and turbine speed [per unit]', series: [['bus_voltage_pu', 'bus voltage', '#c0392b'], ['turbine_speed_pu', 'turbine speed', '#27ae60']] },
  { title: 'Motor power [per unit of 38 MW]', series: [['im_power_pu', 'motor power', '#8e44ad']] },
  { title: 'Power inventory [MW]', scale: 1e-6, series: [['p_turbine_w', 'turbine', '#27ae60'], ['p_generator_w', 'generator', '#16a085'], ['p_inverter_w', 'inverter', '#2980b9'], ['p_motor_w', 'motor', '#8e44ad'], ['p_ship_w', 'ship', '#2c3e50']] },
  { title: 'Rudder and heading [deg]', series: [['rudder_deg', 'rudder', '#d35400'], ['heading_deg', 'heading', '#0b5cad'], ['heading_ref_deg', 'heading order', '#999']] },
  { title: 'Hub depth over propeller radius h/R [-] (ventilation starts below 1.1, ends above 1.3; disk reaches the surface at 1)', sea: true,
    series: [['h_over_r', 'h/R', '#0b5cad'], ['_vent_on', 'ventilation onset 1.1', '#e67e22'], ['_vent_off', 'ventilation end 1.3', '#f5b041'], ['_surface', 'disk at surface 1.0', '#c0392b'], ['_hub_out', 'hub out of water -1', '#7b241c']] },
  { title: 'Propeller surface losses beta_T, beta_Q [-]', sea: true, series: [['beta_t', 'beta_T', '#c0392b'], ['beta_q', 'beta_Q', '#8e44ad']] },
  { title: 'Wave at the stern and hub depth [m]', sea: true, series: [['wave_stern_m', 'wave at stern', '#2980b9'], ['hub_depth_m', 'hub depth', '#2c3e50']] },
  { title: 'Heave [m], pitch and roll [deg]', sea: true, series: [['heave_m', 'heave', '#16a085'], ['pitch_deg', 'pitch (bow down)', '#d35400'], ['roll_deg', 'roll', '#7f8c8d']] },
  { title: 'Second-order wave force [kN]', sea: true, scale: 1e-3, series: [['added_resistance_n', 'added resistance', '#c0392b'], ['drift_force_n', 'drift force (to starboard)', '#2980b9']] },
  { title: 'Fuel power, four turbines [MW]', scale: 1e-6, series: [['fuel_power_w', 'fuel power', '#6e2c00']] },
  { title: 'Brake resistor power [MW]', scale: 1e-6, series: [['brake_power_w', 'brake power', '#c0392b']], only: (c) => c.brake_power_w.some((v) => v > 0) },
];

const SUMMARY_ROWS = [
  ['ship_speed_kn', 'ship speed [kn]'], ['prop_rpm', 'propeller speed [rpm]'], ['turbine_speed_pu', 'turbine speed [pu]'],
  ['bus_voltage_pu', 'bus voltage [pu]'], ['im_power_pu', 'motor power [pu]'], ['thrust_kn', 'thrust [kN]'],
];

let worker = null;
let presets = {};
let scenario = null;      // the scenario being edited (object)
let presetName = 'startup';
let lastResult = null;    // { summary, csv, scenario }
let runId = 0;
let plots = [];

// ---------- small utilities ----------
function getPath(obj, path) { return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), obj); }
function setPath(obj, path, value) {
  const keys = path.split('.');
  let o = obj;
  for (const k of keys.slice(0, -1)) o = o[k];
  o[keys[keys.length - 1]] = value;
}
function clone(x) { return JSON.parse(JSON.stringify(x)); }
function status(text, isError = false) { $('status').textContent = text; $('status').className = isError ? 'error' : ''; }
function notice(text) { $('notice').textContent = text; $('notice').hidden = !text; }

// Only what differs from the preset goes into a link.
function diff(base, cur) {
  if (JSON.stringify(base) === JSON.stringify(cur)) return undefined;
  if (base && cur && typeof base === 'object' && typeof cur === 'object' && !Array.isArray(base) && !Array.isArray(cur)) {
    const out = {};
    for (const k of Object.keys(cur)) {
      const d = diff(base[k], cur[k]);
      if (d !== undefined) out[k] = d;
    }
    return Object.keys(out).length ? out : undefined;
  }
  return cur;
}
function merge(base, d) {
  if (d && typeof d === 'object' && !Array.isArray(d) && base && typeof base === 'object' && !Array.isArray(base)) {
    const out = clone(base);
    for (const k of Object.keys(d)) out[k] = merge(base[k], d[k]);
    return out;
  }
  return d;
}
function depth(text) {
  let d = 0, max = 0, inStr = false, esc = false;
  for (const ch of text) {
    if (inStr) { if (esc) esc = false; else if (ch === '\\') esc = true; else if (ch === '"') inStr = false; continue; }
    if (ch === '"') inStr = true; else if (ch === '{' || ch === '[') { d++; max = Math.max(max, d); } else if (ch === '}' || ch === ']') d--;
  }
  return max;
}
function b64urlEncode(s) {
  const bytes = new TextEncoder().encode(s);
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}
function b64urlDecode(s) {
  if (!/^[A-Za-z0-9_-]*$/.test(s)) throw new Error('the scenario part holds characters a link never has');
  const bin = atob(s.replace(/-/g, '+').replace(/_/g, '/'));
  return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
}

// ---------- worker ----------
const pending = new Map();
function startWorker() {
  worker = new Worker('worker.js', { type: 'module' });
  worker.onmessage = (ev) => {
    const m = ev.data;
    if (m.type === 'ready') { onReady(m); return; }
    const cb = pending.get(m.id);
    if (cb) cb(m);
  };
  worker.onerror = (e) => status(`The simulator failed to load: ${e.message || e}`, true);
}
function ask(msg, onMessage) {
  const id = ++runId;
  pending.set(id, onMessage);
  worker.postMessage({ ...msg, id });
  return id;
}
function validate(sc) {
  return new Promise((resolve) => ask({ type: 'validate', scenario: JSON.stringify(sc) }, (m) => { pending.delete(m.id); resolve(m.errors); }));
}

// ---------- the form ----------
function buildForm() {
  const form = $('form');
  form.replaceChildren();
  for (const [group, fields] of FIELDS) {
    const fs = document.createElement('fieldset');
    const lg = document.createElement('legend');
    lg.textContent = group;
    fs.append(lg);
    for (const [path, label, unit, help, choices] of fields) {
      const id = 'f-' + path.replace(/\./g, '-');
      const div = document.createElement('div');
      div.className = 'field';
      const lab = document.createElement('label');
      lab.htmlFor = id;
      lab.textContent = unit ? `${label} [${unit}]` : label;
      let input;
      if (choices) {
        input = document.createElement('select');
        for (const c of choices) input.append(new Option(c, c));
      } else {
        input = document.createElement('input');
        input.type = 'number';
        input.step = 'any';
      }
      input.id = id;
      input.dataset.path = path;
      input.setAttribute('aria-describedby', id + '-help');
      input.addEventListener('change', () => onFieldChange(input));
      const h = document.createElement('div');
      h.className = 'help';
      h.id = id + '-help';
      h.textContent = help;
      const err = document.createElement('div');
      err.className = 'ferr';
      err.id = id + '-err';
      div.append(lab, input, h, err);
      fs.append(div);
    }
    form.append(fs);
  }
  const fs = document.createElement('fieldset');
  const lg = document.createElement('legend');
  lg.textContent = 'Maneuver (orders)';
  const ta = document.createElement('textarea');
  ta.id = 'f-commands';
  ta.rows = 6;
  ta.setAttribute('aria-label', 'Orders as JSON: time [s], speed [kn], heading [deg], heading rate [deg/s]');
  ta.addEventListener('change', () => {
    try {
      scenario.commands = JSON.parse(ta.value);
      saveEdits();
      markErrors([]);
    } catch (e) {
      markErrors([{ path: 'commands', value: '', message: 'not valid JSON: ' + e.message }]);
    }
  });
  const h = document.createElement('div');
  h.className = 'help';
  h.textContent = 'Orders: [{"t_s": 0, "speed_kn": 25}, {"t_s": 10, "heading_deg": 90, "heading_rate_deg_s": 0.5}]';
  fs.append(lg, ta, h);
  form.append(fs);
}

function fillForm() {
  for (const input of $('form').querySelectorAll('[data-path]')) {
    const v = getPath(scenario, input.dataset.path);
    input.value = v === undefined ? '' : String(v);
  }
  $('f-commands').value = JSON.stringify(scenario.commands, null, 1);
}

function onFieldChange(input) {
  const path = input.dataset.path;
  let v = input.value;
  if (input.tagName === 'SELECT') {
    v = v === 'true' ? true : v === 'false' ? false : v;
  } else {
    v = Number(v);
    if (input.value.trim() === '' || !Number.isFinite(v)) {
      markErrors([{ path, value: input.value, message: 'must be a number' }]);
      return;
    }
  }
  setPath(scenario, path, v);
  saveEdits();
  markErrors([]);
}

function markErrors(errors) {
  for (const e of $('form').querySelectorAll('.ferr')) e.textContent = '';
  const loose = [];
  for (const e of errors) {
    const el = $('f-' + e.path.replace(/\./g, '-') + '-err');
    if (el) el.textContent = e.message; else loose.push(`${e.path}${e.value ? ' = ' + e.value : ''}: ${e.message}`);
  }
  if (loose.length) status(loose.join('\n'), true);
}

function saveEdits() {
  try { localStorage.setItem(STORE_KEY, JSON.stringify({ preset: presetName, scenario })); } catch (_) { /* storage full or blocked */ }
}

function selectPreset(name, sc) {
  presetName = name;
  $('preset').value = name;
  scenario = sc ? sc : JSON.parse(presets[name]);
  $('about').textContent = `${JSON.parse(presets[name]).description} ${ABOUT_EXTRA[name] || ''}`;
  fillForm();
  markErrors([]);
}

// ---------- links ----------
function linkFor() {
  const d = diff(JSON.parse(presets[presetName]), scenario);
  let hash = `#v=${LINK_VERSION}&preset=${encodeURIComponent(presetName)}`;
  if (d !== undefined) hash += `&d=${b64urlEncode(JSON.stringify(d))}`;
  return location.origin + location.pathname + hash;
}

async function fromLink() {
  const hash = location.hash.slice(1);
  if (!hash) return null;
  const fail = (why) => { notice(`This link could not be used: ${why}. Showing the start-up study instead.`); return { failed: true }; };
  if (hash.length > MAX_LINK_CHARS) return fail(`it is ${hash.length} characters long (at most ${MAX_LINK_CHARS})`);
  const params = new URLSearchParams(hash);
  const v = Number(params.get('v'));
  if (!Number.isInteger(v) || v < 1) return fail('it has no version number');
  if (v > LINK_VERSION) return fail(`it was made by a newer version of aes-sim (link version ${v}, this page reads ${LINK_VERSION})`);
  const name = params.get('preset');
  if (!name || !Object.prototype.hasOwnProperty.call(presets, name)) return fail(`it names an unknown study "${String(name).slice(0, 40)}"`);
  let sc = JSON.parse(presets[name]);
  const d = params.get('d');
  if (d) {
    let text;
    try { text = b64urlDecode(d); } catch (e) { return fail(`its scenario part is damaged (${e.message})`); }
    if (depth(text) > MAX_LINK_DEPTH) return fail('its scenario is nested too deeply');
    let parsed;
    try { parsed = JSON.parse(text); } catch (_) { return fail('its scenario part is not valid JSON (truncated?)'); }
    if (parsed === null || typeof parsed !== 'object' || Array.isArray(parsed)) return fail('its scenario part is not an object');
    sc = merge(sc, parsed);
  }
  const errors = await validate(sc);
  if (errors.length) return fail(errors.slice(0, 3).map((e) => `${e.path}${e.value ? ' = ' + e.value : ''}: ${e.message}`).join('; '));
  return { name, scenario: sc };
}

// ---------- running ----------
function run() {
  const sc = clone(scenario);
  $('run').disabled = true;
  $('cancel').disabled = false;
  $('progress').value = 0;
  $('eta').textContent = '';
  status('Running...');
  const started = performance.now();
  ask({ type: 'run', scenario: JSON.stringify(sc) }, (m) => {
    if (m.type === 'progress') {
      $('progress').value = m.fraction;
      const elapsed = (performance.now() - started) / 1000;
      if (elapsed > 0.5 && m.fraction > 0.02) $('eta').textContent = `about ${Math.max(0, elapsed * (1 - m.fraction) / m.fraction).toFixed(1)} s left`;
      return;
    }
    pending.delete(m.id);
    $('run').disabled = false;
    $('cancel').disabled = true;
    $('eta').textContent = '';
    if (m.type === 'error') {
      // A failed run keeps the form and the earlier results.
      status(m.message, true);
      const errs = [];
      for (const line of m.message.split('\n')) {
        const mm = /^([\w.]+) = (.*?): (.*)$/.exec(line);
        if (mm) errs.push({ path: mm[1], value: mm[2], message: mm[3] });
      }
      if (errs.length) markErrors(errs);
      return;
    }
    $('progress').value = 1;
    const summary = JSON.parse(m.summary);
    lastResult = { summary, csv: m.csv, scenario: sc };
    $('export-csv').disabled = false;
    $('export-json').disabled = false;
    showSummary(summary);
    drawPlots(m.columns);
    if (sc.sea.kind !== 'calm') extraSeaPlots(sc);
    status(`Done: ${summary.final_time_s} s simulated in ${(m.wall_ms / 1000).toFixed(2)} s (${(summary.final_time_s / (m.wall_ms / 1000)).toFixed(0)} times real time).`);
  });
}

// ---------- Monte Carlo (ch. 5.4): trials spread over several workers ----------
let mcWorkers = [];
function stopMonteCarlo() { for (const w of mcWorkers) w.terminate(); mcWorkers = []; }

function runMonteCarlo() {
  const sc = clone(scenario);
  const n = Number(sc.monte_carlo && sc.monte_carlo.trials) || 0;
  if (sc.sea.kind === 'calm') { status('Monte Carlo needs a sea: choose a random sea (or the mc-… studies).', true); return; }
  if (!(n >= 1 && n <= 100000)) { status('monte_carlo.trials must be from 1 to 100000 in the page.', true); return; }
  const k = Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2, n));
  $('run').disabled = true; $('mc-run').disabled = true; $('cancel').disabled = false;
  $('progress').value = 0; $('eta').textContent = '';
  status(`Monte Carlo: ${n} trials on ${k} workers...`);
  const started = performance.now();
  const partials = new Array(k);
  const doneBy = new Array(k).fill(0);
  let finished = 0;
  const fail = (msg) => { stopMonteCarlo(); $('run').disabled = false; $('mc-run').disabled = false; $('cancel').disabled = true; status(msg, true); };
  for (let w = 0; w < k; w++) {
    const a = Math.floor((n * w) / k), b = Math.floor((n * (w + 1)) / k);
    const wk = new Worker('worker.js', { type: 'module' });
    mcWorkers.push(wk);
    wk.onmessage = (ev) => {
      const m = ev.data;
      if (m.type === 'ready') wk.postMessage({ type: 'mc', id: w, scenario: JSON.stringify(sc), a, b });
      else if (m.type === 'mc-progress') {
        doneBy[w] = m.done;
        const done = doneBy.reduce((x, y) => x + y, 0);
        $('progress').value = done / n;
        const el = (performance.now() - started) / 1000;
        if (el > 0.5 && done > 0) $('eta').textContent = `${done} of ${n} trials, about ${(el * (n - done) / done).toFixed(1)} s left`;
      } else if (m.type === 'mc-done') {
        partials[w] = m.partial;
        wk.terminate();
        if (++finished === k) {
          mcWorkers = [];
          ask({ type: 'mc-summary', partials }, (r) => {
            pending.delete(r.id);
            $('run').disabled = false; $('mc-run').disabled = false; $('cancel').disabled = true; $('eta').textContent = '';
            if (r.type === 'error') { status(r.message, true); return; }
            const summary = JSON.parse(r.summary);
            lastResult = { summary, csv: '', scenario: sc };
            $('export-json').disabled = false; $('export-csv').disabled = true;
            showMonteCarlo(summary);
            status(`Monte Carlo done: ${n} trials in ${((performance.now() - started) / 1000).toFixed(1)} s.`);
          });
        }
      } else if (m.type === 'error') fail(m.message);
    };
    wk.onerror = (e) => fail('A worker failed: ' + (e.message || e));
  }
}

// RAOs of the hull at the run's ordered speed in head and bow seas, and (for the fuel study) the
// Fig. 5-12 curves, drawn after a run in waves.
function extraSeaPlots(sc) {
  const kn = (sc.commands[0] && sc.commands[0].speed_kn) || 25;
  const lam = Array.from({ length: 60 }, (_, i) => 0.3 + i * 0.045);
  const omegas = lam.map((l) => Math.sqrt((2 * Math.PI * 9.81) / (l * 142)));
  for (const heading of [180, 135]) {
    ask({ type: 'rao', speed_kn: kn, heading_deg: heading, omegas }, (m) => {
      pending.delete(m.id);
      if (m.error) return;
      const r = m.result;
      const pk = r.pitch.amp.map((p, i) => p / ((omegas[i] * omegas[i]) / 9.81));
      linePlot($('plots'), `DTMB 5415 RAOs at ${kn} kn, ${heading === 180 ? 'head' : 'bow'} seas (strip theory, ch. 2.5.2)`, lam,
        [[r.heave.amp, 'heave [m/m]', '#16a085'], [pk, 'pitch / k [-]', '#d35400'], [r.roll.amp, 'roll [rad/m]', '#7f8c8d']], 'wave length / ship length', 'amplitude');
    });
  }
  if (sc.sea.kind === 'regular') {
    const ws = Array.from({ length: 13 }, (_, i) => 0.3 + 0.1 * i);
    ask({ type: 'fuel', scenario: JSON.stringify(sc), omegas: ws }, (m) => {
      pending.delete(m.id);
      if (m.error) { status(m.error, true); return; }
      const colors = ['#aed6f1', '#5dade2', '#2e86c1', '#1f618d', '#154360'];
      for (const heading of ['head', 'bow']) {
        const series = [1, 2, 3, 4, 5].map((ft, j) => [ws.map((w) => { const r = m.rows.find((x) => x.heading === heading && x.amplitude_ft === ft && Math.abs(x.omega_rad_s - w) < 1e-9); return r ? r.fuel_power_w / 1e6 : null; }), `${ft} ft`, colors[j]]);
        linePlot($('plots'), `Fuel power of one prime mover [MW], ${heading} seas, 1 to 5 ft (Fig. 5-12)`, ws, series, 'wave frequency [rad/s]', 'MW');
      }
    });
  }
}

function fmt(x, d = 4) { return x == null || Number.isNaN(x) ? '–' : Number(x).toPrecision(d); }

function linePlot(box, title, x, series, xLabel, yLabel, opts = {}) {
  const div = document.createElement('div');
  div.className = 'plot';
  const h = document.createElement('h3');
  h.textContent = title;
  div.append(h);
  box.append(div);
  const o = {
    width: plotWidth(), height: 220, scales: { x: { time: false }, ...(opts.scales || {}) },
    axes: [{ label: xLabel }, { label: yLabel }],
    series: [{ label: xLabel }, ...series.map(([, label, color, extra]) => ({ label, stroke: color, width: 1.5, ...(extra || {}) }))],
  };
  plots.push(new uPlot(o, [x, ...series.map(([d]) => d)], div));
}

function histogramPlot(box, title, h, xLabel, overlay) {
  const w = (h.hi - h.lo) / h.counts.length;
  const centres = h.counts.map((_, i) => h.lo + (i + 0.5) * w);
  const series = [[h.counts, 'trials', '#2980b9', { paths: uPlot.paths.bars({ size: [0.9, 100] }), fill: '#aed6f1' }]];
  if (overlay) series.push([overlay.values, overlay.label, '#c0392b']);
  linePlot(box, title, centres, series, xLabel, 'trials per bin');
}

function showMonteCarlo(s) {
  for (const p of plots) p.destroy && p.destroy();
  plots = [];
  const box = $('plots');
  box.replaceChildren();
  $('summary-box').hidden = true;
  const info = document.createElement('div');
  info.className = 'plot';
  const a = s.arrival_time_s, r = s.rice, e = s.excess_energy_mj;
  const rows = [['Trials', s.trials], ['Seed', s.seed]];
  if (e) rows.push(['Excess energy vs submerged counterpart [MJ]', `${fmt(e.mean)} ± ${fmt(e.std)}`], ['Excess energy vs calm water [MJ] (thesis: 94.1 ± 33.3)', `${fmt(e.vs_calm_water.mean)} ± ${fmt(e.vs_calm_water.std)}`]);
  rows.push(['First surface effects / censored', `${a.events} / ${a.censored} (cap ${a.cap_s} s)`]);
  const table = document.createElement('table');
  table.innerHTML = '<caption>Monte Carlo summary</caption>';
  for (const [k, v] of rows) { const tr = table.insertRow(); const th = document.createElement('th'); th.scope = 'row'; th.textContent = k; tr.append(th); tr.insertCell().textContent = v; }
  info.append(table);
  if (r) {
    const lam = r.rate_per_s;
    const t8 = document.createElement('table');
    t8.innerHTML = '<caption>Arrival time of the first surface effect [s] (Table 5.8)</caption><thead><tr><th scope="col"></th><th scope="col">mean</th><th scope="col">std</th><th scope="col">skewness</th><th scope="col">kurtosis</th><th scope="col">median</th><th scope="col">mode</th></tr></thead>';
    const body = t8.createTBody();
    for (const [name, vals] of [[`Rice (Z ${fmt(r.z_m, 3)} m, rate ${fmt(lam, 3)}/s)`, [1 / lam, 1 / lam, 2, 9, Math.LN2 / lam, 0]], ['Monte Carlo', [a.mean, a.std, a.skewness, a.kurtosis, a.median, a.mode]]]) {
      const tr = body.insertRow(); const th = document.createElement('th'); th.scope = 'row'; th.textContent = name; tr.append(th);
      for (const v of vals) tr.insertCell().textContent = fmt(v);
    }
    const note = document.createElement('p');
    note.className = 'about';
    note.textContent = `Censored at ${a.cap_s} s alike: Monte Carlo mean of min(T, cap) ${fmt(a.mean_censored)} s, Rice ${fmt(r.mean_censored_s)} s.`;
    info.append(t8, note);
  }
  box.append(info);
  for (const [sig, env] of Object.entries(s.envelopes)) {
    const series = [[env.mean, 'mean', '#0b5cad'], [env.plus_2sigma, '+2 sigma', '#85c1e9'], [env.minus_2sigma, '-2 sigma', '#85c1e9'], [env.min, 'min', '#999', { dash: [4, 4] }], [env.max, 'max', '#999', { dash: [4, 4] }]];
    const tr = (s.traces || [])[0];
    if (tr) { const c = tr.columns.find(([n]) => n === sig); if (c) series.push([c[1].slice(0, env.t_s.length), `trial ${tr.trial}`, '#c0392b']); }
    linePlot(box, `${sig}: envelope over ${s.trials} trials (Fig. 5-20)`, env.t_s, series, 'time [s]', sig);
  }
  const ht = s.histogram_at_t;
  if (ht.n > 0) histogramPlot(box, `${ht.signal} at t = ${ht.t_s} s (Fig. 5-21), skewness ${fmt(ht.skewness, 3)}`, ht.histogram, ht.signal);
  if (e) histogramPlot(box, `Excess energy per trial vs the submerged counterpart [MJ] (Fig. 5-22): ${fmt(e.mean)} ± ${fmt(e.std)}`, e.histogram, 'MJ');
  if (a.events > 0) {
    const h = a.histogram, w = (h.hi - h.lo) / h.counts.length, total = s.trials;
    const overlay = r ? { label: `exponential, Rice rate ${fmt(r.rate_per_s, 3)}/s`, values: h.counts.map((_, i) => total * (Math.exp(-r.rate_per_s * (h.lo + i * w)) - Math.exp(-r.rate_per_s * (h.lo + (i + 1) * w)))) } : null;
    histogramPlot(box, 'Arrival time of the first surface effect [s] (Fig. 5-24)', h, 'time [s]', overlay);
  }
  if (s.onset && s.onset.t_s.length > 1) {
    const o = s.onset;
    linePlot(box, 'Motor power after the onset of a surface effect [pu] (Fig. 5-25)', o.t_s, [[o.mean, 'mean', '#0b5cad'], [o.plus_2sigma, '+2 sigma', '#85c1e9'], [o.min, 'min', '#999']], 'time after onset [s]', 'pu');
  }
  const pg = s.periodogram;
  if (pg.freq_hz.length > 2) {
    const k = pg.freq_hz.findIndex((f) => f > 1.0);
    const n = k > 0 ? k : pg.freq_hz.length;
    const pos = (v) => v.slice(1, n).map((x) => Math.max(x, 1e-9));
    linePlot(box, 'Periodogram of motor power [MW²/Hz] (Welch, Fig. 5-23)', pg.freq_hz.slice(1, n), [[pos(pg.mean), 'mean', '#0b5cad'], [pos(pg.min), 'min', '#999'], [pos(pg.max), 'max', '#c0392b']], 'frequency [Hz]', 'MW²/Hz', { scales: { y: { distr: 3 } } });
  }
}

function cancel() {
  stopMonteCarlo();
  worker.terminate();
  pending.clear();
  $('run').disabled = true;
  $('cancel').disabled = true;
  $('eta').textContent = '';
  status('Cancelled.');
  startWorker();
}

function showSummary(s) {
  const body = $('summary').querySelector('tbody');
  body.replaceChildren(...SUMMARY_ROWS.map(([key, label]) => {
    const v = s.signals[key];
    const tr = document.createElement('tr');
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = label;
    tr.append(th, ...[v.final, v.min, v.max].map((x) => { const td = document.createElement('td'); td.textContent = Number(x).toPrecision(4); return td; }));
    return tr;
  }));
  $('warnings').replaceChildren(...(s.warnings || []).map((w) => { const li = document.createElement('li'); li.textContent = w; return li; }));
  $('summary-box').hidden = false;
}

function plotWidth(box = 'plots') { return Math.max(420, Math.min(720, ($(box).clientWidth || 900) / 2 - 24)); }

function drawPlots(cols) {
  for (const p of plots) p.destroy && p.destroy();
  plots = [];
  const box = $('plots');
  box.replaceChildren();
  const t = cols.t_s;
  // Ship track, equal scale, with time markers and heading arrows.
  const tw = document.createElement('div');
  tw.className = 'plot';
  tw.innerHTML = '<h3>Ship track [m] (north up, east right; marks every 60 s)</h3>';
  const cv = document.createElement('canvas');
  cv.className = 'track';
  cv.setAttribute('role', 'img');
  cv.setAttribute('aria-label', 'Ship track seen from above');
  tw.append(cv);
  box.append(tw);
  drawTrack(cv, cols);
  const level = { _vent_on: 1.1, _vent_off: 1.3, _surface: 1.0, _hub_out: -1.0 };
  const inWaves = cols.h_over_r && cols.h_over_r.some((v) => v !== cols.h_over_r[0]);
  for (const spec of PLOTS) {
    if (spec.only && !spec.only(cols)) continue;
    if (spec.sea && !inWaves) continue;
    const k = spec.scale || 1;
    const data = [t, ...spec.series.map(([name]) => (name in level ? Array.from(t, () => level[name]) : k === 1 ? cols[name] : cols[name].map((v) => v * k)))];
    const div = document.createElement('div');
    div.className = 'plot';
    const h = document.createElement('h3');
    h.textContent = spec.title;
    div.append(h);
    box.append(div);
    const opts = {
      width: plotWidth(),
      height: 220,
      scales: { x: { time: false } },
      axes: [{ label: 'time [s]' }, { label: spec.title.replace(/^.*\[/, '[') }],
      series: [{ label: 't [s]' }, ...spec.series.map(([, label, color]) => ({ label, stroke: color, width: 1.5 }))],
    };
    plots.push(new uPlot(opts, data, div));
  }
}

function drawTrack(cv, cols) {
  const dpr = window.devicePixelRatio || 1;
  const w = cv.clientWidth || 460, h = 320;
  cv.width = w * dpr; cv.height = h * dpr;
  const g = cv.getContext('2d');
  g.scale(dpr, dpr);
  const xs = cols.y_m, ys = cols.x_m; // east to the right, north up
  let [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const span = Math.max(x1 - x0, y1 - y0, 200) * 1.1;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const s = Math.min(w, h) / span;
  const px = (x) => w / 2 + (x - cx) * s, py = (y) => h / 2 - (y - cy) * s;
  g.strokeStyle = '#ddd'; g.lineWidth = 1;
  g.strokeRect(0.5, 0.5, w - 1, h - 1);
  g.strokeStyle = '#0b5cad'; g.lineWidth = 2;
  g.beginPath();
  xs.forEach((x, i) => (i ? g.lineTo(px(x), py(ys[i])) : g.moveTo(px(x), py(ys[i]))));
  g.stroke();
  g.fillStyle = '#1b1b1b'; g.font = '11px system-ui';
  const t = cols.t_s;
  let next = 0;
  for (let i = 0; i < t.length; i++) {
    if (t[i] + 1e-9 < next) continue;
    next += 60;
    const hd = cols.heading_deg[i] * Math.PI / 180;
    const X = px(xs[i]), Y = py(ys[i]);
    g.beginPath(); g.arc(X, Y, 3, 0, 2 * Math.PI); g.fill();
    g.beginPath(); g.moveTo(X, Y); g.lineTo(X + 14 * Math.sin(hd), Y - 14 * Math.cos(hd)); g.stroke();
    g.fillText(`${t[i].toFixed(0)} s`, X + 5, Y - 5);
  }
  g.fillStyle = '#4a4a4a';
  g.fillText(`${(span / 1.1).toFixed(0)} m across`, 8, h - 8);
}

function download(name, text, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// ---------- stability tab ----------
let ipsPlots = [];
let ipsTimer = null;
function ipsArgs() {
  return {
    side: $('ips-side').value, closed: $('ips-loop').value === 'closed',
    omega: 377, vfd: Number($('ips-vfd').value), load: Number($('ips-load').value), torque: Number($('ips-torque').value),
    from_hz: 0.01, to_hz: 1000, points: 300,
  };
}
function ipsUpdate() {
  clearTimeout(ipsTimer);
  ipsTimer = setTimeout(() => {
    const a = ipsArgs();
    for (const el of document.querySelectorAll('.ips-motor')) el.hidden = a.side !== 'motor';
    for (const el of document.querySelectorAll('.ips-gen')) el.hidden = a.side !== 'generator';
    $('ips-torque-out').textContent = a.torque;
    $('ips-load-out').textContent = a.load;
    ask({ type: 'ips', args: a }, (m) => {
      pending.delete(m.id);
      if (m.error) { $('ips-status').textContent = m.error; $('ips-status').className = 'error'; return; }
      $('ips-status').textContent = m.result.stable ? 'Stable: every pole in the left half plane.' : 'UNSTABLE: a pole in the right half plane.';
      $('ips-status').className = m.result.stable ? '' : 'error';
      showIps(m.result, a);
    });
  }, 60);
}
function showIps(r, a) {
  const st = r.steady_state;
  const keys = a.side === 'motor'
    ? [['t_m0', 'T_m0 [N m]'], ['t_ref0', 'T** [N m]'], ['omega_r0', 'ω_r0 [rad/s]'], ['omega_s0', 'ω_s0 [rad/s]'], ['i_s_mag', '|i_s| [A]'], ['i_r_mag', '|i_r| [A]'], ['v_s_mag', '|v_s| [V]']]
    : [['v_gs_mag', '|v_gs| [V]'], ['i_gs_mag', '|i_gs| [A]'], ['i_fd', 'i_fd [A]'], ['v_dc_rect', 'ṽ_dc [V]'], ['v_dc', 'v_dc, bus [V]'], ['i_dc', 'i_dc [A]'], ['cos_phi', 'cos φ']];
  $('ips-steady').querySelector('tbody').replaceChildren(...keys.map(([k, label]) => {
    const tr = document.createElement('tr');
    const th = document.createElement('th'); th.scope = 'row'; th.textContent = label;
    const td = document.createElement('td'); td.textContent = Number(st[k]).toPrecision(5);
    tr.append(th, td); return tr;
  }));
  $('ips-poles').querySelector('tbody').replaceChildren(...r.poles.map((p) => {
    const tr = document.createElement('tr');
    tr.append(...[p.re, p.im, p.damping].map((x) => { const td = document.createElement('td'); td.textContent = Number(x).toPrecision(4); return td; }));
    return tr;
  }));
  for (const p of ipsPlots) p.destroy();
  ipsPlots = [];
  const box = $('ips-plots');
  box.replaceChildren();
  box.append(poleMap(r.poles));
  const f = r.bode.frequency_hz;
  const what = a.closed ? (a.side === 'motor' ? 'torque command to torque' : 'voltage set point to bus voltage') : (a.side === 'motor' ? 'stator voltage to stator current magnitude' : 'field voltage to droop feedback');
  for (const [key, label] of [['magnitude_db', 'magnitude [dB]'], ['phase_deg', 'phase [deg]']]) {
    const div = document.createElement('div');
    div.className = 'plot';
    const h = document.createElement('h3');
    h.textContent = `Bode ${label}: ${what}`;
    div.append(h);
    box.append(div);
    ipsPlots.push(new uPlot({
      width: Math.max(420, Math.min(900, $('ips-plots').clientWidth - 30)), height: 240,
      scales: { x: { time: false, distr: 3 } },
      axes: [{ label: 'frequency [Hz]' }, { label }],
      series: [{ label: 'f [Hz]' }, { label, stroke: '#0b5cad', width: 1.5 }],
    }, [f, r.bode[key]], div));
  }
}

// Pole map: the complex plane with the stable half shaded; poles faster than 2000 /s are listed
// but left off the picture so the slow ones stay readable.
function poleMap(poles) {
  const div = document.createElement('div');
  div.className = 'plot';
  const shown = poles.filter((p) => Math.hypot(p.re, p.im) < 2000);
  const h = document.createElement('h3');
  h.textContent = `Pole map [1/s, rad/s]${shown.length < poles.length ? ` (${poles.length - shown.length} pole(s) faster than 2000 /s off the picture)` : ''}`;
  const cv = document.createElement('canvas');
  cv.className = 'track';
  cv.setAttribute('role', 'img');
  cv.setAttribute('aria-label', `Pole map: ${shown.map((p) => `${p.re.toPrecision(3)}${p.im >= 0 ? '+' : ''}${p.im.toPrecision(3)}j`).join(', ')}`);
  div.append(h, cv);
  requestAnimationFrame(() => {
    const dpr = window.devicePixelRatio || 1;
    const w = cv.clientWidth || 460, hh = 320;
    cv.width = w * dpr; cv.height = hh * dpr;
    const g = cv.getContext('2d');
    g.scale(dpr, dpr);
    const span = Math.max(1, ...shown.map((p) => Math.max(Math.abs(p.re), Math.abs(p.im)))) * 1.15;
    const px = (x) => w * 0.85 + (x / span) * w * 0.8, py = (y) => hh / 2 - (y / span) * hh * 0.45;
    g.fillStyle = '#eef6ee'; g.fillRect(0, 0, px(0), hh);
    g.strokeStyle = '#888'; g.beginPath(); g.moveTo(0, py(0)); g.lineTo(w, py(0)); g.moveTo(px(0), 0); g.lineTo(px(0), hh); g.stroke();
    g.strokeStyle = '#c0392b'; g.lineWidth = 2;
    for (const p of shown) {
      const X = px(p.re), Y = py(p.im);
      g.beginPath(); g.moveTo(X - 5, Y - 5); g.lineTo(X + 5, Y + 5); g.moveTo(X + 5, Y - 5); g.lineTo(X - 5, Y + 5); g.stroke();
    }
    g.fillStyle = '#4a4a4a'; g.font = '11px system-ui';
    g.fillText(`${(-span).toPrecision(3)} /s`, 4, py(0) - 4);
    g.fillText(`${span.toPrecision(3)} rad/s`, px(0) + 4, 12);
  });
  return div;
}

// ---------- start ----------
let initialised = false;
async function onReady(m) {
  if (initialised) {
    // A fresh worker after a cancel: the form and the results stay as they are.
    $('run').disabled = false; $('mc-run').disabled = false;
    return;
  }
  initialised = true;
  presets = m.presets;
  $('preset').replaceChildren(...Object.keys(presets).map((n) => new Option(n, n)));
  buildForm();
  const linked = await fromLink();
  if (linked && !linked.failed) {
    selectPreset(linked.name, linked.scenario);
    $('run').disabled = false; $('mc-run').disabled = false;
    run();
    return;
  }
  let restored = false;
  if (!linked) {
    try {
      const saved = JSON.parse(localStorage.getItem(STORE_KEY) || 'null');
      if (saved && presets[saved.preset] && saved.scenario) {
        const errors = await validate(saved.scenario);
        if (!errors.length) { selectPreset(saved.preset, saved.scenario); restored = true; status('Your last edits are back.'); }
      }
    } catch (_) { /* ignore broken storage */ }
  }
  if (!restored) selectPreset('startup');
  $('run').disabled = false; $('mc-run').disabled = false;
  if (!restored) status('Ready. Choose a study and press Run.');
}

$('form').addEventListener('submit', (e) => e.preventDefault());
$('preset').addEventListener('change', () => { selectPreset($('preset').value); saveEdits(); });
$('run').addEventListener('click', run);
$('mc-run').addEventListener('click', runMonteCarlo);
$('cancel').addEventListener('click', cancel);
$('reset').addEventListener('click', () => { selectPreset(presetName); saveEdits(); status('Back to the preset.'); });
$('share').addEventListener('click', async () => {
  const url = linkFor();
  $('share-url').hidden = false;
  $('share-url').value = url;
  $('share-url').select();
  try { await navigator.clipboard.writeText(url); status('Link copied: it opens this scenario and runs it.'); } catch (_) { status('Link below: copy it by hand.'); }
});
$('export-csv').addEventListener('click', () => {
  if (!lastResult) return;
  download(`${lastResult.scenario.name}-trace.csv`, `# scenario: ${JSON.stringify(lastResult.scenario)}\n${lastResult.csv}`, 'text/csv');
});
$('export-json').addEventListener('click', () => {
  if (!lastResult) return;
  download(`${lastResult.scenario.name}-summary.json`, JSON.stringify({ scenario: lastResult.scenario, summary: lastResult.summary }, null, 1), 'application/json');
});
for (const [tab, panel, other, otherPanel] of [['tab-sim', 'panel-sim', 'tab-ips', 'panel-ips'], ['tab-ips', 'panel-ips', 'tab-sim', 'panel-sim']]) {
  $(tab).addEventListener('click', () => {
    $(tab).setAttribute('aria-selected', 'true'); $(other).setAttribute('aria-selected', 'false');
    $(panel).hidden = false; $(otherPanel).hidden = true;
    if (tab === 'tab-ips') ipsUpdate();
  });
}
for (const id of ['ips-side', 'ips-loop', 'ips-torque', 'ips-load', 'ips-vfd']) $(id).addEventListener('input', ipsUpdate);
window.addEventListener('hashchange', () => location.reload());
startWorker();
