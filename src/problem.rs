//! A planning problem: a scenario turned into a workspace, a robot, a space, a start and a goal.

use crate::geometry::solid::Solid;
use crate::geometry::{Aabb, Shape, Workspace};
use crate::limits;
use crate::math::{Real, Vec2};
use crate::robot::{self, Robot, Verdict};
use crate::scenario::{ObstacleSpec, Scenario, ScenarioError, SolidShape};
use crate::space_info::SpaceInfo;
use crate::validity::RobotInWorkspace;
use std::rc::Rc;

/// Everything a planner run needs.
pub struct Problem {
    /// The scenario the problem came from.
    pub scenario: Scenario,
    /// Space, validity and motion checking.
    pub si: SpaceInfo,
    /// The robot (for outlines and for turning planning states back into scenario states): the
    /// same instance the validity checker uses, so state it learns (a chain's winding) is shared.
    pub robot: Rc<dyn Robot>,
    /// Start state (canonical).
    pub start: Vec<Real>,
    /// Goal state (canonical), if the task has one.
    pub goal: Option<Vec<Real>>,
    /// Distance within which the goal counts as reached.
    pub goal_tolerance: Real,
}

/// An obstacle of the scenario as a shape.
pub fn shape_of(o: &ObstacleSpec) -> Shape {
    match o {
        ObstacleSpec::Rect(r) => Shape::Rect(Aabb::of_points(&[Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3])])),
        ObstacleSpec::Polygon(p) => Shape::Polygon(p.iter().map(|q| Vec2::new(q[0], q[1])).collect()),
        ObstacleSpec::Circle(c) => Shape::Circle(Vec2::new(c[0], c[1]), c[2]),
        ObstacleSpec::Segment(s) => Shape::Segment(Vec2::new(s[0], s[1]), Vec2::new(s[2], s[3])),
    }
}

/// The scenario's 3-D obstacles as solids; an error names a hull parry cannot build.
fn solids_of(sc: &Scenario) -> Result<Vec<Solid>, ScenarioError> {
    sc.obstacles3d
        .iter()
        .enumerate()
        .map(|(i, o)| match &o.shape {
            SolidShape::Box { center, size } => Ok(Solid::cuboid(&o.name, *center, *size)),
            SolidShape::Hull(pts) => {
                Solid::hull(&o.name, pts).map_err(|e| ScenarioError::at(format!("obstacles3d[{i}].hull"), e))
            }
        })
        .collect()
}

fn obstacle_kind(o: &ObstacleSpec) -> &'static str {
    match o {
        ObstacleSpec::Rect(_) => "rect",
        ObstacleSpec::Polygon(_) => "polygon",
        ObstacleSpec::Circle(_) => "circle",
        ObstacleSpec::Segment(_) => "segment",
    }
}

/// Refuse a resolution (a vehicle chain's `max_step`) so fine that the longest motion would be
/// checked in more than [`limits::MAX_MOTION_STEPS`] states: such a motion check would take
/// minutes, and its step count would not fit the buffers that hold it.
fn check_resolution(sc: &Scenario, space: &crate::space::StateSpace) -> Result<(), ScenarioError> {
    let b = sc.bounds;
    let diagonal = ((b[2] - b[0]).powi(2) + (b[3] - b[1]).powi(2)).sqrt();
    let mut checks = vec![("resolution", space.max_extent(), sc.resolution)];
    if let crate::scenario::RobotSpec::Asv { count, broom, max_step, .. } = &sc.robot {
        // No vehicle moves farther than the centroid does plus its distance to the centroid at
        // either end (at most the whole chain's length each).
        checks.push(("robot.max_step", diagonal + 2.0 * *count as Real * broom, *max_step));
    }
    for (path, extent, step) in checks {
        let n = extent / step;
        if n.is_nan() || n > limits::MAX_MOTION_STEPS {
            return Err(ScenarioError::at(
                path,
                format!(
                    "{step:e} is too fine: the longest motion in this robot's space measures {extent:.6e} (in its metric), which would be checked in {n:.3e} states; the limit is {:e}, so it must be at least {:.3e}",
                    limits::MAX_MOTION_STEPS,
                    extent / limits::MAX_MOTION_STEPS
                ),
            ));
        }
    }
    Ok(())
}

