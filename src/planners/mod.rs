//! Planners, one per file, and the registry that lists them with their parameters as data.
//!
//! The generic entry is the [`Planner`] trait: a planner is advanced one iteration at a time by
//! the run loop (`run::Session`), which owns limits, timing and batching. Planners see only a
//! [`SpaceInfo`] bundle, a seeded [`Rng`] and the [`EventLog`]: no scenario or robot types.
//! [`REGISTRY`] lists every planner with its [`ParamSpec`]s; the page builds its parameter panel
//! from that list.

pub mod apf;
pub mod caps;
pub mod est;
pub mod grid;
pub mod hex;
pub mod inspection;
mod params;
pub mod roadmap;
pub mod rrt;
pub mod smoothing;
pub mod tree;
pub mod visibility;

pub use crate::params::{ParamGroup, ParamKind, ParamSpec};
pub use params::{condition_problems, Params};
pub use tree::{PlannerData, Tree};

use crate::events::{EventKind, EventLog};
use crate::math::Real;
use crate::rng::Rng;
use crate::sampler::{Draw, Sampler};
use crate::space_info::SpaceInfo;

/// What a planner is asked to solve.
#[derive(Clone, Debug)]
pub struct Task {
    /// Start state.
    pub start: Vec<Real>,
    /// Goal state (absent for an inspection task).
    pub goal: Option<Vec<Real>>,
    /// Distance within which the goal counts as reached (0: exactly).
    pub goal_tolerance: Real,
    /// The points to inspect, for an inspection task.
    pub inspection: Option<InspectionTask>,
}

impl Task {
    /// The goal, for planners that need one (the session refuses goal-less tasks to them).
    pub fn goal(&self) -> &[Real] {
        self.goal.as_deref().expect("the session gives goal planners a goal")
    }
}

/// Points of interest and the sensor that must see them.
#[derive(Clone, Debug)]
pub struct InspectionTask {
    /// Points to see, in the workspace.
    pub points: Vec<crate::math::Vec2>,
    /// Sensor field of view, radians (centred on the sensor's heading).
    pub fov: Real,
    /// Sensor range.
    pub range: Real,
    /// The scenario's coverage target (fraction of points), the default of the planner's own.
    pub coverage: Real,
    /// Count what a branch sees at its vertices only (the Technion handout's `I_i = I_{i−1} ∪
    /// S(v_i)`), not along its edges too.
    pub at_vertices: bool,
    /// A sight line touching an obstacle's boundary hides the point (the course's test).
    pub touch_hides: bool,
}

impl InspectionTask {
    /// The same task counted another way: `at_vertices` and `touch_hides` as given.
    pub fn counted(&self, at_vertices: bool, touch_hides: bool) -> InspectionTask {
        InspectionTask { at_vertices, touch_hides, ..self.clone() }
    }
}

/// What kind of task a planner solves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TaskKind {
    /// Reach the goal.
    Goal,
    /// See the inspection points.
    Inspection,
}

/// What an iteration may touch.
pub struct Context<'a> {
    /// The space bundle.
    pub si: &'a SpaceInfo,
    /// The run's seeded generator.
    pub rng: &'a mut Rng,
    /// Where events go.
    pub events: &'a mut EventLog,
    /// Nodes the planner may still add (the run's node limit, honoured inside an iteration too).
    pub nodes_left: usize,
    /// Bytes the planner may still store ([`crate::limits::MAX_RUN_BYTES`] less
    /// [`Planner::stored_bytes`]): loops that add many things in one iteration (a roadmap's edges)
    /// take from it, and stop when it is spent.
    pub bytes_left: usize,
    /// The run's sampler.
    pub sampler: &'a mut Sampler,
    /// The iteration being run (0 first).
    pub iteration: u64,
}

