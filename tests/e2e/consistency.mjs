// Browser test: the page never contradicts itself (issue 29). One state for inputs, results and
// the address bar (Reset, Back/Forward, edits kept per study, Monte Carlo and design-tab links),
// labels that match their numbers, and the layout and accessibility leftovers, at the three
// sizes a class meets. Usage: node tests/e2e/consistency.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR
import { mkdirSync } from 'node:fs';
import { assert, axeFindings, checker, launch, openPage, pressAndWait, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
// bypassCSP: axe-core is injected as an inline script (the page's own policy forbids those).
const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
const open = (url, c = ctx) => openPage(c, url, base, errors);
const summaryText = (p) => p.$eval('#summary tbody', (t) => t.textContent);
const preset = (p) => p.$eval('#preset', (s) => s.value);
const link = (name) => `${base}#v=2&preset=${name}`;

await check('Reset right after an out-of-range value clears its error and Run is back', async () => {
  const p = await open(link('head-seas-ss6'));
  const study = await p.inputValue('#f-sea-sea_state');
  await setField(p, 'sea.sea_state', 1);
  await p.click('#reset'); // before the check of the value has answered
  await p.waitForTimeout(1500);
  assert((await p.inputValue('#f-sea-sea_state')) === study, 'the field did not return to the study value');
  assert((await p.getAttribute('#f-sea-sea_state', 'aria-invalid')) === null, 'the field keeps its error after Reset');
  assert((await p.textContent('#f-sea-sea_state-err')) === '', 'the error text stays after Reset');
  assert(!(await p.$eval('#run', (b) => b.disabled)) && !(await p.$eval('#mc-run', (b) => b.disabled)), 'Run or Monte Carlo stays disabled');
  await p.close();
});

await check('edits are kept per study while the page is open, marked, and Reset brings the study back', async () => {
  const p = await open(link('head-seas-ss6'));
  const study = { ss: await p.inputValue('#f-sea-sea_state'), seed: await p.inputValue('#f-sim-seed') };
  await setField(p, 'sea.sea_state', 5);
  await setField(p, 'sim.seed', 3);
  await p.selectOption('#preset', 'startup');
  assert(await p.$eval('#modified', (m) => m.hidden), 'start-up is marked modified');
  await p.selectOption('#preset', 'head-seas-ss6');
  assert((await p.inputValue('#f-sea-sea_state')) === '5' && (await p.inputValue('#f-sim-seed')) === '3', 'the edits were lost on the way back');
  assert(!(await p.$eval('#modified', (m) => m.hidden)), 'no visible modified mark');
  assert(/2 values/.test(await p.textContent('#modified')), `mark: ${await p.textContent('#modified')}`);
  assert((await p.$eval('#preset', (s) => s.selectedOptions[0].text)).includes('(modified)'), 'the picker does not say modified');
  assert(await p.$eval('#f-sea-sea_state-field', (d) => d.classList.contains('edited')), 'the changed field is not marked');
  await p.click('#reset');
  await p.waitForTimeout(300);
  assert((await p.inputValue('#f-sea-sea_state')) === study.ss && (await p.inputValue('#f-sim-seed')) === study.seed, 'Reset did not restore the study');
  assert(await p.$eval('#modified', (m) => m.hidden), 'still marked modified after Reset');
  await p.close();
});

await check('Back and Forward restore inputs and results together; exports are named for what they hold; the tabs are steps too', async () => {
  const p = await open(link('turn-90'));
  await pressAndWait(p);
  const turn = await summaryText(p);
  await p.selectOption('#preset', 'ac-braking');
  assert(await p.$eval('#summary-box', (e) => e.hidden), "the 90 deg turn's summary stays under the braking study");
  assert((await p.$$eval('#plots .uplot', (e) => e.length)) === 0, "the 90 deg turn's plots stay under the braking study");
  await pressAndWait(p);
  const brake = await summaryText(p);
  assert(brake !== turn, 'same summaries');
  await p.goBack();
  await p.waitForFunction(() => document.getElementById('preset').value === 'turn-90', null, { timeout: 10000 });
  await p.waitForFunction((t) => document.querySelector('#summary tbody').textContent === t, turn, { timeout: 10000 });
  assert(/turn/i.test(await p.textContent('#watch')), 'What to watch is not the turn\'s');
  const [dl] = await Promise.all([p.waitForEvent('download'), p.click('#export-csv')]);
  assert(dl.suggestedFilename().includes('turn-90'), `export named ${dl.suggestedFilename()} under turn-90`);
  await p.goForward();
  await p.waitForFunction(() => document.getElementById('preset').value === 'ac-braking', null, { timeout: 10000 });
  await p.waitForFunction((t) => document.querySelector('#summary tbody').textContent === t, brake, { timeout: 10000 });
  await p.click('#tab-ips');
  await p.waitForTimeout(300);
  assert((await p.evaluate(() => location.hash)).includes('tab=ips'), 'the address does not say the tab');
  await p.goBack();
  await p.waitForFunction(() => document.getElementById('tab-sim').getAttribute('aria-selected') === 'true', null, { timeout: 10000 });
  assert((await preset(p)) === 'ac-braking', `Back on the stability tab changed the study to ${await preset(p)}`);
  assert((await summaryText(p)) === brake, 'Back from the stability tab lost the result');
  await p.close();
});

await check('an edit after a run marks the results stale, and Back returns to the run values with their result', async () => {
  const p = await open(link('startup'));
  await setField(p, 'sim.duration_s', 60);
  await pressAndWait(p);
  const first = await summaryText(p);
  await setField(p, 'ship.drag_coeff', 0.004);
  await p.waitForTimeout(300);
  assert(!(await p.$eval('#stale', (e) => e.hidden)), 'results of other values are not marked stale');
  await p.click('#stale-run');
  await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  assert(await p.$eval('#stale', (e) => e.hidden), 'still marked stale after running');
  await p.goBack();
  await p.waitForFunction((t) => document.querySelector('#summary tbody').textContent === t, first, { timeout: 10000 });
  assert((await p.inputValue('#f-ship-drag_coeff')) !== '0.004', 'Back did not restore the earlier value');
  assert(await p.$eval('#stale', (e) => e.hidden), 'stale mark after Back to the matching result');
  await p.close();
});

const mcTable = (p) => p.$$eval('#plots table', (t) => t.map((x) => x.textContent).join('|'));
await check('a Monte Carlo link opens the Monte Carlo view and reruns it to the same numbers', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(link('mc-arrival'), c);
  await setField(p, 'monte_carlo.trials', 6);
  const st = await pressAndWait(p, '#mc-run');
  assert(st.startsWith('Monte Carlo done'), st);
  const mine = await mcTable(p);
  await p.click('#share');
  const url = await p.inputValue('#share-url');
  assert(url.includes('mode=mc'), url);
  const other = await open(url, c);
  await other.waitForFunction(() => document.getElementById('status').textContent.startsWith('Monte Carlo done'), null, { timeout: 120000 });
  assert((await mcTable(other)) === mine, 'the linked Monte Carlo gave other numbers');
  await c.close();
});

