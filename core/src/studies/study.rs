//! One way to write a study. A study is a plan of independent items (Monte Carlo trials, rare-event
//! trials, the polar's speeds), a pure function from one item to a part, an associative merge of
//! parts, the checks that a part from outside must pass, and a summary. Everything generic is
//! written once here: the shard (one versioned format for every study, with its kind, its key and
//! its definition, so shards merge with no other input), item ranges, merging in any order,
//! the items a merge lacks, and the binary form the browser's workers pass.
//!
//! A new study implements [`Study`] in its own file and adds one line to
//! [`crate::for_each_study`]; the command line's shard flags, `aes-sim merge`, the wasm's
//! `studyRange` / `studySummary` and the page's worker pool then serve it.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::fmt::Debug;

/// Identifies the shard format.
pub const FORMAT: &str = "aes-sim shard";
/// Version 2: one envelope for every study (version 1 was the Monte Carlo partial alone).
pub const VERSION: u32 = 2;
/// Most item ranges one shard may list.
pub const MAX_RANGES: usize = 1_000_000;

/// Where a study runs, for its estimate: natively, or in a browser's WebAssembly
/// ([`crate::scenario::WASM_SLOWDOWN`] times slower).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Platform {
    Native,
    Wasm,
}

/// Wall-clock seconds that `items` items of `item_work` units of work each take on `threads`
/// threads (or the page's workers), roughly: at [`crate::scenario::WORK_PER_S`] a thread
/// natively. Said before a long study starts and judged against its budget, never a result.
pub fn wall_estimate_s(items: u64, item_work: f64, threads: usize, platform: Platform) -> f64 {
    let slowdown = match platform {
        Platform::Native => 1.0,
        Platform::Wasm => crate::scenario::WASM_SLOWDOWN,
    };
    items as f64 * item_work / crate::scenario::WORK_PER_S * slowdown / threads.max(1) as f64
}

/// What a study (or a range of its items) is expected to cost, said before it starts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Estimate {
    pub items: u64,
    /// Units of work of one item ([`Study::item_work`]); absent when the items are not runs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub item_work: Option<f64>,
    /// Wall clock on the threads asked for \[s\] ([`wall_estimate_s`]); absent with `item_work`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds: Option<f64>,
}

/// The estimate of `items` items of study `s` on `threads` threads of `platform`.
pub fn estimate<S: Study>(s: &S, items: u64, threads: usize, platform: Platform) -> Estimate {
    let item_work = s.item_work();
    Estimate { items, item_work, seconds: item_work.map(|w| wall_estimate_s(items, w, threads, platform)) }
}

/// A study on the shared pipeline.
pub trait Study: Sized + Sync {
    /// The study's name in shards, in the wasm's `studyRange(kind, ...)` and on the page.
    const KIND: &'static str;
    /// What one item is, for messages and progress ("trial", "speed").
    const ITEM: &'static str;
    /// The study's whole definition: a shard carries it, so `aes-sim merge` needs nothing else.
    type Spec: Serialize + DeserializeOwned + Clone + PartialEq + Debug;
    /// What the items share, built once per process or worker (prototypes, tables).
    type Shared: Sync;
    /// The result of a range of items; merges associatively.
    type Part: Serialize + DeserializeOwned + Clone + PartialEq + Debug + Send;
    type Summary: Serialize;

