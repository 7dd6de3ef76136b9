// Rare events (issue 32): the rate and the consequences of one propeller surface event (ventilation
// onset or emergence of one shaft's hub) by conditioned simulation, for the simulator's study as it
// stands. The wasm makes each trial's sea bring the event at rare_event.time_s; the trials go in
// chunks to a few workers with a progress bar and Cancel; the summary (rate per hour with its
// interval beside Rice's, quantiles, rates past thresholds, worst trials) is the wasm's, and a
// change of a threshold summarises the same trials again. "Show the most likely wave group" and
// each worst trial's "Replay" run through the page's own run (plots and live views). Results are
// kept under the inputs they were computed from: stale under other values, hidden under another
// study.
import { RARE, studyTitle } from './config.js';
import { param, choiceLabel } from './registry.js';
import { $, el, fmt } from './dom.js';
import { REQUEST, WorkerClient } from './protocol.js';
import { announce } from './state.js';
import { StudyPool, summarise } from './pool.js';
import { StudyFold } from './fold.js';

const unitOf = (name) => RARE.units[name.slice(name.lastIndexOf('_') + 1)] || '-';
const clone = (x) => JSON.parse(JSON.stringify(x));

// Hours in words a person reads: "0.00270 hours (9.7 s)", "3.2 hours", "1.4e+05 hours (16 years)".
function hoursWords(h) {
  if (h === null || h === undefined || !Number.isFinite(h)) return 'never (no event in the trials)';
  const s = h * 3600;
  const plain = s < 120 ? `${s.toPrecision(2)} s` : s < 7200 ? `${(s / 60).toPrecision(2)} min` : h < 48 ? null : h < 24 * 730 ? `${(h / 24).toPrecision(2)} days` : `${(h / 8766).toPrecision(2)} years`;
  return `${fmt(h, 3)} hours${plain ? ` (${plain})` : ''}`;
}
const perHour = (x) => `${fmt(x, 4)} per hour`;
// Rice's rate beside the trials' in words from the numbers: inside their 95 % interval, or how far
// outside and which way.
export function riceWords(r, rice) {
  if (!Number.isFinite(rice) || !(r.per_hour > 0)) return 'with no rate from the trials to set it against';
  if (rice >= r.low_per_hour && rice <= r.high_per_hour) return 'within the trials\' 95 % interval';
  const rel = Math.abs(rice - r.per_hour) / r.per_hour;
  return `outside the trials' 95 % interval: ${rel >= 0.1 ? Math.round(100 * rel) : fmt(100 * rel, 2)} % ${rice < r.per_hour ? 'below' : 'above'} their rate`;
}

export class RareView {
  // inputs(): {study, title, scenario, invalid} of the simulator's form, or null while it loads;
  // sheet(scenario): the hull sheet (draft_m, hub_depth_m) of a scenario; onRun({text, name, words,
  // key, at}): run a scenario through the page's run (returns false when the page is busy).
  constructor({ inputs, sheet, onRun }) {
    this.inputs = inputs;
    this.sheet = sheet;
    this.onRun = onRun;
    this.kept = new Map(); // key -> entry
    this.shown = null;
    this.pool = new StudyPool(RARE.maxWorkers);
    this.fold = new StudyFold('rare', { failed: 'The rare-event study failed', cancel: () => this.cancel(), redFailures: true });
    this.ship = null; // the JSON of the ship section the hub depth's default belongs to
    this.hull = null; // {draft_m, hub_depth_m} of that ship
    this.plots = null; // a PlotBox, given by the page (setPlots)
    $('rare-compute').addEventListener('click', () => this.compute());
    $('rare-stale-run').addEventListener('click', () => this.compute());
    $('rare-wave').addEventListener('click', () => this.showWaveGroup());
    for (const id of ['rare-event', 'rare-shaft', 'rare-h0', 'rare-trials']) {
      $(id).addEventListener('change', () => this.sync());
      $(id).addEventListener('input', () => { $(id).removeAttribute('aria-invalid'); $(`${id}-err`) && ($(`${id}-err`).textContent = ''); });
    }
    $('rare-trials').value = String(RARE.trials);
    $('rare-h0').min = String(RARE.h0Min); $('rare-h0').max = String(RARE.h0Max);
    $('rare-trials').max = String(RARE.maxTrials);
  }

