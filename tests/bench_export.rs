//! Benchmark exports: the CSV, JSON and OMPL benchmark log written by `run::report` read back to
//! the per-run statistics, through small readers written here (an RFC 4180 CSV reader, and an OMPL
//! log reader following `readBenchmarkLog` of OMPL's `scripts/ompl_benchmark_statistics.py`), report
//! 001's course benchmark lines read back the same way, and the CLI's `bench --csv --json-file
//! --ompl-log --course-csv` files equal to the library's for the same seeds.

use planarium::planners::{self, Params};
use planarium::run::bench::{self, PlannerBench};
use planarium::run::report::{self, BenchReport, RunRow, SetupReport};
use planarium::scenario::builtin;
use std::collections::BTreeMap;

const RUNS: u64 = 4;
const DATE: &str = "2025-01-31T12:00:00Z";

/// The benchmark the CLI test repeats: narrow, RRT-Connect and RRT with defaults, and RRT stopped
/// after 5 iterations (unsolved runs), seeds 1..=4.
fn benches() -> Vec<PlannerBench> {
    let sc = builtin("narrow").unwrap();
    let setups: [(&str, &str, serde_json::Value); 3] = [
        ("rrt-connect", "rrt-connect", serde_json::json!({})),
        ("rrt", "rrt", serde_json::json!({})),
        ("rrt capped", "rrt", serde_json::json!({"max_iterations": 5})),
    ];
    setups
        .iter()
        .map(|(label, planner, params)| {
            let spec = planners::find(planner).unwrap();
            let params = Params::from_json(spec, params).unwrap();
            let mut b = bench::bench_planner(&sc, planner, &params, RUNS).unwrap();
            b.label = label.to_string();
            b
        })
        .collect()
}

fn report(benches: &[PlannerBench]) -> BenchReport {
    BenchReport::new("Narrow passage", "narrow", DATE, "test host", benches)
}

#[path = "bench_export/readers.rs"]
mod readers;
use readers::*;

#[test]
fn the_report_holds_every_run_and_the_benches_summaries() {
    let benches = benches();
    let r = report(&benches);
    assert_eq!((r.runs, r.time_limit_s, r.setups.len()), (RUNS as usize, 30.0, 3));
    for (b, s) in benches.iter().zip(&r.setups) {
        assert_eq!(
            (s.label.as_str(), s.planner.as_str(), &s.params),
            (b.label.as_str(), b.planner.as_str(), &b.params)
        );
        assert_eq!(s.rows.len(), b.per_run.len());
        for ((seed, solved, st), (row, status)) in b.per_run.iter().zip(s.rows.iter().zip(&b.statuses)) {
            assert_eq!(row, &RunRow::of(*seed, *status, st));
            assert_eq!(row.solved, *solved);
        }
        // The courses' numbers, recomputed here from the per-run stats (not through SetupSummary,
        // which both the bench and the report use).
        let m = s.summary();
        let solved = b.per_run.iter().filter(|r| r.1).count();
        assert_eq!((m.runs, m.solved), (b.per_run.len(), solved));
        let mut checks: Vec<f64> = b.per_run.iter().map(|r| r.2.checks as f64).collect();
        checks.sort_by(f64::total_cmp);
        let n = checks.len();
        let median = if n % 2 == 1 { checks[n / 2] } else { (checks[n / 2 - 1] + checks[n / 2]) / 2.0 };
        assert_eq!(m.checks.median, median);
        let mean_time = b.per_run.iter().map(|r| r.2.time_ms).sum::<f64>() / n as f64;
        assert!((m.time_ms.mean - mean_time).abs() <= 1e-12 * mean_time.max(1.0));
    }
    // Both kinds of run are here: solved ones, and ones stopped by the iteration limit.
    assert!(r.setups[0].rows.iter().all(|x| x.solved && x.status == "solved"));
    assert!(r.setups[2].rows.iter().all(|x| !x.solved && x.status == "iteration_limit" && x.cost.is_none()));
}

