"""The thin layer between Python and the C core: checks, snapping, errors.

Everything here is private.  It validates arguments (before any pixel is
written), snaps float coordinates to the 1/2^S grid, builds the C structs
and translates status codes into exceptions.
"""

import decimal
import fractions
import math
import numbers
import re
import warnings

import numpy as np

from . import _seq
from ._native import ffi, lib


class RastrumError(Exception):
    """An error reported by the rastrum C core."""


# numpy 2's reprs of its scalars, np.float64(300.5), np.int64(3), np.True_:
# a message prints the number as Python would (300.5, 3, True).
_NP_REPR = re.compile(r"\bnp\.(?:float|int|uint|complex|longdouble|clongdouble|half|single|double|"
                      r"bytes_|str_|intp|uintp)\d*\(((?:[^()]|\([^()]*\))*)\)")
_NP_BOOL = re.compile(r"\bnp\.(True|False)_")


class InputError(RastrumError, ValueError):
    """Bad input: the message says which argument and why.  Numbers in it
    print plainly (300.5), never as numpy's reprs (np.float64(300.5)),
    whichever type the caller gave them as: that is done here, once, for
    every message."""

    def __init__(self, *args):
        if len(args) == 1 and isinstance(args[0], str) and "np." in args[0]:
            args = (_NP_BOOL.sub(r"\1", _NP_REPR.sub(r"\1", args[0])),)
        super().__init__(*args)


def plural(n, word, words=None):
    """A count and its noun for a message: "1 int", "3 ints"."""
    return "%d %s" % (n, word if n == 1 else words or word + "s")


# Status codes that mean the caller's input is wrong (InputError); any other
# failure is an internal error of this layer (RastrumError).
_INPUT_ERRORS = frozenset(
    [
        lib.RAST_E_ARG,
        lib.RAST_E_RANGE,
        lib.RAST_E_SUBPIXEL,
        lib.RAST_E_SIZE,
        lib.RAST_E_FORMAT,
        lib.RAST_E_ALGORITHM,
        lib.RAST_E_RULE,
        lib.RAST_E_TOO_MANY,
        lib.RAST_E_WIDE,
    ]
)


def _check(status):
    """Raise the exception that matches a C status; return None on RAST_OK."""
    if status == lib.RAST_OK:
        return
    message = ffi.string(lib.rast_status_str(status)).decode()
    cls = InputError if status in _INPUT_ERRORS else RastrumError
    raise cls("rastrum: %s (status %d)" % (message, status))


RULES = {"evenodd": lib.RAST_RULE_EVENODD, "nonzero": lib.RAST_RULE_NONZERO}
SAMPLE_OFFSETS = {0.5: lib.RAST_SAMPLE_CENTER, 0.0: lib.RAST_SAMPLE_CORNER}
ROUNDINGS = {"exact": lib.RAST_ROUND_EXACT, "textbook": lib.RAST_ROUND_TEXTBOOK}
BOUNDARIES = {
    "exact": lib.RAST_BOUNDARY_EXACT,
    "closed": lib.RAST_BOUNDARY_CLOSED,
    "conservative": lib.RAST_BOUNDARY_CONSERVATIVE,
}
FORMATS = {
    "gray8": lib.RAST_FORMAT_GRAY8,
    "rgb888": lib.RAST_FORMAT_RGB888,
    "rgba8888": lib.RAST_FORMAT_RGBA8888,
    "rgb565": lib.RAST_FORMAT_RGB565,
    "mono1": lib.RAST_FORMAT_MONO1,
}


def _format_bytes(code):
    out = ffi.new("int32_t *")
    _check(lib.rast_format_bytes(code, out))
    return out[0]


FORMAT_BYTES = {name: _format_bytes(code) for name, code in FORMATS.items()}


def _polygon_algorithms():
    """{name: (code, tuple of rule names)} as the C registry lists them."""
    table = {}
    name = ffi.new("char **")
    rules = ffi.new("uint32_t *")
    for code in range(lib.RAST_ALGO_COUNT_):
        if lib.rast_algorithm_info(code, name, rules) != lib.RAST_OK:
            continue  # a number the library does not fill with (yet)
        supported = tuple(r for r, bit in RULES.items() if rules[0] & (1 << bit))
        table[ffi.string(name[0]).decode()] = (code, supported)
    return table


POLYGON_ALGORITHMS = _polygon_algorithms()


def _name(value, what, choices):
    if not isinstance(value, str) or value not in choices:
        raise InputError(
            "unknown %s %r; choose one of: %s" % (what, value, ", ".join(sorted(choices)))
        )
    return value


