// Small DOM helpers shared by the page's modules.
export const $ = (id) => document.getElementById(id);

export function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'attrs') for (const [a, av] of Object.entries(v)) e.setAttribute(a, av);
    else e[k] = v;
  }
  e.append(...children);
  return e;
}

// A table row: a header cell, then data cells.
export function row(head, cells) {
  const tr = document.createElement('tr');
  tr.append(el('th', { scope: 'row', textContent: head }), ...cells.map((c) => el('td', { textContent: c })));
  return tr;
}

export function fmt(x, d = 4) { return x == null || Number.isNaN(x) ? '–' : Number(x).toPrecision(d); }

export function download(name, text, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

export function downloadUrl(name, href) {
  const a = document.createElement('a');
  a.href = href;
  a.download = name;
  a.click();
}
