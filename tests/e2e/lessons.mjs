// Browser test of the lessons (issues 30 and 43): every lesson opens from its link at the three
// sizes with its default run playing before the answer, its controls, plot and live view fit one
// screen (the plot right under the controls on a phone), every control key-stepped and every
// slider dragged, at each size, reruns without moving the screen, keeps the control and the plot in view,
// changes the plot and shows the words of the final run; Back and Forward inside a lesson; a
// keyboard-only lesson; a link's refused value; the drag preview's rate; the time from a control
// to the new plot against the native run of the same scenario (medians per lesson printed); the
// engines lesson's list-valued control (the sets running) stepped and set by "Try this next", its
// words and fuel figure against the native run; the battery lesson's drive-train storage block
// against the native trace; axe-core finds no serious violation before and after a run; every
// lesson about a change answered, changed, and its verdict with both numbers against the native
// one (issue 55), the crash stop's lesson (issue 56) among them.
// Usage: node tests/e2e/lessons.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
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
const latency = {}; // lesson -> [ms] of settled reruns

const idle = (p) => p.waitForFunction(() => !document.getElementById('run').disabled && document.getElementById('results').getAttribute('aria-busy') !== 'true', null, { timeout: 60000 });
const done = async (p) => { await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 }); await idle(p); };
const firstSeries = (p) => p.$eval('#plots .chart', (c) => JSON.stringify(c.uplot.data.slice(1)));
const box = (p, sel) => p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { top: r.top + window.scrollY, bottom: r.bottom + window.scrollY, h: r.height }; });
// Where an element is on the screen now (viewport coordinates).
const onScreen = (p, sel) => p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { top: r.top, bottom: r.bottom, vh: window.innerHeight }; });
const inView = (r) => r.top >= -1 && r.top < r.vh - 10;
// The live view the lesson shows (the one figure of #live that is drawn).
const liveBox = (p) => p.$$eval('#live figure.live-view', (fs) => fs.filter((f) => f.getClientRects().length).map((f) => { const r = f.getBoundingClientRect(); return { top: r.top + window.scrollY, bottom: r.bottom + window.scrollY }; }));
const latencyNow = (p) => p.evaluate(() => window.__lessonLatencyMs);
// The count of reruns that have reached the plot (a mark to wait past: two reruns can measure the
// same latency, so the latency is no mark).
const mark = (p) => p.evaluate(() => window.__lessonRuns || 0);
// A settled rerun after the mark `before`.
const rerun = async (p, before) => { await p.waitForFunction((b) => (window.__lessonRuns || 0) !== b, before, { timeout: 60000 }); await done(p); };
const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s.length ? (s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2) : NaN; };

// A key step of a control as a person does it: a slider one stop up (down at its top), a toggle
// to its other value; focus without scrolling (the hand is already there).
async function keyStep(p, sel) {
  const tag = await p.$eval(sel, (e) => { e.focus({ preventScroll: true }); return e.tagName; });
  if (tag === 'SELECT') {
    await p.$eval(sel, (e) => { e.selectedIndex = (e.selectedIndex + 1) % e.options.length; e.dispatchEvent(new Event('change')); });
    return;
  }
  const atTop = await p.$eval(sel, (e) => Number(e.value) >= Number(e.max));
  await p.keyboard.press(atTop ? 'ArrowLeft' : 'ArrowRight');
}
// A mouse drag of a slider's thumb by a quarter of its width (towards the far side).
async function drag(p, sel) {
  const { x, y, w, frac } = await p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top + r.height / 2, w: r.width, frac: (Number(e.value) - Number(e.min)) / (Number(e.max) - Number(e.min) || 1) }; });
  const from = x + 8 + frac * (w - 16), to = frac > 0.5 ? from - w / 4 : from + w / 4;
  await p.mouse.move(from, y);
  await p.mouse.down();
  for (let i = 1; i <= 5; i++) await p.mouse.move(from + ((to - from) * i) / 5, y);
  await p.mouse.up();
}
const explainedText = (p) => p.evaluate(() => window.__lessonWords());

