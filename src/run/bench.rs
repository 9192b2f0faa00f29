//! Benchmarks over seeds: run planners on one problem for seeds 1..=N and summarise
//! (success rate; median, mean and standard deviation of time, nodes, checks and cost), as a table
//! or JSON. [`export`](super::export) turns the results into a [`BenchReport`](super::export::BenchReport)
//! and writes it as CSV, JSON, an OMPL benchmark log or the courses' table.

use super::{RunConfig, Session, Stats};
use crate::planners::Params;
use crate::problem::Problem;
use crate::scenario::{Scenario, ScenarioError};
use crate::status::Status;
use serde::Serialize;

/// Median, mean and standard deviation of a metric over the runs that have it.
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct Summary {
    /// Median.
    pub median: f64,
    /// Mean.
    pub mean: f64,
    /// Standard deviation (sample, n − 1).
    pub std: f64,
    /// Number of values.
    pub n: usize,
}

impl Summary {
    /// The summary of `xs` (all zeros when empty).
    pub fn of(xs: &[f64]) -> Summary {
        let n = xs.len();
        if n == 0 {
            return Summary::default();
        }
        let mut v = xs.to_vec();
        v.sort_by(f64::total_cmp);
        let median = if n % 2 == 1 { v[n / 2] } else { (v[n / 2 - 1] + v[n / 2]) / 2.0 };
        let mean = v.iter().sum::<f64>() / n as f64;
        let std = if n > 1 { (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt() } else { 0.0 };
        Summary { median, mean, std, n }
    }
}

/// One planner set-up's results over the seeds.
#[derive(Clone, Debug, Serialize)]
pub struct PlannerBench {
    /// The set-up's label (the planner name unless given).
    pub label: String,
    /// Planner name.
    pub planner: String,
    /// Parameters set explicitly.
    pub params: serde_json::Map<String, serde_json::Value>,
    /// Runs.
    pub runs: usize,
    /// Fraction solved.
    pub success_rate: f64,
    /// Planning time, ms (all runs).
    pub time_ms: Summary,
    /// Nodes (all runs).
    pub nodes: Summary,
    /// State checks (all runs).
    pub checks: Summary,
    /// Raw path cost (solved runs).
    pub cost: Summary,
    /// Smoothed path cost (solved runs).
    pub smoothed_cost: Summary,
    /// Per-run statistics, seed order.
    pub per_run: Vec<(u64, bool, Stats)>,
    /// How each run ended, in the order of `per_run`.
    pub statuses: Vec<Status>,
    /// The set-up's planning time limit, seconds (its `time_limit` parameter or the default).
    pub time_limit_s: f64,
}

/// Run `planner` with `params` on `scenario` for seeds `1..=runs`.
pub fn bench_planner(scenario: &Scenario, planner: &str, params: &Params, runs: u64) -> Result<PlannerBench, String> {
    let mut per_run = Vec::new();
    let mut statuses = Vec::new();
    for seed in 1..=runs {
        let problem = Problem::from_scenario(scenario).map_err(|e: ScenarioError| e.to_string())?;
        let config = RunConfig { planner: planner.to_string(), params: params.clone(), seed, record_events: false };
        let mut s = Session::new(problem, config)?;
        let status = s.run_to_end();
        per_run.push((seed, status == Status::Solved, s.stats()));
        statuses.push(status);
    }
    let all = |f: fn(&Stats) -> f64| Summary::of(&per_run.iter().map(|r| f(&r.2)).collect::<Vec<_>>());
    let solved = |f: fn(&Stats) -> Option<f64>| Summary::of(&per_run.iter().filter_map(|r| f(&r.2)).collect::<Vec<_>>());
    Ok(PlannerBench {
        label: planner.to_string(),
        planner: planner.to_string(),
        params: params.values().clone(),
        runs: runs as usize,
        success_rate: per_run.iter().filter(|r| r.1).count() as f64 / runs.max(1) as f64,
        time_ms: all(|s| s.time_ms),
        nodes: all(|s| s.nodes as f64),
        checks: all(|s| s.checks as f64),
        cost: solved(|s| s.cost),
        smoothed_cost: solved(|s| s.smoothed_cost),
        per_run,
        statuses,
        time_limit_s: params.real("time_limit"),
    })
}

/// A plain-text table of benchmark results: per planner its success rate, then median, mean and
/// standard deviation of each metric.
pub fn table(rows: &[PlannerBench]) -> String {
    let mut out = format!("{:<16} {:>8}  {:<14} {:>12} {:>12} {:>12}\n", "planner", "success", "metric", "median", "mean", "std");
    for r in rows {
        let metrics: [(&str, &Summary); 5] =
            [("time_ms", &r.time_ms), ("nodes", &r.nodes), ("checks", &r.checks), ("cost", &r.cost), ("smoothed_cost", &r.smoothed_cost)];
        for (k, (name, m)) in metrics.iter().enumerate() {
            let (p, sr) = if k == 0 { (r.label.as_str(), format!("{:.0}%", r.success_rate * 100.0)) } else { ("", String::new()) };
            out.push_str(&format!("{:<16} {:>8}  {:<14} {:>12.4} {:>12.4} {:>12.4}\n", p, sr, name, m.median, m.mean, m.std));
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
            r.success_rate * 100.0,
            r.time_ms.mean,
            r.time_ms.std,
            r.nodes.mean,
            r.checks.mean,
            r.checks.median
        ));
    }
    out
}
