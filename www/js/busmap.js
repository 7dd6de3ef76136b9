// The bus stability map on the stability tab (issue 44, core's studies::stability_map, `aes-sim
// stability-map`): the whole plant with its bus loads and storage linearised at the form's study,
// its spectral abscissa coloured over two parameters with the boundary where it crosses zero, the
// study's own point marked, and a cell's value, verdict and least damped mode said on hover or
// keyboard focus. Every number is the wasm's; here the pairs offered, units shown and drawing.
import { BUSMAP } from './config.js';
import { $, el, row } from './dom.js';
import { REQUEST, fieldLine } from './protocol.js';
import { param } from './registry.js';
import { sizedCanvas } from './plots.js';

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
        <button id="busmap-cancel" type="button" disabled>Cancel</button></div>
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

// A number with 3 significant digits, a tiny float's noise shown as 0 against the scale.
const num = (v, d = 3) => Number(Number(v).toPrecision(d)).toString();

// How a parameter's SI unit is shown: {unit, pow} (value shown = SI / 10^pow).
function shownUnit(path) {
  const p = param(path);
  const [unit, pow] = BUSMAP.shown[p.unit] || [p.unit, 0];
  return { unit, pow, label: p.label };
}
const toSi = (v, pow) => (pow >= 0 ? v * 10 ** pow : v / 10 ** -pow);
const fromSi = (v, pow) => (pow >= 0 ? v / 10 ** pow : v * 10 ** -pow);
const valueAt = (sc, path) => path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), sc);

// The symmetric-logarithmic coordinate of an abscissa [1/s].
const slog = (a) => Math.sign(a) * Math.log10(1 + Math.abs(a) / BUSMAP.linear1PerS);

export class BusMap {
  // ctx: the page's context (the form's study and the worker).
  constructor(ctx) {
    this.ctx = ctx;
    this.shown = null; // {request, key, point, map, sc}
    this.cell = null; // [i, j] of the cell said
    $('busmap-pair').addEventListener('change', () => this.pairChosen());
    $('busmap-compute').addEventListener('click', () => this.compute());
    // Cancel stops the worker (the page starts a fresh one); the map shown stays.
    $('busmap-cancel').addEventListener('click', () => this.ctx.cancel());
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

  fail(text, inputs) {
    $('busmap-status').textContent = text;
    $('busmap-status').className = 'error';
    this.markInvalid(inputs);
  }

  async compute() {
    const r = this.request();
    if (r.error) { this.fail(r.error, r.inputs); return; }
    this.markInvalid([]);
    const cells = r.x.n * r.y.n;
    $('busmap-compute').disabled = true;
    $('busmap-cancel').disabled = false;
    $('busmap-status').className = '';
    $('busmap-status').textContent = `Linearising the plant at ${cells} points...`;
    const t0 = performance.now();
    try {
      const m = await this.ctx.client.request(REQUEST.stabilityMap, { scenario: r.scenario, x: r.x, y: r.y }, (p) => {
        $('busmap-status').textContent = `Linearising the plant: row ${p.rows} of ${p.of}...`;
      });
      this.shown = { request: r, key: this.stateKey(), point: m.point, map: m.map, sc: r.sc };
      window.__busmap = { request: { scenario: r.scenario, x: r.x, y: r.y }, point: m.point, map: m.map };
      this.cell = null;
      this.show((performance.now() - t0) / 1000);
    } catch (e) {
      if (e.cancelled) { $('busmap-status').textContent = 'Cancelled.'; return; }
      const text = e.fields && e.fields.length ? `The scenario is refused: ${e.fields.slice(0, 3).map(fieldLine).join('; ')}` : `The map could not be computed: ${e.message}`;
      this.fail(text, this.inputsOf(e.message));
    } finally {
      $('busmap-compute').disabled = false;
      $('busmap-cancel').disabled = true;
    }
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
      $('busmap-status').className = '';
      $('busmap-status').textContent = 'The study or the map\'s values changed since the map was computed: compute it again.';
    }
  }

