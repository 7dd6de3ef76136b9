// The operability tab (issue 31): the polar of the simulator's current study (its hull, loading,
// hub depth and criteria), computed by the wasm speed by speed over a few workers with a progress
// bar and Cancel; drawn by polar.js, named cell by cell on hover, tap or the arrow keys, with the
// scatter diagram's operability per speed and the criteria as tables. A cell opens the simulator
// at its speed, wave heading and sea. A polar is kept under the inputs it was computed from: under
// other values of the study it is marked stale, under another study it is not shown.
import { OPERABILITY } from './config.js';
import { $, el, fmt } from './dom.js';
import { announce } from './state.js';
import { StudyPool } from './pool.js';
import { StudyFold } from './fold.js';
import { colourScale, drawPolar, cellAt, cellCentre, margins } from './polar.js';

// What a cell's click sets in the scenario: the polar does not read these (it judges the hull,
// loading, hub depth, spreading and criteria), so opening a cell leaves its polar current. The
// hull model is the simulator's (surge or maneuvering), not the hull's shape: waves need the
// maneuvering model (the scenario checks refuse a random sea without it).
const CELL_FIELDS = ['sea.kind', 'sea.sea_state', 'sea.h_sig_m', 'sea.omega_n_rad_s', 'sea.from_deg', 'hull.model', 'initial.speed_kn'];

function withoutCellFields(sc) {
  const c = JSON.parse(JSON.stringify(sc));
  for (const p of CELL_FIELDS) { const [a, b] = p.split('.'); if (c[a]) delete c[a][b]; }
  if (Array.isArray(c.commands) && c.commands[0]) delete c.commands[0].speed_kn;
  return c;
}

// The heading in words: of the waves relative to the ship (180 head seas, 90 from starboard).
export function headingWords(deg) {
  const d = ((deg % 360) + 360) % 360;
  if (d === 180) return 'head seas';
  if (d === 0) return 'following seas';
  if (d === 90) return 'beam seas from starboard';
  if (d === 270) return 'beam seas from port';
  const side = d < 180 ? 'starboard' : 'port';
  const bow = d > 90 && d < 270;
  return `${bow ? 'bow' : 'quartering'} seas from ${side}`;
}

// Where a criterion is judged, in words (a point of operability.points), or nothing.
const pointWords = (c) => (c.point ? `, at the ${c.point.replace(/_/g, ' ')}` : '');
const m2 = (x) => `${Number(x).toFixed(2)} m`;
const deg = (x) => `${+Number(x).toFixed(2)}°`;
const kn = (x) => `${+Number(x).toFixed(2)} kn`;
const pct = (x) => `${(100 * x).toFixed(1)} %`;

export class OperabilityTab {
  // inputs(): {study, title, scenario, invalid} of the simulator's form, or null while it loads;
  // onOpenCell({speed_kn, set}): open the simulator with these scenario values (set: path -> value,
  // undefined to remove), returning a reason when it cannot.
  constructor({ inputs, onOpenCell }) {
    this.inputs = inputs;
    this.onOpenCell = onOpenCell;
    this.kept = new Map(); // key -> {key, study, polar}
    this.shown = null; // the kept entry drawn
    this.selected = null; // {j, i}
    this.geo = null;
    this.pool = new StudyPool(OPERABILITY.maxWorkers);
    this.fold = new StudyFold('op', { failed: 'The polar failed', cancel: () => this.cancel(), redFailures: true });
    this.touchSelected = null;
    const cv = $('op-canvas');
    this.canvas = cv;
    $('op-compute').addEventListener('click', () => this.compute());
    $('op-stale-run').addEventListener('click', () => this.compute());
    cv.addEventListener('pointermove', (e) => { if (e.pointerType === 'mouse') this.pick(this.at(e), false); });
    cv.addEventListener('pointerleave', (e) => { if (e.pointerType === 'mouse' && document.activeElement !== cv) this.pick(null, false); });
    // A mouse click opens the cell; on a touch screen the first tap names it, a second opens it.
    cv.addEventListener('click', (e) => {
      const c = this.at(e);
      if (!c) return;
      const touch = this.lastPointer && this.lastPointer !== 'mouse';
      const same = this.selected && this.selected.j === c.j && this.selected.i === c.i;
      if (touch && !same) { this.pick(c, true); return; }
      this.open(c);
    });
    cv.addEventListener('pointerdown', (e) => { this.lastPointer = e.pointerType; });
    cv.addEventListener('keydown', (e) => this.key(e));
    cv.addEventListener('focus', () => { if (this.shown && !this.selected && cv.matches(':focus-visible')) this.pick(this.start(), true); });
    new ResizeObserver(() => this.draw()).observe($('op-plot'));
    window.addEventListener('resize', () => this.draw());
  }

