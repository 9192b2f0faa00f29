//! The thin binding the Web Worker drives (Rust-and-WebAssembly book style): `Scene` and `Run` hold
//! core types and translate at the edge (JSON text, flat `Float64Array`s). No DOM work here.
//!
//! A panic aborts the wasm instance; the hook below keeps its message so the worker can read it
//! with [`last_panic`], report it, and be replaced by the page, and writes it to the console.

use crate::planners::{self, Params};
use crate::problem::Problem;
use crate::run::{RunConfig, Session};
use crate::scenario::{self, Scenario, ScenarioError};
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

thread_local! {
    static PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Install the panic hook (called once by the worker after `init`).
#[wasm_bindgen]
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let message = info.to_string();
        // In the devtools console too (web-sys's typed console), with the worker's own stack.
        web_sys::console::error_1(&format!("planarium core panicked: {message}").into());
        PANIC.with(|p| *p.borrow_mut() = message);
    }));
}

/// The message of the last panic, if any.
#[wasm_bindgen]
pub fn last_panic() -> String {
    PANIC.with(|p| p.borrow().clone())
}

/// A fresh seed from the browser's entropy (`getrandom` → Web Crypto), at most 2⁵³ − 1 so it is
/// exact as a JavaScript number. For the page's "New seed"; a run itself is always seeded.
#[wasm_bindgen]
pub fn fresh_seed() -> Result<f64, JsError> {
    crate::rng::fresh_seed().map(|s| s as f64).map_err(|e| JsError::new(&e))
}

/// Crash on purpose (tests of the worker's panic handling).
#[wasm_bindgen]
pub fn debug_panic(message: &str) {
    panic!("{message}");
}

fn error_json(e: &ScenarioError) -> JsError {
    JsError::new(
        &serde_json::json!({"path": e.path, "message": e.message, "line": e.line, "column": e.column, "text": e.to_string()})
            .to_string(),
    )
}

/// The built-in scenarios as JSON: `[{id, course, name, notes, scenario}]`, grouped by course.
#[wasm_bindgen]
pub fn builtins() -> String {
    let list: Vec<serde_json::Value> = scenario::BUILTINS
        .iter()
        .map(|(id, text)| {
            let sc = Scenario::from_json(text).expect("built-ins are valid");
            serde_json::json!({"id": id, "course": scenario::course_of(id), "name": sc.name, "notes": sc.notes,
                               "scenario": serde_json::from_str::<serde_json::Value>(text).unwrap()})
        })
        .collect();
    serde_json::to_string(&list).unwrap()
}

/// The planner registry as JSON: `{planners: [{name, label, summary, params}], run_params}`.
#[wasm_bindgen]
pub fn planners() -> String {
    let run: Vec<serde_json::Value> = planners::RUN_PARAMS.iter().map(|p| p.to_json()).collect();
    format!("{{\"planners\": {}, \"run_params\": {}}}", planners::registry_json(), serde_json::to_string(&run).unwrap())
}

/// The robot kinds as JSON: `[{name, label, drawn, body, sensor, cspace, course_cost, pose,
/// solution_file}]` ([`crate::robot::kinds`]).
#[wasm_bindgen]
pub fn robot_kinds() -> String {
    crate::robot::kinds::kinds_json()
}

/// The suite's scaling benchmark (`planarium scaling`, [`crate::run::scaling`]): `checks` state
/// checks per robot and obstacle count, best of `rounds`, as JSON rows.
#[wasm_bindgen]
pub fn scaling_json(checks: u32, rounds: u32) -> String {
    let rows =
        crate::run::scaling::measure(&[], &crate::run::scaling::SIZES, u64::from(checks.max(1)), rounds.clamp(1, 10));
    serde_json::to_string(&rows).unwrap()
}

/// The input limits as JSON (`docs/limits.md`), for the page's checks before it sends anything.
#[wasm_bindgen]
pub fn limits() -> String {
    crate::limits::to_json().to_string()
}

