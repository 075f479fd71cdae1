#!/usr/bin/env bash
# tools/check-layers and tools/chapter-diff on a tiny fixture repo of two chapters, built afresh
# in a temp dir for every case: the clean fixture passes, and each kind of breach is caught.
#   tests/layering/check_catches.sh [CASE...]     (no CASE: all of them; names below, case_*)
# Prints "ok CASE" or "FAIL CASE: why" per assertion; exit code 1 on any failure.
set -uo pipefail
tools=$(cd "$(dirname "$0")/../../tools" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# The clean fixture: ch01 owns base.h/.cpp, ch02 owns extra.h and adds two lines to base.h, and
# tool.h is the program's (beside the layers), included by chapter 01's program and a test.
# Its traps: a package header, a test tag and a URL in strings, "base.h" reached from its own
# folder, and an image.
make_fixture() {
    local repo=$1
    mkdir -p "$repo"/{rt,chapters/ch01_first,chapters/ch02_second,tests/ch01,tests/ch02,tests/cli}
    printf '# fixture\nch01  base.h base.cpp\nch02  extra.h\nprogram  tool.h\n' >"$repo/rt/layers.txt"
    cat >"$repo/rt/base.h" <<'EOF'
// The first idea. Chapter 01.
#pragma once
#include <vector>
#include "CLI/CLI.hpp"
struct base {
    int value = 1;
    const char* home = "http://example.org/[ch02]";
    int shutter = 0;  // [ch02] the instant a ray leaves
    // [ch02 begin]
    int hook() const { return 2; }
    // [ch02 end]
    int last = 3;
};
EOF
    printf '#include "base.h"\nint base_value() { return base{}.value; }\n' >"$repo/rt/base.cpp"
    printf '#pragma once\n#include "base.h"\n#include "rt/base.h"\nstruct extra { int width = 3; };\n' \
        >"$repo/rt/extra.h"
    printf '#pragma once\n#include "rt/base.h"\nstruct tool { int runs = 1; };\n' >"$repo/rt/tool.h"
    printf '#include "rt/base.h"\n#include "rt/tool.h"\nint main() { return 0; }\n' \
        >"$repo/chapters/ch01_first/main.cpp"
    printf '#pragma once\n#include "rt/extra.h"\n' >"$repo/chapters/ch02_second/scene.h"
    printf '#include "rt/extra.h"\n#include "scene.h"\nint main() { return 0; }\n' \
        >"$repo/chapters/ch02_second/main.cpp"
    printf '#pragma once\n#include "rt/base.h"\n' >"$repo/tests/test_helpers.h"
    printf '#include "test_helpers.h"\n#include "rt/tool.h"\nTEST_CASE("base", "[ch02]") {}\n' \
        >"$repo/tests/ch01/test_base.cpp"
    printf '#include "test_helpers.h"\n#include "rt/extra.h"\n' >"$repo/tests/ch02/test_extra.cpp"
    printf '\x89PNG\r\n\x1a\n\0\0' >"$repo/tests/ch01/picture.png"
    printf '#!/bin/sh\necho the command line\n' >"$repo/tests/cli/run.sh"
}

fail() { echo "FAIL $case: $*"; failures=$((failures + 1)); }

# run TOOL ARGS...: runs a tool, leaving its exit code in $rc, stdout in $out, stderr in $err.
run() {
    "$tools/$1" "${@:2}" >"$work/out" 2>"$work/err"
    rc=$?
    out=$(cat "$work/out") err=$(cat "$work/err")
}

# breach DESCRIPTION COUNT WORD...: check-layers must exit 1 with COUNT findings, one of which
# names every WORD. The fixture was changed just before.
breach() {
    local what=$1 count=$2 line
    shift 2
    run check-layers --root "$repo"
    line=$err
    for word; do line=$(grep -F -- "$word" <<<"$line"); done
    if [ "$rc" -ne 1 ]; then fail "$what: exit code $rc, not 1; stderr: $err"
    elif [ "$(grep -c . <<<"$err")" -ne "$count" ]; then fail "$what: not $count findings: $err"
    elif [ -z "$line" ]; then fail "$what: no finding names all of '$*': $err"
    else echo "ok $case: $what -> $(head -1 <<<"$line")"; fi
}

# has / lacks TEXT: chapter-diff's output holds (or lacks) this exact line.
has() { grep -qxF -- "$1" <<<"$out" && echo "ok $case: shows '$1'" || fail "no line '$1' in: $out${err:+ (stderr: $err)}"; }
lacks() { grep -qF -- "$1" <<<"$out" && fail "'$1' should be hidden: $out" || echo "ok $case: hides '$1'"; }

case_check_passes_clean_fixture() {
    run check-layers --root "$repo"
    if [ "$rc" -ne 0 ] || [ -n "$err" ]; then fail "clean fixture: exit code $rc; stderr: $err"
    elif [ "$out" != "check-layers: 10 files, 14 includes, 4 marked lines, 0 exercise regions: layering holds" ]; then
        fail "clean fixture: unexpected summary '$out'"
    else echo "ok $case: $out"; fi
}
case_check_catches_early_includes_later() {
    echo '#include "extra.h"' >>"$repo/rt/base.h"
    breach "ch01 header includes a ch02 header" 1 "rt/base.h:14 (ch01)" "rt/extra.h (ch02)"
}
case_check_catches_chapter_main_includes_later() {
    echo '#include "rt/extra.h"' >>"$repo/chapters/ch01_first/main.cpp"
    breach "ch01 main includes a ch02 header" 1 "chapters/ch01_first/main.cpp:4" "rt/extra.h (ch02)"
}
case_check_catches_test_includes_later() {
    echo '#include "rt/extra.h"' >>"$repo/tests/test_helpers.h"
    breach "shared test helper includes a ch02 header" 1 "tests/test_helpers.h:3 (shared)" "rt/extra.h"
}
case_check_catches_marked_include() {
    echo '#include "extra.h"  // [ch02] only chapter 02 uses it' >>"$repo/rt/base.cpp"
    breach "marked include still counts" 1 "rt/base.cpp:3" "rt/extra.h (ch02)" "marked [ch02]"
}
case_check_catches_marker_not_later() {
    echo 'int depth = 0;  // [ch02] same chapter as the file' >>"$repo/rt/extra.h"
    breach "marker of the file's own chapter" 1 "rt/extra.h:5" "[ch02]" "not later"
    make_fixture "$repo.2" && repo=$repo.2
    echo 'int depth = 0;  // [ch01] earlier than the file' >>"$repo/rt/extra.h"
    breach "marker of an earlier chapter" 1 "rt/extra.h:5" "[ch01]" "not later"
}
case_check_catches_unbalanced_markers() {
    echo '// [ch02 begin] never closed' >>"$repo/rt/base.h"
    breach "begin without end" 1 "rt/base.h:14" "[ch02 begin] has no end"
    make_fixture "$repo.2" && repo=$repo.2
    echo '// [ch02 end]' >>"$repo/rt/base.cpp"
    breach "end without begin" 1 "rt/base.cpp:3" "[ch02 end] has no begin"
    make_fixture "$repo.3" && repo=$repo.3
    sed -i 's|// \[ch02 begin\]|&\n// [ch02 begin]|' "$repo/rt/base.h"
    breach "nested begin" 1 "rt/base.h:10" "do not nest"
}
# An exercise region of the fixture: base_value's body, in a file that includes the header of
# the stubs' function.
add_exercise() {
    printf '# fixture\nch01  base.h base.cpp core/exercise.h\nch02  extra.h\nprogram  tool.h\n' \
        >"$repo/rt/layers.txt"
    mkdir -p "$repo/rt/core" && printf '#pragma once\n' >"$repo/rt/core/exercise.h"
    printf '%s\n' '#include "base.h"' '#include "rt/core/exercise.h"' 'int base_value() {' \
        '    // [exercise base_value begin]' '    return base{}.value;' \
        '    // [exercise base_value end]' '}' >"$repo/rt/base.cpp"
}
case_check_catches_bad_exercise_regions() {
    add_exercise
    run check-layers --root "$repo"
    if [ "$rc" -ne 0 ] || ! grep -qF "1 exercise regions" <<<"$out"; then
        fail "a good exercise region: exit $rc, $out $err"
    else echo "ok $case: a good exercise region passes"; fi
    sed -i '/rt\/core\/exercise.h/d' "$repo/rt/base.cpp"
    breach "region without the stubs' header" 1 "rt/base.cpp" "does not include rt/core/exercise.h"
    make_fixture "$repo.2" && repo=$repo.2 && add_exercise
    sed -i '/exercise base_value end/d' "$repo/rt/base.cpp"
    breach "begin without end" 1 "rt/base.cpp:4" "exercise 'base_value' has no end"
    make_fixture "$repo.3" && repo=$repo.3 && add_exercise
    sed -i '/exercise base_value begin/d' "$repo/rt/base.cpp"
    breach "end without begin" 1 "rt/base.cpp:5" "ends without a begin"
    make_fixture "$repo.4" && repo=$repo.4 && add_exercise
    sed -i 's|    return base{}.value;|    // [exercise inner begin]\n&\n    // [exercise inner end]|' \
        "$repo/rt/base.cpp"
    breach "nested regions" 2 "rt/base.cpp:5" "do not nest"
    make_fixture "$repo.5" && repo=$repo.5 && add_exercise
    sed -i '/    return base{}.value;/d' "$repo/rt/base.cpp"
    breach "empty region" 1 "rt/base.cpp:5" "exercise 'base_value' is empty"
    make_fixture "$repo.6" && repo=$repo.6 && add_exercise
    sed -i 's|    int value = 1;|#include "rt/core/exercise.h"\n    // [exercise span begin]|; s|    int last = 3;|    // [exercise span end]\n&|' \
        "$repo/rt/base.h"
    breach "region across a later chapter's lines" 1 "rt/base.h" "more than one chapter"
    make_fixture "$repo.7" && repo=$repo.7 && add_exercise
    printf '%s\n' '#pragma once' '#include "rt/core/exercise.h"' 'inline int twice() {' \
        '    // [exercise base_value begin]' '    return 2;' '    // [exercise base_value end]' \
        '}' >"$repo/rt/base.h"
    breach "one name twice" 1 "exercise 'base_value' is also at"
    make_fixture "$repo.8" && repo=$repo.8 && add_exercise
    printf '%s\n' '#include "rt/core/exercise.h"' 'int two() {' '    // [exercise two begin]' \
        '    return 2;' '    // [exercise two end]' '}' >"$repo/tests/ch01/test_two.cpp"
    breach "a region in a test" 1 "tests/ch01/test_two.cpp" "belong in rt/ or chapters/"
}
case_check_catches_unlisted_library_file() {
    echo '#pragma once' >"$repo/rt/stray.h"
    breach "library file missing from layers.txt" 1 "rt/stray.h is not listed"
    echo '#include "rt/stray.h"' >>"$repo/chapters/ch02_second/main.cpp"
    breach "include of an unlisted library file" 2 "chapters/ch02_second/main.cpp:4" \
        "rt/stray.h, which is not listed"
    make_fixture "$repo.2" && repo=$repo.2
    echo 'ch02  base.cpp ghost.h' >>"$repo/rt/layers.txt"
    breach "file listed twice" 2 "base.cpp is listed twice"
    breach "listed file that does not exist" 2 "rt/ghost.h is listed" "does not exist"
}
case_check_catches_layer_includes_program() {
    echo '#include "rt/tool.h"' >>"$repo/rt/base.cpp"
    breach "chapter 01's layer includes the program" 1 "rt/base.cpp:3 (ch01)" "rt/tool.h (program)"
    make_fixture "$repo.2" && repo=$repo.2
    echo '#include "rt/extra.h"' >>"$repo/rt/tool.h"
    breach "the program includes a ch02 header" 1 "rt/tool.h:4 (program)" "rt/extra.h (ch02)"
}
case_check_catches_marker_in_program_file() {
    echo 'int late = 0;  // [ch02] the program belongs to no chapter' >>"$repo/rt/tool.h"
    breach "marker in the program's file" 1 "rt/tool.h:4" "[ch02]" "no chapter"
}
case_chapter_diff_shows_new_file() {
    run chapter-diff ch02 --root "$repo"
    has "--- /dev/null" && has "+++ b/rt/extra.h" && has "+struct extra { int width = 3; };"
    has "+++ b/chapters/ch02_second/main.cpp" && has "+++ b/tests/ch02/test_extra.cpp"
    has "chapter-diff ch02: 4 new files (11 lines), 1 earlier file changed (+4 lines)"
}
case_chapter_diff_shows_marked_lines() {
    run chapter-diff ch02 --root "$repo"
    has "--- a/rt/base.h" && has "+++ b/rt/base.h" && has "     int value = 1;"
    has "+    int shutter = 0;  // [ch02] the instant a ray leaves"
    has "+    // [ch02 begin]" && has "+    int hook() const { return 2; }" && has "+    // [ch02 end]"
    grep -q $'\033' <<<"$out" && fail "colour codes in piped output" || echo "ok $case: no colour when piped"
}
case_chapter_diff_hides_later_lines() {
    run chapter-diff ch01 --root "$repo"
    has "+++ b/rt/base.h" && has "+    int value = 1;" && has "+    int last = 3;"
    lacks "shutter" && lacks "hook" && lacks "extra"
    has "Binary file b/tests/ch01/picture.png is new" && lacks "PNG"
    lacks "+++ b/rt/tool.h" && lacks "command line"  # the program's and the shared files: no chapter's
}
case_chapter_diff_refuses_unknown_chapter() {
    local chapter
    for chapter in ch03 chapter2; do
        run chapter-diff "$chapter" --root "$repo"
        if [ "$rc" -ne 2 ] || [ "$(grep -c . <<<"$err")" -ne 1 ] || [ -n "$out" ]; then
            fail "$chapter: exit code $rc (not 2), stdout '$out', stderr '$err'"
        else echo "ok $case: $chapter -> $err"; fi
    done
}
case_chapter_diff_quiet_when_reader_stops() {
    # Far more output than a pipe holds (64 KiB): chapter-diff is still writing when head leaves.
    seq -f 'int filler_%g = 0;' 20000 >>"$repo/rt/base.cpp"
    "$tools/chapter-diff" ch01 --root "$repo" 2>"$work/err" | head -1 >"$work/out"
    local status=${PIPESTATUS[0]}
    out=$(cat "$work/out") err=$(cat "$work/err")
    if [ -n "$err" ]; then fail "stderr when the reader stops early: $err"
    elif [ "$out" != "--- /dev/null" ]; then fail "head -1 read '$out', not '--- /dev/null'"
    elif [ "$status" -ne 141 ] && [ "$status" -ne 0 ]; then
        fail "exit code $status, not 141 (SIGPIPE, as a shell reports it) or 0"
    else echo "ok $case: quiet when its reader stops after one line (exit code $status)"; fi
}

cases=("$@")
[ $# -gt 0 ] || mapfile -t cases < <(declare -F | sed -n 's/^declare -f case_//p')
for case in "${cases[@]}"; do
    declare -F "case_$case" >/dev/null || { fail "no such case"; continue; }
    repo=$work/$case
    make_fixture "$repo"
    "case_$case"
done
[ "$failures" -eq 0 ] || { echo "$failures assertion(s) failed"; exit 1; }
