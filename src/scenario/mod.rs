//! The scenario contract (`planarium-scenario/1`, see `docs/scenario-format.md`): parse, validate,
//! and turn into a [`Problem`](crate::problem::Problem).
//!
//! The generic entry is [`Scenario::from_json`]. Every error is a [`ScenarioError`] that names the
//! JSON path of what is wrong (`obstacles[3].polygon: needs at least 3 points`), or the line and
//! column of a syntax error. Unknown keys are errors.

mod builtin;
mod error;
mod parse;
mod parse3d;
pub(crate) use parse::key_name;
mod types;

pub use builtin::{builtin, builtin_names, course_of, BUILTINS};
pub use error::ScenarioError;
pub(crate) use parse::join;
pub use types::{
    BoxSpec, DhJoint, Inspection, LinkSpec, MapGrid, ObstacleSpec, PlannerDefaults, PoseSpec, RobotSpec, Scenario,
    SolidShape, SolidSpec, SpatialArmSpec, FORMAT,
};

#[cfg(test)]
mod tests;
