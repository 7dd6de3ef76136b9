// Tabs (ARIA pattern): the tab buttons of index.html in their order, each showing the panel it
// controls; its view says where "Skip to the results" goes. Click, or arrow keys / Home / End on
// the tab list. What showing a tab does to the page's state is main's (the `select` it passes).
import { $ } from './dom.js';
import { tabView } from './views.js';

const TABS = [...$('tabs').querySelectorAll('[role="tab"]')].map((t) => t.id);
export const currentTab = () => (TABS.find((t) => $(t).getAttribute('aria-selected') === 'true') || TABS[0]).slice(4);

// Shows tab `id` (focused if asked); returns whether another tab was shown before, and its view.
export function showTab(id, focus = false) {
  const changed = currentTab() !== id.slice(4);
  for (const tab of TABS) {
    const on = tab === id;
    $(tab).setAttribute('aria-selected', String(on));
    $(tab).tabIndex = on ? 0 : -1;
    $($(tab).getAttribute('aria-controls')).hidden = !on;
  }
  if (focus) $(id).focus();
  // "Skip to the results" goes to the shown tab's results (the simulator's are hidden here).
  const view = tabView(id.slice(4));
  document.querySelector('a.skip').setAttribute('href', view.skip);
  return { changed, view };
}

// select(id, focus): what a click or a key on the tab list asks for.
export function listenTabs(select) {
  for (const tab of TABS) $(tab).addEventListener('click', () => select(tab));
  $('tabs').addEventListener('keydown', (e) => {
    const i = TABS.indexOf(document.activeElement.id);
    if (i < 0) return;
    const j = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: TABS.length - 1 }[e.key];
    if (j === undefined) return;
    e.preventDefault();
    select(TABS[(j + TABS.length) % TABS.length], true);
  });
}
