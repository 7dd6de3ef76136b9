// The scenario form: the study picker, the scenario being edited, its fields (the ones that matter
// for the study on top, the rest folded below), errors at the field, the fields a link changed,
// and the edits kept in localStorage so that they survive a reload.
import { FORM_PLACES, CHAPTERS, STUDIES, studyTitle, STORE_KEY } from './config.js';
import { $, el } from './dom.js';
import { migrate } from './registry.js';
import { fieldLine } from './protocol.js';
import { diff } from './link.js';
import { fieldUnit, fromShown } from './units.js';

function getPath(obj, path) { return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), obj); }
export function setPath(obj, path, value) {
  const keys = path.split('.');
  let o = obj;
  for (const k of keys.slice(0, -1)) o = o[k];
  o[keys[keys.length - 1]] = value;
}
export function deletePath(obj, path) {
  const keys = path.split('.');
  const o = getPath(obj, keys.slice(0, -1).join('.'));
  if (o && typeof o === 'object') delete o[keys[keys.length - 1]];
}
// A value as the form shows it: numbers to 12 significant digits (6.15 - 3.5 shows as 2.65).
const show = (v) => (typeof v === 'number' ? String(Number(v.toPrecision(12))) : String(v));
const fieldId = (path) => 'f-' + path.replace(/\./g, '-');

// Dotted paths of the leaves of a link's difference object.
export function leafPaths(d, prefix = '') {
  if (!d || typeof d !== 'object' || Array.isArray(d)) return [prefix];
  return Object.keys(d).flatMap((k) => leafPaths(d[k], prefix ? `${prefix}.${k}` : k));
}

// The unit a field shows (power in MW, energy in MJ) and the factor from SI to it.
const shownUnit = (m) => (m.unit && m.unit !== '-' ? fieldUnit(m.unit) : { unit: '', factor: 1 });
const shownValue = (m, v) => (typeof v === 'number' && m ? v * shownUnit(m).factor : v);

// A field's help line: what it does, what is allowed and where its default comes from.
function helpText(m) {
  const { unit: u } = shownUnit(m), unit = u ? ` ${u}` : '';
  const range = m.min != null && m.max != null ? ` From ${show(shownValue(m, m.min))} to ${show(shownValue(m, m.max))}${unit}.` : '';
  const empty = m.empty ? (m.empty_is === 'null' ? ` Empty: ${m.empty}.` : ` 0: ${m.empty}.`) : '';
  const source = m.source ? ` Source: ${m.source}.` : '';
  return `${m.help}${range}${empty}${source}`;
}

export class ScenarioForm {
  // presets: {name: scenario JSON text}; meta: the wasm's paramMeta() ({groups, params}), of which
  // the form shows the parameters with a group; onLooseErrors(text): errors of no field on the
  // form; onEdit(): after every accepted edit (the page validates and follows it in the address).
  constructor(presets, meta, { onLooseErrors, onEdit = () => {}, onValidity = () => {}, onSelect = () => {} }) {
    this.onSelect = onSelect;
    this.meta = meta;
    this.byPath = new Map(meta.params.map((m) => [m.path, m]));
    this.presets = presets;
    this.onLooseErrors = onLooseErrors;
    this.onEdit = onEdit;
    this.onValidity = onValidity;
    this.name = null;
    this.scenario = null;
    this.invalid = new Set();
    this.edits = new Map(); // study -> its edited scenario, kept while the page is open (and stored)
    this.home = new Map(); // field div -> its fieldset in the full form
    const listed = new Set(CHAPTERS.flatMap(([, names]) => names));
    const groups = CHAPTERS.map(([chapter, names]) => el('optgroup', { label: chapter },
      ...names.filter((n) => this.has(n)).map((n) => new Option(studyTitle(n), n))));
    const others = Object.keys(presets).filter((n) => !listed.has(n));
    if (others.length) groups.push(el('optgroup', { label: 'Other studies' }, ...others.map((n) => new Option(n, n))));
    $('preset').replaceChildren(...groups);
    this.build();
  }

  preset(name = this.name) { return JSON.parse(this.presets[name]); }
  has(name) { return Object.prototype.hasOwnProperty.call(this.presets, name); }
  // A copy of the scenario being edited.
  current() { return JSON.parse(JSON.stringify(this.scenario)); }
  // A run's name for legends: the study, and what differs from it.
  runName(sc) {
    const paths = this.modified(sc);
    const value = (p) => { const v = p.split('.').reduce((o, k) => o[k], sc); return typeof v === 'string' && v.length > 40 ? `(${v.split('\n').length} lines)` : JSON.stringify(v); };
    const what = paths.slice(0, 2).map((p) => `${p.split('.').pop()} = ${value(p)}`).join(', ');
    return `${studyTitle(this.name)}${what ? `, ${what}${paths.length > 2 ? ', ...' : ''}` : ''}`;
  }

