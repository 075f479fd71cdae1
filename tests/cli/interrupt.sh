#!/usr/bin/env bash
# SIGINT and SIGTERM at any moment of a run leave the old output file as it was and no temporary
# file, and end the program with exit code 130 (SIGINT) or 143 (SIGTERM):
#   interrupt.sh CHAPTER_EXE          (a fast scene: chapter 01's sky)
# Moments: during the render (a long one, before any file is opened), and during the write of a
# large .pfm (once its temporary file holds some bytes) and of a large .png (once its temporary
# file exists: stb compresses the whole image, then writes it at once).
set -uo pipefail
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir out
failures=0

# The old outputs: real images of another size, so a replaced file would show.
"$exe" --quiet --width 16 --spp 1 --out out/old.png --out out/old.pfm || exit 1

# interrupt SIGNAL MOMENT EXT ARGS...: renders ARGS writing over out/old.EXT, sends SIGNAL at
# MOMENT (render | write), and checks the exit code, the old file and the folder.
interrupt() {
    local signal=$1 moment=$2 ext=$3
    shift 3
    local target=out/old.$ext
    local before
    before=$(cksum <"$target")
    # A background job of a script starts with SIGINT ignored; a user's Ctrl-C reaches a program
    # that has it at its default, so start it that way.
    env --default-signal=INT,TERM "$exe" --quiet "$@" --out "$target" 2>stderr.txt &
    local pid=$!
    local seen="" waited=0
    # Wait for the moment: the temporary file (out/old.EXT.tmp.PID) in the right state.
    while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt 3000 ]; do
        local tmp=out/old.$ext.tmp.$pid
        case $moment in
        render) [ "$waited" -ge 50 ] && { [ -e "$tmp" ] && seen="tmp" || seen="render"; } ;;
        write) [ -s "$tmp" ] || { [ "$ext" = png ] && [ -e "$tmp" ]; } && seen="write" ;;
        esac
        [ -n "$seen" ] && break
        sleep 0.01
        waited=$((waited + 1))
    done
    kill -s "$signal" "$pid" 2>/dev/null
    wait "$pid"
    local rc=$?
    local want=130
    [ "$signal" = TERM ] && want=143
    local problem=""
    [ "$seen" = "$moment" ] || problem+=" could not send it during the $moment (saw '$seen');"
    [ "$rc" -eq "$want" ] || problem+=" exit code $rc, not $want;"
    [ "$(cksum <"$target")" = "$before" ] || problem+=" $target was changed;"
    local left
    left=$(ls -A out | grep -vxE 'old.png|old.pfm')
    [ -z "$left" ] || problem+=" left files: $left;"
    if [ -n "$problem" ]; then
        echo "FAIL [SIG$signal during the $moment of .$ext]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
        rm -f out/old.*.tmp.*
    else
        echo "ok   [SIG$signal during the $moment of .$ext] -> exit code $rc, old file kept"
    fi
}

for signal in INT TERM; do
    # About 30 s of rendering if nothing stops it; the signal comes after 0.5 s.
    interrupt "$signal" render png --width 1000 --spp 400
    # 2400 x 1350: a 39 MB PFM and a 10 MB PNG, each some tenths of a second of writing.
    interrupt "$signal" write pfm --width 2400 --spp 1
    interrupt "$signal" write png --width 2400 --spp 1
done

[ "$failures" -eq 0 ] || { echo "$failures interrupted runs left the wrong files"; exit 1; }
echo "every interrupted run kept the old file and left nothing else"
