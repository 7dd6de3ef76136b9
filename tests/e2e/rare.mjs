// Browser test of the rare events (issue 32): in the simulator's results, the head-seas study's
// ventilation onset on the port shaft is computed by conditioned simulation over the page's
// workers (progress, Cancel), and its rate per hour and every consequence's quantiles equal
// `aes-sim rare` (run here) to 1e-9 relative: the wasm and the native build give the same bits;
// the headline, the histograms (units on the axes, quantile lines) and the threshold table are
// drawn, and a threshold typed summarises the same trials again (as --threshold does); the most
// likely wave group runs through the page's run and the live stern view shows the hub at the
// level at the event; a worst trial's replay is that trial (its consequence to 1e-9); a hub depth
// of the control is `--set ship.hull.hub_above_base_m`; results go stale after an edit, come back
// with the edit undone, and leave under a study in calm water; layout and axe at the three sizes
// (screenshots rare-*.png).
// Usage: node tests/e2e/rare.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, axeFindings, checker, launch, openPage, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
const open = (url, c = ctx) => openPage(c, url, base, errors);
const link = (name) => `${base}#v=2&preset=${name}`;
const TRIALS = 40;
const REL = 1e-9;

assert(existsSync(native), `no native ${native}`);
const cliRare = (...args) => JSON.parse(execFileSync(native, ['rare', 'preset:head-seas-ss6', '--trials', String(TRIALS), ...args], { maxBuffer: 64 << 20 }).toString());
const THRESHOLDS = ['--threshold', 'min_bus_voltage_pu=0.9', '--threshold', 'peak_turbine_speed_pu=1.1', '--threshold', 'motor_power_drop_mw=10'];
const cli = cliRare('--event', 'ventilation', '--shaft', 'port', ...THRESHOLDS);
const close = (a, b) => a === b || Math.abs(a - b) <= REL * Math.max(Math.abs(a), Math.abs(b));
// The page's summary against the command line's: the rate, Rice's, every quantile and threshold rate.
function sameSummary(page, want, what) {
  const bad = [];
  const cmp = (name, a, b) => { if (!close(a, b)) bad.push(`${name}: page ${a}, command line ${b}`); };
  assert(page.trials === want.trials && page.event === want.event, `${what}: ${page.trials} trials of "${page.event}" against ${want.trials} of "${want.event}"`);
  for (const k of ['per_hour', 'low_per_hour', 'high_per_hour']) cmp(`rate.${k}`, page.rate[k], want.rate[k]);
  cmp('rice_per_hour', page.rice_per_hour, want.rice_per_hour);
  cmp('hub_depth_m', page.hub_depth_m, want.hub_depth_m);
  want.consequences.forEach((c, k) => {
    const p = page.consequences[k];
    assert(p.name === c.name, `${what}: consequence ${k} is ${p.name}, not ${c.name}`);
    for (const q of ['q05', 'q50', 'q95', 'q99', 'min', 'max']) cmp(`${c.name}.${q}`, p[q], c[q]);
    c.beyond.forEach((b, j) => {
      const pb = p.beyond[j];
      assert(pb && pb.threshold === b.threshold && pb.trials === b.trials, `${what}: ${c.name} past ${b.threshold}: ${pb ? pb.trials : 'no'} trials, command line ${b.trials}`);
      cmp(`${c.name} past ${b.threshold}`, pb.rate.per_hour, b.rate.per_hour);
    });
  });
  assert(!bad.length, `${what}: ${bad.join('; ')}`);
}

