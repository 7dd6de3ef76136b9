// The page: wires the study picker and form, the worker, the plots, kept runs, share links and the
// address bar, exports, presentation mode, the stability tab and the operability tab.
import { DESIGN, DEFAULT_PRESET, SUMMARY_ROWS, STUDIES, DEFAULT_PLOTS, KEY_FIGURES, HULL, studyTitle } from './config.js';
import { $, el, row, download, fmt } from './dom.js';
import { REQUEST, WorkerClient, fieldLine } from './protocol.js';
import { setPhase, isBusy, setResult, getResult, progress, status, notice, etaText, setFormValid } from './state.js';
import { linkHash, readLink, diff } from './link.js';
import { ScenarioForm, setPath, deletePath, leafPaths } from './form.js';
import { Signals, withPrefix } from './units.js';
import { setRegistry } from './registry.js';
import { PlotBox, drawRun, drawSeaExtras, presentPlots } from './plots.js';
import { MonteCarlo, showMonteCarlo } from './montecarlo.js';
import { StabilityTab } from './stability.js';
import { DesignTab } from './design.js';
import { OperabilityTab } from './operability.js';
import { RareView } from './rare.js';
import { LiveViews } from './live.js';
import { HullPanel, HullPicker, num } from './hull.js';
import { LessonView, readLessonHash, controlPath } from './lessons/view.js';

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
// One state (issue 29): the address bar says which tab, study, values and kind of result (one run
// or its Monte Carlo) the page shows; every result drawn is kept under the key of the state it
// belongs to, so Back and Forward restore inputs and results together, and a result is never
// drawn under another study's inputs.
let mode = 'run';
let shown = null; // the key of the drawn result, or null
const drawn = new Map(); // key -> {key, state, study, redraw()}: the last few results, for Back/Forward
const DRAWN_MAX = 6;
// Lessons (issue 30): the simulator's own runs, plots and live views behind a few controls.
let lessons = null; // the LessonView, once the registry is there
let lesson = null; // {def, scenario0} while a lesson is open (scenario0: the study with the lesson's settings)
let lessonPending = false; // a control moved while a run was in flight: run again after it
const stateKey = (m = mode) => `${m}|${form.name}|${JSON.stringify(form.scenario)}`;
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
// The Bode magnitude and phase share one cursor (as the run's plots do).
const stability = new StabilityTab(() => client, new PlotBox($('ips-plots'), { sync: 'ips' }));
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
design.onChange = () => { if (form) follow(false); };
// The operability tab judges the form's study as it stands; a cell opens the simulator there.
const operability = new OperabilityTab({
  inputs: () => (form && form.scenario ? { study: form.name, title: studyTitle(form.name), scenario: form.current(), invalid: form.invalid.size > 0 } : null),
  onOpenCell: openCell,
});
// Rare events (in the simulator's results): the form's study as it stands; its replays run here.
const rareView = new RareView({
  inputs: () => (form && form.scenario && !lesson ? { study: form.name, title: studyTitle(form.name), scenario: form.current(), invalid: form.invalid.size > 0 } : null),
  sheet: (sc) => client.request(REQUEST.hullSheet, { scenario: JSON.stringify(sc) }),
  onRun: runRare,
});
rareView.setPlots(new PlotBox($('rare-plots')));

function startWorker() {
  setPhase('loading');
  client = new WorkerClient({
    onReady,
    onFailure: (e) => status(`The simulator failed to load: ${e.message}`, true),
  });
}

const validate = (sc) => client.request(REQUEST.validate, { scenario: JSON.stringify(sc) });

// The address follows the state: study, edits, mode, tab and the design tab's tuning (a copied
// link adds where the live views stand). An edit replaces the current entry unless that entry
// shows a result of other values: then it pushes, so Back returns to those values and their
// result. A study, tab or mode change pushes.
const hereHash = (view = null) => (lesson ? lessons.hash(lesson.scenario0) : linkHash(form.name, form.preset(), form.scenario, { mode, tab: currentTab(), design: design.changed(), view }));
const current = () => Boolean(shown) && drawn.has(shown) && drawn.get(shown).state === stateKey();
function follow(push) {
  const h = hereHash();
  const st = history.state || {};
  const owner = st.shown && drawn.get(st.shown);
  if (!push && owner && owner.state !== stateKey() && location.hash !== h) push = true;
  history[push ? 'pushState' : 'replaceState']({ shown: current() ? shown : null }, '', h);
}
// After a run or a Monte Carlo study: the entry of these inputs owns what is drawn (a new entry
// when the mode changed, so Back returns to the other view).
function settle() {
  const h = hereHash();
  history[location.hash === h ? 'replaceState' : 'pushState']({ shown }, '', h);
}

