// The lessons' screen: the index, and one lesson's controls, its question, the explanation of each
// run and what to try next. The lessons themselves (controls, stops, question, the claims of each
// run) come from the wasm (core's output::lessons); the page (views/lessons.js) runs the study and
// draws the plots and the live view; this module owns the words' layout and the controls.
import { $, el } from '../dom.js';
import { GLOSSARY } from './catalog.js';

// '#lessons', '#lesson=NAME&PATH=VALUE...' (the values the link sets, as text), or null for any
// other hash. `lessons`: the wasm's lessonMeta.
export function readLessonHash(hash, lessons) {
  if (hash === 'lessons') return { index: true };
  if (!hash.startsWith('lesson=')) return null;
  const params = new URLSearchParams(hash);
  const def = lessons.find((l) => l.name === params.get('lesson'));
  if (!def) return { index: true, unknown: String(params.get('lesson')).slice(0, 40) };
  const values = {};
  for (const c of def.controls) if (params.has(c.path)) values[c.path] = params.get(c.path);
  return { def, values };
}

// A number as the control shows it (no float noise: 2.65, 0.0002).
const show = (v) => (typeof v === 'number' ? String(Number(v.toPrecision(6))) : String(v));
const unitOf = (c) => (c.unit ? ` ${c.unit}` : '');
// The id of a control's element.
const idOf = (c) => `lesson-${c.path.replace(/\./g, '-')}`;
// The stop nearest a value (the thumb's position).
const stopIndex = (c, v) => c.stops.reduce((best, s, i) => (Math.abs(s - v) < Math.abs(c.stops[best] - v) ? i : best), 0);

export class LessonView {
  // lessons: the wasm's lessonMeta; onChange(path, value, settled): a control moved (settled: released
  // or stepped; else a drag in progress); onAnswer(): the question was answered (the first run).
  constructor(lessons, { onChange, onAnswer }) {
    this.lessons = lessons;
    this.onChange = onChange;
    this.onAnswer = onAnswer;
    this.def = null;
    this.answer = null;
    this.isAnswered = false;
    this.before = null;
    this.reference = null; // the settled run before: {values, reading, answer} (core's lessons::Before)
  }

  // The index of lessons, in the lesson box: a first visit starts with the first lesson.
  showIndex(unknown = null) {
    this.def = null;
    $('lesson-box').replaceChildren(el('h2', { textContent: 'Lessons' }),
      ...(unknown ? [el('p', { className: 'error', attrs: { role: 'alert' }, textContent: `There is no lesson "${unknown}": pick one below.` })] : []),
      el('p', { className: 'about', textContent: 'Each lesson is one study with two or three controls. Answer its question first, then move the controls: every change reruns at once, and the run before stays drawn faintly beside the new one. Each takes about ten minutes in class.' }),
      el('p', {}, el('a', { href: `#lesson=${this.lessons[0].name}`, className: 'start-here', textContent: `Start here: ${this.lessons[0].title}` })),
      el('ol', { className: 'lesson-list' }, ...this.lessons.map((l) => el('li', {}, el('a', { href: `#lesson=${l.name}`, textContent: l.title }), el('span', { className: 'hint', textContent: ` ${l.question}` })))),
      el('p', {}, el('a', { href: '#v=2&preset=startup', textContent: 'The full simulator (Lab)' })));
    $('lesson-explain').replaceChildren();
  }