    /// Checks the definition and the study's budgets before any work.
    fn new(spec: Self::Spec) -> Result<Self, String>;
    fn spec(&self) -> &Self::Spec;
    /// The scenario the items run (the command line builds its RAO table on every core first).
    fn scenario(&self) -> &crate::scenario::Scenario;
    /// Number of items in the plan.
    fn items(&self) -> u64;
    /// Units of work of one item ([`crate::scenario::Scenario::work`]'s, every run the item
    /// makes), for the estimate said before a long study starts; None when the item is not a run.
    fn item_work(&self) -> Option<f64> {
        None
    }
    /// Whether the items read the scenario's RAO table (the command line builds it first, its
    /// parts on every core).
    fn needs_rao_table(&self) -> bool {
        self.scenario().sea.kind != crate::scenario::SeaKind::Calm
    }
    fn prepare(&self) -> Result<Self::Shared, String>;
    /// Item `i` alone, as a part.
    fn run(&self, shared: &Self::Shared, i: u64) -> Result<Self::Part, String>;
    /// The part of no items.
    fn empty(&self) -> Self::Part;
    /// Adds `other` (disjoint items of the same study) to `acc`.
    fn merge(&self, acc: &mut Self::Part, other: &Self::Part) -> Result<(), String>;
    /// Checks a part from outside against what the items `ranges` of this study can give.
    fn check_part(&self, part: &Self::Part, ranges: &[(u64, u64)]) -> Result<(), String>;
    /// The study's summary of the items `ranges` (the whole plan, or what was merged so far).
    fn summary(&self, part: &Self::Part, ranges: &[(u64, u64)]) -> Result<Self::Summary, String>;
    /// The key that shards of a study of this definition share: by default a hash of it.
    fn key_of_spec(spec: &Self::Spec) -> String {
        key_of(&serde_json::to_string(spec).unwrap_or_default())
    }
    fn key(&self) -> String {
        Self::key_of_spec(self.spec())
    }
    /// Whether two definitions are of one study (their shards merge): by default equal. The key
    /// says it in a line; this says it for certain (a 64-bit hash can be made to collide).
    fn same_study(a: &Self::Spec, b: &Self::Spec) -> bool {
        a == b
    }
    /// Reads a study's definition from JSON (the wasm's `studyRange`): serde's reading, with the
    /// scenario inside read by the scenario's own reader (errors name its field).
    fn spec_from_json(text: &str) -> Result<Self::Spec, String> {
        spec_with_scenario(text)
    }
    /// A part in binary form (the page's workers pass parts so); JSON unless a study packs it.
    fn part_to_bytes(part: &Self::Part) -> Result<Vec<u8>, String> {
        serde_json::to_vec(part).map_err(|e| e.to_string())
    }
    /// Reads `part_to_bytes`' form (unchecked: the shard checks it with [`Study::check_part`]).
    fn part_from_bytes(b: &[u8]) -> Result<Self::Part, String> {
        serde_json::from_slice(b).map_err(|e| crate::checks::shorten_message(&e.to_string()))
    }
}

/// A definition read from JSON whose field `scenario` (if any) is read by
/// [`crate::scenario::Scenario::from_value`]: migrated, checked, errors naming the field.
pub fn spec_with_scenario<T: DeserializeOwned>(text: &str) -> Result<T, String> {
    let msg = |e: serde_json::Error| crate::checks::shorten_message(&e.to_string());
    let mut v: serde_json::Value = serde_json::from_str(text).map_err(msg)?;
    if let Some(sc) = v.get_mut("scenario") {
        let read = crate::scenario::Scenario::from_value(sc.take()).map_err(|e| format!("scenario: {e}"))?;
        *sc = serde_json::to_value(&read).map_err(msg)?;
    }
    serde_json::from_value(v).map_err(msg)
}

/// A 64-bit FNV-1a hash of a text, in hex: a study's key.
pub fn key_of(text: &str) -> String {
    let h = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3));
    format!("{h:016x}")
}

/// Items `ranges` of a study with their part: what a shard file holds, and what a merge gives.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Shard<Spec, Part> {
    pub format: String,
    pub version: u32,
    pub kind: String,
    pub key: String,
    /// The study's definition ([`Study::Spec`]).
    pub spec: Spec,
    /// Item ranges [a, b) covered, sorted, disjoint and joined.
    pub ranges: Vec<(u64, u64)>,
    pub part: Part,
}

/// The shard type of a study.
pub type ShardOf<S> = Shard<<S as Study>::Spec, <S as Study>::Part>;

/// The first fields of any shard, read before its kind is known.
#[derive(Deserialize)]
struct Head {
    format: String,
    version: u32,
    /// (Absent from a version 1 file: its version is then what the message names.)
    #[serde(default)]
    kind: String,
}

/// Number of items in `ranges` (saturating).
pub fn count(ranges: &[(u64, u64)]) -> u64 {
    ranges.iter().fold(0u64, |n, (a, b)| n.saturating_add(b.saturating_sub(*a)))
}

/// The ranges of 0..`items` that `ranges` leave out.
pub fn missing(ranges: &[(u64, u64)], items: u64) -> Vec<(u64, u64)> {
    let mut sorted = ranges.to_vec();
    sorted.sort_unstable();
    let mut gaps = Vec::new();
    let mut next = 0;
    for (a, b) in sorted {
        if a > next {
            gaps.push((next, a.min(items)));
        }
        next = next.max(b);
    }
    if next < items {
        gaps.push((next, items));
    }
    gaps.retain(|(a, b)| a < b);
    gaps
}

