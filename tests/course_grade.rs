//! `bench --course-grade` (issue 16): the ASV course's protocol — 10 runs per problem, solved when
//! 5 pass within 1 minute (open) or 5 minutes (cluttered). Every official file passes, and every
//! run that counts has a path that the independent re-check of the course's rules accepts, re-done
//! here on the written solution file. Run in release (`cargo test --release --test course_grade`);
//! nothing here measures speed (the limits are minutes; the runs take milliseconds).

use planarium::io::asv::{check_solution, read_solution, solution_text};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::course_grade::{cluttered, grade};
use planarium::run::{RunConfig, Session};
use planarium::scenario::Scenario;
use planarium::status::Status;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/asv");
const FILES: &[(&str, bool)] = &[("3ASV-easy", false), ("3ASV", true), ("7ASV-easy", false), ("7ASV", true)];

fn official(name: &str) -> Scenario {
    let text = std::fs::read_to_string(format!("{DATA}/{name}.txt")).unwrap();
    planarium::io::import(&text, name).unwrap()
}

fn rrt_connect(sc: &Scenario) -> Params {
    let spec = planners::find("rrt-connect").unwrap();
    match &sc.planner {
        Some(d) if d.name == spec.name => {
            Params::from_json(spec, &serde_json::Value::Object(d.params.clone())).unwrap()
        }
        _ => Params::defaults(spec),
    }
}

#[test]
fn every_official_file_passes_the_course_protocol() {
    for &(name, is_cluttered) in FILES {
        let sc = official(name);
        assert_eq!(cluttered(&sc), is_cluttered, "{name}: open or cluttered");
        let g = grade(&sc, name, "rrt-connect", &rrt_connect(&sc), 10, 5, None).unwrap();
        assert_eq!(g.limit_s, if is_cluttered { 300.0 } else { 60.0 }, "{name}");
        assert_eq!(g.runs.len(), 10);
        assert!(g.pass(), "{name}: {}", g.line());
        assert_eq!(g.solved(), 10, "{name}: {}", g.line());
        for r in &g.runs {
            assert_eq!(r.status, Status::Solved, "{name} seed {}", r.seed);
            assert_eq!(r.check, Some(Ok(())), "{name} seed {}", r.seed);
        }
        assert!(g.line().ends_with("PASS"), "{}", g.line());
    }
}

/// The grade's re-check is the course's: the same seeds' solution files, written and read back as
/// text, pass [`check_solution`] (and a file with one step too long does not).
#[test]
fn counted_runs_write_solution_files_the_course_accepts() {
    for &(name, _) in FILES {
        let sc = official(name);
        for seed in [1, 2] {
            let problem = Problem::from_scenario(&sc).unwrap();
            let config =
                RunConfig { planner: "rrt-connect".into(), params: rrt_connect(&sc), seed, record_events: false };
            let mut s = Session::new(problem, config).unwrap();
            assert_eq!(s.run_to_end(), Status::Solved);
            let text = solution_text(s.problem(), s.planning_path(false)).unwrap();
            let mut configs = read_solution(&text).unwrap();
            check_solution(&sc, &configs).unwrap_or_else(|e| panic!("{name} seed {seed}: {e}"));
            // Drop a middle configuration: some vehicle now moves two primitive steps at once.
            let mid = configs.len() / 2;
            configs.remove(mid);
            assert!(check_solution(&sc, &configs).is_err(), "{name} seed {seed}: a gap in the path passes");
        }
    }
}

/// The command line: a directory of problems, one verdict per file, exit code 0; a problem that
/// cannot be solved in time fails with a non-zero exit code (a hidden 1-run, 0.01 s override on asv-15).
#[test]
fn the_command_line_prints_a_verdict_per_file_and_fails_on_a_failure() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["bench", "--course-grade", DATA])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}\n{}", String::from_utf8_lossy(&out.stderr));
    for &(name, _) in FILES {
        let line = text.lines().find(|l| l.starts_with(&format!("{name} "))).unwrap_or_else(|| panic!("{text}"));
        assert!(line.contains("solved 10/10") && line.ends_with("PASS"), "{line}");
    }
    assert!(text.contains("4 of 4 problems pass"), "{text}");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["bench", "--course-grade", "asv-15", "--course-runs", "1", "--course-time-limit", "0.01"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(!out.status.success(), "{text}");
    assert!(text.contains("solved  0/1") && text.contains("FAIL"), "{text}");
    // Not an ASV robot: refused, not graded.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["bench", "--course-grade", "narrow"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("ASV"));
}
