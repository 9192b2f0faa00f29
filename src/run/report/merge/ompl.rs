//! OMPL log shards (`bench --ompl-log`) joined. A log is read as the lines
//! [`to_ompl_log`](crate::run::report::to_ompl_log) writes (the grammar in
//! [`ompl`](crate::run::report::ompl)'s documentation): the lines that say what was run must be
//! the same in every shard; the ones that count or list runs, the date, the host and the total
//! time are written again for all the runs; the runs' own lines are kept as they are, each
//! planner's in seed order.

use super::{check_sizes, detect, earliest, hosts, not_a_bench_output, order_by_seeds, shard_seeds, Format, Shard};
use crate::limits::cut;
use crate::run::report::ompl::ompl_real;

/// A line of a log, as the merge sees it.
#[derive(Clone, Debug, PartialEq)]
enum Piece<'a> {
    /// The same in every shard (what was run and how).
    Same(&'a str),
    /// `Running on HOST`.
    Host(&'a str),
    /// `Starting at DATE`.
    Date(&'a str),
    /// `N runs per set-up, REST` in the set-up text.
    RunsPerSetup(&'a str),
    /// `  label: planner {params} seeds 1,2,3` in the set-up text: what is before ` seeds `.
    SetupSeeds(&'a str),
    /// `S is the random seed`.
    FirstSeed,
    /// `N runs per planner`.
    RunsPerPlanner,
    /// `X seconds spent to collect the data`.
    Total,
    /// Planner `k`'s `N runs` line and its runs.
    Runs(usize),
}

/// One planner's runs: each run's seed, its line, and its time and simplification time (s).
struct Runs<'a> {
    seeds: Vec<u64>,
    lines: Vec<&'a str>,
    seconds: Vec<f64>,
}

/// A log read: its pieces (with each one's line number), its planners' runs, the seeds listed in
/// its set-up text, and its host and date.
struct Log<'a> {
    pieces: Vec<(usize, Piece<'a>)>,
    planners: Vec<Runs<'a>>,
    listed: Vec<Vec<u64>>,
    counts: Vec<(usize, u128)>,
    first_seed: (usize, u64),
}

/// The lines, numbered from 1, and a cursor over them; errors name the file and the line.
struct Lines<'a> {
    name: String,
    lines: Vec<&'a str>,
    at: usize,
}

impl<'a> Lines<'a> {
    fn err(&self, what: &str) -> String {
        format!("{}: line {}: {what} (not a log planarium bench wrote)", self.name, self.at.min(self.lines.len()))
    }

    fn next(&mut self, what: &str) -> Result<&'a str, String> {
        let line = self.lines.get(self.at).copied();
        self.at += 1;
        line.ok_or_else(|| self.err(&format!("the log ends where {what} was expected")))
    }

    /// The next line, which must end with `suffix`; returns what is before it.
    fn before(&mut self, suffix: &str) -> Result<&'a str, String> {
        let line = self.next(&format!("\"… {suffix}\""))?;
        line.strip_suffix(suffix)
            .ok_or_else(|| self.err(&format!("\"{}\" does not end with \"{suffix}\"", cut(line, 80))))
    }

    fn after(&mut self, prefix: &str) -> Result<&'a str, String> {
        let line = self.next(&format!("\"{prefix}…\""))?;
        line.strip_prefix(prefix)
            .ok_or_else(|| self.err(&format!("\"{}\" does not start with \"{prefix}\"", cut(line, 80))))
    }

    /// A count `N` of the line `N suffix`, at most the lines left (nothing is allocated from it).
    fn count(&mut self, suffix: &str) -> Result<usize, String> {
        let n = self.before(suffix)?;
        let left = self.lines.len().saturating_sub(self.at);
        n.parse::<usize>()
            .ok()
            .filter(|&n| n <= left)
            .ok_or_else(|| self.err(&format!("\"{}\" is not a count of the lines that follow", cut(n, 40))))
    }
}

fn seeds_of(text: &str) -> Option<Vec<u64>> {
    text.split(',').map(|s| s.parse().ok()).collect()
}

/// The next `n` lines, each the same in every shard.
fn same<'a>(l: &mut Lines<'a>, pieces: &mut Vec<(usize, Piece<'a>)>, n: usize) -> Result<(), String> {
    for _ in 0..n {
        let line = l.next("a line")?;
        pieces.push((l.at, Piece::Same(line)));
    }
    Ok(())
}

