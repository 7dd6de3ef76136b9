// The results the page has drawn, the last few (for Back and Forward), each kept under the key of
// the state (mode, study and values) it belongs to: inputs and results come back together, and a
// result is never drawn under another study's inputs.
const DRAWN_MAX = 6;

export class Drawn {
  constructor() {
    this.results = new Map(); // key -> {key, state, study, redraw(), isCurrent?()}
    this.shown = null; // the key of the drawn result, or null
  }

  get(key) { return this.results.get(key); }

  // key: unique per result; state: the stateKey of the inputs it belongs to (a replayed Monte Carlo
  // trial belongs to its study's Monte Carlo state). extra: {isCurrent()} for a result that
  // belongs to something else than the form's values alone. It is the one drawn now.
  remember(key, state, redraw, extra = {}) {
    this.results.delete(key);
    this.results.set(key, { key, state, study: state.split('|')[1], redraw, ...extra });
    while (this.results.size > DRAWN_MAX) this.results.delete(this.results.keys().next().value);
    this.shown = key;
  }

  // The result drawn now, or null.
  current() { return (this.shown && this.results.get(this.shown)) || null; }
  // Whether the result drawn now is of `state`.
  shows(state) { const r = this.current(); return Boolean(r) && r.state === state; }

  // The result of a state: its own run or study first, else a trial replayed from it.
  of(state) { return this.results.get(state) || this.lastWhere((r) => r.state === state); }
  lastWhere(test) { return [...this.results.values()].reverse().find(test); }

  // Result r drawn (again, unless it is the one drawn now).
  show(r) {
    if (this.shown !== r.key) r.redraw();
    this.shown = r.key;
  }
}
