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
  // Tables 5.6 and 5.7: each stage's power at the end, its energy over the whole run, and its
  // efficiency as core gives it: energies over the run's last minute with what the stage stored
  // counted (a ratio of powers in a transient is not an efficiency: a rotor giving up speed passes
  // on more than it takes). A stage core does not give (power flowed back through it) shows a dash.
  const inv = s.power_inventory_w || {}, en = s.energy_j || {}, eff = s.efficiency || {};
  const stages = [['turbine', 'gas turbines, shaft'], ['generator', 'generators, electrical', 'generator'], ['inverter', 'into the motors and bus loads', 'power_electronics'], ['motor', 'motors, shaft', 'motor'], ['ship', 'ship, resistance x speed', 'propeller']]
    .filter(([k]) => k in inv);
  const pct = (x) => (x == null ? '–' : `${(100 * x).toFixed(1)} %`);
  const bus = [['storage', 'storage_to_bus', 'storage, to the buses (+) or from them (-)'], ['bus_loads', 'bus_loads', 'ship service and pulsed loads']]
    .filter(([p, e]) => (inv[p] || 0) !== 0 || (en[e] || 0) !== 0);
  const window = 'from_s' in eff ? `efficiency, ${+eff.from_s.toFixed(1)}–${+eff.to_s.toFixed(1)} s` : 'efficiency';
  const body = $('inventory').querySelector('tbody');
  body.replaceChildren(el('tr', {}, ...['stage', 'power now [MW]', 'energy, whole run [MJ]', window].map((h) => el('th', { scope: 'col', textContent: h }))),
    ...stages.flatMap(([k, label, e]) => {
      const r = row(label, [fmt(inv[k] / 1e6), k in en ? fmt(en[k] / 1e6) : '–', e ? pct(eff[e]) : '–']);
      const parts = k === 'generator' ? bus.map(([p, b, l]) => row(l, [fmt((inv[p] || 0) / 1e6), fmt((en[b] || 0) / 1e6), '–'])) : [];
      return [r, ...parts];
    }));
  $('inventory-not-given').replaceChildren(...(eff.not_given || []).map((w) => el('li', { textContent: w })));
  $('inventory-not-given').hidden = !(eff.not_given || []).length;
  // The summary's warnings (core's health checks and the model's range), above the tables.
  $('warnings').replaceChildren(...(s.warnings || []).map((w) => el('li', { textContent: w })));
  $('warnings-box').hidden = !(s.warnings || []).length;
  $('summary-box').hidden = false;
}

registerView({
  id: 'summary',
  drawRun: (ctx, m) => showSummary(ctx.signals, m.summary, m.constants),
});
