// Lessons (issue 30): the simulator's own runs, plots and live views behind a few controls. A
// lesson's address (#lessons, #lesson=NAME&...) is this view's: it opens the index or the lesson,
// and any other address leaves it. Every settled control value is an entry of the page's history:
// Back and Forward move the controls and bring their run back, inside the lesson.
import { DEFAULT_PRESET } from '../config.js';
import { $ } from '../dom.js';
import { setPhase, isBusy, getResult, status, announce } from '../state.js';
import { linkHash } from '../link.js';
import { setPath } from '../form.js';
import { REQUEST } from '../protocol.js';
import { LessonView, readLessonHash } from '../lessons/view.js';
import { registerView } from '../views.js';

let lessons = null; // the LessonView, once the worker is ready
let meta = []; // the wasm's lessonMeta
let pending = null; // a run asked for while one was in flight: {settled}; the last asked wins
const answered = new Set(); // lessons answered in this visit: Back and Forward do not ask again
let opening = 0; // the latest open: an older one still waiting for the worker gives way
let settledAt = 0; // when the control was released (the latency runs from there, waits included)

const getPath = (o, path) => path.split('.').reduce((x, k) => (x == null ? undefined : x[k]), o);
// A control's value is text (a link's: "2.65", "diode", "[1,3]"); the scenario keeps the type it
// has there: a number, or a list or object as JSON (the sets running, `plant.online.sets`). Text
// put where a list belongs would make the run refuse the scenario.
const typed = (was, x) => {
  if (typeof was === 'number') return Number(x);
  if (was !== null && typeof was === 'object' && typeof x === 'string') return JSON.parse(x);
  return x;
};
const labHref = (form) => linkHash(form.name, form.preset(), form.scenario);

// The live views follow the plots in the lesson's Tab order (controls, plot, live picture); the
// Lab keeps them above the plots.
function placeLive(inLesson) {
  if (inLesson) $('plots').after($('live'));
  else $('plots').before($('live'));
}

const SEEN = 'aes-sim-lessons-seen';
function seenLessons() { try { return localStorage.getItem(SEEN) === '1'; } catch (_) { return true; } }

// Shows the lessons' index or one lesson (parsed: readLessonHash's answer).
async function openLesson(ctx, parsed) {
  const { form } = ctx;
  try { localStorage.setItem(SEEN, '1'); } catch (_) { /* private mode: the link stays */ }
  $('start-here-box').hidden = true;
  const mine = ++opening;
  ctx.selectTab('tab-sim', false, false);
  // The lessons are not the Simulator tab: no tab is marked current, the Lessons link is.
  for (const t of document.querySelectorAll('#tabs [role="tab"]')) t.setAttribute('aria-selected', 'false');
  $('lessons-link').setAttribute('aria-current', 'page');
  document.body.classList.add('lesson');
  placeLive(true);
  pending = null;
  ctx.forgetChecks();
  if (parsed.index) {
    ctx.setLesson(null);
    ctx.keep(null);
    document.body.classList.remove('lesson-waiting', 'lesson-answered');
    document.body.dataset.lessonView = '';
    lessons.showIndex(parsed.unknown);
    ctx.clearResults();
    status(parsed.unknown ? 'No such lesson: pick one.' : 'Pick a lesson.');
    return;
  }
  const def = parsed.def;
  let o;
  try {
    o = await ctx.client.request(REQUEST.lessonOpen, { name: def.name, values: parsed.values });
  } catch (e) { status(e.message, true); return; }
  if (mine !== opening) return;
  const same = ctx.lesson && ctx.lesson.def.name === def.name && lessons.def === def;
  ctx.setLesson({ def, defaults: o.defaults });
  form.select(def.preset, JSON.parse(o.scenario));
  ctx.setMode('run');
  document.body.dataset.lessonView = def.view;
  if (same) lessons.setValues(o.values);
  else {
    ctx.keep(null);
    ctx.clearResults();
    lessons.open(def, o, labHref(form), answered.has(def.name));
    // Another lesson opens at its top, not at the index's scroll.
    window.scrollTo(0, 0);
  }
  history.replaceState(history.state, '', lessons.hash(o.defaults));
  const done = answered.has(def.name);
  document.body.classList.toggle('lesson-waiting', !done);
  document.body.classList.toggle('lesson-answered', done);
  if (!done) {
    // The scene moves before the question is answered: the default run plays in the live
    // picture; its plots and words wait for the answer.
    status(`${def.title}: answer the question (or "Just run it") to see the plots.`);
    lessonRun(ctx, true);
    return;
  }
  // Back or Forward within the lesson: the run of these values, drawn again or run again.
  if (ctx.restoreResult()) explainShown(ctx);
  else lessonRun(ctx, true);
}

function leaveLesson(ctx) {
  ctx.setLesson(null);
  ctx.keep(null);
  document.body.classList.remove('lesson', 'lesson-waiting', 'lesson-answered');
  $('lessons-link').removeAttribute('aria-current');
  ctx.selectTab('tab-sim', false, false);
  placeLive(false);
  $('lesson-box').replaceChildren();
  $('lesson-explain').replaceChildren();
}

