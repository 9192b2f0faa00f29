//! The native command line: `plan`, `bench`, `merge`, `scaling`, `validate`, `check-path`,
//! `export-map` and `list`.
//!
//! Every planner parameter is a flag (`--goal-bias 0.2`, `--extend connect`), generated from the
//! planner registry, so a new parameter needs no CLI code.

use clap::{Arg, ArgAction, ArgMatches, Command};
use planarium::planners::{self, Params, PlannerSpec};
use planarium::problem::Problem;
use planarium::run::{bench, report, scaling};
use planarium::scenario::{self, Scenario};
use std::process::ExitCode;

#[path = "planarium/input.rs"]
mod input;
use input::*;
#[path = "planarium/check.rs"]
mod check;
#[path = "planarium/merge.rs"]
mod merge;
#[path = "planarium/plan.rs"]
mod plan;

fn param_flag(name: &str) -> String {
    name.replace('_', "-")
}

/// Every parameter name of every planner and of the run loop, once each.
fn all_param_specs() -> Vec<&'static planners::ParamSpec> {
    let mut out: Vec<&'static planners::ParamSpec> = Vec::new();
    for p in planners::REGISTRY.iter().flat_map(|p| p.all_params()) {
        if !out.iter().any(|q| q.name == p.name) {
            out.push(p);
        }
    }
    out
}

/// When parameter `name` applies, for the help: "(with --sampler gaussian or bridge)" when every
/// planner taking it says the same, else per planner ("(rrt-connect: with --connect range)");
/// none when it always applies.
fn applies_note(name: &str) -> Option<String> {
    let flag = |n: &str| format!("--{}", param_flag(n));
    let takers: Vec<(&str, Option<planarium::params::Condition>)> =
        planners::REGISTRY.iter().filter_map(|p| p.param(name).map(|s| (p.name, s.applies))).collect();
    let first = takers.first()?.1;
    if takers.iter().all(|t| t.1 == first) {
        return first.map(|c| format!("(with {})", c.describe(flag)));
    }
    let mut parts: Vec<(Vec<&str>, planarium::params::Condition)> = Vec::new();
    for (planner, c) in takers {
        let Some(c) = c else { continue };
        match parts.iter_mut().find(|p| p.1 == c) {
            Some(p) => p.0.push(planner),
            None => parts.push((vec![planner], c)),
        }
    }
    let parts: Vec<String> =
        parts.iter().map(|(ps, c)| format!("{}: with {}", ps.join(", "), c.describe(flag))).collect();
    Some(format!("({})", parts.join("; ")))
}

fn with_param_flags(mut cmd: Command) -> Command {
    for p in all_param_specs() {
        let id: &'static str = p.name;
        let help = match applies_note(p.name) {
            Some(note) => format!("{} {note}", p.doc),
            None => p.doc.to_string(),
        };
        cmd = cmd.arg(
            Arg::new(id).long(param_flag(p.name)).value_name("VALUE").help(help).help_heading("Planner parameters"),
        );
    }
    cmd
}

/// The scenario argument every subcommand that reads one takes.
fn scenario_arg() -> Arg {
    Arg::new("scenario")
        .required(true)
        .help("Scenario JSON file, a course file (Technion map JSON, ASV problem text), an occupancy map (map_server's map.yaml naming its image, or a plain .pgm/.png image: dark is occupied), or the id of a built-in scenario (see `list`)")
}

