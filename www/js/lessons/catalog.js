// The words the lessons use, for the "Words used here" fold. The lessons themselves (controls,
// questions, the claims of each run) are core's (output::lessons), through the wasm's lessonMeta.
export const GLOSSARY = [
  ['h/R', 'the propeller hub\'s depth below the water surface divided by the propeller\'s radius; below 1 the disc breaks the surface'],
  ['pu', '"per unit": a value as a fraction of its rating (1 pu is the rated voltage, speed or power)'],
  ['sea state', 'a number for how rough the sea is (2: smooth, 3: moderate, 6: very rough)'],
  ['surface loss', 'a propeller drawing air or breaking the surface: it loses thrust and its motor races'],
  ['set', 'a gas turbine and the generator it turns; a set running burns fuel and shares the load with the others running'],
  ['fuel power', 'the fuel burnt each second times its heating value: the power the fuel brings, of which a gas turbine turns about 37 % into shaft power at its rating and less below it'],
  ['gain', 'how strongly a controller reacts to an error: proportional to the error now, or integral to the error summed over time'],
  ['crash stop', 'full astern ordered at once from full speed ahead: the shafts reverse while the ship still runs ahead, until it is dead in the water (no way ahead left) and then goes astern'],
  ['brake resistor', 'a resistor a chopper switches across the DC bus when its voltage rises too far: it burns the power the motors return as heat'],
  ['storage', 'a battery on a DC bus behind a DC-DC converter: it takes power from the bus (charging) or gives it, up to its power rating, between its lowest and highest allowed charge'],
];
