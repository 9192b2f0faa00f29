//! Property-based pass over generated inputs (issue 13), run by `cargo test --release` and so by
//! `npm test`. Every case is made from its own seed by the crate's seeded generator, so a failure
//! is repeated with `PLANARIUM_PROPS_ONLY=<seed>` (which also prints the input).
//!
//! Inputs: valid scenarios of every robot kind (point, rigid, arm, asv) with random obstacles of
//! every kind; the same with hostile mutations (extreme numbers, wrong types, missing, unknown and
//! duplicated keys, long arrays, huge counts and strings, deep nesting, tiny resolutions); and text
//! mutations of the course files (Technion maps, ASV problem files) and built-in scenarios read
//! through `io::import`. A share of the inputs that become problems is planned with a small
//! budget (any planner of the registry).
//!
//! Asserted for every input (see `tests/fuzz_harness/mod.rs`): no panic; every rejection names
//! where (a JSON path, or a line and column); an accepted scenario reads back equal from its JSON;
//! a run with time limit `T` ends within `T` + 0.1 s (wall time from `Session::new` through the
//! result and the page's path frames); no run exceeds its iteration or node limit; a solved ASV
//! run's solution file passes the checker.
//!
//! The cases run in worker processes (the ignored test `worker`, started by the test itself): a
//! case that aborts the process (an allocation failure, which Rust cannot catch) or hangs (still
//! running after `WATCHDOG_S` seconds) is recorded with its seed, and a new worker goes on after it.
// Worker processes and files: native only (wasm-pack test builds every test for wasm32).
#![cfg(not(target_arch = "wasm32"))]

mod fuzz_harness;

use fuzz_harness as h;
use planarium::rng::Rng;
use serde_json::{json, Value};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Cases per run (each one input; some also planned).
const CASES: u64 = 12_000;
/// The first case's seed; case `i` uses `BASE_SEED + i`.
const BASE_SEED: u64 = 0x1513_0000;
/// A case running longer than this is a hang: the test ends with its seed.
const WATCHDOG_S: u64 = 20;

const EXTREMES: &[f64] = &[
    1e308,
    -1e308,
    -9.2e18,
    9.2e18,
    5e-324,
    -5e-324,
    1e-12,
    2e-12,
    1e-9,
    1.8e19,
    -1.8e19,
    0.0,
    -0.0,
    -1.0,
    1e15,
    4294967296.0,
    1.8446744073709552e19,
    1e-300,
    3.0e38,
];

fn pick<'a, T>(rng: &mut Rng, xs: &'a [T]) -> &'a T {
    &xs[rng.below(xs.len())]
}

fn chance(rng: &mut Rng, p: f64) -> bool {
    rng.uniform01() < p
}

// ---------------------------------------------------------------- valid scenarios

struct Frame {
    x0: f64,
    y0: f64,
    w: f64,
    h: f64,
}

impl Frame {
    fn point(&self, rng: &mut Rng) -> [f64; 2] {
        [self.x0 + rng.uniform(0.0, self.w), self.y0 + rng.uniform(0.0, self.h)]
    }
    fn extent(&self) -> f64 {
        self.w.max(self.h)
    }
}

/// A simple (star-shaped) polygon of `k` points around `c`, radii in `[r/3, r]`.
fn star(rng: &mut Rng, c: [f64; 2], r: f64, k: usize) -> Vec<[f64; 2]> {
    let mut angles: Vec<f64> =
        (0..k).map(|i| (i as f64 + rng.uniform(0.1, 0.9)) * std::f64::consts::TAU / k as f64).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|a| [c[0] + r * rng.uniform(0.34, 1.0) * a.cos(), c[1] + r * rng.uniform(0.34, 1.0) * a.sin()])
        .collect()
}

fn obstacle(rng: &mut Rng, f: &Frame) -> Value {
    let s = f.extent();
    match rng.below(4) {
        0 => {
            let a = f.point(rng);
            let b = [a[0] + rng.uniform(0.01, 0.3) * s, a[1] + rng.uniform(0.01, 0.3) * s];
            json!({"rect": [a[0], a[1], b[0], b[1]]})
        }
        1 => {
            let c = f.point(rng);
            json!({"circle": [c[0], c[1], rng.uniform(0.01, 0.15) * s]})
        }
        2 => {
            let a = f.point(rng);
            let b = f.point(rng);
            json!({"segment": [a[0], a[1], b[0], b[1]]})
        }
        _ => {
            let c = f.point(rng);
            let k = 3 + rng.below(6);
            let r = rng.uniform(0.02, 0.2) * s;
            json!({"polygon": star(rng, c, r, k)})
        }
    }
}

