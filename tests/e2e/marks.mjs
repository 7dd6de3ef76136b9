// Browser test of one meaning per mark and of the phone and the projector (issue 55): a run's own
// lines are solid and the kept run's are the only dashed ones, each legend entry draws its line's
// pattern, and keeping a run never grows the legend or moves the live view; the stern picture's
// thrust words agree with beta_T; one spelling (disc); power and energy fields in MW and MJ
// (the scenario keeps SI); one rudder sign on the plot, the booklet and the live view; the turning
// circle has axes and a scale; a lesson opens at its top; on a phone the verdict is in view after a
// run; presentation mode at 1366x768 shows the question, controls, plot, words and "Try this
// next" of every lesson without scrolling, with larger axis type than the desk's. Screenshots
// marks-*.png at the three sizes.
// Usage: node tests/e2e/marks.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR
import { mkdirSync } from 'node:fs';
import { assert, axeFindings, checker, launch, openPage, pressAndWait, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const open = (url, c) => openPage(c, url, base, errors);
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];

const idle = (p) => p.waitForFunction(() => !document.getElementById('run').disabled && document.getElementById('results').getAttribute('aria-busy') !== 'true', null, { timeout: 60000 });
const done = async (p) => { await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 }); await idle(p); };
// A settled lesson rerun after the count `before` (window.__lessonRuns).
const rerun = async (p, before) => { await p.waitForFunction((b) => (window.__lessonRuns || 0) !== b, before, { timeout: 60000 }); await done(p); };
// A key step of a lesson's first control (a stop up, down at its top; a toggle's next value),
// focused without scrolling, as a person does it with the control in view.
async function stepFirst(p) {
  const id = await p.$eval('#lesson-controls [data-path]', (e) => `#${e.id}`);
  await p.$eval(id, (e) => { const r = e.getBoundingClientRect(); if (r.top < 0 || r.bottom > window.innerHeight) e.scrollIntoView({ block: 'center' }); });
  const before = await p.evaluate(() => window.__lessonRuns || 0);
  const kind = await p.$eval(id, (e) => { e.focus({ preventScroll: true }); return e.tagName === 'SELECT' ? 'select' : Number(e.value) >= Number(e.max) ? 'top' : 'slider'; });
  if (kind === 'select') await p.$eval(id, (e) => { e.selectedIndex = (e.selectedIndex + 1) % e.options.length; e.dispatchEvent(new Event('change')); });
  else await p.keyboard.press(kind === 'top' ? 'ArrowLeft' : 'ArrowRight');
  await rerun(p, before);
  await p.waitForTimeout(200);
}
// Every line plot's series (own and kept) and its legend, as drawn.
const marks = (p, sel = '#plots') => p.$$eval(`${sel} .plot`, (ps) => ps.filter((x) => x.querySelector('.chart') && x.querySelector('.chart').uplot).map((x) => {
  const u = x.querySelector('.chart').uplot;
  const items = [...x.querySelectorAll('.legend li')];
  return {
    title: x.querySelector('h3').textContent,
    time: u.linked,
    own: u.series.slice(1).filter((s) => !/kept run/.test(s.label)).map((s) => ({ label: s.label, dash: s.dash || null, width: s.width, stroke: typeof s.stroke === 'function' ? s.stroke(u, 1) : s.stroke })),
    kept: u.series.slice(1).filter((s) => /kept run/.test(s.label)).map((s) => ({ label: s.label, dash: s.dash || null })),
    legend: items.map((li) => ({ text: li.textContent, kept: li.classList.contains('legend-kept'), shown: li.style.visibility !== 'hidden', dash: li.querySelector('line').getAttribute('stroke-dasharray'), width: Number(li.querySelector('line').getAttribute('stroke-width')), stroke: li.querySelector('line').getAttribute('stroke') })),
    legendH: x.querySelector('.legend').getBoundingClientRect().height,
  };
}));
// Where the lesson's live view and each plot's legend are on the page [px].
const layout = (p) => p.evaluate(() => ({ live: document.getElementById('live').getBoundingClientRect().top + window.scrollY, legends: [...document.querySelectorAll('#plots .legend')].map((l) => l.getBoundingClientRect().height) }));

