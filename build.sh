#!/usr/bin/env bash
# aes-sim: the one entry point.
#
#   ./build.sh            set up what is missing (the Python package aes_sim included), build the
#                         wasm into www/pkg, serve www on http://127.0.0.1:${PORT:-8080}
#   ./build.sh build      set up and build only (native CLI and www/pkg)
#   ./build.sh test       set up, then rustfmt check, the book's links and generated tables (docs/),
#                         clippy and cargo doc (warnings denied), every native test
#                         (release mode), the cluster recipes (GNU parallel and Slurm shards
#                         merge to the single run), the wasm-bindgen tests in Node and the browser
#                         end-to-end test in headless Chromium (screenshots in target/), the
#                         Python package's tests (pytest: its numbers equal the command line's)
#   ./build.sh bench      simulated seconds per wall second of the start-up preset
#   ./build.sh fuzz       the property tests of every entry point (tests/fuzz.rs) with many more
#                         cases (AES_FUZZ_CASES, default 20000; a few minutes), before releases
#   ./build.sh docs       regenerate the book's generated tables in docs/ (scripts/docs.py): the
#                         scenario parameters (from the registry), the plant's health checks (from
#                         core/src/sim/health.rs), the trace signals and one line per module
#   ./build.sh golden     regenerate the golden records of every preset (tests/golden/) after a
#                         deliberate physics change; review the diff before committing
#
# Safe on a fresh machine that reaches only the package registries: every tool comes from
# crates.io or npm by name, and each step is skipped when its result is already there.
set -euo pipefail
cd "$(dirname "$0")"

# Each step's heading carries the seconds since the script started, so a log shows where the time goes.
say() { printf '\033[1m==> %s\033[0m (at %d s)\n' "$*" "$SECONDS"; }

# Exact wasm-bindgen version of Cargo.lock: the CLI must match it.
wasm_bindgen_version() {
  awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock
}

setup() {
  if ! command -v cargo >/dev/null; then
    echo "build.sh: cargo not found; this project needs a Rust toolchain (rustup)" >&2
    exit 1
  fi
  export PATH="$HOME/.cargo/bin:$PATH"
  if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
    say "adding the wasm32-unknown-unknown target"
    rustup target add wasm32-unknown-unknown
  fi
  for comp in rustfmt clippy; do
    if ! rustup component list --installed 2>/dev/null | grep -q "^$comp"; then
      say "adding rustup component $comp"
      rustup component add "$comp"
    fi
  done
  local want
  want="$(wasm_bindgen_version)"
  # wasm-bindgen-cli brings wasm-bindgen (the JS glue of the page's wasm) and
  # wasm-bindgen-test-runner (the wasm tests in Node); plain cargo does the rest.
  if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$want" ] ||
    [ "$(wasm-bindgen-test-runner --version 2>/dev/null | awk '{print $2}')" != "$want" ]; then
    say "installing wasm-bindgen-cli $want (about 3 minutes)"
    cargo install wasm-bindgen-cli --version "=$want" --locked
  fi
  if [ ! -d node_modules ] || [ package-lock.json -nt node_modules ]; then
    if command -v npm >/dev/null; then
      say "installing npm packages"
      npm ci --no-audit --no-fund
    else
      echo "build.sh: npm not found; skipping uPlot and wasm-opt (the page still builds)" >&2
    fi
  fi
  ensure_python_package
}

# pip for the aes_sim package: plain, or on an interpreter whose packages the system manages
# (PEP 668) into the user's site (~/.local), which leaves the system's packages alone.
pip_install() {
  local extra=()
  if python3 -c 'import sys, sysconfig, os; sys.exit(not os.path.exists(os.path.join(sysconfig.get_path("stdlib"), "EXTERNALLY-MANAGED")) or sys.prefix != sys.base_prefix)'; then
    extra=(--user --break-system-packages)
  fi
  # (The empty array spelled so that bash 3.2 with set -u accepts it.)
  python3 -m pip install --quiet --disable-pip-version-check ${extra[@]+"${extra[@]}"} "$@"
}