fn read<'a>(name: &str, text: &'a str) -> Result<Log<'a>, String> {
    if detect(text) != Some(Format::Ompl) {
        return Err(not_a_bench_output(name));
    }
    let mut l = Lines { name: cut(name, 200), lines: text.split('\n').collect(), at: 0 };
    if l.lines.pop() != Some("") {
        return Err(format!("{}: the last line does not end (a bench's OMPL log ends every line)", l.name));
    }
    let mut pieces = Vec::new();
    let mut counts = Vec::new();
    let mut listed = Vec::new();
    same(&mut l, &mut pieces, 3)?; // version, experiment, experiment properties (0)
    pieces.push((l.at + 1, Piece::Host(l.after("Running on ")?)));
    pieces.push((l.at + 1, Piece::Date(l.after("Starting at ")?)));
    if l.next("\"<<<|\"")? != "<<<|" {
        return Err(l.err("\"<<<|\" expected"));
    }
    pieces.push((l.at, Piece::Same("<<<|")));
    same(&mut l, &mut pieces, 1)?; // the scenario
    let line = l.next("\"N runs per set-up, …\"")?;
    let (n, rest) = line.split_once(" runs per set-up, ").ok_or_else(|| l.err("\"N runs per set-up, …\" expected"))?;
    counts.push((l.at, n.parse::<u128>().map_err(|_| l.err("a count of runs expected"))?));
    pieces.push((l.at, Piece::RunsPerSetup(rest)));
    same(&mut l, &mut pieces, 1)?; // "Set-ups (...):"
    loop {
        let line = l.next("\"|>>>\"")?;
        if line == "|>>>" {
            pieces.push((l.at, Piece::Same(line)));
            break;
        }
        let (head, seeds) = line.rsplit_once(" seeds ").ok_or_else(|| l.err("a set-up's line without its seeds"))?;
        listed.push(seeds_of(seeds).ok_or_else(|| l.err("a set-up's seeds are not whole numbers"))?);
        pieces.push((l.at, Piece::SetupSeeds(head)));
    }
    let seed = l.before(" is the random seed")?;
    let first_seed = (l.at, seed.parse::<u64>().map_err(|_| l.err("the random seed is not a whole number"))?);
    pieces.push((l.at, Piece::FirstSeed));
    same(&mut l, &mut pieces, 2)?; // seconds per run, MB per run
    counts.push((l.at + 1, l.before(" runs per planner")?.parse::<u128>().map_err(|_| l.err("a count expected"))?));
    pieces.push((l.at, Piece::RunsPerPlanner));
    l.before(" seconds spent to collect the data")?;
    pieces.push((l.at, Piece::Total));
    let at = l.at;
    let enums = l.count(" enum types")?;
    pieces.push((at + 1, Piece::Same(l.lines[at])));
    same(&mut l, &mut pieces, enums)?;
    let at = l.at;
    let planners = l.count(" planners")?;
    pieces.push((at + 1, Piece::Same(l.lines[at])));
    let mut runs = Vec::new();
    for k in 0..planners {
        same(&mut l, &mut pieces, 1)?; // the planner's name
        let at = l.at;
        let common = l.count(" common properties")?;
        pieces.push((at + 1, Piece::Same(l.lines[at])));
        same(&mut l, &mut pieces, common)?;
        let at = l.at;
        let props = l.count(" properties for each run")?;
        pieces.push((at + 1, Piece::Same(l.lines[at])));
        let names: Vec<&str> = l.lines[l.at..l.at + props].to_vec();
        same(&mut l, &mut pieces, props)?;
        let col = |p: &str| names.iter().position(|n| *n == p);
        let seed_col = col("seed INTEGER").ok_or_else(|| l.err("a planner without the \"seed INTEGER\" property"))?;
        let times: Vec<usize> = ["time REAL", "simplification time REAL"].iter().filter_map(|p| col(p)).collect();
        pieces.push((l.at + 1, Piece::Runs(k)));
        let n = l.count(" runs")?;
        let mut r = Runs { seeds: Vec::with_capacity(n), lines: Vec::with_capacity(n), seconds: Vec::with_capacity(n) };
        for _ in 0..n {
            let line = l.next("a run")?;
            let values: Vec<&str> = line.split("; ").collect();
            if values.len() != props + 1 || !values[props].is_empty() {
                return Err(
                    l.err(&format!("a run of {} values, not {props} each followed by \"; \"", values.len() - 1))
                );
            }
            r.seeds.push(values[seed_col].parse().map_err(|_| l.err("a run's seed is not a whole number"))?);
            let secs = times.iter().map(|&i| if values[i].is_empty() { Ok(0.0) } else { values[i].parse::<f64>() });
            r.seconds.push(secs.sum::<Result<f64, _>>().map_err(|_| l.err("a run's time is not a number"))?);
            r.lines.push(line);
        }
        if l.next("\".\"")? != "." {
            return Err(l.err("\".\" expected after a planner's runs"));
        }
        pieces.push((l.at, Piece::Same(".")));
        runs.push(r);
    }
    if l.at != l.lines.len() {
        l.at += 1;
        return Err(l.err("more lines after the last planner"));
    }
    if listed.len() != runs.len() {
        return Err(format!(
            "{}: the set-up text lists {} set-ups, the log has {} planners",
            l.name,
            listed.len(),
            runs.len()
        ));
    }
    Ok(Log { pieces, planners: runs, listed, counts, first_seed })
}