/// The event kinds as JSON `{kinds: {NAME: number}, stride, setup: [kind, ...]}` (the record
/// stride, and the set-up kinds, `EventKind::SETUP`), checked against `www/run/events.js`.
#[wasm_bindgen]
pub fn event_kinds() -> String {
    let mut m = serde_json::Map::new();
    for (k, name) in crate::events::EventKind::ALL {
        m.insert(name.to_string(), serde_json::json!(k as u8));
    }
    let setup: Vec<u8> = crate::events::EventKind::SETUP.iter().map(|&k| k as u8).collect();
    serde_json::json!({"kinds": m, "stride": crate::events::STRIDE, "setup": setup}).to_string()
}

/// Read any supported file (a scenario, a Technion map, an ASV problem) and return it as scenario
/// JSON; errors are JSON `{path, message, line, column, text}`.
#[wasm_bindgen]
pub fn import_file(text: &str, name: &str) -> Result<String, JsError> {
    let sc = crate::io::import(text, name).map_err(|e| error_json(&e))?;
    Ok(compact(&sc))
}

/// A scenario as compact JSON: what the core hands back to the page is read by the page, not by a
/// person, and pretty-printing made a file within the 16 MiB limit nearly three times its size.
fn compact(sc: &Scenario) -> String {
    serde_json::to_string(sc).expect("a scenario always serialises")
}

/// Read an occupancy map (`io::occupancy`): `bytes` the image (PGM or PNG) named `name`, `yaml`
/// its map_server YAML (text) named `yaml_name`, or none for a plain image (dark is occupied).
/// Returns scenario JSON; errors are JSON `{path, message, line, column, text}`.
#[wasm_bindgen]
pub fn import_map(
    bytes: &[u8],
    name: &str,
    yaml: Option<String>,
    yaml_name: Option<String>,
) -> Result<String, JsError> {
    let y = yaml.as_deref().map(|t| (t, yaml_name.as_deref().unwrap_or("map.yaml")));
    let sc = crate::io::occupancy::import_image(bytes, name, y).map_err(|e| error_json(&e))?;
    Ok(compact(&sc))
}

/// The image a map_server YAML names (its `image` key), so the page can ask for it; errors as
/// [`import_map`]'s.
#[wasm_bindgen]
pub fn map_image_name(yaml: &str, yaml_name: &str) -> Result<String, JsError> {
    crate::io::occupancy::parse_yaml(yaml, yaml_name).map(|m| m.image).map_err(|e| error_json(&e))
}

/// The benchmark page's set-up lines (`[label:] planner [--param value ...]`, one per line, the
/// CLI's `--setup` syntax) as JSON `[{label, planner, params}]` (`params`: the values set); an
/// error names the line. The same parser as the CLI's.
#[wasm_bindgen]
pub fn parse_setups(text: &str) -> Result<String, JsError> {
    let setups = crate::run::bench::parse_setup_lines(text).map_err(|e| JsError::new(&e))?;
    let list: Vec<serde_json::Value> = setups
        .iter()
        .map(|s| serde_json::json!({"label": s.label, "planner": s.spec.name, "params": s.params.values()}))
        .collect();
    Ok(serde_json::to_string(&list).expect("set-ups serialise"))
}

/// Benchmark results in one export format: `report_json` is a bench report (see
/// `docs/benchmarks.md`: `{scenario, scenario_id, date, host, time_limit_s, runs, setups: [{label,
/// planner, params, rows: [{seed, solved, status, time_ms, iterations, nodes, checks, cost,
/// smoothed_cost, smoothing_ms}]}]}`), `format` one of `csv`, `json` (with summaries), `ompl` (an
/// OMPL benchmark log for Planner Arena) or `table` (the courses' Markdown table). The same code
/// writes the CLI's `bench --csv/--json-file/--ompl-log`. Errors are plain messages.
#[wasm_bindgen]
pub fn bench_export(report_json: &str, format: &str) -> Result<String, JsError> {
    let report = crate::run::report::from_json(report_json).map_err(|e| JsError::new(&e))?;
    crate::run::report::render(&report, format).map_err(|e| JsError::new(&e))
}

