#!/usr/bin/python3
"""What a teacher does with chapter 19, end to end: copies the Cornell box's scene file
(assets/scenes/book/ch11.toml), changes the left wall's colour (green to blue) and the tall box's
rotation (15 degrees to -25), renders it with one command, and gets the image: the wall blue,
the box turned; the unchanged file renders the green wall and the box as the book has it.

usage: teacher_edit.py PROGRAM BOOK_CH11_TOML"""
import os
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from rtlib import pfm  # noqa: E402

program, book = sys.argv[1], sys.argv[2]
with open(book, encoding="utf-8") as f:
    text = f.read()
green, blue = "albedo = [0.12, 0.45, 0.15]", "albedo = [0.1, 0.2, 0.6]"
turn, turned = 'rotate = "y", degrees = 15 }', 'rotate = "y", degrees = -25 }'
for old in (green, turn):
    if text.count(old) != 1:
        sys.exit(f"teacher_edit: {book} no longer holds '{old}' once: update this test")
mine = text.replace(green, blue).replace(turn, turned)


def render(folder, name, scene_text, *flags):
    path = os.path.join(folder, name + ".toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(scene_text)
    out = os.path.join(folder, name + ".pfm")
    subprocess.run([program, "--scene-file", path, "--width", "64", "--spp", "16", "--quiet",
                    "--out", out, "--out", os.path.join(folder, name + ".png"), *flags],
                   check=True)
    if not os.path.getsize(os.path.join(folder, name + ".png")):
        sys.exit(f"teacher_edit: {name}: no PNG written")
    return pfm.as_array(pfm.read(out))


with tempfile.TemporaryDirectory() as folder:
    book_image = render(folder, "book", text)
    my_image = render(folder, "my_box", mine)
    # The geometry alone, by chapter 02's normals: a pixel changes only where the box moved.
    book_normals = render(folder, "book_normals", text, "--integrator", "normals")
    my_normals = render(folder, "my_normals", mine, "--integrator", "normals")
failures = []
# The left wall fills the image's left edge (columns 2-7), the middle rows.
wall = (slice(16, 48), slice(2, 8))
book_wall, my_wall = book_image[wall].mean(axis=(0, 1)), my_image[wall].mean(axis=(0, 1))
if not book_wall[1] > 1.5 * book_wall[2]:
    failures.append(f"the book's left wall is not green: mean RGB {book_wall}")
if not my_wall[2] > 1.5 * my_wall[1]:
    failures.append(f"the edited left wall is not blue: mean RGB {my_wall}")
moved = (abs(my_normals - book_normals).max(axis=2) > 0).sum()
if not moved > 50:
    failures.append(f"turning the tall box changed {moved} pixels of the geometry only")
if (my_normals[:12] != book_normals[:12]).any():
    failures.append("the ceiling's pixels changed, though only the box turned")
for failure in failures:
    print("teacher_edit:", failure, file=sys.stderr)
if failures:
    sys.exit(1)
print(f"teacher_edit: left wall {book_wall.round(3)} -> {my_wall.round(3)}; turning the tall "
      f"box changed {moved} of {64 * 64} pixels of its geometry, none of the ceiling's")
