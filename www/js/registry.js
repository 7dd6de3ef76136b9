// The scenario parameters' declarations (the wasm's paramMeta: labels, units, ranges, choices),
// set once when the worker is ready; the page copies none of them.
let byPath = new Map();

export function setRegistry(meta) { byPath = new Map(meta.params.map((m) => [m.path, m])); }

// The declaration of a parameter by its dotted path.
export function param(path) { return byPath.get(path); }

// The label of a choice's value (a hull's name: "DTMB 5415 (destroyer, 142 m)"), or the value.
export function choiceLabel(path, value) {
  const c = byPath.get(path)?.choices?.find((x) => x.value === value);
  return c ? c.label : value;
}
