//! Every registered planner, on every built-in scenario, for several seeds (OMPL's `2denvs`
//! harness): it must solve within an iteration limit, and every returned path, raw and smoothed,
//! must pass an independent checker; every motion of its data (tree edges, roadmap edges) must be
//! valid. The spatial arms (the Puma in 3-D) run on budgets of their own.

mod common;

use planarium::motion::MotionValidator;
use planarium::planners::{self, Params, TaskKind};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::{builtin, builtin_names, Scenario};
use planarium::space_info::Deadline;
use serde_json::json;

/// Planner set-ups; a `range_fraction` becomes a range of that fraction of the space's extent.
fn setups() -> Vec<(&'static str, serde_json::Value)> {
    vec![
        ("rrt", json!({})),
        ("rrt", json!({"extend": "connect"})),
        ("rrt", json!({"goal_bias": 0.2, "range_fraction": 0.05})),
        ("rrt-connect", json!({})),
        ("rrt-connect", json!({"range_fraction": 0.05})),
        ("rrt-connect", json!({"ladder": 8})),
        ("prm", json!({})),
        ("prm-star", json!({})),
        ("lazy-prm", json!({})),
    ]
}

#[test]
fn the_checker_rejects_bad_paths() {
    common::self_test();
}

/// The built-ins a planner of task `task` is run on: every one of that task but horn-20 (a
/// benchmark: OMPL solves it in a third of its runs within 30 s, not a test case) and the vehicle
/// chain's (its paths are re-checked in tests/asv.rs, in primitive steps, against the course's own
/// rules, io::asv::check_solution). The spatial arms are run on budgets of their own
/// ([`spatial_budget`]).
fn builtins_for(task: TaskKind) -> Vec<(&'static str, Scenario)> {
    builtin_names()
        .into_iter()
        .filter(|n| *n != "horn-20")
        .map(|n| (n, builtin(n).unwrap()))
        .filter(|(_, sc)| !matches!(sc.robot, planarium::scenario::RobotSpec::Asv { .. }))
        .filter(|(_, sc)| match task {
            TaskKind::Goal => sc.goal.is_some(),
            TaskKind::Inspection => sc.goal.is_none(),
        })
        .collect()
}

/// A spatial arm's budget in the walk below (a Puma query costs about 10 µs, its motions hundreds of
/// states, and the checker's re-check of a motion, at a quarter of the resolution, milliseconds):
/// one seed; the set-ups must solve `puma-boxes` (each does in under 2 s) within their usual
/// iteration limit, and `puma-rbo-wall` is run for 500 iterations only, not to be solved (within
/// 200,000 iterations neither RRT nor range-step RRT-Connect threads the window; the course's
/// `last-free` RRT-Connect does, and tests/spatial_arm.rs re-checks its paths), so that its
/// trees' and roadmaps' motions near the wall are re-checked; at most 150 motions of a run's data
/// are re-checked independently. `None` for the planar robots.
fn spatial_budget(name: &str, sc: &Scenario) -> Option<(u64, Option<&'static str>)> {
    common::spatial(sc).then_some(if name == "puma-boxes" { (1, None) } else { (1, Some("500")) })
}

