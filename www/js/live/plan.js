// Live view: the ship in its seaway from above: the wave field around it, its track, its waterline
// turned to its heading, the rudder and the course over ground. Position, heading, rudder and drift
// are trace values at the playback time; the waterline comes from the wasm's hullProfile and the
// wave field from the run's own wave components summed in Rust (Sea). No physics here.
import { LIVE } from '../config.js';
import { C, View, fixed, rowAt, rudderText } from './shared.js';

export class PlanView extends View {
  constructor(onResize) {
    super('The ship in its seaway, from above', 'The ship from above on its wave field, with its track, heading and rudder', '--live-side-h', onResize);
  }

  // L: the live views (the trace at their playback time, the hull and the sea).
  draw(L) {
    const { g, w, h } = this;
    const v = (n) => L.v(n), hull = L.hull, P = LIVE.plan;
    const half = hull.lpp_m * P.spanOfLpp * Math.max(1, h / w);
    const s = Math.min(w, h) / (2 * half);
    const x0 = v('x_m'), y0 = v('y_m'), psi = (v('heading_deg') * Math.PI) / 180;
    const px = (east) => w / 2 + (east - y0) * s, py = (north) => h / 2 - (north - x0) * s;
    // The wave field on a coarse grid (summed in Rust), smoothed up to the canvas.
    const gw = P.grid, gh = Math.max(4, Math.round((P.grid * h) / w));
    if (!this.grid || this.grid.w !== gw || this.grid.h !== gh) {
      const c = document.createElement('canvas'); c.width = gw; c.height = gh;
      this.grid = { w: gw, h: gh, canvas: c, ctx: c.getContext('2d'), img: c.getContext('2d').createImageData(gw, gh), north: new Float64Array(gw * gh), east: new Float64Array(gw * gh) };
    }
    const G = this.grid;
    if (L.sea.components > 0) {
      for (let r = 0; r < gh; r++) for (let c = 0; c < gw; c++) {
        G.east[r * gw + c] = y0 + ((c + 0.5) / gw - 0.5) * (w / s);
        G.north[r * gw + c] = x0 - ((r + 0.5) / gh - 0.5) * (h / s);
      }
      const e = L.sea.elevations(L.t, G.north, G.east);
      for (let q = 0; q < e.length; q++) {
        const a = Math.max(0, Math.min(1, 0.5 + e[q] / (2 * L.waveScale)));
        for (let ch = 0; ch < 3; ch++) G.img.data[4 * q + ch] = C.trough[ch] + a * (C.crest[ch] - C.trough[ch]);
        G.img.data[4 * q + 3] = 255;
      }
      G.ctx.putImageData(G.img, 0, 0);
      g.imageSmoothingEnabled = true;
      g.drawImage(G.canvas, 0, 0, w, h);
    } else {
      g.fillStyle = `rgb(${C.trough.map((a, j) => (a + C.crest[j]) / 2).join(',')})`; g.fillRect(0, 0, w, h);
    }
    // Track behind the ship.
    const ts = L.cols.t_s, xs = L.cols.x_m, ys = L.cols.y_m;
    const from = rowAt(ts, L.t - P.trackS);
    g.lineWidth = 4; g.strokeStyle = 'rgba(0, 0, 0, 0.55)';
    const path = new Path2D();
    for (let j = from; j <= L.i; j++) { if (j === from) path.moveTo(px(ys[j]), py(xs[j])); else path.lineTo(px(ys[j]), py(xs[j])); }
    path.lineTo(px(y0), py(x0));
    g.stroke(path); g.lineWidth = 2; g.strokeStyle = C.track; g.stroke(path);
    // The ship to scale: its waterline, turned to its heading (x forward of the CG).
    const toPic = (fwd, stbd) => [px(y0 + fwd * Math.sin(psi) + stbd * Math.cos(psi)), py(x0 + fwd * Math.cos(psi) - stbd * Math.sin(psi))];
    const outline = new Path2D();
    const wl = hull.x_m.map((x, j) => [x - hull.lcg_m, hull.waterline_half_breadth_m[j]]).filter(([, b], j) => b > 0 || j === 0 || j === hull.x_m.length - 1);
    wl.forEach(([f, b], j) => { const [a, c] = toPic(f, b); if (j) outline.lineTo(a, c); else outline.moveTo(a, c); });
    for (const [f, b] of [...wl].reverse()) { const [a, c] = toPic(f, -b); outline.lineTo(a, c); }
    outline.closePath();
    g.fillStyle = C.ship; g.fill(outline); g.strokeStyle = C.hullEdge; g.lineWidth = 1.5; g.stroke(outline);
    // Rudder at the stern, angle from the trace (positive turns to port: trailing edge to port),
    // drawn three times its length so it can be seen.
    const rud = (v('rudder_deg') * Math.PI) / 180, sternF = hull.x_m[0] - hull.lcg_m, len = 3 * 4;
    const [ra, rb] = toPic(sternF, 0), [rc, rd] = toPic(sternF - len * Math.cos(rud), -len * Math.sin(rud));
    g.strokeStyle = C.rudder; g.lineWidth = 3; g.beginPath(); g.moveTo(ra, rb); g.lineTo(rc, rd); g.stroke();
    // Course over ground: the heading turned by the drift angle (the trace's atan2(v, u)), a
    // dashed line ahead of the bow (its direction only).
    const course = psi + (v('drift_angle_deg') * Math.PI) / 180, bowF = hull.x_m[hull.x_m.length - 1] - hull.lcg_m;
    const [ba, bb] = toPic(bowF, 0), run = 0.35 * hull.lpp_m * s;
    const ea = ba + run * Math.sin(course), eb = bb - run * Math.cos(course);
    g.strokeStyle = C.hullEdge; g.fillStyle = C.hullEdge; g.lineWidth = 2; g.setLineDash([5, 4]);
    g.beginPath(); g.moveTo(ba, bb); g.lineTo(ea, eb); g.stroke(); g.setLineDash([]);
    g.beginPath(); g.arc(ea, eb, 3.5, 0, 2 * Math.PI); g.fill();
    // Corner marks: north, the waves' direction, scale, and the figures.
    const fs = Math.max(11, Math.min(L.big ? 20 : 15, Math.round(w / 40)));
    g.font = `${fs}px system-ui, sans-serif`;
    const label = (text, x, y, align = 'left') => {
      g.textAlign = align; g.textBaseline = 'top';
      const tw = g.measureText(text).width;
      g.fillStyle = 'rgba(255, 255, 255, 0.88)'; g.fillRect(align === 'left' ? x - 3 : x - tw - 3, y - 2, tw + 6, fs + 4);
      g.fillStyle = C.text; g.fillText(text, x, y);
    };
    label(`heading ${fixed(v('heading_deg'), 0)}°, ${v('ship_speed_kn').toFixed(1)} kn`, 8, 6);
    // The model's sign, as the plots and the booklet give it (+ turns to port), with its word.
    label(`rudder ${rudderText(v('rudder_deg'))} (drawn ×3)`, 8, 10 + fs);
    label(`drift ${v('drift_angle_deg').toFixed(1)}° (dashed: course over ground)`, 8, 14 + 2 * fs);
    label('N ↑', w - 8, 6, 'right');
    const from_deg = L.from;
    if (from_deg != null) {
      // The waves travel away from where they come from: an arrow the way they go.
      label(`waves from ${from_deg}°`, w - 8, 10 + fs, 'right');
      const d = ((from_deg + 180) * Math.PI) / 180, X = w - 34, Y = 30 + 3 * fs, L = 18;
      g.strokeStyle = C.waveArrow; g.fillStyle = C.waveArrow; g.lineWidth = 3;
      g.beginPath(); g.moveTo(X - L * Math.sin(d), Y + L * Math.cos(d)); g.lineTo(X + L * Math.sin(d), Y - L * Math.cos(d)); g.stroke();
      g.beginPath(); g.arc(X + L * Math.sin(d), Y - L * Math.cos(d), 5, 0, 2 * Math.PI); g.fill();
    }
    const bar = 100 * s;
    g.strokeStyle = '#ffffff'; g.lineWidth = 3; g.beginPath(); g.moveTo(10, h - 10); g.lineTo(10 + bar, h - 10); g.stroke();
    label('100 m', 10, h - 16 - fs);
    L.drawn.plan = { heading_deg: v('heading_deg'), rudder_deg: v('rudder_deg'), x_m: x0, y_m: y0, from_deg };
  }
}
