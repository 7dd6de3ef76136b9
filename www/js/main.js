// The page's core: starts the simulator's worker, keeps one state for the form, the address bar and
// the drawn results (Back and Forward), runs the form's values, and switches the tabs. Every tab,
// fold and result view registers itself (views.js) in its module under views/, imported below in
// the order its hooks run; main.js calls the hooks. The views read the page's state from `ctx` and
// change it only through its functions (setMode, keep, setLesson, run, ...).
import { DEFAULT_PRESET, STUDIES, DEFAULT_PLOTS, studyTitle } from './config.js';
import { $ } from './dom.js';
import { REQUEST, WorkerClient, fieldLine } from './protocol.js';
import { setPhase, isBusy, setResult, getResult, progress, status, notice, etaText, setFormValid } from './state.js';
import { linkHash, readLink } from './link.js';
import { ScenarioForm } from './form.js';
import { Signals } from './units.js';
import { setRegistry } from './registry.js';
import { PlotBox } from './plots.js';
import { drawRun } from './runplots.js';
import { drawSeaExtras } from './seaextras.js';
import { LiveViews } from './live.js';
import { registerView, each, first, merged, tabView, modeView } from './views.js';
import { currentTab, showTab, listenTabs } from './tabs.js';
import { Drawn } from './drawn.js';
import './views/summary.js';
import './views/compare.js';
import './views/hull.js';
import './views/propeller.js';
import './views/share.js';
import './views/montecarlo.js';
import './views/lessons.js';
import './views/design.js';
import './views/stability.js';
import './views/operability.js';
import './views/rare.js';
import './views/fuel.js';
import './views/maneuvers.js';
import './views/schedule.js';
import './views/present.js';

const plots = new PlotBox($('plots'), { more: $('more-plots'), moreBox: $('more-plots-box'), sync: 'run' });
const live = new LiveViews($('live'), plots);
// Set once the first worker is ready; `client` is replaced by a fresh worker after a cancel.
let client = null;
let form = null;
let signals = null;
// One state (issue 29): the address bar says which tab, study, values and kind of result (one run
// or its Monte Carlo) the page shows; every result drawn is kept under the key of the state it
// belongs to (drawn.js).
let mode = 'run';
const drawn = new Drawn();
let kept = null; // a kept run drawn muted under the next: {name, columns, summary}
let lesson = null; // {def, defaults} while a lesson is open
const stateKey = (m = mode) => `${m}|${form.name}|${JSON.stringify(form.scenario)}`;
// The button that shows the form's values in this mode.
const press = () => (modeView(mode) ? modeView(mode).button : 'Run');

function startWorker() {
  setPhase('loading');
  client = new WorkerClient({
    onReady,
    onFailure: (e) => status(`The simulator failed to load: ${e.message}`, true),
  });
}

const validate = (sc) => client.request(REQUEST.validate, { scenario: JSON.stringify(sc) });
// The form's study as it stands, for the views that judge it (null while the page loads).
const studyInputs = () => (form && form.scenario ? { study: form.name, title: studyTitle(form.name), scenario: form.current(), invalid: form.invalid.size > 0 } : null);

// The address follows the state: study, edits, mode, tab and what views add (the design tab's
// tuning; a copied link adds where the live views stand). An edit replaces the current entry
// unless that entry shows a result of other values: then it pushes, so Back returns to those
// values and their result. A study, tab or mode change pushes.
const hereHash = (view = null) => first('hash', ctx) || linkHash(form.name, form.preset(), form.scenario, { mode, tab: currentTab(), ...merged('linkState', ctx), view });
const current = () => drawn.shows(stateKey());
function follow(push) {
  const h = hereHash();
  const st = history.state || {};
  const owner = st.shown && drawn.get(st.shown);
  if (!push && owner && owner.state !== stateKey() && location.hash !== h) push = true;
  // The address is the whole state: an identical one is no step in the history.
  if (location.hash === h) push = false;
  history[push ? 'pushState' : 'replaceState']({ shown: current() ? drawn.shown : null }, '', h);
}
// After a run or a Monte Carlo study: the entry of these inputs owns what is drawn (a new entry
// when the mode changed, so Back returns to the other view).
function settle() {
  const h = hereHash();
  history[location.hash === h ? 'replaceState' : 'pushState']({ shown: drawn.shown }, '', h);
}

// Nothing drawn: no summary, plots, live views or exports of another state.
function clearResults() {
  plots.clear();
  live.hide();
  $('shown-what').hidden = true;
  $('summary-box').hidden = true;
  $('compare-box').hidden = true;
  setResult(null);
  drawn.shown = null;
  showStale();
}