  // Opens lesson `def` with `opened` (lessonOpen's answer: values, defaults, refused). `answered`:
  // the question was answered earlier in this visit (Back and Forward do not ask again).
  open(def, opened, labHref, answered = false) {
    this.def = def;
    this.answer = null; // the answer chosen (null: skipped)
    this.isAnswered = answered;
    this.before = null;
    this.reference = null;
    this.current = { ...opened.values };
    const controls = def.controls.map((c) => this.control(c, opened.values[c.path]));
    // A radio group (the ARIA pattern): arrows move between the answers without choosing; Enter,
    // Space or a click chooses.
    const radios = def.answers.map((a, i) => el('div', { id: `lesson-a${i}`, className: 'lesson-answer', textContent: a, attrs: { role: 'radio', 'aria-checked': 'false', tabindex: i === 0 ? '0' : '-1' } }));
    const group = el('div', { className: 'lesson-answers', attrs: { role: 'radiogroup', 'aria-labelledby': 'lesson-q', 'aria-describedby': 'lesson-wait' } }, ...radios);
    radios.forEach((r, i) => r.addEventListener('click', () => this.answered(i)));
    group.addEventListener('keydown', (e) => {
      const i = radios.indexOf(document.activeElement);
      if (i < 0 || this.isAnswered) return;
      const step = { ArrowDown: 1, ArrowRight: 1, ArrowUp: -1, ArrowLeft: -1 }[e.key];
      if (step) {
        e.preventDefault();
        const j = (i + step + radios.length) % radios.length;
        radios.forEach((r, k) => { r.tabIndex = k === j ? 0 : -1; r.setAttribute('aria-checked', String(k === j)); });
        radios[j].focus();
      } else if (e.key === 'Enter' || e.key === ' ') {
        e.preventDefault();
        this.answered(i);
      }
    });
    const skip = el('button', { type: 'button', id: 'lesson-skip', textContent: 'Just run it' });
    skip.addEventListener('click', () => this.answered(null));
    const refused = opened.refused.length ? [el('div', { id: 'lesson-refused', className: 'error', attrs: { role: 'alert' } },
      el('p', { textContent: 'This link\'s values could not all be used; the lesson\'s own stand in their place:' }),
      el('ul', {}, ...opened.refused.map((r) => el('li', { textContent: r }))))] : [];
    // A link's value between two stops runs at the nearest: said, as the address now carries it.
    if (opened.snapped && opened.snapped.length) refused.push(el('p', { id: 'lesson-snapped', className: 'lesson-snapped', attrs: { role: 'status' }, textContent: `${opened.snapped.join('. ')}.` }));
    $('lesson-box').replaceChildren(
      el('p', { className: 'lesson-nav' }, el('a', { href: '#lessons', textContent: 'All lessons' }), ' · ', el('a', { href: labHref, id: 'lesson-lab', textContent: 'Open in the full simulator (Lab)' })),
      el('h2', { id: 'lesson-title', textContent: def.title }),
      ...refused,
      el('p', { id: 'lesson-story', className: 'lesson-story', textContent: def.story }),
      el('div', { id: 'lesson-predict', className: 'lesson-predict' },
        el('p', { id: 'lesson-q', className: 'lesson-q', textContent: `Predict: ${def.question}` }), group, skip,
        el('p', { id: 'lesson-wait', className: 'hint', textContent: 'The controls below wait for your answer (or "Just run it"): first guess, then see. Arrow keys move between the answers; Enter or Space chooses.' })),
      el('div', { id: 'lesson-controls', className: 'lesson-controls' }, ...controls));
    $('lesson-explain').replaceChildren(
      el('div', { id: 'lesson-observe', attrs: { 'aria-live': 'polite' } }),
      el('details', { className: 'lesson-words' }, el('summary', { textContent: 'Words used here' }),
        el('dl', {}, ...GLOSSARY.flatMap(([k, v]) => [el('dt', { textContent: k }), el('dd', { textContent: v })]))));
    if (answered) this.markAnswered(null);
    else this.setDisabled(true);
  }

  // A slider over the lesson's stops (the label shows the stop under the thumb, with its unit) or
  // a toggle.
  control(c, v) {
    const id = idOf(c);
    const unit = unitOf(c);
    const label = el('label', { htmlFor: id, textContent: `${c.label}${unit ? ` [${c.unit}]` : ''}` });
    if (c.kind === 'toggle') {
      const sel = el('select', { id }, ...c.values.map((x, i) => new Option(c.labels[i], x)));
      sel.value = String(v);
      sel.dataset.path = c.path;
      sel.addEventListener('change', () => { this.current[c.path] = c.values[sel.selectedIndex]; this.onChange(c.path, this.current[c.path], true); });
      return el('div', { className: 'lesson-control' }, label, sel);
    }
    const text = (x) => `${show(x)}${unit}`;
    const out = el('output', { id: `${id}-out`, htmlFor: id, textContent: text(v) });
    const input = el('input', { type: 'range', id, min: '0', max: String(c.stops.length - 1), step: '1', value: String(stopIndex(c, v)), attrs: { 'aria-valuetext': text(v) } });
    input.dataset.path = c.path;
    const at = () => c.stops[Number(input.value)];
    // While dragging: the label follows the thumb and a preview run follows (views/lessons.js
    // throttles it); on release or a key step, the settled run.
    // A key step fires both at once: its preview is dropped for the settled run.
    let later = null;
    input.addEventListener('input', () => {
      out.textContent = text(at());
      input.setAttribute('aria-valuetext', out.textContent);
      this.current[c.path] = at();
      clearTimeout(later);
      later = setTimeout(() => this.onChange(c.path, at(), false), 0);
    });
    input.addEventListener('change', () => { clearTimeout(later); this.current[c.path] = at(); this.onChange(c.path, at(), true); });
    return el('div', { className: 'lesson-control' }, label, input, out);
  }

