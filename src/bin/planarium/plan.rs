//! `planarium plan`: one run of a scenario, printed (or its result JSON), with the course files
//! it can write and the roadmap queries it can answer after.

use super::*;
use planarium::run::{RunConfig, Session};

pub(super) fn plan(m: &ArgMatches) -> Result<(), String> {
    let sc = load_for_plan(m)?;
    // As the page does: the scenario's planner block chooses the planner and seed unless told.
    let block = sc.planner.as_ref();
    let name = m
        .get_one::<String>("planner")
        .cloned()
        .or_else(|| block.map(|b| b.name.clone()))
        .unwrap_or_else(|| "rrt-connect".into());
    let spec = find_planner(&name)?;
    let params = params_for(spec, &sc, m)?;
    let problem = Problem::from_scenario(&sc).map_err(|e| e.to_string())?;
    let seed = match m.get_one::<SeedArg>("seed") {
        Some(SeedArg::Fixed(seed)) => *seed,
        Some(SeedArg::Fresh) => {
            let seed = planarium::rng::fresh_seed()?;
            eprintln!("fresh seed {seed} (--seed {seed} replays this run)");
            seed
        }
        None => block.filter(|b| b.name == spec.name).and_then(|b| b.seed).unwrap_or(1),
    };
    let queries = query_args(m)?;
    let events_file = m.get_one::<String>("events");
    let mut s = Session::new(
        problem,
        RunConfig { planner: spec.name.into(), params, seed, record_events: events_file.is_some() },
    )?;
    s.run_to_end();
    let r = s.result();
    let mut answers = Vec::new();
    for (k, (text, start, goal)) in queries.iter().enumerate() {
        answers.push(match s.query(start, goal) {
            Ok(a) if a.path.is_empty() => format!("  query {}: {text}: the roadmap does not join them", k + 1),
            Ok(a) => format!(
                "  query {}: {text}: {} states, cost {:.4} (the same roadmap: {} vertices now)",
                k + 1,
                a.path.len(),
                a.cost,
                s.stats().nodes
            ),
            Err(e) => format!("  query {}: {text}: {e}", k + 1),
        });
    }
    if let Some(file) = events_file {
        let kinds: serde_json::Map<String, serde_json::Value> = planarium::events::EventKind::ALL
            .iter()
            .map(|(k, name)| (name.to_string(), serde_json::json!(*k as u8)))
            .collect();
        // NaN (unused slots) is not JSON: written as null.
        let records: Vec<serde_json::Value> = s
            .drain_events()
            .into_iter()
            .map(|v| if v.is_finite() { serde_json::json!(v) } else { serde_json::Value::Null })
            .collect();
        let doc = serde_json::json!({"stride": planarium::events::STRIDE, "kinds": kinds, "records": records});
        std::fs::write(file, doc.to_string()).map_err(|e| format!("{file}: {e}"))?;
    }
    if let Some(file) = m.get_one::<String>("asv-solution") {
        if !r.solved {
            return Err(format!("{}: not solved ({}), so no solution written to {file}", sc.name, r.status));
        }
        let text = planarium::io::asv::solution_text(s.problem(), s.planning_path(false))?;
        std::fs::write(file, &text).map_err(|e| format!("{file}: {e}"))?;
        let steps = text.split_whitespace().next().unwrap_or("0");
        eprintln!("wrote {file}: {steps} primitive steps");
    }
    if m.get_flag("json") {
        println!("{}", r.to_json());
    } else {
        let st = &r.stats;
        println!("{} on \"{}\", seed {}: {}", spec.label, sc.name, seed, r.status);
        println!(
            "  time {:.3} ms, {} iterations, {} nodes, {} checks ({} free)",
            st.time_ms, st.iterations, st.nodes, st.checks, st.free_checks
        );
        let sm = &st.sampler;
        if sm.used {
            println!(
                "  sampler {}: {} samples ({} given up), {:.2} draws and {:.2} checks per sample",
                sm.name, sm.accepted, sm.failed, sm.draws_per_sample, sm.checks_per_sample
            );
        } else {
            println!("  no sampler: {} draws no samples through one", spec.label);
        }
        if let Some(c) = st.coverage {
            println!(
                "  coverage {:.1}% (smoothed path: {:.1}%)",
                c * 100.0,
                st.smoothed_coverage.unwrap_or(0.0) * 100.0
            );
        }
        if let (Some(a), Some(b)) = (st.course_coverage, st.continuous_coverage) {
            println!(
                "  course coverage (at vertices) {:.1}%, continuous coverage (along edges) {:.1}%",
                a * 100.0,
                b * 100.0
            );
        }
        if let Some(why) = &r.reason {
            println!("  {why}");
        }
        if r.solved {
            println!("  path: {} states, cost {:.4}", r.path.len(), st.cost.unwrap_or(0.0));
            if let Some(n) = st.repaired {
                println!(
                    "  path certified between its configurations: {n} motion{} met an obstacle between two \
                     checked steps and took a detour",
                    if n == 1 { "" } else { "s" }
                );
            }
            println!("  smoothed: {} states, cost {:.4}", r.smoothed.len(), st.smoothed_cost.unwrap_or(0.0));
            if let (Some(a), Some(b)) = (st.cost_fk, st.smoothed_cost_fk) {
                println!("  cost in report 004's unit (fk): {a:.2}, smoothed {b:.2}");
            }
            print_optimum(&sc, spec.name, st.cost, st.smoothed_cost);
        }
    }
    for line in &answers {
        if m.get_flag("json") {
            eprintln!("{line}");
        } else {
            println!("{line}");
        }
    }
    Ok(())
}

/// For a point robot or a round rigid one: the visibility graph's optimum, and how far
/// above it the path is. Nothing for other robots, maps of more than 5,000 obstacles, or a graph
/// that takes more than 5 s.
fn print_optimum(sc: &Scenario, planner: &str, cost: Option<f64>, smoothed: Option<f64>) {
    if planner == "visibility-graph" || sc.obstacles.len() > 5000 {
        return;
    }
    let Ok(problem) = Problem::from_scenario(sc) else { return };
    if let Ok(o) = planarium::run::optimum_within(problem, 5.0) {
        if let (true, Some(opt), Some(c), Some(sm)) = (o.exact, o.cost, cost, smoothed) {
            let above = |v: f64| 100.0 * (v / opt - 1.0);
            println!(
                "  optimum (visibility graph) {opt:.4}: the path is {:.2}% above it, smoothed {:.2}%",
                above(c),
                above(sm)
            );
        }
    }
}
