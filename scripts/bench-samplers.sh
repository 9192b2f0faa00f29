#!/bin/sh
# Report 001's comparison on the narrow passage and on 7ASV: default RRT-Connect against the
# narrow-passage samplers, Dynamic-Domain RRT and exhausted nodes (20 seeds each, 5 s limit).
# The samplers in their pure form, as the report used them (--uniform-share 0; see docs/samplers-benchmark.md).
# Usage: sh scripts/bench-samplers.sh [planarium binary]   (writes bench/results/samplers-*.md)
set -e
BIN=${1:-./target/release/planarium}
for sc in narrow asv-7; do
  if [ "$sc" = narrow ]; then R=0.05; else R=0.3; fi
  "$BIN" bench "$sc" --runs 20 --report --time-limit 5 --uniform-share 0 \
    --setup "default: rrt-connect" \
    --setup "gaussian: rrt-connect --sampler gaussian" \
    --setup "bridge: rrt-connect --sampler bridge" \
    --setup "obstacle: rrt-connect --sampler obstacle" \
    --setup "near-collision: rrt-connect --sampler near-collision" \
    --setup "dynamic-domain R=$R: rrt-connect --dd-radius $R" \
    --setup "adaptive DD R=$R: rrt-connect --dd-radius $R --dd-adaptive 0.1" \
    --setup "exhausted 4: rrt-connect --exhausted 4" \
    --setup "gaussian + DD: rrt-connect --sampler gaussian --dd-radius $R" \
    --setup "near-collision + exhausted 4: rrt-connect --sampler near-collision --exhausted 4" \
    --setup "near-collision tuned (p 3, sigma 0.005, random 0): rrt-connect --sampler near-collision --perseverance 3 --collision-sigma 0.005 --random-sigma 0" \
    > "bench/results/samplers-$sc.md"
  cat "bench/results/samplers-$sc.md"
done
