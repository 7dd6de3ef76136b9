// The propeller (issue 54): the panel beside the hull's, with its picker. The blades of the study
// (the ship's B-series equivalent, DTMB 4119, or a CSV blade table read by the core), their expanded
// outline and pitch, and KT, 10KQ and the efficiency over J from the vortex lattice, with the B-series
// polynomial of the same Z, P/D and Ae/A0 faint beside them. Picking blades sets
// propeller.model = "geometry" and propeller.geometry in the form's scenario, so the run, the
// address and a downloaded scenario use them. Every number comes from the wasm (propellerCurves,
// propellerGeometryCsv, validateScenario); this module only moves text and draws.
import { choiceLabel } from './registry.js';
import { $, el } from './dom.js';
import { REQUEST, fieldLine } from './protocol.js';
import { announce } from './state.js';
import { PlotBox } from './plots.js';
import { PROPELLER } from './config.js';
import { num } from './hulldraw.js';
import { drawOutline } from './propellerdraw.js';

const clone = (x) => JSON.parse(JSON.stringify(x));
// The named blades in the heading when the study's own model runs.
const SHORT = { b_series: 'its B-series equivalent', dtmb4119: 'DTMB 4119' };
const NAMED = { b_series: 'the ship\'s B-series equivalent (its Z, P/D, Ae/A0)', dtmb4119: 'DTMB 4119 (3 blades, scaled to the ship\'s diameter)' };
// The picker's value of a scenario: its named geometry, "custom", or "model" (no blades: the
// study's own propeller model runs).
const pickOf = (sc) => (sc.propeller.model === 'geometry' && sc.propeller.geometry ? sc.propeller.geometry.name : 'model');
// Four digits after the point, as `aes-sim propeller --markdown` prints KT and 10KQ.
const d4 = (x) => (Number.isFinite(x) ? x.toFixed(4) : '–');

export class PropellerPanel {
  // client: () => the worker client.
  constructor(root, client) {
    this.root = root;
    this.client = client;
    this.key = null;
    this.sheet = null;
    this.custom = null; // the last blade table read: {spec: its propeller.geometry, file}
    this.drawn = null; // what is drawn (a test reads it)
    this.deps = null; // set by attach(): the form and its commit
    announce('propellerPanel', this);
    this.heading = el('h2', { id: 'propeller-h', textContent: 'The propeller' });
    this.select = el('select', { id: 'propeller-geometry' });
    this.file = el('input', { type: 'file', id: 'propeller-csv', accept: '.csv,.txt,text/csv,text/plain', attrs: { 'aria-describedby': 'propeller-csv-help propeller-csv-err' } });
    this.blades = el('input', { type: 'number', id: 'propeller-blades', min: 2, max: 7, step: 1, value: 3, attrs: { 'aria-describedby': 'propeller-csv-help propeller-csv-err' } });
    this.hub = el('input', { type: 'number', id: 'propeller-hub', min: 0.05, max: 0.5, step: 0.01, value: 0.2, attrs: { 'aria-describedby': 'propeller-csv-help propeller-csv-err' } });
    this.error = el('div', { className: 'ferr', id: 'propeller-csv-err', attrs: { 'aria-live': 'polite' } });
    this.note = el('p', { className: 'hint', id: 'propeller-note' });
    // What the last run drawn said of its blades (the summary's propeller note).
    this.ran = el('p', { className: 'hint', id: 'propeller-run', hidden: true });
    this.plotsBox = el('div', { id: 'propeller-plots' });
    this.table = el('table', { id: 'propeller-table' });
    root.setAttribute('aria-labelledby', 'propeller-h');
    this.fold = el('details', { id: 'propeller-fold', open: true }, el('summary', {}, this.heading));
    this.fold.addEventListener('toggle', () => { if (this.fold.open && this.sheet) this.draw(); });
    root.replaceChildren(this.fold);
    this.fold.append(
      el('div', { id: 'propeller-pick', attrs: { role: 'group', 'aria-labelledby': 'propeller-pick-label' } },
        el('div', { className: 'row' }, el('label', { htmlFor: 'propeller-geometry', id: 'propeller-pick-label', textContent: 'Propeller blades' }), this.select),
        el('div', { className: 'field file' },
          el('label', { htmlFor: 'propeller-csv', textContent: 'Upload a blade table (CSV)' }), this.file,
          el('div', { className: 'row propeller-table-args' },
            el('label', { htmlFor: 'propeller-blades', textContent: 'Blades Z' }), this.blades,
            el('label', { htmlFor: 'propeller-hub', textContent: 'Hub ratio, hub diameter / D' }), this.hub),
          el('div', { className: 'help', id: 'propeller-csv-help', innerHTML: 'Header <code>r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D</code> (as <code>aes-sim propeller</code> reads it), rows root to tip, the last at r/R = 1; the propeller\'s diameter is the study\'s. A table that is refused changes nothing.' }),
          this.error)),
      this.note, this.ran, this.plotsBox,
      el('details', { id: 'propeller-points' }, el('summary', { textContent: 'Open-water points: KT, 10KQ and efficiency at each J (table)' }),
        el('div', { className: 'scroll', tabIndex: 0, attrs: { role: 'region', 'aria-label': 'Open-water points' } }, this.table)));
    this.plots = new PlotBox(this.plotsBox);
    this.select.addEventListener('change', () => this.pick(this.select.value));
    this.file.addEventListener('change', () => { if (this.file.files[0]) this.loadFile(this.file.files[0]); });
    for (const f of [this.blades, this.hub]) f.addEventListener('change', () => this.reread());
  }

