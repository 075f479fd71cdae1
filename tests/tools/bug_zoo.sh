#!/usr/bin/env bash
# tools/bug-zoo without building anything: the real zoo's mistakes all still apply to the code,
# with at least three for every chapter that adds library code; and, in a tiny fixture
# repository built afresh for every case, each kind of bad mistake or bad name is refused with
# one line and exit code 2.
#   tests/tools/bug_zoo.sh [CASE...]     (no CASE: all of them; names below, case_*)
# Prints "ok CASE" or "FAIL CASE: why" per assertion; exit code 1 on any failure.
set -uo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
    echo "FAIL $1: $2"
    failures=$((failures + 1))
}

# The fixture: two chapters, a chapter 02 line marked in chapter 01's file, and the real tools.
make_fixture() {
    local fixture=$1
    mkdir -p "$fixture/tools/zoo" "$fixture/rt" "$fixture/chapters/ch01_first" \
        "$fixture/chapters/ch02_second"
    cp "$repo/tools/bug-zoo" "$repo/tools/check-layers" "$fixture/tools/"
    cp -r "$repo/tools/rtlib" "$fixture/tools/"
    printf '%s\n' "ch01 one.h" "ch02 two.h" >"$fixture/rt/layers.txt"
    cat >"$fixture/rt/one.h" <<'CODE'
inline int one() { return 1; }
inline int twice(int x) { return 2 * x; }
inline int later() { return 0; }  // [ch02]
CODE
    cat >"$fixture/rt/two.h" <<'CODE'
inline int two() { return 2; }
CODE
}

# zoo FILE CONTENT: writes tools/zoo/FILE of the fixture.
zoo() {
    printf '%s\n' "$2" >"$fixture/tools/zoo/$1"
}

mistake() {  # a mutant of chapter 01's twice(): name, file, find, replace
    cat <<TOML
[[mutant]]
name = "$1"
mistake = "doubles wrongly"
seen = "a wrong number"
[[mutant.edit]]
file = "$2"
find = "$3"
replace = "$4"
TOML
}

# expect_refusal CASE WANTED ARGS...: exit code 2 and one line on stderr containing WANTED.
expect_refusal() {
    local case=$1 wanted=$2
    shift 2
    "$fixture/tools/bug-zoo" "$@" >"$work/out" 2>"$work/err"
    local status=$?
    [ "$status" -eq 2 ] || fail "$case" "exit code $status, expected 2 ($(cat "$work/err"))"
    [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$case" "expected one line, got: $(cat "$work/err")"
    grep -qF -- "$wanted" "$work/err" || fail "$case" "no '$wanted' in: $(cat "$work/err")"
    [ -s "$work/out" ] && fail "$case" "printed on stdout: $(cat "$work/out")"
    return 0
}

case_real_zoo_applies() {
    local listed
    listed=$("$repo/tools/bug-zoo" --list) || { fail real_zoo_applies "--list failed"; return; }
    # Every chapter with files in rt/layers.txt has at least three mistakes.
    local chapter count
    for chapter in $(awk '/^ch[0-9][0-9] / {print $1}' "$repo/rt/layers.txt" | sort -u); do
        count=$(grep -c "^$chapter " <<<"$listed")
        [ "$count" -ge 3 ] || fail real_zoo_applies "$chapter has $count mistakes, fewer than 3"
    done
    "$repo/tools/bug-zoo" --show "$(head -1 <<<"$listed" | awk '{print $2}')" |
        grep -q '^+++ b/' || fail real_zoo_applies "--show printed no diff"
}

case_fixture_lists() {
    zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;')"
    "$fixture/tools/bug-zoo" --list >"$work/out" 2>"$work/err" ||
        fail fixture_lists "exit $?: $(cat "$work/err")"
    grep -q "^ch01  twice-plus " "$work/out" || fail fixture_lists "not listed: $(cat "$work/out")"
}

case_refuses_unknown_name() {
    zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;')"
    expect_refusal refuses_unknown_name "no mistake or chapter named 'tw1ce'" --list tw1ce
    expect_refusal refuses_unknown_name "no chapter 'ch07'" --check ch07
}

case_refuses_text_not_found() {
    zoo ch01.toml "$(mistake gone rt/one.h 'return 3 * x;' 'return 2 + x;')"
    expect_refusal refuses_text_not_found "occurs 0 times in rt/one.h" --list
}

case_refuses_text_found_twice() {
    zoo ch01.toml "$(mistake thrice-found rt/one.h 'inline int' 'int')"
    expect_refusal refuses_text_found_twice "occurs 3 times" --list
}

case_refuses_line_of_other_chapter() {
    # The marked line is chapter 02's: a chapter 01 mistake may not change it.
    zoo ch01.toml "$(mistake marked rt/one.h 'return 0; }  // [ch02]' 'return 9; }  // [ch02]')"
    expect_refusal refuses_line_of_other_chapter "changes lines of ch02 in rt/one.h:3" --list
}

case_refuses_tests_edit() {
    zoo ch01.toml "$(mistake in-tests tests/ch01/test_one.cpp 'a' 'b')"
    expect_refusal refuses_tests_edit "is not under rt/ or chapters/" --list
}

case_refuses_unknown_key() {
    zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;' |
        sed 's/^seen = .*/&\ncolour = "red"/')"
    expect_refusal refuses_unknown_key "unknown key 'colour'" --list
    zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;')
colour = \"red\""
    expect_refusal refuses_unknown_key "an edit has exactly the keys file, find, replace" --list
}

case_refuses_bad_options() {
    local option
    for option in '"--medium-light along-rays"' '"--scene", "final"' '"; rm -rf /"' '1'; do
        zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;' |
            sed "s|^seen = .*|&\noptions = [$option]|")"
        expect_refusal refuses_bad_options "'options' must be a list of the chapter's" --list
    done
    # A flag and its value, each an item: listed.
    zoo ch01.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;' |
        sed 's|^seen = .*|&\noptions = ["--medium-light", "along-rays"]|')"
    "$fixture/tools/bug-zoo" --list >"$work/out" 2>"$work/err" ||
        fail refuses_bad_options "good options refused: $(cat "$work/err")"
}

case_refuses_duplicate_name() {
    zoo ch01.toml "$(mistake same rt/one.h 'return 2 * x;' 'return 2 + x;')"
    zoo ch02.toml "$(mistake same rt/two.h 'return 2;' 'return 3;')"
    expect_refusal refuses_duplicate_name "name 'same' is taken" --list
}

case_refuses_bad_file_name() {
    zoo chapter1.toml "$(mistake twice-plus rt/one.h 'return 2 * x;' 'return 2 + x;')"
    expect_refusal refuses_bad_file_name "a zoo file is named for a chapter" --list
}

cases=("$@")
[ ${#cases[@]} -eq 0 ] && mapfile -t cases < <(declare -F | awk '{print $3}' | sed -n 's/^case_//p')
for case in "${cases[@]}"; do
    declare -F "case_$case" >/dev/null || { fail "$case" "no such case"; continue; }
    fixture="$work/$case"
    make_fixture "$fixture"
    before=$failures
    "case_$case"
    [ "$failures" -eq "$before" ] && echo "ok $case"
done
[ "$failures" -eq 0 ]
