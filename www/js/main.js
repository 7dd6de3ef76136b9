// The page: wires the form, the worker, the plots, share links, exports and the stability tab.
import { DEFAULT_PRESET, SUMMARY_ROWS } from './config.js';
import { $, el, row, download } from './dom.js';
import { REQUEST, WorkerClient, fieldLine } from './protocol.js';
import { setPhase, isBusy, setResult, getResult, progress, status, notice, etaText } from './state.js';
import { linkHash, readLink } from './link.js';
import { ScenarioForm } from './form.js';
import { Signals } from './units.js';
import { PlotBox, drawRun, drawSeaExtras } from './plots.js';
import { MonteCarlo, showMonteCarlo } from './montecarlo.js';
import { StabilityTab } from './stability.js';

const plots = new PlotBox($('plots'));
const monteCarlo = new MonteCarlo();
// Set once the first worker is ready; `client` is replaced by a fresh worker after a cancel.
let client = null;
let form = null;
let signals = null;
const stability = new StabilityTab(() => client, new PlotBox($('ips-plots'), { maxWidth: 900, columns: 1 }));

function startWorker() {
  setPhase('loading');
  client = new WorkerClient({
    onReady,
    onFailure: (e) => status(`The simulator failed to load: ${e.message}`, true),
  });
}

const validate = (sc) => client.request(REQUEST.validate, { scenario: JSON.stringify(sc) });

// The scenario of the page's link: null without one, {refused: true} (after saying why) when it
// cannot be used, else {name, scenario}, validated.
async function openLink() {
  const link = readLink(location.hash.slice(1), form.presets);
  if (!link) return null;
  const refuse = (why) => {
    notice(`This link could not be used: ${why}. Showing the ${DEFAULT_PRESET} study instead.`);
    return { refused: true };
  };
  if (link.refused) return refuse(link.refused);
  try {
    await validate(link.scenario);
  } catch (e) {
    return refuse(e.fields.length ? e.fields.slice(0, 3).map(fieldLine).join('; ') : e.message);
  }
  return link;
}

async function onReady(m) {
  if (form) { setPhase('idle'); return; } // a fresh worker after a cancel: the page stays as it is
  signals = new Signals(m.signals);
  form = new ScenarioForm(m.presets, { onLooseErrors: (text) => status(text, true) });
  const linked = await openLink();
  if (linked && !linked.refused) {
    form.select(linked.name, linked.scenario);
    setPhase('idle');
    run();
    return;
  }
  let restored = false;
  const saved = linked ? null : form.saved();
  if (saved) {
    try {
      await validate(saved.scenario);
      form.select(saved.preset, saved.scenario);
      restored = true;
    } catch (_) { /* stale edits: start from the preset */ }
  }
  if (!restored) form.select(DEFAULT_PRESET);
  setPhase('idle');
  status(restored ? 'Your last edits are back.' : 'Ready. Choose a study and press Run.');
}

function showSummary(s, constants) {
  $('summary').querySelector('tbody').replaceChildren(...SUMMARY_ROWS.map((name) => {
    const v = s.signals[name];
    return row(signals.labelWithUnit(name, constants), [v.final, v.min, v.max].map((x) => Number(x).toPrecision(4)));
  }));
  $('warnings').replaceChildren(...(s.warnings || []).map((w) => el('li', { textContent: w })));
  $('summary-box').hidden = false;
}

// A failed request keeps the form and the earlier results; refused fields are marked.
function failed(e) {
  if (e.cancelled) return;
  setPhase('idle');
  status(e.message, true);
  form.markErrors(e.fields || []);
}

async function run() {
  if (isBusy() || !form) return;
  const sc = form.current();
  setPhase('running');
  status('Running...');
  const started = performance.now();
  const c = client;
  let m;
  try {
    m = await c.request(REQUEST.run, { scenario: JSON.stringify(sc) }, (p) => progress(p.fraction, etaText(started, p.fraction)));
  } catch (e) { failed(e); return; }
  progress(1);
  setResult({ summary: m.summary, csv: m.csv, scenario: sc });
  setPhase('idle');
  showSummary(m.summary, m.constants);
  drawRun(plots, m.columns, signals, m.constants);
  if (sc.sea.kind !== 'calm') drawSeaExtras(plots, c, sc, m.columns, m.constants, (e) => status(e.message, true));
  const t = m.summary.final_time_s, wall = m.wall_ms / 1000;
  status(`Done: ${t} s simulated in ${wall.toFixed(2)} s (${(t / wall).toFixed(0)} times real time).`);
}

async function runMonteCarlo() {
  if (isBusy() || !form) return;
  const sc = form.current();
  const why = MonteCarlo.refusal(sc);
  if (why) { status(why, true); return; }
  const n = Number(sc.monte_carlo.trials);
  setPhase('montecarlo');
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
  showMonteCarlo(plots, out.summary, signals, out.constants);
  status(`Monte Carlo done: ${n} trials in ${((performance.now() - started) / 1000).toFixed(1)} s.`);
}

function cancel() {
  monteCarlo.stop();
  client.terminate();
  status('Cancelled.');
  startWorker();
}

$('form').addEventListener('submit', (e) => e.preventDefault());
$('preset').addEventListener('change', () => { form.select($('preset').value); form.save(); });
$('run').addEventListener('click', run);
$('mc-run').addEventListener('click', runMonteCarlo);
$('cancel').addEventListener('click', cancel);
$('reset').addEventListener('click', () => {
  if (!form) return;
  form.select(form.name);
  form.save();
  status('Back to the preset.');
});
$('share').addEventListener('click', async () => {
  if (!form) return;
  const url = location.origin + location.pathname + linkHash(form.name, form.preset(), form.scenario);
  $('share-url').hidden = false;
  $('share-url').value = url;
  $('share-url').select();
  try { await navigator.clipboard.writeText(url); status('Link copied: it opens this scenario and runs it.'); } catch (_) { status('Link below: copy it by hand.'); }
});
$('export-csv').addEventListener('click', () => {
  const r = getResult();
  if (r && r.csv) download(`${r.scenario.name}-trace.csv`, `# scenario: ${JSON.stringify(r.scenario)}\n${r.csv}`, 'text/csv');
});
$('export-json').addEventListener('click', () => {
  const r = getResult();
  if (r) download(`${r.scenario.name}-summary.json`, JSON.stringify({ scenario: r.scenario, summary: r.summary }, null, 1), 'application/json');
});
for (const [tab, panel, other, otherPanel] of [['tab-sim', 'panel-sim', 'tab-ips', 'panel-ips'], ['tab-ips', 'panel-ips', 'tab-sim', 'panel-sim']]) {
  $(tab).addEventListener('click', () => {
    $(tab).setAttribute('aria-selected', 'true'); $(other).setAttribute('aria-selected', 'false');
    $(panel).hidden = false; $(otherPanel).hidden = true;
    if (tab === 'tab-ips') stability.update();
  });
}
window.addEventListener('hashchange', () => location.reload());
startWorker();
