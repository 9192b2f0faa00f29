//! The report as CSV (RFC 4180), one row per run.

use super::BenchReport;

/// The CSV header.
pub const CSV_HEADER: &str = "setup,planner,seed,solved,status,time_ms,iterations,nodes,checks,cost,smoothed_cost";

/// One CSV field, quoted as RFC 4180 asks when it holds a comma, a quote or a line break.
pub(crate) fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\r', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A time in milliseconds to the microsecond, without the noise of its binary sum
/// (`5.1`, never `5.1000000000000005`).
pub(crate) fn ms(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r.is_finite() {
        r.to_string()
    } else {
        v.to_string()
    }
}

fn opt(v: Option<f64>) -> String {
    v.map(|x| x.to_string()).unwrap_or_default()
}

/// The runs as CSV (RFC 4180: CRLF line breaks, a header line): one row per run, columns
/// [`CSV_HEADER`]; `solved` is `true`/`false`, costs are empty when unsolved, times in ms to the microsecond.
pub fn to_csv(r: &BenchReport) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push_str("\r\n");
    for s in &r.setups {
        for row in &s.rows {
            let fields = [
                csv_field(&s.label),
                csv_field(&s.planner),
                row.seed.to_string(),
                row.solved.to_string(),
                csv_field(&row.status),
                ms(row.time_ms),
                row.iterations.to_string(),
                row.nodes.to_string(),
                row.checks.to_string(),
                opt(row.cost),
                opt(row.smoothed_cost),
            ];
            out.push_str(&fields.join(","));
            out.push_str("\r\n");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::ms;

    #[test]
    fn times_lose_their_float_noise() {
        assert_eq!(ms(2.1 + 3.0000000000000004), "5.1");
        assert_eq!(ms(5.1000000000000005), "5.1");
        assert_eq!(ms(12.0), "12");
        assert_eq!(ms(0.0004), "0");
        assert_eq!(ms(1234.5678), "1234.568");
    }
}