/// Join OMPL logs (`bench --ompl-log`) into the log a single run over their seeds would have
/// written: the runs' lines in seed order; the counts, seed lists, first seed, total time (the sum
/// of the runs' `time` and `simplification time`), date (the earliest) and host (every shard's)
/// written for them all.
pub fn merge_ompl(shards: &[Shard]) -> Result<String, String> {
    check_sizes(shards)?;
    let mut logs = Vec::with_capacity(shards.len());
    let mut held = Vec::with_capacity(shards.len());
    for s in shards {
        let log = read(s.name, s.text)?;
        let name = cut(s.name, 200);
        let named: Vec<(String, Vec<u64>)> =
            log.planners.iter().enumerate().map(|(k, r)| (format!("planner {}", k + 1), r.seeds.clone())).collect();
        let seeds = shard_seeds(s.name, &named)?;
        for (k, l) in log.listed.iter().enumerate() {
            if *l != log.planners[k].seeds {
                return Err(format!("{name}: the set-up text's seeds of set-up {} are not its runs' seeds", k + 1));
            }
        }
        if let Some((line, n)) = log.counts.iter().find(|(_, n)| *n != seeds.count()) {
            return Err(format!("{name}: line {line}: {n} runs, but each planner has {}", seeds.count()));
        }
        if log.first_seed.1 != seeds.first {
            return Err(format!("{name}: line {}: the random seed is not the first run's", log.first_seed.0));
        }
        logs.push(log);
        held.push(seeds);
    }
    let names: Vec<&str> = shards.iter().map(|s| s.name).collect();
    let (order, union) = order_by_seeds(&names, &held)?;
    let first = &logs[order[0]];
    for &k in &order[1..] {
        let log = &logs[k];
        let differs = first.pieces.iter().zip(&log.pieces).find(|(a, b)| match (&a.1, &b.1) {
            (Piece::Host(_), Piece::Host(_)) | (Piece::Date(_), Piece::Date(_)) => false,
            (x, y) => x != y,
        });
        let (a, b) = match differs {
            Some((a, b)) => (a, b),
            None if first.pieces.len() == log.pieces.len() => continue,
            None => {
                let n = first.pieces.len().min(log.pieces.len());
                let end = |p: &[(usize, Piece)]| p.get(n).map_or(0, |x| x.0);
                (&(end(&first.pieces), Piece::Same("the log's end")), &(end(&log.pieces), Piece::Same("the log's end")))
            }
        };
        let text = |p: &Piece| match p {
            Piece::Same(s) | Piece::RunsPerSetup(s) | Piece::SetupSeeds(s) => cut(s, 120),
            other => format!("{other:?}"),
        };
        return Err(format!(
            "{}: line {} differs from {}'s line {}: \"{}\" there, \"{}\" here; shards of one benchmark have the same scenario, set-ups and parameters",
            cut(names[k], 200),
            b.0,
            cut(names[order[0]], 200),
            a.0,
            text(&a.1),
            text(&b.1)
        ));
    }
    let seeds: Vec<String> = (union.first..=union.last).map(|s| s.to_string()).collect();
    // In the order a single run's log sums them: planner by planner, each in seed order.
    let mut total = 0.0;
    for p in 0..first.planners.len() {
        for &k in &order {
            for x in &logs[k].planners[p].seconds {
                total += x;
            }
        }
    }
    let mut out = String::new();
    let mut line = |s: &str| {
        out.push_str(s);
        out.push('\n');
    };
    for (_, piece) in &first.pieces {
        match piece {
            Piece::Same(s) => line(s),
            Piece::Host(_) => {
                let each = order.iter().map(|&k| host_of(&logs[k]));
                line(&format!("Running on {}", hosts(each)));
            }
            Piece::Date(_) => line(&format!("Starting at {}", earliest(order.iter().map(|&k| date_of(&logs[k]))))),
            Piece::RunsPerSetup(rest) => line(&format!("{} runs per set-up, {rest}", union.count())),
            Piece::SetupSeeds(head) => line(&format!("{head} seeds {}", seeds.join(","))),
            Piece::FirstSeed => line(&format!("{} is the random seed", union.first)),
            Piece::RunsPerPlanner => line(&format!("{} runs per planner", union.count())),
            Piece::Total => line(&format!("{} seconds spent to collect the data", ompl_real(total))),
            &Piece::Runs(p) => {
                line(&format!("{} runs", union.count()));
                for &k in &order {
                    for run in &logs[k].planners[p].lines {
                        line(run);
                    }
                }
            }
        }
    }
    Ok(out)
}

fn host_of<'a>(log: &Log<'a>) -> &'a str {
    log.pieces.iter().find_map(|(_, p)| if let Piece::Host(h) = p { Some(*h) } else { None }).unwrap_or("")
}

fn date_of<'a>(log: &Log<'a>) -> &'a str {
    log.pieces.iter().find_map(|(_, p)| if let Piece::Date(d) = p { Some(*d) } else { None }).unwrap_or("")
}
