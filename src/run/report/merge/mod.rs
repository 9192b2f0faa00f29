//! Shards of one benchmark joined back into the report a single run over all their seeds would
//! have written (`planarium merge`; `docs/benchmarks.md`, "Sharding a study").
//!
//! A study is cut into shards by seeds (`planarium bench … --seeds 1-10`, `--seeds 11-20`, …),
//! each run where there is a core. Each format merges on its own: JSON reports
//! ([`merge_json`], which can then be written in every format), CSVs ([`merge_csv`]) and OMPL
//! logs ([`merge_ompl`]). The merge
//!
//! - puts every set-up's runs in seed order, whatever the order of the files;
//! - recomputes everything computed from the runs (the JSON's summaries, the counts of runs, the
//!   seed lists, the OMPL log's first seed and total time), never averages the shards' numbers;
//! - takes the earliest shard's date and the hosts, in seed order, joined by `+`;
//! - refuses, naming the file and what differs: a file that is not a bench output, shards of
//!   another scenario, set-ups (labels, planners, parameters) or time limit, a shard whose set-ups
//!   ran different seeds, seeds in two shards, a gap between shards (a single run has none: the
//!   missing seeds are named, to be run as one more shard), more than [`MAX_SHARDS`] files, a file
//!   over [`MAX_TEXT_BYTES`](crate::limits::MAX_TEXT_BYTES) or all of them over
//!   [`MAX_MERGE_BYTES`], more than [`MAX_RUNS`](crate::run::bench::MAX_RUNS) seeds in all.
//!
//! A CSV holds neither the scenario nor the parameters: CSV shards are checked on their set-ups'
//! labels and planners and their seeds only. Merge the JSON shards to have everything checked.

mod csv;
mod ompl;

pub use self::csv::merge_csv;
pub use self::ompl::merge_ompl;

use super::{BenchReport, SeedRange, SetupReport};
use crate::limits::cut;
use crate::run::bench::MAX_RUNS;

/// Files one merge reads (each holds one seed at least, so a study of [`MAX_RUNS`] seeds fits).
pub const MAX_SHARDS: usize = MAX_RUNS as usize;

/// Bytes of all the files one merge reads together (each is also at most
/// [`MAX_TEXT_BYTES`](crate::limits::MAX_TEXT_BYTES)): a JSON report of 10,000 seeds and 16
/// set-ups takes about 50 MB.
pub const MAX_MERGE_BYTES: usize = 256 << 20;

/// One shard: the file's name (for messages) and its text.
#[derive(Clone, Copy, Debug)]
pub struct Shard<'a> {
    /// The file's name as the user gave it.
    pub name: &'a str,
    /// Its text.
    pub text: &'a str,
}

/// The formats a bench writes that can be merged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// The JSON report (`bench --json-file`).
    Json,
    /// The CSV (`bench --csv`).
    Csv,
    /// The OMPL benchmark log (`bench --ompl-log`).
    Ompl,
}

impl Format {
    /// The format's name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Format::Json => "a JSON report",
            Format::Csv => "a CSV",
            Format::Ompl => "an OMPL log",
        }
    }
}

/// The format of a bench output, by its first characters: `{` (JSON), the CSV header, or the
/// OMPL log's first line as `planarium bench` writes it. `None` for anything else.
pub fn detect(text: &str) -> Option<Format> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim_start().starts_with('{') {
        Some(Format::Json)
    } else if text.starts_with(&format!("{}\r\n", super::CSV_HEADER))
        || text.starts_with(&format!("{}\n", super::CSV_HEADER))
    {
        Some(Format::Csv)
    } else if text.starts_with("Planarium version ") {
        Some(Format::Ompl)
    } else {
        None
    }
}

/// The message for a file that is not a bench output.
pub fn not_a_bench_output(name: &str) -> String {
    format!(
        "{}: not a bench output (a JSON report starts with '{{', a CSV with the line \"{}\", an OMPL log with \"Planarium version\")",
        cut(name, 200),
        super::CSV_HEADER
    )
}