#[test]
fn csv_reads_back_to_the_per_run_stats() {
    let benches = benches();
    let r = report(&benches);
    let text = report::to_csv(&r);
    assert!(text.ends_with("\r\n") && !text.replace("\r\n", "").contains('\n'), "RFC 4180 line breaks");
    let records = read_csv(&text);
    assert_eq!(
        records[0].join(","),
        "setup,planner,seed,solved,status,time_ms,iterations,nodes,checks,cost,smoothed_cost"
    );
    let rows = &records[1..];
    assert_eq!(rows.len(), 3 * RUNS as usize);
    let expected =
        benches.iter().flat_map(|b| b.per_run.iter().zip(&b.statuses).map(move |(run, status)| (b, run, status)));
    for (rec, (b, (seed, solved, st), status)) in rows.iter().zip(expected) {
        assert_eq!(rec.len(), 11);
        assert_eq!((rec[0].as_str(), rec[1].as_str()), (b.label.as_str(), b.planner.as_str()));
        assert_eq!(rec[2].parse::<u64>().unwrap(), *seed);
        assert_eq!(rec[3].parse::<bool>().unwrap(), *solved);
        assert_eq!(rec[4], status.name());
        assert_eq!(
            rec[5].parse::<f64>().unwrap(),
            (st.time_ms * 1000.0).round() / 1000.0,
            "time in ms, to the microsecond"
        );
        assert_eq!(rec[6].parse::<u64>().unwrap(), st.iterations);
        assert_eq!(rec[7].parse::<u64>().unwrap(), st.nodes);
        assert_eq!(rec[8].parse::<u64>().unwrap(), st.checks);
        assert_eq!(opt_f64(&rec[9]), st.cost);
        assert_eq!(opt_f64(&rec[10]), st.smoothed_cost);
    }
}

/// Report 001's course lines: the course's header exactly, then one line per run (LF-ended, as
/// rl's `std::endl`), set-ups and seeds in order, with the date split into date and time, solved
/// as true/false, the set-up's label, nodes, checks, free checks and the time.
#[test]
fn course_lines_read_back_to_the_per_run_stats() {
    let benches = benches();
    let text = report::render(&report(&benches), "course").unwrap();
    assert!(!text.contains('\r'), "lines end with LF, as rl wrote them");
    let records = read_csv(&text);
    assert_eq!(
        records[0].join(","),
        "date,time,solved,plannerName,#vertices,#totalCollisionQueries,#freeQueries,time_ms"
    );
    assert_eq!(report::COURSE_HEADER, records[0].join(","));
    let runs: Vec<_> = benches.iter().flat_map(|b| b.per_run.iter().map(move |r| (b.label.as_str(), r))).collect();
    assert_eq!(records.len(), 1 + runs.len());
    for (rec, (label, (_, solved, st))) in records[1..].iter().zip(&runs) {
        assert_eq!(rec.len(), 8);
        assert_eq!((rec[0].as_str(), rec[1].as_str()), ("2025-01-31", "12:00:00"));
        assert_eq!(rec[2].parse::<bool>().unwrap(), *solved);
        assert_eq!(rec[3], *label);
        assert_eq!(rec[4].parse::<u64>().unwrap(), st.nodes);
        assert_eq!(rec[5].parse::<u64>().unwrap(), st.checks);
        assert_eq!(rec[6].parse::<u64>().unwrap(), st.free_checks);
        assert!(st.free_checks > 0 && st.free_checks <= st.checks, "{st:?}");
        assert_eq!(
            rec[7].parse::<f64>().unwrap(),
            (st.time_ms * 1000.0).round() / 1000.0,
            "time in ms, to the microsecond"
        );
    }
    // A date that is not the CLI's UTC stamp (the page's own) is kept whole, with no time.
    let mut r = report(&benches);
    r.date = "today, 5 pm".into();
    let rec = &read_csv(&report::render(&r, "course").unwrap())[1];
    assert_eq!((rec[0].as_str(), rec[1].as_str()), ("today, 5 pm", ""));
}

#[test]
fn csv_quotes_as_rfc_4180_asks() {
    let row = RunRow {
        seed: 3,
        solved: false,
        status: "time_limit".into(),
        time_ms: 1.5,
        iterations: 2,
        nodes: 3,
        checks: 4,
        free_checks: 3,
        cost: None,
        smoothed_cost: None,
        smoothing_ms: 0.0,
        cost_fk: None,
        smoothed_cost_fk: None,
    };
    let label = "bridge, \"tuned\"\nσ 0.02";
    let r = BenchReport {
        scenario: "s".into(),
        scenario_id: String::new(),
        date: String::new(),
        host: String::new(),
        time_limit_s: 1.0,
        runs: 1,
        seeds: None,
        setups: vec![SetupReport {
            label: label.into(),
            planner: "rrt".into(),
            params: Default::default(),
            rows: vec![row],
        }],
    };
    let text = report::to_csv(&r);
    assert!(text.contains("\"bridge, \"\"tuned\"\"\nσ 0.02\",rrt,3,false,time_limit,1.5,2,3,4,,\r\n"), "{text}");
    let records = read_csv(&text);
    assert_eq!(records.len(), 2);
    assert_eq!(records[1][0], label);
    assert_eq!((records[1][9].as_str(), records[1][10].as_str()), ("", ""));
}