fn angle(rng: &mut Rng) -> f64 {
    rng.uniform(-std::f64::consts::PI, std::f64::consts::PI)
}

/// A valid scenario document of robot kind `kind` (0 point, 1 rigid, 2 arm, 3 asv); its start
/// and goal may still collide (the problem then says which).
fn valid_scenario(rng: &mut Rng, kind: usize) -> Value {
    let f = if kind == 3 {
        Frame { x0: 0.0, y0: 0.0, w: 1.0, h: 1.0 }
    } else {
        let s = *pick(rng, &[1.0, 2.0, 10.0, 300.0]);
        Frame {
            x0: rng.uniform(-s, s),
            y0: rng.uniform(-s, s),
            w: s * rng.uniform(0.5, 2.0),
            h: s * rng.uniform(0.5, 2.0),
        }
    };
    let s = f.extent();
    let n_obstacles = rng.below(9);
    let obstacles: Vec<Value> = (0..n_obstacles).map(|_| obstacle(rng, &f)).collect();
    let mut inspection = None;
    let (robot, start, goal, resolution) = match kind {
        0 => (json!({"kind": "point"}), f.point(rng).to_vec(), f.point(rng).to_vec(), s * rng.uniform(0.001, 0.01)),
        1 => {
            let k = 3 + rng.below(5);
            let r = rng.uniform(0.01, 0.08) * s;
            let mut robot = json!({"kind": "rigid", "footprint": star(rng, [0.0, 0.0], r, k)});
            if chance(rng, 0.3) {
                robot["rotation_weight"] = json!(rng.uniform(0.01, 2.0) * r);
            }
            let (a, b) = (f.point(rng), f.point(rng));
            (robot, vec![a[0], a[1], angle(rng)], vec![b[0], b[1], angle(rng)], s * rng.uniform(0.001, 0.01))
        }
        2 => {
            let n = 1 + rng.below(5);
            let reach = 0.45 * f.w.min(f.h);
            let links: Vec<f64> = (0..n).map(|_| reach / n as f64 * rng.uniform(0.5, 1.0)).collect();
            let limits: Vec<Value> = (0..n)
                .map(|_| {
                    if chance(rng, 0.5) {
                        Value::Null
                    } else {
                        let lo = rng.uniform(-3.0, 0.0);
                        json!([lo, lo + rng.uniform(0.5, 3.0)])
                    }
                })
                .collect();
            let in_limits = |rng: &mut Rng, l: &Value| match l.as_array() {
                Some(a) => rng.uniform(a[0].as_f64().unwrap(), a[1].as_f64().unwrap()),
                None => angle(rng),
            };
            let start: Vec<f64> = limits.iter().map(|l| in_limits(rng, l)).collect();
            let goal: Vec<f64> = limits.iter().map(|l| in_limits(rng, l)).collect();
            let mut robot = json!({"kind": "arm", "base": [f.x0 + f.w / 2.0, f.y0 + f.h / 2.0], "links": links,
                                   "metric": pick(rng, &["joint", "chain", "max"]), "self_collision": chance(rng, 0.7)});
            if chance(rng, 0.6) {
                robot["limits"] = Value::Array(limits);
            } else {
                robot["limits"] = Value::Null;
            }
            if chance(rng, 0.2) {
                robot["tip"] = json!(0.001);
            }
            if chance(rng, 0.25) {
                inspection = Some(json!({"points": (0..1 + rng.below(6)).map(|_| f.point(rng)).collect::<Vec<_>>(),
                                         "fov": rng.uniform(0.1, 3.0), "range": rng.uniform(0.1, 2.0) * s, "coverage": rng.uniform01()}));
            }
            (robot, start, goal, rng.uniform(0.005, 0.05))
        }
        _ => {
            let n = 3 + rng.below(6);
            let broom = 0.05;
            let r = broom / (2.0 * (std::f64::consts::PI / n as f64).sin());
            let chain = |rng: &mut Rng| -> Vec<f64> {
                let c = [rng.uniform(r + 0.01, 1.0 - r - 0.01), rng.uniform(r + 0.01, 1.0 - r - 0.01)];
                let a0 = angle(rng);
                let flip = if chance(rng, 0.5) { 1.0 } else { -1.0 };
                (0..n)
                    .flat_map(|i| {
                        let a = a0 + flip * i as f64 * std::f64::consts::TAU / n as f64;
                        [c[0] + r * a.cos(), c[1] + r * a.sin()]
                    })
                    .collect()
            };
            let robot = json!({"kind": "asv", "count": n, "broom": broom, "max_step": 0.001});
            (robot, chain(rng), chain(rng), 0.001)
        }
    };
    let mut doc = json!({
        "format": "planarium-scenario/1",
        "name": format!("generated {kind}"),
        "bounds": [f.x0, f.y0, f.x0 + f.w, f.y0 + f.h],
        "obstacles": obstacles,
        "robot": robot,
        "start": start,
        "resolution": resolution,
    });
    if let Some(i) = inspection {
        doc["inspection"] = i;
        if chance(rng, 0.5) {
            doc["planner"] = json!({"name": "inspection"});
        }
    } else {
        doc["goal"] = json!(goal);
    }
    if doc.get("goal").is_some() && chance(rng, 0.3) {
        doc["goal_tolerance"] = json!(rng.uniform(0.0, 0.05) * s);
    }
    if chance(rng, 0.3) {
        doc["touching_allowed"] = json!(chance(rng, 0.5));
    }
    if chance(rng, 0.3) {
        doc["body_in_bounds"] = json!(chance(rng, 0.5));
    }
    if chance(rng, 0.3) && doc.get("planner").is_none() {
        let names = h::planner_names();
        doc["planner"] = json!({"name": pick(rng, &names), "seed": rng.below(1000)});
    }
    doc
}

