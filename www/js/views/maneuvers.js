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
    full-astern stopping test (its track reach in the table, IMO's 15 L a reference for a naval ship) runs the whole
    power plant through the crash stop.</p>
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

// The turning circle seen from above, in ship lengths: east (transfer) to the right, north (the
// approach course, advance) up, a mark every 30 s; axes in ship lengths from where the rudder was
// ordered, with a scale bar in metres.
function drawTurn(cv, b) {
  // Taller than the other pictures (320 px): the axes and the scale take room.
  cv.style.height = '360px';
  const { g, w, h } = sizedCanvas(cv, 360);
  const L = b.length_m, tr = b.turning.track;
  const xs = tr.map((s) => s.y_m / L), ys = tr.map((s) => s.x_m / L);
  const [x0, x1, y0, y1] = [Math.min(...xs, 0), Math.max(...xs), Math.min(...ys, 0), Math.max(...ys)];
  // The plot area: room for the y axis's labels at the left, and below it the x axis's, the
  // scale bar and two lines of text.
  const left = 46, top = 8, right = 10, bottom = 96;
  const pw = w - left - right, ph = h - top - bottom;
  const span = Math.max(x1 - x0, y1 - y0, 1) * 1.1;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, s = Math.min(pw, ph) / span;
  const px = (x) => left + pw / 2 + (x - cx) * s, py = (y) => top + ph / 2 - (y - cy) * s;
  g.strokeStyle = '#ddd'; g.lineWidth = 1; g.strokeRect(0.5, 0.5, w - 1, h - 1);
  // Axes: grid lines and tick labels every `st` ship lengths over the plot area.
  const st = tickStep(Math.max(pw, ph) / s, 6);
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
  g.fillText('transfer, to starboard [ship lengths]', left + pw / 2, top + ph + 20);
  g.save(); g.translate(12, top + ph / 2); g.rotate(-Math.PI / 2); g.fillText('advance [ship lengths]', 0, -6); g.restore();
  g.save(); g.beginPath(); g.rect(left, top, pw, ph); g.clip();
  // The tactical diameter: a grey line across at the 180 deg point's transfer.
  g.strokeStyle = '#8a8a8a'; g.lineWidth = 1.5;
  const td = b.turning.tactical_diameter_m / L;
  g.beginPath(); g.moveTo(px(0), py(cy)); g.lineTo(px(td), py(cy)); g.stroke();
  g.strokeStyle = '#0b5cad'; g.lineWidth = 2;
  g.beginPath(); xs.forEach((x, i) => (i ? g.lineTo(px(x), py(ys[i])) : g.moveTo(px(x), py(ys[i])))); g.stroke();
  g.fillStyle = '#1b1b1b';
  for (let i = 0; i < tr.length; i += 300) { g.beginPath(); g.arc(px(xs[i]), py(ys[i]), 3, 0, 2 * Math.PI); g.fill(); }
  g.restore();
  // A scale bar of a round number of metres, about a fifth of the plot's width, under the axis
  // (never over the track).
  const mStep = tickStep((pw / s) * L / 5, 1), bar = (mStep / L) * s;
  g.strokeStyle = '#1b1b1b'; g.lineWidth = 3;
  g.beginPath(); g.moveTo(8, h - 46); g.lineTo(8 + bar, h - 46); g.stroke();
  g.textAlign = 'left'; g.textBaseline = 'middle'; g.fillText(`${mStep} m`, 14 + bar, h - 46);
  g.textBaseline = 'alphabetic'; g.fillStyle = '#4a4a4a';
  // Two short lines, so that a phone's narrow picture keeps them whole.
  g.fillText(`grey: tactical diameter ${fmt(td, 3)} L (L = ${fmt(L, 4)} m)`, 8, h - 8);
  g.fillText('a mark every 30 s from the rudder order', 8, h - 24);
  return { h, left, top, pw, ph, tick_l: st, scale_m: mStep, scale_px: bar, px_per_l: s };
}

function show(b) {
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
    el('thead', {}, head), el('tbody', {}, ...crit, ...more)));
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
    const { booklet } = await ctx.client.request(REQUEST.maneuvers, { scenario });
    show(booklet);
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
    plots = new PlotBox($('maneuvers-plots'));
    fold = new StudyFold('maneuvers', { failed: 'The maneuvers could not be sailed' });
    $('maneuvers-compute').addEventListener('click', () => compute(ctx));
  },
});
