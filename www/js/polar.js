// The operability polar on a canvas: speed outwards from 0 at the centre, the wave heading around
// it seen from above with the bow up (180 deg, head seas, at the top; 90 deg, waves from starboard,
// on the right; 270 deg, from port, on the left; 0 deg, following seas, at the bottom), each cell a
// wedge coloured by its limiting H_1/3. Geometry, colour scale and hit testing; no physics.
import { OPERABILITY } from './config.js';

const mod360 = (x) => ((x % 360) + 360) % 360;
// Circular distance of two angles [deg].
const apart = (a, b) => Math.abs(mod360(a - b + 180) - 180);

// The colour scale of a polar: bins of one step over the limits that occur (the whole ramp spread
// over them), a colour each, and the "beyond the highest sea" colour.
export function colourScale(polar) {
  const top = Math.max(...polar.seas.map((s) => s.h_sig_m));
  const limits = polar.cells.filter((c) => !c.beyond_listed && c.limiting_hs_m !== null).map((c) => c.limiting_hs_m);
  const low = limits.length ? Math.min(...limits) : 0, high = limits.length ? Math.max(...limits) : top;
  const from = (s) => Math.max(0, Math.floor(low / s + 1e-9) * s);
  const to = (s) => Math.max(from(s) + s, Math.ceil(high / s - 1e-9) * s);
  const step = OPERABILITY.steps.find((s) => (to(s) - from(s)) / s <= OPERABILITY.maxBins + 1e-9) || OPERABILITY.steps[OPERABILITY.steps.length - 1];
  const start = from(step);
  const n = Math.max(1, Math.round((to(step) - start) / step));
  const bins = Array.from({ length: n }, (_, k) => ({ lo: start + k * step, hi: start + (k + 1) * step, colour: ramp(n === 1 ? 1 : k / (n - 1)) }));
  const bin = (hs) => bins[Math.min(n - 1, Math.max(0, Math.floor((hs - start) / step + 1e-9)))];
  return {
    bins, top, step,
    beyond: OPERABILITY.beyond,
    colourOf: (cell) => (cell.beyond_listed || cell.limiting_hs_m === null ? OPERABILITY.beyond.fill : bin(cell.limiting_hs_m).colour),
  };
}

function ramp(t) {
  const c = OPERABILITY.ramp.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
  const x = t * (c.length - 1), i = Math.min(c.length - 2, Math.floor(x)), f = x - i;
  const rgb = c[i].map((v, k) => Math.round(v + f * (c[i + 1][k] - v)));
  return `#${rgb.map((v) => v.toString(16).padStart(2, '0')).join('')}`;
}

// Each cell's radial span [kn] (midway between neighbouring speeds) and angular span [deg]
// (midway between neighbouring headings, around the circle).
function spans(polar) {
  const sp = polar.speeds_kn, n = sp.length;
  const speed = sp.map((s, j) => {
    const lo = j > 0 ? (sp[j - 1] + s) / 2 : n > 1 ? Math.max(0, s - (sp[1] - s) / 2) : 0;
    const hi = j < n - 1 ? (s + sp[j + 1]) / 2 : n > 1 ? s + (s - sp[n - 2]) / 2 : Math.max(1, 1.1 * s);
    return [lo, hi];
  });
  const hd = polar.headings_deg.map(mod360);
  const order = hd.map((h, i) => [h, i]).sort((a, b) => a[0] - b[0]);
  const heading = new Array(hd.length);
  order.forEach(([h, i], k) => {
    if (order.length === 1) { heading[i] = [h - 180, h + 180]; return; }
    const prev = k > 0 ? order[k - 1][0] : order[order.length - 1][0] - 360;
    const next = k < order.length - 1 ? order[k + 1][0] : order[0][0] + 360;
    heading[i] = [(prev + h) / 2, (h + next) / 2];
  });
  return { speed, heading, outer: speed[n - 1][1] };
}