  setPlots(box) { this.plots = box; }

  // The rare view's controls: {event, shaft, h0, trials} and the refusals at their fields.
  controls() {
    const h0 = Number($('rare-h0').value), trials = Number($('rare-trials').value);
    const errors = {};
    if (!($('rare-h0').value !== '' && Number.isFinite(h0) && h0 >= RARE.h0Min && h0 <= RARE.h0Max)) errors['rare-h0'] = `Hub depth h0 = ${$('rare-h0').value || '(empty)'} m: give a depth from ${RARE.h0Min} to ${RARE.h0Max} m.`;
    if (!(Number.isInteger(trials) && trials >= 2 && trials <= RARE.maxTrials)) errors['rare-trials'] = `Trials = ${$('rare-trials').value || '(empty)'}: give a whole number from 2 to ${RARE.maxTrials} (the rate's interval is the trials' spread: one trial has none).`;
    return { event: $('rare-event').value, shaft: $('rare-shaft').value, h0, trials, errors };
  }

  // Why the study cannot have a rare-event study (no random sea), or null.
  static refusal(sc) {
    if (sc.sea && sc.sea.kind === 'random') return null;
    const field = (param('sea.kind') || {}).label || 'sea.kind', kind = sc.sea ? sc.sea.kind : '';
    return `Nothing to compute: this study's ${field.toLowerCase()} is "${choiceLabel('sea.kind', kind)}", and a rare event happens in a random sea. Choose "${choiceLabel('sea.kind', 'random')}" for "${field}" in the form (under "All parameters"), or pick a study in waves such as "${studyTitle('head-seas-ss6')}".`;
  }

  // The key of what a result depends on: the study, its values and the controls.
  keyOf(inp, c = this.controls()) { return `${inp.study}|${JSON.stringify(inp.scenario)}|${c.event}|${c.shaft}|${c.h0}|${c.trials}`; }
  currentKey() { const inp = this.inputs(); return inp ? this.keyOf(inp) : null; }

  // The study's scenario with the event: its level, shaft and hub depth (h0 = draft - hub height;
  // the scenario is left as it is when h0 is the study's own).
  scenarioOf(sc0, c) {
    const sc = clone(sc0);
    sc.rare_event = { ...(sc.rare_event || {}) };
    sc.rare_event.level_h_over_r = c.event === 'emergence' ? 1 : sc.seakeeping.ventilation_on_h_over_r;
    sc.rare_event.shaft = c.shaft;
    if (this.hull && c.h0 !== this.hull.shown) sc.ship.hull = { ...sc.ship.hull, hub_above_base_m: Number((this.hull.draft_m - c.h0).toFixed(9)) };
    sc.sim.duration_s = Math.max(sc.sim.duration_s, sc.rare_event.time_s + sc.rare_event.window_s);
    return sc;
  }

  // The hub depth's default follows the study's ship (its hull sheet, from the wasm).
  async followShip(sc) {
    const ship = JSON.stringify(sc.ship);
    if (ship === this.ship) return;
    this.ship = ship;
    this.hull = null; // (Compute waits for this ship's draft)
    try {
      const { sheet } = await this.sheet(sc);
      if (this.ship !== ship) return;
      // shown: the study's own depth as the control shows it (that value leaves the study as it is).
      this.hull = { draft_m: sheet.draft_m, hub_depth_m: sheet.hub_depth_m, shown: Number(sheet.hub_depth_m.toFixed(3)) };
      $('rare-h0').value = String(this.hull.shown);
      $('rare-h0').removeAttribute('aria-invalid');
      $('rare-h0-err').textContent = '';
      this.sync();
    } catch (e) {
      if (this.ship === ship) this.ship = null; // a cancelled request: ask again next time
    }
  }