// After any change of the inputs: results of other values of this study stay, marked stale with a
// Run at hand; results of another study go (Back brings them back).
function showStale() {
  each('sync', ctx);
  const box = $('stale');
  const r = drawn.current();
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
  if (stale) $('stale-text').textContent = `These results are of other values of this study than the form's now (${r.state.startsWith('mc|') ? 'its Monte Carlo study' : 'one run'}). Press ${press()} to see the form's values.`;
}

// The scenario of a hash: null without one, {refused: true} (after saying why) when it cannot be
// used, else {name, scenario, edited, dropped}, validated. A value the checks refuse loses only
// itself (dropped: those fields, said in the notice): the study's value stands in, the rest of the
// link is kept.
async function openLink(hash) {
  const link = readLink(hash, form.presets);
  if (!link) return null;
  notice(''); // what an earlier link's notice said is not of this one
  const refuse = (why) => {
    notice(`This link could not be used: ${why}. Showing the ${studyTitle(DEFAULT_PRESET)} study instead.`);
    return { refused: true };
  };
  if (link.refused) return refuse(link.refused);
  let dropped = [];
  try {
    await validate(link.scenario);
  } catch (e) {
    if (!e.fields.length) return refuse(e.message);
    const kept = form.withoutRefused(link.name, link.scenario, e.fields);
    try {
      if (!kept) throw e;
      await validate(kept);
    } catch (_) {
      return refuse(e.fields.slice(0, 3).map(fieldLine).join('; '));
    }
    dropped = e.fields;
    link.scenario = kept;
  }
  const said = [...dropped.map((f) => form.refusedLine(f, link.name)), ...link.ignored];
  if (said.length) notice(`${said.join(' ')} The link's other values are kept.`);
  return { ...link, edited: form.modified(link.scenario, link.name), dropped };
}

// A link to a tab with work of its own (the operability polar) does it; false for other tabs.
function tabWork(link) {
  const v = tabView(link.tab);
  if (!v || !v.linked) return false;
  v.linked(ctx);
  return true;
}

async function onReady(m) {
  if (form) { setPhase('idle'); return; } // a fresh worker after a cancel: the page stays as it is
  signals = new Signals(m.signals);
  setRegistry(m.params);
  form = new ScenarioForm(m.presets, m.params, { onLooseErrors: (text) => status(text, true), onEdit, onValidity: (v) => { setFormValid(v); each('sync', ctx); }, onSelect: () => { each('selected', ctx); each('sync', ctx); } });
  each('ready', ctx, m);
  if (first('route', ctx, location.hash.slice(1), true)) return;
  const linked = await openLink(location.hash.slice(1));
  const ok = linked && !linked.refused ? linked : null;
  each('restore', ctx, ok);
  if (ok && ok.tab !== 'sim') selectTab(`tab-${ok.tab}`, false, false);
  // A reload shows the address's state again without running it (a link opened afresh runs).
  const reloaded = (performance.getEntriesByType('navigation')[0] || {}).type === 'reload';
  if (ok && reloaded) {
    form.select(ok.name, ok.scenario);
    form.save();
    mode = ok.mode;
    follow(false);
    setPhase('idle');
    status(`Your edits are back${ok.edited.length ? ` (${ok.edited.length} value(s) changed from the study)` : ''}: press ${press()}.`);
    return;
  }
  if (ok && (ok.edited.length || ok.dropped.length || ok.view || modeView(ok.mode))) {
    form.select(ok.name, ok.scenario);
    form.markLinked(ok.edited, ok.dropped);
    mode = ok.mode;
    follow(false);
    setPhase('idle');
    if (ok.edited.length) status(`This link changed ${ok.edited.length} value(s) of the study (marked in the form).`);
    if (modeView(mode)) { await modeView(mode).again(ctx); return; }
    if (tabWork(ok)) return;
    await run({ focus: false });
    if (ok.view) live.place(ok.view);
    return;
  }
  const saved = linked && linked.refused ? null : form.saved();
  const want = ok ? ok.name : null;
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
  if (ok) { tabWork(ok); return; }
  // A plain first visit opens alive: the default study's run, its drive train playing (held still
  // where the system asks for reduced motion).
  if (!restored && !linked) {
    await run({ focus: false });
    if (getResult() && !matchMedia('(prefers-reduced-motion: reduce)').matches) live.place({ at: 0, speed: 10 }, { scroll: false }).then(() => live.start());
  }
}

