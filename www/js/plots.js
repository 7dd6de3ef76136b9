// Plots: uPlot charts and canvas pictures in a box, the plots of a run (units from signalMeta,
// levels and bases from pageConstants) and the extra plots after a run in waves.
import uPlot from '../vendor/uPlot.esm.js';
import { PLOTS, LEVEL_COLORS, BAND_COLOR, BAND_FILL, TRACK_MARK_S, TRACK_MIN_SPAN_M, RAO, FUEL_OMEGAS, FUEL_COLORS } from './config.js';
import { el } from './dom.js';
import { quantity, withPrefix } from './units.js';
import { REQUEST } from './protocol.js';

const HEIGHT = 220;
const TRACK_MARGIN = 1.1; // the track fills 1/1.1 of the picture

// A box of plots. clear() starts a new generation: plots that arrive late for an older one
// (after an asynchronous request) are dropped.
export class PlotBox {
  constructor(box, { minWidth = 420, maxWidth = 720, columns = 2 } = {}) {
    this.box = box;
    this.plots = [];
    this.generation = 0;
    this.size = { minWidth, maxWidth, columns };
  }

  clear() {
    for (const p of this.plots) p.destroy();
    this.plots = [];
    this.box.replaceChildren();
    return ++this.generation;
  }

  width() {
    const { minWidth, maxWidth, columns } = this.size;
    return Math.max(minWidth, Math.min(maxWidth, (this.box.clientWidth || 900) / columns - (columns > 1 ? 24 : 30)));
  }

  // A panel (titled unless title is null) appended to the box (or null when `generation` is stale).
  panel(title, generation = this.generation, ...content) {
    if (generation !== this.generation) return null;
    const div = el('div', { className: 'plot' }, ...(title ? [el('h3', { textContent: title })] : []), ...content);
    this.box.append(div);
    return div;
  }

  // A line plot. series: [{data, label, color, scale?, ...uPlot series options}]; axes: the
  // y axes [{scale, label}] (a second one goes on the right); x: {data, label, distr?}.
  line(title, x, series, axes, { generation, scales = {}, bands } = {}) {
    const div = this.panel(title, generation);
    if (!div) return;
    const yScales = {};
    for (const a of axes) yScales[a.scale] = scales[a.scale] || {};
    const opts = {
      width: this.width(),
      height: HEIGHT,
      scales: { x: { time: false, ...(x.distr ? { distr: x.distr } : {}) }, ...yScales },
      axes: [{ label: x.label }, ...axes.map((a, i) => ({ scale: a.scale, label: a.label, ...(i ? { side: 1, grid: { show: false } } : {}) }))],
      series: [{ label: x.label }, ...series.map(({ data, color, ...rest }) => ({ stroke: color, width: 1.5, scale: axes[0].scale, ...rest }))],
      ...(bands ? { bands } : {}),
    };
    this.plots.push(new uPlot(opts, [x.data, ...series.map((s) => s.data)], div));
  }

  // A histogram {lo, hi, counts} as bars, with an optional overlay {label, values}.
  histogram(title, h, xLabel, overlay, generation) {
    const w = (h.hi - h.lo) / h.counts.length;
    const centres = h.counts.map((_, i) => h.lo + (i + 0.5) * w);
    const series = [{ data: h.counts, label: 'trials', color: '#2980b9', paths: uPlot.paths.bars({ size: [0.9, 100] }), fill: '#aed6f1' }];
    if (overlay) series.push({ data: overlay.values, label: overlay.label, color: '#c0392b' });
    this.line(title, { data: centres, label: xLabel }, series, [{ scale: 'y', label: 'trials per bin' }], { generation });
  }