/// Every planner of the registry, with the set-ups above (those must solve every built-in) or, for
/// the others, its defaults: on every built-in of its task that it plans for (a planner may refuse
/// a robot it does not handle, as grid search refuses an arm: the run is then skipped), every path
/// it returns, raw and smoothed, passes the independent checker, and every motion its
/// [`PlannerData`](planarium::planners::PlannerData) holds (tree edges, a roadmap's checked edges)
/// is valid, by the crate's validator and, for a sample, independently. Planners outside the
/// set-ups need not solve each built-in (a potential field stops in a local minimum by design: see
/// apf-minimum), but each must solve at least one, so its path check is not vacuous. A planner
/// whose data holds no motion on a run (a descent that kept none) is checked by its path alone.
/// A spatial arm's motions are checked by the crate at the resolution's steps only: its raw paths
/// and data motions are held to that (each state the validator checks is free, by the independent
/// checker), those that meet an obstacle between two steps (at a quarter of the resolution) are
/// printed and counted, and its smoothed paths pass the whole check.
#[test]
fn every_planner_solves_every_builtin_with_valid_paths() {
    let listed = setups();
    let mut motions_checked = std::collections::BTreeMap::<&str, usize>::new();
    for spec in planners::REGISTRY {
        let mut own: Vec<serde_json::Value> =
            listed.iter().filter(|(n, _)| *n == spec.name).map(|(_, p)| p.clone()).collect();
        let must_solve = !own.is_empty();
        if own.is_empty() {
            own.push(json!({}));
        }
        let (mut ran, mut solved) = (0, 0);
        for (name, sc) in builtins_for(spec.task) {
            for params in &own {
                let extent = Problem::from_scenario(&sc).unwrap().si.space.max_extent();
                let mut params = params.clone();
                if let Some(f) = params.as_object_mut().unwrap().remove("range_fraction") {
                    params["range"] = json!(f.as_f64().unwrap() * extent);
                }
                let budget = spatial_budget(name, &sc);
                let must_solve = must_solve && budget.is_none_or(|(_, limit)| limit.is_none());
                let seeds = match budget {
                    Some((seeds, _)) => 1..=seeds,
                    None if must_solve => 1..=4,
                    None => 1..=2,
                };
                for seed in seeds {
                    let mut p = Params::from_json(spec, &params).unwrap();
                    let limit = if must_solve { "200000" } else { "20000" };
                    p.set_text(spec, "max_iterations", budget.and_then(|(_, l)| l).unwrap_or(limit)).unwrap();
                    let problem = Problem::from_scenario(&sc).unwrap();
                    let config = RunConfig { planner: spec.name.into(), params: p, seed, record_events: false };
                    let what = format!("{name} / {} {params} / seed {seed}", spec.name);
                    let mut s = match Session::new(problem, config) {
                        Ok(s) => s,
                        Err(e) => {
                            println!("{what}: not planned for ({e})");
                            break;
                        }
                    };
                    ran += 1;
                    s.run_to_end();
                    let r = s.result();
                    assert!(r.solved || !must_solve, "{what}: {}", r.status);
                    if r.solved {
                        solved += 1;
                        if let Some(e) = common::path_problem(&sc, &r.path) {
                            panic!("{what}: raw path: {e}");
                        }
                        if let Some(e) = common::path_problem(&sc, &r.smoothed) {
                            panic!("{what}: smoothed path: {e}");
                        }
                        let (cost, smoothed) = (r.stats.cost.unwrap(), r.stats.smoothed_cost.unwrap());
                        // Not asserted outside the set-ups: under an arm's chain metric a shortcut's
                        // ends, found by joint interpolation, are not on a shortest motion, so a
                        // shortcut can lengthen the path (RRT* on arm-3, seed 1: 0.7623 → 0.7659).
                        if must_solve {
                            assert!(smoothed <= cost + 1e-9, "{what}: smoothing made it longer ({cost} → {smoothed})");
                        } else if smoothed > cost + 1e-9 {
                            println!("{what}: smoothing made it longer ({cost} → {smoothed})");
                        }
                        assert!(r.stats.checks > 0 && r.stats.nodes >= 2);
                    }
                    // Every motion the planner kept was checked by it: re-check with the crate's
                    // validator and, for a sample, independently.
                    let si = &s.problem().si;
                    // The run's deadline no longer applies: past it, every motion check refuses
                    // (a busy machine re-checking thousands of roadmap edges reached it).
                    si.set_deadline(Deadline::NONE);
                    // The result's paths pass `check-path` (the rule a path from elsewhere is judged by).
                    if r.solved {
                        for (which, path) in [("raw", &r.path), ("smoothed", &r.smoothed)] {
                            let c = planarium::run::check_path(s.problem(), path);
                            assert!(c.valid, "{what}: {which} path refused by check_path: {:?}", c.refusals);
                        }
                    }
                    let mut scratch = vec![0.0; si.dims()];
                    let data = s.planner_data();
                    let most = if budget.is_some() { 7 * 150 } else { usize::MAX };
                    for (e, (a, b)) in data.motions().enumerate() {
                        assert!(si.check_motion(a, b, &mut scratch).is_ok(), "{what}: motion {e} of its data invalid");
                        if e % 7 == 0 && e < most {
                            if let Some(err) = common::motion_problem(&sc, a, b) {
                                panic!("{what}: motion {e} of its data: {err}");
                            }
                        }
                        *motions_checked.entry(spec.name).or_default() += 1;
                    }
                }
            }
        }
        println!("{}: {ran} runs, {solved} solved", spec.name);
        assert!(
            ran > 0 && solved > 0,
            "{}: planned {ran} runs and solved {solved}: its paths went unchecked",
            spec.name
        );
        assert!(
            motions_checked.contains_key(spec.name) != NO_GRAPH.contains(&spec.name),
            "{}: its data held {} motions; a planner that keeps none is listed in NO_GRAPH, \
             which says what is checked instead",
            spec.name,
            motions_checked.get(spec.name).copied().unwrap_or(0)
        );
    }
    println!("motions re-checked per planner: {motions_checked:?}");
}

/// Planners whose [`PlannerData`](planarium::planners::PlannerData) holds no motion (no tree, no
/// graph): only their paths are checked, raw and smoothed, by the independent checker. None today:
/// the potential field keeps its descent as a tree, grid and hexagonal search their search trees,
/// the visibility graph its shortest-path tree, the roadmaps their checked edges.
const NO_GRAPH: &[&str] = &[];

#[test]
fn one_iteration_cannot_outlast_the_time_limit_under_a_chain_metric() {
    // Under the chain metric a straight joint-space step can move away from its target; CONNECT
    // once looped forever here, adding the same node again and again inside one iteration.
    // On a simulated clock (a unit of work, a state checked, costs 20 µs): the run ends within
    // its limit, plus the delay of one look at the clock and one more call's units.
    let sc = builtin("horn-10").unwrap();
    let spec = planners::find("rrt-connect").unwrap();
    let unit = std::time::Duration::from_micros(20);
    for seed in 1..=3 {
        let sim = planarium::clock::simulate(unit, std::time::Duration::from_nanos(50));
        let params = Params::from_json(spec, &json!({"range": 0.55, "time_limit": 5.0})).unwrap();
        let mut s = Session::new(
            Problem::from_scenario(&sc).unwrap(),
            RunConfig { planner: "rrt-connect".into(), params, seed, record_events: false },
        )
        .unwrap();
        sim.take_largest();
        s.run_to_end();
        let delay = planarium::space_info::SLOW_LOOK_MS + 2.0 * sim.take_largest() as f64 * 0.02 + 0.2;
        let ms = s.stats().time_ms;
        eprintln!(
            "seed {seed}: {} after {ms:.3} ms (simulated), {} iterations",
            s.status().name(),
            s.stats().iterations
        );
        assert!(ms <= 5000.0 + delay, "seed {seed}: {ms} ms (simulated) against a 5 s limit");
    }
}
