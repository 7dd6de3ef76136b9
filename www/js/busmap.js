// The bus stability map on the stability tab (issue 44, core's studies::stability_map, `aes-sim
// stability-map`): the whole plant with its bus loads and storage linearised at the form's study,
// its spectral abscissa coloured over two parameters with the boundary where it crosses zero, the
// study's own point marked, and a cell's value, verdict and least damped mode said on hover or
// keyboard focus. Every number is the wasm's: the map is core's "stability-map" study, its rows
// spread over the study pool's workers; here the pairs offered, the units shown and the words
// (the drawing is busmapdraw.js).
import { BUSMAP } from './config.js';
import { $, el, row } from './dom.js';
import { REQUEST } from './protocol.js';
import { announce } from './state.js';
import { StudyPool } from './pool.js';
import { StudyFold } from './fold.js';
import { param } from './registry.js';
import { axesOf, drawMap, frame, fromSi, num, shownUnit, toSi, valueAt, within } from './busmapdraw.js';

// At most four workers, each computing a row at a time.
const MAX_WORKERS = 4;

// One axis's boxes (from, to, values), their labels filled in for the chosen pair.
const axisFields = (k) => `<fieldset id="busmap-${k}"><legend id="busmap-${k}-legend">${k} axis</legend>
        <div class="busmap-range">
          <label for="busmap-${k}-from" id="busmap-${k}-from-l">from</label><input id="busmap-${k}-from" type="number" step="any" inputmode="decimal">
          <label for="busmap-${k}-to" id="busmap-${k}-to-l">to</label><input id="busmap-${k}-to" type="number" step="any" inputmode="decimal">
          <label for="busmap-${k}-n">values</label><input id="busmap-${k}-n" type="number" step="1" min="2" inputmode="numeric">
        </div></fieldset>`;

export const TEMPLATE = `
<section id="busmap" aria-labelledby="busmap-h">
  <h2 id="busmap-h">Bus stability map</h2>
  <div class="busmap-grid">
    <div class="busmap-controls">
      <p class="about">Is the ship's DC bus stable with its constant-power loads and storage? The whole plant of the
        form's study (turbines, generators, buses, shafts, ship service filters, storage and the ship) linearised about its
        calm-water steady state at the speed below; the colour is the spectral abscissa, the largest real part of its
        eigenvalues: negative (blue) where every mode decays, positive (red, hatched) where one grows. The black line
        is the boundary. A constant-power load draws more current as its voltage falls: a negative resistance that
        undamps its input filter.</p>
      <div class="row"><label for="busmap-pair">Parameters</label><select id="busmap-pair"></select></div>
      <div class="row"><label for="busmap-speed">Speed at the operating point [kn]</label>
        <input id="busmap-speed" type="number" step="any" inputmode="decimal"></div>
      ${axisFields('x')}${axisFields('y')}
      <div class="row buttons"><button id="busmap-compute" type="button">Compute the map</button>
        <button id="busmap-cancel" type="button" disabled>Cancel</button>
        <progress id="busmap-progress" max="1" value="0" aria-label="Progress of the bus stability map"></progress>
        <span id="busmap-eta" aria-live="polite"></span></div>
      <div id="busmap-status" role="status" aria-live="polite"></div>
    </div>
    <div id="busmap-body" hidden>
      <p id="busmap-point"></p>
      <figure class="plot busmap-figure">
        <figcaption id="busmap-title"></figcaption>
        <canvas id="busmap-canvas" class="busmap-canvas" tabindex="0" role="img" aria-describedby="busmap-readout busmap-keys"></canvas>
        <p id="busmap-readout" aria-live="polite">Point at a cell, or focus the map and move with the arrow keys.</p>
        <p id="busmap-keys" class="key">Blue: stable; red and hatched: unstable; grey: no steady state there. Black line: the boundary
          (bisected between the cells of each row). Ring: the study's own values. Colour scale: logarithmic beyond ±0.01 1/s.</p>
      </figure>
      <details><summary>The boundary as a table</summary><div class="scroll" id="busmap-table" tabindex="0" role="region" aria-label="The boundary by row"></div></details>
      <p id="busmap-failures" class="hint" hidden></p>
    </div>
  </div>
</section>`;