/// A validated scenario: its normalised JSON and the robot's outlines.
#[wasm_bindgen]
pub struct Scene {
    inner: Problem,
}

#[wasm_bindgen]
impl Scene {
    /// Parse and check a scenario; errors are JSON `{path, message, line, column, text}`.
    #[wasm_bindgen(constructor)]
    pub fn new(text: &str) -> Result<Scene, JsError> {
        let sc = Scenario::from_json(text).map_err(|e| error_json(&e))?;
        Scene::of(&sc)
    }
    /// Read any supported file (as [`import_file`]) straight into a scene: the text limit applies to
    /// `text`, what the user opened, and the scenario is not written out and read again (its JSON
    /// can be longer than the file: a Technion map's numbers, a compact file pretty-printed).
    pub fn from_file(text: &str, name: &str) -> Result<Scene, JsError> {
        let sc = crate::io::import(text, name).map_err(|e| error_json(&e))?;
        Scene::of(&sc)
    }
    /// An occupancy map (as [`import_map`]) straight into a scene.
    pub fn from_map(
        bytes: &[u8],
        name: &str,
        yaml: Option<String>,
        yaml_name: Option<String>,
    ) -> Result<Scene, JsError> {
        let y = yaml.as_deref().map(|t| (t, yaml_name.as_deref().unwrap_or("map.yaml")));
        let sc = crate::io::occupancy::import_image(bytes, name, y).map_err(|e| error_json(&e))?;
        Scene::of(&sc)
    }
    fn of(sc: &Scenario) -> Result<Scene, JsError> {
        let inner = Problem::from_scenario(sc).map_err(|e| error_json(&e))?;
        Ok(Scene { inner })
    }
    /// The scenario in the contract's normalised form (compact JSON).
    pub fn scenario_json(&self) -> String {
        compact(&self.inner.scenario)
    }
    /// A run of `planner` with parameters `params` (a JSON object) and `seed` on this scene, as
    /// [`Run::new`] on its scenario's text, without writing the scenario out and reading it again.
    pub fn run(&self, planner: &str, params: &str, seed: f64) -> Result<Run, JsError> {
        let problem = Problem::from_scenario(&self.inner.scenario).map_err(|e| error_json(&e))?;
        Run::on(problem, planner, params, seed)
    }
    /// For a two-dimensional planning space (a 2-joint arm, a point): whether each cell centre of an
    /// `n × n` grid over the space is valid (1) or not (0), row by row from the lowest second
    /// coordinate; empty for other spaces. State checks made here are not counted.
    pub fn cspace_grid(&self, n: usize) -> Vec<u8> {
        let si = &self.inner.si;
        if si.dims() != 2 || n == 0 || n > 1024 {
            return Vec::new();
        }
        let d = &si.space.dims;
        let mut out = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let q = [
                    d[0].lo + (i as f64 + 0.5) / n as f64 * (d[0].hi - d[0].lo),
                    d[1].lo + (j as f64 + 0.5) / n as f64 * (d[1].hi - d[1].lo),
                ];
                out.push(u8::from(si.is_valid_uncounted(&q)));
            }
        }
        out
    }
    /// What the page may do with this scene ([`crate::scene_caps::SceneCaps`]) as JSON; the
    /// optimum is computed on at most `optimum_max_obstacles` obstacles.
    pub fn caps_json(&self, optimum_max_obstacles: usize) -> String {
        crate::scene_caps::SceneCaps::of(&self.inner, optimum_max_obstacles).to_json().to_string()
    }
    /// The planning space's dimensions as JSON `[{lo, hi, wraps}]`.
    pub fn space_json(&self) -> String {
        let dims: Vec<serde_json::Value> = self
            .inner
            .si
            .space
            .dims
            .iter()
            .map(|d| serde_json::json!({"lo": d.lo, "hi": d.hi, "wraps": d.wraps}))
            .collect();
        serde_json::Value::Array(dims).to_string()
    }
    /// The shortest path's cost by the visibility graph (the reference line of the cost
    /// chart), as JSON `{"cost": c | null, "exact": bool}` (`cost` null: no path; `exact`: the
    /// robot's optimum, a point or a round footprint), or `{"error": why}` for robots it does not
    /// apply to or a graph that takes more than `seconds`.
    pub fn optimum_json(&self, seconds: f64) -> String {
        let r = Problem::from_scenario(&self.inner.scenario)
            .map_err(|e| e.to_string())
            .and_then(|p| crate::run::optimum_within(p, seconds));
        match r {
            Ok(o) => serde_json::json!({"cost": o.cost, "exact": o.exact}).to_string(),
            Err(e) => serde_json::json!({ "error": e }).to_string(),
        }
    }
    /// The robot's outline at scenario state `q`, flat: `[n_polygons, n_1, x, y, ..., n_2, ...]`
    /// (empty when `q` is not a state of this robot).
    pub fn outline(&self, q: &[f64]) -> Vec<f64> {
        if q.len() != self.inner.robot.external_dims() || q.iter().any(|v| !v.is_finite()) {
            return Vec::new();
        }
        match self.inner.robot.encode(q) {
            Ok(internal) => flat_outline(&self.inner, &internal),
            Err(_) => Vec::new(),
        }
    }
}