  // The form and its commit (after the simulator loaded): validate(sc) resolves or throws {fields};
  // commit(sc) puts an accepted scenario in the form; say(text, isError): the status line.
  attach(deps) { this.deps = deps; }

  // The picker follows the scenario; "custom" is offered once a table is known.
  sync(sc) {
    const g = sc.propeller.geometry;
    if (sc.propeller.model === 'geometry' && g && g.name === 'custom') {
      const same = this.custom && JSON.stringify(this.custom.spec) === JSON.stringify(g);
      this.custom = same ? this.custom : { spec: clone(g), file: 'from the address or the scenario', text: null };
      // The fields beside the file say the table's own blades and hub ratio.
      this.blades.value = g.blades;
      this.hub.value = g.hub_ratio == null ? '' : g.hub_ratio;
    }
    const own = sc.propeller.model === 'geometry' ? 'b_series' : sc.propeller.model;
    const opts = [
      ['model', `${choiceLabel('propeller.model', own)}: the study's model, no blades`],
      ['b_series', NAMED.b_series], ['dtmb4119', NAMED.dtmb4119],
      ['custom', this.custom ? `your blade table: ${this.custom.file}` : 'your blade table (upload a CSV below)'],
    ];
    this.select.replaceChildren(...opts.map(([v, t]) => new Option(t, v)));
    this.select.querySelector('option[value="custom"]').disabled = !this.custom;
    this.select.value = pickOf(sc);
  }

  fileError(message) {
    this.error.textContent = message;
    for (const f of [this.file, this.blades, this.hub]) if (message) f.setAttribute('aria-invalid', 'true'); else f.removeAttribute('aria-invalid');
  }

  // Blades by name, the last table read, or none (the study's own model: the geometry is dropped).
  async pick(value) {
    const { form, busy } = this.deps;
    if (busy()) { this.deps.say('Wait for the run to finish, or cancel it, before changing the propeller.', true); this.sync(form.scenario); return; }
    const sc = form.current();
    if (value === 'model') {
      const own = form.preset().propeller.model;
      sc.propeller.model = own === 'geometry' ? 'b_series' : own;
      delete sc.propeller.geometry;
    } else if (value === 'custom') {
      if (!this.custom) { this.sync(form.scenario); this.file.focus(); return; }
      Object.assign(sc.propeller, { model: 'geometry', geometry: clone(this.custom.spec) });
    } else {
      Object.assign(sc.propeller, { model: 'geometry', geometry: { name: value } });
    }
    this.fileError('');
    await this.accept(sc, value === 'model' ? `Propeller: ${choiceLabel('propeller.model', sc.propeller.model)} (no blades).` : `Propeller: ${value === 'custom' ? `your blade table (${this.custom.file})` : NAMED[value]}; the run uses its blades.`);
  }