/// Refuse too many shards, one too large, or too many bytes in all.
fn check_sizes(shards: &[Shard]) -> Result<(), String> {
    if shards.is_empty() {
        return Err("no shard to merge".into());
    }
    if shards.len() > MAX_SHARDS {
        return Err(format!("{} shards; the limit is {MAX_SHARDS} (each holds one seed at least)", shards.len()));
    }
    let mut total = 0usize;
    for s in shards {
        if let Some(why) = crate::limits::text_too_large(s.text) {
            return Err(format!("{}: {why}", cut(s.name, 200)));
        }
        total += s.text.len();
        if total > MAX_MERGE_BYTES {
            return Err(format!(
                "{}: the shards up to this one take {total} bytes; the limit is {MAX_MERGE_BYTES} bytes (256 MiB) for one merge",
                cut(s.name, 200)
            ));
        }
    }
    Ok(())
}

/// The order of the shards by their seeds (`held[i]` is shard `i`'s, `names[i]` its file), after
/// checking that no seed is in two shards, no seed between the first and the last is in none, and
/// they hold at most [`MAX_RUNS`] seeds in all. Returns the order and the union.
fn order_by_seeds(names: &[&str], held: &[SeedRange]) -> Result<(Vec<usize>, SeedRange), String> {
    let mut order: Vec<usize> = (0..held.len()).collect();
    order.sort_by_key(|&i| (held[i].first, held[i].last));
    for w in order.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ra, rb) = (held[a], held[b]);
        if rb.first <= ra.last {
            return Err(format!(
                "{}: seeds {rb} overlap {}'s seeds {ra}: each seed must be in one shard only",
                cut(names[b], 200),
                cut(names[a], 200)
            ));
        }
        if rb.first > ra.last + 1 {
            let missing = SeedRange { first: ra.last + 1, last: rb.first - 1 };
            return Err(format!(
                "seeds {missing} are in no shard ({} ends at seed {}, {} starts at seed {}): a single run has no gap, so merge refuses one; bench them with --seeds {missing} and merge that shard too",
                cut(names[a], 200),
                ra.last,
                cut(names[b], 200),
                rb.first
            ));
        }
    }
    let union = SeedRange { first: held[order[0]].first, last: held[*order.last().expect("one shard at least")].last };
    if union.count() > u128::from(MAX_RUNS) {
        return Err(format!(
            "the shards hold seeds {union}, {} seeds; the limit is {MAX_RUNS} per benchmark",
            union.count()
        ));
    }
    Ok((order, union))
}

/// The earliest of the dates (they are ISO 8601 as the CLI writes them, so they sort as text);
/// empty ones are left out.
fn earliest<'a>(dates: impl Iterator<Item = &'a str>) -> String {
    dates.filter(|d| !d.trim().is_empty()).min().unwrap_or("").to_string()
}

/// The hosts, each once, in the order given, joined by `+`; empty ones are left out.
fn hosts<'a>(names: impl Iterator<Item = &'a str>) -> String {
    let mut out: Vec<&str> = Vec::new();
    for h in names {
        if !h.trim().is_empty() && !out.contains(&h) {
            out.push(h);
        }
    }
    out.join("+")
}

/// A shard's seeds: every set-up's rows consecutive and the same; `what` names the set-ups in
/// messages.
fn shard_seeds(name: &str, setups: &[(String, Vec<u64>)]) -> Result<SeedRange, String> {
    let name = cut(name, 200);
    let mut held: Option<(SeedRange, &str)> = None;
    if setups.is_empty() {
        return Err(format!("{name}: no set-up, so no run to merge"));
    }
    for (what, seeds) in setups {
        let (Some(&first), Some(&last)) = (seeds.first(), seeds.last()) else {
            return Err(format!("{name}: {what} holds no run"));
        };
        if let Some(w) = seeds.windows(2).find(|w| w[0].checked_add(1) != Some(w[1])) {
            return Err(format!(
                "{name}: {what}: seed {} follows seed {}; a bench output holds consecutive seeds",
                w[1], w[0]
            ));
        }
        let range = SeedRange { first, last };
        match held {
            None => held = Some((range, what)),
            Some((r, first_what)) if r != range => {
                return Err(format!("{name}: {what} holds seeds {range} but {first_what} holds {r}"));
            }
            Some(_) => {}
        }
    }
    Ok(held.expect("one set-up at least").0)
}

