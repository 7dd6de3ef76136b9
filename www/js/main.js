// The page: wires the study picker and form, the worker, the plots, kept runs, share links and the
// address bar, exports, presentation mode and the stability tab.
import { DESIGN, DEFAULT_PRESET, SUMMARY_ROWS, STUDIES, DEFAULT_PLOTS, KEY_FIGURES, HULL, studyTitle } from './config.js';
import { $, el, row, download, fmt } from './dom.js';
import { REQUEST, WorkerClient, fieldLine } from './protocol.js';
import { setPhase, isBusy, setResult, getResult, progress, status, notice, etaText, setFormValid } from './state.js';
import { linkHash, readLink, diff } from './link.js';
import { ScenarioForm, setPath, leafPaths } from './form.js';
import { Signals, withPrefix } from './units.js';
import { setRegistry } from './registry.js';
import { PlotBox, drawRun, drawSeaExtras, presentPlots } from './plots.js';
import { MonteCarlo, showMonteCarlo } from './montecarlo.js';
import { StabilityTab } from './stability.js';
import { DesignTab } from './design.js';
import { LiveViews } from './live.js';
import { HullPanel, HullPicker, num } from './hull.js';

const plots = new PlotBox($('plots'), { more: $('more-plots'), moreBox: $('more-plots-box'), sync: 'run' });
const monteCarlo = new MonteCarlo();
const live = new LiveViews($('live'), plots);
// Set once the first worker is ready; `client` is replaced by a fresh worker after a cancel.
let client = null;
let form = null;
let signals = null;
let thesis = []; // the thesis' numbers we compare with (the worker's thesisValues)
let kept = null; // a kept run: {name, columns, summary}
let hullPicker = null;
// The hull panel; its sheet also gives the loading fields their placeholders (the hull's own
// values) and the hub height its h0.
const hullPanel = new HullPanel($('hull-box'), () => client, {
  // Placeholders as numbers one could type (no thousands separators).
  onSheet: (h) => form && form.showHullValues(Object.fromEntries([
    ['draft_m', h.draft_m], ['mass_kg', h.mass_kg], ['kg_m', h.kg_m], ['kxx_m', h.k_m[0]], ['kyy_m', h.k_m[1]], ['kzz_m', h.k_m[2]], ['hub_above_base_m', h.hub_above_base_m],
  ].map(([k, v]) => [`ship.hull.${k}`, `${Math.abs(v) >= 1000 ? String(Math.round(v)) : num(v)} (now)`])), { 'ship.hull.hub_above_base_m': ` Now h0 = ${num(h.draft_m)} - ${num(h.hub_above_base_m)} = ${num(h.hub_depth_m)} m.` }),
});
// The picker and the panel follow the scenario in the form.
function refreshHull() {
  if (!form || !form.scenario) return;
  const sc = form.current();
  if (hullPicker) hullPicker.sync(sc);
  hullPanel.update(sc, hullPicker ? hullPicker.fileOf(sc) : null);
}
const stability = new StabilityTab(() => client, new PlotBox($('ips-plots')));
// The design tab's "run next to the PI loops": the acceleration with the PI loops, kept, then
// again with this LQG/LTR tuning, drawn over it.
const design = new DesignTab(() => client, new PlotBox($('design-plots')), () => form.preset(DESIGN.basePreset), (tuning) => {
  if (isBusy() || !form) return;
  selectTab('tab-sim');
  selectStudy(DESIGN.basePreset);
  const set = { 'controllers.design': 'lqg_ltr' };
  for (const [k, v] of Object.entries(tuning)) set[`controllers.lqg_ltr.${k}`] = v;
  compareWith({ set });
});

function startWorker() {
  setPhase('loading');
  client = new WorkerClient({
    onReady,
    onFailure: (e) => status(`The simulator failed to load: ${e.message}`, true),
  });
}

const validate = (sc) => client.request(REQUEST.validate, { scenario: JSON.stringify(sc) });