// ---------------------------------------------------------------- hostile mutations

/// Paths (as index lists) to every node of `v`.
fn nodes(v: &Value, at: &mut Vec<Vec<Key>>, here: &mut Vec<Key>) {
    at.push(here.clone());
    match v {
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                here.push(Key::I(i));
                nodes(x, at, here);
                here.pop();
            }
        }
        Value::Object(m) => {
            for (k, x) in m {
                here.push(Key::K(k.clone()));
                nodes(x, at, here);
                here.pop();
            }
        }
        _ => {}
    }
}

#[derive(Clone, Debug)]
enum Key {
    I(usize),
    K(String),
}

fn node_mut<'a>(v: &'a mut Value, path: &[Key]) -> &'a mut Value {
    path.iter().fold(v, |v, k| match k {
        Key::I(i) => &mut v[*i],
        Key::K(s) => &mut v[s.as_str()],
    })
}

fn node_ref<'a>(v: &'a Value, path: &[Key]) -> &'a Value {
    path.iter().fold(v, |v, k| match k {
        Key::I(i) => &v[*i],
        Key::K(s) => &v[s.as_str()],
    })
}

/// A string value `"<DEEP>n"` is written as `n` nested arrays.
const DEEP: &str = "__deep__";

fn splice_deep(text: String) -> String {
    let Some(at) = text.find(&format!("\"{DEEP}")) else {
        return text;
    };
    let rest = &text[at + 1 + DEEP.len()..];
    let end = rest.find('"').unwrap_or(0);
    let depth: usize = rest[..end].parse().unwrap_or(1);
    format!("{}{}1{}{}", &text[..at], "[".repeat(depth), "]".repeat(depth), &rest[end + 1..])
}

fn deep(depth: usize) -> Value {
    (0..depth).fold(json!(1), |v, _| json!([v]))
}

