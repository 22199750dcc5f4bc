#!/usr/bin/env bash
# Every check breakshot has, the way CI runs them (.ci/run calls this):
#
#   (a) release build, warnings as errors, and its tests      (preset release);
#       the Python package installed into .venv (scripts/python.sh) and pytest.
#       The tests include `breakshot serve` through real sockets on 127.0.0.1
#       (tests/test_online.cpp: 100 half-sent requests, whole online games,
#       100 rooms at once whose records `breakshot replay` checks): about
#       7 s of the ctest stage, run again under the sanitizers in (b)
#   (b) the same tests under AddressSanitizer + UBSan, built with clang
#       (preset asan), and in the same tree the libFuzzer targets, whose
#       seed corpus replays are among its tests
#   (c) install the release build and build and run the example consumer
#       against it (find_package(breakshot)), and the C API's example
#       (examples/c) through the CMake package and pkg-config, shared and
#       static; build the Python wheel and
#       use it from a fresh environment; run scripts/run.sh --check
#   (d) the browser version: the page's logic in node without a browser
#       (web/tests/unit/, node --test, about 5 s), native and wasm give the
#       same replies byte for byte (web/tests/identity.mjs), and
#       playwright-core drives Chromium through the served page
#       (web/tests/browser.mjs; its online test, two pages playing each
#       other through the server, about 25 s); the npm package
#       (scripts/npm.sh: packed from the wasm build, then npm/tests/run.mjs:
#       installed into an empty folder, its TypeScript examples checked
#       with tsc --strict and run in node, the native command's bytes, bad
#       input, the HTML example in Chromium)
#   (e) the libFuzzer targets of (b): fuzzing scenarios for
#       BREAKSHOT_FUZZ_SECONDS (default 60) seconds, seeded with fuzz/corpus
#       and examples/lab, and game records for BREAKSHOT_RECORD_FUZZ_SECONDS
#       (default 30), seeded with fuzz/record_corpus
#
# (b) and (e) run beside (a), (c) and (d), in a process group of their own
# at the lowest CPU priority: pytest uses one core, links and Chromium's
# waits leave cores idle, and the sanitizer tree is built and run in what
# they leave. Its tests start once (c) has built the wasm engine. Their
# output is shown (from build/logs/background.log) when (d) is done; every
# stage's time is printed at the end.
#
# The last line is the sum over every ctest run and node test script: "N passed, 0 failed".
#
#   scripts/test.sh            everything
#   scripts/test.sh --quick    only (a)
set -Eeuo pipefail
cd "$(dirname "$0")/.."
root=$PWD

quick=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    -h|--help) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done
fuzz_seconds=${BREAKSHOT_FUZZ_SECONDS:-60}
record_fuzz_seconds=${BREAKSHOT_RECORD_FUZZ_SECONDS:-30}

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

logs=$root/build/logs
mkdir -p "$logs"

# --- bookkeeping: stage times, ctest totals, a loud message on failure ---
stage_name=""
stage_t0=0
timings=()
passed=0
failed=0

stage() {
  stage_done
  stage_name=$1
  stage_t0=$SECONDS
  printf '\n==== %s ====\n' "$stage_name"
}
stage_done() {
  if [ -n "$stage_name" ]; then
    timings+=("$(printf '%-44s %4ds' "$stage_name" $((SECONDS - stage_t0)))")
  fi
  stage_name=""
}
background_pid=""
on_error() {
  local rc=$?
  # Stages (b) and (e) run in their own process group beside the others.
  if [ -n "$background_pid" ]; then
    kill -- "-$background_pid" 2>/dev/null || true
  fi
  echo >&2
  echo "test.sh: FAILED (exit $rc) in stage: ${stage_name:-setup}" >&2
  echo "test.sh: logs are in $logs" >&2
  exit "$rc"
}
trap on_error ERR
on_interrupt() {
  if [ -n "$background_pid" ]; then
    kill -- "-$background_pid" 2>/dev/null || true
  fi
  echo "test.sh: interrupted" >&2
  exit 130
}
trap on_interrupt INT TERM