  // After any change of the simulator's inputs or of the controls: the result of these inputs if
  // one is kept; a result of other values of the same study marked stale; none of another study.
  sync() {
    const inp = this.inputs();
    if (!inp) return;
    $('rare-study').textContent = inp.title;
    const why = RareView.refusal(inp.scenario);
    $('rare-nosea').hidden = !why;
    $('rare-nosea').textContent = why || '';
    $('rare-controls').hidden = Boolean(why);
    if (!why) this.followShip(inp.scenario);
    const c = this.controls();
    this.fold.allow(!why && !inp.invalid && this.hull);
    this.fold.refused(inp.invalid, 'A value of the form is refused (marked at its field): correct it to compute.');
    const key = this.keyOf(inp, c);
    const own = this.kept.get(key);
    if (own && own !== this.shown) this.show(own);
    else if (this.shown && this.shown.study !== inp.study) this.show(null);
    this.fold.markStale(Boolean(this.shown) && this.shown.key !== key, 'These results are of other values than the form\'s and the controls\' now (the study\'s values, the event, the shaft, the hub depth or the trials differ). Compute again to see these.');
  }

  status(text, error = false) { this.fold.status(text, error); }

  // Before the first trial (the sea's table and a run in waves to the event's place take seconds):
  // the bar moves without a share and its line says what is being done, not "0 of n".
  preparing(n) {
    $('rare-progress').removeAttribute('value');
    $('rare-eta').textContent = `Preparing the trials (the sea's response table, then a run in waves to the event's place); the first of ${n} starts after.`;
  }

  cancel() { this.pool.cancel(); }

  thresholds() {
    const out = {};
    for (const name of Object.keys(RARE.thresholds)) {
      const input = $(`rare-th-${name}`);
      const v = input ? input.value.trim() : RARE.thresholds[name] === null ? '' : String(RARE.thresholds[name]);
      if (v !== '' && Number.isFinite(Number(v))) out[name] = [Number(v)];
    }
    return out;
  }

  // Runs the trials on the study pool in chunks, the first worker building the RAO table and the
  // trials' scenario (the study's definition), then summarises them.
  async compute() {
    const inp = this.inputs();
    if (!inp || this.fold.busy || inp.invalid || RareView.refusal(inp.scenario) || !this.hull) return;
    const c = this.controls();
    for (const id of ['rare-h0', 'rare-trials']) {
      if (c.errors[id]) $(id).setAttribute('aria-invalid', 'true'); else $(id).removeAttribute('aria-invalid');
      $(`${id}-err`).textContent = c.errors[id] || '';
    }
    const bad = Object.keys(c.errors)[0];
    if (bad) { $(bad).focus(); return; }
    const key = this.keyOf(inp, c);
    const study = JSON.stringify(this.scenarioOf(inp.scenario, c));
    const n = c.trials;
    const started = performance.now();
    const chunk = Math.max(1, Math.min(25, Math.ceil(n / (this.pool.size(n) * 6))));
    let trial = null;
    // The definition every shard carries: the trials' scenario, their number, the thresholds.
    const specOf = async (first) => {
      ({ scenario: trial } = await first.request(REQUEST.rareScenario, { scenario: study }));
      return this.specOf(trial, n);
    };
    await this.fold.compute(async () => {
      const { shards, summary } = await this.pool.run({
        kind: 'rare-events', scenario: study, spec: specOf, n, chunk, item: 'trial',
        onStart: (k) => this.status(`Rare events: ${n} trials on ${k} worker${k > 1 ? 's' : ''}...`),
        onProgress: (done, _, preparing) => (preparing ? this.preparing(n) : this.fold.progress(done, n, started, 'trial')),
      });
      const entry = { key, study: inp.study, title: inp.title, controls: c, trial, shards, summary, ms: performance.now() - started };
      this.kept.delete(key);
      this.kept.set(key, entry);
      while (this.kept.size > RARE.kept) this.kept.delete(this.kept.keys().next().value);
      this.show(entry);
      this.status(`Done: ${n} trials in ${(entry.ms / 1000).toFixed(1)} s.`);
      $('rare-results').focus(); // the results, in view (a phone's screen holds the controls)
    }, { after: () => this.sync() });
  }