def _subpixel_bits(s, most=None):
    most = lib.RAST_MAX_SUBPIXEL_BITS if most is None else most
    if isinstance(s, (bool, np.bool_)) or not isinstance(s, (int, np.integer)):
        raise InputError("subpixel_bits must be an int, not %r" % (s,))
    if not 0 <= s <= most:
        raise InputError("subpixel_bits must be in 0..%d, not %d" % (most, s))
    return int(s)


# ---- the 64-bit vertex path (issue 13) ---------------------------------------
# Polygon fills take subpixel_bits up to 32 and coordinates up to 2**28
# pixels through rast_polygon64 (algorithm "aet", exact rounding, boundary
# "exact" or "conservative"); below 17 bits and inside the 32-bit range
# (|v| * 2**S < 2**27 - 1) both paths give the same pixels, so the 64-bit
# one is taken only when S or a coordinate needs it.

#: Largest |coordinate| of the 64-bit path, in pixels (exclusive).
WIDE_PIXELS = 2 ** lib.RAST_COORD64_PIXEL_BITS


def can_wide(opts):
    """Can the 64-bit path draw a fill with these options?"""
    return (opts.algorithm == lib.RAST_ALGO_AET and opts.rounding == lib.RAST_ROUND_EXACT
            and opts.boundary != lib.RAST_BOUNDARY_CLOSED)


def use_wide(opts, pts):
    """Take the 64-bit path for float64 (N, 2) points `pts` with `opts`?
    Yes when S is above 16, or when a coordinate is past the 32-bit range
    (or not finite: the 64-bit snapping names it as well) and the options
    allow it."""
    if opts.subpixel_bits > lib.RAST_MAX_SUBPIXEL_BITS:
        return True
    if not can_wide(opts) or not len(pts):
        return False
    return bool(lib.rastpy_needs_wide(ffi.from_buffer("double[]", pts), len(pts), opts.subpixel_bits))


def sample_code(sample_offset):
    """RAST_SAMPLE_* for a sample offset of 0.5 or 0, or InputError."""
    sample = None
    if isinstance(sample_offset, numbers.Real) and not isinstance(sample_offset, (bool, np.bool_)):
        try:
            sample = SAMPLE_OFFSETS.get(float(sample_offset))
        except OverflowError:  # an int past float64
            sample = None
    if sample is None:
        raise InputError("sample_offset must be 0.5 (pixel centres) or 0, not %r" % (sample_offset,))
    return sample


def rounding_code(rounding):
    return ROUNDINGS[_name(rounding, "rounding", ROUNDINGS)]


def boundary_code(boundary):
    return BOUNDARIES[_name(boundary, "boundary", BOUNDARIES)]


# Every snapping boundary, (m - 1/2) / 2**S for S in 0..RAST_MAX_SUBPIXEL_BITS,
# is a multiple of 2**-GRID_BITS.
GRID_BITS = 17
_GRID = 1 << GRID_BITS
_NEAR_RANGE = 1 << 28  # past RAST_COORD_MAX pixels at every S
# The 64-bit path's boundaries (S up to 32) are multiples of 2**-33; a
# point between two of them, g + 2**-34, is a float64 while |v| < 2**19.
GRID64_BITS = 33
_GRID64 = 1 << GRID64_BITS
_NEAR64 = 1 << 19


def exact_double(v):
    """A float64 that snaps, at every subpixel_bits S in 0..16, as the exact
    value of `v` does: floor(v * 2**S + 1/2) in exact arithmetic; and at
    every S in 0..32 (the 64-bit path) where |v| < 2**19 pixels.  (Past
    2**19 pixels no float64 can stand for every value at S > 16: there a
    value between two 2**-33 grid points snaps as the float64 given.)

    `v` is an int (any size), a Fraction, a Decimal, a numpy float of any
    width (longdouble) or another real number.  A float64 is itself.  An
    exact value on the 2**-17 grid (every boundary lies on it) is
    representable and returned as it is; any other lies strictly between
    two grid points g < v < g + 2**-17, and so does g + 2**-18, which is
    returned: it is on the same side of every boundary as v.  Values far
    outside the range (|v| >= 2**28) come back as a float64 that is outside
    it too (+-1.8e308 when they do not fit one).  Raises TypeError for
    anything else: bools, strings, complex, None."""
    if isinstance(v, (bool, np.bool_)) or isinstance(v, (str, bytes)):
        raise TypeError("not a real number")
    if type(v) is float or isinstance(v, np.float64):
        return float(v)
    if isinstance(v, decimal.Decimal):
        if v.is_nan():  # float() refuses a signalling NaN
            return math.nan
        if v.is_infinite():
            return float(v)
        exact = fractions.Fraction(v)
    elif isinstance(v, np.floating):
        if not np.isfinite(v):
            return float(v)
        exact = fractions.Fraction(*v.as_integer_ratio())
    elif isinstance(v, (numbers.Rational, np.integer)):
        exact = fractions.Fraction(int(v)) if isinstance(v, np.integer) else fractions.Fraction(v)
    elif isinstance(v, numbers.Real):
        return float(v)
    else:
        raise TypeError("not a real number")
    if abs(exact) >= _NEAR_RANGE:
        try:
            return float(exact)
        except OverflowError:
            return 1.7976931348623157e308 if exact > 0 else -1.7976931348623157e308
    grid = _GRID64 if abs(exact) < _NEAR64 else _GRID
    t = exact * grid
    f = math.floor(t)
    if f == t:
        return float(exact)  # at most 28 + 17 (or 19 + 33) bits: exact
    return (f + 0.5) / grid


