// The live views' shared parts: the colours, the trace's row at a time, the wording that more
// than one view (or the text alternative) prints, and the canvas every view draws on. No number
// of the model here: the views take theirs from the trace and the wasm's pageConstants.
import { LIVE } from '../config.js';
import { el } from '../dom.js';

export const C = LIVE.colors;

// Index of the last row at or before t (t_s increasing).
export function rowAt(ts, t) {
  let lo = 0, hi = ts.length - 1;
  if (t <= ts[0]) return 0;
  if (t >= ts[hi]) return hi;
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (ts[m] <= t) lo = m; else hi = m; }
  return lo;
}

// x to d decimals, never "-0" (a heading of -0.2 deg reads 0).
export const fixed = (x, d) => { const t = x.toFixed(d); return /^-0(\.0*)?$/.test(t) ? t.slice(1) : t; };
export const mw = (w) => `${(w / 1e6).toFixed(1)} MW`;
export const pct = (x) => (Number.isFinite(x) ? `${(100 * x).toFixed(1)} %` : '–');
// The hub's place against the local surface (eq. 2.57 as printed can put it above).
export const hubText = (hub) => (hub >= 0 ? `hub ${hub.toFixed(2)} m below the surface` : `hub ${(-hub).toFixed(2)} m above the surface`);
export const signed = (x, d = 2) => `${x >= 0 ? '+' : '−'}${Math.abs(x).toFixed(d)}`;
// A rudder angle [deg] in the model's sign (+ turns the ship to port; core's ship/rudder.rs), with
// the side in words: "−5.0° (to starboard)". The plots and the booklet use the same sign.
export const rudderText = (deg) => `${deg > 0.05 || deg < -0.05 ? signed(deg, 1) : '0.0'}°${deg > 0.05 ? ' (to port)' : deg < -0.05 ? ' (to starboard)' : ''}`;
// β_T, the share of the open-water thrust a propeller keeps under surface losses (eq. 2.14), in words.
export const thrustKeptText = (b) => `β_T ${b.toFixed(2)}: ${b >= 0.995 ? 'all its thrust' : b < 0.005 ? 'no thrust left' : `${(100 * b).toFixed(0)} % of its thrust`}`;

// A canvas that follows its box's width at a CSS height; draw() redraws after a resize.
export class View {
  constructor(title, label, heightVar, onResize) {
    this.canvas = el('canvas', { className: 'live-canvas', attrs: { role: 'img', 'aria-label': label, 'aria-describedby': 'live-text' } });
    this.canvas.style.height = `var(${heightVar})`;
    this.figure = el('figure', { className: 'plot live-view' }, el('h3', { textContent: title }), this.canvas);
    this.w = 0; this.h = 0;
    new ResizeObserver(() => {
      const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
      if (!w || !h || (w === this.w && h === this.h)) return;
      const dpr = window.devicePixelRatio || 1;
      this.w = w; this.h = h;
      this.canvas.width = Math.round(w * dpr); this.canvas.height = Math.round(h * dpr);
      this.g = this.canvas.getContext('2d');
      this.g.setTransform(dpr, 0, 0, dpr, 0, 0);
      onResize();
    }).observe(this.canvas);
  }
  ready() { return this.g && this.w > 0 && !this.figure.hidden; }
}

// The sets running (set k+1 at index k) when they stay the same through the run: the scenario's
// plant.online.sets (all four by default) and no order starting or stopping one. The trace
// records the sum over the sets running, which share the load evenly. null when an order changes
// them during the run: the trace does not say which run when, and the pictures split over four.
export function steadySets(scenario) {
  if ((scenario.commands || []).some((c) => c.online_sets)) return null;
  const sets = (scenario.plant && scenario.plant.online && scenario.plant.online.sets) || [1, 2, 3, 4];
  return [0, 1, 2, 3].map((k) => sets.includes(k + 1));
}
// The sets running as words and how many ("sets 1 and 3", 2); all four (or unknown): null words.
export function setsText(on) {
  const list = on ? [0, 1, 2, 3].filter((k) => on[k]).map((k) => k + 1) : [1, 2, 3, 4];
  const words = list.length === 4 ? null : list.length === 1 ? `set ${list[0]}` : `sets ${list.slice(0, -1).join(', ')} and ${list[list.length - 1]}`;
  return { words, n: list.length };
}
