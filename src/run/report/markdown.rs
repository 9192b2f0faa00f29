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
/// over the solved runs (— when none solved). For an arm (any run with `cost_fk`), two more
/// columns give the mean cost and smoothed cost in report 004's unit (the `fk` distance), so the
/// table reads in both units.
pub fn course_table(r: &BenchReport) -> String {
    let fk = r.setups.iter().any(|s| s.rows.iter().any(|x| x.cost_fk.is_some()));
    let mut out = String::from(
        "| set-up | planner | runs | solved | mean time (ms) | std time (ms) | median time (ms) | mean nodes | median nodes | mean checks | median checks | mean cost | mean smoothed cost |",
    );
    out.push_str(if fk { " mean cost (fk) | mean smoothed cost (fk) |\n" } else { "\n" });
    out.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    out.push_str(if fk { "---|---|\n" } else { "\n" });
    let md = |s: &str| one_line(s).replace('|', "\\|");
    for s in &r.setups {
        let m = s.summary();
        out.push_str(&format!(
            "| {} | {} | {} | {:.0}% | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
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
        if fk {
            out.push_str(&format!(
                " {} | {} |",
                cell(&m.cost_fk, |x| x.mean, 2),
                cell(&m.smoothed_cost_fk, |x| x.mean, 2)
            ));
        }
        out.push('\n');
    }
    out
}
