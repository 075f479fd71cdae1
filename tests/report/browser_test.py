#!/usr/bin/python3
"""The HTML report in a headless Chromium, opened from disk as a reader opens it:

  browser_test.py REPORT_HTML [--compare ID] [--screenshots DIR]

  load        the page loads (load event, then readyState "complete") with no console error,
              no uncaught exception and no failed request
  images      every <img> has loaded (lazy ones made eager first); at least one image and one
              comparison
  links       every a[href] resolves: a fragment names an element of the page, a file link an
              existing file; web links are counted, not followed
  contract    the comparison chosen (--compare ID, else the first figure.compare whose images
              have the same size) has the parts of the report's contract
  flip        modes "a" and "b", clicked with the mouse, show A and B (the handle hidden);
              the two screenshots differ where the image files A and B differ and nowhere else
  drag        mode "slider" shows A left of the split and B right of it; a drag of the split
              from 50 % to 25 % of the view changes the view only between those columns, and
              there wherever A and B differ; the handle follows the split
  zoom        each zoom button scales the view by its factor, image-rendering pixelated
  afterwards  no console error or failed request while the checks operated the page

--screenshots DIR also writes DIR/first-screen.png (the 1280 x 900 viewport on load) and
DIR/comparison.png (the comparison's figure in slider mode, its split dragged to 35 %).

One line per check with what it measured, a FAIL line for each failure, and the total time.
Exit 0 when every check passes, 1 otherwise (a browser that does not start too: one line)."""
import argparse
import io
import math
import os
import pathlib
import sys
import time
import urllib.parse
import urllib.request

import numpy as np
from PIL import Image

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from rtlib import browser  # noqa: E402

VIEWPORT = (1280, 900)
LOAD_TIMEOUT = 60.0   # seconds for the page, its images and its scripts
LEVELS = 2            # of 255: a pixel differs when some channel differs by more than this
SHOWS_LEVELS = 8      # of 255: a screenshot pixel shows the file's pixel (colour management)
SHOWS_SHARE = 0.99    # of the pixels, for a screenshot to show an image file
FLIP_INSIDE = 0.95    # share of the pixels where A and B differ that must change in a flip
FLIP_OUTSIDE = 0.005  # share of the other pixels that may change
DRAG_COVER = 0.90     # share of the A-vs-B pixels between the two splits that must change
HANDLE = 3            # pixels either side of a split where the handle line may be
ALIGN = 2             # pixels a screenshot may be offset from the view's rounded box
ZOOMS = (1, 2, 4, 8, 16)
VISIBLE = "{opacityProperty: true, visibilityProperty: true}"  # checkVisibility: shown at all
# Two frames, so that the last change is painted, and the end of every animation that ends.
SETTLED = """new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() =>
    Promise.all(document.getAnimations()
        .filter((a) => a.effect && a.effect.getComputedTiming().endTime !== Infinity)
        .map((a) => a.finished.catch(() => null))).then(() => resolve(true)))))"""


