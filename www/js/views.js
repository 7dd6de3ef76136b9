// The page's views: each tab, fold and result view registers itself here, in its own module (its
// DOM, its wiring and what it does on the page's events), and main.js calls the hooks of every view
// that has them, in the order the views were imported. A view is an object:
//   id                  its name (for reading only)
//   tab, skip           the tab it owns (tab-NAME, whose aria-controls names its panel) and where
//                       "Skip to the results" goes while it is shown
//   mode, button        a kind of result of the address besides one run ('mc'), and the button
//                       that computes it (said in the status line)
// and any of these hooks, each given the page's context (main.js's ctx) first:
//   init(ctx)           at start-up, before the simulator loads: build its DOM, make its objects
//   ready(ctx, meta)    the simulator is loaded and the form made (meta: the worker's ready message)
//   route(ctx, hash, first)  an address it owns (a lesson): open it and answer true
//   hash(ctx)           the address while it owns the page, else null
//   restore(ctx, link)  a link was opened (null: none, or refused): take its part of the state
//   linkState(ctx)      what it adds to the address ({design})
//   linked(ctx)         a link opened afresh on its tab: do the tab's work (as a link to a run runs)
//   again(ctx)          compute its mode's result of the form's values
//   selected(ctx)       another study in the form
//   edited(ctx)         an edit of the form's values (before their check)
//   checked(ctx)        the form's values passed the check
//   sync(ctx)           after any change of the inputs or the drawn result
//   drawRun(ctx, m, name)  a run was drawn (m: the worker's answer; name: the run's legend name)
//   shown(ctx)          its tab was shown
//   cancel(ctx)         Cancel was pressed (the worker is replaced next)
const views = [];

export function registerView(view) {
  views.push(view);
  return view;
}

// Calls the hook of every view that has it.
export function each(hook, ...args) {
  for (const v of views) if (v[hook]) v[hook](...args);
}

// The first truthy answer of a hook, else null.
export function first(hook, ...args) {
  for (const v of views) {
    const r = v[hook] && v[hook](...args);
    if (r) return r;
  }
  return null;
}

// The answers of a hook merged into one object.
export const merged = (hook, ...args) => Object.assign({}, ...views.filter((v) => v[hook]).map((v) => v[hook](...args)));

export const tabView = (name) => views.find((v) => v.tab === name) || null;
export const modeView = (mode) => views.find((v) => v.mode === mode) || null;