  // A panel with a canvas picture; draw(canvas) runs once it is laid out.
  canvas(title, ariaLabel, draw) {
    const cv = el('canvas', { className: 'track', attrs: { role: 'img', 'aria-label': ariaLabel } });
    this.panel(title, this.generation, cv);
    requestAnimationFrame(() => draw(cv));
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

const constant = (t, v) => Array.from(t, () => v);

// The plot of one PLOTS entry: series grouped by displayed unit onto one or two y axes.
function runPlot(box, spec, cols, signals, constants) {
  const t = cols.t_s;
  const groups = new Map(); // unit -> {bases: Set, series: []}
  for (const s of spec.series) {
    const { unit, factor } = signals.display(s.signal, spec.prefix);
    if (!groups.has(unit)) groups.set(unit, { bases: new Set(), series: [] });
    const g = groups.get(unit);
    const base = signals.puBase(s.signal, constants);
    if (base) g.bases.add(base);
    const data = factor === 1 ? cols[s.signal] : Array.from(cols[s.signal], (v) => v * factor);
    g.series.push({ data, base, label: s.label || signals.label(s.signal), color: s.color, scale: 'y:' + unit });
  }
  if (groups.size > 2) throw new Error(`plot '${spec.title}': more than two units`);
  const axes = [];
  const series = [];
  for (const [unit, g] of groups) {
    const one = g.bases.size === 1 && g.series.every((s) => s.base);
    // "[kn]", "[pu of 38 MW]"; a dimensionless axis names its quantities: "h/R [-]".
    const label = one ? `pu of ${[...g.bases][0]}` : unit;
    axes.push({ scale: 'y:' + unit, unit: label, label: unit === '-' ? `${g.series.map((s) => s.label).join(', ')} [-]` : `[${label}]` });
    for (const { base, ...s } of g.series) series.push(base && !one ? { ...s, label: `${s.label} (pu of ${base})` } : s);
  }
  let title = `${spec.title} [${axes.map((a) => a.unit).join('; ')}]`;
  let bands;
  if (spec.hOverR) {
    const scale = axes[0].scale;
    for (const b of constants.h_over_r_bands) {
      const i = series.length + 1; // uPlot series index (0 is x)
      series.push({ data: constant(t, b.to), label: `band to ${b.to}`, color: BAND_COLOR, width: 1, scale });
      series.push({ data: constant(t, b.from), label: `band from ${b.from}`, color: BAND_COLOR, width: 1, scale });
      bands = [...(bands || []), { series: [i, i + 1], fill: BAND_FILL }];
      title += ` (${b.label})`;
    }
    constants.h_over_r_levels.forEach((l, j) => {
      series.push({ data: constant(t, l.value), label: `${l.label} (${l.value})`, color: LEVEL_COLORS[j % LEVEL_COLORS.length], dash: [6, 4], width: 1, scale });
    });
  }
  box.line(title, { data: t, label: `time [${signals.meta('t_s').unit}]` }, series, axes, { bands });
}

// Every plot of a run: the track, then PLOTS (the sea plots only when the sea moved h/R).
export function drawRun(box, cols, signals, constants) {
  box.clear();
  const unit = signals.meta('x_m').unit;
  box.canvas(`Ship track [${unit}] (north up, east right; marks every ${TRACK_MARK_S} ${signals.meta('t_s').unit})`, 'Ship track seen from above', (cv) => drawTrack(cv, cols, unit));
  const inWaves = cols.h_over_r.some((v) => v !== cols.h_over_r[0]);
  for (const spec of PLOTS) {
    if (spec.only && !spec.only(cols)) continue;
    if (spec.sea && !inWaves) continue;
    runPlot(box, spec, cols, signals, constants);
  }
}

function drawTrack(cv, cols, unit) {
  const { g, w, h } = sizedCanvas(cv, 320);
  const xs = cols.y_m, ys = cols.x_m; // east to the right, north up
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const span = Math.max(x1 - x0, y1 - y0, TRACK_MIN_SPAN_M) * TRACK_MARGIN;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const s = Math.min(w, h) / span;
  const px = (x) => w / 2 + (x - cx) * s, py = (y) => h / 2 - (y - cy) * s;
  g.strokeStyle = '#ddd'; g.lineWidth = 1;
  g.strokeRect(0.5, 0.5, w - 1, h - 1);
  g.strokeStyle = '#0b5cad'; g.lineWidth = 2;
  g.beginPath();
  xs.forEach((x, i) => (i ? g.lineTo(px(x), py(ys[i])) : g.moveTo(px(x), py(ys[i]))));
  g.stroke();
  g.fillStyle = '#1b1b1b'; g.font = '11px system-ui';
  const t = cols.t_s;
  let next = 0;
  for (let i = 0; i < t.length; i++) {
    if (t[i] + 1e-9 < next) continue;
    next += TRACK_MARK_S;
    const hd = (cols.heading_deg[i] * Math.PI) / 180;
    const X = px(xs[i]), Y = py(ys[i]);
    g.beginPath(); g.arc(X, Y, 3, 0, 2 * Math.PI); g.fill();
    g.beginPath(); g.moveTo(X, Y); g.lineTo(X + 14 * Math.sin(hd), Y - 14 * Math.cos(hd)); g.stroke();
    g.fillText(`${t[i].toFixed(0)} s`, X + 5, Y - 5);
  }
  g.fillStyle = '#4a4a4a';
  g.fillText(`${(span / TRACK_MARGIN).toFixed(0)} ${unit} across`, 8, h - 8);
}

// After a run in waves: the hull's RAOs at the speed ordered at the end of the run, in head and
// bow seas, over wave length / Lpp (g and Lpp from pageConstants); after a run in a regular sea,
// also the fuel study of Fig. 5-12.
export function drawSeaExtras(box, client, scenario, cols, constants, onError) {
  const generation = box.generation;
  const g = constants.gravity_m_s2, lpp = constants.seakeeping_lpp_m;
  const kn = Number(cols.speed_cmd_kn[cols.speed_cmd_kn.length - 1].toPrecision(3));
  const lam = Array.from({ length: RAO.points }, (_, i) => RAO.lambdaFrom + i * RAO.lambdaStep);
  const omegas = lam.map((l) => Math.sqrt((2 * Math.PI * g) / (l * lpp)));
  for (const [heading, name] of RAO.headings) {
    client.request(REQUEST.rao, { speed_kn: kn, heading_deg: heading, omegas }).then(({ result: r }) => {
      const pk = r.pitch.amp.map((p, i) => p / ((omegas[i] * omegas[i]) / g));
      box.line(`DTMB 5415 RAOs at ${kn} kn, ${name} seas (strip theory, ch. 2.5.2)`,
        { data: lam, label: `wave length / Lpp (Lpp = ${quantity(lpp, 'm')})` },
        [{ data: r.heave.amp, label: 'heave [m/m]', color: '#16a085' }, { data: pk, label: 'pitch / k [-]', color: '#d35400' }, { data: r.roll.amp, label: 'roll [rad/m]', color: '#7f8c8d' }],
        [{ scale: 'y', label: 'amplitude' }], { generation });
    }, () => { /* a cancelled or failed RAO leaves the run's plots as they are */ });
  }
  if (scenario.sea.kind !== 'regular') return;
  client.request(REQUEST.fuel, { scenario: JSON.stringify(scenario), omegas: FUEL_OMEGAS }).then(({ rows }) => {
    const { unit, factor } = withPrefix('W', 'M');
    const amplitudes = [...new Set(rows.map((r) => r.amplitude_ft))].sort((a, b) => a - b);
    for (const heading of [...new Set(rows.map((r) => r.heading))]) {
      const series = amplitudes.map((ft, j) => ({
        data: FUEL_OMEGAS.map((w) => { const r = rows.find((x) => x.heading === heading && x.amplitude_ft === ft && Math.abs(x.omega_rad_s - w) < 1e-9); return r ? r.fuel_power_w * factor : null; }),
        label: `${ft} ft`, color: FUEL_COLORS[j % FUEL_COLORS.length],
      }));
      const range = amplitudes.length ? `${amplitudes[0]} to ${amplitudes[amplitudes.length - 1]} ft` : 'no amplitudes';
      box.line(`Fuel power of one prime mover [${unit}], ${heading} seas, ${range} (Fig. 5-12)`,
        { data: FUEL_OMEGAS, label: 'wave frequency [rad/s]' }, series, [{ scale: 'y', label: `[${unit}]` }], { generation });
    }
  }, (e) => { if (!e.cancelled) onError(e); });
}
