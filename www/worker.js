// Module worker: loads the wasm and runs scenarios in chunks, reporting progress.
import init, { presetNames, presetJson, Run } from './pkg/aes_web.js';

await init();
const presets = {};
for (const n of presetNames()) presets[n] = presetJson(n);
postMessage({ type: 'ready', presets });

onmessage = (ev) => {
  const m = ev.data;
  if (m.type !== 'run') return;
  const t0 = performance.now();
  let run;
  try {
    run = new Run(m.scenario);
    let done = 0;
    while (done < 1) {
      done = run.advance(20000);
      postMessage({ type: 'progress', fraction: done });
    }
    const summary = run.summaryJson();
    postMessage({
      type: 'done',
      summary,
      simulated_s: JSON.parse(summary).final_time_s,
      wall_ms: performance.now() - t0,
    });
  } catch (e) {
    postMessage({ type: 'error', message: String(e && e.message ? e.message : e) });
  } finally {
    if (run) run.free();
  }
};