/// A start or goal state `q` (scenario form) as a planning state: the robot's dimension, in
/// bounds, collision-free; errors name the state (`name`) and why.
fn check_state(
    robot: &dyn Robot,
    space: &crate::space::StateSpace,
    workspace: &Workspace,
    sc: &Scenario,
    name: &str,
    q: &[Real],
) -> Result<Vec<Real>, ScenarioError> {
    let dims = robot.external_dims();
    if q.len() != dims {
        return Err(ScenarioError::at(
            name,
            format!(
                "{} {} robot's state has {dims} numbers, found {}",
                if robot.kind().starts_with('a') { "an" } else { "a" },
                robot.kind(),
                q.len()
            ),
        ));
    }
    let mut q = robot.encode(q).map_err(|e| ScenarioError::at(name, e))?;
    space.enforce(&mut q);
    match robot.verdict(workspace, &q) {
        Verdict::Valid => Ok(q),
        Verdict::Invalid(why) => Err(ScenarioError::at(
            name,
            match robot.describe_collision(workspace, &q) {
                Some(what) => format!("{why}: {what}"),
                None => why.to_string(),
            },
        )),
        Verdict::OutOfBounds(d) => {
            let axis = ["x", "y"][d.min(1)];
            let b = sc.bounds;
            let (lo, hi) = if d == 0 { (b[0], b[2]) } else { (b[1], b[3]) };
            Err(ScenarioError::at(name, format!("out of bounds: {axis} must stay within [{lo}, {hi}]")))
        }
        Verdict::Collision(i) if !sc.obstacles3d.is_empty() => {
            let named = &sc.obstacles3d[i].name;
            let what = if named.is_empty() { String::new() } else { format!(", the {named}") };
            let why = robot.describe_collision(workspace, &q).unwrap_or_default();
            Err(ScenarioError::at(name, format!("in collision with obstacles3d[{i}]{what}: {why}")))
        }
        Verdict::Collision(i) => Err(ScenarioError::at(
            name,
            format!("in collision with obstacles[{i}] (a {})", obstacle_kind(&sc.obstacles[i])),
        )),
    }
}

impl Problem {
    /// Another start or goal for this problem (a roadmap's further query): checked as the
    /// scenario's own are, against this problem's robot and workspace (nothing is rebuilt).
    pub fn check_state(&self, name: &str, q: &[Real]) -> Result<Vec<Real>, ScenarioError> {
        check_state(self.robot.as_ref(), &self.si.space, self.si.workspace(), &self.scenario, name, q)
    }

    /// The configurations a last-free connect (the Robotics Library's, in report 001's course)
    /// from `from` toward `target` tests, in order, the first `count` of them (at most
    /// [`MAX_LAST_FREE_STEPS`](crate::planners::tree::MAX_LAST_FREE_STEPS)): the connect's own
    /// schedule ([`LastFreeSteps`](crate::planners::tree::LastFreeSteps)) by the resolution, so the
    /// explain panel steps through the very configurations the planner checked, bit for bit. Empty
    /// when `from` is `target`.
    pub fn connect_configs(&self, from: &[Real], target: &[Real], count: usize) -> Vec<Vec<Real>> {
        use crate::planners::tree::{LastFreeSteps, MAX_LAST_FREE_STEPS};
        let d = self.si.distance(from, target);
        if from.len() != target.len() || d.is_nan() || d <= 0.0 {
            return Vec::new();
        }
        let mut q = vec![0.0; from.len()];
        LastFreeSteps::new(d, self.si.resolution)
            .take(count.min(MAX_LAST_FREE_STEPS))
            .map(|(step, _)| {
                self.si.interpolate(from, target, step / d, &mut q);
                q.clone()
            })
            .collect()
    }

    /// The trees as a spatial arm's tool sweeps them, from a run's node log
    /// ([`crate::run::Session::drain_nodes`]): per node, flat, `[tree, id, n, x, y, z, …]`: the
    /// tool centre point at `n` states of the straight motion from its parent, evenly spread, both
    /// ends kept ([`Spatial::tool_sweep`](crate::robot::Spatial::tool_sweep)): as many as the
    /// motion has `resolution` steps and its end, at most [`limits::MAX_TOOL_POINTS_PER_EDGE`]; a
    /// root (no parent) is its one point. Empty for other robots.
    pub fn tool_tree(&self, log: &crate::events::NodeLog) -> Vec<Real> {
        let Some(sp) = self.robot.spatial() else { return Vec::new() };
        let (dims, stride) = (log.dims, log.stride());
        let mut delta = vec![0.0; dims];
        let mut out = Vec::new();
        for e in log.data.chunks_exact(stride) {
            let (q, pq) = (&e[4..4 + dims], &e[4 + dims..]);
            let steps = if e[3] < 0.0 {
                None
            } else {
                limits::steps(self.si.distance(pq, q), self.si.resolution, limits::MAX_MOTION_STEPS)
            };
            let pts = match steps {
                Some(n) => {
                    self.si.space.difference(pq, q, &mut delta);
                    sp.tool_sweep(pq, &delta, (n + 1).min(limits::MAX_TOOL_POINTS_PER_EDGE))
                }
                None => vec![sp.tool_point(q)],
            };
            out.extend_from_slice(&[e[1], e[2], pts.len() as Real]);
            for p in &pts {
                out.extend_from_slice(p);
            }
        }
        out
    }

