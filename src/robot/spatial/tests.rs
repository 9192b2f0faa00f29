use super::*;
use crate::problem::Problem;
use crate::scenario::Scenario;
use serde_json::json;
use std::f64::consts::FRAC_PI_2;

/// One joint about z, one link: a bar along its x axis, `[0, 1] × [−0.1, 0.1]²` at `q = 0`; a
/// second joint at the bar's end (a = 1) with a short box; the scene a box whose near face is at
/// `x = face`.
pub(super) fn scenario(face: f64, extra: serde_json::Value) -> serde_json::Value {
    let mut sc = json!({
        "bounds": [-3, -3, 3, 3],
        "robot": {
            "kind": "spatial-arm",
            "joints": [
                {"d": 0, "a": 1, "alpha": 0, "limits": [-3, 3]},
                {"d": 0, "a": 0.5, "alpha": 0, "limits": [-3, 3]}
            ],
            "links": [
                {},
                {"boxes": [{"name": "bar", "center": [-0.5, 0, 0], "size": [1, 0.2, 0.2]}]},
                {"name": "hand", "hull": [[-0.5, -0.05, -0.05], [0, -0.05, -0.05], [0, 0.05, -0.05], [-0.5, 0.05, -0.05],
                                          [-0.5, -0.05, 0.05], [0, -0.05, 0.05], [0, 0.05, 0.05], [-0.5, 0.05, 0.05]]}
            ],
            "ignore": [[1, 2]]
        },
        "obstacles3d": [{"name": "wall", "box": {"center": [face + 0.5, 0, 0], "size": [1, 4, 4]}}],
        "start": [1.5, 0],
        "goal": [-1.5, 0],
        "resolution": 0.01
    });
    if let serde_json::Value::Object(m) = extra {
        for (k, v) in m {
            sc["robot"][k] = v;
        }
    }
    sc
}

pub(super) fn problem(sc: &serde_json::Value) -> Problem {
    Problem::from_scenario(&Scenario::from_value(sc).unwrap()).unwrap()
}

#[test]
fn dh_frames_follow_rz_tz_tx_rx() {
    let p = problem(&scenario(5.0, json!({})));
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
    // q = 0: joint 2 at (1, 0, 0), the hand's frame (and the tool) at (1.5, 0, 0).
    let s = arm.skeleton_points(&[0.0, 0.0]);
    assert!(close(s[1], [1.0, 0.0, 0.0]) && close(s[2], [1.5, 0.0, 0.0]), "{s:?}");
    // The first joint a quarter turn: everything along y.
    let s = arm.skeleton_points(&[FRAC_PI_2, 0.0]);
    assert!(close(s[1], [0.0, 1.0, 0.0]) && close(s[2], [0.0, 1.5, 0.0]), "{s:?}");
    // d lifts along the previous z, α twists the next joint's axis: with α = π/2 on joint 1,
    // joint 2 turns about the world's −y, so a quarter turn of it points the hand down... or up.
    let p = problem(&scenario(
        5.0,
        json!({"joints": [{"d": 0.3, "a": 1, "alpha": FRAC_PI_2, "limits": [-3, 3]}, {"a": 0.5, "limits": [-3, 3]}]}),
    ));
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let s = arm.skeleton_points(&[0.0, FRAC_PI_2]);
    assert!(close(s[1], [1.0, 0.0, 0.3]), "{s:?}");
    assert!(close(s[2], [1.0, 0.0, 0.8]), "Rx(π/2) takes the new y axis to the old z: {s:?}");
    // The base pose turns everything: rz = π/2 takes x to y.
    let p = problem(&scenario(5.0, json!({"base": {"translation": [0, 0, 2], "rotation": [0, 0, FRAC_PI_2]}})));
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let s = arm.skeleton_points(&[0.0, 0.0]);
    assert!(close(s[0], [0.0, 0.0, 2.0]) && close(s[2], [0.0, 1.5, 2.0]), "{s:?}");
}

