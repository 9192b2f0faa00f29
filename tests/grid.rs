//! Grid search (issue 17): A*, Dijkstra, BFS and the wavefront on grids made from built-ins, with
//! each diagonal rule; every path through the independent checker; A* closes no more cells than
//! Dijkstra for the same cost; BFS and the wavefront take the same number of moves; weights and
//! connectivity move cost and work the way they must; refusals say what and why.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::builtin;
use serde_json::{json, Value};

fn run(id: &str, params: Value) -> (PlanResult, usize) {
    let sc = builtin(id).unwrap();
    let spec = planners::find("grid-search").unwrap();
    let p = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: "grid-search".into(), params: p, seed: 1, record_events: true })
            .unwrap();
    s.run_to_end();
    let closed =
        s.drain_events().chunks(STRIDE).filter(|r| r[0] as u8 == EventKind::CellState as u8 && r[6] == 2.0).count();
    (s.result(), closed)
}

fn solved(id: &str, params: Value) -> (PlanResult, usize) {
    let sc = builtin(id).unwrap();
    let what = format!("{id} {params}");
    let (r, closed) = run(id, params);
    assert!(r.solved, "{what}: {} {:?}", r.status, r.reason);
    for (name, path) in [("raw", &r.path), ("smoothed", &r.smoothed)] {
        if let Some(e) = common::path_problem(&sc, path) {
            panic!("{what}, {name} path: {e}");
        }
    }
    (r, closed)
}

/// The maps and the cell size each needs (the narrow passage's gap is 0.02 wide).
const MAPS: [(&str, f64); 4] = [("open-field", 0.0), ("zigzag", 0.0), ("apf-minimum", 0.0), ("narrow", 0.005)];

#[test]
fn every_search_and_diagonal_rule_solves_the_point_maps_with_valid_paths() {
    for (id, cell) in MAPS {
        for search in ["astar", "dijkstra", "bfs", "wavefront"] {
            for diagonal in ["yes", "no", "cross-corners"] {
                solved(id, json!({"cell": cell, "search": search, "diagonal": diagonal}));
            }
        }
    }
}

#[test]
fn astar_closes_no_more_cells_than_dijkstra_and_returns_the_same_cost() {
    let mut fewer = 0;
    for (id, cell) in MAPS {
        for diagonal in ["yes", "no"] {
            let (a, a_closed) = solved(id, json!({"cell": cell, "search": "astar", "diagonal": diagonal}));
            let (d, d_closed) = solved(id, json!({"cell": cell, "search": "dijkstra", "diagonal": diagonal}));
            let (ac, dc) = (a.stats.cost.unwrap(), d.stats.cost.unwrap());
            assert!((ac - dc).abs() < 1e-9, "{id} {diagonal}: A* {ac} vs Dijkstra {dc}");
            assert!(a_closed <= d_closed, "{id} {diagonal}: A* closed {a_closed}, Dijkstra {d_closed}");
            fewer += usize::from(a_closed * 2 < d_closed);
        }
    }
    assert!(fewer >= 4, "A* closed under half of Dijkstra's cells on only {fewer} of 8 runs");
}

#[test]
fn bfs_and_the_wavefront_take_the_fewest_moves() {
    for (id, cell) in MAPS {
        let (b, _) = solved(id, json!({"cell": cell, "search": "bfs"}));
        let (w, _) = solved(id, json!({"cell": cell, "search": "wavefront"}));
        assert_eq!(b.path.len(), w.path.len(), "{id}: BFS and the wave take as many moves");
        let (a, _) = solved(id, json!({"cell": cell, "search": "astar"}));
        assert!(a.path.len() >= b.path.len(), "{id}: A* takes fewer moves than BFS");
        assert!(a.stats.cost.unwrap() <= b.stats.cost.unwrap() + 1e-9, "{id}: BFS's way is shorter than A*'s");
    }
}

#[test]
fn weights_and_connectivity_trade_length_for_work() {
    for (id, cell) in MAPS {
        let (a, a_closed) = solved(id, json!({"cell": cell}));
        let (w, w_closed) = solved(id, json!({"cell": cell, "weight": 3.0}));
        assert!(w.stats.cost.unwrap() >= a.stats.cost.unwrap() - 1e-9, "{id}: weighted A* beat the shortest way");
        assert!(w_closed <= a_closed, "{id}: weighted A* closed more cells ({w_closed} > {a_closed})");
        let (four, _) = solved(id, json!({"cell": cell, "diagonal": "no"}));
        let (cross, _) = solved(id, json!({"cell": cell, "diagonal": "cross-corners"}));
        assert!(four.stats.cost.unwrap() >= a.stats.cost.unwrap() - 1e-9, "{id}: 4 neighbours beat 8");
        assert!(cross.stats.cost.unwrap() <= a.stats.cost.unwrap() + 1e-9, "{id}: crossing corners made it longer");
    }
}

#[test]
fn what_cannot_be_searched_is_said() {
    let (r, _) = run("narrow", json!({}));
    assert_eq!(r.status, "no_path", "the 0.02 gap is blocked at cells of 0.025");
    assert!(r.reason.unwrap_or_default().contains("at this cell size"));
    let sc = builtin("ompl-rect").unwrap();
    let spec = planners::find("grid-search").unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let config =
        RunConfig { planner: "grid-search".into(), params: Params::defaults(spec), seed: 1, record_events: false };
    let e = Session::new(problem, config).err().expect("a rigid robot is refused");
    assert!(e.contains("needs a point robot"), "{e}");
    let problem = Problem::from_scenario(&builtin("zigzag").unwrap()).unwrap();
    let p = Params::from_json(spec, &json!({"cell": 1e-5})).unwrap();
    let e =
        Session::new(problem, RunConfig { planner: "grid-search".into(), params: p, seed: 1, record_events: false })
            .err()
            .expect("a grid too fine is refused");
    assert!(e.contains("too small") && e.contains("cells"), "{e}");
}

#[test]
fn max_nodes_equal_to_the_cells_or_vertices_is_enough() {
    // The grid's cells and the visibility graph's vertices are all made when the planner is set
    // up, which refuses more than max_nodes; a limit equal to their number used to stop the run
    // before its first iteration (node limit, 0 iterations).
    let cells = run("open-field", json!({})).0.stats.nodes;
    let (r, _) = solved("open-field", json!({ "max_nodes": cells }));
    assert_eq!(r.stats.nodes, cells);
    let e = Session::new(
        Problem::from_scenario(&builtin("open-field").unwrap()).unwrap(),
        RunConfig {
            planner: "grid-search".into(),
            params: Params::from_json(planners::find("grid-search").unwrap(), &json!({ "max_nodes": cells - 1 }))
                .unwrap(),
            seed: 1,
            record_events: false,
        },
    )
    .err()
    .expect("one cell more than max_nodes is refused");
    assert!(e.contains("max_nodes"), "{e}");
    let spec = planners::find("visibility-graph").unwrap();
    let vis = |params: Value| {
        let mut s = Session::new(
            Problem::from_scenario(&builtin("zigzag").unwrap()).unwrap(),
            RunConfig {
                planner: spec.name.into(),
                params: Params::from_json(spec, &params).unwrap(),
                seed: 1,
                record_events: false,
            },
        )
        .unwrap();
        s.run_to_end();
        s.result()
    };
    let vertices = vis(json!({})).stats.nodes;
    let r = vis(json!({ "max_nodes": vertices }));
    assert!(r.solved, "{} after {} iterations", r.status, r.stats.iterations);
}