  // The study's definition (core's rare::RareSpec) as JSON text: the trials' scenario (text, its
  // 64-bit seed exact), the number of trials and the thresholds typed.
  specOf(trial, n) { return `{"scenario": ${trial}, "trials": ${n}, "thresholds": ${JSON.stringify(this.thresholds())}}`; }

  // The same trials summarised again with the thresholds typed (no trial runs again).
  async resummarise() {
    const entry = this.shown;
    if (!entry) return;
    try {
      const { summary } = await summarise(this.helper(), 'rare-events', this.specOf(entry.trial, entry.controls.trials), entry.shards);
      entry.summary = summary;
      if (this.shown === entry) { this.thresholdTable(summary); announce('rare', { summary, trial: entry.trial }); }
    } catch (e) {
      if (!e.cancelled) this.status(`The thresholds could not be applied: ${e.message}`, true);
    }
  }

  show(entry) {
    this.shown = entry;
    $('rare-body').hidden = !entry;
    if (this.plots) this.plots.clear();
    $('rare-showing').textContent = '';
    announce('rare', entry ? { summary: entry.summary, trial: entry.trial } : null);
    if (!entry) return;
    const s = entry.summary;
    const r = s.rate;
    const lo = r.high_per_hour > 0 ? 1 / r.high_per_hour : null, hi = r.low_per_hour > 0 ? 1 / r.low_per_hour : null;
    const plain = (h) => (h === null ? 'never' : fmt(h, 3));
    // More than one an hour reads as a count per hour (a fraction of an hour between events does
    // not), and is called frequent: at such settings the event is not rare (issue 43).
    const every = () => hoursWords(r.once_every_hours).replace(/^.*\((.*)\)$/, '$1');
    $('rare-headline').textContent = !(r.per_hour > 0)
      ? `No event in ${s.trials} trials`
      : r.per_hour > 1
        ? `About ${fmt(r.per_hour, 3)} an hour (95 %: ${fmt(r.low_per_hour, 3)} to ${fmt(r.high_per_hour, 3)}), one every ${every()}: at these settings the event is frequent, not rare`
        : `About once every ${fmt(r.once_every_hours, 3)} hours (95 %: ${plain(lo)} to ${plain(hi)} hours)${r.once_every_hours < 2 ? `, that is every ${every()}` : ''}`;
    $('rare-event-line').textContent = `The event: ${s.event}, at ${fmt(r.per_hour, 4)} per hour.`;
    const simulated = s.simulated_s >= 3600 ? `${fmt(s.simulated_s / 3600, 3)} h` : `${fmt(s.simulated_s / 60, 3)} min`;
    $('rare-facts').textContent = `Crossing rate ${perHour(r.per_hour)} (95 %: ${fmt(r.low_per_hour, 4)} to ${fmt(r.high_per_hour, 4)}), from ${s.trials} trials (${simulated} simulated); Rice's formula for the hub's depth swing gives ${perHour(s.rice_per_hour)}, ${riceWords(r, s.rice_per_hour)}. Hub ${fmt(s.hub_depth_m, 3)} m below the calm surface, ship at ${fmt(s.speed_kn, 3)} kn; the hub's depth swings with a standard deviation of ${fmt(s.hub_sigma_m, 3)} m, and the level h/R = ${s.level_h_over_r} lies ${fmt(s.level_sigmas, 3)} standard deviations from the calm hub depth.`;
    $('rare-method').textContent = `Method: ${s.method}. h/R at the event as the runs recorded it: mean ${fmt(s.h_over_r_at_event_mean, 4)}, at most ${fmt(s.h_over_r_at_event_worst, 2)} from the level.`;
    $('rare-wave').textContent = 'Show the most likely wave group';
    this.histograms(s);
    this.thresholdTable(s);
    this.worstTable(s);
  }

