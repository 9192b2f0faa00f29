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