/// `a`'s and `b`'s values of what `what` names, refused when they differ.
fn same<T: PartialEq + std::fmt::Debug>(what: &str, names: (&str, &str), a: &T, b: &T) -> Result<(), String> {
    if a == b {
        return Ok(());
    }
    Err(format!(
        "{}: {what} differs from {}'s: {} there, {} here; shards of one benchmark have the same scenario, set-ups and parameters",
        cut(names.1, 200),
        cut(names.0, 200),
        cut(&format!("{a:?}"), 200),
        cut(&format!("{b:?}"), 200)
    ))
}

/// Join JSON reports (`bench --json-file`, or the page's) into one: the report a single run over
/// their seeds would have made, to write in any format (its summaries are computed from the
/// runs when written).
pub fn merge_json(shards: &[Shard]) -> Result<BenchReport, String> {
    check_sizes(shards)?;
    let mut reports = Vec::with_capacity(shards.len());
    let mut held = Vec::with_capacity(shards.len());
    for s in shards {
        if detect(s.text) != Some(Format::Json) {
            return Err(not_a_bench_output(s.name));
        }
        let r = super::from_json(s.text).map_err(|e| format!("{}: {e}", cut(s.name, 200)))?;
        let setups: Vec<(String, Vec<u64>)> = r
            .setups
            .iter()
            .enumerate()
            .map(|(i, x)| (format!("setups[{i}] ({})", cut(&x.label, 100)), x.rows.iter().map(|r| r.seed).collect()))
            .collect();
        let seeds = shard_seeds(s.name, &setups)?;
        if r.runs as u128 != seeds.count() {
            return Err(format!(
                "{}: runs is {} but each set-up holds {} runs",
                cut(s.name, 200),
                r.runs,
                seeds.count()
            ));
        }
        reports.push(r);
        held.push(seeds);
    }
    let names: Vec<&str> = shards.iter().map(|s| s.name).collect();
    let (order, union) = order_by_seeds(&names, &held)?;
    let first = &reports[order[0]];
    for &k in &order[1..] {
        let (r, pair) = (&reports[k], (names[order[0]], names[k]));
        same("the scenario", pair, &first.scenario, &r.scenario)?;
        same("the scenario's id", pair, &first.scenario_id, &r.scenario_id)?;
        same("the time limit (time_limit_s)", pair, &first.time_limit_s.to_bits(), &r.time_limit_s.to_bits())
            .map_err(|_| {
                format!(
                    "{}: the time limit differs from {}'s: {} s there, {} s here; shards of one benchmark have the same scenario, set-ups and parameters",
                    cut(pair.1, 200),
                    cut(pair.0, 200),
                    first.time_limit_s,
                    r.time_limit_s
                )
            })?;
        let labels = |r: &BenchReport| r.setups.iter().map(|s| s.label.clone()).collect::<Vec<_>>();
        same("the set-ups", pair, &labels(first), &labels(r))?;
        for (i, (a, b)) in first.setups.iter().zip(&r.setups).enumerate() {
            same(&format!("setups[{i}] ({})'s planner", cut(&a.label, 100)), pair, &a.planner, &b.planner)?;
            let (pa, pb) = (serde_json::Value::Object(a.params.clone()), serde_json::Value::Object(b.params.clone()));
            if pa != pb {
                return Err(format!(
                    "{}: setups[{i}] ({})'s parameters differ from {}'s: {} there, {} here; shards of one benchmark have the same scenario, set-ups and parameters",
                    cut(pair.1, 200),
                    cut(&a.label, 100),
                    cut(pair.0, 200),
                    cut(&pa.to_string(), 200),
                    cut(&pb.to_string(), 200)
                ));
            }
        }
    }
    let setups = first
        .setups
        .iter()
        .enumerate()
        .map(|(i, s)| SetupReport {
            rows: order.iter().flat_map(|&k| reports[k].setups[i].rows.iter().cloned()).collect(),
            ..s.clone()
        })
        .collect();
    Ok(BenchReport {
        scenario: first.scenario.clone(),
        scenario_id: first.scenario_id.clone(),
        date: earliest(order.iter().map(|&k| reports[k].date.as_str())),
        host: hosts(order.iter().map(|&k| reports[k].host.as_str())),
        time_limit_s: first.time_limit_s,
        runs: union.count() as usize,
        seeds: Some(union),
        setups,
    })
}
