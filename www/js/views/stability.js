// The stability tool's tab (ch. 4): its operating point comes from the worker's ready message, and
// the tab redraws when shown. Below it, the bus stability map of the form's study (issue 44).
import { $ } from '../dom.js';
import { BusMap, TEMPLATE } from '../busmap.js';
import { PlotBox } from '../plots.js';
import { StabilityTab } from '../stability.js';
import { registerView } from '../views.js';

let stability = null;
let busmap = null;

registerView({
  id: 'stability',
  tab: 'ips',
  skip: '#ips-plots',
  // The Bode magnitude and phase share one cursor (as the run's plots do).
  init: (ctx) => {
    stability = new StabilityTab(() => ctx.client, new PlotBox($('ips-plots'), { sync: 'ips' }));
    $('ips-plots').insertAdjacentHTML('afterend', TEMPLATE);
    busmap = new BusMap(ctx);
  },
  ready: (ctx, m) => { stability.setMeta(m.ips); busmap.ready(); },
  selected: () => busmap.studyChosen(),
  sync: () => busmap.sync(),
  shown: () => stability.update(),
});