/// Merges parts that hold one record per item (rare-event trials, the polar's speeds), kept in
/// item order; `index` gives a record's item, `item` names it in the error.
pub fn merge_records<T: Clone>(
    acc: &mut Vec<T>,
    other: &[T],
    index: impl Fn(&T) -> u64,
    item: &str,
) -> Result<(), String> {
    acc.extend(other.iter().cloned());
    acc.sort_by_key(&index);
    if let Some(w) = acc.windows(2).find(|w| index(&w[0]) == index(&w[1])) {
        return Err(format!("{item} {} is in two shards", index(&w[0])));
    }
    Ok(())
}

/// Pairs each record of a one-record-per-item part with its item of `ranges`, after checking
/// that there is one record for each (in order: the study checks each record's own numbers).
pub fn records_of<'a, T>(
    part: &'a [T],
    ranges: &'a [(u64, u64)],
    index: impl Fn(&T) -> u64,
    item: &str,
) -> Result<impl Iterator<Item = (&'a T, u64)>, String> {
    let want = count(ranges);
    if part.len() as u64 != want {
        return Err(format!("{} records for the {want} {item}s of its ranges", part.len()));
    }
    let items = || ranges.iter().flat_map(|&(a, b)| a..b);
    if let Some((r, i)) = part.iter().zip(items()).find(|(r, i)| index(r) != *i) {
        return Err(format!("{item} {} where {item} {i} of its ranges belongs", index(r)));
    }
    Ok(part.iter().zip(items()))
}

/// Checks a range of items before it runs: a < b <= the study's items.
pub fn check_range<S: Study>(study: &S, a: u64, b: u64) -> Result<(), String> {
    let n = study.items();
    if a < b && b <= n {
        Ok(())
    } else {
        Err(format!("need a < b <= the study's {n} {}s", S::ITEM))
    }
}

/// A shard of `study` from its ranges and part.
pub fn shard<S: Study>(study: &S, ranges: Vec<(u64, u64)>, part: S::Part) -> ShardOf<S> {
    Shard {
        format: FORMAT.into(),
        version: VERSION,
        kind: S::KIND.into(),
        key: study.key(),
        spec: study.spec().clone(),
        ranges,
        part,
    }
}

/// Runs items `a..b` one after another (the browser's way; the command line spreads them over
/// threads and merges, with the same result).
pub fn run_range<S: Study>(study: &S, a: u64, b: u64) -> Result<ShardOf<S>, String> {
    check_range(study, a, b).map_err(|e| format!("{}s {a}..{b}: {e}", S::ITEM))?;
    let shared = study.prepare()?;
    let mut acc = study.empty();
    for i in a..b {
        study.merge(&mut acc, &study.run(&shared, i)?)?;
    }
    Ok(shard(study, vec![(a, b)], acc))
}

/// The whole study, one item after another, and its summary.
pub fn run_all<S: Study>(study: &S) -> Result<S::Summary, String> {
    let s = run_range(study, 0, study.items())?;
    study.summary(&s.part, &s.ranges)
}

/// Sorted, disjoint ranges joined where they touch; an error names the overlap.
fn join(mut ranges: Vec<(u64, u64)>) -> Result<Vec<(u64, u64)>, String> {
    ranges.sort_unstable();
    if let Some(w) = ranges.windows(2).find(|w| w[1].0 < w[0].1) {
        return Err(format!("item ranges {}..{} and {}..{} overlap", w[0].0, w[0].1, w[1].0, w[1].1));
    }
    let mut joined: Vec<(u64, u64)> = Vec::new();
    for r in ranges {
        match joined.last_mut() {
            Some(last) if last.1 == r.0 => last.1 = r.1,
            _ => joined.push(r),
        }
    }
    Ok(joined)
}

