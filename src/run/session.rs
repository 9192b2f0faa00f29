use crate::clock::Instant;
use crate::events::EventLog;
use crate::limits::MAX_RUN_BYTES;
use crate::math::Real;
use crate::planners::{
    self, smoothing, Checkpoint, Context, InspectionTask, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind,
};
use crate::problem::Problem;
use crate::rng::Rng;
use crate::sampler::Sampler;
use crate::space_info::Deadline;
use crate::status::Status;

mod report;
/// What to run: a planner by name, its parameters (which include smoothing and limits), a seed.
#[derive(Clone, Debug)]
pub struct RunConfig {
    /// Planner name from the registry.
    pub planner: String,
    /// Parameters (checked against the planner's specs).
    pub params: Params,
    /// Seed of the run's generator.
    pub seed: u64,
    /// Whether to record events (off for benchmarks).
    pub record_events: bool,
}

/// Seed offset of the smoothing generator, so the tree does not depend on smoothing.
const SMOOTHING_STREAM: u64 = 0x5EED_5A00_7415_0001;

/// A bounded batch is suspended (its iteration thrown away and done again in the next batch, see
/// [`crate::journal`]) once it has run this many times its budget: a batch asked for 12 ms ends
/// within about 24 ms plus one state check, whatever one iteration costs.
pub const SUSPEND_AFTER: f64 = 2.0;

/// A bounded batch goes without a snapshot (so it cannot be suspended) when taking one would cost
/// more than this share of its budget, unless the run's batches have been overrunning.
pub const MAX_SNAPSHOT_SHARE: f64 = 0.1;

/// After a bounded batch overruns (or is suspended), this many more take snapshots whatever they
/// cost: a run whose iterations are sometimes slow keeps the means to suspend them for a while.
pub const RISKY_BATCHES: u32 = 64;

/// What a bounded batch changes, kept at its start to go back to when it is suspended.
struct Snapshot {
    planner: Checkpoint,
    rng: Rng,
    sampler: Sampler,
    events: usize,
    iterations: u64,
    checks: u64,
    free_checks: u64,
}

/// The run's limits, read from its parameters once (they are checked before every iteration).
#[derive(Clone, Copy, Debug)]
struct Limits {
    time_ms: f64,
    iterations: u64,
    nodes: usize,
}

/// The answer to [`Session::query`]: empty when the roadmap does not join the two states.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct QueryAnswer {
    /// The path in scenario states, start first.
    pub path: Vec<Vec<Real>>,
    /// Its states' projected points (what the page draws).
    pub points: Vec<[Real; 2]>,
    /// Its cost in the robot's metric (0 when empty).
    pub cost: Real,
}

/// One planning run, advanced in bounded batches.
pub struct Session {
    problem: Problem,
    spec: &'static PlannerSpec,
    config: RunConfig,
    planner: Box<dyn Planner>,
    limits: Limits,
    sampler: Sampler,
    task: Task,
    rng: Rng,
    events: EventLog,
    status: Status,
    iterations: u64,
    elapsed_ms: f64,
    smoothing_ms: f64,
    /// Time smoothing spent in bounded batches that were then suspended (their smoothing is done
    /// again, its checks answered from the journal): counted in the smoothing time that is shown.
    smoothing_tried_ms: f64,
    /// State checks spent planning, all and free, frozen when solved (smoothing's checks are not
    /// the planner's).
    planning_checks: Option<(u64, u64)>,
    path: Vec<Vec<Real>>,
    smoothed: Vec<Vec<Real>>,
    /// Why the planner gave up, when it did.
    reason: Option<String>,
    /// Motions of the raw path replaced by a detour when it was certified (see `certify.rs`).
    repaired: Option<usize>,
    /// Bounded batches suspended so far.
    suspensions: u64,
    /// What the last snapshot cost a node, and how many more bounded batches take one whatever it
    /// costs (see [`RISKY_BATCHES`]).
    snapshot_ms_per_node: f64,
    risky: u32,
    /// Iterations between two looks at the clock in a batch.
    look_every: u64,
}

