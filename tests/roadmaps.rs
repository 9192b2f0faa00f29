//! The roadmap planners (PRM, PRM*, Lazy PRM): they solve the built-ins they apply to with paths
//! the independent checker accepts, every roadmap edge they call valid is valid, one roadmap
//! answers several queries, a seed fixes the roadmap bit for bit, Lazy PRM checks fewer edges
//! than PRM on the same roadmap, and PRM*'s neighbour count follows its rule.

mod common;

use planarium::events::{EventKind, EventLog, STRIDE};
use planarium::motion::MotionValidator;
use planarium::planners::roadmap::{k_star, prm_star, EdgeState, RoadmapPlanner};
use planarium::planners::{self, Context, Params, Planner, Task};
use planarium::problem::Problem;
use planarium::rng::Rng;
use planarium::run::{RunConfig, Session};
use planarium::sampler::Sampler;
use planarium::scenario::{builtin, Scenario};
use serde_json::{json, Value};

const ROADMAPS: [&str; 3] = ["prm", "prm-star", "lazy-prm"];

/// A roadmap planner driven directly (not through a session), so its roadmap can be read.
struct Rig {
    problem: Problem,
    rng: Rng,
    events: EventLog,
    sampler: Sampler,
    planner: RoadmapPlanner,
}

impl Rig {
    fn new(sc: &Scenario, name: &str, params: Value, seed: u64) -> Rig {
        let problem = Problem::from_scenario(sc).unwrap();
        let spec = planners::find(name).unwrap();
        let params = Params::from_json(spec, &params).unwrap();
        let sampler = Sampler::from_params(&problem.si, problem.goal.as_deref(), &params);
        let task = Task {
            start: problem.start.clone(),
            goal: problem.goal.clone(),
            goal_tolerance: problem.goal_tolerance,
            inspection: None,
        };
        let planner = match name {
            "prm-star" => RoadmapPlanner::new(problem.si.dims(), &task, prm_star::rule(&problem.si, &params), false),
            _ => RoadmapPlanner::new(
                problem.si.dims(),
                &task,
                planners::roadmap::fixed_rule(&problem.si, &params),
                name == "lazy-prm",
            ),
        };
        Rig { problem, rng: Rng::new(seed), events: EventLog::new(true), sampler, planner }
    }
    /// Run `f` with a context over the rig's run.
    fn with<T>(&mut self, f: impl FnOnce(&mut RoadmapPlanner, &mut Context) -> T) -> T {
        let mut cx = Context {
            si: &self.problem.si,
            rng: &mut self.rng,
            events: &mut self.events,
            nodes_left: 1_000_000,
            bytes_left: usize::MAX,
            sampler: &mut self.sampler,
            iteration: 0,
        };
        f(&mut self.planner, &mut cx)
    }
    /// Iterate until solved (at most `max` iterations).
    fn solve(&mut self, max: usize) -> Option<Vec<Vec<f64>>> {
        (0..max).find_map(|_| self.with(|p, cx| p.iterate(cx)))
    }
    fn records(&self, kind: EventKind) -> Vec<Vec<f64>> {
        self.events.records().chunks(STRIDE).filter(|r| r[0] == kind as u8 as f64).map(<[f64]>::to_vec).collect()
    }
}

fn session(sc: &Scenario, planner: &str, params: Value, seed: u64) -> Session {
    let spec = planners::find(planner).unwrap();
    let mut p = Params::from_json(spec, &params).unwrap();
    p.set_text(spec, "max_iterations", "200000").unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    Session::new(problem, RunConfig { planner: planner.into(), params: p, seed, record_events: false }).unwrap()
}

#[test]
fn each_roadmap_solves_the_builtins_it_applies_to_with_valid_paths() {
    // Point robots (zigzag and narrow among them), the rigid body in its slot and the 2-link arm.
    for name in ["open-field", "narrow", "zigzag", "slot", "arm-2", "ompl-rect", "technion-mp", "hex-trap"] {
        let sc = builtin(name).unwrap();
        for planner in ROADMAPS {
            for seed in 1..=3 {
                let mut s = session(&sc, planner, json!({}), seed);
                s.run_to_end();
                let r = s.result();
                let what = format!("{name} / {planner} / seed {seed}");
                assert!(r.solved, "{what}: {}", r.status);
                if let Some(e) = common::path_problem(&sc, &r.path) {
                    panic!("{what}: raw path: {e}");
                }
                if let Some(e) = common::path_problem(&sc, &r.smoothed) {
                    panic!("{what}: smoothed path: {e}");
                }
            }
        }
    }
}

