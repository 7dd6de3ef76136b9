// Browser end-to-end test of the page in headless Chromium (Debian's chromium + playwright-core).
// Usage: node tests/e2e/e2e.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { assert, axeFindings, checker, launch, openPage, setField } from './lib.mjs';


const base = process.argv[2];
const shots = process.argv[3];
mkdirSync(shots, { recursive: true });
console.log(`screenshots in ${shots}`);
const { check, finish } = checker();
const browser = await launch();
const context = await browser.newContext({ viewport: { width: 1300, height: 1100 } });
const consoleErrors = [];
const open = (url, ctx = context) => openPage(ctx, url, base, consoleErrors);
async function runAndWait(page) {
  await page.click('#run');
  await page.waitForFunction(() => /^Done|^Cancel/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 60000 });
  return page.textContent('#status');
}
// Every axis label fits along its axis (a longer one is cut, its unit first): measured in the
// axis' own font on the plot's canvas.
const axisLabelsCut = (p) => p.evaluate(() => [...document.querySelectorAll('.chart')].filter((c) => c.getClientRects().length && c.uplot)
  .flatMap((c) => {
    const u = c.uplot;
    return u.axes.filter((a) => a.show !== false && a.label).flatMap((a) => {
      u.ctx.save();
      u.ctx.font = Array.isArray(a.labelFont) ? a.labelFont[0] : a.labelFont;
      const w = u.ctx.measureText(a.label).width;
      u.ctx.restore();
      const room = a.side % 2 === 1 ? u.bbox.height : u.bbox.width;
      return w > room ? [`${c.closest('.plot').querySelector('h3')?.textContent}: "${a.label}" (${Math.round(w)} > ${Math.round(room)} px)`] : [];
    });
  }));
const summaryText = (page) => page.$eval('#summary tbody', (t) => t.textContent);

