//! The ASV course's problem and solution files (the vehicle-chain course, `docs/sources.md`).
//!
//! - [`import_problem`] reads a problem file (vehicle count, initial and goal positions, obstacle
//!   rectangles as four corners each) into a scenario with the course's settings.
//! - [`solution_text`] writes a planned path as the course's solution file: every motion cut into
//!   primitive steps in which no vehicle moves more than `max_step` (exactly the states the planner
//!   checked), first and last line the problem's own initial and goal positions.
//! - [`read_solution`] reads a solution file back, and [`check_solution`] re-checks it against the
//!   course's rules, independently of the robot's code (positions, not planning states; the
//!   course's own turning-angle test of convexity; parametric clipping against the rectangles).

mod check;

pub use check::{check_configuration, check_solution, max_move, path_cost};

use crate::math::Real;
use crate::problem::Problem;
use crate::scenario::{ObstacleSpec, PlannerDefaults, RobotSpec, Scenario, ScenarioError, FORMAT};

/// The course's tolerance `e` on every rule.
pub const TOLERANCE: Real = 1e-5;
/// The course's broom length.
pub const BROOM: Real = 0.05;
/// The course's primitive step: the most any vehicle moves between two configurations.
pub const MAX_STEP: Real = 0.001;

/// The smallest area the course allows a chain of `n` vehicles: `π·(0.007·(n−1))²`.
pub fn min_area(n: usize) -> Real {
    std::f64::consts::PI * (0.007 * (n as Real - 1.0)).powi(2)
}

/// An error at a line and column (both 1-based) of a text file.
fn at(line: usize, column: usize, message: impl Into<String>) -> ScenarioError {
    ScenarioError::new(String::new(), message, Some(line), Some(column))
}

/// The whitespace-separated words of a line with their 1-based columns.
fn words(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, ch) in line.char_indices().chain(std::iter::once((line.len(), ' '))) {
        match (ch.is_whitespace(), start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                out.push((line[..s].chars().count() + 1, &line[s..i]));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// A line's number (1-based) and its words with their columns.
type Line<'a> = (usize, Vec<(usize, &'a str)>);

/// The non-blank lines of a text, with their 1-based numbers.
struct Lines<'a> {
    inner: std::iter::Enumerate<std::str::Lines<'a>>,
    total: usize,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Self {
        Lines { inner: text.lines().enumerate(), total: text.lines().count() }
    }
    /// The next non-blank line, or an error naming what was expected at the end of the file.
    fn next(&mut self, what: &str) -> Result<Line<'a>, ScenarioError> {
        for (i, l) in self.inner.by_ref() {
            let w = words(l);
            if !w.is_empty() {
                return Ok((i + 1, w));
            }
        }
        Err(at(self.total + 1, 1, format!("expected {what}, found the end of the file")))
    }
}

/// The first `count` numbers of a line (more are ignored), or an error at the word that is not one
/// or at the end of a line that is too short.
fn numbers(line: usize, words: &[(usize, &str)], count: usize, what: &str) -> Result<Vec<Real>, ScenarioError> {
    if words.len() < count {
        let end = words.last().map_or(1, |(c, w)| c + w.chars().count());
        return Err(at(line, end, format!("{what} needs {count} numbers, found {}", words.len())));
    }
    words[..count]
        .iter()
        .map(|(c, w)| match w.parse::<Real>() {
            Ok(x) if x != 0.0 && x.abs() < crate::limits::MIN_MAGNITUDE => Err(at(
                line,
                *c,
                format!("{what}: {x:e} is too small: numbers other than 0 must be at least 1e-100 in size"),
            )),
            Ok(x) if x.is_finite() && x.abs() <= crate::limits::MAX_MAGNITUDE => Ok(x),
            Ok(x) if x.is_finite() => {
                Err(at(line, *c, format!("{what}: {x:e} is too large: numbers must lie between -1e9 and 1e9")))
            }
            _ => Err(at(line, *c, format!("{what}: expected a number, found \"{}\"", crate::limits::cut(w, 40)))),
        })
        .collect()
}