def _exact_array(a, what, shape_text):
    """An object or long-double array as float64 through exact_double."""
    flat = a.reshape(-1)
    out = np.empty(flat.shape, np.float64)
    try:
        for i, v in enumerate(flat):
            out[i] = exact_double(v)
    except TypeError:
        raise InputError("%s must be %s of real numbers, not %r (%s)"
                         % (what, shape_text, v, type(v).__name__)) from None
    return out.reshape(a.shape)


def as_numpy(x):
    """np.asarray(x), with a memoryview (or another buffer) read through
    numpy rather than iterated (a 2-D memoryview cannot be)."""
    if isinstance(x, memoryview):
        return np.asarray(x)
    return x


def ndim(x):
    """np.ndim(x), or -1 for what numpy cannot make an array of (ragged,
    recursive or too deeply nested lists): the caller's general path then
    refuses it with an InputError naming the argument."""
    try:
        return np.ndim(x)
    except (ValueError, TypeError, OverflowError, RecursionError):
        return -1


def has_bool(x):
    """Is there a bool (Python's or numpy's) in the nested lists/tuples x?"""
    types = set(map(type, x))
    if bool in types or np.bool_ in types:
        return True
    return any(has_bool(v) for v in x if type(v) in (list, tuple)) if (list in types or tuple in types) else False


def real_array(x, what, shape_text):
    """`x` as a float64 array, C-contiguous (a copy when it is not), or
    InputError naming `what`: coordinates must be real numbers (ints of any
    size, floats of any width, Fraction, Decimal; bool, complex, strings and
    None are refused, not converted, also inside object arrays).  Values
    that are not float64 are converted by exact_double, so that they snap
    as their exact value does."""
    if x is None:
        raise InputError("%s must be %s of numbers, not None" % (what, shape_text))
    try:
        a = np.asarray(x)
    except (TypeError, ValueError, OverflowError):  # e.g. ragged nesting
        raise InputError("%s must be %s of numbers" % (what, shape_text)) from None
    kind = a.dtype.kind
    if kind in "iuf" and isinstance(x, (list, tuple)) and has_bool(x):
        # numpy reads a bool among numbers as 0 / 1 (docs/bad-input.md)
        raise InputError("%s must be %s of real numbers (int or float), not bools" % (what, shape_text))
    if kind == "O" or (kind == "f" and a.dtype.itemsize > 8):
        return _exact_array(a, what, shape_text)
    if kind not in "iuf":
        raise InputError("%s must be %s of real numbers (int or float), not dtype %s"
                         % (what, shape_text, a.dtype))
    if not a.ndim:  # a number where an array is needed: shape () for the caller to refuse
        return np.array(a, np.float64)  # (ascontiguousarray would make it (1,), one coordinate)
    # aligned too: the C glue reads doubles, and a view at an odd address
    # (np.frombuffer with an offset) is C-contiguous but not aligned
    return np.require(a, np.float64, ("C", "A"))


def count_array(x, what):
    """`x` (ring sizes, rings per polygon) as a C-contiguous 1-D uint32
    array of counts, or InputError naming `what`: ints in 0..2**32 - 1
    only (float counts, bools and strings are refused, not truncated)."""
    try:
        a = np.asarray(x)
    except (TypeError, ValueError, OverflowError):
        a = None
    if a is None or a.dtype.kind not in "iu" or (isinstance(x, (list, tuple)) and has_bool(x)):
        raise InputError("%s must be a 1-D list or array of ints (counts), not %s"
                         % (what, "dtype %s" % a.dtype if a is not None else type(x).__name__))
    if a.ndim != 1:
        raise InputError("%s must be 1-D, not shape %s" % (what, a.shape))
    if a.size and (int(a.min()) < 0 or int(a.max()) > 0xFFFFFFFF):
        raise InputError("%s must be counts in 0..2**32 - 1, not %d" % (what, int(a.min()) if a.min() < 0
                                                                       else int(a.max())))
    return np.ascontiguousarray(a, np.uint32)


