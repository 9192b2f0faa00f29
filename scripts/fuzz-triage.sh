#!/usr/bin/env bash
# Replay every artifact in fuzz/artifacts/<target>/ (or the files given) through its target, one
# at a time, and print for each: the first lines of the input, the panic message (or the hang),
# and the first frames inside the planarium crate. See docs/fuzzing.md.
#
#   scripts/fuzz-triage.sh [TARGET [FILE...]]
set -uo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$PWD/fuzz/target}
BIN_DIR=$CARGO_TARGET_DIR/$(rustc -vV | sed -n 's/^host: //p')/release
TARGETS=(${1:-scenario technion asv_problem asv_solution plan})
shift || true
for t in "${TARGETS[@]}"; do
    files=("$@")
    [ ${#files[@]} -eq 0 ] && files=(fuzz/artifacts/$t/*)
    for f in "${files[@]}"; do
        [ -f "$f" ] || continue
        echo "=== $t $f ($(wc -c <"$f") bytes)"
        head -c 300 "$f" | tr -c '[:print:]\n' '?' | head -5
        echo
        out=$(RUST_BACKTRACE=1 timeout 120 "$BIN_DIR/$t" -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=2048 "$f" 2>&1)
        grep -E "panicked at|^thread .* panicked|memory allocation|malloc\(|timeout after|out-of-memory|Running:|Executed" <<<"$out" | grep -v "^Running:" | head -4
        grep -A1 -E "panicked at" <<<"$out" | grep -v "panicked at" | head -2
        grep -E " in planarium::" <<<"$out" | head -4 | sed -E 's/^ *#[0-9]+ 0x[0-9a-f]+ in //'
    done
done