// Issue 46: a study estimated long is said before it starts, and its share link asks again.
await check('a long Monte Carlo study says its estimate and starts only when asked; its share link asks again', async () => {
  const c = await browser.newContext({ viewport: { width: 390, height: 844 }, bypassCSP: true });
  const p = await open(link('mc-arrival'), c);
  await setField(p, 'monte_carlo.trials', 100000);
  await p.click('#mc-run');
  await p.waitForSelector('#long-study[open]', { timeout: 60000 });
  const said = await p.textContent('#long-study-text');
  assert(/^100000 trials on \d workers?: estimated at about [\d.]+ (min|h) in this browser\. Start it now\?$/.test(said), said);
  await p.screenshot({ path: `${shots}/long-study-390.png` });
  assert(!(await axeFindings(p)).length, `axe: ${(await axeFindings(p)).join('; ')}`);
  await p.click('#long-study-no');
  await p.waitForFunction(() => document.getElementById('status').textContent.startsWith('Not started'), null, { timeout: 10000 });
  const st = await p.textContent('#status');
  assert(/^Not started: 100000 trials estimated at about [\d.]+ (min|h) on \d workers?\.$/.test(st), st);
  assert(!(await p.$eval('#mc-run', (b) => b.disabled)) && !(await p.$eval('#run', (b) => b.disabled)), 'the page stays busy after Not now');
  // Asked again and started, it runs (and Cancel stops it).
  await p.click('#mc-run');
  await p.waitForSelector('#long-study[open]', { timeout: 60000 });
  await p.click('#long-study-go');
  await p.waitForFunction(() => /^Monte Carlo: 100000 trials on \d workers?/.test(document.getElementById('status').textContent), null, { timeout: 10000 });
  await p.click('#cancel');
  await p.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 10000 });
  // A link to the Monte Carlo view of these values (as one shared after a study) asks before it
  // reruns.
  await p.click('#share');
  const url = await p.inputValue('#share-url');
  // (Run stays disabled while it asks: the page is opened by hand, not by open().)
  const other = await c.newPage();
  other.on('pageerror', (e) => errors.push(`${url}: ${e}`));
  await other.goto(url.includes('mode=mc') ? url : `${url}&mode=mc`);
  await other.waitForSelector('#long-study[open]', { timeout: 60000 });
  await other.click('#long-study-no');
  await other.waitForFunction(() => document.getElementById('status').textContent.startsWith('Not started'), null, { timeout: 10000 });
  assert(!(await other.$eval('#run', (b) => b.disabled)), 'Run stays disabled after Not now');
  await c.close();
});

