#!/usr/bin/env bash
# Times workload W1 (head seas SS6, 25 kn, 200 components, 80 s, 2.5 ms steps) with this tree's
# aes-sim and with the baseline commit's, side by side and alternating (machines of the same kind
# differ 2-3x, and load changes during a run, so only a ratio measured in one run means anything).
#
#   scripts/bench-vs-baseline.sh [ROUNDS]        (default 5 rounds; BASE=commit, default dac040a)
#
# The baseline is built once in a temporary worktree with its own target directory
# (/tmp/aes-baseline-COMMIT{,-target}) and reused on later runs. Both binaries run the same
# scenario: `bench head-seas-ss6` with the hub depth given explicitly (the preset's h0 moved from
# 6 m to 3.5 m after dac040a; every other setting of W1 is the same in both versions), so W1 is
# the preset as it is now. H0=6 times the preset as it was at dac040a.
#
# Two ratios: W1 as defined in issue 17 (2.5 ms RK4 steps in both), and the preset as shipped now
# (5 ms midpoint steps since issue 17: as close to 1 ms RK4 steps as RK4 at 5 ms,
# tests/multirate.rs). The baseline builds in /tmp, outside this tree's .cargo/config.toml: it
# runs as shipped then, without AVX2.
set -euo pipefail
cd "$(dirname "$0")/.."
base="${BASE:-dac040a}"
rounds="${1:-5}"
h0="${H0:-3.5}"
wt="/tmp/aes-baseline-$base"
tgt="/tmp/aes-baseline-$base-target"

if [ ! -d "$wt" ]; then
  git worktree add --detach "$wt" "$base" >/dev/null
fi
echo "building the baseline $base in $wt (target $tgt)" >&2
(cd "$wt" && CARGO_TARGET_DIR="$tgt" cargo build --release -q -p aes-cli)
echo "building this tree ($(git rev-parse --short HEAD))" >&2
cargo build --release -q -p aes-cli

old="$tgt/release/aes-sim"
new="target/release/aes-sim"
# The hub's depth: `seakeeping.hub_depth_m` at the baseline; the hull's hub height above the base
# (the 5415's draft 6.15 m minus h0) since the hull became one definition (issue 15).
args_old=(bench head-seas-ss6 --repeat 3 --set "seakeeping.hub_depth_m=$h0")
args_new=(bench head-seas-ss6 --repeat 3 --set "ship.hull.hub_above_base_m=$(python3 -c "print(6.15 - $h0)")")
args_same=("${args_new[@]}" --set sim.dt_s=0.0025 --set sim.integrator=rk4)

# wall_s is the best of the repetitions of one call; the ratio of the medians over the rounds.
field() { python3 -c "import json,sys; d=json.load(sys.stdin); print(d['$1'] if d['$1'] is not None else 'nan')"; }
olds=() news=() sames=()
for r in $(seq 1 "$rounds"); do
  o="$("$old" "${args_old[@]}")"
  m="$("$new" "${args_same[@]}")"
  n="$("$new" "${args_new[@]}")"
  ow="$(field wall_s <<<"$o")"; mw="$(field wall_s <<<"$m")"; nw="$(field wall_s <<<"$n")"
  ok="$(field wave_sums_s <<<"$o")"; nk="$(field wave_sums_s <<<"$n")"
  olds+=("$ow") sames+=("$mw") news+=("$nw")
  python3 -c "print(f'round $r: baseline {1e3*$ow:7.2f} ms (wave sums {1e3*$ok:5.2f} ms)   now at 2.5 ms RK4 {1e3*$mw:7.2f} ms   now as shipped {1e3*$nw:7.2f} ms (wave sums {1e3*$nk:5.2f} ms)')"
done
python3 - "${olds[*]}" "${sames[*]}" "${news[*]}" "$base" <<'PY'
import statistics, sys
old, same, new = ([float(v) for v in a.split()] for a in sys.argv[1:4])
mo, ms, mn = statistics.median(old), statistics.median(same), statistics.median(new)
print(f"W1 per trial, median of {len(old)} rounds: baseline {sys.argv[4]} {1e3*mo:.2f} ms; now, 2.5 ms RK4 steps "
      f"{1e3*ms:.2f} ms: {mo/ms:.2f}x faster; now, the preset as shipped (5 ms midpoint steps) {1e3*mn:.2f} ms: {mo/mn:.2f}x faster")
PY
