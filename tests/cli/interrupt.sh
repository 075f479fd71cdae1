#!/usr/bin/env bash
# SIGINT and SIGTERM at any moment of a run leave the old output files as they were and no
# temporary file, and end the program with exit code 130 (SIGINT) or 143 (SIGTERM):
#   interrupt.sh CHAPTER_EXE          (a fast scene: chapter 01's sky)
# Moments: during the render (a long one, before any file is opened), and during the write of a
# large .pfm (once its temporary file holds some bytes) and of a large .png (once its temporary
# file exists: stb compresses the whole image, then writes it at once); and with several outputs
# (rt/files/output_set.h: all or none), during the write of the second, when the first is complete
# in its temporary file.
set -uo pipefail
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir out
failures=0

# The old outputs: real images of another size, so a replaced file would show.
"$exe" --quiet --width 16 --spp 1 --out out/old.png --out out/old.pfm --stats-out out/old.json ||
    exit 1

# interrupt SIGNAL MOMENT WATCHED ARGS...: renders ARGS (naming outputs among out/old.*), sends
# SIGNAL at MOMENT (render, or write: the write of out/WATCHED), and checks the exit code, the old
# files and the folder.
interrupt() {
    local signal=$1 moment=$2 watched=$3
    shift 3
    local label="SIG$signal during the $moment${watched:+ of $watched} ($*)"
    local before
    before=$(cksum out/old.png out/old.pfm out/old.json)
    # A background job of a script starts with SIGINT ignored; a user's Ctrl-C reaches a program
    # that has it at its default, so start it that way.
    env --default-signal=INT,TERM "$exe" --quiet "$@" 2>stderr.txt &
    local pid=$!
    local seen="" waited=0
    # Wait for the moment: the temporary files (out/NAME.tmp.PID.N) in the right state.
    while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt 3000 ]; do
        local tmp
        case $moment in
        render)
            if [ "$waited" -ge 50 ]; then
                seen="render"
                compgen -G "out/*.tmp.$pid.*" >/dev/null && seen="tmp"
            fi
            ;;
        write)
            for tmp in out/"$watched".tmp."$pid".*; do
                [ -s "$tmp" ] || { [ "${watched##*.}" = png ] && [ -e "$tmp" ]; } && seen="write"
            done
            ;;
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
    [ "$(cksum out/old.png out/old.pfm out/old.json)" = "$before" ] ||
        problem+=" an old file was changed;"
    local left
    left=$(ls -A out | grep -vxE 'old.png|old.pfm|old.json')
    [ -z "$left" ] || problem+=" left files: $(echo $left);"
    if [ -n "$problem" ]; then
        echo "FAIL [$label]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
        rm -f out/*.tmp.*
    else
        echo "ok   [$label] -> exit code $rc, old files kept"
    fi
}

# interrupt_second_write SIGNAL: the moment made certain. The second output's temporary file is
# made a FIFO before the run starts (named with the PID the program will have: the subshell's,
# kept through exec), and the test reads a few bytes from it: the first output is then complete in
# its temporary file and the program is in the middle of writing the second (blocked once the
# pipe is full: it cannot reach the renames). SIGNAL then must leave both old images and the old
# record, and no temporary file.
interrupt_second_write() {
    local signal=$1
    local label="SIG$signal in the middle of the second of two outputs"
    local before
    before=$(cksum out/old.png out/old.pfm out/old.json)
    (mkfifo "out/old.pfm.tmp.$BASHPID.1" &&
        exec env --default-signal=INT,TERM "$exe" --quiet --width 400 --spp 1 \
            --out out/old.png --out out/old.pfm --stats-out out/old.json) 2>stderr.txt &
    local pid=$!
    local fifo=out/old.pfm.tmp.$pid.1 problem=""
    local waited=0
    while [ ! -p "$fifo" ] && [ "$waited" -lt 500 ]; do
        sleep 0.01
        waited=$((waited + 1))
    done
    # Read and write (so opening does not wait for the program, and the program never sees the
    # reader go): the program's bytes come through it.
    exec 3<>"$fifo"
    local got
    got=$(timeout 30 head -c 16 <&3 | wc -c)
    [ "$got" -eq 16 ] || problem+=" the second output was not being written (read $got bytes);"
    [ -s "out/old.png.tmp.$pid.0" ] || problem+=" the first output was not complete beside old.png;"
    kill -s "$signal" "$pid" 2>/dev/null
    wait "$pid"
    local rc=$?
    exec 3<&-
    local want=130
    [ "$signal" = TERM ] && want=143
    [ "$rc" -eq "$want" ] || problem+=" exit code $rc, not $want;"
    [ "$(cksum out/old.png out/old.pfm out/old.json)" = "$before" ] ||
        problem+=" an old file was changed;"
    local left
    left=$(ls -A out | grep -vxE 'old.png|old.pfm|old.json')
    [ -z "$left" ] || problem+=" left files: $(echo $left);"
    if [ -n "$problem" ]; then
        echo "FAIL [$label]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
        rm -f out/*.tmp.*
    else
        echo "ok   [$label] -> exit code $rc, old files kept"
    fi
}

for signal in INT TERM; do
    # About 30 s of rendering if nothing stops it; the signal comes after 0.5 s.
    interrupt "$signal" render "" --width 1000 --spp 400 --out out/old.png
    # 2400 x 1350: a 39 MB PFM and a 10 MB PNG, each some tenths of a second of writing.
    interrupt "$signal" write old.pfm --width 2400 --spp 1 --out out/old.pfm
    interrupt "$signal" write old.png --width 2400 --spp 1 --out out/old.png
    # Two outputs and the record: the first complete in its temporary file, the second being
    # written, the record not begun. Both old images and the old record stay.
    interrupt "$signal" write old.pfm --width 2400 --spp 1 --out out/old.png --out out/old.pfm \
        --stats-out out/old.json
    interrupt_second_write "$signal"
done

[ "$failures" -eq 0 ] || { echo "$failures interrupted runs left the wrong files"; exit 1; }
echo "every interrupted run kept the old files and left nothing else"
