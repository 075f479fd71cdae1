#!/usr/bin/python3
"""The render checker against the zoo of classic mistakes: each mistake's image, as a student
with that mistake would write it, must be judged a mismatch and named.

  check_render_zoo.py ZOO_BUILD [--report FILE] [--chapter chNN] [--expect FILE] [--maps DIR]

ZOO_BUILD is a folder that tools/bug-zoo --check filled (zoo.json, and student/NAME.png: each
mistake rendered by the mutated chapter program with seed 2, where the catalogue's image has
seed 1), or tests/checker/zoo, where those images are kept for CI (student/ only: the mistakes
are the catalogue's, report/zoo/catalogue.json; its README says how they are made again). Each
image goes to tools/check-render as our chapter programs make it (sRGB PNG, Schlick's cosine on
the less dense side, textures decoded as sRGB, the catalogue's 64 spp). A mistake is named when
the likely cause is that mistake, or the image-level cause it is (a missing gamma is an encoding
the checker names itself). Prints one line a mistake and the detection rate; --report writes
them as a Markdown table. Exit 1 unless every mistake is either judged a mismatch and named, or
judged a match: some mistakes leave the catalogue's image as it is within noise (a wrong branch
the scene never takes), and a checker that called those a mismatch would be wrong; they are
counted and listed, not hidden.

--expect FILE (tools/check/zoo_verdicts.md) holds each mistake to the verdict written there:
exit 1 also when one it names is judged a match (a checker that called every image a match
would otherwise pass) or one it calls not visible is judged a mismatch. --chapter checks only
that chapter's mistakes; --maps writes the checker's maps there instead of beside the images."""
import argparse
import json
import os
import sys
import tomllib

import checker_in_process

HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SPP = 64  # tools/bug-zoo's CATALOGUE_SPP

# Mistakes that are an image-level cause the checker names in its own words.
IMAGE_LEVEL = {
    "gamma-missing": "gamma missing",
    "gamma-applied-twice": "gamma applied twice",
    "image-upside-down": "upside down",
    "film-height-times-aspect": "not the scene's aspect ratio",
    "sobol-one-scramble-for-every-pixel": "neighbouring pixels share their errors",
}


def scene_of(chapter, flag, scenes):
    for name, entry in scenes.items():
        if [chapter, flag or ""] in entry.get("zoo", []):
            return name
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("zoo_build")
    parser.add_argument("--report")
    parser.add_argument("--renders", type=int,
                        help="our renders that measure the noise (check-render's --renders; "
                        "default: its own, 4 to 32)")
    parser.add_argument("--chapter", help="only this chapter's mistakes (chNN)")
    parser.add_argument("--expect", help="a table of verdicts to hold each mistake to "
                        "(tools/check/zoo_verdicts.md)")
    parser.add_argument("--maps", help="folder for the checker's maps (default: beside the "
                        "images)")
    args = parser.parse_args()
    listed = os.path.join(args.zoo_build, "zoo.json")
    if os.path.exists(listed):
        with open(listed) as f:
            results = json.load(f)
    else:  # tests/checker/zoo: the images only, of the mistakes the catalogue lists
        with open(os.path.join(ROOT, "report", "zoo", "catalogue.json")) as f:
            results = json.load(f)["mistakes"]
    if args.chapter:
        results = [r for r in results if r["chapter"] == args.chapter]
        if not results:
            raise SystemExit(f"check_render_zoo: the zoo has no mistake of {args.chapter}")
    expected = expected_statuses(args.expect) if args.expect else {}
    maps = args.maps or os.path.join(args.zoo_build, "student")
    os.makedirs(maps, exist_ok=True)
    with open(os.path.join(ROOT, "tools", "check", "scenes.toml"), "rb") as f:
        scenes = tomllib.load(f)
    rows, missed, unseen, changed = [], 0, 0, []
    for r in results:
        image = os.path.join(args.zoo_build, "student", r["image"])
        scene = scene_of(r["chapter"], r.get("scene"), scenes)
        if not r["image"].endswith(".png") or not os.path.exists(image) or scene is None:
            rows.append((r["name"], scene or "-", "no image", "-"))
            missed += 1
            continue
        command = [scene, image, "--spp", str(SPP), "--encoding", "srgb", "--fresnel",
                   "schlick", "--texture-decoding", "srgb", "--map",
                   os.path.join(maps, r["name"] + ".check.png")]
        if args.renders:
            command += ["--renders", str(args.renders)]
        if scenes[scene].get("texture"):
            command += ["--texture", os.path.join(ROOT, "assets", "globe.png")]
        code, out, err = checker_in_process.run(command)
        causes = [line.strip() for line in out.splitlines()
                  if line.startswith("likely cause") or line.startswith("  or:")]
        said = " ".join(causes) + err
        named = (code in (1, 2) and f"'{r['name']}'" in said
                 or IMAGE_LEVEL.get(r["name"], "\0") in said)
        verdict = {0: "judged a match", 1: "mismatch", 2: "trouble"}.get(code, "crash")
        # A mistake whose image is its correct image within noise cannot be seen in an image:
        # the checker is right to call it a match. Counted apart, never hidden.
        invisible = code == 0
        status = "named" if named else ("not visible in the image" if invisible else "MISSED")
        rows.append((r["name"], scene, verdict, status if named or invisible else
                     (causes[0] if causes else err.strip())))
        missed += not (named or invisible)
        unseen += invisible
        want = expected.get(r["name"]) if args.expect else None
        if args.expect and want != status:
            changed.append(f"{r['name']}: {status}, where {args.expect} says "
                           f"{want or 'nothing'}")
        print(f"{'ok' if named or invisible else 'MISSED'}: {r['chapter']} {r['name']} "
              f"({scene}): {verdict}; {(causes[0] if causes else err.strip())}")
    named_count = len(rows) - missed - unseen
    print(f"check-render: of {len(rows)} mistakes of the zoo, {named_count} judged a mismatch "
          f"and named, {unseen} not visible in their image (judged a match), {missed} missed")
    if args.report:
        with open(args.report, "w") as f:
            f.write("| mistake | scene | verdict | named |\n|---|---|---|---|\n")
            for row in rows:
                f.write("| " + " | ".join(str(c).replace("|", "\\|") for c in row) + " |\n")
    for line in changed:
        print(f"NOT AS EXPECTED: {line}")
    return 1 if missed or changed else 0


def expected_statuses(table):
    """Each mistake's status ("named" or "not visible in the image") in a Markdown table of
    --report's columns."""
    statuses = {}
    with open(table, encoding="utf-8") as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) == 4 and cells[3] in ("named", "not visible in the image"):
                statuses[cells[0]] = cells[3]
    if not statuses:
        raise SystemExit(f"check_render_zoo: {table} has no table of verdicts")
    return statuses


if __name__ == "__main__":
    sys.exit(main())