impl Session {
    /// A run of `config` on `problem`. Errors name an unknown planner or a task it cannot do.
    pub fn new(problem: Problem, mut config: RunConfig) -> Result<Session, String> {
        let spec = planners::find(&config.planner).ok_or_else(|| {
            format!(
                "unknown planner \"{}\" (known: {})",
                crate::limits::cut(&config.planner, 100),
                planners::names().join(", ")
            )
        })?;
        // Re-check the values against this planner, so its own defaults apply.
        config.params = Params::from_json(spec, &serde_json::Value::Object(config.params.values().clone()))
            .map_err(|(k, e)| format!("{k}: {e}"))?;
        let inspection = problem.scenario.inspection.as_ref().map(|i| InspectionTask {
            points: i.points.iter().map(|p| crate::math::Vec2::new(p[0], p[1])).collect(),
            fov: i.fov,
            range: i.range,
            coverage: i.coverage,
            at_vertices: i.at_vertices(),
            touch_hides: i.touch_hides,
        });
        match spec.task {
            TaskKind::Goal if problem.goal.is_none() => {
                return Err(format!("{} needs a goal; this scenario has none", spec.label))
            }
            TaskKind::Inspection if inspection.is_none() => {
                return Err(format!("{} needs inspection points; this scenario has none", spec.label))
            }
            _ => {}
        }
        let task = Task {
            start: problem.start.clone(),
            goal: problem.goal.clone(),
            goal_tolerance: problem.goal_tolerance,
            inspection,
        };
        problem.si.reset_checks();
        let p = &config.params;
        let limits = Limits {
            time_ms: p.real("time_limit") * 1000.0,
            iterations: p.real("max_iterations") as u64,
            nodes: p.real("max_nodes") as usize,
        };
        // Setting a planner up may be long work too (a decomposition's tiling, a visibility graph's
        // growth): it is planning time, under the same time limit, and counted in the run's time.
        let setup = Instant::now();
        // Exact tests counted before (building the problem) are not this run's work.
        crate::geometry::take_tests();
        problem.si.set_deadline(Deadline::in_ms(limits.time_ms));
        let planner = (spec.make)(&problem.si, &task, &config.params).map_err(|e| format!("{}: {e}", spec.label))?;
        // The set-up's exact tests are its own work, not the first iteration's.
        crate::clock::work(crate::geometry::take_tests() / 16);
        problem.si.look_again_soon();
        let setup_ms = setup.elapsed().as_secs_f64() * 1000.0;
        let sampler = Sampler::from_params(&problem.si, task.goal.as_deref(), &config.params);
        Ok(Session {
            limits,
            sampler,
            task,
            rng: Rng::new(config.seed),
            events: EventLog::new(config.record_events),
            problem,
            spec,
            config,
            planner,
            status: Status::Running,
            iterations: 0,
            elapsed_ms: setup_ms,
            smoothing_ms: 0.0,
            smoothing_tried_ms: 0.0,
            planning_checks: None,
            path: Vec::new(),
            smoothed: Vec::new(),
            reason: None,
            repaired: None,
            suspensions: 0,
            snapshot_ms_per_node: 0.0,
            risky: 0,
            // From every iteration: the first batch learns how long iterations take.
            look_every: 1,
        })
    }

    /// The problem being solved.
    pub fn problem(&self) -> &Problem {
        &self.problem
    }
    /// How the run stands.
    pub fn status(&self) -> Status {
        self.status
    }
    /// The planner's trees.
    pub fn planner_data(&self) -> PlannerData {
        self.planner.data()
    }

    fn limits_status(&self) -> Option<Status> {
        let l = &self.limits;
        if self.elapsed_ms >= l.time_ms || self.problem.si.interrupted() {
            Some(Status::TimeLimit)
        } else if self.iterations >= l.iterations {
            Some(Status::IterationLimit)
        } else if self.planner.out_of_nodes(l.nodes) {
            Some(Status::NodeLimit)
        } else if self.planner.out_of_memory() || self.planner.stored_bytes() > MAX_RUN_BYTES {
            Some(Status::MemoryLimit)
        } else {
            None
        }
    }

    /// The bytes the planner may still store (see [`Context::bytes_left`]).
    fn bytes_left(&self) -> usize {
        MAX_RUN_BYTES.saturating_sub(self.planner.stored_bytes())
    }

