// The hull (issue 15): the picker in the scenario form (embedded hulls by name, "load offsets" from
// a CSV file chosen or dropped on the page, or a whole scenario file), and the hull panel: body
// plan, profile (drawn by hulldraw.js) and hydrostatics of the scenario's hull at its loading. Every
// number comes from the wasm (hullSheet, validateScenario); the offsets are parsed by the same Rust
// code as the command line. This module only moves text.
import { choiceLabel, migrate } from './registry.js';
import { $, el } from './dom.js';
import { REQUEST, fieldLine } from './protocol.js';
import { announce } from './state.js';
import { num, drawBodyPlan, drawProfile } from './hulldraw.js';

const FILE_FIELD = 'ship.hull.offsets_csv';
const FILE_INPUT = 'f-ship-hull-offsets_csv';
// The largest file read (the Rust side bounds a scenario at 4 MiB and says so past it).
const MAX_FILE_BYTES = 4 << 20;
const clone = (x) => JSON.parse(JSON.stringify(x));
const hullTitle = (sheet, file) => (file ? `custom hull (${file})` : sheet.profile.name);

// The hydrostatics table: [label, value, unit].
function tableRows(sheet) {
  const [kxx, kyy, kzz] = sheet.k_m;
  return [
    ['Length between perpendiculars Lpp', sheet.profile.lpp_m, 'm'],
    ['Beam at the waterline B', sheet.beam_m, 'm'],
    ['Draft T', sheet.draft_m, 'm'],
    ['Displaced volume ∇', sheet.volume_m3, 'm³'],
    ['Displacement Δ', sheet.mass_kg / 1000, 't'],
    ['LCB, forward of the aft perpendicular', sheet.lcb_m, 'm'],
    ['KB, centre of buoyancy above base', sheet.kb_m, 'm'],
    ['BM_T, transverse metacentric radius', sheet.bm_t_m, 'm'],
    ['BM_L, longitudinal metacentric radius', sheet.bm_l_m, 'm'],
    ['KG, centre of gravity above base', sheet.kg_m, 'm'],
    ['GM_T = KB + BM_T − KG', sheet.gm_t_m, 'm'],
    ['GM_L = KB + BM_L − KG', sheet.gm_l_m, 'm'],
    ['Waterplane area Awp', sheet.awp_m2, 'm²'],
    ['Radii of gyration k_xx, k_yy, k_zz', `${num(kxx)}, ${num(kyy)}, ${num(kzz)}`, 'm'],
    ['Bilge keels, length and breadth', sheet.bilge_keels_m ? `${num(sheet.bilge_keels_m[0])}, ${num(sheet.bilge_keels_m[1])}` : 'none', sheet.bilge_keels_m ? 'm' : ''],
    ['Propeller hubs, forward of the aft perpendicular', sheet.propeller_x_m, 'm'],
    ['Shafts off the centreline (port +)', sheet.shaft_y_m.map(num).join(', '), 'm'],
    ['Propeller diameter D', sheet.propeller_diameter_m, 'm'],
    ['Hub above base', sheet.hub_above_base_m, 'm'],
    ['Calm-water hub depth h0 = T − hub height', sheet.hub_depth_m, 'm'],
    ['Rudder, forward of the aft perpendicular', sheet.rudder_x_m, 'm'],
  ];
}

