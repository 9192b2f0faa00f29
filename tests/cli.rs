//! The command line's own flags: `--version` names the crate's version (what a course's notes cite
//! beside a figure), and the planner flags generated from the registry are all there by name.

use std::process::Command;

fn planarium(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_planarium")).args(args).output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn version_prints_the_crates_version() {
    for flag in ["--version", "-V"] {
        let (ok, out, err) = planarium(&[flag]);
        assert!(ok, "{flag}: {err}");
        assert_eq!(out.trim(), format!("planarium {}", env!("CARGO_PKG_VERSION")));
    }
}

#[test]
fn every_registry_parameter_is_a_flag_of_plan_and_bench() {
    for cmd in ["plan", "bench"] {
        let (ok, help, err) = planarium(&[cmd, "--help"]);
        assert!(ok, "{cmd} --help: {err}");
        for spec in planarium::planners::REGISTRY.iter().flat_map(|p| p.all_params()) {
            let flag = format!("--{}", spec.name.replace('_', "-"));
            assert!(help.contains(&format!("{flag} <VALUE>")), "{cmd} --help lacks {flag}");
        }
    }
    // A generated flag is parsed, not only listed.
    let (ok, out, err) = planarium(&["plan", "narrow", "--goal-bias", "0.3", "--seed", "2", "--json"]);
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["status"], "solved");
    assert_eq!(r["params"]["goal_bias"], 0.3);
    assert_eq!(r["seed"], 2);
}

#[test]
fn a_reader_that_closes_the_pipe_ends_the_command_quietly() {
    use std::io::Read;
    use std::process::Stdio;
    // `planarium validate big.json | head -c 100`: the scenario printed back is far more than a
    // pipe holds, so the command is still writing when the reader closes the pipe.
    let obstacles: Vec<serde_json::Value> = (0..20_000)
        .map(|i| serde_json::json!({"rect": [0.3 + (i % 100) as f64 * 0.004, 0.3 + (i / 100) as f64 * 0.002, 0.3 + (i % 100) as f64 * 0.004 + 0.001, 0.3 + (i / 100) as f64 * 0.002 + 0.001]}))
        .collect();
    let doc = serde_json::json!({"bounds": [0, 0, 1, 1], "obstacles": obstacles, "robot": {"kind": "point"},
        "start": [0.1, 0.1], "goal": [0.9, 0.9], "resolution": 0.01});
    let file = std::env::temp_dir().join(format!("planarium-cli-pipe-{}.json", std::process::id()));
    std::fs::write(&file, doc.to_string()).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["validate", file.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 100];
    child.stdout.as_mut().unwrap().read_exact(&mut first).unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    std::fs::remove_file(&file).ok();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "a panic on the closed pipe: {err}");
    assert!(first.starts_with(b"{"), "{}", String::from_utf8_lossy(&first));
}

#[test]
fn a_parameter_that_does_not_apply_is_said_so_in_help_and_noted_when_passed() {
    let (ok, help, _) = planarium(&["plan", "--help"]);
    assert!(ok);
    let line = |flag: &str| help.lines().find(|l| l.trim_start().starts_with(flag)).unwrap_or("").to_string();
    assert!(line("--range ").contains("(rrt-connect: with --connect range)"), "{}", line("--range "));
    assert!(line("--epsilon ").contains("(with --connect last-free)"), "{}", line("--epsilon "));
    assert!(line("--sigma ").contains("(with --sampler gaussian or bridge)"), "{}", line("--sigma "));
    // Passed where it does nothing: a note on stderr, not an error; the run goes on.
    let (ok, _, err) = planarium(&[
        "plan",
        "scenarios/puma-rbo-wall.json",
        "--range",
        "0.5",
        "--epsilon",
        "1e-9",
        "--max-iterations",
        "3",
    ]);
    assert!(ok, "{err}");
    let notes: Vec<&str> = err.lines().filter(|l| l.starts_with("note: ")).collect();
    assert_eq!(
        notes,
        ["note: --range does nothing here: rrt-connect uses it only with --connect range (--connect is last-free)"]
    );
    let (ok, _, err) = planarium(&[
        "plan",
        "scenarios/puma-rbo-wall.json",
        "--connect",
        "range",
        "--epsilon",
        "1e-9",
        "--max-iterations",
        "3",
    ]);
    assert!(ok, "{err}");
    assert!(err.contains("note: --epsilon does nothing here"), "{err}");
}