    /// Run at most `max_iterations` iterations, for at most about `max_ms` milliseconds, and return
    /// the status. Limits are checked before every iteration; time spent outside `step` (paused)
    /// does not count.
    ///
    /// A finite `max_ms` makes the batch *bounded*: however long one iteration would take, the
    /// batch ends within about `SUSPEND_AFTER` × `max_ms` (plus one state check). An iteration
    /// still running then is thrown away and done again by the next batch, which replays the
    /// answers already computed ([`crate::journal`]), so the run is the same as in one go, bit
    /// for bit, only its iteration count lags until the iteration completes.
    ///
    /// The exception: a batch whose snapshot would cost more than `MAX_SNAPSHOT_SHARE` of its
    /// budget (a tree of some 20,000 nodes for 12 ms) is run without one while the run's batches
    /// keep to their budget; one that overruns makes the next `RISKY_BATCHES` take snapshots.
    pub fn step(&mut self, max_iterations: u64, max_ms: f64) -> Status {
        if self.status.is_finished() {
            return self.status;
        }
        if !max_ms.is_finite() {
            return self.run_batch(max_iterations, max_ms);
        }
        let begin = Instant::now();
        // A copy costs about 60 ns a node (a mark next to nothing): a big tree's copy (17 ms at
        // 300,000 nodes) is taken only when this run's batches have been overrunning.
        let nodes = self.planner.node_count().max(1) as f64;
        if self.risky == 0 && self.snapshot_ms_per_node * nodes > max_ms * MAX_SNAPSHOT_SHARE {
            let status = self.run_batch(max_iterations, max_ms);
            if begin.elapsed().as_secs_f64() * 1000.0 > max_ms * SUSPEND_AFTER {
                self.risky = RISKY_BATCHES;
            }
            return status;
        }
        let kept = Snapshot {
            planner: self.planner.checkpoint(),
            rng: self.rng.clone(),
            sampler: self.sampler.clone(),
            events: self.events.len(),
            iterations: self.iterations,
            checks: self.problem.si.checks(),
            free_checks: self.problem.si.free_checks(),
        };
        let took = begin.elapsed().as_secs_f64() * 1000.0;
        self.snapshot_ms_per_node = took / nodes;
        self.problem.si.begin_batch(Deadline::in_ms(max_ms.max(0.0) * SUSPEND_AFTER - took));
        let status = self.run_batch(max_iterations, max_ms);
        let suspended = self.problem.si.end_batch();
        self.risky = if suspended || begin.elapsed().as_secs_f64() * 1000.0 > max_ms * SUSPEND_AFTER {
            RISKY_BATCHES
        } else {
            self.risky.saturating_sub(1)
        };
        if suspended {
            // Back to the batch's start; the next batch replays it from the journal.
            match kept.planner {
                Checkpoint::Whole(planner) => self.planner = planner,
                Checkpoint::Mark(mark) => self.planner.rewind(mark),
            }
            self.rng = kept.rng;
            self.sampler = kept.sampler;
            self.events.truncate(kept.events);
            self.iterations = kept.iterations;
            self.problem.si.set_checks(kept.checks, kept.free_checks);
            self.status = Status::Running;
            self.planning_checks = None;
            self.path.clear();
            self.smoothed.clear();
            self.smoothing_tried_ms += self.smoothing_ms;
            self.smoothing_ms = 0.0;
            self.reason = None;
            self.repaired = None;
            self.suspensions += 1;
            return self.status;
        }
        if let Checkpoint::Mark(_) = kept.planner {
            self.planner.release();
        }
        status
    }

    /// Bounded batches suspended so far (each one's iteration was done again in the next batch).
    pub fn suspensions(&self) -> u64 {
        self.suspensions
    }

