// The lessons' screen: the index, and one lesson's controls (sliders and toggles made from the
// registry), its question, the explanation of each run and what to try next. The page (main.js)
// runs the study and draws the plots and the live view; this module owns the words and controls.
import { $, el } from '../dom.js';
import { GLOSSARY, LESSONS } from './catalog.js';

export const lessonByName = (name) => LESSONS.find((l) => l.name === name) || null;

// A control's scenario path (a maneuver order's index in place of N).
export const controlPath = (c) => (c.order === undefined ? c.path : c.path.replace('.N.', `.${c.order}.`));
const getPath = (o, path) => path.split('.').reduce((x, k) => (x == null ? undefined : x[k]), o);

// '#lessons', '#lesson=NAME&PATH=VALUE...' (the values the link sets), or null for any other hash.
export function readLessonHash(hash) {
  if (hash === 'lessons') return { index: true };
  if (!hash.startsWith('lesson=')) return null;
  const params = new URLSearchParams(hash);
  const def = lessonByName(params.get('lesson'));
  if (!def) return { index: true, unknown: String(params.get('lesson')).slice(0, 40) };
  const values = {};
  for (const c of def.controls) {
    const p = controlPath(c);
    if (params.has(p)) values[p] = params.get(p);
  }
  return { def, values };
}

const show = (v) => (typeof v === 'number' ? String(Number(v.toPrecision(6))) : String(v));

export class LessonView {
  // meta: the wasm's paramMeta ({params}); onChange(): a control moved (the page reruns); onAnswer():
  // the question was answered (the first run).
  constructor(meta, { onChange, onAnswer }) {
    this.byPath = new Map(meta.params.map((m) => [m.path, m]));
    this.onChange = onChange;
    this.onAnswer = onAnswer;
    this.def = null;
    this.answer = null;
    this.before = null;
  }

  // The index of lessons, in the lesson box.
  showIndex(unknown = null) {
    this.def = null;
    $('lesson-box').replaceChildren(el('h2', { textContent: 'Lessons' }),
      ...(unknown ? [el('p', { className: 'error', textContent: `There is no lesson "${unknown}": pick one below.` })] : []),
      el('p', { className: 'about', textContent: 'Each lesson is one study with two or three controls. Answer its question first, then move the controls: every change reruns at once, and the run before stays drawn faintly beside the new one.' }),
      el('ol', { className: 'lesson-list' }, ...LESSONS.map((l) => el('li', {}, el('a', { href: `#lesson=${l.name}`, textContent: l.title }), el('span', { className: 'hint', textContent: ` ${l.question}` })))),
      el('p', {}, el('a', { href: '#v=2&preset=startup', textContent: 'The full simulator (Lab)' })));
    $('lesson-explain').replaceChildren();
  }

  // The settings that go with a toggle's value (none for a slider).
  also(c, v) { return c.values && c.also ? c.also[c.values.indexOf(v)] || {} : {}; }

  // A control's value from a link's text, checked against its range (else the study's value).
  value(c, text, scenario) {
    const p = controlPath(c);
    const own = getPath(scenario, p);
    if (text === undefined) return own;
    if (c.values) return c.values.map(String).includes(text) ? c.values[c.values.map(String).indexOf(text)] : own;
    const x = Number(text);
    const [lo, hi] = this.range(c);
    return Number.isFinite(x) && x >= lo && x <= hi ? x : own;
  }

  // A slider's span: the lesson's within the declared range.
  range(c) {
    const m = this.byPath.get(c.path);
    const lo = Math.max(m.min ?? -Infinity, c.span ? c.span[0] : -Infinity), hi = Math.min(m.max ?? Infinity, c.span ? c.span[1] : Infinity);
    return [lo, hi];
  }

  // Opens lesson `def` over `scenario` (the study's, with the lesson's settings and the link's
  // values already in it). Returns nothing; the page runs once the question is answered.
  open(def, scenario, labHref) {
    this.def = def;
    this.answer = null;
    this.before = null;
    // The values run, by path (a slider's position snaps to its step; the value is what it says).
    this.current = Object.fromEntries(def.controls.map((c) => [controlPath(c), getPath(scenario, controlPath(c))]));
    const controls = def.controls.map((c) => this.control(c, scenario));
    const answers = el('div', { className: 'lesson-answers', attrs: { role: 'radiogroup', 'aria-labelledby': 'lesson-q' } },
      ...def.answers.map((a, i) => {
        const id = `lesson-a${i}`;
        const r = el('input', { type: 'radio', name: 'lesson-answer', id, value: String(i) });
        r.addEventListener('change', () => this.answered(i));
        return el('label', { htmlFor: id, className: 'lesson-answer' }, r, ` ${a}`);
      }));
    const skip = el('button', { type: 'button', id: 'lesson-skip', textContent: 'Just run it' });
    skip.addEventListener('click', () => this.answered(null));
    $('lesson-box').replaceChildren(
      el('p', { className: 'lesson-nav' }, el('a', { href: '#lessons', textContent: 'All lessons' }), ' · ', el('a', { href: labHref, id: 'lesson-lab', textContent: 'Open in the full simulator (Lab)' })),
      el('h2', { id: 'lesson-title', textContent: def.title }),
      el('div', { id: 'lesson-controls', className: 'lesson-controls' }, ...controls),
      el('div', { id: 'lesson-predict', className: 'lesson-predict' }, el('p', { id: 'lesson-q', className: 'lesson-q', textContent: `Predict: ${def.question}` }), answers, skip));
    $('lesson-explain').replaceChildren(
      el('div', { id: 'lesson-observe', attrs: { 'aria-live': 'polite' } }),
      el('details', { className: 'lesson-words' }, el('summary', { textContent: 'Words used here' }),
        el('dl', {}, ...GLOSSARY.flatMap(([k, v]) => [el('dt', { textContent: k }), el('dd', { textContent: v })]))));
    this.setDisabled(true);
  }

