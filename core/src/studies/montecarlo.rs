//! Monte Carlo studies (thesis ch. 5.4): trials of one scenario in seas drawn from
//! `trial_seed(master, i)`, their statistics accumulated online into a `Partial` that merges
//! exactly (integer sums, fixed bins, min/max), so threads, shards and browser tabs all give the
//! same summary, beside Rice's analytical arrival rate of surface effects (eqs. 5.1-5.3,
//! `studies::rice`).
//!
//! Definitions:
//! - Excess energy of a trial: the energy drawn by one motor over the run minus that drawn in the
//!   same sea (same seed) with the propeller's surface losses switched off (its fully submerged
//!   counterpart) \[MJ\]. It isolates what the surface effects cost, not the added resistance. The
//!   summary gives also the excess over the calm-water power at the ordered speed (which includes
//!   the added resistance and every other effect of the sea).
//! - Arrival time: the first instant beta_T < 1 on either shaft (ventilation or emergence); trials
//!   without one by the end are censored at `sim.duration_s`.

use crate::scenario::Scenario;
use crate::signals::Signal;
use crate::sim::{Prototype, SimError};
use crate::studies::rice::{rice_summary, RiceSummary};
use crate::studies::stats::{trial_seed, welch, ExactMoments, Histogram};
use crate::studies::study::Study;
use serde::{Deserialize, Serialize};

/// Most memory one accumulator of a study may take \[bytes\]: its moment rows (envelopes, onset,
/// periodogram) and kept traces, estimated by [`study_bytes`] and checked by [`check_study`]
/// before the study starts (a native study holds about two per thread; its summary's JSON is
/// about 1.5 times the rows' share). The presets keep at most 2.6 MB.
pub const MAX_STUDY_BYTES: f64 = 64.0e6;

/// Most simulated work a whole study may ask for: trials times [`Scenario::work`] of one trial
/// ([`crate::scenario::WORK_PER_S`] a second natively: 1e12 is about 6 hours on one core).
pub const MAX_STUDY_WORK: f64 = 1.0e12;

/// Envelope quantum (2^-16 of the unit; values to 2^29) and scalar quantum (2^-12; values to 4096).
const ENV_BITS: i32 = 16;
const SCALAR_BITS: i32 = 12;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Envelope {
    pub signal: String,
    pub rows: Vec<ExactMoments>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeptTrace {
    pub trial: u64,
    pub seed: u64,
    pub t_s: Vec<f64>,
    pub columns: Vec<(String, Vec<f64>)>,
}

/// Accumulated statistics of a set of trials (a shard's part, or the whole study's); the shard
/// around it ([`crate::studies::study::Shard`]) says which trials and which study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Partial {
    pub record_interval_s: f64,
    pub envelopes: Vec<Envelope>,
    pub at_time: ExactMoments,
    pub at_time_hist: Histogram,
    pub excess_energy_mj: ExactMoments,
    pub excess_hist: Histogram,
    /// The same against the calm-water power of the ordered speed (the run's first row).
    pub excess_vs_calm_mj: ExactMoments,
    pub excess_vs_calm_hist: Histogram,
    pub arrival: ExactMoments,
    pub arrival_hist: Histogram,
    /// min(arrival, cap) over all trials (for the censored comparison and the rate estimate).
    pub exposure: ExactMoments,
    pub censored: u64,
    pub onset: Vec<ExactMoments>,
    pub periodogram_hz: Vec<f64>,
    pub periodogram: Vec<ExactMoments>,
    pub traces: Vec<KeptTrace>,
}

impl Partial {
    /// No trials yet.
    pub fn empty(sc: &Scenario) -> Partial {
        let m = &sc.monte_carlo;
        let cap = sc.sim.duration_s;
        Partial {
            record_interval_s: sc.sim.record_interval_s,
            envelopes: m.envelope_signals.iter().map(|s| Envelope { signal: s.clone(), rows: Vec::new() }).collect(),
            at_time: ExactMoments::new(SCALAR_BITS, 4),
            at_time_hist: Histogram::new(m.histogram_lo, m.histogram_hi, m.histogram_bins as usize),
            excess_energy_mj: ExactMoments::new(SCALAR_BITS, 4),
            excess_hist: Histogram::new(-200.0, 200.0, 40),
            excess_vs_calm_mj: ExactMoments::new(SCALAR_BITS, 4),
            excess_vs_calm_hist: Histogram::new(-200.0, 600.0, 40),
            arrival: ExactMoments::new(SCALAR_BITS, 4),
            arrival_hist: Histogram::new(0.0, cap, 45),
            exposure: ExactMoments::new(SCALAR_BITS, 2),
            censored: 0,
            onset: Vec::new(),
            periodogram_hz: Vec::new(),
            periodogram: Vec::new(),
            traces: Vec::new(),
        }
    }

