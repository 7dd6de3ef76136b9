//! The seakeeping hull and its RAO tables, built once and shared by every study (runs in waves,
//! Monte Carlo trials, the fuel study, repeated runs in the browser).

use super::strip::Ship;
use super::tables::{RaoTable, SeakeepingGrid};
use std::sync::{Arc, Mutex, OnceLock};

/// RAO tables of the DTMB 5415, computed once per grid and shared (Monte Carlo trials, repeated
/// runs in the browser).
pub fn rao_table(grid: &SeakeepingGrid) -> Result<Arc<RaoTable>, String> {
    type Cache = Mutex<Vec<(SeakeepingGrid, Arc<RaoTable>)>>;
    static CACHE: OnceLock<Cache> = OnceLock::new();
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

/// The seakeeping hull (built once).
pub fn dtmb5415() -> &'static Ship {
    static SHIP: OnceLock<Ship> = OnceLock::new();
    SHIP.get_or_init(Ship::dtmb5415)
}