#[test]
fn touching_the_scene_is_a_collision_and_a_gap_is_not() {
    // The hand's hull reaches x = 1.5 at q = 0.
    for (face, free) in [(1.5, false), (1.5 + 1e-6, true), (1.2, false)] {
        let mut sc = scenario(face, json!({}));
        sc["start"] = json!([1.5, 0]);
        let p = problem(&sc);
        let ws = p.si.workspace();
        assert_eq!(p.robot.is_valid(ws, &[0.0, 0.0]), free, "face at {face}");
        if !free {
            assert_eq!(p.robot.verdict(ws, &[0.0, 0.0]), Verdict::Collision(0));
            assert_eq!(p.robot.describe_collision(ws, &[0.0, 0.0]).unwrap(), "hand meets the wall");
        }
    }
    // Turned away from the wall, it is free.
    let p = problem(&scenario(1.2, json!({})));
    assert!(p.robot.is_valid(p.si.workspace(), &[FRAC_PI_2, 0.0]));
}

#[test]
fn exempt_links_and_ignored_pairs_are_not_tested() {
    // A post in the bar's middle, away from the hand.
    let post = json!([{"name": "post", "box": {"center": [0.5, 0, 0], "size": [0.1, 0.1, 0.1]}}]);
    let mut sc = scenario(5.0, json!({}));
    sc["obstacles3d"] = post.clone();
    sc["start"] = json!([1.5, 0]);
    let p = problem(&sc);
    assert_eq!(p.robot.describe_collision(p.si.workspace(), &[0.0, 0.0]).unwrap(), "link1's bar meets the post");
    // A numbered name is a label, said without "the" (the Robotics Library's box2).
    let mut sc = scenario(5.0, json!({}));
    sc["obstacles3d"] = json!([{"name": "box2", "box": {"center": [0.5, 0, 0], "size": [0.1, 0.1, 0.1]}}]);
    sc["start"] = json!([1.5, 0]);
    let p = problem(&sc);
    assert_eq!(p.robot.describe_collision(p.si.workspace(), &[0.0, 0.0]).unwrap(), "link1's bar meets box2");
    let mut sc = scenario(5.0, json!({"exempt": [1]}));
    sc["obstacles3d"] = post;
    let p = problem(&sc);
    assert!(p.robot.is_valid(p.si.workspace(), &[0.0, 0.0]), "link 1 is exempt from the scene");
    let q = [0.0, 3.0];
    // Folded back, the hand lies on the bar: ignored by default here, a collision when tested.
    // (Tested, the two always touch at the elbow: no start is free, so the robot is built alone.)
    let sc = Scenario::from_value(&scenario(5.0, json!({"ignore": []}))).unwrap();
    let arm = SpatialArmRobot::from_spec(&sc.robot).unwrap();
    let ws = problem(&scenario(5.0, json!({}))).si.workspace().clone();
    assert_eq!(arm.verdict(&ws, &q), Verdict::Invalid("two links of the arm meet"));
    assert_eq!(arm.describe_collision(&ws, &q).unwrap(), "link1's bar meets hand");
    assert!(!arm.is_valid(&ws, &q));
    let p = problem(&scenario(5.0, json!({})));
    assert!(p.robot.is_valid(p.si.workspace(), &q));
}

#[test]
fn limits_and_a_start_in_collision_are_named() {
    let p = problem(&scenario(5.0, json!({})));
    assert_eq!(p.robot.verdict(p.si.workspace(), &[3.1, 0.0]), Verdict::Invalid("a joint is outside its limits"));
    let mut sc = scenario(1.2, json!({}));
    sc["start"] = json!([0, 0]);
    let err = Problem::from_scenario(&Scenario::from_value(&sc).unwrap()).err().unwrap().to_string();
    assert!(err.contains("start") && err.contains("obstacles3d[0], the wall: hand meets the wall"), "{err}");
    sc["start"] = json!([1.5, 3.0]);
    sc["robot"]["ignore"] = json!([]);
    sc["obstacles3d"] = json!([]);
    let err = Problem::from_scenario(&Scenario::from_value(&sc).unwrap()).err().unwrap().to_string();
    assert!(err.contains("two links of the arm meet: link1's bar meets hand"), "{err}");
}

