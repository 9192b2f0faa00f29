//! The readers `bench_export.rs` checks the exports with: an RFC 4180 CSV reader and an OMPL
//! benchmark log reader following `readBenchmarkLog` of OMPL's `ompl_benchmark_statistics.py`.

use super::*;

// ---------------------------------------------------------------------------------------------
// A tiny RFC 4180 reader: quoted fields, doubled quotes, CRLF (or LF) record ends.

pub(super) fn read_csv(text: &str) -> Vec<Vec<String>> {
    let mut records = Vec::new();
    let mut record = Vec::new();
    let mut field = String::new();
    let mut chars = text.chars().peekable();
    let mut quoted = false;
    while let Some(c) = chars.next() {
        if quoted {
            match c {
                '"' if chars.peek() == Some(&'"') => {
                    chars.next();
                    field.push('"');
                }
                '"' => quoted = false,
                _ => field.push(c),
            }
            continue;
        }
        match c {
            '"' => {
                assert!(field.is_empty(), "a quote inside an unquoted field: {field:?}");
                quoted = true;
            }
            ',' => record.push(std::mem::take(&mut field)),
            '\r' | '\n' => {
                if c == '\r' {
                    assert_eq!(chars.next(), Some('\n'), "CR without LF");
                }
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
            }
            _ => field.push(c),
        }
    }
    assert!(!quoted, "unterminated quoted field");
    assert!(field.is_empty() && record.is_empty(), "the last record has no line break");
    records
}

pub(super) fn opt_f64(s: &str) -> Option<f64> {
    (!s.is_empty()).then(|| s.parse().unwrap())
}

// ---------------------------------------------------------------------------------------------
// An OMPL benchmark log reader following readBenchmarkLog (ompl_benchmark_statistics.py): the
// same lines, the same tokens, the same optional parts.

#[derive(Debug, PartialEq)]
pub(super) struct OmplPlanner {
    pub(super) name: String,
    pub(super) common: Vec<String>,
    /// (column name as the reader makes it: words joined by `_`, type).
    pub(super) properties: Vec<(String, String)>,
    /// One row per run; `None` for an empty value (or `nan`/`inf`, as the reader stores NULL).
    pub(super) runs: Vec<Vec<Option<String>>>,
}

#[derive(Debug, PartialEq)]
pub(super) struct OmplLog {
    pub(super) version: String,
    pub(super) experiment: String,
    pub(super) host: String,
    pub(super) date: String,
    pub(super) setup: String,
    pub(super) cpuinfo: Option<String>,
    pub(super) seed: String,
    pub(super) time_limit: f64,
    pub(super) memory_limit: f64,
    pub(super) runs_per_planner: i64,
    pub(super) total_time: f64,
    pub(super) enums: Vec<Vec<String>>,
    pub(super) planners: Vec<OmplPlanner>,
}

pub(super) struct Lines<'a> {
    pub(super) lines: Vec<&'a str>,
    pub(super) at: usize,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Lines<'a> {
        assert!(text.ends_with('\n'), "the log ends with a line break");
        assert!(!text.contains('\r'), "EOL is \\n");
        Lines { lines: text[..text.len() - 1].split('\n').collect(), at: 0 }
    }
    fn next(&mut self) -> &'a str {
        let l = self.lines.get(self.at).unwrap_or_else(|| panic!("log ends early at line {}", self.at + 1));
        self.at += 1;
        l
    }
    fn peek(&self) -> Option<&'a str> {
        self.lines.get(self.at).copied()
    }
    /// readLogValue: the token at `index` (negative: from the end) when the expected tokens match,
    /// else the line is not consumed.
    fn value(&mut self, index: isize, expected: &[(isize, &str)]) -> Option<String> {
        let tokens: Vec<&str> = self.peek()?.split_whitespace().collect();
        let at = |i: isize| if i < 0 { tokens.len().checked_sub(i.unsigned_abs()) } else { Some(i as usize) };
        for (i, want) in expected {
            if at(*i).and_then(|k| tokens.get(k)) != Some(want) {
                return None;
            }
        }
        self.at += 1;
        Some(tokens[at(index).unwrap()].to_string())
    }
    fn required(&mut self, what: &str, index: isize, expected: &[(isize, &str)]) -> String {
        let line = self.peek().map(str::to_string);
        self.value(index, expected).unwrap_or_else(|| panic!("unable to read {what} from {line:?}"))
    }
    fn multiline(&mut self) -> Option<String> {
        if !self.peek()?.starts_with("<<<|") {
            return None;
        }
        self.next();
        let mut value = String::new();
        loop {
            let l = self.next();
            if l.starts_with("|>>>") {
                return Some(value);
            }
            value.push_str(l);
            value.push('\n');
        }
    }
}