/// Change `doc` in one hostile way; may return text directly (for duplicated keys).
fn mutate(rng: &mut Rng, doc: &mut Value) {
    if !doc.is_object() {
        return;
    }
    let mut all = Vec::new();
    nodes(doc, &mut all, &mut Vec::new());
    let numbers: Vec<&Vec<Key>> = all.iter().filter(|p| node_ref(doc, p).is_number()).collect();
    match rng.below(12) {
        0..=2 if !numbers.is_empty() => {
            let p = (*pick(rng, &numbers)).clone();
            *node_mut(doc, &p) = json!(*pick(rng, EXTREMES));
        }
        3 => {
            let p = pick(rng, &all).clone();
            *node_mut(doc, &p) = pick(
                rng,
                &[json!("x"), json!(true), Value::Null, json!({}), json!([]), json!([[1, 2]]), json!(-1), json!(1.5)],
            )
            .clone();
        }
        4 => {
            let objects: Vec<&Vec<Key>> = all.iter().filter(|p| node_ref(doc, p).is_object()).collect();
            let p = (*pick(rng, &objects)).clone();
            if let Value::Object(m) = node_mut(doc, &p) {
                if !m.is_empty() {
                    let k = m.keys().nth(rng.below(m.len())).unwrap().clone();
                    if chance(rng, 0.7) {
                        m.remove(&k);
                    } else {
                        m.insert(format!("{k}_"), json!(1));
                    }
                }
            }
        }
        5 => {
            let k = rng.below(4);
            let r = 0.001 * rng.uniform01();
            match k {
                0 => doc["resolution"] = json!(*pick(rng, &[1e-12, 2e-12, 1e-9, 1e-7, 5e-324])),
                1 => doc["resolution"] = json!(r),
                2 => {
                    if let Some(Value::Array(b)) = doc.get_mut("bounds") {
                        if !b.is_empty() {
                            b[0] = json!(*pick(rng, &[-9.2e18, -1e308, -1e15]));
                        }
                    }
                }
                _ => {
                    if let Some(Value::Array(g)) = doc.get_mut("goal") {
                        if let Some(last) = g.last_mut() {
                            *last = json!(*pick(rng, &[1.8e19, 1e308, -9.2e18, 1e15]));
                        }
                    }
                }
            }
        }
        6 => {
            // Long arrays.
            let n = *pick(rng, &[1000usize, 5000, 20_000]);
            match rng.below(4) {
                0 => {
                    doc["obstacles"] =
                        Value::Array((0..n).map(|i| json!({"circle": [i as f64 * 1e-3, 0.5, 1e-4]})).collect())
                }
                1 => doc["obstacles"] = json!([{"polygon": star(rng, [0.5, 0.5], 0.1, n)}]),
                2 => {
                    let k = n / 10;
                    doc["robot"] = json!({"kind": "arm", "links": vec![0.5 / k as f64; k]});
                    doc["start"] = json!(vec![0.01; k]);
                    doc["goal"] = json!(vec![0.02; k]);
                }
                _ => doc["start"] = json!(vec![0.5; n]),
            }
        }
        7 => {
            // Huge counts.
            doc["robot"] = json!({"kind": "asv", "count": *pick(rng, &[1_000_000u64, 1u64 << 40, u64::MAX, 100_000])});
        }
        8 => doc["name"] = json!("n".repeat(*pick(rng, &[10_000usize, 1_000_000]))),
        // Deep nesting is spliced into the text at the end (see `DEEP`): walking it here is slow.
        9 => doc["notes"] = json!(format!("{DEEP}{}", *pick(rng, &[10usize, 100, 127, 128, 129, 500, 5000]))),
        10 => {
            if let Value::Object(m) = doc {
                m.insert("planner".into(), json!({"name": pick(rng, &h::planner_names()), "max_nodes": 1e8, "time_limit": 3600, "max_iterations": 1e9}));
            }
        }
        _ => {
            let p = pick(rng, &all).clone();
            let replacement = deep(1 + rng.below(40));
            *node_mut(doc, &p) = replacement;
        }
    }
}

/// The scenario text with one top-level key written twice (serde_json keeps the last).
fn duplicate_key(rng: &mut Rng, doc: &Value) -> String {
    let text = doc.to_string();
    let keys: Vec<&String> = doc.as_object().map(|m| m.keys().collect()).unwrap_or_default();
    if keys.is_empty() {
        return text;
    }
    let k = pick(rng, &keys);
    let values = [json!(0), json!("dup"), json!([0, 0, 1, 1]), Value::Null];
    let v = pick(rng, &values);
    format!("{{\"{k}\": {v}, {}", &text[1..])
}

// ---------------------------------------------------------------- course files

const COURSE_FILES: &[&str] = &[
    include_str!("../fuzz/corpus/technion/map_ip.json"),
    include_str!("../fuzz/corpus/technion/map_mp.json"),
    include_str!("../fuzz/corpus/asv_problem/3ASV-easy.txt"),
    include_str!("../fuzz/corpus/asv_problem/3ASV.txt"),
    include_str!("../fuzz/corpus/asv_problem/7ASV-easy.txt"),
    include_str!("../fuzz/corpus/asv_problem/7ASV.txt"),
    include_str!("../scenarios/slot.json"),
    include_str!("../scenarios/arm-2.json"),
    include_str!("../scenarios/open-field.json"),
];

