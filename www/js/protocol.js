// The worker protocol, shared by the page and the worker.
//
// Worker -> page, once after loading: {type: 'ready', presets: {name: json}, signals: [meta], hulls: [names],
//   params: {groups, params} (paramMeta), thesis: [{key, value, printed, unit, where, what, note}]
//   (thesisValues: the thesis' numbers we compare with, core/data/thesis_values.csv),
//   ips: [declaration] (ipsMeta: the stability tab's inputs), lessons: [lesson] (lessonMeta: the
//   lessons' controls, questions and plots, core's output::lessons)}
//   (signals: signalMeta() of the wasm, in trace column order), or, if loading fails,
//   {type: 'error', id: null, error}.
// Page -> worker: one message per request, {type, id, ...arguments}; the request types are
//   REQUEST below. Worker -> page, for each request: any number of {type: 'progress', id, ...},
//   then exactly one of {type: 'done', id, ...result} or {type: 'error', id, error}.
// Every failure has one shape: error = {message, fields?: [{path, value, message}]}; `fields`
// names scenario fields the checks refused (the form marks them). Nobody parses `message`.

export const REQUEST = {
  validate: 'validate', // {scenario} -> done {} | error with fields
  // {columns: {name: Float64Array}} (a finished run's, every signal) -> done {csv}: the trace as CSV,
  // made only when exported (core's Trace::to_csv: the native command's text to the byte).
  traceCsv: 'trace-csv',
  // {scenario, live?, lesson?} -> progress {fraction, rows?, constants?} ... done {summary, columns,
  // wall_ms, constants, lesson?}; with live, progress carries the rows recorded since the last
  // report ({name: Float64Array}) and the first also the page constants. With lesson ({name,
  // values}), done carries the run's explanation (lessonExplain: sentences, facts, verdict, next, at_s).
  run: 'run',
  // {name, values: {path: text}} -> done {scenario (JSON text), values, defaults, refused: [sentence]}:
  // a lesson's scenario with a link's values, each refused one said and the lesson's own used.
  lessonOpen: 'lesson-open',
  // A study on the shared pipeline (core's studies::study; kind: 'monte-carlo', 'operability',
  // 'rare-events'; spec: its definition as JSON text): {kind, spec, scenario, a, b, raoTable?} ->
  // done {shard}: items a..b as a binary shard (Uint8Array, moved); the pool of pool.js sends them.
  study: 'study',
  // {kind, spec, shards, scenario?} -> done {summary, constants?}: the shards merged and summarised
  // (the JSON of the study's aes-sim command, each 64-bit `seed` a string of its digits).
  studySummary: 'study-summary',
  // {kind, spec, workers} -> done {estimate: {items, item_work?, seconds?}}: what the study costs
  // on `workers` workers of this browser (core's study::estimate), asked before it starts.
  studyEstimate: 'study-estimate',
  raoTable: 'rao-table', // {scenario} -> done {values} (Float64Array: the RAO table, built once)
  trial: 'trial', // {scenario, i} -> done {scenario}: trial i's scenario as JSON text (exact seed)
  // {scenario, hist, bin} -> progress {tried} ... done {trial}: the first trial whose value falls in
  // bin `bin` of histogram `hist` (at_time, excess, excess_vs_calm, arrival), or null if none does.
  findTrial: 'find-trial',
  rao: 'rao', // {scenario, speed_kn, heading_deg, omegas} -> done {result}: RAOs of the scenario's hull
  hullSheet: 'hull-sheet', // {scenario} -> done {sheet}: body plan, profile, hydrostatics (presentation::HullSheet)
  // The propeller panel (issue 54): {scenario} -> done {sheet, wall_ms}: propellerCurves (the blades'
  // outline and pitch, KT, KQ, efficiency over J by the vortex lattice, the B-series of the same Z,
  // P/D and Ae/A0), wall_ms the worker's time for it.
  propeller: 'propeller',
  // {text, blades, hub_ratio} -> done {geometry}: a CSV blade table read by the core
  // (propellerGeometryCsv: a "custom" propeller.geometry), or the core's refusal naming row and column.
  propellerCsv: 'propeller-csv',
  fuel: 'fuel', // {scenario, omegas} -> done {rows}
  maneuvers: 'maneuvers', // {scenario} -> done {booklet, constants} (`aes-sim maneuvers`' JSON: IMO's standard maneuvers; the page constants)
  schedule: 'schedule', // {scenario} -> done {schedule} (`aes-sim schedule --json`'s schedule: turbines online by speed and sea state)
  // {args: {side, closed, point: {omega_rad_s, v_fd_v, load_a, torque_nm, from_hz, to_hz, points}}}
  // -> done {result} (the JSON of `aes-sim ips bode`)
  ips: 'ips',
  design: 'design', // {scenario} -> done {result} (LQG/LTR design and analysis, ch. 3.1)
  // The bus stability map (issue 44): {scenario (JSON text), x: {path, from, to, n}, y: {...}} ->
  // done {point, spec}: `point` the plant linearised at the scenario's own values (stabilityPoint:
  // eigenvalues, spectral_abscissa, least_damped_hz), `spec` the JSON text of the
  // "stability-map" study (its axes checked by stabilityAxis), which the study pool runs.
  stabilitySpec: 'stability-spec',
  // Rare events by conditioned simulation (issue 32). {scenario} -> done {scenario}: the scenario
  // every trial runs, as JSON text (rareScenario: the ship's place at the event from a run in
  // waves); the scenario must have a random sea and rare_event.level_h_over_r set.
  rareScenario: 'rare-scenario',
  // {scenario (rareScenario's, with rare_event.shape), passes} -> done {scenario}: the ship's place
  // and speed at the event taken from runs to the event in that scenario's own sea, `passes` times
  // (as each trial places itself; the most likely wave group slows the ship less than a random sea).
  rarePlace: 'rare-place',
};