#[wasm_bindgen]
impl Scene {
    /// For a robot in 3-D: its link frames' origins and its tool centre point at scenario state
    /// `q`, flat `[x, y, z, ...]`; empty for other robots or a `q` that is not a state.
    pub fn skeleton(&self, q: &[f64]) -> Vec<f64> {
        match (self.inner.robot.spatial(), self.state(q)) {
            (Some(sp), Some(q)) => sp.skeleton(&q).concat(),
            _ => Vec::new(),
        }
    }
    /// The configurations a last-free connect from `from` toward `target` tests, the first
    /// `count` (`Problem::connect_configs`), flat, a state after another (as the state log's,
    /// `Run.drain_states`): the explain panel's steps through a connect.
    pub fn connect_configs(&self, from: &[f64], target: &[f64], count: usize) -> Vec<f64> {
        match (self.state(from), self.state(target)) {
            (Some(a), Some(b)) => {
                self.inner.connect_configs(&a, &b, count).iter().flat_map(|q| self.inner.robot.decode(q)).collect()
            }
            _ => Vec::new(),
        }
    }
    /// For a robot in 3-D, what a 3-D view draws, once, as JSON: `{links, tool, parts: [{link,
    /// name, vertices, triangles}], obstacles: [{name, vertices, triangles}]}`: each part's triangle
    /// mesh in its link's frame (placed by [`link_frames`](Scene::link_frames)), the scene's 3-D
    /// obstacles' in the world, flat (`vertices` x, y, z…; `triangles` indices, counter-clockwise
    /// seen from outside), the tool centre point in the last link's frame; `null` for other robots.
    pub fn spatial_json(&self) -> String {
        let Some(sp) = self.inner.robot.spatial() else { return "null".into() };
        let parts: Vec<serde_json::Value> = sp
            .part_meshes()
            .iter()
            .map(|p| {
                let mut m = p.mesh.to_json();
                m["link"] = p.link.into();
                m["name"] = p.name.clone().into();
                m
            })
            .collect();
        let obstacles: Vec<serde_json::Value> = self
            .inner
            .si
            .workspace()
            .solids
            .iter()
            .map(|s| {
                let mut m = crate::geometry::mesh::Mesh::of_solid(s).to_json();
                m["name"] = s.name.clone().into();
                m
            })
            .collect();
        serde_json::json!({
            "links": self.inner.robot.external_dims() + 1,
            "tool": sp.tool(),
            "parts": parts,
            "obstacles": obstacles,
        })
        .to_string()
    }
    /// For a robot in 3-D: every link's frame at scenario state `q` (link 0, the base, first), 16
    /// numbers each, a 4×4 matrix column-major; empty for other robots or a `q` that is not a state.
    pub fn link_frames(&self, q: &[f64]) -> Vec<f64> {
        match (self.inner.robot.spatial(), self.state(q)) {
            (Some(sp), Some(q)) => sp.link_frames(&q).concat(),
            _ => Vec::new(),
        }
    }
    /// For a robot in 3-D: the tool centre point at each of `states` (scenario states one after
    /// another, flat), flat `[x, y, z, ...]`, in one call (a path's curve); empty for other
    /// robots, or when `states` is not a whole number of states or one is not a state.
    pub fn tool_points(&self, states: &[f64]) -> Vec<f64> {
        let (Some(sp), dims) = (self.inner.robot.spatial(), self.inner.robot.external_dims()) else {
            return Vec::new();
        };
        if dims == 0 || states.len() % dims != 0 {
            return Vec::new();
        }
        let mut out = Vec::with_capacity(states.len() / dims * 3);
        for q in states.chunks_exact(dims) {
            let Some(q) = self.state(q) else { return Vec::new() };
            out.extend_from_slice(&sp.tool_point(&q));
        }
        out
    }
    /// What scenario state `q` collides with, in words ("link6's bar meets the lintel"), or ""
    /// when it is free or the robot cannot say. Not counted.
    pub fn collision(&self, q: &[f64]) -> String {
        self.state(q)
            .and_then(|q| self.inner.robot.describe_collision(self.inner.si.workspace(), &q))
            .unwrap_or_default()
    }
    /// For a robot in 3-D: what collides at scenario state `q` and where, flat `[link, other,
    /// obstacle, x, y, z]`: the link (0 the base) of the part hit, the other link (-1: a scene
    /// obstacle), the obstacle's index in `obstacles3d` (-1: two links), a world point where they
    /// meet; empty when the arm is free, for other robots, or a `q` that is not a state. Not counted.
    pub fn contact(&self, q: &[f64]) -> Vec<f64> {
        let (Some(sp), Some(q)) = (self.inner.robot.spatial(), self.state(q)) else { return Vec::new() };
        match sp.contact(self.inner.si.workspace(), &q) {
            Some(c) => {
                let idx = |v: Option<usize>| v.map_or(-1.0, |i| i as f64);
                vec![c.link as f64, idx(c.other), idx(c.solid), c.at[0], c.at[1], c.at[2]]
            }
            None => Vec::new(),
        }
    }
    fn state(&self, q: &[f64]) -> Option<Vec<f64>> {
        if q.len() != self.inner.robot.external_dims() || q.iter().any(|v| !v.is_finite()) {
            return None;
        }
        self.inner.robot.encode(q).ok()
    }
}

