//! The report as JSON: [`to_json`] writes it with each set-up's summary, [`from_json`] reads it
//! back (or the page's own) and checks it.

use super::{BenchReport, SetupReport, SetupSummary};
use serde::Serialize;

/// Read a report (as [`to_json`] writes it, or as the page builds it; `summary` and other extra
/// keys are ignored) and [check](BenchReport::check) it.
pub fn from_json(text: &str) -> Result<BenchReport, String> {
    let mut r: BenchReport = // serde's messages echo the values they refuse: cut, controls shown.
        serde_json::from_str(text).map_err(|e| format!("bench report: {}", crate::limits::cut(&e.to_string(), 300)))?;
    if r.runs == 0 {
        r.runs = r.setups.iter().map(|s| s.rows.len()).max().unwrap_or(0);
    }
    r.check().map_err(|e| format!("bench report: {e}"))?;
    Ok(r)
}

/// The report as pretty JSON: the report's own fields, and for each set-up its `summary`
/// ([`SetupSummary`]).
pub fn to_json(r: &BenchReport) -> String {
    // The report's fields in its own order (a round trip through `from_json` is checked in the
    // tests), each set-up followed by its summary.
    #[derive(Serialize)]
    struct SetupOut<'a> {
        #[serde(flatten)]
        setup: &'a SetupReport,
        summary: SetupSummary,
    }
    #[derive(Serialize)]
    struct ReportOut<'a> {
        scenario: &'a str,
        scenario_id: &'a str,
        date: &'a str,
        host: &'a str,
        time_limit_s: f64,
        runs: usize,
        #[serde(skip_serializing_if = "Option::is_none")]
        seeds: Option<super::SeedRange>,
        setups: Vec<SetupOut<'a>>,
    }
    let out = ReportOut {
        scenario: &r.scenario,
        scenario_id: &r.scenario_id,
        date: &r.date,
        host: &r.host,
        time_limit_s: r.time_limit_s,
        runs: r.runs,
        seeds: r.seeds,
        setups: r.setups.iter().map(|s| SetupOut { setup: s, summary: s.summary() }).collect(),
    };
    serde_json::to_string_pretty(&out).expect("a report serialises") + "\n"
}
