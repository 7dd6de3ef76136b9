//! The seakeeping hull and its RAO tables, built once and shared by every study (runs in waves,
//! Monte Carlo trials, the fuel study, repeated runs in the browser).

use super::strip::Ship;
use super::tables::{RaoTable, SeakeepingGrid};
use crate::as_printed::AsPrintedParams;
use std::sync::{Arc, Mutex, OnceLock};

/// A table is keyed by its grid and the strip-theory switches of `as_printed`.
type Key = (SeakeepingGrid, AsPrintedParams);
type Cache = Mutex<Vec<(Key, Arc<RaoTable>)>>;
/// The tables made so far (at most four grids).
static CACHE: OnceLock<Cache> = OnceLock::new();

/// RAO tables of the DTMB 5415, computed once per grid and shared (Monte Carlo trials, repeated
/// runs in the browser).
pub fn rao_table(grid: &SeakeepingGrid) -> Result<Arc<RaoTable>, String> {
    rao_table_as(grid, &AsPrintedParams::default())
}

/// `rao_table` with the strip-theory switches of `printed` (the others do not change the table).
pub fn rao_table_as(grid: &SeakeepingGrid, printed: &AsPrintedParams) -> Result<Arc<RaoTable>, String> {
    let key = (*grid, printed.strip_theory());
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(c) = cache.lock() {
        if let Some((_, t)) = c.iter().find(|(g, _)| *g == key) {
            return Ok(t.clone());
        }
    }
    let ship = dtmb5415();
    let t = Arc::new(RaoTable::compute_as(ship, grid, &key.1)?);
    if let Ok(mut c) = cache.lock() {
        if c.len() >= 4 {
            c.remove(0);
        }
        c.push((key, t.clone()));
    }
    Ok(t)
}

/// Puts a table of `grid` built elsewhere (`RaoTable::values` of another web worker's table)
/// into the cache, so this process does not build it again.
pub fn insert_rao_table(grid: &SeakeepingGrid, values: &[f64]) -> Result<(), String> {
    insert_rao_table_as(grid, &AsPrintedParams::default(), values)
}

/// `insert_rao_table` for the table of `grid` with the strip-theory switches of `printed`.
pub fn insert_rao_table_as(grid: &SeakeepingGrid, printed: &AsPrintedParams, values: &[f64]) -> Result<(), String> {
    let key = (*grid, printed.strip_theory());
    let t = Arc::new(RaoTable::from_values(grid, values)?);
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(mut c) = cache.lock() {
        c.retain(|(g, _)| *g != key);
        if c.len() >= 4 {
            c.remove(0);
        }
        c.push((key, t));
    }
    Ok(())
}

/// The seakeeping hull (built once).
pub fn dtmb5415() -> &'static Ship {
    static SHIP: OnceLock<Ship> = OnceLock::new();
    SHIP.get_or_init(Ship::dtmb5415)
}
