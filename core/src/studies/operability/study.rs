//! The operability polar on the shared study pipeline: item j is speed j of the request, a part
//! is the cells and scatter shares of some speeds, and the summary is the polar.

use super::{assemble, scatter::Scatter, Cell, Polar, PolarRequest, PolarSetup, PolarSpec};
use crate::scenario::Scenario;
use crate::studies::study::{merge_records, missing, records_of, Study};
use serde::{Deserialize, Serialize};

/// The definition of a polar: the scenario (its ship, criteria, spreading) and the request (the
/// speeds, headings, seas and scatter diagram).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolarStudySpec {
    pub scenario: Scenario,
    #[serde(default)]
    pub request: PolarRequest,
}

/// One speed's cells (every heading) and, with a scatter diagram, each heading's operable share.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedRow {
    /// The speed's index in the request's speeds.
    pub speed: u64,
    pub cells: Vec<Cell>,
    pub shares: Vec<f64>,
}

/// The operability polar as a study.
pub struct OperabilityPolar {
    spec: PolarStudySpec,
    polar: PolarSpec,
    scatter: Option<Scatter>,
}

impl Study for OperabilityPolar {
    const KIND: &'static str = "operability";
    const ITEM: &'static str = "speed";
    type Spec = PolarStudySpec;
    /// The judge, the RAO table and the frequency grid every speed reads.
    type Shared = PolarSetup;
    type Part = Vec<SpeedRow>;
    type Summary = Polar;

    fn new(spec: PolarStudySpec) -> Result<OperabilityPolar, String> {
        spec.scenario.validate().map_err(|e| format!("its scenario is not valid: {e}"))?;
        let (polar, scatter) = spec.request.resolve()?;
        polar.check(spec.scenario.seakeeping.grid.speed_max_kn)?;
        Ok(OperabilityPolar { spec, polar, scatter })
    }
    fn spec(&self) -> &PolarStudySpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        &self.spec.scenario
    }
    fn items(&self) -> u64 {
        self.polar.speeds_kn.len() as u64
    }
    /// The polar is made of the RAO table, whatever the scenario's own sea.
    fn needs_rao_table(&self) -> bool {
        true
    }
    fn prepare(&self) -> Result<PolarSetup, String> {
        PolarSetup::new(&self.spec.scenario, self.polar.clone(), self.scatter.as_ref())
    }
    fn run(&self, setup: &PolarSetup, j: u64) -> Result<Vec<SpeedRow>, String> {
        let (cells, shares) = setup.speed(j as usize, self.scatter.as_ref());
        Ok(vec![SpeedRow { speed: j, cells, shares }])
    }
    fn empty(&self) -> Vec<SpeedRow> {
        Vec::new()
    }
    fn merge(&self, acc: &mut Vec<SpeedRow>, other: &Vec<SpeedRow>) -> Result<(), String> {
        merge_records(acc, other, |r| r.speed, "speed")
    }
    /// One row for each speed of the ranges, in order, each with one cell per heading at its own
    /// speed and as many shares as cells (none without a scatter diagram).
    fn check_part(&self, part: &Vec<SpeedRow>, ranges: &[(u64, u64)]) -> Result<(), String> {
        let headings = part.first().map_or(0, |r| r.cells.len());
        for (r, j) in records_of(part, ranges, |r| r.speed, "speed")? {
            let speed = self.polar.speeds_kn[j as usize];
            let shares = if self.scatter.is_some() { r.cells.len() } else { 0 };
            if r.cells.is_empty()
                || r.cells.len() != headings
                || r.shares.len() != shares
                || r.cells.iter().any(|c| c.speed_kn != speed)
            {
                return Err(format!("speed {j}: not the row of speed {j} ({} kn) of this polar", speed));
            }
        }
        Ok(())
    }
    fn summary(&self, part: &Vec<SpeedRow>, ranges: &[(u64, u64)]) -> Result<Polar, String> {
        let gaps = missing(ranges, self.items());
        if let Some((a, b)) = gaps.first() {
            return Err(format!("the polar lacks speeds {a}..{b} (of {})", self.items()));
        }
        let setup = self.prepare()?;
        let rows = part.iter().map(|r| (r.cells.clone(), r.shares.clone())).collect();
        let polar = assemble(&self.spec.scenario, &setup, rows, self.scatter.as_ref())?;
        crate::checks::check_finite(&polar)?;
        Ok(polar)
    }
}
