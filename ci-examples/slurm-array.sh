#!/usr/bin/env bash
# creepbench on a Slurm cluster for large suites or studies: one array task per shard.
#   sbatch --array=1-16 ci-examples/slurm-array.sh
# then, when every task has ended, one report from all shards:
#   ./target/release/creepbench merge results/shard-* --report reports
#SBATCH --job-name=creepbench
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
#SBATCH --output=logs/creepbench-%A_%a.out
set -euo pipefail
cd "${SLURM_SUBMIT_DIR:-.}"
i="${SLURM_ARRAY_TASK_ID:?submit as an array job: sbatch --array=1-N}"
n="${SLURM_ARRAY_TASK_COUNT:?submit as an array job: sbatch --array=1-N}"
mkdir -p gate logs
./target/release/creepbench run --quiet --shard "$i/$n" --results "results/shard-$i" --report "report-$i"
./target/release/creepbench check --quiet --shard "$i/$n" --junit "gate/junit-$i.xml" --json "gate/check-$i.json"
