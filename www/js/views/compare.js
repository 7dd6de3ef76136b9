// Kept runs and comparisons: "Keep this run" pins a run that the next ones draw over (dashed,
// muted), the study's "Compare with ..." buttons, and the key figures of the kept run against the
// new one.
import { STUDIES, KEY_FIGURES } from '../config.js';
import { $, el, fmt } from '../dom.js';
import { isBusy, getResult, status } from '../state.js';
import { setPath } from '../form.js';
import { withPrefix } from '../units.js';
import { registerView } from '../views.js';

// A key figure of config.js as a label with its unit and a reader of a summary.
function keyFigure(signals, fig) {
  if (fig.energy) {
    const { unit, factor } = withPrefix('J', fig.prefix);
    return { label: `${fig.text} [${unit}]`, f: (s) => s.energy_j[fig.energy] * factor };
  }
  const { unit, factor } = signals.display(fig.signal, fig.prefix);
  const shown = fig.stat.endsWith('_s') ? 's' : unit;
  const stat = (x) => (fig.stat === 'swing' ? x.max - x.min : x[fig.stat]);
  return {
    label: `${fig.text.replace('{}', signals.label(fig.signal))} [${shown}]`,
    // null: a statistic the summary leaves undefined (a settling time of a signal that does not settle).
    f: (s) => { const x = stat(s.signals[fig.signal]); return x === null || x === undefined ? null : x * (fig.stat.endsWith('_s') ? 1 : factor); },
  };
}

// The kept run against the new one: key figures side by side.
function showComparison(ctx, now) {
  const box = $('compare-box');
  const { kept } = ctx;
  if (!kept || !now) { box.hidden = true; return; }
  const rows = [];
  for (const fig of KEY_FIGURES) {
    const { label, f } = keyFigure(ctx.signals, fig);
    let a, b;
    try { a = f(kept.summary); b = f(now.summary); } catch (_) { continue; }
    if (fig.none && (a === null || b === null)) {
      // Undefined on one side or both: said in words (config.js), no difference.
      if (a === null && b === null) continue;
      const say = (x) => (x === null ? fig.none : fmt(x));
      rows.push(el('tr', {}, el('th', { scope: 'row', textContent: label }), el('td', { textContent: say(a) }), el('td', { textContent: say(b) }), el('td', { textContent: '–' })));
      continue;
    }
    if (a === null || b === null || !Number.isFinite(a) || !Number.isFinite(b) || (a === 0 && b === 0)) continue;
    const d = b - a;
    // Coloured and worded by better or worse where the figure has a good direction, else neutral.
    const good = fig.better && d !== 0 ? (d > 0) === (fig.better === 'higher') : null;
    const cell = el('td', { textContent: `${d >= 0 ? '+' : ''}${fmt(d, 3)}${good === null ? '' : good ? ' (better)' : ' (worse)'}`, className: good === null ? '' : good ? 'better' : 'worse' });
    rows.push(el('tr', {}, el('th', { scope: 'row', textContent: label }), el('td', { textContent: fmt(a) }), el('td', { textContent: fmt(b) }), cell));
  }
  const head = el('tr', {}, ...['key figure', `kept: ${kept.name}`, `this run: ${now.name}`, 'difference'].map((h) => el('th', { scope: 'col', textContent: h })));
  box.replaceChildren(el('h2', { textContent: 'Compared with the kept run (dashed, muted in every plot)' }),
    el('div', { className: 'scroll', tabIndex: 0, attrs: { role: 'region', 'aria-label': 'Key figures compared' } }, el('table', { id: 'compare-table' }, el('thead', {}, head), el('tbody', {}, ...rows))));
  box.hidden = false;
}

function keep(ctx) {
  const r = getResult();
  if (!r || !r.columns) return;
  ctx.keep({ name: r.name, columns: r.columns, summary: r.summary });
  $('unkeep').hidden = false;
  status(`Kept: ${r.name}. The next runs draw over it, muted and dashed.`);
}

// "Compare with ...": keep this study's run (running it first if needed), then run the other
// (c.preset: another study; c.set: path -> value in this one).
export async function compareWith(ctx, c) {
  const { form } = ctx;
  if (isBusy() || !form) return;
  const r = getResult();
  if (!r || !r.columns || JSON.stringify(r.scenario) !== JSON.stringify(form.scenario)) await ctx.run({ focus: false });
  if (!getResult() || !getResult().columns) return;
  keep(ctx);
  if (c.preset) ctx.selectStudy(c.preset);
  else {
    for (const [path, v] of Object.entries(c.set)) setPath(form.scenario, path, v);
    form.fill();
    form.save();
  }
  await ctx.run();
}

function showCompareButtons(ctx) {
  const study = STUDIES[ctx.form.name] || {};
  $('compare-with').replaceChildren(...(study.compare || []).map((c) => {
    const b = el('button', { type: 'button', textContent: `Compare with ${c.label}` });
    b.addEventListener('click', () => compareWith(ctx, c));
    return b;
  }));
}

registerView({
  id: 'compare',
  init(ctx) {
    $('keep').addEventListener('click', () => keep(ctx));
    $('unkeep').addEventListener('click', () => { ctx.keep(null); $('unkeep').hidden = true; $('compare-box').hidden = true; status('The kept run is forgotten.'); });
  },
  selected: showCompareButtons,
  drawRun: (ctx, m, name) => showComparison(ctx, { summary: m.summary, name }),
});