/// A whole number on its own at the start of a line.
fn count(line: usize, words: &[(usize, &str)], what: &str, least: usize) -> Result<usize, ScenarioError> {
    let (c, w) = words[0];
    match w.parse::<usize>() {
        Ok(k) if k >= least => Ok(k),
        _ => Err(at(line, c, format!("{what} must be a whole number, {least} or more, found \"{w}\""))),
    }
}

/// Read an ASV problem file as a scenario: bounds `[0, 0, 1, 1]`, brooms 0.05 long, the default
/// minimum area, convex, steps of 0.001 (also the motion resolution), touching allowed, and
/// RRT-Connect selected. `name` (the file's stem) titles it. Errors name the line and column.
///
/// Each rectangle is the bounding box of its four corners (the official files repeat a corner now
/// and then); numbers after the `2n` of a configuration line, or the 8 of an obstacle line, are
/// ignored.
pub fn import_problem(text: &str, name: &str) -> Result<Scenario, ScenarioError> {
    let mut lines = Lines::new(text);
    let (l, w) = lines.next("the number of vehicles")?;
    let n = count(l, &w, "the number of vehicles", 3)?;
    if n > crate::limits::MAX_VEHICLES {
        return Err(at(l, w[0].0, format!("{n} vehicles; the limit is {}", crate::limits::MAX_VEHICLES)));
    }
    let (l, w) = lines.next("the initial positions")?;
    let start = numbers(l, &w, 2 * n, "the initial positions")?;
    let (l, w) = lines.next("the goal positions")?;
    let goal = numbers(l, &w, 2 * n, "the goal positions")?;
    let (l, w) = lines.next("the number of obstacles")?;
    let k = count(l, &w, "the number of obstacles", 0)?;
    if k > crate::limits::MAX_OBSTACLES {
        return Err(at(l, w[0].0, format!("{k} obstacles; the limit is {}", crate::limits::MAX_OBSTACLES)));
    }
    let mut obstacles = Vec::with_capacity(k.min(lines.total));
    for i in 0..k {
        let what = format!("obstacle {} of {k}", i + 1);
        let (l, w) = lines.next(&format!("{what} (four corners)"))?;
        let c = numbers(l, &w, 8, &what)?;
        let xs = [c[0], c[2], c[4], c[6]];
        let ys = [c[1], c[3], c[5], c[7]];
        let min = |v: [Real; 4]| v.iter().copied().fold(Real::INFINITY, Real::min);
        let max = |v: [Real; 4]| v.iter().copied().fold(Real::NEG_INFINITY, Real::max);
        let rect = [min(xs), min(ys), max(xs), max(ys)];
        // A scenario's rect has an area (a wall of none is a segment): refuse what would not read
        // back when the imported problem is saved or shared.
        if rect[0] == rect[2] || rect[1] == rect[3] {
            return Err(at(l, w[0].0, format!("{what} has zero width or height: its corners lie on one line")));
        }
        obstacles.push(ObstacleSpec::Rect(rect));
    }
    let title = if name.trim().is_empty() { "ASV problem".to_string() } else { crate::limits::cut(name, 100) };
    let area = min_area(n);
    let defaults = CourseDefaults::for_chain(n);
    let mut params = serde_json::Map::new();
    params.insert("range".into(), serde_json::json!(defaults.range));
    if defaults.ladder > 0 {
        params.insert("ladder".into(), serde_json::json!(defaults.ladder));
    }
    Ok(Scenario {
        format: FORMAT.to_string(),
        name: title.clone(),
        notes: format!(
            "{title}: {n} vehicles in a chain joined by brooms {BROOM} long, from an ASV problem file (UQ COMP3702). \
             The chain must stay convex with an area of at least {area:.6}, keep its brooms off the obstacles \
             (touching allowed), and move no vehicle more than {MAX_STEP} per step. The planner searches the \
             centroid, the first broom's heading and the chain's turns; the tree is drawn at the centroid. {}",
            defaults.sentence(n)
        ),
        bounds: [0.0, 0.0, 1.0, 1.0],
        obstacles,
        obstacles3d: Vec::new(),
        robot: RobotSpec::Asv { count: n, broom: BROOM, min_area: area, convex: true, max_step: MAX_STEP },
        start,
        goal: Some(goal),
        goal_tolerance: 0.0,
        resolution: MAX_STEP,
        body_in_bounds: false,
        touching_allowed: true,
        inspection: None,
        planner: Some(PlannerDefaults { name: "rrt-connect".into(), seed: None, params }),
        map: None,
    })
}

