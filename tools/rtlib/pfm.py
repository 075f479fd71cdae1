"""PFM images (Portable Float Map), as the renderer writes them (rt/image/image_io.cpp).

The header is three tokens and a scale, each ended by one white-space character: "PF" (three
channels) or "Pf" (one), the width and the height, and a number whose sign is the byte order of
the 32-bit floats that follow (negative: little endian). The rows are stored bottom row first.
An Image holds them top row first, as the renderer's pixel (x, y) and --crop count them, so
pixels[(y * width + x) * channels + c] is channel c of pixel (x, y).

Standard library only (tools run by an interpreter without numpy read images too); as_array
gives numpy's view for the tools that compute with it."""
import array
import sys
from typing import NamedTuple

CHANNELS = {b"PF": 3, b"Pf": 1}


class FormatError(ValueError):
    """A file that is not a PFM image, or is cut short; the message names the file."""


class Image(NamedTuple):
    width: int
    height: int
    channels: int
    pixels: array.array  # 32-bit floats ("f"), rows top to bottom, channels interleaved


def read(path):
    """The image in the PFM file at path."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, scale: each ended by one white-space byte
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        if pos == start or pos == len(data):
            raise FormatError(f"'{path}' must be a PFM image, got a header cut short")
        fields.append(data[start:pos])
        pos += 1
    magic, width, height, scale = fields
    if magic not in CHANNELS:
        raise FormatError(f"'{path}' must be a PFM image (PF or Pf), got header {magic!r}")
    try:
        width, height, scale = int(width), int(height), float(scale)
    except ValueError:
        raise FormatError(f"'{path}' must have a PFM header 'WIDTH HEIGHT SCALE', got "
                          f"{b' '.join(fields[1:])!r}") from None
    if width <= 0 or height <= 0 or scale == 0:
        raise FormatError(f"'{path}' must have a positive size and a non-zero scale, got "
                          f"{width} x {height}, scale {scale}")
    channels = CHANNELS[magic]
    row = width * channels
    stored = array.array("f")
    if stored.itemsize != 4:
        raise FormatError("PFM images need 32-bit floats, and this Python's array('f') is not")
    body = data[pos:]
    if len(body) != 4 * row * height:
        raise FormatError(f"'{path}' must hold {width} x {height} x {channels} floats "
                          f"({4 * row * height} bytes), got {len(body)} bytes")
    stored.frombytes(body)
    if (scale < 0) != (sys.byteorder == "little"):
        stored.byteswap()
    pixels = array.array("f")
    for y in range(height - 1, -1, -1):  # the file's last row is the image's top row
        pixels.extend(stored[y * row:(y + 1) * row])
    return Image(width, height, channels, pixels)


def encode(image, byteorder="little"):
    """The bytes of image (an Image; pixels any sequence of numbers, top row first) as a PFM
    file, with the floats in the given byte order ("little" or "big")."""
    if byteorder not in ("little", "big"):
        raise ValueError(f"byteorder must be 'little' or 'big', got {byteorder!r}")
    magics = {n: m for m, n in CHANNELS.items()}
    if image.channels not in magics:
        raise ValueError(f"a PFM image has 1 or 3 channels, got {image.channels}")
    pixels = array.array("f", image.pixels)
    row = image.width * image.channels
    if len(pixels) != row * image.height:
        raise ValueError(f"a {image.width} x {image.height} x {image.channels} image must have "
                         f"{row * image.height} values, got {len(pixels)}")
    stored = array.array("f")
    for y in range(image.height - 1, -1, -1):  # bottom row first
        stored.extend(pixels[y * row:(y + 1) * row])
    if byteorder != sys.byteorder:
        stored.byteswap()
    scale = "-1.0" if byteorder == "little" else "1.0"
    header = f"{magics[image.channels].decode()}\n{image.width} {image.height}\n{scale}\n"
    return header.encode() + stored.tobytes()


def write(path, image, byteorder="little"):
    """Writes image to path as a PFM file (encode)."""
    data = encode(image, byteorder)
    with open(path, "wb") as f:
        f.write(data)


def as_array(image):
    """The image as a numpy array of height x width x channels, float64, top row first."""
    import numpy  # here, so that the readers without numpy can import this module

    values = numpy.frombuffer(image.pixels, dtype=numpy.float32)
    return values.astype(numpy.float64).reshape(image.height, image.width, image.channels)