const TOKENS: &[&str] = &[
    "1e308",
    "-9.2e18",
    "5e-324",
    "1e-12",
    "18446744073709551615",
    "99999999999",
    "-1",
    "0",
    "NaN",
    "inf",
    "x",
    "\n",
    " ",
    "[",
    "]",
    "{",
    "}",
    ",",
    "\"",
    ":",
    "null",
    "1e400",
    "\u{0}",
    "é",
];

fn text_mutation(rng: &mut Rng) -> String {
    let mut t: Vec<u8> = pick(rng, COURSE_FILES).as_bytes().to_vec();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(t.len() + 1);
        match rng.below(7) {
            0 if at < t.len() => t[at] = *pick(rng, b"0123456789-.eE \n{}[],:\"x"),
            1 => {
                let end = (at + rng.below(20)).min(t.len());
                t.drain(at..end);
            }
            2 => {
                let end = (at + rng.below(40)).min(t.len());
                let piece = t[at..end].to_vec();
                t.splice(at..at, piece);
            }
            3 => {
                let tok = pick(rng, TOKENS).as_bytes().to_vec();
                t.splice(at..at, tok);
            }
            4 => {
                // Replace the number starting at or after `at` by an extreme one.
                if let Some(s) = (at..t.len()).find(|&i| t[i].is_ascii_digit()) {
                    let e = (s..t.len()).find(|&i| !(t[i].is_ascii_digit() || t[i] == b'.')).unwrap_or(t.len());
                    let tok = pick(rng, TOKENS[..6].as_ref()).as_bytes().to_vec();
                    t.splice(s..e, tok);
                }
            }
            5 => t.truncate(at),
            _ => {
                // A huge first line (the vehicle count of an ASV file).
                if !t.starts_with(b"{") {
                    let n = pick(rng, &["1000000000", "18446744073709551615", "4611686018427387904", "100000"])
                        .as_bytes()
                        .to_vec();
                    let end = t.iter().position(|&b| b == b'\n').unwrap_or(t.len());
                    t.splice(0..end, n);
                }
            }
        }
    }
    String::from_utf8_lossy(&t).into_owned()
}

// ---------------------------------------------------------------- one case

/// The input of case `seed`, and whether to plan it (with which budget).
fn make_case(seed: u64) -> (String, Option<h::Budget>) {
    let mut rng = Rng::new(seed);
    let text = match rng.below(100) {
        0..=34 => valid_scenario(&mut rng, (seed % 4) as usize).to_string(),
        35..=74 => {
            let mut doc = valid_scenario(&mut rng, (seed % 4) as usize);
            for _ in 0..1 + rng.below(3) {
                mutate(&mut rng, &mut doc);
            }
            splice_deep(if chance(&mut rng, 0.15) { duplicate_key(&mut rng, &doc) } else { doc.to_string() })
        }
        _ => text_mutation(&mut rng),
    };
    let budget = chance(&mut rng, 0.45).then(|| h::Budget {
        planner: rng.below(64),
        seed: rng.next_u64() % 1000,
        time_s: *pick(&mut rng, &[0.01, 0.02, 0.05]),
        iterations: 1 + rng.below(2000) as u64,
        nodes: 2 + rng.below(2000) as u64,
        shortcuts: rng.below(50) as u64,
        events: chance(&mut rng, 0.5),
    });
    (text, budget)
}

/// What happened to one case (`Err`: the property broken).
fn run_case(text: &str, budget: Option<h::Budget>) -> Result<Option<h::RunReport>, String> {
    let outcome = h::check_import(text)?;
    match (outcome, budget) {
        (h::Outcome::Problem(p), Some(b)) => h::plan(*p, &b),
        _ => Ok(None),
    }
}

/// Whether a run ended within its time limit + `TIME_SLACK_S`.
fn in_time(r: &h::RunReport, b: &h::Budget) -> bool {
    r.wall_s <= b.time_s + h::TIME_SLACK_S
}

/// The minimised inputs of past findings, `fuzz/regressions/<target>/<file>`, sorted.
fn regression_files() -> Vec<(String, std::path::PathBuf)> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions");
    let mut out = Vec::new();
    for target in ["scenario", "technion", "asv_problem", "asv_solution", "plan"] {
        let Ok(dir) = std::fs::read_dir(root.join(target)) else {
            continue;
        };
        let mut files: Vec<_> = dir.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_file()).collect();
        files.sort();
        out.extend(files.into_iter().map(|f| (target.to_string(), f)));
    }
    out
}

