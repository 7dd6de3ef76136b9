// A run's summary table under its plots: the key signals' final, min and max values, the power
// inventory (Tables 5.6, 5.7) and the summary's warnings (core's health checks, the model's range).
import { SUMMARY_ROWS } from '../config.js';
import { $, el, row, fmt } from '../dom.js';
import { registerView } from '../views.js';

function showSummary(signals, s, constants) {
  $('summary').querySelector('tbody').replaceChildren(...SUMMARY_ROWS.map((name) => {
    const v = s.signals[name];
    return row(signals.labelWithUnit(name, constants), [v.final, v.min, v.max].map((x) => Number(x).toPrecision(4)));
  }));
  // Tables 5.6 and 5.7: each stage's power at the end and what it passes on of the power it
  // takes, now and over the whole run (energies). A ratio of powers in a transient is not an
  // efficiency: a stage that gives up stored energy passes on more than it takes.
  const inv = s.power_inventory_w || {}, en = s.energy_j || {};
  const stages = [['turbine', 'gas turbines, shaft'], ['generator', 'generators, electrical'], ['inverter', 'into the motors'], ['motor', 'motors, shaft'], ['ship', 'ship, resistance x speed']]
    .filter(([k]) => k in inv);
  const ratio = (out, into) => (into > 0 && out >= 0 ? `${(100 * out / into).toFixed(1)} %` : '–');
  // With storage or other loads on the buses the motors' input is the generators' output plus
  // what the storage gives, less what the loads take (the drive train's picture counts the same).
  const bus = { storage: ['storage', 'storage_to_bus', 'storage, to the buses (+) or from them (-)'], loads: ['bus_loads', 'bus_loads', 'ship service and pulsed loads'] };
  const extra = Object.values(bus).filter(([p, e]) => (inv[p] || 0) !== 0 || (en[e] || 0) !== 0);
  const busIn = (o, key) => o.generator + (o[bus.storage[key]] || 0) - (o[bus.loads[key]] || 0);
  const into = (k, prev, o, key) => (k === 'inverter' ? busIn(o, key) : o[prev]);
  const body = $('inventory').querySelector('tbody');
  body.replaceChildren(el('tr', {}, ...['stage', 'power now [MW]', 'out / in now', 'energy, whole run [MJ]', 'out / in, whole run'].map((h) => el('th', { scope: 'col', textContent: h }))),
    ...stages.flatMap(([k, label], i) => {
      const prev = i > 0 ? stages[i - 1][0] : null;
      const r = row(label, [fmt(inv[k] / 1e6), prev ? ratio(inv[k], into(k, prev, inv, 0)) : '–', k in en ? fmt(en[k] / 1e6) : '–', prev && k in en ? ratio(en[k], into(k, prev, en, 1)) : '–']);
      const parts = k === 'generator' ? extra.map(([p, e, l]) => row(l, [fmt((inv[p] || 0) / 1e6), '–', fmt((en[e] || 0) / 1e6), '–'])) : [];
      return [r, ...parts];
    }));
  const over = stages.some(([k], i) => i > 0 && into(k, stages[i - 1][0], inv, 0) > 0 && inv[k] > into(k, stages[i - 1][0], inv, 0));
  $('inventory-over').hidden = !over;
  // The summary's warnings (core's health checks and the model's range), above the tables.
  $('warnings').replaceChildren(...(s.warnings || []).map((w) => el('li', { textContent: w })));
  $('warnings-box').hidden = !(s.warnings || []).length;
  $('summary-box').hidden = false;
}

registerView({
  id: 'summary',
  drawRun: (ctx, m) => showSummary(ctx.signals, m.summary, m.constants),
});
