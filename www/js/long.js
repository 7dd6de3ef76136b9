// Before a long study (issue 46): its estimate said in a modal dialog, and the study started only
// when the user says so. The estimate is the wasm's (core's study::estimate, this browser's speed);
// the dialog is made once, here.
import { LONG_STUDY } from './config.js';
import { el } from './dom.js';

// A wall-clock duration as an estimate is read: seconds, minutes, hours or days.
export function durationText(s) {
  if (s < 90) return `about ${Math.round(s)} s`;
  if (s < 2 * 3600) return `about ${Math.round(s / 60)} min`;
  if (s < 2 * 86400) return `about ${(s / 3600).toFixed(1)} h`;
  return `about ${Math.round(s / 86400)} days`;
}

let dialog = null;

function made() {
  if (dialog) return dialog;
  dialog = el('dialog', { id: 'long-study', attrs: { 'aria-labelledby': 'long-study-h', 'aria-describedby': 'long-study-text' } },
    el('h2', { id: 'long-study-h' }, 'This study takes a while'),
    el('p', { id: 'long-study-text' }),
    el('p', { className: 'hint' }, 'It runs in this tab: keep it open. Cancel stops it at any time; nothing already shown is lost.'),
    el('form', { method: 'dialog', className: 'row buttons' },
      el('button', { id: 'long-study-go', value: 'go' }, 'Start it'),
      el('button', { id: 'long-study-no', value: 'no', autofocus: true }, 'Not now')));
  document.body.append(dialog);
  return dialog;
}

// Resolves to true when the study of `estimate` ({items, seconds?}) may start on `workers`
// workers: at once if it is short (or its items are not runs), else when the user says so.
// `item` names its items ("trial", "run", "speed").
export function startLong(estimate, workers, item) {
  if (!(estimate.seconds > LONG_STUDY.askAboveS)) return Promise.resolve(true);
  const d = made();
  const plural = (n, w) => `${n} ${w}${n === 1 ? '' : 's'}`;
  d.querySelector('#long-study-text').textContent = `${plural(estimate.items, item)} on ${plural(workers, 'worker')}: estimated at ${durationText(estimate.seconds)} in this browser. Start it now?`;
  d.returnValue = '';
  return new Promise((resolve) => {
    d.addEventListener('close', () => resolve(d.returnValue === 'go'), { once: true });
    d.showModal();
  });
}

// The words for a study that was not started, or was stopped.
export function stoppedText(e) {
  return e.declined ? e.message : 'Cancelled.';
}
