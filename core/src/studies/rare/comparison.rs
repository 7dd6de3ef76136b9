//! The same events with another plant (`--against`), trial by trial.

use super::*;

/// The same study with another plant (thesis ch. 6.1: an event's consequences with and without
/// storage): `other`'s plant in the study's trial scenario, so every trial meets the same
/// conditioned sea at the same place, speed estimate and time, and only the plant differs. The
/// two scenarios must differ in nothing but their `plant` section (a different sea, ship or event
/// would not be the same event).
pub fn with_plant(spec: &RareSpec, sc: &Scenario, other: &Scenario) -> Result<RareSpec, String> {
    let (a, b) =
        (serde_json::to_value(sc).map_err(|e| e.to_string())?, serde_json::to_value(other).map_err(|e| e.to_string())?);
    let (Some(a), Some(b)) = (a.as_object(), b.as_object()) else {
        return Err("a scenario is not an object".into());
    };
    let differ: Vec<&str> = a
        .iter()
        .filter(|(k, v)| !matches!(k.as_str(), "plant" | "name" | "description") && b.get(k.as_str()) != Some(v))
        .map(|(k, _)| k.as_str())
        .collect();
    if !differ.is_empty() {
        return Err(format!(
            "the two scenarios differ in {} as well as in their plant: only the plant may differ, so that the trials meet the same events",
            differ.join(", ")
        ));
    }
    let mut s = spec.clone();
    s.scenario.plant = other.plant.clone();
    s.scenario.validate().map_err(|e| e.to_string())?;
    Ok(s)
}

/// One consequence of the same events in two plants, trial by trial.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairedConsequence {
    pub name: &'static str,
    pub label: &'static str,
    pub larger_is_worse: bool,
    /// Means given the event (weighted by the trials' crossing rates), first plant and second.
    pub mean: f64,
    pub mean_other: f64,
    /// The second plant's value minus the first's: its weighted mean and 95 % interval (the
    /// ratio estimator's standard error over the trials).
    pub difference: f64,
    pub difference_low: f64,
    pub difference_high: f64,
    /// Share of the trials (weighted) in which the second plant did better.
    pub other_better_share: f64,
    /// Share of the trials (weighted) in which both gave the same value (no brake energy in
    /// either, say): neither better nor worse.
    pub tied_share: f64,
}

/// The paired comparison of two plants' trials of the same study ([`with_plant`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Paired {
    pub trials: usize,
    pub consequences: Vec<PairedConsequence>,
}

/// Trials `a` and `b` of the same events, matched by trial and sea seed; weights are `a`'s
/// crossing rates (the same seas on the same track give the same rates).
pub fn paired(a: &[TrialRecord], b: &[TrialRecord]) -> Result<Paired, String> {
    if a.len() != b.len() || a.len() < MIN_TRIALS as usize {
        return Err(format!("{} and {} trials: the same number, at least {MIN_TRIALS}, are needed", a.len(), b.len()));
    }
    if let Some((x, _)) = a.iter().zip(b).find(|(x, y)| x.trial != y.trial || x.seed != y.seed) {
        return Err(format!("trial {}: the two studies' trials are not the same events", x.trial));
    }
    let w: Vec<f64> = a.iter().map(|t| t.crossing_rate_per_s).collect();
    let sw: f64 = w.iter().sum();
    if sw.is_nan() || sw <= 0.0 {
        return Err("the trials' seas have no crossing rate".into());
    }
    let wmean = |x: &dyn Fn(usize) -> f64| (0..a.len()).map(|j| w[j] * x(j)).sum::<f64>() / sw;
    let consequences = CONSEQUENCES
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let d = |j: usize| b[j].values[k] - a[j].values[k];
            let mean_d = wmean(&d);
            // The ratio estimator's standard error with the n / (n - 1) of a sample variance (without
            // it the interval of 2 trials is 29 % too narrow).
            let n = a.len() as f64;
            let ss: f64 = (0..a.len()).map(|j| (w[j] * (d(j) - mean_d)) * (w[j] * (d(j) - mean_d))).sum();
            let se = libm::sqrt(n / (n - 1.0) * ss) / sw;
            let better = |j: usize| {
                let dj = d(j);
                f64::from(u8::from(if c.larger_is_worse { dj < 0.0 } else { dj > 0.0 }))
            };
            let tied = |j: usize| f64::from(u8::from(d(j) == 0.0));
            PairedConsequence {
                name: c.name,
                label: c.label,
                larger_is_worse: c.larger_is_worse,
                mean: wmean(&|j| a[j].values[k]),
                mean_other: wmean(&|j| b[j].values[k]),
                difference: mean_d,
                difference_low: mean_d - 1.96 * se,
                difference_high: mean_d + 1.96 * se,
                other_better_share: wmean(&better),
                tied_share: wmean(&tied),
            }
        })
        .collect();
    Ok(Paired { trials: a.len(), consequences })
}