// The panel in the results: heading, the two drawings (canvas, role img, labelled) and the table
// (their text alternative). update(scenario) asks the worker for the sheet of the scenario's hull.
export class HullPanel {
  constructor(root, client, { onSheet = () => {} } = {}) {
    this.root = root;
    this.client = client; // () => the worker client
    this.onSheet = onSheet;
    this.key = null;
    this.sheet = null;
    this.file = null;
    this.drawn = null; // what the drawings hold (a test reads it)
    announce('hullPanel', this);
    const C = (id, label) => el('canvas', { id, className: 'hull-canvas', attrs: { role: 'img', 'aria-label': label, 'aria-describedby': 'hull-table-caption' } });
    this.heading = el('h2', { id: 'hull-h', textContent: 'The hull' });
    this.note = el('p', { className: 'hint', id: 'hull-note' });
    this.bodyCanvas = C('hull-bodyplan', 'Body plan');
    this.profileCanvas = C('hull-profile', 'Profile');
    this.table = el('table', { id: 'hull-table' }, el('caption', { id: 'hull-table-caption', textContent: 'Hydrostatics at this loading (from the offsets)' }),
      el('thead', {}, el('tr', {}, ...['quantity', 'value', 'unit'].map((t) => el('th', { scope: 'col', textContent: t })))), el('tbody'));
    root.setAttribute('aria-labelledby', 'hull-h');
    // Folded where the study does not depend on the hull (calm water: fold()); drawn when opened.
    this.fold = el('details', { id: 'hull-fold', open: true }, el('summary', {}, this.heading));
    this.fold.addEventListener('toggle', () => { if (this.fold.open) this.draw(); });
    root.replaceChildren(this.fold);
    this.fold.append(this.note,
      el('div', { className: 'hull-drawings' },
        el('figure', { className: 'plot hull-fig wide' }, el('h3', { textContent: 'Profile: keel and deck lines, waterline, propeller, rudder, G and B' }), this.profileCanvas),
        el('figure', { className: 'plot hull-fig' }, el('h3', { textContent: 'Body plan: sections, aft half left, forward half right' }), this.bodyCanvas),
        el('div', { className: 'scroll hull-table' }, this.table)));
    let width = 0;
    new ResizeObserver(() => {
      const w = this.root.clientWidth;
      if (this.sheet && Math.abs(w - width) > 1) { width = w; this.draw(); }
    }).observe(root);
  }

  // The sheet of the scenario's hull (asked again only when the hull or the propeller changed).
  // file: the name of a custom hull's offsets file, if known.
  async update(scenario, file = null) {
    const key = JSON.stringify([scenario.ship, scenario.propeller.diameter_m, file]);
    if (key === this.key) return this.sheet;
    this.key = key;
    let sheet;
    try {
      ({ sheet } = await this.client().request(REQUEST.hullSheet, { scenario: JSON.stringify(scenario) }));
    } catch (e) {
      if (key !== this.key) return null;
      this.key = null; // asked again next time (a cancel ends the worker with the request)
      if (e.cancelled) return null;
      this.note.textContent = `The hull cannot be drawn (${e.fields && e.fields.length ? e.fields.slice(0, 2).map(fieldLine).join('; ') : e.message}); ${this.sheet ? 'showing the last valid hull' : 'nothing to draw yet'}.`;
      this.note.classList.add('error');
      return null;
    }
    if (key !== this.key) return null; // a newer request is under way
    this.sheet = sheet;
    this.file = scenario.ship.hull && scenario.ship.hull.name === 'custom' ? file : null;
    this.note.classList.remove('error');
    this.draw();
    this.onSheet(sheet);
    return sheet;
  }

  // Opens the panel for a study in waves (the strip theory uses the hull), folds it in calm water.
  folded(calm) { this.fold.open = !calm; }