// The drive train's storage blocks (a run with storage): the charge and power each bus's block
// shows are the native run's trace at the picture's time, to the digits printed (the trace records
// the two buses' sum of power and their mean charge; each block shows half and the mean), and the
// text alternative says the same.
async function storageBlockAgrees(p) {
  await p.waitForFunction(() => window.__liveViews.drawn.train && window.__liveViews.drawn.train.branches, null, { timeout: 10000 });
  const { t, drawn, text } = await p.evaluate(() => { const L = window.__liveViews; L.pause(); L.seek(L.t); L.text.textContent = L.describe(); return { t: L.drawn.t, drawn: L.drawn.train.branches, text: document.getElementById('live-text').textContent }; });
  const file = `${shots}/lesson-scenario.json`, csv = `${shots}/lesson-trace.csv`;
  writeFileSync(file, await p.evaluate(() => window.__scenarioText()));
  execFileSync(native, ['run', file, '--out', csv], { stdio: ['ignore', 'ignore', 'inherit'] });
  const [head, ...rows] = readFileSync(csv, 'utf8').trim().split('\n').map((l) => l.split(','));
  const col = (n) => head.indexOf(n);
  const row = rows.reduce((a, b) => (Math.abs(Number(b[col('t_s')]) - t) < Math.abs(Number(a[col('t_s')]) - t) ? b : a));
  const soc = `${(100 * Number(row[col('storage_soc')])).toFixed(1)} %`, mw = `${(Math.abs(Number(row[col('storage_power_w')])) / 2e6).toFixed(1)} MW`;
  assert(drawn.storage_soc_text === soc, `at ${t} s the storage block shows ${drawn.storage_soc_text} charged, the native trace ${soc}`);
  assert(drawn.storage_text.endsWith(mw), `at ${t} s the storage block shows "${drawn.storage_text}", the native trace ${mw} on each bus`);
  assert(text.includes(`storage on each bus ${soc} charged, `) && new RegExp(`storage on each bus [^;]* ${mw}`).test(text), `the text alternative: ${text}`);
  console.log(`     battery at ${t.toFixed(1)} s: each bus's storage block ${soc} charged, ${drawn.storage_text}, as the native trace`);
}