class Run:
    """The browser, the page and the failures so far."""

    def __init__(self, b, page_path):
        self.b = b
        self.page_path = page_path
        self.failures = 0
        self.stage = "start"  # the check under way
        self.requests = {}  # requestId: URL, to name a failed request
        self.offset = None  # of the comparison's images from its view's rounded box: view_pixels

    def fail(self, check, message):
        print(f"FAIL {check}: {message}")
        self.failures += 1

    def js(self, expression):
        return self.b.evaluate(expression, timeout=LOAD_TIMEOUT)

    def settle(self):
        """Waits until the page has painted its last change and its animations have ended."""
        self.js(SETTLED)

    def page_errors(self):
        """One line for each console error, uncaught exception and failed request kept."""
        events = self.b.take_events({"Network.requestWillBeSent", "Runtime.consoleAPICalled",
                                     "Runtime.exceptionThrown", "Log.entryAdded",
                                     "Network.loadingFailed", "Network.responseReceived"})
        lines = []
        for name, p in events:
            if name == "Network.requestWillBeSent":
                self.requests[p["requestId"]] = p["request"]["url"]
            elif name == "Runtime.consoleAPICalled" and p["type"] in ("error", "assert"):
                text = " ".join(str(arg.get("value", arg.get("description", "")))
                                for arg in p.get("args", []))
                frames = p.get("stackTrace", {}).get("callFrames", [])
                where = f" ({self.short(frames[0]['url'])}:{frames[0]['lineNumber'] + 1})" \
                    if frames else ""
                lines.append(f"console.{p['type']}: {text}{where}")
            elif name == "Runtime.exceptionThrown":
                d = p["exceptionDetails"]
                text = d.get("exception", {}).get("description") or d.get("text", "")
                lines.append(f"uncaught exception: {text.splitlines()[0]} "
                             f"({self.short(d.get('url', ''))}:{d.get('lineNumber', 0) + 1})")
            elif name == "Log.entryAdded" and p["entry"]["level"] == "error" \
                    and p["entry"]["source"] != "network":  # that one is a failed request too
                entry = p["entry"]
                lines.append(f"error logged: {entry['text']} {self.short(entry.get('url', ''))}")
            elif name == "Network.loadingFailed":
                url = self.requests.get(p["requestId"], "?")
                lines.append(f"failed request: {self.short(url)}: {p['errorText']}")
            elif name == "Network.responseReceived" and p["response"].get("status", 0) >= 400:
                lines.append(f"failed request: {self.short(p['response']['url'])}: "
                             f"status {p['response']['status']}")
        return lines

    def short(self, url):
        """A file URL as a path relative to the page's folder."""
        if url.startswith("file://"):
            path = urllib.request.url2pathname(urllib.parse.urlsplit(url).path)
            return os.path.relpath(path, os.path.dirname(self.page_path))
        return url

    def file_of(self, url):
        return urllib.request.url2pathname(urllib.parse.urlsplit(url).path)

    # Boxes are dicts of left, top, width, height in viewport CSS pixels.

    def box(self, element):
        return self.js(f"""(() => {{ const r = {element}.getBoundingClientRect();
            return {{left: r.left, top: r.top, width: r.width, height: r.height}}; }})()""")

    def click(self, element):
        """A real click (mouse events at the element's centre), once it is on the screen."""
        self.js(f"{element}.scrollIntoView({{block: 'nearest', inline: 'nearest', "
                f"behavior: 'instant'}})")
        r = self.box(element)
        self.b.click(r["left"] + r["width"] / 2, r["top"] + r["height"] / 2)
        self.settle()

    def view_pixels(self, view, image):
        """The pixels the view shows, image's size. The view's box may sit at a fractional
        position, so its images may show a pixel off its rounded box: the first call finds the
        offset that matches image best (within ALIGN pixels) and later calls keep it, so that a
        view that moves shows as a change."""
        h, w = image.shape[:2]
        r = self.box(view)
        scroll = self.js("[scrollX, scrollY]")
        x, y = round(r["left"] + scroll[0]), round(r["top"] + scroll[1])
        x0, y0 = max(0, x - ALIGN), max(0, y - ALIGN)
        shot = pixels(self.b.screenshot(x0, y0, w + x - x0 + ALIGN, h + y - y0 + ALIGN))
        if self.offset is None:
            scores = {}
            for dy in range(y0 - y, ALIGN + 1):
                for dx in range(x0 - x, ALIGN + 1):
                    part = shot[y - y0 + dy:y - y0 + dy + h, x - x0 + dx:x - x0 + dx + w]
                    if part.shape[:2] == (h, w):
                        scores[dx, dy] = np.abs(part - image).mean()
            self.offset = min(scores, key=scores.get)
        dx, dy = self.offset
        return shot[y - y0 + dy:y - y0 + dy + h, x - x0 + dx:x - x0 + dx + w]


def pixels(png_or_path):
    if isinstance(png_or_path, bytes):
        png_or_path = io.BytesIO(png_or_path)
    with Image.open(png_or_path) as image:
        return np.asarray(image.convert("RGB"), dtype=np.int16)


def differs(a, b, levels=LEVELS):
    return (np.abs(a - b) > levels).any(axis=2)