fn cli() -> Command {
    let scenario_arg = scenario_arg();
    Command::new("planarium")
        .version(env!("CARGO_PKG_VERSION"))
        .about("Motion-planning playground core: plan, benchmark and validate scenarios")
        .subcommand_required(true)
        .subcommand(with_param_flags(
            Command::new("plan")
                .about("Plan once and print the result")
                .arg(scenario_arg.clone())
                .arg(Arg::new("planner").long("planner").help("Planner name (default: the scenario's planner block's, else rrt-connect)"))
                .arg(Arg::new("seed").long("seed").value_parser(seed_arg).help("Seed, or \"random\" for a fresh one (printed, so the run can be replayed); default: the scenario's planner block's, else 1"))
                .arg(Arg::new("json").long("json").action(ArgAction::SetTrue).help("Print the result JSON of the contract"))
                .arg(Arg::new("robot").long("robot").value_name("ROBOT").help("For a Technion map: arm (the course's manipulator) or dot (the point robot); default: arm when the map has a START, else dot"))
                .arg(Arg::new("start").long("start").value_name("X,Y|Q1,...").allow_hyphen_values(true).help("The start state, comma-separated (x,y for a point robot, 4 joint angles for the Technion arm); replaces the scenario's or map's"))
                .arg(Arg::new("goal").long("goal").value_name("X,Y|Q1,...").allow_hyphen_values(true).help("The goal state, comma-separated; replaces the scenario's or map's"))
                .arg(
                    Arg::new("query")
                        .long("query")
                        .value_name("START:GOAL")
                        .action(ArgAction::Append)
                        .allow_hyphen_values(true)
                        .help("After the run, another query on its roadmap (prm, prm-star, lazy-prm), start and goal comma-separated (e.g. 0.1,0.1:0.9,0.5); repeat for more. The roadmap is reused: no milestone is added"),
                )
                .arg(
                    Arg::new("events")
                        .long("events")
                        .value_name("FILE")
                        .help("Write every event of the run as JSON: {\"stride\": 12, \"kinds\": {NAME: number}, \"records\": [...]} (the worker's stream; see src/events.rs)"),
                )
                .arg(
                    Arg::new("asv-solution")
                        .long("asv-solution")
                        .value_name("FILE")
                        .help("For an ASV problem: write the smoothed path as the course's solution file (primitive steps of at most max_step)"),
                ),
        ))
        .subcommand(with_param_flags(
            Command::new("bench")
                .about("Run planners for seeds 1..N (or A..B with --seeds) and summarise")
                .arg(scenario_arg.clone())
                .arg(Arg::new("planners").long("planners").default_value("rrt,rrt-connect").help("Comma-separated planner names (ignored when --setup is given)"))
                .arg(
                    Arg::new("setup")
                        .long("setup")
                        .action(ArgAction::Append)
                        .value_name("SETUP")
                        .help("A planner set-up to compare, repeatable: \"[label:] planner [--param value ...]\", e.g. \"bridge: rrt-connect --sampler bridge --sigma 0.02\"; the other flags apply to every set-up"),
                )
                .arg(Arg::new("report").long("report").action(ArgAction::SetTrue).help("Print report 001's table (avg and std of time, avg nodes, avg and median checks) as Markdown"))
                .arg(Arg::new("runs").long("runs").default_value("20").value_parser(clap::value_parser!(u64)).help("Seeds 1..=runs (at most 10,000)"))
                .arg(
                    Arg::new("seeds")
                        .long("seeds")
                        .value_name("A-B")
                        .allow_hyphen_values(true)
                        .help("Run seeds A..=B only: one shard of a study, joined with the others by `planarium merge` (--runs N is --seeds 1-N; give one of them)"),
                )
                .arg(Arg::new("json").long("json").action(ArgAction::SetTrue).help("Print JSON instead of a table"))
                .arg(
                    Arg::new("course-table")
                        .long("course-table")
                        .action(ArgAction::SetTrue)
                        .help("Print the courses' table as Markdown (success; mean, std and median time; nodes; checks; cost; smoothed cost)"),
                )
                .arg(Arg::new("csv").long("csv").value_name("FILE").help("Also write every run as CSV (one row per run; see docs/benchmarks.md)"))
                .arg(Arg::new("json-file").long("json-file").value_name("FILE").help("Also write the report (runs and summaries) as JSON"))
                .arg(
                    Arg::new("course-csv")
                        .long("course-csv")
                        .value_name("FILE")
                        .help("Also write report 001's course benchmark lines, one per run: date,time,solved,plannerName,#vertices,#totalCollisionQueries,#freeQueries,time_ms (the Robotics Library's benchmark file; see docs/benchmarks.md)"),
                )
                .arg(Arg::new("more").num_args(0..).value_name("SCENARIO").help("More scenarios to grade (with --course-grade)"))
                .arg(
                    Arg::new("course-grade")
                        .long("course-grade")
                        .action(ArgAction::SetTrue)
                        .help("Grade ASV problems as the course did: 10 runs (seeds 1..10), solved when 5 pass the course's rules within 60 s (open map) or 300 s (cluttered: 3 obstacles or more); a verdict per file; exit code 2 when one fails. SCENARIO may be a directory (its .txt files)"),
                )
                .arg(Arg::new("course-runs").long("course-runs").hide(true).value_parser(clap::value_parser!(u64).range(1..=1000)))
                .arg(Arg::new("course-time-limit").long("course-time-limit").hide(true).value_parser(clap::value_parser!(f64)))
                .arg(
                    Arg::new("ompl-log")
                        .long("ompl-log")
                        .value_name("FILE")
                        .help("Also write an OMPL benchmark log (ompl_benchmark_statistics.py FILE -d bench.db, then upload bench.db to plannerarena.org)"),
                ),
        ))
        .subcommand(
            Command::new("scaling")
                .about("Time one state check among 10 to 100,000 obstacles, for the point, a rectangle and an arm")
                .arg(Arg::new("robots").long("robots").default_value("").help("Comma-separated robots (point, rectangle, arm; default: all)"))
                .arg(Arg::new("sizes").long("sizes").default_value("10,100,1000,10000,100000").help("Comma-separated obstacle counts"))
                .arg(Arg::new("checks").long("checks").default_value("200000").value_parser(clap::value_parser!(u64)).help("State checks per robot and size"))
                .arg(Arg::new("rounds").long("rounds").default_value("3").value_parser(clap::value_parser!(u32)).help("Rounds (the best is kept)"))
                .arg(Arg::new("json-file").long("json-file").value_name("FILE").help("Also write the rows as JSON")),
        )
        .subcommand(merge::command())
        .subcommand(Command::new("validate").about("Check a scenario and print it normalised").arg(scenario_arg.clone()))
        .subcommand(check::command())
        .subcommand(
            Command::new("export-map")
                .about("Rasterise a scenario's obstacles as an occupancy map: PREFIX.pgm and PREFIX.yaml in map_server's form (and PREFIX.png with --png)")
                .arg(scenario_arg)
                .arg(Arg::new("cell").long("cell").required(true).value_parser(clap::value_parser!(f64)).help("Side of a pixel, in scenario units"))
                .arg(Arg::new("out").long("out").required(true).value_name("PREFIX").help("Output path without extension"))
                .arg(Arg::new("png").long("png").action(ArgAction::SetTrue).help("Also write PREFIX.png (the same grid as an 8-bit grey PNG)")),
        )
        .subcommand(Command::new("list").about("List built-in scenarios and planners"))
}

