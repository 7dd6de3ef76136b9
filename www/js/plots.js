// Plots: uPlot charts and canvas pictures in a box, sized to their container and re-fitted when it
// changes (ResizeObserver), with their PNG export and table of numbers. What a run draws in it is
// runplots.js; the plots asked of the worker after a run in waves, seaextras.js.
import uPlot from '../vendor/uPlot.esm.js';
import { EVENT_COLOR, KEPT_STYLE } from './config.js';
import { el, fmt, downloadUrl } from './dom.js';

const plotHeight = () => parseFloat(getComputedStyle(document.body).getPropertyValue('--plot-h')) || 240;

// Tick labels with as many digits as the step needs ("0.995, 1, 1.005", not "1, 1, 1"); on a log
// axis, powers of ten read as "1e-3".
function ticks(u, splits, axisIdx, space, incr) {
  const scaleKey = u.axes[axisIdx].scale;
  if (u.scales[scaleKey] && u.scales[scaleKey].distr === 3) {
    return splits.map((v) => {
      if (v == null) return '';
      const e = Math.log10(v);
      if (Math.abs(e - Math.round(e)) > 1e-6) return '';
      return Math.abs(e) <= 3 ? String(Number(v.toPrecision(1))) : `1e${Math.round(e)}`;
    });
  }
  const digits = tickDecimals(incr);
  return splits.map((v) => (v == null ? '' : Math.abs(v) >= 1e6 ? v.toExponential(2) : v.toFixed(digits)));
}

// Decimals that show every multiple of a tick step `incr` exactly: 1 for 2.5 (not 0, which
// printed 2.5 as "3"), 0 for 25, 2 for 0.25 and for 0.05; at most 8.
export function tickDecimals(incr) {
  if (!(incr > 0) || !Number.isFinite(incr)) return 0;
  for (let d = 0; d < 8; d++) {
    const x = incr * 10 ** d;
    if (Math.abs(x - Math.round(x)) <= 1e-9 * Math.max(1, x)) return d;
  }
  return 8;
}

// Every plot on the page, for presentation mode's type size.
const ALL_PLOTS = new Set();
const presenting = () => document.body.classList.contains('presenting');

// Axis type for presentation (16 px, readable from the back of a classroom) or the desk (12 px):
// the fonts' size and the room the ticks and labels take.
function axisType(u, big) {
  const css = big ? 16 : 12;
  const dpr = devicePixelRatio || 1;
  u.axes.forEach((a, i) => {
    for (const f of [a.font, a.labelFont]) {
      if (!Array.isArray(f)) continue;
      f[2] = css;
      f[1] = Math.round(css * dpr * 10) / 10;
      f[0] = f[0].replace(/[0-9.]+px/, `${f[1]}px`);
    }
    const size = i === 0 ? (big ? 64 : 50) : big ? 80 : 60;
    a.size = () => size;
    a.labelSize = big ? 38 : 30;
  });
}

// Presentation mode on or off: every plot's axis type, then its size (the plots' height follows
// --plot-h).
export function presentPlots(big) {
  for (const u of ALL_PLOTS) {
    if (!u.root.isConnected) { ALL_PLOTS.delete(u); continue; }
    axisType(u, big);
    u.setSize({ width: u.width, height: plotHeight() });
    u.redraw(false, true);
  }
}

// A line's width when its plot names none [CSS px].
const LINE_WIDTH = 1.8;
const SVG = 'http://www.w3.org/2000/svg';

// A legend swatch: a short stretch of the line as drawn (colour, width, dash pattern).
function swatch({ color, stroke, width = LINE_WIDTH, dash = null }) {
  const svg = document.createElementNS(SVG, 'svg');
  for (const [k, v] of Object.entries({ width: 30, height: 10, viewBox: '0 0 30 10', 'aria-hidden': 'true', class: 'swatch-line' })) svg.setAttribute(k, v);
  const ln = document.createElementNS(SVG, 'line');
  for (const [k, v] of Object.entries({ x1: 1, y1: 5, x2: 29, y2: 5, stroke: color || stroke, 'stroke-width': width, ...(dash ? { 'stroke-dasharray': dash.join(' ') } : {}) })) ln.setAttribute(k, v);
  svg.append(ln);
  return svg;
}