/// One regression input through its fuzz target's checks (as `fuzz/fuzz_targets/<target>.rs`
/// does, but with the 0.1 s slack on the time limit).
fn run_regression(target: &str, data: &[u8]) -> Result<Option<(h::RunReport, h::Budget)>, String> {
    let text = String::from_utf8_lossy(data);
    match target {
        "scenario" => h::check_scenario(&text).map(|_| None),
        "technion" => h::check_technion(&text).map(|_| None),
        "asv_problem" => h::check_asv_problem(&text).map(|_| None),
        "asv_solution" => {
            let (problem, solution) = match text.split_once("\n===\n") {
                Some((p, s)) => (p.to_string(), s),
                None => (planarium::scenario::builtin("asv-3-easy").expect("built-in").to_json(), &*text),
            };
            h::check_asv_solution(&problem, solution).map(|_| None)
        }
        "plan" if data.len() >= 8 => {
            let b = h::Budget::from_bytes(&data[..8]);
            Ok(run_case(&String::from_utf8_lossy(&data[8..]), Some(b))?.map(|r| (r, b)))
        }
        _ => Ok(None),
    }
}

static CURRENT: AtomicU64 = AtomicU64::new(u64::MAX);
static PANIC: Mutex<Option<String>> = Mutex::new(None);

fn seed_file_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz_props.{}.last-seed", std::process::id()))
}

/// The worker: runs cases `from..to` in this process and reports on stdout, one line each:
/// `FAIL <seed> <message>` per broken property, `RUN <seed> <wall s> <time limit s>` per planned
/// run, and `DONE` at the end. A case that aborts the process (an allocation failure) or hangs
/// (the watchdog ends the process after `WATCHDOG_S`) leaves its seed in `PLANARIUM_PROPS_SEED_FILE`
/// for the parent, which records it and starts a new worker after it.
#[test]
#[ignore = "run by generated_inputs_keep_the_properties in a child process"]
fn worker() {
    use std::io::Write;
    let var = |k: &str| {
        std::env::var(k)
            .unwrap_or_else(|_| panic!("{k} not set: this test is run by generated_inputs_keep_the_properties"))
    };
    let (from, to): (u64, u64) =
        (var("PLANARIUM_PROPS_FROM").parse().unwrap(), var("PLANARIUM_PROPS_TO").parse().unwrap());
    let verbose = std::env::var_os("PLANARIUM_PROPS_VERBOSE").is_some();
    let regressions = std::env::var_os("PLANARIUM_PROPS_REGRESSIONS").is_some().then(regression_files);
    let seed_file = std::fs::File::create(var("PLANARIUM_PROPS_SEED_FILE")).expect("seed file");
    std::panic::set_hook(Box::new(|info| {
        *PANIC.lock().unwrap_or_else(|e| e.into_inner()) = Some(info.to_string().replace('\n', " "));
    }));
    static STARTED: Mutex<Option<Instant>> = Mutex::new(None);
    std::thread::spawn(|| loop {
        std::thread::sleep(Duration::from_millis(200));
        let since = STARTED.lock().map(|t| t.map(|t| t.elapsed())).unwrap_or_default();
        if since.is_some_and(|d| d > Duration::from_secs(WATCHDOG_S)) {
            let seed = CURRENT.load(Ordering::SeqCst);
            let _ = writeln!(std::io::stdout(), "HANG {seed} still running after {WATCHDOG_S} s");
            let _ = std::io::stdout().flush();
            std::process::exit(3);
        }
    });
    let mut out = std::io::stdout().lock();
    for seed in from..to {
        {
            use std::os::unix::fs::FileExt;
            let _ = seed_file.write_all_at(format!("{seed:020}\n").as_bytes(), 0);
        }
        CURRENT.store(seed, Ordering::SeqCst);
        *STARTED.lock().unwrap() = Some(Instant::now());
        let r = catch_unwind(AssertUnwindSafe(|| {
            if let Some(files) = &regressions {
                let (target, file) = &files[seed as usize];
                return run_regression(target, &std::fs::read(file).expect("regression file"));
            }
            let (text, budget) = make_case(seed);
            if verbose {
                let shown = if text.len() > 20_000 {
                    format!("{}… ({} bytes)", &text[..text.floor_char_boundary(20_000)], text.len())
                } else {
                    text.clone()
                };
                eprintln!("case {seed}: budget {budget:?}\n{shown}");
            }
            run_case(&text, budget).map(|r| r.map(|r| (r, budget.unwrap())))
        }));
        if let Some(t) = *STARTED.lock().unwrap() {
            if verbose || t.elapsed() > Duration::from_millis(100) {
                eprintln!("case {seed}: {:.3} s", t.elapsed().as_secs_f64());
            }
        }
        *STARTED.lock().unwrap() = None;
        // A run past its time limit + 0.1 s is run again: the machine is shared, and a run
        // preempted for a while is not the core's fault. Only an overrun that happens twice
        // breaks the property; a single one is reported (`STALL`) and counted by the parent.
        let r = match r {
            Ok(Ok(Some((first, b)))) if !in_time(&first, &b) => {
                let again = catch_unwind(AssertUnwindSafe(|| {
                    if let Some(files) = &regressions {
                        let (target, file) = &files[seed as usize];
                        return run_regression(target, &std::fs::read(file).expect("regression file"));
                    }
                    let (text, budget) = make_case(seed);
                    run_case(&text, budget).map(|r| r.map(|r| (r, budget.unwrap())))
                }));
                match again {
                    Ok(Ok(Some((second, _)))) if in_time(&second, &b) => {
                        writeln!(
                            out,
                            "STALL {seed} {:.6} {:.6} {} {}",
                            first.wall_s, second.wall_s, b.time_s, first.planner
                        )
                        .unwrap();
                        Ok(Ok(Some((second, b))))
                    }
                    Ok(Ok(Some((second, _)))) => Ok(Err(format!(
                        "{} ran {:.3} s, then {:.3} s again, with time_limit {} s ({:?})",
                        first.planner, first.wall_s, second.wall_s, b.time_s, first.status
                    ))),
                    other => other,
                }
            }
            other => other,
        };
        match r {
            Ok(Ok(Some((report, b)))) => {
                writeln!(out, "RUN {seed} {:.6} {} {}", report.wall_s, b.time_s, report.planner).unwrap()
            }
            Ok(Ok(None)) => {}
            Ok(Err(e)) => writeln!(out, "FAIL {seed} {}", e.replace('\n', " ")).unwrap(),
            Err(_) => {
                let msg = PANIC.lock().unwrap_or_else(|e| e.into_inner()).take().unwrap_or_default();
                writeln!(out, "FAIL {seed} panic: {msg}").unwrap();
            }
        }
    }
    writeln!(out, "DONE").unwrap();
}

