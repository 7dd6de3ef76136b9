// The plots of a run (units from signalMeta, levels and bases from pageConstants): the study's
// plots first, the others under "More plots", a kept run drawn muted under the new one, and the
// ship's track.
import uPlot from '../vendor/uPlot.esm.js';
import { PLOTS, DEFAULT_PLOTS, LEVEL_COLORS, BAND_FILL, BAND_EDGE, SURFACE_FILL, KEPT_STYLE, TRACK_MARK_S, TRACK_MIN_SPAN_M } from './config.js';
import { el } from './dom.js';
import { sizedCanvas } from './plots.js';

const TRACK_MARGIN = 1.1; // the track fills 1/1.1 of the picture

// Characters of an axis label that fit along a plot's height (bold 12 px, 240 px plots: 143 px
// between the axes, about 7 px a character).
const AXIS_LABEL_CHARS = 20;
const fitLabel = (text, n) => (text.length <= n ? text : text.slice(0, Math.max(1, n - 1)) + '…');

// Times where surface losses start: beta_T leaves its submerged value (the propeller's fixed
// factor, 1 by default; read from the trace, not computed). A run whose propellers start under
// losses (a hub too shallow for the sea) has its first onset at its first row.
export function lossStarts(cols, submerged = 1) {
  const b = cols.beta_t, t = cols.t_s, out = [];
  for (let i = 0; i < b.length; i++) if (b[i] < submerged && (i === 0 || b[i - 1] >= submerged)) out.push(t[i]);
  return out;
}

// Series data of a kept run on the new run's time base (uPlot.join fills gaps with null).
function aligned(t, tk, columns) {
  const same = t.length === tk.length && t.every((v, i) => v === tk[i]);
  if (same) return { x: t, cols: columns.map(([a, b]) => [a, b]) };
  const j = uPlot.join([[Array.from(t), ...columns.map(([a]) => Array.from(a))], [Array.from(tk), ...columns.map(([, b]) => Array.from(b))]]);
  const n = columns.length;
  return { x: j[0], cols: columns.map((_, i) => [j[1 + i], j[1 + n + i]]) };
}

// The plot of one PLOTS entry: series grouped by displayed unit (and `axis: 'right'`) onto one or
// two y axes; a kept run's lines muted on the same axes.
function runPlot(box, spec, cols, signals, constants, kept, more, markers) {
  const groups = new Map(); // axis key -> {unit, bases: Set, series: []}
  const keptCols = kept && spec.series.every((s) => kept.columns[s.signal]) ? kept.columns : null;
  const { x, cols: pairs } = aligned(cols.t_s, keptCols ? keptCols.t_s : cols.t_s, spec.series.map((s) => [cols[s.signal], keptCols ? keptCols[s.signal] : cols[s.signal]]));
  spec.series.forEach((s, k) => {
    const { unit, factor } = signals.display(s.signal, spec.prefix);
    const key = s.axis === 'right' ? `${unit}:right` : unit;
    if (!groups.has(key)) groups.set(key, { unit, bases: new Set(), series: [], kept: [] });
    const g = groups.get(key);
    const base = signals.puBase(s.signal, constants);
    if (base) g.bases.add(base);
    const scale = 'y:' + key;
    const scaled = (d) => (factor === 1 ? d : Array.from(d, (v) => (v == null ? null : v * factor)));
    const label = s.label || signals.label(s.signal);
    // The run's own lines are solid (told apart by colour and width): a dash means the kept run.
    const { signal, axis, axisName, dash, ...style } = s;
    g.series.push({ ...style, data: scaled(pairs[k][0]), base, label, axisName: axisName || label, scale });
    if (keptCols) g.kept.push({ data: scaled(pairs[k][1]), label: `${label}, kept run (${kept.name})`, color: s.color + '88', dash: KEPT_STYLE.dash, width: KEPT_STYLE.width, scale, kept: true });
  });
  if (groups.size > 2) throw new Error(`plot '${spec.title}': more than two axes`);
  const axes = [];
  const series = [];
  for (const [key, g] of groups) {
    const one = g.bases.size === 1 && g.series.every((s) => s.base);
    const unitText = one ? `pu of ${[...g.bases][0]}` : g.unit;
    const names = g.series.map((s) => s.axisName).join(', ');
    // "heading [deg]" / "rudder [deg]" when two axes share a unit; "h/R [-]" when dimensionless.
    // A plot may name its one axis itself (`yLabel`, e.g. h/R of both shafts).
    // An axis label runs along the plot's height: more than about 20 characters would be cut,
    // unit first. Several lines on one axis are named by the first (the legend names them all).
    const named = `${names} [${unitText}]`.length <= AXIS_LABEL_CHARS ? names : g.series[0].axisName;
    const label = spec.yLabel && groups.size === 1 ? spec.yLabel
      : groups.size > 1 || g.unit === '-' ? `${fitLabel(named, AXIS_LABEL_CHARS - unitText.length - 3)} [${unitText}]` : `[${unitText}]`;
    axes.push({ scale: 'y:' + key, unit: unitText, label });
    for (const { base, axisName, ...s } of g.series) series.push(base && !one ? { ...s, label: `${s.label} (pu of ${base})` } : s);
  }
  for (const g of groups.values()) series.push(...g.kept);
  const units = [...new Set(axes.map((a) => a.unit))];
  const title = `${spec.title} [${units.join('; ')}]`;
  // The legend's entry for the kept run: one, short, its place held when there is none.
  const opts = { more, time: true, markers: spec.events ? markers : [], keptKey: keptCols ? fitLabel(kept.name || 'the run before', 40) : '' };
  if (spec.hOverR) {
    const lv = constants.h_over_r_levels;
    opts.hbands = constants.h_over_r_bands.map((b) => ({ from: b.from, to: b.to, fill: BAND_FILL, edge: BAND_EDGE }));
    const surface = Math.max(...lv.map((l) => l.value));
    opts.hbands.unshift({ from: surface, to: Math.min(...lv.map((l) => l.value), ...Array.from(cols.h_over_r)) - 1, fill: SURFACE_FILL });
    opts.levels = lv.map((l, j) => ({ value: l.value, label: l.label, color: LEVEL_COLORS[j % LEVEL_COLORS.length] }));
    const sw = (fill) => el('span', { className: 'swatch', attrs: { style: `background:${fill}` } });
    opts.key = [sw(BAND_FILL), ...constants.h_over_r_bands.map((b) => `${b.label}; `), sw(SURFACE_FILL), `below ${surface}: the disc breaks the surface; `,
      el('span', { textContent: `▼ ${markers.length} loss onsets` })];
    const lo = Math.min(...lv.map((l) => l.value));
    opts.scales = { [axes[0].scale]: { range: (u, min, max) => [Math.min(min, lo - 0.2), Math.max(max, 2)] } };
  } else if (spec.events && markers.length) {
    opts.key = [`▼ surface losses start (${markers.length}×)`];
  } else if (spec.key) {
    opts.key = [spec.key];
  }
  return box.line(title, { data: x, label: `time [${signals.meta('t_s').unit}]` }, series, axes, opts);
}