impl Context<'_> {
    /// Draw a sample for tree `tree` from the run's sampler; `false` when the sampler gave up.
    /// Logs a `Sample` event when it succeeds.
    pub fn sample(&mut self, tree: usize, out: &mut [Real]) -> bool {
        let mut d = Draw { si: self.si, rng: self.rng, events: self.events, tree };
        let ok = self.sampler.sample(&mut d, out);
        if ok {
            let p = self.si.project(out);
            self.events.push(EventKind::Sample, tree, self.sampler.origin(), -1, p, p, out, out);
        }
        ok
    }
    /// Log a growth step's choice: node `near` of tree `tree` (state `from`) grows toward
    /// `target`, at distance `d`; `domain`: the node's dynamic-domain radius (∞: none);
    /// `sample`: whether the target is a sample (not a state of the other tree).
    #[allow(clippy::too_many_arguments)]
    pub fn note_nearest(
        &mut self,
        tree: usize,
        near: u32,
        from: &[Real],
        target: &[Real],
        d: Real,
        domain: Real,
        sample: bool,
    ) {
        if self.events.enabled {
            let (p, t) = (self.si.project(from), self.si.project(target));
            self.events.values(
                EventKind::Nearest,
                tree,
                near as i64,
                -1,
                [p.x, p.y, t.x, t.y, d, domain, sample as u8 as f64, 0.0],
            );
            self.events.attach(from, target, f64::NAN);
        }
    }
    /// Log a growth step's steering: from node `near` (state `from`) a step of `step` (the range
    /// `range`) to the state `new`, which is the target itself when `reached`.
    #[allow(clippy::too_many_arguments)]
    pub fn note_steer(
        &mut self,
        tree: usize,
        near: u32,
        from: &[Real],
        new: &[Real],
        step: Real,
        range: Real,
        reached: bool,
    ) {
        if self.events.enabled {
            let (p, q) = (self.si.project(new), self.si.project(from));
            self.events.values(
                EventKind::Steer,
                tree,
                near as i64,
                -1,
                [p.x, p.y, q.x, q.y, step, range, reached as u8 as f64, 0.0],
            );
            self.events.attach(new, from, f64::NAN);
        }
    }
    /// Log a ladder step from node `near` (state `from`) to `step` after a full step collided:
    /// a `Steer` whose `parent` is the number of coordinates moved and `pc1` the try's number.
    pub fn note_ladder(&mut self, tree: usize, near: u32, from: &[Real], step: &[Real], moved: usize, attempt: u32) {
        if self.events.enabled {
            let (p, q) = (self.si.project(step), self.si.project(from));
            let len = self.si.distance(from, step);
            self.events.values(
                EventKind::Steer,
                tree,
                near as i64,
                moved as i64,
                [p.x, p.y, q.x, q.y, len, len, 0.0, attempt as f64],
            );
            self.events.attach(step, from, f64::NAN);
        }
    }
    /// Log a blocked motion from node `from` (state `a`) toward `b`, found invalid at `at`, with
    /// what blocked it and where ([`SpaceInfo::blocked_at`]).
    pub fn note_collision(&mut self, tree: usize, from: u32, a: &[Real], b: &[Real], at: &[Real]) {
        if self.events.enabled {
            let (why, p) = self.si.blocked_at(a, b, at);
            let pp = self.si.project(a);
            self.events.push(EventKind::Collision, tree, why, from as i64, p, pp, at, a);
        }
    }
}

pub use crate::limits::{bytes_of, nested_bytes};

/// A roadmap's edge counts (the contract's `stats.roadmap`).
#[derive(Clone, Copy, Debug, Default, serde::Serialize, PartialEq, Eq)]
pub struct RoadmapCounts {
    /// Edge motions checked (PRM and PRM*: every candidate edge; Lazy PRM: those a query's path
    /// used).
    pub edges_checked: u64,
    /// Of those, found blocked.
    pub edges_invalid: u64,
    /// Edges in the roadmap: checked valid, or (Lazy PRM) not yet checked.
    pub edges: u64,
}

/// What a bounded batch keeps to go back to ([`Planner::checkpoint`]).
pub enum Checkpoint {
    /// A copy of the whole planner.
    Whole(Box<dyn Planner>),
    /// The planner's own mark, for its [`Planner::rewind`].
    Mark(Box<dyn std::any::Any>),
}

impl Checkpoint {
    /// A copy of `planner` as it stands.
    pub fn copy_of<P: Planner + Clone + 'static>(planner: &P) -> Self {
        Checkpoint::Whole(Box::new(planner.clone()))
    }
}