    /// Checks everything a part from outside claims about the trials `ranges` (checked by the
    /// shard: sorted, disjoint, within the study) of the study `sc`: that every accumulator has
    /// the quantum, order, bins and counts this study makes (nothing more samples than trials,
    /// nothing that could overflow when merged).
    pub fn validate(&self, sc: &Scenario, ranges: &[(u64, u64)]) -> Result<(), String> {
        let trials = crate::studies::study::count(ranges);
        if self.record_interval_s != sc.sim.record_interval_s {
            return Err(format!(
                "record_interval_s = {}: must equal the scenario's sim.record_interval_s = {}",
                crate::checks::num(self.record_interval_s),
                sc.sim.record_interval_s
            ));
        }
        let e = Partial::empty(sc);
        let moments = |name: &str, x: &ExactMoments, want: &ExactMoments, max_n: u64| -> Result<(), String> {
            if x.bits != want.bits || x.order != want.order {
                return Err(format!(
                    "{name}: bits = {}, order = {}: this study uses bits = {}, order = {}",
                    x.bits, x.order, want.bits, want.order
                ));
            }
            if x.n > max_n || x.clamped > x.n {
                return Err(format!("{name}: n = {}, clamped = {}: at most {max_n} samples", x.n, x.clamped));
            }
            x.check_consistent().map_err(|e| format!("{name}: {e}"))
        };
        let hist = |name: &str, h: &Histogram, want: &Histogram, max_n: u64| -> Result<(), String> {
            if h.lo != want.lo || h.hi != want.hi || h.counts.len() != want.counts.len() {
                return Err(format!(
                    "{name}: bins [{}, {}) x {}: this study uses [{}, {}) x {}",
                    h.lo,
                    h.hi,
                    h.counts.len(),
                    want.lo,
                    want.hi,
                    want.counts.len()
                ));
            }
            let total =
                h.counts.iter().try_fold(h.below, |a, c| a.checked_add(*c)).and_then(|a| a.checked_add(h.above));
            match total {
                Some(t) if t <= max_n => Ok(()),
                _ => Err(format!("{name}: more counts than the {max_n} trials")),
            }
        };
        moments("at_time", &self.at_time, &e.at_time, trials)?;
        hist("at_time_hist", &self.at_time_hist, &e.at_time_hist, trials)?;
        moments("excess_energy_mj", &self.excess_energy_mj, &e.excess_energy_mj, trials)?;
        hist("excess_hist", &self.excess_hist, &e.excess_hist, trials)?;
        moments("excess_vs_calm_mj", &self.excess_vs_calm_mj, &e.excess_vs_calm_mj, trials)?;
        hist("excess_vs_calm_hist", &self.excess_vs_calm_hist, &e.excess_vs_calm_hist, trials)?;
        moments("arrival", &self.arrival, &e.arrival, trials)?;
        hist("arrival_hist", &self.arrival_hist, &e.arrival_hist, trials)?;
        moments("exposure", &self.exposure, &e.exposure, trials)?;
        if self.arrival.n.checked_add(self.censored) != Some(trials) || self.exposure.n != trials {
            return Err(format!(
                "censored = {}, arrival.n = {}, exposure.n = {}: events plus censored trials must be the {trials} trials",
                self.censored, self.arrival.n, self.exposure.n
            ));
        }
        // Each histogram counts what its moments count, and the values that are not finite
        // (which the moments count as clamped only).
        for (name, h, x) in [
            ("at_time_hist", &self.at_time_hist, &self.at_time),
            ("excess_hist", &self.excess_hist, &self.excess_energy_mj),
            ("excess_vs_calm_hist", &self.excess_vs_calm_hist, &self.excess_vs_calm_mj),
            ("arrival_hist", &self.arrival_hist, &self.arrival),
        ] {
            let total = h.total();
            if total < x.n || total > x.n.saturating_add(x.clamped) {
                return Err(format!(
                    "{name}: {total} counts beside n = {}, clamped = {}: the histogram counts the same trials",
                    x.n, x.clamped
                ));
            }
            h.check_within(x).map_err(|e| format!("{name}: {e}"))?;
        }
        if !sc.monte_carlo.excess_energy && (self.excess_energy_mj.n > 0 || self.excess_vs_calm_mj.n > 0) {
            return Err("excess_energy_mj: samples, but the scenario's monte_carlo.excess_energy is off".into());
        }
        let cap = sc.sim.duration_s;
        if self.arrival.n > 0 && (self.arrival.min < 0.0 || self.arrival.max > cap + sc.sim.record_interval_s) {
            return Err(format!(
                "arrival: min = {}, max = {}: events happen within the run, 0 to {} s",
                crate::checks::num(self.arrival.min),
                crate::checks::num(self.arrival.max),
                crate::checks::num(cap)
            ));
        }
        if self.exposure.n > 0 && (self.exposure.min < 0.0 || self.exposure.max > cap) {
            return Err(format!(
                "exposure: min = {}, max = {}: within 0 to {} s",
                crate::checks::num(self.exposure.min),
                crate::checks::num(self.exposure.max),
                crate::checks::num(cap)
            ));
        }
        let dt = sc.sim.record_interval_s;
        let max_rows = (sc.sim.duration_s / dt) as usize + 2;
        let rows = |name: &str, r: &[ExactMoments], max: usize| -> Result<(), String> {
            if r.len() > max {
                return Err(format!("{name}: {} rows, at most {max}", r.len()));
            }
            let want = ExactMoments::new(ENV_BITS, 2);
            r.iter().enumerate().try_for_each(|(i, x)| moments(&format!("{name}.{i}"), x, &want, trials))?;
            // A trial gives a prefix of the rows (a run that stops early gives fewer): the
            // counts never grow along the rows.
            match r.windows(2).position(|w| w[1].n > w[0].n) {
                Some(i) => Err(format!(
                    "{name}.{}: n = {} after n = {} in the row before: a row counts no more trials than the one before",
                    i + 1,
                    r[i + 1].n,
                    r[i].n
                )),
                None => Ok(()),
            }
        };
        if self.envelopes.len() != sc.monte_carlo.envelope_signals.len()
            || self.envelopes.iter().zip(&sc.monte_carlo.envelope_signals).any(|(a, b)| &a.signal != b)
        {
            return Err("envelopes: not the scenario's monte_carlo.envelope_signals".into());
        }
        for env in &self.envelopes {
            rows(&format!("envelopes.{}", env.signal), &env.rows, max_rows)?;
        }
        rows("onset", &self.onset, (sc.monte_carlo.onset_window_s / dt) as usize + 2)?;
        if let Some(x) = self.onset.first().filter(|x| x.n > self.arrival.n) {
            return Err(format!(
                "onset.0: n = {} with {} events (arrival.n): the onset is counted only over trials with an event",
                x.n, self.arrival.n
            ));
        }
        rows("periodogram", &self.periodogram, max_rows)?;
        if let Some((i, x)) = self.periodogram.iter().enumerate().find(|(_, x)| x.n > 0 && x.min < 0.0) {
            return Err(format!(
                "periodogram.{i}: min = {}: a power spectral density is never negative",
                crate::checks::num(x.min)
            ));
        }
        if !self.periodogram.is_empty() && self.periodogram_hz.len() != self.periodogram.len()
            || self.periodogram_hz.iter().any(|f| !f.is_finite())
        {
            return Err("periodogram_hz: must be finite, one per periodogram row".into());
        }
        // Welch's frequencies: k / (segment x dt), the same arithmetic as `welch`.
        let seg = libm::round(sc.monte_carlo.periodogram_segment_s / dt) as usize;
        if let Some((k, f)) =
            self.periodogram_hz.iter().enumerate().find(|&(k, f)| *f != k as f64 / (seg as f64 * dt) || k > seg / 2)
        {
            return Err(format!(
                "periodogram_hz.{k} = {}: Welch's frequencies are k / ({seg} samples x {} s), up to k = {}",
                crate::checks::num(*f),
                crate::checks::num(dt),
                seg / 2
            ));
        }
        if self.traces.len() > sc.monte_carlo.keep_traces as usize {
            return Err(format!(
                "traces: {} kept, the scenario keeps {}",
                self.traces.len(),
                sc.monte_carlo.keep_traces
            ));
        }
        if let Some(w) = self.traces.windows(2).find(|w| w[1].trial <= w[0].trial) {
            return Err(format!(
                "traces: trial {} after trial {}: kept traces are sorted and distinct",
                w[1].trial, w[0].trial
            ));
        }
        for t in &self.traces {
            if !ranges.iter().any(|&(a, b)| (a..b).contains(&t.trial))
                || t.trial >= sc.monte_carlo.keep_traces as u64
                || t.t_s.len() > max_rows
                || t.columns.iter().any(|(_, c)| c.len() != t.t_s.len())
                || t.t_s.iter().chain(t.columns.iter().flat_map(|(_, c)| c)).any(|x| !x.is_finite())
            {
                return Err(format!("traces: trial {} is not a finite trace of a trial in the ranges", t.trial));
            }
            self.check_trace(sc, t).map_err(|e| format!("traces: trial {}: {e}", t.trial))?;
        }
        Ok(())
    }

