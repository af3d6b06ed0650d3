#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build for SECONDS each, all at once
# (the time is wall-clock, so the whole run takes SECONDS), starting from a
# copy of the seed corpus (the seeds in the repository stay untouched).
# Exits non-zero when a target crashes, leaks, times out or is missing.
#
#   CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DGGSTUDIO_FUZZ=ON -DGGSTUDIO_BUILD_TESTS=ON
#   ninja -C build-fuzz fuzz_native_loader fuzz_gggenerator_importer fuzz_condition_parser fuzz_scenario_parser fuzz_plcopen_reader
#   tests/fuzz/run-fuzzers.sh build-fuzz 60
set -u

if [ $# -ne 2 ]; then
    echo "usage: $0 BUILD_DIR SECONDS" >&2
    exit 2
fi
build_dir=$1
duration=$2
case $duration in
    '' | *[!0-9]*) echo "SECONDS must be a whole number, not '$duration'" >&2; exit 2 ;;
esac

here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/ggstudio-fuzz.XXXXXX") || exit 2
failed=0

# run TARGET MAX_LEN DICTIONARY: prints its report into $work/TARGET/report
# and leaves $work/TARGET/failed when the target failed.
run() {
    local target=$1 max_len=$2 dictionary=$3
    local binary=$build_dir/tests/fuzz/$target
    local dir=$work/$target
    mkdir -p "$dir/corpus" "$dir/artifacts"
    exec >"$dir/report"
    if [ ! -x "$binary" ]; then
        echo "!! $target: no $binary (configure with -DGGSTUDIO_FUZZ=ON and build it)"
        touch "$dir/failed"
        return
    fi
    cp "$here/corpus/$target/"* "$dir/corpus/"
    echo "== $target: ${duration}s"
    # -max_len: above the largest seed (a full model file is 6-14 KB), far
    # below the 64 MiB file limit, so time goes into structure, not size.
    if "$binary" -max_total_time="$duration" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
        -dict="$here/$dictionary" -artifact_prefix="$dir/artifacts/" -print_final_stats=1 \
        "$dir/corpus" >"$dir/log.txt" 2>&1; then
        grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$dir/log.txt" | sed 's/^/   /'
    else
        echo "!! $target failed: log $dir/log.txt, failing input(s) in $dir/artifacts/"
        grep -E -A12 'ERROR: |runtime error|deadly signal|Test unit written' "$dir/log.txt" | head -40 | sed 's/^/   /'
        touch "$dir/failed"
    fi
}

targets=(fuzz_native_loader fuzz_gggenerator_importer fuzz_condition_parser fuzz_scenario_parser fuzz_plcopen_reader)
run fuzz_native_loader 32768 json.dict &
run fuzz_gggenerator_importer 32768 json.dict &
run fuzz_condition_parser 2048 conditions.dict &
run fuzz_scenario_parser 4096 scenario.dict &
# An export is 36 KB, most of it the embedded model: a whole seed fits.
run fuzz_plcopen_reader 65536 xml.dict &
wait

for target in "${targets[@]}"; do
    cat "$work/$target/report"
    [ -e "$work/$target/failed" ] && failed=1
done

if [ $failed -eq 0 ]; then
    rm -rf "$work"
    echo "all fuzzers ran clean"
else
    echo "kept $work for inspection"
fi
exit $failed
