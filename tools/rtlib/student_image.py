"""A student's image, from any program: PPM (P3 text or P6), PNG, PFM or EXR, read by
OpenImageIO's readers (Debian's python3-openimageio), never by a parser of our own.

read(path) gives an Image: its pixels as float64 numpy values, rows from the top, RGB; 8-bit
files as their codes 0..255, float files as the values themselves. A file OpenImageIO cannot
read, or reads only in part (a truncated PPM), raises BadImage with one line naming it."""
import contextlib
import os
from typing import NamedTuple

import numpy as np

FLOAT_FORMATS = (".pfm", ".exr")
MAX_SIDE = 16384         # pixels a side, at most: the book's largest image is 1200 wide
MAX_PIXELS = 1 << 26     # and 64 Mi pixels in all, refused before the pixels are read


class BadImage(ValueError):
    """The file is not an image this checker reads; the message names it and why."""


class Image(NamedTuple):
    pixels: np.ndarray  # (height, width, 3) float64
    eight_bit: bool     # codes 0..255 (PPM, PNG) rather than linear floats (PFM, EXR)
    kind: str           # "PPM (P3)", "PNG", ...

    @property
    def width(self):
        return self.pixels.shape[1]

    @property
    def height(self):
        return self.pixels.shape[0]


def _kind(path, header):
    ext = os.path.splitext(path)[1].lower()
    if header[:2] in (b"P3", b"P6"):
        return f"PPM ({header[:2].decode()})"
    if header[:8] == b"\x89PNG\r\n\x1a\n":
        return "PNG"
    if header[:2] in (b"PF", b"Pf"):
        return "PFM"
    if header[:4] == b"\x76\x2f\x31\x01":
        return "EXR"
    raise BadImage(f"'{path}' is not a PPM, PNG, PFM or EXR image (its first bytes are "
                   f"{header[:8]!r}; extension '{ext}')")


def _first_line(message):
    lines = message.strip().splitlines()
    return lines[0] if lines else ""


@contextlib.contextmanager
def _quiet_stderr():
    """The C libraries under OpenImageIO (libpng) print their own errors to the process's
    stderr; OpenImageIO reports them too, so they are silenced for the one line we print."""
    saved = os.dup(2)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


def read(path):
    with _quiet_stderr():
        return _read(path)


def _read(path):
    try:
        with open(path, "rb") as f:
            header = f.read(8)
    except OSError as e:
        raise BadImage(f"cannot read '{path}': {e.strerror}")
    kind = _kind(path, header)
    import OpenImageIO as oiio  # imported here: --help works without it
    image = oiio.ImageInput.open(path)
    if image is None:
        raise BadImage(f"cannot read '{path}' as {kind}: {_first_line(oiio.geterror())}")
    try:
        spec = image.spec()
        eight_bit = spec.format.basetype == oiio.UINT8
        floats = spec.format.basetype in (oiio.FLOAT, oiio.HALF, oiio.DOUBLE)
        if not (eight_bit or floats):
            raise BadImage(f"'{path}' holds {spec.format} values; the checker reads 8-bit "
                           "images (PPM with maximum 255, PNG) and float ones (PFM, EXR)")
        if not (0 < spec.width <= MAX_SIDE and 0 < spec.height <= MAX_SIDE
                and spec.width * spec.height <= MAX_PIXELS):
            raise BadImage(f"'{path}' says it is {spec.width} x {spec.height}: beyond the "
                           f"checker's limit of {MAX_SIDE} a side and {MAX_PIXELS} pixels")
        if spec.nchannels not in (3, 4):
            raise BadImage(f"'{path}' has {spec.nchannels} channels; an RGB image has 3")
        pixels = image.read_image(0, 0, 0, 3, oiio.UINT8 if eight_bit else oiio.FLOAT)
        error = _first_line(image.geterror())
    finally:
        image.close()
    if pixels is None or error:
        raise BadImage(f"cannot read '{path}' as {kind}: "
                       f"{error or 'the file ends before its pixels do'}")
    pixels = np.asarray(pixels, dtype=np.float64).reshape(spec.height, spec.width, 3)
    return Image(pixels, eight_bit, kind)