// One meaning per mark, in a lesson: before and after a change (the run before kept).
function marksAgree(ms, keptExpected, where) {
  assert(ms.length >= 1, `${where}: no plot`);
  for (const m of ms) {
    for (const s of m.own) assert(s.dash === null, `${where}, ${m.title}: the run's own line "${s.label}" is dashed ${JSON.stringify(s.dash)}`);
    const own = m.legend.filter((l) => !l.kept);
    assert(own.length === m.own.length, `${where}, ${m.title}: ${own.length} legend entries for ${m.own.length} lines`);
    own.forEach((l, i) => assert(l.dash === null && l.stroke === m.own[i].stroke && l.width === m.own[i].width, `${where}, ${m.title}: the legend draws "${l.text}" as ${l.stroke} ${l.width} px dash ${l.dash}, the plot ${m.own[i].stroke} ${m.own[i].width} px`));
    // Two lines of one colour are told apart by width.
    for (let i = 0; i < m.own.length; i++) for (let j = i + 1; j < m.own.length; j++) {
      assert(m.own[i].stroke !== m.own[j].stroke || m.own[i].width !== m.own[j].width, `${where}, ${m.title}: "${m.own[i].label}" and "${m.own[j].label}" look the same`);
    }
    const key = m.legend.filter((l) => l.kept);
    assert(key.length === 1, `${where}, ${m.title}: ${key.length} entries for the run before`);
    assert(key[0].shown === keptExpected && key[0].dash, `${where}, ${m.title}: the run before's entry shown ${key[0].shown} (expected ${keptExpected}), dash ${key[0].dash}`);
    if (keptExpected) {
      assert(m.kept.length === m.own.length && m.kept.every((s) => s.dash), `${where}, ${m.title}: kept lines ${JSON.stringify(m.kept)}`);
      assert(/run before/.test(key[0].text), `${where}, ${m.title}: the key says "${key[0].text}"`);
    }
  }
}

for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: a lesson's own lines are solid, the run before is the only dashed mark, its one legend key keeps its place: the legend and the live view do not move after a change (screenshots)`, async () => {
    const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
    for (const name of ['waves', 'power']) {
      const p = await open(`${base}#lesson=${name}`, c);
      await idle(p);
      await p.click('#lesson-a0');
      await p.waitForFunction(() => document.querySelector('#lesson-observe p'), null, { timeout: 60000 });
      await done(p);
      await p.waitForTimeout(200);
      marksAgree(await marks(p), false, `${name} first run`);
      const l0 = await layout(p);
      await stepFirst(p);
      marksAgree(await marks(p), true, `${name} after a change`);
      if (name === 'waves') {
        // Redrawn with the run before (dashed) on it, the h/R plot's levels, band edges and event
        // markers are stroked solid (uPlot left the kept lines' dash on the canvas before).
        const strokes = await p.$eval('#plots .chart', async (c) => {
          const u = c.uplot, ctx = u.ctx, seen = [], stroke = ctx.stroke;
          ctx.stroke = function (...a) { seen.push({ style: String(ctx.strokeStyle), dash: ctx.getLineDash().length }); return stroke.apply(this, a); };
          // uPlot draws on its next commit: wait a frame, twice (the second redraw inherits the
          // first's last pattern).
          for (let k = 0; k < 2; k++) { u.redraw(false, true); await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 30))); }
          ctx.stroke = stroke;
          return seen;
        });
        const marksDrawn = strokes.filter((x) => ['#b03a2e', '#7b241c', '#4a0f0a', '#a04000'].includes(x.style));
        assert(marksDrawn.length >= 4 && marksDrawn.every((x) => x.dash === 0), `h/R plot: ${marksDrawn.filter((x) => x.dash).length} of ${marksDrawn.length} level, band or event strokes dashed`);
        assert(strokes.some((x) => x.dash > 0), 'h/R plot: the run before is not drawn dashed');
      }
      const l1 = await layout(p);
      assert(Math.abs(l1.live - l0.live) <= 1 && l1.legends.every((x, i) => Math.abs(x - l0.legends[i]) <= 1),
        `${name}: after a change the live view moved from ${Math.round(l0.live)} to ${Math.round(l1.live)} px, the legends from ${l0.legends.map(Math.round)} to ${l1.legends.map(Math.round)} px`);
      if (name === 'waves') await p.screenshot({ path: `${shots}/marks-lesson-${w}x${h}.png`, fullPage: w < 600 });
      const v = await axeFindings(p);
      assert(!v.length, v.join(' | '));
      await p.close();
    }
    await c.close();
  });
}

