// The scenario form: the study chooser's scenario being edited, its fields, field errors, and the
// edits kept in localStorage so that they survive a reload.
import { FIELDS, ABOUT_EXTRA, ORDERS_HELP, ORDERS_LABEL, STORE_KEY } from './config.js';
import { $, el } from './dom.js';
import { fieldLine } from './protocol.js';

function getPath(obj, path) { return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), obj); }
function setPath(obj, path, value) {
  const keys = path.split('.');
  let o = obj;
  for (const k of keys.slice(0, -1)) o = o[k];
  o[keys[keys.length - 1]] = value;
}
const fieldId = (path) => 'f-' + path.replace(/\./g, '-');

export class ScenarioForm {
  // presets: {name: scenario JSON text}; onLooseErrors(text): errors of no field on the form.
  constructor(presets, { onLooseErrors }) {
    this.presets = presets;
    this.onLooseErrors = onLooseErrors;
    this.name = null;
    this.scenario = null;
    $('preset').replaceChildren(...Object.keys(presets).map((n) => new Option(n, n)));
    this.build();
  }

  preset(name = this.name) { return JSON.parse(this.presets[name]); }
  has(name) { return Object.prototype.hasOwnProperty.call(this.presets, name); }
  // A copy of the scenario being edited.
  current() { return JSON.parse(JSON.stringify(this.scenario)); }

  build() {
    const form = $('form');
    form.replaceChildren();
    for (const [group, fields] of FIELDS) {
      const fs = el('fieldset', {}, el('legend', { textContent: group }));
      for (const [path, label, unit, help, choices] of fields) {
        const id = fieldId(path);
        let input;
        if (choices) {
          input = el('select', {}, ...choices.map((c) => new Option(c, c)));
        } else {
          input = el('input', { type: 'number', step: 'any' });
        }
        input.id = id;
        input.dataset.path = path;
        input.setAttribute('aria-describedby', id + '-help');
        input.addEventListener('change', () => this.onFieldChange(input));
        const h = el('div', { className: 'help', id: id + '-help' }, el('span', { textContent: help }), el('span', { className: 'preset-value' }));
        fs.append(el('div', { className: 'field' },
          el('label', { htmlFor: id, textContent: unit ? `${label} [${unit}]` : label }),
          input, h, el('div', { className: 'ferr', id: id + '-err' })));
      }
      form.append(fs);
    }
    const ta = el('textarea', { id: 'f-commands', rows: 6, attrs: { 'aria-label': ORDERS_LABEL } });
    ta.addEventListener('change', () => {
      try {
        this.scenario.commands = JSON.parse(ta.value);
        this.save();
        this.markErrors([]);
      } catch (e) {
        this.markErrors([{ path: 'commands', value: '', message: 'not valid JSON: ' + e.message }]);
      }
    });
    form.append(el('fieldset', {}, el('legend', { textContent: 'Maneuver (orders)' }), ta, el('div', { className: 'help', textContent: ORDERS_HELP })));
  }

  fill() {
    const preset = this.preset();
    for (const input of $('form').querySelectorAll('[data-path]')) {
      const v = getPath(this.scenario, input.dataset.path);
      input.value = v === undefined ? '' : String(v);
      const p = getPath(preset, input.dataset.path);
      $(input.id + '-help').querySelector('.preset-value').textContent = p === undefined ? '' : ` Study value: ${p}.`;
    }
    $('f-commands').value = JSON.stringify(this.scenario.commands, null, 1);
  }

  onFieldChange(input) {
    const path = input.dataset.path;
    let v = input.value;
    if (input.tagName === 'SELECT') {
      v = v === 'true' ? true : v === 'false' ? false : v;
    } else {
      v = Number(v);
      if (input.value.trim() === '' || !Number.isFinite(v)) {
        this.markErrors([{ path, value: input.value, message: 'must be a number' }]);
        return;
      }
    }
    setPath(this.scenario, path, v);
    this.save();
    this.markErrors([]);
  }

  // Shows each refused field under its input; the others go to onLooseErrors.
  markErrors(fields) {
    for (const e of $('form').querySelectorAll('.ferr')) e.textContent = '';
    const loose = [];
    for (const f of fields) {
      const e = $(fieldId(f.path) + '-err');
      if (e) e.textContent = f.message; else loose.push(fieldLine(f));
    }
    if (loose.length) this.onLooseErrors(loose.join('\n'));
  }

  select(name, scenario) {
    this.name = name;
    $('preset').value = name;
    this.scenario = scenario || this.preset(name);
    $('about').textContent = `${this.preset(name).description} ${ABOUT_EXTRA[name] || ''}`;
    this.fill();
    this.markErrors([]);
  }

  save() {
    try { localStorage.setItem(STORE_KEY, JSON.stringify({ preset: this.name, scenario: this.scenario })); } catch (_) { /* storage full or blocked */ }
  }

  // The edits of the last visit, {preset, scenario}, if any (not yet validated).
  saved() {
    try {
      const s = JSON.parse(localStorage.getItem(STORE_KEY) || 'null');
      return s && this.has(s.preset) && s.scenario ? s : null;
    } catch (_) { return null; }
  }
}
