//! The numbers of a benchmark, below both [`bench`](super::bench) (which computes them) and
//! [`report`](super::report) (which writes them): one [`RunRow`] per run, a [`SetupSummary`] per
//! planner set-up, and the [`Summary`] (median, mean, standard deviation) of one metric.

use super::Stats;
use crate::status::Status;
use serde::{Deserialize, Serialize};

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
    /// Whether it summarises no values (such a summary is left out of the JSON).
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

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

/// One run of a benchmark: the seed and how it went (the contract's `stats`, flattened).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunRow {
    /// The seed.
    pub seed: u64,
    /// Whether a path was found (`status` is `"solved"`).
    pub solved: bool,
    /// How the run ended: a status name (`solved`, `time_limit`, `iteration_limit`, `node_limit`,
    /// `memory_limit`, `cancelled`, `no_path`, `running`).
    pub status: String,
    /// Planning time, milliseconds (smoothing excluded).
    pub time_ms: f64,
    /// Planner iterations.
    pub iterations: u64,
    /// Nodes in all trees.
    pub nodes: u64,
    /// State validity checks.
    pub checks: u64,
    /// Of those, the ones that found the state valid (optional, 0 when absent: reports written
    /// before it was counted).
    #[serde(default)]
    pub free_checks: u64,
    /// Raw path cost (`null` when unsolved).
    #[serde(default)]
    pub cost: Option<f64>,
    /// Smoothed path cost (`null` when unsolved).
    #[serde(default)]
    pub smoothed_cost: Option<f64>,
    /// Smoothing time, milliseconds (optional, 0 when absent).
    #[serde(default)]
    pub smoothing_ms: f64,
    /// Arm robots: the raw path's cost in report 004's unit (`stats.cost_fk`); absent otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cost_fk: Option<f64>,
    /// Arm robots: the smoothed path's cost in report 004's unit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoothed_cost_fk: Option<f64>,
}

impl RunRow {
    /// The row of one run's statistics.
    pub fn of(seed: u64, status: Status, st: &Stats) -> RunRow {
        RunRow {
            seed,
            solved: status == Status::Solved,
            status: status.name().to_string(),
            time_ms: st.time_ms,
            iterations: st.iterations,
            nodes: st.nodes,
            checks: st.checks,
            free_checks: st.free_checks,
            cost: st.cost,
            smoothed_cost: st.smoothed_cost,
            smoothing_ms: st.smoothing_ms,
            cost_fk: st.cost_fk,
            smoothed_cost_fk: st.smoothed_cost_fk,
        }
    }
}

/// A set-up's summary: the courses' numbers.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SetupSummary {
    /// Runs.
    pub runs: usize,
    /// Runs solved.
    pub solved: usize,
    /// Fraction solved.
    pub success_rate: f64,
    /// Planning time, ms (all runs).
    pub time_ms: Summary,
    /// Nodes (all runs).
    pub nodes: Summary,
    /// State checks (all runs).
    pub checks: Summary,
    /// Free state checks (all runs).
    pub free_checks: Summary,
    /// Raw path cost (solved runs).
    pub cost: Summary,
    /// Smoothed path cost (solved runs).
    pub smoothed_cost: Summary,
    /// Raw path cost in report 004's unit (solved arm runs; absent when none).
    #[serde(skip_serializing_if = "Summary::is_empty")]
    pub cost_fk: Summary,
    /// Smoothed path cost in report 004's unit (solved arm runs; absent when none).
    #[serde(skip_serializing_if = "Summary::is_empty")]
    pub smoothed_cost_fk: Summary,
}

impl SetupSummary {
    /// The summary of some runs: success rate; median, mean and standard deviation of time, nodes
    /// and checks over all runs, of cost and smoothed cost over the solved runs.
    pub fn of(rows: &[RunRow]) -> SetupSummary {
        let all = |f: fn(&RunRow) -> f64| Summary::of(&rows.iter().map(f).collect::<Vec<_>>());
        let solved_only = |f: fn(&RunRow) -> Option<f64>| Summary::of(&rows.iter().filter_map(f).collect::<Vec<_>>());
        let runs = rows.len();
        let solved = rows.iter().filter(|r| r.solved).count();
        SetupSummary {
            runs,
            solved,
            success_rate: solved as f64 / runs.max(1) as f64,
            time_ms: all(|r| r.time_ms),
            nodes: all(|r| r.nodes as f64),
            checks: all(|r| r.checks as f64),
            free_checks: all(|r| r.free_checks as f64),
            cost: solved_only(|r| r.cost),
            smoothed_cost: solved_only(|r| r.smoothed_cost),
            cost_fk: solved_only(|r| r.cost_fk),
            smoothed_cost_fk: solved_only(|r| r.smoothed_cost_fk),
        }
    }
}