#[test]
fn every_edge_a_roadmap_calls_valid_is_valid() {
    for name in ["narrow", "zigzag", "slot"] {
        let sc = builtin(name).unwrap();
        for planner in ROADMAPS {
            let mut rig = Rig::new(&sc, planner, json!({}), 2);
            assert!(rig.solve(100_000).is_some(), "{name} / {planner}");
            let g = rig.planner.roadmap();
            let mut scratch = vec![0.0; rig.problem.si.dims()];
            let mut valid = 0;
            for (i, e) in g.edges().iter().enumerate() {
                if e.state != EdgeState::Valid {
                    continue;
                }
                valid += 1;
                let (a, b) = (g.state(e.a), g.state(e.b));
                assert!(rig.problem.si.check_motion(a, b, &mut scratch).is_ok(), "{name} / {planner}: edge {i}");
                if i % 5 == 0 {
                    if let Some(err) = common::motion_problem(&sc, a, b) {
                        panic!("{name} / {planner}: edge {i}: {err}");
                    }
                }
            }
            assert!(valid > 0, "{name} / {planner}: no valid edge");
            for v in 0..g.len() as u32 {
                assert!(common::state_problem(&sc, g.state(v)).is_none(), "{name} / {planner}: vertex {v}");
            }
        }
    }
}

#[test]
fn one_roadmap_answers_two_more_queries_without_new_milestones() {
    let sc = builtin("zigzag").unwrap();
    // Two other queries in the zigzag's corridor: across the whole map the other way, and between
    // two of its middle legs.
    let queries = [([0.92, 0.1], [0.08, 0.9]), ([0.3, 0.5], [0.7, 0.2])];
    for planner in ROADMAPS {
        let mut rig = Rig::new(&sc, planner, json!({}), 5);
        // Grow past the first solution, so the roadmap covers the corridor.
        assert!(rig.solve(100_000).is_some(), "{planner}: the task");
        for _ in 0..400 {
            rig.with(|p, cx| p.grow(cx));
        }
        let milestones = rig.planner.stats().milestones;
        for (start, goal) in queries {
            let path = rig.with(|p, cx| p.query(cx, &start, &goal));
            let path = path.unwrap_or_else(|| panic!("{planner}: no path {start:?} → {goal:?}"));
            let mut other = sc.clone();
            other.start = start.to_vec();
            other.goal = Some(goal.to_vec());
            if let Some(e) = common::path_problem(&other, &path) {
                panic!("{planner}: {start:?} → {goal:?}: {e}");
            }
            assert_eq!(rig.planner.stats().milestones, milestones, "{planner}: a query added milestones");
        }
    }
}

#[test]
fn a_finished_session_answers_more_queries_on_its_roadmap_and_refuses_what_it_cannot() {
    // What `plan --query` does: the session's own roadmap, after its run, two vertices a query.
    let sc = builtin("zigzag").unwrap();
    for planner in ROADMAPS {
        let mut s = session(&sc, planner, json!({}), 5);
        assert!(s.query(&[0.92, 0.1], &[0.08, 0.9]).unwrap_err().contains("not finished"), "{planner}: before the run");
        s.run_to_end();
        let before = s.result();
        let nodes = s.stats().nodes;
        let answer = s.query(&[0.92, 0.1], &[0.08, 0.9]).unwrap();
        let (path, cost) = (answer.path.clone(), answer.cost);
        assert_eq!(answer.points.len(), path.len());
        assert!(!path.is_empty(), "{planner}: the other way across the zigzag");
        let mut other = sc.clone();
        other.start = vec![0.92, 0.1];
        other.goal = Some(vec![0.08, 0.9]);
        if let Some(e) = common::path_problem(&other, &path) {
            panic!("{planner}: the query's path: {e}");
        }
        assert_eq!((path[0].clone(), path.last().unwrap().clone()), (vec![0.92, 0.1], vec![0.08, 0.9]));
        let length: f64 =
            path.windows(2).map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt()).sum();
        assert!((length - cost).abs() < 1e-9, "{planner}: cost {cost} is the path's length {length}");
        assert_eq!(s.stats().nodes, nodes + 2, "{planner}: only the two terminals join the roadmap");
        assert_eq!(s.result().path, before.path, "{planner}: the run's own path is kept");
        // A state in a wall is refused with its name; a tree planner keeps nothing to query.
        let e = s.query(&[0.92, 0.1], &[0.6, 0.5]).unwrap_err();
        assert!(e.starts_with("goal"), "{planner}: {e}");
    }
    let mut s = session(&sc, "rrt-connect", json!({}), 5);
    s.run_to_end();
    assert!(s.query(&[0.92, 0.1], &[0.08, 0.9]).unwrap_err().contains("keeps no roadmap"));
}

