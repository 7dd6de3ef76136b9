// One pool of workers for every study on the shared pipeline (Monte Carlo, the operability polar,
// rare events: core's studies::study): the items go in chunks to up to `max` workers (a queue: a
// worker that finishes takes the next chunk), the first worker builds the RAO table once and hands
// it to the others, progress comes with the time left, Cancel terminates the workers, and the
// first failure stops them all. A worker that finished its share waits in `idle` for the next
// study: its wasm is then compiled and its hot code already optimised by the engine (fresh workers
// made the first study after the page opened take about half as long again).
import { durationText, startLong } from './long.js';
import { REQUEST, RequestError, WorkerClient } from './protocol.js';

// "k of n trials, about t s left": the time left from the rate so far (none in the first half second).
export function progressText(done, n, started, item) {
  const secs = (performance.now() - started) / 1000;
  const left = done && done < n && secs > 0.5 ? `, about ${((secs * (n - done)) / done).toFixed(1)} s left` : '';
  return `${done} of ${n} ${item}s${left}`;
}

export class StudyPool {
  constructor(max) { this.max = max; this.workers = []; this.idle = []; }

  // The workers a study of n items uses (idle ones first).
  size(n) { return Math.max(1, Math.min(this.max, navigator.hardwareConcurrency || 2, n)); }

  cancel() {
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }

  // Runs items 0..n of the study `kind` over size(n) workers, `chunk` items a request.
  // scenario: the JSON text whose RAO table the items read (rao = false: a study that reads none,
  // the bus stability map's linearisation, skips building it). spec: the study's definition as JSON
  // text, or an async function (first worker) -> spec, for a study whose definition a worker
  // computes first (rare events: the ship's place at the event). onProgress(done, n) after each
  // chunk (and onProgress(0, n, true) first, while the first worker prepares: the RAO table, the
  // definition, the estimate; then onProgress(0, n, false) as the items start); onStart(k) once
  // the workers are chosen. A study estimated long on them (core's
  // study::estimate) starts only when the user says so in the dialog of long.js; else it fails,
  // cancelled and `declined`, with the estimate in its message (its items named `item`). Then the
  // first worker merges and summarises the shards (with the page constants of `scenario` when
  // `constants`). Resolves to {spec, shards (binary, in item order), summary, constants?}; the
  // workers wait in `idle` afterwards.
  async run({ kind, scenario, spec, n, chunk = 1, constants = false, rao = true, item = 'item', onStart = () => {}, onProgress = () => {} }) {
    const k = this.size(n);
    let failed = null;
    this.workers = Array.from({ length: k }, () => {
      const w = this.idle.pop() || new WorkerClient();
      w.onFailure = (e) => { failed = failed || e; };
      return w;
    });
    onStart(k);
    const queue = [];
    for (let a = 0; a < n; a += chunk) queue.push([a, Math.min(n, a + chunk)]);
    const shards = new Array(queue.length);
    let done = 0;
    onProgress(0, n, true);
    try {
      const first = this.workers[0];
      await first.ready;
      const { values } = rao ? await first.request(REQUEST.raoTable, { scenario }) : {};
      const definition = typeof spec === 'function' ? await spec(first) : spec;
      const { estimate } = await first.request(REQUEST.studyEstimate, { kind, spec: definition, workers: k });
      if (!(await startLong(estimate, k, item))) {
        this.idle.push(...this.workers);
        this.workers = [];
        const e = new RequestError({ message: `Not started: ${estimate.items} ${item}s estimated at ${durationText(estimate.seconds)} on ${k} worker${k > 1 ? 's' : ''}.` }, true);
        e.declined = true;
        throw e;
      }
      let next = 0;
      onProgress(0, n, false);
      await Promise.all(this.workers.map(async (w, i) => {
        await w.ready;
        // The first worker keeps its own table; each other one loads it with its first chunk.
        let raoTable = i === 0 ? null : values;
        while (next < queue.length && !failed) {
          const j = next++;
          const [a, b] = queue[j];
          const { shard } = await w.request(REQUEST.study, { kind, spec: definition, scenario, a, b, ...(raoTable ? { raoTable } : {}) });
          raoTable = null;
          shards[j] = shard;
          done += b - a;
          onProgress(done, n);
        }
      }));
      if (failed) throw failed;
      const out = await summarise(first, kind, definition, shards, constants ? scenario : null);
      this.idle.push(...this.workers);
      this.workers = [];
      return { spec: definition, shards, ...out };
    } catch (e) {
      this.cancel();
      throw e;
    }
  }
}

// The summary of a study's binary shards, merged and summarised by `worker` (with the page
// constants of `scenario` when given). The shards are copied, not moved: a view keeps them to
// summarise again (rare events' thresholds).
export function summarise(worker, kind, spec, shards, scenario = null) {
  return worker.request(REQUEST.studySummary, { kind, spec, shards, ...(scenario ? { scenario } : {}) });
}