// The address follows the study: '#v=1&preset=NAME' (a copied link adds the edits).
const studyHash = (name) => linkHash(name, form.preset(name), form.preset(name));
function follow(name, push) {
  const h = studyHash(name);
  if (location.hash === h) return;
  history[push ? 'pushState' : 'replaceState'](null, '', h);
}

// The scenario of a hash: null without one, {refused: true} (after saying why) when it cannot be
// used, else {name, scenario, edited}, validated.
async function openLink(hash) {
  const link = readLink(hash, form.presets);
  if (!link) return null;
  const refuse = (why) => {
    notice(`This link could not be used: ${why}. Showing the ${studyTitle(DEFAULT_PRESET)} study instead.`);
    return { refused: true };
  };
  if (link.refused) return refuse(link.refused);
  try {
    await validate(link.scenario);
  } catch (e) {
    return refuse(e.fields.length ? e.fields.slice(0, 3).map(fieldLine).join('; ') : e.message);
  }
  const d = diff(form.preset(link.name), link.scenario);
  return { ...link, edited: d === undefined ? [] : leafPaths(d) };
}

async function onReady(m) {
  if (form) { setPhase('idle'); return; } // a fresh worker after a cancel: the page stays as it is
  signals = new Signals(m.signals);
  setRegistry(m.params);
  design.configure(m.params);
  thesis = m.thesis || [];
  stability.setMeta(m.ips);
  form = new ScenarioForm(m.presets, m.params, { onLooseErrors: (text) => status(text, true), onEdit, onValidity: setFormValid, onSelect: () => { showCompareButtons(); refreshHull(); forgetLink(); } });
  hullPicker = new HullPicker(m.hulls || [], {
    form, validate, say: status, busy: isBusy,
    // An accepted hull or scenario file: into the form (a scenario file may name its study).
    commit: (sc, { name } = {}) => {
      if (name && name !== form.name) { form.select(name, sc); follow(name, true); } else { form.scenario = sc; form.fill(); }
      form.save();
      onEdit();
    },
  });
  const linked = await openLink(location.hash.slice(1));
  if (linked && !linked.refused && (linked.edited.length || linked.view)) {
    form.select(linked.name, linked.scenario);
    form.markLinked(linked.edited);
    setPhase('idle');
    if (linked.edited.length) status(`This link changed ${linked.edited.length} value(s) of the study (marked in the form).`);
    await run({ focus: false });
    if (linked.view) live.place(linked.view);
    return;
  }
  const saved = linked && linked.refused ? null : form.saved();
  const want = linked && !linked.refused ? linked.name : null;
  let restored = false;
  if (saved && (!want || want === saved.preset)) {
    try {
      await validate(saved.scenario);
      form.select(saved.preset, saved.scenario);
      restored = true;
    } catch (_) { /* stale edits: start from the preset */ }
  }
  if (!restored) form.select(want || DEFAULT_PRESET);
  follow(form.name, false);
  setPhase('idle');
  status(restored ? 'Your last edits are back.' : 'Ready. Choose a study and press Run.');
}

// After an accepted edit: the scenario is checked at once (errors at the field, Run waits), and
// a page opened from a link now shows the study, not the link's values.
let validating = 0;
async function onEdit() {
  follow(form.name, false);
  forgetLink();
  const mine = ++validating;
  try {
    await validate(form.current());
    if (mine === validating) { form.markErrors([]); refreshHull(); }
  } catch (e) {
    if (mine === validating && !e.cancelled) form.markErrors(e.fields || []);
  }
}

// A copied link shows under the buttons until the study or a value changes: then it would share
// another scenario than the one on the page.
function forgetLink() {
  $('share-url').hidden = true;
  $('share-url').value = '';
  $('share-too-long').hidden = true;
}

function selectStudy(name, push = true) {
  form.select(name);
  form.save();
  follow(name, push);
}

// Back/Forward and a hand-edited address: show the study of the address.
async function route() {
  if (!form) return;
  const link = await openLink(location.hash.slice(1));
  if (!link || link.refused) return;
  if (link.name === form.name && !link.edited.length) return;
  form.select(link.name, link.scenario);
  form.markLinked(link.edited);
  status(`${studyTitle(link.name)}: press Run.`);
}

