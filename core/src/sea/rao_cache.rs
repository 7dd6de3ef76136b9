//! RAO tables, built once per hull, grid and strip-theory switches and shared by every study
//! (runs in waves, Monte Carlo trials, the fuel study, repeated runs in the browser).

use crate::as_printed::AsPrintedParams;
use crate::sea::seakeeping::reflection::ShortWaveForce;
use crate::sea::seakeeping::tables::{ForEach, RaoTable, SeakeepingGrid};
use crate::ship::hull::ShipHull;
use std::sync::{Arc, Mutex, OnceLock};

/// A table is keyed by its hull (`ShipHull::table_key`), its grid, the strip-theory switches
/// of `as_printed`, `seakeeping.aft_end_terms` and `seakeeping.short_wave_force`.
type Key = (Arc<str>, SeakeepingGrid, AsPrintedParams, bool, ShortWaveForce);
type Cache = Mutex<Vec<(Key, Arc<RaoTable>)>>;
/// The tables made so far (at most `MAX_TABLES`, the oldest dropped first).
static CACHE: OnceLock<Cache> = OnceLock::new();
/// Tables kept (a table of the default grid is 0.4 MB).
const MAX_TABLES: usize = 4;

fn key(
    hull: &ShipHull,
    grid: &SeakeepingGrid,
    printed: &AsPrintedParams,
    aft_end_terms: bool,
    short_wave: ShortWaveForce,
) -> Key {
    (hull.table_key(), *grid, printed.strip_theory(), aft_end_terms, short_wave)
}

fn keep(k: Key, t: Arc<RaoTable>) {
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(mut c) = cache.lock() {
        c.retain(|(g, _)| *g != k);
        if c.len() >= MAX_TABLES {
            c.remove(0);
        }
        c.push((k, t));
    }
}

/// The RAO table of `hull` on `grid` with the strip-theory switches of `printed` (the others do
/// not change the table), STF's aft-end terms or not (`seakeeping.aft_end_terms`) and the mean
/// force's short-wave part (`seakeeping.short_wave_force`), computed on first use.
/// The build's parts are run by `each` (`Serial`, or the command line's threads).
pub fn rao_table_with(
    hull: &ShipHull,
    grid: &SeakeepingGrid,
    printed: &AsPrintedParams,
    aft_end_terms: bool,
    short_wave: ShortWaveForce,
    each: &dyn ForEach,
) -> Result<Arc<RaoTable>, String> {
    let k = key(hull, grid, printed, aft_end_terms, short_wave);
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(c) = cache.lock() {
        if let Some((_, t)) = c.iter().find(|(g, _)| *g == k) {
            return Ok(t.clone());
        }
    }
    let mut ship = hull.strip_ship()?;
    ship.aft_end_terms = aft_end_terms;
    ship.short_wave = short_wave;
    let t = Arc::new(RaoTable::compute_with(&ship, grid, &k.2, each)?);
    keep(k, t.clone());
    Ok(t)
}

/// Puts a table built elsewhere (`RaoTable::values` of another web worker's table) into the
/// cache, so this process does not build it again.
pub fn insert_rao_table(
    hull: &ShipHull,
    grid: &SeakeepingGrid,
    printed: &AsPrintedParams,
    aft_end_terms: bool,
    short_wave: ShortWaveForce,
    values: &[f64],
) -> Result<(), String> {
    let t = Arc::new(RaoTable::from_values(grid, values)?);
    keep(key(hull, grid, printed, aft_end_terms, short_wave), t);
    Ok(())
}
