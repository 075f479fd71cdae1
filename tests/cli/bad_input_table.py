#!/usr/bin/env python3
"""Runs every row of the README's table "Bad input and what it gets", so the table cannot drift
from what the programs do.

usage: bad_input_table.py README.md BIN_DIR [--chapter chNN] [--list]

Each row's command runs in a fresh folder holding the test files the README lists (made here),
with its program taken from BIN_DIR. A row passes when the exit code is the table's; stdout is
empty; stderr is empty for "(nothing)", else exactly one line "<program>: error: ..." holding
the table's message; and the folder is exactly as before (same files, same bytes: nothing
created, nothing changed, no temporary file left). A command
"PROGRAM ARGS & sleep S; kill -SIG $!" starts the program, sends SIG after S seconds and expects
it to die of it (exit code 128 + SIG, as a shell reports it). --chapter runs only the rows of
that chapter's program; --list prints the rows. Exit code 0 when every row passes, 1 otherwise.
"""
import argparse
import filecmp
import os
import re
import shlex
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "tools"))
from rtlib import pfm  # noqa: E402  (tools/rtlib: the tools' PFM writer)

SECTION = "## Bad input and what it gets"
INTERRUPT = re.compile(
    r"^(?P<command>.+?) & sleep (?P<seconds>[0-9.]+); kill -(?P<signal>[A-Z]+) \$!$")
ROW_TIMEOUT = 60  # seconds; a refusal takes well under one


def read_rows(readme):
    """The table's rows as dicts (line, input, command, exit, message); message None = nothing."""
    with open(readme, encoding="utf-8") as f:
        lines = f.read().splitlines()
    try:
        start = lines.index(SECTION)
    except ValueError:
        sys.exit(f"{readme}: no section '{SECTION}'")
    rows = []
    in_table = False
    for number, line in enumerate(lines[start + 1:], start + 2):
        if line.startswith("## "):
            break
        if not line.startswith("|"):
            if in_table:
                break
            continue
        in_table = True
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if cells[0] == "bad input" or set(line) <= set("|-"):
            continue  # the header and its rule
        if len(cells) != 4:
            sys.exit(f"{readme}:{number}: a row needs 4 cells, got {len(cells)}: {line}")
        command = re.fullmatch(r"`(.+)`", cells[1])
        message = re.fullmatch(r"`(.+)`", cells[3])
        if not command or not cells[2].isdigit() or not (message or cells[3] == "(nothing)"):
            sys.exit(f"{readme}:{number}: expected | input | `command` | exit code | `message` or "
                     f"(nothing) |, got: {line}")
        rows.append({"line": number, "input": cells[0], "command": command.group(1),
                     "exit": int(cells[2]), "message": message.group(1) if message else None})
    if not rows:
        sys.exit(f"{readme}: the section '{SECTION}' has no table rows")
    return rows


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png(width, height, compressed=None):
    """An 8-bit RGB PNG: its header, the IDAT chunk (if any) and the end chunk."""
    header = png_chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    data = png_chunk(b"IDAT", compressed) if compressed is not None else b""
    return b"\x89PNG\r\n\x1a\n" + header + data + png_chunk(b"IEND", b"")


def zeros_deflated(mebibytes):
    """A zlib stream of `mebibytes` MiB of zeros, made in a moment: one compressed MiB, ended by a
    full flush (which empties the compressor's window, so the next MiB compresses to the same
    bytes), repeated; then the end of the stream with the checksum of the whole."""
    zeros, z = bytes(1 << 20), zlib.compressobj(9)
    first = z.compress(zeros) + z.flush(zlib.Z_FULL_FLUSH)  # with the 2-byte zlib header
    again = z.compress(zeros) + z.flush(zlib.Z_FULL_FLUSH)
    end = z.flush()  # an empty last block, then the Adler-32 of what z saw (4 bytes)
    checksum = 1
    for _ in range(mebibytes):
        checksum = zlib.adler32(zeros, checksum)
    return first + again * (mebibytes - 1) + end[:-4] + struct.pack(">I", checksum)


