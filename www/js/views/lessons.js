// Lessons (issue 30): the simulator's own runs, plots and live views behind a few controls. A
// lesson's address (#lessons, #lesson=NAME&...) is this view's: it opens the index or the lesson,
// and any other address leaves it.
import { DEFAULT_PRESET } from '../config.js';
import { $ } from '../dom.js';
import { setPhase, isBusy, getResult, status } from '../state.js';
import { linkHash } from '../link.js';
import { setPath } from '../form.js';
import { LessonView, readLessonHash, controlPath } from '../lessons/view.js';
import { registerView } from '../views.js';

let lessons = null; // the LessonView, once the registry is there
let pending = false; // a control moved while a run was in flight: run again after it

// The lesson's study with its settings, as the lesson starts from it.
function lessonScenario(form, def) {
  const sc = form.preset(def.preset);
  for (const [p, v] of Object.entries(def.set)) setPath(sc, p, v);
  return sc;
}
const labHref = (form) => linkHash(form.name, form.preset(), form.scenario);

// Shows the lessons' index or one lesson (parsed: readLessonHash's answer).
function openLesson(ctx, parsed) {
  const { form } = ctx;
  ctx.selectTab('tab-sim', false, false);
  document.body.classList.add('lesson');
  ctx.kept = null;
  pending = false;
  ctx.forgetChecks();
  if (parsed.index) {
    ctx.lesson = null;
    document.body.dataset.lessonView = '';
    lessons.showIndex(parsed.unknown);
    ctx.clearResults();
    status(parsed.unknown ? 'No such lesson: pick one.' : 'Pick a lesson.');
    return;
  }
  const def = parsed.def;
  const sc0 = lessonScenario(form, def);
  const sc = JSON.parse(JSON.stringify(sc0));
  for (const c of def.controls) {
    const p = controlPath(c), v = lessons.value(c, parsed.values[p], sc0);
    setPath(sc, p, v);
    for (const [q, x] of Object.entries(lessons.also(c, v))) setPath(sc, q, x);
  }
  ctx.lesson = { def, scenario0: sc0 };
  form.select(def.preset, sc);
  ctx.mode = 'run';
  ctx.clearResults();
  document.body.dataset.lessonView = def.view;
  lessons.open(def, sc, labHref(form));
  history.replaceState(history.state, '', lessons.hash(sc0));
  status(`${def.title}: answer the question (or "Just run it") to run.`);
}

function leaveLesson(ctx) {
  ctx.lesson = null;
  ctx.kept = null;
  document.body.classList.remove('lesson');
  $('lesson-box').replaceChildren();
  $('lesson-explain').replaceChildren();
}

// A lesson's run: the one before stays drawn faintly; at most one in flight, the last asked wins.
async function lessonRun(ctx) {
  if (!ctx.lesson) return;
  if (isBusy()) { pending = true; return; }
  const r = getResult();
  ctx.kept = r && r.columns ? { name: 'the run before', columns: r.columns, summary: r.summary } : null;
  const asked = performance.now();
  await ctx.run({ focus: false, order: ctx.lesson.def.plots });
  const res = getResult();
  const { lesson } = ctx;
  if (lesson && res && res.columns && res.study === lesson.def.preset) {
    window.__lessonLatencyMs = performance.now() - asked; // for the browser test: control to plot
    lessons.explain(res.summary, res.markers || []);
    // The screen stays where the hand is: the control being moved and the plot do not scroll away.
    ctx.live.place({ at: lesson.def.at, speed: 2 }, { scroll: false });
  }
  if ($('lesson-lab')) $('lesson-lab').href = labHref(ctx.form);
  if (pending) { pending = false; lessonRun(ctx); }
}

registerView({
  id: 'lessons',
  ready(ctx, m) {
    const { form } = ctx;
    lessons = new LessonView(m.params, {
      onChange: (path, v, also = {}) => {
        setPath(form.scenario, path, v);
        for (const [q, x] of Object.entries(also)) setPath(form.scenario, q, x);
        history.replaceState(history.state, '', lessons.hash(ctx.lesson.scenario0));
        lessonRun(ctx);
      },
      onAnswer: () => lessonRun(ctx),
    });
    // For the browser test: the scenario a lesson runs, as text.
    window.__scenarioText = () => JSON.stringify(form.current());
  },
  // first: the page's start, with the form's study not chosen yet.
  route(ctx, hash, first) {
    const parsed = readLessonHash(hash);
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
  hash: (ctx) => (ctx.lesson ? lessons.hash(ctx.lesson.scenario0) : null),
});
