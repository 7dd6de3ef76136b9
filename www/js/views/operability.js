// The operability tab (issue 31): its panel's DOM, built here (only operability.js reads it), the
// OperabilityTab on the form's study as it stands, and a cell opened in the simulator.
import { $ } from '../dom.js';
import { isBusy, status } from '../state.js';
import { setPath, deletePath } from '../form.js';
import { OperabilityTab } from '../operability.js';
import { registerView } from '../views.js';

const TEMPLATE = `
<section class="op-controls" aria-label="Operability polar">
  <p class="about">For each ship speed and wave heading: the highest significant wave height H_1/3 in which every
    seakeeping criterion of the scenario holds (motions, accelerations, slamming, deck wetness, propeller ventilation
    and emergence; the list, limits and sources come with the polar), the criterion that limits it, and the share of a
    wave scatter diagram in which the ship can operate. It judges the study of the Simulator tab as it stands, with
    your edits: its hull, loading, propeller hub depth and criteria.</p>
  <p class="op-study-line">Study: <strong id="op-study"></strong></p>
  <div class="row buttons">
    <button id="op-compute" type="button" disabled>Compute the polar</button>
    <button id="op-cancel" type="button" disabled>Cancel</button>
  </div>
  <div class="row">
    <progress id="op-progress" max="1" value="0" aria-label="Progress of the polar"></progress>
    <span id="op-eta" aria-live="polite"></span>
  </div>
  <div id="op-status" role="status" aria-live="polite"></div>
</section>
<section id="op-results" aria-label="The operability polar" tabindex="-1">
  <div id="op-stale" class="stale-box" role="status" hidden><p id="op-stale-text"></p><button id="op-stale-run" type="button">Compute these values</button></div>
  <p id="op-empty" class="hint">No polar yet: press "Compute the polar" (it takes a few seconds and runs beside the page).</p>
  <div id="op-body" hidden>
    <h2 id="op-title"></h2>
    <p id="op-judged" class="hint"></p>
    <div id="op-figure">
      <div id="op-plot"><canvas id="op-canvas" tabindex="0" role="application" aria-roledescription="polar plot" aria-describedby="op-click"></canvas></div>
      <div id="op-side">
        <div id="op-cell" class="op-cell" aria-live="off"></div>
        <div id="op-legend" class="op-legend"></div>
      </div>
    </div>
    <p id="op-click" class="hint">Seen from above with the bow up: waves from ahead (head seas, 180°) at the top, from starboard (90°) on the right,
      from port (270°) on the left, from astern (following seas, 0°) at the bottom; speed grows outwards from 0 kn at the centre.
      A click on a cell (a second tap on a touch screen, Enter on the focused plot or a button of the table) opens the Simulator tab at its
      speed (the first order's, and the ship starts at it) and wave heading in the first sea the cell fails (the highest listed sea where it passes them all), with the
      maneuvering hull model that waves need: press Run there. The run sails the hull's own maneuvering model, which holds its speed order
      at every speed and heading of this polar in sea states 4 to 6; its heading it holds only where the rudders beat the waves' yaw moment
      (at the lowest speeds in quartering seas they do not, as at sea): a run that loses its speed or its heading says why in its warnings.</p>
    <details id="op-grid-box"><summary id="op-grid-summary">The polar as a table: limiting H_1/3 [m] by speed and heading</summary>
      <div id="op-grid" class="scroll" tabindex="0" role="region" aria-label="Limiting H_1/3 by speed and heading"></div>
    </details>
    <div class="op-tables">
      <div id="op-scatter" class="scroll" tabindex="0" role="region" aria-label="Operability of the scatter diagram"></div>
      <div id="op-criteria" class="scroll" tabindex="0" role="region" aria-label="Criteria"></div>
    </div>
  </div>
</section>`;

let operability = null;

// A cell of the operability polar: the simulator at its speed (the first order's), sea and wave
// heading, through the form (the address, the "(changed)" marks and the stored edits follow), then
// the Simulator tab (a step in the history: Back returns to the polar). Returns why it cannot.
function openCell(ctx, { speed_kn, set, words }) {
  const { form } = ctx;
  if (!form) return 'The simulator is still loading.';
  if (isBusy()) return 'A run is in progress on the Simulator tab: wait for it or cancel it first.';
  const sc = form.scenario;
  if (!Array.isArray(sc.commands) || !sc.commands.length) sc.commands = [{ t_s: 0 }];
  sc.commands[0].speed_kn = speed_kn;
  for (const [path, v] of Object.entries(set)) { if (v === undefined) deletePath(sc, path); else setPath(sc, path, v); }
  form.fill();
  form.save();
  ctx.selectTab('tab-sim');
  ctx.onEdit(false);
  // The study's words describe its own values: say first what this run is.
  $('about').textContent = `This run is a cell of the operability polar: ${words}. The study's text below describes its own values, not this cell's.`;
  status(`From the operability polar: ${words}. Press Run.`);
  $('run').focus();
  return null;
}

registerView({
  id: 'operability',
  tab: 'operability',
  skip: '#op-results',
  init(ctx) {
    $('panel-operability').innerHTML = TEMPLATE;
    operability = new OperabilityTab({ inputs: ctx.studyInputs, onOpenCell: (c) => openCell(ctx, c) });
  },
  sync: () => operability.sync(),
  shown: () => { operability.sync(); operability.draw(); },
  // A link to this tab computes its polar (as a link to a run runs it).
  linked: () => { operability.compute(); },
});
