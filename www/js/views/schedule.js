// How many gas turbines should run (issue 45; core's studies::schedule, `aes-sim schedule`): speed
// against sea state, each cell coloured by the sets online that burn least fuel with the reserve,
// its fuel saving against all four on hover or focus, and a click that opens the simulator at that
// speed and sea with those sets online. Every number is the wasm's.
import { $, el, fmt } from '../dom.js';
import { REQUEST } from '../protocol.js';
import { isBusy, status, announce } from '../state.js';
import { setPath } from '../form.js';
import { StudyFold } from '../fold.js';
import { registerView } from '../views.js';

const TEMPLATE = `
<section class="schedule" aria-labelledby="schedule-h">
  <p class="about">The thesis runs all four gas turbines at every speed, each at part load where its efficiency is worst, and
    asks for "a more intelligent operating schedule" (ch. 6.1). Here, for the plant of the form, each speed and sea state
    (head seas) gets the fewest-fuel number of sets online that still keeps a reserve: the chance that the sea's power
    swings exceed the online sets' rating within the reserve window stays below <code>plant.online.reserve_probability</code>.
    Hover or focus a cell for its fuel saving against four online; a click opens the Simulator tab at that speed and sea
    with those sets online: press Run there.</p>
  <div class="row buttons">
    <button id="schedule-compute" type="button">Compute the schedule</button>
  </div>
  <div id="schedule-status" role="status" aria-live="polite"></div>
  <div id="schedule-body" hidden>
    <p id="schedule-hover" class="hint" aria-live="polite">Hover a cell for its fuel saving.</p>
    <div id="schedule-grid" class="scroll" tabindex="0" role="region" aria-label="Sets online by speed and sea state"></div>
    <p id="schedule-legend" class="hint"></p>
  </div>
</section>`;

// The colours of one to four sets online (light to dark), and a cell no count drives.
const COLOURS = ['#d9ecd0', '#9fd18b', '#3b7a2b', '#1f4a17'];
const TEXT = ['#1b1b1b', '#1b1b1b', '#ffffff', '#ffffff'];
// The sets a count runs on the page's simulator: one on each shaft's bus first.
const SETS = [[1], [1, 3], [1, 2, 3], [1, 2, 3, 4]];

let fold = null; // its shownKey: the scenario the result shown belongs to

function words(c) {
  if (c.count == null) return `${c.speed_kn} kn in SS${c.sea_state}: beyond the plant`;
  const fuel = `${fmt(c.fuel_power_w / 1e6, 3)} MW of fuel power against ${fmt(c.fuel_power_four_w / 1e6, 3)} MW with four`;
  const why = c.reserve_unmet ? ' (no count keeps the reserve)' : c.below_min_load ? ' (the reserve needs sets below their minimum load)' : c.reserve_decides ? ' (the reserve decides: fewer would burn less)' : '';
  return `${c.speed_kn} kn in SS${c.sea_state}: ${c.count} set${c.count > 1 ? 's' : ''} online, fuel saving ${fmt(100 * c.saving, 3)} % (${fuel})${why}`;
}

// A cell of the schedule: the simulator at its speed (the first order's, and the ship starts at
// it), its sea state from ahead and its sets online, through the form; then the Simulator tab.
function openCell(ctx, c) {
  const { form } = ctx;
  if (!form) return 'The simulator is still loading.';
  if (isBusy()) return 'A run is in progress on the Simulator tab: wait for it or cancel it first.';
  if (c.count == null) return 'Not even four sets drive this speed.';
  const sc = form.scenario;
  if (!Array.isArray(sc.commands) || !sc.commands.length) sc.commands = [{ t_s: 0 }];
  sc.commands[0].speed_kn = c.speed_kn;
  const set = {
    'initial.speed_kn': c.speed_kn, 'sea.kind': 'random', 'sea.sea_state': c.sea_state, 'sea.h_sig_m': 0, 'sea.omega_n_rad_s': 0,
    'sea.from_deg': 0, 'hull.model': 'maneuvering', 'plant.online.sets': SETS[c.count - 1],
  };
  for (const [path, v] of Object.entries(set)) setPath(sc, path, v);
  form.fill();
  form.save();
  ctx.selectTab('tab-sim');
  ctx.onEdit(false);
  const w = `${c.speed_kn} kn into head seas of sea state ${c.sea_state} with sets ${SETS[c.count - 1].join(', ')} online, starting at that speed`;
  $('about').textContent = `This run is a cell of the turbine schedule: ${w}.`;
  status(`From the turbine schedule: ${w}. Press Run.`);
  $('run').focus();
  return null;
}