#[test]
fn json_round_trips_and_carries_the_summaries() {
    let benches = benches();
    let r = report(&benches);
    let text = report::to_json(&r);
    let back = report::from_json(&text).unwrap();
    assert_same_report(&back, &r);
    // Written again, the JSON reads back to the same report (and, with exact float parsing, the
    // same text).
    assert_same_report(&report::from_json(&report::to_json(&back)).unwrap(), &r);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["scenario_id"], "narrow");
    assert_eq!(v["date"], DATE);
    for (b, s) in benches.iter().zip(v["setups"].as_array().unwrap()) {
        let m = &s["summary"];
        assert_eq!(m["success_rate"].as_f64().unwrap(), b.summary.success_rate);
        assert_eq!(m["runs"], RUNS);
        for (key, want) in [
            ("time_ms", &b.summary.time_ms),
            ("nodes", &b.summary.nodes),
            ("checks", &b.summary.checks),
            ("cost", &b.summary.cost),
            ("smoothed_cost", &b.summary.smoothed_cost),
        ] {
            assert_eq!(m[key], serde_json::to_value(want).unwrap(), "{key}");
        }
        assert_eq!(s["rows"].as_array().unwrap().len(), RUNS as usize);
    }
}

#[test]
fn from_json_takes_the_pages_minimal_report_and_says_what_is_wrong() {
    // What the page builds from its runs' results: the optional fields left out.
    let minimal = r#"{"scenario": "Narrow passage", "time_limit_s": 5, "setups": [{"label": "a", "planner": "rrt",
        "rows": [{"seed": 1, "solved": true, "status": "solved", "time_ms": 2.5, "iterations": 10, "nodes": 8, "checks": 99, "cost": 1.5, "smoothed_cost": 1.2},
                 {"seed": 2, "solved": false, "status": "time_limit", "time_ms": 5000, "iterations": 10, "nodes": 8, "checks": 99, "cost": null}]}]}"#;
    let r = report::from_json(minimal).unwrap();
    assert_eq!((r.runs, r.scenario_id.as_str(), r.setups[0].rows[1].smoothed_cost), (2, "", None));
    assert_eq!(r.setups[0].summary().success_rate, 0.5);
    for format in report::FORMATS {
        assert!(!report::render(&r, format).unwrap().is_empty());
    }
    let bad = [
        (minimal.replace("\"time_limit\"", "\"timeout\""), "setups[0].rows[1].status: unknown status \"timeout\""),
        (
            minimal.replace("\"solved\": false", "\"solved\": true"),
            "setups[0].rows[1]: solved is true but status is \"time_limit\"",
        ),
        (
            minimal.replace("\"time_ms\": 2.5", "\"time_ms\": -1"),
            "setups[0].rows[0].time_ms: must be a non-negative number",
        ),
        (minimal.replace("\"label\": \"a\", ", ""), "missing field `label`"),
        ("[1, 2]".to_string(), "bench report:"),
    ];
    for (text, want) in bad {
        let e = report::from_json(&text).unwrap_err();
        assert!(e.starts_with("bench report: ") && e.contains(want), "{e} (wanted: {want})");
    }
    let e = report::render(&r, "xml").unwrap_err();
    assert_eq!(e, "unknown export format \"xml\" (known: csv, json, ompl, table, course)");
}

