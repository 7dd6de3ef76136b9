// The standard maneuvers of the form's ship (core's studies::maneuvers, `aes-sim maneuvers`): the
// 35 deg turning circle and the 10/10 and 20/20 zig-zags from the study's first ordered speed with
// the shafts held, drawn, and the booklet's table beside IMO MSC.137(76)'s limits. All of it is
// this module: the fold's DOM, the request and the drawing; every number is the wasm's.
import { $, el, fmt, row } from '../dom.js';
import { studyTitle } from '../config.js';
import { choiceLabel } from '../registry.js';
import { REQUEST } from '../protocol.js';
import { announce } from '../state.js';
import { PlotBox, sizedCanvas } from '../plots.js';
import { StudyFold } from '../fold.js';
import { registerView } from '../views.js';
import { RUDDER_SIGN } from '../units.js';

const TEMPLATE = `
<section class="maneuvers" aria-labelledby="maneuvers-h">
  <p class="about">The ship of the form as it stands, from its first ordered speed with its shafts held at that speed's
    calm-water rpm, as a trials booklet gives it: the turning circle with 35&deg; of rudder and the zig-zags, each beside
    the limit of IMO's standards for ship manoeuvrability. Only the hull, its rudders and propellers move in these; the
    full-astern stopping test (IMO's track reach limit a reference for a naval ship) runs the whole power plant through
    the crash stop: its track is drawn after the zig-zags, with the speed, the bus and where the ship's energy goes on
    one time axis below it.</p>
  <div class="row buttons">
    <button id="maneuvers-compute" type="button">Compute the booklet</button>
  </div>
  <div id="maneuvers-status" role="status" aria-live="polite"></div>
  <div id="maneuvers-fix" class="row buttons" hidden></div>
  <div id="maneuvers-body" hidden>
    <div id="maneuvers-table" class="scroll" tabindex="0" role="region" aria-label="The booklet: IMO criteria"></div>
    <div id="maneuvers-plots"></div>
  </div>
</section>`;

let plots = null;
let fold = null; // its shownKey: the scenario the result shown belongs to

// A tick step for a span (1, 2 or 5 times a power of ten) giving about `n` ticks.
function tickStep(span, n) {
  const raw = span / n, p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((st) => st >= raw);
}

// A plan view in ship lengths (east to the right, north, the approach course, up) at one scale
// both ways, with grid lines and tick labels every round number of ship lengths: draws the axes
// and returns the mapping. `xs`, `ys`: the points the view must hold [ship lengths]; `min`: the
// smallest span shown [ship lengths]. The plot area leaves room below for the x axis's label,
// a scale bar and two lines of text.
function planAxes(cv, xs, ys, xLabel, yLabel, min = 1) {
  // Taller than the other pictures (320 px): the axes and the scale take room.
  cv.style.height = '360px';
  const { g, w, h } = sizedCanvas(cv, 360);
  const [x0, x1, y0, y1] = [Math.min(...xs, 0), Math.max(...xs), Math.min(...ys, 0), Math.max(...ys)];
  const left = 46, top = 8, right = 10, bottom = 96;
  const pw = w - left - right, ph = h - top - bottom;
  const span = Math.max(x1 - x0, y1 - y0, min) * 1.1;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, s = Math.min(pw, ph) / span;
  const px = (x) => left + pw / 2 + (x - cx) * s, py = (y) => top + ph / 2 - (y - cy) * s;
  g.strokeStyle = '#ddd'; g.lineWidth = 1; g.strokeRect(0.5, 0.5, w - 1, h - 1);
  // Ticks from the shorter side's span, so a wide picture still labels its short axis.
  const st = tickStep(Math.min(pw, ph) / s, 5);
  const [ex0, ex1] = [cx - pw / 2 / s, cx + pw / 2 / s], [ey0, ey1] = [cy - ph / 2 / s, cy + ph / 2 / s];
  g.font = '12px system-ui'; g.fillStyle = '#1b1b1b';
  const lab = (v) => String(Number(v.toFixed(6)));
  g.textAlign = 'center'; g.textBaseline = 'top';
  for (let v = Math.ceil(ex0 / st) * st; v <= ex1 + 1e-9; v += st) {
    g.strokeStyle = Math.abs(v) < 1e-9 ? '#9a9a9a' : '#e6e6e6';
    g.beginPath(); g.moveTo(px(v), top); g.lineTo(px(v), top + ph); g.stroke();
    g.fillText(lab(v), px(v), top + ph + 4);
  }
  g.textAlign = 'right'; g.textBaseline = 'middle';
  for (let v = Math.ceil(ey0 / st) * st; v <= ey1 + 1e-9; v += st) {
    g.strokeStyle = Math.abs(v) < 1e-9 ? '#9a9a9a' : '#e6e6e6';
    g.beginPath(); g.moveTo(left, py(v)); g.lineTo(left + pw, py(v)); g.stroke();
    g.fillText(lab(v), left - 6, py(v));
  }
  g.strokeStyle = '#4a4a4a'; g.strokeRect(left + 0.5, top + 0.5, pw, ph);
  g.textAlign = 'center'; g.textBaseline = 'top';
  g.fillText(xLabel, left + pw / 2, top + ph + 20);
  g.save(); g.translate(12, top + ph / 2); g.rotate(-Math.PI / 2); g.fillText(yLabel, 0, -6); g.restore();
  // Drawing inside the plot area: clipped to it (`inside`); `line` strokes a polyline of
  // points i in [from, to).
  const inside = (draw) => { g.save(); g.beginPath(); g.rect(left, top, pw, ph); g.clip(); draw(); g.restore(); };
  const line = (from, to, color, width) => {
    g.strokeStyle = color; g.lineWidth = width;
    g.beginPath();
    for (let i = from; i < to; i++) (i > from ? g.lineTo(px(xs[i]), py(ys[i])) : g.moveTo(px(xs[i]), py(ys[i])));
    g.stroke();
  };
  return { g, w, h, left, top, pw, ph, st, s, cy, px, py, inside, line };
}