pub(super) fn read_ompl_log(text: &str) -> OmplLog {
    let mut l = Lines::new(text);
    let first: Vec<&str> = l.peek().unwrap().split_whitespace().collect();
    let version = if first.get(1) == Some(&"version") {
        l.next();
        format!("{} {}", first[0], first.last().unwrap())
    } else {
        "OMPL 0.0.0".into()
    };
    let experiment = l.required("experiment name", -1, &[(0, "Experiment")]);
    let n_props: usize = l.value(0, &[(-2, "experiment"), (-1, "properties")]).map_or(0, |s| s.parse().unwrap());
    for _ in 0..n_props {
        assert!(l.next().contains(" = "));
    }
    let host = l.required("hostname", -1, &[(0, "Running")]);
    let date_line = l.next();
    assert!(date_line.starts_with("Starting"));
    let date = date_line.split_whitespace().skip(2).collect::<Vec<_>>().join(" ");
    let setup = l.multiline().expect("the setup block");
    let cpuinfo = l.multiline();
    let seed = l.required("random seed", 0, &[(-2, "random"), (-1, "seed")]);
    let time_limit = l.required("time limit", 0, &[(-3, "seconds"), (-2, "per"), (-1, "run")]).parse().unwrap();
    let memory_limit = l.required("memory limit", 0, &[(-3, "MB"), (-2, "per"), (-1, "run")]).parse().unwrap();
    let runs_per_planner = l.value(0, &[(-3, "runs"), (-2, "per"), (-1, "planner")]).map_or(-1, |s| s.parse().unwrap());
    let total_time = l.required("total time", 0, &[(-3, "collect"), (-2, "the"), (-1, "data")]).parse().unwrap();
    let n_enums: usize = l.value(0, &[(-2, "enum")]).map_or(0, |s| s.parse().unwrap());
    let enums = (0..n_enums).map(|_| l.next().split('|').map(String::from).collect()).collect();
    let n_planners: usize = l.required("planner count", 0, &[(-1, "planners")]).parse().unwrap();
    let mut planners = Vec::new();
    for _ in 0..n_planners {
        let name = l.next().to_string();
        let n_common: usize = l.next().split_whitespace().next().unwrap().parse().unwrap();
        let common = (0..n_common).map(|_| l.next().to_string()).collect();
        let n_properties: usize = l.next().split_whitespace().next().unwrap().parse().unwrap();
        let properties: Vec<(String, String)> = (0..n_properties)
            .map(|_| {
                let field: Vec<&str> = l.next().split_whitespace().collect();
                (field[..field.len() - 1].join("_"), field[field.len() - 1].to_string())
            })
            .collect();
        let n_runs: usize = l.next().split_whitespace().next().unwrap().parse().unwrap();
        let mut runs = Vec::new();
        for _ in 0..n_runs {
            // `line.split('; ')[:-1]`: every value is followed by "; ".
            let parts: Vec<&str> = l.next().split("; ").collect();
            assert_eq!(parts.last(), Some(&""), "a run line ends with \"; \"");
            let values: Vec<Option<String>> = parts[..parts.len() - 1]
                .iter()
                .map(|x| (!x.is_empty() && *x != "nan" && *x != "inf").then(|| x.to_string()))
                .collect();
            assert_eq!(values.len(), properties.len(), "one value per property in {name}");
            runs.push(values);
        }
        let next = l.next().trim();
        if next != "." {
            // Progress properties: a count, names, a run count, one line per run, then ".".
            let n: usize = next.split_whitespace().next().unwrap().parse().unwrap();
            for _ in 0..n {
                l.next();
            }
            let m: usize = l.next().split_whitespace().next().unwrap().parse().unwrap();
            for _ in 0..m {
                l.next();
            }
            assert_eq!(l.next().trim(), ".");
        }
        planners.push(OmplPlanner { name, common, properties, runs });
    }
    assert_eq!(l.peek(), None, "nothing after the last planner");
    OmplLog {
        version,
        experiment,
        host,
        date,
        setup,
        cpuinfo,
        seed,
        time_limit,
        memory_limit,
        runs_per_planner,
        total_time,
        enums,
        planners,
    }
}

/// A planner's runs as maps from column name to value.
pub(super) fn ompl_runs(p: &OmplPlanner) -> Vec<BTreeMap<String, Option<String>>> {
    p.runs.iter().map(|r| p.properties.iter().map(|(n, _)| n.clone()).zip(r.iter().cloned()).collect()).collect()
}

pub(super) fn int(v: &Option<String>) -> u64 {
    v.as_deref().expect("a value").parse().unwrap()
}

pub(super) fn real(v: &Option<String>) -> Option<f64> {
    v.as_deref().map(|s| s.parse().unwrap())
}

pub(super) fn assert_same_report(a: &BenchReport, b: &BenchReport) {
    // Exact: serde_json's float_roundtrip feature (Cargo.toml) reads every number back to the
    // same double.
    let (x, y) = (serde_json::to_value(a).unwrap(), serde_json::to_value(b).unwrap());
    assert_eq!(x, y, "reports differ");
}

// ---------------------------------------------------------------------------------------------
