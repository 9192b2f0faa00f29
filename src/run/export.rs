//! Benchmark results as one [`BenchReport`] (scenario, date, host, time limit, and per set-up its
//! planner, parameters and one [`RunRow`] per seed) and its four renderings: CSV ([`to_csv`]),
//! JSON with summaries ([`to_json`], read back by [`from_json`]), an OMPL benchmark log that
//! `ompl_benchmark_statistics.py` turns into a Planner Arena database ([`to_ompl_log`]), and the
//! courses' Markdown table ([`course_table`]). The CLI's `bench` and the page (through wasm's
//! `bench_export`) both write through these functions. No clock is read here: the caller passes
//! the date and host.
//!
//! # The OMPL benchmark log
//!
//! Sources read:
//! - OMPL's manual, "The benchmark logfile format" (EBNF), in `doc/markdown/benchmark.md` of
//!   <https://github.com/ompl/ompl> (rendered at <https://ompl.kavrakilab.org/benchmark.html>);
//! - the writer, `ompl::tools::Benchmark::saveResultsToStream` in
//!   `src/ompl/tools/benchmark/src/Benchmark.cpp`, and its run properties (`time REAL`,
//!   `solved BOOLEAN`, `status ENUM`, `graph states INTEGER`, `solution length REAL`,
//!   `simplification time REAL`, `simplified solution length REAL`, ...);
//! - the reader, `readBenchmarkLog` in `scripts/ompl_benchmark_statistics.py`, which is what
//!   Planner Arena's databases are made with (`ompl_benchmark_statistics.py LOG -d bench.db`);
//! - `ompl::base::PlannerStatus` (`src/ompl/base/PlannerStatus.h` for the values,
//!   `src/ompl/base/src/PlannerStatus.cpp` `asString` for the names; the names of ABORT and
//!   INFEASIBLE, added after the version of that file read, are written as "Abort" and
//!   "Infeasible"; the reader only stores them as descriptions) for the `status` enum; the
//!   `collision checks INTEGER` name is RRT*'s progress property ("the number of state validator
//!   calls", benchmark.md's database schema);
//! - Planner Arena's `scripts/plannerarena/server.R`: planner names shown without `geometric_`,
//!   `simplified_<attribute>` plotted beside `<attribute>`, ENUM columns drawn by the enum of the
//!   same name;
//! - MoveIt's benchmark log writer (`moveit_ros/benchmarks`), another library writing this format,
//!   for `-1 MB per run` (no memory cap) and a library name other than OMPL in the version line.
//!
//! The grammar written here (`EOL` is `\n`; every count is followed by that many items):
//!
//! ```text
//! logfile       ::= preamble planner_data*
//! preamble      ::= "Planarium version " version EOL            (library_name " version " version_number)
//!                   "Experiment " name EOL                      (name: no whitespace; the reader takes the last word)
//!                   "0 experiment properties" EOL
//!                   "Running on " host EOL                      (host: no whitespace, same reason)
//!                   "Starting at " date EOL
//!                   "<<<|" EOL setup_lines "|>>>" EOL           (the setup text; no cpuinfo block, it is optional)
//!                   int " is the random seed" EOL               (the first run's seed)
//!                   float " seconds per run" EOL                (the time limit)
//!                   "-1 MB per run" EOL                         (no memory limit)
//!                   int " runs per planner" EOL
//!                   float " seconds spent to collect the data" EOL   (sum of planning and smoothing times)
//!                   "2 enum types" EOL
//!                   "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|"
//!                       "Approximate solution|Exact solution|Crash|Abort|Infeasible" EOL
//!                   "planarium_status|running|solved|time limit|iteration limit|node limit|cancelled|no path" EOL
//!                   int " planners" EOL
//! planner_data  ::= "geometric_" label EOL                      (label: no whitespace, ';', '|' or '`')
//!                   int " common properties" EOL (name " = " value EOL)*     (planner, explicit parameters; sorted)
//!                   "11 properties for each run" EOL (property_name " " type EOL)*
//!                   int " runs" EOL (value "; ")* EOL per run   (value: a number, or empty when absent)
//!                   "." EOL                                     (no progress properties)
//! ```
//!
//! The run properties, in OMPL's (sorted) order: `collision checks INTEGER` (state checks),
//! `graph states INTEGER` (nodes), `iterations INTEGER`, `planarium status ENUM` (our status),
//! `seed INTEGER`, `simplification time REAL` (smoothing, s), `simplified solution length REAL`
//! (smoothed cost), `solution length REAL` (cost), `solved BOOLEAN` (0/1), `status ENUM` (OMPL's
//! `PlannerStatus`: solved → Exact solution, a limit → Timeout, cancelled → Abort, no path →
//! Infeasible), `time REAL` (planning time, seconds). The three solution properties are empty
//! for unsolved runs, as OMPL leaves them out.

