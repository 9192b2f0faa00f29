//! The report as report 001's course benchmark file: one line per run, as the course's framework
//! (the Robotics Library's planning demo, `rlPlanDemo`) appended them to its benchmark file, and
//! from which the report's avgT, stdT, avgNodes and avgQueries were computed.
//!
//! The header is the course's own, [`COURSE_HEADER`]. Each field, followed from rl's demo
//! (`demos/rlPlanDemo/Thread.cpp`: `QDateTime::currentDateTime().toString("yyyy-MM-dd,HH:mm:ss.zzz")`,
//! then `solved ? "true" : "false"`, the planner's name, `getNumVertices()`,
//! `SimpleModel::getTotalQueries()`, `getFreeQueries()`, the time; lines ended by `std::endl`):
//! - `date`, `time`: when the benchmark ran, `2019-02-10` and `14:03:07`, UTC, the same on every
//!   line (rl stamps each run at its end in local time, to the millisecond; a report here carries
//!   one date, to the second);
//! - `solved`: `true` or `false`;
//! - `plannerName`: the set-up's label (the planner's name unless given: the report's table names
//!   its columns by set-up, "default", "2. Sampling near collisions");
//! - `#vertices`: nodes of both trees, roots included; `#totalCollisionQueries`: state checks;
//!   `#freeQueries`: free state checks (see
//!   [`SpaceInfo::free_checks`](crate::space_info::SpaceInfo::free_checks));
//! - `time_ms`: planning time in milliseconds (smoothing excluded).
//!
//! Lines end with `\n`, as rl's `std::endl` does; a label holding a comma, a quote or a line
//! break is quoted as RFC 4180 asks.

use super::BenchReport;

/// The course's header line.
pub const COURSE_HEADER: &str = "date,time,solved,plannerName,#vertices,#totalCollisionQueries,#freeQueries,time_ms";

/// `date` and `time` of a report's date: `YYYY-MM-DD` and `HH:MM:SS` from the CLI's
/// `YYYY-MM-DDTHH:MM:SSZ`; another string (the page's own) is the date, with no time.
fn date_and_time(date: &str) -> (String, String) {
    match date.split_once('T') {
        Some((d, t)) if d.len() == 10 && t.len() >= 8 && t.is_char_boundary(8) => (d.to_string(), t[..8].to_string()),
        _ => (date.to_string(), String::new()),
    }
}

/// The runs as the course's benchmark file: [`COURSE_HEADER`], then one line per run, set-ups in
/// order, seeds in order.
pub fn to_course_csv(r: &BenchReport) -> String {
    let (date, time) = date_and_time(&super::one_line(&r.date));
    let (date, time) = (super::csv::csv_field(&date), super::csv::csv_field(&time));
    let mut out = String::from(COURSE_HEADER);
    out.push('\n');
    for s in &r.setups {
        let name = super::csv::csv_field(&s.label);
        for row in &s.rows {
            out.push_str(&format!(
                "{date},{time},{},{name},{},{},{},{}\n",
                row.solved,
                row.nodes,
                row.checks,
                row.free_checks,
                super::csv::ms(row.time_ms)
            ));
        }
    }
    out
}
