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
//! a run with time limit `T` ends within `T` and the mechanism's delay ([`bound_s`]: one look at
//! the clock, one call's units), from `Session::new` through the result, on a simulated clock
//! (`planarium::clock::simulate`, each unit of work 1 µs), so exactly on any machine however busy;
//! no run exceeds its iteration or node limit; a solved ASV run's solution file passes the checker.
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

#[path = "fuzz_props/inputs.rs"]
mod inputs;
use inputs::*;

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
    let mut budget = chance(&mut rng, 0.45).then(|| h::Budget {
        planner: rng.below(64),
        seed: rng.next_u64() % 1000,
        time_s: *pick(&mut rng, &[0.01, 0.02, 0.05]),
        iterations: 1 + rng.below(2000) as u64,
        nodes: 2 + rng.below(2000) as u64,
        shortcuts: rng.below(50) as u64,
        events: chance(&mut rng, 0.5),
    });
    // A document whose planner block is the visibility graph's is mostly planned by it (its
    // parameters apply only then), with room for its vertices.
    if let Some(b) = budget.as_mut().filter(|_| text.contains("\"visibility-graph\"")) {
        if chance(&mut rng, 0.7) {
            b.planner = h::planner_names().iter().position(|n| *n == "visibility-graph").expect("registered");
            b.nodes = 2 + rng.below(100_000) as u64;
        }
    }
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

/// What a unit of work costs on the simulated clock the cases run on (`planarium::clock::simulate`:
/// about what one costs here), and a read of it.
const SIM_UNIT: Duration = Duration::from_micros(1);
const SIM_READ: Duration = Duration::from_nanos(50);