// A scale bar of a round number of metres, about a fifth of the plot's width, under the axis
// (never over the track), and two short lines of text under it (a phone's narrow picture keeps
// them whole). Returns what the axes and the bar are.
function scaleBar(a, L, lines) {
  const { g, h, pw, s } = a;
  const mStep = tickStep((pw / s) * L / 5, 1), bar = (mStep / L) * s;
  g.strokeStyle = '#1b1b1b'; g.lineWidth = 3;
  g.beginPath(); g.moveTo(8, h - 46); g.lineTo(8 + bar, h - 46); g.stroke();
  g.fillStyle = '#1b1b1b'; g.textAlign = 'left'; g.textBaseline = 'middle'; g.fillText(`${mStep} m`, 14 + bar, h - 46);
  g.textBaseline = 'alphabetic'; g.fillStyle = '#4a4a4a';
  g.fillText(lines[0], 8, h - 24);
  g.fillText(lines[1], 8, h - 8);
  return { h, left: a.left, top: a.top, pw, ph: a.ph, tick_l: a.st, scale_m: mStep, scale_px: bar, px_per_l: s };
}

// The turning circle seen from above, in ship lengths: east (transfer) to the right, north (the
// approach course, advance) up, a mark every 30 s; axes in ship lengths from where the rudder was
// ordered, with a scale bar in metres.
function drawTurn(cv, b) {
  const L = b.length_m, tr = b.turning.track;
  const xs = tr.map((s) => s.y_m / L), ys = tr.map((s) => s.x_m / L);
  const a = planAxes(cv, xs, ys, 'transfer, to starboard [ship lengths]', 'advance [ship lengths]');
  const { g, px, py } = a;
  const td = b.turning.tactical_diameter_m / L;
  a.inside(() => {
    // The tactical diameter: a grey line across at the 180 deg point's transfer.
    g.strokeStyle = '#8a8a8a'; g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(px(0), py(a.cy)); g.lineTo(px(td), py(a.cy)); g.stroke();
    a.line(0, xs.length, '#0b5cad', 2);
    g.fillStyle = '#1b1b1b';
    for (let i = 0; i < tr.length; i += 300) { g.beginPath(); g.arc(px(xs[i]), py(ys[i]), 3, 0, 2 * Math.PI); g.fill(); }
  });
  return scaleBar(a, L, ['a mark every 30 s from the rudder order', `grey: tactical diameter ${fmt(td, 3)} L (L = ${fmt(L, 4)} m)`]);
}

// The stop's samples are 0.5 s apart (core's studies::stopping); its pictures show from the
// order to twice the time to dead in the water (rounded up to 10 s): the stop and as long again
// going astern.
const STOP_MARK_S = 10;
function stopWindow(st) {
  const until = Math.ceil((2 * st.time_to_dead_s) / 10) * 10;
  return st.track.filter((s) => s.t_s <= until + 1e-9);
}