def snap_points(xy, s, what="points"):
    """float (N, 2) array-like -> int32 (N, 2) array on the 1/2^s grid,
    snapped exactly as the fills snap; InputError names a bad point."""
    s = _subpixel_bits(s)
    pts = real_array(xy, what, "an (N, 2) array-like")
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise InputError("%s must have shape (N, 2), not %s" % (what, pts.shape))
    out = np.empty(pts.shape, np.int32)
    bad = lib.rastpy_snap_points(
        ffi.from_buffer("double[]", pts), len(pts), s, ffi.from_buffer("int32_t[]", out)
    )
    if bad >= 0:
        _check_glue(bad + 1, pts, s, what)
    return out


def _make_fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding="exact", boundary="exact"):
    _name(algorithm, "algorithm", POLYGON_ALGORITHMS)
    _name(rule, "fill rule", RULES)
    code, supported = POLYGON_ALGORITHMS[algorithm]
    if rule not in supported:
        raise InputError(
            "algorithm %r does not support the %r rule; algorithms that do: %s"
            % (
                algorithm,
                rule,
                ", ".join(a for a, (_, r) in POLYGON_ALGORITHMS.items() if rule in r),
            )
        )
    s = _subpixel_bits(subpixel_bits, lib.RAST_MAX_SUBPIXEL_BITS64)
    if s > lib.RAST_MAX_SUBPIXEL_BITS and (algorithm != "aet" or rounding != "exact"
                                           or boundary == "closed"):
        raise InputError(
            "subpixel_bits=%d: above %d bits (the 64-bit path) only algorithm='aet' with "
            "rounding='exact' and boundary 'exact' or 'conservative'; not algorithm=%r, "
            "rounding=%r, boundary=%r" % (s, lib.RAST_MAX_SUBPIXEL_BITS, algorithm, rounding, boundary))
    opts = ffi.new("rast_fill_opts *")
    opts.algorithm = code
    opts.rule = RULES[rule]
    opts.subpixel_bits = s
    opts.sample = sample_code(sample_offset)
    opts.rounding = rounding_code(rounding)
    opts.boundary = boundary_code(boundary)
    return opts


# Checked option structs by their arguments (and the arguments' types, so
# that True or 8.0 are still refused): a hit skips every check.  C only
# reads the structs, so threads may share them.
_OPTS_CACHE = {}


def cached_opts(kind, make, *args):
    """``make(*args)``, remembered under (kind, args, their types)."""
    key = (kind,) + args + tuple(type(a) for a in args)
    try:
        return _OPTS_CACHE[key]
    except (KeyError, TypeError, ValueError):  # ValueError: a writable memoryview
        pass
    opts = make(*args)
    if len(_OPTS_CACHE) < 4096:
        try:
            _OPTS_CACHE[key] = opts
        except (TypeError, ValueError):
            pass
    return opts


def fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding="exact", boundary="exact"):
    """A checked, read-only ``rast_fill_opts *``."""
    return cached_opts("polygon", _make_fill_opts, algorithm, rule, subpixel_bits, sample_offset,
                       rounding, boundary)


def deprecated(message, stacklevel=3):
    """Warn that a spelling will go in the next release (DeprecationWarning,
    pointing at the caller's line)."""
    warnings.warn(message + " (deprecated: it will be removed in the next release)", DeprecationWarning,
                  stacklevel=stacklevel)


def shading_precision(shading, precision, default="gouraud"):
    """The C precision name for the ``shading=`` / ``precision=`` pair:
    ``shading`` is "gouraud" or "flat" (what is interpolated), ``precision``
    "exact" or "fixed" (how).  ``precision="flat"`` is the old spelling of
    ``shading="flat"``: it still works, with a DeprecationWarning."""
    if isinstance(precision, str) and precision == "flat":
        deprecated('precision="flat" is now shading="flat"', stacklevel=4)
        shading = "flat"
    if shading is None:
        shading = default
    if not isinstance(shading, str) or shading not in ("gouraud", "flat"):
        raise InputError("unknown shading %r; choose one of: gouraud, flat" % (shading,))
    if shading == "flat":
        return "flat"
    if isinstance(precision, str) and precision not in ("exact", "fixed"):
        raise InputError("unknown precision %r; choose one of: exact, fixed" % (precision,))
    return precision