for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: every lesson opens alive, fits one screen, and every control key-stepped and every slider dragged reruns in place (screenshots)`, async () => {
    const ctx = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
    const p = await openPage(ctx, `${base}#lessons`, base, errors);
    const LESSONS = (await p.$$eval('.lesson-list a', (a) => a.map((x) => x.getAttribute('href').slice('#lesson='.length)))).map((name) => ({ name }));
    assert(LESSONS.length >= 6, `the index lists ${LESSONS.length} lessons`);
    assert(await p.isVisible('#lesson-box .start-here'), 'no "Start here" on the index');
    const current = await p.$$eval('#tabs [aria-selected="true"]', (t) => t.length);
    assert(current === 0, 'the lessons index marks a tab as current');
    if (w === 1366) await p.screenshot({ path: `${shots}/lessons-index.png` });
    let where = 'the index';
    try {
      for (const lesson of LESSONS) {
        where = `${lesson.name}: opening`;
        await p.goto(`${base}#lesson=${lesson.name}`);
        // The new lesson's own question: the one before stays in the page (answered) until the
        // worker has opened this one, which a loaded machine can delay past the hash change.
        await p.waitForFunction(() => document.body.classList.contains('lesson-waiting') && document.getElementById('lesson-q'), null, { timeout: 30000 });
        assert(await p.$eval('#lesson-controls input, #lesson-controls select', (e) => e.disabled), `${lesson.name}: a control acts before the prediction`);
        // Alive before the answer: the default run plays in the live picture; the reason the
        // controls wait is in view.
        await p.waitForFunction(() => [...document.querySelectorAll('#live figure.live-view')].some((f) => f.getClientRects().length), null, { timeout: 60000 });
        await idle(p);
        assert(inView(await onScreen(p, '#lesson-wait')), `${lesson.name}: the line saying why the controls wait is not in view`);
        if (w !== 1920) await p.screenshot({ path: `${shots}/lesson-${lesson.name}-before-${w}x${h}.png` });
        let v = await axeFindings(p);
        assert(!v.length, `${lesson.name} before the answer: ${v.join(' | ')}`);
        where = `${lesson.name}: first run`;
        await p.click('#lesson-a0');
        await p.waitForFunction(() => document.querySelector('#lesson-observe p'), null, { timeout: 60000 });
        await done(p);
        await p.waitForTimeout(250);
        assert(/\d/.test(await p.textContent('#lesson-observe')), `${lesson.name}: no explanation with numbers`);
        const ctl = await box(p, '#lesson-box'), plot = await box(p, '#plots .plot'), views = await liveBox(p);
        assert(views.length === 1, `${lesson.name}: ${views.length} live views shown`);
        const ids = await p.$$eval('#lesson-controls [data-path]', (e) => e.map((x) => `#${x.id}`));
        assert(ids.length >= 2 && ids.length <= 4, `${lesson.name}: ${ids.length} controls`);
        if (w >= 1366) {
          const bottom = Math.max(ctl.bottom, plot.bottom, views[0].bottom);
          assert(bottom <= h, `${lesson.name} at ${w}x${h}: controls, plot and live view end at ${Math.round(bottom)} px`);
        } else {
          const controls = await box(p, '#lesson-controls');
          assert(plot.top > controls.bottom && plot.top - ctl.bottom < 60 && plot.top < views[0].top, `${lesson.name} on the phone: controls end ${Math.round(ctl.bottom)}, plot at ${Math.round(plot.top)}, live view at ${Math.round(views[0].top)}`);
        }
        if (w >= 1920) {
          const width = (await p.$eval('#plots .plot', (e) => e.getBoundingClientRect().width));
          assert(width >= 600, `${lesson.name} at ${w}: the plot is ${Math.round(width)} px wide (490 before issue 43)`);
        }
        if (w !== 1920 || lesson.name === 'power' || lesson.name === 'engines') await p.screenshot({ path: `${shots}/lesson-${lesson.name}-${w}x${h}.png`, fullPage: w < 600 });
        v = await axeFindings(p);
        assert(!v.length, `${lesson.name} after a run: ${v.join(' | ')}`);
        // Every control: a key step (and a slider a drag too) reruns; the screen
        // does not move, the control and the plot stay in view, the plot changes, the words are
        // the final run's; the earlier run stays, faint, with one legend entry.
        for (const id of ids) {
          const steps = (await p.$eval(id, (e) => e.type === 'range')) ? [keyStep, drag] : [keyStep];
          for (const step of steps) {
            where = `${lesson.name}: ${step.name} of ${id}`;
            await p.$eval(id, (e) => { const r = e.getBoundingClientRect(); if (r.top < 0 || r.bottom > window.innerHeight) e.scrollIntoView({ block: 'center' }); });
            const y0 = await p.evaluate(() => window.scrollY);
            const before = await firstSeries(p), lat = await mark(p);
            await step(p, id);
            await rerun(p, lat);
            (latency[lesson.name] ||= []).push(await latencyNow(p));
            await p.waitForTimeout(150);
            const y1 = await p.evaluate(() => window.scrollY);
            assert(Math.abs(y1 - y0) <= 2, `the page scrolled from ${y0} to ${y1}`);
            assert(inView(await onScreen(p, id)), 'the control moved out of view');
            assert(inView(await onScreen(p, '#plots .plot')) || w < 600, 'the plot is out of view');
            assert((await firstSeries(p)) !== before, 'the plot did not change');
            assert((await p.textContent('#lesson-observe .lesson-explain')) === (await explainedText(p)), 'the words are not those of the final run');
            const legend = await p.$eval('#plots .plot .legend', (l) => [...l.children].filter((x) => x.style.visibility !== 'hidden').length + '|' + [...l.children].filter((x) => x.style.visibility !== 'hidden').map((x) => x.textContent).join('|'));
            assert(/run before/.test(legend), `the run before is not drawn (${legend.slice(0, 160)})`);
            const series = await p.$eval('#plots .chart', (c) => c.uplot.series.length - 1);
            const entries = Number(legend.split('|')[0]);
            assert(entries <= series / 2 + 1, `${entries} legend entries for ${series} lines`);
          }
        }
        // The battery lesson after its steps has a battery: the drive train's storage branches.
        if (lesson.name === 'battery') await p.screenshot({ path: `${shots}/lesson-battery-storage-${w}x${h}.png`, fullPage: w < 600 });
      }
    } catch (e) { throw new Error(`${where}: ${e.message}`); }
    await ctx.close();
  });
}

