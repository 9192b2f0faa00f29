//! Benchmarks over seeds: run planners on one problem for seeds 1..=N (or one shard of them,
//! seeds A..=B, which [`merge`](super::report::merge) joins back into one report) and summarise
//! (success rate; median, mean and standard deviation of time, nodes, checks and cost, as
//! [`summary`](super::summary) computes them), as a table or JSON. [`report`](super::report) turns
//! the results into a [`BenchReport`](super::report::BenchReport) and writes it as CSV, JSON, an
//! OMPL benchmark log or the courses' table.

pub use super::summary::Summary;
use super::summary::{RunRow, SetupSummary};
use super::{RunConfig, Session, Stats};
use crate::planners::{self, Params, PlannerSpec};
use crate::problem::Problem;
use crate::scenario::{Scenario, ScenarioError};
use crate::status::Status;
use serde::Serialize;

/// One planner set-up's results over the seeds.
#[derive(Clone, Debug, Serialize)]
pub struct PlannerBench {
    /// The set-up's label (the planner name unless given).
    pub label: String,
    /// Planner name.
    pub planner: String,
    /// Parameters set explicitly.
    pub params: serde_json::Map<String, serde_json::Value>,
    /// The courses' numbers: runs, success rate, and the summaries of time, nodes, checks, cost
    /// and smoothed cost (in JSON, flattened into the set-up's object).
    #[serde(flatten)]
    pub summary: SetupSummary,
    /// Per-run statistics, seed order.
    pub per_run: Vec<(u64, bool, Stats)>,
    /// How each run ended, in the order of `per_run`.
    pub statuses: Vec<Status>,
    /// The set-up's planning time limit, seconds (its `time_limit` parameter or the default).
    pub time_limit_s: f64,
}

/// A planner set-up as the CLI's `--setup` and the benchmark page's lines write it:
/// `[label:] planner [--param value ...]` (flags in the CLI's spelling, `--goal-bias 0.2`).
#[derive(Clone)]
pub struct Setup {
    /// The label (without one: the set-up's text after the label, e.g. `rrt --goal-bias 0.2`).
    pub label: String,
    /// The planner.
    pub spec: &'static PlannerSpec,
    /// Its parameters: `base(spec)` with the set-up's values on top.
    pub params: Params,
}

impl std::fmt::Debug for Setup {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Setup")
            .field("label", &self.label)
            .field("planner", &self.spec.name)
            .field("params", &self.params.values())
            .finish()
    }
}

/// Parse one set-up; `base` gives the parameters the set-up's values go on top of (the CLI: the
/// scenario's planner block and the command's flags; the page: the defaults). Errors say what is
/// wrong, without saying where (the caller adds the `--setup` or the line).
pub fn parse_setup(text: &str, base: impl Fn(&'static PlannerSpec) -> Result<Params, String>) -> Result<Setup, String> {
    let (label, rest) = match text.split_once(':') {
        Some((l, r)) if !l.contains("--") => (Some(l.trim()), r),
        _ => (None, text),
    };
    let mut words = rest.split_whitespace();
    let name = words.next().ok_or("no planner name")?;
    let spec = planners::find(name)
        .ok_or_else(|| format!("unknown planner \"{name}\" (known: {})", planners::names().join(", ")))?;
    let mut params = base(spec)?;
    while let Some(flag) = words.next() {
        let key =
            flag.strip_prefix("--").ok_or_else(|| format!("expected --param, found \"{flag}\""))?.replace('-', "_");
        let value = words.next().ok_or_else(|| format!("{flag} needs a value"))?;
        if spec.param(&key).is_none() {
            return Err(format!("{flag} is not a parameter of {}", spec.name));
        }
        params.set_text(spec, &key, value)?;
    }
    let label = match label {
        Some(l) if !l.is_empty() => l.to_string(),
        _ => rest.trim().to_string(),
    };
    Ok(Setup { label, spec, params })
}

/// Parse the page's set-up lines (one per line; blank lines and `#` comments skipped) on top of
/// each planner's defaults; an error names its line (`set-up line 2: ...`).
pub fn parse_setup_lines(text: &str) -> Result<Vec<Setup>, String> {
    if let Some(why) = crate::limits::text_too_large(text) {
        return Err(why);
    }
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if out.len() == MAX_SETUPS {
            return Err(format!("set-up line {}: more than {MAX_SETUPS} set-ups (compare fewer at a time)", i + 1));
        }
        let setup = parse_setup(line, |spec| Ok(Params::defaults(spec)));
        out.push(setup.map_err(|e| format!("set-up line {}: {}", i + 1, crate::limits::cut(&e, 300)))?);
    }
    if out.is_empty() {
        return Err("no set-up: write one per line, e.g. \"rrt-connect\" or \"biased: rrt --goal-bias 0.2\"".into());
    }
    Ok(out)
}

/// Set-ups compared in one benchmark (the page's plots label each one).
pub const MAX_SETUPS: usize = 16;

/// Seeds one benchmark runs per set-up (the benchmark page's limit on its runs, too).
pub const MAX_RUNS: u64 = 10_000;