  key(e) {
    const p = this.shown && this.shown.polar;
    if (!p) return;
    const ns = p.speeds_kn.length, nh = p.headings_deg.length;
    const c = this.selected || this.start();
    const move = { ArrowUp: [1, 0], ArrowDown: [-1, 0], ArrowRight: [0, -1], ArrowLeft: [0, 1] }[e.key];
    if (move) {
      e.preventDefault();
      this.pick({ j: Math.min(ns - 1, Math.max(0, c.j + move[0])), i: (c.i + move[1] + nh) % nh }, true);
    } else if (e.key === 'Enter' || e.key === ' ') {
      e.preventDefault();
      this.open(c);
    }
  }

  // The first cell the keys name: the middle speed in head seas (or the first heading).
  start() {
    const p = this.shown.polar;
    const i = Math.max(0, p.headings_deg.findIndex((h) => h === 180));
    return { j: Math.floor(p.speeds_kn.length / 2), i };
  }

  at(e) {
    if (!this.shown || !this.geo) return null;
    const r = this.canvas.getBoundingClientRect();
    return cellAt(this.shown.polar, this.geo, e.clientX - r.left, e.clientY - r.top);
  }

  // The key of the inputs a polar depends on (the study and its values but for what a cell sets).
  keyOf(inp) { return `${inp.study}|${JSON.stringify(withoutCellFields(inp.scenario))}`; }

  // The request the page makes: the grid of config.js, speeds up to the scenario's RAO table.
  request(sc) {
    const top = Number(sc.seakeeping && sc.seakeeping.grid && sc.seakeeping.grid.speed_max_kn);
    const speeds = OPERABILITY.speedsKn.filter((v) => !Number.isFinite(top) || v <= top);
    return { speeds_kn: speeds, headings_deg: OPERABILITY.headingsDeg, sea_states: OPERABILITY.seaStates };
  }

  // After any change of the simulator's inputs (and on showing the tab): the polar of these inputs
  // if one is kept; a polar of other values of the same study marked stale; none of another study.
  sync() {
    const inp = this.inputs();
    if (!inp) return;
    $('op-study').textContent = inp.title;
    this.fold.allow(!inp.invalid);
    // A refused value waits at its field on the Simulator tab; say so here too.
    this.fold.refused(inp.invalid, 'A value of the form is refused (marked at its field on the Simulator tab): correct it to compute.');
    const key = this.keyOf(inp);
    const own = this.kept.get(key);
    if (own && own !== this.shown) this.show(own);
    else if (this.shown && this.shown.study !== inp.study) this.show(null);
    this.fold.markStale(Boolean(this.shown) && this.shown.key !== key, 'This polar is of other values of this study than the simulator\'s form now (its hull, loading, hub depth or criteria may differ). Compute it again to judge the form\'s values.');
  }

  status(text, error = false) { this.fold.status(text, error); }

  cancel() { this.pool.cancel(); }

  // Computes the polar of the form's values on the study pool: the speeds go one at a time to up
  // to OPERABILITY.maxWorkers workers, then one worker joins them into the polar.
  async compute() {
    const inp = this.inputs();
    if (!inp || this.fold.busy) return;
    if (inp.invalid) return;
    const key = this.keyOf(inp);
    const scenario = JSON.stringify(inp.scenario);
    const req = this.request(inp.scenario);
    const n = req.speeds_kn.length;
    if (!n) { this.status('No speed of the grid is within the scenario\'s RAO table (seakeeping.grid.speed_max_kn).', true); return; }
    const started = performance.now();
    const spec = JSON.stringify({ scenario: inp.scenario, request: req });
    await this.fold.compute(async () => {
      const { summary: polar } = await this.pool.run({
        kind: 'operability', scenario, spec, n, item: 'speed',
        onStart: (k) => this.status(`Computing the polar: ${n} speeds x ${req.headings_deg.length} headings x ${req.sea_states.length} seas on ${k} worker${k > 1 ? 's' : ''}...`),
        onProgress: (done, _, preparing) => this.fold.progress(done, n, started, 'speed', preparing),
      });
      const entry = { key, study: inp.study, title: inp.title, polar, ms: performance.now() - started };
      this.kept.delete(key);
      this.kept.set(key, entry);
      while (this.kept.size > OPERABILITY.kept) this.kept.delete(this.kept.keys().next().value);
      this.selected = null;
      this.show(entry);
      this.status(`Done: ${polar.cells.length} cells in ${(entry.ms / 1000).toFixed(1)} s. Point at a cell to name it.`);
    }, { after: () => this.sync() });
  }

