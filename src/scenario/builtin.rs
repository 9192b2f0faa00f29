//! The built-in scenarios, one JSON file each under `scenarios/`, embedded in the binary so the
//! page, the CLI and the tests all see the same documents.

use super::{Scenario, ScenarioError};

/// `(id, JSON text)` of every built-in scenario, in the order the page lists them.
pub const BUILTINS: &[(&str, &str)] = &[
    ("open-field", include_str!("../../scenarios/open-field.json")),
    ("narrow", include_str!("../../scenarios/narrow.json")),
    ("zigzag", include_str!("../../scenarios/zigzag.json")),
    ("slot", include_str!("../../scenarios/slot.json")),
    ("arm-2", include_str!("../../scenarios/arm-2.json")),
    ("arm-3", include_str!("../../scenarios/arm-3.json")),
    ("horn-10", include_str!("../../scenarios/horn-10.json")),
    ("horn-20", include_str!("../../scenarios/horn-20.json")),
    ("ompl-rect", include_str!("../../scenarios/ompl-rect.json")),
    ("technion-mp", include_str!("../../scenarios/technion-mp.json")),
    ("technion-ip", include_str!("../../scenarios/technion-ip.json")),
    ("asv-3-easy", include_str!("../../scenarios/asv-3-easy.json")),
    ("asv-3", include_str!("../../scenarios/asv-3.json")),
    ("asv-7-easy", include_str!("../../scenarios/asv-7-easy.json")),
    ("asv-7", include_str!("../../scenarios/asv-7.json")),
    ("asv-15", include_str!("../../scenarios/asv-15.json")),
    ("asv-7-long-gap", include_str!("../../scenarios/asv-7-long-gap.json")),
    ("hex-open", include_str!("../../scenarios/hex-open.json")),
    ("hex-corridor", include_str!("../../scenarios/hex-corridor.json")),
    ("hex-trap", include_str!("../../scenarios/hex-trap.json")),
    ("hex-trap-modified", include_str!("../../scenarios/hex-trap-modified.json")),
    ("apf-minimum", include_str!("../../scenarios/apf-minimum.json")),
    ("puma-rbo-wall", include_str!("../../scenarios/puma-rbo-wall.json")),
    ("puma-boxes", include_str!("../../scenarios/puma-boxes.json")),
];

/// The course (or source) a built-in scenario comes from, for grouping them in the page.
pub fn course_of(id: &str) -> &'static str {
    match id {
        "slot" | "arm-3" => "Polygon robot and chain (report 003)",
        "arm-2" => "Configuration space",
        _ if id.starts_with("horn-") || id.starts_with("ompl-") => "OMPL benchmarks",
        _ if id.starts_with("technion-") => "Technion manipulator and inspection (report 004)",
        _ if id.starts_with("asv-") => "Vehicles joined by brooms (report 000)",
        _ if id.starts_with("apf-") || id.starts_with("hex-") => "Hexagons and potential fields (report 002)",
        _ if id.starts_with("puma-") => "Puma 560 in 3-D, RRT-Connect's extensions (report 001)",
        _ => "First steps",
    }
}

/// The ids of the built-in scenarios.
pub fn builtin_names() -> Vec<&'static str> {
    BUILTINS.iter().map(|(n, _)| *n).collect()
}

/// A built-in scenario by id.
pub fn builtin(id: &str) -> Result<Scenario, ScenarioError> {
    let (_, text) = BUILTINS.iter().find(|(n, _)| *n == id).ok_or_else(|| {
        ScenarioError::at("", format!("no built-in scenario \"{id}\" (known: {})", builtin_names().join(", ")))
    })?;
    Scenario::from_json(text)
}
