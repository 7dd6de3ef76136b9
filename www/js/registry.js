// The scenario parameters' declarations (the wasm's paramMeta: labels, units, ranges, choices),
// set once when the worker is ready; the page copies none of them.
let byPath = new Map();
let renamedPaths = [];

export function setRegistry(meta) {
  byPath = new Map(meta.params.map((m) => [m.path, m]));
  renamedPaths = meta.renamed || [];
}

// A scenario (or the part of one a link or a file carries) with every field that has an old name
// (sim.dt_s) moved to its new path (stepping.dt_s), as the wasm's reader does; a field given under
// both names keeps both, and the reader refuses it.
export function migrate(sc) {
  if (!sc || typeof sc !== 'object' || Array.isArray(sc)) return sc;
  const out = JSON.parse(JSON.stringify(sc));
  for (const [from, to] of renamedPaths) {
    const [fs, fk] = from.split('.'), [ts, tk] = to.split('.');
    const src = out[fs];
    if (!src || typeof src !== 'object' || !(fk in src)) continue;
    const dst = out[ts] = out[ts] && typeof out[ts] === 'object' ? out[ts] : {};
    if (tk in dst) continue;
    dst[tk] = src[fk];
    delete src[fk];
    if (!Object.keys(src).length) delete out[fs];
  }
  return out;
}

// The declaration of a parameter by its dotted path.
export function param(path) { return byPath.get(path); }

// The label of a choice's value (a hull's name: "DTMB 5415 (destroyer, 142 m)"), or the value.
export function choiceLabel(path, value) {
  const c = byPath.get(path)?.choices?.find((x) => x.value === value);
  return c ? c.label : value;
}
