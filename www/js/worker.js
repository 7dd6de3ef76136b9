// Module worker: loads the wasm and answers the requests of protocol.js. Runs go in chunks with
// progress reports; the main thread never runs physics. Cancel = the page terminates this worker
// and starts a fresh one.
import init, { presetNames, presetJson, validateScenario, signalMeta, paramMeta, thesisValues, pageConstants, Run, ipsAnalysis, ipsMeta, studyRange, studySummary, studyEstimate, trialScenario, raoJson, fuelStudy, maneuversBooklet, turbineSchedule, designLqgLtr, raoTableValues, raoTableLoad, trialBins, hullSheet, hullNames, propellerCurves, propellerGeometryCsv, rareScenario, rarePlace, lessonMeta, lessonOpen, traceCsvOf, stabilityPoint, stabilityAxis } from '../pkg/aes_web.js';
import { REQUEST, reply, errorOf } from './protocol.js';
import { RUN_CHUNK_STEPS, PROGRESS_EVERY_MS } from './config.js';

let signals = [];

// Field errors of a scenario (JSON text): [] when it passes the checks.
function check(scenario) {
  try { return validateScenario(scenario); } catch (e) { return [{ path: '(scenario)', value: '', message: String(e) }]; }
}

// Refuses a scenario the checks refuse, with the refused fields.
function checked(scenario) {
  const fields = check(scenario);
  if (fields.length) throw Object.assign(new Error('invalid scenario'), { fields });
  return scenario;
}

const constantsOf = (scenario) => JSON.parse(pageConstants(scenario));