function show(ctx, s) {
  $('schedule-body').hidden = false;
  const head = el('tr', {}, el('th', { scope: 'col', textContent: 'speed [kn]' }), ...s.sea_states.map((ss) => el('th', { scope: 'col', textContent: `SS${ss}` })));
  const rows = s.speeds_kn.map((v) => el('tr', {}, el('th', { scope: 'row', textContent: String(v) }), ...s.sea_states.map((ss) => {
    const c = s.cells.find((x) => x.speed_kn === v && x.sea_state === ss);
    const n = c && c.count;
    const mark = !c || n == null ? '–' : `${n}${c.reserve_unmet ? '!' : c.below_min_load ? '+' : c.reserve_decides ? '*' : ''}`;
    const b = el('button', { type: 'button', className: 'schedule-cell', textContent: mark, title: c ? words(c) : '' });
    b.dataset.speed = String(v);
    b.dataset.ss = String(ss);
    if (n) { b.style.background = COLOURS[n - 1]; b.style.color = TEXT[n - 1]; }
    b.setAttribute('aria-label', c ? words(c) : `${v} kn SS${ss}`);
    const hover = () => { $('schedule-hover').textContent = c ? words(c) : ''; };
    b.addEventListener('mouseenter', hover);
    b.addEventListener('focus', hover);
    b.addEventListener('click', () => { const why = c && openCell(ctx, c); if (why) $('schedule-status').textContent = why; });
    return el('td', {}, b);
  })));
  $('schedule-grid').replaceChildren(el('table', {}, el('caption', { textContent: `Gas turbine sets online (reserve: overload chance below ${s.reserve_probability} in ${s.reserve_window_s} s)` }),
    el('thead', {}, head), el('tbody', {}, ...rows)));
  $('schedule-legend').textContent = 'Darker: more sets online (1 to 4). * the reserve decides (fewer sets would burn less), + the reserve needs sets below their minimum load, ! no count keeps the reserve, – beyond the plant.';
}

async function compute(ctx) {
  const inp = ctx.studyInputs();
  if (!inp) return;
  if (inp.invalid) { fold.status('A value of the form is refused (marked at its field): correct it first.'); return; }
  const scenario = JSON.stringify(inp.scenario);
  await fold.compute(async () => {
    fold.status('Computing the schedule...');
    const { schedule } = await ctx.client.request(REQUEST.schedule, { scenario });
    show(ctx, schedule);
    fold.shownKey = scenario;
    const four = schedule.cells.filter((c) => c.count === 4).length;
    fold.status(`Done (${inp.title}): ${schedule.cells.length} cells, ${schedule.cells.length - four} of them with fewer than four sets online.`);
    announce('schedule', schedule);
  }, { onFail: () => { $('schedule-body').hidden = true; fold.shownKey = null; } });
}

// A schedule of another plant is not shown under this one.
function sync(ctx) {
  const inp = ctx.studyInputs();
  fold.drop(inp ? JSON.stringify(inp.scenario) : null, 'The study changed since the schedule was computed: compute it again.');
}

registerView({
  id: 'schedule',
  sync,
  init(ctx) {
    $('schedule-box').insertAdjacentHTML('beforeend', TEMPLATE);
    fold = new StudyFold('schedule', { failed: 'The schedule could not be computed' });
    $('schedule-compute').addEventListener('click', () => compute(ctx));
  },
});