/// A planner, advanced one iteration at a time.
pub trait Planner {
    /// Run one iteration; `Some(path)` when it found a solution (start first, goal last).
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>>;
    /// What the session keeps at the start of a bounded batch, to go back to when the batch is
    /// suspended (see [`crate::journal`]): a copy of the planner as it stands
    /// ([`Checkpoint::copy_of`]), or, for a planner whose state between iterations only grows,
    /// a mark of itself that it notes changes against and goes back to by
    /// [`rewind`](Self::rewind), far cheaper than a copy of its trees.
    fn checkpoint(&mut self) -> Checkpoint;
    /// Back to the state of this planner's own [`Checkpoint::Mark`], the last it made.
    fn rewind(&mut self, _mark: Box<dyn std::any::Any>) {
        unreachable!("a planner that marks itself rewinds itself")
    }
    /// The batch ended without going back: forget the mark (a planner that marks itself).
    fn release(&mut self) {}
    /// Nodes in all trees.
    fn node_count(&self) -> usize;
    /// Roadmap planners: the edges checked and those in the roadmap (`None` for the others).
    fn roadmap_counts(&self) -> Option<RoadmapCounts> {
        None
    }
    /// The trees, for drawing and checking.
    fn data(&self) -> PlannerData;
    /// For planners that keep improving after a first solution (RRT*, inspection): the best
    /// path so far, which the session returns when a limit stops the run.
    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        None
    }
    /// For inspection planners: the best branch's coverage so far (fraction of points seen).
    fn coverage(&self) -> Option<Real> {
        None
    }
    /// Whether the run must stop at its node limit `max_nodes` before the next iteration, which
    /// would need a node past it. By default, when the planner holds `max_nodes` nodes already:
    /// it has no room for the next. A planner that makes all its nodes when it is set up (a
    /// grid's cells, a visibility graph's vertices; the set-up refuses more than `max_nodes`)
    /// needs no more, and one that adds several at once says so before it would pass the limit.
    fn out_of_nodes(&self, max_nodes: usize) -> bool {
        self.node_count() >= max_nodes
    }
    /// The bytes the planner holds: its trees, roadmap, cells, per-node data, counted from their
    /// lengths (not capacities, so a snapshot holds the same and runs in batches stop where a run
    /// in one go does). The session stops the run at [`crate::limits::MAX_RUN_BYTES`]. Called
    /// before every iteration: it must be quick.
    fn stored_bytes(&self) -> usize;
    /// Whether an iteration stopped adding for want of [`Context::bytes_left`]: the run then stops
    /// at its memory limit too.
    fn out_of_memory(&self) -> bool {
        false
    }
    /// What to change when the run stops at its memory limit (the end of its reason).
    fn memory_advice(&self) -> &'static str {
        "lower max_nodes"
    }
    /// For planners that can conclude "no path" by their method (cell decomposition, potential
    /// fields): why they gave up. The session stops with [`Status::NoPath`](crate::status::Status)
    /// and reports the reason.
    fn gave_up(&self) -> Option<String> {
        None
    }
    /// For planners that keep a roadmap (PRM, PRM*, Lazy PRM): answer another query on it as it
    /// stands, `start` and `goal` being valid planning states; `Some(None)` when the roadmap does
    /// not join them. `None`: this planner keeps nothing a new query could reuse.
    fn query(&mut self, _cx: &mut Context, _start: &[Real], _goal: &[Real]) -> Option<Option<Vec<Vec<Real>>>> {
        None
    }
}

/// How a registered planner is made for a task: the planner, or why it cannot plan for it.
pub type MakePlanner = fn(&SpaceInfo, &Task, &Params) -> Result<Box<dyn Planner>, String>;

/// A registered planner: its name, what it is, its parameters, and how to make one.
pub struct PlannerSpec {
    /// The name used by the CLI, the scenario format and the page.
    pub name: &'static str,
    /// A human title.
    pub label: &'static str,
    /// One line on what it does.
    pub summary: &'static str,
    /// What one of its iterations does (the page's tooltip on its iteration count).
    pub iteration: &'static str,
    /// What its state checks count (the page's tooltip on "Checks").
    pub checks: &'static str,
    /// Its own parameters.
    pub params: &'static [ParamSpec],
    /// The shared groups of parameters it also takes (sampler, tree variants), between its own
    /// and the run parameters. Its own take precedence (a planner may change a default).
    pub groups: &'static [ParamGroup],
    /// The task it solves.
    pub task: TaskKind,
    /// What it can do and shows ([`caps`]).
    pub caps: caps::Capabilities,
    /// Construct it for a task; an error says why it cannot plan for this problem (a robot it
    /// does not handle).
    pub make: MakePlanner,
}