  axes() {
    const { map } = this.shown;
    return [map.x, map.y].map((a) => ({ ...shownUnit(a.path), values: a.values }));
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
    const within = (v, vals) => v >= vals[0] && v <= vals[vals.length - 1];
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
    $('busmap-status').className = '';
    $('busmap-status').textContent = `Done: ${all.length + failed} cells in ${seconds.toFixed(1)} s; ${unstable} unstable; ${crossed.length ? `the boundary crosses ${crossed.length} of ${map.y.values.length} rows` : 'no boundary within the map'}.`;
    $('busmap-readout').textContent = 'Point at a cell, or focus the map and move with the arrow keys.';
    this.draw();
  }

  // The plot's frame: margins and the value-to-pixel maps (cells centred on their values).
  frame(w, h) {
    const [ax, ay] = this.axes();
    const m = { l: 58, r: 84, t: 10, b: 44 };
    const span = (v) => {
      const d = v.length > 1 ? (v[v.length - 1] - v[0]) / (v.length - 1) : 1;
      return [v[0] - d / 2, v[v.length - 1] + d / 2, d];
    };
    const [x0, x1, dx] = span(ax.values), [y0, y1, dy] = span(ay.values);
    const pw = w - m.l - m.r, ph = h - m.t - m.b;
    const px = (x) => m.l + ((x - x0) / (x1 - x0)) * pw, py = (y) => m.t + ph - ((y - y0) / (y1 - y0)) * ph;
    return { m, pw, ph, px, py, x0, x1, y0, y1, dx, dy, ax, ay };
  }

  // The colour of an abscissa: blue to red through near white, at least a third of the way from
  // white on either side so that the sign always shows.
  colourer() {
    const all = this.shown.map.abscissa.flat().filter((a) => a != null);
    const lo = Math.min(-BUSMAP.linear1PerS, ...all), hi = Math.max(BUSMAP.linear1PerS, ...all);
    const { stable, zero, unstable } = BUSMAP.colors;
    const mix = (c, t) => `rgb(${zero.map((z, k) => Math.round(z + (c[k] - z) * t)).join(',')})`;
    const colour = (a) => (a < 0 ? mix(stable, 0.33 + 0.67 * slog(a) / slog(lo)) : mix(unstable, 0.33 + 0.67 * slog(a) / slog(hi)));
    return { lo, hi, colour };
  }