def int_pair(pair, not_pair, not_ints):
    """Two ints (numpy ints too, never bools) from `pair`, or InputError
    with the message `not_pair` or `not_ints` % (pair,)."""
    try:
        a, b = as_numpy(pair)
    except (TypeError, ValueError):
        raise InputError(not_pair % (pair,)) from None
    for v in (a, b):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
            raise InputError(not_ints % (pair,))
    return int(a), int(b)


_MAX_DIM = lib.RAST_MAX_DIM


def shape2(shape):
    """(H, W) as two ints >= 0, or InputError."""
    if type(shape) is tuple and len(shape) == 2:  # the common case, quickly
        h, w = shape
        if type(h) is int and type(w) is int and 0 <= h <= _MAX_DIM and 0 <= w <= _MAX_DIM:
            return shape
    h, w = int_pair(shape, "shape must be a pair (height, width), not %r",
                    "shape must hold two ints, not %r")
    for v in (h, w):
        if not 0 <= v <= lib.RAST_MAX_DIM:
            raise InputError("shape %r: each side must be in 0..%d" % (shape, lib.RAST_MAX_DIM))
    return int(h), int(w)


def _geo_mapping(obj):
    """The GeoJSON-like mapping of a shapely geometry, an object with
    ``__geo_interface__`` or a mapping with "type" and "coordinates";
    None for anything else."""
    gi = getattr(obj, "__geo_interface__", None)
    if gi is None and isinstance(obj, dict) and "type" in obj:
        gi = obj
    return gi


#: The error's words for a GeoJSON FeatureCollection given where a list of
#: features (or geometries) is expected.
FEATURE_COLLECTION = 'a GeoJSON FeatureCollection; pass the list of its features, fc["features"]'


def is_feature_collection(obj):
    """Is `obj` a GeoJSON FeatureCollection (a mapping, or an object whose
    ``__geo_interface__`` is one, as a GeoDataFrame's)?"""
    gi = obj if isinstance(obj, dict) else getattr(obj, "__geo_interface__", None)
    return isinstance(gi, dict) and gi.get("type") == "FeatureCollection"


def _geo_rings(gi, rings, holes):
    """Append the rings of a Polygon / MultiPolygon / GeometryCollection
    mapping to `rings`, and whether each is a hole to `holes`."""
    kind = gi.get("type")
    if kind == "Polygon":
        for k, r in enumerate(gi["coordinates"]):
            rings.append(r)
            holes.append(k > 0)
    elif kind == "MultiPolygon":
        for poly in gi["coordinates"]:
            _geo_rings({"type": "Polygon", "coordinates": poly}, rings, holes)
    elif kind == "GeometryCollection":
        for g in gi["geometries"]:
            _geo_rings(g, rings, holes)
    elif kind == "FeatureCollection":
        raise InputError("rings: got %s" % FEATURE_COLLECTION)
    else:
        raise InputError("rings: a %s geometry has no area to fill; Polygon, MultiPolygon or "
                         "GeometryCollection of them are needed" % (kind,))


def _ring_list(rings, holes=None):
    """A list of rings from one (N, 2) ring, an (N, 1, 2) OpenCV contour, a
    shapely / __geo_interface__ polygon, or a sequence of rings.  With
    `holes` (a list), whether each ring is a hole (geometries' interiors) is
    appended to it."""
    gi = _geo_mapping(rings)
    if gi is not None:
        out, flags = [], []
        _geo_rings(gi, out, flags)
        if holes is not None:
            holes.extend(flags)
        return out
    rings = as_numpy(rings)
    if isinstance(rings, np.ndarray):
        if rings.ndim == 2:
            out = [rings]
        elif rings.ndim == 3 and rings.shape[1:] == (1, 2):
            out = [rings]  # one OpenCV contour
        elif rings.ndim == 3:
            out = list(rings)
        else:
            raise InputError("rings must be an (N, 2) array, an (N, 1, 2) contour or a list of them, "
                             "not shape %s" % (rings.shape,))
    else:
        try:
            out = list(rings)
        except TypeError:
            raise InputError("rings must be an (N, 2) array-like or a list of them, not %s"
                             % type(rings).__name__) from None
        if out and ndim(out[0]) == 0 and not isinstance(out[0], (str, bytes)) and out[0] is not None:
            raise InputError("rings: got a flat list of %s (shape (%d,)); a ring needs shape "
                             "(N, 2); for a COCO polygon [x0, y0, x1, y1, ...] use "
                             "rastrum.coco.rings(segmentation)" % (plural(len(out), "number"), len(out)))
        if out and ndim(out[0]) == 1:
            out = [out]  # one ring given as a list of (x, y) pairs
        else:
            flat = []
            for r in out:  # geometries among the rings
                g = _geo_mapping(r)
                if g is None:
                    flat.append(r)
                    if holes is not None:
                        holes.append(False)
                else:
                    _geo_rings(g, flat, holes if holes is not None else [])
            return flat
    if holes is not None:
        holes.extend([False] * len(out))
    return out