// Every plot of a run: the study's plots first (`order`: PLOTS ids and 'track'), the others under
// "More plots". kept: {name, columns} of a kept run, or null.
export function drawRun(box, cols, signals, constants, scenario, { order = DEFAULT_PLOTS, kept = null } = {}) {
  box.clear();
  const inWaves = cols.h_over_r.some((v) => v !== cols.h_over_r[0]);
  const markers = inWaves ? lossStarts(cols, scenario.propeller.beta_t) : [];
  const drawn = {};
  const shown = (id) => order.includes(id);
  const track = (more) => {
    const unit = signals.meta('x_m').unit;
    const from = scenario.sea.kind === 'calm' ? '' : `; arrow: waves from ${scenario.sea.from_deg}°`;
    box.canvas(`Ship track [${unit}] (north up; marks every ${TRACK_MARK_S} ${signals.meta('t_s').unit}${from})`, 'Ship track seen from above', (cv) => drawTrack(cv, cols, unit, scenario, kept), more);
  };
  const specs = PLOTS.filter((spec) => !(spec.only && !spec.only(cols)) && !(spec.sea && !inWaves) && !(spec.asked && !shown(spec.id)));
  for (const id of order) {
    if (id === 'track') { track(false); continue; }
    const spec = specs.find((s) => s.id === id);
    if (spec) drawn[id] = runPlot(box, spec, cols, signals, constants, kept, false, markers);
  }
  for (const spec of specs) if (!shown(spec.id)) drawn[spec.id] = runPlot(box, spec, cols, signals, constants, kept, true, markers);
  if (!shown('track')) track(true);
  return { markers, drawn };
}

function drawTrack(cv, cols, unit, scenario, kept) {
  const { g, w, h } = sizedCanvas(cv, 320);
  const xs = cols.y_m, ys = cols.x_m; // east to the right, north up
  const all = (a, b) => (kept ? [...a, ...b] : [...a]);
  const kx = kept ? kept.columns.y_m : [], ky = kept ? kept.columns.x_m : [];
  const ax = all(xs, kx), ay = all(ys, ky);
  const [x0, x1, y0, y1] = [Math.min(...ax), Math.max(...ax), Math.min(...ay), Math.max(...ay)];
  const span = Math.max(x1 - x0, y1 - y0, TRACK_MIN_SPAN_M) * TRACK_MARGIN;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const s = Math.min(w, h) / span;
  const px = (x) => w / 2 + (x - cx) * s, py = (y) => h / 2 - (y - cy) * s;
  g.strokeStyle = '#ddd'; g.lineWidth = 1;
  g.strokeRect(0.5, 0.5, w - 1, h - 1);
  if (kept) {
    g.strokeStyle = '#8a8a8a'; g.setLineDash(KEPT_STYLE.dash); g.lineWidth = 2;
    g.beginPath(); kx.forEach((x, i) => (i ? g.lineTo(px(x), py(ky[i])) : g.moveTo(px(x), py(ky[i])))); g.stroke();
    g.setLineDash([]);
  }
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
  g.fillText(`${(span / TRACK_MARGIN).toFixed(0)} ${unit} across${kept ? `; dashed: kept run (${kept.name})` : ''}`, 8, h - 8);
  if (scenario.sea.kind !== 'calm') {
    // Waves travel away from `from_deg`: an arrow in the corner pointing the way they go.
    const d = ((scenario.sea.from_deg + 180) * Math.PI) / 180, X = w - 40, Y = 40, L = 24;
    const ex = X + L * Math.sin(d), ey = Y - L * Math.cos(d);
    g.strokeStyle = '#117a65'; g.fillStyle = '#117a65'; g.lineWidth = 3;
    g.beginPath(); g.moveTo(X - L * Math.sin(d), Y + L * Math.cos(d)); g.lineTo(ex, ey); g.stroke();
    g.beginPath(); g.arc(ex, ey, 5, 0, 2 * Math.PI); g.fill();
    g.fillText('waves', X - 16, Y + 36);
  }
}
