// Browser test of the lessons (issue 30): every lesson opens from its link at the three sizes, its
// controls, plot and live view fit one screen (the plot right under the controls on a phone),
// every control reruns and changes the plot, the time from a control to the new plot is measured
// against the native run of the same scenario, axe-core finds no serious violation, and a link with
// non-default values opens to the same numbers.
// Usage: node tests/e2e/lessons.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, writeFileSync, existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, axeFindings, checker, launch, openPage } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];

const done = (p) => p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent) && !document.getElementById('run').disabled, null, { timeout: 60000 });
const firstSeries = (p) => p.$eval('#plots .chart', (c) => JSON.stringify(c.uplot.data.slice(1)));
const box = (p, sel) => p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { top: r.top + window.scrollY, bottom: r.bottom + window.scrollY, h: r.height }; });
// The live view the lesson shows (the one figure of #live that is drawn).
const liveBox = (p) => p.$$eval('#live figure.live-view', (fs) => fs.filter((f) => f.getClientRects().length).map((f) => { const r = f.getBoundingClientRect(); return { top: r.top + window.scrollY, bottom: r.bottom + window.scrollY }; }));
// Moves a control to another value as a person does (a slider released, a toggle switched).
async function move(p, sel) {
  return p.$eval(sel, (e) => {
    if (e.tagName === 'SELECT') e.selectedIndex = (e.selectedIndex + 1) % e.options.length;
    else {
      const lo = Number(e.min), hi = Number(e.max), st = Number(e.step), v = Number(e.value);
      const up = v + 2 * st <= hi ? v + 2 * st : v - 2 * st;
      e.value = String(Math.min(hi, Math.max(lo, up)));
      e.dispatchEvent(new Event('input'));
    }
    e.dispatchEvent(new Event('change'));
    return e.value;
  });
}

for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: every lesson opens from its link and fits one screen${w === 1366 ? ', every control reruns and changes the plot' : ''} (screenshots)`, async () => {
    const ctx = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true });
    const p = await openPage(ctx, `${base}#lessons`, base, errors);
    const LESSONS = (await p.$$eval('.lesson-list a', (a) => a.map((x) => x.getAttribute('href').slice('#lesson='.length)))).map((name) => ({ name }));
    assert(LESSONS.length >= 6, `the index lists ${LESSONS.length} lessons`);
    if (w === 1366) await p.screenshot({ path: `${shots}/lessons-index.png` });
    let where = 'the index';
    try {
    for (const lesson of LESSONS) {
      where = `${lesson.name}: opening`;
      await p.goto(`${base}#lesson=${lesson.name}`);
      await p.waitForFunction(() => document.getElementById('lesson-q'), null, { timeout: 30000 });
      assert(await p.$eval('#lesson-controls input, #lesson-controls select', (e) => e.disabled), `${lesson.name}: a control acts before the prediction`);
      where = `${lesson.name}: first run`;
      await p.click('#lesson-a0');
      await p.waitForFunction(() => document.querySelector('#lesson-observe p'), null, { timeout: 60000 });
      await done(p);
      await p.waitForTimeout(250);
      assert(/\d/.test(await p.textContent('#lesson-observe')), `${lesson.name}: no explanation with numbers`);
      const ctl = await box(p, '#lesson-box'), plot = await box(p, '#plots .plot'), views = await liveBox(p);
      assert(views.length === 1, `${lesson.name}: ${views.length} live views shown`);
      const n = await p.$$eval('#lesson-controls [data-path]', (e) => e.length);
      assert(n >= 2 && n <= 4, `${lesson.name}: ${n} controls`);
      if (w >= 1366) {
        const bottom = Math.max(ctl.bottom, plot.bottom, views[0].bottom);
        assert(bottom <= h, `${lesson.name} at ${w}x${h}: controls, plot and live view end at ${Math.round(bottom)} px`);
      } else {
        const controls = await box(p, '#lesson-controls');
        assert(plot.top > controls.bottom && plot.top - ctl.bottom < 60 && plot.top < views[0].top, `${lesson.name} on the phone: controls end ${Math.round(ctl.bottom)}, plot at ${Math.round(plot.top)}, live view at ${Math.round(views[0].top)}`);
      }
      if (w !== 1920) await p.screenshot({ path: `${shots}/lesson-${lesson.name}-${w}x${h}.png`, fullPage: w < 600 });
      const v = await axeFindings(p);
      assert(!v.length, `${lesson.name}: ${v.join(' | ')}`);
      // Each control reruns and the plot changes; the earlier run stays, faint (at the laptop's
      // size: the other two check the layout).
      const ids = w === 1366 ? await p.$$eval('#lesson-controls [data-path]', (e) => e.map((x) => `#${x.id}`)) : [];
      for (const id of ids) {
        where = `${lesson.name}: moving ${id}`;
        const before = await firstSeries(p);
        await move(p, id);
        await p.waitForFunction((b) => { const c = document.querySelector('#plots .chart'); return c && c.uplot && JSON.stringify(c.uplot.data.slice(1)) !== b && !document.getElementById('run').disabled; }, before, { timeout: 60000 });
        await done(p);
        const legend = await p.$$eval('#plots .u-legend .u-label', (l) => l.map((x) => x.textContent).join('|'));
        assert(/run before/.test(legend), `${lesson.name} ${id}: the run before is not drawn (${legend.slice(0, 120)})`);
      }
    }
    } catch (e) { throw new Error(`${where}: ${e.message}`); }
    await ctx.close();
  });
}