  build() {
    const form = $('form');
    form.replaceChildren();
    for (const [group, title] of this.meta.groups) {
      const fs = el('fieldset', {}, el('legend', { textContent: title }));
      for (const m of this.meta.params.filter((p) => p.group === group)) {
        const id = fieldId(m.path);
        let input;
        if (m.kind === 'choice') {
          input = el('select', {}, ...m.choices.map((c) => new Option(c.label, c.value)));
        } else if (m.kind === 'switch') {
          input = el('select', {}, new Option('no', 'false'), new Option('yes', 'true'));
        } else {
          input = el('input', { type: 'text', inputMode: m.kind === 'integer' ? 'numeric' : 'decimal', autocomplete: 'off' });
        }
        input.id = id;
        input.dataset.path = m.path;
        if (m.empty_is === 'null') input.dataset.optional = 'true';
        input.setAttribute('aria-describedby', `${id}-help ${id}-err`);
        input.addEventListener('change', () => this.onFieldChange(input));
        input.addEventListener('input', () => { if (input.tagName === 'INPUT') this.checkNumber(input); });
        const derived = FORM_PLACES.derived[m.path];
        const h = el('div', { className: 'help', id: id + '-help' }, el('span', { textContent: helpText(m) }), el('span', { className: 'preset-value' }),
          ...(derived ? [el('output', { className: 'derived', id: `${id}-derived`, htmlFor: id })] : []));
        const { unit } = shownUnit(m);
        const div = el('div', { className: 'field', id: id + '-field' },
          el('label', { htmlFor: id, textContent: unit ? `${m.label} [${unit}]` : m.label }),
          input, h, el('div', { className: 'ferr', id: id + '-err' }));
        fs.append(div);
        this.home.set(div, fs);
      }
      const into = FORM_PLACES.into[group];
      if (into) $(into).replaceChildren(fs); else form.append(fs);
    }
    const order = (f) => this.byPath.get(`commands.N.${f}`);
    const ordersLabel = 'Orders as JSON: ' + ['t_s', 'speed_kn', 'heading_deg', 'heading_rate_deg_s']
      .map((f) => `${order(f).label.toLowerCase()} ${f} [${order(f).unit}]`).join(', ');
    const ta = el('textarea', { id: 'f-commands', rows: 6, attrs: { 'aria-label': ordersLabel, 'aria-describedby': 'f-commands-err' } });
    ta.addEventListener('change', () => {
      try {
        this.scenario.commands = JSON.parse(ta.value);
        this.setError('commands', '');
        this.save();
        this.onEdit();
      } catch (e) {
        this.setError('commands', 'not valid JSON: ' + e.message);
      }
    });
    form.append(el('fieldset', {}, el('legend', { textContent: 'Maneuver (orders)' }), ta, el('div', { className: 'ferr', id: 'f-commands-err' }), el('div', { className: 'help', textContent: `${ordersLabel}. Each order keeps its fields until another gives them; e.g. [{"t_s": 0, "speed_kn": 25}, {"t_s": 10, "heading_deg": 90, "heading_rate_deg_s": 0.5}].` })));
  }

  // The study's parameters that matter go on top; the others back into the full form.
  arrange() {
    for (const [div, fs] of this.home) if (div.parentElement !== fs) fs.append(div);
    const params = (STUDIES[this.name] && STUDIES[this.name].params) || [];
    $('key-fields').replaceChildren(...params.map((p) => $(fieldId(p) + '-field')).filter(Boolean));
    // Keep the full form's order inside each fieldset.
    for (const fs of new Set(this.home.values())) {
      const order = [...this.home.keys()].filter((d) => this.home.get(d) === fs && d.parentElement === fs);
      fs.append(...order);
    }
  }

  fill() {
    const preset = this.preset();
    for (const input of $('controls').querySelectorAll('[data-path]')) {
      const m = this.byPath.get(input.dataset.path);
      const v = getPath(this.scenario, input.dataset.path);
      input.value = v == null ? '' : show(shownValue(m, v));
      const p = getPath(preset, input.dataset.path);
      const opt = input.tagName === 'SELECT' ? [...input.options].find((o) => o.value === String(p)) : null;
      $(input.id + '-help').querySelector('.preset-value').textContent = p == null ? '' : ` Study value: ${opt ? opt.text : show(shownValue(m, p))}.`;
    }
    $('f-commands').value = JSON.stringify(this.scenario.commands, null, 1);
  }

