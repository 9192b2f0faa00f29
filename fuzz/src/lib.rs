//! Shared code of the fuzz targets: the checks of `tests/fuzz_harness/mod.rs` (the same file the
//! property test uses), so a target and `cargo test` assert the same properties.

#[path = "../../tests/fuzz_harness/mod.rs"]
pub mod harness;

/// How far past its time limit a fuzzed run may end before the target calls it a hang. Looser
/// than the 0.1 s: coverage instrumentation slows the core down several times, and
/// libFuzzer's own `-timeout=` catches the real hangs. The property test checks the 0.1 s.
pub const FUZZ_TIME_SLACK_S: f64 = 0.5;

/// Input bytes as the page reads a file: UTF-8, invalid sequences replaced.
pub fn text(data: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(data)
}

/// Panic with the property broken, so libFuzzer keeps the input.
pub fn expect<T>(r: Result<T, String>) -> T {
    match r {
        Ok(v) => v,
        Err(e) => panic!("property broken: {e}"),
    }
}

/// Run one input of `target`, timing it (and, first, read `PLANARIUM_FUZZ_LOCATION`). When `PLANARIUM_FUZZ_SLOWEST` names a directory, the
/// slowest input seen so far by this target (across processes: libFuzzer's fork mode starts
/// many) is kept there as `<target>.slowest` (the input) and `<target>.slowest.txt` (its seconds),
/// so `scripts/fuzz.sh` can report the slowest unit of every input run, not only the corpus's.
pub fn timed(target: &str, data: &[u8], f: impl FnOnce()) {
    static INIT: std::sync::Once = std::sync::Once::new();
    INIT.call_once(|| {
        harness::set_require_location(std::env::var("PLANARIUM_FUZZ_LOCATION").map_or(true, |v| v != "0"))
    });
    let t = std::time::Instant::now();
    f();
    let secs = t.elapsed().as_secs_f64();
    let Some(dir) = std::env::var_os("PLANARIUM_FUZZ_SLOWEST") else {
        return;
    };
    let dir = std::path::PathBuf::from(dir);
    thread_local! {
        static SLOWEST: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    }
    let stats = dir.join(format!("{target}.slowest.txt"));
    let best = SLOWEST.with(|s| {
        s.get().unwrap_or_else(|| {
            std::fs::read_to_string(&stats).ok().and_then(|t| t.split_whitespace().next()?.parse().ok()).unwrap_or(0.0)
        })
    });
    if secs > best {
        SLOWEST.with(|s| s.set(Some(secs)));
        let _ = std::fs::write(dir.join(format!("{target}.slowest")), data);
        let _ = std::fs::write(&stats, format!("{secs:.6} seconds, {} bytes\n", data.len()));
    } else {
        SLOWEST.with(|s| s.set(Some(best)));
    }
}
