#!/usr/bin/env node
// Seeded, repeatable fuzz campaign over every export of the page's wasm (www/pkg/aes_web.js):
// every exported function and every method of the classes `Run` and `Sea`, called with
// arguments that are valid most of the time and hostile the rest (NaN, infinities, huge and
// negative numbers, wrong types, empty and 1 MB strings, control characters, scenarios with one
// field made impossible, damaged shards). The calls run in a worker thread that is ended when a
// call passes the time bound (unbounded work) and started again after a trap. Each call is judged:
//
// - no trap (a WebAssembly.RuntimeError, `unreachable`): the wasm is then unusable on the page;
// - a refusal's message under 2 kB, with no raw control character;
// - a successful result with no NaN, infinity, undefined or null where a number is expected (a
//   Float64Array or a number, or a JSON key that names a unit) and no "NaN"/"inf" in its words;
// - an impossible number (NaN, an infinity) given and a success: accepted;
// - each call within the time bound (30 s).
//
// Prints a summary line and writes the findings (the call and what was wrong) to
// target/fuzz/wasm-findings-seedN.json.
//
//     node scripts/fuzz-wasm.mjs [--cases 1000] [--seed 1] [--bound-s 30]
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import path from 'node:path';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const PKG = path.join(ROOT, 'www', 'pkg');
const CONTROL = /[\x00-\x08\x0b-\x1f\x7f\x80-\x9f]/;
const NONFINITE_WORD = /(?<![A-Za-z_])(NaN|-?inf|-?Infinity)(?![A-Za-z_])/;
const UNIT_KEY = /_(s|m|kn|w|j|pu|deg|kg|hz|rad|n|nm|v|a|rpm|m2|m3|mj|mw|kw|kj|per_h|per_nm|m_s|rad_s|pct|frac)$/;
// Keys whose null is a deliberate "none" (an Option in the core), as in scripts/fuzz-cli.py.
const NULL_MEANS_NONE = new Set(['wave_sums_s', 'settling_time_s', 'bus_recovery_s', 'turbine_recovery_s',
  'fuel_per_nmi_j', 'sensitivity_w_per_n', 'excess_energy_mj', 'excess_vs_calm_mj', 'phase_crossover_rad_s',
  'gain_crossover_rad_s', 'kg_per_nmi_std', 'rate_per_s', 'bilge_keels_m']);

// A small seeded generator (mulberry32): the same seed gives the same calls.
function rng(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return {
    next,
    chance: (p) => next() < p,
    int: (lo, hi) => lo + Math.floor(next() * (hi - lo + 1)),
    uniform: (lo, hi) => lo + next() * (hi - lo),
    pick: (xs) => xs[Math.floor(next() * xs.length)],
  };
}

const HOSTILE_NUMBERS = [NaN, Infinity, -Infinity, 1e308, -1e308, 0, -0, -1, 1e-320, 2 ** 53, 4294967296, -5, 1e9];
const NONFINITE = (x) => typeof x === 'number' && !Number.isFinite(x);
const HOSTILE_VALUES = ['', ' ', '{', 'null', '[]', '{}', '\x1b[2J\x07', 'a\rb\nc', 'x'.repeat(1 << 20), 5, null, undefined,
  {}, [], true, '"\\u0000"', '{"name": "\\u001b]0;t\\u0007"}'];

