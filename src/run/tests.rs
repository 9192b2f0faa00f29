use super::*;
use crate::planners::{self, Params};
use crate::problem::Problem;
use crate::scenario::builtin;
use crate::status::Status;

fn session(scenario: &str, planner: &str, seed: u64, params: serde_json::Value) -> Session {
    let spec = planners::find(planner).unwrap();
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(&builtin(scenario).unwrap()).unwrap();
    Session::new(problem, RunConfig { planner: planner.into(), params, seed, record_events: true }).unwrap()
}

#[test]
fn limits_are_honoured() {
    let mut s = session("narrow", "rrt", 1, serde_json::json!({"max_iterations": 50, "goal_bias": 0.0}));
    assert_eq!(s.run_to_end(), Status::IterationLimit);
    assert_eq!(s.stats().iterations, 50);
    let mut s = session("narrow", "rrt", 1, serde_json::json!({"max_nodes": 20, "goal_bias": 0.0}));
    assert_eq!(s.run_to_end(), Status::NodeLimit);
    assert_eq!(s.stats().nodes, 20);
    // Strict inside an iteration too: connect growth adds many nodes per iteration.
    for planner in ["rrt", "rrt-connect"] {
        let params = if planner == "rrt" {
            serde_json::json!({"max_nodes": 37, "extend": "connect", "range": 0.01})
        } else {
            serde_json::json!({"max_nodes": 37, "range": 0.01})
        };
        let mut s = session("narrow", planner, 2, params);
        assert_eq!(s.run_to_end(), Status::NodeLimit, "{planner}");
        assert_eq!(s.stats().nodes, 37, "{planner}");
    }
    // On a simulated clock (a unit of work costs 1 µs): the run stops at its limit, late by at most
    // one look at the clock and one more call's units (tests/limits.rs tests this at length).
    let sim = crate::clock::simulate(std::time::Duration::from_micros(1), std::time::Duration::from_nanos(50));
    let mut s = session("narrow", "rrt", 1, serde_json::json!({"time_limit": 0.05, "goal_bias": 0.0, "range": 0.001}));
    sim.take_largest();
    assert_eq!(s.run_to_end(), Status::TimeLimit);
    let delay = crate::space_info::SLOW_LOOK_MS + 2.0 * sim.take_largest() as f64 * 1e-3 + 0.2;
    let ms = s.stats().time_ms;
    assert!((50.0..=50.0 + delay).contains(&ms), "stopped at the limit: {ms} ms (simulated)");
}

#[test]
fn stepping_in_batches_gives_the_same_run_as_one_go() {
    let mut a = session("slot", "rrt-connect", 3, serde_json::json!({}));
    let mut b = session("slot", "rrt-connect", 3, serde_json::json!({}));
    a.run_to_end();
    let mut events = Vec::new();
    while !b.step(7, f64::INFINITY).is_finished() {
        events.extend(b.drain_events());
    }
    events.extend(b.drain_events());
    assert_eq!(a.drain_events(), events);
    assert_eq!(a.result().path, b.result().path);
    assert_eq!(a.result().stats.iterations, b.result().stats.iterations);
}

#[test]
fn cancel_stops_at_once() {
    let mut s = session("narrow", "rrt", 1, serde_json::json!({"goal_bias": 0.0}));
    s.step(10, f64::INFINITY);
    s.cancel();
    assert_eq!(s.step(1000, f64::INFINITY), Status::Cancelled);
    assert_eq!(s.stats().iterations, 10);
}

#[test]
fn bench_summary_statistics() {
    let m = bench::Summary::of(&[3.0, 1.0, 2.0, 4.0]);
    assert_eq!((m.median, m.mean, m.n), (2.5, 2.5, 4));
    assert!((m.std - 1.2909944487358056).abs() < 1e-12);
}

#[test]
fn set_ups_parse_the_same_for_the_cli_and_the_page() {
    use super::bench::{parse_setup, parse_setup_lines};
    let base = |spec| Ok(crate::planners::Params::defaults(spec));
    let s = parse_setup("biased: rrt --goal-bias 0.2 --extend connect", base).unwrap();
    assert_eq!((s.label.as_str(), s.spec.name), ("biased", "rrt"));
    assert_eq!((s.params.real("goal_bias"), s.params.choice("extend")), (0.2, "connect"));
    // Without a label: the set-up's text.
    assert_eq!(parse_setup("rrt --goal-bias 0.2", base).unwrap().label, "rrt --goal-bias 0.2");
    assert_eq!(parse_setup("  rrt-connect ", base).unwrap().label, "rrt-connect");
    assert!(parse_setup("rrt --goal-bais 0.2", base).unwrap_err().contains("--goal-bais is not a parameter of rrt"));
    assert!(parse_setup("rrt --goal-bias", base).unwrap_err().contains("needs a value"));
    assert!(parse_setup("rrt --goal-bias 7", base).is_err(), "out of range");
    assert!(parse_setup("rrrt", base).unwrap_err().contains("unknown planner"));
    let lines = parse_setup_lines("# a comment\nrrt-connect\n\nrrt --goal-bais 1").unwrap_err();
    assert!(lines.starts_with("set-up line 4: "), "{lines}");
    assert_eq!(parse_setup_lines("a: rrt\nb: rrt-star").unwrap().len(), 2);
    assert!(parse_setup_lines("\n# nothing\n").is_err());
}
