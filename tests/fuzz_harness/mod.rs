//! The checks shared by the cargo fuzz targets (`fuzz/`, which includes this file by path) and the
//! property test (`tests/fuzz_props.rs`): each entry feeds one input to the core the way the CLI
//! and the page do, and returns `Err` with the property it broke. A panic inside the core is not
//! caught here (libFuzzer records it as a crash; the property test catches it per input).
//!
//! Properties (issue 13):
//! - every rejection names where: a non-empty JSON path, or a line and a column;
//! - a run with limits (time `T`, iterations, nodes) ends near `T` (measured on the thread's clock,
//!   `planarium::clock`, from `Session::new` through the result and the page's path frames: the
//!   fuzz targets allow `T` + `FUZZ_TIME_SLACK_S` of wall time; the property pass runs on a
//!   simulated clock and allows exactly the mechanism's delay) and never exceeds its iteration or
//!   node limit;
//! - an accepted scenario written back out (`Scenario::to_json`) reads back equal;
//! - a solved ASV run's solution file reads back and passes the independent checker.
#![allow(dead_code)]

use planarium::clock::Instant;
use planarium::io;
use planarium::planners::{self, Params, REGISTRY};
use planarium::problem::Problem;
use planarium::robot::Robot;
use planarium::run::{RunConfig, Session};
use planarium::scenario::{RobotSpec, Scenario, ScenarioError};
use planarium::status::Status;

/// Animation spacing of the page's path frames (`www/worker.js`'s `FRAME_SPACING`).
pub const FRAME_SPACING: f64 = 0.004;

/// Whether an error says where: a JSON path, or a line and column.
pub fn located(e: &ScenarioError) -> bool {
    !e.path.is_empty() || (e.line.is_some() && e.column.is_some())
}

static REQUIRE_LOCATION: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(true);

/// Whether a rejection without a location breaks a property (default: yes). The fuzz targets turn
/// it off with `PLANARIUM_FUZZ_LOCATION=0`, to look for panics and hangs past a known finding.
pub fn set_require_location(on: bool) {
    REQUIRE_LOCATION.store(on, std::sync::atomic::Ordering::Relaxed);
}

fn require_located(stage: &str, e: &ScenarioError) -> Result<(), String> {
    if located(e) || !REQUIRE_LOCATION.load(std::sync::atomic::Ordering::Relaxed) {
        Ok(())
    } else {
        Err(format!("{stage} rejected the input without saying where: {e:?}"))
    }
}

/// What a document became.
pub enum Outcome {
    /// Rejected (with a location) while reading.
    Rejected(ScenarioError),
    /// Read, but the problem was rejected (with a location).
    Invalid(ScenarioError),
    /// Read and built.
    Problem(Box<Problem>),
}

/// A scenario read, then built into a problem; both errors must say where; an accepted scenario
/// must survive `to_json` and back.
pub fn scenario_outcome(stage: &str, read: Result<Scenario, ScenarioError>) -> Result<Outcome, String> {
    let sc = match read {
        Ok(sc) => sc,
        Err(e) => {
            require_located(stage, &e)?;
            return Ok(Outcome::Rejected(e));
        }
    };
    let text = sc.to_json();
    match Scenario::from_json(&text) {
        Ok(back) if back == sc => {}
        Ok(back) => return Err(format!("{stage}: the scenario written back reads as another one:\n{text}\n{back:?}")),
        Err(e) => return Err(format!("{stage}: the scenario written back is rejected ({e}):\n{text}")),
    }
    match Problem::from_scenario(&sc) {
        Ok(p) => Ok(Outcome::Problem(Box::new(p))),
        Err(e) => {
            require_located("Problem::from_scenario", &e)?;
            Ok(Outcome::Invalid(e))
        }
    }
}

/// Target (a): a scenario document.
pub fn check_scenario(text: &str) -> Result<Outcome, String> {
    scenario_outcome("Scenario::from_json", Scenario::from_json(text))
}

/// Target (b): a Technion HW3 map.
pub fn check_technion(text: &str) -> Result<Outcome, String> {
    scenario_outcome("technion::import_map", io::technion::import_map(text, "fuzz"))
}