// key: unique per result; state: the stateKey of the inputs it belongs to (a replayed Monte Carlo
// trial belongs to its study's Monte Carlo state).
// extra: {isCurrent()} for a result that belongs to something else than the form's values alone.
function remember(key, state, redraw, extra = {}) {
  drawn.delete(key);
  drawn.set(key, { key, state, study: state.split('|')[1], redraw, ...extra });
  while (drawn.size > DRAWN_MAX) drawn.delete(drawn.keys().next().value);
  shown = key;
}
// The result of a state: its own run or study first, else a trial replayed from it.
const resultOf = (state) => drawn.get(state) || [...drawn.values()].reverse().find((r) => r.state === state);

// Nothing drawn: no summary, plots, live views or exports of another state.
function clearResults() {
  plots.clear();
  live.hide();
  $('shown-what').hidden = true;
  $('summary-box').hidden = true;
  $('compare-box').hidden = true;
  setResult(null);
  shown = null;
  showStale();
}

// After any change of the inputs: results of other values of this study stay, marked stale with a
// Run at hand; results of another study go (Back brings them back).
function showStale() {
  operability.sync();
  rareView.sync();
  const box = $('stale');
  const r = shown && drawn.get(shown);
  if (r && r.study !== form.name) { clearResults(); return; }
  // A rare-event run belongs to the rare-event result it came from (the form's values and the
  // rare controls); every other result to the form's values in its mode.
  const stale = Boolean(r) && (r.isCurrent ? !r.isCurrent() : r.state !== stateKey());
  if (stale && r.isCurrent) {
    box.hidden = false;
    document.getElementById('results').classList.add('stale');
    $('stale-text').textContent = 'This run is a rare-event trial of other values than the form\'s and the rare-event controls\' now. Press Run to see the form\'s values, or compute the rare events again.';
    return;
  }
  box.hidden = !stale;
  document.getElementById('results').classList.toggle('stale', stale);
  if (stale) $('stale-text').textContent = `These results are of other values of this study than the form's now (${r.state.startsWith('mc|') ? 'its Monte Carlo study' : 'one run'}). Press ${mode === 'mc' ? 'Monte Carlo' : 'Run'} to see the form's values.`;
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

// The lesson's study with its settings, as the lesson starts from it.
function lessonScenario(def) {
  const sc = form.preset(def.preset);
  for (const [p, v] of Object.entries(def.set)) setPath(sc, p, v);
  return sc;
}
const labHref = () => linkHash(form.name, form.preset(), form.scenario);

// Shows the lessons' index or one lesson (parsed: readLessonHash's answer).
function openLesson(parsed) {
  selectTab('tab-sim', false, false);
  document.body.classList.add('lesson');
  kept = null;
  lessonPending = false;
  validating++;
  if (parsed.index) {
    lesson = null;
    document.body.dataset.lessonView = '';
    lessons.showIndex(parsed.unknown);
    clearResults();
    status(parsed.unknown ? 'No such lesson: pick one.' : 'Pick a lesson.');
    return;
  }
  const def = parsed.def;
  const sc0 = lessonScenario(def);
  const sc = JSON.parse(JSON.stringify(sc0));
  for (const c of def.controls) {
    const p = controlPath(c), v = lessons.value(c, parsed.values[p], sc0);
    setPath(sc, p, v);
    for (const [q, x] of Object.entries(lessons.also(c, v))) setPath(sc, q, x);
  }
  lesson = { def, scenario0: sc0 };
  form.select(def.preset, sc);
  mode = 'run';
  clearResults();
  document.body.dataset.lessonView = def.view;
  lessons.open(def, sc, labHref());
  history.replaceState(history.state, '', lessons.hash(sc0));
  status(`${def.title}: answer the question (or "Just run it") to run.`);
}
function leaveLesson() {
  lesson = null;
  kept = null;
  document.body.classList.remove('lesson');
  $('lesson-box').replaceChildren();
  $('lesson-explain').replaceChildren();
}

// A lesson's run: the one before stays drawn faintly; at most one in flight, the last asked wins.
async function lessonRun() {
  if (!lesson) return;
  if (isBusy()) { lessonPending = true; return; }
  const r = getResult();
  kept = r && r.columns ? { name: 'the run before', columns: r.columns, summary: r.summary } : null;
  const asked = performance.now();
  await run({ focus: false, order: lesson.def.plots });
  const res = getResult();
  if (lesson && res && res.columns && res.study === lesson.def.preset) {
    window.__lessonLatencyMs = performance.now() - asked; // for the browser test: control to plot
    lessons.explain(res.summary, res.markers || []);
    live.place({ at: lesson.def.at, speed: 2 });
  }
  if ($('lesson-lab')) $('lesson-lab').href = labHref();
  if (lessonPending) { lessonPending = false; lessonRun(); }
}

async function onReady(m) {
  if (form) { setPhase('idle'); return; } // a fresh worker after a cancel: the page stays as it is
  signals = new Signals(m.signals);
  setRegistry(m.params);
  design.configure(m.params);
  thesis = m.thesis || [];
  stability.setMeta(m.ips);
  form = new ScenarioForm(m.presets, m.params, { onLooseErrors: (text) => status(text, true), onEdit, onValidity: (v) => { setFormValid(v); operability.sync(); rareView.sync(); }, onSelect: () => { showCompareButtons(); refreshHull(); forgetLink(); operability.sync(); rareView.sync(); } });
  lessons = new LessonView(m.params, {
    onChange: (path, v, also = {}) => {
      setPath(form.scenario, path, v);
      for (const [q, x] of Object.entries(also)) setPath(form.scenario, q, x);
      history.replaceState(history.state, '', lessons.hash(lesson.scenario0));
      lessonRun();
    },
    onAnswer: () => lessonRun(),
  });
  // For the browser test: the scenario a lesson runs, as text.
  window.__scenarioText = () => JSON.stringify(form.current());
  hullPicker = new HullPicker(m.hulls || [], {
    form, validate, say: status, busy: isBusy,
    // An accepted hull or scenario file: into the form (a scenario file may name its study).
    commit: (sc, { name } = {}) => {
      const other = name && name !== form.name;
      if (other) form.select(name, sc); else { form.scenario = sc; form.fill(); }
      form.save();
      onEdit(other);
    },
  });
  const lessonLink = readLessonHash(location.hash.slice(1));
  if (lessonLink) {
    form.select(DEFAULT_PRESET);
    setPhase('idle');
    openLesson(lessonLink);
    return;
  }
  const linked = await openLink(location.hash.slice(1));
  design.restore(linked && !linked.refused ? linked.design : null);
  if (linked && !linked.refused && linked.tab !== 'sim') selectTab(`tab-${linked.tab}`, false, false);
  // A reload shows the address's state again without running it (a link opened afresh runs).
  const reloaded = (performance.getEntriesByType('navigation')[0] || {}).type === 'reload';
  if (linked && !linked.refused && reloaded) {
    form.select(linked.name, linked.scenario);
    form.save();
    mode = linked.mode;
    follow(false);
    setPhase('idle');
    status(`Your edits are back${linked.edited.length ? ` (${linked.edited.length} value(s) changed from the study)` : ''}: press ${mode === 'mc' ? 'Monte Carlo' : 'Run'}.`);
    return;
  }
  if (linked && !linked.refused && (linked.edited.length || linked.view || linked.mode === 'mc')) {
    form.select(linked.name, linked.scenario);
    form.markLinked(linked.edited);
    mode = linked.mode;
    follow(false);
    setPhase('idle');
    if (linked.edited.length) status(`This link changed ${linked.edited.length} value(s) of the study (marked in the form).`);
    if (linked.mode === 'mc') { await runMonteCarlo(); return; }
    if (linked.tab === 'operability') { operability.compute(); return; }
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
  follow(false);
  setPhase('idle');
  status(restored ? 'Your last edits are back.' : 'Ready. Choose a study and press Run.');
  // A link to the operability tab computes its polar (as a link to a run runs it).
  if (linked && !linked.refused && linked.tab === 'operability') operability.compute();
}

// After an accepted edit: the scenario is checked at once (errors at the field, Run waits), and
// a page opened from a link now shows the study, not the link's values.
let validating = 0;
async function onEdit(push = false) {
  follow(push);
  forgetLink();
  showStale();
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

// Another study: its own edits of this visit come back with it (the picker marks them), and what
// was drawn for it last comes back too, else nothing is drawn.
function selectStudy(name, push = true) {
  validating++; // a check still on its way belongs to the study left
  form.select(name);
  form.save();
  mode = 'run';
  const last = [...drawn.values()].reverse().find((r) => r.study === name);
  if (last) { last.redraw(); shown = last.key; mode = last.state.split('|')[0]; } else clearResults();
  follow(push);
  showStale();
}

// Back/Forward and a hand-edited address: the tab, study, values and mode of the address, with
// their result when the page still has it; else nothing is drawn and the status says what to press.
async function route() {
  if (!form || isBusy()) return;
  const lessonLink = readLessonHash(location.hash.slice(1));
  if (lessonLink) { openLesson(lessonLink); return; }
  if (document.body.classList.contains('lesson')) leaveLesson();
  const link = await openLink(location.hash.slice(1));
  if (!link || link.refused) return;
  validating++;
  selectTab(`tab-${link.tab}`, false, false);
  design.restore(link.design);
  form.select(link.name, link.scenario);
  form.save();
  form.markLinked(link.edited);
  mode = link.mode;
  const key = stateKey();
  const r = resultOf(key);
  if (r) {
    if (shown !== r.key) r.redraw();
    shown = r.key;
    status(`${studyTitle(link.name)}: the result of these values is back.`);
  } else {
    clearResults();
    status(`${studyTitle(link.name)}${link.edited.length ? `, ${link.edited.length} value(s) changed` : ''}: press ${mode === 'mc' ? 'Monte Carlo' : 'Run'} to see its result.`);
  }
  showStale();
  history.replaceState({ shown: current() ? shown : null }, '', location.hash);
}

function showSummary(s, constants) {
  $('summary').querySelector('tbody').replaceChildren(...SUMMARY_ROWS.map((name) => {
    const v = s.signals[name];
    return row(signals.labelWithUnit(name, constants), [v.final, v.min, v.max].map((x) => Number(x).toPrecision(4)));
  }));
  // Tables 5.6 and 5.7: each stage's power at the end and what it passes on of the power it
  // takes, now and over the whole run (energies). A ratio of powers in a transient is not an
  // efficiency: a stage that gives up stored energy passes on more than it takes.
  const inv = s.power_inventory_w || {}, en = s.energy_j || {};
  const stages = [['turbine', 'gas turbines, shaft'], ['generator', 'generators, electrical'], ['inverter', 'into the motors'], ['motor', 'motors, shaft'], ['ship', 'ship, resistance x speed']]
    .filter(([k]) => k in inv);
  const ratio = (out, into) => (into > 0 && out >= 0 ? `${(100 * out / into).toFixed(1)} %` : '–');
  const body = $('inventory').querySelector('tbody');
  body.replaceChildren(el('tr', {}, ...['stage', 'power now [MW]', 'out / in now', 'energy, whole run [MJ]', 'out / in, whole run'].map((h) => el('th', { scope: 'col', textContent: h }))),
    ...stages.map(([k, label], i) => {
      const prev = i > 0 ? stages[i - 1][0] : null;
      return row(label, [fmt(inv[k] / 1e6), prev ? ratio(inv[k], inv[prev]) : '–', k in en ? fmt(en[k] / 1e6) : '–', prev && k in en ? ratio(en[k], en[prev]) : '–']);
    }));
  const over = stages.some(([k], i) => i > 0 && inv[stages[i - 1][0]] > 0 && inv[k] > inv[stages[i - 1][0]]);
  $('inventory-over').hidden = !over;
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
    f: (s) => { const x = stat(s.signals[fig.signal]); return x === null || x === undefined ? null : x * (fig.stat.endsWith('_s') ? 1 : factor); },
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
    if (a === null || b === null || !Number.isFinite(a) || !Number.isFinite(b) || (a === 0 && b === 0)) continue;
    const d = b - a;
    // Coloured and worded by better or worse where the figure has a good direction, else neutral.
    const good = fig.better && d !== 0 ? (d > 0) === (fig.better === 'higher') : null;
    const cell = el('td', { textContent: `${d >= 0 ? '+' : ''}${fmt(d, 3)}${good === null ? '' : good ? ' (better)' : ' (worse)'}`, className: good === null ? '' : good ? 'better' : 'worse' });
    rows.push(el('tr', {}, el('th', { scope: 'row', textContent: label }), el('td', { textContent: fmt(a) }), el('td', { textContent: fmt(b) }), cell));
  }
  const head = el('tr', {}, ...['key figure', `kept: ${kept.name}`, `this run: ${now.name}`, 'difference'].map((h) => el('th', { scope: 'col', textContent: h })));
  box.replaceChildren(el('h2', { textContent: 'Compared with the kept run (dashed, muted in every plot)' }),
    el('div', { className: 'scroll', tabIndex: 0, attrs: { role: 'region', 'aria-label': 'Key figures compared' } }, el('table', { id: 'compare-table' }, el('thead', {}, head), el('tbody', {}, ...rows))));
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
// replay: {text, name, words, state, isCurrent, at}: a rare-event scenario (its trial's or the
// most likely wave group's), said in words, shown with the live views at its event (at).
// order: the plots to draw first (a lesson's), else the study's.
async function run({ focus = true, trial = null, replay = null, order: plotOrder = null } = {}) {
  if (isBusy() || !form || form.invalid.size) return;
  const given = trial || replay;
  const text = given ? given.text : JSON.stringify(form.current());
  const sc = given ? JSON.parse(given.text) : form.current(); // (its seed only for display)
  // The inputs this result will belong to, taken now (the form may change while it runs).
  const state = replay ? replay.state : stateKey(trial ? 'mc' : 'run'), study = form.name;
  setPhase('running');
  status(replay ? `Running ${replay.words}...` : 'Running...');
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
  const name = trial ? `${studyTitle(form.name)}, Monte Carlo trial ${trial.i} (sea seed ${seed})` : replay ? replay.name : runName(sc);
  setPhase('idle');
  const draw = () => {
    setResult({ summary: m.summary, csv: m.csv, scenario: sc, text, columns: m.columns, name, study });
    // A rare-event run says above its views what it is (a run of the form's values needs no line).
    $('shown-what').hidden = !replay;
    $('shown-what').textContent = replay ? `Shown: ${replay.words}. The ${replay.shaft} hub's h/R at the event (t = ${replay.at} s): ${hrAt(m.columns, replay)}.` : '';
    showSummary(m.summary, m.constants);
    showComparison({ summary: m.summary, name });
    const order = plotOrder || (STUDIES[study] && STUDIES[study].plots) || DEFAULT_PLOTS;
    const { markers } = drawRun(plots, m.columns, signals, m.constants, sc, { order, kept });
    getResult().markers = markers;
    // (Not in a lesson: its RAO and fuel plots are folded away, and the worker would compute them
    // before the next run a slider asks for.)
    if (sc.sea.kind !== 'calm' && !lesson) drawSeaExtras(plots, client, sc, m.columns, m.constants, (e) => status(e.message, true));
    live.show(m.columns, m.constants, sc, text).catch((e) => status(`The live views failed: ${e.message}`, true));
    return markers;
  };
  if (!given) mode = 'run';
  const markers = draw();
  remember(trial ? `trial ${trial.i}|${state}` : replay ? `${replay.name}|${state}` : state, state, draw, replay ? { isCurrent: replay.isCurrent } : {});
  settle();
  showStale();
  const t = m.summary.final_time_s, wall = m.wall_ms / 1000;
  const events = sc.sea.kind === 'calm' ? '' : ` Surface losses started ${markers.length} time(s).`;
  if (replay) {
    // The views stand at the event, in view; the line says what they show.
    const hr = ` The ${replay.shaft} hub's h/R at the event: ${hrAt(m.columns, replay)}.`;
    status(`Done: showing ${replay.words}; ${t} s simulated in ${wall.toFixed(2)} s.${events}${hr} The live views stand at the event (t = ${replay.at} s): press Play.`);
    live.place({ at: replay.at, speed: 1 }).then(() => $('shown-what').scrollIntoView({ block: 'start' }));
    return;
  }
  status(`Done${trial ? ` (${name})` : ''}: ${t} s simulated in ${wall.toFixed(2)} s (${(t / wall).toFixed(0)} times real time).${events}`);
  if (focus) $('results').focus();
}

async function runMonteCarlo() {
  if (isBusy() || !form || form.invalid.size) return;
  const sc = form.current();
  const why = MonteCarlo.refusal(sc);
  if (why) { status(why, true); return; }
  const n = Number(sc.monte_carlo.trials);
  const state = stateKey('mc'), study = form.name;
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
  setPhase('idle');
  const draw = () => {
    setResult({ summary: out.summary, csv: '', scenario: sc, study, name: `${studyTitle(study)}, Monte Carlo` });
    live.hide();
    $('summary-box').hidden = true;
    $('compare-box').hidden = true;
    $('shown-what').hidden = true;
    showMonteCarlo(plots, out.summary, signals, out.constants, { onReplay: replayTrial, onPickBar: replayFromBar, thesis, study });
  };
  mode = 'mc';
  draw();
  remember(state, state, draw);
  settle();
  showStale();
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

// A cell of the operability polar: the simulator at its speed (the first order's), sea and wave
// heading, through the form (the address, the "(changed)" marks and the stored edits follow), then
// the Simulator tab (a step in the history: Back returns to the polar). Returns why it cannot.
function openCell({ speed_kn, set, words }) {
  if (!form) return 'The simulator is still loading.';
  if (isBusy()) return 'A run is in progress on the Simulator tab: wait for it or cancel it first.';
  const sc = form.scenario;
  if (!Array.isArray(sc.commands) || !sc.commands.length) sc.commands = [{ t_s: 0 }];
  sc.commands[0].speed_kn = speed_kn;
  for (const [path, v] of Object.entries(set)) { if (v === undefined) deletePath(sc, path); else setPath(sc, path, v); }
  form.fill();
  form.save();
  selectTab('tab-sim');
  onEdit(false);
  status(`From the operability polar: ${words}. Press Run.`);
  $('run').focus();
  return null;
}

// h/R of a rare event's hub at the event, read from the run's own trace.
function hrAt(cols, { at, hr }) {
  const i = cols.t_s.findIndex((x) => x >= at - 1e-9);
  return i >= 0 ? cols[hr][i].toFixed(3) : '–';
}

// A rare-event scenario through the page's run (plots and live views). Returns why it cannot.
function runRare({ text, name, words, key, at, hr, shaft }) {
  if (!form) return 'The simulator is still loading.';
  if (isBusy()) return 'A run is in progress: wait for it or cancel it first.';
  if (form.invalid.size) return 'A value of the form is refused (marked at its field): correct it first.';
  run({ focus: false, replay: { text, name, words, at, hr, shaft, state: `rare|${key}`, isCurrent: () => rareView.currentKey() === key } });
  return null;
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
const TABS = [['tab-sim', 'panel-sim'], ['tab-design', 'panel-design'], ['tab-ips', 'panel-ips'], ['tab-operability', 'panel-operability']];
const SKIP_TARGETS = { 'tab-sim': '#results', 'tab-ips': '#ips-plots', 'tab-design': '#design-plots', 'tab-operability': '#op-results' };
const currentTab = () => (TABS.find(([t]) => $(t).getAttribute('aria-selected') === 'true') || TABS[0])[0].slice(4);
// push: a tab the user picked is a step in the history (Back returns to the tab before).
function selectTab(id, focus = false, push = true) {
  const changed = currentTab() !== id.slice(4);
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
  if (id === 'tab-operability') { operability.sync(); operability.draw(); }
  if (changed && push && form) follow(true);
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
  validating++; // a check of the values left behind must not mark the study's own
  form.reset();
  onEdit();
  status('Back to the study\'s values.');
});
$('stale-run').addEventListener('click', () => (mode === 'mc' ? runMonteCarlo() : run()));
$('share').addEventListener('click', async () => {
  if (!form) return;
  const r = getResult();
  const view = r && r.columns && JSON.stringify(r.scenario) === JSON.stringify(form.scenario) ? live.view() : null;
  const url = location.origin + location.pathname + hereHash(view);
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
startWorker();