/// RRT-Connect's step range for imported problems of up to [`LONG_CHAIN`]` - 1` vehicles (in the
/// chain's metric; see `robot::AsvRobot`).
pub const DEFAULT_RANGE: Real = 0.1;

/// From this many vehicles an imported problem gets [`LONG_CHAIN_RANGE`] and [`LONG_CHAIN_LADDER`].
/// The official files have 3 and 7 vehicles, and solve fastest with [`DEFAULT_RANGE`] and no ladder
/// (7ASV, seeds 1-30: median 111 ms against 200 ms); a 15-vehicle chain in the 7ASV map solves
/// in seconds with the shorter step and the ladder, and often not in a minute without them
/// (`docs/performance.md`, "The ladder move and a shorter step").
pub const LONG_CHAIN: usize = 8;
/// RRT-Connect's range for a chain of [`LONG_CHAIN`] vehicles or more.
pub const LONG_CHAIN_RANGE: Real = 0.05;
/// Ladder steps for a chain of [`LONG_CHAIN`] vehicles or more.
pub const LONG_CHAIN_LADDER: u32 = 8;

/// The planner settings an imported problem file starts with, chosen from its chain's length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CourseDefaults {
    /// RRT-Connect's step range.
    pub range: Real,
    /// Ladder steps after a blocked step (0: none).
    pub ladder: u32,
}

impl CourseDefaults {
    /// The settings for a chain of `n` vehicles.
    pub fn for_chain(n: usize) -> CourseDefaults {
        if n >= LONG_CHAIN {
            CourseDefaults { range: LONG_CHAIN_RANGE, ladder: LONG_CHAIN_LADDER }
        } else {
            CourseDefaults { range: DEFAULT_RANGE, ladder: 0 }
        }
    }
    /// What the scenario's notes say of them, so the page shows which were used and why.
    fn sentence(&self, n: usize) -> String {
        if self.ladder > 0 {
            format!(
                "Planner: RRT-Connect with range {} and {} ladder steps, the settings for a chain of {LONG_CHAIN} \
                 vehicles or more (this one has {n}), which solve long chains in the course's cluttered maps.",
                self.range, self.ladder
            )
        } else {
            format!(
                "Planner: RRT-Connect with range {}, the settings for a chain of fewer than {LONG_CHAIN} vehicles \
                 (this one has {n}).",
                self.range
            )
        }
    }
}

/// The course's solution file for `path`, a path of planning states from `problem`'s start to its
/// goal (as `Session::planning_path` returns it). Every motion is cut into the primitive steps the
/// planner checked (no vehicle moves more than `max_step` in one), each decoded to positions; the
/// first and last lines are the problem's own initial and goal positions. First line `m cost`: the
/// number of steps and the sum over steps of the distances moved by all vehicles. Errors when the
/// problem is not an ASV one, or the path does not join start and goal with valid states.
pub fn solution_text(problem: &Problem, path: &[Vec<Real>]) -> Result<String, String> {
    let configs = primitive_steps(problem, path)?;
    let mut out = format!("{} {}\n", configs.len() - 1, path_cost(&configs));
    for c in &configs {
        let line: Vec<String> = c.iter().map(|x| x.to_string()).collect();
        out.push_str(&line.join(" "));
        out.push('\n');
    }
    Ok(out)
}