const status = (p) => p.textContent('#rare-status');
async function openRare(p) {
  await p.$eval('#rare-box', (d) => { d.open = true; });
  await p.waitForFunction(() => !document.getElementById('rare-compute').disabled, null, { timeout: 30000 });
}
async function compute(p, trials = TRIALS) {
  await p.fill('#rare-trials', String(trials));
  await p.dispatchEvent('#rare-trials', 'change');
  await p.click('#rare-compute');
  await p.waitForFunction(() => /^Done|failed|refused|Cancelled/.test(document.getElementById('rare-status').textContent), null, { timeout: 120000 });
  const st = await status(p);
  assert(st.startsWith('Done'), `status: ${st}`);
}
const summaryOf = (p) => p.evaluate(() => window.__rare && window.__rare.summary);
// Waits for the page's run (the wave group or a replay) to end.
async function runEnds(p) {
  await p.waitForFunction(() => /^Done|^Cancel/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 60000 });
  const st = await p.textContent('#status');
  assert(st.startsWith('Done'), `the run: ${st}`);
  return st;
}

let page = null;
await check(`${TRIALS} trials of the head-seas study compute over the workers with a progress bar, and the rate and every quantile equal aes-sim rare to 1e-9`, async () => {
  const p = await open(link('head-seas-ss6'));
  page = p;
  await openRare(p);
  assert(Number(await p.inputValue('#rare-h0')) === 3.5, `the hub depth's default is ${await p.inputValue('#rare-h0')} m, not the study's 3.5 m`);
  assert((await p.inputValue('#rare-trials')) === '200', 'the trials\' default is not 200');
  await p.evaluate(() => {
    window.__samples = [];
    const tick = () => { window.__samples.push(document.getElementById('rare-progress').value); if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  const t0 = Date.now();
  await compute(p);
  const ms = Date.now() - t0;
  const samples = await p.evaluate(() => { window.__stop = true; return window.__samples; });
  const between = samples.filter((v) => v > 0 && v < 1);
  assert(between.length >= 1, `no progress between 0 and 1 (${[...new Set(samples)].join(', ')})`);
  assert(new RegExp(`^${TRIALS} of ${TRIALS} trials`).test(await p.textContent('#rare-eta')), `progress text: ${await p.textContent('#rare-eta')}`);
  sameSummary(await summaryOf(p), cli, 'ventilation, port');
  console.log(`     ${TRIALS} trials in ${ms} ms; rate ${cli.rate.per_hour} per hour (page and command line), Rice ${cli.rice_per_hour}; medians ${cli.consequences.map((c) => `${c.name} ${c.q50}`).join(', ')}`);
});

await check('the headline says the rate in the unit that reads ("About N an hour ... frequent, not rare" above one an hour, else "About once every N hours (95 %: A to B hours)"), beside Rice, the hub depth, speed and sigma; five histograms with units on the axes and quantile lines; the threshold table re-summarises a typed threshold as --threshold does', async () => {
  const p = page;
  const head = await p.textContent('#rare-headline');
  const r = cli.rate;
  const want = r.per_hour > 1
    ? `About ${r.per_hour.toPrecision(3)} an hour (95 %: ${r.low_per_hour.toPrecision(3)} to ${r.high_per_hour.toPrecision(3)}), one every `
    : `About once every ${r.once_every_hours.toPrecision(3)} hours (95 %: ${(1 / r.high_per_hour).toPrecision(3)} to ${(1 / r.low_per_hour).toPrecision(3)} hours)`;
  assert(head.startsWith(want), `headline "${head}", want it to start "${want}"`);
  assert((r.per_hour > 1) === head.includes('frequent, not rare'), `headline "${head}" at ${r.per_hour} per hour`);
  const facts = await p.textContent('#rare-facts');
  for (const w of [cli.rate.per_hour.toPrecision(4), cli.rice_per_hour.toPrecision(4), 'Rice', cli.hub_depth_m.toPrecision(3), cli.speed_kn.toPrecision(3), cli.hub_sigma_m.toPrecision(3), cli.level_sigmas.toPrecision(3)]) assert(facts.includes(w), `the facts lack "${w}": ${facts}`);
  // A histogram per consequence that varies over the trials (one that does not is said in words).
  const panels = await p.$$eval('#rare-plots .plot', (ps) => ps.map((x) => {
    const c = x.querySelector('.chart');
    return { axes: c ? c.uplot.axes.map((a) => a.label) : null, w: c ? c.getBoundingClientRect().width : 0, key: (x.querySelector('.key') || {}).textContent || '', text: x.textContent };
  }));
  assert(panels.length === 5, `${panels.length} panels`);
  cli.consequences.forEach((c, k) => {
    const pl = panels[k];
    if (!(c.max > c.min)) { assert(!pl.axes && pl.text.includes('Every trial'), `consequence ${c.name}, the same in every trial, is not said so: ${pl.text}`); return; }
    assert(pl.axes && pl.axes.every((l) => /\[[^\]]+\]/.test(l || '')) && pl.w > 150, `histogram of ${c.name} without units or too narrow: ${JSON.stringify(pl.axes)}, ${pl.w} px`);
    assert(pl.key.includes('50 %') && pl.key.includes(Number(c.q50).toPrecision(4)), `histogram ${c.name}'s key lacks its median: ${pl.key}`);
  });
  // The threshold table: the defaults' rates, then a typed threshold.
  const cells = await p.$$eval('#rare-thresholds-table tbody tr', (rs) => rs.map((x) => [...x.cells].map((c) => c.querySelector('input') ? c.querySelector('input').value : c.textContent)));
  assert(cells.length === 5, `${cells.length} threshold rows`);
  const bus = cli.consequences[0].beyond[0];
  assert(cells[0][1] === '0.9' && cells[0][2] === `${bus.trials} of ${TRIALS}` && cells[0][3].startsWith(bus.rate.per_hour.toPrecision(4)), `bus voltage row: ${cells[0].join(' | ')}`);
  assert(cells[1][1] === '1.1' && cells[3][1] === '10' && cells[2][1] === '' && cells[4][1] === '', `threshold defaults: ${cells.map((c) => c[1]).join(', ')}`);
  await p.fill('#rare-th-min_bus_voltage_pu', '0.8');
  await p.dispatchEvent('#rare-th-min_bus_voltage_pu', 'change');
  const other = cliRare('--threshold', 'min_bus_voltage_pu=0.8');
  const b8 = other.consequences[0].beyond[0];
  await p.waitForFunction((t) => document.querySelector('#rare-thresholds-table tbody tr').cells[2].textContent.startsWith(`${t} of`), b8.trials, { timeout: 10000 });
  const s = await summaryOf(p);
  const got = s.consequences[0].beyond[0];
  assert(got.threshold === 0.8 && close(got.rate.per_hour, b8.rate.per_hour), `past 0.8 pu: page ${JSON.stringify(got)}, command line ${JSON.stringify(b8)}`);
  assert((await status(p)).startsWith('Done'), 'the re-summary changed the status');
  console.log(`     headline: ${head}; past 0.8 pu: ${b8.trials} trials, ${b8.rate.per_hour} per hour`);
});

await check('"Show the most likely wave group" runs the page\'s run: the plots and the live stern view show the hub at h/R 1.1 at the event, with a line saying what is shown', async () => {
  const p = page;
  await p.click('#rare-wave');
  const st = await runEnds(p);
  assert(/most likely wave group/.test(st), `status: ${st}`);
  const what = await p.textContent('#shown-what');
  assert(!(await p.$eval('#shown-what', (e) => e.hidden)) && /most likely wave group/.test(what) && /h\/R at the event \(t = 150 s\): 1\.1\d\d/.test(what), `the line over the views: ${what}`);
  await p.waitForFunction(() => window.__liveViews && window.__liveViews.drawn && window.__liveViews.drawn.stern && Math.abs(window.__liveViews.drawn.t - 150) < 1e-6, null, { timeout: 10000 });
  const d = await p.evaluate(() => ({ t: window.__liveViews.drawn.t, hr: window.__liveViews.drawn.stern.h_over_r, hidden: document.getElementById('live').hidden, t1: window.__liveViews.t1 }));
  assert(!d.hidden && Math.abs(d.hr - 1.1) < 0.01 && Math.abs(d.t1 - 165) < 1e-6, `the live stern view at ${d.t} s draws h/R ${d.hr} (run of ${d.t1} s)`);
  assert(/h\/R 1\.1\d \(ventilating|h\/R 1\.1\d \(/.test(await p.textContent('#live-text')), `live text: ${await p.textContent('#live-text')}`);
  assert((await p.$$eval('#plots .uplot', (u) => u.length)) >= 3, 'the run\'s plots are not drawn');
  assert(await p.$eval('#stale', (e) => e.hidden), 'the wave group\'s run is marked stale');
  await p.$eval('#shown-what', (e) => e.scrollIntoView());
  await p.screenshot({ path: `${shots}/rare-wave-group-1366x768.png` });
  console.log(`     stern view at ${d.t} s: h/R ${d.hr.toFixed(4)}`);
});

await check('a worst trial\'s Replay runs that trial: its lowest bus voltage over the window equals the summary\'s to 1e-9', async () => {
  const p = page;
  const worst = cli.worst.find((w) => w.consequence === 'min_bus_voltage_pu');
  const btn = `#rare-worst-table button[data-trial="${worst.trial}"]`;
  await p.click(btn);
  await runEnds(p);
  const lo = await p.evaluate(() => {
    const c = window.__liveViews.cols;
    let m = Infinity;
    c.t_s.forEach((t, i) => { if (t >= 150 - 1e-9 && t <= 165 + 1e-9) m = Math.min(m, c.bus_voltage_pu[i]); });
    return m;
  });
  assert(close(lo, worst.value), `replayed trial ${worst.trial}: lowest bus voltage ${lo}, the summary's ${worst.value}`);
  assert(/trial \d+/.test(await p.textContent('#shown-what')), 'no line saying which trial is shown');
  console.log(`     trial ${worst.trial} (seed ${await p.getAttribute(btn, 'data-seed')}): ${lo} pu`);
});

await check('an edit of the study marks the results stale (the replay too) and undoing it brings them back; a hub depth of the control equals --set ship.hull.hub_above_base_m; a study in calm water offers nothing to compute', async () => {
  const p = page;
  await setField(p, 'sim.seed', 2);
  await p.waitForTimeout(200);
  assert(!(await p.$eval('#rare-stale', (e) => e.hidden)) && (await p.$eval('#rare-results', (e) => e.classList.contains('rare-is-stale'))), 'results of other values are not marked stale');
  assert(!(await p.$eval('#stale', (e) => e.hidden)), 'the replayed trial is not marked stale');
  await setField(p, 'sim.seed', 1);
  await p.waitForTimeout(200);
  assert(await p.$eval('#rare-stale', (e) => e.hidden), 'the results of the form\'s values are still marked stale');
  // Another hub depth: stale, then computed; the command line with the same hub height.
  await p.fill('#rare-h0', '6');
  await p.dispatchEvent('#rare-h0', 'change');
  assert(!(await p.$eval('#rare-stale', (e) => e.hidden)), 'another hub depth does not mark the results stale');
  await compute(p);
  // (The bus voltage's threshold is still the 0.8 pu typed above: a threshold stays as typed.)
  const deep = ['--threshold', 'min_bus_voltage_pu=0.8', ...THRESHOLDS.slice(2), '--set', 'ship.hull.hub_above_base_m=0.15'];
  sameSummary(await summaryOf(p), cliRare(...deep), 'h0 = 6 m');
  await p.click('#tab-sim');
  await p.selectOption('#preset', 'startup');
  await p.waitForTimeout(300);
  assert(await p.$eval('#rare-body', (e) => e.hidden), 'the head-seas results show under the start-up study');
  assert(!(await p.$eval('#rare-nosea', (e) => e.hidden)) && (await p.$eval('#rare-controls', (e) => e.hidden)), 'a study in calm water offers a computation');
  console.log(`     calm water: ${await p.textContent('#rare-nosea')}`);
});

await check('Cancel stops a computation and the next one computes', async () => {
  const p = page;
  await p.selectOption('#preset', 'head-seas-ss6');
  await openRare(p);
  await p.fill('#rare-trials', '1000');
  await p.dispatchEvent('#rare-trials', 'change');
  await p.click('#rare-compute');
  // 1000 trials are estimated at over a minute on two workers (about 69 s): then the page asks
  // first, and Start it starts them.
  await p.waitForFunction(() => document.getElementById('rare-progress').value > 0 || document.querySelector('#long-study[open]'), null, { timeout: 30000 });
  if (await p.$('#long-study[open]')) await p.click('#long-study-go');
  await p.waitForFunction(() => document.getElementById('rare-progress').value > 0, null, { timeout: 30000 });
  await p.click('#rare-cancel');
  await p.waitForFunction(() => document.getElementById('rare-status').textContent === 'Cancelled.', null, { timeout: 10000 });
  assert(await p.$eval('#rare-cancel', (b) => b.disabled), 'Cancel stays enabled');
  await p.fill('#rare-trials', '1001');
  await p.click('#rare-compute');
  assert((await p.getAttribute('#rare-trials', 'aria-invalid')) === 'true' && /2 to 1000/.test(await p.textContent('#rare-trials-err')), 'too many trials are not refused at the field');
  await compute(p, 8);
  await p.close();
});

// Layout and accessibility: the fold open with results, nothing wider than the screen, no two
// plots overlapping, axe clean.
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];
const RULES = ['heading-order', 'empty-table-header', 'landmark-one-main', 'scrollable-region-focusable', 'landmark-no-duplicate-main'];
for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: the rare events fit, no plots overlap, axe clean (screenshots)`, async () => {
    const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
    const p = await open(link('head-seas-ss6'), c);
    await openRare(p);
    await compute(p);
    await p.waitForTimeout(300);
    const l = await p.evaluate(() => {
      const W = document.documentElement.clientWidth;
      const clipped = (e) => { for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) if (getComputedStyle(a).overflowX !== 'visible') return true; return false; };
      const over = [...document.querySelectorAll('#rare-box *')].filter((e) => e.getClientRects().length && e.getBoundingClientRect().right > W + 1 && !clipped(e)).map((e) => `${e.tagName}#${e.id}.${e.className}`).slice(0, 5);
      const boxes = [...document.querySelectorAll('#rare-plots .plot')].map((e) => e.getBoundingClientRect());
      const overlaps = [];
      for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) {
        const a = boxes[i], b = boxes[j];
        if (a.left < b.right - 1 && b.left < a.right - 1 && a.top < b.bottom - 1 && b.top < a.bottom - 1) overlaps.push(`${i}/${j}`);
      }
      const unfit = [...document.querySelectorAll('#rare-plots .plot')].filter((p) => p.querySelector('.uplot') && p.querySelector('.uplot').getBoundingClientRect().right > p.getBoundingClientRect().right + 1).length;
      return { W, scroll: document.documentElement.scrollWidth, over, overlaps, unfit };
    });
    assert(l.scroll <= l.W, `the page is ${l.scroll} px wide in a ${l.W} px viewport`);
    assert(!l.over.length && !l.overlaps.length && !l.unfit, `overflowing ${l.over.join(', ')}; overlapping plots ${l.overlaps.join(', ')}; ${l.unfit} plot(s) wider than their panel`);
    await p.$eval('#rare-box', (e) => e.scrollIntoView());
    await p.screenshot({ path: `${shots}/rare-${w}x${h}.png` });
    await p.$eval('#rare-plots', (e) => e.scrollIntoView());
    await p.screenshot({ path: `${shots}/rare-plots-${w}x${h}.png` });
    if (w < 600) await p.locator('#rare-box').screenshot({ path: `${shots}/rare-box-${w}x${h}.png` });
    const v = await axeFindings(p, { rules: RULES });
    assert(!v.length, v.join(' | '));
    await c.close();
  });
}

await finish(browser, errors);
