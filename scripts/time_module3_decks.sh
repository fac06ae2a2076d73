#!/usr/bin/env bash
# CPU time of CONTACT's module-3 decks of issue 46's physics against this project's imported
# scenes of the same deck (issue 46 item 5): dissimilar bodies (K != 0) beside their uncoupled
# twins (the same scenes with the bodies' combined G and nu, K = 0), viscoelastic bodies, the
# interface layer and its plasticity, CONTACT's FASTSIM and FaStrip, surface temperatures.
#
#   scripts/time_module3_decks.sh CONTACT [ROUNDS] [CREEPBENCH]
#
# CONTACT: a CONTACT program (e.g. a gfortran build, reference/README.md);
# ROUNDS: alternated rounds, the median taken (default 3); CREEPBENCH: default
# target/release/creepbench; DECKS (environment): the decks to time, default all of them; REPEAT
# (environment, default 1): each program's run repeated that many times under one GNU time and its
# CPU time divided by it, for decks whose scenes run below the timer's 10 ms resolution (a run of a
# few milliseconds reads 0.00). Each deck is run whole by CONTACT (`CONTACT 2 NAME` in a scratch
# folder); this project runs every scene of scenes/contact_public/ whose [origin] file is the deck
# in one process (`creepbench simulate SCENE...`, one thread, the scene's own solvers), as CONTACT
# runs the deck's cases in one; CPU time is user + system (GNU time). Prints a Markdown table;
# docs/models.md ("Speed against CONTACT") has the measured one.
set -euo pipefail

contact=${1:?usage: $0 CONTACT [ROUNDS] [CREEPBENCH]}
rounds=${2:-3}
bin=${3:-target/release/creepbench}
contact=$(realpath "$contact")
bin=$(realpath "$bin")
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RAYON_NUM_THREADS=1

# plastic_3bl (1 x 1 grids) runs below GNU time's 10 ms resolution in both programs.
decks=${DECKS:-"examples/bentall examples/spence35 examples/visc_cylindr examples/tractcurv
examples/fastsim examples/ertz_temperature testbank/examples_temp/euro_tractcurv
testbank/examples_plast/tractcurve_plast testbank/examples_plast/catt3d_plast"}

repeat=${REPEAT:-1}

# CPU seconds (user + system) of a command, its output discarded, the mean of `repeat` runs timed
# together (the shell's loop counted in: against the program timed); a command that fails stops
# the script with its name.
cpu() {
  if ! /usr/bin/time -f "%U %S" -o "$work/t" bash -c 'for _ in $(seq "$0"); do "$@" || exit 1; done' "$repeat" "$@" >/dev/null 2>"$work/err"; then
    echo "failed: $* ($(tail -1 "$work/err"))" >&2
    exit 1
  fi
  awk -v n="$repeat" '{ printf "%.4f", ($1 + $2) / n }' "$work/t"
}

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# The deck's scenes copied with their tables, the references resolved from the copy; with
# `twin`, dissimilar bodies replaced by their combined constants (K = 0).
scenes_of() {
  local name=$1 out=$2 twin=${3:-}
  mkdir -p "$out"
  for f in $(grep -l "^file = \"$name.inp\"" "$root"/scenes/contact_public/*.toml); do
    local stem
    stem=$(basename "$f" .toml)
    cp "$root"/scenes/contact_public/"$stem"*.csv "$out"/ 2>/dev/null || true
    if [ -n "$twin" ]; then
      python3 - "$f" "$out/$stem.toml" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
v = {k: float(re.search(rf"^{k} = (\S+)", s, re.M).group(1)) for k in ("g1_mpa", "g2_mpa", "poisson1", "poisson2")}
g = 2 * v["g1_mpa"] * v["g2_mpa"] / (v["g1_mpa"] + v["g2_mpa"])
nu = g * (v["poisson1"] / v["g1_mpa"] + v["poisson2"] / v["g2_mpa"]) / 2
s = re.sub(r"^g1_mpa = .*\n^g2_mpa = .*\n^poisson1 = .*\n^poisson2 = .*\n", f"g_mpa = {g!r}\npoisson = {nu!r}\n", s, flags=re.M)
open(sys.argv[2], "w").write(s)
PY
    else
      cp "$f" "$out/"
    fi
  done
}

# All of a deck's scenes in one `creepbench simulate` process, as CONTACT runs the deck's cases.
ours() {
  cpu "$bin" simulate "$1"/*.toml --out "$work/res"
}

echo "| deck | cases run by CONTACT | scenes | CONTACT s | creepbench s | factor |"
echo "|---|---|---|---|---|---|"
for d in $decks; do
  name=$(basename "$d")
  src="$root/reference/contact_public/$d.inp"
  mkdir -p "$work/c_$name"
  cp "$src" "$work/c_$name/"
  scenes_of "$name" "$work/s_$name"
  twin=""
  if grep -q "^g1_mpa" "$work/s_$name"/*.toml; then
    scenes_of "$name" "$work/k0_$name" twin
    twin=1
  fi
  cs="" os="" ks=""
  for _ in $(seq "$rounds"); do
    cs="$cs $(cd "$work/c_$name" && cpu "$contact" 2 "$name")"
    os="$os $(ours "$work/s_$name")"
    [ -n "$twin" ] && ks="$ks $(ours "$work/k0_$name")"
  done
  c=$(echo "$cs" | median)
  o=$(echo "$os" | median)
  n=$(grep -c "^ Case " "$work/c_$name/$name.out" || true)
  ns=$(ls "$work/s_$name"/*.toml | wc -l)
  echo "| $d | $n | $ns | $c | $o | $(awk -v c="$c" -v o="$o" 'BEGIN { printf "%.1f", c / o }') |"
  if [ -n "$twin" ]; then
    k=$(echo "$ks" | median)
    echo "| $d, uncoupled twin (K = 0) | – | $ns | – | $k | coupled / twin $(awk -v o="$o" -v k="$k" 'BEGIN { printf "%.2f", o / k }') |"
  fi
done