await check("the thesis' Table 5.8 columns stand only beside the thesis' own study; a histogram of some trials says how many", async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(link('mc-wigley'), c);
  await setField(p, 'monte_carlo.trials', 6);
  await pressAndWait(p, '#mc-run');
  const heads = await p.$$eval('#plots th', (t) => t.map((x) => x.textContent));
  assert(!heads.some((h) => /thesis/.test(h)), `thesis columns beside the Wigley study: ${heads.join(', ')}`);
  assert(!heads.some((h) => h.trim() === ''), 'an empty table header');
  const p2 = await open(link('mc-arrival'), c);
  await setField(p2, 'monte_carlo.trials', 6);
  await pressAndWait(p2, '#mc-run');
  assert((await p2.$$eval('#plots th', (t) => t.map((x) => x.textContent))).includes('thesis: Rice'), 'no thesis column beside the thesis study');
  const titles = await p2.$$eval('#plots h3', (h) => h.map((x) => x.textContent));
  const arrival = titles.find((t) => t.startsWith('Arrival time'));
  const events = Number((await p2.textContent('#plots')).match(/First surface effects \/ censored(\d+) \//)?.[1]);
  if (arrival && events < 6) assert(arrival.includes(`${events} of 6 trials`), `histogram title: ${arrival}`);
  await c.close();
});

await check("the design tab's settings are in the address and survive a reload", async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(base, c);
  await p.click('#tab-design');
  await p.waitForFunction(() => document.getElementById('design-status').textContent.length > 0, null, { timeout: 30000 });
  const want = await p.$eval('#design-q', (e) => {
    e.value = String(Number(e.min) + 1);
    e.dispatchEvent(new Event('input'));
    e.dispatchEvent(new Event('change'));
    return e.value;
  });
  await p.waitForTimeout(300);
  const hash = await p.evaluate(() => location.hash);
  assert(hash.includes('tab=design') && hash.includes('design='), `address: ${hash}`);
  await p.reload();
  await p.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await p.getAttribute('#tab-design', 'aria-selected')) === 'true', 'the reload left the design tab');
  assert((await p.inputValue('#design-q')) === want, `q after reload ${await p.inputValue('#design-q')} (want ${want})`);
  // The same tuning from the address alone, in a fresh page.
  const q = await open(base + hash, await browser.newContext({ viewport: { width: 1366, height: 768 } }));
  assert((await q.inputValue('#design-q')) === want, 'a link did not carry the tuning');
  await c.close();
});

