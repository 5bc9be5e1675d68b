#!/usr/bin/env bash
# Mutation testing of the motion rules and path services with cargo-mutants.
#
#   scripts/mutants.sh                      # every file of src/kinematics and src/services
#   scripts/mutants.sh src/kinematics/ik.rs # only these files
#
# One file at a time, one job at a time (-j 1), each file under the shared
# cargo lock (the machine has two cores for everyone); each mutant's build
# and test run is cut after MUTANTS_TIMEOUT seconds (default 300).
# Two passes per file. The first builds and runs only the library's unit
# tests (`cargo test --lib`: the tests of src/kinematics/ and src/services/
# live there, so a mutant costs one test binary, a few seconds). The second
# (`--iterate`) gives the mutants the first pass missed or cut to the whole
# suite (golden scripts, CLI, serial): MUTANTS_PASSES=1 skips it. Set
# MUTANTS_TEST_ARGS to run other `cargo test` arguments in the second pass.
# Results go to mutants.out/FILE/mutants.out/ (caught.txt, missed.txt,
# timeout.txt, unviable.txt; the second pass's lists replace the first's
# for the mutants it re-ran). MUTANTS_ARGS adds cargo-mutants options (for
# example `--in-place`, which reuses ./target instead of building a copy of
# the tree from scratch).
# Install the tool once with: flock /work/cargo.lock cargo install cargo-mutants
set -euo pipefail
cd "$(dirname "$0")/.."
lock=${CARGO_LOCK:-/work/cargo.lock}
timeout=${MUTANTS_TIMEOUT:-300}
if ! cargo mutants --version >/dev/null 2>&1; then
    echo "cargo-mutants is not installed: flock $lock cargo install cargo-mutants" >&2
    exit 2
fi
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
    files=(src/kinematics/*.rs src/services/*.rs)
fi
status=0
for f in "${files[@]}"; do
    test_args=()
    if [ -n "${MUTANTS_TEST_ARGS:-}" ]; then
        read -r -a test_args <<<"$MUTANTS_TEST_ARGS"
    fi
    out="mutants.out/$(basename "$f" .rs)"
    mkdir -p "$out"
    read -r -a extra <<<"${MUTANTS_ARGS:-}"
    jobs=(-j 1)
    # --in-place runs one mutant at a time by itself and refuses -j.
    [[ " ${extra[*]} " == *" --in-place "* ]] && jobs=()
    base=(cargo mutants "${jobs[@]}" --timeout "$timeout" "${extra[@]}" --file "$f" --output "$out")
    # -C goes to the build as well as to the test run: one test binary.
    passes=("${base[*]} -C --lib")
    if [ "${MUTANTS_PASSES:-2}" != 1 ]; then
        passes+=("${base[*]} --iterate -- ${test_args[*]}")
    fi
    for pass in "${passes[@]}"; do
        read -r -a cmd <<<"$pass"
        echo "== $f: ${cmd[*]}" >&2
        if [ -e "$lock" ]; then
            flock "$lock" "${cmd[@]}" || status=$?
        else
            "${cmd[@]}" || status=$?
        fi
    done
done
exit "$status"
