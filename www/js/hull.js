// The hull (issue 15): the picker in the scenario form (embedded hulls by name, "load offsets" from
// a CSV file chosen or dropped on the page, or a whole scenario file), and the hull panel: body
// plan, profile and hydrostatics of the scenario's hull at its loading. Every number comes from the
// wasm (hullSheet, validateScenario); the offsets are parsed by the same Rust code as the command
// line. This module only draws and moves text.
import { choiceLabel, migrate } from './registry.js';
import { HULL } from './config.js';
import { $, el } from './dom.js';
import { REQUEST, fieldLine } from './protocol.js';

const FILE_FIELD = 'ship.hull.offsets_csv';
const FILE_INPUT = 'f-ship-hull-offsets_csv';
// The largest file read (the Rust side bounds a scenario at 4 MiB and says so past it).
const MAX_FILE_BYTES = 4 << 20;
const clone = (x) => JSON.parse(JSON.stringify(x));

// A number for the table and the labels: about four significant digits, no exponent.
export function num(x) {
  if (x == null || !Number.isFinite(x)) return '–';
  const a = Math.abs(x);
  if (a >= 1000) return Math.round(x).toLocaleString('en-US');
  if (a >= 100) return x.toFixed(1);
  if (a >= 10) return x.toFixed(2);
  return x.toFixed(a >= 1 || a === 0 ? 2 : 3);
}

const hullTitle = (sheet, file) => (file ? `custom hull (${file})` : sheet.profile.name);

// A tick step of about `n` ticks over `span`: 1, 2 or 5 times a power of ten.
function tickStep(span, n) {
  const raw = span / Math.max(1, n);
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((k) => k * p).find((s) => s >= raw) || 10 * p;
}

// A canvas sized to its box (CSS width, height in CSS pixels) at the device's pixel ratio.
function prepare(canvas, height) {
  const w = Math.max(200, canvas.clientWidth || canvas.parentElement.clientWidth);
  canvas.style.height = `${Math.round(height(w))}px`;
  const h = Math.round(height(w));
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, w, h);
  g.font = '12px system-ui, sans-serif';
  g.lineJoin = 'round';
  return { g, w, h };
}

// Axes in metres: a frame, ticks and their labels, the axis titles. sx, sy map metres to pixels;
// xLabel(v) writes a tick's value (the body plan writes half-breadths without sign).
function axes(g, box, sx, sy, [x0, x1], [y0, y1], titles, xLabel = num) {
  const C = HULL.colors;
  g.strokeStyle = C.grid; g.lineWidth = 1; g.fillStyle = C.axis;
  const dx = tickStep(x1 - x0, Math.max(2, Math.floor((box.r - box.l) / 70)));
  const dy = tickStep(y1 - y0, Math.max(2, Math.floor((box.b - box.t) / 36)));
  g.textAlign = 'center'; g.textBaseline = 'top';
  for (let v = Math.ceil(x0 / dx) * dx; v <= x1 + 1e-9; v += dx) {
    const X = sx(v);
    g.beginPath(); g.moveTo(X, box.t); g.lineTo(X, box.b); g.stroke();
    g.fillText(xLabel(Number(v.toPrecision(6))).replace(/\.0+$/, ''), X, box.b + 4);
  }
  g.textAlign = 'right'; g.textBaseline = 'middle';
  for (let v = Math.ceil(y0 / dy) * dy; v <= y1 + 1e-9; v += dy) {
    const Y = sy(v);
    g.beginPath(); g.moveTo(box.l, Y); g.lineTo(box.r, Y); g.stroke();
    g.fillText(num(Number(v.toPrecision(6))).replace(/\.0+$/, ''), box.l - 5, Y);
  }
  g.strokeStyle = C.axis;
  g.strokeRect(box.l, box.t, box.r - box.l, box.b - box.t);
  g.fillStyle = C.text; g.textAlign = 'center'; g.textBaseline = 'bottom';
  g.fillText(titles[0], (box.l + box.r) / 2, box.b + 34);
  g.save();
  g.translate(13, (box.t + box.b) / 2); g.rotate(-Math.PI / 2);
  g.textBaseline = 'middle';
  g.fillText(titles[1], 0, 0);
  g.restore();
}

// The rows of a station that belong to the hull: from the last row without breadth below the first
// with breadth (the keel or a transom's lower edge) to the highest row with breadth (as HullProfile).
function stationRows(s) {
  const first = s.half_breadth_m.findIndex((b) => b > 0);
  if (first < 0) return [];
  let top = s.half_breadth_m.length - 1;
  while (top > 0 && !(s.half_breadth_m[top] > 0)) top--;
  const out = [];
  for (let i = Math.max(0, first - 1); i <= top; i++) out.push([s.half_breadth_m[i], s.z_m[i]]);
  return out;
}