    /// A kept trace is one trial's own rows: its seed, the study's columns, time from 0 rising
    /// one record interval a row (to 1e-9 of the run), and every value of an enveloped signal
    /// within that row's envelope, which counts the same trial (the envelope's min and max are
    /// the values themselves, so the check is exact).
    fn check_trace(&self, sc: &Scenario, t: &KeptTrace) -> Result<(), String> {
        use crate::checks::num;
        let want = trial_seed(sc.sim.seed, t.trial);
        if t.seed != want {
            return Err(format!("seed = {}: trial {}'s seed is {want}", t.seed, t.trial));
        }
        let names = trace_columns(&sc.monte_carlo);
        if t.columns.len() != names.len() || t.columns.iter().zip(&names).any(|((a, _), b)| a != b) {
            return Err(format!("columns: must be {}", names.join(", ")));
        }
        let dt = sc.sim.record_interval_s;
        let tol = 1e-9 * sc.sim.duration_s.max(1.0);
        if let Some(k) =
            (0..t.t_s.len()).find(|&k| (t.t_s[k] - k as f64 * dt).abs() > tol || (k > 0 && t.t_s[k] <= t.t_s[k - 1]))
        {
            return Err(format!(
                "t_s.{k} = {}: time rises from 0 by the record interval, {} s a row (row {k} is at {} s)",
                num(t.t_s[k]),
                num(dt),
                num(k as f64 * dt)
            ));
        }
        // Columns without an envelope: within what a run allows.
        let radius = 0.5 * sc.propeller.diameter_m;
        let h = crate::studies::rare::checks::MAX_HUB_DEPTH_M / radius;
        let p = crate::studies::rare::checks::MAX_POWER_DROP_OF_RATED;
        for (name, col) in &t.columns {
            let (lo, hi, why) = match name.as_str() {
                "beta_t" => (0.0, 1.0, "the thrust kept, from 0 (no thrust) to 1 (fully submerged)"),
                "h_over_r" => (-h, h, "the hub within 200 m of the surface"),
                "im_power_pu" => (-p, p, "100 times the motor's rating: beyond its pull-out torque"),
                _ => continue,
            };
            if let Some((k, v)) = col.iter().enumerate().find(|(_, v)| !(lo..=hi).contains(*v)) {
                return Err(format!(
                    "columns.{name}.{k} = {}: must be from {} to {} ({why})",
                    num(*v),
                    num(lo),
                    num(hi)
                ));
            }
        }
        for env in &self.envelopes {
            let Some((_, col)) = t.columns.iter().find(|(n, _)| n == &env.signal) else { continue };
            if col.len() > env.rows.len() {
                return Err(format!(
                    "columns.{}: {} rows, but its envelope has {}: the envelope counts every kept trial's rows",
                    env.signal,
                    col.len(),
                    env.rows.len()
                ));
            }
            if let Some((k, (v, r))) =
                col.iter().zip(&env.rows).enumerate().find(|(_, (v, r))| r.n == 0 || **v < r.min || **v > r.max)
            {
                return Err(format!(
                    "columns.{}.{k} = {}: outside its envelope's row, min = {}, max = {} (the envelope counts this trial)",
                    env.signal,
                    num(*v),
                    num(r.min),
                    num(r.max)
                ));
            }
        }
        Ok(())
    }

