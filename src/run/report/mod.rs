//! Benchmark results as one [`BenchReport`] (scenario, date, host, time limit, and per set-up its
//! planner, parameters and one [`RunRow`] per seed) and its four renderings, one file each: CSV
//! ([`to_csv`], in [`csv`](mod@csv)), JSON with summaries ([`to_json`], read back by [`from_json`],
//! in [`json`]), an OMPL benchmark log that `ompl_benchmark_statistics.py` turns into a Planner
//! Arena database ([`to_ompl_log`], in [`ompl`], whose documentation is the log's grammar), the
//! courses' Markdown table ([`course_table`], in [`markdown`]) and report 001's course benchmark
//! lines ([`to_course_csv`], in [`course`]); [`render`] picks one by name. The
//! CLI's `bench` and the page (through wasm's `bench_export`) both write through these functions.
//! No clock is read here: the caller passes the date and host ([`utc_timestamp`] formats it).
//!
//! The dependency is one-way: the report is made from [`bench`](super::bench)'s results; the rows
//! and summaries both use are in [`summary`](super::summary).

pub mod course;
pub mod csv;
pub mod json;
pub mod markdown;
pub mod merge;
pub mod ompl;

pub use self::course::{to_course_csv, COURSE_HEADER};
pub use self::csv::{to_csv, CSV_HEADER};
pub use self::json::{from_json, to_json};
pub use self::markdown::course_table;
pub use self::ompl::{ompl_planner_names, to_ompl_log, OMPL_RUN_PROPERTIES};
pub use super::summary::{RunRow, SetupSummary};

use super::bench::PlannerBench;
use crate::status::Status;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

/// One planner set-up's runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SetupReport {
    /// The set-up's label (the planner name unless given).
    pub label: String,
    /// Planner name (as in the registry).
    pub planner: String,
    /// The parameters set explicitly.
    #[serde(default)]
    pub params: Map<String, Value>,
    /// One row per run, in seed order.
    pub rows: Vec<RunRow>,
}

/// A benchmark: every set-up's runs on one scenario.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BenchReport {
    /// The scenario's name.
    pub scenario: String,
    /// The scenario's id (a built-in's id, a file's stem; may be empty).
    #[serde(default)]
    pub scenario_id: String,
    /// When the benchmark ran, as the caller formats it (the CLI: UTC, `2025-01-31T12:00:00Z`).
    #[serde(default)]
    pub date: String,
    /// Where it ran (the CLI: the host name; the page: its own string).
    #[serde(default)]
    pub host: String,
    /// The planning time limit per run, seconds (the largest of the set-ups').
    pub time_limit_s: f64,
    /// Runs per set-up (when absent: the most rows of any set-up).
    #[serde(default)]
    pub runs: usize,
    /// The seeds every set-up ran, `first..=last` (the CLI's `bench` writes it; a report without it,
    /// as the page builds one, says its seeds only in its rows).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seeds: Option<SeedRange>,
    /// The set-ups, in the order they ran.
    pub setups: Vec<SetupReport>,
}

/// The seeds of a benchmark or of one shard of it: `first..=last`, each set-up one run per seed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SeedRange {
    /// The first seed.
    pub first: u64,
    /// The last seed (inclusive).
    pub last: u64,
}

impl SeedRange {
    /// The range the rows' seeds make when they are consecutive and ascending, else `None`.
    pub fn of_rows(rows: &[RunRow]) -> Option<SeedRange> {
        let (first, last) = (rows.first()?.seed, rows.last()?.seed);
        let consecutive = rows.windows(2).all(|w| w[0].seed.checked_add(1) == Some(w[1].seed));
        consecutive.then_some(SeedRange { first, last })
    }

    /// How many seeds.
    pub fn count(&self) -> u128 {
        u128::from(self.last - self.first) + 1
    }
}

impl std::fmt::Display for SeedRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}-{}", self.first, self.last)
    }
}

/// The formats [`render`] writes.
pub const FORMATS: [&str; 5] = ["csv", "json", "ompl", "table", "course"];

const STATUSES: [Status; 8] = [
    Status::Running,
    Status::Solved,
    Status::TimeLimit,
    Status::IterationLimit,
    Status::NodeLimit,
    Status::Cancelled,
    Status::NoPath,
    // Last, so the OMPL export's enum values of the others stay what they were.
    Status::MemoryLimit,
];

fn parse_status(name: &str) -> Option<Status> {
    STATUSES.iter().copied().find(|s| s.name() == name)
}

impl From<&PlannerBench> for SetupReport {
    fn from(b: &PlannerBench) -> SetupReport {
        let rows = b
            .per_run
            .iter()
            .enumerate()
            .map(|(i, (seed, solved, st))| {
                // `statuses` is parallel to `per_run`; a bench made without it still converts.
                let status =
                    b.statuses.get(i).copied().unwrap_or(if *solved { Status::Solved } else { Status::TimeLimit });
                RunRow::of(*seed, status, st)
            })
            .collect();
        SetupReport { label: b.label.clone(), planner: b.planner.clone(), params: b.params.clone(), rows }
    }
}

impl SetupReport {
    /// The set-up's summary: success rate; median, mean and standard deviation of time, nodes and
    /// checks over all runs, of cost and smoothed cost over the solved runs (as
    /// [`bench_planner`](super::bench::bench_planner) computes them).
    pub fn summary(&self) -> SetupSummary {
        SetupSummary::of(&self.rows)
    }
}