#[test]
fn the_ompl_log_parses_and_holds_the_stats() {
    let benches = benches();
    let r = report(&benches);
    let log = read_ompl_log(&report::to_ompl_log(&r));
    assert_eq!(log.version, format!("Planarium {}", env!("CARGO_PKG_VERSION")));
    assert_eq!((log.experiment.as_str(), log.host.as_str(), log.date.as_str()), ("Narrow_passage", "test_host", DATE));
    assert!(
        log.setup.contains("Narrow passage") && log.setup.contains("rrt capped: rrt {\"max_iterations\":5.0}"),
        "{}",
        log.setup
    );
    assert_eq!(log.cpuinfo, None);
    assert_eq!(
        (log.seed.as_str(), log.time_limit, log.memory_limit, log.runs_per_planner),
        ("1", 30.0, -1.0, RUNS as i64)
    );
    let total: f64 = r.setups.iter().flat_map(|s| &s.rows).map(|x| (x.time_ms + x.smoothing_ms) / 1000.0).sum();
    assert!((log.total_time - total).abs() < 1e-12);
    let status_enum = log.enums.iter().find(|e| e[0] == "status").expect("OMPL's status enum");
    assert_eq!(status_enum[1..].len(), 10);
    assert_eq!((status_enum[1 + 4].as_str(), status_enum[1 + 6].as_str()), ("Timeout", "Exact solution"));
    let ours = log.enums.iter().find(|e| e[0] == "planarium_status").expect("our status enum");
    let names: Vec<&str> = log.planners.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["geometric_rrt-connect", "geometric_rrt", "geometric_rrt_capped"]);
    for (p, b) in log.planners.iter().zip(&benches) {
        assert!(p.common.contains(&format!("planner = {}", b.planner)));
        for (name, ty) in &p.properties {
            assert!(["BOOLEAN", "INTEGER", "REAL", "ENUM"].contains(&ty.as_str()), "{name} {ty}");
            if ty == "ENUM" {
                assert!(log.enums.iter().any(|e| &e[0] == name), "an enum named {name}");
            }
        }
        let runs = ompl_runs(p);
        assert_eq!(runs.len(), b.per_run.len());
        for (run, ((seed, solved, st), status)) in runs.iter().zip(b.per_run.iter().zip(&b.statuses)) {
            assert_eq!(real(&run["time"]), Some(st.time_ms / 1000.0), "time in seconds");
            assert_eq!(int(&run["solved"]), u64::from(*solved));
            assert_eq!(int(&run["seed"]), *seed);
            assert_eq!(int(&run["graph_states"]), st.nodes);
            assert_eq!(int(&run["collision_checks"]), st.checks);
            assert_eq!(int(&run["iterations"]), st.iterations);
            assert_eq!(real(&run["solution_length"]), st.cost);
            assert_eq!(real(&run["simplified_solution_length"]), st.smoothed_cost);
            assert_eq!(real(&run["simplification_time"]), solved.then_some(st.smoothing_ms / 1000.0));
            let ompl_status = &status_enum[1 + int(&run["status"]) as usize];
            assert_eq!(ompl_status, if *solved { "Exact solution" } else { "Timeout" });
            assert_eq!(ours[1 + int(&run["planarium_status"]) as usize], status.name().replace('_', " "));
        }
    }
}

#[test]
fn ompl_names_are_single_words_and_unique() {
    let mut r = report(&benches());
    r.scenario = "My  scene; v2".into();
    r.host = "lab machine 3".into();
    r.setups[1].label = "near-collision tuned (p 3; σ 0.005)".into();
    r.setups[2].label = "near-collision tuned (p 3| σ 0.005)".into();
    r.setups[0].params.insert("sampler".into(), "bridge".into());
    let text = report::to_ompl_log(&r);
    let log = read_ompl_log(&text);
    assert_eq!((log.experiment.as_str(), log.host.as_str()), ("My__scene__v2", "lab_machine_3"));
    let names: Vec<&str> = log.planners.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "geometric_rrt-connect",
            "geometric_near-collision_tuned_(p_3__σ_0.005)",
            "geometric_near-collision_tuned_(p_3__σ_0.005)_2"
        ]
    );
    assert_eq!(log.planners[0].common, ["planner = rrt-connect", "sampler = bridge"]);
}

#[test]
fn the_course_table_shows_the_summaries() {
    let benches = benches();
    let r = report(&benches);
    let t = report::course_table(&r);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(lines.len(), 2 + 3);
    assert!(lines[0]
        .starts_with("| set-up | planner | runs | solved | mean time (ms) | std time (ms) | median time (ms) |"));
    for (line, b) in lines[2..].iter().zip(&benches) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        assert_eq!(cells.len(), 13);
        assert_eq!(cells[0], b.label);
        assert_eq!(cells[3], format!("{:.0}%", b.summary.success_rate * 100.0));
        assert_eq!(cells[4], format!("{:.2}", b.summary.time_ms.mean));
        assert_eq!(cells[9], format!("{:.0}", b.summary.checks.mean));
        let cost = if b.summary.cost.n == 0 { "—".to_string() } else { format!("{:.4}", b.summary.cost.mean) };
        assert_eq!(cells[11], cost);
    }
    assert_eq!(report::render(&r, "table").unwrap(), t);
}

