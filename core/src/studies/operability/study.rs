//! The operability polar on the shared study pipeline: item j is speed j of the request, a part
//! is the cells and scatter shares of some speeds, and the summary is the polar.

use super::{assemble, bounds::CellLimits, scatter::Scatter, Cell, Polar, PolarRequest, PolarSetup, PolarSpec};
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
    /// The spec as the cells are made of it (headings once, seas sorted), and the criteria.
    normalised: PolarSpec,
    criteria: usize,
    scatter: Option<Scatter>,
    /// The setup and the bounds the rows of shards from outside are checked against, made at
    /// the first check (the RAO table is cached, and a merge's summary needs it anyway).
    bounds: std::sync::OnceLock<Result<(PolarSetup, CellLimits), String>>,
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
        // The lists and the work are checked now, before a command builds the RAO table.
        PolarSetup::check(&spec.scenario, polar.clone(), scatter.as_ref())?;
        let mut normalised = polar.clone();
        normalised.normalise();
        let criteria = spec.scenario.operability.criteria.len();
        Ok(OperabilityPolar { spec, polar, normalised, criteria, scatter, bounds: std::sync::OnceLock::new() })
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
    /// One row for each speed of the ranges, in order: one cell per heading of the polar (after
    /// [`PolarSpec::normalise`]) at its own speed and heading, each sea's values and limits for
    /// every criterion, a limiting criterion among them, at most every sea passed, and a share in
    /// [0, 1] per heading with a scatter diagram (none without); then each cell's numbers within
    /// what the RAO table allows and consistent with each other ([`CellLimits::check`]).
    fn check_part(&self, part: &Vec<SpeedRow>, ranges: &[(u64, u64)]) -> Result<(), String> {
        use crate::checks::num;
        let (h, nseas, nc) = (&self.normalised.headings_deg, self.normalised.seas.len(), self.criteria);
        for (r, j) in records_of(part, ranges, |r| r.speed, "speed")? {
            let speed = self.polar.speeds_kn[j as usize];
            let not =
                |what: String| Err(format!("speed {j}: {what}: not the row of speed {j} ({speed} kn) of this polar"));
            let shares = if self.scatter.is_some() { h.len() } else { 0 };
            if r.cells.len() != h.len() || r.shares.len() != shares {
                return not(format!(
                    "{} cells and {} shares for its {} headings",
                    r.cells.len(),
                    r.shares.len(),
                    h.len()
                ));
            }
            if let Some((k, x)) = r.shares.iter().enumerate().find(|(_, x)| !(0.0..=1.0).contains(*x)) {
                return not(format!("shares.{k} = {}: an operable share is from 0 to 1", num(*x)));
            }
            for (k, (c, &hd)) in r.cells.iter().zip(h).enumerate() {
                if c.speed_kn != speed || c.heading_deg != hd {
                    return not(format!(
                        "cells.{k}: speed_kn = {}, heading_deg = {}: the cell of {speed} kn, {hd} deg",
                        num(c.speed_kn),
                        num(c.heading_deg)
                    ));
                }
                if c.values.len() != nseas
                    || c.limit_hs_m.len() != nseas
                    || c.values.iter().chain(&c.limit_hs_m).any(|v| v.len() != nc)
                {
                    return not(format!("cells.{k}: values and limit_hs_m must hold {nseas} seas x {nc} criteria"));
                }
                if c.limiting_criterion.is_some_and(|i| i >= nc) || c.seas_passed > nseas {
                    return not(format!(
                        "cells.{k}: limiting_criterion = {:?}, seas_passed = {}: at most criterion {} and {nseas} seas",
                        c.limiting_criterion,
                        c.seas_passed,
                        nc.saturating_sub(1)
                    ));
                }
            }
        }
        let (setup, limits) = self
            .bounds
            .get_or_init(|| {
                self.prepare().map(|s| {
                    let l = CellLimits::of(&s);
                    (s, l)
                })
            })
            .as_ref()
            .map_err(|e| e.clone())?;
        let hs: Vec<f64> = self.normalised.seas.iter().map(|s| s.h_sig_m).collect();
        for r in part {
            for (k, c) in r.cells.iter().enumerate() {
                limits.check(&setup.judge, c, &hs).map_err(|e| {
                    format!("speed {}: cells.{k} ({} deg): {e}", r.speed, crate::checks::num(c.heading_deg))
                })?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studies::study::{check_shard, run_range, Merger};

    /// Shards of a small polar (2 speeds x 3 headings, one of them given twice, 2 seas) merge in
    /// either order to the polar of one run; a shard whose row is not its speed's (a heading
    /// changed, a cell dropped, a criterion index past the list, a share above 1) is refused.
    #[test]
    fn polar_shards_merge_and_tampered_rows_are_refused() {
        let request = PolarRequest {
            speeds_kn: Some(vec![0.0, 18.0]),
            headings_deg: Some(vec![0.0, 90.0, 360.0, 180.0]),
            sea_states: Some(vec![4, 6]),
            ..Default::default()
        };
        let spec = PolarStudySpec { scenario: Scenario::default(), request };
        let study = OperabilityPolar::new(spec.clone()).unwrap();
        let whole = crate::studies::study::run_all(&study).unwrap();
        let (a, b) = (run_range(&study, 0, 1).unwrap(), run_range(&study, 1, 2).unwrap());
        let mut m = Merger::new(OperabilityPolar::new(spec.clone()).unwrap());
        m.add(b.clone()).unwrap();
        m.add(a.clone()).unwrap();
        let (s, merged) = m.finish().unwrap();
        assert_eq!(s.summary(&merged.part, &merged.ranges).unwrap(), whole);
        assert_eq!(whole.headings_deg, vec![0.0, 90.0, 180.0]);
        let refused = |change: &dyn Fn(&mut SpeedRow)| {
            let mut bad = b.clone();
            change(&mut bad.part[0]);
            check_shard(&study, &bad).unwrap_err()
        };
        let e = refused(&|r| r.cells[1].heading_deg = 45.0);
        assert!(
            e.starts_with("speed 1: cells.1: speed_kn = 18, heading_deg = 45") && e.contains("not the row of speed 1"),
            "{e}"
        );
        assert!(refused(&|r| {
            r.cells.pop();
        })
        .starts_with("speed 1"));
        assert!(refused(&|r| r.cells[0].limiting_criterion = Some(99)).starts_with("speed 1"));
        assert!(refused(&|r| r.shares[0] = 1.5).starts_with("speed 1"));
        // A polar lacking a speed is not drawn.
        let e = study.summary(&a.part, &a.ranges).unwrap_err();
        assert_eq!(e, "the polar lacks speeds 1..2 (of 2)");
    }
}