await check('the Lab: every time plot of head seas draws its own lines solid; one spelling (disc); the stern picture\'s thrust words agree with beta_T', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(`${base}#v=2&preset=head-seas-ss6`, c);
  const st = await pressAndWait(p);
  assert(/^Done/.test(st), st);
  await p.$eval('#more-plots-box', (d) => { d.open = true; });
  await p.waitForTimeout(300);
  // The run's plots over time (the RAOs after a run in waves are the hull's, not the run's).
  for (const m of [...await marks(p), ...await marks(p, '#more-plots')].filter((x) => x.time)) {
    for (const s of m.own) assert(s.dash === null, `${m.title}: "${s.label}" is dashed`);
    for (let i = 0; i < m.own.length; i++) for (let j = i + 1; j < m.own.length; j++) assert(m.own[i].stroke !== m.own[j].stroke || m.own[i].width !== m.own[j].width, `${m.title}: two lines look the same`);
  }
  // One spelling: the page's words and the h/R plot's levels (pageConstants) say disc.
  const words = await p.evaluate(() => document.body.innerText + JSON.stringify(window.__liveViews.k.h_over_r_levels));
  assert(!/\bdisks?\b/i.test(words), `"disk" on the page: ${(words.match(/.{0,40}\bdisks?\b.{0,40}/i) || [''])[0]}`);
  assert(/disc/.test(words), 'no "disc" on the page');
  // The stern picture at the run's lowest beta_T and at a row with all thrust kept.
  const said = await p.evaluate(() => {
    const L = window.__liveViews, b = L.cols.beta_t;
    let lo = 0, hi = 0;
    for (let i = 0; i < b.length; i++) { if (b[i] < b[lo]) lo = i; if (b[i] > b[hi]) hi = i; }
    return [lo, hi].map((i) => { L.seek(L.cols.t_s[i]); return { beta: b[i], text: L.drawn.stern.thrust_text }; });
  });
  for (const { beta, text } of said) {
    const want = beta < 0.005 ? 'no thrust left' : beta >= 0.995 ? 'all its thrust' : `${(100 * beta).toFixed(0)} % of its thrust`;
    assert(text === `β_T ${beta.toFixed(2)}: ${want}`, `beta_T ${beta}: the stern picture says "${text}"`);
    assert(!(beta < 0.005 && /kept/.test(text)), `no thrust, yet "${text}"`);
  }
  console.log(`     the stern picture says "${said[0].text}" and "${said[1].text}"`);
  await c.close();
});

await check('power and energy fields show MW and MJ (the scenario keeps W and J): a storage of 100 MJ and 5 MW typed runs as 1e8 J and 5e6 W', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(`${base}#v=2&preset=head-seas-ss6-storage`, c);
  const labels = await p.$$eval('#controls .field label', (ls) => ls.map((l) => l.textContent));
  const units = labels.flatMap((l) => (l.match(/\[([^\]]+)\]/) || [])[1] || []);
  assert(!units.includes('W') && !units.includes('J'), `fields in W or J: ${labels.filter((l) => /\[(W|J)\]/.test(l)).join(', ')}`);
  const energy = await p.$eval('label[for="f-plant-storage-energy_j"]', (l) => l.textContent);
  assert(/\[MJ\]/.test(energy), energy);
  const sc0 = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(Number(await p.inputValue('#f-plant-storage-energy_j')) === sc0.plant.storage.energy_j / 1e6, `energy shown ${await p.inputValue('#f-plant-storage-energy_j')} for ${sc0.plant.storage.energy_j} J`);
  assert(/MW\./.test(await p.textContent('#f-plant-storage-power_w-help')), await p.textContent('#f-plant-storage-power_w-help'));
  await setField(p, 'plant.storage.energy_j', 100);
  await setField(p, 'plant.storage.power_w', 5);
  const sc = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(sc.plant.storage.energy_j === 1e8 && sc.plant.storage.power_w === 5e6, `the scenario holds ${sc.plant.storage.energy_j} J and ${sc.plant.storage.power_w} W`);
  assert(!(await p.getAttribute('#f-plant-storage-energy_j', 'aria-invalid')), 'the field is marked invalid');
  await c.close();
});