/// The configurations of [`solution_text`], as positions: `path` cut into the primitive steps the
/// planner checked, the problem's own start and goal first and last. The page animates these.
pub fn primitive_steps(problem: &Problem, path: &[Vec<Real>]) -> Result<Vec<Vec<Real>>, String> {
    let sc = &problem.scenario;
    let max_step = match sc.robot {
        RobotSpec::Asv { max_step, .. } => max_step,
        _ => return Err(format!("a solution file is for an ASV problem; this robot is a {} robot", sc.robot.kind())),
    };
    let goal = sc.goal.as_ref().ok_or("the scenario has no goal")?;
    // A run whose start is already the goal has a one-state path: its file is that state twice
    // (one step of length 0), since the course's file holds the start and the goal lines.
    let doubled;
    let path = match path {
        [] => return Err("the path has no state".into()),
        [one] => {
            doubled = [one.clone(), one.clone()];
            &doubled[..]
        }
        _ => path,
    };
    let robot = &problem.robot;
    let si = &problem.si;
    let check = |q: &[Real]| -> Result<(), String> {
        match si.verdict(q) {
            crate::robot::Verdict::Valid => Ok(()),
            v => Err(format!("the path has an invalid state ({v:?}) at {:?}", robot.decode(q))),
        }
    };
    let mut configs = vec![robot.decode(&path[0])];
    check(&path[0])?;
    let mut q = vec![0.0; si.dims()];
    for w in path.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        // The same states `SpaceInfo::check_motion` checked: i/n of the way for i in 1..n, then b.
        let n = si
            .motion_model()
            .steps(a, b, si.distance(a, b), si.resolution)
            .ok_or("a motion of the path has too many primitive steps to write")?;
        if configs.len().saturating_add(n) > crate::limits::MAX_SOLUTION_STEPS {
            return Err(format!("the solution would have more than {} steps", crate::limits::MAX_SOLUTION_STEPS));
        }
        for i in 1..n {
            si.interpolate(a, b, i as Real / n as Real, &mut q);
            check(&q)?;
            configs.push(robot.decode(&q));
        }
        check(b)?;
        configs.push(robot.decode(b));
    }
    // The problem's own numbers first and last: in place of the decoded ones when they are that
    // close, else as one more (tiny) step.
    for (end, exact) in [(0, &sc.start), (configs.len() - 1, goal)] {
        let gap = max_move(&configs[end], exact);
        if gap > max_step {
            let which = if end == 0 { "start" } else { "goal" };
            return Err(format!("the path's {which} is {gap} away from the problem's"));
        }
        if gap <= TOLERANCE / 2.0 {
            configs[end] = exact.clone();
        } else if end == 0 {
            configs.insert(0, exact.clone());
        } else {
            configs.push(exact.clone());
        }
    }
    Ok(configs)
}

/// Read a solution file: `m cost`, then `m + 1` lines of positions. Errors name the line.
pub fn read_solution(text: &str) -> Result<Vec<Vec<Real>>, String> {
    let mut lines = Lines::new(text);
    let (l, w) = lines.next("the line \"m cost\"").map_err(|e| e.to_string())?;
    let m = count(l, &w, "the number of steps", 0).map_err(|e| e.to_string())?;
    if m >= crate::limits::MAX_SOLUTION_STEPS {
        return Err(format!("line {l}: {m} steps; the limit is {}", crate::limits::MAX_SOLUTION_STEPS - 1));
    }
    // Room for what the text can hold, not for what its first line claims.
    let mut configs: Vec<Vec<Real>> = Vec::with_capacity((m + 1).min(lines.total));
    for i in 0..=m {
        let (l, w) = lines.next(&format!("configuration {i} of {m} steps")).map_err(|e| e.to_string())?;
        let c = numbers(l, &w, w.len(), &format!("configuration {i}")).map_err(|e| e.to_string())?;
        if c.len() % 2 == 1 || c.is_empty() {
            return Err(format!("line {l}: configuration {i} has {} numbers, not x y pairs", c.len()));
        }
        if let Some(first) = configs.first() {
            if first.len() != c.len() {
                return Err(format!(
                    "line {l}: configuration {i} has {} numbers, the first has {}",
                    c.len(),
                    first.len()
                ));
            }
        }
        configs.push(c);
    }
    if let Ok((l, _)) = lines.next("") {
        return Err(format!("line {l}: more configurations than the {m} steps of the first line"));
    }
    Ok(configs)
}

#[cfg(test)]
mod tests;
