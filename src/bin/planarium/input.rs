//! What the user hands the CLI: files (a scenario, a course's file, an occupancy map), read
//! within the size limits; `--seed`, `--start`/`--goal` and `--query` values, each checked with an
//! error naming the flag; and the scenario `plan` runs once they are applied.

use clap::ArgMatches;
use planarium::problem::Problem;
use planarium::scenario::{self, Scenario};

/// A file's text, refused past [`planarium::limits::MAX_TEXT_BYTES`] without reading the rest.
pub fn read_limited(path: &str) -> Result<String, String> {
    let bytes = read_bytes_limited(std::path::Path::new(path))?;
    String::from_utf8(bytes).map_err(|e| format!("{path}: not UTF-8 text (byte {})", e.utf8_error().valid_up_to()))
}

/// A file's bytes, refused past [`planarium::limits::MAX_TEXT_BYTES`] without reading the rest.
pub fn read_bytes_limited(path: &std::path::Path) -> Result<Vec<u8>, String> {
    use std::io::Read;
    let shown = path.display();
    let max = planarium::limits::MAX_TEXT_BYTES as u64;
    let file = std::fs::File::open(path).map_err(|e| format!("{shown}: {e}"))?;
    let mut bytes = Vec::new();
    file.take(max + 1).read_to_end(&mut bytes).map_err(|e| format!("{shown}: {e}"))?;
    if bytes.len() as u64 > max {
        return Err(format!("{shown}: the file is larger than the limit of {max} bytes (16 MiB)"));
    }
    Ok(bytes)
}

/// Whether `arg` is an occupancy map file: by its extension, or a PGM/PNG by its first bytes.
pub fn is_map_file(arg: &str) -> bool {
    use std::io::Read;
    if planarium::io::occupancy::is_map_name(arg) {
        return true;
    }
    let mut head = [0u8; 8];
    let n = std::fs::File::open(arg).and_then(|mut f| f.read(&mut head)).unwrap_or(0);
    planarium::io::occupancy::sniff(&head[..n]).is_some()
}

/// An occupancy map: map_server's YAML (its image read from the YAML's folder) or a plain image.
pub fn load_map(arg: &str) -> Result<Scenario, String> {
    use planarium::io::occupancy;
    let path = std::path::Path::new(arg);
    let file_name = path.file_name().and_then(|s| s.to_str()).unwrap_or(arg).to_string();
    if occupancy::is_yaml_name(arg) {
        let text = read_limited(arg)?;
        let meta = occupancy::parse_yaml(&text, &file_name).map_err(|e| e.to_string())?;
        let image = path.parent().unwrap_or(std::path::Path::new(".")).join(&meta.image);
        let bytes = read_bytes_limited(&image)?;
        occupancy::import_image(&bytes, &meta.image, Some((&text, &file_name))).map_err(|e| e.to_string())
    } else {
        let bytes = read_bytes_limited(path)?;
        occupancy::import_image(&bytes, &file_name, None).map_err(|e| e.to_string())
    }
}

pub fn load(arg: &str) -> Result<Scenario, String> {
    if std::path::Path::new(arg).is_file() && is_map_file(arg) {
        load_map(arg)
    } else if std::path::Path::new(arg).exists() {
        let text = read_limited(arg)?;
        let stem = std::path::Path::new(arg).file_stem().and_then(|s| s.to_str()).unwrap_or(arg);
        planarium::io::import(&text, stem).map_err(|e| format!("{arg}: {e}"))
    } else if scenario::builtin_names().contains(&arg) {
        scenario::builtin(arg).map_err(|e| e.to_string())
    } else {
        Err(format!(
            "{arg}: no such file, and not a built-in scenario (built-ins: {})",
            scenario::builtin_names().join(", ")
        ))
    }
}

/// `--seed`: a number, or `random` for a fresh one drawn when the run starts.
#[derive(Clone, Debug)]
pub enum SeedArg {
    Fixed(u64),
    Fresh,
}

pub fn seed_arg(text: &str) -> Result<SeedArg, String> {
    if text == "random" {
        return Ok(SeedArg::Fresh);
    }
    text.parse().map(SeedArg::Fixed).map_err(|_| {
        format!(
            "\"{}\" is not a seed: a whole number from 0 to {}, or \"random\"",
            planarium::limits::cut(text, 100),
            u64::MAX
        )
    })
}

/// Most numbers in a `--start` or `--goal` state.
pub const MAX_STATE_NUMBERS: usize = 256;
/// Queries `plan --query` answers on one roadmap.
pub const MAX_QUERIES: usize = 1000;