  draw() {
    const sheet = this.sheet;
    if (!sheet || this.root.hidden) return;
    const name = hullTitle(sheet, this.file);
    this.heading.textContent = `The hull: ${name}`;
    this.note.textContent = `Lpp ${num(sheet.profile.lpp_m)} m, beam ${num(sheet.beam_m)} m, draft ${num(sheet.draft_m)} m, displacement ${num(sheet.mass_kg / 1000)} t. `
      + 'Drawn to scale from the offsets; the strip theory of the RAOs and runs in waves uses these sections.'
      + ((sheet.approximated_stations || []).length
        ? ` Taken approximately: ${sheet.approximated_stations.map(([x, why]) => `x = ${num(x)} m (${why})`).join('; ')}.`
        : '');
    const bp = drawBodyPlan(this.bodyCanvas, sheet);
    const pr = drawProfile(this.profileCanvas, sheet);
    this.bodyCanvas.setAttribute('aria-label', `Body plan of the ${name}: ${bp.aft} sections of the aft half on the left, ${bp.fore} of the forward half on the right, `
      + `beam ${num(sheet.beam_m)} m, waterline at ${num(sheet.draft_m)} m above base. The numbers are in the table below.`);
    this.profileCanvas.setAttribute('aria-label', `Profile of the ${name}: ${num(sheet.profile.lpp_m)} m between perpendiculars, waterline at ${num(sheet.draft_m)} m, `
      + `propeller of ${num(sheet.propeller_diameter_m)} m with its hub ${num(sheet.hub_above_base_m)} m above base (h0 = ${num(sheet.hub_depth_m)} m) ${num(sheet.propeller_x_m)} m forward of the aft perpendicular, rudder at ${num(sheet.rudder_x_m)} m`
      + `${pr.stretch > 1 ? `; heights drawn ${pr.stretch} times larger than lengths` : ''}.`);
    this.table.tBodies[0].replaceChildren(...tableRows(sheet).map(([label, v, unit]) => el('tr', {},
      el('th', { scope: 'row', textContent: label }), el('td', { textContent: typeof v === 'number' ? num(v) : v }), el('td', { className: 'unit', textContent: unit }))));
    this.drawn = { name, bodyPlan: bp, profile: pr, volume_m3: sheet.volume_m3 };
  }
}

// The picker: the hull select, the file field (offsets CSV or a scenario JSON, chosen or dropped on
// the page) and the loading fields beside them (the form's 'hull-loading' group).
export class HullPicker {
  // form: the ScenarioForm; validate(sc): resolves or throws {fields}; commit(sc, {name?}): puts an
  // accepted scenario in the form (fill, save, follow); say(text, isError): the status line.
  constructor(names, { form, validate, commit, say, busy }) {
    Object.assign(this, { form, validate, commit, say, busy });
    this.custom = null; // the last custom hull: {spec: its ship.hull section, file: its file's name}
    this.select = $('hull');
    this.select.replaceChildren(...names.map((n) => new Option(choiceLabel('ship.hull.name', n), n)));
    this.select.addEventListener('change', () => this.pick(this.select.value));
    const file = $(FILE_INPUT);
    file.addEventListener('change', () => { if (file.files[0]) this.loadFile(file.files[0]); });
    // A file dropped anywhere on the simulator tab.
    const panel = $('panel-sim');
    panel.addEventListener('dragover', (e) => {
      if (![...(e.dataTransfer?.types || [])].includes('Files')) return;
      e.preventDefault();
      document.body.classList.add('dropping');
    });
    panel.addEventListener('dragleave', (e) => { if (!e.relatedTarget || !panel.contains(e.relatedTarget)) document.body.classList.remove('dropping'); });
    panel.addEventListener('drop', (e) => {
      document.body.classList.remove('dropping');
      const f = e.dataTransfer?.files?.[0];
      if (!f) return;
      e.preventDefault();
      this.loadFile(f);
    });
  }

  // The name of the file of the scenario's custom hull, if known.
  fileOf(scenario) {
    const h = scenario.ship.hull || {};
    return h.name === 'custom' && this.custom && this.custom.spec.offsets_csv === h.offsets_csv ? this.custom.file : null;
  }

  // The select follows the scenario; "custom" is offered once a custom hull is known.
  sync(scenario) {
    const hull = scenario.ship.hull || {};
    if (hull.name === 'custom') {
      const same = this.custom && this.custom.spec.offsets_csv === hull.offsets_csv;
      this.custom = { spec: clone(hull), file: same ? this.custom.file : null };
    }
    const opt = [...this.select.options].find((o) => o.value === 'custom');
    if (opt) {
      opt.disabled = !this.custom;
      opt.text = this.custom ? `custom offsets${this.custom.file ? `: ${this.custom.file}` : ''}` : 'custom offsets (load a file below)';
    }
    this.select.value = hull.name || 'dtmb5415';
  }

  fileError(message) {
    const input = $(FILE_INPUT), e = $(`${FILE_INPUT}-err`);
    e.textContent = message;
    if (message) input.setAttribute('aria-invalid', 'true'); else input.removeAttribute('aria-invalid');
  }

