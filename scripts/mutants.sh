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
# tests (`cargo test --lib`: the tests of src/kinematics/ live there, so a
# mutant costs one test binary, a few seconds), and for a file of
# src/services/ the services' tests too (`--test services`: they run whole
# programs through a Session, a layer above the services, so they are an
# integration test; a second test binary). The second
# (`--iterate`) gives the mutants the first pass missed or cut to the whole
# suite (golden scripts, CLI, serial): MUTANTS_PASSES=1 skips it. Set
# MUTANTS_TEST_ARGS to run other `cargo test` arguments in the second pass.
# Results go to mutants.out/DIR-FILE/mutants.out/ (caught.txt, missed.txt,
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
# One line per file: caught (a test failed, or it hung: timeout) of the
# viable mutants (those that build), counting only the mutants the file has
# now (--iterate keeps the names of earlier runs, whose lines may have moved).
summarize() {
    local f=$1 d=$2/mutants.out
    local now caught missed timeout unviable viable
    mkdir -p "$d"
    touch "$d/caught.txt" "$d/previously_caught.txt" "$d/missed.txt" "$d/timeout.txt" "$2/unviable-all.txt"
    now=$(mktemp)
    cargo mutants --list --file "$f" 2>/dev/null | sort -u >"$now"
    count() { sort -u "$@" | comm -12 - "$now"; }
    unviable=$(count "$2/unviable-all.txt" | wc -l)
    caught=$(cat "$d/caught.txt" "$d/previously_caught.txt" | sort -u \
        | comm -23 - <(sort -u "$2/unviable-all.txt") | comm -12 - "$now" | wc -l)
    missed=$(count "$d/missed.txt" | wc -l)
    timeout=$(count "$d/timeout.txt" | wc -l)
    local untested=$(($(wc -l <"$now") - caught - missed - timeout - unviable))
    rm -f "$now"
    viable=$((caught + missed + timeout))
    echo "$f: $((caught + timeout)) of $viable viable caught" \
        "($((viable ? 100 * (caught + timeout) / viable : 100)) %;" \
        "$timeout by timeout), $missed missed, $unviable unviable, $untested not run"
}
# Runs one cargo-mutants command (under the cargo lock when there is one)
# and keeps its unviable mutants: --iterate files earlier unviable ones
# under previously_caught, so every pass's are kept to tell them apart.
run_pass() {
    local out=$1
    shift
    echo "== $f: $*" >&2
    if [ -e "$lock" ]; then
        flock "$lock" "$@" || status=$?
    else
        "$@" || status=$?
    fi
    cat "$out/mutants.out/unviable.txt" >>"$out/unviable-all.txt" 2>/dev/null || true
    sort -u -o "$out/unviable-all.txt" "$out/unviable-all.txt"
}
summary=()
status=0
for f in "${files[@]}"; do
    test_args=()
    if [ -n "${MUTANTS_TEST_ARGS:-}" ]; then
        read -r -a test_args <<<"$MUTANTS_TEST_ARGS"
    fi
    # src/kinematics/mod.rs -> mutants.out/kinematics-mod
    out=${f#src/}
    out="mutants.out/${out//\//-}"
    out=${out%.rs}
    mkdir -p "$out"
    read -r -a extra <<<"${MUTANTS_ARGS:-}"
    jobs=(-j 1)
    # --in-place runs one mutant at a time by itself and refuses -j.
    [[ " ${extra[*]} " == *" --in-place "* ]] && jobs=()
    base=(cargo mutants "${jobs[@]}" --timeout "$timeout" "${extra[@]}" --file "$f" --output "$out")
    # -C goes to the build as well as to the test run.
    first=(-C --lib)
    [[ $f == src/services/* ]] && first+=(-C --test=services)
    run_pass "$out" "${base[@]}" "${first[@]}"
    # The whole suite, for what the library tests left (if anything).
    if [ "${MUTANTS_PASSES:-2}" != 1 ] && { [ -s "$out/mutants.out/missed.txt" ] \
        || [ -s "$out/mutants.out/timeout.txt" ]; }; then
        run_pass "$out" "${base[@]}" --iterate -- "${test_args[@]}"
    fi
    summary+=("$(summarize "$f" "$out")")
done
printf '%s\n' "${summary[@]}" >&2
exit "$status"