await check('a lesson in presentation mode at 1920x1080 keeps its controls, plots and live view on one screen (screenshot)', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1920, height: 1080 }, bypassCSP: true });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await p.click('#lesson-a1');
  await done(p);
  await p.click('#present');
  await p.waitForTimeout(800);
  const ctl = await box(p, '#lesson-box'), plots = await p.$$eval('#plots .plot', (ps) => ps.map((x) => x.getBoundingClientRect().bottom + window.scrollY)), views = await liveBox(p);
  const bottom = Math.max(ctl.bottom, ...plots, views[0].bottom);
  assert(bottom <= 1080, `presenting: controls, plots and live view end at ${Math.round(bottom)} px`);
  await p.screenshot({ path: `${shots}/lesson-presenting-1920x1080.png` });
  const v = await axeFindings(p);
  assert(!v.length, v.join(' | '));
  await ctx.close();
});

await check('on a phone a rerun leaves the screen where the hand is: the slider being moved does not scroll away (issue 43)', async () => {
  const ctx = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await p.click('#lesson-a0');
  await done(p);
  const id = '#lesson-sea-sea_state';
  await p.$eval(id, (e) => e.scrollIntoView({ block: 'center' }));
  const y0 = await p.evaluate(() => window.scrollY);
  const top0 = await p.$eval(id, (e) => e.getBoundingClientRect().top);
  const before = await p.evaluate(() => window.__lessonLatencyMs);
  await move(p, id);
  await p.waitForFunction((b) => window.__lessonLatencyMs !== b && !document.getElementById('run').disabled, before, { timeout: 60000 });
  await p.waitForTimeout(300);
  const y1 = await p.evaluate(() => window.scrollY);
  const top1 = await p.$eval(id, (e) => e.getBoundingClientRect().top);
  assert(Math.abs(top1 - top0) <= 2, `the slider moved on the screen from ${Math.round(top0)} to ${Math.round(top1)} px (scroll ${Math.round(y0)} -> ${Math.round(y1)})`);
  await ctx.close();
});

await check('from a control to the new plot: at most 1.5 x the native run of the same scenario + 150 ms (measured side by side)', async () => {
  assert(existsSync(native), `no native ${native}`);
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await p.click('#lesson-a0');
  await done(p);
  const lines = [];
  let worst = 0;
  for (const id of ['#lesson-sea-sea_state', '#lesson-ship-hull-hub_above_base_m', '#lesson-initial-speed_kn']) {
    const before = await p.evaluate(() => window.__lessonLatencyMs);
    await move(p, id);
    await p.waitForFunction((b) => window.__lessonLatencyMs !== b && !document.getElementById('run').disabled, before, { timeout: 60000 });
    const browserMs = await p.evaluate(() => window.__lessonLatencyMs);
    const file = `${shots}/lesson-scenario.json`;
    writeFileSync(file, await p.evaluate(() => window.__scenarioText()));
    const t0 = performance.now();
    execFileSync(native, ['run', file], { stdio: ['ignore', 'ignore', 'inherit'] });
    const nativeMs = performance.now() - t0;
    const allowed = 1.5 * nativeMs + 150;
    worst = Math.max(worst, browserMs / allowed);
    lines.push(`${id}: browser ${browserMs.toFixed(0)} ms, native ${nativeMs.toFixed(0)} ms, allowed ${allowed.toFixed(0)} ms`);
  }
  console.log(`     ${lines.join('; ')}`);
  assert(worst <= 1, `too slow: ${lines.join('; ')}`);
  await ctx.close();
});

await check('a lesson link with non-default values opens to the same numbers', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=turn`, base, errors);
  await p.click('#lesson-a1');
  await done(p);
  await move(p, '#lesson-commands-1-heading_deg');
  await p.waitForFunction(() => /commands\.1\.heading_deg=/.test(location.hash), null, { timeout: 10000 });
  await done(p);
  await p.waitForTimeout(200);
  const url = p.url();
  const mine = await p.evaluate(() => window.__scenarioText());
  const mineText = await p.textContent('#lesson-observe .lesson-explain');
  const q = await openPage(await browser.newContext({ viewport: { width: 1366, height: 768 } }), url, base, errors);
  assert((await q.inputValue('#lesson-commands-1-heading_deg')) === (await p.inputValue('#lesson-commands-1-heading_deg')), 'the slider is not where the link put it');
  await q.click('#lesson-skip');
  await done(q);
  await q.waitForTimeout(200);
  assert((await q.evaluate(() => window.__scenarioText())) === mine, 'the link ran another scenario');
  assert((await q.textContent('#lesson-observe .lesson-explain')) === mineText, 'the link gave other numbers');
  // Every lesson reaches the Lab with its scenario, and the Lab reaches the lessons.
  await q.click('#lesson-lab');
  await q.waitForFunction(() => !document.body.classList.contains('lesson') && document.getElementById('preset').value === 'turn-90', null, { timeout: 10000 });
  assert(await q.isVisible('#lessons-link'), 'no way from the Lab to the lessons');
  await ctx.close();
});

await finish(browser, errors);