    /// Adds the statistics of other trials of the same study (the shard checks that they are
    /// disjoint and of the same study); keeps the first `keep_traces` trials' traces.
    pub fn merge(&mut self, b: &Partial, keep_traces: usize) -> Result<(), String> {
        for (e, f) in self.envelopes.iter_mut().zip(&b.envelopes) {
            merge_rows(&mut e.rows, &f.rows, 2)?;
        }
        self.at_time.merge(&b.at_time)?;
        self.at_time_hist.merge(&b.at_time_hist)?;
        self.excess_energy_mj.merge(&b.excess_energy_mj)?;
        self.excess_hist.merge(&b.excess_hist)?;
        self.excess_vs_calm_mj.merge(&b.excess_vs_calm_mj)?;
        self.excess_vs_calm_hist.merge(&b.excess_vs_calm_hist)?;
        self.arrival.merge(&b.arrival)?;
        self.arrival_hist.merge(&b.arrival_hist)?;
        self.exposure.merge(&b.exposure)?;
        self.censored = self.censored.checked_add(b.censored).ok_or("censored: the count overflows")?;
        merge_rows(&mut self.onset, &b.onset, 2)?;
        if self.periodogram_hz.is_empty() {
            self.periodogram_hz = b.periodogram_hz.clone();
        }
        merge_rows(&mut self.periodogram, &b.periodogram, 2)?;
        self.traces.extend(b.traces.iter().cloned());
        self.traces.sort_by_key(|t| t.trial);
        self.traces.truncate(keep_traces);
        Ok(())
    }
}

fn merge_rows(a: &mut Vec<ExactMoments>, b: &[ExactMoments], order: u8) -> Result<(), String> {
    while a.len() < b.len() {
        a.push(ExactMoments::new(ENV_BITS, order));
    }
    for (x, y) in a.iter_mut().zip(b) {
        x.merge(y)?;
    }
    Ok(())
}

/// First bytes of a part in binary form (`Partial::to_bytes`).
const BINARY_MAGIC: &[u8; 8] = b"AESMCP02";
/// Bytes of one packed `ExactMoments`: bits i32, order u8, n u64, four i128 sums, min and max
/// f64, clamped u64 (little-endian).
const PACKED_MOMENTS: usize = 4 + 1 + 8 + 4 * 16 + 8 + 8 + 8;

/// The small part of a binary partial, as JSON: everything but the moment rows, and their counts.
#[derive(Serialize, Deserialize)]
struct BinaryHead {
    partial: Partial,
    /// Rows of each envelope, then of the onset, then of the periodogram.
    rows: Vec<usize>,
}

impl Partial {
    /// The partial in a compact binary form (the browser's workers pass partials so): the rows of
    /// exact moments (envelopes, onset, periodogram: nearly all of a partial) packed with their
    /// bits as they are, the rest as JSON. `from_bytes` gives back an equal partial.
    pub fn to_bytes(&self) -> Result<Vec<u8>, String> {
        let mut head = self.clone();
        let mut rows: Vec<Vec<ExactMoments>> = head.envelopes.iter_mut().map(|e| std::mem::take(&mut e.rows)).collect();
        rows.push(std::mem::take(&mut head.onset));
        rows.push(std::mem::take(&mut head.periodogram));
        let json = serde_json::to_vec(&BinaryHead { partial: head, rows: rows.iter().map(Vec::len).collect() })
            .map_err(|e| e.to_string())?;
        let n: usize = rows.iter().map(Vec::len).sum();
        let mut out = crate::studies::study::frame(BINARY_MAGIC, &json, n * PACKED_MOMENTS);
        for m in rows.iter().flatten() {
            out.extend_from_slice(&m.bits.to_le_bytes());
            out.push(m.order);
            out.extend_from_slice(&m.n.to_le_bytes());
            for v in m.sums {
                out.extend_from_slice(&v.to_le_bytes());
            }
            out.extend_from_slice(&m.min.to_le_bytes());
            out.extend_from_slice(&m.max.to_le_bytes());
            out.extend_from_slice(&m.clamped.to_le_bytes());
        }
        Ok(out)
    }

    /// Reads `to_bytes`' form back (the shard checks it).
    pub fn from_bytes(b: &[u8]) -> Result<Partial, String> {
        let bad = |what: &str| format!("not a binary Monte Carlo partial ({what})");
        let (json, body) = crate::studies::study::unframe(b, BINARY_MAGIC, &bad)?;
        let head: BinaryHead =
            serde_json::from_slice(json).map_err(|e| bad(&crate::checks::shorten_message(&e.to_string())))?;
        let mut p = head.partial;
        let total: usize = head.rows.iter().try_fold(0usize, |a, &r| a.checked_add(r)).ok_or_else(|| bad("rows"))?;
        if head.rows.len() != p.envelopes.len() + 2 || body.len() != total.saturating_mul(PACKED_MOMENTS) {
            return Err(bad("rows"));
        }
        let mut chunks = body.chunks_exact(PACKED_MOMENTS).map(|c| {
            let f8 = |i: usize| <[u8; 8]>::try_from(&c[i..i + 8]).unwrap_or([0; 8]);
            let mut sums = [0i128; 4];
            for (k, v) in sums.iter_mut().enumerate() {
                let at = 13 + 16 * k;
                *v = i128::from_le_bytes(<[u8; 16]>::try_from(&c[at..at + 16]).unwrap_or([0; 16]));
            }
            ExactMoments {
                bits: i32::from_le_bytes(<[u8; 4]>::try_from(&c[0..4]).unwrap_or([0; 4])),
                order: c[4],
                n: u64::from_le_bytes(f8(5)),
                sums,
                min: f64::from_le_bytes(f8(77)),
                max: f64::from_le_bytes(f8(85)),
                clamped: u64::from_le_bytes(f8(93)),
            }
        });
        let mut take = |n: usize| chunks.by_ref().take(n).collect::<Vec<_>>();
        for (e, &n) in p.envelopes.iter_mut().zip(&head.rows) {
            e.rows = take(n);
        }
        let k = p.envelopes.len();
        p.onset = take(head.rows[k]);
        p.periodogram = take(head.rows[k + 1]);
        Ok(p)
    }
}

/// Energy of one motor over a trace \[J\] (trapezoid over the recorded rows of `im_power_pu`).
fn motor_energy(sc: &Scenario, pu: &[f64], dt: f64) -> f64 {
    let p = sc.plant.motor.rated_power_w;
    pu.windows(2).map(|w| 0.5 * (w[0] + w[1]) * p * dt).sum()
}

