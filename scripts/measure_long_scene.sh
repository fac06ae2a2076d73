#!/usr/bin/env bash
# The memory and files of a scene at the step limit (issue 48 item 6): a 1×1 grid, FASTSIM, a
# step creepage of 2 000 000 steps (`[limits] max_steps`' default), run with `creepbench
# simulate` under GNU time; prints the peak resident memory and the size of each file written.
# docs/performance.md has the measured numbers.
#
#   scripts/measure_long_scene.sh [CREEPBENCH] [STEPS]
#
# CREEPBENCH: the program (default target/release/creepbench; build it with
# `cargo build --release`). STEPS: the steps (default 2000000). Needs /usr/bin/time (GNU time).
set -euo pipefail

bin=${1:-target/release/creepbench}
steps=${2:-2000000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat > "$work/long_step.toml" <<TOML
name = "long_step"
solvers = ["fastsim"]

[contact]
a_mm = 8.56
b_mm = 4.08
fn_n = 100000.0
mu = 0.4

[material]
g_mpa = 82000.0
poisson = 0.28

[grid]
mx = 1
my = 1

[creepage]
kind = "step"
c = 0.001
steps = $steps
TOML

/usr/bin/time -v "$bin" simulate "$work/long_step.toml" --out "$work/out" 2> "$work/time.txt" >/dev/null \
    || { cat "$work/time.txt" >&2; exit 1; }
grep -E "rows in" "$work/time.txt" || true
peak_kb=$(awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }' "$work/time.txt")
wall=$(awk '/Elapsed \(wall clock\)/ { print $NF }' "$work/time.txt")
echo "steps: $steps"
echo "peak RSS: $((peak_kb / 1024)) MiB ($peak_kb kB)"
echo "wall: $wall"
for f in "$work"/out/long_step/*; do
    printf '%s: %s bytes\n' "$(basename "$f")" "$(stat -c %s "$f")"
done