// The shown run's explanation, and the live picture at the instant its words quote.
function explainShown(ctx) {
  const res = getResult();
  const { lesson } = ctx;
  if (!lesson || !res || !res.columns || res.study !== lesson.def.preset || !res.lesson) return;
  // The screen stays where the hand is: the control being moved and the plot do not scroll away.
  if (lessons.isAnswered) {
    lessons.explain(res.lesson, res.lessonValues);
    ctx.live.pause();
    ctx.live.place({ at: res.lesson.at_s, speed: 2 }, { scroll: false });
    return;
  }
  // Before the answer the default run plays from its start, about half a minute through (held
  // still where the system asks for reduced motion).
  const t = res.summary.final_time_s;
  ctx.live.place({ at: 0, speed: Math.max(1, t / 30) }, { scroll: false }).then(() => {
    if (!matchMedia('(prefers-reduced-motion: reduce)').matches && ctx.lesson && !lessons.isAnswered) ctx.live.start();
  });
}

// A lesson's run: the settled one before stays drawn faintly; at most one in flight, the last
// asked wins. settled: a released control (the run the history and the words are of); else a
// preview while dragging.
async function lessonRun(ctx, settled = true) {
  if (!ctx.lesson) return;
  if (isBusy()) { pending = { settled: settled || (pending && pending.settled) }; return; }
  const r = getResult();
  if (settled || !ctx.kept) ctx.keep(r && r.columns && !r.preview ? { name: 'the run before', columns: r.columns, summary: r.summary } : ctx.kept);
  const asked = settledAt || performance.now();
  if (settled) settledAt = 0;
  const { def } = ctx.lesson;
  // A preview while dragging runs the start of the story, short enough for several a second (the
  // last settled run's pace); the release runs it whole, with its words.
  const preview = settled ? null : previewSeconds(r, ctx.form.scenario.sim.duration_s);
  // A settled run carries the run before (its values, reading and the answer) for core's verdict.
  const values = lessons.values();
  const before = lessons.referenceRun();
  await ctx.run({ focus: false, order: def.plots, lesson: settled ? { name: def.name, values, ...(before ? { before } : {}) } : null, preview });
  const res = getResult();
  if (res && res.columns && ctx.lesson) {
    res.preview = !settled;
    res.lessonValues = values;
    if (settled) {
      announce('lessonRun', { latencyMs: performance.now() - asked }); // release to plot
      explainShown(ctx);
    } else announce('lessonPreview', null);
  }
  if ($('lesson-lab')) $('lesson-lab').href = labHref(ctx.form);
  if (pending) { const p = pending; pending = null; lessonRun(ctx, p.settled); }
}

// Simulated seconds of a preview: a run of about PREVIEW_MS at the pace of the run shown (whole
// seconds; at least a tenth of the story, at most all of it).
const PREVIEW_MS = 120;
function previewSeconds(r, full) {
  if (!r || !r.summary || !r.wallMs) return full;
  const pace = r.summary.final_time_s / r.wallMs;
  return Math.min(full, Math.max(Math.ceil(full / 10), Math.round(pace * PREVIEW_MS)));
}

registerView({
  id: 'lessons',
  ready(ctx, m) {
    const { form } = ctx;
    meta = m.lessons;
    // Until the lessons have been opened once, the Lab shows the way to them first.
    $('start-here-box').hidden = seenLessons();
    lessons = new LessonView(meta, {
      // path null: several values set at once ("Set it" of Try this next).
      onChange: (path, v, settled) => {
        const { def } = ctx.lesson;
        const values = lessons.values();
        for (const c of def.controls) {
          if (path !== null && c.path !== path) continue;
          const x = values[c.path];
          for (const p of [c.path, ...c.with_paths]) setPath(form.scenario, p, typed(getPath(form.scenario, p), x));
          if (c.kind === 'toggle') for (const [q, y] of c.settings[c.values.indexOf(String(x))] || []) setPath(form.scenario, q, typed(getPath(form.scenario, q), y));
        }
        // A settled value is a step in the history (Back returns to the one before).
        // (Values that change nothing, "Set it" of values already set, are no step.)
        if (settled) {
          settledAt = performance.now();
          const h = lessons.hash(ctx.lesson.defaults);
          if (location.hash !== h) history.pushState({ shown: null }, '', h);
        }
        lessonRun(ctx, settled);
      },
      // The default run is there (or on its way): its plots and words now show.
      onAnswer: () => {
        answered.add(ctx.lesson.def.name);
        document.body.classList.remove('lesson-waiting');
        document.body.classList.add('lesson-answered');
        const r = getResult();
        if (r && r.lesson && ctx.restoreResult()) explainShown(ctx); else if (!isBusy()) lessonRun(ctx, true);
      },
    });
  },
  // first: the page's start, with the form's study not chosen yet.
  route(ctx, hash, first) {
    const parsed = readLessonHash(hash, meta);
    if (!parsed) {
      if (document.body.classList.contains('lesson')) leaveLesson(ctx);
      return false;
    }
    if (first) {
      ctx.form.select(DEFAULT_PRESET);
      setPhase('idle');
    }
    openLesson(ctx, parsed);
    return true;
  },
  hash: (ctx) => (ctx.lesson && lessons.def ? lessons.hash(ctx.lesson.defaults) : null),
});
