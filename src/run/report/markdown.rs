//! The report as the courses' Markdown table.

use super::{one_line, BenchReport};
use crate::run::summary::Summary;

fn cell(m: &Summary, f: fn(&Summary) -> f64, digits: usize) -> String {
    if m.n == 0 {
        "—".into()
    } else {
        format!("{:.*}", digits, f(m))
    }
}

/// The courses' table as Markdown, one row per set-up: success rate; mean, standard deviation and
/// median of planning time; mean and median nodes and state checks; mean cost and smoothed cost
/// over the solved runs (— when none solved).
pub fn course_table(r: &BenchReport) -> String {
    let mut out = String::from(
        "| set-up | planner | runs | solved | mean time (ms) | std time (ms) | median time (ms) | mean nodes | median nodes | mean checks | median checks | mean cost | mean smoothed cost |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let md = |s: &str| one_line(s).replace('|', "\\|");
    for s in &r.setups {
        let m = s.summary();
        out.push_str(&format!(
            "| {} | {} | {} | {:.0}% | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            md(&s.label),
            md(&s.planner),
            m.runs,
            m.success_rate * 100.0,
            cell(&m.time_ms, |x| x.mean, 2),
            cell(&m.time_ms, |x| x.std, 2),
            cell(&m.time_ms, |x| x.median, 2),
            cell(&m.nodes, |x| x.mean, 1),
            cell(&m.nodes, |x| x.median, 1),
            cell(&m.checks, |x| x.mean, 0),
            cell(&m.checks, |x| x.median, 0),
            cell(&m.cost, |x| x.mean, 4),
            cell(&m.smoothed_cost, |x| x.mean, 4),
        ));
    }
    out
}