  histograms(s) {
    const box = this.plots;
    if (!box) return;
    const rows = [];
    for (const c of s.consequences) {
      const unit = unitOf(c.name);
      const xs = c.values;
      const bins = Math.max(5, Math.min(30, Math.ceil(Math.sqrt(xs.length))));
      const title = `${c.label} [${unit}], given the event: ${s.trials} trials`;
      rows.push([`${RARE.short[c.name] || c.name} [${unit}]`, c.q05, c.q50, c.q95, c.q99, c.min, c.max]);
      // Every trial alike (no brake energy at all): said, not drawn as one bar.
      if (!(c.max > c.min)) { box.panel(title, box.generation, false, el('p', { className: 'rare-same', textContent: `Every trial: ${fmt(c.min)} ${unit}.` })); continue; }
      const lo = c.min, hi = c.max;
      const w = (hi - lo) / bins;
      const counts = new Array(bins).fill(0);
      for (const v of xs) counts[Math.min(bins - 1, Math.max(0, Math.floor((v - lo) / w)))]++;
      const vlines = RARE.quantiles.map(([q, label, color, dash]) => ({ x: c[q], label, color, dash }));
      box.histogram(title, { lo, hi, counts }, `${RARE.short[c.name] || c.name} [${unit}]`, null, undefined, null,
        { vlines, edges: true, key: [`Quantiles given the event (weighted by each sea's crossing rate), drawn as labelled lines: 5 % ${fmt(c.q05)}, 50 % ${fmt(c.q50)}, 95 % ${fmt(c.q95)}, 99 % ${fmt(c.q99)} ${unit}.`] });
    }
    $('rare-quantiles').replaceChildren(el('table', { id: 'rare-quantiles-table', attrs: { 'aria-labelledby': 'rare-quantiles-cap' } },
      el('thead', {}, el('tr', {}, ...['consequence', '5 %', '50 %', '95 %', '99 %', 'lowest', 'highest'].map((h) => el('th', { scope: 'col', textContent: h })))),
      el('tbody', {}, ...rows.map(([name, ...v]) => el('tr', {}, el('th', { scope: 'row', textContent: name }), ...v.map((x) => el('td', { textContent: fmt(x) })))))));
  }

  // Rate per hour past a threshold, one input per consequence; a change summarises again.
  thresholdTable(s) {
    const old = Object.fromEntries(Object.keys(RARE.thresholds).map((n) => [n, $(`rare-th-${n}`) ? $(`rare-th-${n}`).value : null]));
    const body = s.consequences.map((c) => {
      const unit = unitOf(c.name);
      const id = `rare-th-${c.name}`;
      const worse = c.name.startsWith('min_') ? 'below' : 'above';
      const v = old[c.name] !== null ? old[c.name] : RARE.thresholds[c.name] === null ? '' : String(RARE.thresholds[c.name]);
      const input = el('input', { type: 'number', id, value: v, step: 'any', className: 'rare-th', attrs: { 'aria-label': `Threshold of the ${RARE.short[c.name] || c.label} [${unit}] (${worse} it counts)` } });
      input.addEventListener('change', () => this.resummarise());
      const b = c.beyond[0];
      const cells = b ? [`${b.trials} of ${s.trials}`, `${fmt(b.rate.per_hour, 4)} (${fmt(b.rate.low_per_hour, 3)} to ${fmt(b.rate.high_per_hour, 3)})`, hoursWords(b.rate.once_every_hours)] : ['–', '–', '–'];
      return el('tr', {}, el('th', { scope: 'row', textContent: `${RARE.short[c.name] || c.label} [${unit}], ${worse}` }), el('td', {}, input), ...cells.map((t) => el('td', { textContent: t })));
    });
    $('rare-thresholds').replaceChildren(el('table', { id: 'rare-thresholds-table', attrs: { 'aria-labelledby': 'rare-thresholds-cap' } },
      el('thead', {}, el('tr', {}, ...['consequence, counted', 'threshold', 'trials past it', 'per hour (95 %)', 'once every'].map((h) => el('th', { scope: 'col', textContent: h })))),
      el('tbody', {}, ...body)));
  }

