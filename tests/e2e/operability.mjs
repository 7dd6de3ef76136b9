// Browser test of the operability tab (issue 31): the polar is computed in workers speed by speed
// with a progress bar (and Cancel), drawn, and every cell's numbers are those of the command line
// (`aes-sim operability preset:startup`, run here); the hover text names a cell with them; a click
// (or Enter) on a cell opens the simulator at its speed, sea state and wave heading; the polar
// follows the one state (stale under other values, gone under another study, back with Back); the
// address carries the tab through a reload; layout and axe at the three sizes (screenshots).
// Usage: node tests/e2e/operability.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync, writeFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, axeFindings, checker, launch, openPage, pressAndWait, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
const open = (url, c = ctx) => openPage(c, url, base, errors);
const link = (name, tab = null) => `${base}#v=2&preset=${name}${tab ? `&tab=${tab}` : ''}`;
const TOL = 1e-6;

assert(existsSync(native), `no native ${native}`);
const cli = JSON.parse(execFileSync(native, ['operability', 'preset:startup'], { maxBuffer: 256 << 20 }).toString());
const nh = cli.headings_deg.length;
const cliCell = (j, i) => cli.cells[j * nh + i];
const idx = (speed, heading) => [cli.speeds_kn.indexOf(speed), cli.headings_deg.indexOf(heading)];
// The cell the checks name: 12 kn in bow seas from starboard, limited below the highest sea.
const [J, I] = idx(12, 135);
assert(J >= 0 && I >= 0 && !cliCell(J, I).beyond_listed, 'the command line has no 12 kn, 135 deg cell limited below the highest sea');

const done = (p) => p.waitForFunction(() => /^Done|failed|refused/.test(document.getElementById('op-status').textContent), null, { timeout: 120000 });
async function compute(p) {
  await p.click('#op-compute');
  await done(p);
  const st = await p.textContent('#op-status');
  assert(st.startsWith('Done'), `status: ${st}`);
}
// Where a cell is drawn, in page coordinates.
async function cellPoint(p, j, i) {
  const [x, y] = await p.evaluate(([a, b]) => window.__operability.centre(a, b), [j, i]);
  const r = await p.$eval('#op-canvas', (e) => { const b = e.getBoundingClientRect(); return { x: b.x, y: b.y }; });
  return [r.x + x, r.y + y];
}
const firstOrder = async (p) => JSON.parse(await p.inputValue('#f-commands'))[0];
// The sea the simulator opens at for a cell: the first it fails, or the highest listed.
const seaStateOf = (c) => 2 + Math.min(c.seas_passed, cli.seas.length - 1);