await check('the Bode magnitude and phase share one cursor and line up', async () => {
  const p = await open(base);
  await p.click('#tab-ips');
  await p.waitForFunction(() => document.querySelectorAll('#ips-plots .chart').length >= 2, null, { timeout: 30000 });
  const keys = await p.$$eval('#ips-plots .chart', (c) => c.filter((x) => x.uplot).map((x) => x.uplot.cursor.sync && x.uplot.cursor.sync.key));
  assert(keys.length >= 2 && keys.every((k) => k && k === keys[0]), `cursor sync keys: ${keys}`);
  // The magnitude stands above the phase with its plot area in line (same left edge and width).
  const boxes = await p.$$eval('#ips-plots .chart', (c) => c.filter((x) => x.uplot).map((x) => { const r = x.getBoundingClientRect(); return [Math.round(r.left + x.uplot.bbox.left / devicePixelRatio), Math.round(x.uplot.bbox.width / devicePixelRatio), Math.round(r.top)]; }));
  assert(boxes.length === 2 && boxes[0][0] === boxes[1][0] && boxes[0][1] === boxes[1][1] && boxes[1][2] > boxes[0][2], `Bode plot areas not in line: ${JSON.stringify(boxes)}`);
  await p.close();
});

await check('power ratios are named for what they are, headings never read -0, compare colours mean better or worse', async () => {
  const p = await open(link('acceleration'));
  await pressAndWait(p);
  const heads = await p.$$eval('#inventory th[scope=col]', (t) => t.map((x) => x.textContent));
  // The efficiency column is core's (energies over the last minute, stores counted): never over 100 %.
  assert(heads.some((h) => /^efficiency, \d+(\.\d+)?–\d+(\.\d+)? s$/.test(h)) && !heads.some((h) => /now/.test(h) && /out \/ in/.test(h)), `inventory columns: ${heads}`);
  const effs = await p.$$eval('#inventory tr', (rows) => rows.slice(1).map((r) => r.cells[3] && r.cells[3].textContent));
  assert(effs.filter((t) => t !== '–').length === 4 && effs.every((t) => t === '–' || (/^\d+\.\d %$/.test(t) && parseFloat(t) <= 100)), `efficiencies: ${effs}`);
  assert((await p.evaluate(async () => (await import('./js/live/shared.js')).fixed(-0.2, 0))) === '0', 'a heading of -0.2 deg reads -0');
  const words = await p.evaluate(async () => { const { keeps } = await import('./js/live/drivetrain.js'); return [keeps(130.5, 100), keeps(95, 100)]; });
  assert(words[0] === 'out/in 130.5 %' && words[1] === 'keeps 95.0 %', `the drive train says ${words}`);
  assert(!/heading -0°/.test(await p.textContent('#live')), 'the live text says heading -0');
  await p.click('#compare-with button');
  await p.waitForFunction(() => document.getElementById('preset').value === 'acceleration-high-gains' && /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  const cells = await p.$$eval('#compare-table tbody tr', (rows) => rows.map((r) => ({ label: r.cells[0].textContent, text: r.cells[3].textContent, cls: r.cells[3].className })));
  assert(cells.length > 3, `${cells.length} compared figures`);
  for (const c of cells) {
    assert(['', 'better', 'worse'].includes(c.cls), `${c.label}: class ${c.cls}`);
    assert((c.cls === 'better') === c.text.includes('(better)') && (c.cls === 'worse') === c.text.includes('(worse)'), `${c.label}: "${c.text}" coloured ${c.cls}`);
  }
  const dip = cells.find((c) => c.label.startsWith('lowest bus voltage'));
  assert(dip && (dip.text.startsWith('+') ? dip.cls === 'better' : dip.cls !== 'better'), `bus dip: ${JSON.stringify(dip)}`);
  const peak = cells.find((c) => c.label.startsWith('peak motor power'));
  assert(!peak || peak.cls === '', 'a figure with no good direction is coloured');
  await p.close();
});

const withEdits = (name, d) => `${base}#v=2&preset=${name}&d=${Buffer.from(JSON.stringify(d)).toString('base64url')}`;
const waitDone = (p) => p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent) && !document.getElementById('run').disabled, null, { timeout: 90000 });
await check('a stalled plant is called stalled: the summary warns and the live drive train draws the set as stalled', async () => {
  const p = await open(withEdits('acceleration', { controllers: { field: { kp: 5 } } }));
  await waitDone(p);
  assert(!(await p.$eval('#warnings-box', (b) => b.hidden)), 'no warnings box beside the results');
  assert(/stall/i.test(await p.textContent('#warnings')), `warnings: ${await p.textContent('#warnings')}`);
  await p.waitForFunction(() => window.__liveViews && window.__liveViews.cols, null, { timeout: 20000 });
  await p.evaluate(() => window.__liveViews.seek(100));
  await p.waitForTimeout(200);
  const warn = await p.evaluate(() => window.__liveViews.drawn.train && window.__liveViews.drawn.train.warn);
  assert(warn && warn.turbine === 'STALLED', `drive train at 100 s: ${JSON.stringify(warn)}`);
  await p.close();
});
await check('a propeller out of the water all run is counted and warned about (h0 = 0.15 m)', async () => {
  const p = await open(withEdits('head-seas-ss6', { sim: { duration_s: 40 }, ship: { hull: { hub_above_base_m: 6.0 } } }));
  await waitDone(p);
  const st = await p.textContent('#status');
  const n = Number((st.match(/Surface losses started (\d+) time/) || [])[1]);
  assert(n >= 1, `status: ${st}`);
  assert(/out of the water/i.test(await p.textContent('#warnings')), `warnings: ${await p.textContent('#warnings')}`);
  await p.close();
});
await check('a signal that does not settle gets no settling time in the comparison', async () => {
  const p = await open(link('turn-90'));
  await setField(p, 'sim.duration_s', 120);
  await pressAndWait(p);
  await p.click('#keep');
  await pressAndWait(p);
  const rows = await p.$$eval('#compare-table tbody tr', (r) => r.map((x) => [x.cells[0].textContent, x.cells[1].textContent, x.cells[2].textContent]));
  const turbine = rows.find(([l]) => /turbine speed settles/.test(l));
  assert(!turbine || (turbine[1] === 'no settling time' && turbine[2] === 'no settling time'), `turbine speed, flat at 1 pu: ${JSON.stringify(turbine)}`);
  await p.close();
});
await check("the Monte Carlo's Rice note is computed from the numbers it compares", async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(link('mc-excess-energy'), c);
  await setField(p, 'monte_carlo.trials', 8);
  await pressAndWait(p, '#mc-run');
  const note = await p.textContent('#rice-note');
  assert(!/the means stay close/.test(note) && /standard error/.test(note), `note: ${note}`);
  assert(/either shaft/.test(await p.textContent('#plots')), 'the Rice line does not say which event it predicts');
  await c.close();
});