def shows(part, image):
    """The share of part's pixels that show image's, within colour management's rounding. The
    outermost rows and columns are left out: in a view at a fractional position, a clip-path's
    edge blends them with what lies under them (Chromium snaps the images to whole pixels, not
    the clip)."""
    inner = (slice(1, -1), slice(1, -1))
    return float((~differs(part[inner], image[inner], SHOWS_LEVELS)).mean())


def share(count, total):
    return count / total if total else 0.0


# The checks, in order; each prints its line.

def check_load(run, url, shots):
    start = time.monotonic()
    run.b.navigate(url, timeout=LOAD_TIMEOUT)
    run.settle()
    if shots:
        with open(os.path.join(shots, "first-screen.png"), "wb") as f:
            f.write(run.b.screenshot())
    run.b.pump(0.2)  # an error reported just after the load event
    errors = run.page_errors()
    for line in errors:
        run.fail("load", line)
    print(f"load: {url} in {time.monotonic() - start:.1f} s, {len(errors)} console errors "
          "or failed requests")


def check_images(run):
    images = run.js("""(async () => {
        const images = [...document.images];
        for (const image of images) image.loading = "eager";
        await Promise.all(images.map((image) => image.complete ? null : new Promise((done) => {
            image.addEventListener("load", done, {once: true});
            image.addEventListener("error", done, {once: true});
        })));
        await Promise.all(images.map((image) => image.decode().catch(() => null)));
        return images.map((image) => ({src: image.getAttribute("src") || image.currentSrc,
                                       ok: image.complete && image.naturalWidth > 0}));
    })()""")
    comparisons = run.js("document.querySelectorAll('figure.compare').length")
    broken = [image["src"] for image in images if not image["ok"]]
    for src in broken:
        run.fail("images", f"not loaded: {src}")
    if not images:
        run.fail("images", "the page has no image")
    if not comparisons:
        run.fail("images", "the page has no comparison (figure.compare)")
    print(f"images: {len(images) - len(broken)} of {len(images)} loaded, "
          f"{comparisons} comparisons")


def check_links(run):
    page = run.js("""({url: document.URL.split("#")[0],
        links: [...document.querySelectorAll("a[href]")].map((a) => [a.getAttribute("href"),
                                                                      a.href]),
        names: [...document.querySelectorAll("[id]")].map((e) => e.id).concat(
               [...document.querySelectorAll("a[name]")].map((e) => e.name))})""")
    names = set(page["names"])
    counts = {"in-page": 0, "file": 0, "web": 0, "other": 0}
    for raw, resolved in page["links"]:
        parts = urllib.parse.urlsplit(resolved)
        target = urllib.parse.urlunsplit(parts._replace(fragment=""))
        fragment = urllib.parse.unquote(parts.fragment)
        if parts.scheme in ("http", "https"):
            counts["web"] += 1
        elif parts.scheme in ("mailto", "data"):
            counts["other"] += 1
        elif parts.scheme != "file":
            run.fail("links", f"href '{raw}': a {parts.scheme}: link, not a file or a fragment")
        elif target == page["url"]:
            counts["in-page"] += 1
            if fragment and fragment not in names:
                run.fail("links", f"href '{raw}': no element of the page has id '{fragment}'")
        else:
            counts["file"] += 1
            if not os.path.exists(run.file_of(target)):
                run.fail("links", f"href '{raw}': no file {run.short(target)}")
    print(f"links: {counts['in-page']} in the page and {counts['file']} to files checked, "
          f"{counts['web']} web links not followed, {counts['other']} mail or data links")


def choose_comparison(run, wanted):
    """The selector of the comparison to operate and its images' files, or None."""
    figures = run.js("""[...document.querySelectorAll("figure.compare")].map((f) => {
        const a = f.querySelector("img.compare-a"), b = f.querySelector("img.compare-b");
        return {id: f.id, a: a && a.src, b: b && b.src,
                same: !!(a && b && a.naturalWidth > 0 && a.naturalWidth === b.naturalWidth &&
                         a.naturalHeight === b.naturalHeight)};
    })""")
    if wanted:
        chosen = [f for f in figures if f["id"] == wanted]
        if not chosen:
            run.fail("contract", f"no figure.compare has id '{wanted}'")
            return None
        if not chosen[0]["same"]:
            run.fail("contract", f"{wanted}: its images A and B are not loaded or differ in size")
            return None
    else:
        chosen = [f for f in figures if f["same"]]
        if not chosen:
            run.fail("contract", "no figure.compare has images A and B of the same size")
            return None
    figure = chosen[0]
    if not figure["id"]:
        run.fail("contract", "the comparison has no id")
        return None
    return figure


