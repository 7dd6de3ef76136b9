// wasm speed in Node against the native `aes-sim bench` figure, for the same preset.
// Usage: node scripts/bench-wasm.mjs [preset] (after ./build.sh build)
// Env: PKG (the wasm pkg dir, default www/pkg), NATIVE (the aes-sim binary, default
// target/release/aes-sim), REPEATS (runs of each, the best kept; default 3). On a loaded machine
// `chrt -f 10 env REPEATS=10 node scripts/bench-wasm.mjs head-seas-ss6` keeps other jobs from
// preempting the 10-20 ms runs.
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..');
const { initSync, presetJson, Run } = await import(path.join(process.env.PKG || path.join(root, 'www/pkg'), 'aes_web.js'));
initSync({ module: readFileSync(path.join(process.env.PKG || path.join(root, 'www/pkg'), 'aes_web_bg.wasm')) });
const name = process.argv[2] || 'startup';
const scenario = presetJson(name);
let best = Infinity;
const repeats = Math.max(1, Number(process.env.REPEATS) || 3);
for (let i = 0; i < repeats; i++) {
  const t0 = performance.now();
  const run = new Run(scenario);
  while (run.advance(100000) < 1) { /* run to the end */ }
  best = Math.min(best, (performance.now() - t0) / 1000);
  run.free();
}
const simulated = JSON.parse(scenario).sim.duration_s;
let native = { wall_s: Infinity };
for (let i = 0; i < repeats; i++) {
  const bin = process.env.NATIVE || path.join(root, 'target/release/aes-sim');
  const n = JSON.parse(execFileSync(bin, ['bench', name]).toString());
  if (n.wall_s < native.wall_s) native = n;
}
console.log(JSON.stringify({
  preset: name,
  simulated_s: simulated,
  wasm_wall_s: best,
  wasm_realtime_factor: simulated / best,
  native_wall_s: native.wall_s,
  native_realtime_factor: native.realtime_factor,
  wasm_over_native: best / native.wall_s,
}, null, 1));