// After an accepted edit: the scenario is checked at once (errors at the field, Run waits), and
// a page opened from a link now shows the study, not the link's values.
let validating = 0;
async function onEdit(push = false) {
  follow(push);
  each('edited', ctx);
  showStale();
  const mine = ++validating;
  try {
    await validate(form.current());
    if (mine === validating) { form.markErrors([]); each('checked', ctx); }
  } catch (e) {
    if (mine === validating && !e.cancelled) form.markErrors(e.fields || []);
  }
}

// Another study: its own edits of this visit come back with it (the picker marks them), and what
// was drawn for it last comes back too, else nothing is drawn.
function selectStudy(name, push = true) {
  validating++; // a check still on its way belongs to the study left
  form.select(name);
  form.save();
  mode = 'run';
  const last = drawn.lastWhere((r) => r.study === name);
  if (last) { last.redraw(); drawn.shown = last.key; mode = last.state.split('|')[0]; } else clearResults();
  follow(push);
  showStale();
}

// Back/Forward and a hand-edited address: the tab, study, values and mode of the address, with
// their result when the page still has it; else nothing is drawn and the status says what to press.
async function route() {
  if (!form || isBusy()) return;
  if (first('route', ctx, location.hash.slice(1), false)) return;
  const link = await openLink(location.hash.slice(1));
  if (!link || link.refused) return;
  validating++;
  selectTab(`tab-${link.tab}`, false, false);
  each('restore', ctx, link);
  form.select(link.name, link.scenario);
  form.save();
  form.markLinked(link.edited, link.dropped);
  mode = link.mode;
  const key = stateKey();
  const r = drawn.of(key);
  if (r) {
    drawn.show(r);
    status(`${studyTitle(link.name)}: the result of these values is back.`);
  } else {
    clearResults();
    status(`${studyTitle(link.name)}${link.edited.length ? `, ${link.edited.length} value(s) changed` : ''}: press ${press()} to see its result.`);
  }
  showStale();
  // An address with a refused value now says the values shown (the notice says what was refused).
  history.replaceState({ shown: current() ? drawn.shown : null }, '', link.dropped.length ? hereHash() : location.hash);
}

// A failed request keeps the form and the earlier results; refused fields are marked.
function failed(e) {
  live.hide(); // it may hold part of the run that failed
  if (e.declined) { setPhase('idle'); status(e.message); return; } // a long study the user did not start
  if (e.cancelled) return;
  setPhase('idle');
  status(e.message, true);
  form.markErrors(e.fields || []);
}

// trial: {i, text} replays Monte Carlo trial i from its scenario text (exact 64-bit seed).
// replay: {text, name, words, state, isCurrent, at, shaft, hrAt(columns)}: a rare-event scenario
// (its trial's or the most likely wave group's), said in words, shown with the live views at its
// event (at). order: the plots to draw first (a lesson's), else the study's.
// lesson: {name, values}: the run's explanation as that lesson comes with the result. preview: a
// run while a control is dragged, of `preview` simulated seconds: drawn, but no result of the
// form's values (not kept for Back, no step in the history).
async function run({ focus = true, trial = null, replay = null, order: plotOrder = null, lesson = null, preview = null } = {}) {
  if (isBusy() || !form || form.invalid.size) return;
  const given = trial || replay;
  const sc = given ? JSON.parse(given.text) : form.current(); // (its seed only for display)
  if (preview) sc.sim.duration_s = Math.min(sc.sim.duration_s, preview);
  const text = given ? given.text : JSON.stringify(sc);
  // The inputs this result will belong to, taken now (the form may change while it runs).
  const state = replay ? replay.state : stateKey(trial ? 'mc' : 'run'), study = form.name;
  setPhase('running');
  status(replay ? `Running ${replay.words}...` : 'Running...');
  const started = performance.now();
  const c = client;
  let m;
  try {
    m = await c.request(REQUEST.run, { scenario: text, live: true, ...(lesson ? { lesson } : {}) }, (p) => {
      progress(p.fraction, etaText(started, p.fraction));
      if (p.rows) live.follow(p.rows, p.constants, sc, text);
    });
  } catch (e) { failed(e); return; }
  progress(1);
  const seed = trial ? (trial.text.match(/"seed":\s*(\d+)/) || [])[1] : null;
  const name = trial ? `${studyTitle(form.name)}, Monte Carlo trial ${trial.i} (sea seed ${seed})` : replay ? replay.name : form.runName(sc);
  setPhase('idle');
  const draw = () => {
    setResult({ summary: m.summary, csv: !m.lesson, scenario: sc, text, columns: m.columns, name, study, lesson: m.lesson || null, wallMs: m.wall_ms });
    // A rare-event run says above its views what it is (a run of the form's values needs no line).
    $('shown-what').hidden = !replay;
    $('shown-what').textContent = replay ? `Shown: ${replay.words}. The ${replay.shaft} hub's h/R at the event (t = ${replay.at} s): ${replay.hrAt(m.columns)}.` : '';
    each('drawRun', ctx, m, name);
    const order = plotOrder || (STUDIES[study] && STUDIES[study].plots) || DEFAULT_PLOTS;
    const { markers } = drawRun(plots, m.columns, signals, m.constants, sc, { order, kept: ctx.kept });
    getResult().markers = markers;
    // (Not in a lesson: its RAO and fuel plots are folded away, and the worker would compute them
    // before the next run a slider asks for.)
    if (sc.sea.kind !== 'calm' && !ctx.lesson) drawSeaExtras(plots, client, sc, m.columns, m.constants, (e) => status(e.message, true));
    live.show(m.columns, m.constants, sc, text).catch((e) => status(`The live views failed: ${e.message}`, true));
    return markers;
  };
  if (!given) mode = 'run';
  const markers = draw();
  if (preview) return;
  drawn.remember(trial ? `trial ${trial.i}|${state}` : replay ? `${replay.name}|${state}` : state, state, draw, replay ? { isCurrent: replay.isCurrent } : {});
  settle();
  showStale();
  const t = m.summary.final_time_s, wall = m.wall_ms / 1000;
  const events = sc.sea.kind === 'calm' ? '' : ` Surface losses started ${markers.length} time(s).`;
  if (replay) {
    // The views stand at the event, in view; the line says what they show.
    const hr = ` The ${replay.shaft} hub's h/R at the event: ${replay.hrAt(m.columns)}.`;
    status(`Done: showing ${replay.words}; ${t} s simulated in ${wall.toFixed(2)} s.${events}${hr} The live views stand at the event (t = ${replay.at} s): press Play.`);
    live.place({ at: replay.at, speed: 1 }).then(() => $('shown-what').scrollIntoView({ block: 'start' }));
    return;
  }
  status(`Done${trial ? ` (${name})` : ''}: ${t} s simulated in ${wall.toFixed(2)} s (${(t / wall).toFixed(0)} times real time).${events}`);
  if (focus) $('results').focus();
}

