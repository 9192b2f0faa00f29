//! The registry's capabilities are true of the planners: every event kind a planner emits is one
//! its `caps.events` declares (the page checks it handles each declared kind), a planner that
//! answers further queries answers one, and the derived flags follow the parameter groups.

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params, REGISTRY};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::builtin;
use serde_json::json;
use std::collections::BTreeSet;

/// The event kinds of a run (at most `iterations` iterations).
fn kinds(scenario: &str, planner: &str, mut params: serde_json::Value, iterations: u64) -> (BTreeSet<u8>, Session) {
    let sc = builtin(scenario).unwrap();
    let spec = planners::find(planner).unwrap();
    params["max_iterations"] = json!(iterations);
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: planner.into(), params, seed: 3, record_events: true }).unwrap();
    s.run_to_end();
    let log = s.drain_events();
    (log.chunks_exact(STRIDE).map(|c| c[0] as u8).collect(), s)
}

fn name(k: u8) -> &'static str {
    EventKind::ALL.iter().find(|(e, _)| *e as u8 == k).map(|(_, n)| *n).unwrap()
}

#[test]
fn every_emitted_event_is_declared() {
    for spec in REGISTRY {
        let scenario = if spec.task == planners::TaskKind::Inspection { "technion-ip" } else { "narrow" };
        let mut runs = vec![json!({})];
        if spec.samples() {
            runs.push(json!({"sampler": "gaussian"}));
        }
        if spec.tree_variants() {
            runs.push(json!({"dd_radius": 0.05, "exhausted": 3}));
        }
        let declared: BTreeSet<u8> = spec.caps.events.iter().map(|(k, _)| k as u8).collect();
        let mut seen = BTreeSet::new();
        for params in runs {
            let (emitted, _) = kinds(scenario, spec.name, params.clone(), 3000);
            for k in &emitted {
                assert!(
                    declared.contains(k),
                    "{} emits {} ({params}) but its caps.events do not declare it",
                    spec.name,
                    name(*k)
                );
            }
            seen.extend(emitted);
        }
        let unseen: Vec<_> = declared.difference(&seen).map(|&k| name(k)).collect();
        eprintln!("{}: declared but not seen on {scenario}: {unseen:?}", spec.name);
        assert!(!seen.is_empty(), "{} emitted nothing", spec.name);
    }
}

#[test]
fn derived_flags_follow_the_groups_and_the_planner() {
    for spec in REGISTRY {
        assert_eq!(spec.samples(), spec.all_params().any(|p| p.name == "sampler"), "{}", spec.name);
        assert_eq!(spec.tree_variants(), spec.all_params().any(|p| p.name == "dd_radius"), "{}", spec.name);
        assert!(
            !spec.caps.pseudocode.is_empty() && !REGISTRY.iter().any(|p| p.name == spec.caps.pseudocode),
            "{}: a pseudocode key apart from the planner names",
            spec.name
        );
        assert!(!spec.caps.legend.is_empty() || !spec.caps.marks.is_empty(), "{}: a legend", spec.name);
        // A planner that says it answers further queries answers one on the roadmap it built.
        if spec.task == planners::TaskKind::Goal {
            let (_, mut s) = kinds("open-field", spec.name, json!({}), 300);
            let (start, goal) = (s.problem().start.clone(), s.problem().goal.clone().unwrap());
            assert_eq!(s.query(&start, &goal).is_ok(), spec.caps.queries, "{}: caps.queries", spec.name);
        }
    }
}