// ---------------------------------------------------------------------------------------------
// The worker: loads the wasm as the page's worker does (the glue's init with the module's bytes)
// and makes the calls it is sent, one at a time.
async function workerMain() {
  const { gen } = workerData;
  const W = await import(pathToFileURL(path.join(PKG, 'aes_web.js')).href + `?gen=${gen}`);
  W.initSync({ module: readFileSync(path.join(PKG, 'aes_web_bg.wasm')) });
  const call = (c) => {
    if (c.cls === 'Run' || c.cls === 'Sea') {
      if (c.method === 'constructor') return new W[c.cls](...c.args);
      if (c.method === 'signalNames') return W.Run.signalNames();
      const obj = new W[c.cls](c.ctor);
      try {
        if (c.cls === 'Run' && c.method !== 'advance') {
          for (let k = 0; k < 50 && obj.advance(c.steps) < 1; k++);
        }
        // A getter (Sea.components) is read, a method called.
        const d = Object.getOwnPropertyDescriptor(W[c.cls].prototype, c.method);
        return d && d.get ? obj[c.method] : obj[c.method](...c.args);
      } finally {
        obj.free();
      }
    }
    return W[c.fn](...c.args);
  };
  parentPort.on('message', (c) => {
    parentPort.postMessage({ start: c.i });
    const t0 = performance.now();
    let out;
    try {
      const value = call(c);
      out = { i: c.i, ok: true, value: summarise(value), ms: performance.now() - t0 };
    } catch (e) {
      const trap = e instanceof WebAssembly.RuntimeError || /unreachable|RuntimeError/.test(String(e && e.stack));
      const msg = typeof e === 'string' ? e : (e && e.message !== undefined ? String(e.message) : String(e));
      out = { i: c.i, ok: false, trap, msg, type: e === null ? 'null' : typeof e, ms: performance.now() - t0 };
    }
    parentPort.postMessage(out);
  });
  parentPort.postMessage({ ready: true });
}

// What the main thread needs of a result (a big string is sent whole: the checks read it).
function summarise(v) {
  if (v instanceof Float64Array) return { kind: 'f64', bad: v.findIndex((x) => !Number.isFinite(x)), n: v.length, at: Array.from(v.slice(0, 3)) };
  if (v instanceof Uint8Array) return { kind: 'bytes', n: v.length, bytes: v };
  if (Array.isArray(v)) return { kind: 'array', value: JSON.parse(JSON.stringify(v, (_k, x) => (x === undefined ? '__undefined__' : x))) };
  if (v === undefined) return { kind: 'undefined' };
  if (v === null) return { kind: 'null' };
  if (typeof v === 'object' && v.constructor && v.constructor.name !== 'Object') return { kind: 'object', name: v.constructor.name };
  return { kind: typeof v, value: v };
}

// ---------------------------------------------------------------------------------------------
// The main thread: generates the calls, sends them, judges the results.