function cancel() {
  each('cancel', ctx);
  client.terminate();
  status('Cancelled.');
  startWorker();
}

registerView({ id: 'sim', tab: 'sim', skip: '#results' });
// push: a tab the user picked is a step in the history (Back returns to the tab before).
function selectTab(id, focus = false, push = true) {
  const { changed, view } = showTab(id, focus);
  if (view.shown) view.shown(ctx);
  if (changed && push && form) follow(true);
}
listenTabs(selectTab);

// What the views see of the page: its state and the core's moves.
const ctx = {
  get client() { return client; },
  get form() { return form; },
  get signals() { return signals; },
  get mode() { return mode; },
  get kept() { return kept; },
  get lesson() { return lesson; },
  // The views change the page's state through these, never by writing it.
  setMode: (m) => { mode = m; },
  keep: (run) => { kept = run; },
  setLesson: (l) => { lesson = l; },
  plots, live, validate, studyInputs, stateKey, hereHash, follow, settle, remember: (...a) => drawn.remember(...a), showStale, clearResults, failed, run, onEdit, selectStudy, selectTab, cancel,
  forgetChecks: () => { validating++; }, // a check still on its way is of values left behind
  // The result of the form's values drawn again, if the page still has it (Back within a lesson).
  restoreResult: () => {
    const r = drawn.of(stateKey());
    if (!r) return false;
    drawn.show(r);
    showStale();
    return true;
  },
};
each('init', ctx);

$('form').addEventListener('submit', (e) => e.preventDefault());
$('preset').addEventListener('change', () => selectStudy($('preset').value));
$('run').addEventListener('click', () => run());
$('cancel').addEventListener('click', cancel);
// A press on Reset keeps the focus where it is: a value being typed is not committed first (its
// error would appear and move Reset from under the pointer before the click).
$('reset').addEventListener('pointerdown', (e) => e.preventDefault());
$('reset').addEventListener('click', () => {
  if (!form) return;
  validating++; // a check of the values left behind must not mark the study's own
  form.reset();
  onEdit();
  status('Back to the study\'s values.');
});
$('stale-run').addEventListener('click', () => (modeView(mode) ? modeView(mode).again(ctx) : run()));
window.addEventListener('popstate', route);
// The browser tests' hooks, for a page a test opened (it sets the flag before the page loads).
if (globalThis.aesTestHooks) (await import('./testhooks.js')).install(ctx);
startWorker();