/// Which bin of each of the study's histograms one trial's value falls in (None: outside the
/// histogram's range, or no value, e.g. no surface event). The page replays a trial from a
/// histogram bar by running trials in order until one lands in that bar: the summary keeps no
/// per-trial values (its memory does not grow with the trials), and a trial's seed reproduces it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct TrialBins {
    pub at_time: Option<usize>,
    pub excess: Option<usize>,
    pub excess_vs_calm: Option<usize>,
    pub arrival: Option<usize>,
}

/// The bins of trial `i` (see [`TrialBins`]).
pub fn trial_bins(sc: &Scenario, i: u64) -> Result<TrialBins, String> {
    let p = run_trial(sc, i)?;
    let bin = |h: &Histogram| h.counts.iter().position(|&c| c > 0);
    Ok(TrialBins {
        at_time: bin(&p.at_time_hist),
        excess: bin(&p.excess_hist),
        excess_vs_calm: bin(&p.excess_vs_calm_hist),
        arrival: bin(&p.arrival_hist),
    })
}

/// Runs trial `i` of the study `sc` and returns its statistics as a one-trial partial.
pub fn run_trial(sc: &Scenario, i: u64) -> Result<Partial, String> {
    Trials::new(sc).run(i)
}

/// A study's trials: what they share is built once (the run up to its start without the sea, see
/// [`Prototype`], and with `excess_energy` its submerged counterpart's), each trial adding its own
/// sea. A trial gives the same bits as built from scratch.
pub struct Trials {
    sc: Scenario,
    run: Result<Prototype, SimError>,
    submerged: Option<Result<Prototype, SimError>>,
}

impl Trials {
    pub fn new(sc: &Scenario) -> Trials {
        let submerged = sc.monte_carlo.excess_energy.then(|| {
            let mut sub = sc.clone();
            sub.seakeeping.surface_losses = false;
            Prototype::new(&sub)
        });
        Trials { sc: sc.clone(), run: Prototype::new(sc), submerged }
    }

    /// Runs trial `i` and returns its statistics as a one-trial partial.
    pub fn run(&self, i: u64) -> Result<Partial, String> {
        run_trial_from(&self.sc, i, &self.run, self.submerged.as_ref())
    }
}

fn run_trial_from(
    sc: &Scenario,
    i: u64,
    proto: &Result<Prototype, SimError>,
    submerged: Option<&Result<Prototype, SimError>>,
) -> Result<Partial, String> {
    let m = &sc.monte_carlo;
    let mut s = sc.clone();
    s.sim.seed = trial_seed(sc.sim.seed, i);
    let fail = |e: crate::SimError| format!("trial {i} (sea seed {}): {e}", s.sim.seed);
    let mut sim = proto.as_ref().map_err(|e| fail(e.clone()))?.with_seed(s.sim.seed).map_err(fail)?;
    let chunk = sim.record_every().max(1) * 10;
    while !sim.done() {
        sim.advance(chunk).map_err(fail)?;
        if m.stop_at_first_event {
            if let Some(te) = sim.first_surface_event() {
                if sim.time() >= te + m.onset_window_s {
                    break;
                }
            }
        }
    }
    let event = sim.first_surface_event();
    let result = sim.finish();
    let dt = s.sim.record_interval_s;
    let mut p = Partial::empty(sc);
    // Signal names were checked when the scenario was validated; a name that is not a signal is
    // an error here, never an empty column.
    let column =
        |name: &str| result.trace.column(name).ok_or_else(|| format!("monte_carlo: '{name}' is not a trace column"));
    for e in p.envelopes.iter_mut() {
        e.rows = column(&e.signal)?
            .iter()
            .map(|&v| {
                let mut x = ExactMoments::new(ENV_BITS, 2);
                x.push(v);
                x
            })
            .collect();
    }
    let row = libm::round(m.histogram_time_s / dt) as usize;
    if let Some(&v) = column(&m.histogram_signal)?.get(row) {
        p.at_time.push(v);
        p.at_time_hist.push(v);
    }
    let power = result.trace.get(Signal::ImPowerPu);
    if let Some(sub) = submerged {
        let counterpart = |e: SimError| format!("trial {i} (submerged counterpart): {e}");
        let mut sim = sub.as_ref().map_err(|e| counterpart(e.clone()))?.with_seed(s.sim.seed).map_err(counterpart)?;
        sim.advance(u64::MAX).map_err(counterpart)?;
        let r = sim.finish();
        let n = power.len().min(r.trace.len());
        let base = r.trace.get(Signal::ImPowerPu);
        let e = (motor_energy(&s, &power[..n], dt) - motor_energy(&s, &base[..n], dt)) / 1e6;
        p.excess_energy_mj.push(e);
        p.excess_hist.push(e);
        let calm: Vec<f64> = vec![power.first().copied().unwrap_or(0.0); n];
        let c = (motor_energy(&s, &power[..n], dt) - motor_energy(&s, &calm, dt)) / 1e6;
        p.excess_vs_calm_mj.push(c);
        p.excess_vs_calm_hist.push(c);
    }
    let cap = s.sim.duration_s;
    match event {
        Some(t) => {
            p.arrival.push(t);
            p.arrival_hist.push(t);
            p.exposure.push(t.min(cap));
            let start = libm::ceil(t / dt) as usize;
            let n = libm::round(m.onset_window_s / dt) as usize + 1;
            p.onset = power
                .iter()
                .skip(start)
                .take(n)
                .map(|&v| {
                    let mut x = ExactMoments::new(ENV_BITS, 2);
                    x.push(v);
                    x
                })
                .collect();
        }
        None => {
            p.censored = 1;
            p.exposure.push(cap);
        }
    }
    // Welch periodogram of one motor's power [MW^2/Hz].
    let seg = libm::round(m.periodogram_segment_s / dt) as usize;
    if power.len() >= seg.max(4) {
        let mw: Vec<f64> = power.iter().map(|v| v * s.plant.motor.rated_power_w / 1e6).collect();
        let (f, psd) = welch(&mw, dt, seg);
        p.periodogram_hz = f;
        p.periodogram = psd
            .iter()
            .map(|&v| {
                let mut x = ExactMoments::new(ENV_BITS, 2);
                x.push(v);
                x
            })
            .collect();
    }
    if i < m.keep_traces as u64 {
        let t = result.trace.get(Signal::TS).to_vec();
        let names = trace_columns(m);
        p.traces = vec![KeptTrace {
            trial: i,
            seed: s.sim.seed,
            t_s: t,
            columns: names.iter().map(|n| Ok((n.clone(), column(n)?.to_vec()))).collect::<Result<_, String>>()?,
        }];
    }
    Ok(p)
}