// The full-astern stop seen from above, as the turning circle is drawn: its track from the order
// until dead in the water (blue), a mark every 10 s, the order point (ring) and the point dead
// in the water (square) marked; the way astern after it is left to the traces below.
function drawStop(cv, b, limit) {
  const L = b.length_m, st = b.stopping;
  const tr = st.track.filter((s) => s.t_s <= st.time_to_dead_s + 1e-9);
  const xs = tr.map((s) => s.y_m / L), ys = tr.map((s) => s.x_m / L);
  const a = planAxes(cv, xs, ys, 'lateral deviation, to starboard [ship lengths]', 'head reach [ship lengths]');
  const { g, px, py } = a;
  const n = xs.length - 1;
  a.inside(() => {
    a.line(0, xs.length, '#0b5cad', 2.5);
    g.fillStyle = '#1b1b1b';
    const every = Math.round(STOP_MARK_S / (tr[1].t_s - tr[0].t_s));
    for (let i = every; i < n; i += every) { g.beginPath(); g.arc(px(xs[i]), py(ys[i]), 3, 0, 2 * Math.PI); g.fill(); }
    // The order: a ring; dead in the water: a filled square; each labelled to the right.
    g.strokeStyle = '#1b1b1b'; g.lineWidth = 2;
    g.beginPath(); g.arc(px(xs[0]), py(ys[0]), 6, 0, 2 * Math.PI); g.stroke();
    g.fillStyle = '#b8480b';
    g.fillRect(px(xs[n]) - 6, py(ys[n]) - 6, 12, 12);
    g.font = '12px system-ui'; g.textBaseline = 'middle'; g.fillStyle = '#1b1b1b';
    // Right of the point, or left of it where the plot's edge would cut the words; in two lines
    // where neither side has room (a phone's picture).
    const say = (text, i) => {
      const room = (dir) => (dir > 0 ? a.left + a.pw - px(xs[i]) : px(xs[i]) - a.left) - 12;
      const w = g.measureText(text).width;
      const dir = w <= room(1) ? 1 : w <= room(-1) ? -1 : 0;
      const parts = dir ? [text] : text.split(', ');
      g.textAlign = dir < 0 ? 'right' : 'left';
      parts.forEach((t, k) => g.fillText(t, px(xs[i]) + (dir < 0 ? -10 : 10), py(ys[i]) + 14 * k));
    };
    say('full astern ordered', 0);
    say(`dead in the water, ${fmt(st.time_to_dead_s, 3)} s`, n);
  });
  // IMO's limit lies far off this picture: said in words, with how many times the track reach.
  const imo = `IMO's limit ${fmt(limit, 3)} L (${fmt(limit / st.track_reach_l, 2)} times this)`;
  return scaleBar(a, L, [`a mark every ${STOP_MARK_S} s; L = ${fmt(L, 4)} m`, `track reach ${fmt(st.track_reach_l, 3)} L; ${imo}`]);
}

// The stop's traces on one time axis from the order: speed and shaft speed, the bus voltage
// within its band (pageConstants' health levels), and the motors' and brake resistors' power.
function stopTraces(st, band) {
  const tr = stopWindow(st);
  const x = { data: tr.map((s) => s.t_s), label: 'time from the full-astern order [s]' };
  const col = (k, scale = 1) => tr.map((s) => s[k] * scale);
  const dead = `marker: dead in the water at ${fmt(st.time_to_dead_s, 3)} s`;
  const opts = (more) => ({ time: true, markers: [st.time_to_dead_s], key: [dead, ...more] });
  plots.line(`Crash stop from ${fmt(st.approach_kn, 3)} kn: speed and shaft speed`, x, [
    { data: col('speed_kn'), label: 'speed through the water (ahead, then astern) [kn]', color: '#0b5cad', width: 2.4 },
    { data: col('shaft_rpm'), label: 'shaft speed, port (negative: astern) [rpm]', color: '#b8480b', width: 1.6, scale: 'rpm' },
  ], [{ scale: 'y', label: 'speed [kn]' }, { scale: 'rpm', label: 'shaft [rpm]' }], opts([]));
  plots.line(`Crash stop: bus voltage (highest ${fmt(st.peak_bus_voltage_pu, 3)} pu)`, x, [
    { data: col('bus_voltage_pu'), label: 'bus voltage, mean of the two buses [pu]', color: '#0b5cad', width: 2.4 },
  ], [{ scale: 'y', label: 'bus voltage [pu]' }], {
    ...opts([`; shaded: the bus's band, ${band.bus_voltage_low_pu} to ${+band.bus_voltage_high_pu.toPrecision(6)} pu`]),
    hbands: [{ from: band.bus_voltage_low_pu, to: band.bus_voltage_high_pu, fill: 'rgba(39, 174, 96, 0.12)', edge: '#5b8f6b' }],
    // The whole band in view, and the trace wherever it leaves it.
    scales: { y: { range: (u, lo, hi) => [Math.min(lo, band.bus_voltage_low_pu) - 0.02, Math.max(hi, band.bus_voltage_high_pu) + 0.02] } },
  });
  plots.line(`Crash stop: motor and brake power (the motors returned up to ${fmt(st.peak_regenerated_w / 1e6, 3)} MW)`, x, [
    { data: col('motor_power_w', 1e-6), label: 'into the motors, both (negative: returned to the bus) [MW]', color: '#0b5cad', width: 2.4 },
    { data: col('brake_power_w', 1e-6), label: 'burnt in the brake resistors [MW]', color: '#b8480b', width: 1.6 },
  ], [{ scale: 'y', label: 'power [MW]' }], opts([]));
}

