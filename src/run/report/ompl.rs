//! The report as an OMPL benchmark log ([`to_ompl_log`]) and the planner names it uses
//! ([`ompl_planner_names`]).
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

use super::{one_line, parse_status, BenchReport, STATUSES};
use crate::status::Status;
use serde_json::Value;

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
        Status::TimeLimit | Status::IterationLimit | Status::NodeLimit | Status::MemoryLimit => 4,
        Status::Solved => 6,
        Status::Cancelled => 8,
        Status::NoPath => 9,
    }
}

/// A word the OMPL reader keeps whole: whitespace, `;`, `|` and backquotes become `_`.
fn ompl_word(s: &str) -> String {
    s.trim()
        .chars()
        .map(|c| if c.is_whitespace() || c.is_control() || matches!(c, ';' | '|' | '`') { '_' } else { c })
        .collect()
}

/// A number as the OMPL reader takes it (`nan`/`inf` for non-finite values).
pub(crate) fn ompl_real(x: f64) -> String {
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