  draw() {
    const cv = $('busmap-canvas');
    const phone = window.innerWidth < BUSMAP.phoneBelowPx;
    const { g, w, h } = sizedCanvas(cv, phone ? BUSMAP.phoneHeightPx : BUSMAP.heightPx);
    this.drawnW = cv.clientWidth;
    const f = this.frame(w, h);
    const { map } = this.shown;
    const { lo, hi, colour } = this.colourer();
    g.fillStyle = '#fff'; g.fillRect(0, 0, w, h);
    // Cells, and a hatch over the unstable ones (the verdict not by colour alone).
    const hatch = document.createElement('canvas');
    hatch.width = hatch.height = 8;
    const hg = hatch.getContext('2d');
    hg.strokeStyle = 'rgba(90,0,0,0.45)'; hg.lineWidth = 1; hg.beginPath(); hg.moveTo(0, 8); hg.lineTo(8, 0); hg.stroke();
    const pattern = g.createPattern(hatch, 'repeat');
    map.y.values.forEach((y, j) => map.x.values.forEach((x, i) => {
      const a = map.abscissa[j][i];
      const X0 = f.px(x - f.dx / 2), X1 = f.px(x + f.dx / 2), Y0 = f.py(y + f.dy / 2), Y1 = f.py(y - f.dy / 2);
      g.fillStyle = a == null ? BUSMAP.colors.failed : colour(a);
      g.fillRect(Math.floor(X0), Math.floor(Y0), Math.ceil(X1) - Math.floor(X0), Math.ceil(Y1) - Math.floor(Y0));
      if (a != null && a >= 0) { g.fillStyle = pattern; g.fillRect(X0, Y0, X1 - X0, Y1 - Y0); }
    }));
    g.strokeStyle = '#666'; g.lineWidth = 1; g.strokeRect(f.m.l + 0.5, f.m.t + 0.5, f.pw - 1, f.ph - 1);
    // The boundary: white under black, broken where a row has none.
    for (const [width, style] of [[5, '#fff'], [2.5, '#000']]) {
      g.strokeStyle = style; g.lineWidth = width; g.lineJoin = 'round'; g.beginPath();
      let on = false;
      map.boundary_x.forEach((b, j) => {
        if (b == null) { on = false; return; }
        const X = f.px(b), Y = f.py(map.y.values[j]);
        if (on) g.lineTo(X, Y); else g.moveTo(X, Y);
        on = true;
      });
      g.stroke();
      // A row alone is a short tick across it.
      map.boundary_x.forEach((b, j) => {
        if (b == null || map.boundary_x[j - 1] != null || map.boundary_x[j + 1] != null) return;
        const X = f.px(b), Y = f.py(map.y.values[j]), half = Math.abs(f.py(f.dy / 2) - f.py(0));
        g.beginPath(); g.moveTo(X, Y - half); g.lineTo(X, Y + half); g.stroke();
      });
    }
    this.axesDrawn(g, f, w, h);
    this.colourBar(g, f, w, lo, hi, colour);
    if (this.cell) {
      const [i, j] = this.cell, x = map.x.values[i], y = map.y.values[j];
      g.lineWidth = 2; g.strokeStyle = '#000';
      g.strokeRect(f.px(x - f.dx / 2), f.py(y + f.dy / 2), f.px(x + f.dx / 2) - f.px(x - f.dx / 2), f.py(y - f.dy / 2) - f.py(y + f.dy / 2));
    }
    // The study's own values, where they fall inside the map.
    const own = [valueAt(this.shown.sc, map.x.path), valueAt(this.shown.sc, map.y.path)];
    const within = (v, vals) => v >= vals[0] && v <= vals[vals.length - 1];
    if (within(own[0], map.x.values) && within(own[1], map.y.values)) {
      const X = f.px(own[0]), Y = f.py(own[1]);
      g.lineWidth = 3; g.strokeStyle = '#fff'; g.beginPath(); g.arc(X, Y, 7, 0, 2 * Math.PI); g.stroke();
      g.lineWidth = 2; g.strokeStyle = '#000'; g.beginPath(); g.arc(X, Y, 7, 0, 2 * Math.PI); g.stroke();
      g.font = '12px system-ui'; g.fillStyle = '#000';
      const t = 'this study', tw = g.measureText(t).width;
      const tx = X + 10 + tw < f.m.l + f.pw ? X + 10 : X - 10 - tw;
      g.fillStyle = 'rgba(255,255,255,0.85)'; g.fillRect(tx - 2, Y - 19, tw + 4, 15);
      g.fillStyle = '#000'; g.fillText(t, tx, Y - 7);
    }
  }