  // Shows a kept polar (or none): the plot, its legend, tables and text alternative.
  show(entry) {
    this.shown = entry;
    this.selected = null;
    $('op-body').hidden = !entry;
    $('op-empty').hidden = Boolean(entry);
    if (!entry) { this.geo = null; return; }
    const p = entry.polar;
    this.scale = colourScale(p);
    $('op-title').textContent = `Operability polar: ${entry.title}`;
    const formula = p.hub_depth_formula === 'consistent' ? 'the consistent hub-depth formula' : `the hub-depth formula ${p.hub_depth_formula}`;
    $('op-judged').textContent = `Hull ${p.hull}, propeller hub ${m2(p.hub_depth_m)} below the calm surface (${formula}), wave spreading cos^${+p.spreading.toFixed(2)} (sea.spreading; 0: long-crested). Seas: ${p.seas.map((s) => `${s.name} (H_1/3 ${m2(s.h_sig_m)}, T_p ${s.tp_s.toFixed(1)} s)`).join(', ')}.`;
    this.legend(p);
    this.tables(p);
    this.readout();
    this.draw();
  }

  legend(p) {
    const s = this.scale;
    const sw = (background) => el('span', { className: 'op-swatch', attrs: { style: `background: ${background}` } });
    const { fill, hatch } = OPERABILITY.beyond;
    const last = p.seas[p.seas.length - 1];
    const beyond = p.cells.some((c) => c.beyond_listed || c.limiting_hs_m === null);
    $('op-legend').replaceChildren(
      el('p', { className: 'op-legend-h', textContent: 'Limiting H_1/3 [m]: the highest significant wave height in which every criterion holds (the colours span the limits of this polar)' }),
      el('ul', {}, ...s.bins.map((b) => el('li', {}, sw(b.colour), `${b.lo.toFixed(2)} to ${b.hi.toFixed(2)} m`)),
        ...(beyond ? [el('li', {}, sw(`repeating-linear-gradient(-45deg, ${fill} 0 3px, ${hatch} 3px 4px)`), `passes every listed sea, up to ${last.name} (H_1/3 ${m2(last.h_sig_m)}): beyond the highest sea (hatched)`)] : [])),
    );
  }