function showSummary(s, constants) {
  $('summary').querySelector('tbody').replaceChildren(...SUMMARY_ROWS.map((name) => {
    const v = s.signals[name];
    return row(signals.labelWithUnit(name, constants), [v.final, v.min, v.max].map((x) => Number(x).toPrecision(4)));
  }));
  // Tables 5.6 and 5.7: each stage's power at the end and the efficiency of the stage.
  const inv = s.power_inventory_w || {}, eff = s.efficiency || {};
  const stages = [['turbine', 'gas turbines, shaft', null], ['generator', 'generators, electrical', 'generator'], ['inverter', 'into the motors', 'power_electronics'], ['motor', 'motors, shaft', 'motor'], ['ship', 'ship, resistance x speed', 'propeller']];
  const body = $('inventory').querySelector('tbody');
  body.replaceChildren(el('tr', {}, ...['stage', 'power [MW]', 'efficiency of the stage'].map((h) => el('th', { scope: 'col', textContent: h }))),
    ...stages.filter(([k]) => k in inv).map(([k, label, e]) => row(label, [fmt(inv[k] / 1e6), e && e in eff ? `${(eff[e] * 100).toFixed(1)} %` : '–'])));
  // The summary's warnings (core's health checks and the model's range), above the tables.
  $('warnings').replaceChildren(...(s.warnings || []).map((w) => el('li', { textContent: w })));
  $('warnings-box').hidden = !(s.warnings || []).length;
  $('summary-box').hidden = false;
}

// A key figure of config.js as a label with its unit and a reader of a summary.
function keyFigure(fig) {
  if (fig.energy) {
    const { unit, factor } = withPrefix('J', fig.prefix);
    return { label: `${fig.text} [${unit}]`, f: (s) => s.energy_j[fig.energy] * factor };
  }
  const { unit, factor } = signals.display(fig.signal, fig.prefix);
  const shown = fig.stat.endsWith('_s') ? 's' : unit;
  const stat = (x) => (fig.stat === 'swing' ? x.max - x.min : x[fig.stat]);
  return {
    label: `${fig.text.replace('{}', signals.label(fig.signal))} [${shown}]`,
    // null: a statistic the summary leaves undefined (a settling time of a signal that does not settle).
    f: (s) => { const x = stat(s.signals[fig.signal]); return x === null ? null : x * (fig.stat.endsWith('_s') ? 1 : factor); },
  };
}

// The kept run against the new one: key figures side by side.
function showComparison(now) {
  const box = $('compare-box');
  if (!kept || !now) { box.hidden = true; return; }
  const rows = [];
  for (const fig of KEY_FIGURES) {
    const { label, f } = keyFigure(fig);
    let a, b;
    try { a = f(kept.summary); b = f(now.summary); } catch (_) { continue; }
    if (fig.none && (a === null || b === null)) {
      // Undefined on one side or both: said in words (config.js), no difference.
      if (a === null && b === null) continue;
      const say = (x) => (x === null ? fig.none : fmt(x));
      rows.push(el('tr', {}, el('th', { scope: 'row', textContent: label }), el('td', { textContent: say(a) }), el('td', { textContent: say(b) }), el('td', { textContent: '–' })));
      continue;
    }
    if (!Number.isFinite(a) || !Number.isFinite(b) || (a === 0 && b === 0)) continue;
    const d = b - a;
    const cell = el('td', { textContent: `${d >= 0 ? '+' : ''}${fmt(d, 3)}`, className: d > 0 ? 'up' : d < 0 ? 'down' : '' });
    rows.push(el('tr', {}, el('th', { scope: 'row', textContent: label }), el('td', { textContent: fmt(a) }), el('td', { textContent: fmt(b) }), cell));
  }
  const head = el('tr', {}, ...['key figure', `kept: ${kept.name}`, `this run: ${now.name}`, 'difference'].map((h) => el('th', { scope: 'col', textContent: h })));
  box.replaceChildren(el('h2', { textContent: 'Compared with the kept run (dashed, muted in every plot)' }),
    el('div', { className: 'scroll' }, el('table', { id: 'compare-table' }, el('thead', {}, head), el('tbody', {}, ...rows))));
  box.hidden = false;
}

