// The hull: the panel of the study's hull (its sheet also gives the loading fields their
// placeholders, the hull's own values, and the hub height its h0) and the picker with its file
// loader; both follow the scenario in the form.
import { $ } from '../dom.js';
import { isBusy, status } from '../state.js';
import { HullPanel, HullPicker } from '../hull.js';
import { num } from '../hulldraw.js';
import { registerView } from '../views.js';

let panel = null;
let picker = null;

function refresh(ctx) {
  const { form } = ctx;
  if (!form || !form.scenario) return;
  const sc = form.current();
  if (picker) picker.sync(sc);
  panel.update(sc, picker ? picker.fileOf(sc) : null);
}

registerView({
  id: 'hull',
  init(ctx) {
    panel = new HullPanel($('hull-box'), () => ctx.client, {
      // Placeholders as numbers one could type (no thousands separators).
      onSheet: (h) => ctx.form && ctx.form.showHullValues(Object.fromEntries([
        ['draft_m', h.draft_m], ['mass_kg', h.mass_kg], ['kg_m', h.kg_m], ['kxx_m', h.k_m[0]], ['kyy_m', h.k_m[1]], ['kzz_m', h.k_m[2]], ['hub_above_base_m', h.hub_above_base_m],
      ].map(([k, v]) => [`ship.hull.${k}`, `${Math.abs(v) >= 1000 ? String(Math.round(v)) : num(v)} (now)`])), { 'ship.hull.hub_above_base_m': ` Now h0 = ${num(h.draft_m)} - ${num(h.hub_above_base_m)} = ${num(h.hub_depth_m)} m.` }),
    });
  },
  ready(ctx, m) {
    const { form } = ctx;
    picker = new HullPicker(m.hulls || [], {
      form, validate: ctx.validate, say: status, busy: isBusy,
      // An accepted hull or scenario file: into the form (a scenario file may name its study).
      commit: (sc, { name } = {}) => {
        const other = name && name !== form.name;
        if (other) form.select(name, sc); else { form.scenario = sc; form.fill(); }
        form.save();
        ctx.onEdit(other);
      },
    });
  },
  // A study in calm water does not depend on the hull's sections: its panel starts folded.
  selected(ctx) { if (ctx.form && ctx.form.scenario) panel.folded(ctx.form.scenario.sea.kind === 'calm'); refresh(ctx); },
  checked: refresh,
});
