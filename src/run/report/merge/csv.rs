//! CSV shards (`bench --csv`) joined: each set-up's rows from every shard, in seed order, under
//! one header, written as [`to_csv`](crate::run::report::to_csv) writes them.

use super::{check_sizes, detect, not_a_bench_output, order_by_seeds, same, shard_seeds, Format, Shard};
use crate::limits::cut;
use crate::run::report::csv::csv_field;
use crate::run::report::CSV_HEADER;

/// Fields of a bench CSV's row.
const FIELDS: usize = 11;

/// One record: its first line's number and its fields.
type Record = (usize, Vec<String>);

/// RFC 4180 records (quoted fields, doubled quotes, CRLF or LF line ends); errors give the line.
/// A record of more than [`FIELDS`] fields is refused as soon as its next field starts.
fn records(name: &str, text: &str) -> Result<Vec<Record>, String> {
    let name = cut(name, 200);
    let mut out = Vec::new();
    let (mut record, mut field) = (Vec::new(), String::new());
    let (mut line, mut start) = (1usize, 1usize);
    let mut quoted = false;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if quoted {
            match c {
                '"' if chars.peek() == Some(&'"') => {
                    chars.next();
                    field.push('"');
                }
                '"' => quoted = false,
                '\n' => {
                    line += 1;
                    field.push(c);
                }
                _ => field.push(c),
            }
            continue;
        }
        match c {
            '"' if field.is_empty() => quoted = true,
            '"' => return Err(format!("{name}: line {line}: a quote inside an unquoted field")),
            ',' => {
                record.push(std::mem::take(&mut field));
                if record.len() >= FIELDS {
                    return Err(format!(
                        "{name}: line {start}: more than {FIELDS} fields; a bench CSV row has {FIELDS}"
                    ));
                }
            }
            '\r' | '\n' => {
                if c == '\r' && chars.next_if_eq(&'\n').is_none() {
                    return Err(format!("{name}: line {line}: a carriage return without a line feed"));
                }
                record.push(std::mem::take(&mut field));
                out.push((start, std::mem::take(&mut record)));
                line += 1;
                start = line;
            }
            _ => field.push(c),
        }
    }
    if quoted {
        return Err(format!("{name}: line {start}: a quoted field is not closed"));
    }
    if !field.is_empty() || !record.is_empty() {
        return Err(format!("{name}: line {start}: the last line does not end (a bench CSV ends every line)"));
    }
    Ok(out)
}

/// One set-up's rows in one shard: its label, planner and records.
struct Group {
    label: String,
    planner: String,
    seeds: Vec<u64>,
    rows: Vec<Vec<String>>,
}

/// A shard's set-ups: consecutive rows of one label and planner whose seeds follow each other.
fn groups(name: &str, text: &str) -> Result<Vec<Group>, String> {
    if detect(text) != Some(Format::Csv) {
        return Err(not_a_bench_output(name));
    }
    let shown = cut(name, 200);
    let mut out: Vec<Group> = Vec::new();
    for (line, rec) in records(name, text)?.into_iter().skip(1) {
        if rec.len() != FIELDS {
            return Err(format!("{shown}: line {line}: {} fields; a bench CSV row has {FIELDS}", rec.len()));
        }
        let seed: u64 = rec[2].parse().map_err(|_| {
            format!("{shown}: line {line}: seed \"{}\" is not a whole number from 0 to {}", cut(&rec[2], 40), u64::MAX)
        })?;
        if !matches!(rec[3].as_str(), "true" | "false") {
            return Err(format!("{shown}: line {line}: solved is \"{}\", not true or false", cut(&rec[3], 40)));
        }
        let follows = out.last().is_some_and(|g| {
            g.label == rec[0] && g.planner == rec[1] && g.seeds.last().and_then(|s| s.checked_add(1)) == Some(seed)
        });
        if !follows {
            out.push(Group { label: rec[0].clone(), planner: rec[1].clone(), seeds: Vec::new(), rows: Vec::new() });
        }
        let g = out.last_mut().expect("pushed");
        g.seeds.push(seed);
        g.rows.push(rec);
    }
    Ok(out)
}

/// Join CSV shards (`bench --csv`) into the CSV a single run over their seeds would have written.
/// A CSV holds neither the scenario nor the parameters: the shards are checked on their set-ups'
/// labels and planners, and their seeds.
pub fn merge_csv(shards: &[Shard]) -> Result<String, String> {
    check_sizes(shards)?;
    let mut all = Vec::with_capacity(shards.len());
    let mut held = Vec::with_capacity(shards.len());
    for s in shards {
        let g = groups(s.name, s.text)?;
        let named: Vec<(String, Vec<u64>)> = g
            .iter()
            .enumerate()
            .map(|(i, g)| (format!("set-up {} ({})", i + 1, cut(&g.label, 100)), g.seeds.clone()))
            .collect();
        held.push(shard_seeds(s.name, &named)?);
        all.push(g);
    }
    let names: Vec<&str> = shards.iter().map(|s| s.name).collect();
    let (order, _) = order_by_seeds(&names, &held)?;
    let first = &all[order[0]];
    let setups = |g: &[Group]| g.iter().map(|g| (g.label.clone(), g.planner.clone())).collect::<Vec<_>>();
    for &k in &order[1..] {
        same("the set-ups (label, planner)", (names[order[0]], names[k]), &setups(first), &setups(&all[k]))?;
    }
    let mut out = String::from(CSV_HEADER);
    out.push_str("\r\n");
    // Set-up by set-up, each one's rows shard by shard in seed order.
    let (all, order) = (&all, &order);
    for row in (0..first.len()).flat_map(|i| order.iter().flat_map(move |&k| &all[k][i].rows)) {
        let fields: Vec<String> = row.iter().map(|f| csv_field(f)).collect();
        out.push_str(&fields.join(","));
        out.push_str("\r\n");
    }
    Ok(out)
}