use super::bench::{PlannerBench, Summary};
use crate::status::Status;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

/// One run of a benchmark: the seed and how it went (the contract's `stats`, flattened).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunRow {
    /// The seed.
    pub seed: u64,
    /// Whether a path was found (`status` is `"solved"`).
    pub solved: bool,
    /// How the run ended: a status name (`solved`, `time_limit`, `iteration_limit`, `node_limit`,
    /// `cancelled`, `no_path`, `running`).
    pub status: String,
    /// Planning time, milliseconds (smoothing excluded).
    pub time_ms: f64,
    /// Planner iterations.
    pub iterations: u64,
    /// Nodes in all trees.
    pub nodes: u64,
    /// State validity checks.
    pub checks: u64,
    /// Raw path cost (`null` when unsolved).
    #[serde(default)]
    pub cost: Option<f64>,
    /// Smoothed path cost (`null` when unsolved).
    #[serde(default)]
    pub smoothed_cost: Option<f64>,
    /// Smoothing time, milliseconds (optional, 0 when absent).
    #[serde(default)]
    pub smoothing_ms: f64,
}

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
    /// The set-ups, in the order they ran.
    pub setups: Vec<SetupReport>,
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
    /// Raw path cost (solved runs).
    pub cost: Summary,
    /// Smoothed path cost (solved runs).
    pub smoothed_cost: Summary,
}

/// The formats [`render`] writes.
pub const FORMATS: [&str; 4] = ["csv", "json", "ompl", "table"];

const STATUSES: [Status; 7] = [
    Status::Running,
    Status::Solved,
    Status::TimeLimit,
    Status::IterationLimit,
    Status::NodeLimit,
    Status::Cancelled,
    Status::NoPath,
];

/// OMPL's `PlannerStatus::StatusType` names, in value order (`status|...` enum line).
const OMPL_STATUS: [&str; 10] = [
    "Unknown status",
    "Invalid start",
    "Invalid goal",
    "Unrecognized goal type",
    "Timeout",
    "Approximate solution",
    "Exact solution",
    "Crash",
    "Abort",
    "Infeasible",
];

/// OMPL's `PlannerStatus` value for one of our statuses.
fn ompl_status(s: Status) -> usize {
    match s {
        Status::Running => 0,
        Status::TimeLimit | Status::IterationLimit | Status::NodeLimit => 4,
        Status::Solved => 6,
        Status::Cancelled => 8,
        Status::NoPath => 9,
    }
}

fn parse_status(name: &str) -> Option<Status> {
    STATUSES.iter().copied().find(|s| s.name() == name)
}

