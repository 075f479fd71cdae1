"""The HTML report (report/index.html): the Markdown report's text, converted by Debian's
python3-markdown, with image comparisons a reader operates (report/html/report.js) and, beside
each pair, a false-colour map of where the two differ. A page opened from disk may not read its
own images' pixels (browsers taint canvases and block fetch under file://), so the maps are
computed here.

  Comparison(...)          one pair: its Markdown (for README.md) and its HTML (for the page)
  difference_map(a, b, out)  writes the map of two PNGs of one size; returns its scale
  Gallery(...)             comparisons shown together (a table of images in README.md)
  page(lines, title, root)  the page from the report's lines: Markdown strings, Comparisons and
                           Galleries
"""
import html
import os
import re

import markdown
import numpy as np
from matplotlib import colormaps
from PIL import Image

ZOOMS = (1, 2, 4, 8, 16)
# The colour scale of every map: black where the two agree, through purple and orange to pale
# yellow at the map's full scale (the CSS legend, .map-legend, draws the same stops).
COLOURS = "inferno"


def slug(text):
    """A heading's id as GitHub makes it, so that the Markdown report's links work in both."""
    return re.sub(r"[^a-z0-9_ -]", "", text.lower()).replace(" ", "-")


def read_display(path):
    """A PNG's display values (its 8-bit codes over 255), height x width x 3."""
    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"), dtype=np.float64) / 255.0


def difference_map(a_path, b_path, out_path):
    """Writes out_path, the largest difference over the channels of each pixel in display
    values, from black (equal) to pale yellow (the scale and more). The scale is the 99th
    percentile of the differing pixels (at least one 8-bit code), so that a few extreme pixels
    do not hide the rest. Returns (scale, fraction of pixels that differ)."""
    a, b = read_display(a_path), read_display(b_path)
    if a.shape != b.shape:
        raise ValueError(f"{a_path} is {a.shape[1]}x{a.shape[0]} but {b_path} is "
                         f"{b.shape[1]}x{b.shape[0]}: a comparison needs one size")
    difference = np.abs(b - a).max(axis=2)
    differing = difference > 0
    scale = max(float(np.percentile(difference[differing], 99)) if differing.any() else 0.0,
                1.0 / 255.0)
    # A palette image of the scale's 256 colours: a third of the bytes of RGB, for the noise.
    levels = np.round(np.clip(difference / scale, 0.0, 1.0) * 255).astype(np.uint8)
    palette = np.round(colormaps[COLOURS](np.arange(256) / 255.0)[:, :3] * 255)
    image = Image.fromarray(levels, mode="L").convert("P")
    image.putpalette(palette.astype(np.uint8).flatten().tolist())
    save_png(image, out_path, optimize=True)
    return scale, float(differing.mean())