def make_files(folder, with_bomb):
    """The test files the README lists, in folder (bomb.png, the slow one, only if asked)."""
    # old.png: 16 x 8 texels of a gradient, each row a filter byte (0: none) and its RGB bytes.
    rows = b"".join(b"\x00" + bytes((x * 13 + y * 29 + c * 71) % 256 for x in range(16)
                                    for c in range(3)) for y in range(8))
    old_png = png(16, 8, zlib.compress(rows))
    files = {
        "old.png": old_png,
        "old.pfm": pfm.encode(pfm.Image(2, 1, 3, [0.25, 0.5, 1, 2, 4, 8])),
        "empty.png": b"",
        "half.png": old_png[:len(old_png) // 2],
        "notes.png": b"These are not the pixels you are looking for.\n",
        "huge.png": png(100000, 100000),
        # OBJ models (chapter 18): an index past the vertices, UTF-16 text, points only, and a
        # triangle of zero area.
        "bad_index.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
        "utf16.obj": "v 0 0 0\n".encode("utf-16"),
        "points.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n",
        "flat.obj": b"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
        # Scene files (chapter 19): a misspelt key, named objects in a cycle, a texture file that
        # is missing, a later format, and a file that is not TOML.
        "misspelt.toml": b'format = 1\n[world]\nobjects = [{ type = "sphere", center = [0, 0, 0], '
                         b'raduis = 1 }]\n',
        "cycle.toml": b'format = 1\n[named_objects.a]\nuse = "b"\n[named_objects.b]\nuse = "a"\n'
                      b'[world]\nobjects = ["a"]\n',
        "no_texture.toml": b'format = 1\n[textures]\nmap = { type = "image", file = "maps/earth.png" }\n',
        "later.toml": b"format = 2\n",
        "not_toml.toml": b"<scene><sphere/></scene>\n",
    }
    if with_bomb:  # 256 MiB of zeros in about 256 KiB, where a 1 x 1 image needs 4 bytes
        files["bomb.png"] = png(1, 1, zeros_deflated(256))
    for name, data in files.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    for name in ("dir.png", "dir.json"):
        os.mkdir(os.path.join(folder, name))


def differences(before, after):
    """What changed from folder `before` to folder `after`: created, removed or changed files."""
    found = []
    compare = filecmp.dircmp(before, after, ignore=[])

    def walk(c, prefix):
        found.extend(f"removed {prefix}{n}" for n in c.left_only)
        found.extend(f"created {prefix}{n}" for n in c.right_only)
        found.extend(f"changed {prefix}{n}" for n in c.diff_files + c.funny_files)
        for name, sub in c.subdirs.items():
            walk(sub, prefix + name + "/")

    walk(compare, "")
    # dircmp compares by size and time first; compare every common file's bytes as well.
    for dirpath, _, names in os.walk(before):
        for name in names:
            a = os.path.join(dirpath, name)
            b = os.path.join(after, os.path.relpath(a, before))
            if os.path.isfile(b) and not filecmp.cmp(a, b, shallow=False):
                found.append(f"changed {os.path.relpath(a, before)}")
    return sorted(set(found))


def run_row(row, bin_dir, files):
    """Runs one row in a copy of `files`; returns what went wrong (a list) and the stderr."""
    problems = []
    interrupt = INTERRUPT.match(row["command"])
    words = shlex.split(interrupt.group("command") if interrupt else row["command"])
    program = words[0]
    words[0] = os.path.join(bin_dir, program)
    if not os.access(words[0], os.X_OK):
        return [f"no program {words[0]}"], ""
    with tempfile.TemporaryDirectory() as work:
        folder = os.path.join(work, "run")
        shutil.copytree(files, folder, symlinks=True)
        out_path, err_path = os.path.join(work, "stdout"), os.path.join(work, "stderr")
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            process = subprocess.Popen(words, cwd=folder, stdin=subprocess.DEVNULL, stdout=out,
                                       stderr=err)
            try:
                if interrupt:
                    time.sleep(float(interrupt.group("seconds")))
                    if process.poll() is not None:
                        problems.append("the program had ended before the signal")
                    else:
                        process.send_signal(getattr(signal, "SIG" + interrupt.group("signal")))
                process.wait(timeout=ROW_TIMEOUT)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
                problems.append(f"still running after {ROW_TIMEOUT} s")
        # A shell reports a death by signal N as 128 + N; Popen as -N.
        code = process.returncode if process.returncode >= 0 else 128 - process.returncode
        with open(out_path, "rb") as f:
            stdout = f.read().decode(errors="replace")
        with open(err_path, "rb") as f:
            stderr = f.read().decode(errors="replace")
        if code != row["exit"]:
            problems.append(f"exit code {code}, not {row['exit']}")
        if stdout:
            problems.append(f"stdout is not empty: {stdout[:200]!r}")
        if row["message"] is None:
            if stderr:
                problems.append(f"stderr is not empty: {stderr[:200]!r}")
        else:
            prefix = f"{program}: error: "
            if stderr.count("\n") != 1 or not stderr.endswith("\n"):
                problems.append(f"stderr is not exactly one line: {stderr[:400]!r}")
            if not stderr.startswith(prefix):
                problems.append(f"stderr does not start with '{prefix}'")
            if row["message"] not in stderr:
                problems.append(f"stderr does not hold '{row['message']}'")
        problems.extend(differences(files, folder))
        return problems, stderr.rstrip("\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("readme")
    parser.add_argument("bin_dir", help="the folder of the chapter programs")
    parser.add_argument("--chapter", help="only the rows of this chapter's program (chNN)")
    parser.add_argument("--list", action="store_true", help="print the rows, run none")
    args = parser.parse_args()

    args.bin_dir = os.path.abspath(args.bin_dir)
    rows = read_rows(args.readme)
    if args.chapter:
        rows = [r for r in rows if r["command"].startswith(args.chapter + "_")]
        if not rows:
            sys.exit(f"{args.readme}: no row runs a program of {args.chapter}")
    if args.list:
        for r in rows:
            print(f"{r['line']}: {r['command']}  -> {r['exit']}, {r['message']}")
        return 0

    failures = 0
    with tempfile.TemporaryDirectory() as files:
        make_files(files, with_bomb=any("bomb.png" in row["command"] for row in rows))
        for row in rows:
            started = time.monotonic()
            problems, stderr = run_row(row, args.bin_dir, files)
            took = time.monotonic() - started
            if problems:
                failures += 1
                print(f"FAIL {args.readme}:{row['line']} [{row['command']}]: "
                      f"{'; '.join(problems)}")
                print(f"     stderr: {stderr}")
            else:
                print(f"ok   [{row['command']}] ({took:.2f} s) -> {stderr or '(nothing)'}")
    print(f"{len(rows) - failures} of {len(rows)} rows hold")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
