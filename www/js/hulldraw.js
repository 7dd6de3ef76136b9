// The hull's two drawings to scale, body plan and profile, on canvases from the sheet the wasm
// computes (hullSheet); each returns what it drew (the browser test reads it).
import { HULL } from './config.js';

// A number for the table and the labels: about four significant digits, no exponent.
export function num(x) {
  if (x == null || !Number.isFinite(x)) return '–';
  const a = Math.abs(x);
  if (a >= 1000) return Math.round(x).toLocaleString('en-US');
  if (a >= 100) return x.toFixed(1);
  if (a >= 10) return x.toFixed(2);
  return x.toFixed(a >= 1 || a === 0 ? 2 : 3);
}

// A tick step of about `n` ticks over `span`: 1, 2 or 5 times a power of ten.
function tickStep(span, n) {
  const raw = span / Math.max(1, n);
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((k) => k * p).find((s) => s >= raw) || 10 * p;
}

// A canvas sized to its box (CSS width, height in CSS pixels) at the device's pixel ratio.
export function prepare(canvas, height) {
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
export function axes(g, box, sx, sy, [x0, x1], [y0, y1], titles, xLabel = num) {
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
export function label(g, text, x, y, color) {
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