await check('on a phone a rerun leaves the screen where the hand is: the slider being moved does not scroll away (issue 43)', async () => {
  const ctx = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await idle(p);
  await p.click('#lesson-a0');
  await done(p);
  const id = '#lesson-sea-sea_state';
  await p.$eval(id, (e) => e.scrollIntoView({ block: 'center' }));
  const y0 = await p.evaluate(() => window.scrollY);
  const top0 = await p.$eval(id, (e) => e.getBoundingClientRect().top);
  const lat = await mark(p);
  await keyStep(p, id);
  await rerun(p, lat);
  await p.waitForTimeout(300);
  const y1 = await p.evaluate(() => window.scrollY);
  const top1 = await p.$eval(id, (e) => e.getBoundingClientRect().top);
  assert(Math.abs(top1 - top0) <= 2, `the slider moved on the screen from ${Math.round(top0)} to ${Math.round(top1)} px (scroll ${Math.round(y0)} -> ${Math.round(y1)})`);
  await ctx.close();
});

await check('Back and Forward inside a lesson restore its values, plot and words (issue 43)', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=turn`, base, errors);
  await idle(p);
  await p.click('#lesson-a0');
  await done(p);
  // The run's own lines (the faint one is whichever run was shown before).
  const ownLines = () => p.$eval('#plots .chart', (c) => JSON.stringify(c.uplot.data.slice(1).filter((_, i) => !/kept run/.test(c.uplot.series[i + 1].label))));
  const state = async () => ({ value: await p.inputValue('#lesson-commands-1-heading_deg'), words: await p.textContent('#lesson-observe .lesson-explain'), plot: await ownLines(), hash: await p.evaluate(() => location.hash) });
  const s0 = await state();
  let lat = await mark(p);
  await keyStep(p, '#lesson-commands-1-heading_deg');
  await rerun(p, lat);
  const s1 = await state();
  lat = await mark(p);
  await keyStep(p, '#lesson-commands-1-heading_deg');
  await rerun(p, lat);
  const s2 = await state();
  assert(s0.value !== s1.value && s1.value !== s2.value && s1.words !== s2.words, 'the steps did not change the lesson');
  const same = (a, b, what) => { for (const k of ['value', 'words', 'plot', 'hash']) assert(a[k] === b[k], `${what}: ${k} differs (${String(a[k]).slice(0, 80)} / ${String(b[k]).slice(0, 80)})`); };
  await p.goBack();
  await p.waitForFunction((v) => document.getElementById('lesson-commands-1-heading_deg').value === v, s1.value, { timeout: 20000 });
  await idle(p);
  await p.waitForTimeout(300);
  same(await state(), s1, 'Back');
  assert(!(await p.$eval('#lesson-commands-1-heading_deg', (e) => e.disabled)), 'Back: the controls are disabled');
  assert(await p.isHidden('#lesson-skip'), 'Back: the question asks again');
  await p.goBack();
  await p.waitForFunction((v) => document.getElementById('lesson-commands-1-heading_deg').value === v, s0.value, { timeout: 20000 });
  await idle(p);
  await p.waitForTimeout(300);
  same(await state(), s0, 'Back twice');
  await p.goForward();
  await p.waitForFunction((v) => document.getElementById('lesson-commands-1-heading_deg').value === v, s1.value, { timeout: 20000 });
  await idle(p);
  await p.waitForTimeout(300);
  same(await state(), s1, 'Forward');
  await ctx.close();
});

await check('a lesson by keyboard alone: arrows browse the answers without choosing, Enter chooses, focus goes to the first control, Tab goes controls, plot, live picture', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await idle(p);
  const y0 = await p.evaluate(() => window.scrollY);
  await p.focus('#lesson-a0');
  await p.keyboard.press('ArrowDown');
  await p.keyboard.press('ArrowDown');
  assert(await p.$eval('#lesson-controls input', (e) => e.disabled), 'an arrow key chose an answer');
  assert((await p.evaluate(() => document.activeElement.id)) === 'lesson-a2', 'the arrows did not move to the third answer');
  await p.keyboard.press('ArrowUp');
  await p.keyboard.press('Enter');
  await p.waitForFunction(() => document.querySelector('#lesson-observe p'), null, { timeout: 60000 });
  await done(p);
  assert(/You predicted: less often/.test(await p.textContent('#lesson-observe')), 'the answer chosen is not the one said');
  const first = await p.$eval('#lesson-controls [data-path]', (e) => e.id);
  assert((await p.evaluate(() => document.activeElement.id)) === first, `focus is on ${await p.evaluate(() => document.activeElement.id || document.activeElement.tagName)}, not the first control`);
  assert(Math.abs((await p.evaluate(() => window.scrollY)) - y0) <= 2, 'answering scrolled the page');
  const lat = await mark(p);
  await p.keyboard.press('ArrowLeft');
  await rerun(p, lat);
  const n = await p.$$eval('#lesson-controls [data-path]', (e) => e.length);
  for (let i = 1; i < n; i++) await p.keyboard.press('Tab');
  const order = [];
  for (let i = 0; i < 40 && order[order.length - 1] !== 'live'; i++) {
    await p.keyboard.press('Tab');
    const where = await p.evaluate(() => { const a = document.activeElement; return a.closest('#plots') ? 'plot' : a.closest('#live') ? 'live' : a.closest('#lesson-box') ? 'controls' : a.closest('#lesson-explain') ? 'words' : a.id || a.tagName; });
    if (order[order.length - 1] !== where) order.push(where);
  }
  const seq = order.filter((x) => x === 'plot' || x === 'live');
  assert(seq[0] === 'plot' && seq.includes('live'), `Tab after the controls went ${order.join(' -> ')}`);
  await ctx.close();
});

await check('a lesson link with a value out of range says so in view and uses the lesson\'s value', async () => {
  const ctx = await browser.newContext({ viewport: { width: 390, height: 844 } });
  const p = await openPage(ctx, `${base}#lesson=waves&sea.sea_state=9`, base, errors);
  await p.waitForSelector('#lesson-refused', { timeout: 20000 });
  const text = await p.textContent('#lesson-refused');
  assert(/9 is outside this lesson's range, 2 to 6/.test(text), text);
  assert(inView(await onScreen(p, '#lesson-refused')), 'the message is not in view');
  assert((await p.textContent('#lesson-sea-sea_state-out')).trim() === '6', 'the slider does not show the lesson\'s sea state');
  await ctx.close();
});

