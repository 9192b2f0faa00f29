//! PRM*: the roadmap whose neighbour set shrinks as it grows, asymptotically optimal.
//!
//! S. Karaman, E. Frazzoli, "Sampling-based algorithms for optimal motion planning", IJRR 30(7),
//! 2011; the k rule as OMPL's `PRMstar` (`KStarStrategy`). A new milestone connects to its
//! `k = ⌈f·e·(1 + 1/d)·ln n⌉` nearest vertices, or to those within
//! `r = f·γ·(ln n / n)^(1/d)`, `γ = 2·(1 + 1/d)^(1/d)·(μ/ζ_d)^(1/d)` (`f`: `factor`, `n`: vertices
//! before the new one, `d`: dimensions, `μ`: the product of the coordinate ranges, `ζ_d`: the
//! volume of the unit `d`-ball), by checked motions; otherwise as PRM. Seeded by the run's
//! [`Rng`] only. See [`super::common`].
//!
//! [`Rng`]: crate::rng::Rng

use super::{Neighbours, RoadmapPlanner};
use crate::events::EventKind;
use crate::math::Real;
use crate::planners::caps::Capabilities;
use crate::planners::{ParamSpec, Params, PlannerSpec, TaskKind};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "prm-star",
    label: "PRM*",
    summary: "A roadmap whose neighbour count grows as ln n, so its paths approach the shortest.",
    iteration: "Add one milestone, check the motions to its k* = k·ln n nearest, then search the roadmap again.",
    checks: "State validity checks: the milestones and the states along every candidate edge (each motion is checked state by state at the scenario's resolution).",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        improves: true,
        events: super::prm::SPEC.caps.events.with(&[EventKind::Cost]),
        pseudocode: "roadmap-prm-star",
        ..super::prm::SPEC.caps
    },

    make: |si, task, params| {
        Ok(Box::new(
            RoadmapPlanner::new(si.dims(), task, rule(si, params), false).improving(params.real("improve_for") as u64),
        ))
    },
};

/// PRM*'s parameters.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice(
        "connect",
        "Neighbours",
        &["k-nearest", "radius"],
        0,
        "k-nearest: the ⌈f·e·(1 + 1/d)·ln n⌉ nearest vertices; radius: those within f·γ·(ln n / n)^(1/d).",
    ),
    ParamSpec::int(
        "improve_for",
        "Improve for",
        0.0,
        1e9,
        500.0,
        "Iterations (milestones) spent shortening the path after the first solution, the roadmap searched again after each (0: return the first solution).",
    ),
    ParamSpec::real(
        "factor",
        "Factor",
        0.1,
        100.0,
        1.0,
        "f: scales k or the radius above the bound that makes PRM* asymptotically optimal.",
    ),
];

/// `f·e·(1 + 1/d)`: PRM*'s `k = ⌈k_prm · ln n⌉` (OMPL's `kPRMConstant_`, times the factor).
pub fn k_prm(factor: Real, d: usize) -> Real {
    factor * std::f64::consts::E * (1.0 + 1.0 / d as Real)
}

/// Volume of the unit ball in `d` dimensions.
fn unit_ball_volume(d: usize) -> Real {
    match d {
        0 => 1.0,
        1 => 2.0,
        _ => unit_ball_volume(d - 2) * 2.0 * std::f64::consts::PI / d as Real,
    }
}

/// The neighbour rule `params` choose.
pub fn rule(si: &SpaceInfo, params: &Params) -> Neighbours {
    let (n, f) = (si.dims(), params.real("factor"));
    if params.choice("connect") == "radius" {
        let d = n as Real;
        let measure: Real = si.space.dims.iter().map(|dim| dim.hi - dim.lo).product();
        let gamma = 2.0 * libm::pow(1.0 + 1.0 / d, 1.0 / d) * libm::pow(measure / unit_ball_volume(n), 1.0 / d);
        Neighbours::RStar(f * gamma)
    } else {
        Neighbours::KStar(k_prm(f, n))
    }
}