function makeGen(r, fx) {
  const num = (lo, hi) => (r.chance(0.8) ? r.uniform(lo, hi) : r.pick([...HOSTILE_NUMBERS, '5', null, undefined, {}]));
  const f64 = (lo, hi, nMax = 8) => {
    if (r.chance(0.1)) return r.pick([new Float64Array(0), new Float64Array(300000).fill(1), [1, 2], 'x', null]);
    const a = new Float64Array(r.int(1, nMax));
    for (let k = 0; k < a.length; k++) a[k] = r.chance(0.9) ? r.uniform(lo, hi) : r.pick(HOSTILE_NUMBERS);
    return a;
  };
  const setPath = (obj, p, v) => {
    const keys = p.split('.');
    let o = obj;
    for (const k of keys.slice(0, -1)) {
      if (typeof o[k] !== 'object' || o[k] === null) o[k] = {};
      o = o[k];
    }
    o[keys[keys.length - 1]] = v;
  };
  // A scenario: a preset made short (the point is inputs, not long runs), one field made hostile
  // a third of the time, or a hostile value instead of JSON.
  const scenario = (short = true) => {
    if (r.chance(0.08)) return r.pick(HOSTILE_VALUES);
    const sc = JSON.parse(fx.presets[r.pick(Object.keys(fx.presets))]);
    if (short) setPath(sc, 'sim.duration_s', r.pick([2, 5, 10]));
    if (sc.monte_carlo) sc.monte_carlo.trials = Math.min(sc.monte_carlo.trials || 2, 3);
    if (r.chance(0.35)) {
      const p = r.pick(fx.params);
      const v = p.kind === 'number' || p.kind === 'integer'
        ? r.pick([NaN, Infinity, 1e308, -1e308, -1, 0, 1e-320, p.min !== undefined && p.min !== null ? p.min - 1 : -1, p.max !== undefined && p.max !== null ? p.max * 2 + 1 : 1e9])
        : r.pick(['', '\x1b[31m', 'nope', 5, null, []]);
      setPath(sc, p.path, v);
      // JSON has no NaN: write it as the bare token so the parser meets it.
      return JSON.stringify(sc).replace(/null/, r.chance(0.2) ? 'NaN' : 'null');
    }
    return JSON.stringify(sc);
  };
  const text = () => r.pick(HOSTILE_VALUES);
  const studyKind = () => (r.chance(0.9) ? r.pick(fx.kinds) : text());
  const spec = (kind) => {
    if (r.chance(0.12)) return text();
    const raw = scenario();
    let sc;
    try { sc = JSON.parse(raw); } catch (_) { return raw; }
    switch (kind) {
      case 'monte-carlo': return JSON.stringify(sc);
      case 'operability': return JSON.stringify({ scenario: sc, request: { speeds_kn: [r.pick([12, 15, -1, NaN, 1e308])], headings_deg: [180], sea_states: [r.pick([4, 2, 9])] } });
      case 'rare-events': return JSON.stringify({ scenario: sc, trials: r.pick([1, 2, 0, 1e9]), thresholds: {} });
      case 'fuel-per-mile': return JSON.stringify({ scenario: sc, speeds_kn: [r.pick([15, 0, -3, 1e308])], seeds: r.pick([1, 0, 1e6]), from_s: r.pick([1, 0, -1, 1e9]) });
      case 'storage-sizing': return JSON.stringify({ scenario: sc, energies_j: [r.pick([5e7, 0, -1, 1e308])], powers_w: [r.pick([5e6, 0, -1])] });
      case 'stability-map': return fx.stabilitySpec && r.chance(0.6) ? fx.stabilitySpec : JSON.stringify({ scenario: sc, x: {}, y: {} });
      default: return JSON.stringify(sc);
    }
  };
  const shards = () => {
    if (r.chance(0.1)) return r.pick([[], null, 'x', [new Uint8Array(0)], [new Uint8Array(1 << 16)]]);
    const list = [];
    for (let k = r.int(1, 3); k > 0; k--) {
      const s = r.pick(fx.shards);
      const b = new Uint8Array(s.bytes);
      if (r.chance(0.5)) for (let m = 0; m < 4; m++) b[r.int(0, b.length - 1)] = r.int(0, 255);
      list.push(r.chance(0.15) ? b.slice(0, b.length >> 1) : b);
    }
    return list;
  };
  const kindOfShards = () => r.pick(fx.shards);
  const lessonName = () => (r.chance(0.85) ? r.pick(fx.lessons.map((l) => l.name)) : text());
  const lessonValues = (name) => {
    const l = fx.lessons.find((x) => x.name === name);
    const vals = {};
    if (l && r.chance(0.85)) {
      for (const c of l.controls) if (r.chance(0.7)) vals[c.path] = String(r.chance(0.8) ? r.pick(c.stops || c.values || [1]) : r.pick(['NaN', 'abc', '-1e308', '', '\x1b[1m5']));
    }
    if (r.chance(0.15)) vals[r.pick(['nope', '', '=5', 'sea.sea_state.x'])] = '5';
    return r.chance(0.05) ? text() : JSON.stringify(vals);
  };
  const paramPath = () => (r.chance(0.85) ? r.pick(fx.params.filter((p) => p.kind === 'number')).path : text());

  // Each export: its arguments, and whether a success with them would accept an impossible number.
  return {
    designLqgLtr: () => [scenario()],
    fuelStudy: () => [scenario(), f64(0.2, 2, 3)],
    hullNames: () => [],
    hullProfile: () => [scenario()],
    hullSheet: () => [scenario()],
    ipsAnalysis: () => [r.chance(0.9) ? r.pick(['generator', 'motor']) : text(), num(1, 5000), num(0.01, 1000), num(0.01, 1000), num(0.01, 10000),
      r.chance(0.9) ? r.chance(0.5) : text(), num(0.001, 1), num(10, 1000), r.chance(0.9) ? r.int(2, 50) : r.pick(HOSTILE_NUMBERS)],
    ipsMeta: () => [],
    lessonMeta: () => [],
    lessonOpen: () => { const n = lessonName(); return [n, lessonValues(n)]; },
    maneuversBooklet: () => [scenario(false)],
    pageConstants: () => [scenario()],
    paramMeta: () => [],
    presetJson: () => [r.chance(0.8) ? r.pick(Object.keys(fx.presets)) : text()],
    presetNames: () => [],
    propellerCurves: () => [scenario()],
    propellerGeometryCsv: () => [r.chance(0.6) ? fx.geometryCsv : r.chance(0.5) ? fx.geometryCsv.replace(/0\.\d+/, r.pick(['NaN', '-1', '1e308', 'x', ''])) : text(),
      r.chance(0.8) ? r.int(2, 7) : r.pick(HOSTILE_NUMBERS), num(0.1, 0.3)],
    raoJson: () => [scenario(), num(0, 30), num(0, 360), f64(0.2, 2, 4)],
    raoTableLoad: () => [scenario(), f64(-1, 1, 20)],
    raoTableValues: () => [scenario()],
    rarePlace: () => [scenario(), r.chance(0.8) ? r.int(0, 2) : r.pick(HOSTILE_NUMBERS)],
    rareScenario: () => [scenario()],
    runSummary: () => [scenario()],
    signalMeta: () => [],
    stabilityAxis: () => [scenario(), r.chance(0.8) ? 'x axis' : text(), paramPath(), num(0, 1e6), num(0, 1e7), r.chance(0.8) ? r.int(2, 5) : r.pick(HOSTILE_NUMBERS)],
    stabilityPoint: () => [scenario()],
    studyEstimate: () => { const k = studyKind(); return [k, spec(k), r.chance(0.8) ? r.int(1, 8) : r.pick(HOSTILE_NUMBERS)]; },
    studyRange: () => { const k = studyKind(); return [k, spec(k), 0, r.chance(0.85) ? 1 : r.pick([0, -1, 2 ** 32, NaN, 1e9])]; },
    studySummary: () => { const s = kindOfShards(); return r.chance(0.8) ? [s.kind, s.spec, shards()] : [studyKind(), spec(s.kind), shards()]; },
    thesisValues: () => [],
    traceCsvOf: () => { const rows = r.chance(0.8) ? r.int(1, 3) : r.pick(HOSTILE_NUMBERS); return [f64(-1e3, 1e3, fx.signals * 3), rows]; },
    trialBins: () => [scenario(), r.chance(0.8) ? r.int(0, 5) : r.pick(HOSTILE_NUMBERS)],
    trialScenario: () => [scenario(), r.chance(0.8) ? r.int(0, 5) : r.pick(HOSTILE_NUMBERS)],
    turbineSchedule: () => [scenario()],
    validateScenario: () => [scenario()],
    'Run.constructor': () => [scenario()],
    'Run.advance': () => [r.chance(0.8) ? r.int(1, 5000) : r.pick(HOSTILE_NUMBERS)],
    'Run.column': () => [r.chance(0.8) ? r.pick(fx.signalNames) : text()],
    'Run.columnFrom': () => [r.chance(0.8) ? r.pick(fx.signalNames) : text(), r.chance(0.8) ? r.int(0, 100) : r.pick(HOSTILE_NUMBERS)],
    'Run.lessonExplain': () => { const n = lessonName(); return [n, lessonValues(n), r.chance(0.7) ? null : text()]; },
    'Run.rows': () => [],
    'Run.signalNames': () => [],
    'Run.summaryJson': () => [],
    'Run.traceCsv': () => [],
    'Sea.constructor': () => [scenario()],
    'Sea.elevations': () => [num(0, 1000), f64(-500, 500, 10), f64(-500, 500, 10)],
    'Sea.components': () => [],
    _scenario: scenario,
  };
}

