//! What a [`Session`] reports: its statistics (the costs, coverages and counts of the paths it
//! found) and its result in the contract's JSON form.

use super::Session;
use crate::math::Real;
use crate::planners::{self, smoothing, InspectionTask, TaskKind};
use crate::run::{PlanResult, SamplerSummary, Stats};
use crate::status::Status;

impl Session {
    /// Statistics so far.
    pub fn stats(&self) -> Stats {
        let si = &self.problem.si;
        let solved = self.status == Status::Solved;
        Stats {
            time_ms: self.elapsed_ms,
            iterations: self.iterations,
            nodes: self.planner.node_count() as u64,
            checks: self.planning_checks.map_or_else(|| si.checks(), |c| c.0),
            free_checks: self.planning_checks.map_or_else(|| si.free_checks(), |c| c.1),
            cost: solved.then(|| smoothing::path_cost(si, &self.path)),
            smoothed_cost: solved.then(|| smoothing::path_cost(si, &self.smoothed)),
            smoothing_ms: self.smoothing_ms,
            coverage: self.coverage(&self.path).or_else(|| self.planner.coverage()),
            smoothed_coverage: self.coverage(&self.smoothed),
            course_coverage: self.coverage_by(&self.path, planners::inspection::course_coverage),
            continuous_coverage: self.coverage_by(&self.path, planners::inspection::continuous_coverage),
            cost_fk: self.cost_fk(&self.path),
            smoothed_cost_fk: self.cost_fk(&self.smoothed),
            repaired: self.repaired.map(|r| r as u64),
            roadmap: self.planner.roadmap_counts(),
            sampler: SamplerSummary::of(
                self.sampler.name(),
                self.spec.groups.iter().any(|g| g.name == crate::sampler::SAMPLER_GROUP.name),
                self.sampler.stats(),
            ),
        }
    }

    /// The fraction of inspection points a path sees (inspection planners only; `None` before a
    /// path exists).
    fn coverage(&self, path: &[Vec<Real>]) -> Option<Real> {
        match (&self.task.inspection, self.spec.task) {
            (Some(i), TaskKind::Inspection) if !path.is_empty() => {
                Some(planners::inspection::path_coverage(&self.problem.si, i, path))
            }
            _ => None,
        }
    }

    /// A path's coverage by a given definition (inspection planners only; `None` before a path).
    fn coverage_by(
        &self,
        path: &[Vec<Real>],
        by: fn(&crate::space_info::SpaceInfo, &InspectionTask, &[Vec<Real>]) -> Real,
    ) -> Option<Real> {
        match (&self.task.inspection, self.spec.task) {
            (Some(i), TaskKind::Inspection) if !path.is_empty() => Some(by(&self.problem.si, i, path)),
            _ => None,
        }
    }

    /// A solved arm path's cost in report 004's unit (`None` for other robots or before a path).
    fn cost_fk(&self, path: &[Vec<Real>]) -> Option<Real> {
        match &self.problem.scenario.robot {
            crate::scenario::RobotSpec::Arm { links, .. } if !path.is_empty() => {
                Some(crate::robot::fk_path_cost(links, path))
            }
            _ => None,
        }
    }

    /// The result in the contract's form.
    pub fn result(&self) -> PlanResult {
        PlanResult {
            solved: self.status == Status::Solved,
            status: self.status.name(),
            seed: self.config.seed,
            planner: self.spec.name.to_string(),
            params: self.config.params.values().clone(),
            path: self.problem.decode_path(&self.path),
            smoothed: self.problem.decode_path(&self.smoothed),
            stats: self.stats(),
            reason: self.reason.clone(),
        }
    }
}
