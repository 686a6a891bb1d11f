"""The thin layer between Python and the C core: checks, snapping, errors.

Everything here is private.  It validates arguments (before any pixel is
written), snaps float coordinates to the 1/2^S grid, builds the C structs
and translates status codes into exceptions.
"""

import functools

import numpy as np

from ._native import ffi, lib


class RastrumError(Exception):
    """An error reported by the rastrum C core."""


class InputError(RastrumError, ValueError):
    """Bad input: the message says which argument and why."""


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
_RULE_NAMES = {v: k for k, v in RULES.items()}
SAMPLE_OFFSETS = {0.5: lib.RAST_SAMPLE_CENTER, 0.0: lib.RAST_SAMPLE_CORNER}
FORMATS = {
    "gray8": lib.RAST_FORMAT_GRAY8,
    "rgb888": lib.RAST_FORMAT_RGB888,
    "rgba8888": lib.RAST_FORMAT_RGBA8888,
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
        _check(lib.rast_algorithm_info(code, name, rules))
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


def _subpixel_bits(s):
    if isinstance(s, (bool, np.bool_)) or not isinstance(s, (int, np.integer)):
        raise InputError("subpixel_bits must be an int, not %r" % (s,))
    if not 0 <= s <= lib.RAST_MAX_SUBPIXEL_BITS:
        raise InputError(
            "subpixel_bits must be in 0..%d, not %d" % (lib.RAST_MAX_SUBPIXEL_BITS, s)
        )
    return int(s)


@functools.lru_cache(maxsize=256)
def _fill_opts_cached(algorithm, rule, s, sample):
    opts = ffi.new("rast_fill_opts *")
    opts.algorithm = algorithm
    opts.rule = rule
    opts.subpixel_bits = s
    opts.sample = sample
    return opts


def fill_opts(algorithm, rule, subpixel_bits, sample_offset):
    """A checked, read-only ``rast_fill_opts *`` (shared: C only reads it)."""
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
    s = _subpixel_bits(subpixel_bits)
    try:
        sample = SAMPLE_OFFSETS.get(float(sample_offset))
    except (TypeError, ValueError):
        sample = None
    if sample is None or isinstance(sample_offset, (bool, np.bool_)):
        raise InputError("sample_offset must be 0.5 (pixel centres) or 0, not %r" % (sample_offset,))
    return _fill_opts_cached(code, RULES[rule], s, sample)


def shape2(shape):
    """(H, W) as two ints >= 0, or InputError."""
    try:
        h, w = shape
    except (TypeError, ValueError):
        raise InputError("shape must be a pair (height, width), not %r" % (shape,)) from None
    for v in (h, w):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
            raise InputError("shape must hold two ints, not %r" % (shape,))
        if not 0 <= v <= lib.RAST_MAX_DIM:
            raise InputError("shape %r: each side must be in 0..%d" % (shape, lib.RAST_MAX_DIM))
    return int(h), int(w)


def _ring_list(rings):
    """A list of rings from one (N, 2) ring or a sequence of rings."""
    if isinstance(rings, np.ndarray):
        if rings.ndim == 2:
            return [rings]
        if rings.ndim == 3:
            return list(rings)
        raise InputError("rings must be an (N, 2) array or a list of them, not shape %s" % (rings.shape,))
    try:
        rings = list(rings)
    except TypeError:
        raise InputError("rings must be an (N, 2) array-like or a list of them") from None
    if rings and np.ndim(rings[0]) == 1:
        return [rings]  # one ring given as a list of (x, y) pairs
    return rings


def snap(rings, s):
    """Snap rings to 1/2^s pixel: (points int32 (N, 2), ring sizes uint32).

    v_fixed = floor(v * 2^s + 1/2), exact in float64 (scaling by a power of
    two and adding 1/2 lose nothing at these magnitudes).
    """
    arrays = []
    for k, ring in enumerate(_ring_list(rings)):
        try:
            a = np.asarray(ring, dtype=np.float64)
        except (TypeError, ValueError):
            raise InputError("ring %d is not an (N, 2) array of numbers" % k) from None
        if a.ndim != 2 or a.shape[1] != 2:
            raise InputError("ring %d must have shape (N, 2), not %s" % (k, a.shape))
        if a.shape[0] < 3:
            raise InputError("ring %d has %d points; a ring needs at least 3" % (k, a.shape[0]))
        arrays.append(a)
    if not arrays:
        return np.zeros((0, 2), np.int32), np.zeros(0, np.uint32)
    pts = arrays[0] if len(arrays) == 1 else np.concatenate(arrays)
    scaled = np.floor(pts * float(1 << s) + 0.5)
    limit = lib.RAST_COORD_MAX
    bad = ~(np.abs(scaled) <= limit)  # also catches NaN
    if bad.any():
        idx = int(np.flatnonzero(bad.any(axis=1))[0])
        raise InputError(
            "point %s is not finite or outside +-%.6g pixels, the range at subpixel_bits=%d"
            % (tuple(pts[idx].tolist()), limit / float(1 << s), s)
        )
    if len(pts) > lib.RAST_MAX_POINTS:
        raise InputError("%d points; at most %d per call" % (len(pts), lib.RAST_MAX_POINTS))
    sizes = np.fromiter((len(a) for a in arrays), dtype=np.uint32, count=len(arrays))
    return np.ascontiguousarray(scaled, dtype=np.int32), sizes


def make_target(array, fmt):
    """A ``rast_target *`` over a checked uint8 array (kept alive by the
    returned cdata's owner: hold both while C runs).

    The caller has checked: uint8, writable, pixels of each row contiguous,
    a positive row stride.  Sub-views (strided rows) are fine: C only ever
    touches the H x W pixels, never the bytes between rows.
    """
    h, w = array.shape[0], array.shape[1]
    bpp = FORMAT_BYTES_BY_CODE[fmt]
    stride = array.strides[0] if h > 1 else w * bpp
    pixels = ffi.cast("void *", array.__array_interface__["data"][0]) if array.size else ffi.NULL
    target = ffi.new("rast_target *")
    _check(lib.rast_target_init(target, pixels, w, h, stride, fmt))
    return target


def fill_polygon(target, rings, pixel, opts, s):
    """Fill `rings` into `target` with the pixel bytes `pixel`."""
    pts, sizes = snap(rings, s)
    poly = ffi.new("rast_polygon *")
    poly.points = ffi.cast("rast_point *", ffi.from_buffer(pts)) if len(pts) else ffi.NULL
    poly.ring_sizes = ffi.cast("uint32_t *", ffi.from_buffer(sizes)) if len(sizes) else ffi.NULL
    poly.nrings = len(sizes)
    size = ffi.new("size_t *")
    clip = target.clip
    _check(lib.rast_scratch_size(opts, len(pts), clip.x1 - clip.x0, clip.y1 - clip.y0, size))
    scratch = np.empty(size[0], np.uint8)
    _check(lib.rast_fill_polygon(target, poly, opts, pixel, ffi.from_buffer(scratch), size[0]))


FORMAT_BYTES_BY_CODE = {code: FORMAT_BYTES[name] for name, code in FORMATS.items()}