/// Every vertex's bits, and every edge (ends, length's bits, state), in order.
type Bits = (Vec<u64>, Vec<(u32, u32, u64, EdgeState)>);

fn fingerprint(rig: &Rig) -> Bits {
    let g = rig.planner.roadmap();
    (
        g.states().iter().map(|x| x.to_bits()).collect(),
        g.edges().iter().map(|e| (e.a, e.b, e.len.to_bits(), e.state)).collect(),
    )
}

#[test]
fn a_seed_fixes_the_roadmap_bit_for_bit() {
    let sc = builtin("zigzag").unwrap();
    for planner in ROADMAPS {
        let build = |seed| {
            let mut rig = Rig::new(&sc, planner, json!({}), seed);
            for _ in 0..300 {
                rig.with(|p, cx| p.iterate(cx));
            }
            rig
        };
        let (a, b, c) = (build(7), build(7), build(8));
        assert_eq!(fingerprint(&a), fingerprint(&b), "{planner}: same seed");
        assert_eq!(a.events.records().len(), b.events.records().len());
        assert!(a.events.records().iter().zip(b.events.records()).all(|(x, y)| x.to_bits() == y.to_bits()));
        assert_ne!(fingerprint(&a).0, fingerprint(&c).0, "{planner}: another seed, another roadmap");
    }
}

#[test]
fn lazy_prm_checks_fewer_edges_than_prm_on_the_same_roadmap() {
    for (name, seed, grow) in [("zigzag", 1, 600), ("zigzag", 2, 600), ("narrow", 3, 2500), ("slot", 2, 2500)] {
        let sc = builtin(name).unwrap();
        let (mut eager, mut lazy) = (Rig::new(&sc, "prm", json!({}), seed), Rig::new(&sc, "lazy-prm", json!({}), seed));
        // The same milestones: grow both as many steps, then query once.
        for rig in [&mut eager, &mut lazy] {
            rig.with(|p, cx| p.init(cx));
            for _ in 0..grow {
                rig.with(|p, cx| p.grow(cx));
            }
        }
        assert_eq!(fingerprint(&eager).0, fingerprint(&lazy).0, "{name}: the same milestones");
        let before = eager.planner.stats().edges_checked;
        assert_eq!(lazy.planner.stats().edges_checked, 0, "{name}: Lazy PRM checked edges while growing");
        let p = eager.with(|p, cx| p.query_vertices(cx, 0, 1)).unwrap_or_else(|| panic!("{name}: PRM"));
        let q = lazy.with(|p, cx| p.query_vertices(cx, 0, 1)).unwrap_or_else(|| panic!("{name}: Lazy PRM"));
        assert_eq!(eager.planner.stats().edges_checked, before, "{name}: PRM's query checks nothing");
        for path in [&p, &q] {
            assert!(common::path_problem(&sc, path).is_none(), "{name}: {:?}", common::path_problem(&sc, path));
        }
        // Lazy PRM's edges are PRM's candidates; it checked only those its paths used.
        let (e, l) = (eager.planner.stats(), lazy.planner.stats());
        assert_eq!(lazy.planner.roadmap().edges().len() as u64, e.edges_checked, "{name}: the same candidate edges");
        eprintln!("{name} seed {seed}: edges checked: Lazy PRM {} of PRM's {}", l.edges_checked, e.edges_checked);
        assert!(l.edges_checked * 2 < e.edges_checked, "{name}: lazy {} vs PRM {}", l.edges_checked, e.edges_checked);
        // The shortest path over the valid edges is the same length either way.
        let cost = |path: &[Vec<f64>]| path.windows(2).map(|w| eager.problem.si.distance(&w[0], &w[1])).sum::<f64>();
        assert!((cost(&p) - cost(&q)).abs() < 1e-9, "{name}: {} vs {}", cost(&p), cost(&q));
        // What the page draws: one record per lazily checked edge.
        assert_eq!(lazy.records(EventKind::EdgeChecked).len() as u64, l.edges_checked);
        let unchecked = lazy.records(EventKind::RoadmapEdge).iter().filter(|r| r[1] == 1.0).count();
        assert_eq!(unchecked, lazy.planner.roadmap().edges().len(), "{name}: every lazy edge is drawn unchecked");
    }
}

