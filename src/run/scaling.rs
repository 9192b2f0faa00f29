//! The suite's scaling benchmark: the cost of one state check among 10 to 100,000
//! obstacles, for the point, a rigid rectangle and a 3-link arm. The map is a 2 × 1 box whose right
//! half holds `n` small blocks in a grid; the states are uniform (valid or not), drawn from a fixed
//! seed, so every run checks the same states and counts the same valid ones (native and wasm alike).
//!
//! `planarium scaling` runs it natively, `scaling_json` in wasm (`npm run bench` does both), and the
//! criterion group `scaling` in `benches/core.rs` times the same maps.

use crate::clock::Instant;
use crate::geometry::Workspace;
use crate::problem::Problem;
use crate::rng::Rng;
use crate::scenario::Scenario;
use serde::Serialize;

/// The obstacle counts measured.
pub const SIZES: [usize; 5] = [10, 100, 1000, 10_000, 100_000];

/// A 2 × 1 map whose right half holds `n` small blocks in a grid, with `robot` (JSON) starting at
/// `start` in the free left half.
pub fn blocks(n: usize, robot: serde_json::Value, start: serde_json::Value) -> Problem {
    let side = (n as f64).sqrt().ceil() as usize;
    let cell = 1.0 / side as f64;
    let mut obstacles = Vec::with_capacity(n);
    'grid: for i in 0..side {
        for j in 0..side {
            if obstacles.len() == n {
                break 'grid;
            }
            let (x, y) = (1.0 + i as f64 * cell, j as f64 * cell);
            obstacles
                .push(serde_json::json!({ "rect": [x + 0.3 * cell, y + 0.3 * cell, x + 0.7 * cell, y + 0.7 * cell] }));
        }
    }
    let v = serde_json::json!({ "bounds": [0, 0, 2, 1], "obstacles": obstacles, "robot": robot, "start": start, "goal": start, "resolution": 0.002 });
    Problem::from_scenario(&Scenario::from_value(&v).expect("a valid scenario")).expect("a valid problem")
}

/// The robots, each with a start in the free half: `(name, robot, start)`.
pub fn robots() -> [(&'static str, serde_json::Value, serde_json::Value); 3] {
    let pi = std::f64::consts::PI;
    [
        ("point", serde_json::json!({ "kind": "point" }), serde_json::json!([0.5, 0.5])),
        (
            "rectangle",
            serde_json::json!({ "kind": "rigid", "footprint": [[-0.05, -0.01], [0.05, -0.01], [0.05, 0.01], [-0.05, 0.01]] }),
            serde_json::json!([0.5, 0.5, 0.0]),
        ),
        (
            "arm",
            serde_json::json!({ "kind": "arm", "base": [1.0, 0.5], "links": [0.25, 0.2, 0.15], "limits": [[-pi, pi], [-pi, pi], [-pi, pi]] }),
            serde_json::json!([pi, 0.0, 0.0]),
        ),
    ]
}

/// `n` uniform states (valid or not) from seed `seed`.
pub fn uniform_states(p: &Problem, n: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let mut q = vec![0.0; p.si.dims()];
            p.si.sample(&mut rng, &mut q);
            q
        })
        .collect()
}

/// One robot among `obstacles` obstacles.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    /// The robot's name in [`robots`].
    pub robot: String,
    /// How many obstacles.
    pub obstacles: usize,
    /// Nanoseconds per state check (the best of the rounds).
    pub ns_per_check: f64,
    /// This row's time per check over the 10-obstacle row's.
    pub ratio_to_10: f64,
    /// Valid states among the checks (the same in every run, native or wasm).
    pub valid: u64,
    /// Milliseconds to build the workspace's broad phase (boxes, hierarchy, grid) from its obstacles.
    pub build_ms: f64,
    /// Bytes of the broad phase (boxes, hierarchy, grid).
    pub broad_phase_bytes: usize,
}

/// Time `checks` state checks (cycling over 1024 uniform states), best of `rounds`, for each robot
/// named in `only` (all when empty) and each obstacle count in `sizes`.
pub fn measure(only: &[String], sizes: &[usize], checks: u64, rounds: u32) -> Vec<Row> {
    let mut rows = Vec::new();
    for (robot, spec, start) in robots() {
        if !only.is_empty() && !only.iter().any(|o| o == robot) {
            continue;
        }
        let mut first: Option<f64> = None;
        for &n in sizes {
            let p = blocks(n, spec.clone(), start.clone());
            let ws = p.si.workspace();
            let t = Instant::now();
            let built = Workspace::new(ws.bounds, ws.obstacles.clone());
            let build_ms = t.elapsed().as_secs_f64() * 1000.0;
            let states = uniform_states(&p, 1024, 5);
            // An untimed pass first (caches, the processor's clock).
            let warm = states.iter().take(checks as usize).filter(|q| p.si.is_valid(q)).count();
            let (mut best, mut valid) = (f64::INFINITY, warm as u64);
            for _ in 0..rounds.max(1) {
                let t = Instant::now();
                valid = (0..checks).filter(|&k| p.si.is_valid(&states[k as usize % states.len()])).count() as u64;
                best = best.min(t.elapsed().as_secs_f64() * 1e9 / checks.max(1) as f64);
            }
            let base = *first.get_or_insert(best);
            rows.push(Row {
                robot: robot.into(),
                obstacles: n,
                ns_per_check: best,
                ratio_to_10: best / base,
                valid,
                build_ms,
                broad_phase_bytes: built.broad_phase_bytes(),
            });
        }
    }
    rows
}

/// The rows as a Markdown table.
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "| robot | obstacles | ns / check | × the first | valid | build ms | broad phase kB |\n|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        s += &format!(
            "| {} | {} | {:.1} | {:.2} | {} | {:.2} | {:.0} |\n",
            r.robot,
            r.obstacles,
            r.ns_per_check,
            r.ratio_to_10,
            r.valid,
            r.build_ms,
            r.broad_phase_bytes as f64 / 1024.0
        );
    }
    s
}