# Runs one ctest preset, shows its output and adds its counts to the totals.
run_ctest() {
  ctest --preset "$1" 2>&1 | tee "$logs/ctest-$1.log"
  count_ctest "$1" "$logs/ctest-$1.log"
}
# Adds the counts of a ctest log to the totals.
count_ctest() {
  local preset=$1 log=$2 line total nfail nskip
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1)
  if [ -z "$line" ]; then
    echo "test.sh: no ctest summary for preset $preset" >&2
    return 1
  fi
  nfail=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  total=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")
  # Skipped tests (web_identity before the wasm build exists) are not passes.
  nskip=$(grep -cE '^\s*[0-9]+ - .* \(Skipped\)$' "$log" || true)
  passed=$((passed + total - nfail - nskip))
  failed=$((failed + nfail))
}

# Runs pytest and adds its counts ("N passed" and "N failed" of its last
# line) to the totals.
run_pytest() {
  local log=$logs/pytest.log line np nf=0 n
  BREAKSHOT_CLI=$root/build/release/breakshot .venv/bin/python -m pytest -q \
    -p no:cacheprovider python/tests 2>&1 | tee "$log" || true
  line=$(tail -n 1 "$log")
  if ! grep -qE '[0-9]+ passed' <<<"$line"; then
    echo "test.sh: no summary line from pytest" >&2
    return 1
  fi
  np=$(grep -oE '[0-9]+ passed' <<<"$line" | cut -d' ' -f1)
  # No failures: grep finds nothing, which must not set off the ERR trap.
  for n in $(grep -oE '[0-9]+ (failed|errors?)' <<<"$line" | cut -d' ' -f1 || true); do
    nf=$((nf + n))
  done
  passed=$((passed + np))
  failed=$((failed + nf))
}

# Runs a node test script that ends with "N passed, M failed" and adds its
# counts to the totals.
run_node_tests() {
  local name=$1 log=$logs/node-$1.log line
  shift
  "$@" 2>&1 | tee "$log"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
  if [ -z "$line" ]; then
    echo "test.sh: no summary line from the $name tests" >&2
    return 1
  fi
  passed=$((passed + $(cut -d' ' -f1 <<<"$line")))
  failed=$((failed + $(cut -d' ' -f3 <<<"$line")))
}

t_start=$SECONDS

stage "setup (scripts/setup.sh)"
scripts/setup.sh
stage_done
wasm_built=$logs/wasm-built
rm -f "$wasm_built"

