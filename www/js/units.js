// Units and labels of recorded signals, from the wasm's signalMeta (sent in the worker's 'ready'
// message), and the per-unit bases from pageConstants. The page guesses no unit.

const PREFIX = { '': 1, k: 1e3, M: 1e6 };
// Units a metric prefix may go in front of.
const PREFIXABLE = new Set(['W', 'N', 'V', 'A', 'J']);

export class Signals {
  constructor(meta) {
    this.byName = new Map(meta.map((m) => [m.name, m]));
  }

  meta(name) {
    const m = this.byName.get(name);
    if (!m) throw new Error(`no signal '${name}' in signalMeta`);
    return m;
  }

  label(name) { return this.meta(name).label; }

  // Unit shown for a signal with an optional prefix ('k', 'M'): {unit, factor}.
  display(name, prefix = '') {
    return withPrefix(this.meta(name).unit, prefix);
  }

  // For a per-unit signal, what one unit is, e.g. "38 MW" (from pageConstants); null otherwise.
  puBase(name, constants) {
    const b = constants && constants.pu_bases && constants.pu_bases.find((x) => x.signal === name);
    return b ? quantity(b.value, b.unit) : null;
  }

  // The unit as shown: "kn", per unit with its base: "pu of 38 MW".
  unitText(name, constants) {
    const base = this.puBase(name, constants);
    return base ? `pu of ${base}` : this.display(name).unit;
  }

  // "label [unit]": "motor power [pu of 38 MW]".
  labelWithUnit(name, constants) { return `${this.label(name)} [${this.unitText(name, constants)}]`; }

  // A y-axis label (short: the title says what): "[pu of 38 MW]", dimensionless "h/R [-]".
  axisLabel(name, constants) {
    const unit = this.unitText(name, constants);
    return unit === '-' ? `${this.label(name)} [-]` : `[${unit}]`;
  }
}

// A unit with a metric prefix ('k', 'M') where one may go: {unit, factor} (value times factor).
export function withPrefix(unit, prefix = '') {
  if (!prefix || !PREFIXABLE.has(unit)) return { unit, factor: 1 };
  return { unit: prefix + unit, factor: 1 / PREFIX[prefix] };
}

// A value with its unit, with a metric prefix where one reads better: 38e6 W -> "38 MW".
export function quantity(value, unit) {
  let prefix = '';
  if (PREFIXABLE.has(unit)) prefix = Math.abs(value) >= 1e6 ? 'M' : Math.abs(value) >= 1e4 ? 'k' : '';
  const v = value / PREFIX[prefix];
  return `${Number(v.toPrecision(4))} ${prefix}${unit}`;
}

// The unit a form field shows for a parameter declared in `unit`, as the lessons write it: power
// in MW, energy in MJ (the scenario keeps SI). {unit, factor}: shown value = SI value times factor.
const FIELD_PREFIX = { W: 'M', J: 'M' };
export function fieldUnit(unit) { return withPrefix(unit, FIELD_PREFIX[unit] || ''); }
// A shown value back to SI, without the float noise of the division (21.5 MW is 21500000 W).
export function fromShown(x, factor) { return factor === 1 ? x : Number((x / factor).toPrecision(15)); }

// The page's one rudder sign (the model's: core's ship/rudder.rs), said under every plot of it.
export const RUDDER_SIGN = 'Rudder angle in the model\'s sign: + turns the ship to port, − to starboard (the live view says the side in words).';