// A run's name for legends: the study, and what differs from it.
function runName(sc) {
  const d = diff(form.preset(form.name), sc);
  const paths = d === undefined ? [] : leafPaths(d);
  const value = (p) => { const v = p.split('.').reduce((o, k) => o[k], sc); return typeof v === 'string' && v.length > 40 ? `(${v.split('\n').length} lines)` : JSON.stringify(v); };
  const what = paths.slice(0, 2).map((p) => `${p.split('.').pop()} = ${value(p)}`).join(', ');
  return `${studyTitle(form.name)}${what ? `, ${what}${paths.length > 2 ? ', ...' : ''}` : ''}`;
}

// A failed request keeps the form and the earlier results; refused fields are marked.
function failed(e) {
  live.hide(); // it may hold part of the run that failed
  if (e.cancelled) return;
  setPhase('idle');
  status(e.message, true);
  form.markErrors(e.fields || []);
}

// trial: {i, text} replays Monte Carlo trial i from its scenario text (exact 64-bit seed).
async function run({ focus = true, trial = null } = {}) {
  if (isBusy() || !form || form.invalid.size) return;
  const text = trial ? trial.text : JSON.stringify(form.current());
  const sc = trial ? JSON.parse(trial.text) : form.current(); // (its seed only for display)
  setPhase('running');
  status('Running...');
  const started = performance.now();
  const c = client;
  let m;
  try {
    m = await c.request(REQUEST.run, { scenario: text, live: true }, (p) => {
      progress(p.fraction, etaText(started, p.fraction));
      if (p.rows) live.follow(p.rows, p.constants, sc, text);
    });
  } catch (e) { failed(e); return; }
  progress(1);
  const seed = trial ? (trial.text.match(/"seed":\s*(\d+)/) || [])[1] : null;
  const name = trial ? `${studyTitle(form.name)}, Monte Carlo trial ${trial.i} (sea seed ${seed})` : runName(sc);
  setResult({ summary: m.summary, csv: m.csv, scenario: sc, text, columns: m.columns, name });
  setPhase('idle');
  showSummary(m.summary, m.constants);
  showComparison({ summary: m.summary, name });
  const order = (STUDIES[form.name] && STUDIES[form.name].plots) || DEFAULT_PLOTS;
  const { markers } = drawRun(plots, m.columns, signals, m.constants, sc, { order, kept });
  if (sc.sea.kind !== 'calm') drawSeaExtras(plots, c, sc, m.columns, m.constants, (e) => status(e.message, true));
  live.show(m.columns, m.constants, sc, text).catch((e) => status(`The live views failed: ${e.message}`, true));
  const t = m.summary.final_time_s, wall = m.wall_ms / 1000;
  const events = sc.sea.kind === 'calm' ? '' : ` Surface losses started ${markers.length} time(s).`;
  status(`Done${trial ? ` (${name})` : ''}: ${t} s simulated in ${wall.toFixed(2)} s (${(t / wall).toFixed(0)} times real time).${events}`);
  if (focus) $('results').focus();
}

async function runMonteCarlo() {
  if (isBusy() || !form || form.invalid.size) return;
  const sc = form.current();
  const why = MonteCarlo.refusal(sc);
  if (why) { status(why, true); return; }
  const n = Number(sc.monte_carlo.trials);
  setPhase('montecarlo');
  live.hide();
  const started = performance.now();
  let out;
  try {
    out = await monteCarlo.run(client, sc, (done, k) => {
      if (done === 0) { status(`Monte Carlo: ${n} trials on ${k} workers...`); return; }
      const secs = (performance.now() - started) / 1000;
      progress(done / n, secs > 0.5 ? `${done} of ${n} trials, about ${((secs * (n - done)) / done).toFixed(1)} s left` : '');
    });
  } catch (e) { failed(e); return; }
  setResult({ summary: out.summary, csv: '', scenario: sc });
  setPhase('idle');
  $('summary-box').hidden = true;
  $('compare-box').hidden = true;
  showMonteCarlo(plots, out.summary, signals, out.constants, { onReplay: replayTrial, onPickBar: replayFromBar, thesis });
  status(`Monte Carlo done: ${n} trials in ${((performance.now() - started) / 1000).toFixed(1)} s.`);
  $('results').focus();
}

