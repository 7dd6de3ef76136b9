// Sharing and exports of the simulator tab: "Copy link" (or the scenario as a file when its link
// would be too long), the trace CSV and the summary JSON. A copied link shows under the buttons
// until the study or a value changes: then it would share another scenario than the one on the page.
import { REQUEST } from '../protocol.js';
import { HULL } from '../config.js';
import { $, download } from '../dom.js';
import { getResult, status } from '../state.js';
import { registerView } from '../views.js';

function forgetLink() {
  $('share-url').hidden = true;
  $('share-url').value = '';
  $('share-too-long').hidden = true;
}

async function share(ctx) {
  const { form } = ctx;
  if (!form) return;
  const r = getResult();
  const view = r && r.columns && JSON.stringify(r.scenario) === JSON.stringify(form.scenario) ? ctx.live.view() : null;
  const url = location.origin + location.pathname + ctx.hereHash(view);
  // A custom hull's offsets (or a long blade table) can make the link longer than browsers, chat programs and mail keep:
  // then the page offers the scenario as a file instead of a link that would break.
  const tooLong = url.length > HULL.maxLinkChars;
  $('share-too-long').hidden = !tooLong;
  if (tooLong) {
    $('share-url').hidden = true;
    const sc = form.scenario;
    const big = [sc.ship.hull && sc.ship.hull.name === 'custom' && 'the custom hull\'s offsets', sc.propeller.geometry && sc.propeller.geometry.name === 'custom' && 'the blade table\'s rows'].filter(Boolean);
    $('share-too-long-text').textContent = `This scenario's link would be ${url.length.toLocaleString('en-US')} characters long (${big.length ? `${big.join(' and ')} are in it` : 'its edits are in it'}), more than the ${HULL.maxLinkChars.toLocaleString('en-US')} a link can safely carry. Download the scenario instead: it holds them, and opens here with "Load hull offsets or a scenario" (or with aes-sim).`;
    status('No link: this scenario is too large for one. Download it as a file (below the buttons).');
    $('share-file').focus();
    return;
  }
  $('share-url').hidden = false;
  $('share-url').value = url;
  $('share-url').select();
  try { await navigator.clipboard.writeText(url); status('Link copied: it opens this scenario and runs it.'); } catch (_) { status('Link below: copy it by hand.'); }
}

registerView({
  id: 'share',
  init(ctx) {
    $('share').addEventListener('click', () => share(ctx));
    $('share-file').addEventListener('click', () => {
      if (ctx.form) download(`${ctx.form.scenario.name || 'scenario'}-scenario.json`, JSON.stringify(ctx.form.current(), null, 1), 'application/json');
    });
    $('export-csv').addEventListener('click', async () => {
      const r = getResult();
      if (!(r && r.csv && r.columns)) return;
      // The text is made now, from the kept columns (a run does not spend its time on it).
      const { csv } = await ctx.client.request(REQUEST.traceCsv, { columns: r.columns });
      download(`${r.scenario.name}-trace.csv`, `# scenario: ${r.text || JSON.stringify(r.scenario)}\n${csv}`, 'text/csv');
    });
    $('export-json').addEventListener('click', () => {
      const r = getResult();
      // The scenario as its own text: a replayed trial's 64-bit seed survives.
      if (r) download(`${r.scenario.name}-summary.json`, `{"scenario": ${r.text || JSON.stringify(r.scenario)},\n"summary": ${JSON.stringify(r.summary, null, 1)}}`, 'application/json');
    });
  },
  selected: forgetLink,
  edited: forgetLink,
});
