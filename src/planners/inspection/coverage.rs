//! What a path sees, and smoothing that keeps it.

use super::bits::{count, covers};
use super::visibility::Visibility;
use crate::math::Real;
use crate::planners::InspectionTask;
use crate::space_info::SpaceInfo;

/// The points `task`'s sensor sees along `path` (one bit per point), at every state of each motion
/// at most the motion resolution apart, as the planner checks its edges (with the task's
/// `at_vertices`: at the path's states only).
pub fn seen_along(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Vec<u64> {
    let view = Visibility::of(task.clone());
    let words = task.points.len().div_ceil(64).max(1);
    let (mut seen, mut edge) = (vec![0u64; words], vec![0u64; words]);
    let mut buf = vec![0.0; si.dims()];
    if let Some(first) = path.first() {
        view.look(si, first, &vec![0u64; words], &mut seen);
    }
    for w in path.windows(2) {
        view.sweep(si, &w[0], &w[1], &seen, &mut edge, &mut buf);
        seen.iter_mut().zip(&edge).for_each(|(s, e)| *s |= e);
    }
    seen
}

/// The coverage `path` reaches: the fraction of `task`'s points it sees ([`seen_along`]); 1 when
/// the task has no points.
pub fn path_coverage(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Real {
    match task.points.len() {
        0 => 1.0,
        n => count(&seen_along(si, task, path)) as Real / n as Real,
    }
}

/// The coverage `path` reaches by the Technion course's definition, whatever the task's own
/// settings: the points seen at its vertices only, a sight line that touches an obstacle hiding
/// the point.
pub fn course_coverage(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Real {
    path_coverage(si, &task.counted(true, true), path)
}

/// The coverage `path` reaches by Planarium's continuous definition, whatever the task's own
/// settings: the points seen along every motion at the motion resolution, only a sight line
/// through an obstacle's interior hiding the point.
pub fn continuous_coverage(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Real {
    path_coverage(si, &task.counted(false, false), path)
}

/// Random shortcut smoothing that keeps what the path sees: each attempt of
/// [`smoothing::shortcut`](crate::planners::smoothing::shortcut) is kept only if the shortened path still
/// sees every point the original saw (plain shortcutting cuts the detours an inspection path takes
/// to look at things). Counted at the vertices (`at_vertices`), an attempt is one shortcut alone
/// ([`smoothing::shortcut_only`](crate::planners::smoothing::shortcut_only)): the vertex reduction
/// that ends each plain attempt drops the vertices that saw the points, so every attempt would be
/// refused; it is tried once at the end instead.
pub fn shortcut(
    si: &SpaceInfo,
    task: &InspectionTask,
    path: &[Vec<Real>],
    attempts: usize,
    rng: &mut crate::rng::Rng,
) -> Vec<Vec<Real>> {
    let must = seen_along(si, task, path);
    let mut path = path.to_vec();
    for _ in 0..attempts {
        if path.len() < 3 || si.out_of_time() {
            break;
        }
        let next = if task.at_vertices {
            crate::planners::smoothing::shortcut_only(si, &path, 1, rng)
        } else {
            crate::planners::smoothing::shortcut(si, &path, 1, rng)
        };
        if next != path && covers(&seen_along(si, task, &next), &must) {
            path = next;
        }
    }
    if task.at_vertices && !si.out_of_time() {
        let next = crate::planners::smoothing::reduce_vertices(si, &path, &mut vec![0.0; si.dims()]);
        if next != path && covers(&seen_along(si, task, &next), &must) {
            path = next;
        }
    }
    path
}