// A Monte Carlo trial as a single run (plots and live views): its scenario comes from the wasm
// with the trial's exact seed.
// A histogram bar picked: find its first trial (trials run in order in the worker), replay it.
async function replayFromBar(hist, bin) {
  if (isBusy() || !form) return;
  status('Finding a trial in that bar (trials run in order until one lands in it)...');
  let r;
  try {
    r = await client.request(REQUEST.findTrial, { scenario: JSON.stringify(form.current()), hist, bin }, (p) => status(`Finding a trial in that bar: ${p.tried} tried...`));
  } catch (e) { failed(e); return; }
  if (r.trial === null) { status('No trial of this study lands in that bar.', true); return; }
  if ($('mc-trial')) $('mc-trial').value = String(r.trial);
  await replayTrial(r.trial);
}

async function replayTrial(i) {
  if (isBusy() || !form) return;
  let r;
  try {
    r = await client.request(REQUEST.trial, { scenario: JSON.stringify(form.current()), i });
  } catch (e) { failed(e); return; }
  await run({ trial: { i, text: r.scenario } });
}

function keep() {
  const r = getResult();
  if (!r || !r.columns) return;
  kept = { name: r.name, columns: r.columns, summary: r.summary };
  $('unkeep').hidden = false;
  status(`Kept: ${r.name}. The next runs draw over it, muted and dashed.`);
}

// "Compare with ...": keep this study's run (running it first if needed), then run the other.
async function compareWith(c) {
  if (isBusy() || !form) return;
  const r = getResult();
  if (!r || !r.columns || JSON.stringify(r.scenario) !== JSON.stringify(form.scenario)) await run({ focus: false });
  if (!getResult() || !getResult().columns) return;
  keep();
  if (c.preset) selectStudy(c.preset);
  else {
    for (const [path, v] of Object.entries(c.set)) setPath(form.scenario, path, v);
    form.fill();
    form.save();
  }
  await run();
}

function showCompareButtons() {
  const study = STUDIES[form.name] || {};
  $('compare-with').replaceChildren(...(study.compare || []).map((c) => {
    const b = el('button', { type: 'button', textContent: `Compare with ${c.label}` });
    b.addEventListener('click', () => compareWith(c));
    return b;
  }));
}

function cancel() {
  monteCarlo.stop();
  client.terminate();
  status('Cancelled.');
  startWorker();
}

// Tabs (ARIA pattern): click, or arrow keys / Home / End on the tab list.
const TABS = [['tab-sim', 'panel-sim'], ['tab-design', 'panel-design'], ['tab-ips', 'panel-ips']];
const SKIP_TARGETS = { 'tab-sim': '#results', 'tab-ips': '#ips-plots', 'tab-design': '#design-plots' };
function selectTab(id, focus = false) {
  for (const [tab, panel] of TABS) {
    const on = tab === id;
    $(tab).setAttribute('aria-selected', String(on));
    $(tab).tabIndex = on ? 0 : -1;
    $(panel).hidden = !on;
  }
  if (focus) $(id).focus();
  // "Skip to the results" goes to the shown tab's results (the simulator's are hidden here).
  document.querySelector('a.skip').setAttribute('href', SKIP_TARGETS[id]);
  if (id === 'tab-ips') stability.update();
  if (id === 'tab-design') design.update();
}
for (const [tab] of TABS) $(tab).addEventListener('click', () => selectTab(tab));
$('tabs').addEventListener('keydown', (e) => {
  const i = TABS.findIndex(([t]) => t === document.activeElement.id);
  if (i < 0) return;
  const j = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: TABS.length - 1 }[e.key];
  if (j === undefined) return;
  e.preventDefault();
  selectTab(TABS[(j + TABS.length) % TABS.length][0], true);
});