  input(path) { return $(fieldId(path)); }

  // The hull's own values (from hullSheet) as placeholders of the empty optional fields, and the
  // derived line of a field (e.g. h0 under the hub height). values: {path: text}.
  showHullValues(placeholders, derived) {
    for (const [path, text] of Object.entries(placeholders)) { const i = this.input(path); if (i) i.placeholder = text; }
    for (const [path, text] of Object.entries(derived)) { const o = $(fieldId(path) + '-derived'); if (o) o.textContent = text; }
  }

  // A number field that does not hold a number is marked at once (Run waits for it).
  // An optional field may be empty (the hull's own value).
  checkNumber(input) {
    const m = this.byPath.get(input.dataset.path);
    const v = Number(input.value);
    const empty = input.value.trim() === '';
    const whole = m.kind === 'integer';
    const bad = empty ? !input.dataset.optional : !Number.isFinite(v) || (whole && !Number.isInteger(v));
    this.setError(input.dataset.path, bad ? `${m.label} must be ${whole ? 'a whole number' : 'a number'}${input.dataset.optional ? ' (or empty for ' + m.empty + ')' : ''}` : '');
    return !bad;
  }

  onFieldChange(input) {
    if (this.dropping) return;
    const path = input.dataset.path;
    let v = input.value;
    if (input.tagName === 'SELECT') {
      v = v === 'true' ? true : v === 'false' ? false : v;
    } else {
      if (!this.checkNumber(input)) return;
      v = v.trim() === '' ? undefined : fromShown(Number(v), shownUnit(this.byPath.get(path)).factor);
    }
    // An emptied optional field: null where the study sets a value (a link carries the change),
    // else no key at all.
    if (v === undefined && getPath(this.preset(), path) != null) setPath(this.scenario, path, null);
    else if (v === undefined) deletePath(this.scenario, path);
    else setPath(this.scenario, path, v);
    this.setError(path, '');
    const note = $(fieldId(path) + '-field').querySelector('.link-refused');
    if (note) note.remove(); // the link's refused value is no longer what the field is about
    this.save();
    this.onEdit();
  }

  // Sets or clears (message '') the error of one field: shown under it, aria-invalid on it.
  setError(path, message) {
    const input = path === 'commands' ? $('f-commands') : this.input(path);
    const e = $((path === 'commands' ? 'f-commands' : fieldId(path)) + '-err');
    if (!input || !e) return false;
    e.textContent = message;
    if (message) { input.setAttribute('aria-invalid', 'true'); this.invalid.add(path); } else { input.removeAttribute('aria-invalid'); this.invalid.delete(path); }
    this.onValidity(this.invalid.size === 0);
    return true;
  }

  // Shows each refused field under its input (all others cleared); the rest go to onLooseErrors.
  markErrors(fields) {
    for (const p of [...this.invalid]) this.setError(p, '');
    const loose = [];
    for (const f of fields) if (!this.setError(f.path, f.message)) loose.push(fieldLine(f));
    if (loose.length) this.onLooseErrors(loose.join('\n'));
    this.onValidity(this.invalid.size === 0);
  }

  // Marks the fields a link changed from the study's values, and says at each field whose value
  // the link could not use (`refused`: the checks' fields) why and what stands in its place.
  markLinked(paths, refused = []) {
    for (const d of document.querySelectorAll('.field.linked')) d.classList.remove('linked');
    for (const p of paths) { const d = $(fieldId(p) + '-field'); if (d) d.classList.add('linked'); }
    for (const e of document.querySelectorAll('.link-refused')) e.remove();
    for (const f of refused) {
      const d = $(fieldId(f.path) + '-field');
      if (d) d.append(el('div', { className: 'ferr link-refused', attrs: { role: 'note' }, textContent: this.refusedLine(f) }));
    }
  }

  // A link's value the checks refused, for people: the field's label, the value (shortened), what
  // is allowed and the study's value used instead.
  refusedLine(f, name = this.name) {
    const m = this.byPath.get(f.path);
    const label = m ? `${m.label}${m.unit && m.unit !== '-' ? ` [${m.unit}]` : ''} (${f.path})` : f.path;
    const value = String(f.value == null ? '' : f.value);
    const own = getPath(this.preset(name), f.path);
    const unit = m && m.unit && m.unit !== '-' ? ` ${m.unit}` : '';
    const used = own == null ? 'its default' : `the study's value, ${show(own)}${unit},`;
    return `The link's ${label} = ${value.length > 24 ? `${value.slice(0, 24)}...` : value} was refused (${f.message}); ${used} is used.`;
  }

