// Module worker: loads the wasm and runs scenarios in chunks, reporting progress. The main thread
// never runs physics. Cancel = the page terminates this worker and starts a fresh one.
import init, { presetNames, presetJson, validateScenario, Run, ipsAnalysis, mcRange, mcSummary, raoJson, fuelStudy } from './pkg/aes_web.js';

await init();
const presets = {};
for (const n of presetNames()) presets[n] = presetJson(n);
postMessage({ type: 'ready', presets, signals: Run.signalNames() });

function runScenario(id, scenario) {
  const t0 = performance.now();
  let run;
  try {
    run = new Run(scenario);
    let done = 0;
    let lastReport = 0;
    while (done < 1) {
      done = run.advance(20000);
      const now = performance.now();
      if (now - lastReport > 100 || done >= 1) {
        postMessage({ type: 'progress', id, fraction: done, elapsed_ms: now - t0 });
        lastReport = now;
      }
    }
    const summary = run.summaryJson();
    const columns = {};
    const transfer = [];
    for (const name of Run.signalNames()) {
      const col = run.column(name);
      columns[name] = col;
      transfer.push(col.buffer);
    }
    postMessage({ type: 'done', id, summary, columns, csv: run.traceCsv(), wall_ms: performance.now() - t0 }, transfer);
  } catch (e) {
    postMessage({ type: 'error', id, message: String(e && e.message ? e.message : e) });
  } finally {
    if (run) run.free();
  }
}

// A worker's trials stay as separate partials (merging needs the exact integer sums, which only
// the Rust side holds); the summary worker merges them all.
function mcSummaryPartials(parts) { return parts; }

onmessage = (ev) => {
  const m = ev.data;
  if (m.type === 'run') {
    runScenario(m.id, m.scenario);
  } else if (m.type === 'validate') {
    try {
      postMessage({ type: 'validated', id: m.id, errors: validateScenario(m.scenario) });
    } catch (e) {
      postMessage({ type: 'validated', id: m.id, errors: [{ path: '(scenario)', value: '', message: String(e) }] });
    }
  } else if (m.type === 'mc') {
    // Monte Carlo trials a..b in about ten chunks: progress after each, and few partials to merge
    // (each carries whole envelopes).
    try {
      const parts = [];
      const chunk = Math.max(1, Math.ceil((m.b - m.a) / 10));
      for (let i = m.a; i < m.b; i += chunk) {
        const j = Math.min(m.b, i + chunk);
        parts.push(mcRange(m.scenario, i, j));
        postMessage({ type: 'mc-progress', id: m.id, done: j - m.a });
      }
      postMessage({ type: 'mc-done', id: m.id, partial: mcSummaryPartials(parts) });
    } catch (e) {
      postMessage({ type: 'error', id: m.id, message: String(e && e.message ? e.message : e) });
    }
  } else if (m.type === 'mc-summary') {
    try {
      postMessage({ type: 'mc-summary', id: m.id, summary: mcSummary(m.partials.flat()) });
    } catch (e) {
      postMessage({ type: 'error', id: m.id, message: String(e && e.message ? e.message : e) });
    }
  } else if (m.type === 'fuel') {
    try {
      postMessage({ type: 'fuel', id: m.id, rows: JSON.parse(fuelStudy(m.scenario, new Float64Array(m.omegas))) });
    } catch (e) {
      postMessage({ type: 'fuel', id: m.id, error: String(e && e.message ? e.message : e) });
    }
  } else if (m.type === 'rao') {
    try {
      postMessage({ type: 'rao', id: m.id, result: JSON.parse(raoJson(m.speed_kn, m.heading_deg, new Float64Array(m.omegas))) });
    } catch (e) {
      postMessage({ type: 'rao', id: m.id, error: String(e && e.message ? e.message : e) });
    }
  } else if (m.type === 'ips') {
    try {
      const a = m.args;
      const out = ipsAnalysis(a.side, a.omega, a.vfd, a.load, a.torque, a.closed, a.from_hz, a.to_hz, a.points);
      postMessage({ type: 'ips', id: m.id, result: JSON.parse(out) });
    } catch (e) {
      postMessage({ type: 'ips', id: m.id, error: String(e && e.message ? e.message : e) });
    }
  }
};