impl RunRow {
    /// The row of one run's statistics.
    pub fn of(seed: u64, status: Status, st: &super::Stats) -> RunRow {
        RunRow {
            seed,
            solved: status == Status::Solved,
            status: status.name().to_string(),
            time_ms: st.time_ms,
            iterations: st.iterations,
            nodes: st.nodes,
            checks: st.checks,
            cost: st.cost,
            smoothed_cost: st.smoothed_cost,
            smoothing_ms: st.smoothing_ms,
        }
    }
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

impl SetupSummary {
    /// The summary of some runs (see [`SetupReport::summary`]).
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
            cost: solved_only(|r| r.cost),
            smoothed_cost: solved_only(|r| r.smoothed_cost),
        }
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
            setups: benches.iter().map(SetupReport::from).collect(),
        }
    }

    /// Check what JSON cannot: known status names, `solved` agreeing with the status, finite
    /// non-negative times and finite costs. Errors name the offending row.
    pub fn check(&self) -> Result<(), String> {
        if !(self.time_limit_s.is_finite() && self.time_limit_s >= 0.0) {
            return Err(format!("time_limit_s: must be a non-negative number, not {}", self.time_limit_s));
        }
        for (i, s) in self.setups.iter().enumerate() {
            if s.label.trim().is_empty() {
                return Err(format!("setups[{i}].label: must not be empty"));
            }
            for (j, r) in s.rows.iter().enumerate() {
                let at = format!("setups[{i}].rows[{j}]");
                let status = parse_status(&r.status).ok_or_else(|| {
                    let known: Vec<&str> = STATUSES.iter().map(|s| s.name()).collect();
                    format!("{at}.status: unknown status \"{}\" (known: {})", r.status, known.join(", "))
                })?;
                if r.solved != (status == Status::Solved) {
                    return Err(format!("{at}: solved is {} but status is \"{}\"", r.solved, r.status));
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

/// Read a report (as [`to_json`] writes it, or as the page builds it; `summary` and other extra
/// keys are ignored) and [check](BenchReport::check) it.
pub fn from_json(text: &str) -> Result<BenchReport, String> {
    let mut r: BenchReport = serde_json::from_str(text).map_err(|e| format!("bench report: {e}"))?;
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
        setups: Vec<SetupOut<'a>>,
    }
    let out = ReportOut {
        scenario: &r.scenario,
        scenario_id: &r.scenario_id,
        date: &r.date,
        host: &r.host,
        time_limit_s: r.time_limit_s,
        runs: r.runs,
        setups: r.setups.iter().map(|s| SetupOut { setup: s, summary: s.summary() }).collect(),
    };
    serde_json::to_string_pretty(&out).expect("a report serialises") + "\n"
}

/// The CSV header.
pub const CSV_HEADER: &str = "setup,planner,seed,solved,status,time_ms,iterations,nodes,checks,cost,smoothed_cost";

/// One CSV field, quoted as RFC 4180 asks when it holds a comma, a quote or a line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\r', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn opt(v: Option<f64>) -> String {
    v.map(|x| x.to_string()).unwrap_or_default()
}

/// The runs as CSV (RFC 4180: CRLF line breaks, a header line): one row per run, columns
/// [`CSV_HEADER`]; `solved` is `true`/`false`, costs are empty when unsolved, times in ms.
pub fn to_csv(r: &BenchReport) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push_str("\r\n");
    for s in &r.setups {
        for row in &s.rows {
            let fields = [
                csv_field(&s.label),
                csv_field(&s.planner),
                row.seed.to_string(),
                row.solved.to_string(),
                csv_field(&row.status),
                row.time_ms.to_string(),
                row.iterations.to_string(),
                row.nodes.to_string(),
                row.checks.to_string(),
                opt(row.cost),
                opt(row.smoothed_cost),
            ];
            out.push_str(&fields.join(","));
            out.push_str("\r\n");
        }
    }
    out
}

/// A word the OMPL reader keeps whole: whitespace, `;`, `|` and backquotes become `_`.
fn ompl_word(s: &str) -> String {
    s.trim()
        .chars()
        .map(|c| if c.is_whitespace() || c.is_control() || matches!(c, ';' | '|' | '`') { '_' } else { c })
        .collect()
}

/// One line of free text (no line breaks).
fn one_line(s: &str) -> String {
    s.chars().map(|c| if c == '\n' || c == '\r' { ' ' } else { c }).collect()
}

/// A number as the OMPL reader takes it (`nan`/`inf` for non-finite values).
fn ompl_real(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        "inf".into()
    } else {
        x.to_string()
    }
}

/// The OMPL planner name of each set-up: `geometric_<label>` with the label made one word, made
/// unique with `_2`, `_3`, ... when two labels give the same word.
pub fn ompl_planner_names(r: &BenchReport) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for s in &r.setups {
        let base = format!("geometric_{}", ompl_word(&s.label));
        let mut name = base.clone();
        let mut k = 2;
        while names.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        names.push(name);
    }
    names
}

/// The run properties of the log, in order (OMPL sorts them by name).
pub const OMPL_RUN_PROPERTIES: [&str; 11] = [
    "collision checks INTEGER",
    "graph states INTEGER",
    "iterations INTEGER",
    "planarium status ENUM",
    "seed INTEGER",
    "simplification time REAL",
    "simplified solution length REAL",
    "solution length REAL",
    "solved BOOLEAN",
    "status ENUM",
    "time REAL",
];