/// What one accumulator of the study `sc` keeps: (moment rows, kept trace values, bytes).
pub fn study_bytes(sc: &Scenario) -> (f64, f64, f64) {
    let m = &sc.monte_carlo;
    let dt = sc.sim.record_interval_s;
    let rows = libm::floor(sc.sim.duration_s / dt) + 1.0;
    let onset = libm::round(m.onset_window_s / dt) + 1.0;
    let bins = libm::round(m.periodogram_segment_s / dt) / 2.0 + 1.0;
    let moments = m.envelope_signals.len() as f64 * rows + onset.min(rows) + bins;
    let columns = trace_columns(m).len() as f64 + 1.0;
    let traces = (m.keep_traces as u64).min(m.trials) as f64 * rows * columns;
    let bytes = moments * std::mem::size_of::<ExactMoments>() as f64 + traces * 8.0;
    (moments, traces, bytes)
}

/// The columns of a kept trace: the envelope signals, then those the page draws beside them.
fn trace_columns(m: &crate::scenario::MonteCarloParams) -> Vec<String> {
    let mut names: Vec<String> = m.envelope_signals.clone();
    for extra in [Signal::HOverR, Signal::BetaT, Signal::ImPowerPu] {
        if !names.iter().any(|n| n == extra.name()) {
            names.push(extra.name().into());
        }
    }
    names
}

/// Checks before a study starts that what it keeps fits [`MAX_STUDY_BYTES`] and its work
/// [`MAX_STUDY_WORK`]; the error says what the study would take and what to reduce.
pub fn check_study(sc: &Scenario) -> Result<(), String> {
    let m = &sc.monte_carlo;
    let (moments, traces, bytes) = study_bytes(sc);
    if bytes > MAX_STUDY_BYTES {
        return Err(format!(
            "monte_carlo: this study keeps about {:.0} MB ({} envelope signals x {:.0} rows and {:.0} more moment rows, \
             {} kept traces of {:.3e} values); at most {:.0} MB: record less often (sim.record_interval_s = {}), \
             shorten the run (sim.duration_s = {}), or keep fewer monte_carlo.envelope_signals or monte_carlo.keep_traces",
            bytes / 1e6,
            m.envelope_signals.len(),
            libm::floor(sc.sim.duration_s / sc.sim.record_interval_s) + 1.0,
            moments - m.envelope_signals.len() as f64 * (libm::floor(sc.sim.duration_s / sc.sim.record_interval_s) + 1.0),
            (m.keep_traces as u64).min(m.trials),
            traces,
            MAX_STUDY_BYTES / 1e6,
            crate::checks::num(sc.sim.record_interval_s),
            crate::checks::num(sc.sim.duration_s)
        ));
    }
    let work = m.trials as f64 * sc.work();
    if work > MAX_STUDY_WORK {
        return Err(format!(
            "monte_carlo.trials = {}: with {:.3e} units of work a trial this study is {work:.3e}; at most {MAX_STUDY_WORK:e} \
             (about 8 hours on one core): fewer trials, or a shorter run (sim.duration_s = {})",
            m.trials,
            sc.work(),
            crate::checks::num(sc.sim.duration_s)
        ));
    }
    Ok(())
}

/// The whole study of `sc` (its `monte_carlo` section), one trial after another, and its summary.
pub fn run_study(sc: &Scenario) -> Result<StudySummary, String> {
    crate::studies::study::run_all(&MonteCarlo::new(sc.clone())?)
}

/// A histogram in a summary: bins over [lo, hi), with the counts that fell outside.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistogramSummary {
    pub lo: f64,
    pub hi: f64,
    pub counts: Vec<u64>,
    pub below: u64,
    pub above: u64,
}

impl From<&Histogram> for HistogramSummary {
    fn from(h: &Histogram) -> Self {
        HistogramSummary { lo: h.lo, hi: h.hi, counts: h.counts.clone(), below: h.below, above: h.above }
    }
}

/// Statistics over trials of one signal, row by recorded row (an envelope, the onset window).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RowStats {
    pub t_s: Vec<f64>,
    /// Trials that reached the row (fewer towards the end when trials stop at their first event).
    pub n: Vec<u64>,
    pub mean: Vec<Option<f64>>,
    pub std: Vec<Option<f64>>,
    pub min: Vec<Option<f64>>,
    pub max: Vec<Option<f64>>,
    pub plus_2sigma: Vec<Option<f64>>,
    pub minus_2sigma: Vec<Option<f64>>,
}

impl RowStats {
    fn of(rows: &[ExactMoments], dt: f64) -> RowStats {
        let each = |f: &dyn Fn(&ExactMoments) -> f64| rows.iter().map(|r| stat(r.n, f(r))).collect::<Vec<_>>();
        RowStats {
            t_s: (0..rows.len()).map(|i| i as f64 * dt).collect(),
            n: rows.iter().map(|r| r.n).collect(),
            min: each(&|r| r.min),
            max: each(&|r| r.max),
            // The spread needs two trials or more (a row where one is left has none).
            plus_2sigma: rows.iter().map(|r| r.std_defined().map(|s| r.mean() + 2.0 * s)).collect(),
            minus_2sigma: rows.iter().map(|r| r.std_defined().map(|s| r.mean() - 2.0 * s)).collect(),
            mean: each(&|r| r.mean()),
            std: rows.iter().map(|r| r.std_defined()).collect(),
        }
    }
}

/// Excess energy against the calm-water power at the ordered speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExcessVsCalm {
    pub mean: Option<f64>,
    pub std: Option<f64>,
    pub histogram: HistogramSummary,
    pub definition: &'static str,
}