// Where the polar sits in a canvas of w x h CSS pixels: centre, radius, and the mapping of
// (speed [kn], heading [deg]) to pixels. Margins hold the degree and heading labels.
export function layout(polar, w, h, { mx, my }) {
  const R = Math.max(40, Math.min((w - 2 * mx) / 2, (h - 2 * my) / 2));
  const cx = w / 2, cy = my + Math.max(R, (h - 2 * my) / 2);
  const s = spans(polar);
  const rOf = (kn) => (R * kn) / s.outer;
  // Heading h: x = cx + r sin h, y = cy + r cos h (0 at the bottom, 90 on the right, 180 on top).
  const at = (kn, deg) => [cx + rOf(kn) * Math.sin((deg * Math.PI) / 180), cy + rOf(kn) * Math.cos((deg * Math.PI) / 180)];
  return { cx, cy, R, spans: s, rOf, at, w, h };
}

// The cell under a point (CSS pixels of the canvas): {j, i} (speed index, heading index) or null.
export function cellAt(polar, geo, x, y) {
  const dx = x - geo.cx, dy = y - geo.cy;
  const kn = (Math.hypot(dx, dy) / geo.R) * geo.spans.outer;
  const j = geo.spans.speed.findIndex(([lo, hi]) => kn >= lo && kn < hi);
  if (j < 0) return null;
  const deg = mod360((Math.atan2(dx, dy) * 180) / Math.PI);
  let i = 0;
  polar.headings_deg.forEach((hd, k) => { if (apart(deg, hd) < apart(deg, polar.headings_deg[i])) i = k; });
  return { j, i };
}

// The middle of a cell in CSS pixels (the browser test points there).
export function cellCentre(polar, geo, j, i) {
  const [lo, hi] = geo.spans.speed[j], [a0, a1] = geo.spans.heading[i];
  return geo.at(lo === 0 && j === 0 && polar.speeds_kn[0] === 0 ? 0 : (lo + hi) / 2, (a0 + a1) / 2);
}

// One wedge's path: heading span a0..a1 [deg] between radii r0 and r1 [px]. Canvas angles run
// clockwise from +x; heading h sits at canvas angle 90 - h.
function wedge(g, geo, r0, r1, a0, a1) {
  const phi = (deg) => ((90 - deg) * Math.PI) / 180;
  g.beginPath();
  if (a1 - a0 >= 359.999) {
    g.arc(geo.cx, geo.cy, r1, 0, 2 * Math.PI);
    if (r0 > 0) { g.moveTo(geo.cx + r0, geo.cy); g.arc(geo.cx, geo.cy, r0, 0, 2 * Math.PI, true); }
  } else {
    g.arc(geo.cx, geo.cy, r1, phi(a0), phi(a1), true);
    if (r0 > 0) g.arc(geo.cx, geo.cy, r0, phi(a1), phi(a0), false); else g.lineTo(geo.cx, geo.cy);
  }
  g.closePath();
}

let hatchPattern = null;
function hatch(g) {
  if (hatchPattern) return hatchPattern;
  const c = document.createElement('canvas');
  c.width = 8; c.height = 8;
  const h = c.getContext('2d');
  h.fillStyle = OPERABILITY.beyond.fill; h.fillRect(0, 0, 8, 8);
  h.strokeStyle = OPERABILITY.beyond.hatch; h.lineWidth = 1.2;
  h.beginPath(); h.moveTo(0, 8); h.lineTo(8, 0); h.moveTo(-2, 2); h.lineTo(2, -2); h.moveTo(6, 10); h.lineTo(10, 6); h.stroke();
  hatchPattern = g.createPattern(c, 'repeat');
  return hatchPattern;
}

// A text with a white halo (readable over any cell colour).
function label(g, text, x, y, align = 'center', base = 'middle') {
  g.textAlign = align; g.textBaseline = base;
  g.lineWidth = 3; g.strokeStyle = '#ffffff'; g.lineJoin = 'round';
  g.strokeText(text, x, y);
  g.fillStyle = '#1b1b1b'; g.fillText(text, x, y);
}

const fontSize = (narrow) => (narrow ? 11 : 12);
// Room round the circle for the labels: the side words ("270°", "beam") beside it, a line above and
// below it.
export function margins(g, narrow) {
  const fs = fontSize(narrow);
  g.font = `600 ${fs}px system-ui, sans-serif`;
  const side = Math.max(...['270°', '90°', 'beam'].map((t) => g.measureText(t).width));
  return { mx: Math.ceil(side) + 14, my: fs + 16 };
}