/// The report as an OMPL benchmark log (the grammar in this module's documentation), which
/// `ompl_benchmark_statistics.py LOG -d bench.db` reads into a database for Planner Arena.
pub fn to_ompl_log(r: &BenchReport) -> String {
    let mut o = String::new();
    let mut line = |s: &str| {
        o.push_str(s);
        o.push('\n');
    };
    line(&format!("Planarium version {}", env!("CARGO_PKG_VERSION")));
    let exp = [&r.scenario, &r.scenario_id]
        .iter()
        .map(|s| ompl_word(s))
        .find(|s| !s.is_empty())
        .unwrap_or_else(|| "NO_NAME".into());
    line(&format!("Experiment {exp}"));
    line("0 experiment properties");
    let host = ompl_word(&r.host);
    line(&format!("Running on {}", if host.is_empty() { "UNKNOWN" } else { &host }));
    line(&format!("Starting at {}", one_line(r.date.trim())));
    // The setup text: what OMPL's SimpleSetup::print and printProperties would say.
    line("<<<|");
    line(&format!(
        "Planarium benchmark of scenario \"{}\" (id \"{}\")",
        one_line(&r.scenario),
        one_line(&r.scenario_id)
    ));
    line(&format!("{} runs per set-up, time limit {} s per run", r.runs, r.time_limit_s));
    line("Set-ups (label: planner, explicit parameters as JSON):");
    for s in &r.setups {
        let seeds: Vec<String> = s.rows.iter().map(|x| x.seed.to_string()).collect();
        line(&format!(
            "  {}: {} {} seeds {}",
            one_line(&s.label),
            one_line(&s.planner),
            Value::Object(s.params.clone()),
            seeds.join(",")
        ));
    }
    line("|>>>");
    let seed = r.setups.iter().flat_map(|s| s.rows.first()).map(|x| x.seed).next().unwrap_or(0);
    line(&format!("{seed} is the random seed"));
    line(&format!("{} seconds per run", ompl_real(r.time_limit_s)));
    line("-1 MB per run");
    line(&format!("{} runs per planner", r.runs));
    let total: f64 = r.setups.iter().flat_map(|s| &s.rows).map(|x| (x.time_ms + x.smoothing_ms) / 1000.0).sum();
    line(&format!("{} seconds spent to collect the data", ompl_real(total)));
    line("2 enum types");
    line(&format!("status|{}", OMPL_STATUS.join("|")));
    let ours: Vec<String> = STATUSES.iter().map(|s| s.name().replace('_', " ")).collect();
    line(&format!("planarium_status|{}", ours.join("|")));
    line(&format!("{} planners", r.setups.len()));
    for (s, name) in r.setups.iter().zip(ompl_planner_names(r)) {
        line(&name);
        let mut common: Vec<(String, String)> = vec![("planner".into(), s.planner.clone())];
        for (k, v) in &s.params {
            common.push((k.clone(), v.as_str().map_or_else(|| v.to_string(), String::from)));
        }
        common.sort();
        line(&format!("{} common properties", common.len()));
        for (k, v) in &common {
            line(&format!("{} = {}", one_line(k), one_line(v)));
        }
        line(&format!("{} properties for each run", OMPL_RUN_PROPERTIES.len()));
        for p in OMPL_RUN_PROPERTIES {
            line(p);
        }
        line(&format!("{} runs", s.rows.len()));
        for x in &s.rows {
            let status = parse_status(&x.status).unwrap_or(if x.solved { Status::Solved } else { Status::Running });
            let ours = STATUSES.iter().position(|s| *s == status).unwrap_or(0);
            let solved_only = |v: f64| if x.solved { ompl_real(v) } else { String::new() };
            let values = [
                x.checks.to_string(),
                x.nodes.to_string(),
                x.iterations.to_string(),
                ours.to_string(),
                x.seed.to_string(),
                solved_only(x.smoothing_ms / 1000.0),
                x.smoothed_cost.map(ompl_real).unwrap_or_default(),
                x.cost.map(ompl_real).unwrap_or_default(),
                u8::from(x.solved).to_string(),
                ompl_status(status).to_string(),
                ompl_real(x.time_ms / 1000.0),
            ];
            let mut row = String::new();
            for v in values {
                row.push_str(&v);
                row.push_str("; ");
            }
            line(&row);
        }
        line(".");
    }
    o
}

fn cell(m: &Summary, f: fn(&Summary) -> f64, digits: usize) -> String {
    if m.n == 0 {
        "—".into()
    } else {
        format!("{:.*}", digits, f(m))
    }
}

/// The courses' table as Markdown, one row per set-up: success rate; mean, standard deviation and
/// median of planning time; mean and median nodes and state checks; mean cost and smoothed cost
/// over the solved runs (— when none solved).
pub fn course_table(r: &BenchReport) -> String {
    let mut out = String::from(
        "| set-up | planner | runs | solved | mean time (ms) | std time (ms) | median time (ms) | mean nodes | median nodes | mean checks | median checks | mean cost | mean smoothed cost |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let md = |s: &str| one_line(s).replace('|', "\\|");
    for s in &r.setups {
        let m = s.summary();
        out.push_str(&format!(
            "| {} | {} | {} | {:.0}% | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            md(&s.label),
            md(&s.planner),
            m.runs,
            m.success_rate * 100.0,
            cell(&m.time_ms, |x| x.mean, 2),
            cell(&m.time_ms, |x| x.std, 2),
            cell(&m.time_ms, |x| x.median, 2),
            cell(&m.nodes, |x| x.mean, 1),
            cell(&m.nodes, |x| x.median, 1),
            cell(&m.checks, |x| x.mean, 0),
            cell(&m.checks, |x| x.median, 0),
            cell(&m.cost, |x| x.mean, 4),
            cell(&m.smoothed_cost, |x| x.mean, 4),
        ));
    }
    out
}

/// The report in one of [`FORMATS`]: `csv`, `json`, `ompl` (the OMPL benchmark log) or `table`
/// (the courses' Markdown table).
pub fn render(r: &BenchReport, format: &str) -> Result<String, String> {
    match format {
        "csv" => Ok(to_csv(r)),
        "json" => Ok(to_json(r)),
        "ompl" => Ok(to_ompl_log(r)),
        "table" => Ok(course_table(r)),
        _ => Err(format!("unknown export format \"{format}\" (known: {})", FORMATS.join(", "))),
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
