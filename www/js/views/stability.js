// The stability tool's tab (ch. 4): its operating point comes from the worker's ready message, and
// the tab redraws when shown.
import { $ } from '../dom.js';
import { PlotBox } from '../plots.js';
import { StabilityTab } from '../stability.js';
import { registerView } from '../views.js';

let stability = null;

registerView({
  id: 'stability',
  tab: 'ips',
  skip: '#ips-plots',
  // The Bode magnitude and phase share one cursor (as the run's plots do).
  init: (ctx) => { stability = new StabilityTab(() => ctx.client, new PlotBox($('ips-plots'), { sync: 'ips' })); },
  ready: (ctx, m) => stability.setMeta(m.ips),
  shown: () => stability.update(),
});
