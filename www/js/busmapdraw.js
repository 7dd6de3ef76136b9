// The bus stability map's drawing (busmap.js computes and says it): the cells coloured by their
// spectral abscissa on a symmetric-logarithmic scale, unstable ones hatched, the boundary, the
// axes in their shown units, the colour bar, the cell said and the study's own values.
import { BUSMAP } from './config.js';
import { param } from './registry.js';
import { sizedCanvas } from './plots.js';

// A number with 3 significant digits, a tiny float's noise shown as 0 against the scale.
export const num = (v, d = 3) => Number(Number(v).toPrecision(d)).toString();

// How a parameter's SI unit is shown: {unit, pow} (value shown = SI / 10^pow).
export function shownUnit(path) {
  const p = param(path);
  const [unit, pow] = BUSMAP.shown[p.unit] || [p.unit, 0];
  return { unit, pow, label: p.label };
}
export const toSi = (v, pow) => (pow >= 0 ? v * 10 ** pow : v / 10 ** -pow);
export const fromSi = (v, pow) => (pow >= 0 ? v / 10 ** pow : v * 10 ** -pow);
export const valueAt = (sc, path) => path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), sc);
// Whether v lies within an axis's values.
export const within = (v, vals) => v >= vals[0] && v <= vals[vals.length - 1];

// The symmetric-logarithmic coordinate of an abscissa [1/s].
const slog = (a) => Math.sign(a) * Math.log10(1 + Math.abs(a) / BUSMAP.linear1PerS);

// The map's two axes: label, shown unit and values.
export const axesOf = (map) => [map.x, map.y].map((a) => ({ ...shownUnit(a.path), values: a.values }));

// The plot's frame: margins and the value-to-pixel maps (cells centred on their values).
export function frame(shown, w, h) {
  const [ax, ay] = axesOf(shown.map);
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
function colourer(map) {
  const all = map.abscissa.flat().filter((a) => a != null);
  const lo = Math.min(-BUSMAP.linear1PerS, ...all), hi = Math.max(BUSMAP.linear1PerS, ...all);
  const { stable, zero, unstable } = BUSMAP.colors;
  const mix = (c, t) => `rgb(${zero.map((z, k) => Math.round(z + (c[k] - z) * t)).join(',')})`;
  const colour = (a) => (a < 0 ? mix(stable, 0.33 + 0.67 * slog(a) / slog(lo)) : mix(unstable, 0.33 + 0.67 * slog(a) / slog(hi)));
  return { lo, hi, colour };
}

export function drawMap(cv, shown, cell) {
  const phone = window.innerWidth < BUSMAP.phoneBelowPx;
  const { g, w, h } = sizedCanvas(cv, phone ? BUSMAP.phoneHeightPx : BUSMAP.heightPx);
  const f = frame(shown, w, h);
  const { map } = shown;
  const { lo, hi, colour } = colourer(map);
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
  axesDrawn(g, f, w, h);
  colourBar(g, f, w, lo, hi, colour);
  if (cell) {
    const [i, j] = cell, x = map.x.values[i], y = map.y.values[j];
    g.lineWidth = 2; g.strokeStyle = '#000';
    g.strokeRect(f.px(x - f.dx / 2), f.py(y + f.dy / 2), f.px(x + f.dx / 2) - f.px(x - f.dx / 2), f.py(y - f.dy / 2) - f.py(y + f.dy / 2));
  }
  // The study's own values, where they fall inside the map.
  const own = [valueAt(shown.sc, map.x.path), valueAt(shown.sc, map.y.path)];
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
function axesDrawn(g, f, w, h) {
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
function colourBar(g, f, w, lo, hi, colour) {
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