/// Checks what a shard from outside claims about `study`: format, version, kind and key, its
/// ranges (each a..b with a < b <= items, sorted, disjoint), and its part ([`Study::check_part`]).
pub fn check_shard<S: Study>(study: &S, s: &ShardOf<S>) -> Result<(), String> {
    use crate::checks::shorten;
    if s.format != FORMAT || s.version != VERSION {
        return Err(format!(
            "format = '{}' version {}: expected '{FORMAT}' version {VERSION}",
            shorten(&s.format),
            s.version
        ));
    }
    if s.kind != S::KIND {
        return Err(format!("kind = '{}': a shard of another kind of study, not {}", shorten(&s.kind), S::KIND));
    }
    if S::key_of_spec(&s.spec) != s.key {
        return Err(format!("key = '{}': not the key of its own definition (the shard was altered)", shorten(&s.key)));
    }
    if s.key != study.key() || !S::same_study(&s.spec, study.spec()) {
        return Err(format!(
            "key = '{}': a shard of another study (this one's key is {})",
            shorten(&s.key),
            study.key()
        ));
    }
    if s.ranges.len() > MAX_RANGES {
        return Err(format!("ranges: {} ranges, at most {MAX_RANGES}", s.ranges.len()));
    }
    let n = study.items();
    let mut last_end = 0u64;
    for (k, &(a, b)) in s.ranges.iter().enumerate() {
        if !(a < b && b <= n) {
            return Err(format!("ranges.{k} = [{a}, {b}]: need a < b <= the study's {n} {}s", S::ITEM));
        }
        if k > 0 && a < last_end {
            return Err(format!("ranges.{k} = [{a}, {b}]: ranges must be sorted and must not overlap"));
        }
        last_end = b;
    }
    study.check_part(&s.part, &s.ranges)
}

/// A study's shards merged one at a time as they come (memory does not grow with their number;
/// the result does not depend on their order or on how the items were split).
pub struct Merger<S: Study> {
    pub study: S,
    acc: Option<ShardOf<S>>,
}

impl<S: Study> Merger<S> {
    pub fn new(study: S) -> Merger<S> {
        Merger { study, acc: None }
    }

    /// Checks one more shard ([`check_shard`]) and merges it.
    pub fn add(&mut self, s: ShardOf<S>) -> Result<(), String> {
        check_shard(&self.study, &s)?;
        match self.acc.as_mut() {
            None => {
                let mut s = s;
                s.ranges = join(s.ranges)?;
                self.acc = Some(s);
            }
            Some(acc) => {
                let mut ranges = acc.ranges.clone();
                ranges.extend(s.ranges.iter().copied());
                let ranges = join(ranges)?;
                self.study.merge(&mut acc.part, &s.part)?;
                acc.ranges = ranges;
            }
        }
        Ok(())
    }

    /// The study and its merged shard; an error if none was added.
    pub fn finish(self) -> Result<(S, ShardOf<S>), String> {
        let shard = self.acc.ok_or_else(|| "no shards given".to_string())?;
        Ok((self.study, shard))
    }
}

/// First bytes of a shard in binary form ([`to_bytes`]).
const BINARY_MAGIC: &[u8; 8] = b"AESSHD02";

/// The shard's envelope as JSON, then its part in the study's binary form.
pub fn to_bytes<S: Study>(s: &ShardOf<S>) -> Result<Vec<u8>, String> {
    let head = shard_head::<S>(s);
    let json = serde_json::to_vec(&head).map_err(|e| e.to_string())?;
    let part = S::part_to_bytes(&s.part)?;
    let mut out = frame(BINARY_MAGIC, &json, part.len());
    out.extend_from_slice(&part);
    Ok(out)
}

fn shard_head<S: Study>(s: &ShardOf<S>) -> Shard<S::Spec, ()> {
    Shard {
        format: s.format.clone(),
        version: s.version,
        kind: s.kind.clone(),
        key: s.key.clone(),
        spec: s.spec.clone(),
        ranges: s.ranges.clone(),
        part: (),
    }
}

/// A binary frame: `magic` (8 bytes), the length of `json` (u64, little-endian), `json`, then
/// room for `body` bytes the caller appends.
pub fn frame(magic: &[u8; 8], json: &[u8], body: usize) -> Vec<u8> {
    let mut out = Vec::with_capacity(16 + json.len() + body);
    out.extend_from_slice(magic);
    out.extend_from_slice(&(json.len() as u64).to_le_bytes());
    out.extend_from_slice(json);
    out
}

/// [`frame`]'s JSON and what follows it; `bad` words an error ("header", "length").
pub fn unframe<'a>(b: &'a [u8], magic: &[u8; 8], bad: &dyn Fn(&str) -> String) -> Result<(&'a [u8], &'a [u8]), String> {
    if b.len() < 16 || &b[..8] != magic {
        return Err(bad("header"));
    }
    let len = usize::try_from(u64::from_le_bytes(b[8..16].try_into().map_err(|_| bad("length"))?))
        .map_err(|_| bad("length"))?;
    let json = b.get(16..16usize.saturating_add(len)).ok_or_else(|| bad("length"))?;
    Ok((json, &b[16 + len..]))
}

