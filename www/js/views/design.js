// The controller design tab (ch. 3): its tuning is part of the address, and "run next to the PI
// loops" runs the acceleration with the PI loops, keeps it, then runs it again with this LQG/LTR
// tuning, drawn over it.
import { DESIGN } from '../config.js';
import { $ } from '../dom.js';
import { isBusy } from '../state.js';
import { PlotBox } from '../plots.js';
import { DesignTab } from '../design.js';
import { registerView } from '../views.js';
import { compareWith } from './compare.js';

let design = null;

registerView({
  id: 'design',
  tab: 'design',
  skip: '#design-plots',
  init(ctx) {
    design = new DesignTab(() => ctx.client, new PlotBox($('design-plots')), () => ctx.form.preset(DESIGN.basePreset), (tuning) => {
      if (isBusy() || !ctx.form) return;
      ctx.selectTab('tab-sim');
      ctx.selectStudy(DESIGN.basePreset);
      const set = { 'controllers.design': 'lqg_ltr' };
      for (const [k, v] of Object.entries(tuning)) set[`controllers.lqg_ltr.${k}`] = v;
      compareWith(ctx, { set });
    });
    design.onChange = () => { if (ctx.form) ctx.follow(false); };
  },
  ready: (ctx, m) => design.configure(m.params),
  restore: (ctx, link) => design.restore(link ? link.design : null),
  linkState: () => ({ design: design.changed() }),
  shown: () => design.update(),
});