await check('one rudder sign (+ turns to port): the heading plot, the booklet\'s zig-zag and the live view say it alike; the turning circle has axes in ship lengths and a scale in metres (screenshots)', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await open(`${base}#v=2&preset=turn-360`, c);
  const st = await pressAndWait(p);
  assert(/^Done/.test(st), st);
  const plot = (await marks(p)).concat(await marks(p, '#more-plots')).find((m) => m.title.startsWith('Heading and rudder'));
  assert(plot && plot.own.some((s) => s.label === 'rudder (+ to port)'), `the heading plot's lines: ${plot && plot.own.map((s) => s.label)}`);
  const key = await p.$$eval('#plots .plot, #more-plots .plot', (ps) => ps.find((x) => x.querySelector('h3').textContent.startsWith('Heading and rudder')).querySelector('.key').textContent);
  assert(/\+ turns the ship to port/.test(key), `the heading plot's key: ${key}`);
  // The live view at the run's most negative rudder (a turn to starboard) and its text.
  const live = await p.evaluate(() => {
    const L = window.__liveViews, r = L.cols.rudder_deg;
    let k = 0;
    for (let i = 0; i < r.length; i++) if (r[i] < r[k]) k = i;
    L.seek(L.cols.t_s[k]);
    L.text.textContent = L.describe();
    return { rudder: r[k], text: L.text.textContent };
  });
  assert(live.rudder < -1, `the turn's rudder goes down to ${live.rudder}`);
  assert(live.text.includes(`rudder −${Math.abs(live.rudder).toFixed(1)}° (to starboard)`), `at ${live.rudder.toFixed(1)}° the live text says ${live.text}`);
  // The booklet: its zig-zag's rudder drawn in the same sign, the turning circle with axes.
  await p.$eval('#maneuvers-box', (e) => { e.open = true; });
  await p.click('#maneuvers-compute');
  await p.waitForFunction(() => /^Done/.test(document.getElementById('maneuvers-status').textContent), null, { timeout: 60000 });
  await p.waitForTimeout(300);
  const z = await p.evaluate(() => {
    const b = window.__maneuvers, u = document.querySelector('#maneuvers-plots .chart').uplot;
    const i = u.series.findIndex((s) => /rudder/.test(s.label));
    return { label: u.series[i].label, drawn: Array.from(u.data[i].slice(0, 400)), booklet: b.zigzag_10.track.slice(0, 400).map((s) => s.rudder_deg), key: document.querySelector('#maneuvers-plots .plot:nth-child(2) .key').textContent };
  });
  assert(z.label === 'rudder (+ to port) [deg]' && /\+ turns the ship to port/.test(z.key), `the zig-zag's rudder: ${z.label}; ${z.key}`);
  assert(z.drawn.every((v, i) => v === -z.booklet[i]) && z.booklet.some((v) => v !== 0), 'the zig-zag\'s rudder is not the booklet\'s in the model\'s sign');
  const axes = await p.$eval('#maneuvers-plots canvas.track', (cv) => ({ ...cv.drawnAxes, shownH: cv.getBoundingClientRect().height }));
  assert(axes && axes.tick_l > 0 && axes.scale_m > 0, `the turning circle's axes: ${JSON.stringify(axes)}`);
  // One metre is as long across as up: the picture is shown at the height it is drawn for.
  assert(Math.abs(axes.shownH - axes.h) < 0.5, `the turning circle is drawn ${axes.h} px high and shown ${axes.shownH} px`);
  const L = await p.evaluate(() => window.__maneuvers.length_m);
  assert(Math.abs(axes.scale_px - (axes.scale_m / L) * axes.px_per_l) < 1e-6 && axes.scale_px > 20, `the scale bar: ${axes.scale_m} m drawn ${axes.scale_px} px at ${axes.px_per_l} px per ship length`);
  for (const [w, h] of SIZES) {
    await p.setViewportSize({ width: w, height: h });
    await p.waitForTimeout(400);
    await p.locator('#maneuvers-plots .plot').first().screenshot({ path: `${shots}/marks-turning-circle-${w}x${h}.png` });
  }
  await c.close();
});

await check('a lesson opened from the index opens at its top (the index scrolled to its end first)', async () => {
  for (const [w, h] of [[1366, 768], [390, 844]]) {
    const c = await browser.newContext({ viewport: { width: w, height: h }, hasTouch: w < 600 });
    const p = await open(`${base}#lessons`, c);
    await p.evaluate(() => window.scrollTo(0, document.body.scrollHeight));
    const y0 = await p.evaluate(() => window.scrollY);
    await p.locator('.lesson-list a').last().click();
    await p.waitForFunction(() => document.getElementById('lesson-title'), null, { timeout: 30000 });
    await idle(p);
    const r = await p.$eval('#lesson-title', (e) => ({ top: e.getBoundingClientRect().top, scroll: window.scrollY }));
    assert(r.top >= 0 && r.top < 300, `at ${w}x${h} (the index scrolled to ${Math.round(y0)} px) the lesson's title is at ${Math.round(r.top)} px on the screen (scroll ${Math.round(r.scroll)})`);
    await c.close();
  }
});