def check_contract(run, figure):
    """Whether the comparison has the parts that the checks after this one operate (the view,
    its images and handle, the mode buttons and zoom 1); a missing other part is a failure too,
    but the checks go on without it."""
    f = f"document.getElementById({figure['id']!r})"
    operated = [".compare-frame .compare-view", ".compare-view img.compare-a",
                ".compare-view img.compare-b", ".compare-view .compare-handle",
                *(f".compare-mode[data-mode='{mode}']" for mode in ("slider", "a", "b")),
                ".compare-zoom[data-zoom='1']"]
    parts = [*operated, ".compare-controls", "img.compare-diff", "figcaption",
             *(f".compare-zoom[data-zoom='{zoom}']" for zoom in ZOOMS[1:])]
    missing = run.js(f"{parts!r}.filter((part) => !{f}.querySelector(part))")
    for part in missing:
        run.fail("contract", f"{figure['id']} has no {part}")
    print(f"contract: {figure['id']} ({run.short(figure['a'])} against "
          f"{run.short(figure['b'])}): {len(parts) - len(missing)} of {len(parts)} parts")
    return not set(missing) & set(operated)


def check_flip(run, a, b, sel):
    run.click(sel["zoom"](1))
    size = (a.shape[1], a.shape[0])
    r = run.box(sel["view"])
    if abs(r["width"] - size[0]) > 0.5 or abs(r["height"] - size[1]) > 0.5:
        run.fail("flip", f"at zoom 1 the view is {r['width']:g} x {r['height']:g} CSS pixels, "
                 f"its images {size[0]} x {size[1]}")
        return False
    run.click(sel["mode"]("a"))
    shot_a = run.view_pixels(sel["view"], a)
    handle_a = run.js(f"{sel['handle']}.checkVisibility({VISIBLE})")
    run.click(sel["mode"]("b"))
    shot_b = run.view_pixels(sel["view"], b)
    handle_b = run.js(f"{sel['handle']}.checkVisibility({VISIBLE})")
    mask = differs(a, b)
    changed = differs(shot_a, shot_b)
    inside = share((changed & mask).sum(), mask.sum())
    outside = share((changed & ~mask).sum(), (~mask).sum())
    shows_a, shows_b = shows(shot_a, a), shows(shot_b, b)
    if not mask.any():
        run.fail("flip", "images A and B are the same: nothing to see (choose another with "
                 "--compare)")
    elif inside < FLIP_INSIDE:
        run.fail("flip", f"the view changed at {inside:.1%} of the pixels where A and B differ "
                 f"(at least {FLIP_INSIDE:.0%} expected)")
    if outside > FLIP_OUTSIDE:
        run.fail("flip", f"the view changed at {outside:.2%} of the pixels where A and B are "
                 f"the same (at most {FLIP_OUTSIDE:.1%} expected)")
    for mode, got in (("a", shows_a), ("b", shows_b)):
        if got < SHOWS_SHARE:
            run.fail("flip", f"mode {mode} shows image {mode.upper()} at only {got:.1%} of the "
                     f"pixels (at least {SHOWS_SHARE:.0%} expected)")
    for mode, shown in (("a", handle_a), ("b", handle_b)):
        if shown:
            run.fail("flip", f"the handle shows in mode {mode}")
    print(f"flip: changed at {inside:.1%} of the {mask.sum()} pixels where A and B differ, "
          f"{outside:.2%} of the {(~mask).sum()} others; mode a shows A at {shows_a:.1%}, "
          f"mode b shows B at {shows_b:.1%}; the handle "
          f"{'shows' if handle_a or handle_b else 'is hidden'} in them")
    return True