  // Moves the controls to `values` (Back and Forward).
  setValues(values) {
    this.current = { ...values };
    for (const c of this.def.controls) {
      const e = $(idOf(c));
      if (!e) continue;
      const v = values[c.path];
      if (c.kind === 'toggle') e.value = String(v);
      else {
        e.value = String(stopIndex(c, v));
        $(`${idOf(c)}-out`).textContent = `${show(v)}${unitOf(c)}`;
        e.setAttribute('aria-valuetext', $(`${idOf(c)}-out`).textContent);
      }
    }
  }

  // The controls wait for the prediction (then the first run).
  setDisabled(on) {
    for (const i of $('lesson-controls').querySelectorAll('input, select')) i.disabled = on;
  }

  // The question answered (i: the answer, null: skipped): the answers stay in view, marked, and the
  // controls act.
  markAnswered(i) {
    for (const r of document.querySelectorAll('#lesson-predict [role="radio"]')) {
      r.setAttribute('aria-disabled', 'true');
      r.setAttribute('aria-checked', String(r.id === `lesson-a${i}`));
      r.tabIndex = -1;
    }
    $('lesson-skip').disabled = true;
    $('lesson-wait').textContent = i === null ? 'Answered earlier: move the controls.' : 'Now move the controls: each change reruns.';
    this.setDisabled(false);
  }

  answered(i) {
    if (this.isAnswered || !this.def) return;
    this.isAnswered = true;
    this.answer = i;
    this.markAnswered(i);
    // Focus goes to the first control, without moving the screen.
    const first = $('lesson-controls').querySelector('input, select');
    if (first) first.focus({ preventScroll: true });
    this.onAnswer();
  }

  // The controls' values now, by path.
  values() { return { ...this.current }; }

  // The lesson's address: its name and the values that differ from the lesson's own.
  hash(defaults) {
    const params = new URLSearchParams({ lesson: this.def.name });
    for (const [p, v] of Object.entries(this.values())) if (String(defaults[p]) !== String(v)) params.set(p, String(v));
    return `#${params.toString()}`;
  }

  // The run before, for the verdict on the next run (null: none yet, or a lesson one run answers).
  referenceRun() { return this.reference; }

  // After a run: the explanation core computed from it (sentences true of this run), the verdict
  // on the prediction (the first run after it, or core's verdict against the run before once the
  // question's change is made), and what to try next with a button that sets it. values: the
  // controls' values the run had.
  explain(e, values = this.current) {
    const def = this.def;
    const parts = [];
    const verdict = (text) => el('p', { id: 'lesson-verdict', className: 'lesson-verdict', textContent: text });
    if (e.verdict) {
      parts.push(verdict(e.verdict.text));
    } else if (typeof this.answer === 'number' && this.before === null) {
      const shows = e.right === null ? ` ${e.verdict_note}` : e.right === this.answer ? ' The run agrees.' : ` The run shows: ${def.answers[e.right]}.`;
      parts.push(verdict(`You predicted: ${def.answers[this.answer]}.${shows}`));
    } else if (e.right === null && e.verdict_note && this.before === null) {
      parts.push(verdict(e.verdict_note));
    }
    parts.push(el('p', { className: 'lesson-explain', textContent: e.sentences.map(([s]) => s).join(' ') }));
    const tryIt = el('button', { type: 'button', id: 'lesson-try', textContent: 'Set it' });
    tryIt.addEventListener('click', () => {
      const values = { ...this.current };
      for (const [p, v] of e.next.set) values[p] = this.def.controls.find((c) => c.path === p).kind === 'toggle' ? v : Number(v);
      this.setValues(values);
      this.onChange(null, null, true);
    });
    parts.push(el('p', { className: 'lesson-next' }, el('strong', { textContent: 'Try this next: ' }), `${e.next.text} `, tryIt));
    if (this.before) parts.push(el('p', { className: 'hint', textContent: 'The faint dashed lines are the run before this one.' }));
    $('lesson-observe').replaceChildren(...parts);
    this.before = true;
    this.reference = e.reading ? { values: { ...values }, reading: e.reading.value, answer: this.answer } : null;
  }
}
