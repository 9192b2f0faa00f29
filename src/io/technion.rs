//! The Technion HW3 maps (courses.md §5). Work in progress: see issue 3.

use crate::scenario::{Scenario, ScenarioError};

/// Read a Technion map (`map_mp.json` or `map_ip.json`) as a scenario.
pub fn import_map(_text: &str, _name: &str) -> Result<Scenario, ScenarioError> {
    Err(ScenarioError::at("", "Technion maps are not supported by this build yet"))
}