impl PlannerSpec {
    /// Every parameter the planner takes, in lookup order: its own, its groups', the run's.
    pub fn all_params(&self) -> impl Iterator<Item = &'static ParamSpec> + '_ {
        self.params.iter().chain(self.groups.iter().flat_map(|g| g.params.iter())).chain(RUN_PARAMS.iter())
    }
    /// Whether it draws samples from the run's sampler (it takes the sampler's group).
    pub fn samples(&self) -> bool {
        self.groups.iter().any(|g| g.name == crate::sampler::SAMPLER_GROUP.name)
    }
    /// Whether it takes the tree variants (the tree group).
    pub fn tree_variants(&self) -> bool {
        self.groups.iter().any(|g| g.name == tree::TREE_GROUP.name)
    }
    /// The spec of one of its parameters.
    pub fn param(&self, name: &str) -> Option<&'static ParamSpec> {
        self.all_params().find(|p| p.name == name)
    }
}

/// Every planner.
pub static REGISTRY: &[PlannerSpec] = &[
    rrt::rrt::SPEC,
    rrt::rrt_connect::SPEC,
    rrt::rrt_star::SPEC,
    rrt::informed_rrt_star::SPEC,
    roadmap::prm::SPEC,
    roadmap::prm_star::SPEC,
    roadmap::lazy_prm::SPEC,
    est::SPEC,
    est::BI_SPEC,
    inspection::SPEC,
    hex::SPEC,
    grid::SPEC,
    apf::SPEC,
    visibility::SPEC,
];

/// A planner by name.
pub fn find(name: &str) -> Option<&'static PlannerSpec> {
    REGISTRY.iter().find(|p| p.name == name)
}

/// The names of every planner.
pub fn names() -> Vec<&'static str> {
    REGISTRY.iter().map(|p| p.name).collect()
}

/// The planner a scenario's planner block names (`"planner": {"name": ...}`), or the error for the
/// block's `name` key. With [`check_block_params`], the planner side of the block's validation: the
/// scenario parses the block's form and asks here about what only the registry knows.
pub fn block_planner(name: &str) -> Result<&'static PlannerSpec, String> {
    find(name)
        .ok_or_else(|| format!("unknown planner \"{}\" (known: {})", crate::limits::cut(name, 100), names().join(", ")))
}

/// Check a scenario's planner block's parameters (the block without `name` and `seed`) against
/// `spec`'s; an error is `(key, message)`, the key relative to the block.
pub fn check_block_params(
    spec: &'static PlannerSpec,
    params: &serde_json::Map<String, serde_json::Value>,
) -> Result<(), (String, String)> {
    Params::from_json(spec, &serde_json::Value::Object(params.clone())).map(|_| ())
}

/// The registry as JSON (for the page's planner picker and parameter panel).
pub fn registry_json() -> String {
    let list: Vec<serde_json::Value> = REGISTRY
        .iter()
        .map(|p| {
            serde_json::json!({
                "name": p.name, "label": p.label, "summary": p.summary,
                "iteration": p.iteration, "checks": p.checks,
                "params": p.params.iter().map(ParamSpec::to_json).collect::<Vec<_>>(),
                "groups": p.groups.iter().map(|g| serde_json::json!({
                    "name": g.name, "label": g.label,
                    // A planner's own parameter of the same name replaces the group's.
                    "params": g.params.iter().filter(|s| !p.params.iter().any(|o| o.name == s.name)).map(ParamSpec::to_json).collect::<Vec<_>>(),
                })).collect::<Vec<_>>(),
                "task": match p.task { TaskKind::Goal => "goal", TaskKind::Inspection => "inspection" },
                "caps": p.caps.to_json(p.samples(), p.tree_variants()),
            })
        })
        .collect();
    serde_json::to_string(&list).expect("registry serialises")
}

/// Parameters every run loop understands, beside the planner's own: smoothing and limits.
pub static RUN_PARAMS: &[ParamSpec] = &[
    ParamSpec::int(
        "shortcut_attempts",
        "Shortcut attempts",
        0.0,
        10000.0,
        100.0,
        "Random shortcut smoothing attempts on the found path (0: no smoothing).",
    ),
    ParamSpec::real("time_limit", "Time limit (s)", 0.01, 3600.0, 30.0, "Stop after this much planning time."),
    ParamSpec::int("max_iterations", "Iteration limit", 1.0, 1e9, 1e7, "Stop after this many iterations."),
    ParamSpec::int(
        "max_nodes",
        "Node limit",
        2.0,
        crate::limits::MAX_NODES,
        1e6,
        "Stop when the trees hold this many nodes (at most a million: see docs/limits.md).",
    ),
];