// The legend under a line plot: every line of the run with its pattern, and one entry for a kept
// run's lines (`keptKey`, see PlotBox.line), its place held while there is none.
function legend(series, keptKey) {
  const own = series.filter((s) => !s.kept);
  const keptOne = series.find((s) => s.kept);
  const items = own.map((s) => el('li', {}, swatch(s), s.label));
  if (keptKey !== undefined) {
    // Grey: it stands for every kept line, each drawn faint in its own line's colour.
    const li = el('li', { className: 'legend-kept' }, swatch(KEPT_STYLE), keptKey || 'the run before');
    if (!keptOne) li.style.visibility = 'hidden';
    items.push(li);
  }
  return el('ul', { className: 'legend', attrs: { 'aria-label': 'Lines' } }, ...items);
}

// A box of plots. clear() starts a new generation: plots that arrive late for an older one
// (after an asynchronous request) are dropped. `more`: a second container for the plots that do
// not tell the study's story (one click away).
export class PlotBox {
  constructor(box, { more = null, moreBox = null, sync = null } = {}) {
    this.box = box;
    this.more = more;
    this.moreBox = moreBox;
    this.sync = sync;
    this.plots = [];
    this.generation = 0;
    this.observer = new ResizeObserver((entries) => {
      for (const e of entries) {
        const u = e.target.uplot;
        const w = Math.floor(e.contentRect.width);
        if (u && w > 0 && (w !== u.width || plotHeight() !== u.height)) u.setSize({ width: w, height: plotHeight() });
      }
    });
  }

  clear() {
    for (const p of this.plots) { ALL_PLOTS.delete(p); p.destroy(); }
    this.plots = [];
    this.observer.disconnect();
    this.box.replaceChildren();
    if (this.more) { this.more.replaceChildren(); this.moreBox.hidden = true; }
    return ++this.generation;
  }

  // A panel (titled unless title is null) appended to the box or to `more` (or null when
  // `generation` is stale).
  panel(title, generation = this.generation, more = false, ...content) {
    if (generation !== this.generation) return null;
    const div = el('figure', { className: 'plot' }, ...(title ? [el('h3', { textContent: title })] : []), ...content);
    if (more && this.more) { this.more.append(div); this.moreBox.hidden = false; } else this.box.append(div);
    return div;
  }