def save_png(image, path, **options):
    """Writes a PIL image as PNG to path, whole or not at all (through a file beside it)."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    image.save(path + ".tmp.png", **options)
    os.replace(path + ".tmp.png", path)


def image_size(path):
    with Image.open(path) as image:
        return image.size


class Comparison:
    """Images a and b (paths relative to the report folder, root) as a comparison: in the
    Markdown report, `markdown` (the lines it shows instead, images side by side by default);
    in the HTML report, the pair stacked with a slider, a flip and zoom, and the difference map
    (written to maps/NAME.png under the report's html folder)."""

    def __init__(self, root, name, a, b, a_label, b_label, caption="", markdown_lines=None,
                 small=False):
        self.root, self.name, self.a, self.b = root, name, a, b
        self.a_label, self.b_label, self.caption, self.small = a_label, b_label, caption, small
        self.markdown = markdown_lines if markdown_lines is not None else [
            f"| {a_label} | {b_label} |", "|---|---|", f"| ![{a_label}]({a}) | ![{b_label}]({b}) |"]

    def html(self):
        a_path, b_path = (os.path.join(self.root, p) for p in (self.a, self.b))
        width, height = image_size(a_path)
        if image_size(b_path) != (width, height):
            return self.side_by_side()
        diff = f"html/maps/{self.name}.png"
        scale, differing = difference_map(a_path, b_path, os.path.join(self.root, diff))
        e = html.escape
        buttons = "".join(
            f'<button type="button" class="compare-mode" data-mode="{mode}">{e(label)}</button>'
            for mode, label in (("slider", "slider"), ("a", self.a_label), ("b", self.b_label)))
        buttons += '<span class="gap"></span>' + "".join(
            f'<button type="button" class="compare-zoom" data-zoom="{z}">{z}x</button>'
            for z in ZOOMS)
        if differing == 0:
            said = "The two images are identical, byte for byte in their 8-bit codes."
        else:
            said = (f"Where they differ ({100 * differing:.1f} % of the pixels): the largest "
                    f"difference over the channels, black where equal, "
                    f'<span class="map-legend"></span> to {scale * 255:.0f} of 255 and more.')
        return (
            f'<figure class="compare{" small" if self.small else ""}" '
            f'id="compare-{e(self.name)}">'
            f'<div class="compare-controls">{buttons}</div>'
            '<div class="compare-panels"><div>'
            '<div class="compare-frame">'
            f'<div class="compare-view" tabindex="0" data-width="{width}" '
            f'data-height="{height}" style="width:{width}px;height:{height}px">'
            f'<img class="compare-a" src="{e(self.a)}" alt="{e(self.a_label)}" '
            f'width="{width}" height="{height}">'
            f'<img class="compare-b" src="{e(self.b)}" alt="{e(self.b_label)}" '
            f'width="{width}" height="{height}">'
            '<div class="compare-handle"></div></div></div>'
            f'<div class="compare-labels"><span>{e(self.a_label)}</span>'
            f'<span>{e(self.b_label)}</span></div></div>'
            f'<img class="compare-diff" src="{e(diff)}" alt="where they differ" '
            f'width="{width}" height="{height}"></div>'
            f"<figcaption>{self.caption}{' ' if self.caption else ''}{said} "
            "Drag across the image, or choose one image (a click on it flips to the other); "
            "zoom shows single pixels.</figcaption></figure>")


    def side_by_side(self):
        """Two images of different sizes: side by side, nothing to flip or subtract."""
        e = html.escape
        images = "".join(f'<img src="{e(path)}" alt="{e(label)}">'
                         for path, label in ((self.a, self.a_label), (self.b, self.b_label)))
        return (f'<figure class="pair{" small" if self.small else ""}" id="pair-{e(self.name)}">'
                f'<div class="pair-images">{images}</div><figcaption>{self.caption}'
                f"{' ' if self.caption else ''}{e(self.a_label)} (left) and {e(self.b_label)} "
                "(right) differ in size, so they are shown side by side.</figcaption></figure>")


class Gallery:
    """Comparisons shown together in the page (small ones side by side); in the Markdown
    report, the lines `markdown_lines`."""

    def __init__(self, markdown_lines, comparisons):
        self.markdown, self.comparisons = markdown_lines, comparisons

    def html(self):
        return ('<div class="gallery">' + "".join(c.html() for c in self.comparisons)
                + "</div>")


def markdown_of(lines):
    """README.md's text: each Comparison or Gallery as its Markdown lines."""
    out = []
    for line in lines:
        out += [line] if isinstance(line, str) else line.markdown
    return "\n".join(out)


def page(lines, title, root):
    """report/index.html's text. Links to README.md#heading become links inside the page."""
    widgets, text = {}, []
    for line in lines:
        if not isinstance(line, str):
            key = f"COMPARISON{len(widgets)}PLACEHOLDER"
            widgets[key] = line.html()
            text += ["", key, ""]
        else:
            text.append(line)
    converter = markdown.Markdown(
        extensions=["tables", "fenced_code", "toc"],
        extension_configs={"toc": {"slugify": lambda value, _separator: slug(value),
                                   "toc_depth": "2-3"}})
    body = converter.convert("\n".join(text))
    for key, widget in widgets.items():
        body = body.replace(f"<p>{key}</p>", widget)
    body = re.sub(r'href="README\.md#', 'href="#', body)
    leftover = re.search(r"COMPARISON\d+PLACEHOLDER", body)
    if leftover:
        raise ValueError(f"a comparison was not placed in the page: {leftover.group(0)}")
    missing = [src for src in re.findall(r'<img[^>]* src="([^"]+)"', body)
               if not re.match(r"[a-z]+:", src)
               and not os.path.exists(os.path.join(root, html.unescape(src)))]
    if missing:
        raise ValueError(f"the page shows images that are not there: {', '.join(missing)}")
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<title>{html.escape(title)}</title>\n"
            "<link rel=\"stylesheet\" href=\"html/report.css\">\n</head>\n<body>\n"
            f"<nav class=\"toc\" aria-label=\"contents\">{converter.toc}</nav>\n"
            f"<main>\n{body}\n</main>\n<script src=\"html/report.js\"></script>\n"
            "</body>\n</html>\n")


def split_side_by_side(path, outs, pad=4):
    """Writes the images of a row of len(outs) images of one size, pad pixels apart (as
    oiiotool --mosaic:pad=PAD Nx1 makes it), to the paths outs, left to right."""
    with Image.open(path) as row:
        count = len(outs)
        width, height = row.size
        if (width - pad * (count - 1)) % count:
            raise ValueError(f"{path} ({width} pixels wide) is not {count} images {pad} apart")
        each = (width - pad * (count - 1)) // count
        for i, out in enumerate(outs):
            left = i * (each + pad)
            save_png(row.crop((left, 0, left + each, height)), out)