impl BenchReport {
    /// The report of benchmark results (as [`bench_planner`](super::bench::bench_planner) returns
    /// them); `date` and `host` are the caller's strings. The time limit is the largest set-up's.
    pub fn new(scenario: &str, scenario_id: &str, date: &str, host: &str, benches: &[PlannerBench]) -> BenchReport {
        BenchReport {
            scenario: scenario.to_string(),
            scenario_id: scenario_id.to_string(),
            date: date.to_string(),
            host: host.to_string(),
            time_limit_s: benches.iter().map(|b| b.time_limit_s).fold(0.0, f64::max),
            runs: benches.iter().map(|b| b.per_run.len()).max().unwrap_or(0),
            seeds: None,
            setups: benches.iter().map(SetupReport::from).collect(),
        }
        .with_seeds()
    }

    /// The report with [`seeds`](Self::seeds) set when every set-up ran the same consecutive
    /// seeds (else left as it was).
    pub fn with_seeds(mut self) -> BenchReport {
        let mut ranges = self.setups.iter().map(|s| SeedRange::of_rows(&s.rows));
        if let Some(Some(first)) = ranges.next() {
            if ranges.all(|r| r == Some(first)) {
                self.seeds = Some(first);
            }
        }
        self
    }

    /// Check what JSON cannot: known status names, `solved` agreeing with the status, finite
    /// non-negative times and finite costs. Errors name the offending row.
    pub fn check(&self) -> Result<(), String> {
        if !(self.time_limit_s.is_finite() && self.time_limit_s >= 0.0) {
            return Err(format!("time_limit_s: must be a non-negative number, not {}", self.time_limit_s));
        }
        if let Some(r) = self.seeds {
            if r.first > r.last {
                return Err(format!("seeds: first ({}) is after last ({})", r.first, r.last));
            }
        }
        for (i, s) in self.setups.iter().enumerate() {
            if s.label.trim().is_empty() {
                return Err(format!("setups[{i}].label: must not be empty"));
            }
            if let Some(want) = self.seeds {
                let held = SeedRange::of_rows(&s.rows);
                if held != Some(want) {
                    let held = held.map_or_else(|| seed_list(&s.rows), |h| h.to_string());
                    return Err(format!("setups[{i}].rows: hold seeds {held}, but seeds says {want}"));
                }
            }
            for (j, r) in s.rows.iter().enumerate() {
                let at = format!("setups[{i}].rows[{j}]");
                let status = parse_status(&r.status).ok_or_else(|| {
                    let known: Vec<&str> = STATUSES.iter().map(|s| s.name()).collect();
                    format!(
                        "{at}.status: unknown status \"{}\" (known: {})",
                        crate::limits::cut(&r.status, 100),
                        known.join(", ")
                    )
                })?;
                if r.solved != (status == Status::Solved) {
                    return Err(format!(
                        "{at}: solved is {} but status is \"{}\"",
                        r.solved,
                        crate::limits::cut(&r.status, 100)
                    ));
                }
                for (name, v) in [
                    ("time_ms", Some(r.time_ms)),
                    ("smoothing_ms", Some(r.smoothing_ms)),
                    ("cost", r.cost),
                    ("smoothed_cost", r.smoothed_cost),
                ] {
                    if let Some(v) = v {
                        if !(v.is_finite() && v >= 0.0) {
                            return Err(format!("{at}.{name}: must be a non-negative number, not {v}"));
                        }
                    }
                }
            }
        }
        Ok(())
    }
}

/// The rows' seeds as a short list (`1,2,4,...` cut after 10), for messages.
fn seed_list(rows: &[RunRow]) -> String {
    if rows.is_empty() {
        return "none".into();
    }
    let mut s: Vec<String> = rows.iter().take(10).map(|r| r.seed.to_string()).collect();
    if rows.len() > 10 {
        s.push(format!("... ({} in all)", rows.len()));
    }
    s.join(",")
}

/// One line of free text (no line breaks).
fn one_line(s: &str) -> String {
    s.chars().map(|c| if c == '\n' || c == '\r' { ' ' } else { c }).collect()
}

/// The report in one of [`FORMATS`]: `csv`, `json`, `ompl` (the OMPL benchmark log), `table`
/// (the courses' Markdown table) or `course` (report 001's course benchmark lines).
pub fn render(r: &BenchReport, format: &str) -> Result<String, String> {
    match format {
        "csv" => Ok(to_csv(r)),
        "json" => Ok(to_json(r)),
        "ompl" => Ok(to_ompl_log(r)),
        "table" => Ok(course_table(r)),
        "course" => Ok(to_course_csv(r)),
        _ => Err(format!(
            "unknown export format \"{}\" (known: {})",
            crate::limits::cut(format, 100),
            FORMATS.join(", ")
        )),
    }
}

/// A UTC timestamp `YYYY-MM-DDTHH:MM:SSZ` of `unix_seconds` since 1970-01-01 (the proleptic
/// Gregorian calendar; Howard Hinnant's `civil_from_days`). The caller reads the clock.
pub fn utc_timestamp(unix_seconds: u64) -> String {
    let days = (unix_seconds / 86_400) as i64;
    let secs = unix_seconds % 86_400;
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z", secs / 3600, secs / 60 % 60, secs % 60)
}