  tables(p) {
    const nh = p.headings_deg.length;
    // The scatter diagram's operability per speed and overall.
    const sc = p.scatter;
    $('op-scatter').replaceChildren(...(sc ? [
      el('table', { id: 'op-scatter-table' },
        el('caption', { textContent: `Operable share of the ${sc.name} scatter diagram (every heading equally likely)` }),
        el('thead', {}, el('tr', {}, el('th', { scope: 'col', textContent: 'speed [kn]' }), el('th', { scope: 'col', textContent: 'operable [%]' }))),
        el('tbody', {}, ...p.speeds_kn.map((v, j) => el('tr', {}, el('th', { scope: 'row', textContent: +v.toFixed(2) }), el('td', { textContent: (100 * sc.per_speed[j]).toFixed(1) }))),
          el('tr', { className: 'op-overall' }, el('th', { scope: 'row', textContent: 'all speeds' }), el('td', { textContent: (100 * sc.overall).toFixed(1) })))),
      el('p', { className: 'hint', textContent: `Source: ${sc.source}` }),
    ] : [el('p', { className: 'hint', textContent: 'No scatter diagram was asked for.' })]));
    // The criteria with their limits and sources (the scenario's operability.criteria).
    $('op-criteria').replaceChildren(el('table', { id: 'op-criteria-table' },
      el('caption', { textContent: 'Criteria (the scenario\'s operability.criteria): each must hold' }),
      el('thead', {}, el('tr', {}, ...['criterion', 'limit (in the criterion\'s unit)', 'source'].map((h) => el('th', { scope: 'col', textContent: h })))),
      el('tbody', {}, ...p.criteria.map((c) => el('tr', {}, el('th', { scope: 'row', textContent: `${c.label}${pointWords(c)}` }), el('td', { textContent: String(c.limit) }), el('td', { className: 'op-source', textContent: c.source }))))));
    // The text alternative of the plot: limiting H_1/3 by speed and heading; a cell's button opens it.
    const head = el('tr', {}, el('th', { scope: 'col', textContent: 'speed [kn] \\ heading [deg]' }), ...p.headings_deg.map((h) => el('th', { scope: 'col', textContent: `${+h.toFixed(2)}` })));
    const body = p.speeds_kn.map((v, j) => el('tr', {}, el('th', { scope: 'row', textContent: `${+v.toFixed(2)}` }), ...p.headings_deg.map((h, i) => {
      const c = p.cells[j * nh + i];
      const text = c.beyond_listed || c.limiting_hs_m === null ? `> ${p.seas[p.seas.length - 1].h_sig_m.toFixed(1)}` : c.limiting_hs_m.toFixed(2);
      // The name starts with the visible text (what a speech user says to press it).
      const b = el('button', { type: 'button', className: 'op-cellbtn', textContent: text,
        attrs: { 'aria-label': `${text} m at ${kn(v)}, ${deg(h)} (${headingWords(h)}): open in the simulator` } });
      b.addEventListener('click', () => this.open({ j, i }));
      b.addEventListener('focus', () => this.pick({ j, i }, true));
      return el('td', {}, b);
    })));
    $('op-grid-summary').textContent = `The polar as a table: limiting H_1/3 [m] by speed and heading ("> ${p.seas[p.seas.length - 1].h_sig_m.toFixed(1)}": passes every listed sea)`;
    $('op-grid').replaceChildren(el('table', { id: 'op-grid-table' },
      el('caption', { textContent: 'Limiting H_1/3 [m]' }), el('thead', {}, head), el('tbody', {}, ...body)));
  }

  hsWords(p, c) {
    const last = p.seas[p.seas.length - 1];
    if (c.limiting_hs_m === null) return `passes every listed sea; no criterion limits it`;
    if (c.beyond_listed) return `passes every listed sea (up to ${last.name}, H_1/3 ${m2(last.h_sig_m)}); at its spectral shape the limit would be ${c.limiting_hs_m.toFixed(3)} m`;
    return `limiting H_1/3 ${c.limiting_hs_m.toFixed(3)} m`;
  }

  // Names the cell {j, i} (or says how to) in the readout beside the plot.
  readout() {
    const box = $('op-cell');
    const p = this.shown && this.shown.polar;
    for (const a of ['speed', 'heading', 'limitingHsM', 'criterion', 'seasPassed']) delete box.dataset[a];
    if (!p || !this.selected) {
      box.replaceChildren(el('p', { textContent: 'Point at a cell to name it (on a touch screen: tap it; with the keyboard: focus the plot and use the arrow keys).' }));
      return;
    }
    const { j, i } = this.selected;
    const c = p.cells[j * p.headings_deg.length + i];
    const crit = c.limiting_criterion === null ? null : p.criteria[c.limiting_criterion];
    const passed = c.seas_passed > 0 ? p.seas[c.seas_passed - 1] : null;
    Object.assign(box.dataset, { speed: String(c.speed_kn), heading: String(c.heading_deg), limitingHsM: c.limiting_hs_m === null ? 'null' : String(c.limiting_hs_m), criterion: String(c.limiting_criterion), seasPassed: String(c.seas_passed) });
    const lines = [
      el('p', { className: 'op-cell-h', textContent: `${kn(c.speed_kn)}, waves at ${deg(c.heading_deg)} (${headingWords(c.heading_deg)})` }),
      el('p', { textContent: c.beyond_listed || c.limiting_hs_m === null ? this.hsWords(p, c)[0].toUpperCase() + this.hsWords(p, c).slice(1) : `Limiting H_1/3: ${c.limiting_hs_m.toFixed(3)} m` }),
    ];
    if (crit) lines.push(el('p', { textContent: `${c.beyond_listed ? 'First to reach its limit above that' : 'Limited by'}: ${crit.label}${pointWords(crit)}, limit ${crit.limit} (source: ${crit.source})` }));
    lines.push(el('p', { textContent: `Highest sea passed: ${passed ? `${passed.name} (H_1/3 ${m2(passed.h_sig_m)}, T_p ${passed.tp_s.toFixed(1)} s)` : 'none of the listed seas'}` }));
    if (p.scatter) lines.push(el('p', { textContent: `Operable in ${pct(p.scatter.share[j][i])} of the ${p.scatter.name} sea states at this speed and heading.` }));
    box.replaceChildren(...lines);
  }