#[test]
fn the_keys_are_checked_with_their_paths() {
    let cases: Vec<(serde_json::Value, &str)> = vec![
        (json!({"joints": []}), "robot.joints: needs at least one joint"),
        (json!({"joints": [{"limits": [1, 0]}, {"limits": [-1, 1]}]}), "robot.joints[0].limits: needs lo < hi"),
        (json!({"joints": [{"limits": [-20, 0]}, {"limits": [-1, 1]}]}), "robot.joints[0].limits: must lie within"),
        (
            json!({"joints": [{"limits": [-1, 1], "twist": 0}, {"limits": [-1, 1]}]}),
            "robot.joints[0].twist: unknown key",
        ),
        (json!({"links": [{}, {}]}), "robot.links: needs one link per joint and the base (3), found 2"),
        (
            json!({"links": [{}, {}, {"hull": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]}]}),
            "robot.links[2].hull: its points lie in one plane",
        ),
        (
            json!({"links": [{}, {}, {"hull": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]}),
            "robot.links[2].hull: needs at least 4 points",
        ),
        (
            json!({"links": [{}, {"boxes": [{"center": [0, 0, 0], "size": [1, 0, 1]}]}, {}]}),
            "robot.links[1].boxes[0].size[1]: a box's size must be positive",
        ),
        (json!({"ignore": [[0, 3]]}), "robot.ignore[0][1]: must be a link"),
        (json!({"ignore": [[1, 1]]}), "robot.ignore[0]: pairs two different links"),
        (json!({"exempt": [7]}), "robot.exempt[0]: must be a link"),
        (json!({"tool": [0, 0]}), "robot.tool: must be a point [x, y, z]"),
        (json!({"metric": "chain"}), "robot.metric: must be joint"),
        (json!({"base": {"rotation": [0, 0]}}), "robot.base.rotation: must be angles"),
    ];
    for (extra, want) in cases {
        let err = Scenario::from_value(&scenario(5.0, extra.clone()))
            .err()
            .unwrap_or_else(|| panic!("{extra} parsed"))
            .to_string();
        assert!(err.contains(want), "{extra}: {err}");
    }
    let mut sc = scenario(5.0, json!({}));
    sc["obstacles3d"] = json!([{"hull": vec![[0.0, 0.0, 0.0]; 1025]}]);
    let err = Scenario::from_value(&sc).err().unwrap().to_string();
    assert!(err.contains("obstacles3d[0].hull: has 1025 points; the limit is 1024"), "{err}");
    sc["obstacles3d"] = json!([{"box": {"center": [0, 0, 0], "size": [1, 1, 1]}, "hull": []}]);
    assert!(Scenario::from_value(&sc).err().unwrap().to_string().contains("obstacles3d[0]: has both"));
    sc["obstacles3d"] = json!([{"sphere": 1}]);
    assert!(Scenario::from_value(&sc).err().unwrap().to_string().contains("obstacles3d[0]: needs a box or a hull"));
    sc["obstacles3d"] = json!([]);
    sc["obstacles"] = json!([{"rect": [0, 0, 1, 1]}]);
    assert!(Scenario::from_value(&sc).err().unwrap().to_string().contains("obstacles: a spatial arm moves in 3-D"));
    let mut point = json!({"bounds": [0, 0, 1, 1], "robot": {"kind": "point"}, "start": [0.1, 0.1], "goal": [0.9, 0.9],
        "obstacles3d": [{"box": {"center": [0, 0, 0], "size": [1, 1, 1]}}]});
    assert!(Scenario::from_value(&point).err().unwrap().to_string().contains("obstacles3d: only a spatial-arm robot"));
    point["obstacles3d"] = json!([]);
    assert!(Scenario::from_value(&point).is_ok());
}

#[test]
fn the_scenario_round_trips() {
    let sc = Scenario::from_value(&scenario(5.0, json!({"tool": [0.1, 0, 0], "exempt": [0]}))).unwrap();
    let again = Scenario::from_json(&sc.to_json()).unwrap();
    assert_eq!(sc, again);
}