// The drag preview's rate is a machine's speed: the issue's 4 a second holds on the machine where
// the native run of the waves lesson takes WAVES_NATIVE_REF_MS (measured 468 ms); a slower machine,
// measured side by side, is allowed that much fewer (the same share of its speed).
const WAVES_NATIVE_REF_MS = 470;
await check('while a slider is dragged the plot follows: at least 4 preview runs a second in `waves`, scaled by the native run\'s speed measured beside it', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await idle(p);
  await p.click('#lesson-a0');
  await done(p);
  const id = '#lesson-initial-speed_kn';
  const n0 = await p.evaluate(() => window.__lessonPreviews || 0);
  const t0 = Date.now();
  // 3 s of dragging: a new thumb position every 50 ms, never released.
  const { x, y, w } = await p.$eval(id, (e) => { const r = e.getBoundingClientRect(); return { x: r.left + 8, y: r.top + r.height / 2, w: r.width - 16 }; });
  await p.mouse.move(x + w / 2, y);
  await p.mouse.down();
  for (let i = 0; i < 60; i++) {
    await p.mouse.move(x + w / 2 + (w / 3) * Math.sin(i / 6), y);
    await p.waitForTimeout(50);
  }
  const secs = (Date.now() - t0) / 1000;
  const n = (await p.evaluate(() => window.__lessonPreviews || 0)) - n0;
  const lat = await mark(p);
  await p.mouse.up();
  await rerun(p, lat);
  const file = `${shots}/lesson-scenario.json`;
  writeFileSync(file, await p.evaluate(() => window.__scenarioText()));
  const nat = [];
  for (let i = 0; i < 3; i++) {
    const t1 = performance.now();
    execFileSync(native, ['run', file], { stdio: ['ignore', 'ignore', 'inherit'] });
    nat.push(performance.now() - t1);
  }
  const need = 4 * Math.min(1, WAVES_NATIVE_REF_MS / median(nat));
  console.log(`     waves: ${n} preview runs in ${secs.toFixed(1)} s of dragging (${(n / secs).toFixed(1)} a second; native run ${median(nat).toFixed(0)} ms, so at least ${need.toFixed(1)} asked)`);
  assert(n / secs >= need, `${(n / secs).toFixed(1)} previews a second, ${need.toFixed(1)} asked`);
  assert((await p.textContent('#lesson-observe .lesson-explain')) === (await explainedText(p)), 'the words are not those of the released value');
  await ctx.close();
});

