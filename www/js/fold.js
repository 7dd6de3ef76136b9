// A study fold's working parts, one skeleton for every fold that computes a study of the form
// (fuel, maneuvers, schedule, rare events, operability): its busy flag, Compute and Cancel, the
// progress bar and time left, the status line, and the mark of a result of other inputs. The
// fold's elements are found by its id prefix: NAME-compute, NAME-status, and where the fold has
// them NAME-cancel, NAME-progress, NAME-eta, NAME-results (busy while computing, its stale class
// NAME-is-stale), NAME-stale and NAME-stale-text (the stale box), NAME-body (the result).
import { $ } from './dom.js';
import { fieldLine } from './protocol.js';
import { stoppedText } from './long.js';
import { progressText } from './pool.js';

export class StudyFold {
  // failed: the words before a failure's message ("The fuel study failed"). cancel(): stops the
  // work (a fold with a Cancel button). redFailures: a failure's status reads as an error.
  constructor(name, { failed, cancel = null, redFailures = false }) {
    this.name = name;
    this.failed = failed;
    this.stop = cancel;
    this.redFailures = redFailures;
    this.busy = false;
    this.shownKey = null; // the inputs the result shown belongs to (folds that drop() it)
    if (cancel) $(this.id('cancel')).addEventListener('click', cancel);
  }

  id(part) { return `${this.name}-${part}`; }
  el(part) { return document.getElementById(this.id(part)); }

  status(text, error = false) {
    const s = this.el('status');
    s.textContent = text;
    if (this.redFailures) s.className = error ? 'error' : '';
  }

  // `preparing`: before the first item (the workers build what every item needs): the bar has no
  // share, and the words say so instead of "0 of n".
  progress(done, n, started, item, preparing = false) {
    if (preparing) {
      this.el('progress').removeAttribute('value');
      this.el('eta').textContent = `Preparing the workers; the first of ${n} ${item}s starts after.`;
      return;
    }
    this.el('progress').value = done / n;
    this.el('eta').textContent = progressText(done, n, started, item);
  }

  // Compute pressable unless busy or `allowed` is false.
  allow(allowed) { this.el('compute').disabled = this.busy || !allowed; }

  // A refused value of the form: said in the status line while nothing runs, unsaid once mended.
  refused(invalid, text) {
    if (invalid && !this.busy) this.status(text, true);
    else if (this.el('status').textContent === text) this.status('');
  }

  // Runs work() with Compute held down, Cancel pressable and the results busy. A failure is said
  // in the status line (cancelled, the scenario's refused fields, or `failed` and its message)
  // after onFail(e); after() runs last either way (the inputs may have changed meanwhile).
  async compute(work, { onFail = () => {}, after = () => {} } = {}) {
    if (this.busy) return;
    this.busy = true;
    this.el('compute').disabled = true;
    if (this.stop) this.el('cancel').disabled = false;
    const results = this.el('results');
    if (results) results.setAttribute('aria-busy', 'true');
    try {
      await work();
    } catch (e) {
      if (this.stop) this.stop();
      onFail(e);
      if (this.stop && e.cancelled) this.status(stoppedText(e));
      else this.status(e.fields && e.fields.length ? `The scenario is refused: ${e.fields.slice(0, 3).map(fieldLine).join('; ')}` : `${this.failed}: ${e.message}`, true);
      if (this.el('progress')) { this.el('progress').value = 0; this.el('eta').textContent = ''; }
    } finally {
      this.busy = false;
      this.el('compute').disabled = false;
      if (this.stop) this.el('cancel').disabled = true;
      if (results) results.setAttribute('aria-busy', 'false');
      after();
    }
  }

  // A result kept beside others: marked stale (the box with its line) while of other inputs.
  markStale(stale, text) {
    this.el('stale').hidden = !stale;
    this.el('results').classList.toggle(`${this.name}-is-stale`, stale);
    if (stale) this.el('stale-text').textContent = text;
  }

  // A single result: hidden once the inputs (`key`) are no longer those it was computed from (it
  // would read as theirs), the status line saying to compute again.
  drop(key, text) {
    if (!this.shownKey || key === this.shownKey) return;
    this.shownKey = null;
    this.el('body').hidden = true;
    this.status(text);
  }
}
