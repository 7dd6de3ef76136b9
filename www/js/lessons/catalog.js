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
];
