//! Sharded benchmarks: `planarium bench … --seeds A-B` runs one shard, `planarium merge` joins
//! shards into the files a single run over all their seeds writes. Seeds 1-3 and 4-6 merged (in
//! either order) equal seeds 1-6 in one run, in JSON, CSV and the OMPL log, byte for byte once what
//! the clock decides (times, the date, the host) is masked; each refusal fires with its message.

use planarium::run::report::{merge, OMPL_RUN_PROPERTIES};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A temporary directory, removed when dropped.
struct Dir(PathBuf);

impl Dir {
    fn new(tag: &str) -> Dir {
        let d = std::env::temp_dir().join(format!("planarium-shards-{tag}-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        Dir(d)
    }
    fn at(&self, name: &str) -> String {
        self.0.join(name).to_string_lossy().into_owned()
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

fn planarium<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_planarium")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

/// Solved runs (RRT-Connect) and unsolved ones (RRT stopped after 5 iterations: empty costs).
const SETUPS: [&str; 4] = ["--setup", "rrt-connect", "--setup", "capped: rrt --max-iterations 5"];

/// `bench SCENARIO --seeds SEEDS [extra] --json-file STEM.json --csv STEM.csv --ompl-log STEM.log`
/// with `setups` (or [`SETUPS`]).
fn bench(dir: &Dir, stem: &str, scenario: &str, seeds: &str, setups: Option<&[&str]>, extra: &[&str]) {
    let mut args: Vec<String> = vec!["bench".into(), scenario.into(), "--seeds".into(), seeds.into()];
    args.extend(setups.unwrap_or(&SETUPS).iter().map(|s| s.to_string()));
    args.extend(extra.iter().map(|s| s.to_string()));
    for (flag, ext) in [("--json-file", "json"), ("--csv", "csv"), ("--ompl-log", "log")] {
        args.push(flag.into());
        args.push(dir.at(&format!("{stem}.{ext}")));
    }
    let (ok, err) = planarium(&args);
    assert!(ok, "bench {seeds}: {err}");
}

fn read(path: &str) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The pretty JSON with what the clock decides replaced by `T`: `date`, `host`, every row's
/// `time_ms` and `smoothing_ms`, and the median, mean and std of each summary's `time_ms`. Returns
/// the text and how many values were masked.
fn mask_json(text: &str) -> (String, usize) {
    let (mut out, mut masked, mut in_time) = (String::new(), 0, false);
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        let key = t.split(':').next().unwrap_or("");
        let clocked = match key {
            "\"date\"" | "\"host\"" | "\"smoothing_ms\"" => true,
            "\"time_ms\"" if t.trim_end().ends_with('{') => {
                in_time = true;
                false
            }
            "\"time_ms\"" => true,
            "\"median\"" | "\"mean\"" | "\"std\"" => in_time,
            _ => {
                if t.starts_with('}') {
                    in_time = false;
                }
                false
            }
        };
        if clocked {
            let indent = &line[..line.len() - t.len()];
            let comma = if t.trim_end().ends_with(',') { "," } else { "" };
            out.push_str(&format!("{indent}{key}: T{comma}\n"));
            masked += 1;
        } else {
            out.push_str(line);
        }
    }
    (out, masked)
}

/// The CSV with its `time_ms` column (the sixth) replaced by `T` (the labels here hold no comma
/// nor quote, so a line splits at its commas).
fn mask_csv(text: &str) -> (String, usize) {
    let mut masked = 0;
    let lines: Vec<String> = text
        .split("\r\n")
        .enumerate()
        .map(|(i, line)| {
            if i == 0 || line.is_empty() {
                return line.to_string();
            }
            assert!(!line.contains('"'), "{line}");
            let mut f: Vec<&str> = line.split(',').collect();
            assert_eq!(f.len(), 11, "{line}");
            f[5] = "T";
            masked += 1;
            f.join(",")
        })
        .collect();
    (lines.join("\r\n"), masked)
}

/// The OMPL log with the host, the date, the total time and each run's `time` and
/// `simplification time` replaced by `T`.
fn mask_ompl(text: &str) -> (String, usize) {
    let col = |p: &str| OMPL_RUN_PROPERTIES.iter().position(|x| *x == p).unwrap();
    let clocked = [col("time REAL"), col("simplification time REAL")];
    let mut masked = 0;
    let mut out = String::new();
    for line in text.split_inclusive('\n') {
        let body = line.trim_end_matches('\n');
        let new = if body.starts_with("Running on ") || body.starts_with("Starting at ") {
            format!("{} T", &body[..11])
        } else if body.ends_with(" seconds spent to collect the data") {
            "T seconds spent to collect the data".to_string()
        } else if body.ends_with("; ") && body.split("; ").count() == OMPL_RUN_PROPERTIES.len() + 1 {
            let mut f: Vec<&str> = body.split("; ").collect();
            for &i in &clocked {
                f[i] = "T";
            }
            f.join("; ")
        } else {
            out.push_str(line);
            continue;
        };
        masked += 1;
        out.push_str(&new);
        out.push('\n');
    }
    (out, masked)
}

#[test]
fn two_shards_merged_are_the_single_run_byte_for_byte_but_the_clock() {
    let d = Dir::new("same");
    bench(&d, "all", "narrow", "1-6", None, &[]);
    bench(&d, "a", "narrow", "1-3", None, &[]);
    bench(&d, "b", "narrow", "4-6", None, &[]);
    // The shards in either order: the merge puts runs in seed order.
    let (ok, err) = planarium(&[
        "merge",
        &d.at("b.json"),
        &d.at("a.json"),
        "--json-file",
        &d.at("m.json"),
        "--csv",
        &d.at("mj.csv"),
        "--ompl-log",
        &d.at("mj.log"),
    ]);
    assert!(ok, "{err}");
    let (ok, err) = planarium(&["merge", &d.at("a.csv"), &d.at("b.csv"), "--csv", &d.at("m.csv")]);
    assert!(ok, "{err}");
    let (ok, err) = planarium(&["merge", &d.at("b.log"), &d.at("a.log"), "--ompl-log", &d.at("m.log")]);
    assert!(ok, "{err}");

    let single = read(&d.at("all.json"));
    let merged = read(&d.at("m.json"));
    let (want, n) = mask_json(&single);
    // date, host; 2 set-ups × 6 runs × (time, smoothing); 2 set-ups × (median, mean, std) of time.
    assert_eq!(n, 2 + 2 * 6 * 2 + 2 * 3, "{want}");
    assert_eq!(mask_json(&merged), (want, n));
    for (file, mask) in
        [("all.csv", mask_csv as fn(&str) -> (String, usize)), ("all.log", mask_ompl as fn(&str) -> (String, usize))]
    {
        let (want, n) = mask(&read(&d.at(file)));
        assert_eq!(n, if file.ends_with("csv") { 12 } else { 3 + 12 }, "{file}: {want}");
        let ext = &file[4..];
        for merged in [format!("m.{ext}"), format!("mj.{ext}")] {
            assert_eq!(mask(&read(&d.at(&merged))), (want.clone(), n), "{merged} against {file}");
        }
    }
    // Not vacuous: the merged summary is the single run's, which is not the shards' average.
    let v = |t: &str| serde_json::from_str::<serde_json::Value>(t).unwrap();
    let (all, a, b) = (v(&single), v(&read(&d.at("a.json"))), v(&read(&d.at("b.json"))));
    // (With 3 + 3 runs the median of all is often the average of the shards' medians: the std is
    // never, short of a coincidence.)
    let std = |r: &serde_json::Value| r["setups"][0]["summary"]["checks"]["std"].as_f64().unwrap();
    assert_ne!(std(&all), (std(&a) + std(&b)) / 2.0, "pick seeds whose stds do not average");
    assert_eq!(v(&merged)["setups"][0]["summary"]["checks"], all["setups"][0]["summary"]["checks"]);
    assert_eq!((a["seeds"]["first"].as_u64(), a["seeds"]["last"].as_u64()), (Some(1), Some(3)));
    assert_eq!(v(&merged)["seeds"], all["seeds"]);
    let seeds: Vec<u64> =
        v(&merged)["setups"][1]["rows"].as_array().unwrap().iter().map(|r| r["seed"].as_u64().unwrap()).collect();
    assert_eq!(seeds, [1, 2, 3, 4, 5, 6]);
    // One shard's runs are its own: equal to the single run's rows 4-6 (but the clock).
    assert_eq!(
        a["setups"][0]["rows"].as_array().unwrap().iter().map(|r| r["checks"].clone()).collect::<Vec<_>>(),
        all["setups"][0]["rows"].as_array().unwrap()[..3].iter().map(|r| r["checks"].clone()).collect::<Vec<_>>()
    );
}

#[test]
fn the_seed_flags_are_checked_with_errors_naming_them() {
    for (args, want) in [
        (vec!["--runs", "3", "--seeds", "1-3"], "--runs and --seeds are both given"),
        (vec!["--seeds", "5-3"], "--seeds \"5-3\": the first seed (5) is after the last (3)"),
        (vec!["--seeds", "-1-3"], "--seeds \"-1-3\": the first seed must be at least 0"),
        (vec!["--seeds", "1-10001"], "--seeds \"1-10001\": 10001 seeds; the limit is 10000"),
        (vec!["--seeds", "a-3"], "--seeds \"a-3\": the first seed \"a\" is not a whole number"),
        (vec!["--seeds", "1-"], "--seeds \"1-\": the last seed is missing"),
        (vec!["--seeds", "0-18446744073709551616"], "the last seed \"18446744073709551616\" is not a whole number"),
        (vec!["--runs", "10001"], "--runs 10001: from 1 to 10000"),
        (vec!["--runs", "0"], "--runs 0: from 1 to 10000"),
    ] {
        let mut all = vec!["bench", "narrow", "--planners", "rrt-connect"];
        all.extend(&args);
        let (ok, err) = planarium(&all);
        assert!(!ok && err.contains(want), "{args:?}: {err} (wanted: {want})");
    }
    // The bounds themselves run: seed 0, a single seed, the last u64 seeds.
    let d = Dir::new("bounds");
    for (seeds, first, last) in
        [("0-1", 0, 1), ("7", 7, 7), ("18446744073709551614-18446744073709551615", u64::MAX - 1, u64::MAX)]
    {
        let out = d.at("r.json");
        let (ok, err) =
            planarium(&["bench", "narrow", "--planners", "rrt-connect", "--seeds", seeds, "--json-file", &out]);
        assert!(ok, "{seeds}: {err}");
        let r = planarium::run::report::from_json(&read(&out)).unwrap();
        let got: Vec<u64> = r.setups[0].rows.iter().map(|x| x.seed).collect();
        assert_eq!(got, (first..=last).collect::<Vec<_>>());
        assert_eq!(r.seeds.map(|s| (s.first, s.last)), Some((first, last)));
    }
}

/// `merge SHARDS… OUTPUT`: the error, which must name `want` (each string).
fn refused(shards: &[String], output: &[&str], want: &[&str]) {
    let mut args: Vec<String> = vec!["merge".into()];
    args.extend(shards.iter().cloned());
    args.extend(output.iter().map(|s| s.to_string()));
    let (ok, err) = planarium(&args);
    assert!(!ok, "{args:?} was merged");
    for w in want {
        assert!(err.contains(w), "{args:?}: {err} (wanted: {w})");
    }
}

#[test]
fn merge_refuses_what_a_single_run_could_not_have_written() {
    let d = Dir::new("refuse");
    bench(&d, "a", "narrow", "1-3", None, &[]);
    bench(&d, "overlap", "narrow", "3-6", None, &[]);
    bench(&d, "gap", "narrow", "5-6", None, &[]);
    bench(&d, "scene", "open-field", "4-6", None, &[]);
    bench(
        &d,
        "planner",
        "narrow",
        "4-6",
        Some(&["--setup", "rrt-connect", "--setup", "capped: est --max-iterations 5"]),
        &[],
    );
    bench(
        &d,
        "params",
        "narrow",
        "4-6",
        Some(&["--setup", "rrt-connect", "--setup", "capped: rrt --max-iterations 6"]),
        &[],
    );
    bench(&d, "limit", "narrow", "4-6", None, &["--time-limit", "20"]);
    let f = |stem: &str, ext: &str| d.at(&format!("{stem}.{ext}"));
    let out = d.at("out");
    for (ext, flag) in [("json", "--json-file"), ("csv", "--csv"), ("log", "--ompl-log")] {
        let (a, o) = (f("a", ext), f("overlap", ext));
        let refuse = |other: &str, want: &[&str]| refused(&[a.clone(), f(other, ext)], &[flag, &out], want);
        refuse("overlap", &[&o, "seeds 3-6 overlap", &a, "seeds 1-3", "one shard only"]);
        refuse("gap", &["seeds 4-4 are in no shard", &a, "ends at seed 3", "starts at seed 5", "--seeds 4-4"]);
        refuse("planner", &[&f("planner", ext), "differ", &a]);
        if ext != "csv" {
            refuse("scene", &[&f("scene", ext), "differ", &a, "Open"]);
            refuse("params", &[&f("params", ext), "differ", &a, "max_iterations"]);
            refuse("limit", &[&f("limit", ext), "differ", &a, "20"]);
        }
    }
    // What differs is named.
    refused(
        &[f("a", "json"), f("scene", "json")],
        &["--json-file", &out],
        &["the scenario differs", "\"Narrow passage\" there, \"Open field\" here"],
    );
    refused(
        &[f("a", "json"), f("planner", "json")],
        &["--json-file", &out],
        &["setups[1] (capped)'s planner differs", "\"rrt\" there, \"est\" here"],
    );
    refused(
        &[f("a", "json"), f("params", "json")],
        &["--json-file", &out],
        &["setups[1] (capped)'s parameters differ", "{\"max_iterations\":5.0} there, {\"max_iterations\":6.0} here"],
    );
    refused(
        &[f("a", "json"), f("limit", "json")],
        &["--json-file", &out],
        &["the time limit differs", "30 s there, 20 s here"],
    );
    refused(
        &[f("a", "log"), f("params", "log")],
        &["--ompl-log", &out],
        &["line 11 differs from", "line 11", "max_iterations"],
    );
    // A CSV holds no parameters: CSV shards of other parameters are not told apart (merge the JSON).
    let (ok, err) = planarium(&["merge", &f("a", "csv"), &f("params", "csv"), "--csv", &d.at("weak.csv")]);
    assert!(ok, "{err}");
    // Mixed formats, outputs the shards cannot give, files that are not bench outputs.
    refused(
        &[f("a", "json"), f("overlap", "csv")],
        &["--csv", &out],
        &["is a CSV but", "is a JSON report: merge shards of one format"],
    );
    refused(&[f("a", "csv")], &["--json-file", &out], &["--json-file is written from JSON shards only"]);
    refused(&[f("a", "log")], &["--csv", &out], &["--csv is written from JSON shards only"]);
    refused(&[f("a", "json")], &[], &["nothing to write"]);
    let scenario = d.at("scenario.json");
    std::fs::write(&scenario, planarium::scenario::builtin("narrow").unwrap().to_json()).unwrap();
    refused(&[f("a", "json"), scenario.clone()], &["--json-file", &out], &[&scenario, "bench report: missing field"]);
    let text = d.at("notes.txt");
    std::fs::write(&text, "seed,time\n1,2\n").unwrap();
    refused(std::slice::from_ref(&text), &["--csv", &out], &[&text, "not a bench output"]);
    // A shard cut short: the OMPL log's last planner loses its last run.
    let log = read(&f("a", "log"));
    let cut_log = d.at("cut.log");
    let lines: Vec<&str> = log.lines().collect();
    std::fs::write(&cut_log, lines[..lines.len() - 2].join("\n") + "\n.\n").unwrap();
    refused(std::slice::from_ref(&cut_log), &["--ompl-log", &out], &[&cut_log, "line 61: a run of 0 values, not 11"]);
    // A shard over the size limit is refused before it is read whole.
    let big = d.at("big.json");
    let file = std::fs::File::create(&big).unwrap();
    file.set_len(planarium::limits::MAX_TEXT_BYTES as u64 + 1).unwrap();
    refused(&[f("a", "json"), big.clone()], &["--json-file", &out], &[&big, "larger than the limit of 16777216 bytes"]);
    assert!(!Path::new(&out).exists(), "nothing is written when a merge is refused");
}

fn shard<'a>(name: &'a str, text: &'a str) -> merge::Shard<'a> {
    merge::Shard { name, text }
}

/// The library's merge, on texts edited to be what `bench` never writes.
#[test]
fn the_library_merge_checks_each_shard_on_its_own() {
    let d = Dir::new("lib");
    bench(&d, "a", "narrow", "1-3", None, &[]);
    bench(&d, "b", "narrow", "4-6", None, &[]);
    let (a, b) = (read(&d.at("a.json")), read(&d.at("b.json")));
    let ok = merge::merge_json(&[shard("b", &b), shard("a", &a)]).unwrap();
    assert_eq!((ok.runs, ok.seeds.map(|s| (s.first, s.last))), (6, Some((1, 6))));
    // A set-up that lost a run: its rows no longer hold the seeds the report says.
    let mut v: serde_json::Value = serde_json::from_str(&a).unwrap();
    v["setups"][1]["rows"].as_array_mut().unwrap().pop();
    let e = merge::merge_json(&[shard("a2", &v.to_string()), shard("b", &b)]).unwrap_err();
    assert!(e.contains("a2: bench report: setups[1].rows: hold seeds 1-2, but seeds says 1-3"), "{e}");
    // Without `seeds` (as the page writes a report), the set-ups must still hold the same seeds.
    v.as_object_mut().unwrap().remove("seeds");
    let e = merge::merge_json(&[shard("a3", &v.to_string()), shard("b", &b)]).unwrap_err();
    assert!(e.contains("a3: setups[1] (capped) holds seeds 1-2 but setups[0] (rrt-connect) holds 1-3"), "{e}");
    // `runs` that is not the rows'.
    let mut v: serde_json::Value = serde_json::from_str(&a).unwrap();
    v["runs"] = 5.into();
    let e = merge::merge_json(&[shard("a4", &v.to_string())]).unwrap_err();
    assert!(e.contains("a4: runs is 5 but each set-up holds 3 runs"), "{e}");
    // Too many shards, checked before any is read.
    let many = vec![shard("x", ""); merge::MAX_SHARDS + 1];
    let e = merge::merge_json(&many).unwrap_err();
    assert!(e.contains("10001 shards; the limit is 10000"), "{e}");
    // CSV: a row with a field too many, and a seed that is not a number, named by line.
    let csv = read(&d.at("a.csv"));
    let bad = csv.replacen("rrt-connect,rrt-connect,2,", "rrt-connect,rrt-connect,2,x,", 1);
    let e = merge::merge_csv(&[shard("c", &bad)]).unwrap_err();
    assert!(e.contains("c: line 3: more than 11 fields"), "{e}");
    let bad = csv.replacen("rrt-connect,rrt-connect,2,", "rrt-connect,rrt-connect,two,", 1);
    let e = merge::merge_csv(&[shard("c", &bad)]).unwrap_err();
    assert!(e.contains("c: line 3: seed \"two\" is not a whole number"), "{e}");
}
