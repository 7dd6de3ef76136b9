// The propeller: the panel of the study's blades beside the hull's (outline, pitch, open-water
// curves) with its picker; it follows the scenario in the form, and a pick goes into the form.
import { $ } from '../dom.js';
import { isBusy, status } from '../state.js';
import { PropellerPanel } from '../propeller.js';
import { registerView } from '../views.js';

let panel = null;

function refresh(ctx) {
  const { form } = ctx;
  if (!form || !form.scenario) return;
  const sc = form.current();
  panel.sync(sc);
  panel.update(sc);
}

registerView({
  id: 'propeller',
  init(ctx) {
    panel = new PropellerPanel($('propeller-box'), () => ctx.client);
  },
  ready(ctx) {
    const { form } = ctx;
    panel.attach({
      form, validate: ctx.validate, say: status, busy: isBusy,
      commit: (sc) => { form.scenario = sc; form.fill(); form.save(); ctx.onEdit(false); },
    });
  },
  drawRun(ctx, m) { panel.ranWith(m.summary); },
  selected(ctx) { panel.ranWith(null); refresh(ctx); },
  checked: refresh,
});