export class BusMap {
  // ctx: the page's context (the form's study and the worker).
  constructor(ctx) {
    this.ctx = ctx;
    this.shown = null; // {request, key, point, map, sc}
    this.cell = null; // [i, j] of the cell said
    this.pool = new StudyPool(MAX_WORKERS);
    // Cancel stops the pool's workers; the map shown stays.
    this.fold = new StudyFold('busmap', { failed: 'The map could not be computed', cancel: () => this.pool.cancel(), redFailures: true });
    $('busmap-pair').addEventListener('change', () => this.pairChosen());
    $('busmap-compute').addEventListener('click', () => this.compute());
    for (const i of document.querySelectorAll('#busmap input')) i.addEventListener('input', () => this.sync());
    $('busmap-pair').addEventListener('change', () => this.sync());
    const cv = $('busmap-canvas');
    // A mouse over a cell, or a finger on it.
    for (const ev of ['pointermove', 'pointerdown']) cv.addEventListener(ev, (e) => this.hover(e));
    cv.addEventListener('keydown', (e) => this.key(e));
    cv.addEventListener('focus', () => { if (this.shown && !this.cell) this.select(this.startCell()); });
    new ResizeObserver(() => { if (this.shown && cv.clientWidth && cv.clientWidth !== this.drawnW) this.draw(); }).observe(cv);
  }

  // The pairs, labelled from the registry (once the simulator is loaded).
  ready() {
    $('busmap-pair').replaceChildren(...BUSMAP.pairs.map((p) => el('option', { value: p.id, textContent: `${param(p.x[0]).label} and ${param(p.y[0]).label}` })));
    this.pairChosen();
    this.studyChosen();
  }

  // Another study in the form: the speed of its operating point (its initial speed, or when it
  // starts from rest its first ordered speed).
  studyChosen() {
    const inp = this.ctx.studyInputs();
    if (!inp) return;
    const sc = inp.scenario;
    const v = sc.initial && sc.initial.speed_kn > 0 ? sc.initial.speed_kn : ((sc.commands || [])[0] || {}).speed_kn;
    $('busmap-speed').value = v > 0 ? v : '';
  }

  pair() { return BUSMAP.pairs.find((p) => p.id === $('busmap-pair').value) || BUSMAP.pairs[0]; }

  pairChosen() {
    const p = this.pair();
    for (const [axis, [path, from, to, n]] of [['x', p.x], ['y', p.y]]) {
      const u = shownUnit(path);
      $(`busmap-${axis}-legend`).textContent = `${axis} axis: ${u.label} [${u.unit}]`;
      $(`busmap-${axis}-from-l`).textContent = `from [${u.unit}]`;
      $(`busmap-${axis}-to-l`).textContent = `to [${u.unit}]`;
      $(`busmap-${axis}-from`).value = num(fromSi(from, u.pow), 6);
      $(`busmap-${axis}-to`).value = num(fromSi(to, u.pow), 6);
      $(`busmap-${axis}-n`).value = n;
    }
    this.markInvalid([]);
  }

  // The request of the controls, or {error, inputs} naming the box at fault.
  request() {
    const inp = this.ctx.studyInputs();
    if (!inp) return { error: 'The simulator is loading.', inputs: [] };
    if (inp.invalid) return { error: 'A value of the form is refused (marked at its field): correct it first.', inputs: [] };
    const read = (id, name) => {
      const t = $(id).value.trim(), v = Number(t);
      return t === '' || !Number.isFinite(v) ? { error: `${name} = ${t === '' ? '(empty)' : t.slice(0, 20)}: must be a number`, inputs: [$(id)] } : { v };
    };
    const speed = read('busmap-speed', 'Speed at the operating point [kn]');
    if (speed.error) return speed;
    const p = this.pair(), out = {};
    for (const [axis, path] of [['x', p.x[0]], ['y', p.y[0]]]) {
      const u = shownUnit(path);
      const from = read(`busmap-${axis}-from`, `${axis} axis, ${u.label}, from [${u.unit}]`);
      const to = read(`busmap-${axis}-to`, `${axis} axis, ${u.label}, to [${u.unit}]`);
      const n = read(`busmap-${axis}-n`, `${axis} axis, ${u.label}, values`);
      for (const r of [from, to, n]) if (r.error) return r;
      out[axis] = { path, from: toSi(from.v, u.pow), to: toSi(to.v, u.pow), n: n.v };
    }
    const sc = JSON.parse(JSON.stringify(inp.scenario));
    sc.initial = { ...(sc.initial || {}), speed_kn: speed.v };
    return { scenario: JSON.stringify(sc), sc, x: out.x, y: out.y, title: inp.title, speed: speed.v };
  }

  // The boxes a refused request names are marked (aria-invalid, described by the status).
  markInvalid(inputs) {
    for (const i of document.querySelectorAll('#busmap [aria-invalid]')) { i.removeAttribute('aria-invalid'); i.removeAttribute('aria-errormessage'); }
    for (const i of inputs) { i.setAttribute('aria-invalid', 'true'); i.setAttribute('aria-errormessage', 'busmap-status'); }
  }