# The Python package aes_sim (python/, docs/python.md): maturin, numpy and pytest from PyPI when
# missing, then one release build of the thin crate into this workspace's target/ (aes-core's
# release build is reused, not rebuilt) and `pip install ./python`. Skipped when the installed
# package is this checkout's and no source is newer than its install.
ensure_python_package() {
  if ! python3 -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; then
    echo "build.sh: the Python package aes_sim needs python3 >= 3.11; skipping it" >&2
    return
  fi
  local stamp=target/python-package.stamp so
  so="$(cd / && python3 -c 'import aes_sim._aes_sim as m; print(m.__file__)' 2>/dev/null || true)"
  if [ -n "$so" ] && [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$so" ] && [ ! "$so" -nt "$stamp" ] &&
    [ -z "$(find core python .cargo Cargo.toml Cargo.lock -newer "$stamp" \
      -not -path '*/__pycache__*' -not -path '*/.pytest_cache*' -print -quit)" ]; then
    return
  fi
  if ! python3 -m maturin --version >/dev/null 2>&1 || ! python3 -c 'import numpy, pytest' 2>/dev/null; then
    say "installing maturin, numpy and pytest from PyPI"
    pip_install 'maturin>=1.5,<2' numpy pytest || true
  fi
  say "building and installing the Python package aes_sim (pip install ./python)"
  # No build isolation: the maturin just installed builds it, nothing is fetched again. A failure
  # is said but does not stop the page's set-up (./build.sh test then fails at the Python tests).
  if ! pip_install --no-build-isolation --force-reinstall --no-deps ./python; then
    echo "build.sh: the Python package aes_sim was not installed (see above); docs/python.md" >&2
    return
  fi
  mkdir -p target
  (cd / && python3 -c 'import aes_sim._aes_sim as m; print(m.__file__)') > "$stamp"
}

ensure_chromium() {
  if [ -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
    return
  fi
  say "installing Debian's chromium for the browser test"
  local sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium > /dev/null
}

ensure_parallel() {
  if command -v parallel >/dev/null; then
    return
  fi
  say "installing Debian's GNU parallel for the sharding check"
  local sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq parallel > /dev/null
}

build_web() {
  say "building the wasm (release) into www/pkg"
  # cargo and the wasm-bindgen on PATH: nothing is downloaded at build time.
  cargo build --release --target wasm32-unknown-unknown -p aes-web
  wasm-bindgen --target web --no-typescript --out-dir www/pkg "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release/aes_web.wasm"
  # npm's binaryen only: Debian's binaryen breaks current wasm-bindgen output (toolchain notes).
  if [ -x node_modules/.bin/wasm-opt ]; then
    node_modules/.bin/wasm-opt -O3 --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int \
      --enable-sign-ext --enable-mutable-globals \
      www/pkg/aes_web_bg.wasm -o www/pkg/aes_web_bg.wasm
  fi
  if [ -f node_modules/uplot/dist/uPlot.esm.js ]; then
    mkdir -p www/vendor
    cp node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css www/vendor/
  fi
}

build_native() {
  say "building the aes-sim command (release)"
  cargo build --release -p aes-cli
}

# tests/ is its package's root, so cargo's automatic discovery (which looks in <root>/tests/) finds
# none of its files: each is listed in tests/Cargo.toml, and a file left out is never compiled.
check_tests_listed() {
  local f missing=0
  for f in tests/*.rs; do
    [ "$f" = tests/lib.rs ] && continue
    if ! grep -qx "path = \"${f#tests/}\"" tests/Cargo.toml; then
      echo "$f is not a [[test]] in tests/Cargo.toml: it would never be compiled" >&2
      missing=1
    fi
  done
  return "$missing"
}

run_tests() {
  local log
  log="$(mktemp)"
  say "rustfmt check"
  cargo fmt --all -- --check
  say "every link and anchor of the README, CONTRIBUTING.md and docs/ resolves (the check refuses broken ones)"
  python3 scripts/check-links.py --self-test
  python3 scripts/check-links.py
  say "every tests/*.rs is a [[test]] in tests/Cargo.toml (none left uncompiled)"
  check_tests_listed
  say "no import cycle between core's modules or folders (and the check refuses fake cycles)"
  python3 scripts/check_module_cycles.py --self-test
  python3 scripts/check_module_cycles.py
  say "no module of core imports a higher layer (and the check refuses a fake upward import)"
  python3 scripts/check_module_layers.py --self-test
  python3 scripts/check_module_layers.py
  say "clippy (warnings are errors)"
  cargo clippy --workspace --all-targets --release -- -D warnings
  say "cargo doc builds without warnings (about 40-80 s on 2 cores)"
  RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --workspace
  say "native tests (release)"
  cargo test --workspace --release 2>&1 | tee "$log"
  say "validation report: every row within its tolerance, docs/validation.md up to date"
  cargo build --release -p aes-cli
  ./target/release/aes-sim validate --check docs/validation.md
  say "the book's generated tables are current (parameters, health checks, signals, modules)"
  python3 scripts/docs.py --check
  say "cluster recipes: GNU parallel and Slurm shards merge to the single run (docs/cluster.md)"
  ensure_parallel
  scripts/check-sharding.sh target/release/aes-sim 2>&1 | tee -a "$log"
  say "wasm-bindgen tests in Node"
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner WASM_BINDGEN_TEST_ONLY_NODE=1 \
    cargo test --release --target wasm32-unknown-unknown -p aes-web 2>&1 | tee -a "$log"
  say "browser end-to-end test (headless Chromium)"
  ensure_chromium
  build_web
  local port shots
  port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  shots="$PWD/target/e2e-screenshots"
  python3 -m http.server --bind 127.0.0.1 --directory www "$port" > /dev/null 2>&1 &
  local server=$!
  trap "kill $server 2>/dev/null || true" EXIT
  for _ in $(seq 1 50); do
    python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
    sleep 0.1
  done
  node tests/e2e/e2e.mjs "http://127.0.0.1:$port/" "$shots" 2>&1 | tee -a "$log"
  say "browser test: one state for inputs, results and the address bar; labels; layout (issue 29)"
  node tests/e2e/consistency.mjs "http://127.0.0.1:$port/" "$shots" 2>&1 | tee -a "$log"
  say "browser test: the lessons (issue 30)"
  node tests/e2e/lessons.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: the operability polar (issue 31)"
  node tests/e2e/operability.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: rare events by conditioned simulation (issue 32)"
  node tests/e2e/rare.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: fuel per mile, a study on the shared pipeline (issue 41)"
  node tests/e2e/fuel.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: the standard maneuvers booklet (issue 42)"
  node tests/e2e/maneuvers.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: the propeller panel, blades from their geometry (issue 54)"
  node tests/e2e/propeller.mjs "http://127.0.0.1:$port/" "$shots" target/release/aes-sim 2>&1 | tee -a "$log"
  say "browser test: links and errors that help (issue 55)"
  node tests/e2e/links.mjs "http://127.0.0.1:$port/" "$shots" 2>&1 | tee -a "$log"
  say "browser test: one meaning per mark, units, the phone and the projector (issue 55)"
  node tests/e2e/marks.mjs "http://127.0.0.1:$port/" "$shots" 2>&1 | tee -a "$log"
  kill "$server" 2>/dev/null || true
  trap - EXIT
  say "the Python package: its numbers equal the command line's (issue 58; pytest)"
  python3 -m pytest -q -p no:cacheprovider python/tests 2>&1 | tee -a "$log"
  # One closing line for the whole suite (pipefail has already stopped us on any failure).
  awk '/^test result:/ { p += $4; f += $6 } /^e2e: / { p += $2; f += $4 } /^[0-9]+ passed/ { p += $1 } END { printf "all tests: %d passed, %d failed\n", p, f }' "$log"
  rm -f "$log"
}

case "${1:-serve}" in
  serve)
    setup
    build_native
    build_web
    port="${PORT:-8080}"
    say "serving www on http://127.0.0.1:$port (Ctrl-C to stop)"
    exec python3 -m http.server --bind 127.0.0.1 --directory www "$port"
    ;;
  build)
    setup
    build_native
    build_web
    ;;
  test)
    setup
    run_tests
    ;;
  fuzz)
    AES_FUZZ_CASES="${AES_FUZZ_CASES:-20000}" cargo test --release -p aes-tests --test fuzz
    AES_FUZZ_CASES="${AES_FUZZ_CASES:-20000}" cargo test --release -p aes-tests --test shard_checks
    cargo test --release -p aes-cli --test hardening
    ;;
  validate)
    setup
    build_native
    ./target/release/aes-sim validate --out docs/validation.md --figures docs/validation
    git --no-pager diff --stat -- docs/validation.md docs/validation || true
    ;;
  docs)
    # The book's generated tables (scripts/docs.py --check and tests/registry.rs check them).
    build_native
    python3 scripts/docs.py
    git --no-pager diff --stat -- docs || true
    ;;
  golden)
    UPDATE_GOLDEN=1 cargo test --release -p aes-tests --test golden
    git --no-pager diff --stat -- tests/golden || true
    ;;
  bench)
    setup
    build_native
    ./target/release/aes-sim bench startup
    ;;
  *)
    echo "usage: ./build.sh [serve|build|test|bench|fuzz|golden|validate|docs]" >&2
    exit 2
    ;;
esac
