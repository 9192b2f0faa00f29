//! `check-path`: paths from elsewhere judged by the rule Planarium's planners keep
//! ([`planarium::run::check_path`]): every state valid, every motion certified free all along at
//! the scenario's resolution, from the start to the goal.
//!
//! The paths file is JSON: one path (an array of states, or an object with a `path` key, as a
//! result file has), an array of such objects, or one such value per line (JSON lines, as the
//! project's OMPL harness writes with `--paths`). An object's `seed` is shown with its path.

use clap::{Arg, ArgAction, ArgMatches, Command};
use planarium::problem::Problem;
use planarium::run::{check_path, PathCheck};
use serde_json::Value;

/// At most this many paths in one file, and states in one path.
const MAX_PATHS: usize = 100_000;
const MAX_STATES: usize = 1_000_000;

pub fn command() -> Command {
    Command::new("check-path")
        .about("Check paths against a scenario as Planarium's planners must pass: every state valid, every motion certified free between its states at the scenario's resolution, from the start to the goal. Exit status 1 when a path is refused")
        .arg(super::scenario_arg())
        .arg(Arg::new("paths").required(true).help("JSON file: a path (an array of states, or an object with a \"path\" key such as a result file), an array of such objects, or one per line"))
        .arg(Arg::new("json").long("json").action(ArgAction::SetTrue).help("Print the verdicts as JSON"))
}

/// One path of the file: its `seed` when it has one, and its states.
struct Given {
    seed: Option<u64>,
    states: Vec<Vec<f64>>,
}

/// A value as a path: an array of states or an object with a `path` key; `at` names it in errors.
fn path_of(v: &Value, at: &str) -> Result<Given, String> {
    let (seed, states) = match v {
        Value::Object(o) => match o.get("path") {
            Some(p) => (o.get("seed").and_then(Value::as_u64), p),
            None => return Err(format!("{at}: an object without a \"path\" key")),
        },
        Value::Array(_) => (None, v),
        _ => return Err(format!("{at}: a path must be an array of states or an object with a \"path\" key")),
    };
    let Value::Array(list) = states else { return Err(format!("{at}: \"path\" must be an array of states")) };
    if list.len() > MAX_STATES {
        return Err(format!("{at}: more than {MAX_STATES} states"));
    }
    let states = list
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let Value::Array(xs) = s else { return Err(format!("{at}: state {k} must be an array of numbers")) };
            xs.iter().map(|x| x.as_f64().ok_or_else(|| format!("{at}: state {k}: {x} is not a number"))).collect()
        })
        .collect::<Result<Vec<Vec<f64>>, String>>()?;
    Ok(Given { seed, states })
}

/// The file's paths (see the module documentation); errors name the file and the line or item.
fn read_paths(name: &str, text: &str) -> Result<Vec<Given>, String> {
    let values: Vec<(String, Value)> = match serde_json::from_str::<Value>(text) {
        // An array of states is one path; an array of objects is many.
        Ok(Value::Array(items)) if items.first().is_some_and(Value::is_object) => {
            items.into_iter().enumerate().map(|(k, v)| (format!("{name}: item {k}"), v)).collect()
        }
        Ok(v) => vec![(name.to_string(), v)],
        Err(whole) => {
            let mut out = Vec::new();
            for (k, line) in text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty()) {
                let at = format!("{name}: line {}", k + 1);
                let v = serde_json::from_str(line).map_err(|e| {
                    if out.is_empty() {
                        format!("{name}: not JSON ({whole})")
                    } else {
                        format!("{at}: not JSON ({e})")
                    }
                })?;
                out.push((at, v));
            }
            out
        }
    };
    if values.len() > MAX_PATHS {
        return Err(format!("{name}: more than {MAX_PATHS} paths"));
    }
    if values.is_empty() {
        return Err(format!("{name}: no path in the file"));
    }
    values.iter().map(|(at, v)| path_of(v, at)).collect()
}

fn line(k: usize, g: &Given, c: &PathCheck) -> String {
    let name = match g.seed {
        Some(s) => format!("path {} (seed {s})", k + 1),
        None => format!("path {}", k + 1),
    };
    if c.valid {
        return format!("{name}: valid: {} states, every motion certified free", c.states);
    }
    let mut out = format!("{name}: refused ({} of {} motions refused)", c.motions_refused, c.motions);
    for r in &c.refusals {
        out.push_str(&match r.what {
            "motion" => format!("\n  motion {} (path[{}] → path[{}]): {}", r.at + 1, r.at, r.at + 1, r.why),
            what => format!("\n  {what} (path[{}]): {}", r.at, r.why),
        });
    }
    out
}

/// Check every path; `Ok(true)` when all are valid.
pub fn run(m: &ArgMatches) -> Result<bool, String> {
    let sc = super::load(m.get_one::<String>("scenario").unwrap())?;
    let problem = Problem::from_scenario(&sc).map_err(|e| e.to_string())?;
    let file = m.get_one::<String>("paths").unwrap();
    let given = read_paths(file, &super::read_limited(file)?)?;
    let checks: Vec<PathCheck> = given.iter().map(|g| check_path(&problem, &g.states)).collect();
    let valid = checks.iter().filter(|c| c.valid).count();
    if m.get_flag("json") {
        let paths: Vec<Value> = given
            .iter()
            .zip(&checks)
            .map(|(g, c)| {
                let mut v = serde_json::to_value(c).unwrap();
                if let Some(s) = g.seed {
                    v["seed"] = s.into();
                }
                v
            })
            .collect();
        let motions: usize = checks.iter().map(|c| c.motions).sum();
        let refused: usize = checks.iter().map(|c| c.motions_refused).sum();
        println!(
            "{}",
            serde_json::json!({ "paths": paths, "valid": valid, "refused": checks.len() - valid, "motions": motions, "motions_refused": refused })
        );
    } else {
        for (k, (g, c)) in given.iter().zip(&checks).enumerate() {
            println!("{}", line(k, g, c));
        }
        println!("{valid} of {} paths valid", checks.len());
    }
    Ok(valid == checks.len())
}