  // `scenario` of study `name` with each refused field back at the study's value (or left out where
  // the study sets none): the rest of a link is kept when one of its values is bad. Null when a
  // refused field is not a place the study's values can fill.
  withoutRefused(name, scenario, fields) {
    const out = JSON.parse(JSON.stringify(scenario));
    const preset = this.preset(name);
    for (const f of fields) {
      const keys = String(f.path || '').split('.');
      const parent = keys.length > 1 ? getPath(out, keys.slice(0, -1).join('.')) : out;
      if (!f.path || keys.some((k) => k === '' || k === '__proto__') || parent == null || typeof parent !== 'object') return null;
      const own = getPath(preset, f.path);
      if (own === undefined) deletePath(out, f.path); else setPath(out, f.path, JSON.parse(JSON.stringify(own)));
    }
    return out;
  }

  select(name, scenario) {
    // A field still being typed in is committed to the study it was typed for: moving it (below)
    // would blur it and its change would land in the new study.
    const active = document.activeElement;
    if (active && active.dataset && active.dataset.path && $('controls').contains(active)) active.blur();
    this.name = name;
    $('preset').value = name;
    this.scenario = scenario || (this.edits.has(name) ? JSON.parse(JSON.stringify(this.edits.get(name))) : this.preset(name));
    const study = STUDIES[name] || {};
    $('about').textContent = study.about || this.preset(name).description;
    $('watch').replaceChildren(...(study.watch ? [el('strong', { textContent: 'What to watch' }), study.watch] : []),
      ...(study.note ? [el('p', { textContent: study.note })] : []));
    this.arrange();
    this.fill();
    this.markErrors([]);
    this.markLinked([]);
    this.showModified();
    this.onSelect(name);
  }

  // Back to the study's own values: its kept edits go, every error goes with them, and so does a
  // value still being typed (it is dropped, not committed).
  reset() {
    const active = document.activeElement;
    if (active && active.dataset && active.dataset.path && $('controls').contains(active)) {
      this.dropping = true;
      active.blur();
      this.dropping = false;
    }
    this.edits.delete(this.name);
    this.select(this.name, this.preset(this.name));
    this.save();
  }

  // The paths where the scenario (or sc) differs from its study's (or name's) values.
  modified(sc = this.scenario, name = this.name) {
    const d = diff(this.preset(name), sc);
    return d === undefined ? [] : leafPaths(d);
  }

  // A visible mark of what differs from the study: beside the picker (with Reset at hand), on
  // each changed field, and in the picker for every study edited in this visit.
  showModified() {
    const paths = this.modified();
    const box = $('modified');
    box.hidden = paths.length === 0;
    box.textContent = paths.length ? `Modified: ${paths.length} value${paths.length > 1 ? 's' : ''} differ${paths.length > 1 ? '' : 's'} from the study's (marked "changed"). Reset brings the study's values back.` : '';
    for (const d of document.querySelectorAll('.field.edited')) d.classList.remove('edited');
    for (const p of paths) { const d = $(fieldId(p) + '-field'); if (d) d.classList.add('edited'); }
    for (const o of $('preset').options) {
      const title = o.dataset.title || (o.dataset.title = o.text);
      o.text = this.edits.has(o.value) ? `${title} (modified)` : title;
    }
  }

  save() {
    if (this.modified().length) this.edits.set(this.name, JSON.parse(JSON.stringify(this.scenario))); else this.edits.delete(this.name);
    this.showModified();
    try {
      localStorage.setItem(STORE_KEY, JSON.stringify({ preset: this.name, scenario: this.scenario, edits: Object.fromEntries(this.edits) }));
    } catch (_) { /* storage full or blocked */ }
  }

  // The edits of the last visit, {preset, scenario}, if any (not yet validated); the other
  // studies' edits of that visit are kept again (each is checked when its study is opened).
  saved() {
    try {
      const s = JSON.parse(localStorage.getItem(STORE_KEY) || 'null');
      if (s && s.edits && typeof s.edits === 'object') {
        for (const [name, sc] of Object.entries(s.edits)) if (this.has(name) && sc && typeof sc === 'object') this.edits.set(name, migrate(sc));
      }
      return s && this.has(s.preset) && s.scenario ? { ...s, scenario: migrate(s.scenario) } : null;
    } catch (_) { return null; }
  }
}