/// A `--start`/`--goal` value: finite numbers separated by commas.
pub fn state_arg(flag: &str, text: &str) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() > MAX_STATE_NUMBERS {
        return Err(format!("--{flag}: {} numbers; the limit is {MAX_STATE_NUMBERS}", parts.len()));
    }
    parts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            p.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                let p = planarium::limits::cut(p, 40);
                format!(
                    "--{flag} {}: number {} (\"{p}\") is not a finite number",
                    planarium::limits::cut(text, 80),
                    i + 1
                )
            })
        })
        .collect()
}

/// A `--query`'s text, start and goal.
pub type Query = (String, Vec<f64>, Vec<f64>);

/// `plan --query START:GOAL` (repeatable): each query's text and its two states.
pub fn query_args(m: &ArgMatches) -> Result<Vec<Query>, String> {
    let texts: Vec<&String> = m.get_many::<String>("query").map(|q| q.collect()).unwrap_or_default();
    if texts.len() > MAX_QUERIES {
        return Err(format!("--query: {} queries; the limit is {MAX_QUERIES}", texts.len()));
    }
    texts
        .into_iter()
        .map(|text| {
            let cut = planarium::limits::cut(text, 80);
            let (a, b) =
                text.split_once(':').ok_or_else(|| format!("--query {cut}: start and goal are separated by ':'"))?;
            Ok((cut.to_string(), state_arg("query", a)?, state_arg("query", b)?))
        })
        .collect()
}

/// The scenario `plan` runs: [`load`]'s, with `--robot` (Technion maps only), `--start` and
/// `--goal` applied; errors about those states name the flag.
pub fn load_for_plan(m: &ArgMatches) -> Result<Scenario, String> {
    let arg = m.get_one::<String>("scenario").unwrap();
    let start = m.get_one::<String>("start").map(|t| state_arg("start", t)).transpose()?;
    let goal = m.get_one::<String>("goal").map(|t| state_arg("goal", t)).transpose()?;
    let robot = m.get_one::<String>("robot").cloned();
    if robot.is_none() && start.is_none() && goal.is_none() {
        return load(arg);
    }
    // Name the flag in errors about the states it gave.
    let flagged = |e: planarium::scenario::ScenarioError| {
        let flag =
            ["start", "goal", "robot"].into_iter().find(|k| e.path.starts_with(k) && m.get_one::<String>(k).is_some());
        match flag {
            Some(k) => format!("{arg}: --{k}{}: {}", &e.path[k.len()..], e.message),
            None => format!("{arg}: {e}"),
        }
    };
    let text = (std::path::Path::new(arg).exists() && !is_map_file(arg)).then(|| read_limited(arg)).transpose()?;
    if let Some(text) = text.as_ref().filter(|t| planarium::io::detect(t) == planarium::io::Format::TechnionMap) {
        let stem = std::path::Path::new(arg).file_stem().and_then(|s| s.to_str()).unwrap_or(arg);
        let opts = planarium::io::technion::MapOptions { robot, start, goal };
        return planarium::io::technion::import_map_with(text, stem, &opts).map_err(flagged);
    }
    if robot.is_some() {
        return Err(format!("{arg}: --robot applies to Technion maps only (a scenario names its own robot)"));
    }
    let mut sc = load(arg)?;
    if let Some(s) = start {
        sc.start = s;
    }
    if goal.is_some() {
        sc.goal = goal;
    }
    Problem::from_scenario(&sc).map_err(flagged)?;
    Ok(sc)
}

/// `bench`'s seeds: `--seeds A-B`, or `--runs N` (seeds 1..=N, 20 unless given); not both. Errors
/// name the flag.
pub fn bench_seeds(m: &ArgMatches) -> Result<(u64, u64), String> {
    use clap::parser::ValueSource;
    use planarium::run::bench::MAX_RUNS;
    let runs_given = m.value_source("runs") == Some(ValueSource::CommandLine);
    match m.get_one::<String>("seeds") {
        Some(_) if runs_given => Err(
            "--runs and --seeds are both given: --runs N is --seeds 1-N, so give one (--seeds A-B for a shard of a study)"
                .into(),
        ),
        Some(text) => planarium::run::bench::parse_seed_range(text).map_err(|e| format!("--seeds {e}")),
        None => {
            let runs = *m.get_one::<u64>("runs").expect("--runs has a default");
            if runs == 0 || runs > MAX_RUNS {
                return Err(format!("--runs {runs}: from 1 to {MAX_RUNS} (more seeds: shard them with --seeds and merge)"));
            }
            Ok((1, runs))
        }
    }
}
