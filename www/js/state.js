// The page's busy/idle state, in one place: which buttons can be pressed, the progress bar, the
// status line and the notice. Every other module asks for a phase; none touches these controls.
import { $ } from './dom.js';

// loading: no simulator yet (start-up, or a fresh worker after cancel); idle: ready;
// running: one run; montecarlo: a Monte Carlo study.
const PHASES = ['loading', 'idle', 'running', 'montecarlo'];
let phase = 'loading';
let formValid = true; // Run waits while a field is invalid
let result = null; // the last result: {summary, csv, scenario, columns}; csv: the trace can be exported (a run's, not a lesson's or Monte Carlo's)

function render() {
  const idle = phase === 'idle';
  const busy = phase === 'running' || phase === 'montecarlo';
  $('run').disabled = !idle || !formValid;
  $('mc-run').disabled = !idle || !formValid;
  $('keep').disabled = !idle || !(result && result.columns);
  $('loading').hidden = phase !== 'loading';
  $('cancel').disabled = !busy;
  $('export-csv').disabled = !(result && result.csv);
  $('export-json').disabled = !result;
  $('results').setAttribute('aria-busy', String(busy));
}

export function setPhase(p) {
  if (!PHASES.includes(p)) throw new Error(`no phase '${p}'`);
  phase = p;
  // Loading (the page's start, or a fresh worker after Cancel): no share of work is done.
  if (p === 'running' || p === 'montecarlo' || p === 'loading') progress(0, '');
  else $('eta').textContent = '';
  if (!$('progress').hasAttribute('value')) $('progress').value = 0; // a study that ended while it prepared
  render();
}
export function getPhase() { return phase; }
export function isBusy() { return phase === 'running' || phase === 'montecarlo'; }

export function setFormValid(v) { formValid = v; render(); }

export function setResult(r) { result = r; render(); }
export function getResult() { return result; }

// fraction null: work with no share to show yet (a study preparing): the bar moves without one.
export function progress(fraction, eta = '') {
  if (fraction === null) $('progress').removeAttribute('value'); else $('progress').value = fraction;
  $('eta').textContent = eta;
}

export function status(text, isError = false) {
  $('status').textContent = text;
  $('status').className = isError ? 'error' : '';
}

export function notice(text) {
  $('notice').textContent = text;
  $('notice').hidden = !text;
}

// What a view has just shown (a study's result, a lesson's run landed), by name, for whoever
// listens: the browser tests' hooks (testhooks.js) when a test loads them, nobody otherwise. A
// listener hears the last of each name shown before it came, too.
const lastShown = new Map();
let listener = null; // one: the tests' hooks
export function announce(name, value) {
  lastShown.set(name, value);
  if (listener) listener(name, value);
}
export function onAnnounce(f) {
  listener = f;
  for (const [name, value] of lastShown) f(name, value);
}

// "about 3.2 s left" from the elapsed wall time and the fraction done (empty early on).
export function etaText(startedMs, fraction) {
  const elapsed = (performance.now() - startedMs) / 1000;
  if (elapsed <= 0.5 || fraction <= 0.02) return '';
  return `about ${Math.max(0, (elapsed * (1 - fraction)) / fraction).toFixed(1)} s left`;
}