fn params_for(spec: &'static PlannerSpec, sc: &Scenario, m: &ArgMatches) -> Result<Params, String> {
    // Scenario defaults first (when they are for this planner), then flags.
    let mut params = match &sc.planner {
        Some(d) if d.name == spec.name => Params::from_json(spec, &serde_json::Value::Object(d.params.clone()))
            .map_err(|(k, e)| format!("planner.{k}: {e}"))?,
        _ => Params::defaults(spec),
    };
    for p in all_param_specs() {
        if let Some(v) = m.get_one::<String>(p.name) {
            if spec.param(p.name).is_none() {
                return Err(format!("--{} is not a parameter of {}", param_flag(p.name), spec.name));
            }
            params.set_text(spec, p.name, v).map_err(|e| {
                let why = e.split_once(": ").map_or(e.as_str(), |(_, w)| w);
                format!("--{} {v}: {why}", param_flag(p.name))
            })?;
        }
    }
    // Not an error (scripts pass full parameter sets), but a flag nothing reads is said so.
    for p in all_param_specs() {
        let Some(own) = spec.param(p.name).filter(|_| m.get_one::<String>(p.name).is_some()) else { continue };
        if let Some(c) = own.applies.filter(|_| !own.applies_with(&params)) {
            let flag = |n: &str| format!("--{}", param_flag(n));
            let now = match c {
                planarium::params::Condition::OneOf(q, _) => format!("--{} is {}", param_flag(q), params.choice(q)),
                planarium::params::Condition::Positive(q) => format!("--{} is {}", param_flag(q), params.real(q)),
            };
            eprintln!(
                "note: --{} does nothing here: {} uses it only with {} ({now})",
                param_flag(p.name),
                spec.name,
                c.describe(flag)
            );
        }
    }
    Ok(params)
}