// The stopping test's rows of the table: what the criterion's track reach does not say.
function stopRows(b) {
  const st = b.stopping;
  if (!st) return [row('full-astern stopping test', [`not run: ${b.stopping_refused}`, '', ''])];
  const r = (what, value) => row(`full-astern stop: ${what}`, [value, '', '']);
  return [
    r('head reach', `${fmt(st.head_reach_l, 3)} L (${fmt(st.head_reach_m, 3)} m)`),
    r('lateral deviation (+ to starboard)', `${fmt(st.lateral_deviation_l, 3)} L (${fmt(st.lateral_deviation_m, 3)} m)`),
    r('time to dead in the water', `${fmt(st.time_to_dead_s, 3)} s`),
    r('highest bus voltage', `${fmt(st.peak_bus_voltage_pu, 3)} pu (${fmt(st.peak_bus_voltage_v / 1e3, 3)} kV)`),
    r('brake energy until dead in the water', `${fmt(st.brake_energy_j / 1e6, 3)} MJ`),
    r('storage took until dead in the water', `${fmt(st.storage_taken_j / 1e6, 3)} MJ`),
    r('highest power the motors returned', `${fmt(st.peak_regenerated_w / 1e6, 3)} MW`),
    ...(st.adjustments.length ? [r('changed to run it', st.adjustments.join('; '))] : []),
    ...(st.warnings.length ? [r('health warnings', st.warnings.join('; '))] : []),
  ];
}

function show(b, constants) {
  $('maneuvers-body').hidden = false;
  const L = b.length_m, t = b.turning;
  const head = el('tr', {}, ...['criterion', 'ours', 'IMO limit', 'verdict'].map((x) => el('th', { scope: 'col', textContent: x })));
  const crit = b.criteria.map((c) => row(c.name, [`${fmt(c.value, 3)} ${c.unit}`, `${fmt(c.limit, 3)} ${c.unit}`, c.pass ? 'pass' : 'fail']));
  const more = [
    row('steady turning diameter', [`${fmt(t.steady_diameter_m / L, 3)} L`, '', '']),
    row('speed in the steady turn', [`${fmt(100 * t.speed_ratio, 3)} % of the approach`, '', '']),
    row('coasting to 5 kn with the propellers stopped', [`${fmt(b.coasting.track_reach_m / L, 3)} L in ${fmt(b.coasting.time_s, 3)} s`, '', '']),
  ];
  $('maneuvers-table').replaceChildren(el('table', {}, el('caption', { textContent: `From ${fmt(b.approach_kn, 3)} kn with the shafts at ${fmt(b.shaft_rpm, 3)} rpm (L = ${fmt(L, 4)} m)` }),
    el('thead', {}, head), el('tbody', {}, ...crit, ...more, ...stopRows(b))));
  plots.clear();
  plots.canvas('Turning circle with 35° of rudder, seen from above [ship lengths]', `Turning circle: advance ${fmt(t.advance_m / L, 3)} ship lengths, tactical diameter ${fmt(t.tactical_diameter_m / L, 3)} ship lengths`, (cv) => { cv.drawnAxes = drawTurn(cv, b); });
  for (const z of [b.zigzag_10, b.zigzag_20]) {
    const tr = z.track;
    plots.line(`${z.rudder_deg}/${z.rudder_deg} zig-zag: heading and rudder [deg] (overshoots ${fmt(z.first_overshoot_deg, 3)}° and ${fmt(z.second_overshoot_deg, 3)}°)`,
      { data: tr.map((s) => s.t_s), label: 'time [s]' }, [
        { data: tr.map((s) => s.heading_deg), label: 'heading change (+ to starboard) [deg]', color: '#0b5cad', width: 2.4 },
        // The booklet records the rudder positive to starboard (core's studies::maneuvers); the
        // page gives every rudder angle in the model's sign, + turning the ship to port.
        { data: tr.map((s) => -s.rudder_deg), label: 'rudder (+ to port) [deg]', color: '#b8480b', width: 1.4 },
      ], [{ scale: 'y', label: 'angle [deg]' }], { key: [RUDDER_SIGN] });
  }
  const st = b.stopping;
  if (!st) return;
  const c = b.criteria.find((x) => x.name.startsWith('stopping ability'));
  plots.canvas(`Full-astern stop from ${fmt(st.approach_kn, 3)} kn, seen from above [ship lengths]`, `Full-astern stop: track reach ${fmt(st.track_reach_l, 3)} ship lengths, head reach ${fmt(st.head_reach_l, 3)}, lateral deviation ${fmt(st.lateral_deviation_l, 3)}, dead in the water ${fmt(st.time_to_dead_s, 3)} s after the order; IMO's limit ${fmt(c.limit, 3)} ship lengths`, (cv) => { cv.drawnAxes = drawStop(cv, b, c.limit); });
  stopTraces(st, constants.warnings);
}