function walkJson(v, at, problems, checkNull) {
  if (Array.isArray(v)) { v.slice(0, 100000).forEach((x, k) => walkJson(x, `${at}[${k}]`, problems, checkNull)); return; }
  if (v && typeof v === 'object') {
    const check = checkNull && v.admissible !== false;
    for (const [k, x] of Object.entries(v)) {
      if (x === null && check && UNIT_KEY.test(k) && !NULL_MEANS_NONE.has(k)) problems.push(['null_number', `null at ${at}.${k}`]);
      walkJson(x, `${at}.${k}`, problems, checkNull);
    }
    return;
  }
  if (typeof v === 'string') {
    if (v === '__undefined__') problems.push(['undefined', `undefined at ${at}`]);
    else if (v.length < 400 && NONFINITE_WORD.test(v) && / /.test(v)) problems.push(['nan_text', `${at}: ${JSON.stringify(v.slice(0, 160))}`]);
  }
}

function judge(c, res, boundMs) {
  const problems = [];
  if (res.timeout) problems.push(['slow', `no answer in ${boundMs / 1000} s`]);
  else if (res.ok === false) {
    if (res.trap) problems.push(['trap', res.msg.slice(0, 300)]);
    if (res.msg.length > 2048) problems.push(['long_error', `${res.msg.length} characters`]);
    const m = CONTROL.exec(res.msg.replace(/\n/g, ' '));
    if (m) problems.push(['control_char_error', `${JSON.stringify(m[0])} in ${JSON.stringify(res.msg.slice(Math.max(0, m.index - 60), m.index + 20))}`]);
    if (!res.msg.trim()) problems.push(['empty_error', `thrown ${res.type} with no words`]);
  } else if (res.ok) {
    const v = res.value;
    if (v.kind === 'f64' && v.bad >= 0) problems.push(['nonfinite', `element ${v.bad} of ${v.n} not finite`]);
    if (v.kind === 'number' && !Number.isFinite(v.value)) problems.push(['nonfinite', `returned ${v.value}`]);
    if ((v.kind === 'undefined' || v.kind === 'null') && !['Run.constructor', 'Sea.constructor', 'raoTableLoad', 'Run.advance'].includes(c.name) && c.name !== 'validateScenario') {
      problems.push(['null_result', `returned ${v.kind}`]);
    }
    if (v.kind === 'string') {
      let parsed;
      try { parsed = JSON.parse(v.value); } catch (_) { parsed = undefined; }
      if (parsed !== undefined) walkJson(parsed, '$', problems, !['presetJson', 'paramMeta', 'rareScenario', 'rarePlace', 'trialScenario', 'lessonOpen', 'ipsMeta', 'lessonMeta'].includes(c.name));
      else if (c.name !== 'Run.traceCsv' && c.name !== 'traceCsvOf' && NONFINITE_WORD.test(v.value)) problems.push(['nan_text', v.value.slice(0, 200)]);
      else if ((c.name === 'Run.traceCsv' || c.name === 'traceCsvOf') && /(^|,)(NaN|-?inf)(,|$)/m.test(v.value)) problems.push(['nan_text', 'a NaN cell in the CSV']);
    }
    if (v.kind === 'array') walkJson(v.value, '$', problems, false);
    if (c.impossible.length && !['validateScenario', 'presetJson'].includes(c.name) && v.kind !== 'undefined') {
      problems.push(['accepted_impossible', c.impossible.join('; ')]);
    }
  }
  return problems;
}