  // One row per consequence, its worst trials as Replay buttons (a consequence every trial has
  // alike, such as no brake energy at all, has no worst trial).
  worstTable(s) {
    const same = [];
    const rows = s.consequences.map((c) => {
      const unit = unitOf(c.name);
      if (!(c.max > c.min)) { same.push(`${RARE.short[c.name]} ${fmt(c.min)} ${unit}`); return null; }
      const cells = s.worst.filter((w) => w.consequence === c.name).map((w) => {
        const b = el('button', { type: 'button', className: 'rare-replay', attrs: { 'data-seed': w.seed, 'data-trial': String(w.trial) } },
          `Replay trial ${w.trial}`, el('span', { className: 'rare-v', textContent: ` ${fmt(w.value)} ${unit}` }));
        b.addEventListener('click', () => this.replay(w, c));
        return el('td', {}, b);
      });
      return el('tr', {}, el('th', { scope: 'row', textContent: `${RARE.short[c.name]} [${unit}]` }), ...cells);
    }).filter(Boolean);
    $('rare-worst').replaceChildren(el('table', { id: 'rare-worst-table', attrs: { 'aria-labelledby': 'rare-worst-cap' } },
      el('thead', {}, el('tr', {}, ...['consequence', 'worst', 'second', 'third'].map((h) => el('th', { scope: 'col', textContent: h })))),
      el('tbody', {}, ...rows)),
      ...(same.length ? [el('p', { className: 'hint', textContent: `The same in every trial: ${same.join('; ')}.` })] : []));
  }

  eventWords(s) { return `${s.shaft} hub through h/R = ${s.level_h_over_r} at t = ${JSON.parse(this.shown.trial).rare_event.time_s} s`; }

  // A worker for the page's small requests (an idle one of the study's, which holds the RAO table).
  helper() {
    if (!this.pool.idle.length) this.pool.idle.push(new WorkerClient());
    return this.pool.idle[0];
  }

  // The trials' scenario with the conditional mean sea (NewWave), through the page's run. The
  // ship's place at the event is taken in that sea first (as each trial takes it in its own).
  async showWaveGroup() {
    const e = this.shown;
    if (!e || this.fold.busy) return;
    const sc = JSON.parse(e.trial);
    sc.rare_event.shape = 'most_likely';
    $('rare-showing').textContent = 'Placing the ship at the event in the most likely wave group...';
    let text;
    try {
      ({ scenario: text } = await this.helper().request(REQUEST.rarePlace, { scenario: JSON.stringify(sc), passes: RARE.placePasses }));
    } catch (err) {
      $('rare-showing').textContent = err.cancelled ? '' : `The most likely wave group failed: ${err.message}`;
      return;
    }
    if (this.shown !== e) return;
    const words = `the most likely wave group that brings the ${this.eventWords(e.summary)} (the conditional mean sea, NewWave)`;
    this.run(e, text, `${e.title}, rare event: the most likely wave group`, words, sc.rare_event.time_s);
  }

  // A worst trial: the trials' scenario with its sea's seed (64 bits, written exactly) and the
  // ship's place and speed at the event as the trial took them (the worst trial's own `sets`,
  // numbers written in full by the summary): the run is the trial's own.
  replay(w, c) {
    const e = this.shown;
    if (!e) return;
    const sc = JSON.parse(e.trial);
    sc.sim.seed = '__SEED__';
    for (const set of w.sets) {
      const [path, value] = set.split('=');
      const [section, field] = path.split('.');
      if (section === 'rare_event' && field.startsWith('ship_') && field in sc.rare_event) sc.rare_event[field] = Number(value);
    }
    const text = JSON.stringify(sc).replace('"__SEED__"', w.seed);
    const words = `trial ${w.trial} (sea seed ${w.seed}), one of the worst for the ${RARE.short[c.name]} (${fmt(w.value)} ${unitOf(c.name)} over the ${sc.rare_event.window_s} s after the event): its sea brings the ${this.eventWords(e.summary)}`;
    this.run(e, text, `${e.title}, rare event: trial ${w.trial}`, words, sc.rare_event.time_s);
  }

  run(e, text, name, words, at) {
    const why = this.onRun({ text, name, words, key: e.key, at, hr: e.summary.shaft === 'starboard' ? 'h_over_r_stbd' : 'h_over_r', shaft: e.summary.shaft });
    if (why) { $('rare-showing').textContent = why; return; }
    $('rare-showing').textContent = `Shown in the live views and plots: ${words}. The views stop at the event; press Play there to watch what follows.`;
  }
}
