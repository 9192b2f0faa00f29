//! Course file formats, read into scenarios and written from results.
//!
//! The generic entry is [`import`]: it recognises a document by its content (a Planarium scenario,
//! a Technion HW3 map, an ASV problem file) and returns a [`Scenario`]. Each format has its own file.

pub mod asv;
pub mod occupancy;
pub mod technion;

use crate::scenario::{Scenario, ScenarioError};

/// The formats [`import`] recognises.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// `planarium-scenario/1` JSON.
    Scenario,
    /// The Technion HW3 map JSON (`WIDTH`, `HEIGHT`, `OBSTACLES`, ...).
    TechnionMap,
    /// The ASV course's problem text file.
    AsvProblem,
}

/// Which format `text` is in, by its content: JSON whose top level has the Technion keys
/// (`OBSTACLES`, `WIDTH`) is a map, other JSON a scenario (which reports its own syntax errors),
/// anything else an ASV problem file.
pub fn detect(text: &str) -> Format {
    if !text.trim_start().starts_with('{') {
        return Format::AsvProblem;
    }
    match serde_json::from_str::<serde_json::Value>(text) {
        Ok(serde_json::Value::Object(m)) if m.contains_key("OBSTACLES") || m.contains_key("WIDTH") => {
            Format::TechnionMap
        }
        _ => Format::Scenario,
    }
}

/// Read any supported document as a scenario; `name` (a file name) titles scenarios whose format
/// has no name of its own.
pub fn import(text: &str, name: &str) -> Result<Scenario, ScenarioError> {
    if let Some(why) = crate::limits::text_too_large(text) {
        return Err(ScenarioError::document(why));
    }
    match detect(text) {
        Format::Scenario => Scenario::from_json(text),
        Format::TechnionMap => technion::import_map(text, name),
        Format::AsvProblem => asv::import_problem(text, name),
    }
}