  pick(c, announce) {
    const same = (a, b) => (a && b ? a.j === b.j && a.i === b.i : a === b);
    if (same(c, this.selected)) return;
    this.selected = c;
    $('op-cell').setAttribute('aria-live', announce ? 'polite' : 'off');
    this.readout();
    this.draw();
  }

  // Opens the simulator at a cell: its speed, sea.kind random, the first sea the cell fails (the
  // highest listed when it passes them all) and the waves from (180 - heading) mod 360 (ship
  // heading north: waves from 0 are head seas).
  open(c) {
    const p = this.shown && this.shown.polar;
    if (!p || !c) return;
    const cell = p.cells[c.j * p.headings_deg.length + c.i];
    const s = Math.min(cell.seas_passed, p.seas.length - 1);
    const req = this.request(this.inputs().scenario);
    // The ship starts at the cell's speed, so the run shows the sea's effect, not an acceleration.
    const set = { 'sea.kind': 'random', 'sea.from_deg': (((180 - cell.heading_deg) % 360) + 360) % 360, 'hull.model': 'maneuvering', 'initial.speed_kn': cell.speed_kn };
    // The page asks for Table 2.4's sea states (config.js): the sea is the sea state; a sea of
    // one's own would be its height and modal frequency.
    if (req.sea_states && p.seas.length === req.sea_states.length) Object.assign(set, { 'sea.sea_state': req.sea_states[s], 'sea.h_sig_m': 0, 'sea.omega_n_rad_s': 0 });
    else Object.assign(set, { 'sea.sea_state': undefined, 'sea.h_sig_m': p.seas[s].h_sig_m, 'sea.omega_n_rad_s': p.seas[s].omega_n_rad_s });
    const why = this.onOpenCell({ speed_kn: cell.speed_kn, set, words: `${kn(cell.speed_kn)}, waves at ${deg(cell.heading_deg)} (${headingWords(cell.heading_deg)}, from ${deg(set['sea.from_deg'])} for a ship heading north), ${p.seas[s].name}, starting at that speed, with the maneuvering hull model (waves need it)` });
    if (why) this.status(why, true);
  }

  // Draws the shown polar at the size of its box: as wide as the box, no taller than the window
  // leaves room for (the whole circle in view at 1366x768).
  draw() {
    const cv = this.canvas;
    if (!this.shown || !cv.offsetParent) return;
    const w = $('op-plot').clientWidth;
    if (!w) return;
    // As tall as the circle at this width needs (no taller than the window leaves room for).
    const narrow = w < 480;
    const { mx, my } = margins(cv.getContext('2d'), narrow);
    const h = Math.round(Math.max(240, Math.min(w - 2 * mx + 2 * my, window.innerHeight - 150)));
    if (cv.style.height !== `${h}px`) cv.style.height = `${h}px`;
    this.geo = drawPolar(cv, this.shown.polar, this.scale, { selected: this.selected, narrow });
    const p = this.shown.polar, last = p.seas[p.seas.length - 1];
    const worst = p.cells.filter((c) => !c.beyond_listed && c.limiting_hs_m !== null).reduce((a, c) => (a && a.limiting_hs_m <= c.limiting_hs_m ? a : c), null);
    const beyond = p.cells.filter((c) => c.beyond_listed).length;
    cv.setAttribute('aria-label', `Operability polar of ${this.shown.title}: ${p.speeds_kn.length} speeds from ${kn(p.speeds_kn[0])} to ${kn(p.speeds_kn[p.speeds_kn.length - 1])}, ${p.headings_deg.length} wave headings. ${beyond} of ${p.cells.length} cells pass every listed sea up to ${last.name}${worst ? `; the lowest limit is ${m2(worst.limiting_hs_m)} at ${kn(worst.speed_kn)}, ${deg(worst.heading_deg)}` : ''}. Arrow keys move between cells, Enter opens the simulator at the cell; the table under "The polar as a table" gives every cell.`);
    // Where a cell is drawn and its colour (what a test checks of the drawing).
    announce('operability', { polar: p, centre: (j, i) => cellCentre(p, this.geo, j, i), colour: (j, i) => this.scale.colourOf(p.cells[j * p.headings_deg.length + i]) });
  }
}