/// What a pass over cases found.
#[derive(Default)]
struct Pass {
    failures: Vec<(u64, String)>,
    planned: u64,
    /// Runs past their time limit + 0.1 s once but not when run again: `first second limit planner`.
    stalls: Vec<(u64, String)>,
    /// The planned run closest to (or furthest past) its time limit: wall s, limit s, case, planner.
    slowest: (f64, f64, u64, String),
}

/// Runs cases `first..end` (generated, or the regression files by index) in worker processes, so
/// an abort or a hang is recorded with its case and the pass goes on.
fn drive(first: u64, end: u64, regressions: bool, verbose: bool) -> Pass {
    let seed_file = seed_file_path();
    let mut pass = Pass::default();
    let mut from = first;
    while from < end {
        let _ = std::fs::remove_file(&seed_file);
        let mut cmd = std::process::Command::new(std::env::current_exe().expect("test binary"));
        cmd.args(["--ignored", "--exact", "worker", "--nocapture", "--test-threads=1", "-q"])
            .env("PLANARIUM_PROPS_FROM", from.to_string())
            .env("PLANARIUM_PROPS_TO", end.to_string())
            .env("PLANARIUM_PROPS_SEED_FILE", &seed_file)
            .stderr(if verbose { std::process::Stdio::inherit() } else { std::process::Stdio::piped() });
        if verbose {
            cmd.env("PLANARIUM_PROPS_VERBOSE", "1");
        }
        if regressions {
            cmd.env("PLANARIUM_PROPS_REGRESSIONS", "1");
        }
        let child = cmd.output().expect("the worker starts");
        let stdout = String::from_utf8_lossy(&child.stdout);
        let mut done = false;
        for line in stdout.lines() {
            let mut w = line.splitn(3, ' ');
            match (w.next(), w.next().and_then(|s| s.parse::<u64>().ok()), w.next()) {
                (Some("RUN"), Some(seed), Some(rest)) => {
                    pass.planned += 1;
                    let v: Vec<&str> = rest.split(' ').collect();
                    let (wall, limit): (f64, f64) = (v[0].parse().unwrap(), v[1].parse().unwrap());
                    if wall - limit > pass.slowest.0 - pass.slowest.1 {
                        pass.slowest = (wall, limit, seed, v[2].to_string());
                    }
                }
                (Some("FAIL"), Some(seed), Some(msg)) | (Some("HANG"), Some(seed), Some(msg)) => {
                    pass.failures.push((seed, msg.to_string()))
                }
                (Some("STALL"), Some(seed), Some(rest)) => pass.stalls.push((seed, rest.to_string())),
                (Some("DONE"), ..) => done = true,
                _ => {}
            }
        }
        if done {
            break;
        }
        // The worker died (an abort, or the watchdog): its last case is the culprit.
        let last: u64 = std::fs::read_to_string(&seed_file).ok().and_then(|s| s.trim().parse().ok()).unwrap_or(from);
        if !pass.failures.iter().any(|(s, _)| *s == last) {
            let stderr = String::from_utf8_lossy(&child.stderr);
            let why = stderr
                .lines()
                .find(|l| l.contains("memory allocation") || l.contains("panicked"))
                .unwrap_or("")
                .to_string();
            pass.failures.push((last, format!("the process died ({}): {why}", child.status)));
        }
        from = last + 1;
    }
    let _ = std::fs::remove_file(&seed_file);
    pass
}