  // The boxes a message of the wasm is about: an axis's values or range, or the speed.
  inputsOf(message) {
    const m = message.match(/^([xy]) axis: (.*)/s);
    if (m) return /values/.test(m[2].split(':')[0]) ? [$(`busmap-${m[1]}-n`)] : [$(`busmap-${m[1]}-from`), $(`busmap-${m[1]}-to`)];
    if (/^a map of .* cells/.test(message)) return [$('busmap-x-n'), $('busmap-y-n')];
    if (/initial\.speed_kn/.test(message)) return [$('busmap-speed')];
    return [];
  }

  // The operating point and the study's spec from the first worker (the axes checked there),
  // then the rows over the pool; the map drawn is the study's summary.
  async compute() {
    if (this.fold.busy) return;
    const r = this.request();
    if (r.error) { this.fold.status(r.error, true); this.markInvalid(r.inputs); return; }
    this.markInvalid([]);
    const n = r.y.n, cells = r.x.n * r.y.n, started = performance.now();
    let point = null;
    await this.fold.compute(async () => {
      const { summary: map } = await this.pool.run({
        // A run in calm water has no seaway: its workers need no RAO table.
        kind: 'stability-map', scenario: r.scenario, n, item: 'row', rao: ((r.sc.sea || {}).kind || 'calm') !== 'calm',
        spec: async (w) => {
          const m = await w.request(REQUEST.stabilitySpec, { scenario: r.scenario, x: r.x, y: r.y });
          point = m.point;
          return m.spec;
        },
        onStart: (k) => this.fold.status(`Linearising the plant at ${cells} points on ${k} worker${k > 1 ? 's' : ''}...`),
        onProgress: (done, _, preparing) => this.fold.progress(done, n, started, 'row', preparing),
      });
      this.shown = { request: r, key: this.stateKey(), point, map, sc: r.sc };
      announce('busmap', { request: { scenario: r.scenario, x: r.x, y: r.y }, point, map });
      this.cell = null;
      this.show((performance.now() - started) / 1000);
    }, { onFail: (e) => this.markInvalid(this.inputsOf(e.message)) });
  }

  // What the map shown was computed from: the form's study and the controls.
  stateKey() {
    const r = this.request();
    return r.error ? null : JSON.stringify([r.scenario, r.x, r.y]);
  }

  // A map of other values is dimmed and said to be (the form or the controls changed).
  sync() {
    if (!this.shown) return;
    const stale = this.stateKey() !== this.shown.key;
    $('busmap-body').classList.toggle('stale', stale);
    if (stale) {
      this.fold.status('The study or the map\'s values changed since the map was computed: compute it again.');
    }
  }

  axes() { return axesOf(this.shown.map); }

  draw() {
    drawMap($('busmap-canvas'), this.shown, this.cell);
    this.drawnW = $('busmap-canvas').clientWidth;
  }

  show(seconds) {
    const { map, point, request: r, sc } = this.shown;
    const [ax, ay] = this.axes();
    $('busmap-body').hidden = false;
    $('busmap-body').classList.remove('stale');
    const sx = (v, a) => `${num(fromSi(v, a.pow))} ${a.unit}`;
    const own = [valueAt(sc, map.x.path), valueAt(sc, map.y.path)];
    const verdict = (a) => (a < 0 ? 'stable: every mode decays' : 'unstable: a mode grows');
    const mode = (hz) => (hz > 0 ? `its least damped mode rings at ${num(hz)} Hz` : 'its least damped mode does not oscillate (0 Hz)');
    const off = within(own[0], map.x.values) && within(own[1], map.y.values) ? '' : ' (outside the map\'s ranges: no ring is drawn)';
    $('busmap-point').textContent = `At the study's own values (${ax.label} ${sx(own[0], ax)}, ${ay.label} ${sx(own[1], ay)}, ${num(r.speed)} kn)${off}: spectral abscissa ${num(point.spectral_abscissa)} 1/s, ${verdict(point.spectral_abscissa)}; ${mode(point.least_damped_hz)}.`;
    $('busmap-title').textContent = `Spectral abscissa [1/s] over ${ax.label} [${ax.unit}] and ${ay.label} [${ay.unit}]: ${r.title}, at ${num(r.speed)} kn`;
    // The boundary by row, in words and as a table.
    const rows = map.y.values.map((y, j) => {
      const b = map.boundary_x[j], cells = map.abscissa[j].filter((a) => a != null);
      const where = b != null ? sx(b, ax) : cells.length && cells.every((a) => a < 0) ? 'none: stable across the row' : cells.length && cells.every((a) => a >= 0) ? 'none: unstable across the row' : 'not found in the row';
      return row(sx(y, ay), [where]);
    });
    $('busmap-table').replaceChildren(el('table', {}, el('caption', { textContent: `The boundary in ${ax.label} [${ax.unit}] at each ${ay.label} [${ay.unit}]` }),
      el('thead', {}, el('tr', {}, el('th', { scope: 'col', textContent: `${ay.label} [${ay.unit}]` }), el('th', { scope: 'col', textContent: `boundary [${ax.unit}]` }))), el('tbody', {}, ...rows)));
    const crossed = map.boundary_x.map((b, j) => [b, map.y.values[j]]).filter(([b]) => b != null);
    const all = map.abscissa.flat().filter((a) => a != null);
    const unstable = all.filter((a) => a >= 0).length;
    const along = crossed.length ? `the boundary runs from ${sx(crossed[0][0], ax)} at ${sx(crossed[0][1], ay)} to ${sx(crossed[crossed.length - 1][0], ax)} at ${sx(crossed[crossed.length - 1][1], ay)}` : 'no boundary crosses the map';
    $('busmap-canvas').setAttribute('aria-label', `Stability map over ${ax.label} ${sx(ax.values[0], ax)} to ${sx(ax.values[ax.values.length - 1], ax)} and ${ay.label} ${sx(ay.values[0], ay)} to ${sx(ay.values[ay.values.length - 1], ay)}: ${all.length - unstable} cells stable, ${unstable} unstable; ${along}.`);
    const failed = map.abscissa.flat().length - all.length;
    $('busmap-failures').hidden = !failed;
    $('busmap-failures').textContent = failed ? `${failed} cell(s) have no steady state (grey), for instance: ${map.failures.slice(0, 2).join('; ')}` : '';
    this.fold.status(`Done: ${all.length + failed} cells in ${seconds.toFixed(1)} s; ${unstable} unstable; ${crossed.length ? `the boundary crosses ${crossed.length} of ${map.y.values.length} rows` : 'no boundary within the map'}.`);
    $('busmap-readout').textContent = 'Point at a cell, or focus the map and move with the arrow keys.';
    this.draw();
  }

