"""How a renderer turns linear light into the numbers of an image file, and back.

An encoding maps linear radiance (numpy arrays, any shape) to the values a file holds: 8-bit
codes 0..255 for PPM and PNG, the radiance itself for PFM and EXR. Each has a continuous form
(the code before it is rounded to an integer, for expectations at many samples) and a decoding
(the linear light a code stands for, the middle of its interval).

  gamma2   the book's write_color: int(256 * clamp(sqrt(x), 0, 0.999))
  linear8  the book before its gamma section: int(256 * clamp(x, 0, 0.999))
  gamma4   gamma applied twice: int(256 * clamp(sqrt(sqrt(x)), 0, 0.999))
  srgb     this project's PNG: round(255 * sRGB(clamp(x, 0, 1)))
  float    PFM and EXR: x itself
"""
import numpy as np

EIGHT_BIT = ("gamma2", "linear8", "gamma4", "srgb")
NAMES = {"gamma2": "the book's gamma 2 (square root, then int(256 x))",
         "linear8": "no gamma (the linear value, then int(256 x))",
         "gamma4": "gamma applied twice (a fourth root)",
         "srgb": "sRGB",
         "float": "linear floats"}


def _srgb(x):
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def _srgb_inverse(s):
    return np.where(s <= 0.04045, s / 12.92, np.power((s + 0.055) / 1.055, 2.4))


def _shaped(x, how):
    """The encoding's curve, before it is scaled to codes: in [0, 1] for the 8-bit ones."""
    x = np.nan_to_num(np.asarray(x, dtype=np.float64), nan=0.0, posinf=1.0, neginf=0.0)
    if how == "gamma2":
        return np.sqrt(np.clip(x, 0.0, None))
    if how == "gamma4":
        return np.sqrt(np.sqrt(np.clip(x, 0.0, None)))
    if how == "linear8":
        return np.clip(x, 0.0, None)
    raise ValueError(how)


def encode(x, how):
    """The file's values for linear light x."""
    if how == "float":
        return np.asarray(x, dtype=np.float64)
    if how == "srgb":
        return np.round(255.0 * _srgb(np.asarray(x, dtype=np.float64)))
    return np.floor(256.0 * np.clip(_shaped(x, how), 0.0, 0.999))


def encode_continuous(x, how):
    """encode() without the rounding: the code's expected value when noise spans many codes
    (int() of a value spread over many codes is on average half a code below it)."""
    if how == "float":
        return np.asarray(x, dtype=np.float64)
    if how == "srgb":
        return 255.0 * _srgb(np.asarray(x, dtype=np.float64))
    return np.clip(256.0 * np.clip(_shaped(x, how), 0.0, 0.999) - 0.5, 0.0, 255.0)


def decode(codes, how):
    """The linear light that the file's values stand for (the middle of each code's interval)."""
    codes = np.asarray(codes, dtype=np.float64)
    if how == "float":
        return codes
    if how == "srgb":
        return _srgb_inverse(codes / 255.0)
    shaped = (codes + 0.5) / 256.0
    if how == "gamma2":
        return shaped * shaped
    if how == "gamma4":
        return shaped ** 4
    return shaped