// The body plan: sections of the aft half on the left, the forward half on the right (the naval
// architects' convention), at 1:1 scale, waterline marked. Returns what was drawn (for the test).
export function drawBodyPlan(canvas, sheet) {
  const C = HULL.colors;
  const xs = sheet.stations.map((s) => s.x_m);
  const mid = (Math.min(...xs) + Math.max(...xs)) / 2;
  const secs = sheet.stations.map((s) => ({ x: s.x_m, rows: stationRows(s) })).filter((s) => s.rows.length);
  const ymax = Math.max(...secs.flatMap((s) => s.rows.map((r) => r[0])), sheet.beam_m / 2) * 1.08;
  const zs = secs.flatMap((s) => s.rows.map((r) => r[1]));
  const z0 = Math.min(0, ...zs), z1 = Math.max(...zs, sheet.draft_m) + 0.04 * (Math.max(...zs) - z0);
  const m = { l: 52, r: 12, t: 26, b: 42 };
  const scaleOf = (w) => Math.min((w - m.l - m.r) / (2 * ymax), 420 / (z1 - z0));
  const { g, w, h } = prepare(canvas, (W) => m.t + m.b + (z1 - z0) * scaleOf(W));
  const s = scaleOf(w);
  const cx = m.l + (w - m.l - m.r) / 2;
  const box = { l: m.l, r: w - m.r, t: m.t, b: h - m.b };
  const sx = (y) => cx + y * s, sy = (z) => box.b - (z - z0) * s;
  axes(g, box, sx, sy, [-(w - m.l - m.r) / 2 / s, (w - m.l - m.r) / 2 / s], [z0, z1 - 1e-9],
    ['half-breadth [m]', 'height above base [m]'], (v) => num(Math.abs(v)));
  // Water below the waterline, the waterline, the centreline.
  g.fillStyle = C.waterFill; g.fillRect(box.l, sy(sheet.draft_m), box.r - box.l, box.b - sy(sheet.draft_m));
  g.strokeStyle = C.axis; g.setLineDash([4, 3]); g.beginPath(); g.moveTo(cx, box.t); g.lineTo(cx, box.b); g.stroke();
  g.setLineDash([]);
  g.strokeStyle = C.hull; g.lineWidth = 1.4;
  let aft = 0, fore = 0;
  for (const sec of secs) {
    for (const side of sec.x < mid - 1e-9 ? [-1] : sec.x > mid + 1e-9 ? [1] : [-1, 1]) {
      if (side < 0) aft++; else fore++;
      g.beginPath();
      sec.rows.forEach(([b, z], i) => (i ? g.lineTo(sx(side * b), sy(z)) : g.moveTo(sx(side * b), sy(z))));
      g.stroke();
    }
  }
  g.strokeStyle = C.water; g.lineWidth = 2.5;
  g.beginPath(); g.moveTo(box.l, sy(sheet.draft_m)); g.lineTo(box.r, sy(sheet.draft_m)); g.stroke();
  g.fillStyle = C.text; g.textBaseline = 'bottom';
  g.textAlign = 'left'; g.fillText('aft half', box.l + 4, box.t - 6);
  g.textAlign = 'right'; g.fillText('forward half', box.r - 4, box.t - 6);
  g.textAlign = 'left'; g.textBaseline = 'bottom';
  label(g, `waterline, T = ${num(sheet.draft_m)} m`, box.l + 4, sy(sheet.draft_m) - 3, C.water);
  return { stations: secs.length, aft, fore, scale_px_per_m: s };
}

// Text on a white ground (readable over the lines), baseline 'bottom', the current alignment.
function label(g, text, x, y, color) {
  const w = g.measureText(text).width, x0 = g.textAlign === 'right' ? x - w : g.textAlign === 'center' ? x - w / 2 : x;
  g.fillStyle = 'rgba(255, 255, 255, 0.85)';
  g.fillRect(x0 - 2, y - 14, w + 4, 15);
  g.fillStyle = color;
  g.textBaseline = 'bottom';
  g.fillText(text, x, y);
}

// Linear interpolation of ys over increasing xs at x (ends held).
function interp(xs, ys, x) {
  if (!xs.length) return 0;
  if (x <= xs[0]) return ys[0];
  for (let i = 1; i < xs.length; i++) if (x <= xs[i]) return ys[i - 1] + ((ys[i] - ys[i - 1]) * (x - xs[i - 1])) / (xs[i] - xs[i - 1]);
  return ys[ys.length - 1];
}