fn flat_outline(p: &Problem, q: &[f64]) -> Vec<f64> {
    let polys = p.robot.outline(q);
    let mut out = vec![polys.len() as f64];
    for poly in polys {
        out.push(poly.len() as f64);
        for v in poly {
            out.extend_from_slice(&[v.x, v.y]);
        }
    }
    out
}

/// A planning run, stepped by the worker.
#[wasm_bindgen]
pub struct Run {
    inner: Session,
}

#[wasm_bindgen]
impl Run {
    /// A run of `planner` with parameters `params` (a JSON object) and `seed` on a scenario.
    #[wasm_bindgen(constructor)]
    pub fn new(scenario: &str, planner: &str, params: &str, seed: f64) -> Result<Run, JsError> {
        let sc = Scenario::from_json(scenario).map_err(|e| error_json(&e))?;
        let problem = Problem::from_scenario(&sc).map_err(|e| error_json(&e))?;
        Run::on(problem, planner, params, seed)
    }
}

impl Run {
    fn on(problem: Problem, planner: &str, params: &str, seed: f64) -> Result<Run, JsError> {
        let spec = planners::find(planner)
            .ok_or_else(|| JsError::new(&format!("unknown planner \"{}\"", crate::limits::cut(planner, 100))))?;
        let value: serde_json::Value = serde_json::from_str(params)
            .map_err(|e| JsError::new(&format!("parameters: {}", crate::limits::echo(&e.to_string()))))?;
        let params = Params::from_json(spec, &value).map_err(|(k, m)| JsError::new(&format!("{k}: {m}")))?;
        if !(seed >= 0.0 && seed.fract() == 0.0 && seed < 9007199254740992.0) {
            return Err(JsError::new("seed: must be a whole number from 0 to 2^53 - 1 (9007199254740991)"));
        }
        let config = RunConfig { planner: planner.to_string(), params, seed: seed as u64, record_events: true };
        Ok(Run { inner: Session::new(problem, config).map_err(|e| JsError::new(&e))? })
    }
}

