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

/// What a table is built from: the hull, the grid, the strip-theory switches of `printed` (the
/// others do not change the table), STF's aft-end terms or not (`seakeeping.aft_end_terms`) and
/// the mean force's short-wave part (`seakeeping.short_wave_force`).
#[derive(Debug, Clone, Copy)]
pub struct TableSpec<'a> {
    pub hull: &'a ShipHull,
    pub grid: &'a SeakeepingGrid,
    pub printed: &'a AsPrintedParams,
    pub aft_end_terms: bool,
    pub short_wave: ShortWaveForce,
}

fn key(s: &TableSpec) -> Key {
    (s.hull.table_key(), *s.grid, s.printed.strip_theory(), s.aft_end_terms, s.short_wave)
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

/// Whether the table of `spec` is built and kept (nothing is built).
pub fn is_cached(spec: &TableSpec) -> bool {
    let k = key(spec);
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    cache.lock().map(|c| c.iter().any(|(g, _)| *g == k)).unwrap_or(false)
}

/// The RAO table of `spec`, computed on first use, its build's parts run by `each` (`Serial`, or
/// the command line's threads).
pub fn rao_table_with(spec: &TableSpec, each: &dyn ForEach) -> Result<Arc<RaoTable>, String> {
    let k = key(spec);
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Ok(c) = cache.lock() {
        if let Some((_, t)) = c.iter().find(|(g, _)| *g == k) {
            return Ok(t.clone());
        }
    }
    let mut ship = spec.hull.strip_ship()?;
    ship.aft_end_terms = spec.aft_end_terms;
    ship.short_wave = spec.short_wave;
    let t = Arc::new(RaoTable::compute_with(&ship, spec.grid, &k.2, each)?);
    keep(k, t.clone());
    Ok(t)
}

/// The digest a table's values carry from the worker that built them to the others: FNV-1a (64
/// bit) over the table's key (hull, grid and switches, as `Debug` prints them: the same text
/// natively and in wasm) and the bits of every value, cut to 52 bits so that it travels exactly as
/// one f64. It ties the values to the scenario they were built for and catches any change on the
/// way (a table of another hull on the same grid, values negated or scaled): not a defence against
/// a page that forges both, which could as well change the scenario.
fn digest(k: &Key, values: &[f64]) -> f64 {
    const PRIME: u64 = 0x0000_0100_0000_01b3;
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let text = format!("{k:?}");
    for b in text.bytes().chain(values.iter().flat_map(|v| v.to_bits().to_le_bytes())) {
        h = (h ^ u64::from(b)).wrapping_mul(PRIME);
    }
    (h >> 12) as f64
}

/// The table's values (`RaoTable::values`) followed by their digest: what a worker that built
/// the table hands to the others ([`insert_rao_table`]).
pub fn rao_table_values(spec: &TableSpec, each: &dyn ForEach) -> Result<Vec<f64>, String> {
    let mut v = rao_table_with(spec, each)?.values();
    v.push(digest(&key(spec), &v));
    Ok(v)
}

/// Puts a table built elsewhere ([`rao_table_values`] of another web worker) into the cache, so
/// this process does not build it again, once its digest says it is this scenario's table as built.
pub fn insert_rao_table(spec: &TableSpec, values_and_digest: &[f64]) -> Result<(), String> {
    let k = key(spec);
    let Some((&got, values)) = values_and_digest.split_last() else {
        return Err("an RAO table handed over: no values".into());
    };
    if got.to_bits() != digest(&k, values).to_bits() {
        return Err("an RAO table handed over is not the table this scenario builds (its digest differs): \
                    built for another hull, grid or switches, or changed on the way"
            .into());
    }
    let t = Arc::new(RaoTable::from_values(spec.grid, values)?);
    keep(k, t);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea::seakeeping::tables::Serial;

    /// A table handed over is taken only as built for its scenario: negated transfer functions
    /// (the grid kept), one value changed in its last bit, a table of another hull on the same
    /// grid, another switch and a missing digest are refused; the table as built is taken.
    #[test]
    fn a_handed_over_table_must_be_this_scenarios() {
        let grid = SeakeepingGrid { n_omega: 6, n_speed: 2, n_heading: 3, ..Default::default() };
        let p = AsPrintedParams::default();
        let hull = |name: &str| {
            crate::ship::hull::HullSpec { name: name.into(), ..Default::default() }.resolve(1025.0).unwrap()
        };
        let (d, w) = (hull("dtmb5415"), hull("wigley"));
        let spec = |hull, aft_end_terms| TableSpec {
            hull,
            grid: &grid,
            printed: &p,
            aft_end_terms,
            short_wave: ShortWaveForce::default(),
        };
        let v = rao_table_values(&spec(&d, true), &Serial).unwrap();
        insert_rao_table(&spec(&d, true), &v).unwrap();
        let refused = |v: &[f64]| insert_rao_table(&spec(&d, true), v).unwrap_err();
        let per = RaoTable::VALUES_PER_POINT;
        let mut negated = v.clone();
        for (i, x) in negated.iter_mut().enumerate().take(v.len() - 1) {
            if (3..13).contains(&(i % per)) {
                *x = -*x;
            }
        }
        assert!(refused(&negated).contains("its digest differs"));
        let mut nudged = v.clone();
        nudged[7] = f64::from_bits(nudged[7].to_bits() ^ 1);
        assert!(refused(&nudged).contains("its digest differs"));
        assert!(refused(&v[..v.len() - 1]).contains("its digest differs"));
        assert!(refused(&[]).contains("no values"));
        let other = rao_table_values(&spec(&w, true), &Serial).unwrap();
        assert!(refused(&other).contains("its digest differs"));
        assert!(insert_rao_table(&spec(&d, false), &v).unwrap_err().contains("its digest differs"));
    }
}