/// Excess motor energy due to surface effects, per trial \[MJ\].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExcessEnergy {
    pub mean: Option<f64>,
    pub std: Option<f64>,
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub histogram: HistogramSummary,
    pub definition: &'static str,
    pub vs_calm_water: ExcessVsCalm,
}

/// Arrival times of the first surface effect \[s\], with censoring at the run's end.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ArrivalTimes {
    pub events: u64,
    pub censored: u64,
    pub cap_s: f64,
    pub mean: Option<f64>,
    pub std: Option<f64>,
    pub skewness: Option<f64>,
    pub kurtosis: Option<f64>,
    pub median: Option<f64>,
    pub mode: Option<f64>,
    pub histogram: HistogramSummary,
    pub mean_censored: Option<f64>,
    pub std_censored: Option<f64>,
    pub rate_per_s: Option<f64>,
}

/// The histogram of one signal at one time over trials.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistogramAtTime {
    pub signal: String,
    pub t_s: f64,
    pub n: u64,
    pub mean: Option<f64>,
    pub std: Option<f64>,
    pub skewness: Option<f64>,
    pub histogram: HistogramSummary,
}

/// Welch periodogram of one motor's power over trials.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PeriodogramSummary {
    /// Trials that ran at least one whole segment, the ones averaged (a trial that stops at its
    /// first surface effect may end before one).
    pub trials: u64,
    /// Welch's segment \[s\] (`monte_carlo.periodogram_segment_s`).
    pub segment_s: f64,
    pub freq_hz: Vec<f64>,
    pub unit: &'static str,
    pub mean: Vec<Option<f64>>,
    pub min: Vec<Option<f64>>,
    pub max: Vec<Option<f64>>,
}

/// The public summary of a study (documented in docs/studies/monte-carlo.md).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudySummary {
    pub trials: u64,
    pub trials_requested: u64,
    pub seed: u64,
    pub ranges: Vec<(u64, u64)>,
    pub excess_energy_mj: Option<ExcessEnergy>,
    pub arrival_time_s: ArrivalTimes,
    pub rice: Option<RiceSummary>,
    pub histogram_at_t: HistogramAtTime,
    pub envelopes: std::collections::BTreeMap<String, RowStats>,
    pub onset: RowStats,
    pub periodogram: PeriodogramSummary,
    pub traces: Vec<KeptTrace>,
}

/// `x`, read from a histogram of the values `m` counts, held within their extremes: a bin's
/// interpolation or centre can lie beyond them (four arrivals at 0 s gave a median of 0.111 s,
/// the first bin's middle, beside a mean and maximum of 0).
fn within(x: f64, m: &ExactMoments) -> f64 {
    x.max(m.min).min(m.max)
}

/// A statistic of `n` samples: None (JSON null) when undefined because there are none.
fn stat(n: u64, x: f64) -> Option<f64> {
    (n > 0).then_some(x)
}

/// The public summary of the trials `ranges` of the study `sc`.
pub fn study_summary(sc: &Scenario, ranges: &[(u64, u64)], p: &Partial) -> Result<StudySummary, String> {
    let m = &sc.monte_carlo;
    let envelopes =
        p.envelopes.iter().map(|e| (e.signal.clone(), RowStats::of(&e.rows, p.record_interval_s))).collect();
    let events = p.arrival.n;
    let ee = &p.excess_energy_mj;
    let ec = &p.excess_vs_calm_mj;
    let excess_energy_mj = m.excess_energy.then(|| ExcessEnergy {
        mean: stat(ee.n, ee.mean()),
        std: ee.std_defined(),
        min: stat(ee.n, ee.min),
        max: stat(ee.n, ee.max),
        histogram: (&p.excess_hist).into(),
        definition: "energy drawn by one motor minus that drawn in the same sea without surface losses [MJ]",
        vs_calm_water: ExcessVsCalm {
            mean: stat(ec.n, ec.mean()),
            std: ec.std_defined(),
            histogram: (&p.excess_vs_calm_hist).into(),
            definition:
                "energy drawn by one motor minus its calm-water power at the ordered speed times the duration [MJ]",
        },
    });
    let exposure_total = p.exposure.mean() * p.exposure.n as f64;
    Ok(StudySummary {
        trials: crate::studies::study::count(ranges),
        trials_requested: m.trials,
        seed: sc.sim.seed,
        ranges: ranges.to_vec(),
        excess_energy_mj,
        arrival_time_s: ArrivalTimes {
            events,
            censored: p.censored,
            cap_s: sc.sim.duration_s,
            mean: stat(events, p.arrival.mean()),
            std: p.arrival.std_defined(),
            skewness: p.arrival.skewness_defined(),
            kurtosis: p.arrival.kurtosis_defined(),
            median: stat(p.arrival_hist.total(), within(p.arrival_hist.median(), &p.arrival)),
            mode: stat(p.arrival_hist.total(), within(p.arrival_hist.mode(), &p.arrival)),
            histogram: (&p.arrival_hist).into(),
            mean_censored: stat(p.exposure.n, p.exposure.mean()),
            std_censored: p.exposure.std_defined(),
            rate_per_s: (exposure_total > 0.0).then(|| events as f64 / exposure_total),
        },
        rice: rice_summary(sc)?,
        histogram_at_t: HistogramAtTime {
            signal: m.histogram_signal.clone(),
            t_s: m.histogram_time_s,
            n: p.at_time.n,
            mean: stat(p.at_time.n, p.at_time.mean()),
            std: p.at_time.std_defined(),
            skewness: p.at_time.skewness_defined(),
            histogram: (&p.at_time_hist).into(),
        },
        envelopes,
        onset: RowStats::of(&p.onset, p.record_interval_s),
        periodogram: PeriodogramSummary {
            trials: p.periodogram.first().map_or(0, |r| r.n),
            segment_s: m.periodogram_segment_s,
            freq_hz: p.periodogram_hz.clone(),
            unit: "MW^2/Hz",
            mean: p.periodogram.iter().map(|r| stat(r.n, r.mean())).collect(),
            min: p.periodogram.iter().map(|r| stat(r.n, r.min)).collect(),
            max: p.periodogram.iter().map(|r| stat(r.n, r.max)).collect(),
        },
        traces: p.traces.clone(),
    })
}

