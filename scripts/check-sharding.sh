#!/usr/bin/env bash
# CI check of the cluster recipes in docs/cluster.md, at small scale on this machine, for every
# study on the shared pipeline (Monte Carlo, rare events, the operability polar, fuel per mile,
# storage sizing, the stability map): each run as one process, as shards under GNU parallel (the recipe's exact command, on localhost) and as a Slurm
# job array (docs/slurm/*.sbatch run as plain bash, one array task after another), merged with
# `aes-sim merge`: both merged summaries must equal the single process's byte for byte.
#
#   scripts/check-sharding.sh [AES_SIM]      (default target/release/aes-sim)
set -euo pipefail
cd "$(dirname "$0")/.."
AES_SIM="$(realpath "${1:-target/release/aes-sim}")"
export AES_SIM
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
repo="$PWD"

# check STUDY SCENARIO ITEMS SHARDS ARGS: the three ways give one summary.
check() {
  local study="$1" scenario="$2" n="$3" s="$4" args="$5" count=""
  local dir="$work/$study"
  mkdir -p "$dir/parallel"
  case "$study" in mc | rare) count="--trials $n" ;; esac
  # shellcheck disable=SC2086
  "$AES_SIM" "$study" "$scenario" $count --threads 1 $args > "$dir/single.json" 2>/dev/null

  # GNU parallel, as in docs/cluster.md (-j 2: local cores; the docs add --sshlogin for hosts).
  (
    cd "$dir/parallel"
    # shellcheck disable=SC2086
    seq 0 $((s - 1)) | awk -v n="$n" -v s="$s" '{ print int($1 * n / s) ".." int(($1 + 1) * n / s) }' |
      parallel --will-cite -j 2 --halt now,fail=1 \
        "$AES_SIM" "$study" "$scenario" $count --threads 1 --trial-range {} --partial shard-{#}.json $args 2>/dev/null
    ls shard-*.json | "$AES_SIM" merge --files-from - > merged.json
  )
  cmp "$dir/single.json" "$dir/parallel/merged.json"

  # Slurm job array: each task as Slurm would start it, then the merge job.
  (
    cd "$dir"
    for i in $(seq 0 $((s - 1))); do
      STUDY="$study" SCENARIO="$scenario" ITEMS="$n" STUDY_ARGS="$args" \
        SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_TASK_COUNT=$s bash "$repo/docs/slurm/study-shard.sbatch" 2>/dev/null
    done
    OUT=slurm.json bash "$repo/docs/slurm/study-merge.sbatch" 2>/dev/null
  )
  cmp "$dir/single.json" "$dir/slurm.json"
  echo "sharding: $study: GNU parallel ($s shards) and the Slurm array ($s tasks) merge to the single run's summary, byte for byte"
}

# Small studies: 10 trials of 20 s of mc-excess-energy; 4 conditioned trials of 25 s in SS6 head
# seas; a polar of 4 speeds x 3 headings x 2 seas; fuel per mile at 3 speeds x 2 seas, 30 s runs;
# storage sizing of 2 x 2 sizes and the run without, 30 s runs; a stability map of 6 x 5 cells.
check mc preset:mc-excess-energy 10 4 "--set sim.duration_s=20 --set monte_carlo.histogram_time_s=10"
check rare preset:head-seas-ss6 4 2 "--set rare_event.time_s=20 --set rare_event.window_s=5 --set sim.duration_s=25"
check operability preset:startup 4 2 "--speeds 0,10,20,30 --headings 0,90,180 --sea-states 4,6"
check fuel-per-mile preset:head-seas-ss6 6 3 "--speeds 12,18,24 --seeds 2 --set sim.duration_s=30 --from 10"
check storage-sizing preset:head-seas-ss6 5 3 "--energy-mj 25,100 --power-mw 5,10 --duration-s 30 --json"
check stability-map preset:acceleration 5 2 "--set initial.speed_kn=20 --set commands.0.speed_kn=20 --x plant.loads.ship_service_w=1e6:2e7:6 --y plant.loads.filter_capacitance_f=0.01:0.04:5"