const page = await open(base);
let firstSummary;
await check('start-up runs and the plots are drawn with data', async () => {
  await setField(page, 'sim.duration_s', 120);
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  const n = await page.$$eval('#plots .uplot', (els) => els.length);
  assert(n >= 5, `only ${n} plots`);
  const rows = await page.$$eval('#summary tbody tr', (r) => r.length);
  assert(rows === 6, `${rows} summary rows`);
  firstSummary = await summaryText(page);
  assert(/\d/.test(firstSummary), 'no numbers in the summary');
  await page.screenshot({ path: `${shots}/startup.png` });
});
await check('a changed parameter changes the result', async () => {
  await setField(page, 'ship.drag_coeff', 0.004);
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  assert((await summaryText(page)) !== firstSummary, 'same summary after changing C_r');
});
await check('a copied link reproduces the identical run in a new page', async () => {
  const mine = await summaryText(page);
  await page.click('#share');
  const url = await page.inputValue('#share-url');
  assert(url.includes('#v=2&preset=startup&d='), url);
  const other = await open(url);
  await other.waitForFunction(() => document.getElementById('status').textContent.startsWith('Done'), null, { timeout: 60000 });
  const theirs = await summaryText(other);
  assert(theirs === mine, `summaries differ:\n${mine}\n${theirs}`);
  assert((await other.inputValue('#f-ship-drag_coeff')) === '0.004', 'form not restored');
  await other.close();
});
for (const [name, hash, want] of [
  ['a damaged link', '#v=1&preset=startup&d=@@@', 'damaged'],
  ['a link from a newer version', '#v=99&preset=startup', 'newer version'],
  ['a truncated link', '#v=1&preset=startup&d=eyJzaGlwIjp7Im1h', 'not valid JSON'],
  ['a hostile deeply nested link', '#v=1&preset=startup&d=' + Buffer.from('['.repeat(500)).toString('base64url'), 'nested too deeply'],
  // (A link with one out-of-range value keeps the rest of its study: tests/e2e/links.mjs.)
  ['a huge link', '#v=1&preset=startup&d=' + 'A'.repeat(20000), 'characters long'],
  ['a link with script text', '#v=1&preset=' + encodeURIComponent('<script>alert(1)</script>'), 'unknown study'],
]) {
  await check(`${name} shows a clear message and falls back to the preset`, async () => {
    const p = await open(base + hash);
    const text = await p.textContent('#notice');
    assert(!(await p.$eval('#notice', (n) => n.hidden)), 'no notice shown');
    assert(text.includes(want), `notice was: ${text}`);
    assert((await p.$eval('#preset', (s) => s.value)) === 'startup', 'did not fall back to start-up');
    assert(!(await p.textContent('#status')).startsWith('Running'), 'ran something');
    if (name === 'a damaged link') await p.screenshot({ path: `${shots}/broken-link.png` });
    await p.close();
  });
}
await check('a long run can be cancelled and the form survives', async () => {
  await setField(page, 'sim.duration_s', 18000);
  await page.click('#run');
  await page.waitForFunction(() => document.getElementById('progress').value > 0.002, null, { timeout: 30000 });
  await page.click('#cancel');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 5000 });
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-sim-duration_s')) === '18000', 'form lost its edit');
  assert((await page.$$eval('#plots .uplot', (els) => els.length)) >= 5, 'earlier plots were lost');
});
await check('edits survive a reload', async () => {
  await page.reload();
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-sim-duration_s')) === '18000', 'duration not restored');
  assert((await page.inputValue('#f-ship-drag_coeff')) === '0.004', 'C_r not restored');
});
await check('a bad value is marked at its field (aria-invalid) and Run waits for it', async () => {
  await setField(page, 'sim.duration_s', 60);
  await setField(page, 'ship.wetted_area_m2', -5);
  await page.waitForFunction(() => document.getElementById('f-ship-wetted_area_m2').getAttribute('aria-invalid') === 'true', null, { timeout: 10000 });
  const err = await page.textContent('#f-ship-wetted_area_m2-err');
  assert(err.includes('from'), `field error: ${err}`);
  assert(await page.$eval('#run', (b) => b.disabled), 'Run is enabled while a field is invalid');
  const desc = await page.getAttribute('#f-ship-wetted_area_m2', 'aria-describedby');
  assert(desc.includes('f-ship-wetted_area_m2-err'), `aria-describedby: ${desc}`);
  await setField(page, 'ship.wetted_area_m2', 5200);
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 10000 });
});
await check('maneuvering study draws the track', async () => {
  await page.selectOption('#preset', 'turn-90');
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  await page.screenshot({ path: `${shots}/turn-90.png` });
});
await check('head seas: with default settings the propeller ventilates (event markers, h/R band, losses)', async () => {
  await page.selectOption('#preset', 'head-seas-ss6');
  assert((await page.inputValue('#f-seakeeping-stern_motion')) === 'consistent', 'the default is not the consistent hub depth');
  const st = await runAndWait(page);
  assert(/^Done/.test(st), st);
  const m = st.match(/Surface losses started (\d+) time/);
  assert(m && Number(m[1]) >= 1, `no ventilation event: ${st}`);
  const titles = await page.$$eval('#plots h3', (hs) => hs.map((h) => h.textContent));
  assert(titles[0].startsWith('Hub depth over propeller radius'), titles.join(' | '));
  assert(titles.some((t) => t.startsWith('Thrust and torque kept')), 'no loss plot');
  assert(/loss onsets/.test(await page.textContent('#plots')), 'no event key');
  await page.screenshot({ path: `${shots}/head-seas.png` });
});
// Live views (issue 14): what they draw is the trace at the cursor, read through the page's test
// hook window.__liveViews (its `drawn` record and its log of every frame while playing).
await check('live views draw the trace at the cursor: hub depth, wave at the stern, block powers', async () => {
  await page.waitForFunction(() => window.__liveViews && window.__liveViews.cols && !document.getElementById('live').hidden, null, { timeout: 20000 });
  const bad = await page.evaluate(() => {
    const L = window.__liveViews, c = L.cols, out = [];
    for (const i of [50, 300, 555, c.t_s.length - 1]) {
      L.seek(c.t_s[i]);
      const d = L.drawn;
      const want = { hub: c.hub_depth_m[i], wave: c.wave_stern_m[i], turbine: c.p_turbine_w[i] / 4 / 1e6, generator: c.p_generator_w[i] / 4 / 1e6, inverter: c.p_inverter_w[i] / 2 / 1e6, motor: c.p_motor_w[i] / 2 / 1e6, ship: c.p_ship_w[i] / 1e6 };
      const got = { hub: d.stern.hub_depth_m, wave: d.stern.wave_stern_m, turbine: d.train.turbine_mw, generator: d.train.generator_mw, inverter: d.train.inverter_mw, motor: d.train.motor_mw, ship: d.train.ship_mw };
      for (const k of Object.keys(want)) if (got[k] !== want[k]) out.push(`t = ${c.t_s[i]} s ${k}: drawn ${got[k]}, trace ${want[k]}`);
      if (d.row !== i) out.push(`t = ${c.t_s[i]} s: drawn row ${d.row}`);
    }
    return out;
  });
  assert(!bad.length, bad.join('; '));
  const text = await page.textContent('#live-text');
  assert(/h\/R/.test(text) && /MW/.test(text), `text alternative: ${text}`);
  const followed = await page.evaluate(() => window.__liveViews.followed);
  assert(followed >= 1, 'the live views did not follow the run while it ran');
  console.log(`     the live views followed the run through ${followed} chunk(s) before its end`);
});
await check('live views: a head-seas run played at 10x shows the disc out of the water when h/R < 1 and the turbine warning at overspeed; frame time and rate', async () => {
  await page.$eval('#live', (e) => e.scrollIntoView());
  await page.selectOption('#live-speed', '10');
  await page.evaluate(() => window.__liveViews.seek(0));
  const wall0 = Date.now();
  await page.click('#live-play');
  await page.waitForFunction(() => !window.__liveViews.playing, null, { timeout: 30000 });
  const wall = (Date.now() - wall0) / 1000;
  const r = await page.evaluate(() => {
    const L = window.__liveViews, log = L.log, lv = L.k.warnings;
    const out = log.filter((f) => f.h_over_r < 1), over = log.filter((f) => f.turbine_pu > lv.turbine_overspeed_pu);
    return { frames: log.length, out: out.length, outDrawn: out.filter((f) => f.disc_out).length, inDrawnOut: log.filter((f) => f.h_over_r >= 1 && f.disc_out).length,
      over: over.length, overWarn: over.filter((f) => f.turbine_warn === 'OVERSPEED' && f.turbine_edge === '#b03a2e').length,
      falseWarn: log.filter((f) => f.turbine_pu <= lv.turbine_overspeed_pu && f.turbine_warn).length, stats: L.stats(), end: L.t, t1: L.t1 };
  });
  console.log(`     live views: ${r.frames} frames over ${r.end.toFixed(1)} s simulated in ${wall.toFixed(1)} s wall; median frame ${r.stats.medianFrameMs.toFixed(2)} ms (95 % ${r.stats.p95FrameMs.toFixed(2)} ms), ${r.stats.fps.toFixed(1)} frames/s, rate ${r.stats.rate.toFixed(2)}x (asked 10x); ${r.out} frames with h/R < 1, ${r.over} with overspeed`);
  assert(r.end === r.t1, `stopped at ${r.end} s of ${r.t1}`);
  assert(r.out > 0, 'no frame with h/R < 1 in the head-seas run');
  assert(r.outDrawn === r.out, `${r.out - r.outDrawn} frames with h/R < 1 drawn with the disc under water`);
  assert(r.inDrawnOut === 0, `${r.inDrawnOut} frames with h/R >= 1 drawn with the disc out of the water`);
  assert(r.over > 0, 'no frame with turbine overspeed in the head-seas run');
  assert(r.overWarn === r.over && r.falseWarn === 0, `turbine warning: ${r.overWarn} of ${r.over} overspeed frames, ${r.falseWarn} false`);
  assert(r.stats.medianFrameMs < 16, `median frame ${r.stats.medianFrameMs} ms`);
  assert(Math.abs(r.stats.rate - 10) < 0.5, `playback rate ${r.stats.rate}x`);
  assert(r.stats.fps > 30, `${r.stats.fps} frames/s`);
  // A frame with the disc out of the water, for the screenshot.
  await page.evaluate(() => { const L = window.__liveViews, c = L.cols; const i = c.h_over_r.findIndex((v) => v < 1); L.seek(c.t_s[i]); });
  await page.$eval('#live', (e) => e.scrollIntoView());
  await page.screenshot({ path: `${shots}/live-emerged.png` });
});
await check('live views: the plots\' cursor follows the playback and a click on a plot moves it', async () => {
  const off = await page.evaluate(() => {
    const L = window.__liveViews;
    L.seek(40);
    return L.timePlots().map((u) => Math.abs(u.cursor.left - u.valToPos(40, 'x')));
  });
  assert(off.length >= 5 && off.every((d) => d < 1), `cursor offsets ${off}`);
  const u = await page.$('#plots .plot .u-over');
  const box = await u.boundingBox();
  await page.mouse.click(box.x + box.width * 0.25, box.y + box.height / 2);
  const t = await page.evaluate(() => window.__liveViews.t);
  assert(Math.abs(t - 20) < 2, `a click a quarter into an 80 s plot moved the playback to ${t} s`);
  // The keyboard: the play button and the time slider.
  await page.focus('#live-time');
  await page.keyboard.press('ArrowRight');
  const t2 = await page.evaluate(() => window.__liveViews.t);
  assert(t2 > t, `ArrowRight on the time slider: ${t} -> ${t2}`);
  await page.focus('#live-play');
  await page.keyboard.press('Enter');
  assert(await page.evaluate(() => window.__liveViews.playing), 'Enter on Play did not play');
  await page.keyboard.press('Enter');
  assert(!(await page.evaluate(() => window.__liveViews.playing)), 'Enter on Pause did not pause');
});
await check('compare runs: "compare with eq. 2.57 as printed" draws both runs on one plot and a table of differences', async () => {
  await page.click('text=Compare with eq. 2.57 as printed');
  await page.waitForFunction(() => !document.getElementById('compare-box').hidden && /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  // One legend entry for the kept run, drawn dashed, its lines the only dashed ones.
  const legend = await page.$eval('#plots .plot', (p) => ({ kept: p.querySelector('.legend-kept').textContent, dash: p.querySelector('.legend-kept line').getAttribute('stroke-dasharray'), own: p.querySelector('.chart').uplot.series.slice(1).filter((s) => !/kept run/.test(s.label) && s.dash).length }));
  assert(legend.kept.length > 0 && legend.dash && legend.own === 0, `the first plot's legend: ${JSON.stringify(legend)}`);
  const series = await page.$eval('#plots .plot', (p) => p.querySelector('.chart').uplot.series.length);
  assert(series >= 3, `${series} series`);
  const rows = await page.$$eval('#compare-table tbody tr', (r) => r.length);
  assert(rows >= 4, `${rows} rows of differences`);
  assert((await page.inputValue('#f-seakeeping-stern_motion')) === 'thesis_eq_2_57', 'the compare did not switch the formula');
  await page.screenshot({ path: `${shots}/compare.png` });
  await page.click('#unkeep');
});
await check('tick labels show every multiple of the step exactly (2.5 is not "3")', async () => {
  const got = await page.evaluate(async () => {
    const { tickDecimals } = await import('./js/plots.js');
    return [2.5, 25, 0.25, 0.05, 1, 0.1, 0.2, 5000, 1e-3].map(tickDecimals);
  });
  assert(JSON.stringify(got) === JSON.stringify([1, 0, 2, 2, 0, 1, 1, 0, 3]), `decimals ${got}`);
});
await check('a copied link goes away when the study or a value changes (it would share another scenario)', async () => {
  await page.selectOption('#preset', 'startup');
  await page.click('#share');
  assert(await page.isVisible('#share-url'), 'no link shown');
  await setField(page, 'sim.duration_s', 100);
  await page.waitForFunction(() => document.getElementById('share-url').hidden, null, { timeout: 5000 });
  await page.click('#share');
  assert(await page.isVisible('#share-url'), 'no link shown after the edit');
  await page.selectOption('#preset', 'turn-90');
  await page.waitForFunction(() => document.getElementById('share-url').hidden, null, { timeout: 5000 });
});
await check('Monte Carlo runs over workers and shows the Table 5.8 comparison and histograms', async () => {
  await page.selectOption('#preset', 'mc-arrival');
  await setField(page, 'monte_carlo.trials', 6);
  await page.click('#mc-run');
  await page.waitForFunction(() => /^Monte Carlo done|error/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 120000 });
  const st = await page.textContent('#status');
  assert(/^Monte Carlo done: 6 trials/.test(st), st);
  const text = await page.textContent('#plots');
  assert(/Table 5.8/.test(text) && /Rice/.test(text), 'no Table 5.8');
  assert((await page.$$eval('#plots .uplot', (els) => els.length)) >= 3, 'too few Monte Carlo plots');
  const cut = await axisLabelsCut(page);
  assert(!cut.length, `axis labels cut: ${cut.join(' | ')}`);
  // (Drawn when a trial ran one whole Welch segment: with 6 trials of this study none may.)
  assert(!/Periodogram/.test(text) || /Periodogram [^\n]*, \d+ (of 6 )?trials/.test(text), 'the periodogram does not say how many trials it averages');
  await page.screenshot({ path: `${shots}/monte-carlo.png` });
});
await check('Monte Carlo: a trial replays as a single run in the live views, and its seed reproduces it', async () => {
  const env = await page.evaluate(() => {
    for (const c of document.querySelectorAll('#plots .chart')) {
      const u = c.uplot, k = u && u.series.findIndex((x) => /^trial \d+$/.test(x.label || ''));
      if (k > 0) return { label: u.series[k].label, title: c.closest('.plot').querySelector('h3').textContent, data: Array.from(u.data[k]) };
    }
    return null;
  });
  assert(env, 'no trial drawn in the envelopes');
  const i = Number(env.label.split(' ')[1]);
  assert((await page.inputValue('#mc-trial')) === String(i), 'the replay field does not start at the drawn trial');
  await page.click('#mc-replay');
  await page.waitForFunction(() => /^Done \(/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 60000 });
  const st = await page.textContent('#status');
  assert(st.includes(`Monte Carlo trial ${i} (sea seed `), st);
  await page.waitForFunction(() => window.__liveViews.cols && !document.getElementById('live').hidden, null, { timeout: 20000 });
  const sig = /h\/R/.test(env.title) ? 'h_over_r' : 'im_power_pu';
  const diffs = await page.evaluate(([sig, data]) => { const c = window.__liveViews.cols[sig]; let n = 0; for (let j = 0; j < Math.min(data.length, c.length); j++) if (data[j] != null && data[j] !== c[j]) n++; return n; }, [sig, env.data]);
  assert(diffs === 0, `${diffs} values of ${sig} differ between the Monte Carlo trial and its replay`);
  await page.$eval('#live', (e) => e.scrollIntoView());
  await page.screenshot({ path: `${shots}/monte-carlo-replay.png` });
});
await check('Monte Carlo: a click on a histogram bar replays a trial whose value lies in that bar', async () => {
  await page.click('#mc-run');
  await page.waitForFunction(() => /^Monte Carlo done/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 120000 });
  // The arrival-time histogram: its first non-empty bar, and where it lies.
  const bar = await page.evaluate(() => {
    for (const c of document.querySelectorAll('#plots .chart')) {
      if (!/Arrival time/.test(c.closest('.plot').querySelector('h3').textContent)) continue;
      const u = c.uplot, x = u.data[0], n = u.data[1], i = n.findIndex((k) => k > 0), w = x[1] - x[0];
      const left = u.valToPos(x[i], 'x'), top = u.valToPos(n[i] / 2, 'y');
      c.scrollIntoView();
      return { i, lo: x[i] - w / 2, hi: x[i] + w / 2, left, top };
    }
    return null;
  });
  assert(bar && bar.i >= 0, 'no arrival histogram with a bar');
  // A real mouse click on the bar (the plot's overlay takes the pointer).
  const box = await page.evaluate(() => {
    for (const c of document.querySelectorAll('#plots .chart')) {
      if (!/Arrival time/.test(c.closest('.plot').querySelector('h3').textContent)) continue;
      const r = c.uplot.over.getBoundingClientRect();
      return { x: r.left, y: r.top };
    }
    return null;
  });
  const clicked = box !== null;
  if (clicked) {
    // 3 px into the bar: the first bar's centre can sit on the plot's very edge.
    await page.mouse.move(box.x + bar.left + 3, box.y + bar.top);
    await page.mouse.click(box.x + bar.left + 3, box.y + bar.top);
  }
  assert(clicked, 'could not click the arrival histogram');
  await page.waitForFunction(() => /^Done \(/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 60000 });
  const st = await page.textContent('#status');
  assert(/Monte Carlo trial \d+ \(sea seed /.test(st), st);
  // The replayed run's first surface effect (beta_T leaves 1) lies in the clicked bar.
  const first = await page.evaluate(() => { const c = window.__liveViews.cols; const i = c.beta_t.findIndex((b) => b < 1); return i < 0 ? null : c.t_s[i]; });
  assert(first !== null && first >= bar.lo - 0.11 && first < bar.hi + 0.11, `first surface effect at ${first} s, the bar is ${bar.lo} to ${bar.hi} s`);
});
await check('a running Monte Carlo study can be cancelled and the form survives', async () => {
  await setField(page, 'monte_carlo.trials', 400);
  await page.click('#mc-run');
  await page.waitForFunction(() => document.getElementById('progress').value > 0, null, { timeout: 60000 });
  await page.click('#cancel');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 5000 });
  await page.waitForFunction(() => !document.getElementById('mc-run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-monte_carlo-trials')) === '400', 'form lost its edit');
});
await check('100 Monte Carlo trials of head seas SS6 on 2 workers (speed report)', async () => {
  await page.selectOption('#preset', 'head-seas-ss6');
  await setField(page, 'monte_carlo.trials', 100);
  // The same study natively on 2 threads, on the same machine in the same run, before and after
  // each of the browser's (issue 17 asks for the ratio; machines differ 2-3x and the load
  // changes, so only a ratio measured side by side means anything).
  const native = fileURLToPath(new URL('../../target/release/aes-sim', import.meta.url));
  const nativeRun = () => {
    if (!existsSync(native)) return null;
    const t1 = Date.now();
    execFileSync(native, ['mc', 'preset:head-seas-ss6', '--trials', '100', '--threads', '2', '--quiet'], { stdio: ['ignore', 'ignore', 'inherit'] });
    return (Date.now() - t1) / 1000;
  };
  // Three browser runs, each between two native ones (the load on a shared machine drifts within
  // seconds): the ratio of the medians.
  const natives = [nativeRun()];
  const browsers = [];
  for (let round = 0; round < 3; round++) {
    const t0 = Date.now();
    await page.click('#mc-run');
    // The last round's "done" must go first (the button is disabled while a study runs).
    await page.waitForFunction(() => document.getElementById('mc-run').disabled || !/^Monte Carlo done/.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    await page.waitForFunction(() => /^Monte Carlo done/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 180000 });
    browsers.push((Date.now() - t0) / 1000);
    assert(/^Monte Carlo done/.test(await page.textContent('#status')), await page.textContent('#status'));
    natives.push(nativeRun());
  }
  const median = (v) => {
    const w = [...v].sort((a, b) => a - b);
    const m = Math.floor(w.length / 2);
    return w.length % 2 ? w[m] : 0.5 * (w[m - 1] + w[m]);
  };
  const browserS = median(browsers);
  // Every trial of this study runs its 80 s, so the periodogram averages all 100 and says so.
  const titles = await page.$$eval('#plots h3', (hs) => hs.map((h) => h.textContent));
  assert(titles.some((t) => /^Periodogram .*, 100 trials$/.test(t)), `no periodogram of 100 trials: ${titles.filter((t) => /Periodogram/.test(t))}`);
  console.log(`     ${await page.textContent('#status')} (wall ${browserS.toFixed(1)} s, ${await page.evaluate(() => navigator.hardwareConcurrency)} cores)`);
  if (natives[0] === null) {
    console.log(`     (no ${native}: browser/native not measured)`);
  } else {
    const nativeS = median(natives);
    const fmt = (v) => v.map((x) => x.toFixed(2)).join(', ');
    console.log(`     browser/native for 100 trials of head-seas-ss6 on 2 workers/threads, medians: ${browserS.toFixed(2)} s / ${nativeS.toFixed(2)} s = ${(browserS / nativeS).toFixed(2)} (browser ${fmt(browsers)} s; native around them ${fmt(natives)} s)`);
  }
});
await check('fuel study draws the Fig. 5-12 curves and the RAOs', async () => {
  await page.selectOption('#preset', 'fuel-regular-seas');
  await setField(page, 'sim.duration_s', 10);
  await runAndWait(page);
  await page.waitForFunction(() => [...document.querySelectorAll('#results h3')].filter((h) => /Fig. 5-12|RAOs/.test(h.textContent)).length >= 4, null, { timeout: 60000 });
  await page.screenshot({ path: `${shots}/fuel.png`, fullPage: true });
});
await check('stability tab shows poles and Bode plots, and follows the slider', async () => {
  await page.click('#tab-ips');
  await page.waitForFunction(() => document.getElementById('ips-status').textContent.startsWith('Stable'), null, { timeout: 10000 });
  const before = await page.textContent('#ips-steady');
  await page.fill('#ips-torque', '200');
  await page.dispatchEvent('#ips-torque', 'input');
  await page.waitForFunction((b) => document.getElementById('ips-steady').textContent !== b, before, { timeout: 10000 });
  assert((await page.$$eval('#ips-plots .uplot', (els) => els.length)) === 2, 'no Bode plots');
  assert((await page.$$eval('#ips-plots canvas.track', (els) => els.length)) === 1, 'no pole map');
  assert((await page.$$eval('#ips-poles tbody tr', (r) => r.length)) === 6, 'expected 6 poles above the torque threshold');
  // The steady state says which side of the torque threshold it is (eqs. 4.23-4.24).
  assert(/not active \(T\*\* below/.test(before) && /rotor-flux limitactive \(T\*\* above/.test(await page.textContent('#ips-steady')), 'the flux limit row does not follow the torque');
  // The plots' text alternative says where a line peaks (the resonance's frequency).
  const peak = await page.$eval('#ips-plots .plot details table tbody tr td:nth-child(4)', (td) => td.textContent);
  assert(/ at [\d.e+-]+ Hz$/.test(peak), `the Bode table's highest value does not say where: ${peak}`);
  await page.screenshot({ path: `${shots}/stability.png` });
});
await check('controller design tab: LTR closes the gap to the Kalman target as q grows; margins; the acceleration beside the PI loops', async () => {
  const p = await open(base);
  await p.click('#tab-design');
  await p.waitForFunction(() => document.getElementById('design-status').textContent.startsWith('Stable'), null, { timeout: 20000 });
  assert((await p.$$eval('#design-plots canvas.track', (e) => e.length)) === 1, 'no pole map');
  assert((await p.$$eval('#design-margins tbody tr', (r) => r.length)) === 2, 'margins of two inputs expected');
  // The largest gap between the loop's and the target's singular values [dB] below 5 rad/s.
  const gap = () => p.$eval('#design-plots .chart', (c) => {
    const d = c.uplot.data, n = (d.length - 1) / 2;
    let g = 0;
    for (let i = 0; i < d[0].length && d[0][i] < 5; i++) for (let k = 1; k <= n; k++) g = Math.max(g, Math.abs(d[k][i] - d[k + n][i]));
    return g;
  });
  const gapAt = async (log10q) => {
    const before = await p.textContent('#design-q-out');
    await p.fill('#design-q', String(log10q));
    await p.dispatchEvent('#design-q', 'input');
    await p.waitForFunction((b) => document.getElementById('design-q-out').textContent !== b, before, { timeout: 10000 });
    await p.waitForFunction((q) => document.querySelector('#design-plots .chart')?.uplot && document.getElementById('design-status').textContent.startsWith('Stable'), log10q, { timeout: 20000 });
    await p.waitForTimeout(300);
    return gap();
  };
  const g1 = await gapAt(1), g2 = await gapAt(2), g3 = await gapAt(3);
  console.log(`     loop-to-target gap below 5 rad/s: ${g1.toFixed(2)}, ${g2.toFixed(2)}, ${g3.toFixed(2)} dB at q = 10, 100, 1000`);
  assert(g2 < g1 && g3 < g2, `the gap does not shrink: ${g1} ${g2} ${g3}`);
  await p.click('#design-run');
  await p.waitForFunction(() => !document.getElementById('compare-box').hidden && /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  assert((await p.$eval('#f-controllers-design', (e) => e.value)) === 'lqg_ltr', 'the second run is not the LQG/LTR one');
  await p.screenshot({ path: `${shots}/design-compare.png` });
  await p.close();
});
await check('extreme values never freeze the stability tab or the simulator (clean errors, then recovery)', async () => {
  // Stability tab: a field voltage of 1e300 on the generator side gets a named error at once.
  await page.click('#tab-ips');
  await page.selectOption('#ips-side', 'generator');
  await page.dispatchEvent('#ips-side', 'change');
  await page.waitForFunction(() => /^Stable|^UNSTABLE/.test(document.getElementById('ips-status').textContent), null, { timeout: 10000 });
  const t0 = Date.now();
  await page.fill('#ips-vfd', '1e300');
  await page.dispatchEvent('#ips-vfd', 'input');
  await page.dispatchEvent('#ips-vfd', 'change');
  await page.waitForFunction(() => document.getElementById('ips-status').className === 'error', null, { timeout: 10000 });
  const msg = await page.textContent('#ips-status');
  assert(/v_fd|field voltage/i.test(msg), `stability error does not name the input: ${msg}`);
  // The box at fault is marked, and the last results are dimmed as not following the controls.
  assert(await page.$eval('#ips-vfd', (e) => e.getAttribute('aria-invalid') === 'true'), 'the field voltage box is not marked invalid');
  assert(await page.$eval('#ips-plots', (e) => e.classList.contains('stale')), 'the old plots are not marked as stale');
  await page.fill('#ips-vfd', '28.5');
  await page.dispatchEvent('#ips-vfd', 'input');
  await page.dispatchEvent('#ips-vfd', 'change');
  await page.waitForFunction(() => /^Stable|^UNSTABLE/.test(document.getElementById('ips-status').textContent), null, { timeout: 10000 });
  assert(await page.$eval('#ips-vfd', (e) => !e.hasAttribute('aria-invalid')), 'the field voltage box is still marked invalid');
  assert(await page.$eval('#ips-plots', (e) => !e.classList.contains('stale')), 'the plots are still marked as stale');
  // The Bode phase is unwrapped (no jump of 180 deg or more between neighbours), and an unstable
  // operating point (closed loop, 5 A, a 200 V field) is named on the pole map.
  const jumps = await page.$$eval('#ips-plots .chart', (cs) => cs.filter((c) => c.uplot && /phase/.test(c.closest('.plot').querySelector('h3').textContent))
    .flatMap((c) => { const d = c.uplot.data[1]; return d.slice(1).map((v, i) => Math.abs(v - d[i])).filter((x) => x >= 180); }));
  assert(!jumps.length, `phase jumps of ${jumps}`);
  await page.selectOption('#ips-loop', 'closed');
  await page.dispatchEvent('#ips-loop', 'input');
  await page.fill('#ips-load', '5');
  await page.dispatchEvent('#ips-load', 'input');
  await page.fill('#ips-vfd', '200');
  await page.dispatchEvent('#ips-vfd', 'input');
  await page.waitForFunction(() => /^UNSTABLE/.test(document.getElementById('ips-status').textContent), null, { timeout: 10000 });
  const map = await page.$eval('#ips-plots canvas[role="img"]', (c) => c.getAttribute('aria-label'));
  assert(/unstable: 1\.\d+[+-]/.test(map), `the pole map does not name the unstable poles: ${map}`);
  await page.screenshot({ path: `${shots}/stability-unstable.png` });
  for (const [id, v] of [['#ips-vfd', '28.5'], ['#ips-load', '45']]) { await page.fill(id, v); await page.dispatchEvent(id, 'input'); }
  await page.selectOption('#ips-loop', 'open');
  await page.dispatchEvent('#ips-loop', 'input');
  await page.waitForFunction(() => /^Stable|^UNSTABLE/.test(document.getElementById('ips-status').textContent), null, { timeout: 10000 });
  await page.selectOption('#ips-side', 'motor');
  await page.dispatchEvent('#ips-side', 'change');
  // Simulator: 1e300 s of simulated time is refused at the field, Run waits, the page answers.
  await page.click('#tab-sim');
  await setField(page, 'sim.duration_s', '1e300');
  await page.waitForFunction(() => document.getElementById('f-sim-duration_s').getAttribute('aria-invalid') === 'true', null, { timeout: 10000 });
  assert(await page.$eval('#run', (b) => b.disabled), 'Run is enabled with 1e300 s');
  await setField(page, 'sim.duration_s', 60);
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 10000 });
  console.log(`     extreme values answered in ${Date.now() - t0} ms`);
});
await check('keyboard: the Run button is reachable and labelled inputs exist', async () => {
  const unlabelled = await page.$$eval('input, select, textarea', (els) => els.filter((e) => !e.labels?.length && !e.getAttribute('aria-label') && !e.hidden).map((e) => e.id));
  assert(unlabelled.length === 0, `unlabelled: ${unlabelled}`);
});
// The page as a class meets it: a laptop, a projector and a phone. Nothing overflows the viewport
// width, no two plots overlap, plots re-fit after a resize, axe-core finds no serious or critical
// violation on either tab, every axis has a unit, Back and Forward restore the study.
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];
const wide = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
const layout = (p) => p.evaluate(() => {
  const W = document.documentElement.clientWidth;
  const clipped = (e) => { for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) if (getComputedStyle(a).overflowX !== 'visible') return true; return false; };
  const over = [...document.querySelectorAll('body *')].filter((e) => {
    if (!e.getClientRects().length || e.classList.contains('skip')) return false;
    const r = e.getBoundingClientRect();
    return r.width > 0 && r.right > W + 1 && !clipped(e);
  }).map((e) => `${e.tagName}#${e.id}.${e.className}`).slice(0, 5);
  const plots = [...document.querySelectorAll('.plot')].filter((e) => e.getClientRects().length);
  const boxes = plots.map((e) => e.getBoundingClientRect());
  const overlaps = [];
  for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) {
    const a = boxes[i], b = boxes[j];
    if (a.left < b.right - 1 && b.left < a.right - 1 && a.top < b.bottom - 1 && b.top < a.bottom - 1) overlaps.push(`${i}/${j}`);
  }
  const unfit = plots.filter((p) => { const c = p.querySelector('.uplot, canvas.track'); return c && c.getBoundingClientRect().right > p.getBoundingClientRect().right + 1; }).length;
  return { W, scroll: document.documentElement.scrollWidth, over, overlaps, unfit, plots: plots.length };
});
const assertLayout = (l, where) => {
  assert(l.scroll <= l.W, `${where}: page is ${l.scroll} px wide in a ${l.W} px viewport`);
  assert(!l.over.length, `${where}: overflowing ${l.over.join(', ')}`);
  assert(!l.overlaps.length, `${where}: plots overlap (${l.overlaps.join(', ')})`);
  assert(!l.unfit, `${where}: ${l.unfit} plot(s) wider than their panel`);
};
// Every axis of every drawn uPlot names a unit in brackets.
const axesWithoutUnit = (p) => p.evaluate(() => [...document.querySelectorAll('.chart')].filter((c) => c.getClientRects().length && c.uplot)
  .flatMap((c) => c.uplot.axes.filter((a) => a.show !== false && !/\[[^\]]+\]/.test(a.label || '')).map((a) => `${c.closest('.plot').querySelector('h3')?.textContent}: "${a.label}"`)));