fn find_planner(name: &str) -> Result<&'static PlannerSpec, String> {
    planners::find(name).ok_or_else(|| {
        format!("unknown planner \"{}\" (known: {})", planarium::limits::cut(name, 100), planners::names().join(", "))
    })
}

fn run_bench(m: &ArgMatches) -> Result<(), String> {
    if m.get_flag("course-grade") {
        if m.get_one::<String>("seeds").is_some() {
            return Err("--seeds does not apply to --course-grade (the course's seeds are 1 to 10)".into());
        }
        return run_course_grade(m);
    }
    if m.get_many::<String>("more").is_some() {
        return Err("several scenarios are graded with --course-grade only; bench one at a time otherwise".into());
    }
    let sc = load(m.get_one::<String>("scenario").unwrap())?;
    Problem::from_scenario(&sc).map_err(|e| e.to_string())?;
    let (first, last) = bench_seeds(m)?;
    let runs = last - first + 1;
    let seeds = format!("seeds {first}..={last}");
    let mut rows = Vec::new();
    let setups: Vec<String> = match m.get_many::<String>("setup") {
        Some(v) => v.cloned().collect(),
        None => m
            .get_one::<String>("planners")
            .unwrap()
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .map(String::from)
            .collect(),
    };
    for text in &setups {
        let setup = bench::parse_setup(text, |spec| params_for(spec, &sc, m))
            .map_err(|e| format!("--setup \"{}\": {e}", planarium::limits::cut(text, 100)))?;
        let mut row = bench::bench_seeds(&sc, setup.spec.name, &setup.params, first, last)?;
        row.label = setup.label;
        eprintln!(
            "{}: {:.0}% solved, median {:.0} checks",
            row.label,
            row.summary.success_rate * 100.0,
            row.summary.checks.median
        );
        rows.push(row);
    }
    let scenario_arg = m.get_one::<String>("scenario").unwrap();
    // As `load` reads it: a file (its stem) before a built-in (its id).
    let path = std::path::Path::new(scenario_arg);
    let scenario_id =
        if path.exists() { path.file_stem().and_then(|s| s.to_str()).unwrap_or(scenario_arg) } else { scenario_arg }
            .to_string();
    let report = report::BenchReport::new(&sc.name, &scenario_id, &now_utc(), &host_name(), &rows);
    for (flag, format) in [("csv", "csv"), ("json-file", "json"), ("ompl-log", "ompl"), ("course-csv", "course")] {
        if let Some(file) = m.get_one::<String>(flag) {
            std::fs::write(file, report::render(&report, format)?).map_err(|e| format!("{file}: {e}"))?;
            eprintln!("wrote {file}");
        }
    }
    if m.get_flag("course-table") {
        println!("{} — {} seeded runs per set-up ({seeds})\n", sc.name, runs);
        print!("{}", report::course_table(&report));
    } else if m.get_flag("report") {
        println!("{} — {} seeded runs per set-up ({seeds})\n", sc.name, runs);
        print!("{}", bench::report_table(&rows));
    } else if m.get_flag("json") {
        let out = serde_json::json!({"scenario": sc.name, "runs": runs, "seeds": {"first": first, "last": last}, "planners": rows});
        println!("{}", serde_json::to_string_pretty(&out).unwrap());
    } else {
        println!("{} — {} seeded runs per planner ({seeds})\n", sc.name, runs);
        print!("{}", bench::table(&rows));
    }
    Ok(())
}

