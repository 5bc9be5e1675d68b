#!/usr/bin/env bash
# Mutation testing of the motion rules and path services with cargo-mutants.
#
#   scripts/mutants.sh                      # every file of src/kinematics and src/services
#   scripts/mutants.sh src/kinematics/ik.rs # only these files
#
# One file at a time, one job at a time (-j 1), each file under the shared
# cargo lock (the machine has two cores for everyone); each mutant's build
# and test run is cut after MUTANTS_TIMEOUT seconds (default 300). A
# src/kinematics file is tested by the kinematics unit and property tests
# (`--lib --test 'kinematics_*'`); any other file by the whole suite. Set
# MUTANTS_TEST_ARGS to choose other `cargo test` arguments. Results go to
# mutants.out/FILE/ (caught.txt, missed.txt, timeout.txt, unviable.txt).
# MUTANTS_ARGS adds cargo-mutants options (for example `--in-place`, which
# reuses ./target instead of building a copy of the tree from scratch).
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
    case "$f" in
        */tests.rs) continue ;;
    esac
    if [ -n "${MUTANTS_TEST_ARGS:-}" ]; then
        read -r -a test_args <<<"$MUTANTS_TEST_ARGS"
    elif [[ "$f" == src/kinematics/* ]]; then
        test_args=(--lib --test 'kinematics_*')
    else
        test_args=()
    fi
    out="mutants.out/$(basename "$f" .rs)"
    mkdir -p "$out"
    read -r -a extra <<<"${MUTANTS_ARGS:-}"
    jobs=(-j 1)
    # --in-place runs one mutant at a time by itself and refuses -j.
    [[ " ${extra[*]} " == *" --in-place "* ]] && jobs=()
    cmd=(cargo mutants "${jobs[@]}" --timeout "$timeout" "${extra[@]}" --file "$f" --output "$out" -- "${test_args[@]}")
    echo "== $f" >&2
    if [ -e "$lock" ]; then
        flock "$lock" "${cmd[@]}" || status=$?
    else
        "${cmd[@]}" || status=$?
    fi
done
exit "$status"