  // The cell under the pointer.
  hover(e) {
    if (!this.shown) return;
    const cv = $('busmap-canvas'), r = cv.getBoundingClientRect();
    const f = frame(this.shown, cv.clientWidth, r.height);
    const xv = f.x0 + ((e.clientX - r.left - f.m.l) / f.pw) * (f.x1 - f.x0);
    const yv = f.y0 + ((f.m.t + f.ph - (e.clientY - r.top)) / f.ph) * (f.y1 - f.y0);
    const { map } = this.shown;
    const i = Math.round((xv - map.x.values[0]) / f.dx), j = Math.round((yv - map.y.values[0]) / f.dy);
    if (i < 0 || j < 0 || i >= map.x.values.length || j >= map.y.values.length) return;
    this.select([i, j]);
  }

  // The study's own cell, or the middle one.
  startCell() {
    const { map, sc } = this.shown;
    const near = (vals, v) => (v == null ? Math.floor(vals.length / 2) : vals.reduce((b, x, k) => (Math.abs(x - v) < Math.abs(vals[b] - v) ? k : b), 0));
    return [near(map.x.values, valueAt(sc, map.x.path)), near(map.y.values, valueAt(sc, map.y.path))];
  }

  key(e) {
    if (!this.shown) return;
    const step = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[e.key];
    if (!step && e.key !== 'Home' && e.key !== 'End') return;
    e.preventDefault();
    const { map } = this.shown, [nx, ny] = [map.x.values.length, map.y.values.length];
    let [i, j] = this.cell || this.startCell();
    if (e.key === 'Home') i = 0;
    else if (e.key === 'End') i = nx - 1;
    else { i = Math.min(nx - 1, Math.max(0, i + step[0])); j = Math.min(ny - 1, Math.max(0, j + step[1])); }
    this.select([i, j]);
  }

  // Says cell [i, j]: its values, its abscissa and verdict in words, its least damped mode.
  select([i, j]) {
    if (this.cell && this.cell[0] === i && this.cell[1] === j) return;
    this.cell = [i, j];
    announce('busmapCell', [i, j]);
    const { map } = this.shown, [ax, ay] = this.axes();
    const a = map.abscissa[j][i], hz = map.least_damped_hz[j][i];
    const at = `${ax.label} ${num(fromSi(map.x.values[i], ax.pow))} ${ax.unit}, ${ay.label} ${num(fromSi(map.y.values[j], ay.pow))} ${ay.unit}`;
    let says;
    if (a == null) says = 'no steady state here (grey)';
    else {
      const verdict = a < 0 ? 'stable: every mode decays' : 'unstable: a mode grows';
      const mode = hz > 0 ? `the least damped mode rings at ${num(hz)} Hz` : 'the least damped mode does not oscillate (0 Hz)';
      says = `spectral abscissa ${num(a)} 1/s, ${verdict}; ${mode}`;
    }
    $('busmap-readout').textContent = `${at}: ${says}.`;
    this.draw();
  }
}