/// How far past its time limit a run may end on the simulated clock: the look at the clock that
/// finds the deadline passed comes at most `SLOW_LOOK_MS` late, or one call's units (`largest`:
/// the most units one call counted), and winding the iteration down counts at most one more call;
/// plus the reads' own cost.
fn bound_s(b: &h::Budget, largest: u64) -> f64 {
    let unit_ms = SIM_UNIT.as_secs_f64() * 1000.0;
    b.time_s + (planarium::space_info::SLOW_LOOK_MS + 2.0 * largest as f64 * unit_ms + 0.2) / 1000.0
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
/// does, but with the time limit checked on the simulated clock, see [`bound_s`]).
fn run_regression(target: &str, data: &[u8]) -> Result<Option<(h::RunReport, h::Budget)>, String> {
    let text = String::from_utf8_lossy(data);
    match target {
        "scenario" => h::check_scenario(&text).map(|_| None),
        "technion" => h::check_technion(&text).map(|_| None),
        "asv_problem" => h::check_asv_problem(&text).map(|_| None),
        "map" => h::check_map(data).map(|_| None),
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
/// `FAIL <seed> <message>` per broken property, `RUN <seed> <simulated s> <time limit s>` per planned
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
        // On a simulated clock: the run's time against its limit is exact, whatever the machine's
        // load (a hang that counts no work is the watchdog's).
        let sim = planarium::clock::simulate(SIM_UNIT, SIM_READ);
        sim.take_largest();
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
        let largest = sim.take_largest();
        drop(sim);
        let r = match r {
            Ok(Ok(Some((report, b)))) if report.wall_s > bound_s(&b, largest) => Ok(Err(format!(
                "{} ran {:.6} s (simulated) with time_limit {} s, past its bound {:.6} s ({:?})",
                report.planner,
                report.wall_s,
                b.time_s,
                bound_s(&b, largest),
                report.status
            ))),
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
    /// The planned run closest to (or furthest past) its time limit: simulated s, limit s, case,
    /// planner.
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
    if !pass.failures.is_empty() {
        let mut msg = format!("{} of {} regression inputs broke a property:\n", pass.failures.len(), files.len());
        for (i, e) in &pass.failures {
            let e: String = e.chars().take(300).collect();
            msg += &format!("  {}: {e}\n", files[*i as usize].1.display());
        }
        panic!("{msg}");
    }
}

/// Occupancy maps (issue 17), generated: small PGM (P2 or P5, 8 or 16 bit) and PNG images, alone or
/// behind a map_server YAML, then cut, bit-flipped or with a header or key changed; each read by
/// the `map` target's checks (no panic, errors located, an accepted map's scenario read back equal
/// and built into a problem).
#[test]
fn generated_maps_keep_the_properties() {
    let mut failures = Vec::new();
    let (mut planned, mut invalid, mut rejected) = (0, 0, 0);
    for seed in 0..1500u64 {
        let mut rng = Rng::new(0x6d61_7073 ^ seed);
        let (w, h) = (rng.below(12), rng.below(12));
        let deep = chance(&mut rng, 0.2);
        let max = if deep { 65535 } else { 255 };
        let pixels: Vec<u32> = (0..w * h).map(|_| if chance(&mut rng, 0.3) { 0 } else { max }).collect();
        let mut image: Vec<u8> = match rng.below(3) {
            0 => {
                let mut t = format!("P2\n# fuzz\n{w} {h}\n{max}\n");
                for p in &pixels {
                    t += &format!("{p} ");
                }
                t.into_bytes()
            }
            1 => {
                let mut b = format!("P5\n{w} {h}\n{max}\n").into_bytes();
                for p in &pixels {
                    if deep {
                        b.extend_from_slice(&(*p as u16).to_be_bytes());
                    } else {
                        b.push(*p as u8);
                    }
                }
                b
            }
            _ => {
                use planarium::io::occupancy::{Occupancy, OccupancyGrid};
                let (w, h) = (w.max(1), h.max(1));
                let cells = (0..w * h)
                    .map(|_| if chance(&mut rng, 0.3) { Occupancy::Occupied } else { Occupancy::Free })
                    .collect();
                let grid = OccupancyGrid { width: w, height: h, cells, resolution: 0.05, origin: [0.0, 0.0] };
                planarium::io::occupancy::to_png(&grid)
            }
        };
        match rng.below(6) {
            0 if !image.is_empty() => image.truncate(rng.below(image.len())),
            1 if !image.is_empty() => {
                let k = rng.below(image.len());
                image[k] ^= 1 << rng.below(8);
            }
            2 if image.len() > 4 => image[1] = b"0125679Z"[rng.below(8)],
            _ => {}
        }
        let mut data = Vec::new();
        if chance(&mut rng, 0.6) {
            let res = *pick(&mut rng, &["0.05", "0", "-1", "1e308", "nan", "0.1 0.2", "1e-300"]);
            let origin = *pick(&mut rng, &["[0, 0, 0]", "[-1.5, 2, 0]", "[0, 0, 0.5]", "[1e300, 0, 0]", "[0,", "x"]);
            let mut yaml = format!("image: fuzz.pgm\nresolution: {res}\norigin: {origin}\nnegate: {}\noccupied_thresh: 0.65\nfree_thresh: 0.196\n", rng.below(3));
            if chance(&mut rng, 0.2) {
                yaml = yaml.replace("resolution", "resolutoin");
            }
            data.extend_from_slice(yaml.as_bytes());
            data.extend_from_slice(b"\n===\n");
        }
        data.extend_from_slice(&image);
        match h::check_map(&data) {
            Err(e) => failures.push(format!("map seed {seed}: {e}")),
            Ok(h::Outcome::Problem(_)) => planned += 1,
            Ok(h::Outcome::Invalid(_)) => invalid += 1,
            Ok(h::Outcome::Rejected(_)) => rejected += 1,
        }
    }
    eprintln!("generated maps: {planned} built into problems, {invalid} read but invalid, {rejected} refused");
    assert!(failures.is_empty(), "{} map inputs broke a property:\n{}", failures.len(), failures.join("\n"));
    // not vacuous: both sides of the reader are reached
    assert!(planned > 150 && rejected > 150, "{planned} planned, {rejected} refused");
}