await check('from a control to the new plot: at most 1.5 x the native run of the same scenario + 150 ms (measured side by side; medians per lesson)', async () => {
  assert(existsSync(native), `no native ${native}`);
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const lines = [];
  let worst = 0;
  for (const name of ['power', 'waves', 'turn', 'braking', 'bus', 'engines', 'sign']) {
    const p = await openPage(ctx, `${base}#lesson=${name}`, base, errors);
    await idle(p);
    await p.click('#lesson-skip');
    await done(p);
    const id = await p.$eval('#lesson-controls [data-path]', (e) => `#${e.id}`);
    const ms = [], nat = [];
    for (let i = 0; i < 3; i++) {
      const lat = await mark(p);
      await keyStep(p, id);
      await rerun(p, lat);
      ms.push(await latencyNow(p));
      const file = `${shots}/lesson-scenario.json`;
      writeFileSync(file, await p.evaluate(() => window.__scenarioText()));
      const t0 = performance.now();
      execFileSync(native, ['run', file], { stdio: ['ignore', 'ignore', 'inherit'] });
      nat.push(performance.now() - t0);
    }
    (latency[name] ||= []).push(...ms);
    const allowed = 1.5 * median(nat) + 150;
    worst = Math.max(worst, median(ms) / allowed);
    lines.push(`${name}: median ${median(ms).toFixed(0)} ms (native ${median(nat).toFixed(0)} ms, allowed ${allowed.toFixed(0)} ms)`);
    await p.close();
  }
  console.log(`     ${lines.join('; ')}`);
  console.log(`     all reruns of this file, median per lesson: ${Object.entries(latency).map(([k, v]) => `${k} ${median(v).toFixed(0)} ms (${v.length})`).join(', ')}`);
  assert(worst <= 1, `too slow: ${lines.join('; ')}`);
  await ctx.close();
});

await check('a lesson in presentation mode at 1920x1080 keeps its controls, plots and live view on one screen (screenshot)', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1920, height: 1080 }, bypassCSP: true });
  const p = await openPage(ctx, `${base}#lesson=waves`, base, errors);
  await idle(p);
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

await check('a lesson link with non-default values opens to the same numbers', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=turn`, base, errors);
  await idle(p);
  await p.click('#lesson-a1');
  await done(p);
  const lat = await mark(p);
  await keyStep(p, '#lesson-commands-1-heading_deg');
  await rerun(p, lat);
  await p.waitForFunction(() => /commands\.1\.heading_deg=/.test(location.hash), null, { timeout: 10000 });
  const url = p.url();
  const mine = await p.evaluate(() => window.__scenarioText());
  const mineText = await p.textContent('#lesson-observe .lesson-explain');
  const q = await openPage(await browser.newContext({ viewport: { width: 1366, height: 768 } }), url, base, errors);
  await idle(q);
  assert((await q.inputValue('#lesson-commands-1-heading_deg')) === (await p.inputValue('#lesson-commands-1-heading_deg')), 'the slider is not where the link put it');
  await q.click('#lesson-skip');
  await q.waitForFunction(() => document.querySelector('#lesson-observe .lesson-explain'), null, { timeout: 60000 });
  await idle(q);
  assert((await q.evaluate(() => window.__scenarioText())) === mine, 'the link ran another scenario');
  assert((await q.textContent('#lesson-observe .lesson-explain')) === mineText, 'the link gave other numbers');
  // Every lesson reaches the Lab with its scenario, and the Lab reaches the lessons.
  await q.click('#lesson-lab');
  await q.waitForFunction(() => !document.body.classList.contains('lesson') && document.getElementById('preset').value === 'turn-90', null, { timeout: 10000 });
  assert(await q.isVisible('#lessons-link'), 'no way from the Lab to the lessons');
  await ctx.close();
});

await check('one value per lesson: the page says the words the native claim check gives (aes-sim lesson)', async () => {
  assert(existsSync(native), `no native ${native}`);
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const VALUES = { power: 'commands.0.speed_kn=20', waves: 'sea.sea_state=4', turn: 'commands.1.heading_deg=45', braking: 'plant.dc_link.brake_resistor_ohm=0', bus: 'controllers.field.kp=0.001', sign: 'seakeeping.stern_motion=thesis_eq_2_57', battery: 'plant.storage.energy_j=50000000', stopping: 'plant.storage.energy_j=150000000' };
  for (const [name, value] of Object.entries(VALUES)) {
    const p = await openPage(ctx, `${base}#lesson=${name}&${value}`, base, errors);
    await idle(p);
    await p.click('#lesson-skip');
    await p.waitForFunction(() => document.querySelector('#lesson-observe .lesson-explain'), null, { timeout: 60000 });
    await idle(p);
    const page = await p.textContent('#lesson-observe .lesson-explain');
    const words = execFileSync(native, ['lesson', name, '--value', value], { encoding: 'utf8' }).split('\n')[1];
    assert(page === words, `${name} ${value}:\n page:   ${page}\n native: ${words}`);
    if (name === 'battery') await storageBlockAgrees(p);
    await p.close();
  }
  await ctx.close();
});