// What a printable call looks like in the findings: long strings and arrays shortened.
function printable(x) {
  if (typeof x === 'string') return x.length > 300 ? `${x.slice(0, 300)}... (${x.length} characters)` : x;
  if (x instanceof Float64Array || x instanceof Uint8Array) return `${x.constructor.name}(${x.length}) [${Array.from(x.slice(0, 6)).join(', ')}${x.length > 6 ? ', ...' : ''}]`;
  if (Array.isArray(x)) return x.map(printable);
  if (typeof x === 'number' && !Number.isFinite(x)) return String(x);
  if (x === undefined) return 'undefined';
  return x;
}

// Non-finite numbers given where a number is asked: a success with them accepts the impossible.
function impossibleOf(name, args) {
  const out = [];
  args.forEach((a, k) => {
    if (NONFINITE(a)) out.push(`argument ${k + 1} = ${a}`);
    if (a instanceof Float64Array && a.some((x) => !Number.isFinite(x))) out.push(`argument ${k + 1} holds a non-finite number`);
  });
  if (name === 'ipsAnalysis' && typeof args[0] !== 'string') return out;
  return out;
}

async function main() {
  const argv = process.argv.slice(2);
  const opt = (name, dflt) => { const k = argv.indexOf(`--${name}`); return k >= 0 ? Number(argv[k + 1]) : dflt; };
  const replay = argv.indexOf('--replay');
  if (replay >= 0) {
    // One saved call in a fresh instance: is the trap its own, or left by an earlier call?
    const dec = (x) => (Array.isArray(x) ? x.map(dec) : x && typeof x === 'object'
      ? ('type' in x ? new globalThis[x.type](x.values.map(dec)) : 'number' in x ? Number(x.number) : 'undefined' in x ? undefined : x) : x);
    const c = JSON.parse(readFileSync(argv[replay + 1], 'utf8'));
    c.args = dec(c.args);
    const w = new Worker(fileURLToPath(import.meta.url), { workerData: { gen: 0 } });
    w.on('message', (m) => {
      if (m.ready) w.postMessage(c);
      else if (m.start === undefined) { console.log(JSON.stringify({ call: c.name, ok: m.ok, trap: m.trap, msg: m.msg && m.msg.slice(0, 300) })); w.terminate(); }
    });
    return;
  }
  const cases = opt('cases', 1000);
  const seed = opt('seed', 1);
  const boundMs = opt('bound-s', 30) * 1000;
  const outDir = path.join(ROOT, 'target', 'fuzz');
  mkdirSync(outDir, { recursive: true });

  // The fixtures the generators draw from, made with the wasm itself.
  const W = await import(pathToFileURL(path.join(PKG, 'aes_web.js')).href);
  W.initSync({ module: readFileSync(path.join(PKG, 'aes_web_bg.wasm')) });
  const fx = { presets: {}, params: JSON.parse(W.paramMeta()).params, lessons: JSON.parse(W.lessonMeta()), signalNames: W.Run.signalNames(), shards: [] };
  fx.signals = fx.signalNames.length;
  for (const n of W.presetNames()) fx.presets[n] = W.presetJson(n);
  fx.kinds = ['monte-carlo', 'operability', 'rare-events', 'fuel-per-mile', 'storage-sizing', 'stability-map', 'rare-against'];
  fx.geometryCsv = readFileSync(path.join(ROOT, 'core', 'data', 'dtmb4119_geometry.csv'), 'utf8');
  const short = (name, d = 5) => { const sc = JSON.parse(fx.presets[name]); sc.sim.duration_s = d; if (sc.monte_carlo) sc.monte_carlo.trials = 2; return sc; };
  const specs = [
    ['monte-carlo', JSON.stringify(short('mc-wigley'))],
    ['operability', JSON.stringify({ scenario: short('head-seas-ss6'), request: { speeds_kn: [12, 15], headings_deg: [180], sea_states: [4] } })],
    ['fuel-per-mile', JSON.stringify({ scenario: short('head-seas-ss6', 20), speeds_kn: [15, 18], seeds: 1, from_s: 2 })],
    ['storage-sizing', JSON.stringify({ scenario: short('head-seas-ss6', 20), energies_j: [5e7], powers_w: [5e6] })],
  ];
  try {
    const sc = short('startup'); sc.initial.speed_kn = 20;
    const ax = (w, p, a, b) => W.stabilityAxis(JSON.stringify(sc), w, p, a, b, 2);
    fx.stabilitySpec = `{"scenario":${JSON.stringify(sc)},"x":${ax('x axis', 'plant.loads.ship_service_w', 1e6, 2e6)},"y":${ax('y axis', 'plant.loads.filter_capacitance_f', 0.01, 0.02)}}`;
    specs.push(['stability-map', fx.stabilitySpec]);
  } catch (e) { console.error(`no stability-map spec: ${e.message || e}`); }
  for (const [kind, spec] of specs) {
    try { fx.shards.push({ kind, spec, bytes: W.studyRange(kind, spec, 0, 1) }); } catch (e) { console.error(`no ${kind} shard: ${String(e.message || e).slice(0, 200)}`); }
  }

  const r = rng(seed);
  const gen = makeGen(r, fx);
  const names = Object.keys(gen).filter((n) => !n.startsWith('_'));
  // Every export is called; the list checks that none was missed (a new export needs a generator).
  const exported = Object.keys(W).filter((k) => typeof W[k] === 'function' && !['default', 'initSync'].includes(k) && !/^[A-Z]/.test(k));
  const missing = exported.filter((k) => !names.includes(k));
  for (const cls of ['Run', 'Sea']) {
    for (const m of Object.getOwnPropertyNames(W[cls].prototype)) {
      const d = Object.getOwnPropertyDescriptor(W[cls].prototype, m);
      const callable = typeof d.value === 'function' || typeof d.get === 'function';
      if (!['constructor', 'free', '__destroy_into_raw'].includes(m) && callable && !names.includes(`${cls}.${m}`)) missing.push(`${cls}.${m}`);
    }
  }
  if (missing.length) console.error(`exports without a generator: ${missing.join(', ')}`);

  const calls = [];
  for (let i = 0; i < cases; i++) {
    const name = names[i % names.length === 0 && i < names.length ? i : r.int(0, names.length - 1)] ;
    const args = gen[name]();
    const c = { i, name, args, impossible: impossibleOf(name, args) };
    if (name.includes('.')) {
      [c.cls, c.method] = name.split('.');
      if (c.method !== 'constructor' && c.method !== 'signalNames') { c.ctor = gen._scenario(); c.steps = 2000; }
    } else c.fn = name;
    calls.push(c);
  }

  const counts = { success: 0, refusal: 0, finding: 0 };
  const byKind = {};
  const perExport = {};
  const findings = [];
  const t0 = Date.now();
  let generation = 0;
  let next = 0;
  await new Promise((resolve) => {
    const start = () => {
      const w = new Worker(fileURLToPath(import.meta.url), { workerData: { gen: generation++ } });
      let timer = null;
      let current = null;
      const send = () => {
        if (next >= calls.length) { w.terminate(); resolve(); return; }
        current = calls[next++];
        const { impossible, ...msg } = current;
        w.postMessage(msg);
        timer = setTimeout(() => {
          record(current, { timeout: true });
          w.terminate();
          start();
        }, boundMs);
      };
      w.on('message', (m) => {
        if (m.ready) { send(); return; }
        if (m.start !== undefined) return;
        clearTimeout(timer);
        record(current, m);
        if (m.trap) { w.terminate(); start(); return; }
        send();
      });
      w.on('error', (e) => { clearTimeout(timer); if (current) record(current, { ok: false, trap: true, msg: String(e && e.message) }); start(); });
    };
    start();
  });

  function record(c, res) {
    const problems = judge(c, res, boundMs);
    const pe = perExport[c.name] || (perExport[c.name] = { calls: 0, success: 0, refusal: 0, finding: 0 });
    pe.calls++;
    const kind = problems.length ? 'finding' : res.ok ? 'success' : 'refusal';
    pe[kind]++;
    counts[kind]++;
    for (const [k] of problems) byKind[k] = (byKind[k] || 0) + 1;
    if (problems.some(([k]) => k === 'trap' || k === 'slow')) {
      // The whole call, to replay in a fresh instance (`--replay FILE`): typed arrays as
      // {type, values}, non-finite numbers as text.
      const enc = (x) => (x instanceof Float64Array || x instanceof Uint8Array ? { type: x.constructor.name, values: Array.from(x).map(enc) }
        : Array.isArray(x) ? x.map(enc) : typeof x === 'number' && !Number.isFinite(x) ? { number: String(x) } : x === undefined ? { undefined: true } : x);
      const { impossible, ...whole } = c;
      writeFileSync(path.join(outDir, `wasm-replay-seed${seed}-${c.i}.json`), JSON.stringify({ ...whole, args: enc(c.args) }));
    }
    if (problems.length) {
      findings.push({ call: c.name, args: printable(c.args), ctor: c.ctor !== undefined ? printable(c.ctor) : undefined, problems, error: res.msg ? res.msg.slice(0, 400) : undefined });
    }
    if ((c.i + 1) % 200 === 0) console.error(`  ${c.i + 1}/${calls.length} calls, ${((Date.now() - t0) / 1000).toFixed(0)} s`);
  }

  const elapsed = (Date.now() - t0) / 1000;
  const file = path.join(outDir, `wasm-findings-seed${seed}.json`);
  writeFileSync(file, JSON.stringify({ seed, calls: calls.length, elapsed_s: elapsed, counts, findings_by_kind: byKind, per_export: perExport, missing, findings }, null, 1));
  console.log(`fuzz-wasm: ${calls.length} calls over ${names.length} exports in ${elapsed.toFixed(0)} s (seed ${seed}): ${counts.refusal} clean refusals, ${counts.success} successes, `
    + `${counts.finding} with findings ${JSON.stringify(byKind)}; details in ${path.relative(ROOT, file)}`);
  process.exitCode = findings.length || missing.length ? 1 : 0;
}

if (isMainThread) await main();
else await workerMain();