def rings_f64(rings, holes=None):
    """The rings as checked, C-contiguous float64 (N, 2) arrays (an
    (N, 1, 2) contour is reshaped).  A ring of no points is nothing
    (dropped): empty input draws nothing; rings of 1 or 2 points are kept
    and enclose nothing.  With `holes` (a list), whether each kept ring is
    a hole is put there."""
    arrays = []
    flags = [] if holes is not None else None
    ring_list = _ring_list(rings, flags)
    for k, ring in enumerate(ring_list):
        if type(ring) is np.ndarray and ring.dtype == _F64 and ring.ndim == 2 and ring.shape[1:] == (2,) \
                and ring.flags.c_contiguous and ring.flags.aligned:
            a = ring
        else:
            a = real_array(ring, "rings: ring %d" % k, "an (N, 2) array-like")
        if a.size == 0 and a.ndim <= 2:
            continue  # [] or np.zeros((0, 2))
        if a.ndim == 3 and a.shape[1:] == (1, 2):
            a = a.reshape(-1, 2)
        if a.ndim != 2 or a.shape[1] != 2:
            raise InputError("rings: ring %d has shape %s; a ring needs shape (N, 2) (or (N, 1, 2), an "
                             "OpenCV contour)" % (k, a.shape))
        arrays.append(a)
        if holes is not None:
            holes.append(flags[k])
    return arrays


def format_stride(fmt, width):
    """Bytes of a packed row of `width` pixels of format code `fmt`."""
    out = ffi.new("int32_t *")
    _check(lib.rast_format_stride(fmt, width, out))
    return out[0]


def make_target(array, fmt, width=None):
    """A ``rast_target *`` over a checked uint8 array.  The target holds a
    raw pointer: keep `array` alive as long as the target is used.

    The caller has checked: the format's dtype (uint8; uint16 for rgb565),
    writable, pixels of each row contiguous, a positive row stride.  For
    mono1 `array` is (H, ceil(W/8)) packed bytes and `width` is W.  Sub-views (strided rows) are fine: C only ever
    touches the H x W pixels, never the bytes between rows.
    """
    h, w = array.shape[0], array.shape[1]
    if width is not None:  # mono1: the array holds packed bytes, not pixels
        w = width
    stride = array.strides[0] if h > 1 else format_stride(fmt, w)
    if abs(stride) > INT32_MAX:
        raise InputError("the array's row stride, %d bytes, does not fit the core's int32 "
                         "stride (at most 2**31-1): copy the array first" % stride)
    if not array.size:
        pixels = ffi.NULL
    elif array.flags.c_contiguous:
        pixels = ffi.from_buffer(array, require_writable=True)
    else:
        pixels = ffi.cast("void *", array.__array_interface__["data"][0])
    target = ffi.new("rast_target *")
    _check(lib.rast_target_init(target, pixels, w, h, stride, fmt))
    return target


#: The array dtypes packed_rings takes (by identity: numpy's float64 and
#: int32, native order), whose values real_array gives as they are.
_RING_DTYPES = (np.dtype(np.float64), np.dtype(np.int32))


def packed_rings(rings):
    """(float64 (N, 2) points, ring sizes or NULL, number of rings) of a list
    in a common form, read in one C pass (rastrum._seq.rings: a list of
    float64 or int32 (N, 2) arrays, none empty, or of (x, y) pairs, or of
    rings of pairs); None for anything else, which _points checks.  No
    point is checked here: the C call refuses a bad one, and the caller
    then takes the general path, which names it."""
    got = _packed(rings)
    if got is None:
        return None
    raw, sizes = got
    pts = np.frombuffer(raw, _F64).reshape(-1, 2)
    if sizes is None:
        return pts, ffi.NULL, 1
    return pts, _from_buffer(_UINT32S, sizes), len(sizes) >> 2


def packed_call(rings):
    """packed_rings' rings as one C call takes them: (the points as a
    ``double[]`` cdata, their number, ring sizes or NULL, number of rings),
    or None.  No numpy array is made of the points (a quick path's call
    needs their memory and count only; its errors go to the general path,
    which packs them again and names the bad point)."""
    got = _packed(rings)
    if got is None:
        return None
    raw, sizes = got
    if sizes is None:
        return _from_buffer(_DOUBLES, raw), len(raw) >> 4, ffi.NULL, 1
    return _from_buffer(_DOUBLES, raw), len(raw) >> 4, _from_buffer(_UINT32S, sizes), len(sizes) >> 2