#[test]
fn lazy_prm_searches_once_an_iteration_and_runs_as_one_query_an_iteration_would() {
    // An iteration searches the roadmap at most once: after an invalid edge, the next iteration
    // searches again without growing, so a batch suspended in a long query replays one search.
    // The run is the one a whole query per iteration gives: the same records, checks and path.
    for (name, seed) in [("zigzag", 1), ("narrow", 3), ("slot", 2)] {
        let sc = builtin(name).unwrap();
        let (mut stepped, mut whole) =
            (Rig::new(&sc, "lazy-prm", json!({}), seed), Rig::new(&sc, "lazy-prm", json!({}), seed));
        let (mut iterations, mut again) = (0u64, 0u64);
        let p = (0..20_000)
            .find_map(|_| {
                let (searches, invalid) = (stepped.planner.stats().searches, stepped.planner.stats().edges_invalid);
                let found = stepped.with(|p, cx| p.iterate(cx));
                let s = stepped.planner.stats();
                iterations += 1;
                assert!(s.searches - searches <= 1, "{name}: {} searches in one iteration", s.searches - searches);
                again += (s.edges_invalid > invalid) as u64;
                found
            })
            .unwrap_or_else(|| panic!("{name}: Lazy PRM"));
        assert!(again > 3, "{name}: only {again} searches found an invalid edge");
        // The same run, each query searched to its end in one go.
        whole.with(|p, cx| p.init(cx));
        let q = (0..20_000)
            .find_map(|i| {
                let grew = whole.with(|p, cx| p.grow(cx));
                if !grew && i > 0 {
                    return None;
                }
                whole.with(|p, cx| p.query_vertices(cx, 0, 1))
            })
            .unwrap_or_else(|| panic!("{name}: Lazy PRM in whole queries"));
        assert_eq!(p, q, "{name}: the same path");
        assert_eq!(stepped.planner.stats(), whole.planner.stats(), "{name}: the same searches and checks");
        // The same records, and the iterations' `Solved` at the end.
        let (a, b) = (stepped.events.records(), whole.events.records());
        assert_eq!(a.len(), b.len() + STRIDE, "{name}: record counts");
        assert_eq!(a[b.len()], EventKind::Solved as u8 as f64, "{name}: the last record");
        let first_difference = a.iter().zip(b).position(|(x, y)| x.to_bits() != y.to_bits());
        assert_eq!(first_difference, None, "{name}: the records differ from number {first_difference:?} on");
        assert!(iterations > stepped.planner.stats().milestones as u64, "{name}: {iterations} iterations");
    }
}

#[test]
fn in_a_session_lazy_prm_solves_with_prms_milestones_and_fewer_checks() {
    for seed in 1..=5 {
        let sc = builtin("zigzag").unwrap();
        let (mut a, mut b) = (session(&sc, "prm", json!({}), seed), session(&sc, "lazy-prm", json!({}), seed));
        a.run_to_end();
        b.run_to_end();
        let (ra, rb) = (a.result(), b.result());
        assert!(ra.solved && rb.solved);
        assert_eq!(ra.stats.nodes, rb.stats.nodes, "seed {seed}: solved at the same milestone");
        assert!(rb.stats.checks < ra.stats.checks, "seed {seed}: {} vs {}", rb.stats.checks, ra.stats.checks);
    }
}