let page = null;
await check('the tab computes the polar speed by speed with a progress bar, beside a page that keeps answering, and draws it', async () => {
  const p = await open(link('startup'));
  page = p;
  await p.click('#tab-operability');
  assert((await p.getAttribute('#tab-operability', 'aria-selected')) === 'true', 'the tab is not selected');
  assert((await p.evaluate(() => location.hash)).includes('tab=operability'), `address: ${await p.evaluate(() => location.hash)}`);
  // Sample the progress bar and the gaps between animation frames while it computes.
  await p.evaluate(() => {
    window.__samples = [];
    window.__gaps = [];
    let last = performance.now();
    const tick = (t) => { window.__samples.push(document.getElementById('op-progress').value); window.__gaps.push(t - last); last = t; if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  await compute(p);
  const { samples, gaps } = await p.evaluate(() => { window.__stop = true; return { samples: window.__samples, gaps: window.__gaps }; });
  const between = samples.filter((v) => v > 0 && v < 1);
  assert(between.length >= 1, `no progress between 0 and 1 (samples: ${[...new Set(samples)].join(', ')})`);
  assert(samples.every((v, k) => k === 0 || v >= samples[k - 1] || v === 0), 'the progress went backwards');
  assert(/11 of 11 speeds/.test(await p.textContent('#op-eta')), `progress text: ${await p.textContent('#op-eta')}`);
  const worst = Math.max(...gaps.slice(2));
  assert(worst < 400, `the page froze for ${Math.round(worst)} ms while the polar was computed`);
  console.log(`     progress values seen: ${[...new Set(between.map((v) => v.toFixed(2)))].join(' ')}; longest frame ${Math.round(worst)} ms`);
  // Drawn: the middle of the named cell has its colour.
  const drawn = await p.evaluate(([j, i]) => {
    const cv = document.getElementById('op-canvas'), dpr = window.devicePixelRatio || 1;
    const [x, y] = window.__operability.centre(j, i);
    const d = cv.getContext('2d').getImageData(Math.round(x * dpr), Math.round(y * dpr), 1, 1).data;
    const want = window.__operability.colour(j, i);
    return { got: [d[0], d[1], d[2]], want: [1, 3, 5].map((k) => parseInt(want.slice(k, k + 2), 16)) };
  }, [J, I]);
  assert(drawn.got.every((v, k) => Math.abs(v - drawn.want[k]) <= 3), `cell colour ${drawn.got} (want ${drawn.want})`);
  assert(!(await p.$eval('#op-body', (e) => e.hidden)), 'the polar is hidden');
});

await check('every cell of the page\'s polar equals the command line\'s (limiting H_1/3 within 1e-6, criterion, seas passed, scatter)', async () => {
  const pol = await page.evaluate(() => window.__operability.polar);
  assert(JSON.stringify(pol.speeds_kn) === JSON.stringify(cli.speeds_kn) && JSON.stringify(pol.headings_deg) === JSON.stringify(cli.headings_deg), 'the page\'s grid is not the command line\'s');
  assert(JSON.stringify(pol.seas.map((s) => s.name)) === JSON.stringify(cli.seas.map((s) => s.name)), 'other seas');
  const fields = (c) => JSON.stringify([c.quantity, c.label, c.point || '', c.limit, c.source]);
  assert(pol.criteria.length === cli.criteria.length && pol.criteria.every((c, k) => fields(c) === fields(cli.criteria[k])), 'other criteria');
  let worst = 0;
  pol.cells.forEach((c, k) => {
    const n = cli.cells[k];
    assert(c.speed_kn === n.speed_kn && c.heading_deg === n.heading_deg && c.limiting_criterion === n.limiting_criterion && c.seas_passed === n.seas_passed && c.beyond_listed === n.beyond_listed,
      `cell ${n.speed_kn} kn, ${n.heading_deg} deg: page ${JSON.stringify([c.limiting_criterion, c.seas_passed, c.beyond_listed])}, command line ${JSON.stringify([n.limiting_criterion, n.seas_passed, n.beyond_listed])}`);
    if (n.limiting_hs_m === null) assert(c.limiting_hs_m === null, `cell ${k}: a limit where the command line has none`);
    else worst = Math.max(worst, Math.abs(c.limiting_hs_m - n.limiting_hs_m));
  });
  assert(worst <= TOL, `limiting H_1/3 differs by up to ${worst} m`);
  const sc = Math.max(...pol.scatter.per_speed.map((v, j) => Math.abs(v - cli.scatter.per_speed[j])), Math.abs(pol.scatter.overall - cli.scatter.overall));
  assert(sc <= TOL, `scatter operability differs by ${sc}`);
  // The scatter table shows the same (in percent), with the diagram's name and source.
  const rows = await page.$$eval('#op-scatter-table tbody tr', (r) => r.map((x) => x.cells[1].textContent));
  assert(rows.length === cli.speeds_kn.length + 1 && rows[rows.length - 1] === (100 * cli.scatter.overall).toFixed(1), `scatter table: ${rows.join(', ')}`);
  const text = await page.textContent('#op-scatter');
  assert(text.includes(cli.scatter.name) && text.includes(cli.scatter.source), 'the scatter table does not name its diagram and source');
  const crit = await page.textContent('#op-criteria');
  assert(cli.criteria.every((c) => crit.includes(c.label) && crit.includes(c.source)), 'a criterion or its source is missing from the list');
  console.log(`     264 cells: largest difference of limiting H_1/3 ${worst.toExponential(2)} m; scatter ${sc.toExponential(2)}`);
});

await check('hovering a cell names it: speed, heading, limiting H_1/3 (as the command line prints it), the limiting criterion with its limit and source, the highest sea passed', async () => {
  const p = page;
  const [x, y] = await cellPoint(p, J, I);
  await p.mouse.move(x, y);
  await p.waitForFunction(() => document.getElementById('op-cell').dataset.speed !== undefined, null, { timeout: 5000 });
  const d = await p.$eval('#op-cell', (e) => ({ ...e.dataset, text: e.textContent }));
  const n = cliCell(J, I), crit = cli.criteria[n.limiting_criterion];
  assert(Number(d.speed) === n.speed_kn && Number(d.heading) === n.heading_deg, `named ${d.speed} kn, ${d.heading} deg`);
  assert(Math.abs(Number(d.limitingHsM) - n.limiting_hs_m) <= TOL, `hover limit ${d.limitingHsM}, command line ${n.limiting_hs_m}`);
  const want = [`12 kn`, `135°`, 'bow seas from starboard', `Limiting H_1/3: ${n.limiting_hs_m.toFixed(3)} m`, crit.label, `limit ${crit.limit}`, crit.source, `Highest sea passed: ${cli.seas[n.seas_passed - 1].name}`];
  for (const w of want) assert(d.text.includes(w), `the hover text lacks "${w}": ${d.text}`);
  console.log(`     hover: ${d.text.slice(0, 160)}...`);
  // A cell that passes every listed sea says so.
  const k = cli.cells.findIndex((c) => c.beyond_listed && c.limiting_hs_m !== null && c.speed_kn > 0);
  const [bx, by] = await cellPoint(p, Math.floor(k / nh), k % nh);
  await p.mouse.move(bx, by);
  await p.waitForFunction((h) => document.getElementById('op-cell').dataset.heading === String(h) || true, cli.cells[k].heading_deg);
  await p.waitForTimeout(100);
  const t = await p.textContent('#op-cell');
  assert(/passes every listed sea/i.test(t) && t.includes(cli.cells[k].limiting_hs_m.toFixed(3)), `beyond cell: ${t}`);
});

await check('a click on a cell opens the simulator at its speed, sea state and wave heading (marked changed); Back returns to the polar, still current', async () => {
  const p = page;
  const [x, y] = await cellPoint(p, J, I);
  await p.mouse.click(x, y);
  await p.waitForFunction(() => document.getElementById('tab-sim').getAttribute('aria-selected') === 'true', null, { timeout: 5000 });
  const n = cliCell(J, I);
  assert((await p.inputValue('#f-sea-kind')) === 'random', `sea kind ${await p.inputValue('#f-sea-kind')}`);
  assert(Number(await p.inputValue('#f-sea-sea_state')) === seaStateOf(n), `sea state ${await p.inputValue('#f-sea-sea_state')} (want ${seaStateOf(n)})`);
  assert(Number(await p.inputValue('#f-sea-from_deg')) === 45, `waves from ${await p.inputValue('#f-sea-from_deg')} (want 45)`);
  assert((await firstOrder(p)).speed_kn === 12, `first order ${JSON.stringify(await firstOrder(p))}`);
  assert((await p.inputValue('#f-hull-model')) === 'maneuvering', `hull model ${await p.inputValue('#f-hull-model')}`);
  assert(!(await p.$eval('#run', (b) => b.disabled)), 'Run is disabled: the scenario of the cell is refused');
  for (const f of ['#f-sea-kind-field', '#f-sea-from_deg-field']) assert(await p.$eval(f, (e) => e.classList.contains('edited')), `${f} is not marked changed`);
  const hash = await p.evaluate(() => location.hash);
  assert(!hash.includes('tab=') && hash.includes('&d='), `address after the click: ${hash}`);
  assert(/Press Run/.test(await p.textContent('#status')), `status: ${await p.textContent('#status')}`);
  await p.goBack();
  await p.waitForFunction(() => document.getElementById('tab-operability').getAttribute('aria-selected') === 'true', null, { timeout: 5000 });
  await p.waitForTimeout(200);
  assert(!(await p.$eval('#op-body', (e) => e.hidden)) && (await p.$eval('#op-stale', (e) => e.hidden)), 'Back to the polar: not shown, or marked stale');
});

await check('the keyboard names cells with the arrow keys and Enter opens the simulator there', async () => {
  const p = page;
  await p.focus('#op-canvas');
  await p.keyboard.press('ArrowLeft');
  const d = await p.$eval('#op-cell', (e) => ({ ...e.dataset }));
  assert(d.speed !== undefined, 'the arrow key named no cell');
  const j = cli.speeds_kn.indexOf(Number(d.speed)), i = cli.headings_deg.indexOf(Number(d.heading));
  const n = cliCell(j, i);
  assert(Math.abs(Number(d.limitingHsM) - n.limiting_hs_m) <= TOL, 'the named cell\'s limit is not the command line\'s');
  await p.keyboard.press('Enter');
  await p.waitForFunction(() => document.getElementById('tab-sim').getAttribute('aria-selected') === 'true', null, { timeout: 5000 });
  assert(Number(await p.inputValue('#f-sea-from_deg')) === ((180 - n.heading_deg) % 360 + 360) % 360, `waves from ${await p.inputValue('#f-sea-from_deg')} for heading ${n.heading_deg}`);
  assert((await firstOrder(p)).speed_kn === n.speed_kn, 'another speed');
  assert(Number(await p.inputValue('#f-sea-sea_state')) === seaStateOf(n), 'another sea state');
  assert((await p.evaluate(() => document.activeElement.id)) === 'run', 'focus is not on Run');
});

await check('an edit of the study marks the polar stale (with Compute at hand); another study shows none', async () => {
  const p = page;
  await p.click('#tab-sim');
  await setField(p, 'ship.hull.hub_above_base_m', 3);
  await p.click('#tab-operability');
  await p.waitForTimeout(200);
  assert(!(await p.$eval('#op-stale', (e) => e.hidden)), 'a polar of other values is not marked stale');
  await p.click('#tab-sim');
  await p.selectOption('#preset', 'head-seas-ss6');
  await p.click('#tab-operability');
  await p.waitForTimeout(200);
  assert(await p.$eval('#op-body', (e) => e.hidden), 'the start-up polar shows under another study');
  assert((await p.textContent('#op-study')).length > 0 && !(await p.textContent('#op-study')).startsWith('Start-up'), 'the tab does not name the study it judges');
});

// Issue 42: the polar opened runs that diverged or sped up below 12 kn (0 kn and 3 kn in beam seas).
await check('a slow beam-sea cell (3 kn, waves on the beam) opens a run that completes and holds its order, on the page and natively', async () => {
  const p = await open(link('startup', 'operability'));
  await compute(p);
  const [j, i] = idx(3, 90);
  assert(j >= 0 && i >= 0, 'the polar has no 3 kn, 90 deg cell');
  const [x, y] = await cellPoint(p, j, i);
  await p.mouse.click(x, y);
  await p.waitForFunction(() => document.getElementById('tab-sim').getAttribute('aria-selected') === 'true', null, { timeout: 5000 });
  assert((await firstOrder(p)).speed_kn === 3, `first order ${JSON.stringify(await firstOrder(p))}`);
  const st = await pressAndWait(p);
  assert(st.startsWith('Done'), `status: ${st}`);
  const warnings = await p.$$eval('#warnings li', (l) => l.map((e) => e.textContent));
  assert(!warnings.some((w) => /diverged|speed order not held/.test(w)), `warnings: ${JSON.stringify(warnings)}`);
  // The same scenario natively: it runs to its end and the speed order is held.
  const file = `${shots}/operability-3kn-beam.json`;
  writeFileSync(file, await p.evaluate(() => window.__scenarioText()));
  const mine = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  const sum = JSON.parse(execFileSync(native, ['run', file], { maxBuffer: 64 << 20 }).toString());
  assert(Math.abs(sum.final_time_s - mine.sim.duration_s) < 1e-6, `native run ended at ${sum.final_time_s} s of ${mine.sim.duration_s}`);
  assert(!sum.warnings.some((w) => /diverged|speed order not held/.test(w)), `native warnings: ${JSON.stringify(sum.warnings)}`);
  console.log(`     3 kn, waves on the beam, sea state ${mine.sea.sea_state}: ${mine.sim.duration_s} s, final speed ${sum.signals.ship_speed_kn.final.toFixed(2)} kn`);
  await p.close();
});

await check('the address carries tab=operability; a reload shows the tab; Cancel stops a polar and the next one computes', async () => {
  const p = page;
  assert((await p.evaluate(() => location.hash)).includes('tab=operability'), 'no tab in the address');
  await p.reload();
  await p.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await p.getAttribute('#tab-operability', 'aria-selected')) === 'true' && !(await p.$eval('#panel-operability', (e) => e.hidden)), 'the reload left the tab');
  await p.click('#op-compute');
  await p.click('#op-cancel');
  await p.waitForFunction(() => document.getElementById('op-status').textContent === 'Cancelled.', null, { timeout: 10000 });
  assert(await p.$eval('#op-cancel', (b) => b.disabled), 'Cancel stays enabled');
  await compute(p);
  await p.close();
});

// Layout and accessibility: a link to the tab computes its polar; the polar, its legend and the
// named cell fit without overlapping; nothing wider than the screen; axe with the table open.
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];
const RULES = ['heading-order', 'empty-table-header', 'landmark-one-main', 'scrollable-region-focusable', 'landmark-no-duplicate-main'];
for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: a link to the tab computes the polar, it fits and nothing overlaps, axe clean (screenshots)`, async () => {
    const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
    const p = await open(link('startup', 'operability'), c);
    await done(p);
    assert((await p.textContent('#op-status')).startsWith('Done'), await p.textContent('#op-status'));
    const rect = (sel) => p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { left: r.left, right: r.right, top: r.top + scrollY, bottom: r.bottom + scrollY }; });
    const cv = await rect('#op-canvas'), side = await rect('#op-side'), click = await rect('#op-click');
    const wide = await p.evaluate(() => document.documentElement.scrollWidth);
    assert(wide <= w, `the page is ${wide} px wide on a ${w} px screen`);
    assert(cv.right <= w + 0.5 && cv.left >= 0, `the plot spans ${Math.round(cv.left)}..${Math.round(cv.right)} px`);
    const overlap = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
    assert(!overlap(cv, side) && !overlap(cv, click), 'the legend or the line under the plot overlaps the plot');
    if (w >= 1366) assert(cv.bottom <= h, `the polar ends at ${Math.round(cv.bottom)} px of a ${h} px screen`);
    // The labels drawn round the polar stay inside the canvas (the heading words at the sides).
    const inside = await p.evaluate(() => { const g = window.__operability; const cvs = document.getElementById('op-canvas'); return g && cvs.clientWidth > 0; });
    assert(inside, 'no polar drawn');
    await p.$eval('#op-canvas', (e) => e.scrollIntoView({ block: 'center' }));
    const [x, y] = await cellPoint(p, J, I);
    await p.mouse.move(x, y);
    await p.waitForTimeout(150);
    await p.screenshot({ path: `${shots}/operability-${w}x${h}.png` });
    if (w < 600) await p.screenshot({ path: `${shots}/operability-${w}x${h}-full.png`, fullPage: true });
    await p.$eval('#op-grid-box', (d) => { d.open = true; });
    const v = await axeFindings(p, { rules: RULES });
    assert(!v.length, v.join(' | '));
    if (w < 600) {
      // On a touch screen the first tap names a cell, a second tap on it opens the simulator.
      await p.$eval('#op-canvas', (e) => e.scrollIntoView({ block: 'center' }));
      const [tx, ty] = await cellPoint(p, J, I - 1);
      await p.touchscreen.tap(tx, ty);
      await p.waitForTimeout(150);
      const named = await p.$eval('#op-cell', (e) => e.dataset.heading);
      assert(Number(named) === cli.headings_deg[I - 1], `the tap named heading ${named}`);
      assert((await p.getAttribute('#tab-operability', 'aria-selected')) === 'true', 'the first tap left the tab');
      await p.touchscreen.tap(tx, ty);
      await p.waitForFunction(() => document.getElementById('tab-sim').getAttribute('aria-selected') === 'true', null, { timeout: 5000 });
      assert(Number(await p.inputValue('#f-sea-from_deg')) === 180 - cli.headings_deg[I - 1], 'the second tap opened another cell');
    }
    await c.close();
  });
}

await finish(browser, errors);