const axeSerious = (p) => axeFindings(p);
for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: no horizontal overflow, no overlapping plots, units on every axis, no serious axe violation`, async () => {
    await wide.setDefaultTimeout(30000);
    const p = await open(base + '#v=1&preset=head-seas-ss6', wide);
    await p.setViewportSize({ width: w, height: h });
    assertLayout(await layout(p), 'before a run');
    await runAndWait(p);
    await p.waitForTimeout(300);
    assertLayout(await layout(p), 'head seas');
    await p.screenshot({ path: `${shots}/size-${w}x${h}.png` });
    await p.$eval('#live', (e) => e.scrollIntoView());
    await p.waitForTimeout(100);
    await p.screenshot({ path: `${shots}/live-${w}x${h}.png` });
    await p.click('#more-plots-box summary');
    await p.waitForFunction(() => document.querySelectorAll('#more-plots .uplot').length >= 4, null, { timeout: 30000 });
    await p.waitForTimeout(300);
    assertLayout(await layout(p), 'more plots open');
    const noUnit = await axesWithoutUnit(p);
    assert(!noUnit.length, `axes without a unit: ${noUnit.join(' | ')}`);
    const cut = await axisLabelsCut(p);
    assert(!cut.length, `axis labels cut: ${cut.join(' | ')}`);
    const v1 = await axeSerious(p);
    assert(!v1.length, `simulator tab: ${v1.join(' | ')}`);
    await p.click('#tab-ips');
    await p.waitForFunction(() => document.querySelectorAll('#ips-plots .uplot').length === 2, null, { timeout: 10000 });
    await p.waitForTimeout(300);
    assertLayout(await layout(p), 'stability tab');
    assert(!(await axesWithoutUnit(p)).length, 'stability axes without a unit');
    const v2 = await axeSerious(p);
    assert(!v2.length, `stability tab: ${v2.join(' | ')}`);
    await p.screenshot({ path: `${shots}/stability-${w}x${h}.png` });
    await p.click('#tab-design');
    await p.waitForFunction(() => document.querySelectorAll('#design-plots .uplot').length === 2, null, { timeout: 20000 });
    await p.waitForTimeout(300);
    assertLayout(await layout(p), 'design tab');
    assert(!(await axesWithoutUnit(p)).length, 'design axes without a unit');
    const v3 = await axeSerious(p);
    assert(!v3.length, `design tab: ${v3.join(' | ')}`);
    await p.screenshot({ path: `${shots}/design-${w}x${h}.png`, fullPage: w < 500 });
    await p.close();
  });
}
await check('presentation mode: form folded away, wider plots, no overflow, and back', async () => {
  await page.click('#tab-sim');
  const widthBefore = await page.$eval('#plots .uplot', (e) => e.getBoundingClientRect().width);
  await page.click('#present');
  await page.waitForFunction(() => document.body.classList.contains('presenting'), null, { timeout: 5000 });
  await page.waitForTimeout(400);
  assert(await page.$eval('#present', (b) => b.getAttribute('aria-pressed') === 'true'), 'aria-pressed not set');
  // The study picker and the Run buttons stay (a teacher switches studies); the form folds away.
  assert(!(await page.isVisible('#all-fields')), 'the full form is still shown');
  assert(await page.isVisible('#preset') && await page.isVisible('#run'), 'study picker or Run hidden');
  const widthAfter = await page.$eval('#plots .uplot', (e) => e.getBoundingClientRect().width);
  assert(widthAfter > widthBefore, `plots did not grow: ${widthBefore} -> ${widthAfter}`);
  // Readable from the back: the axes' type grows to 16 px; the comparison stays at hand.
  const axisPx = () => page.$$eval('#plots .chart', (cs) => cs.filter((c) => c.uplot).flatMap((c) => c.uplot.axes.map((a) => a.font[2])));
  const big = await axisPx();
  assert(big.length && big.every((px) => px === 16), `axis type while presenting: ${big}`);
  assert(await page.isVisible('#keep'), 'Keep this run is hidden while presenting');
  if (await page.$$eval('#compare-with button', (b) => b.length)) assert(await page.isVisible('#compare-with'), 'the compare buttons are hidden while presenting');
  const cut = await axisLabelsCut(page);
  assert(!cut.length, `axis labels cut while presenting: ${cut.join(' | ')}`);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert(overflow <= 1, `horizontal overflow ${overflow} px`);
  await page.screenshot({ path: `${shots}/presentation.png` });
  await page.click('#present');
  await page.waitForFunction(() => !document.body.classList.contains('presenting'), null, { timeout: 5000 });
  assert(await page.isVisible('#all-fields'), 'the form did not come back');
  const desk = await axisPx();
  assert(desk.every((px) => px === 12), `axis type after presenting: ${desk}`);
});
await check('a resize re-fits the plots to their panels', async () => {
  const p = await open(base + '#v=1&preset=startup', wide);
  await p.setViewportSize({ width: 1366, height: 768 });
  await runAndWait(p);
  const fit = () => p.$eval('#plots .chart', (c) => [c.uplot.width, Math.floor(c.getBoundingClientRect().width)]);
  const [w0, c0] = await fit();
  assert(Math.abs(w0 - c0) <= 2, `plot ${w0} px in a ${c0} px panel`);
  await p.setViewportSize({ width: 1920, height: 1080 });
  await p.waitForTimeout(400);
  const [w1, c1] = await fit();
  assert(w1 !== w0 && Math.abs(w1 - c1) <= 2, `after the resize: plot ${w1} px (was ${w0}) in a ${c1} px panel`);
  await p.close();
});
await check('the tabs follow the ARIA pattern: arrow keys move between them', async () => {
  const p = await open(base, wide);
  await p.focus('#tab-sim');
  await p.keyboard.press('ArrowRight');
  assert((await p.getAttribute('#tab-design', 'aria-selected')) === 'true', 'ArrowRight did not select the design tab');
  assert(await p.evaluate(() => document.activeElement.id === 'tab-design'), 'focus did not follow');
  await p.keyboard.press('End');
  assert((await p.getAttribute('#tab-operability', 'aria-selected')) === 'true', 'End did not select the last tab (operability)');
  // "Skip to the results" goes to the shown tab's results.
  assert((await p.getAttribute('a.skip', 'href')) === '#op-results', 'the skip link does not lead to the operability results');
  await p.keyboard.press('ArrowLeft');
  assert((await p.getAttribute('#tab-ips', 'aria-selected')) === 'true', 'ArrowLeft did not select the stability tab');
  assert((await p.getAttribute('a.skip', 'href')) === '#ips-plots', 'the skip link does not lead to the stability results');
  await p.keyboard.press('Home');
  assert((await p.getAttribute('a.skip', 'href')) === '#results', 'the skip link did not come back');
  assert((await p.getAttribute('#tab-sim', 'aria-selected')) === 'true', 'Home did not come back');
  await p.close();
});
await check('the address follows the study; Back and Forward restore it', async () => {
  const p = await open(base, wide);
  await p.selectOption('#preset', 'turn-90');
  await p.selectOption('#preset', 'ac-braking');
  assert(p.url().includes('preset=ac-braking'), p.url());
  await p.goBack();
  await p.waitForFunction(() => document.getElementById('preset').value === 'turn-90', null, { timeout: 5000 });
  await p.goForward();
  await p.waitForFunction(() => document.getElementById('preset').value === 'ac-braking', null, { timeout: 5000 });
  await p.close();
});
await check('a link of version 1 (time step and method under sim, as the page wrote them before stepping) opens with them in stepping', async () => {
  // Recorded from the page before the change: head seas with Duration 20, Time step 0.0025 and RK4.
  const p = await open(`${base}#v=1&preset=head-seas-ss6&d=eyJzaW0iOnsiZHVyYXRpb25fcyI6MjAsImR0X3MiOjAuMDAyNSwiaW50ZWdyYXRvciI6InJrNCJ9fQ`, wide);
  await p.waitForFunction(() => document.getElementById('f-stepping-dt_s')?.value === '0.0025', null, { timeout: 10000 });
  assert((await p.inputValue('#f-stepping-integrator')) === 'rk4', 'integrator not restored');
  assert((await p.inputValue('#f-sim-duration_s')) === '20', 'duration not restored');
  const st = await runAndWait(p);
  assert(st.startsWith('Done'), st);
  await p.close();
});
await check('a linked page marks the fields the link changed', async () => {
  const d = Buffer.from(JSON.stringify({ ship: { drag_coeff: 0.004 } })).toString('base64url');
  const p = await open(`${base}#v=1&preset=startup&d=${d}`, wide);
  await p.waitForFunction(() => document.querySelector('#f-ship-drag_coeff-field.linked'), null, { timeout: 5000 });
  assert((await p.$$eval('.field.linked', (e) => e.length)) === 1, 'more than one field marked');
  await p.close();
});
await check('a link with a place in the live views opens the run there, and Copy link keeps the place', async () => {
  const p = await open(`${base}#v=1&preset=head-seas-ss6&at=10.5&speed=10`, wide);
  await p.waitForFunction(() => window.__liveViews && window.__liveViews.cols && !window.__liveViews.streaming && Math.abs(window.__liveViews.t - 10.5) < 1e-6, null, { timeout: 60000 });
  assert((await p.inputValue('#live-speed')) === '10', `speed ${await p.inputValue('#live-speed')}`);
  await p.evaluate(() => window.__liveViews.seek(20));
  await p.click('#share');
  const url = await p.inputValue('#share-url');
  assert(/&at=20&speed=10$/.test(url), url);
  await p.close();
});
await check('live views respect prefers-reduced-motion: the power arrows hold still while playing', async () => {
  const calm = await browser.newContext({ viewport: { width: 1366, height: 768 }, reducedMotion: 'reduce' });
  const p = await open(`${base}#v=1&preset=startup&at=30&speed=10`, calm);
  await p.waitForFunction(() => window.__liveViews && window.__liveViews.cols && !window.__liveViews.streaming && window.__liveViews.t === 30, null, { timeout: 60000 });
  assert(/reduced motion/.test(await p.textContent('#live')), 'no word about reduced motion');
  await p.click('#live-play');
  await p.waitForTimeout(800);
  const r = await p.evaluate(() => ({ t: window.__liveViews.t, dash: window.__liveViews.dashPhase }));
  assert(r.t > 30 && r.dash === 0, `t ${r.t}, dash phase ${r.dash}`);
  await p.close();
  await calm.close();
});
// The hull (issue 15): picker, body plan, profile, hydrostatics, custom offsets through the Rust
// parser, links, and the panel at the three sizes. A context of its own (its own stored edits).
const hullCtx = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true, acceptDownloads: true });
const hullRow = (p, start) => p.$$eval('#hull-table tbody tr', (rows, s) => {
  const r = rows.find((x) => x.cells[0].textContent.startsWith(s));
  return r ? Number(r.cells[1].textContent.replace(/,/g, '')) : NaN;
}, start);
const hullDrawn = (p, name) => p.waitForFunction((n) => window.__hullPanel && window.__hullPanel.drawn && window.__hullPanel.drawn.name.includes(n), name, { timeout: 20000 });
// Pixels of a canvas that are not white (a drawing, not an empty box).
const inked = (p, sel) => p.$eval(sel, (c) => {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200)) n++;
  return n;
});
// The Wigley formula sampled at a fifth of the embedded scale (L 20 m, B 2 m, T 1.25 m), vertical
// sides up to 2 m: a small custom hull in the long format, stations 1..9 (no empty end stations).
const L = 20, B = 2, T = 1.25;
const wigleyCsv = ['# Wigley hull sampled by the e2e test', 'station_index,x_m,z_m,half_breadth_m'];
for (let i = 1; i <= 9; i++) {
  const x = (i * L) / 10, xi = (2 * x) / L - 1;
  for (let j = 0; j <= 8; j++) {
    const z = (j * 2) / 8, d = Math.max(0, T - z) / T;
    wigleyCsv.push(`${i},${x},${z},${((B / 2) * (1 - xi * xi) * (1 - d * d)).toFixed(4)}`);
  }
}
const brokenCsv = 'station_index,x_m,z_m,half_breadth_m\n1,2,0,0\n1,2,1,0.5\n1,2,oops,0.7\n';
const file = (name, text) => ({ name, mimeType: 'text/csv', buffer: Buffer.from(text) });
const hullPage = await open(base + '#v=1&preset=head-seas-ss6', hullCtx);
await check('hull: picking the Wigley draws its body plan and profile and gives its hydrostatics (volume = (4/9) L B T x 0.9945)', async () => {
  const p = hullPage;
  await hullDrawn(p, 'DTMB 5415');
  assert((await p.$$eval('#hull option', (o) => o.map((x) => x.value))).join() === 'dtmb5415,wigley,custom', 'hull choices');
  await p.selectOption('#hull', 'wigley');
  await hullDrawn(p, 'Wigley');
  const [l, b, t, v] = [await hullRow(p, 'Length'), await hullRow(p, 'Beam'), await hullRow(p, 'Draft'), await hullRow(p, 'Displaced volume')];
  const want = (4 / 9) * l * b * t * 0.9945;
  assert(Math.abs(v - want) / want < 0.01, `volume ${v} m^3, want about ${want.toFixed(0)} (L ${l}, B ${b}, T ${t})`);
  assert(Math.abs(v - 2763) < 30, `volume ${v} m^3 at T = ${t} m`);
  const d = await p.evaluate(() => window.__hullPanel.drawn);
  assert(d.bodyPlan.aft >= 5 && d.bodyPlan.fore >= 5, `body plan sections: ${JSON.stringify(d.bodyPlan)}`);
  for (const c of ['#hull-bodyplan', '#hull-profile']) {
    assert((await inked(p, c)) > 2000, `${c} is (nearly) empty`);
    assert((await p.getAttribute(c, 'role')) === 'img' && /Wigley/.test(await p.getAttribute(c, 'aria-label')), `${c}: role or label`);
  }
  const units = await p.$$eval('#hull-table tbody tr', (rows) => rows.filter((r) => !r.cells[2].textContent && !/none/.test(r.cells[1].textContent)).map((r) => r.cells[0].textContent));
  assert(!units.length, `rows without a unit: ${units}`);
  // The hub height is the study's knob; h0 follows the hull's draft.
  const h0 = await p.textContent('#f-ship-hull-hub_above_base_m-derived');
  assert(/h0 = 6\.25 - 2\.65 = 3\.60 m/.test(h0), `h0 line: ${h0}`);
});
await check('hull: a share link with the Wigley round-trips (by name)', async () => {
  const p = hullPage;
  await p.click('#share');
  const url = await p.inputValue('#share-url');
  const d = JSON.parse(Buffer.from(new URL(url).hash.match(/&d=([^&]+)/)[1], 'base64url').toString());
  assert(d.ship.hull.name === 'wigley' && !d.ship.hull.offsets_csv && url.length < 300, `link: ${url}`);
  const other = await open(url, hullCtx);
  await hullDrawn(other, 'Wigley');
  assert((await other.inputValue('#hull')) === 'wigley', 'hull not restored');
  await other.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 90000 });
  await other.click('#more-plots-box summary');
  await other.waitForFunction(() => [...document.querySelectorAll('#more-plots h3')].filter((h) => /RAOs/.test(h.textContent)).length >= 2, null, { timeout: 60000 });
  const titles = await other.$$eval('#more-plots h3', (hs) => hs.map((h) => h.textContent).filter((t) => /RAOs/.test(t)));
  assert(titles.every((t) => t.startsWith('Wigley RAOs')), `RAO plots: ${titles.join(' | ')}`);
  await other.close();
});
await check('hull: a custom offsets file loads through the Rust parser; it asks for draft and KG, then draws', async () => {
  const p = hullPage;
  await p.setInputFiles('#f-ship-hull-offsets_csv', file('small-wigley.csv', wigleyCsv.join('\n')));
  await p.waitForFunction(() => document.getElementById('f-ship-hull-draft_m').getAttribute('aria-invalid') === 'true', null, { timeout: 10000 });
  assert((await p.inputValue('#hull')) === 'custom', 'the hull select does not show the custom hull');
  assert(/draft/.test(await p.textContent('#f-ship-hull-draft_m-err')), 'no error at the draft');
  await setField(p, 'ship.hull.draft_m', T);
  await setField(p, 'ship.hull.kg_m', 1.0);
  await setField(p, 'ship.hull.hub_above_base_m', 0.2);
  await hullDrawn(p, 'small-wigley.csv');
  const [l, v] = [await hullRow(p, 'Length'), await hullRow(p, 'Displaced volume')];
  assert(Math.abs(l - 16) < 1e-6, `Lpp ${l} (stations from 2 to 18 m)`);
  assert(v > 15 && v < 25, `volume ${v} m^3`);
  assert(!(await p.$eval('#run', (b) => b.disabled)), 'Run is disabled with a complete custom hull');
});
await check('hull: a broken offsets file is refused with its line number, and the hull stays', async () => {
  const p = hullPage;
  const before = await p.evaluate(() => JSON.stringify(window.__hullPanel.sheet));
  await p.setInputFiles('#f-ship-hull-offsets_csv', file('broken.csv', brokenCsv));
  await p.waitForFunction(() => document.getElementById('f-ship-hull-offsets_csv-err').textContent, null, { timeout: 10000 });
  const err = await p.textContent('#f-ship-hull-offsets_csv-err');
  assert(/^broken\.csv: line 4/.test(err) && /oops/.test(err), `error: ${err}`);
  assert((await p.getAttribute('#f-ship-hull-offsets_csv', 'aria-invalid')) === 'true', 'file field not marked');
  await p.waitForTimeout(300);
  assert((await p.evaluate(() => JSON.stringify(window.__hullPanel.sheet))) === before, 'the hull changed');
  assert((await p.inputValue('#f-ship-hull-draft_m')) === String(T), 'the loading was lost');
  await p.$eval('#hull-pick', (e) => e.scrollIntoView());
  await p.screenshot({ path: `${shots}/hull-file-error.png` });
});
await check('hull: a custom hull too large for a link is offered as a scenario file, which loads back', async () => {
  const p = hullPage;
  const big = readFileSync(fileURLToPath(new URL('../../core/data/dtmb5415_offsets.csv', import.meta.url)), 'utf8');
  // Dropped on the page (a synthetic drop with the file in its DataTransfer).
  await p.evaluate((text) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], 'dtmb5415-copy.csv', { type: 'text/csv' }));
    document.getElementById('results').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, big);
  await p.waitForFunction(() => /dtmb5415-copy/.test(document.getElementById('hull').selectedOptions[0].text), null, { timeout: 10000 });
  await setField(p, 'ship.hull.draft_m', 6.15);
  await setField(p, 'ship.hull.kg_m', 7.555);
  await hullDrawn(p, 'dtmb5415-copy.csv');
  await p.click('#share');
  assert(!(await p.$eval('#share-too-long', (e) => e.hidden)), 'no "too large" message');
  assert(await p.$eval('#share-url', (e) => e.hidden), 'a link was offered anyway');
  assert(/characters/.test(await p.textContent('#share-too-long-text')), 'message');
  const [dl] = await Promise.all([p.waitForEvent('download'), p.click('#share-file')]);
  const text = readFileSync(await dl.path(), 'utf8');
  const sc = JSON.parse(text);
  assert(sc.ship.hull.name === 'custom' && sc.ship.hull.offsets_csv.length > 20000, 'the file lacks the hull');
  await p.selectOption('#hull', 'dtmb5415');
  await hullDrawn(p, 'DTMB 5415');
  await p.setInputFiles('#f-ship-hull-offsets_csv', { name: 'scenario.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await p.waitForFunction(() => document.getElementById('hull').value === 'custom', null, { timeout: 10000 });
  await hullDrawn(p, 'custom hull');
  assert(Math.abs((await hullRow(p, 'Draft')) - 6.15) < 1e-9, 'draft of the loaded scenario');
});
for (const [w, h] of SIZES) {
  await check(`hull panel at ${w}x${h}: no overflow or overlap, axes in metres, no serious axe violation (screenshot)`, async () => {
    const p = await open(base + '#v=1&preset=head-seas-ss6', hullCtx);
    await p.setViewportSize({ width: w, height: h });
    await p.selectOption('#hull', 'wigley');
    await hullDrawn(p, 'Wigley');
    await p.waitForTimeout(300);
    assertLayout(await layout(p), 'hull panel');
    const d = await p.evaluate(() => window.__hullPanel.drawn);
    assert(d.bodyPlan.scale_px_per_m > 0 && d.profile.propeller.radius_px > 2, JSON.stringify(d));
    const v = await axeSerious(p);
    assert(!v.length, `hull panel: ${v.join(' | ')}`);
    await p.$eval('#hull-box', (e) => e.scrollIntoView());
    await p.screenshot({ path: `${shots}/hull-${w}x${h}.png` });
    await p.selectOption('#hull', 'dtmb5415');
    await hullDrawn(p, 'DTMB 5415');
    await p.waitForTimeout(200);
    await p.$eval('#hull-box', (e) => e.scrollIntoView());
    await p.screenshot({ path: `${shots}/hull-5415-${w}x${h}.png`, fullPage: w < 500 });
    await p.close();
  });
}
await check('every study at 1920x1080 (screenshots)', async () => {
  const p = await open(base, wide);
  await p.setViewportSize({ width: 1920, height: 1080 });
  const names = await p.$$eval('#preset option', (o) => o.map((x) => x.value));
  for (const name of names) {
    await p.selectOption('#preset', name);
    const st = await runAndWait(p);
    assert(st.startsWith('Done'), `${name}: ${st}`);
    await p.waitForTimeout(200);
    await p.screenshot({ path: `${shots}/study-${name}.png` });
  }
  await p.close();
});
await finish(browser, consoleErrors);