/// Target (f): an occupancy map (issue 17): a map_server YAML, a line `===`, then the image's
/// bytes (PGM or PNG); without `===` the whole input is a plain image.
pub fn check_map(data: &[u8]) -> Result<Outcome, String> {
    let split = data.windows(5).position(|w| w == b"\n===\n");
    let (yaml, image) = match split {
        Some(k) => (Some(String::from_utf8_lossy(&data[..k]).into_owned()), &data[k + 5..]),
        None => (None, data),
    };
    let name = if image.starts_with(b"\x89PNG") { "fuzz.png" } else { "fuzz.pgm" };
    let read = io::occupancy::import_image(image, name, yaml.as_deref().map(|y| (y, "fuzz.yaml")));
    scenario_outcome("occupancy::import_image", read)
}

/// Target (c): an ASV problem file.
pub fn check_asv_problem(text: &str) -> Result<Outcome, String> {
    scenario_outcome("asv::import_problem", io::asv::import_problem(text, "fuzz"))
}

/// Any document, recognised by content as the page's Open file… and the CLI do.
pub fn check_import(text: &str) -> Result<Outcome, String> {
    scenario_outcome("io::import", io::import(text, "fuzz"))
}

/// Target (d): an ASV solution file checked against a problem (an ASV problem file or a scenario).
/// The reader's errors are text: they must name a line. Returns whether the checker accepted it.
pub fn check_asv_solution(problem_text: &str, solution_text: &str) -> Result<bool, String> {
    let sc = match io::import(problem_text, "fuzz") {
        Ok(sc) => sc,
        Err(e) => {
            require_located("io::import", &e)?;
            return Ok(false);
        }
    };
    let configs = match io::asv::read_solution(solution_text) {
        Ok(c) => c,
        Err(e) => {
            if !e.starts_with("line ") && REQUIRE_LOCATION.load(std::sync::atomic::Ordering::Relaxed) {
                return Err(format!("asv::read_solution rejected the file without naming a line: {e}"));
            }
            return Ok(false);
        }
    };
    Ok(io::asv::check_solution(&sc, &configs).is_ok())
}

/// The limits of one small run.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Index into the planner registry (taken modulo its length).
    pub planner: usize,
    /// The run's seed.
    pub seed: u64,
    /// `time_limit`, seconds.
    pub time_s: f64,
    /// `max_iterations`.
    pub iterations: u64,
    /// `max_nodes`.
    pub nodes: u64,
    /// `shortcut_attempts`.
    pub shortcuts: u64,
    /// Record events (the page does; the CLI only with `--events`).
    pub events: bool,
}

impl Budget {
    /// A budget from a few bytes (the fuzz target's selector).
    pub fn from_bytes(b: &[u8]) -> Budget {
        let g = |i: usize| b.get(i).copied().unwrap_or(0) as u64;
        Budget {
            planner: g(0) as usize,
            seed: g(1) | (g(2) << 8),
            time_s: 0.2,
            iterations: 1 + (g(3) | (g(4) << 8)) % 3000,
            nodes: 2 + (g(5) | (g(6) << 8)) % 3000,
            shortcuts: g(7) % 101,
            events: g(1) & 1 == 1,
        }
    }
}

/// What a small run did.
#[derive(Debug)]
pub struct RunReport {
    /// Planner name.
    pub planner: &'static str,
    /// Final status.
    pub status: Status,
    /// Time on the thread's clock (`planarium::clock`: the real one, or a simulated one) from
    /// `Session::new` to the end of the path frames, seconds.
    pub wall_s: f64,
    /// Iterations run.
    pub iterations: u64,
    /// Nodes in the trees.
    pub nodes: u64,
}