    fn run_batch(&mut self, max_iterations: u64, max_ms: f64) -> Status {
        let begin = Instant::now();
        let base = self.elapsed_ms;
        // The time limit also holds inside an iteration's long loops (and smoothing after it).
        self.problem.si.set_deadline(Deadline::in_ms(self.limits.time_ms - base));
        let mut done = 0;
        let (mut last_look, mut at16) = (0.0, 0.0);
        while done < max_iterations {
            if let Some(s) = self.limits_status() {
                self.stop(s);
                break;
            }
            let nodes_left = self.limits.nodes.saturating_sub(self.planner.node_count());
            let bytes_left = self.bytes_left();
            let mut cx = Context {
                si: &self.problem.si,
                rng: &mut self.rng,
                events: &mut self.events,
                nodes_left,
                bytes_left,
                sampler: &mut self.sampler,
                iteration: self.iterations,
            };
            let found = self.planner.iterate(&mut cx);
            if crate::clock::is_simulated() {
                // A simulated clock (tests) also moves on for the planner's own work between
                // questions: one unit, and one per 16 exact tests not counted by a question.
                crate::clock::iteration_done(1 + crate::geometry::take_tests() / 16);
            }
            self.iterations += 1;
            done += 1;
            if self.problem.si.suspended() && !self.problem.si.interrupted() {
                // Thrown away by `step`, which goes back to the batch's start.
                self.elapsed_ms = base + begin.elapsed().as_secs_f64() * 1000.0;
                return self.status;
            }
            if self.problem.si.interrupted() {
                // The deadline cut the iteration short: whatever it found was checked in full
                // (a refused motion is never part of a path), but the run is out of time.
                self.elapsed_ms = base + begin.elapsed().as_secs_f64() * 1000.0;
                match found {
                    Some(path) => self.finish_solved(path),
                    None => self.stop(Status::TimeLimit),
                }
                return self.status;
            }
            if let Some(path) = found {
                self.elapsed_ms = base + begin.elapsed().as_secs_f64() * 1000.0;
                self.finish_solved(path);
                return self.status;
            }
            if let Some(why) = self.planner.gave_up() {
                self.elapsed_ms = base + begin.elapsed().as_secs_f64() * 1000.0;
                self.reason = Some(why);
                self.status = Status::NoPath;
                return self.status;
            }
            // Reading the clock costs more than a cheap iteration: look every 16, or after every
            // iteration once 16 of them took more than an eighth of a batch (so a batch of slow
            // iterations overshoots by one iteration, not by fifteen), until 16 take less than
            // a hundredth of one again. (Kept from batch to batch.)
            if done % self.look_every == 0 {
                let spent = begin.elapsed().as_secs_f64() * 1000.0;
                self.elapsed_ms = base + spent;
                if spent - last_look > max_ms / 8.0 {
                    self.look_every = 1;
                } else if self.look_every == 1 && done % 16 == 0 && spent - at16 < max_ms / 100.0 {
                    self.look_every = 16;
                }
                if done % 16 == 0 {
                    at16 = spent;
                }
                last_look = spent;
                if spent >= max_ms {
                    break;
                }
            }
        }
        self.elapsed_ms = base + begin.elapsed().as_secs_f64() * 1000.0;
        if self.status == Status::Running {
            if let Some(s) = self.limits_status() {
                self.stop(s);
            }
        }
        self.status
    }

    /// A limit was reached: an anytime planner's best path so far still solves the task.
    fn stop(&mut self, limit: Status) {
        match self.planner.best_so_far() {
            Some(path) => self.finish_solved(path),
            None => {
                self.status = limit;
                if limit == Status::MemoryLimit {
                    self.reason = Some(self.memory_reason());
                }
            }
        }
    }

    /// Why a run stopped at its memory limit, and what to change.
    fn memory_reason(&self) -> String {
        format!(
            "the planner holds {:.0} MB for its {} nodes{}, as much as a run may hold ({:.0} MB): {}",
            self.planner.stored_bytes() as f64 / 1e6,
            self.planner.node_count(),
            if self.planner.out_of_memory() { " and their edges" } else { "" },
            MAX_RUN_BYTES as f64 / 1e6,
            self.planner.memory_advice()
        )
    }

    fn finish_solved(&mut self, path: Vec<Vec<Real>>) {
        self.planning_checks = Some((self.problem.si.checks(), self.problem.si.free_checks()));
        let t = Instant::now();
        let mut rng = Rng::new(self.config.seed ^ SMOOTHING_STREAM);
        // A path whose motions were tested only at their configurations is certified first.
        let path = if self.problem.si.motion_model().walks_by_states() {
            match super::certify::certify(&self.problem, &path, &mut rng) {
                Ok(c) => {
                    self.repaired = Some(c.repaired);
                    c.path
                }
                Err(reason) => {
                    self.status = Status::NoPath;
                    self.reason = Some(reason);
                    return;
                }
            }
        } else {
            path
        };
        let attempts = self.config.params.real("shortcut_attempts") as usize;
        // An inspection path's detours are what it is for: only shortcuts that keep every point
        // it sees are taken.
        self.smoothed = match (&self.task.inspection, self.spec.task) {
            (Some(i), TaskKind::Inspection) => {
                planners::inspection::shortcut(&self.problem.si, i, &path, attempts, &mut rng)
            }
            _ => smoothing::shortcut(&self.problem.si, &path, attempts, &mut rng),
        };
        self.smoothing_ms = std::mem::take(&mut self.smoothing_tried_ms) + t.elapsed().as_secs_f64() * 1000.0;
        self.path = path;
        self.status = Status::Solved;
    }