/// A shard's seeds, `A-B` (`A..=B`; a single seed may be written `A`): whole numbers, `A ≤ B`, at
/// most [`MAX_RUNS`] of them. Errors say what is wrong without naming the flag (the caller does).
pub fn parse_seed_range(text: &str) -> Result<(u64, u64), String> {
    let shown = crate::limits::cut(text.trim(), 60);
    if text.trim().starts_with('-') {
        return Err(format!(
            "\"{shown}\": the first seed must be at least 0 (seeds are whole numbers from 0 to {})",
            u64::MAX
        ));
    }
    let (a, b) = text.trim().split_once('-').unwrap_or((text.trim(), text.trim()));
    let whole = |s: &str, which: &str| {
        let s = s.trim();
        if s.is_empty() {
            return Err(format!("\"{shown}\": the {which} seed is missing (write A-B, e.g. 1-10)"));
        }
        s.parse::<u64>().map_err(|_| {
            format!(
                "\"{shown}\": the {which} seed \"{}\" is not a whole number from 0 to {} (write A-B, e.g. 1-10)",
                crate::limits::cut(s, 40),
                u64::MAX
            )
        })
    };
    let (first, last) = (whole(a, "first")?, whole(b, "last")?);
    if first > last {
        return Err(format!("\"{shown}\": the first seed ({first}) is after the last ({last})"));
    }
    if last - first >= MAX_RUNS {
        return Err(format!(
            "\"{shown}\": {} seeds; the limit is {MAX_RUNS} per benchmark (split it into shards and merge them)",
            u128::from(last - first) + 1
        ));
    }
    Ok((first, last))
}

/// Run `planner` with `params` on `scenario` for seeds `1..=runs`.
pub fn bench_planner(scenario: &Scenario, planner: &str, params: &Params, runs: u64) -> Result<PlannerBench, String> {
    bench_seeds(scenario, planner, params, 1, runs)
}

/// Run `planner` with `params` on `scenario` for seeds `first..=last` (one shard of a study).
pub fn bench_seeds(
    scenario: &Scenario,
    planner: &str,
    params: &Params,
    first: u64,
    last: u64,
) -> Result<PlannerBench, String> {
    let mut per_run = Vec::new();
    let mut statuses = Vec::new();
    for seed in first..=last {
        let problem = Problem::from_scenario(scenario).map_err(|e: ScenarioError| e.to_string())?;
        let config = RunConfig { planner: planner.to_string(), params: params.clone(), seed, record_events: false };
        let mut s = Session::new(problem, config)?;
        let status = s.run_to_end();
        per_run.push((seed, status == Status::Solved, s.stats()));
        statuses.push(status);
    }
    let rows: Vec<RunRow> =
        per_run.iter().zip(&statuses).map(|((seed, _, st), status)| RunRow::of(*seed, *status, st)).collect();
    Ok(PlannerBench {
        label: planner.to_string(),
        planner: planner.to_string(),
        params: params.values().clone(),
        summary: SetupSummary::of(&rows),
        per_run,
        statuses,
        time_limit_s: params.real("time_limit"),
    })
}

/// A plain-text table of benchmark results: per planner its success rate, then median, mean and
/// standard deviation of each metric.
pub fn table(rows: &[PlannerBench]) -> String {
    let mut out =
        format!("{:<16} {:>8}  {:<14} {:>12} {:>12} {:>12}\n", "planner", "success", "metric", "median", "mean", "std");
    for r in rows {
        let m = &r.summary;
        let metrics: [(&str, &Summary); 6] = [
            ("time_ms", &m.time_ms),
            ("nodes", &m.nodes),
            ("checks", &m.checks),
            ("free_checks", &m.free_checks),
            ("cost", &m.cost),
            ("smoothed_cost", &m.smoothed_cost),
        ];
        for (k, (name, m)) in metrics.iter().enumerate() {
            let (p, sr) = if k == 0 {
                (r.label.as_str(), format!("{:.0}%", r.summary.success_rate * 100.0))
            } else {
                ("", String::new())
            };
            out.push_str(&format!(
                "{:<16} {:>8}  {:<14} {:>12.4} {:>12.4} {:>12.4}\n",
                p, sr, name, m.median, m.mean, m.std
            ));
        }
    }
    out
}

/// A Markdown table in the form of report 001's (one row per set-up): success, mean and standard
/// deviation of time, mean nodes, mean and median state checks ("queries").
pub fn report_table(rows: &[PlannerBench]) -> String {
    let mut out = String::from("| set-up | solved | avgT (ms) | stdT (ms) | avgNodes | avgQueries | median queries |\n|---|---|---|---|---|---|---|\n");
    for r in rows {
        out.push_str(&format!(
            "| {} | {:.0}% | {:.2} | {:.2} | {:.1} | {:.0} | {:.0} |\n",
            r.label,
            r.summary.success_rate * 100.0,
            r.summary.time_ms.mean,
            r.summary.time_ms.std,
            r.summary.nodes.mean,
            r.summary.checks.mean,
            r.summary.checks.median
        ));
    }
    out
}