  // A line plot. series: [{data, label, color, scale?, ...uPlot series options}]; axes: the
  // y axes [{scale, label}] (a second one goes on the right); x: {data, label, distr?, range?}
  // (range: [min, max] of the x axis, else the data's).
  // hbands: [{from, to, fill, edge?}] shaded across the plot; levels: [{value, label, color}];
  // markers: x values of events; key: a line under the plot saying what the shading means.
  // vlines: [{x, label, color, dash}] dashed vertical lines labelled at the top (quantiles).
  // keptKey: the legend's one entry for a kept run's lines (series with `kept: true`), a string
  // (its name) or '' (none now: its place is kept, so a run kept later does not move the page
  // under the plot); undefined: no such entry.
  line(title, x, series, axes, { generation, scales = {}, more = false, hbands = [], levels = [], markers = [], vlines = [], key = null, time = false, keptKey } = {}) {
    const div = this.panel(title, generation, more);
    if (!div) return null;
    const chart = el('div', { className: 'chart' });
    div.append(chart, legend(series, keptKey));
    const yScales = {};
    for (const a of axes) yScales[a.scale] = scales[a.scale] || {};
    const overlay = (u) => {
      const { ctx } = u;
      const { left, top, width, height } = u.bbox;
      ctx.save();
      // uPlot leaves the last dashed series' pattern on the context: bands, levels and markers
      // are solid.
      ctx.setLineDash([]);
      ctx.beginPath(); ctx.rect(left, top, width, height); ctx.clip();
      const sc = axes[0].scale;
      for (const b of hbands) {
        const y0 = u.valToPos(b.from, sc, true), y1 = u.valToPos(b.to, sc, true);
        ctx.fillStyle = b.fill;
        ctx.fillRect(left, Math.min(y0, y1), width, Math.abs(y1 - y0));
        if (b.edge) {
          ctx.strokeStyle = b.edge; ctx.lineWidth = 1;
          for (const y of [y0, y1]) { ctx.beginPath(); ctx.moveTo(left, y); ctx.lineTo(left + width, y); ctx.stroke(); }
        }
      }
      const dpr = devicePixelRatio || 1;
      // Levels solid and labelled: a dash on a plot means a kept run.
      for (const l of levels) {
        const y = u.valToPos(l.value, sc, true);
        ctx.strokeStyle = l.color; ctx.lineWidth = 1.5 * dpr;
        ctx.beginPath(); ctx.moveTo(left, y); ctx.lineTo(left + width, y); ctx.stroke();
      }
      for (const v of vlines) {
        const X = u.valToPos(v.x, 'x', true);
        ctx.strokeStyle = v.color; ctx.lineWidth = 2 * dpr; ctx.setLineDash((v.dash || []).map((d) => d * dpr));
        ctx.beginPath(); ctx.moveTo(X, top); ctx.lineTo(X, top + height); ctx.stroke();
        ctx.setLineDash([]);
      }
      ctx.strokeStyle = EVENT_COLOR; ctx.lineWidth = 1.5 * dpr;
      for (const t of markers) {
        const X = u.valToPos(t, 'x', true);
        ctx.beginPath(); ctx.moveTo(X, top); ctx.lineTo(X, top + height); ctx.stroke();
        ctx.fillStyle = EVENT_COLOR;
        ctx.beginPath(); ctx.moveTo(X - 5 * dpr, top); ctx.lineTo(X + 5 * dpr, top); ctx.lineTo(X, top + 8 * dpr); ctx.fill();
      }
      ctx.restore();
    };
    // Labels drawn over the plot area, on top of the traces (after them), each on a light
    // backdrop so a trace passing over it never hides it: clipped to the plot, 11 px type, text
    // alignment set (uPlot leaves its axis alignment on the context).
    const labels = (u, baseline, draw) => {
      const { ctx } = u;
      const dpr = devicePixelRatio || 1;
      const { left, top, width, height } = u.bbox;
      ctx.save();
      ctx.beginPath(); ctx.rect(left, top, width, height); ctx.clip();
      ctx.font = `${Math.round(11 * dpr)}px system-ui, sans-serif`;
      ctx.textAlign = 'left'; ctx.textBaseline = baseline;
      const backed = (text, x, y, color) => {
        const tw = ctx.measureText(text).width, th = 13 * dpr;
        ctx.fillStyle = 'rgba(255, 255, 255, 0.85)';
        ctx.fillRect(x, baseline === 'top' ? y : y - th, tw + 4 * dpr, th);
        ctx.fillStyle = color;
        ctx.fillText(text, x + 2 * dpr, baseline === 'top' ? y + dpr : y);
      };
      draw(ctx, { left, top, width, dpr, th: 13 * dpr, backed });
      ctx.restore();
    };
    // The vertical lines' labels at the top, one row lower where they would overprint.
    const vlineLabels = (u) => {
      if (!vlines.length) return;
      labels(u, 'top', (ctx, { left, top, width, dpr, th, backed }) => {
        const placed = [];
        for (const v of vlines) {
          const X = u.valToPos(v.x, 'x', true);
          const tw = ctx.measureText(v.label).width;
          const x0 = Math.min(X + 2 * dpr, left + width - tw - 4 * dpr);
          let row = 0;
          while (placed.some((p) => p.row === row && x0 < p.x1 && p.x0 < x0 + tw + 4 * dpr)) row++;
          placed.push({ row, x0, x1: x0 + tw + 4 * dpr });
          backed(v.label, x0, top + 2 * dpr + row * (th + 2 * dpr), v.color);
        }
      });
    };
    // The levels' labels above their lines. Labels whose lines lie closer than a label's height
    // (a wide y range) would overprint: the lines are all drawn, the crowded labels left to the
    // key under the plot.
    const levelLabels = (u) => {
      if (!levels.length) return;
      labels(u, 'bottom', (ctx, { left, dpr, th, backed }) => {
        const labelled = [];
        for (const l of levels) {
          const y = u.valToPos(l.value, axes[0].scale, true);
          if (labelled.some((y0) => Math.abs(y0 - y) < th + 2 * dpr)) continue;
          labelled.push(y);
          backed(`${l.label} (${l.value})`, left + 2 * dpr, y - 3 * dpr, l.color);
        }
      });
    };
    const opts = {
      width: Math.max(200, Math.floor(chart.clientWidth || 440)),
      height: plotHeight(),
      scales: { x: { time: false, ...(x.distr ? { distr: x.distr } : {}), ...(x.range ? { range: () => x.range } : {}) }, ...yScales },
      axes: [{ label: x.label, values: ticks }, ...axes.map((a, i) => ({ scale: a.scale, label: a.label, values: ticks, size: 60, ...(i ? { side: 1, grid: { show: false } } : {}) }))],
      series: [{ label: x.label }, ...series.map(({ data, color, kept, ...rest }) => ({ stroke: color, width: LINE_WIDTH, scale: axes[0].scale, spanGaps: true, ...rest }))],
      // The legend is the page's own (legend()): it draws each line's pattern.
      legend: { show: false },
      // No horizontal cursor line: parked at mid-height by the live views' cursor, it read as a
      // threshold.
      // One cursor across the box's time plots, and across any other plots that share their x
      // axis (the Bode magnitude and phase); zoom is linked on time plots only.
      cursor: this.sync ? { y: false, sync: { key: time ? this.sync : `${this.sync}:${x.label}`, setSeries: false } } : { y: false },
      hooks: { drawClear: [overlay], draw: [levelLabels, vlineLabels], ...(time && this.sync ? { setScale: [(u, key) => this.linkZoom(u, key)] } : {}) },
    };
    const u = new uPlot(opts, [x.data, ...series.map((s) => s.data)], chart);
    ALL_PLOTS.add(u);
    if (presenting()) { axisType(u, true); u.redraw(false, true); }
    u.linked = time;
    chart.uplot = u;
    this.observer.observe(chart);
    this.plots.push(u);
    div.append(this.tools(title, u, x, series, key));
    return u;
  }