  // A slider (with its value and unit beside it) or a toggle, from the registry's declaration.
  control(c, scenario) {
    const p = controlPath(c);
    const m = this.byPath.get(c.path);
    const id = `lesson-${p.replace(/\./g, '-')}`;
    const unit = m.unit && m.unit !== '-' ? ` ${m.unit}` : '';
    const v = getPath(scenario, p);
    if (c.values) {
      const sel = el('select', { id }, ...c.values.map((x, i) => new Option(c.labels[i], String(x))));
      sel.value = String(v);
      sel.dataset.path = p;
      sel.addEventListener('change', () => { this.current[p] = c.values[sel.selectedIndex]; this.onChange(p, this.current[p], c.also ? c.also[sel.selectedIndex] : {}); });
      return el('div', { className: 'lesson-control' }, el('label', { htmlFor: id, textContent: m.label }), sel);
    }
    const [lo, hi] = this.range(c);
    // A slider in decades moves log10 of the value; the value is rounded to 3 digits.
    const to = c.log ? (x) => Math.log10(x) : (x) => x;
    const from = c.log ? (x) => Number((10 ** x).toPrecision(3)) : (x) => x;
    const out = el('output', { id: `${id}-out`, htmlFor: id, textContent: `${show(v)}${unit}` });
    const input = el('input', { type: 'range', id, min: String(to(lo)), max: String(to(hi)), step: String(c.step), value: String(to(v)), attrs: { 'aria-valuetext': `${show(v)}${unit}` } });
    input.dataset.path = p;
    input.title = m.help;
    input.addEventListener('input', () => { out.textContent = `${show(from(Number(input.value)))}${unit}`; input.setAttribute('aria-valuetext', out.textContent); });
    input.addEventListener('change', () => { this.current[p] = from(Number(input.value)); this.onChange(p, this.current[p]); });
    return el('div', { className: 'lesson-control' }, el('label', { htmlFor: id, textContent: `${m.label}${unit ? ` [${unit.trim()}]` : ''}` }), input, out);
  }

  // The controls wait for the prediction (then the first run).
  setDisabled(on) {
    for (const i of $('lesson-controls').querySelectorAll('input, select')) i.disabled = on;
  }

  answered(i) {
    if (this.answer !== null || !this.def) return;
    this.answer = i;
    for (const r of document.querySelectorAll('#lesson-predict input, #lesson-skip')) r.disabled = true;
    this.setDisabled(false);
    this.onAnswer();
  }

  // The controls' values now, by scenario path.
  values() { return { ...this.current }; }

  // The lesson's address: its name and the values that differ from the study's.
  hash(scenario0) {
    const params = new URLSearchParams({ lesson: this.def.name });
    for (const [p, v] of Object.entries(this.values())) if (String(getPath(scenario0, p)) !== String(v)) params.set(p, String(v));
    return `#${params.toString()}`;
  }

  // After a run: what it showed, in its own numbers, then what to try next.
  explain(s, markers) {
    const def = this.def;
    const values = this.values();
    const parts = [];
    if (this.answer !== null && this.before === null) {
      const right = def.right ? def.right({ s, markers, values }) : null;
      parts.push(el('p', { className: 'lesson-verdict', textContent: `You predicted: ${def.answers[this.answer]}.${right === null ? '' : right === this.answer ? ' The run agrees.' : ` The run shows: ${def.answers[right]}.`}` }));
    }
    parts.push(el('p', { className: 'lesson-explain', textContent: def.explain({ s, markers, values, before: this.before }) }),
      el('p', { className: 'lesson-next' }, el('strong', { textContent: 'Try this next: ' }), def.next));
    if (this.before) parts.push(el('p', { className: 'hint', textContent: 'The faint dashed lines are the run before this one.' }));
    $('lesson-observe').replaceChildren(...parts);
    this.before = { s, markers: markers.length };
  }
}
