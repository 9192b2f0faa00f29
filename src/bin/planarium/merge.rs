//! `planarium merge`: shards of one benchmark (`bench --seeds A-B`) joined into the files a single
//! run over all their seeds would have written (`planarium::run::report::merge`).

use clap::{Arg, ArgAction, ArgMatches, Command};
use planarium::run::report::{self, merge};

pub fn command() -> Command {
    Command::new("merge")
        .about("Join the shards of a benchmark (bench --seeds A-B) into the report of all their seeds: runs in seed order, summaries recomputed")
        .arg(
            Arg::new("shards")
                .required(true)
                .num_args(1..)
                .value_name("SHARD")
                .help("The shards' files, all of one format and in any order: JSON reports (bench --json-file), CSVs (bench --csv) or OMPL logs (bench --ompl-log)"),
        )
        .arg(Arg::new("json-file").long("json-file").value_name("FILE").help("Write the merged report as JSON (from JSON shards)"))
        .arg(Arg::new("csv").long("csv").value_name("FILE").help("Write the merged runs as CSV (from JSON or CSV shards)"))
        .arg(Arg::new("ompl-log").long("ompl-log").value_name("FILE").help("Write the merged OMPL benchmark log (from JSON shards or OMPL logs)"))
        .arg(
            Arg::new("course-table")
                .long("course-table")
                .action(ArgAction::SetTrue)
                .help("Print the courses' table of the merged report as Markdown (from JSON shards)"),
        )
}

pub fn run(m: &ArgMatches) -> Result<(), String> {
    let outputs: Vec<(&str, &String)> =
        ["json-file", "csv", "ompl-log"].into_iter().filter_map(|k| m.get_one::<String>(k).map(|f| (k, f))).collect();
    if outputs.is_empty() && !m.get_flag("course-table") {
        return Err("nothing to write: give --json-file, --csv or --ompl-log (or --course-table)".into());
    }
    let names: Vec<&String> = m.get_many::<String>("shards").expect("required").collect();
    if names.len() > merge::MAX_SHARDS {
        return Err(format!("{} shards; the limit is {}", names.len(), merge::MAX_SHARDS));
    }
    // Every file within the size limit, all of them within the merge's.
    let mut texts = Vec::with_capacity(names.len());
    let mut total = 0usize;
    for name in &names {
        let text = super::read_limited(name)?;
        total += text.len();
        if total > merge::MAX_MERGE_BYTES {
            return Err(format!(
                "{name}: the shards up to this one take {total} bytes; the limit is {} bytes (256 MiB) for one merge",
                merge::MAX_MERGE_BYTES
            ));
        }
        texts.push(text);
    }
    let shards: Vec<merge::Shard> =
        names.iter().zip(&texts).map(|(name, text)| merge::Shard { name: name.as_str(), text }).collect();
    let format = merge::detect(shards[0].text).ok_or_else(|| merge::not_a_bench_output(shards[0].name))?;
    for s in &shards[1..] {
        let f = merge::detect(s.text).ok_or_else(|| merge::not_a_bench_output(s.name))?;
        if f != format {
            return Err(format!(
                "{} is {} but {} is {}: merge shards of one format",
                s.name,
                f.name(),
                shards[0].name,
                format.name()
            ));
        }
    }
    let written: Vec<(&String, String)> = match format {
        merge::Format::Json => {
            let r = merge::merge_json(&shards)?;
            if m.get_flag("course-table") {
                print!("{}", report::course_table(&r));
            }
            let kind = |flag: &str| match flag {
                "json-file" => "json",
                "csv" => "csv",
                _ => "ompl",
            };
            outputs
                .iter()
                .map(|(flag, file)| Ok((*file, report::render(&r, kind(flag))?)))
                .collect::<Result<_, String>>()?
        }
        merge::Format::Csv | merge::Format::Ompl => {
            let (own, why) = if format == merge::Format::Csv {
                ("csv", "a CSV holds neither the scenario, the parameters nor the smoothing times")
            } else {
                ("ompl-log", "an OMPL log holds times in seconds, not the report's milliseconds")
            };
            let other = outputs.iter().map(|(flag, _)| *flag).find(|flag| *flag != own);
            if let Some(flag) = other.or(m.get_flag("course-table").then_some("course-table")) {
                return Err(format!(
                    "--{flag} is written from JSON shards only ({why}): bench the shards with --json-file and merge those, or merge these with --{own}"
                ));
            }
            let text =
                if format == merge::Format::Csv { merge::merge_csv(&shards)? } else { merge::merge_ompl(&shards)? };
            outputs.iter().map(|(_, file)| (*file, text.clone())).collect()
        }
    };
    for (file, text) in written {
        std::fs::write(file, text).map_err(|e| format!("{file}: {e}"))?;
        eprintln!("wrote {file}");
    }
    Ok(())
}