  // Zooming one time plot zooms all (guarded against the echo).
  linkZoom(src, key) {
    if (key !== 'x' || this.zooming) return;
    this.zooming = true;
    const { min, max } = src.scales.x;
    for (const u of this.plots) if (u !== src && u.linked) u.setScale('x', { min, max });
    this.zooming = false;
  }

  // Under a plot: what the shading means, PNG export, and the text alternative (a table of each
  // line's first, lowest and highest with where they are, and last value).
  tools(title, u, x, series, key) {
    const png = el('button', { type: 'button', textContent: 'PNG' });
    png.setAttribute('aria-label', `Save "${title}" as PNG`);
    png.addEventListener('click', () => downloadUrl(`${(title || 'plot').replace(/[^\w]+/g, '-').slice(0, 60)}.png`, u.ctx.canvas.toDataURL('image/png')));
    // Where each line is lowest and highest, as well (a resonance's frequency, a dip's time).
    const xs = Array.from(x.data);
    const xUnit = (/\[([^\]]+)\]/.exec(x.label) || [])[1];
    const at = (i) => `${fmt(xs[i])}${xUnit && xUnit !== '-' ? ` ${xUnit}` : ''}`;
    const rows = series.map((s) => {
      const idx = Array.from(s.data).map((y, i) => [y, i]).filter(([y]) => y != null && Number.isFinite(y));
      if (!idx.length) return el('tr', {}, el('th', { scope: 'row', textContent: s.label }), ...[0, 1, 2, 3].map(() => el('td', { textContent: '–' })));
      const lo = idx.reduce((a, b) => (b[0] < a[0] ? b : a)), hi = idx.reduce((a, b) => (b[0] > a[0] ? b : a));
      return el('tr', {}, el('th', { scope: 'row', textContent: s.label }),
        el('td', { textContent: fmt(idx[0][0]) }), el('td', { textContent: `${fmt(lo[0])} at ${at(lo[1])}` }),
        el('td', { textContent: `${fmt(hi[0])} at ${at(hi[1])}` }), el('td', { textContent: fmt(idx[idx.length - 1][0]) }));
    });
    const table = el('table', {}, el('caption', { textContent: `${title}: over ${x.label}` }),
      el('thead', {}, el('tr', {}, ...['line', 'first', 'lowest', 'highest', 'last'].map((h) => el('th', { scope: 'col', textContent: h })))),
      el('tbody', {}, ...rows));
    const details = el('details', {}, el('summary', { textContent: 'Numbers' }), el('div', { className: 'scroll', tabIndex: 0, attrs: { role: 'region', 'aria-label': 'Numbers' } }, table));
    return el('div', { className: 'tools' }, ...(key ? [el('span', { className: 'key' }, ...key)] : []), png, details);
  }

  // A histogram {lo, hi, counts} as bars, with an optional overlay {label, values}.
  // onPick(bin): a click on a non-empty bar (the bar under the cursor).
  // vlines and key: as line()'s (a key replaces the line about clicking a bar).
  // edges: the x axis spans the bins' edges (lo to hi), not only their centres. The count axis
  // starts at 0 (uPlot's own range cut the lowest bars off).
  histogram(title, h, xLabel, overlay, generation, onPick = null, { vlines = [], key: note = null, edges = false } = {}) {
    const w = (h.hi - h.lo) / h.counts.length;
    const centres = h.counts.map((_, i) => h.lo + (i + 0.5) * w);
    const series = [{ data: h.counts, label: 'trials', color: '#1f618d', paths: uPlot.paths.bars({ size: [0.9, 100] }), fill: '#aed6f1', points: { show: false } }];
    if (overlay) series.push({ data: overlay.values, label: overlay.label, color: '#b03a2e', points: { show: false } });
    const key = note || (onPick ? ['Click a bar to replay one of its trials in the live views.'] : null);
    const u = this.line(title, { data: centres, label: xLabel, ...(edges ? { range: [h.lo, h.hi] } : {}) }, series, [{ scale: 'y', label: 'trials per bin [count]' }], { generation, key, vlines, scales: { y: { range: (_, __, max) => [0, max > 0 ? max * 1.05 : 1] } } });
    if (u && onPick) {
      u.over.style.cursor = 'pointer';
      u.over.addEventListener('click', () => {
        const i = u.cursor.idx;
        if (i !== null && i !== undefined && h.counts[i] > 0) onPick(i);
      });
    }
    return u;
  }

  // A panel with a canvas picture; draw(canvas) runs once it is laid out and again on a resize.
  canvas(title, ariaLabel, draw, more = false) {
    const cv = el('canvas', { className: 'track', attrs: { role: 'img', 'aria-label': ariaLabel } });
    this.panel(title, this.generation, more, cv);
    let lastW = 0;
    const ro = new ResizeObserver(() => { if (cv.clientWidth && cv.clientWidth !== lastW) { lastW = cv.clientWidth; draw(cv); } });
    ro.observe(cv);
    this.plots.push({ destroy: () => ro.disconnect() });
    return cv;
  }
}

// A canvas sized for the device's pixels; returns its 2-D context and CSS size.
export function sizedCanvas(cv, height) {
  const dpr = window.devicePixelRatio || 1;
  const w = cv.clientWidth || 460;
  cv.width = w * dpr; cv.height = height * dpr;
  const g = cv.getContext('2d');
  g.scale(dpr, dpr);
  return { g, w, h: height };
}