    /// A run's state log ([`crate::run::Session::drain_states`]) in scenario states, flat: `[dims,
    /// then per entry kind, extra, q…, pq…]` (`dims` numbers a state; states the log could not
    /// give are NaN), for an explain panel. Empty when the log is empty.
    pub fn explain_states(&self, log: &crate::events::StateLog) -> Vec<Real> {
        let (dims, stride) = (log.dims, log.stride());
        if log.data.is_empty() || dims == 0 {
            return Vec::new();
        }
        let ext = self.robot.external_dims();
        let mut out = Vec::with_capacity(1 + log.data.len() / stride * (2 + 2 * ext));
        out.push(ext as Real);
        for e in log.data.chunks_exact(stride) {
            out.extend_from_slice(&e[1..3]);
            for q in [&e[3..3 + dims], &e[3 + dims..]] {
                let x = if q.iter().all(|v| v.is_finite()) { self.robot.decode(q) } else { Vec::new() };
                if x.len() == ext {
                    out.extend_from_slice(&x);
                } else {
                    out.resize(out.len() + ext, Real::NAN);
                }
            }
        }
        out
    }

    /// A planning path as scenario states.
    pub fn decode_path(&self, path: &[Vec<Real>]) -> Vec<Vec<Real>> {
        path.iter().map(|q| self.robot.decode(q)).collect()
    }

    /// Build the problem, checking the planner block against the registry, and that start and goal
    /// have the robot's dimension, lie in bounds and are collision-free; errors say which key or
    /// state and why.
    pub fn from_scenario(sc: &Scenario) -> Result<Problem, ScenarioError> {
        check_planner_block(sc)?;
        let b = sc.bounds;
        let mut workspace = Workspace::new(
            Aabb { min: Vec2::new(b[0], b[1]), max: Vec2::new(b[2], b[3]) },
            sc.obstacles.iter().map(shape_of).collect(),
        );
        workspace.touching_allowed = sc.touching_allowed;
        workspace.map_grid = sc.map.as_ref().map(|m| (Vec2::new(m.origin[0], m.origin[1]), m.resolution));
        workspace.solids = solids_of(sc)?;
        let robot: Rc<dyn Robot> =
            robot::from_spec(&sc.robot, sc.body_in_bounds).map_err(|e| ScenarioError::at("robot.kind", e))?.into();
        let space = robot.space(&workspace);
        check_resolution(sc, &space)?;
        let check = |name: &str, q: &[Real]| check_state(robot.as_ref(), &space, &workspace, sc, name, q);
        let start = check("start", &sc.start)?;
        let goal = sc.goal.as_deref().map(|g| check("goal", g)).transpose()?;
        let validity = RobotInWorkspace { robot: Rc::clone(&robot), workspace };
        Ok(Problem {
            robot,
            scenario: sc.clone(),
            si: SpaceInfo::new(space, validity, sc.resolution),
            start,
            goal,
            goal_tolerance: sc.goal_tolerance,
        })
    }
}

/// The scenario's planner block against the registry: a planner it has, parameters that planner
/// takes with values in range; an error names the block's key (`planner.name`, `planner.range`).
/// The scenario parses the block's shape; what only the registry knows is checked here, above the
/// planners, so the scenario module does not depend on them.
fn check_planner_block(sc: &Scenario) -> Result<(), ScenarioError> {
    let Some(block) = &sc.planner else { return Ok(()) };
    let spec = crate::planners::block_planner(&block.name).map_err(|msg| ScenarioError::at("planner.name", msg))?;
    crate::planners::check_block_params(spec, &block.params)
        .map_err(|(key, msg)| ScenarioError::at(crate::scenario::join("planner", &key), msg))
}
