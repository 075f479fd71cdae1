#!/usr/bin/env bash
# tools/exercise without building anything, on this repository's own exercises: what a
# workspace holds (chapters 01 to NN as chapter NN sees them, the stubs, the record), what
# solution and restore give back, and each bad input refused with one line, exit code 2 and
# nothing written. (Building a workspace and running its targets is tools/run-tests' exercise
# stage: `tools/exercise verify`.)
#   tests/tools/exercise.sh [CASE...]     (no CASE: all of them; names below, case_*)
# Prints "ok CASE" or "FAIL CASE: why" per assertion; exit code 1 on any failure.
set -uo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
tool="$repo/tools/exercise"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
    echo "FAIL $1: $2"
    failures=$((failures + 1))
}

# The first chapter with exercises, and one of its exercises and their file.
chapter=$("$tool" list | sed -n '1s/^\(ch[0-9][0-9]\) .*/\1/p')
first_exercise=$("$tool" list "$chapter" | sed -n 's/^  step 1: \([^ ,]*\).*/\1/p')

# expect_refusal CASE WANTED ARGS...: exit code 2, one line on stderr containing WANTED, and
# nothing on stdout.
expect_refusal() {
    local case=$1 wanted=$2
    shift 2
    (cd "$work" && "$tool" "$@") >"$work/out" 2>"$work/err"
    local status=$?
    [ "$status" -eq 2 ] || fail "$case" "exit code $status, expected 2 ($(cat "$work/err"))"
    [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$case" "expected one line, got: $(cat "$work/err")"
    grep -qF -- "$wanted" "$work/err" || fail "$case" "no '$wanted' in: $(cat "$work/err")"
    [ -s "$work/out" ] && fail "$case" "printed on stdout: $(cat "$work/out")"
    return 0
}

# A fresh workspace of the first chapter with exercises in $work/ws.
start() {
    "$tool" start "$chapter" "$work/ws" >"$work/out" 2>"$work/err" ||
        { fail "$1" "start failed: $(cat "$work/err")"; return 1; }
}

case_start_writes_chapters_up_to_its_own() {
    start start_writes_chapters_up_to_its_own || return
    local n=${chapter#ch} later
    later=$(printf 'ch%02d' $((10#$n + 1)))
    [ -f "$work/ws/.exercise/workspace.json" ] || fail start_writes "no record"
    [ -f "$work/ws/WORKSPACE.md" ] || fail start_writes "no WORKSPACE.md"
    ls -d "$work/ws/chapters/${chapter}_"* >/dev/null 2>&1 || fail start_writes "no $chapter program"
    ls -d "$work/ws/chapters/${later}_"* >/dev/null 2>&1 && fail start_writes "holds $later"
    [ -d "$work/ws/tests/$later" ] && fail start_writes "holds tests/$later"
    [ -d "$work/ws/tests/tools" ] && fail start_writes "holds the tools' tests"
    grep -q "^$later " "$work/ws/rt/layers.txt" && fail start_writes "layers.txt lists $later"
    # No line a later chapter marks is left, in any file of the workspace (a marker is in a //
    # comment; a Catch2 tag "[ch06]" in a string is none).
    local marked
    marked=$(grep -rHoE --include='*.h' --include='*.cpp' "//.*\[ch[0-9][0-9]( begin| end)?\]" \
        "$work/ws/rt" "$work/ws/chapters" \
        "$work/ws/tests" | awk -v n="$((10#$n))" '{
            match($0, /\[ch[0-9][0-9]( begin| end)?\]$/)
            if (substr($0, RSTART + 3, 2) + 0 > n) { print; exit }
        }')
    [ -n "$marked" ] && fail start_writes "a later chapter's marked line: $marked"
    # The workspace's own layering holds.
    "$work/ws/tools/check-layers" --root "$work/ws" >/dev/null 2>"$work/err" ||
        fail start_writes "check-layers in the workspace: $(cat "$work/err")"
    return 0
}

case_start_stubs_every_exercise() {
    start start_stubs_every_exercise || return
    local count stubs
    count=$("$tool" list "$chapter" | sed -n 's/^ch[0-9][0-9] .*: \([0-9]*\) exercises$/\1/p')
    stubs=$(grep -rh 'rt::not_implemented_yet("' "$work/ws/rt" "$work/ws/chapters" | wc -l)
    [ "$stubs" -eq "$count" ] || fail start_stubs "$stubs stubs for $count exercises"
    grep -rqF "rt::not_implemented_yet(\"$first_exercise\", \"chapter ${chapter#ch} README step 1\")" \
        "$work/ws/rt" || fail start_stubs "no stub naming $first_exercise and step 1"
    # Earlier chapters keep their code: the workspace's chapter 01 files equal the checkout's.
    cmp -s "$repo/rt/core/vec3.h" "$work/ws/rt/core/vec3.h" || fail start_stubs "vec3.h differs"
    return 0
}

case_restore_gives_the_solution_back() {
    start restore_gives_the_solution_back || return
    "$tool" restore "$work/ws" >"$work/out" 2>"$work/err" ||
        { fail restore "restore failed: $(cat "$work/err")"; return; }
    grep -rq 'not_implemented_yet("' "$work/ws/rt" "$work/ws/chapters" &&
        fail restore "a stub is left"
    # The stubbed files are now the checkout's as chapter NN sees them: for a file without
    # later chapters' lines, the checkout's file itself.
    local file
    for file in $("$tool" list "$chapter" | sed -n 's/^  step [0-9]*: .*(\(.*\))$/\1/p' |
        tr ',' '\n' | sort -u); do
        grep -qE "\[ch[0-9][0-9]( begin| end)?\]" "$repo/$file" && continue
        cmp -s "$repo/$file" "$work/ws/$file" || fail restore "$file differs from the checkout's"
    done
    return 0
}

case_solution_prints_the_code() {
    "$tool" solution "$chapter" "$first_exercise" >"$work/out" 2>"$work/err" ||
        { fail solution "failed: $(cat "$work/err")"; return; }
    local where file line
    where=$(head -1 "$work/out" | sed -n 's|^// \([^:]*\):\([0-9]*\): .*|\1 \2|p')
    read -r file line <<<"$where"
    [ -n "$file" ] || { fail solution "no header line: $(head -1 "$work/out")"; return; }
    # The second line printed is the first line of the solution in the real file.
    [ "$(sed -n 2p "$work/out")" = "$(sed -n "${line}p" "$repo/$file")" ] ||
        fail solution "prints '$(sed -n 2p "$work/out")', the file has '$(sed -n "${line}p" "$repo/$file")'"
    return 0
}

case_refuses_unknown_chapter() {
    expect_refusal refuses_unknown_chapter "unknown chapter 'ch99'" start ch99 "$work/nothing"
    [ -e "$work/nothing" ] && fail refuses_unknown_chapter "wrote $work/nothing"
    expect_refusal refuses_unknown_chapter "unknown chapter 'five'" solution five
}

case_refuses_chapter_without_exercises() {
    local none
    none=$(cd "$repo/chapters" && for d in ch[0-9][0-9]_*; do echo "${d:0:4}"; done |
        grep -vxF -f <("$tool" list | sed -n 's/^\(ch[0-9][0-9]\) .*/\1/p') | head -1)
    [ -n "$none" ] || return 0
    expect_refusal refuses_chapter_without_exercises "$none has no exercises" start "$none" \
        "$work/nothing"
    [ -e "$work/nothing" ] && fail refuses_chapter_without_exercises "wrote $work/nothing"
    return 0
}

case_refuses_folder_that_is_no_workspace() {
    mkdir -p "$work/mine" && echo "my notes" >"$work/mine/notes.txt"
    expect_refusal refuses_folder "is not an empty folder or a workspace" start "$chapter" \
        "$work/mine"
    [ "$(ls "$work/mine")" = notes.txt ] || fail refuses_folder "the folder changed"
    expect_refusal refuses_folder "is not an exercise workspace" check "$work/mine"
    expect_refusal refuses_folder "is not an exercise workspace" restore "$work/mine"
    [ "$(cat "$work/mine/notes.txt")" = "my notes" ] || fail refuses_folder "notes changed"
    return 0
}

case_refuses_to_start_over_a_workspace() {
    start refuses_to_start_over_a_workspace || return
    echo "// my code" >>"$work/ws/WORKSPACE.md"
    expect_refusal refuses_start_over "is already an exercise workspace ($chapter)" start \
        "$chapter" "$work/ws"
    tail -1 "$work/ws/WORKSPACE.md" | grep -qF "// my code" || fail refuses_start_over "overwrote"
    return 0
}

case_refuses_workspace_of_another_version() {
    start refuses_workspace_of_another_version || return
    sed -i 's/"version": "[0-9a-f]*"/"version": "0123456789abcdef"/' \
        "$work/ws/.exercise/workspace.json"
    cp -r "$work/ws" "$work/before"
    expect_refusal refuses_other_version "was written from another version" check "$work/ws"
    expect_refusal refuses_other_version "was written from another version" restore "$work/ws"
    diff -r "$work/before" "$work/ws" >/dev/null || fail refuses_other_version "changed files"
    return 0
}

case_refuses_unknown_exercise() {
    start refuses_unknown_exercise || return
    expect_refusal refuses_unknown_exercise "'no_such' is no exercise" restore "$work/ws" no_such
    expect_refusal refuses_unknown_exercise "'no_such' is no exercise or file" solution \
        "$chapter" no_such
}

case_refuses_no_verify_workers() {
    expect_refusal refuses_no_verify_workers "--workers must be at least 1, got 0" verify \
        --workers 0 "$chapter"
}

# tools/exercise verify's order: each worker a run of consecutive chapters (neighbours share
# most of their objects), every chapter exactly once, and a worker whose run is done taking the
# later half of the longest other run, never a chapter another worker has taken.
case_verify_keeps_neighbouring_chapters_together() {
    local out
    out=$(/usr/bin/python3 - "$tool" <<'PYTHON' 2>&1
import importlib.machinery, importlib.util, sys
loader = importlib.machinery.SourceFileLoader("exercise", sys.argv[1])
spec = importlib.util.spec_from_loader("exercise", loader)
tool = importlib.util.module_from_spec(spec)
loader.exec_module(tool)
tags = [f"ch{n:02d}" for n in range(1, 20) if n != 13]
runs = tool.schedule(tags, 2)
print([list(r) for r in runs] == [tags[:9], tags[9:]], "two runs")
runs = tool.schedule(tags[:5], 3)
print([list(r) for r in runs] == [tags[:2], tags[2:4], tags[4:5]], "three uneven runs")
runs = tool.schedule(tags, 2)
mine = [tool.next_chapter(runs, 0) for _ in range(9)]
theirs = [tool.next_chapter(runs, 1) for _ in range(3)]
mine += [tool.next_chapter(runs, 0) for _ in range(3)]
print(mine == tags[:9] + tags[15:18] and theirs == tags[9:12],
      "own run, then the later half of the other's rest")
theirs += [tool.next_chapter(runs, 1) for _ in range(3)]
print(theirs == tags[9:15] and tool.next_chapter(runs, 1) is None
      and tool.next_chapter(runs, 0) is None, "every chapter once")
PYTHON
)
    grep -q "^False" <<<"$out" && fail verify_keeps_neighbouring_chapters_together "$out"
    [ "$(grep -c "^True" <<<"$out")" -eq 4 ] ||
        fail verify_keeps_neighbouring_chapters_together "expected 4 True lines: $out"
    return 0
}

cases=("$@")
[ ${#cases[@]} -eq 0 ] && mapfile -t cases < <(declare -F | awk '{print $3}' | sed -n 's/^case_//p')
for case in "${cases[@]}"; do
    declare -F "case_$case" >/dev/null || { fail "$case" "no such case"; continue; }
    rm -rf "$work/ws" "$work/before" "$work/mine" "$work/nothing"
    before=$failures
    "case_$case"
    [ "$failures" -eq "$before" ] && echo "ok $case"
done
[ "$failures" -eq 0 ]