/// `bench --course-grade`: the ASV course's verdict per file (`planarium::run::course_grade`).
fn run_course_grade(m: &ArgMatches) -> Result<(), String> {
    use planarium::run::course_grade;
    let mut args: Vec<String> = vec![m.get_one::<String>("scenario").unwrap().clone()];
    args.extend(m.get_many::<String>("more").into_iter().flatten().cloned());
    let mut files = Vec::new();
    for a in args {
        let path = std::path::Path::new(&a);
        if path.is_dir() {
            let mut inside: Vec<String> = std::fs::read_dir(path)
                .map_err(|e| format!("{a}: {e}"))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "txt"))
                .map(|p| p.to_string_lossy().into_owned())
                .collect();
            inside.sort();
            if inside.is_empty() {
                return Err(format!("{a}: no .txt problem file in this directory"));
            }
            files.extend(inside);
        } else {
            files.push(a);
        }
    }
    if files.len() > 100 {
        return Err(format!("{} problems: grade at most 100 at a time", files.len()));
    }
    let runs = m.get_one::<u64>("course-runs").copied().unwrap_or(course_grade::COURSE_RUNS);
    let needed = if runs == course_grade::COURSE_RUNS { course_grade::COURSE_NEEDED } else { runs.div_ceil(2) };
    let limit = m.get_one::<f64>("course-time-limit").copied();
    let mut failed = 0;
    for f in &files {
        let sc = load(f)?;
        let spec = match &sc.planner {
            Some(d) => planners::find(&d.name)
                .ok_or_else(|| format!("{f}: unknown planner \"{}\"", planarium::limits::cut(&d.name, 100)))?,
            None => planners::find("rrt-connect").expect("rrt-connect is registered"),
        };
        let params = params_for(spec, &sc, m)?;
        let path = std::path::Path::new(f);
        let name = if path.exists() { path.file_stem().and_then(|s| s.to_str()).unwrap_or(f) } else { f };
        let g = course_grade::grade(&sc, name, spec.name, &params, runs, needed, limit)?;
        println!("{}", g.line());
        if !g.pass() {
            failed += 1;
        }
    }
    println!(
        "{} of {} problems pass ({runs} runs each, {needed} must pass the course's rules within the limit)",
        files.len() - failed,
        files.len()
    );
    if failed > 0 {
        return Err(format!("{failed} of {} problems fail the course's grading", files.len()));
    }
    Ok(())
}

fn run_scaling(m: &ArgMatches) -> Result<(), String> {
    let list = |name: &str| m.get_one::<String>(name).unwrap().split(',').map(str::trim).filter(|s| !s.is_empty());
    let robots: Vec<String> = list("robots").map(String::from).collect();
    let sizes: Vec<usize> =
        list("sizes").map(|s| s.parse().map_err(|e| format!("--sizes {s}: {e}"))).collect::<Result<_, _>>()?;
    if sizes.iter().any(|&n| n == 0 || n > 1_000_000) {
        return Err("--sizes: each between 1 and 1,000,000".into());
    }
    let rows =
        scaling::measure(&robots, &sizes, *m.get_one::<u64>("checks").unwrap(), *m.get_one::<u32>("rounds").unwrap());
    if let Some(file) = m.get_one::<String>("json-file") {
        std::fs::write(file, serde_json::to_string_pretty(&rows).unwrap()).map_err(|e| format!("{file}: {e}"))?;
        eprintln!("wrote {file}");
    }
    print!("{}", scaling::table(&rows));
    Ok(())
}

