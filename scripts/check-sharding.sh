#!/usr/bin/env bash
# CI check of the cluster recipes in docs/cluster.md, at small scale on this machine: a Monte
# Carlo study run as one process, as shards under GNU parallel (the recipe's exact command, on
# localhost) and as a Slurm job array (docs/slurm/*.sbatch run as plain bash, one array task
# after another), merged with `aes-sim merge`: both merged summaries must equal the single
# process's byte for byte.
#
#   scripts/check-sharding.sh [AES_SIM]      (default target/release/aes-sim)
set -euo pipefail
cd "$(dirname "$0")/.."
AES_SIM="$(realpath "${1:-target/release/aes-sim}")"
export AES_SIM
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# A small study: 10 trials of 20 s of mc-excess-energy, 4 shards.
SCENARIO="preset:mc-excess-energy"
N=10
S=4
MC_ARGS="--set sim.duration_s=20 --set monte_carlo.histogram_time_s=10"
export SCENARIO MC_ARGS
# shellcheck disable=SC2086
"$AES_SIM" mc "$SCENARIO" --trials "$N" --threads 1 $MC_ARGS > "$work/single.json" 2>/dev/null

# GNU parallel, as in docs/cluster.md (-j 2: local cores; the docs add --sshlogin for hosts).
mkdir -p "$work/parallel"
(
  cd "$work/parallel"
  # shellcheck disable=SC2086
  seq 0 $((S - 1)) | awk -v n="$N" -v s="$S" '{ print int($1 * n / s) ".." int(($1 + 1) * n / s) }' |
    parallel --will-cite -j 2 --halt now,fail=1 \
      "$AES_SIM" mc "$SCENARIO" --trials "$N" --threads 1 --trial-range {} --partial shard-{#}.json $MC_ARGS 2>/dev/null
  ls shard-*.json | "$AES_SIM" merge --files-from - > merged.json
)
cmp "$work/single.json" "$work/parallel/merged.json"

# Slurm job array: each task as Slurm would start it, then the merge job.
(
  cd "$work"
  for i in $(seq 0 $((S - 1))); do
    SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_TASK_COUNT=$S TRIALS=$N bash "$OLDPWD/docs/slurm/mc-shard.sbatch" 2>/dev/null
  done
  OUT=slurm.json bash "$OLDPWD/docs/slurm/mc-merge.sbatch" 2>/dev/null
)
cmp "$work/single.json" "$work/slurm.json"
echo "sharding: GNU parallel ($S shards) and the Slurm array ($S tasks) merge to the single run's summary, byte for byte"