def drag_split(run, sel, start, end):
    """Presses at the split's fraction start of the view's width, moves to end in steps and
    releases."""
    r = run.box(sel["view"])
    y = r["top"] + r["height"] / 2
    xs = [r["left"] + r["width"] * (start + (end - start) * i / 5) for i in range(6)]
    run.b.mouse_move(xs[0], y)
    run.b.mouse_press(xs[0], y)
    for x in xs[1:]:
        run.b.mouse_move(x, y, pressed=True)
    run.b.mouse_release(xs[-1], y)
    run.settle()


def check_drag(run, a, b, sel):
    width = a.shape[1]
    run.click(sel["mode"]("slider"))
    before = run.view_pixels(sel["view"], a)
    handles = [handle_at(run, sel)]
    drag_split(run, sel, 0.5, 0.25)
    after = run.view_pixels(sel["view"], a)
    handles.append(handle_at(run, sel))
    columns = np.arange(width)
    near = (columns >= width * 0.25 - HANDLE) & (columns <= width * 0.5 + HANDLE)
    between = (columns > width * 0.25 + HANDLE) & (columns < width * 0.5 - HANDLE)
    changed = differs(before, after)
    mask = differs(a, b)
    strays = int(changed[:, ~near].sum())
    cover = share((changed & mask)[:, between].sum(), mask[:, between].sum())
    left, right = columns < width * 0.5 - HANDLE, columns > width * 0.5 + HANDLE
    shows_left = shows(before[:, left], a[:, left])
    shows_right = shows(before[:, right], b[:, right])
    if strays:
        run.fail("drag", f"{strays} pixels changed outside the columns between the splits")
    if not mask[:, between].any():
        run.fail("drag", "A and B are the same between 25 % and 50 % of the width: nothing to "
                 "see (choose another comparison with --compare)")
    elif cover < DRAG_COVER:
        run.fail("drag", f"between the splits the view changed at {cover:.1%} of the pixels "
                 f"where A and B differ (at least {DRAG_COVER:.0%} expected)")
    for split, at in zip((50, 25), handles):
        if at is None:
            run.fail("drag", f"the handle does not show in mode slider (split at {split} %)")
        elif abs(at - split / 100 * width) > HANDLE:
            run.fail("drag", f"the handle is at {100 * at / width:.1f} % of the view, not at "
                     f"{split} %")
    if min(shows_left, shows_right) < SHOWS_SHARE:
        run.fail("drag", f"split at 50 %: left of it A shows at {shows_left:.1%}, right of it "
                 f"B at {shows_right:.1%} (at least {SHOWS_SHARE:.0%} each expected)")
    print(f"drag: 50 % to 25 %: changed at {cover:.1%} of the {mask[:, between].sum()} pixels "
          f"between where A and B differ, {strays} pixels elsewhere; at 50 % A shows left at "
          f"{shows_left:.1%}, B right at {shows_right:.1%}")


def handle_at(run, sel):
    """Where the handle's centre is, in CSS pixels from the view's left; None when hidden."""
    return run.js(f"""(() => {{ const handle = {sel['handle']};
        if (!handle.checkVisibility({VISIBLE})) return null;
        const h = handle.getBoundingClientRect(), v = {sel['view']}.getBoundingClientRect();
        return h.left + h.width / 2 - v.left; }})()""")


def check_zoom(run, a, sel):
    h, w = a.shape[:2]
    rendering = run.js(f"""[{sel['a']}, {sel['b']}].map((image) =>
        getComputedStyle(image).imageRendering)""")
    zooms = [zoom for zoom in ZOOMS if run.js(f"{sel['zoom'](zoom)} !== null")]
    sizes = []
    for zoom in zooms:
        run.click(sel["zoom"](zoom))
        r = run.box(sel["view"])
        sizes.append(f"{r['width']:g}x{r['height']:g}")
        if abs(r["width"] - w * zoom) > 0.5 or abs(r["height"] - h * zoom) > 0.5:
            run.fail("zoom", f"at zoom {zoom} the view is {r['width']:g} x {r['height']:g} CSS "
                     f"pixels, not {w * zoom} x {h * zoom}")
    run.click(sel["zoom"](1))
    if any(value != "pixelated" for value in rendering):
        run.fail("zoom", f"images A and B have image-rendering {' and '.join(rendering)}, not "
                 "pixelated")
    print(f"zoom: view {', '.join(sizes)} CSS pixels at zoom {', '.join(map(str, zooms))}; "
          f"image-rendering {', '.join(sorted(set(rendering)))}")