export function messageOf(e) {
  return String(e && e.message ? e.message : e);
}

// One line for a refused field: "path = value: message".
export function fieldLine(f) {
  return `${f.path}${f.value ? ' = ' + f.value : ''}: ${f.message}`;
}

// The error of a failed request; `fields` only when the scenario checks named some.
export function errorOf(e, fields) {
  if (fields && fields.length) return { message: fields.map(fieldLine).join('\n'), fields };
  return { message: messageOf(e) };
}

export const reply = {
  ready: (presets, signals, hulls, params, thesis, ips, lessons) => ({ type: 'ready', presets, signals, hulls, params, thesis, ips, lessons }),
  progress: (id, data) => ({ type: 'progress', id, ...data }),
  done: (id, data) => ({ type: 'done', id, ...data }),
  error: (id, error) => ({ type: 'error', id, error }),
};

// A request that failed: carries the protocol's error. `cancelled` when the worker was stopped.
export class RequestError extends Error {
  constructor(error, cancelled = false) {
    super(error.message);
    this.fields = error.fields || [];
    this.cancelled = cancelled;
  }
}

// The page's end of one worker: promise-based requests with progress callbacks.
export class WorkerClient {
  constructor({ onReady = () => {}, onFailure = () => {} } = {}) {
    // Replaceable: a pooled worker reports to its present user.
    this.onFailure = onFailure;
    this.worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.pending = new Map();
    this.nextId = 0;
    this.ready = new Promise((resolve, reject) => { this.settleReady = { resolve, reject }; });
    this.ready.catch(() => {}); // a failed start is reported through onFailure
    this.worker.onmessage = (ev) => {
      const m = ev.data;
      if (m.type === 'ready') { this.settleReady.resolve(m); onReady(m); return; }
      if (m.id == null) { this.settleReady.reject(new RequestError(m.error)); this.onFailure(m.error); return; }
      const p = this.pending.get(m.id);
      if (!p) return;
      if (m.type === 'progress') { p.onProgress(m); return; }
      this.pending.delete(m.id);
      if (m.type === 'done') p.resolve(m);
      else p.reject(new RequestError(m.error || { message: `unexpected reply '${m.type}'` }));
    };
    this.worker.onerror = (e) => {
      const error = { message: messageOf(e) };
      this.settleReady.reject(new RequestError(error));
      this.failAll(error);
      this.onFailure(error);
    };
  }

  request(type, args = {}, onProgress = () => {}) {
    const id = ++this.nextId;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, onProgress });
      this.worker.postMessage({ ...args, type, id });
    });
  }

  failAll(error, cancelled = false) {
    for (const p of this.pending.values()) p.reject(new RequestError(error, cancelled));
    this.pending.clear();
  }

  // Stops the worker; its open requests fail as cancelled.
  terminate() {
    this.worker.terminate();
    this.settleReady.reject(new RequestError({ message: 'cancelled' }, true));
    this.failAll({ message: 'cancelled' }, true);
  }
}