/// The definition of a comparison of two plants: the two studies (the second from [`with_plant`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PairedSpec {
    pub first: RareSpec,
    pub second: RareSpec,
}

/// One trial in both plants.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PairedRecord {
    pub first: TrialRecord,
    pub second: TrialRecord,
}

/// The JSON of `aes-sim rare --against`: both summaries and the paired consequences (the keys in
/// this order, as the command has always printed them).
#[derive(Debug, Clone, Serialize)]
pub struct PairedSummary {
    pub first: RareSummary,
    pub paired: Paired,
    pub second: RareSummary,
}

/// The same trials in two plants on the study pipeline: item i is trial i in each.
pub struct RarePair {
    spec: PairedSpec,
    first: RareEvents,
    second: RareEvents,
}

impl Study for RarePair {
    const KIND: &'static str = "rare-against";
    const ITEM: &'static str = "trial";
    type Spec = PairedSpec;
    type Shared = (Trials, Trials);
    type Part = Vec<PairedRecord>;
    type Summary = PairedSummary;

    fn new(spec: PairedSpec) -> Result<RarePair, String> {
        if spec.first.trials != spec.second.trials {
            return Err("the two plants' studies must have as many trials".into());
        }
        let (first, second) = (RareEvents::new(spec.first.clone())?, RareEvents::new(spec.second.clone())?);
        Ok(RarePair { spec, first, second })
    }
    fn spec(&self) -> &PairedSpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        self.first.scenario()
    }
    fn items(&self) -> u64 {
        self.first.items()
    }
    /// A trial in each plant.
    fn item_work(&self) -> Option<f64> {
        Some(trial_work(self.first.scenario()) + trial_work(self.second.scenario()))
    }
    /// Each plant's seakeeping tables are built as its trials ask (as before the pipeline).
    fn needs_rao_table(&self) -> bool {
        false
    }
    fn prepare(&self) -> Result<(Trials, Trials), String> {
        Ok((self.first.prepare()?, self.second.prepare()?))
    }
    fn run(&self, (a, b): &(Trials, Trials), i: u64) -> Result<Vec<PairedRecord>, String> {
        Ok(vec![PairedRecord { first: a.run(i)?, second: b.run(i)? }])
    }
    fn empty(&self) -> Vec<PairedRecord> {
        Vec::new()
    }
    fn merge(&self, acc: &mut Vec<PairedRecord>, other: &Vec<PairedRecord>) -> Result<(), String> {
        crate::studies::study::merge_records(acc, other, |t| t.first.trial, "trial")
    }
    /// Each plant's records as its own study checks them.
    fn check_part(&self, part: &Vec<PairedRecord>, ranges: &[(u64, u64)]) -> Result<(), String> {
        let (a, b) = split(part);
        self.first.check_part(&a, ranges).map_err(|e| format!("first: {e}"))?;
        self.second.check_part(&b, ranges).map_err(|e| format!("second: {e}"))
    }
    fn summary(&self, part: &Vec<PairedRecord>, ranges: &[(u64, u64)]) -> Result<PairedSummary, String> {
        let (a, b) = split(part);
        let (first, second) = (self.first.summary(&a, ranges)?, self.second.summary(&b, ranges)?);
        Ok(PairedSummary { first, paired: paired(&a, &b)?, second })
    }
}

/// A paired part as the two plants' records.
fn split(part: &[PairedRecord]) -> (Vec<TrialRecord>, Vec<TrialRecord>) {
    part.iter().map(|p| (p.first.clone(), p.second.clone())).unzip()
}