def _packed(rings):
    """(bytearray of float64 (x, y) pairs, bytearray of uint32 ring sizes or
    None for one ring) of a list _seq.rings reads, at most RAST_MAX_POINTS
    points; None for anything else."""
    got = _seq.rings(rings, np.ndarray, _RING_DTYPES) if type(rings) is list else None
    if got is None or len(got[0]) > _MAX_POINTS_BYTES:
        return None
    return got


_from_buffer, _DOUBLES, _UINT32S = ffi.from_buffer, ffi.typeof("double[]"), ffi.typeof("uint32_t[]")
_MAX_POINTS_BYTES = 16 * lib.RAST_MAX_POINTS  # two float64 a point


def _points(rings):
    """(float64 (N, 2) points, ring sizes as a cdata or NULL for one ring)."""
    quick = packed_rings(rings)
    if quick is not None:
        return quick
    arrays = rings_f64(rings)
    if len(arrays) == 1:
        pts, sizes = arrays[0], ffi.NULL
    elif arrays:
        pts, sizes = np.concatenate(arrays), ffi.new("uint32_t[]", [len(a) for a in arrays])
    else:
        pts, sizes = np.zeros((0, 2)), ffi.NULL
    if pts.shape[0] > lib.RAST_MAX_POINTS:
        raise InputError("%d points; at most %d per call" % (pts.shape[0], lib.RAST_MAX_POINTS))
    return pts, sizes, len(arrays)


_F64 = np.dtype(np.float64)