// The words that compare numbers come from the numbers: the page's own routines, given two means
// 40 % apart and two equal ones, say "differ" and "agree" (and which way), in the page itself.
await check('Monte Carlo and rare-event words: two means 40 % apart are never called agreeing, equal ones are', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(link('mc-arrival'), c);
  const out = await p.evaluate(async () => {
    const mc = await import('./js/montecarlo.js');
    const rare = await import('./js/rare.js');
    const arrival = (mean, meanCensored) => ({ mean, std: 10, mean_censored: meanCensored, std_censored: 10, events: 200, cap_s: 90, skewness: 2, kurtosis: 9 });
    const rice = (meanCensored) => ({ mean_censored_with_start_s: meanCensored, rate_per_s: 1 / 20 });
    const th = (v) => (key) => ({ 'table_5_8.rice.mean_s': 20, 'table_5_8.monte_carlo.mean_s': v, 'table_5_8.monte_carlo.std_s': 10, 'table_5_8.monte_carlo.trials': 189 })[key] ?? null;
    const excess = (calm) => ({ mean: -5, std: 7, vs_calm_water: { mean: calm, std: 57 } });
    return {
      apart: mc.meanWords(14, 0.5, 10, 0.5, 's'), same: mc.meanWords(10, 0.5, 10, 0.5, 's'), within: mc.meanWords(10.5, 0.5, 10, 0, 's'),
      noSpread: mc.meanWords(14, 0, 10, 0, 's'), oneTrial: mc.meanWords(14, NaN, 10, 0, 's'),
      riceApart: mc.riceComparison(arrival(14, 14), rice(10), 200), riceSame: mc.riceComparison(arrival(10, 10), rice(10), 200),
      riceFlat: mc.riceComparison({ ...arrival(90, 90), std_censored: 0 }, rice(89.97), 2),
      thesisApart: mc.table58Comparison(arrival(14, 14), rice(10), th(10)), thesisSame: mc.table58Comparison(arrival(10, 10), { rate_per_s: 1 / 20 }, th(10)),
      excessApart: mc.excessComparison(excess(140), 100, { mean: 100, std: 33 }), excessSame: mc.excessComparison(excess(100), 100, { mean: 100, std: 33, printedMean: '100', printedStd: '33' }),
      rareIn: rare.riceWords({ per_hour: 100, low_per_hour: 95, high_per_hour: 105 }, 100), rareOut: rare.riceWords({ per_hour: 100, low_per_hour: 95, high_per_hour: 105 }, 140),
    };
  });
  const says = (name, re) => assert(re.test(typeof out[name] === 'string' ? out[name] : out[name].text), `${name}: ${JSON.stringify(out[name])}`);
  const never = (name, re) => assert(!re.test(typeof out[name] === 'string' ? out[name] : out[name].text), `${name}: ${JSON.stringify(out[name])}`);
  assert(!out.apart.agree && out.same.agree && out.within.agree && !out.noSpread.agree && !out.oneTrial.agree, JSON.stringify(out));
  says('apart', /^differ: ours is 4\.0 s \(40 %\) above/); never('apart', /agree|close|similar/);
  says('same', /^agree/); says('noSpread', /no spread/); says('oneTrial', /one trial/);
  says('riceApart', /differ by 4\.0 s.*later than Poisson/); never('riceApart', /agree|stay close/);
  says('riceSame', /The means of min\(T, cap\) agree/);
  says('riceFlat', /no spread between the 2 trials/); never('riceFlat', /one trial|agree/);
  says('thesisApart', /Monte Carlo means .* differ: ours is 4\.0 s \(40 %\) above/); never('thesisApart', /Monte Carlo means \([^)]*\) agree/);
  says('thesisSame', /Monte Carlo means .* agree.*Rice's means .* agree within 1 %/);
  says('excessApart', /one motor draws 5\.000 MJ less/); says('excessApart', /differ: ours is 40 MJ \(40 %\) above.*1\.40 times the thesis'/); never('excessApart', /thesis' [^.]*agree/);
  says('excessSame', /calm water and the thesis' 100 ± 33 MJ .*agree/);
  says('rareIn', /^within the trials' 95 % interval/); says('rareOut', /^outside the trials' 95 % interval: 40 % above/);
  await c.close();
});