#[test]
fn a_run_plans_around_the_wall() {
    // The wall at x ∈ [1.2, 2.2], |y| ≤ 2: from 1.5 rad to −1.5 rad the arm must fold its hand.
    let mut sc = scenario(1.2, json!({}));
    sc["obstacles3d"] = json!([{"name": "wall", "box": {"center": [1.7, 0, 0], "size": [1, 1.2, 4]}}]);
    sc["start"] = json!([1.5, 0]);
    sc["goal"] = json!([-1.5, 0]);
    sc["planner"] = json!({"name": "rrt-connect", "seed": 3});
    let p = problem(&sc);
    let spec = crate::planners::find("rrt-connect").unwrap();
    let params = crate::planners::Params::from_json(spec, &json!({})).unwrap();
    let config = crate::run::RunConfig { planner: "rrt-connect".into(), params, seed: 3, record_events: false };
    let mut s = crate::run::Session::new(problem(&sc), config).unwrap();
    assert_eq!(s.run_to_end(), crate::status::Status::Solved);
    let path = s.result().path;
    assert!(path.len() > 2, "the hand must fold: {path:?}");
    // Independently re-checked at a twentieth of the resolution.
    for w in path.windows(2) {
        let n = 200;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            let q: Vec<f64> = w[0].iter().zip(&w[1]).map(|(a, b)| a + t * (b - a)).collect();
            assert!(p.robot.is_valid(p.si.workspace(), &q), "{q:?}");
        }
    }
}

#[test]
fn clearance_is_the_gap_to_the_wall() {
    // At q = 0 the hand's far face is at x = 1.5: the wall's face 0.5 beyond it.
    let p = problem(&scenario(2.0, json!({})));
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let ws = p.si.workspace();
    let c = arm.clearance(ws, &[0.0, 0.0], 1.0).unwrap();
    assert!((c - 0.5).abs() < 1e-9, "{c}");
    assert_eq!(arm.clearance(ws, &[0.0, 0.0], 0.1), Some(0.1), "capped");
    // Touching (and past the limits) is no clearance at all.
    assert_eq!(arm.clearance(ws, &[3.5, 0.0], 1.0), Some(0.0));
    let p = problem(&scenario(1.5, json!({})));
    assert_eq!(arm.clearance(p.si.workspace(), &[0.0, 0.0], 1.0), Some(0.0));
}

/// The certificate the motion check rests on, on the Puma and its course scene: every state whose
/// arm moved less than a state's clearance from it (by the displacement bound) is free, and the
/// bound is never below how far the tool centre point really travels.
#[test]
fn puma_clearance_and_displacement_certify_motions() {
    let p = Problem::from_scenario(&crate::scenario::builtin("puma-rbo-wall").unwrap()).unwrap();
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let ws = p.si.workspace();
    let mut rng = crate::rng::Rng::new(7);
    let lims = arm.limits.clone();
    let draw = |rng: &mut crate::rng::Rng| -> Vec<f64> {
        lims.iter().map(|[lo, hi]| lo + (hi - lo) * rng.uniform01()).collect()
    };
    let (mut certified, mut near) = (0, 0);
    for _ in 0..300 {
        let a = draw(&mut rng);
        let c = arm.clearance(ws, &a, 0.2).unwrap();
        assert_eq!(c > 0.0, arm.is_valid(ws, &a));
        if c == 0.0 {
            continue;
        }
        near += (c < 0.2) as usize;
        let b = draw(&mut rng);
        // The furthest fraction towards b the bound certifies, and states up to it.
        let full = arm.displacement_bound(&a, &b).unwrap();
        let reach = (c / full).min(1.0);
        let mut last = arm.tool_point(&a);
        let mut travelled = 0.0;
        for i in 1..=40 {
            let t = reach * i as f64 / 40.0;
            let q: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x + t * (y - x)).collect();
            let tool = arm.tool_point(&q);
            travelled += (0..3).map(|k| (tool[k] - last[k]).powi(2)).sum::<f64>().sqrt();
            last = tool;
            assert!(travelled <= full * t + 1e-12, "the tool travelled {travelled} > bound {}", full * t);
            if t < reach {
                certified += 1;
                assert!(arm.is_valid(ws, &q), "a state within clearance {c} of a free state collides: {q:?}");
            }
        }
    }
    assert!(certified > 1000 && near > 20, "only {certified} states certified, {near} near the scene");
}

