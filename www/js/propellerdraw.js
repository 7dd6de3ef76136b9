// The propeller's expanded blade outline to scale on a canvas, from the rows the wasm gives
// (propellerCurves: each row's leading and trailing edge over D, skew already in them); returns
// what it drew (the browser test reads it). The hull panel's axes and labels (hulldraw.js).
import { PROPELLER } from './config.js';
import { num, prepare, axes, label } from './hulldraw.js';

// The outline: chordwise position x/D across, radius r/R up, one unit of r/R drawn as long as half
// a unit of x/D (R = D/2: the blade's true shape); the hub's radius shaded, the mid-chord line
// (where skew moves the sections) dashed.
export function drawOutline(canvas, sheet) {
  const C = PROPELLER.colors;
  const rows = sheet.rows;
  const xs = rows.flatMap((r) => [r.leading_d, r.trailing_d]);
  const half = Math.max(0.2, ...xs.map(Math.abs)) * 1.1; // x/D either side of the generator line
  const r0 = 0, r1 = 1.06;
  // Room on the left for tick labels of three decimals and the axis title beside them.
  const m = { l: 66, r: 12, t: 26, b: 42 };
  // Pixels per D: the width's or the tallest drawing's, whichever is smaller.
  const scaleOf = (w) => Math.min((w - m.l - m.r) / (2 * half), PROPELLER.outlineMaxPx / (0.5 * (r1 - r0)));
  const { g, w, h } = prepare(canvas, (W) => m.t + m.b + 0.5 * (r1 - r0) * scaleOf(W));
  const s = scaleOf(w);
  const box = { l: m.l, r: w - m.r, t: m.t, b: h - m.b };
  const cx = (box.l + box.r) / 2;
  const sx = (x) => cx + x * s, sy = (r) => box.b - 0.5 * (r - r0) * s;
  axes(g, box, sx, sy, [-(box.r - box.l) / 2 / s, (box.r - box.l) / 2 / s], [r0, r1 - 1e-9], ['chordwise position x/D [-] (leading edge left)', 'radius r/R [-]']);
  // The hub.
  g.fillStyle = C.hub; g.fillRect(box.l, sy(sheet.hub_ratio), box.r - box.l, box.b - sy(sheet.hub_ratio));
  // The blade: leading edge root to tip, trailing edge back.
  g.beginPath();
  rows.forEach((r, i) => (i ? g.lineTo(sx(r.leading_d), sy(r.r_r)) : g.moveTo(sx(r.leading_d), sy(r.r_r))));
  for (let i = rows.length - 1; i >= 0; i--) g.lineTo(sx(rows[i].trailing_d), sy(rows[i].r_r));
  g.closePath();
  g.fillStyle = C.bladeFill; g.fill();
  g.strokeStyle = C.blade; g.lineWidth = 1.8; g.stroke();
  // The mid-chord line and the rows' sections.
  g.strokeStyle = C.blade; g.lineWidth = 1; g.setLineDash([4, 3]);
  g.beginPath();
  rows.forEach((r, i) => { const x = sx((r.leading_d + r.trailing_d) / 2); if (i) g.lineTo(x, sy(r.r_r)); else g.moveTo(x, sy(r.r_r)); });
  g.stroke();
  g.setLineDash([]);
  g.strokeStyle = C.section; g.lineWidth = 1;
  for (const r of rows) { g.beginPath(); g.moveTo(sx(r.leading_d), sy(r.r_r)); g.lineTo(sx(r.trailing_d), sy(r.r_r)); g.stroke(); }
  g.font = '12px system-ui, sans-serif';
  g.textAlign = 'left';
  label(g, `hub, ${num(sheet.hub_ratio)} D`, box.l + 4, sy(sheet.hub_ratio) - 3, C.text);
  const skewed = rows.some((r) => r.skew_deg !== 0);
  // Above the frame, the longest of these that fits.
  const says = [`${sheet.blades} blades, Ae/A0 ${num(sheet.area_ratio)}; dashed: mid-chord${skewed ? ' (skewed)' : ', no skew'}`,
    `${sheet.blades} blades, Ae/A0 ${num(sheet.area_ratio)}; dashed: mid-chord`, `${sheet.blades} blades, Ae/A0 ${num(sheet.area_ratio)}`];
  label(g, says.find((t) => g.measureText(t).width <= box.r - box.l) || says[says.length - 1], box.l, box.t - 5, C.text);
  return { rows: rows.length, scale_px_per_d: s, width_px: w, height_px: h };
}