  // Ticks at round values of each axis, in its shown unit, and the axis titles with units.
  axesDrawn(g, f, w, h) {
    g.fillStyle = '#1b1b1b'; g.strokeStyle = '#444'; g.lineWidth = 1; g.font = '12px system-ui';
    const ticks = (a, b, px) => {
      // At most one tick a 60 px, and at least three where the range allows.
      const want = Math.max(3, Math.floor(px / 60));
      const raw = (b - a) / (want + 1), p = 10 ** Math.floor(Math.log10(raw));
      const step = [1, 2, 2.5, 5, 10].map((k) => k * p).find((s) => s >= raw);
      const out = [];
      for (let v = Math.ceil(a / step) * step; v <= b + step * 1e-9; v += step) out.push(Number(v.toPrecision(12)));
      return out;
    };
    const sxLo = fromSi(f.x0, f.ax.pow), sxHi = fromSi(f.x1, f.ax.pow);
    g.textAlign = 'center'; g.textBaseline = 'top';
    for (const v of ticks(sxLo, sxHi, f.pw)) {
      const X = f.px(toSi(v, f.ax.pow));
      g.beginPath(); g.moveTo(X, f.m.t + f.ph); g.lineTo(X, f.m.t + f.ph + 4); g.stroke();
      g.fillText(String(v), X, f.m.t + f.ph + 6);
    }
    g.fillText(`${f.ax.label} [${f.ax.unit}]`, f.m.l + f.pw / 2, h - 16);
    const syLo = fromSi(f.y0, f.ay.pow), syHi = fromSi(f.y1, f.ay.pow);
    g.textAlign = 'right'; g.textBaseline = 'middle';
    for (const v of ticks(syLo, syHi, f.ph * 1.4)) {
      const Y = f.py(toSi(v, f.ay.pow));
      g.beginPath(); g.moveTo(f.m.l - 4, Y); g.lineTo(f.m.l, Y); g.stroke();
      g.fillText(String(v), f.m.l - 6, Y);
    }
    g.save(); g.translate(14, f.m.t + f.ph / 2); g.rotate(-Math.PI / 2); g.textAlign = 'center';
    g.fillText(`${f.ay.label} [${f.ay.unit}]`, 0, 0); g.restore();
    g.textAlign = 'left'; g.textBaseline = 'alphabetic';
  }

  // The colour bar at the right: the abscissa's range on the same symmetric-log scale, zero
  // marked, its unit 1/s.
  colourBar(g, f, w, lo, hi, colour) {
    const X = w - f.m.r + 12, W = 12, top = f.m.t, H = f.ph;
    const s0 = slog(lo), s1 = slog(hi);
    const yOf = (a) => top + H - ((slog(a) - s0) / (s1 - s0)) * H;
    for (let k = 0; k < H; k++) {
      const s = s1 - ((k + 0.5) / H) * (s1 - s0);
      const a = Math.sign(s) * (10 ** Math.abs(s) - 1) * BUSMAP.linear1PerS;
      g.fillStyle = colour(a); g.fillRect(X, top + k, W, 1);
    }
    g.strokeStyle = '#444'; g.lineWidth = 1; g.strokeRect(X + 0.5, top + 0.5, W - 1, H - 1);
    g.font = '11px system-ui'; g.fillStyle = '#1b1b1b'; g.textBaseline = 'middle'; g.textAlign = 'left';
    const marks = [lo, 0, hi];
    for (let k = -3; k <= 3; k++) for (const sgn of [-1, 1]) { const v = sgn * 10 ** k; if (v > lo && v < hi) marks.push(v); }
    const placed = [];
    for (const v of marks) {
      const Y = yOf(v);
      if (placed.some((p) => Math.abs(p - Y) < 13)) continue;
      placed.push(Y);
      g.beginPath(); g.moveTo(X + W, Y); g.lineTo(X + W + 3, Y); g.stroke();
      g.fillText(v === 0 ? '0' : num(v, 2), X + W + 5, Y);
    }
    g.save(); g.translate(w - 6, top + H / 2); g.rotate(-Math.PI / 2); g.textAlign = 'center'; g.textBaseline = 'bottom';
    g.fillText('spectral abscissa [1/s]', 0, 0); g.restore();
    g.textBaseline = 'alphabetic';
  }

  // The cell under the pointer.
  hover(e) {
    if (!this.shown) return;
    const cv = $('busmap-canvas'), r = cv.getBoundingClientRect();
    const f = this.frame(cv.clientWidth, r.height);
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
    window.__busmapCell = [i, j];
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