/// Reads [`to_bytes`]' form (unchecked: merge it with a [`Merger`], which checks it).
pub fn from_bytes<S: Study>(b: &[u8]) -> Result<ShardOf<S>, String> {
    let bad = |what: &str| format!("not a binary shard ({what})");
    let (json, body) = unframe(b, BINARY_MAGIC, &bad)?;
    let head: Shard<S::Spec, ()> =
        serde_json::from_slice(json).map_err(|e| bad(&crate::checks::shorten_message(&e.to_string())))?;
    let part = S::part_from_bytes(body).map_err(|e| bad(&e))?;
    let Shard { format, version, kind, key, spec, ranges, .. } = head;
    Ok(Shard { format, version, kind, key, spec, ranges, part })
}

/// The kind of a shard's JSON text, after checking its format and version.
pub fn kind_of(text: &str) -> Result<String, String> {
    use crate::checks::shorten;
    let h: Head = serde_json::from_str(text).map_err(|e| {
        format!("not an aes-sim shard (format, version, kind): {}", crate::checks::shorten_message(&e.to_string()))
    })?;
    if h.format != FORMAT || h.version != VERSION {
        return Err(format!(
            "format = '{}' version {}: expected '{FORMAT}' version {VERSION}",
            shorten(&h.format),
            h.version
        ));
    }
    Ok(h.kind)
}

/// Reads a shard's JSON (unchecked: merge it with a [`Merger`], which checks it).
pub fn from_json<S: Study>(text: &str) -> Result<ShardOf<S>, String> {
    let kind = kind_of(text)?;
    if kind != S::KIND {
        return Err(format!(
            "kind = '{}': a shard of another kind of study, not {}",
            crate::checks::shorten(&kind),
            S::KIND
        ));
    }
    serde_json::from_str(text)
        .map_err(|e| format!("not a {} shard: {}", S::KIND, crate::checks::shorten_message(&e.to_string())))
}

/// Something done with a study type chosen by its kind at run time ([`dispatch`]).
pub trait Visit {
    type Out;
    fn visit<S: Study>(self) -> Self::Out;
}

macro_rules! dispatch_kinds {
    ($($study:path),* $(,)?) => {
        /// Every study kind on the pipeline.
        pub const KINDS: &[&str] = &[$(<$study as Study>::KIND),*];

        /// Calls `v` with the study of `kind`; an error names the kinds there are.
        pub fn dispatch<V: Visit>(kind: &str, v: V) -> Result<V::Out, String> {
            $(if kind == <$study as Study>::KIND {
                return Ok(v.visit::<$study>());
            })*
            Err(format!("kind '{}': one of {}", crate::checks::shorten(kind), KINDS.join(", ")))
        }
    };
}
crate::for_each_study!(dispatch_kinds);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_items_are_the_gaps() {
        assert_eq!(missing(&[(2, 4), (6, 7)], 9), vec![(0, 2), (4, 6), (7, 9)]);
        assert_eq!(missing(&[(0, 9)], 9), vec![]);
        assert_eq!(join(vec![(3, 5), (0, 3), (7, 8)]).unwrap(), vec![(0, 5), (7, 8)]);
        assert_eq!(join(vec![(0, 3), (2, 4)]).unwrap_err(), "item ranges 0..3 and 2..4 overlap");
        assert_eq!(count(&[(0, 3), (5, 9)]), 7);
    }

    /// A shard's touching ranges are joined as it is taken, first or later: the summary's ranges
    /// do not depend on how many shards were merged.
    #[test]
    fn a_first_shard_has_its_ranges_joined() {
        let mut sc = crate::scenario::Scenario::default();
        sc.sim.duration_s = 2.0;
        sc.monte_carlo.trials = 3;
        let mc = || crate::studies::montecarlo::MonteCarlo::new(sc.clone()).unwrap();
        let mut s = run_range(&mc(), 0, 2).unwrap();
        s.ranges = vec![(0, 1), (1, 2)];
        let mut m = Merger::new(mc());
        m.add(s).unwrap();
        assert_eq!(m.finish().unwrap().1.ranges, vec![(0, 2)]);
    }

    #[test]
    fn every_kind_dispatches_to_itself() {
        struct Name;
        impl Visit for Name {
            type Out = &'static str;
            fn visit<S: Study>(self) -> &'static str {
                S::KIND
            }
        }
        for k in KINDS {
            assert_eq!(dispatch(k, Name).unwrap(), *k);
        }
        assert!(dispatch("fuel", Name).unwrap_err().starts_with("kind 'fuel': one of monte-carlo"));
    }
}