/// Names of the trace columns a study may collect.
pub fn signal_names() -> impl Iterator<Item = &'static str> {
    crate::signals::names()
}

/// The Monte Carlo study of a scenario (its `monte_carlo` section): trial i sails the sea of
/// `trial_seed(sim.seed, i)`.
pub struct MonteCarlo {
    sc: Scenario,
}

impl Study for MonteCarlo {
    const KIND: &'static str = "monte-carlo";
    const ITEM: &'static str = "trial";
    type Spec = Scenario;
    type Shared = Trials;
    type Part = Partial;
    type Summary = StudySummary;

    fn new(sc: Scenario) -> Result<MonteCarlo, String> {
        sc.validate().map_err(|e| format!("its scenario is not valid: {e}"))?;
        check_study(&sc)?;
        Ok(MonteCarlo { sc })
    }
    fn spec(&self) -> &Scenario {
        &self.sc
    }
    fn scenario(&self) -> &Scenario {
        &self.sc
    }
    fn items(&self) -> u64 {
        self.sc.monte_carlo.trials
    }
    fn item_work(&self) -> Option<f64> {
        Some(self.sc.work())
    }
    fn prepare(&self) -> Result<Trials, String> {
        Ok(Trials::new(&self.sc))
    }
    fn run(&self, trials: &Trials, i: u64) -> Result<Partial, String> {
        trials.run(i)
    }
    fn empty(&self) -> Partial {
        Partial::empty(&self.sc)
    }
    fn merge(&self, acc: &mut Partial, other: &Partial) -> Result<(), String> {
        acc.merge(other, self.sc.monte_carlo.keep_traces as usize)
    }
    fn check_part(&self, part: &Partial, ranges: &[(u64, u64)]) -> Result<(), String> {
        part.validate(&self.sc, ranges)
    }
    fn summary(&self, part: &Partial, ranges: &[(u64, u64)]) -> Result<StudySummary, String> {
        study_summary(&self.sc, ranges, part)
    }
    /// The definition is the scenario itself.
    fn spec_from_json(text: &str) -> Result<Scenario, String> {
        Scenario::from_json(text).map_err(|e| e.to_string())
    }
    fn part_to_bytes(part: &Partial) -> Result<Vec<u8>, String> {
        part.to_bytes()
    }
    fn part_from_bytes(b: &[u8]) -> Result<Partial, String> {
        Partial::from_bytes(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A shard is a < b <= trials; merging needs one partial, and one merged alone is itself.
    /// Issue 34: what a study keeps is bounded before it starts. The valid 4.9 kB
    /// scenario (calm, 1,020 s recorded every 5 ms, 20 envelope signals, 10 kept traces, 10
    /// trials; it took 7.6 GB; 8.7 kB written out since the scenario has its operability section)
    /// is refused with a message naming what to reduce, in every way a
    /// study starts (a shard, a range as the browser runs it, a partial naming it); every
    /// preset's study fits with room (at most 2.6 MB, the budget 64 MB), and 1e7 trials of a
    /// 1,000 s run are over the work budget.
    #[test]
    fn a_study_keeps_what_its_budget_allows() {
        for name in crate::scenario::presets::PRESET_NAMES {
            let sc = crate::scenario::presets::preset(name).unwrap();
            let (_, _, bytes) = study_bytes(&sc);
            assert!(bytes <= 2.6e6, "{name}: {bytes} bytes");
            assert!(check_study(&sc).is_ok(), "{name}: {:?}", check_study(&sc));
        }
        let mut sc = Scenario::default();
        sc.sim.duration_s = 900.0;
        sc.sim.record_interval_s = 0.005;
        sc.monte_carlo.trials = 10;
        sc.monte_carlo.keep_traces = 10;
        sc.monte_carlo.envelope_signals = signal_names().take(20).map(String::from).collect();
        assert!(sc.validate().is_ok(), "{:?}", sc.validate());
        assert!(sc.to_json().len() < 11000, "{} bytes", sc.to_json().len());
        let e = MonteCarlo::new(sc.clone()).err().unwrap();
        assert!(e.starts_with("monte_carlo: this study keeps about 735 MB (20 envelope signals x 180001 rows"), "{e}");
        assert!(e.contains("at most 64 MB: record less often (sim.record_interval_s = 0.005)"), "{e}");
        let mut long = Scenario::default();
        long.sim.duration_s = 1000.0;
        long.monte_carlo.trials = 10_000_000;
        let e = check_study(&long).unwrap_err();
        assert!(e.starts_with("monte_carlo.trials = 10000000: with"), "{e}");
    }

    #[test]
    fn shards_are_checked_and_merged() {
        use crate::studies::study::{check_range, run_range, Merger};
        let mut sc = Scenario::default();
        sc.monte_carlo.trials = 4;
        let mc = MonteCarlo::new(sc.clone()).unwrap();
        assert!(check_range(&mc, 0, 4).is_ok() && check_range(&mc, 3, 4).is_ok());
        for (a, b) in [(2, 2), (3, 1), (0, 5)] {
            assert_eq!(check_range(&mc, a, b).unwrap_err(), "need a < b <= the study's 4 trials");
        }
        assert!(run_range(&mc, 3, 9).unwrap_err().starts_with("trials 3..9: need a < b"));
        assert_eq!(Merger::new(MonteCarlo::new(sc.clone()).unwrap()).finish().err().unwrap(), "no shards given");
        let mut m = Merger::new(MonteCarlo::new(sc.clone()).unwrap());
        let empty = crate::studies::study::shard(&mc, vec![], Partial::empty(&sc));
        m.add(empty.clone()).unwrap();
        assert_eq!(m.finish().unwrap().1, empty);
    }
}