const handlers = {
  [REQUEST.validate]: (m) => { checked(m.scenario); return {}; },

  [REQUEST.traceCsv]: (m) => {
    const cols = signals.map(({ name }) => m.columns[name]);
    const rows = cols.length && cols[0] ? cols[0].length : 0;
    const flat = new Float64Array(cols.length * rows);
    cols.forEach((c, i) => flat.set(c, i * rows));
    return { csv: traceCsvOf(flat, rows) };
  },

  [REQUEST.run]: (m, progress) => {
    const t0 = performance.now();
    const run = new Run(checked(m.scenario));
    try {
      let done = 0, lastReport = 0, sent = 0;
      // With m.live, each report carries the rows recorded since the last one (and the first
      // the page constants), so the page's live views follow the run as it goes.
      const rows = () => {
        const n = run.rows();
        if (!m.live || n <= sent) return {};
        const out = {};
        for (const { name } of signals) out[name] = run.columnFrom(name, sent);
        const first = sent === 0;
        sent = n;
        return first ? { rows: out, constants: constantsOf(m.scenario) } : { rows: out };
      };
      while (done < 1) {
        done = run.advance(RUN_CHUNK_STEPS);
        const now = performance.now();
        if (now - lastReport > PROGRESS_EVERY_MS && done < 1) { progress({ fraction: done, ...rows() }); lastReport = now; }
      }
      progress({ fraction: 1 });
      const columns = {};
      const transfer = [];
      for (const { name } of signals) {
        columns[name] = run.column(name);
        transfer.push(columns[name].buffer);
      }
      // A lesson's run: its explanation from the same finished run (core's output::lessons).
      const lesson = m.lesson ? JSON.parse(run.lessonExplain(m.lesson.name, JSON.stringify(m.lesson.values), m.lesson.before ? JSON.stringify(m.lesson.before) : null)) : undefined;
      return [{ summary: JSON.parse(run.summaryJson()), columns, wall_ms: performance.now() - t0, constants: constantsOf(m.scenario), lesson }, transfer];
    } finally {
      run.free();
    }
  },

  // Items a..b of a study (core's studies::study: Monte Carlo, operability, rare events) as one
  // binary shard, moved to the page; the RAO table comes from the pool's first worker (built once)
  // with this worker's first chunk, and stays in its cache.
  [REQUEST.study]: (m) => {
    if (m.raoTable) raoTableLoad(m.scenario, m.raoTable);
    const shard = studyRange(m.kind, m.spec, m.a, m.b);
    return [{ shard }, [shard.buffer]];
  },

  // The shards merged and summarised (the JSON of the study's aes-sim command); every 64-bit
  // `seed` is kept exact as a string of its digits. With a scenario, its page constants too.
  [REQUEST.studySummary]: (m) => {
    const text = studySummary(m.kind, m.spec, m.shards).replace(/"seed":(\d+)/g, '"seed":"$1"');
    return { summary: JSON.parse(text), ...(m.scenario ? { constants: constantsOf(m.scenario) } : {}) };
  },

  [REQUEST.studyEstimate]: (m) => ({ estimate: JSON.parse(studyEstimate(m.kind, m.spec, m.workers)) }),

  [REQUEST.lessonOpen]: (m) => JSON.parse(lessonOpen(m.name, JSON.stringify(m.values || {}))),

  [REQUEST.raoTable]: (m) => {
    const values = raoTableValues(checked(m.scenario));
    return [{ values }, [values.buffer]];
  },

  [REQUEST.trial]: (m) => ({ scenario: trialScenario(checked(m.scenario), m.i) }),

  // Trials run in order until one lands in the bar (a trial's seed reproduces it; the summary keeps
  // no per-trial values). Bounded by the study's trials.
  [REQUEST.findTrial]: (m, progress) => {
    const n = Number(JSON.parse(checked(m.scenario)).monte_carlo.trials);
    let last = performance.now();
    for (let i = 0; i < n; i++) {
      if (JSON.parse(trialBins(m.scenario, i))[m.hist] === m.bin) return { trial: i };
      if (performance.now() - last > PROGRESS_EVERY_MS) { progress({ tried: i + 1 }); last = performance.now(); }
    }
    return { trial: null };
  },

  [REQUEST.maneuvers]: (m) => ({ booklet: JSON.parse(maneuversBooklet(checked(m.scenario))), constants: constantsOf(m.scenario) }),
  [REQUEST.schedule]: (m) => ({ schedule: JSON.parse(turbineSchedule(checked(m.scenario))) }),
  [REQUEST.fuel]: (m) => ({ rows: JSON.parse(fuelStudy(checked(m.scenario), new Float64Array(m.omegas))) }),

  [REQUEST.rao]: (m) => ({ result: JSON.parse(raoJson(checked(m.scenario), m.speed_kn, m.heading_deg, new Float64Array(m.omegas))) }),

  [REQUEST.hullSheet]: (m) => ({ sheet: JSON.parse(hullSheet(checked(m.scenario))) }),

  // The scenario is checked by propellerCurves itself; only a refusal asks for the fields by name.
  [REQUEST.propeller]: (m) => {
    const t0 = performance.now();
    let text;
    try { text = propellerCurves(m.scenario); } catch (e) { checked(m.scenario); throw e; }
    return { sheet: JSON.parse(text), wall_ms: performance.now() - t0 };
  },
  [REQUEST.propellerCsv]: (m) => ({ geometry: JSON.parse(propellerGeometryCsv(m.text, m.blades, m.hub_ratio)) }),

  // The scenario every trial of a rare-event study runs (the ship's place at the event from a run
  // in waves), as JSON text.
  [REQUEST.rareScenario]: (m) => ({ scenario: rareScenario(checked(m.scenario)) }),

  // The ship placed at the event in the scenario's own conditioned sea (core's rare::place_ship).
  [REQUEST.rarePlace]: (m) => ({ scenario: rarePlace(checked(m.scenario), m.passes) }),

  [REQUEST.design]: (m) => ({ result: JSON.parse(designLqgLtr(checked(m.scenario))) }),
  // The operating point first (its error names the field: a speed of 0 kn), then each axis checked
  // as the command line checks it; the spec is put together from their texts unparsed (the
  // scenario's numbers as the page sent them).
  [REQUEST.stabilitySpec]: (m) => {
    const sc = checked(m.scenario);
    const point = JSON.parse(stabilityPoint(sc));
    const axis = (which, a) => stabilityAxis(sc, which, a.path, a.from, a.to, a.n);
    return { point, spec: `{"scenario":${sc},"x":${axis('x axis', m.x)},"y":${axis('y axis', m.y)}}` };
  },
  [REQUEST.ips]: (m) => {
    const { side, closed, point: p } = m.args;
    return { result: JSON.parse(ipsAnalysis(side, p.omega_rad_s, p.v_fd_v, p.load_a, p.torque_nm, closed, p.from_hz, p.to_hz, p.points)) };
  },
};

// Requests that arrive while the wasm loads wait for it (in order).
let loaded;

onmessage = async (ev) => {
  const m = ev.data;
  try { await loaded; } catch (_) { return; } // the page was told in the failure message
  const handler = handlers[m.type];
  try {
    if (!handler) throw new Error(`unknown request '${String(m.type).slice(0, 40)}'`);
    const out = handler(m, (data) => postMessage(reply.progress(m.id, data)));
    const [data, transfer] = Array.isArray(out) ? out : [out, []];
    postMessage(reply.done(m.id, data), transfer);
  } catch (e) {
    postMessage(reply.error(m.id, errorOf(e, e && e.fields)));
  }
};

loaded = init().then(() => {
  signals = JSON.parse(signalMeta());
  const presets = {};
  for (const n of presetNames()) presets[n] = presetJson(n);
  postMessage(reply.ready(presets, signals, hullNames(), JSON.parse(paramMeta()), JSON.parse(thesisValues()), JSON.parse(ipsMeta()), JSON.parse(lessonMeta())));
});
loaded.catch((e) => postMessage(reply.error(null, errorOf(e))));