/// Target (e): plan on a problem under `budget`, as the CLI does (the scenario's planner block
/// first when it names this planner, then the limits), then read the result, the page's path
/// frames and, for a solved ASV run, the solution file. `Ok(None)`: the planner cannot take this
/// problem (a clear error from `Session::new`).
pub fn plan(problem: Problem, budget: &Budget) -> Result<Option<RunReport>, String> {
    let spec = &REGISTRY[budget.planner % REGISTRY.len()];
    let mut values = match &problem.scenario.planner {
        Some(d) if d.name == spec.name => d.params.clone(),
        _ => serde_json::Map::new(),
    };
    values.insert("time_limit".into(), serde_json::json!(budget.time_s));
    values.insert("max_iterations".into(), serde_json::json!(budget.iterations));
    values.insert("max_nodes".into(), serde_json::json!(budget.nodes));
    values.insert("shortcut_attempts".into(), serde_json::json!(budget.shortcuts));
    let params = Params::from_json(spec, &serde_json::Value::Object(values))
        .map_err(|(k, e)| format!("the harness's own parameters were refused: {k}: {e}"))?;
    let config = RunConfig { planner: spec.name.into(), params, seed: budget.seed, record_events: budget.events };
    let t0 = Instant::now();
    let mut s = match Session::new(problem, config) {
        Ok(s) => s,
        Err(e) if !e.is_empty() => return Ok(None),
        Err(_) => return Err(format!("{}: Session::new failed with an empty message", spec.name)),
    };
    // With events, the page's state log too (a spatial arm's explain panel reads it).
    s.log_states(budget.events);
    s.run_to_end();
    let r = s.result();
    let _ = r.to_json();
    let _ = s.drain_events();
    let states = s.drain_states();
    let _ = s.problem().explain_states(&states);
    if r.solved {
        path_frames(&s, false);
        path_frames(&s, true);
        let written = match io::asv::solution_text(s.problem(), s.planning_path(false)) {
            // With a goal tolerance the path ends in the goal region, not always within a primitive
            // step of the exact goal the course's file must end at: saying so is right. A path
            // with an invalid state is never right.
            Err(e) if s.problem().goal_tolerance > 0.0 && !e.contains("invalid state") => None,
            other => Some(other),
        };
        if let (true, Some(text)) = (s.problem().robot.kind() == "asv", written) {
            let text = text?;
            let configs = io::asv::read_solution(&text)
                .map_err(|e| format!("{}: the solution file written does not read back: {e}", spec.name))?;
            io::asv::check_solution(&s.problem().scenario, &configs)
                .map_err(|e| format!("{}: the solution file written fails the checker: {e}", spec.name))?;
        }
    }
    let wall_s = t0.elapsed().as_secs_f64();
    let report = RunReport {
        planner: spec.name,
        status: s.status(),
        wall_s,
        iterations: r.stats.iterations,
        nodes: r.stats.nodes,
    };
    if report.iterations > budget.iterations {
        return Err(format!(
            "{}: {} iterations past max_iterations {}",
            spec.name, report.iterations, budget.iterations
        ));
    }
    if report.nodes > budget.nodes {
        return Err(format!("{}: {} nodes past max_nodes {}", spec.name, report.nodes, budget.nodes));
    }
    if !report.status.is_finished() {
        return Err(format!("{}: run_to_end returned while still running", spec.name));
    }
    Ok(Some(report))
}

/// What `wasm.rs`'s `Run::path_frames` computes, through the public API: a vehicle chain's
/// primitive steps, else states `FRAME_SPACING` apart (at most 10 000 per motion), each decoded
/// and outlined.
pub fn path_frames(s: &Session, raw: bool) -> usize {
    let p = s.problem();
    let path = s.planning_path(raw);
    let mut floats = 0;
    if p.robot.kind() == "asv" {
        if let Ok(steps) = io::asv::primitive_steps(p, path) {
            for c in &steps {
                floats += c.len();
                if let Ok(internal) = p.robot.encode(c) {
                    floats += outline_len(&*p.robot, &internal);
                }
            }
            return floats;
        }
    }
    let dims = p.si.dims();
    let mut q = vec![0.0; dims];
    for w in path.windows(2) {
        let n = ((p.si.distance(&w[0], &w[1]) / FRAME_SPACING).ceil() as usize).clamp(1, 10_000);
        for i in 0..n {
            p.si.interpolate(&w[0], &w[1], i as f64 / n as f64, &mut q);
            floats += p.robot.decode(&q).len() + outline_len(&*p.robot, &q);
        }
    }
    floats
}

fn outline_len(robot: &dyn Robot, q: &[f64]) -> usize {
    robot.outline(q).iter().map(|poly| 1 + 2 * poly.len()).sum::<usize>() + 1
}

/// The planner names, for reports.
pub fn planner_names() -> Vec<&'static str> {
    planners::names()
}

/// Whether a scenario's robot is a vehicle chain (for reports).
pub fn is_asv(sc: &Scenario) -> bool {
    matches!(sc.robot, RobotSpec::Asv { .. })
}
