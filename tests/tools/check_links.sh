#!/usr/bin/env bash
# tools/check-links on a tiny fixture repository, built afresh in a temp dir for every case: its
# good links pass, and each kind of broken link is caught, one line naming the file and line.
#   tests/tools/check_links.sh [CASE...]     (no CASE: all of them; names below, case_*)
# Prints "ok CASE" or "FAIL CASE: why" per assertion; exit code 1 on any failure.
set -uo pipefail
tools=$(cd "$(dirname "$0")/../../tools" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# The fixture: README.md links a page, a heading of it, a folder, an image, a heading of its own
# (a setext one) and a repeated heading; reached by a reference definition and wrapped over two
# lines too. Its traps: web and mail links, links in code spans, in a fenced block and in an
# HTML comment, all to files that do not exist.
make_fixture() {
    local repo=$1
    mkdir -p "$repo/docs"
    cat >"$repo/README.md" <<'EOF'
Top
===

See [the guide](docs/guide.md), its [odd heading](docs/guide.md#step-2-the-cameras-lens--aperture),
[the second "Notes"](docs/guide.md#notes-1), [the folder](docs/), [the top](#top) and
![a picture](docs/picture.png); the guide [by reference][guide], and [a link whose text
wraps](docs/guide.md#notes).

[guide]: docs/guide.md

Elsewhere: [a site](https://example.org/nowhere.md), [mail](mailto:someone@example.org).
Not links: `[in code](nowhere.md)` and <!-- [in a comment](nowhere.md) -->.

```
[in a fenced block](nowhere.md)
```
EOF
    cat >"$repo/docs/guide.md" <<'EOF'
# The guide

## Step 2: the camera's *lens* & `aperture`

## Notes

## Notes

Back to [the top](../README.md#top).
EOF
    printf '\x89PNG\r\n\x1a\n' >"$repo/docs/picture.png"
    git -C "$repo" init -q && git -C "$repo" add . || fail "cannot make the fixture repository"
}

fail() { echo "FAIL $case: $*"; failures=$((failures + 1)); }

# run: check-links on the fixture, leaving its exit code in $rc, stdout in $out, stderr in $err.
run() {
    "$tools/check-links" --root "$repo" >"$work/out" 2>"$work/err"
    rc=$?
    out=$(cat "$work/out") err=$(cat "$work/err")
}

# broken WHAT LINE: check-links must exit 1 with exactly this one line on stderr. The fixture
# was changed just before.
broken() {
    run
    if [ "$rc" -ne 1 ]; then fail "$1: exit code $rc, not 1; stderr: $err"
    elif [ "$err" != "$2" ]; then fail "$1: stderr is not '$2' but: $err"
    else echo "ok $case: $1 -> $err"; fi
}

case_passes_good_fixture() {
    run
    if [ "$rc" -ne 0 ] || [ -n "$err" ]; then fail "good fixture: exit code $rc; stderr: $err"
    elif [ "$out" != "check-links: 2 Markdown files, 9 links: all resolve" ]; then
        fail "good fixture: unexpected summary '$out'"
    else echo "ok $case: $out"; fi
}
case_catches_missing_file() {
    echo 'And [a lost page](docs/lost.md).' >>"$repo/README.md"
    broken "missing file" "README.md:17: link 'docs/lost.md' does not resolve (no such file or folder)"
}
case_catches_missing_anchor() {
    echo 'And [a lost step](guide.md#step-3).' >>"$repo/docs/guide.md"
    broken "missing heading" \
        "docs/guide.md:10: link 'guide.md#step-3' does not resolve (no heading or id 'step-3' in docs/guide.md)"
    make_fixture "$repo.2" && repo=$repo.2
    echo 'And [our own lost part](#bottom).' >>"$repo/README.md"
    broken "missing heading of the same file" \
        "README.md:17: link '#bottom' does not resolve (no heading or id 'bottom' in README.md)"
    make_fixture "$repo.3" && repo=$repo.3
    echo 'And [a third Notes](docs/guide.md#notes-2).' >>"$repo/README.md"
    broken "a repeat beyond the last" \
        "README.md:17: link 'docs/guide.md#notes-2' does not resolve (no heading or id 'notes-2' in docs/guide.md)"
}
case_catches_ignored_target() {
    # A file git ignores is in no clone, though it is on this disk.
    mkdir -p "$repo/build" && echo 'built' >"$repo/build/log.md" && echo 'build/' >"$repo/.gitignore"
    echo 'And [the build log](build/log.md).' >>"$repo/README.md"
    broken "ignored file" "README.md:17: link 'build/log.md' does not resolve (no such file or folder)"
}
case_refuses_non_repository() {
    rm -rf "$repo/.git"
    run
    if [ "$rc" -ne 2 ] || [ "$(grep -c . <<<"$err")" -ne 1 ] || [ -n "$out" ]; then
        fail "not a repository: exit code $rc (not 2), stdout '$out', stderr '$err'"
    else echo "ok $case: not a repository -> $err"; fi
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