// Draws the polar; selected: {j, i} or null. Returns the layout (for hit testing).
export function drawPolar(cv, polar, scale, { selected = null, narrow = false } = {}) {
  const dpr = window.devicePixelRatio || 1;
  const w = cv.clientWidth, h = cv.clientHeight;
  cv.width = Math.round(w * dpr); cv.height = Math.round(h * dpr);
  const g = cv.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, w, h);
  const geo = layout(polar, w, h, margins(g, narrow));
  const nh = polar.headings_deg.length;
  polar.cells.forEach((cell, k) => {
    const j = Math.floor(k / nh), i = k % nh;
    const [lo, hi] = geo.spans.speed[j], [a0, a1] = geo.spans.heading[i];
    wedge(g, geo, geo.rOf(lo), geo.rOf(hi), a0, a1);
    g.fillStyle = cell.beyond_listed || cell.limiting_hs_m === null ? hatch(g) : scale.colourOf(cell);
    g.fill();
    g.strokeStyle = OPERABILITY.edge; g.lineWidth = 0.6; g.stroke();
  });
  // The outer rim, the degree marks and the heading names.
  g.strokeStyle = '#4a4a4a'; g.lineWidth = 1;
  g.beginPath(); g.arc(geo.cx, geo.cy, geo.R, 0, 2 * Math.PI); g.stroke();
  const fs = fontSize(narrow);
  g.font = `${fs}px system-ui, sans-serif`;
  for (let d = 0; d < 360; d += OPERABILITY.headingTicksDeg) {
    const rad = (d * Math.PI) / 180, sx = Math.sin(rad), cy = Math.cos(rad);
    g.beginPath(); g.moveTo(geo.cx + geo.R * sx, geo.cy + geo.R * cy); g.lineTo(geo.cx + (geo.R + 5) * sx, geo.cy + (geo.R + 5) * cy); g.stroke();
    const rr = geo.R + 8 + (Math.abs(sx) > 0.3 ? 10 : 0) * Math.abs(sx);
    const x = geo.cx + rr * sx, y = geo.cy + (geo.R + 13) * cy;
    if (d === 180 || d === 0 || d === 90 || d === 270) continue;
    label(g, `${d}°`, x, y);
  }
  g.font = `600 ${fs}px system-ui, sans-serif`;
  label(g, '180° head seas', geo.cx, geo.cy - geo.R - 8, 'center', 'bottom');
  label(g, '0° following seas', geo.cx, geo.cy + geo.R + 8, 'center', 'top');
  label(g, '90°', geo.cx + geo.R + 8, geo.cy - fs * 0.6, 'left');
  label(g, 'beam', geo.cx + geo.R + 8, geo.cy + fs * 0.6, 'left');
  label(g, '270°', geo.cx - geo.R - 8, geo.cy - fs * 0.6, 'right');
  label(g, 'beam', geo.cx - geo.R - 8, geo.cy + fs * 0.6, 'right');
  // Speeds along the line to following seas (every ring where the labels have room).
  g.font = `${fs}px system-ui, sans-serif`;
  const gap = geo.R / polar.speeds_kn.length;
  const stride = Math.max(1, Math.ceil((fs + 6) / gap));
  polar.speeds_kn.forEach((kn, j) => {
    if (j % stride !== 0 && j !== polar.speeds_kn.length - 1) return;
    if (j === polar.speeds_kn.length - 1 && j % stride !== 0 && (j % stride) < stride / 2) return;
    const [x, y] = geo.at(kn, 0);
    label(g, `${+kn.toFixed(2)} kn`, x + 3, y, 'left');
  });
  if (selected) {
    const [lo, hi] = geo.spans.speed[selected.j], [a0, a1] = geo.spans.heading[selected.i];
    wedge(g, geo, geo.rOf(lo), geo.rOf(hi), a0, a1);
    g.lineWidth = 4; g.strokeStyle = '#ffffff'; g.stroke();
    g.lineWidth = 2; g.strokeStyle = '#000000'; g.stroke();
  }
  return geo;
}