#[test]
fn utc_timestamps_follow_the_civil_calendar() {
    for (secs, want) in [
        (0, "1970-01-01T00:00:00Z"),
        (951_782_400, "2000-02-29T00:00:00Z"),
        (1_709_210_096, "2024-02-29T12:34:56Z"),
        (4_102_444_799, "2099-12-31T23:59:59Z"),
        (253_402_300_799, "9999-12-31T23:59:59Z"),
    ] {
        assert_eq!(report::utc_timestamp(secs), want);
    }
}

// ---------------------------------------------------------------------------------------------

fn without_times(mut r: BenchReport) -> BenchReport {
    r.date.clear();
    r.host.clear();
    for row in r.setups.iter_mut().flat_map(|s| s.rows.iter_mut()) {
        row.time_ms = 0.0;
        row.smoothing_ms = 0.0;
    }
    r
}

/// The OMPL log without what the clock decides (times, date, host).
fn ompl_without_times(mut log: OmplLog) -> OmplLog {
    log.date.clear();
    log.host.clear();
    log.total_time = 0.0;
    for p in &mut log.planners {
        let clocked: Vec<usize> = p
            .properties
            .iter()
            .enumerate()
            .filter(|(_, (n, _))| n == "time" || n == "simplification_time")
            .map(|(i, _)| i)
            .collect();
        for run in &mut p.runs {
            for &i in &clocked {
                run[i] = run[i].as_ref().map(|_| "t".to_string());
            }
        }
    }
    log
}

#[test]
fn the_cli_writes_the_same_four_formats() {
    let dir = std::env::temp_dir().join(format!("planarium-bench-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, json, log, course) = (dir.join("b.csv"), dir.join("b.json"), dir.join("b.log"), dir.join("c.csv"));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args([
            "bench",
            "narrow",
            "--runs",
            &RUNS.to_string(),
            "--setup",
            "rrt-connect",
            "--setup",
            "rrt",
            "--setup",
            "rrt capped: rrt --max-iterations 5",
        ])
        .arg("--csv")
        .arg(&csv)
        .arg("--json-file")
        .arg(&json)
        .arg("--ompl-log")
        .arg(&log)
        .arg("--course-csv")
        .arg(&course)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let read = |p: &std::path::Path| std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    let (csv_text, json_text, log_text, course_text) = (read(&csv), read(&json), read(&log), read(&course));
    std::fs::remove_dir_all(&dir).ok();

    let lib = report(&benches());
    // JSON: the same report, up to what the clock decides.
    let cli = report::from_json(&json_text).unwrap();
    let date = cli.date.as_bytes();
    assert!(cli.date.len() == 20 && date[4] == b'-' && date[10] == b'T' && date[19] == b'Z', "{}", cli.date);
    assert!(!cli.host.is_empty());
    assert!(cli.setups.iter().flat_map(|s| &s.rows).all(|x| x.time_ms > 0.0));
    assert_same_report(&without_times(cli.clone()), &without_times(lib.clone()));
    // CSV: the same records but the time column.
    // (read from the CLI's own CSV, exactly: these bypass JSON parsing).
    let drop_time = |t: &str| {
        read_csv(t)
            .into_iter()
            .map(|mut r| {
                r.remove(5);
                r
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(drop_time(&csv_text), drop_time(&report::to_csv(&lib)));
    // Course lines: the same but date, time and time_ms; the date and time the JSON's.
    let course_records = read_csv(&course_text);
    assert!(course_records[1..].iter().all(|r| format!("{}T{}Z", r[0], r[1]) == cli.date), "{course_text}");
    let undated = |t: &str| {
        read_csv(t)
            .into_iter()
            .map(|mut r| {
                r.truncate(7);
                r.drain(0..2);
                r
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(undated(&course_text), undated(&report::to_course_csv(&lib)));
    // OMPL log: the same log but times, date and host.
    assert_eq!(
        ompl_without_times(read_ompl_log(&log_text)),
        ompl_without_times(read_ompl_log(&report::to_ompl_log(&lib)))
    );
}