#[wasm_bindgen]
impl Run {
    /// Run at most `iterations` iterations for at most `max_ms` ms; returns the status name.
    pub fn step(&mut self, iterations: f64, max_ms: f64) -> String {
        self.inner.step(iterations as u64, max_ms).name().to_string()
    }
    /// Record events from now on, or not (the benchmark page's runs draw nothing).
    pub fn record_events(&mut self, on: bool) {
        self.inner.set_record_events(on)
    }
    /// Take the events recorded since the last call (flat records, see `www/run/events.js`).
    pub fn drain_events(&mut self) -> Vec<f64> {
        self.inner.drain_events()
    }
    /// Keep the added nodes' states from now on, or not, for [`drain_tool_tree`](Run::drain_tool_tree)
    /// (a 3-D view's trees). Drawing only: the run is the same.
    pub fn log_nodes(&mut self, on: bool) {
        self.inner.log_nodes(on)
    }
    /// Keep the full states of the records a growth step is explained by from now on, or not, for
    /// [`drain_states`](Run::drain_states) (an explain panel for a robot of more than two
    /// coordinates). Explaining only: the run is the same.
    pub fn log_states(&mut self, on: bool) {
        self.inner.log_states(on)
    }
    /// The state log since the last call (`Problem::explain_states`): flat `[dims, then per
    /// record of a growth step's kinds (Sample, SampleRejected, Nearest, Steer, Collision,
    /// NodeAdded, TreesConnected), in order: kind, extra, q…, pq…]`; empty when there is none.
    pub fn drain_states(&mut self) -> Vec<f64> {
        let log = self.inner.drain_states();
        self.inner.problem().explain_states(&log)
    }
    /// For a robot in 3-D, the nodes added since the last call as the tool sweeps their edges:
    /// flat `[tree, id, n, x, y, z…]` per node (`Problem::tool_tree`); empty for other robots.
    pub fn drain_tool_tree(&mut self) -> Vec<f64> {
        let log = self.inner.drain_nodes();
        self.inner.problem().tool_tree(&log)
    }
    /// After the run, another query on its roadmap (PRM, PRM*, Lazy PRM): `start` and `goal` are
    /// scenario states. JSON `{path, points, cost}` (`path` empty when the roadmap does not join
    /// them); an error names the state or says why the run cannot be queried. Its events are
    /// recorded as the run's are.
    pub fn query(&mut self, start: &[f64], goal: &[f64]) -> Result<String, JsError> {
        let answer = self.inner.query(start, goal).map_err(|e| JsError::new(&e))?;
        Ok(serde_json::to_string(&answer).unwrap())
    }
    /// Stop now.
    pub fn cancel(&mut self) {
        self.inner.cancel()
    }
    /// The statistics so far, as JSON.
    pub fn stats_json(&self) -> String {
        serde_json::to_string(&self.inner.stats()).unwrap()
    }
    /// The result in the contract's form, as JSON.
    pub fn result_json(&self) -> String {
        self.inner.result().to_json()
    }
    /// For a solved vehicle-chain (asv) run: the course's solution file for the smoothed path, in
    /// primitive steps of at most `max_step`. An error for other robots or an unsolved run.
    pub fn asv_solution(&self) -> Result<String, JsError> {
        if self.inner.status() != crate::status::Status::Solved {
            return Err(JsError::new("the run is not solved"));
        }
        crate::io::asv::solution_text(self.inner.problem(), self.inner.planning_path(false))
            .map_err(|e| JsError::new(&e))
    }
    /// The smoothed path (raw path if `raw`) sampled every `spacing` (robot metric) for animation,
    /// flat: `[dims, frames, then per frame: state…, outline (as [`Scene::outline`])…]`: each frame
    /// is `dims` numbers (a scenario state) then its outline. A vehicle chain's frames are its
    /// primitive steps (no vehicle moves more than `max_step` between two).
    pub fn path_frames(&self, raw: bool, spacing: f64) -> Vec<f64> {
        let p = self.inner.problem();
        let path = self.inner.planning_path(raw);
        // A vehicle chain is shown in the course's primitive steps, exactly as its solution file.
        if p.robot.caps().solution_file {
            if let Ok(steps) = crate::io::asv::primitive_steps(p, path) {
                let mut out = vec![p.robot.external_dims() as f64, steps.len() as f64];
                for c in &steps {
                    out.extend_from_slice(c);
                    let internal = p.robot.encode(c).unwrap_or_default();
                    out.extend(if internal.is_empty() { vec![0.0] } else { flat_outline(p, &internal) });
                }
                return out;
            }
        }
        let (states, _) = self.frame_states(raw, spacing);
        let external = p.robot.external_dims();
        let mut out = vec![external as f64, states.len() as f64];
        for q in &states {
            out.extend(p.robot.decode(q));
            out.extend(flat_outline(p, q));
        }
        out
    }
    /// The length along the path (robot metric) at each of [`Run::path_frames`]'s frames for the
    /// same `raw` and `spacing`, then at each waypoint: `[frames, lengths…, waypoints, lengths…]`.
    /// The last is the path's cost as the run's stats give it (the same sum). Empty for a vehicle
    /// chain (its frames are the course's primitive steps).
    pub fn path_lengths(&self, raw: bool, spacing: f64) -> Vec<f64> {
        if self.inner.problem().robot.caps().solution_file {
            return Vec::new();
        }
        let (states, at) = self.frame_states(raw, spacing);
        let path = self.inner.planning_path(raw);
        let si = &self.inner.problem().si;
        let mut out = vec![states.len() as f64];
        out.extend_from_slice(&at);
        out.push(path.len() as f64);
        let mut s = 0.0;
        for (i, q) in path.iter().enumerate() {
            if i > 0 {
                s += si.distance(&path[i - 1], q);
            }
            out.push(s);
        }
        out
    }
}