// The predict-observe-explain loop (issue 55): each lesson about a change, answered, then the
// question's control moved one step; the verdict on the prediction (#lesson-verdict) gives the
// run before's number and the run now's and is the native `aes-sim lesson --before default
// --answer N` verdict for the same values, to the character.
const CHANGES = { waves: 'ship.hull.hub_above_base_m', sign: 'seakeeping.stern_motion', braking: 'plant.dc_link.brake_resistor_ohm', bus: 'controllers.field.kp', engines: 'plant.online.sets', battery: 'plant.storage.energy_j', stopping: 'plant.storage.energy_j' };
await check('every lesson about a change, answered and changed, says its verdict with the numbers before and now, the same as aes-sim lesson\'s (issue 55)', async () => {
  assert(existsSync(native), `no native ${native}`);
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  let n = 0;
  for (const [name, path] of Object.entries(CHANGES)) {
    const p = await openPage(ctx, `${base}#lesson=${name}`, base, errors);
    await idle(p);
    const answer = n++ % 3;
    await p.click(`#lesson-a${answer}`);
    await p.waitForFunction(() => document.querySelector('#lesson-observe .lesson-explain'), null, { timeout: 60000 });
    await done(p);
    const first = await p.textContent('#lesson-verdict');
    assert(/One run (cannot answer|shows one choice)|does not answer/.test(first), `${name}: the first run's verdict: ${first}`);
    const lat = await mark(p);
    await keyStep(p, `#lesson-${path.replace(/\./g, '-')}`);
    await rerun(p, lat);
    await p.waitForTimeout(200);
    const page = await p.textContent('#lesson-verdict');
    const values = await p.evaluate(() => [...new URLSearchParams(location.hash.slice(1))].filter(([k]) => k !== 'lesson').map(([k, v]) => `${k}=${v}`));
    assert(values.some((v) => v.startsWith(`${path}=`)), `${name}: the address does not carry the change: ${values.join(' ')}`);
    const args = ['lesson', name, '--before', 'default', '--answer', String(answer + 1), ...values.flatMap((v) => ['--value', v])];
    const words = execFileSync(native, args, { encoding: 'utf8' }).split('\n')[0];
    assert(page === words, `${name} ${values.join(' ')}:\n page:   ${page}\n native: ${words}`);
    assert(/You predicted: /.test(page) && / before \(/.test(page) && / now \(/.test(page) && /\d/.test(page), `${name}: no verdict with both numbers: ${page}`);
    console.log(`     ${name}: ${page}`);
    await p.close();
  }
  await ctx.close();
});

await check('engines (issue 45): answered, the sets control stepped to two reruns with two sets; the page\'s words and fuel figure are the native run\'s; "Set it" brings all four back and the fuel rises', async () => {
  assert(existsSync(native), `no native ${native}`);
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await openPage(ctx, `${base}#lesson=engines`, base, errors);
  await idle(p);
  await p.click('#lesson-a0');
  await p.waitForFunction(() => document.querySelector('#lesson-observe .lesson-explain'), null, { timeout: 60000 });
  await done(p);
  const sets = '#lesson-plant-online-sets';
  assert((await p.inputValue(sets)) === '[1,2,3,4]', `the lesson opens with ${await p.inputValue(sets)}`);
  const fuelOf = (words) => { const m = /burns? ([\d.]+) MW of fuel power/.exec(words || ''); return m ? Number(m[1]) : NaN; };
  const four = fuelOf(await p.textContent('#lesson-observe .lesson-explain'));
  let lat = await mark(p);
  await keyStep(p, sets);
  await rerun(p, lat);
  assert((await p.$eval(sets, (e) => e.selectedOptions[0].textContent)) === 'two', 'the step did not choose two');
  const scenario = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(JSON.stringify(scenario.plant.online.sets) === '[1,3]', `the run's sets: ${JSON.stringify(scenario.plant.online.sets)}`);
  assert(/plant\.online\.sets=%5B1%2C3%5D/.test(await p.evaluate(() => location.hash)), `the address does not carry the sets: ${await p.evaluate(() => location.hash)}`);
  const page = await p.textContent('#lesson-observe .lesson-explain');
  const words = execFileSync(native, ['lesson', 'engines', '--value', 'plant.online.sets=[1,3]'], { encoding: 'utf8' }).split('\n')[1];
  assert(page === words, `engines with two sets:\n page:   ${page}\n native: ${words}`);
  const two = fuelOf(page);
  // The fuel plot's last point is the figure the words quote (MW, one decimal).
  const last = await p.$eval('#plots .chart', (c) => { const d = c.uplot.data[1]; return d[d.length - 1]; });
  assert(Number.isFinite(two) && Math.abs(last - two) <= 0.05, `the words say ${two} MW of fuel, the plot ends at ${last}`);
  assert(two < four, `two sets burn ${two} MW, four ${four} MW`);
  console.log(`     engines: fuel power at 60 s, four sets ${four} MW, two ${two} MW (native: ${fuelOf(words)} MW)`);
  lat = await mark(p);
  await p.click('#lesson-try');
  await rerun(p, lat);
  assert((await p.inputValue(sets)) === '[1,2,3,4]', `"Set it" left the control at ${await p.inputValue(sets)}`);
  const again = fuelOf(await p.textContent('#lesson-observe .lesson-explain'));
  assert(again === four && again > two, `after "Set it": ${again} MW (four sets ${four} MW, two ${two} MW)`);
  await ctx.close();
});

await check('outside the lessons (issue 43): Reset with a refused value still being typed restores the study and enables Run; presentation mode at 1920x1080 shows What to watch and the first plot', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1920, height: 1080 } });
  const p = await openPage(ctx, `${base}#v=2&preset=head-seas-ss6`, base, errors);
  const sel = '#f-sea-sea_state';
  await p.$eval(sel, (e) => { for (let d = e.closest('details'); d; d = d.parentElement.closest('details')) d.open = true; });
  for (const commit of [true, false]) {
    await p.fill(sel, '1');
    if (commit) { await p.dispatchEvent(sel, 'change'); await p.waitForFunction((s) => document.querySelector(s).getAttribute('aria-invalid') === 'true', sel, { timeout: 10000 }); }
    await p.click('#reset');
    await p.waitForTimeout(500);
    const [v, invalid, run, modified] = [await p.inputValue(sel), await p.$eval(sel, (e) => e.getAttribute('aria-invalid')), await p.$eval('#run', (e) => e.disabled), await p.isVisible('#modified')];
    assert(v === '6' && !invalid && !run && !modified, `Reset ${commit ? 'after' : 'while'} typing 1: field ${v}, invalid ${invalid}, Run disabled ${run}, modified shown ${modified}`);
  }
  await p.click('#run');
  await done(p);
  await p.click('#present');
  await p.waitForTimeout(800);
  const watch = await onScreen(p, '#watch'), plot = await onScreen(p, '#plots .plot');
  assert(watch.bottom <= 1080 && plot.top + 0.5 * (plot.bottom - plot.top) <= 1080, `presenting: What to watch ends at ${Math.round(watch.bottom)}, the first plot spans ${Math.round(plot.top)} to ${Math.round(plot.bottom)} px`);
  await p.screenshot({ path: `${shots}/lab-presenting-1920x1080.png` });
  await ctx.close();
});

await finish(browser, errors);
