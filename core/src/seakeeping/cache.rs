//! The seakeeping hull and its RAO tables, built once and shared by every study (runs in waves,
//! Monte Carlo trials, the fuel study, repeated runs in the browser).

use super::strip::Ship;
use super::tables::{RaoTable, SeakeepingGrid};
use std::sync::{Arc, Mutex, OnceLock};

type Cache = Mutex<Vec<(SeakeepingGrid, Arc<RaoTable>)>>;
/// The tables made so far (at most four grids).
static CACHE: OnceLock<Cache> = OnceLock::new();

/// RAO tables of the DTMB 5415, computed once per grid and shared (Monte Carlo trials, repeated
/// runs in the browser).
pub fn rao_table(grid: &SeakeepingGrid) -> Result<Arc<RaoTable>, String> {
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(c) = cache.lock() {
        if let Some((_, t)) = c.iter().find(|(g, _)| g == grid) {
            return Ok(t.clone());
        }
    }
    let ship = dtmb5415();
    let t = Arc::new(RaoTable::compute(ship, grid)?);
    if let Ok(mut c) = cache.lock() {
        if c.len() >= 4 {
            c.remove(0);
        }
        c.push((*grid, t.clone()));
    }
    Ok(t)
}

/// Puts a table of `grid` built elsewhere (`RaoTable::values` of another web worker's table)
/// into the cache, so this process does not build it again.
pub fn insert_rao_table(grid: &SeakeepingGrid, values: &[f64]) -> Result<(), String> {
    let t = Arc::new(RaoTable::from_values(grid, values)?);
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(mut c) = cache.lock() {
        c.retain(|(g, _)| g != grid);
        if c.len() >= 4 {
            c.remove(0);
        }
        c.push((*grid, t));
    }
    Ok(())
}

/// The seakeeping hull (built once).
pub fn dtmb5415() -> &'static Ship {
    static SHIP: OnceLock<Ship> = OnceLock::new();
    SHIP.get_or_init(Ship::dtmb5415)
}