  // An embedded hull by name (the loading fields go back to the hull's own; the hub height, the
  // studies' knob, stays), or back to the last custom hull.
  async pick(name) {
    if (this.busy()) return;
    const sc = this.form.current();
    const prev = sc.ship.hull || {};
    if (name === 'custom') {
      if (!this.custom) { this.sync(sc); $(FILE_INPUT).focus(); return; }
      sc.ship.hull = clone(this.custom.spec);
    } else {
      sc.ship.hull = { name };
      if (prev.hub_above_base_m != null) sc.ship.hull.hub_above_base_m = prev.hub_above_base_m;
    }
    this.fileError('');
    await this.accept(sc, `Hull: ${choiceLabel('ship.hull.name', name)}.`);
  }

  // Validates; a refused hull file (name or offsets) leaves the scenario as it was; refusals of the
  // loading fields (a custom hull without draft or KG) are shown at those fields, the hull kept.
  async accept(sc, said, { name, file, source } = {}) {
    let fields = [];
    try { await this.validate(sc); } catch (e) {
      if (e.cancelled) return false;
      fields = e.fields || [{ path: '(scenario)', value: '', message: e.message }];
    }
    const fatal = fields.filter((f) => f.path === FILE_FIELD || f.path === 'ship.hull.name' || f.path === '(file)' || f.path === '(scenario)');
    if (fatal.length) {
      this.fileError(`${file || source || 'the hull'}: ${fatal.map((f) => (f.path === FILE_FIELD ? f.message : fieldLine(f))).join('; ')}`);
      this.sync(this.form.scenario);
      this.say('The file was not used: the hull stays as it was (the reason is under the file field).', true);
      $(FILE_INPUT).focus();
      return false;
    }
    if (file) this.custom = { spec: clone(sc.ship.hull), file };
    else if (source && sc.ship.hull && sc.ship.hull.name === 'custom') this.custom = { spec: clone(sc.ship.hull), file: `from ${source}` };
    this.sync(sc);
    this.commit(sc, { name });
    this.form.markErrors(fields);
    if (fields.length) {
      const loading = $('hull-loading-box');
      if (loading) loading.open = true;
      const first = this.form.input(fields[0].path);
      if (first) first.focus();
      this.say(`${said} Fill in the marked fields (${fields.map((f) => f.path.split('.').pop()).join(', ')}) to draw and run it.`, true);
    } else {
      this.say(said);
    }
    return true;
  }

  async loadFile(file) {
    if (this.busy()) { this.say('Wait for the run to finish, or cancel it, before loading a file.', true); return; }
    if (file.size > MAX_FILE_BYTES) { this.fileError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MiB: at most 4 MiB`); return; }
    let text;
    try { text = await file.text(); } catch (e) { this.fileError(`${file.name} could not be read: ${e.message}`); return; }
    this.fileError('');
    if (/^\s*\{/.test(text)) { await this.loadScenario(text, file.name); return; }
    const sc = this.form.current();
    const prev = sc.ship.hull || {};
    // A new file for a custom hull keeps its loading; over an embedded hull it starts afresh
    // (the studies' hub height kept).
    const hull = prev.name === 'custom' ? { ...prev } : (prev.hub_above_base_m != null ? { hub_above_base_m: prev.hub_above_base_m } : {});
    Object.assign(hull, { name: 'custom', offsets_csv: text });
    sc.ship.hull = hull;
    const ok = await this.accept(sc, `Offsets of ${file.name} read.`, { file: file.name });
    if (ok) this.sync(sc);
  }

  // A scenario file (as the page downloads it, or aes-sim reads it): the study of its name if
  // the page has one, else the study now picked.
  async loadScenario(text, fileName) {
    let sc;
    try { sc = migrate(JSON.parse(text)); } catch (e) { this.fileError(`${fileName}: not valid JSON (${e.message})`); return; }
    if (!sc || typeof sc !== 'object' || !sc.ship) { this.fileError(`${fileName}: neither hull offsets (CSV) nor a scenario (JSON with a ship)`); return; }
    const name = typeof sc.name === 'string' && this.form.has(sc.name) ? sc.name : this.form.name;
    await this.accept(sc, `Scenario ${fileName} loaded.`, { name, source: fileName });
  }
}