    /// The path found, in planning states (`raw`: as the planner returned it; else smoothed).
    pub fn planning_path(&self, raw: bool) -> &[Vec<Real>] {
        if raw {
            &self.path
        } else {
            &self.smoothed
        }
    }

    /// Record events from now on, or not (benchmarks: nothing to draw, no time spent on it).
    /// Turning it off drops the events waiting.
    pub fn set_record_events(&mut self, on: bool) {
        self.events.enabled = on;
        if !on {
            self.events.drain();
            self.events.drain_states();
        }
    }

    /// Stop the run now.
    pub fn cancel(&mut self) {
        if !self.status.is_finished() {
            self.status = Status::Cancelled;
        }
    }

    /// Another query on a finished run's roadmap (PRM, PRM*, Lazy PRM): `start` and `goal` are
    /// scenario states, checked as the scenario's own are (errors name `start` or `goal`). The
    /// planner joins them to the roadmap as it stands and searches it; events are recorded as in
    /// the run. The answer: the path in scenario states (empty when the roadmap does not join
    /// them), its projected points and its cost in the robot's metric. The run's own path and
    /// status are kept.
    pub fn query(&mut self, start: &[Real], goal: &[Real]) -> Result<QueryAnswer, String> {
        if !self.status.is_finished() {
            return Err("the run has not finished: a roadmap is queried once it is built".into());
        }
        let start_q = self.problem.check_state("start", start).map_err(|e| e.to_string())?;
        let goal_q = self.problem.check_state("goal", goal).map_err(|e| e.to_string())?;
        self.problem.si.set_deadline(Deadline::in_ms(self.limits.time_ms));
        let nodes_left = self.limits.nodes.saturating_sub(self.planner.node_count());
        let bytes_left = self.bytes_left();
        let mut cx = Context {
            si: &self.problem.si,
            rng: &mut self.rng,
            events: &mut self.events,
            nodes_left,
            bytes_left,
            sampler: &mut self.sampler,
            iteration: self.iterations,
        };
        let answer = self.planner.query(&mut cx, &start_q, &goal_q);
        let interrupted = self.problem.si.interrupted();
        self.problem.si.set_deadline(Deadline::NONE);
        match answer {
            None => Err(format!("{} keeps no roadmap to query", self.spec.label)),
            Some(_) if interrupted => Err("the query ran out of the run's time limit".into()),
            Some(None) => Ok(QueryAnswer::default()),
            Some(Some(path)) => Ok(QueryAnswer {
                cost: smoothing::path_cost(&self.problem.si, &path),
                points: path.iter().map(|q| self.problem.si.project(q)).map(|p| [p.x, p.y]).collect(),
                path: self.problem.decode_path(&path),
            }),
        }
    }

    /// Run until solved or a limit is reached.
    pub fn run_to_end(&mut self) -> Status {
        while !self.step(u64::MAX, f64::INFINITY).is_finished() {}
        self.status
    }

    /// Take the events recorded since the last drain (flat records, see [`crate::events`]).
    pub fn drain_events(&mut self) -> Vec<f64> {
        self.events.drain()
    }

    /// Keep every added node's full state and its parent's from now on, or not (a 3-D view draws
    /// the tree at the spatial arm's tool: [`Problem::tool_tree`]). Drawing only: the run is the same.
    pub fn log_nodes(&mut self, on: bool) {
        self.events.log_nodes(if on { self.problem.si.dims() } else { 0 });
    }

    /// Keep the full states of the records a growth step is explained by from now on, or not
    /// ([`crate::events::StateLog`]; an explain panel for a robot of more than two coordinates).
    /// Explaining only: the run is the same.
    pub fn log_states(&mut self, on: bool) {
        self.events.log_states(if on { self.problem.si.dims() } else { 0 });
    }

    /// Take the state log since the last call (see [`log_states`](Session::log_states)).
    pub fn drain_states(&mut self) -> crate::events::StateLog {
        self.events.drain_states()
    }

    /// Take the node log since the last call (see [`log_nodes`](Session::log_nodes)).
    pub fn drain_nodes(&mut self) -> crate::events::NodeLog {
        self.events.drain_nodes()
    }
}
