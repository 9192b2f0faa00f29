//! The ASV course's grading protocol (`docs/sources.md`): every problem is run 10 times
//! (seeds 1..=10); a run counts when the planner solves it within the problem's time limit **and**
//! its path, cut into the solution file's primitive steps, passes the independent re-check of the
//! course's Tester rules ([`crate::io::asv::check_solution`]); a problem passes when at least 5
//! runs count.
//!
//! The time limit is 1 minute in an open map and 5 minutes in a cluttered one. The course does not
//! define "cluttered"; here a map is **cluttered when it has 3 obstacles or more** (the official
//! files: 3ASV-easy and 7ASV-easy have 2 walls, open; 3ASV and 7ASV have 7, cluttered). Times are
//! wall-clock (the course counted CPU time; with one thread they are close), from the start of
//! planning to the end of smoothing, path cutting and re-checking included.

use super::{RunConfig, Session};
use crate::clock::Instant;
use crate::planners::Params;
use crate::problem::Problem;
use crate::scenario::{RobotSpec, Scenario};
use crate::status::Status;

/// Runs per problem, and runs that must count, in the course's protocol.
pub const COURSE_RUNS: u64 = 10;
/// At least this many of [`COURSE_RUNS`] runs must count.
pub const COURSE_NEEDED: u64 = 5;
/// The time limits, seconds: open and cluttered maps.
pub const OPEN_LIMIT_S: f64 = 60.0;
/// See [`OPEN_LIMIT_S`].
pub const CLUTTERED_LIMIT_S: f64 = 300.0;
/// A map with this many obstacles or more is cluttered.
pub const CLUTTERED_OBSTACLES: usize = 3;

/// Whether the course would call the scenario's map cluttered (see the module documentation).
pub fn cluttered(sc: &Scenario) -> bool {
    sc.obstacles.len() >= CLUTTERED_OBSTACLES
}

/// One graded run.
#[derive(Clone, Debug)]
pub struct GradedRun {
    /// The seed.
    pub seed: u64,
    /// How the planner ended.
    pub status: Status,
    /// Wall time, seconds: planning, smoothing, cutting into primitive steps and re-checking.
    pub time_s: f64,
    /// The re-check's verdict on the path (`None` when there was no path).
    pub check: Option<Result<(), String>>,
    /// Whether the run counts: solved within the limit and the path passes the re-check.
    pub counts: bool,
}

/// One problem's verdict.
#[derive(Clone, Debug)]
pub struct Grade {
    /// The problem's name (the file's stem or the built-in's id).
    pub name: String,
    /// Whether the map is cluttered.
    pub cluttered: bool,
    /// The time limit applied, seconds.
    pub limit_s: f64,
    /// Runs that must count.
    pub needed: u64,
    /// Every run, seed order.
    pub runs: Vec<GradedRun>,
}

impl Grade {
    /// Runs that count.
    pub fn solved(&self) -> u64 {
        self.runs.iter().filter(|r| r.counts).count() as u64
    }
    /// Whether the problem passes.
    pub fn pass(&self) -> bool {
        self.solved() >= self.needed
    }
    /// Median and maximum time of the runs that count, seconds (`None` when none counts).
    pub fn median_max(&self) -> Option<(f64, f64)> {
        let mut t: Vec<f64> = self.runs.iter().filter(|r| r.counts).map(|r| r.time_s).collect();
        if t.is_empty() {
            return None;
        }
        t.sort_by(f64::total_cmp);
        let n = t.len();
        let median = if n % 2 == 1 { t[n / 2] } else { 0.5 * (t[n / 2 - 1] + t[n / 2]) };
        Some((median, t[n - 1]))
    }
    /// The verdict line: `NAME  cluttered (300 s)  solved 10/10  median 0.05 s  max 0.1 s  PASS`.
    pub fn line(&self) -> String {
        let times = match self.median_max() {
            Some((med, max)) => format!("median {med:.3} s  max {max:.3} s"),
            None => "median -  max -".to_string(),
        };
        let failures: Vec<String> = self
            .runs
            .iter()
            .filter(|r| !r.counts)
            .map(|r| match &r.check {
                Some(Err(e)) => format!("seed {}: path rejected ({})", r.seed, crate::limits::cut(e, 120)),
                Some(Ok(())) => format!("seed {}: over the limit ({:.1} s)", r.seed, r.time_s),
                None => format!("seed {}: {}", r.seed, r.status.name()),
            })
            .collect();
        format!(
            "{:<20} {:<9} ({:>3.0} s)  solved {:>2}/{:<2} (needs {})  {}  {}{}",
            self.name,
            if self.cluttered { "cluttered" } else { "open" },
            self.limit_s,
            self.solved(),
            self.runs.len(),
            self.needed,
            times,
            if self.pass() { "PASS" } else { "FAIL" },
            if failures.is_empty() { String::new() } else { format!("\n    {}", failures.join("\n    ")) }
        )
    }
}

/// Grade `planner` with `params` on the ASV problem `sc`: `runs` seeds (the course: 10), of which
/// `needed` must count (the course: 5), each with the course's time limit or `limit_s` when given.
pub fn grade(
    sc: &Scenario,
    name: &str,
    planner: &str,
    params: &Params,
    runs: u64,
    needed: u64,
    limit_s: Option<f64>,
) -> Result<Grade, String> {
    if !matches!(sc.robot, RobotSpec::Asv { .. }) {
        return Err(format!("{name}: --course-grade grades ASV problems (the course's vehicles), not this robot"));
    }
    if runs == 0 || runs > 1000 || needed > runs {
        return Err(format!("course grading: {runs} runs with {needed} needed (runs 1..=1000, needed ≤ runs)"));
    }
    let cluttered = cluttered(sc);
    let limit_s = limit_s.unwrap_or(if cluttered { CLUTTERED_LIMIT_S } else { OPEN_LIMIT_S });
    if !(limit_s > 0.0 && limit_s <= 3600.0) {
        return Err(format!("course grading: a time limit of {limit_s} s (0 to 3600)"));
    }
    let mut params = params.clone();
    let spec = crate::planners::find(planner)
        .ok_or_else(|| format!("unknown planner \"{}\"", crate::limits::cut(planner, 100)))?;
    params.set_text(spec, "time_limit", &limit_s.to_string())?;
    let mut graded = Vec::new();
    for seed in 1..=runs {
        let problem = Problem::from_scenario(sc).map_err(|e| e.to_string())?;
        let config = RunConfig { planner: planner.to_string(), params: params.clone(), seed, record_events: false };
        let t0 = Instant::now();
        let mut s = Session::new(problem, config)?;
        let status = s.run_to_end();
        let check = (status == Status::Solved).then(|| {
            crate::io::asv::primitive_steps(s.problem(), s.planning_path(false))
                .and_then(|steps| crate::io::asv::check_solution(sc, &steps))
        });
        let time_s = t0.elapsed().as_secs_f64();
        let counts = matches!(check, Some(Ok(()))) && time_s <= limit_s;
        graded.push(GradedRun { seed, status, time_s, check, counts });
    }
    Ok(Grade { name: name.to_string(), cluttered, limit_s, needed, runs: graded })
}