// The profile (side view, bow to the right): keel and deck lines, waterline, the propeller disc at
// its hub height with its diameter, the rudder (at its position; blade size schematic), G and B.
// 1:1 scale unless the drawing would be flatter than HULL.minDrawPx: then heights are stretched by
// a whole factor, said on the vertical axis.
export function drawProfile(canvas, sheet) {
  const C = HULL.colors, p = sheet.profile, T = sheet.draft_m, D = sheet.propeller_diameter_m;
  const keel = p.keel_z_m.map((z) => z + T), deck = p.deck_z_m.map((z) => z + T);
  const hub = sheet.hub_above_base_m, px = sheet.propeller_x_m, rx = sheet.rudder_x_m;
  const xa = Math.min(...p.x_m, px - 0.6 * D, rx - 0.6 * D), xb = Math.max(...p.x_m);
  const pad = 0.03 * (xb - xa);
  const x0 = xa - pad, x1 = xb + pad;
  // The rudder: a blade from the hull's bottom at its position down to the propeller's lower tip.
  const rTop = interp(p.x_m, keel, rx), rLow = Math.min(rTop - 0.5 * D, hub - D / 2), chord = 0.5 * D;
  const z0 = Math.min(0, ...keel, hub - 0.6 * D, rLow - 0.05 * D), zTop = Math.max(...deck, T);
  const z1 = zTop + 0.08 * (zTop - z0);
  const m = { l: 52, r: 12, t: 24, b: 42 };
  const s = (w) => (w - m.l - m.r) / (x1 - x0);
  const stretch = (w) => Math.max(1, Math.ceil(HULL.minDrawPx / ((z1 - z0) * s(w))));
  const { g, w, h } = prepare(canvas, (W) => m.t + m.b + (z1 - z0) * s(W) * stretch(W));
  const k = stretch(w), sh = s(w);
  const box = { l: m.l, r: w - m.r, t: m.t, b: h - m.b };
  const sx = (x) => box.l + (x - x0) * sh, sy = (z) => box.b - (z - z0) * sh * k;
  axes(g, box, sx, sy, [x0, x1], [z0, z1 - 1e-9],
    ['x from the aft perpendicular [m]', 'height above base [m]']);
  g.fillStyle = C.waterFill; g.fillRect(box.l, sy(T), box.r - box.l, box.b - sy(T));
  // The hull: keel line aft to fore, deck line back.
  g.beginPath();
  p.x_m.forEach((x, i) => (i ? g.lineTo(sx(x), sy(keel[i])) : g.moveTo(sx(x), sy(keel[i]))));
  for (let i = p.x_m.length - 1; i >= 0; i--) g.lineTo(sx(p.x_m[i]), sy(deck[i]));
  g.closePath();
  g.fillStyle = C.fill; g.fill();
  g.strokeStyle = C.hull; g.lineWidth = 1.8; g.stroke();
  g.fillStyle = C.rudder; g.globalAlpha = 0.85;
  g.fillRect(sx(rx - chord / 2), sy(rTop), Math.max(2, chord * sh), Math.max(2, sy(rLow) - sy(rTop)));
  g.globalAlpha = 1;
  // The propeller disc seen from the side (a thin ellipse, its height the diameter) and its hub.
  g.strokeStyle = C.prop; g.lineWidth = 2;
  g.beginPath(); g.ellipse(sx(px), sy(hub), Math.max(2.5, 0.1 * D * sh), (D / 2) * sh * k, 0, 0, 2 * Math.PI); g.stroke();
  g.fillStyle = C.prop; g.beginPath(); g.arc(sx(px), sy(hub), 3, 0, 2 * Math.PI); g.fill();
  // Waterline.
  g.strokeStyle = C.water; g.lineWidth = 2.5;
  g.beginPath(); g.moveTo(box.l, sy(T)); g.lineTo(box.r, sy(T)); g.stroke();
  // G and B.
  g.fillStyle = C.text; g.font = 'bold 12px system-ui, sans-serif'; g.textAlign = 'center'; g.textBaseline = 'middle';
  const mark = (x, z, t, up) => { g.beginPath(); g.arc(sx(x), sy(z), 3, 0, 2 * Math.PI); g.fill(); g.fillText(t, sx(x) + 10, sy(z) + (up ? -8 : 8)); };
  mark(p.lcg_m, sheet.kg_m, 'G', sheet.kg_m >= sheet.kb_m);
  mark(sheet.lcb_m, sheet.kb_m, 'B', sheet.kb_m > sheet.kg_m);
  // Labels: the waterline on the right, the propeller and rudder on the left, above the water.
  g.font = '12px system-ui, sans-serif'; g.textBaseline = 'bottom';
  g.textAlign = 'right';
  label(g, `waterline, T = ${num(T)} m`, box.r - 4, sy(T) - 3, C.water);
  // Above the frame: what the red and orange shapes are, and the vertical scale.
  const kText = k > 1 ? `heights drawn ×${k}` : '';
  const room = box.r - box.l - (kText ? g.measureText(kText).width + 12 : 0);
  const says = [`propeller (red) D = ${num(D)} m, hub ${num(hub)} m above base, h0 = ${num(sheet.hub_depth_m)} m; rudder (orange, size schematic)`,
    `propeller D = ${num(D)} m, h0 = ${num(sheet.hub_depth_m)} m; rudder (orange)`, `D = ${num(D)} m, h0 = ${num(sheet.hub_depth_m)} m`];
  g.textAlign = 'left';
  label(g, says.find((t) => g.measureText(t).width <= room) || says[says.length - 1], box.l, box.t - 5, C.prop);
  if (kText) { g.textAlign = 'right'; label(g, kText, box.r, box.t - 5, C.text); }
  return { stretch: k, scale_px_per_m: sh, propeller: { x_px: sx(px), hub_px: sy(hub), radius_px: (D / 2) * sh * k }, waterline_px: sy(T) };
}

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
    this.drawn = null; // what the drawings hold (the test reads it through window.__hullPanel)
    window.__hullPanel = this;
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