# Stages (b) and (e) run beside (a), (c) and (d), at the lowest CPU
# priority: they take what the other stages leave idle (pytest's one core,
# the links, Chromium's waits) without slowing them. Their output goes to
# build/logs/background.log and is shown when (d) is done.
if [ "$quick" -eq 0 ]; then
  background_log=$logs/background.log
  background_times=$logs/background-times.txt
  : >"$background_times"
  rm -f "$logs/ctest-asan.log"
  set -m
  (
    renice -n 19 -p "$BASHPID" >/dev/null
    trap - ERR
    set -e
    bg_stage() { bg_name=$1; bg_t0=$SECONDS; printf '\n==== %s ====\n' "$bg_name"; }
    bg_done() { printf '%-44s %4ds\n' "$bg_name" $((SECONDS - bg_t0)) >>"$background_times"; }
    bg_stage "(b) asan: configure + build (clang; the tests, the fuzz targets)"
    cmake --preset asan
    cmake --build --preset asan
    bg_done
    # web_identity compares native and wasm replies: it waits for (c) to
    # have built the wasm engine.
    while [ ! -e "$wasm_built" ]; do sleep 2; done
    bg_stage "(b) asan: ctest under ASan/UBSan (with the fuzz corpus replays)"
    ctest_rc=0
    ctest --preset asan >"$logs/ctest-asan.log" 2>&1 || ctest_rc=$?
    if [ "$ctest_rc" -ne 0 ]; then cat "$logs/ctest-asan.log"; else tail -n 25 "$logs/ctest-asan.log"; fi
    bg_done

    # The fuzz targets were built and their seed corpora replayed above.
    # The two fuzzers run side by side, one core each (each is one process
    # of one thread), each for its own seconds and into its own log.
    fuzz_dir=build/asan/fuzz
    bg_stage "(e) fuzz: libFuzzer, scenarios ${fuzz_seconds}s and game records ${record_fuzz_seconds}s"
    mkdir -p $fuzz_dir/corpus-work $fuzz_dir/record-corpus-work $fuzz_dir/artifacts
    $fuzz_dir/breakshot_fuzz_record \
      -max_total_time="$record_fuzz_seconds" -timeout=10 -rss_limit_mb=4096 -max_len=16384 \
      -artifact_prefix=$fuzz_dir/artifacts/ -print_final_stats=1 \
      $fuzz_dir/record-corpus-work fuzz/record_corpus >"$logs/fuzz-record.log" 2>&1 &
    record_pid=$!
    scenario_rc=0
    $fuzz_dir/breakshot_fuzz \
      -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=4096 -max_len=4096 \
      -dict=fuzz/scenario.dict -artifact_prefix=$fuzz_dir/artifacts/ \
      -print_final_stats=1 $fuzz_dir/corpus-work fuzz/corpus examples/lab \
      >"$logs/fuzz.log" 2>&1 || scenario_rc=$?
    record_rc=0
    wait "$record_pid" || record_rc=$?
    for fuzzer in breakshot_fuzz breakshot_fuzz_record; do
      if [ $fuzzer = breakshot_fuzz ]; then
        rc=$scenario_rc fuzz_log=$logs/fuzz.log what="scenario fuzzer"
      else
        rc=$record_rc fuzz_log=$logs/fuzz-record.log what="record fuzzer"
      fi
      echo "-- $fuzzer ($fuzz_log)"
      if [ "$rc" -ne 0 ]; then
        tail -n 80 "$fuzz_log"
        echo "test.sh: the $what found a failing input (exit $rc); it is in $fuzz_dir/artifacts/"
        echo "test.sh: reproduce with: $fuzz_dir/$fuzzer $fuzz_dir/artifacts/FILE"
      else
        grep -E '^(#[0-9]+ *DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb)' \
          "$fuzz_log" || true
      fi
    done
    bg_done
    [ "$ctest_rc" -eq 0 ] && [ "$scenario_rc" -eq 0 ] && [ "$record_rc" -eq 0 ]
  ) >"$background_log" 2>&1 &
  background_pid=$!
  set +m
  echo
  echo "==== (b) asan and (e) fuzz: started beside the other stages at the lowest priority (log: $background_log) ===="
fi

stage "(a) release: configure + build (-Werror)"
cmake --preset release
cmake --build --preset release
stage "(a) release: ctest"
run_ctest release
stage "(a) python: .venv + pip install (scripts/python.sh)"
scripts/python.sh
stage "(a) python: pytest"
run_pytest