  // A scenario with new blades: checked, then into the form; refused, the form keeps its own.
  async accept(sc, said, file = null) {
    const { form, validate, commit, say } = this.deps;
    try { await validate(sc); } catch (e) {
      if (e.cancelled) return false;
      const fields = e.fields && e.fields.length ? e.fields : [{ path: '(scenario)', value: '', message: e.message }];
      const own = fields.filter((f) => f.path.startsWith('propeller.'));
      this.fileError(`${file ? `${file}: ` : ''}${(own.length ? own : fields).slice(0, 2).map(fieldLine).join('; ')}`);
      this.sync(form.scenario);
      say('The propeller was not changed (the reason is under the blade table field).', true);
      return false;
    }
    commit(sc);
    this.sync(sc);
    say(said);
    return true;
  }

  // A CSV blade table: read by the core with the blades and hub ratio beside it.
  async loadFile(file) {
    const { busy, say } = this.deps;
    if (busy()) { say('Wait for the run to finish, or cancel it, before loading a file.', true); return; }
    if (file.size > PROPELLER.maxFileBytes) { this.fileError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MiB: a blade table is a few kB`); return; }
    let text;
    try { text = await file.text(); } catch (e) { this.fileError(`${file.name} could not be read: ${e.message}`); return; }
    await this.readTable(text, file.name);
  }

  // A blade table's text (from file `name`) with the blades and hub ratio of the fields beside it.
  async readTable(text, name) {
    const { say } = this.deps;
    const field = (input) => Number(input.value === '' ? NaN : input.value);
    let geometry;
    try {
      ({ geometry } = await this.client().request(REQUEST.propellerCsv, { text, blades: field(this.blades), hub_ratio: field(this.hub) }));
    } catch (e) {
      if (e.cancelled) return;
      this.fileError(`${name}: ${e.message}`);
      this.sync(this.deps.form.scenario);
      say('The blade table was not used: the propeller stays as it was (the reason is under the file field).', true);
      this.file.focus();
      return;
    }
    const sc = this.deps.form.current();
    Object.assign(sc.propeller, { model: 'geometry', geometry });
    const before = this.custom;
    this.custom = { spec: clone(geometry), file: name, text };
    if (!(await this.accept(sc, `Blade table ${name} read: the run uses its ${geometry.blades} blades, hub ${geometry.hub_ratio} D.`, name))) this.custom = before;
    else this.fileError('');
  }

  // The blades or hub ratio changed while a table of one's own runs: the table read again with them.
  reread() {
    if (this.deps && !this.deps.busy() && this.custom && this.custom.text && this.select.value === 'custom') this.readTable(this.custom.text, this.custom.file);
  }

  // A run was drawn: what its summary says of the blades it ran on (nothing on another model).
  ranWith(summary) {
    const p = summary && summary.propeller;
    this.ran.hidden = !p;
    this.ran.textContent = p ? `The run shown above: ${p.note}.` : '';
  }

  // The panel of the scenario's propeller (asked again only when what it depends on changed).
  async update(sc) {
    const key = JSON.stringify([sc.propeller, sc.plant.motor]);
    if (key === this.key) return this.sheet;
    this.key = key;
    const t0 = performance.now();
    let sheet, wall;
    try {
      ({ sheet, wall_ms: wall } = await this.client().request(REQUEST.propeller, { scenario: JSON.stringify(sc) }));
    } catch (e) {
      if (key !== this.key) return null;
      this.key = null;
      if (e.cancelled) return null;
      this.note.textContent = `The propeller cannot be drawn (${e.fields && e.fields.length ? e.fields.slice(0, 2).map(fieldLine).join('; ') : e.message}); ${this.sheet ? 'showing the last valid one' : 'nothing to draw yet'}.`;
      this.note.classList.add('error');
      return null;
    }
    if (key !== this.key) return null;
    this.sheet = sheet;
    this.note.classList.remove('error');
    this.draw();
    // From the request to the curves on the page, and the worker's share of it [ms].
    this.timing = { request_to_drawn_ms: performance.now() - t0, worker_ms: wall };
    if (this.drawn) this.drawn.timing = this.timing;
    return sheet;
  }

  draw() {
    const s = this.sheet;
    if (!s || this.root.hidden || !this.fold.open) return;
    const name = s.name === 'custom' ? `your blade table${this.custom ? ` (${this.custom.file})` : ''}` : NAMED[s.name] || s.name;
    // Not run: the study's own model runs; the blades drawn are what picking them would run.
    const model = choiceLabel('propeller.model', this.deps ? this.deps.form.scenario.propeller.model : 'b_series');
    this.heading.textContent = s.runs_it ? `The propeller: ${name}` : `The propeller: ${model}, the study's model; blades drawn: ${SHORT[s.name] || name}`;
    const e = s.series;
    const rpm = s.flow.rev_per_s * 60;
    this.note.textContent = `${s.blades} blades, P/D at 0.7 R ${num(s.pitch_07)}, Ae/A0 ${num(s.area_ratio)} (from the chords), hub ${num(s.hub_ratio)} D, at the study's diameter D = ${num(s.flow.diameter_m)} m. `
      + `KT and KQ from a vortex lattice on the blades (thesis ch. 3.2) in sea water at ${num(rpm)} rpm, the flow the run's table is built in. `
      + (s.runs_it ? 'The run uses these curves (propeller.model = geometry; astern and past zero thrust the four-quadrant series, scaled to them). '
        : 'The run uses the study\'s own model; pick blades above to run them. ')
      + `Faint and dashed: the B-series polynomial of ${e.blades} blades, P/D ${num(e.pitch_ratio)}, Ae/A0 ${num(e.area_ratio)}${e.held ? ' (held at the edge of the series\' range)' : ''}.`;
    this.plots.clear();
    let outline = null;
    const xs = s.rows.map((r) => r.r_r);
    this.plots.canvas('Expanded blade outline, to scale', `Expanded outline of one blade: ${s.rows.length} rows from r/R ${num(xs[0])} to 1, largest chord ${num(Math.max(...s.rows.map((r) => r.c_d)))} D. The rows are in the table of pitch below.`,
      (cv) => { outline = drawOutline(cv, s); if (this.drawn) this.drawn.outline = outline; });
    this.plots.line('Pitch distribution P/D', { data: xs, label: 'radius r/R [-]' },
      [{ data: s.rows.map((r) => r.p_d), label: 'local pitch P/D', color: PROPELLER.colors.pitch, width: 2 },
        { data: s.rows.map((r) => r.c_d), label: 'chord c/D', color: PROPELLER.colors.section, dash: [2, 3] }],
      [{ scale: 'y', label: 'P/D, c/D [-]' }]);
    const js = s.open_water.map((p) => p.j);
    const series = s.series.rows;
    const positive = (rows, f) => rows.map((p) => (p.kt > 0 ? f(p) : null));
    this.plots.line('Open water: KT, 10KQ and efficiency over J', { data: js, label: 'advance ratio J [-]' }, [
      { data: s.open_water.map((p) => p.kt), label: 'KT, these blades', color: PROPELLER.colors.kt, width: 2.4 },
      { data: s.open_water.map((p) => 10 * p.kq), label: '10KQ, these blades', color: PROPELLER.colors.kq, width: 2.4 },
      { data: positive(s.open_water, (p) => p.eta), label: 'efficiency η0, these blades', color: PROPELLER.colors.eta, width: 2.4 },
      { data: series.map((p) => p.kt), label: 'KT, B-series (faint)', color: PROPELLER.colors.ktSeries, width: 1.2, dash: [6, 4] },
      { data: series.map((p) => 10 * p.kq), label: '10KQ, B-series (faint)', color: PROPELLER.colors.kqSeries, width: 1.2, dash: [6, 4] },
      { data: positive(series, (p) => p.eta), label: 'η0, B-series (faint)', color: PROPELLER.colors.etaSeries, width: 1.2, dash: [6, 4] },
    ], [{ scale: 'y', label: 'KT, 10KQ, η0 [-]' }], { key: ['η0 = J KT / (2π KQ), drawn where KT > 0.'] });
    const head = ['J [-]', 'KT', '10KQ', 'η0', 'KT, B-series', '10KQ, B-series', 'η0, B-series'];
    this.table.replaceChildren(el('caption', { textContent: `Open water of ${name} by the vortex lattice, and the B-series polynomial beside it` }),
      el('thead', {}, el('tr', {}, ...head.map((t) => el('th', { scope: 'col', textContent: t })))),
      el('tbody', {}, ...s.open_water.map((p, i) => el('tr', {}, el('th', { scope: 'row', textContent: p.j.toFixed(3) }),
        ...[d4(p.kt), d4(10 * p.kq), p.kt > 0 ? p.eta.toFixed(3) : '–', d4(series[i].kt), d4(10 * series[i].kq), series[i].kt > 0 ? series[i].eta.toFixed(3) : '–']
          .map((t) => el('td', { textContent: t }))))));
    this.drawn = { name: s.name, runs_it: s.runs_it, points: js.length, outline, timing: this.timing || null };
  }
}
