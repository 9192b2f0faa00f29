#!/usr/bin/env bash
# Repeat the fuzz campaign (docs/fuzzing.md): every cargo fuzz target in fuzz/, one after the
# other, one libFuzzer job each (the machine is shared), for SECONDS each (default 60).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Runs in libFuzzer's fork mode with one job, so a crash or a hang is recorded
# (fuzz/artifacts/<target>/) and the campaign goes on. Prints per target: inputs run, crashes,
# timeouts (a unit over TIMEOUT seconds, default 1), out-of-memory, and the slowest unit of all
# inputs run (kept in fuzz/work/<target>.slowest). The working corpus grows in fuzz/work/<target>
# (not committed); the committed seeds in fuzz/corpus/<target> are only read.
#
# Environment: TIMEOUT (s, default 1), RSS_MB (default 2048), JOBS (default 1),
# CARGO_TARGET_DIR (default fuzz/target), FUZZ_FLAGS (extra libFuzzer flags).
set -euo pipefail

cd "$(dirname "$0")/.."
ROOT=$PWD
SECONDS_PER_TARGET=${1:-60}
shift || true
ALL_TARGETS=(scenario technion asv_problem asv_solution plan map)
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=("${ALL_TARGETS[@]}")
TIMEOUT=${TIMEOUT:-1}
RSS_MB=${RSS_MB:-2048}
JOBS=${JOBS:-1}
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/fuzz/target}
# cargo fuzz needs nightly flags; the stable toolchain accepts them with RUSTC_BOOTSTRAP.
export RUSTC_BOOTSTRAP=1

if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "installing cargo-fuzz" >&2
    cargo install cargo-fuzz
fi

dict_of() {
    case $1 in
        asv_problem | asv_solution) echo "$ROOT/fuzz/asv.dict" ;;
        *) echo "$ROOT/fuzz/scenario.dict" ;;
    esac
}

cargo fuzz build --fuzz-dir fuzz >&2
BIN_DIR=$CARGO_TARGET_DIR/$(rustc -vV | sed -n 's/^host: //p')/release
mkdir -p fuzz/work fuzz/artifacts
export PLANARIUM_FUZZ_SLOWEST=$ROOT/fuzz/work

summary=()
for t in "${TARGETS[@]}"; do
    mkdir -p "fuzz/work/$t" "fuzz/artifacts/$t"
    log="fuzz/work/$t.log"
    rm -f "fuzz/work/$t.slowest" "fuzz/work/$t.slowest.txt"
    before=$(find "fuzz/artifacts/$t" -type f | wc -l)
    echo "== $t: ${SECONDS_PER_TARGET}s, -timeout=$TIMEOUT" >&2
    # One fork job: a crash or hang ends the child, is saved, and fuzzing goes on.
    "$BIN_DIR/$t" "fuzz/work/$t" "fuzz/corpus/$t" \
        -dict="$(dict_of "$t")" -max_len=65536 -timeout="$TIMEOUT" -rss_limit_mb="$RSS_MB" -malloc_limit_mb="$RSS_MB" \
        -fork="$JOBS" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -max_total_time="$SECONDS_PER_TARGET" -artifact_prefix="fuzz/artifacts/$t/" -print_final_stats=1 \
        ${FUZZ_FLAGS:-} >"$log" 2>&1 || true
    # Fork mode's status lines: "#N: cov: .. ft: .. corp: .. exec/s: .. oom/timeout/crash: a/b/c time: ..".
    last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1 || true)
    runs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
    otc=$(sed -E 's/.*oom\/timeout\/crash: ([0-9]+\/[0-9]+\/[0-9]+).*/\1/' <<<"$last")
    IFS=/ read -r ooms timeouts crashes <<<"${otc:-0/0/0}"
    after=$(find "fuzz/artifacts/$t" -type f | wc -l)
    slowest=$(cat "fuzz/work/$t.slowest.txt" 2>/dev/null || echo "n/a")
    # A slowest unit is often a moment the shared machine was busy: replay it three times.
    if [ -f "fuzz/work/$t.slowest" ]; then
        replay=$(for _ in 1 2 3; do "$BIN_DIR/$t" "fuzz/work/$t.slowest" 2>&1 | sed -nE 's/^Executed .* in ([0-9]+) ms$/\1/p'; done | sort -n | head -1)
        slowest="${slowest%$'\n'} (replayed: ${replay:-?} ms)"
    fi
    line=$(printf '%-13s inputs %10s   crashes %3s   timeouts %3s   ooms %3s   new artifacts %3s   slowest unit %s' \
        "$t" "${runs:-?}" "${crashes:-?}" "${timeouts:-?}" "${ooms:-?}" "$((after - before))" "${slowest%$'\n'}")
    echo "$line" >&2
    summary+=("$line")
done

echo
echo "fuzz campaign: ${SECONDS_PER_TARGET}s per target, -timeout=${TIMEOUT}s, $JOBS job(s), $(git rev-parse --short HEAD)"
printf '%s\n' "${summary[@]}"
echo "artifacts: fuzz/artifacts/<target>/ (reproduce: see docs/fuzzing.md); logs: fuzz/work/<target>.log"