// At the studies' own trials, the texts beside the numbers: the words follow what the tables show
// (an excess energy's sign, ours against the thesis' Table 5.8 and ch. 5.4.1), and no stale figure
// or claim of the old texts is left.
await check("at their own trials, the Monte Carlo studies' texts say what their numbers show", async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const stale = /stay close|million times|this is the thesis' figure|alone cost|over (100|200|50) random seas/;
  const cells = (p) => p.$$eval('#plots table', (ts) => ts.filter((t) => t.caption).map((t) => [t.caption.textContent, [...t.tBodies[0].rows].map((r) => [...r.cells].map((x) => x.textContent))]));
  const ratioWords = (text, ours, theirs) => {
    const rel = Math.abs(ours - theirs) / theirs;
    assert(Number.isFinite(rel), `not numbers: ${ours}, ${theirs}`);
    if (rel > 0.2) assert(/differ/.test(text) && !/\) agree/.test(text), `${ours} against ${theirs} (${Math.round(100 * rel)} % apart) in: ${text}`);
  };
  const p = await open(link('mc-arrival'), c);
  await pressAndWait(p, '#mc-run');
  let text = `${await p.textContent('#about')} ${await p.textContent('#watch')} ${await p.textContent('#plots')}`;
  assert(!stale.test(text), `stale text: ${(text.match(stale) || [])[0]}`);
  const t58 = (await cells(p)).find(([cap]) => /Table 5\.8/.test(cap))[1];
  const mean = t58.find(([n]) => n === 'mean').map(Number);
  const note = await p.textContent('#thesis-note');
  ratioWords(note.split(';')[0], mean[2], mean[4]);
  ratioWords(note.split(';')[1], mean[1], mean[3]);
  assert(/below/.test(note.split(';')[0]) === mean[2] < mean[4], `which way: ${note}`);
  const rice = await p.textContent('#rice-note');
  const [, mcCens, riceCens] = (await p.textContent('#plots')).match(/mean of min\(T, cap\) ([\d.]+) s, Rice ([\d.]+) s/).map(Number);
  if (Math.abs(mcCens - riceCens) / riceCens > 0.2) assert(!/agree/.test(rice), `${mcCens} s against ${riceCens} s called agreeing: ${rice}`);
  const p2 = await open(link('mc-excess-energy'), c);
  await pressAndWait(p2, '#mc-run');
  text = `${await p2.textContent('#about')} ${await p2.textContent('#watch')} ${await p2.textContent('#plots')}`;
  assert(!stale.test(text), `stale text: ${(text.match(stale) || [])[0]}`);
  const summary = (await cells(p2)).find(([cap]) => cap === 'Monte Carlo summary')[1];
  const vsSub = Number(summary.find(([n]) => /submerged/.test(n))[1].split(' ± ')[0]);
  const calmRow = summary.find(([n]) => /calm water/.test(n));
  const vsCalm = Number(calmRow[1].split(' ± ')[0]), thesisCalm = Number(calmRow[0].match(/thesis: ([\d.]+)/)[1]);
  const excess = await p2.textContent('#excess-note');
  assert(excess.includes(`draws ${Math.abs(vsSub).toPrecision(4)} MJ ${vsSub < 0 ? 'less' : 'more'}`) || /tell from nil/.test(excess), `excess ${vsSub} MJ in: ${excess}`);
  ratioWords(excess.slice(excess.indexOf('Ours against calm water')), vsCalm, thesisCalm);
  const titles = await p2.$$eval('#plots h3', (h) => h.map((x) => x.textContent));
  assert(titles.filter((t) => /Fig\. 5-22/.test(t)).every((t) => /calm water/.test(t)), `Fig. 5-22 beside another excess: ${titles.join(' | ')}`);
  await c.close();
});