def bad_point_message(what, pts, k, s, sizes=None, wide=False):
    """Why point k of `pts` (float64 (N, 2)) was refused: NaN, infinite or
    out of range at subpixel_bits=s.  With `sizes` (the ring sizes), say
    which ring and point; with sizes an int (3), which triangle and vertex."""
    x, y = pts[k].tolist()
    where = "point %d " % k if len(pts) > 1 else ""
    if isinstance(sizes, int):
        where = "triangle %d, vertex %d " % (k // sizes, k % sizes)
    elif sizes is not None:
        ring = 0
        while k >= sizes[ring]:
            k -= sizes[ring]
            ring += 1
        where = "ring %d, point %d " % (ring, k)
    if x != x or y != y:
        why = "is NaN, not a finite number"
    elif x in (_INF, -_INF) or y in (_INF, -_INF):
        why = "is infinite, not a finite number"
    elif wide:
        why = ("is outside the range +-%r pixels (|coordinate| must stay below 2**28 pixels "
               "at every subpixel_bits; subpixel_bits=%d)" % (((1 << (s + lib.RAST_COORD64_PIXEL_BITS)) - 1) / float(1 << s), s))
    else:
        # the limit exactly (a dyadic float's repr is exact): at S = 10 it is
        # 131071.9990234375, which %g would print as 131072
        why = ("is outside the range +-%r pixels (|coordinate| * 2**subpixel_bits must stay "
               "below 2**27; subpixel_bits=%d)" % (lib.RAST_COORD_MAX / float(1 << s), s))
    return "%s: %s(%r, %r) %s" % (what, where, x, y, why)


_INF = float("inf")


def _check_glue(result, pts, s, what="points", sizes=None, wide=False):
    """Raise for a rastpy_* result (see _build.py)."""
    if result == 0:
        return
    if result > 0:
        raise InputError(bad_point_message(what, pts, result - 1, s, sizes, wide))
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for the scratch of %d points" % len(pts))
    _check(result)


def fill_polygon(target, rings, pixel, opts, s):
    """Snap `rings` to 1/2^s pixel and fill them into `target` with the pixel
    bytes `pixel`.  Checks everything before a pixel is written."""
    pts, sizes, nrings = _points(rings)
    if not nrings:
        return
    xy = ffi.from_buffer("double[]", pts)
    wide = use_wide(opts, pts)
    result = (lib.rastpy_fill_polygon64 if wide else lib.rastpy_fill_polygon)(
        target, xy, len(pts), sizes, nrings, opts, pixel, ffi.NULL)
    if result:
        _check_glue(result, pts, s, "rings", [len(pts)] if nrings == 1 else sizes, wide)


def mask_polygon(shape, rings, opts, s):
    """A new bool (H, W) mask of the polygon (bytes 1 inside, 0 outside).

    The array starts uninitialised: C writes every byte exactly once, which
    saves the clearing pass np.zeros would make."""
    h, w = shape
    if (
        type(rings) is np.ndarray  # one float64 ring: straight to C
        and rings.dtype == _F64
        and rings.ndim == 2
        and rings.shape[1] == 2
        and rings.shape[0] >= 3
        and rings.flags.c_contiguous
        and rings.flags.aligned  # C reads doubles: not a view at an odd address
    ):
        pts, sizes, nrings = rings, ffi.NULL, 1
    else:
        pts, sizes, nrings = _points(rings)
        if not nrings:
            return np.zeros(shape, bool)
    mask = np.empty(shape, bool)
    wide = use_wide(opts, pts)
    result = (lib.rastpy_mask_polygon64 if wide else lib.rastpy_mask_polygon)(
        ffi.from_buffer(mask) if h and w else ffi.NULL, h, w,
        ffi.from_buffer("double[]", pts), len(pts), sizes, nrings, opts,
    )
    if result:
        _check_glue(result, pts, s, "rings", [len(pts)] if nrings == 1 else sizes, wide)
    return mask


INT32_MAX = 2**31 - 1


def fill_polygon_gouraud(target, rings, colors, opts, shade, s, blend=None):
    """As fill_polygon, with RGBA `colors` (uint8 (N, 4), one per vertex of
    the rings in order) interpolated by the AET (rast_fill_polygon_gouraud;
    `blend` a ``rast_blend_opts *``: rast_fill_polygon_gouraud_blend)."""
    pts, sizes, nrings = _points(rings)
    if not nrings:
        return
    if s > lib.RAST_MAX_SUBPIXEL_BITS:
        raise InputError("vertex_colors: subpixel_bits must be in 0..%d for a shaded fill, not %d"
                         % (lib.RAST_MAX_SUBPIXEL_BITS, s))
    if colors.shape != (len(pts), 4):
        raise InputError("vertex_colors: %s for %s" % (plural(colors.shape[0], "colour"),
                                                        plural(len(pts), "vertex", "vertices")))
    xy = ffi.from_buffer("double[]", pts)
    _check_glue(lib.rastpy_fill_polygon_gouraud(target, xy, len(pts), sizes, nrings, opts,
                                                ffi.from_buffer("uint8_t[]", colors), shade,
                                                blend if blend is not None else ffi.NULL), pts, s,
                "rings", [len(pts)] if nrings == 1 else sizes)



# ---- region fill ---------------------------------------------------------------

# Stack for the span seed fill: what rast_seed_stack_size guarantees, but at
# most this many bytes (np.empty does not touch the pages it does not use,
# so a fill pays only for the depth it reaches); if even that cannot be
# had, SEED_STACK_FALLBACK.  Less is still exact: the C fill goes on in
# fixed memory, only slower.
SEED_STACK_CAP = 1 << 30
SEED_STACK_FALLBACK = 1 << 26


def seed_point(seed, target):
    """(x, y) ints inside the target, or InputError."""
    x, y = int_pair(seed, "seed must be a pair (x, y), not %r",
                    "seed must hold two ints (pixel column, row), not %r")
    if not (0 <= x < target.width and 0 <= y < target.height):
        raise InputError("seed %r is outside the %d x %d canvas" % (seed, target.width, target.height))
    return x, y


def seed_fill(target, seed, pixel, boundary, connectivity, stack_bytes=None):
    """rast_flood_fill (boundary None) or rast_boundary_fill into `target`.

    `stack_bytes` None: what the clip needs, up to SEED_STACK_CAP."""
    x, y = seed_point(seed, target)
    # an integer 4 or 8 only: `in` would compare an array element-wise
    # (and raise numpy's "truth value ... ambiguous" instead of saying which)
    if (isinstance(connectivity, (bool, np.bool_)) or not isinstance(connectivity, (int, np.integer))
            or connectivity not in (4, 8)):
        raise InputError("connectivity must be 4 or 8, not %r" % (connectivity,))
    if stack_bytes is None:
        need = ffi.new("size_t *")
        _check(lib.rast_seed_stack_size(target.clip.x1 - target.clip.x0,
                                        target.clip.y1 - target.clip.y0, need))
        stack_bytes = min(need[0], SEED_STACK_CAP)
    try:
        stack = np.empty((stack_bytes + 7) // 8, np.uint64)
    except MemoryError:
        stack_bytes = min(stack_bytes, SEED_STACK_FALLBACK)
        stack = np.empty((stack_bytes + 7) // 8, np.uint64)
    mem = ffi.from_buffer(stack) if stack_bytes else ffi.NULL
    if boundary is None:
        _check(lib.rast_flood_fill(target, x, y, pixel, int(connectivity), mem, stack_bytes))
    else:
        _check(lib.rast_boundary_fill(target, x, y, pixel, boundary, int(connectivity), mem, stack_bytes))