def save_comparison(run, sel, shots):
    run.click(sel["mode"]("slider"))
    drag_split(run, sel, 0.25, 0.35)
    # A viewport tall enough for the whole figure: a capture beyond the viewport lays the page
    # out again at another size, and the rectangle measured before would miss the figure.
    height = max(VIEWPORT[1], math.ceil(run.box(sel["figure"])["height"]) + 16)
    run.b.resize(VIEWPORT[0], height)
    run.js(f"{sel['figure']}.scrollIntoView({{block: 'start', behavior: 'instant'}})")
    run.settle()
    r = run.box(sel["figure"])
    scroll = run.js("[scrollX, scrollY]")
    png = run.b.screenshot(round(r["left"] + scroll[0]), round(r["top"] + scroll[1]),
                           round(r["width"]), round(r["height"]))
    run.b.resize(*VIEWPORT)
    with open(os.path.join(shots, "comparison.png"), "wb") as f:
        f.write(png)
    print(f"screenshots: {shots}/first-screen.png, {shots}/comparison.png "
          f"({round(r['width'])} x {round(r['height'])})")


def selectors(figure_id):
    """JavaScript expressions of the comparison's parts."""
    f = f"document.getElementById({figure_id!r})"
    return {"figure": f,
            "view": f"{f}.querySelector('.compare-view')",
            "a": f"{f}.querySelector('img.compare-a')",
            "b": f"{f}.querySelector('img.compare-b')",
            "handle": f"{f}.querySelector('.compare-handle')",
            "mode": lambda mode: f"{f}.querySelector(\".compare-mode[data-mode='{mode}']\")",
            "zoom": lambda zoom: f"{f}.querySelector(\".compare-zoom[data-zoom='{zoom}']\")"}


def run_checks(run, url, args):
    """The checks in order; run.stage names the one under way, for a browser that fails it."""
    def step(name, check, *check_args):
        run.stage = name
        return check(run, *check_args)

    step("load", check_load, url, args.screenshots)
    step("images", check_images)
    step("links", check_links)
    figure = step("contract", choose_comparison, args.compare)
    if figure and step("contract", check_contract, figure):
        a, b = pixels(run.file_of(figure["a"])), pixels(run.file_of(figure["b"]))
        sel = selectors(figure["id"])
        run.js(f"{sel['figure']}.scrollIntoView({{block: 'start', behavior: 'instant'}})")
        if step("flip", check_flip, a, b, sel):
            step("drag", check_drag, a, b, sel)
            step("zoom", check_zoom, a, sel)
            if args.screenshots:
                step("screenshots", save_comparison, sel, args.screenshots)
    run.stage = "afterwards"
    run.b.pump(0.2)
    errors = run.page_errors()
    for line in errors:
        run.fail("afterwards", line)
    print(f"afterwards: {len(errors)} console errors or failed requests while operating the page")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("report", metavar="REPORT_HTML")
    parser.add_argument("--compare", metavar="ID", help="the id of the comparison to operate")
    parser.add_argument("--screenshots", metavar="DIR", help="write the README's screenshots")
    args = parser.parse_args()
    start = time.monotonic()
    path = os.path.realpath(args.report)
    if not os.path.isfile(path):
        print(f"FAIL load: no file {args.report}")
        return 1
    if args.screenshots:
        os.makedirs(args.screenshots, exist_ok=True)
    try:
        with browser.Browser() as b:
            b.open_page(*VIEWPORT)
            run = Run(b, path)
            try:
                run_checks(run, pathlib.Path(path).as_uri(), args)
            except browser.BrowserError as e:
                run.fail(run.stage, f"the browser: {e}")
            failures = run.failures
    except browser.BrowserError as e:
        print(f"FAIL browser: {e}")
        return 1
    verdict = "every check passes" if not failures else f"{failures} failures"
    print(f"total: {time.monotonic() - start:.1f} s, {verdict}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