/// `m · v` for a 4×4 column-major matrix and a point.
fn apply(m: &[f64; 16], v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|r| m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r])
}

/// The 3-D view's data agrees with the collision query: every vertex of every part's mesh, moved
/// by its link's frame, is a vertex of the part as the query places it (and every vertex of the
/// placed part is one of the mesh's), at random states of the Puma; the last frame takes the tool
/// to the tool centre point; each link frame's origin is the skeleton's.
#[test]
fn meshes_moved_by_the_link_frames_are_where_the_kinematics_puts_the_parts() {
    for id in ["puma-rbo-wall", "puma-boxes"] {
        let p = Problem::from_scenario(&crate::scenario::builtin(id).unwrap()).unwrap();
        let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
        let meshes = arm.part_meshes();
        assert!(meshes.len() >= 7, "{id}: {} parts", meshes.len());
        let mut rng = crate::rng::Rng::new(3);
        for _ in 0..20 {
            let q: Vec<f64> = arm.limits.iter().map(|[lo, hi]| rng.uniform(*lo, *hi)).collect();
            let frames = arm.link_frames(&q);
            assert_eq!(frames.len(), q.len() + 1);
            let placed = arm.placed_vertices(&q);
            for (i, m) in meshes.iter().enumerate() {
                let drawn: Vec<[f64; 3]> = m.mesh.vertices.iter().map(|v| apply(&frames[m.link], *v)).collect();
                let near = |a: &[f64; 3], b: &[f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9);
                for d in &drawn {
                    assert!(placed[i].iter().any(|w| near(d, w)), "{id}: {}'s vertex {d:?} is not the query's", m.name);
                }
                for w in &placed[i] {
                    // a hull point inside a face is not a vertex of the hull's mesh: only the extreme ones
                    let on_hull = drawn.iter().any(|d| near(d, w));
                    assert!(
                        on_hull || m.mesh.vertices.len() < placed[i].len(),
                        "{id}: {}'s vertex {w:?} is not drawn",
                        m.name
                    );
                }
            }
            let tool = apply(frames.last().unwrap(), arm.tool());
            let tcp = arm.tool_point(&q);
            assert!(tool.iter().zip(tcp).all(|(a, b)| (a - b).abs() < 1e-12), "{tool:?} vs {tcp:?}");
            let skeleton = arm.skeleton_points(&q);
            for (f, s) in frames.iter().zip(&skeleton) {
                assert!((0..3).all(|k| (f[12 + k] - s[k]).abs() < 1e-12), "{f:?} vs {s:?}");
            }
        }
    }
}

/// Every triangle of every part's and obstacle's mesh faces outwards (its normal points away from
/// every other vertex: the solids are convex), none is degenerate, and a hull's mesh is closed
/// (each edge in two triangles, once each way).
#[test]
fn mesh_triangles_face_outwards() {
    use crate::geometry::mesh::Mesh;
    for id in ["puma-rbo-wall", "puma-boxes"] {
        let p = Problem::from_scenario(&crate::scenario::builtin(id).unwrap()).unwrap();
        let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
        let mut meshes: Vec<(String, Mesh)> = arm.part_meshes().into_iter().map(|m| (m.name, m.mesh)).collect();
        meshes.extend(p.si.workspace().solids.iter().map(|s| (s.name.clone(), Mesh::of_solid(s))));
        assert!(meshes.len() > 8);
        for (name, m) in &meshes {
            assert!(m.triangles.len() >= 4, "{id}: {name}");
            let mut edges = std::collections::HashSet::new();
            for t in &m.triangles {
                let n = m.normal(*t);
                let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                assert!(len > 1e-12, "{id}: {name}: a degenerate triangle {t:?}");
                let a = m.vertices[t[0] as usize];
                for v in &m.vertices {
                    let d = (0..3).map(|k| n[k] / len * (v[k] - a[k])).sum::<f64>();
                    assert!(d < 1e-9, "{id}: {name}: triangle {t:?} faces inwards ({d})");
                }
                for k in 0..3 {
                    assert!(edges.insert((t[k], t[(k + 1) % 3])), "{id}: {name}: edge twice the same way");
                }
            }
            assert!(edges.iter().all(|&(a, b)| edges.contains(&(b, a))), "{id}: {name}: the mesh is not closed");
        }
    }
    // A box's winding, by hand: its +z face's normal is +z.
    let b = Mesh::of_box([0.0; 3], [1.0, 2.0, 3.0]);
    assert_eq!(b.vertices.len(), 8);
    assert_eq!(b.triangles.len(), 12);
    let up = b.triangles.iter().filter(|t| t.iter().all(|&i| b.vertices[i as usize][2] == 3.0)).count();
    assert_eq!(up, 2);
    for t in b.triangles.iter().filter(|t| t.iter().all(|&i| b.vertices[i as usize][2] == 3.0)) {
        assert!(b.normal(*t)[2] > 0.0);
    }
}