if [ "$quick" -eq 0 ]; then
  stage "(c) install + example consumer"
  rm -rf build/install build/consumer
  cmake --install build/release --prefix build/install
  # The installed package must stand alone: nlohmann_json and the build's
  # flag target are build-only dependencies of the library.
  if grep -nE 'nlohmann|breakshot_flags' build/install/lib*/cmake/breakshot/*.cmake; then
    echo "test.sh: the installed breakshot package refers to a build-only dependency" >&2
    false
  fi
  cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$root/build/install"
  cmake --build build/consumer -j 2
  build/consumer/consumer
  # The C API from C (examples/c/example.c, -std=c99 -Wall -Wextra -Werror):
  # through the CMake package (breakshot::c and breakshot::c_static) and
  # through pkg-config (breakshot, breakshot-static); every build prints
  # the same.
  rm -rf build/example-c
  cmake -S examples/c -B build/example-c -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$root/build/install"
  cmake --build build/example-c -j 2
  build/example-c/example_c >build/example-c/cmake.txt
  build/example-c/example_c_static >build/example-c/cmake-static.txt
  pc_path=$(echo "$root"/build/install/lib*/pkgconfig)
  pc() { PKG_CONFIG_PATH=$pc_path pkg-config "$@"; }
  cc -std=c99 -Wall -Wextra -Werror examples/c/example.c $(pc --cflags --libs breakshot) \
    -Wl,-rpath,"$(pc --variable=libdir breakshot)" -o build/example-c/example_pc
  cc -std=c99 -Wall -Wextra -Werror examples/c/example.c $(pc --cflags --libs breakshot-static) \
    -o build/example-c/example_pc_static
  build/example-c/example_pc >build/example-c/pkg-config.txt
  build/example-c/example_pc_static >build/example-c/pkg-config-static.txt
  for out in cmake-static pkg-config pkg-config-static; do
    cmp build/example-c/cmake.txt build/example-c/$out.txt
  done
  head -n 3 build/example-c/cmake.txt
  echo "examples/c built four ways (CMake package, pkg-config; shared, static): the same output"

  stage "(c) python: a wheel installed into a fresh environment"
  rm -rf build/dist build/wheel-venv
  BREAKSHOT_CMAKE_BUILD_DIR=$root/build/release \
    .venv/bin/python -m build --no-isolation --wheel --outdir build/dist . >"$logs/wheel.log" 2>&1 \
    || { cat "$logs/wheel.log"; false; }
  /usr/bin/python3 -m venv --system-site-packages build/wheel-venv
  build/wheel-venv/bin/python -m pip install --no-deps --no-index --disable-pip-version-check \
    --quiet build/dist/breakshot-*.whl
  (cd build && wheel-venv/bin/python -c 'import sys, breakshot
sys.stdout.write(breakshot.simulate(sys.argv[1]).to_json())' ../examples/pool/break_8ball.json) \
    >build/wheel-break.json
  cmp build/wheel-break.json <(build/release/breakshot simulate examples/pool/break_8ball.json)
  echo "the wheel's breakshot.simulate gives the command's bytes"

  stage "(c) scripts/run.sh --check (the README's main job)"
  scripts/run.sh --check >"$logs/run.log" 2>&1 || { cat "$logs/run.log"; false; }
  tail -n 6 "$logs/run.log"

  # The wasm build exists now: the sanitizer tree's web_identity test
  # (native and wasm replies) may run.
  touch "$wasm_built"

  stage "(d) web: the page's unit tests (node --test)"
  run_node_tests unit node web/tests/unit/run.mjs
  stage "(d) web: native and wasm replies, byte for byte"
  run_node_tests identity node web/tests/identity.mjs --probe build/release/web_api_probe \
    --engine build/web/dist/breakshot.js
  stage "(d) web: browser tests (playwright-core + /usr/bin/chromium)"
  (cd web/tests && npm ci --no-audit --no-fund --loglevel=error)
  run_node_tests browser node web/tests/browser.mjs --cli build/release/breakshot \
    --root build/web/dist --shots build/web/screenshots
  # scripts/npm.sh calls scripts/web.sh, which has nothing to rebuild here.
  stage "(d) npm: the package packed, installed and run"
  scripts/npm.sh
  run_node_tests npm node npm/tests/run.mjs --native build/release --playwright web/tests \
    --shots build/npm/screenshots

  stage "(b) and (e): waiting for the sanitizer tests and the fuzzers"
  background_rc=0
  wait "$background_pid" || background_rc=$?
  background_pid=""
  cat "$background_log"
  while IFS= read -r line; do timings+=("$line"); done <"$background_times"
  if [ -f "$logs/ctest-asan.log" ]; then
    count_ctest asan "$logs/ctest-asan.log"
  fi
  if [ "$background_rc" -ne 0 ]; then
    echo "test.sh: the sanitizer build, its tests or the fuzzers failed (exit $background_rc); see above and $background_log" >&2
    false
  fi
fi
stage_done
trap - ERR

echo
echo "==== stage times ===="
printf '%s\n' "${timings[@]}"
printf '%-44s %4ds\n' "total" $((SECONDS - t_start))
echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