/// Runs past the time limit once only (the machine was busy), printed so they are not hidden.
fn report_stalls(pass: &Pass) {
    for (seed, rest) in &pass.stalls {
        let v: Vec<&str> = rest.split(' ').collect();
        eprintln!(
            "fuzz_props: case {seed} ({}) ran {} s with time_limit {} s, then {} s when run again: counted as a stall of the machine, not a failure",
            v.get(3).unwrap_or(&"?"),
            v.first().unwrap_or(&"?"),
            v.get(2).unwrap_or(&"?"),
            v.get(1).unwrap_or(&"?")
        );
    }
}

/// Runs `CASES` generated cases, or only `PLANARIUM_PROPS_ONLY=<seed>` (printing its input).
#[test]
fn generated_inputs_keep_the_properties() {
    let only: Option<u64> =
        std::env::var("PLANARIUM_PROPS_ONLY").ok().map(|s| s.trim().parse().expect("PLANARIUM_PROPS_ONLY: a seed"));
    let (first, end) = match only {
        Some(s) => (s, s + 1),
        None => (BASE_SEED, BASE_SEED + CASES),
    };
    let t0 = Instant::now();
    let pass = drive(first, end, false, only.is_some());
    let s = &pass.slowest;
    eprintln!(
        "fuzz_props: {} cases in {:.1} s, {} planned; closest to its time limit: seed {} ({}) ran {:.3} s of {} s; {} failures",
        end - first,
        t0.elapsed().as_secs_f64(),
        pass.planned,
        s.2,
        s.3,
        s.0,
        s.1,
        pass.failures.len()
    );
    report_stalls(&pass);
    if !pass.failures.is_empty() {
        let mut msg = format!(
            "{} of {} generated inputs broke a property (repeat one with PLANARIUM_PROPS_ONLY=<seed>):\n",
            pass.failures.len(),
            end - first
        );
        for (seed, e) in pass.failures.iter().take(40) {
            let e: String = e.chars().take(300).collect();
            msg += &format!("  seed {seed}: {e}\n");
        }
        panic!("{msg}");
    }
}

/// Every minimised finding in `fuzz/regressions/<target>/` keeps the properties now.
#[test]
fn regressions_keep_the_properties() {
    let files = regression_files();
    assert!(!files.is_empty(), "fuzz/regressions/ holds the findings' inputs");
    let pass = drive(0, files.len() as u64, true, false);
    report_stalls(&pass);
    if !pass.failures.is_empty() {
        let mut msg = format!("{} of {} regression inputs broke a property:\n", pass.failures.len(), files.len());
        for (i, e) in &pass.failures {
            let e: String = e.chars().take(300).collect();
            msg += &format!("  {}: {e}\n", files[*i as usize].1.display());
        }
        panic!("{msg}");
    }
}