/// The node log gives each added node's tool curve from its parent, ending at its own tool point,
/// and does not change the run: the same records and path with the log as without.
#[test]
fn the_tool_tree_follows_the_nodes_and_leaves_the_run_alone() {
    use crate::run::{RunConfig, Session};
    let sc = crate::scenario::builtin("puma-rbo-wall").unwrap();
    let config = || RunConfig {
        planner: "rrt-connect".into(),
        params: crate::planners::Params::from_json(crate::planners::find("rrt-connect").unwrap(), &json!({})).unwrap(),
        seed: 2,
        record_events: true,
    };
    let mut plain = Session::new(Problem::from_scenario(&sc).unwrap(), config()).unwrap();
    let mut logged = Session::new(Problem::from_scenario(&sc).unwrap(), config()).unwrap();
    logged.log_nodes(true);
    let (mut a, mut b, mut tree) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..20 {
        let (s1, s2) = (plain.step(20, f64::INFINITY), logged.step(20, f64::INFINITY));
        a.extend(plain.drain_events());
        b.extend(logged.drain_events());
        let log = logged.drain_nodes();
        tree.extend(logged.problem().tool_tree(&log));
        assert_eq!(s1, s2);
        if s1.is_finished() {
            break;
        }
    }
    assert_eq!(a, b, "the node log changes no record");
    assert_eq!(plain.planning_path(true), logged.planning_path(true));
    // Each NODE_ADDED record has its entry, in order, its last point its tool point.
    let added: Vec<&[f64]> = b
        .chunks_exact(crate::events::STRIDE)
        .filter(|r| r[0] == crate::events::EventKind::NodeAdded as u8 as f64)
        .collect();
    assert!(added.len() > 10, "{} nodes", added.len());
    let (mut at, mut n) = (0, 0);
    let arm = logged.problem();
    while at < tree.len() {
        let (t, id, k) = (tree[at], tree[at + 1], tree[at + 2] as usize);
        assert!((1..=crate::limits::MAX_TOOL_POINTS_PER_EDGE).contains(&k));
        let r = added[n];
        assert_eq!((t, id), (r[1], r[2]), "entry {n}");
        let last = &tree[at + 3 + 3 * (k - 1)..at + 6 + 3 * (k - 1)];
        // seen from above, the last point is the record's (x, y): the tool's projection
        assert!((last[0] - r[4]).abs() < 1e-12 && (last[1] - r[5]).abs() < 1e-12, "{last:?} vs {r:?}");
        if r[3] >= 0.0 {
            assert!(k > 1, "an edge has its parent's end too");
            let first = &tree[at + 3..at + 6];
            assert!((first[0] - r[6]).abs() < 1e-12 && (first[1] - r[7]).abs() < 1e-12, "starts at the parent's tool");
        }
        at += 3 + 3 * k;
        n += 1;
    }
    assert_eq!(n, added.len());
    assert!(arm.robot.spatial().is_some());
}