impl Run {
    /// The path's animation states (internal), sampled every `spacing`, and the length along the
    /// path at each (the sum of the segments before it, plus the fraction of its own).
    fn frame_states(&self, raw: bool, spacing: f64) -> (Vec<Vec<f64>>, Vec<f64>) {
        let p = self.inner.problem();
        let path = self.inner.planning_path(raw);
        let dims = p.si.dims();
        // The spacing grows so that a long path (or a long tree branch) stays within
        // `MAX_PATH_FRAMES` frames; step counts are computed checked.
        let length: f64 = path.windows(2).map(|w| p.si.distance(&w[0], &w[1])).sum();
        let most = crate::limits::MAX_PATH_FRAMES as f64;
        let spacing = spacing.max(1e-9).max(length / most);
        let mut states: Vec<Vec<f64>> = Vec::new();
        let mut at: Vec<f64> = Vec::new();
        let mut before = 0.0;
        for w in path.windows(2) {
            if states.len() >= crate::limits::MAX_PATH_FRAMES {
                break;
            }
            let d = p.si.distance(&w[0], &w[1]);
            let n = crate::limits::steps(d, spacing, 10_000.0).unwrap_or(10_000);
            for i in 0..n {
                let mut q = vec![0.0; dims];
                p.si.interpolate(&w[0], &w[1], i as f64 / n as f64, &mut q);
                states.push(q);
                at.push(before + d * (i as f64 / n as f64));
            }
            before += d;
        }
        if let Some(last) = path.last() {
            states.push(last.clone());
            at.push(length); // the path's end: its whole length (the cost's sum), even if cut short
        }
        (states, at)
    }
}