#[test]
fn prm_star_connects_each_milestone_by_its_rule() {
    // An empty square: every candidate edge is valid, so a vertex's edges to older vertices are
    // exactly its neighbour set.
    let sc = Scenario::from_json(
        r#"{"format": "planarium-scenario/1", "name": "empty", "bounds": [0, 0, 1, 1], "obstacles": [],
            "robot": {"kind": "point"}, "start": [0.1, 0.1], "goal": [0.9, 0.9]}"#,
    )
    .unwrap();
    // The rule itself: k = ⌈e·(1 + 1/d)·ln n⌉, as OMPL's PRMstar.
    let kp = prm_star::k_prm(1.0, 2);
    assert!((kp - std::f64::consts::E * 1.5).abs() < 1e-12);
    assert_eq!(k_star(kp, 100), 19); // ⌈4.077 · 4.605⌉ = ⌈18.78⌉
    assert_eq!(k_star(kp, 1000), 29);
    assert_eq!(k_star(kp, 1), 1);
    for (params, radius) in [(json!({}), false), (json!({"connect": "radius"}), true), (json!({"factor": 2.0}), false)]
    {
        let mut rig = Rig::new(&sc, "prm-star", params.clone(), 4);
        rig.with(|p, cx| p.init(cx));
        for _ in 0..600 {
            rig.with(|p, cx| p.grow(cx));
        }
        let rule = rig.planner.rule();
        let g = rig.planner.roadmap();
        let mut by_vertex = vec![0usize; g.len()];
        for e in g.edges() {
            assert_eq!(e.state, EdgeState::Valid);
            by_vertex[e.b as usize] += 1;
        }
        let mut grew = false;
        for v in 1..g.len() {
            let want = if radius {
                let r = rule.radius(v, 2).unwrap();
                (0..v as u32).filter(|&u| rig.problem.si.distance(g.state(u), g.state(v as u32)) <= r).count()
            } else {
                rule.k(v).unwrap().min(v)
            };
            assert_eq!(by_vertex[v], want, "{params}: vertex {v}");
            grew |= v > 10 && by_vertex[v] > by_vertex[10];
        }
        if !radius {
            assert!(grew, "{params}: k grows with n");
        }
    }
}

#[test]
fn prm_star_keeps_shortening_its_path_and_reports_each_improvement() {
    // improve_for 0 is the first solution; with improve_for the same roadmap grows on (same draws),
    // its first Cost event is that first solution's cost, each later one is shorter, none is under
    // the visibility graph's optimum, and the path returned is the last one reported.
    for (name, optimum) in [("zigzag", 3.859660), ("narrow", 1.150026)] {
        let sc = builtin(name).unwrap();
        for seed in 1..=3 {
            let mut first = session(&sc, "prm-star", json!({"improve_for": 0}), seed);
            first.run_to_end();
            let first_cost = first.result().stats.cost.unwrap();
            let spec = planners::find("prm-star").unwrap();
            let params = Params::from_json(spec, &json!({"improve_for": 300})).unwrap();
            let problem = Problem::from_scenario(&sc).unwrap();
            let mut s =
                Session::new(problem, RunConfig { planner: "prm-star".into(), params, seed, record_events: true })
                    .unwrap();
            s.run_to_end();
            let r = s.result();
            assert!(r.solved, "{name} / {seed}");
            let ev = s.drain_events();
            let costs: Vec<f64> =
                ev.chunks(STRIDE).filter(|c| c[0] as u8 == EventKind::Cost as u8).map(|c| c[6]).collect();
            assert!((costs[0] - first_cost).abs() < 1e-12, "{name} / {seed}: first cost {} vs {first_cost}", costs[0]);
            assert!(costs.windows(2).all(|w| w[1] < w[0]), "{name} / {seed}: {costs:?}");
            assert!(costs.iter().all(|&c| c >= optimum - 1e-6), "{name} / {seed}: {costs:?} under {optimum}");
            assert_eq!(r.stats.cost.unwrap(), *costs.last().unwrap(), "{name} / {seed}: the path returned");
            if let Some(e) = common::path_problem(&sc, &r.path) {
                panic!("{name} / {seed}: {e}");
            }
            println!(
                "{name} seed {seed}: first {first_cost:.4}, then {} improvements to {:.4}",
                costs.len() - 1,
                costs.last().unwrap()
            );
        }
    }
}
