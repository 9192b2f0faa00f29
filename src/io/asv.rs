//! The ASV course's problem and solution files (courses.md §1). Work in progress: see issue 3.

use crate::scenario::{Scenario, ScenarioError};

/// Read an ASV problem file as a scenario.
pub fn import_problem(_text: &str, _name: &str) -> Result<Scenario, ScenarioError> {
    Err(ScenarioError::at("", "ASV problem files are not supported by this build yet"))
}
