// The browser tests' view into the page (tests/e2e), loaded only for a page whose test set the
// flag `aesTestHooks` before it loaded: what the views showed, as window.__NAME, and a few readers.
// Nothing of the page reads these.
import { getResult, onAnnounce } from './state.js';

export function install(ctx) {
  // The live views: what was drawn, frame times and the playback rate (no pixel-peeping).
  window.__liveViews = ctx.live;
  // The scenario the form runs (a lesson's too), as text, and the words of the shown run.
  window.__scenarioText = () => JSON.stringify(ctx.form.current());
  window.__lessonWords = () => { const r = getResult(); return r && r.lesson ? r.lesson.sentences.map(([s]) => s).join(' ') : null; };
  onAnnounce((name, value) => {
    if (name === 'lessonRun') {
      // A lesson's settled run has landed: release to plot, and how many so far.
      window.__lessonLatencyMs = value.latencyMs;
      window.__lessonRuns = (window.__lessonRuns || 0) + 1;
    } else if (name === 'lessonPreview') {
      window.__lessonPreviews = (window.__lessonPreviews || 0) + 1;
    } else {
      // hullPanel, operability, rare, fuel, maneuvers, schedule, busmap (the
      // stability map) and busmapCell (its cell said): the last one shown.
      window[`__${name}`] = value;
    }
  });
}
