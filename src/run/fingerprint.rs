//! A run's fingerprint: FNV-1a (64-bit) over the bits of every event record and every path number.
//! The same scenario, planner, parameters and seed must give the same fingerprint natively, in Node
//! and in the browser; `tests/golden/runs.json` pins them and every build is checked against it.

use super::{RunConfig, Session};
use crate::planners::{self, Params};
use crate::problem::Problem;
use crate::scenario::Scenario;

/// FNV-1a over the little-endian bytes of `xs`, continuing from `h`.
pub fn fnv1a(mut h: u64, xs: &[f64]) -> u64 {
    for x in xs {
        for b in x.to_bits().to_le_bytes() {
            h ^= b as u64;
            h = h.wrapping_mul(0x100_0000_01b3);
        }
    }
    h
}

/// FNV-1a's offset basis.
pub const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// What a run produced, in a few comparable numbers.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Fingerprint {
    /// Hash of the whole event log, as 16 hex digits.
    pub events: String,
    /// Hash of the raw path then the smoothed path, as 16 hex digits.
    pub path: String,
    /// Iterations.
    pub iterations: u64,
    /// Nodes.
    pub nodes: u64,
    /// State checks.
    pub checks: u64,
}

/// Run `planner` with `params` (a JSON object) and `seed` on `scenario` to the end, and fingerprint it.
pub fn fingerprint(
    scenario: &Scenario,
    planner: &str,
    params: &serde_json::Value,
    seed: u64,
) -> Result<Fingerprint, String> {
    fingerprint_in_batches(scenario, planner, params, seed, f64::INFINITY).map(|(f, _)| f)
}

/// Like [`fingerprint`], but run in bounded batches of `max_ms` (as the page's worker does), which
/// may be suspended and replayed ([`crate::journal`]); also returns how many were suspended.
pub fn fingerprint_in_batches(
    scenario: &Scenario,
    planner: &str,
    params: &serde_json::Value,
    seed: u64,
    max_ms: f64,
) -> Result<(Fingerprint, u64), String> {
    let spec = planners::find(planner).ok_or("unknown planner")?;
    let params = Params::from_json(spec, params).map_err(|(k, e)| format!("{k}: {e}"))?;
    let problem = Problem::from_scenario(scenario).map_err(|e| e.to_string())?;
    let mut s = Session::new(problem, RunConfig { planner: planner.into(), params, seed, record_events: true })?;
    let mut log = Vec::new();
    while !s.step(u64::MAX, max_ms).is_finished() {
        log.extend(s.drain_events());
    }
    log.extend(s.drain_events());
    let events = fnv1a(FNV_OFFSET, &log);
    let r = s.result();
    let mut h = FNV_OFFSET;
    for q in r.path.iter().chain(&r.smoothed) {
        h = fnv1a(h, q);
    }
    let f = Fingerprint {
        events: format!("{events:016x}"),
        path: format!("{h:016x}"),
        iterations: r.stats.iterations,
        nodes: r.stats.nodes,
        checks: r.stats.checks,
    };
    Ok((f, s.suspensions()))
}
