// Share links and the address bar: #v=2&preset=NAME&d=BASE64URL(JSON of what differs from the
// preset), optionally &mode=mc (the study's Monte Carlo view rather than one run), &tab=design|ips|operability
// (the tab shown), &design=BASE64URL(JSON of the design tab's tuning) and &at=SECONDS&speed=X
// (where the live views stand and how fast they play: a link opens the run there). Reading a link
// refuses, with a reason a person can act on, anything too long, too deep, damaged, from a newer
// page or naming an unknown study. Pure functions: no DOM, no worker (the caller validates).

import { migrate } from './registry.js';

// 2: the time step, its method and the sample periods moved into `stepping` (a link of version 1
// names them by their old paths and is read with them moved).
export const LINK_VERSION = 2;
export const MAX_LINK_CHARS = 16000;
export const MAX_LINK_DEPTH = 12;

function clone(x) { return JSON.parse(JSON.stringify(x)); }
const isObject = (x) => x && typeof x === 'object' && !Array.isArray(x);

// What differs in `cur` from `base` (undefined when nothing does); arrays are taken whole.
export function diff(base, cur) {
  if (JSON.stringify(base) === JSON.stringify(cur)) return undefined;
  if (isObject(base) && isObject(cur)) {
    const out = {};
    for (const k of Object.keys(cur)) {
      const d = diff(base[k], cur[k]);
      if (d !== undefined) out[k] = d;
    }
    return Object.keys(out).length ? out : undefined;
  }
  return cur;
}

export function merge(base, d) {
  if (isObject(d) && isObject(base)) {
    const out = clone(base);
    for (const k of Object.keys(d)) out[k] = merge(base[k], d[k]);
    return out;
  }
  return d;
}

// Nesting depth of JSON text, counted without parsing it (a hostile link cannot blow the stack).
export function depth(text) {
  let d = 0, max = 0, inStr = false, esc = false;
  for (const ch of text) {
    if (inStr) { if (esc) esc = false; else if (ch === '\\') esc = true; else if (ch === '"') inStr = false; continue; }
    if (ch === '"') inStr = true; else if (ch === '{' || ch === '[') { d++; max = Math.max(max, d); } else if (ch === '}' || ch === ']') d--;
  }
  return max;
}

export function b64urlEncode(s) {
  const bytes = new TextEncoder().encode(s);
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function b64urlDecode(s) {
  if (!/^[A-Za-z0-9_-]*$/.test(s)) throw new Error('the scenario part holds characters a link never has');
  const bin = atob(s.replace(/-/g, '+').replace(/_/g, '/'));
  return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
}

export const MODES = ['run', 'mc'];
export const TABS = ['sim', 'design', 'ips', 'operability'];

// The hash of a link to `scenario`, edited from preset `name` (whose scenario is `preset`);
// view: {at, speed} of the live views, or null; mode: 'run' or 'mc'; tab: one of TABS; design:
// the design tab's tuning when it differs from the declared defaults, else null.
export function linkHash(name, preset, scenario, { view = null, mode = 'run', tab = 'sim', design = null } = {}) {
  const d = diff(preset, scenario);
  let hash = `#v=${LINK_VERSION}&preset=${encodeURIComponent(name)}`;
  if (d !== undefined) hash += `&d=${b64urlEncode(JSON.stringify(d))}`;
  if (mode !== 'run') hash += `&mode=${mode}`;
  if (tab !== 'sim') hash += `&tab=${tab}`;
  if (design) hash += `&design=${b64urlEncode(JSON.stringify(design))}`;
  if (view) hash += `&at=${Number(view.at.toFixed(3))}&speed=${view.speed}`;
  return hash;
}

// A link's text as a message quotes it: at most 24 characters.
const quote = (x) => { const t = String(x); return `"${t.length > 24 ? `${t.slice(0, 24)}...` : t}"`; };

// The design tab's tuning in a link: an object of finite numbers (the tab checks their ranges),
// or null when absent or damaged (a bad part only loses the tuning, never the scenario: said in
// `ignored`).
function readDesign(params, ignored) {
  const d = params.get('design');
  if (!d) return null;
  const lost = () => { ignored.push('The link\'s design tab tuning (design=...) is damaged: the tab\'s own is used.'); return null; };
  if (d.length > 2000) return lost();
  try {
    const t = JSON.parse(b64urlDecode(d));
    if (!isObject(t) || !Object.values(t).every((x) => typeof x === 'number' && Number.isFinite(x))) return lost();
    return t;
  } catch (_) { return lost(); }
}

// The live views' place in a link: {at, speed} when both are sensible numbers, else null (a bad
// value only loses the place, never the scenario: said in `ignored`).
function readView(params, ignored) {
  if (!params.has('at')) return null;
  const at = Number(params.get('at')), speed = Number(params.get('speed') || 1);
  if (!(Number.isFinite(at) && at >= 0 && at <= 1e7 && Number.isFinite(speed) && speed > 0 && speed <= 1000)) {
    ignored.push(`The link's place in the live views (at=${quote(params.get('at'))}, speed=${quote(params.get('speed') || 1)}) is not used: at is a time from 0 to 1e7 s, speed a number above 0 up to 1000.`);
    return null;
  }
  return { at, speed };
}

// Reads a hash (without '#'): null when there is none, {refused: reason} when it cannot be used,
// else {name, scenario, view, mode, tab, design, ignored} (not yet validated; ignored: a sentence
// for each optional part that could not be used). `presets` maps names to scenario JSON text.
export function readLink(hash, presets) {
  if (!hash) return null;
  const refuse = (reason) => ({ refused: reason });
  if (hash.length > MAX_LINK_CHARS) return refuse(`it is ${hash.length} characters long (at most ${MAX_LINK_CHARS})`);
  const params = new URLSearchParams(hash);
  const v = Number(params.get('v'));
  if (!Number.isInteger(v) || v < 1) return refuse('it has no version number');
  if (v > LINK_VERSION) return refuse(`it was made by a newer version of aes-sim (link version ${v}, this page reads ${LINK_VERSION})`);
  const name = params.get('preset');
  if (!name || !Object.prototype.hasOwnProperty.call(presets, name)) return refuse(`it names an unknown study "${String(name).slice(0, 40)}"`);
  let scenario = JSON.parse(presets[name]);
  const d = params.get('d');
  if (d) {
    let text;
    try { text = b64urlDecode(d); } catch (e) { return refuse(`its scenario part is damaged (${e.message})`); }
    if (depth(text) > MAX_LINK_DEPTH) return refuse('its scenario is nested too deeply');
    let parsed;
    try { parsed = JSON.parse(text); } catch (_) { return refuse('its scenario part is not valid JSON (truncated?)'); }
    if (!isObject(parsed)) return refuse('its scenario part is not an object');
    scenario = merge(scenario, v < 2 ? migrate(parsed) : parsed);
  }
  const ignored = [];
  const choice = (key, allowed, fallback) => {
    if (!params.has(key) || allowed.includes(params.get(key))) return params.get(key) || fallback;
    ignored.push(`The link's ${key}=${quote(params.get(key))} is not one of ${allowed.join(', ')}: ${fallback} is used.`);
    return fallback;
  };
  const mode = choice('mode', MODES, 'run');
  const tab = choice('tab', TABS, 'sim');
  return { name, scenario, view: readView(params, ignored), mode, tab, design: readDesign(params, ignored), ignored };
}