/// The current time, UTC, as `YYYY-MM-DDTHH:MM:SSZ` (the benchmark report's date).
fn now_utc() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    report::utc_timestamp(secs)
}

/// The machine's name, for the benchmark report: `$HOSTNAME`/`$COMPUTERNAME`, else the kernel's,
/// else "unknown".
fn host_name() -> String {
    let from_env = ["HOSTNAME", "COMPUTERNAME"].iter().find_map(|k| std::env::var(k).ok());
    let from_file =
        || ["/proc/sys/kernel/hostname", "/etc/hostname"].iter().find_map(|f| std::fs::read_to_string(f).ok());
    from_env
        .or_else(from_file)
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "unknown".into())
}

/// `export-map`: the scenario rasterised at `--cell`, written as PREFIX.pgm + PREFIX.yaml (+ .png).
fn export_map(m: &ArgMatches) -> Result<(), String> {
    use planarium::io::occupancy;
    let sc = load(m.get_one::<String>("scenario").unwrap())?;
    let cell = *m.get_one::<f64>("cell").unwrap();
    let grid = occupancy::scenario_to_grid(&sc, cell).map_err(|e| format!("--{e}"))?;
    let prefix = m.get_one::<String>("out").unwrap();
    let base = std::path::Path::new(prefix).file_name().and_then(|s| s.to_str()).unwrap_or("map").to_string();
    let (pgm, yaml) = occupancy::to_pgm_yaml(&grid, &format!("{base}.pgm"));
    let write = |ext: &str, bytes: &[u8]| {
        let f = format!("{prefix}.{ext}");
        std::fs::write(&f, bytes).map_err(|e| format!("{f}: {e}"))?;
        eprintln!("wrote {f}");
        Ok::<(), String>(())
    };
    write("pgm", &pgm)?;
    write("yaml", yaml.as_bytes())?;
    if m.get_flag("png") {
        write("png", &occupancy::to_png(&grid))?;
    }
    Ok(())
}

fn main() -> ExitCode {
    // A closed pipe ends the process as it ends other command-line tools (the shell sees SIGPIPE),
    // instead of a panic on the next write: Rust starts programs with SIGPIPE ignored.
    #[cfg(unix)]
    // SAFETY: called once, first thing, before any other thread exists; SIG_DFL is a valid handler.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let m = cli().get_matches();
    let r = match m.subcommand() {
        Some(("plan", m)) => plan::plan(m),
        Some(("bench", m)) => run_bench(m),
        Some(("merge", m)) => merge::run(m),
        Some(("scaling", m)) => run_scaling(m),
        Some(("validate", m)) => load(m.get_one::<String>("scenario").unwrap()).and_then(|sc| {
            Problem::from_scenario(&sc).map_err(|e| e.to_string())?;
            println!("{}", sc.to_json());
            Ok(())
        }),
        Some(("check-path", m)) => match check::run(m) {
            Ok(true) => Ok(()),
            Ok(false) => return ExitCode::from(1),
            Err(e) => Err(e),
        },
        Some(("export-map", m)) => export_map(m),
        Some(("list", _)) => {
            println!("Built-in scenarios:");
            for (id, _) in scenario::BUILTINS {
                let sc = scenario::builtin(id).expect("built-ins are valid");
                println!("  {id:<12} {}", sc.name);
            }
            println!("Planners:");
            for p in planners::REGISTRY {
                println!("  {:<12} {}", p.name, p.summary);
            }
            Ok(())
        }
        _ => unreachable!("clap requires a subcommand"),
    };
    match r {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