await check('on a 390x844 phone the verdict is in view after the run, with the controls (pinned at the foot of the screen)', async () => {
  const c = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, bypassCSP: true });
  const p = await open(`${base}#lesson=waves`, c);
  await idle(p);
  await p.click('#lesson-a1');
  await p.waitForFunction(() => document.querySelector('#lesson-observe p'), null, { timeout: 60000 });
  await done(p);
  const verdict = async () => p.evaluate(() => {
    const e = document.getElementById('lesson-verdict') || document.querySelector('#lesson-observe .lesson-verdict');
    if (!e) return null;
    const r = e.getBoundingClientRect(), ctl = document.querySelector('#lesson-controls [data-path]').getBoundingClientRect();
    return { top: r.top, bottom: r.bottom, vh: window.innerHeight, text: e.textContent, control: ctl.bottom };
  });
  const v = await verdict();
  assert(v && v.top >= 0 && v.bottom <= v.vh, `the verdict is at ${v && Math.round(v.top)} to ${v && Math.round(v.bottom)} px of ${v && v.vh}`);
  assert(v.control <= v.top, `the verdict covers the control (control ends ${Math.round(v.control)}, verdict from ${Math.round(v.top)})`);
  await p.screenshot({ path: `${shots}/marks-verdict-390x844.png` });
  // After a change: the verdict on the change (once the lessons say one) is in view too.
  await stepFirst(p);
  const after = await verdict();
  if (after) assert(after.top >= 0 && after.bottom <= after.vh, `after a change the verdict is at ${Math.round(after.top)} px`);
  const a = await axeFindings(p);
  assert(!a.length, a.join(' | '));
  await c.close();
});

await check('presentation mode at 1366x768: every lesson shows its question, controls, plot, words and "Try this next" without scrolling; at 1920x1080 too; axis type larger than the desk\'s (screenshots)', async () => {
  const bad = [];
  for (const [w, h] of [[1366, 768], [1920, 1080]]) {
    const c = await browser.newContext({ viewport: { width: w, height: h } });
    const p = await open(`${base}#lessons`, c);
    const names = await p.$$eval('.lesson-list a', (a) => a.map((x) => x.getAttribute('href').slice('#lesson='.length)));
    await p.click('#present');
    for (const name of names) {
      await p.goto(`${base}#lesson=${name}`);
      await p.waitForFunction(() => document.body.classList.contains('lesson-waiting') && document.getElementById('lesson-q'), null, { timeout: 30000 });
      await idle(p);
      await p.click('#lesson-a0');
      await p.waitForFunction(() => document.querySelector('#lesson-observe .lesson-next'), null, { timeout: 60000 });
      await done(p);
      await p.waitForTimeout(300);
      const r = await p.evaluate(() => {
        const box = (sel) => { const e = document.querySelector(sel); const b = e.getBoundingClientRect(); return { top: b.top, bottom: b.bottom }; };
        const u = document.querySelector('#plots .chart').uplot;
        return { scroll: window.scrollY, q: box('#lesson-q'), controls: box('#lesson-controls'), plot: box('#plots .plot'), words: box('#lesson-observe .lesson-explain'), next: box('#lesson-observe .lesson-next'), tick: u.axes[0].font[2], presenting: document.body.classList.contains('presenting') };
      });
      const parts = ['q', 'controls', 'plot', 'words', 'next'];
      const out = parts.filter((k) => r[k].top < 0 || r[k].bottom > h);
      if (!r.presenting) bad.push(`${name} at ${w}: not presenting`);
      if (out.length) bad.push(`${name} at ${w}x${h}: ${out.map((k) => `${k} ${Math.round(r[k].top)}-${Math.round(r[k].bottom)}`).join(', ')}`);
      // Desk-mode ticks are 12 px (e2e.mjs checks them).
      if (!(r.tick > 12)) bad.push(`${name}: axis type ${r.tick} px`);
      if (name === 'waves' || name === 'battery') await p.screenshot({ path: `${shots}/marks-presenting-${name}-${w}x${h}.png` });
    }
    await c.close();
  }
  assert(!bad.length, bad.join('; '));
});

await finish(browser, errors);