// Where things are: Run above the fold at 1366x768, the plots up in presentation mode and on the
// phone, one main landmark, and axe after a run and after a Monte Carlo study at every size.
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];
const RULES = ['heading-order', 'empty-table-header', 'landmark-one-main', 'scrollable-region-focusable', 'landmark-no-duplicate-main'];
for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: Run in view on load, the plots come up, one main landmark, axe clean after a run and a Monte Carlo study (screenshots)`, async () => {
    const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true });
    const p = await open(link('head-seas-ss6'), c);
    const run = await p.$eval('#run', (b) => b.getBoundingClientRect().bottom);
    if (w >= 1366) assert(run <= h, `Run is ${Math.round(run)} px down a ${h} px screen`);
    assert((await p.$$eval('main', (m) => m.length)) === 1 && (await p.$$eval('main[role=tabpanel]', (m) => m.length)) === 0, 'not one main landmark');
    await setField(p, 'sim.duration_s', 120);
    await pressAndWait(p);
    await p.waitForTimeout(300);
    let v = await axeFindings(p, { rules: RULES });
    assert(!v.length, `after a run: ${v.join(' | ')}`);
    await p.screenshot({ path: `${shots}/consistency-run-${w}x${h}.png` });
    const top = (sel) => p.$eval(sel, (e) => e.getBoundingClientRect().top + window.scrollY);
    if (w < 600) assert((await top('#plots')) < (await top('#live')), 'on the phone the plots come after the live views');
    await p.click('#present');
    await p.waitForTimeout(500);
    assert(await p.isVisible('#watch'), 'presentation hides What to watch');
    const firstPlot = await top('#plots .plot'), live = await top('#live');
    if (w >= 1366) assert(live < h && firstPlot < 2 * h, `presenting: live views at ${Math.round(live)} px, first plot at ${Math.round(firstPlot)} px`);
    await p.screenshot({ path: `${shots}/consistency-presenting-${w}x${h}.png` });
    v = await axeFindings(p, { rules: RULES });
    assert(!v.length, `presenting: ${v.join(' | ')}`);
    await p.click('#present');
    await p.selectOption('#preset', 'mc-arrival');
    await setField(p, 'monte_carlo.trials', 6);
    await pressAndWait(p, '#mc-run');
    await p.waitForTimeout(300);
    v = await axeFindings(p, { rules: RULES });
    assert(!v.length, `after a Monte Carlo study: ${v.join(' | ')}`);
    await p.screenshot({ path: `${shots}/consistency-mc-${w}x${h}.png` });
    await c.close();
  });
}

await finish(browser, errors);