/// A suspended batch's records go, and their node log entries with them; records drained before
/// are counted, so the entries kept are the right ones.
#[test]
fn the_node_log_follows_truncation() {
    use crate::events::{EventKind, EventLog};
    let mut log = EventLog::new(true);
    log.log_nodes(2);
    let p = crate::math::Vec2::new(0.0, 0.0);
    let add =
        |log: &mut EventLog, id: i64| log.push(EventKind::NodeAdded, 0, id, 0, p, p, &[id as f64, 0.0], &[0.0, 0.0]);
    add(&mut log, 1);
    log.at(EventKind::Sample, 0, p, &[0.0, 0.0]);
    assert_eq!(log.drain().len(), 2 * crate::events::STRIDE);
    add(&mut log, 2);
    log.at(EventKind::Sample, 0, p, &[0.0, 0.0]);
    add(&mut log, 3);
    log.truncate(2); // record 4 (node 3) goes
    let n = log.drain_nodes();
    let ids: Vec<f64> = n.data.chunks_exact(n.stride()).map(|e| e[2]).collect();
    assert_eq!(ids, [1.0, 2.0]);
    let records: Vec<f64> = n.data.chunks_exact(n.stride()).map(|e| e[0]).collect();
    assert_eq!(records, [0.0, 2.0]);
}

/// A range of 0 means the kind's own default for a spatial arm (OMPL's 0.2 × the extent is
/// 2.8 rad on the Puma, too long a step to thread its window), OMPL's for the others.
#[test]
fn the_default_range_is_the_kinds() {
    use crate::planners::rrt::resolve_range;
    let puma = Problem::from_scenario(&crate::scenario::builtin("puma-rbo-wall").unwrap()).unwrap();
    assert!(0.2 * puma.si.space.max_extent() > 2.5);
    assert_eq!(resolve_range(&puma.si, 0.0), 0.2);
    assert_eq!(resolve_range(&puma.si, 0.05), 0.05);
    let narrow = Problem::from_scenario(&crate::scenario::builtin("narrow").unwrap()).unwrap();
    assert_eq!(resolve_range(&narrow.si, 0.0), 0.2 * narrow.si.space.max_extent());
}

#[test]
fn answers_read_back_from_the_last_placement_are_a_fresh_querys() {
    // A recorded run asks again about the state a check just found blocked (the collision's
    // verdict, its contact) and projects the state just checked: those read the query's placement
    // and answer instead of computing them again, and must give what a fresh arm gives, bit for bit.
    let p = Problem::from_scenario(&crate::scenario::builtin("puma-rbo-wall").unwrap()).unwrap();
    let arm = SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let ws = p.si.workspace();
    let fresh = || SpatialArmRobot::from_spec(&p.scenario.robot).unwrap();
    let mut rng = crate::rng::Rng::new(11);
    let draw = |rng: &mut crate::rng::Rng| -> Vec<f64> {
        arm.limits.iter().map(|[lo, hi]| lo + (hi - lo) * rng.uniform01()).collect()
    };
    let (mut blocked, mut free) = (0, 0);
    for _ in 0..200 {
        let q = draw(&mut rng);
        let valid = arm.is_valid(ws, &q);
        let bits = |p: [f64; 3]| p.map(f64::to_bits);
        assert_eq!(bits(arm.tool_point(&q)), bits(fresh().chain.point_on_last(&q, &arm.tool)));
        assert_eq!(arm.verdict(ws, &q), fresh().verdict(ws, &q));
        assert_eq!(arm.describe_collision(ws, &q), fresh().describe_collision(ws, &q));
        let (a, b) = (arm.contact(ws, &q), fresh().contact(ws, &q));
        assert_eq!(
            a.map(|c| (c.link, c.other, c.solid, bits(c.at))),
            b.map(|c| (c.link, c.other, c.solid, bits(c.at)))
        );
        // (not the clearance: its gaps are measured from where the last tests' GJK ended)
        if valid {
            free += 1;
        } else {
            blocked += 1;
        }
    }
    assert!(blocked > 10 && free > 10, "{blocked} blocked, {free} free states drawn");
    // The answer belongs to its scene: the same state against a scene without the wall is asked anew.
    let mut bare = ws.clone();
    bare.solids.clear();
    let q = (0..500).map(|_| draw(&mut rng)).find(|q| matches!(arm.verdict(ws, q), Verdict::Collision(_))).unwrap();
    assert!(!matches!(arm.verdict(&bare, &q), Verdict::Collision(_)), "an empty scene has nothing to hit");
    assert!(matches!(arm.verdict(ws, &q), Verdict::Collision(_)));
}