// A hull that goes straight only cannot sail them: one click sets the field the refusal names, or
// opens a study that turns (core's message names both), and computes.
const TURNING_STUDY = 'turn-360';
function offerFixes(ctx, sc) {
  const box = $('maneuvers-fix');
  box.hidden = !sc.hull || sc.hull.model === 'maneuvering';
  if (box.hidden) return;
  const model = el('button', { type: 'button', id: 'maneuvers-fix-model', textContent: `Use the hull model "${choiceLabel('hull.model', 'maneuvering')}" and compute` });
  model.addEventListener('click', () => {
    const f = $('f-hull-model');
    f.value = 'maneuvering';
    f.dispatchEvent(new Event('change'));
    compute(ctx);
  });
  const study = el('button', { type: 'button', id: 'maneuvers-fix-study', textContent: `Open "${studyTitle(TURNING_STUDY)}" and compute` });
  study.addEventListener('click', () => { ctx.selectStudy(TURNING_STUDY); compute(ctx); });
  box.replaceChildren(model, study);
}

async function compute(ctx) {
  const inp = ctx.studyInputs();
  if (!inp) return;
  $('maneuvers-fix').hidden = true;
  if (inp.invalid) { fold.status('A value of the form is refused (marked at its field): correct it first.'); return; }
  const scenario = JSON.stringify(inp.scenario);
  await fold.compute(async () => {
    fold.status('Sailing the maneuvers...');
    const { booklet, constants } = await ctx.client.request(REQUEST.maneuvers, { scenario });
    show(booklet, constants);
    fold.shownKey = scenario;
    const failed = booklet.criteria.filter((c) => !c.pass).length;
    fold.status(`Done (${inp.title}): ${failed ? `${failed} of ${booklet.criteria.length} IMO criteria not met` : `all ${booklet.criteria.length} IMO criteria met`}.`);
    announce('maneuvers', booklet);
  }, { onFail: () => { $('maneuvers-body').hidden = true; fold.shownKey = null; offerFixes(ctx, inp.scenario); } });
}

// A booklet of another ship or speed is not shown under this one.
function sync(ctx) {
  const inp = ctx.studyInputs();
  if (inp && inp.scenario.hull && inp.scenario.hull.model === 'maneuvering') $('maneuvers-fix').hidden = true;
  fold.drop(inp ? JSON.stringify(inp.scenario) : null, 'The study changed since the booklet was computed: compute it again.');
}

registerView({
  id: 'maneuvers',
  sync,
  init(ctx) {
    $('maneuvers-box').insertAdjacentHTML('beforeend', TEMPLATE);
    // One cursor across the stop's traces (their shared time axis).
    plots = new PlotBox($('maneuvers-plots'), { sync: 'maneuvers' });
    fold = new StudyFold('maneuvers', { failed: 'The maneuvers could not be sailed' });
    $('maneuvers-compute').addEventListener('click', () => compute(ctx));
  },
});