// Presentation mode: full screen, large type, the form folded away.
function present(on) {
  document.body.classList.toggle('presenting', on);
  presentPlots(on);
  $('present').setAttribute('aria-pressed', String(on));
  $('present').textContent = on ? 'Leave presentation' : 'Presentation mode';
  if (on && document.documentElement.requestFullscreen && !document.fullscreenElement) document.documentElement.requestFullscreen().catch(() => {});
  if (!on && document.fullscreenElement) document.exitFullscreen().catch(() => {});
}
$('present').addEventListener('click', () => present(!document.body.classList.contains('presenting')));
document.addEventListener('fullscreenchange', () => { if (!document.fullscreenElement && document.body.classList.contains('presenting')) present(false); });

$('form').addEventListener('submit', (e) => e.preventDefault());
$('preset').addEventListener('change', () => selectStudy($('preset').value));
$('run').addEventListener('click', () => run());
$('mc-run').addEventListener('click', runMonteCarlo);
$('cancel').addEventListener('click', cancel);
$('keep').addEventListener('click', keep);
$('unkeep').addEventListener('click', () => { kept = null; $('unkeep').hidden = true; $('compare-box').hidden = true; status('The kept run is forgotten.'); });
$('reset').addEventListener('click', () => {
  if (!form) return;
  form.select(form.name);
  form.save();
  follow(form.name, false);
  status('Back to the study\'s values.');
});
$('share').addEventListener('click', async () => {
  if (!form) return;
  const r = getResult();
  const view = r && r.columns && JSON.stringify(r.scenario) === JSON.stringify(form.scenario) ? live.view() : null;
  const url = location.origin + location.pathname + linkHash(form.name, form.preset(), form.scenario, view);
  // A custom hull's offsets can make the link longer than browsers, chat programs and mail keep:
  // then the page offers the scenario as a file instead of a link that would break.
  const tooLong = url.length > HULL.maxLinkChars;
  $('share-too-long').hidden = !tooLong;
  if (tooLong) {
    $('share-url').hidden = true;
    $('share-too-long-text').textContent = `This scenario's link would be ${url.length.toLocaleString('en-US')} characters long (the custom hull's offsets are in it), more than the ${HULL.maxLinkChars.toLocaleString('en-US')} a link can safely carry. Download the scenario instead: it holds the hull, and opens here with "Load hull offsets or a scenario" (or with aes-sim).`;
    status('No link: this scenario is too large for one. Download it as a file (below the buttons).');
    $('share-file').focus();
    return;
  }
  $('share-url').hidden = false;
  $('share-url').value = url;
  $('share-url').select();
  try { await navigator.clipboard.writeText(url); status('Link copied: it opens this scenario and runs it.'); } catch (_) { status('Link below: copy it by hand.'); }
});
$('share-file').addEventListener('click', () => {
  if (form) download(`${form.scenario.name || 'scenario'}-scenario.json`, JSON.stringify(form.current(), null, 1), 'application/json');
});
$('export-csv').addEventListener('click', () => {
  const r = getResult();
  if (r && r.csv) download(`${r.scenario.name}-trace.csv`, `# scenario: ${r.text || JSON.stringify(r.scenario)}\n${r.csv}`, 'text/csv');
});
$('export-json').addEventListener('click', () => {
  const r = getResult();
  // The scenario as its own text: a replayed trial's 64-bit seed survives.
  if (r) download(`${r.scenario.name}-summary.json`, `{"scenario": ${r.text || JSON.stringify(r.scenario)},\n"summary": ${JSON.stringify(r.summary, null, 1)}}`, 'application/json');
});
window.addEventListener('popstate', route);
window.addEventListener('hashchange', route);
startWorker();
