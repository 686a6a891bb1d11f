"""Issue 5: ONE table of every public entry point x bad input.

Each row says what a call with that input must do: raise the documented
exception with a message matching a regex (which names the argument where
there is one), or work (non-contiguous, read-only or integer input: the
same pixels as the plain float64 call), or draw nothing (empty input).
Every row runs against a canvas wrapped around a slice of a larger
guard-patterned array, and the whole array must be byte-for-byte what it
should be afterwards: untouched when the call raised.  The caller's input
arrays must be unchanged too.

To cover a new entry point, add one ``Entry`` to ENTRIES: its geometry kind
and options decide which generic rows apply; add explicit rows for inputs
of its own.
"""

import decimal
import fractions
import math
import re

import warnings

import numpy as np
import pytest

import rastrum
from rastrum._native import lib

NAN, INF = float("nan"), float("inf")
SHAPE = (10, 12)
COLOR = (10, 20, 30)
PAST_RANGE = (lib.RAST_COORD_MAX + 1) / 256.0  # just past the range at S = 8
AT_RANGE = lib.RAST_COORD_MAX / 256.0           # the last coordinate in it
# The polygon fills (polygon_mask, Canvas.fill_polygon with a colour) take
# the 64-bit path past the 32-bit range: their range is +-2**28 pixels at
# every subpixel_bits, and their subpixel_bits go up to 32.
PAST_RANGE64 = float(2 ** lib.RAST_COORD64_PIXEL_BITS)  # snaps to 2**(S+28) > the limit
AT_RANGE64 = (2 ** (8 + lib.RAST_COORD64_PIXEL_BITS) - 1) / 256.0

# Good geometry of each kind, as a tuple of the geometric arguments; the
# generic rows change the LAST one (named ARG[kind] in messages).
GOOD = {
    "ring": (np.array([(1.5, 1.0), (10.0, 2.25), (4.0, 8.5), (2.0, 6.0)]),),
    "tris": (np.array([[(1.5, 1.0), (10.0, 2.25), (4.0, 8.5)], [(0, 0), (5, 0), (0, 5)]], float),),
    "tri": (np.array([(1.5, 1.0), (10.0, 2.25), (4.0, 8.5)]),),
    "seg": (np.array([1.0, 1.5]), np.array([10.25, 7.0])),
    "points": (np.array([(1.0, 1.0), (10.0, 3.0), (4.0, 8.0)]),),
    "ptri": (np.array([3.0, 3.0]), np.array([(1.5, 1.0), (10.0, 2.25), (4.0, 8.5)])),
    "rect": (np.array([1.5, 1.0, 9.0, 8.5]),),
    "seed": (np.array([3, 4]),),
}
ARG = {"ring": r"\brings\b", "tris": r"\btris\b", "tri": r"\btri\b", "seg": r"\bp1\b",
       "points": r"\bpoints\b", "ptri": r"\btri\b",
       "rect": r"\brect\b", "seed": r"\bseed\b"}
# The shading calls' good colours and depths, for the geometry above.
VCOLORS = np.array([[(255, 0, 0), (0, 255, 0), (0, 0, 255)], [(9, 9, 9), (200, 100, 0), (0, 50, 250)]])
RCOLORS = np.array([(255, 0, 0), (0, 255, 0), (0, 0, 255), (90, 90, 90)])
PCOLORS = np.array([(255, 0, 0), (0, 255, 0), (0, 0, 255), (90, 90, 90)])
DEPTHS = np.array([(1.0, 2.0, 3.0), (-5.0, 0.0, 8.0)])
EDGE = (1, 2, 3)


def _fit(colors, g):
    """The first len(g) rows of `colors` (one per triangle), when g has a
    length (so that an empty batch gets no colours): the colour rows must
    not be what fails in a geometry row."""
    try:
        return colors[:min(len(g), len(colors))]
    except TypeError:
        return colors


class Entry:
    """A public entry point: how to call it with geometry `g` (a tuple as in
    GOOD) on canvas `c`, and which options it takes."""

    def __init__(self, name, kind, call, options=(), canvas=False, color=False, shape=False,
                 wide=False):
        self.name, self.kind, self.call = name, kind, call
        self.options, self.canvas, self.color, self.shape = set(options), canvas, color, shape
        self.wide = wide  # the 64-bit vertex path: S up to 32, +-2**28 pixels ("area": method area only)


FILL = ("algorithm", "subpixel_bits", "sample_offset", "rounding", "boundary")
ENTRIES = [
    Entry("polygon_mask", "ring", lambda c, g, kw: rastrum.polygon_mask(g[0], kw.pop("shape", SHAPE), **kw),
          FILL + ("rule",), shape=True, wide=True),
    Entry("Canvas.fill_polygon", "ring", lambda c, g, kw: c.fill_polygon(g[0], kw.pop("color", COLOR), **kw),
          FILL + ("rule",), canvas=True, color=True, wide=True),
    Entry("triangles_mask", "tris", lambda c, g, kw: rastrum.triangles_mask(g[0], kw.pop("shape", SHAPE), **kw),
          FILL + ("mode",), shape=True),
    Entry("triangles_count", "tris", lambda c, g, kw: rastrum.triangles_count(g[0], kw.pop("shape", SHAPE), **kw),
          FILL, shape=True),
    Entry("Canvas.fill_triangles", "tris",
          lambda c, g, kw: c.fill_triangles(g[0], kw.pop("color", COLOR), **kw), FILL, canvas=True, color=True),
    Entry("Canvas.fill_triangle", "tri",
          lambda c, g, kw: c.fill_triangle(g[0], kw.pop("color", COLOR), **kw), FILL, canvas=True, color=True),
    Entry("Canvas.line", "seg", lambda c, g, kw: c.line(g[0], g[1], kw.pop("color", COLOR), **kw),
          ("algorithm", "subpixel_bits", "sample_offset"), canvas=True, color=True),
    Entry("Canvas.polyline", "points", lambda c, g, kw: c.polyline(g[0], kw.pop("color", COLOR), **kw),
          ("algorithm", "subpixel_bits", "sample_offset", "closed"), canvas=True, color=True),
    Entry("line_pixels", "seg", lambda c, g, kw: rastrum.line_pixels(g[0], g[1], **kw),
          ("algorithm", "subpixel_bits", "sample_offset", "clip")),
    Entry("point_in_triangle", "ptri", lambda c, g, kw: rastrum.point_in_triangle(g[0], g[1], **kw),
          ("method", "subpixel_bits")),
    # The shading calls (issue 4's Gouraud work) and the seed fills.
    Entry("Canvas.fill_triangles(vertex_colors)", "tris",
          lambda c, g, kw: c.fill_triangles(g[0], vertex_colors=kw.pop("vertex_colors", _fit(VCOLORS, g[0])), **kw),
          FILL + ("vertex_colors", "precision", "fraction_bits"), canvas=True),
    Entry("Canvas.fill_triangles(vertex_colors, aa)", "tris",
          lambda c, g, kw: c.fill_triangles(g[0], vertex_colors=kw.pop("vertex_colors", _fit(VCOLORS, g[0])),
                                            aa="area", **kw),
          ("subpixel_bits", "sample_offset", "vertex_colors"), canvas=True),
    Entry("Canvas.fill_triangles(color per triangle)", "tris",
          lambda c, g, kw: c.fill_triangles(g[0], kw.pop("color", _fit(VCOLORS[:, 0], g[0])), **kw), FILL, canvas=True),
    Entry("Canvas.fill_triangles(depth)", "tris",
          lambda c, g, kw: c.fill_triangles(g[0], vertex_colors=_fit(VCOLORS, g[0]),
                                            depth=kw.pop("depth", _fit(DEPTHS, g[0])), **kw),
          FILL + ("depth", "precision", "fraction_bits"), canvas=True),
    Entry("Canvas.fill_rect_gouraud", "rect",
          lambda c, g, kw: c.fill_rect_gouraud(g[0], kw.pop("corner_colors", RCOLORS), **kw),
          ("corner_colors", "precision", "fraction_bits", "subpixel_bits", "sample_offset", "method"), canvas=True),
    Entry("Canvas.fill_polygon(vertex_colors)", "ring",
          lambda c, g, kw: c.fill_polygon(g[0], vertex_colors=kw.pop("polygon_colors", PCOLORS), **kw),
          FILL + ("rule", "polygon_colors", "precision"), canvas=True),
    # coverage (docs/coverage.md); the rule's rows are in tests/test_coverage.py
    Entry("polygon_coverage", "ring",
          lambda c, g, kw: rastrum.polygon_coverage(g[0], kw.pop("shape", SHAPE), **kw),
          ("method", "subpixel_bits", "sample_offset", "dtype"), shape=True, wide="area"),
    Entry("triangles_coverage", "tris",
          lambda c, g, kw: rastrum.triangles_coverage(g[0], kw.pop("shape", SHAPE), **kw),
          ("method", "subpixel_bits", "sample_offset", "dtype"), shape=True),
    Entry("Canvas.flood_fill", "seed", lambda c, g, kw: c.flood_fill(g[0], kw.pop("color", COLOR), **kw),
          ("connectivity",), canvas=True, color=True),
    Entry("Canvas.boundary_fill", "seed",
          lambda c, g, kw: c.boundary_fill(g[0], kw.pop("color", COLOR), kw.pop("boundary_value", EDGE), **kw),
          ("connectivity", "boundary_value"), canvas=True, color=True),
]


def both(arg, problem):
    """A regex matching a message that names `arg` and says `problem`."""
    return r"(?is)(?=.*(?:%s))(?=.*(?:%s))" % (arg, problem)


def _set_last(value):
    """Put `value` into the last coordinate of the last argument."""
    def change(g):
        a = np.array(g[-1], dtype=float)
        a.reshape(-1)[-2] = value
        return g[:-1] + (a,)
    return change


def _replace(fn):
    return lambda g: g[:-1] + (fn(g[-1]),)


def _object_last(value):
    """The last argument as an object array (Python numbers) with `value`
    as its last coordinate (issue 18: never converted silently)."""
    def change(g):
        a = np.array(np.asarray(g[-1]).tolist(), dtype=object)
        a.reshape(-1)[-2] = value
        return g[:-1] + (a,)
    return change


def _as_objects(kind):
    """The last argument's values as exact objects of `kind` (Fraction,
    Decimal): the same values, so the same pixels."""
    def fn(a):
        a = np.asarray(a)
        return np.array([kind(v) for v in a.reshape(-1).tolist()], dtype=object).reshape(a.shape)
    return fn


def _strided(a):
    """The same values as a non-contiguous view (every other element)."""
    big = np.zeros(a.shape[:-1] + (2 * a.shape[-1],))
    big[..., ::2] = a
    view = big[..., ::2]
    assert not view.flags.c_contiguous
    return view


def _read_only(a):
    a = a.copy()
    a.setflags(write=False)
    return a


RAISE, SAME, NOTHING = "raises", "same", "nothing"

# Geometry rows: label -> (change, {kind: expectation}); an expectation is
# (RAISE, exception, problem regex) -- the argument's name is added -- or
# (SAME,) or (NOTHING,).  "*" is every kind not listed.
SHAPE_ERR = (RAISE, rastrum.InputError, r"shape|pair|three|at least")
# A seed is a pixel: two ints inside the canvas, never floats (even 3.0).
SEED_INTS = (RAISE, rastrum.InputError, r"two ints")
SEED_PAIR = (RAISE, rastrum.InputError, r"pair")
GEOMETRY = {
    "NaN": (_set_last(NAN), {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"\bNaN\b")}),
    "+inf": (_set_last(INF), {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"infinite")}),
    "-inf": (_set_last(-INF), {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"infinite")}),
    "huge 1e300": (_set_last(1e300), {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"range")}),
    "just past the range": (_set_last(PAST_RANGE),
                            {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"range")}),
    "-(just past the range)": (_set_last(-PAST_RANGE),
                               {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"range")}),
    "dtype complex": (_replace(lambda a: np.asarray(a, complex)),
                      {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"real numbers")}),
    "dtype bool": (_replace(lambda a: np.asarray(a) > 2),
                   {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"real numbers")}),
    "dtype str": (_replace(lambda a: np.asarray(a).astype(str)),
                  {"seed": SEED_INTS, "*": (RAISE, rastrum.InputError, r"real numbers|pair")}),
    "None": (_replace(lambda a: None), {"seed": SEED_PAIR, "*": (RAISE, rastrum.InputError, r"must")}),
    # Issue 18: Python ints of any size, bools and strings inside object
    # arrays, memoryviews, exact numbers.
    "int 2**1024": (_object_last(2 ** 1024), {"seed": (RAISE, rastrum.InputError, r"outside"),
                                              "*": (RAISE, rastrum.InputError, r"range")}),
    "-(int 2**1024)": (_object_last(-2 ** 1024), {"seed": (RAISE, rastrum.InputError, r"outside"),
                                                  "*": (RAISE, rastrum.InputError, r"range")}),
    "object array with a bool": (_object_last(True), {"seed": SEED_INTS,
                                                      "*": (RAISE, rastrum.InputError, r"real numbers.*bool")}),
    "object array with a str": (_object_last("1.5"), {"seed": SEED_INTS,
                                                      "*": (RAISE, rastrum.InputError, r"real numbers.*str")}),
    "object array with None": (_object_last(None), {"seed": SEED_INTS,
                                                    "*": (RAISE, rastrum.InputError, r"real numbers")}),
    "memoryview": (_replace(lambda a: memoryview(np.ascontiguousarray(a))), {"*": (SAME,)}),
    "Fraction objects": (_replace(_as_objects(fractions.Fraction)), {"seed": SEED_INTS, "*": (SAME,)}),
    "Decimal objects": (_replace(_as_objects(decimal.Decimal)), {"seed": SEED_INTS, "*": (SAME,)}),
    "longdouble": (_replace(lambda a: np.asarray(a, np.longdouble)), {"seed": SEED_INTS, "*": (SAME,)}),
    "wrong last axis (3)": (_replace(lambda a: np.concatenate([a, a[..., :1]], axis=-1)),
                            {"seed": SEED_PAIR, "*": SHAPE_ERR}),
    "too few vertices": (_replace(lambda a: a[..., :1] if a.ndim == 1 else a[:, :2] if a.ndim == 3
                                  else a[:2] if len(a) > 3 else a[:1]),
                         # A ring of 1 or 2 points draws nothing (as in C, rasterio, cv2, skia);
                         # it raised before issue 14.
                         {"ring": (NOTHING,), "seed": SEED_PAIR, "*": SHAPE_ERR}),
    "empty": (_replace(lambda a: a[:0]),
              {"ring": (NOTHING,), "tris": (NOTHING,), "points": (NOTHING,), "seed": SEED_PAIR, "*": SHAPE_ERR}),
    "empty list": (_replace(lambda a: []),
                   {"ring": (NOTHING,), "tris": (NOTHING,), "points": (NOTHING,), "seed": SEED_PAIR,
                    "*": SHAPE_ERR}),
    # Inputs that must work: the same pixels as the float64 call (a seed:
    # floats, even 3.0, are refused).
    "non-contiguous": (_replace(_strided), {"seed": SEED_INTS, "*": (SAME,)}),
    "read-only input": (_replace(_read_only), {"*": (SAME,)}),
    "Fortran order": (_replace(np.asfortranarray), {"*": (SAME,)}),
    "nested lists": (_replace(lambda a: np.asarray(a).tolist()), {"*": (SAME,)}),
    "float32": (_replace(lambda a: np.asarray(a, np.float32)), {"seed": SEED_INTS, "*": (SAME,)}),
}
# Integers and the edge of the range work too (compared with float64).
INT_ROWS = {
    "dtype int32": lambda a: np.round(a).astype(np.int32),
    "dtype uint8": lambda a: np.round(a).astype(np.uint8),
    "at the range": lambda a: np.where(np.arange(a.size).reshape(a.shape) == a.size - 2, AT_RANGE, a),
}

# Option rows: option -> [(bad value, problem regex)].
OPTIONS = {
    "algorithm": [("bogus", r"algorithm"), (None, r"algorithm"), (3, r"algorithm"), ("AET", r"algorithm")],
    "rule": [("bogus", r"rule"), (None, r"rule"), ("even-odd", r"rule")],
    "rounding": [("bogus", r"rounding"), (None, r"rounding")],
    "boundary": [("bogus", r"boundary"), (1, r"boundary")],
    "mode": [("bogus", r"mode"), (None, r"mode")],
    "dtype": [(np.int32, r"dtype"), ("bogus", r"dtype"), (bool, r"dtype")],
    "method": [("bogus", r"method"), (None, r"method")],
    "subpixel_bits": [(-1, r"subpixel"), (17, r"subpixel"), (8.0, r"subpixel"), (True, r"subpixel"),
                      (NAN, r"subpixel"), ("8", r"subpixel"), (None, r"subpixel")],
    "sample_offset": [(0.25, r"offset"), (1, r"offset"), (NAN, r"offset"), (INF, r"offset"),
                      ("0.5", r"offset"), (None, r"offset")],
    "clip": [((0, 0, 1), r"clip"), ((0, 0, 1.5, 2), r"clip"), ((0, 0, 2 ** 31, 1), r"clip"),
             ("abcd", r"clip"), ((0, 0, NAN, 1), r"clip")],
    "closed": [("yes", r"closed"), (None, r"closed"), (2, r"closed")],
    "color": [(256, r"colou?r"), (-1, r"colou?r"), ((1, 2), r"colou?r"), ((1, 2, 3, 4, 5), r"colou?r"),
              (1.5, r"colou?r"), (NAN, r"colou?r"), ("redd", r"colou?r .redd."), (None, r"colou?r"),
              ((1.5, 2, 3), r"colou?r"), ((0, 0, 256), r"colou?r"), (True, r"colou?r")],
    "vertex_colors": [(VCOLORS[:1], r"vertex_colors"), (VCOLORS + 0.5, r"vertex_colors"),
                      (VCOLORS * 2, r"vertex_colors.*0\.\.255"), (-VCOLORS, r"vertex_colors.*0\.\.255"),
                      (VCOLORS[..., :2], r"vertex_colors"), (None, r"vertex_colors|colou?r"),
                      ("red", r"vertex_colors")],
    "polygon_colors": [(PCOLORS[:3], r"vertex_colors.*3 colours for 4 vertices"),
                       (PCOLORS + 0.5, r"vertex_colors"), (PCOLORS * 2, r"vertex_colors.*0\.\.255"),
                       (-PCOLORS, r"vertex_colors.*0\.\.255"), (PCOLORS[:, :2], r"vertex_colors"),
                       ("red", r"vertex_colors")],
    "precision": [("bogus", r"precision"), (None, r"precision"), ("EXACT", r"precision")],
    "fraction_bits": [(8.0, r"fraction_bits"), (None, r"fraction_bits"), (True, r"fraction_bits")],
    "depth": [(DEPTHS[:1], r"depth"), (DEPTHS + NAN, r"depth"), (np.where(DEPTHS > 2, INF, DEPTHS), r"depth"),
              (DEPTHS * 1e300, r"depth"), (DEPTHS.astype(complex), r"depth"), ("near", r"depth")],
    "corner_colors": [(RCOLORS[:3], r"corner_colors"), (RCOLORS + 0.5, r"corner_colors"),
                      (RCOLORS * 2, r"corner_colors.*0\.\.255"), (None, r"corner_colors"),
                      ("red", r"corner_colors")],
    "connectivity": [(6, r"connectivity"), (0, r"connectivity"), (True, r"connectivity"),
                     ("4", r"connectivity"), (None, r"connectivity"), (4.5, r"connectivity")],
    "boundary_value": [(256, r"colou?r"), ((1, 2), r"colou?r"), (None, r"colou?r"), (NAN, r"colou?r")],
    "shape": [((-1, 5), r"shape"), ((5, -1), r"shape"), ((5,), r"shape"), ((1, 2, 3), r"shape"),
              ((1.5, 5), r"shape"), (None, r"shape"), ("ab", r"shape"), ((2 ** 31, 5), r"shape"),
              ((lib.RAST_MAX_DIM + 1, 1), r"shape"), ((NAN, 5), r"shape")],
}


def _expectation(table, kind):
    return table.get(kind, table.get("*"))


# The range rows of the entries on the 64-bit path: just past +-2**28 px.
WIDE_GEOMETRY = {
    "just past the range": _set_last(PAST_RANGE64),
    "-(just past the range)": _set_last(-PAST_RANGE64),
}
# Their subpixel_bits run to 32 (17 is good there), and above 16 they
# take only the options of the 64-bit path.
WIDE_OPTIONS = {
    "subpixel_bits": [(v, p) for v, p in OPTIONS["subpixel_bits"] if v != 17] + [(33, r"subpixel.*0\.\.32")],
}
WIDE_ROWS = {
    "subpixel_bits=24, algorithm=xscan": dict(subpixel_bits=24, algorithm="xscan"),
    "subpixel_bits=20, boundary=closed": dict(subpixel_bits=20, boundary="closed"),
    "subpixel_bits=17, rounding=textbook": dict(subpixel_bits=17, rounding="textbook"),
}

# polygon_coverage: "area" takes S up to 32 (rast_polygon_coverage64), the
# other methods 0..16.
AREA_WIDE_ROWS = {
    "subpixel_bits=17, method=ss4": dict(subpixel_bits=17, method="ss4"),
    "subpixel_bits=20, method=accumulate": dict(subpixel_bits=20, method="accumulate"),
}


def _rows():
    rows = []
    for e in ENTRIES:
        for label, (change, table) in GEOMETRY.items():
            if e.wide and label in WIDE_GEOMETRY:
                change = WIDE_GEOMETRY[label]
            exp = _expectation(table, e.kind)
            if exp[0] == RAISE:
                exp = (RAISE, exp[1], both(ARG[e.kind], exp[2]))
            if e.name == "Canvas.fill_polygon(vertex_colors)" and label == "too few vertices":
                # the 2-point ring is fine; its 4 colours are not
                exp = (RAISE, rastrum.InputError, r"vertex_colors: 4 colours for 2 vertices")
            rows.append((e.name, label, ("geometry", change, None), exp))
        for label, fn in INT_ROWS.items():
            if e.kind == "seed":  # ints are what a seed is; the range is the canvas
                rows.append((e.name, label, ("geometry", _replace(fn), None),
                             (RAISE, rastrum.InputError, both(ARG["seed"], "two ints")) if label == "at the range"
                             else (SAME,)))
                continue
            if e.kind == "rect" and label == "at the range":  # a side past 2**26 - 1 units
                rows.append((e.name, label, ("geometry", _replace(fn), None),
                             (RAISE, rastrum.InputError, both(ARG["rect"], "side"))))
                continue
            rows.append((e.name, label, ("geometry", _replace(fn), _replace(lambda a, fn=fn: np.asarray(fn(a), float))),
                         (SAME,)))
        opts = set(e.options) | ({"color"} if e.color else set()) | ({"shape"} if e.shape else set())
        if e.wide:
            rows.append((e.name, "at the 64-bit range",
                         ("geometry", _set_last(AT_RANGE64), None), ("works",)))
            for label, kw in (WIDE_ROWS if e.wide is True else AREA_WIDE_ROWS).items():
                rows.append((e.name, label, ("options", kw),
                             (RAISE, rastrum.InputError,
                              r"subpixel_bits.*aet" if e.wide is True else r"subpixel_bits")))
        for opt in sorted(opts):
            for value, problem in (WIDE_OPTIONS if e.wide else OPTIONS).get(opt, OPTIONS[opt]):
                rows.append((e.name, "%s=%r" % (opt, value), ("option", opt, value),
                             (RAISE, rastrum.InputError, problem)))
        if "fraction_bits" in e.options:
            for fb in (0, 17, -1):
                rows.append((e.name, "fixed, fraction_bits=%d" % fb,
                             ("options", dict(precision="fixed", fraction_bits=fb)),
                             (RAISE, rastrum.InputError, r"fraction_bits.*1\.\.16")))
        if "rule" in e.options:
            rows.append((e.name, "edgefill with nonzero", ("options", dict(algorithm="edgefill", rule="nonzero")),
                         (RAISE, rastrum.InputError, r"support")))
        if e.shape:
            for shape in ((0, 5), (5, 0), (0, 0)):
                rows.append((e.name, "shape=%r" % (shape,), ("option", "shape", shape), ("empty", shape)))
        if e.canvas:
            rows.append((e.name, "read-only target", ("read-only target",),
                         (RAISE, rastrum.InputError, r"read-only")))
            rows.append((e.name, "zero-size canvas", ("zero-size canvas",),
                         (RAISE, rastrum.InputError, r"seed.*outside") if e.kind == "seed" else (NOTHING,)))
    return rows


TABLE = _rows()


def _target():
    """A guard-patterned array and an rgb888 canvas wrapped around a slice
    of it (a sub-view with a row stride, as Canvas.wrap allows)."""
    big = (np.arange(14 * 16 * 3) % 251).astype(np.uint8).reshape(14, 16, 3)
    view = big[2:2 + SHAPE[0], 1:1 + SHAPE[1]]
    return big, rastrum.Canvas.wrap(view)


def _run(entry, geometry, kw, canvas):
    return entry.call(canvas, geometry, dict(kw))


def _same(a, b):
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.dtype == b.dtype \
            and np.array_equal(a, b)
    return a == b


def _snapshot(g):
    return [None if a is None else np.array(a, copy=True) if isinstance(a, np.ndarray) else repr(a) for a in g]


@pytest.mark.parametrize("row", TABLE, ids=["%s | %s" % (r[0], r[1]) for r in TABLE])
def test_bad_input(row):
    name, label, how, expect = row
    entry = next(e for e in ENTRIES if e.name == name)
    good = GOOD[entry.kind]
    geometry, kw, equivalent = good, {}, good
    big, canvas = _target()
    if how[0] == "geometry":
        geometry = how[1](good)
        equivalent = how[2](good) if how[2] else good
    elif how[0] == "option":
        kw = {how[1]: how[2]}
    elif how[0] == "options":
        kw = dict(how[1])
    elif how[0] == "read-only target":
        canvas.array.setflags(write=False)  # after the wrap: the canvas must notice
    elif how[0] == "zero-size canvas":
        canvas = rastrum.Canvas.wrap(big[:0, :0])
    before = big.copy()
    inputs = _snapshot(geometry)

    if expect[0] == RAISE:
        _, exc, pattern = expect
        with pytest.raises(exc) as info:
            _run(entry, geometry, kw, canvas)
        assert re.search(pattern, str(info.value)), "message %r does not match %r" % (str(info.value), pattern)
        assert np.array_equal(big, before), "the target changed although the call raised"
        assert canvas.depth is None, "a depth buffer was made although the call raised"
        if exc is rastrum.InputError:
            assert isinstance(info.value, ValueError)
    elif expect[0] == SAME:
        got = _run(entry, geometry, kw, canvas)
        ref_big, ref_canvas = _target()
        want = _run(entry, equivalent, kw, ref_canvas)
        assert _same(got, want)
        assert np.array_equal(big, ref_big)
    elif expect[0] == NOTHING:
        got = _run(entry, geometry, kw, canvas)
        assert np.array_equal(big, before)
        if isinstance(got, np.ndarray):
            assert not got.any()
    elif expect[0] == "works":  # at the 64-bit range: accepted, and the mask is the oracle's
        got = _run(entry, geometry, kw, canvas)
        if isinstance(got, np.ndarray) and entry.wide == "area":  # coverage levels, exact rationals
            import oracle_coverage as oc
            exact = oc.coverage_exact([np.asarray(geometry[0], float)], SHAPE, subpixel_bits=8)
            assert np.array_equal(got, np.vectorize(lambda a: oc.level(a, 255))(exact))
        elif isinstance(got, np.ndarray):
            from oracle import oracle_mask
            assert np.array_equal(got, oracle_mask([np.asarray(geometry[0], float)], SHAPE))
        else:
            assert not np.array_equal(big, before)
    else:  # ("empty", shape): an empty result of that shape
        got = _run(entry, geometry, kw, canvas)
        assert got.shape == expect[1]
        assert np.array_equal(big, before)
    for a, b in zip(_snapshot(geometry), inputs):  # the caller's input is untouched
        if isinstance(a, np.ndarray) and a.dtype.kind in "fc":
            assert np.array_equal(a, b, equal_nan=True)
        elif isinstance(a, np.ndarray):
            assert np.array_equal(a, b)
        else:
            assert a == b


def test_every_entry_draws_with_good_input():
    """The rows above mean something only if the good call draws."""
    for e in ENTRIES:
        big, canvas = _target()
        before = big.copy()
        got = _run(e, GOOD[e.kind], {}, canvas)
        if e.canvas:
            assert not np.array_equal(big, before), e.name
        elif isinstance(got, np.ndarray):
            assert got.any(), e.name
        else:
            assert got is True or got is False, e.name


# Public names that other branches were adding while this table was
# written (main's shading, scene and seed-fill work): they still need their
# Entry (or explicit rows).  Remove a name from here when it gets one.
AWAITING_ROWS = set()


def test_every_public_drawing_name_has_an_entry():
    """A new public function or Canvas method fails here until it has an
    Entry (or is listed as not drawing)."""
    not_drawing = {"Canvas", "ALGORITHMS", "AA_METHODS", "RastrumError", "InputError", "__version__",
                   "Canvas.wrap", "Canvas.to_image", "Canvas.save", "Canvas.array", "Canvas.width",
                   "Canvas.height", "Canvas.format"}
    public = {n for n in rastrum.__all__} | {
        "Canvas." + n for n in dir(rastrum.Canvas) if not n.startswith("_")}
    covered = {e.name for e in ENTRIES} | not_drawing | set(EXTRA_COVERED) | AWAITING_ROWS
    missing = sorted(public - covered)
    assert not missing, "no bad-input rows for: %s" % missing


# ---- the rest of the public surface: one explicit row each ------------------

def _wrap_then(setup):
    def call():
        a = np.zeros((4, 5, 3), np.uint8)
        return rastrum.Canvas.wrap(setup(a))
    return call


def _ro(a):
    a.setflags(write=False)
    return a


def _on_canvas(method, *args, **kw):
    """Call a Canvas method on a zero canvas; when it raises, the canvas
    must still be zero."""
    def call():
        c = rastrum.Canvas((6, 7), format="rgb888")
        try:
            return getattr(c, method)(*args, **kw)
        finally:
            assert not c.array.any(), "%s wrote pixels before raising" % method
    return call


OTHER = [
    # (name, label, call, exception or None for "works", regex)
    ("Canvas", "width -1", lambda: rastrum.Canvas((5, -1)), rastrum.InputError, r"shape"),
    ("Canvas", "height -1", lambda: rastrum.Canvas((-1, 5)), rastrum.InputError, r"shape"),
    ("Canvas", "width 2**31", lambda: rastrum.Canvas((1, 2 ** 31)), rastrum.InputError, r"shape"),
    ("Canvas", "width 1.5", lambda: rastrum.Canvas((5, 1.5)), rastrum.InputError, r"shape"),
    ("Canvas", "width NaN", lambda: rastrum.Canvas((5, NAN)), rastrum.InputError, r"shape"),
    ("Canvas", "width '5'", lambda: rastrum.Canvas((5, "5")), rastrum.InputError, r"shape"),
    ("Canvas", "width 0", lambda: rastrum.Canvas((5, 0)), None, None),
    ("Canvas", "format bogus", lambda: rastrum.Canvas((5, 5), "bogus"), rastrum.InputError, r"format"),
    ("Canvas", "format None", lambda: rastrum.Canvas((5, 5), None), rastrum.InputError, r"format"),
    ("Canvas", "background 256", lambda: rastrum.Canvas((5, 5), background=256), rastrum.InputError, r"colou?r"),
    ("Canvas", "background NaN", lambda: rastrum.Canvas((5, 5), background=NAN), rastrum.InputError, r"colou?r"),
    ("Canvas", "background (1, 2)", lambda: rastrum.Canvas((5, 5), background=(1, 2)), rastrum.InputError,
     r"colou?r"),
    ("Canvas.wrap", "float32", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.float32)), rastrum.InputError,
     r"uint8"),
    # A uint16 array needs format= (rgb565 or label): the dtype does not say which.
    ("Canvas.wrap", "uint16 (H, W, 3)", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.uint16)),
     rastrum.InputError, r"needs format="),
    ("Canvas.wrap", "uint16 (H, W), no format", lambda: rastrum.Canvas.wrap(np.zeros((4, 5), np.uint16)),
     rastrum.InputError, r"needs format="),
    ("Canvas.wrap", "rgb565, uint16 (H, W, 3)",
     lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.uint16), format="rgb565"),
     rastrum.InputError, r"uint16 only as rgb565"),
    ("Canvas.wrap", "label, float", lambda: rastrum.Canvas.wrap(np.zeros((4, 5), np.float64), format="label"),
     rastrum.InputError, r"integer array"),
    ("Canvas.wrap", "label, (H, W, 3)", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.int32), format="label"),
     rastrum.InputError, r"\(H, W\) array"),
    ("Canvas.wrap", "label, read-only", lambda: rastrum.Canvas.wrap(_ro(np.zeros((4, 5), np.int32)),
                                                                    format="label"),
     rastrum.InputError, r"writable"),
    ("Canvas.wrap", "label, column stride", lambda: rastrum.Canvas.wrap(np.zeros((4, 6), np.int32)[:, ::2],
                                                                        format="label"),
     rastrum.InputError, r"contiguous"),
    ("Canvas.wrap", "a list", lambda: rastrum.Canvas.wrap([[0, 0], [0, 0]]), rastrum.InputError, r"array"),
    ("line_pixels", "more than max_pixels", lambda: rastrum.line_pixels((0, 0), (2 ** 27 - 1, 0), subpixel_bits=0),
     rastrum.InputError, r"max_pixels"),
    ("line_pixels", "max_pixels=10 for 11", lambda: rastrum.line_pixels((0, 0), (10, 0), subpixel_bits=0,
                                                                        sample_offset=0, max_pixels=10),
     rastrum.InputError, r"11 pixels.*max_pixels=10"),
    ("line_pixels", "max_pixels=11 for 11", lambda: rastrum.line_pixels((0, 0), (10, 0), subpixel_bits=0,
                                                                        sample_offset=0, max_pixels=11), None, None),
    # found by test_fuzz_api: a 2-D memoryview clip raised NotImplementedError, an array precision
    # ValueError (truth value of an array)
    ("line_pixels", "clip a 2-D memoryview", lambda: rastrum.line_pixels((0, 0), (5, 0), clip=memoryview(
        np.zeros((2, 2), np.int64))), rastrum.InputError, r"clip"),
    ("line_pixels", "clip a 1-D memoryview", lambda: rastrum.line_pixels((0, 0), (5, 0), clip=memoryview(
        np.array([0, 0, 3, 3], np.int64))), None, None),
    ("Canvas.fill_triangles", "precision an array", lambda: rastrum.Canvas((4, 4)).fill_triangles(
        [[(0, 0), (4, 0), (0, 4)]], 7, precision=np.zeros(3)), rastrum.InputError, r"precision"),
    ("line_pixels", "max_pixels=-1", lambda: rastrum.line_pixels((0, 0), (1, 0), max_pixels=-1),
     rastrum.InputError, r"max_pixels"),
    ("line_pixels", "max_pixels=1.5", lambda: rastrum.line_pixels((0, 0), (1, 0), max_pixels=1.5),
     rastrum.InputError, r"max_pixels"),
    ("line_pixels", "max_pixels=True", lambda: rastrum.line_pixels((0, 0), (1, 0), max_pixels=True),
     rastrum.InputError, r"max_pixels"),
    ("Canvas.wrap", "a memoryview", lambda: rastrum.Canvas.wrap(memoryview(np.zeros((4, 5), np.uint8))),
     rastrum.InputError, r"array"),
    # a row stride past the core's int32 (issue 18: was OverflowError); no
    # byte of the view is touched
    ("Canvas.wrap", "row stride 2**31", lambda: rastrum.Canvas.wrap(np.lib.stride_tricks.as_strided(
        np.zeros(8, np.uint8), shape=(2, 2), strides=(2 ** 31, 1))), rastrum.InputError, r"stride"),
    # Canvas.depth: a checked property (issue 18: a (1, 4) array overflowed the heap)
    ("Canvas.depth", "shape (1, 4)", lambda: _set_depth(np.full((1, 4), 2 ** 31 - 1, np.int32)),
     rastrum.InputError, r"depth.*shape"),
    ("Canvas.depth", "int64", lambda: _set_depth(np.zeros(SHAPE, np.int64)), rastrum.InputError,
     r"depth.*int32"),
    ("Canvas.depth", "float32", lambda: _set_depth(np.zeros(SHAPE, np.float32)), rastrum.InputError,
     r"depth.*int32"),
    ("Canvas.depth", "big-endian int32", lambda: _set_depth(np.zeros(SHAPE, ">i4")), rastrum.InputError,
     r"depth.*byte order"),
    ("Canvas.depth", "transposed shape", lambda: _set_depth(np.zeros(SHAPE[::-1], np.int32)),
     rastrum.InputError, r"depth.*shape"),
    ("Canvas.depth", "Fortran order", lambda: _set_depth(np.asfortranarray(np.zeros(SHAPE, np.int32))),
     rastrum.InputError, r"depth.*contiguous"),
    ("Canvas.depth", "column stride", lambda: _set_depth(np.zeros((SHAPE[0], 2 * SHAPE[1]), np.int32)[:, ::2]),
     rastrum.InputError, r"depth.*contiguous"),
    ("Canvas.depth", "read-only", lambda: _set_depth(_ro(np.zeros(SHAPE, np.int32))), rastrum.InputError,
     r"depth.*writable"),
    ("Canvas.depth", "a list", lambda: _set_depth(np.zeros(SHAPE, np.int32).tolist()), rastrum.InputError,
     r"depth.*array"),
    ("Canvas.depth", "a memoryview", lambda: _set_depth(memoryview(np.zeros(SHAPE, np.int32))),
     rastrum.InputError, r"depth.*array"),
    ("Canvas.depth", "an int", lambda: _set_depth(0), rastrum.InputError, r"depth"),
    ("Canvas.depth", "(H, W) int32", lambda: _set_depth(np.zeros(SHAPE, np.int32)), None, None),
    ("Canvas.depth", "None", lambda: _set_depth(None), None, None),
    # depths are int32: a fraction is refused, never rounded (0.4 and 0.2 tied)
    ("Canvas.fill_triangles", "depth 0.4 and 0.2", lambda: rastrum.Canvas((4, 4)).fill_triangles(
        [[(0, 0), (4, 0), (0, 4)]], 7, depth=[[0.4, 0.2, 0]]), rastrum.InputError, r"depth.*integers.*2\*\*"),
    ("Canvas.fill_triangles", "depth Fraction 1/3", lambda: rastrum.Canvas((4, 4)).fill_triangles(
        [[(0, 0), (4, 0), (0, 4)]], 7, depth=np.array([[fractions.Fraction(1, 3), 0, 0]], object)),
     rastrum.InputError, r"depth.*integers"),
    ("Canvas.fill_triangles", "depth 5.0 (an integer)", lambda: rastrum.Canvas((4, 4)).fill_triangles(
        [[(0, 0), (4, 0), (0, 4)]], 7, depth=[[5.0, 1, 2]]), None, None),
    ("Canvas.wrap", "read-only", _wrap_then(_ro), rastrum.InputError, r"writable"),
    ("Canvas.wrap", "broadcast (read-only)", lambda: rastrum.Canvas.wrap(
        np.broadcast_to(np.zeros(3, np.uint8), (4, 5, 3))), rastrum.InputError, r"writable"),
    ("Canvas.wrap", "column stride", _wrap_then(lambda a: a[:, ::2]), rastrum.InputError, r"contiguous"),
    ("Canvas.wrap", "Fortran order", lambda: rastrum.Canvas.wrap(np.asfortranarray(np.zeros((4, 5), np.uint8))),
     rastrum.InputError, r"contiguous"),
    ("Canvas.wrap", "reversed rows", _wrap_then(lambda a: a[::-1]), rastrum.InputError, r"contiguous|order"),
    ("Canvas.wrap", "1-d", lambda: rastrum.Canvas.wrap(np.zeros(20, np.uint8)), rastrum.InputError, r"shape"),
    ("Canvas.wrap", "2 channels", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 2), np.uint8)), rastrum.InputError,
     r"shape"),
    ("Canvas.wrap", "format mismatch", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.uint8), "gray8"),
     rastrum.InputError, r"format"),
    ("Canvas.wrap", "format bogus", lambda: rastrum.Canvas.wrap(np.zeros((4, 5, 3), np.uint8), "bogus"),
     rastrum.InputError, r"format"),
    ("Canvas.wrap", "empty", lambda: rastrum.Canvas.wrap(np.zeros((0, 5), np.uint8)), None, None),
    ("Canvas.wrap", "a row slice (row stride)", _wrap_then(lambda a: a[1:3, 1:4]), None, None),
    ("Canvas.save", "unknown extension", lambda: rastrum.Canvas((2, 2)).save("/tmp/x.unknownext"), ValueError,
     r"extension"),
    ("Canvas.save", "missing directory", lambda: rastrum.Canvas((2, 2)).save("/nonexistent-dir/x.png"), OSError,
     r"No such file|nonexistent"),
    ("Canvas.to_image", "an empty canvas", lambda: rastrum.Canvas((0, 0)).to_image(), None, None),
    # canvas34's Pillow shapes and stroke: the canvas untouched (_on_canvas); more in tests/test_shapes.py
    ("Canvas.ellipse", "box x1 < x0", _on_canvas("ellipse", (5, 1, 2, 4), 7), rastrum.InputError, r"x1 >= x0"),
    ("Canvas.ellipse", "no colour", _on_canvas("ellipse", (1, 1, 4, 4)), rastrum.InputError, r"fill or outline"),
    ("Canvas.ellipse", "width 10**400", _on_canvas("ellipse", (1, 1, 4, 4), 7, 9, 10 ** 400), rastrum.InputError,
     r"width"),
    ("Canvas.ellipse", "complex box", _on_canvas("ellipse", (1j, 1, 4, 4), 7), rastrum.InputError, r"xy.*complex"),
    ("Canvas.circle", "radius -1", _on_canvas("circle", (3, 3), -1, 7), rastrum.InputError, r"radius"),
    ("Canvas.circle", "radius 10**400", _on_canvas("circle", (3, 3), 10 ** 400, 7), rastrum.InputError, r"radius"),
    ("Canvas.circle", "centre bools", _on_canvas("circle", (True, 3), 1, 7), rastrum.InputError, r"xy.*bools"),
    ("Canvas.rounded_rectangle", "radius NaN", _on_canvas("rounded_rectangle", (1, 1, 4, 4), NAN, 7),
     rastrum.InputError, r"radius"),
    ("Canvas.arc", "end NaN", _on_canvas("arc", (1, 1, 4, 4), 0, NAN, 7), rastrum.InputError, r"end"),
    ("Canvas.arc", "no fill", _on_canvas("arc", (1, 1, 4, 4), 0, 90), rastrum.InputError, r"fill"),
    # the fill is valid, the outline 2**40 wide is past the grid: neither is drawn
    ("Canvas.pieslice", "outline width 2**40", _on_canvas("pieslice", (1, 1, 4, 4), 0, 90, 7, 9, 2 ** 40),
     rastrum.InputError, r"(outside|past) the range"),
    ("Canvas.chord", "outline width 2**62", _on_canvas("chord", (1, 1, 4, 4), 0, 90, 7, 9, 2 ** 62),
     rastrum.InputError, r"(outside|past) the range"),
    ("Canvas.chord", "start 'a'", _on_canvas("chord", (1, 1, 4, 4), "a", 90, 7), rastrum.InputError, r"start"),
    ("Canvas.regular_polygon", "n_sides 2", _on_canvas("regular_polygon", (3, 3, 2), 2, 0, 7), rastrum.InputError,
     r"n_sides"),
    ("Canvas.regular_polygon", "n_sides 2**64", _on_canvas("regular_polygon", (3, 3, 2), 2 ** 64, 0, 7),
     rastrum.InputError, r"n_sides"),
    ("Canvas.regular_polygon", "no radius", _on_canvas("regular_polygon", (3, 3), 4, 0, 7), rastrum.InputError,
     r"bounding_circle"),
    ("Canvas.stroke", "width 0", _on_canvas("stroke", [(1, 1), (4, 4)], 7, 0), rastrum.InputError, r"width"),
    ("Canvas.stroke", "join 'sharp'", _on_canvas("stroke", [(1, 1), (4, 4)], 7, 2, join="sharp"),
     rastrum.InputError, r"join"),
    ("Canvas.stroke", "geometry None", _on_canvas("stroke", None, 7, 2), rastrum.InputError, r"geometry|None"),
    ("ALGORITHMS", "unknown entry point", lambda: rastrum.ALGORITHMS["bogus"], KeyError, r"bogus"),
    ("AA_METHODS", "unknown entry point", lambda: rastrum.AA_METHODS["bogus"], KeyError, r"bogus"),
]
EXTRA_COVERED = {row[0] for row in OTHER} | {"render_mesh", "scene", "Canvas.packed", "Canvas.clear_depth"}
# rasterize's rows (every kind of bad geometry, value, dtype, transform and
# shape, out untouched) are in tests/test_rasterize.py.
EXTRA_COVERED |= {"rasterize", "IDENTITY"}
# Issue 14's names have their rows beside their tests: tests/test_coco.py
# (every rastrum.coco name) and tests/test_ml.py (masks, labels);
# coco.polygons and the Polygons batch in tests/test_coco_polygons.py.
EXTRA_COVERED |= {"coco", "masks", "labels", "Polygons"}
# Paths and strokes: their rows are in tests/test_path.py (test_bad_paths,
# the SVG grammar's errors) and tests/test_stroke.py (test_bad_arguments).
EXTRA_COVERED |= {"Path", "stroke"}
# Issue 36's names have their rows beside their tests: tests/test_gis_parity.py
# (geometry_mask, geometry_window, grid) and tests/test_zonal.py (zonal_stats).
EXTRA_COVERED |= {"geometry_mask", "geometry_window", "grid", "zonal_stats"}
# coverage_fractions' bad input: tests/test_gis_coverage.py.
EXTRA_COVERED |= {"coverage_fractions"}
# Opacity: Canvas.composite's rows (coverage shape and dtype, premultiplied,
# opacity, format; the canvas untouched) are in tests/test_opacity.py.
EXTRA_COVERED |= {"Canvas.composite"}


def _set_depth(value):
    """Set Canvas.depth on a canvas of SHAPE; the buffer and the pixels must
    be as they were when it raises."""
    canvas = rastrum.Canvas(SHAPE, format="gray8")
    canvas.fill_triangles([[(0, 0), (12, 0), (0, 10)]], 7, depth=[[1, 2, 3]])
    before, depth = canvas.array.copy(), canvas.depth
    try:
        canvas.depth = value
    except rastrum.InputError:
        assert canvas.depth is depth and np.array_equal(canvas.array, before)
        raise
    assert canvas.depth is value


@pytest.mark.parametrize("name,label,call,exc,pattern", OTHER, ids=["%s | %s" % (r[0], r[1]) for r in OTHER])
def test_other_bad_input(name, label, call, exc, pattern):
    if exc is None:
        call()
        return
    with pytest.raises(exc) as info:
        call()
    assert re.search(pattern, str(info.value), re.I), str(info.value)


# ---- render_mesh and the OBJ reader (rastrum.scene) ----------------------------

def _mesh_args():
    from rastrum.scene import sphere
    v, f, n = sphere(4, 8)
    return dict(vertices=v, faces=f, normals=n)


def _with(key, fn):
    return lambda a: dict(a, **{key: fn(a[key])})


# label -> (change of the keyword arguments, message regex); every one an InputError.
MESH_ROWS = {
    "vertices NaN": (_with("vertices", lambda v: np.where(np.arange(v.size).reshape(v.shape) == 4, NAN, v)),
                     r"vertices.*finite"),
    "vertices inf": (_with("vertices", lambda v: np.where(v > 0, INF, v)), r"vertices.*finite"),
    "vertices complex": (_with("vertices", lambda v: v.astype(complex)), r"vertices.*real numbers"),
    "vertices bool": (_with("vertices", lambda v: v > 0), r"vertices.*real numbers"),
    "vertices str": (_with("vertices", lambda v: v.astype(str)), r"vertices.*real numbers"),
    "vertices None": (_with("vertices", lambda v: None), r"vertices"),
    "vertices (V, 2)": (_with("vertices", lambda v: v[:, :2]), r"vertices.*shape"),
    "faces float": (_with("faces", lambda f: f.astype(float)), r"faces.*int"),
    "faces -1": (_with("faces", lambda f: f - 1), r"faces.*index"),
    "faces past the vertices": (_with("faces", lambda f: f + 1000), r"faces.*index"),
    "faces (F, 4)": (_with("faces", lambda f: np.c_[f, f[:, :1]]), r"faces.*shape"),
    "faces None": (_with("faces", lambda f: None), r"faces"),
    "shape -1": (lambda a: dict(a, shape=(16, -1)), r"shape"),
    "shape 1.5": (lambda a: dict(a, shape=(16, 1.5)), r"shape.*ints"),
    "shape 'big'": (lambda a: dict(a, shape="big"), r"shape.*pair"),
    "size -1 (the deprecated spelling)": (lambda a: dict(a, size=(-1, 16)), r"shape|size"),
    "size and shape": (lambda a: dict(a, size=(16, 12), shape=(12, 16)), r"not also size"),
    "normals NaN": (_with("normals", lambda n: n * NAN), r"normals.*finite"),
    "normals wrong shape": (_with("normals", lambda n: n[:3]), r"normals.*shape"),
    "shading phong": (lambda a: dict(a, shading="phong"), r"shading"),
    "shading None": (lambda a: dict(a, shading=None), r"shading"),
    "light NaN": (lambda a: dict(a, light=(NAN, 0, 1)), r"light.*finite"),
    "light zero": (lambda a: dict(a, light=(0, 0, 0)), r"light.*non-zero"),
    "light (1, 2)": (lambda a: dict(a, light=(1, 2)), r"light.*3 numbers"),
    "light 'up'": (lambda a: dict(a, light="up"), r"light.*real numbers"),
    "ambient 2": (lambda a: dict(a, ambient=2), r"ambient.*\[0, 1\]"),
    "ambient NaN": (lambda a: dict(a, ambient=NAN), r"ambient.*finite"),
    "ambient 'x'": (lambda a: dict(a, ambient="x"), r"ambient.*number"),
    "color 256": (lambda a: dict(a, color=(256, 0, 0)), r"color.*0\.\.255"),
    "color -1": (lambda a: dict(a, color=(-1, 0, 0)), r"color.*0\.\.255"),
    "color 2 channels": (lambda a: dict(a, color=(1, 2)), r"color.*3 int"),
    "color 'redd'": (lambda a: dict(a, color="redd"), r"colou?r 'redd'"),
    "color 1.5": (lambda a: dict(a, color=(1.5, 2, 3)), r"color.*int"),
    "rotation 2x2": (lambda a: dict(a, rotation=np.eye(2)), r"rotation.*3x3"),
    "rotation NaN": (lambda a: dict(a, rotation=np.eye(3) * NAN), r"rotation.*finite"),
    "projection fisheye": (lambda a: dict(a, projection="fisheye"), r"projection"),
    "scale 1e10": (lambda a: dict(a, scale=1e10), r"out of range.*scale"),
    "scale NaN": (lambda a: dict(a, scale=NAN), r"scale.*finite"),
    "scale 'big'": (lambda a: dict(a, scale="big"), r"scale.*number"),
    "fov 0": (lambda a: dict(a, projection="perspective", fov=0), r"fov"),
    "fov 180": (lambda a: dict(a, projection="perspective", fov=180), r"fov"),
    "distance 0": (lambda a: dict(a, projection="perspective", distance=0), r"behind the eye"),
    "precision double": (lambda a: dict(a, precision="double"), r"precision"),
    "subpixel_bits 17": (lambda a: dict(a, subpixel_bits=17), r"subpixel"),
    "cull 'yes'": (lambda a: dict(a, cull="yes"), r"cull"),
    "depth 'yes'": (lambda a: dict(a, depth="yes"), r"depth"),
}
MESH_NEW_CANVAS = {  # only without canvas=
    "format cmyk": (lambda a: dict(a, format="cmyk"), r"format"),
    "background 300": (lambda a: dict(a, background=300), r"colou?r"),
}


@pytest.mark.parametrize("label", list(MESH_ROWS) + list(MESH_NEW_CANVAS))
def test_render_mesh_bad_input(label):
    """render_mesh: the InputError naming the argument; a canvas given
    with canvas= is untouched (pixels and depth buffer), and so are the
    caller's arrays."""
    change, pattern = {**MESH_ROWS, **MESH_NEW_CANVAS}[label]
    args = change(_mesh_args())
    v, f = args.pop("vertices"), args.pop("faces")
    if "size" not in args:
        args.setdefault("shape", (12, 16))
    inputs = _snapshot((v, f, args.get("normals")))
    with pytest.raises(rastrum.InputError) as info, warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # size=: the old spelling
        rastrum.render_mesh(v, f, **args)
    assert re.search(pattern, str(info.value), re.I), str(info.value)
    args.pop("shape", None)
    if label in MESH_NEW_CANVAS or label.startswith(("size", "shape")):
        return
    big, canvas = _target()
    canvas.fill_triangles(GOOD["tris"][0], vertex_colors=VCOLORS, depth=DEPTHS)
    before, depth = big.copy(), canvas.depth.copy()
    with pytest.raises(rastrum.InputError):
        rastrum.render_mesh(v, f, canvas=canvas, **args)
    assert np.array_equal(big, before)
    assert np.array_equal(canvas.depth, depth)
    for a, b in zip(_snapshot((v, f, args.get("normals"))), inputs):
        if isinstance(a, np.ndarray) and a.dtype.kind in "fc":
            assert np.array_equal(a, b, equal_nan=True)
        elif isinstance(a, np.ndarray):
            assert np.array_equal(a, b)


def test_render_mesh_good_input_draws():
    big, canvas = _target()
    before = big.copy()
    args = _mesh_args()
    rastrum.render_mesh(args["vertices"], args["faces"], canvas=canvas)
    assert not np.array_equal(big, before)
    assert rastrum.render_mesh(args["vertices"], args["faces"], shape=(6, 8), format="gray8").array.any()


OBJ_ROWS = [
    ("v with 2 numbers", "v 1 2\n", r":1: v needs 3 numbers"),
    ("v NaN", "v nan 0 0\n", r":1: non-finite"),
    ("v inf", "v inf 0 0\n", r":1: non-finite"),
    ("v text", "v a b c\n", r":1: bad number"),
    ("vn with 4 numbers", "vn 0 0 1 1\n", r":1: vn needs 3 numbers"),
    ("face of 2 corners", "v 0 0 0\nv 1 0 0\nf 1 2\n", r":3: a face needs at least 3 corners"),
    ("index 0", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", r":4: vertex index 0 out of range"),
    ("index past the end", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", r":4: vertex index 9 out of range"),
    ("negative index past the start", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", r":4: vertex index -4"),
    ("huge index", "v 0 0 0\nf 1 1 99999999999999999999\n", r":2: vertex index 9+ out of range"),
    ("index text", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n", r":4: bad vertex index 'a'"),
    ("index 1.5", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1.5 2 3\n", r":4: bad vertex index '1.5'"),
    ("corner of 4 fields", "v 0 0 0\nf 1/1/1/1 1 1\n", r":2: bad face corner"),
    ("normals for some corners", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3\n",
     r":5: normals given for some corners only"),
    ("normal index past the end", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//2 2//1 3//1\n",
     r":5: normal index 2 out of range"),
    ("some faces with normals", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 3\n",
     r": some faces give normals and others do not"),
    # issue 18: a face past max_face_corners (65536) is refused, not fanned
    ("face of 65537 corners", "v 0 0 0\nf" + " 1" * 65537 + "\n", r":2: a face of more than max_face_corners"),
]


@pytest.mark.parametrize("label,text,pattern", OBJ_ROWS, ids=[r[0] for r in OBJ_ROWS])
def test_read_obj_bad_file(label, text, pattern, tmp_path):
    """rastrum.scene.read_obj: an InputError naming the file and line, from a
    file object and from a path alike."""
    import io
    from rastrum.scene import read_obj
    with pytest.raises(rastrum.InputError, match=pattern):
        read_obj(io.StringIO(text))
    path = tmp_path / "bad.obj"
    path.write_text(text)
    with pytest.raises(rastrum.InputError, match=re.escape(str(path)) + pattern):
        read_obj(str(path))


def test_read_obj_not_a_file(tmp_path):
    from rastrum.scene import read_obj
    for source in (None, 5, b"v 0 0 0"):
        with pytest.raises(rastrum.InputError, match=r"source must be a path or a text file"):
            read_obj(source)
    path = tmp_path / "binary.obj"
    path.write_bytes(b"v 0 0 0\n\xff\xfe\x00\n")
    with pytest.raises(rastrum.InputError, match=r"not a text \(UTF-8\) OBJ file"):
        read_obj(path)
    with pytest.raises(FileNotFoundError):
        read_obj(tmp_path / "missing.obj")


def test_packed_and_clear_depth():
    """Canvas.packed is the buffer itself (a view; mono1 packed bits) and
    cannot be replaced; clear_depth takes no argument and only drops the
    depth buffer."""
    c = rastrum.Canvas((2, 10), format="mono1")
    assert c.packed.shape == (2, 2) and c.packed.dtype == np.uint8
    c.fill_polygon([(0, 0), (3, 0), (3, 2), (0, 2)], 1, subpixel_bits=0)
    assert c.packed[0, 0] == 0b11100000 and c.packed[0, 1] == 0
    with pytest.raises(AttributeError):
        c.packed = np.zeros((2, 2), np.uint8)
    big, canvas = _target()
    canvas.fill_triangles(GOOD["tris"][0], vertex_colors=VCOLORS, depth=DEPTHS)
    before = big.copy()
    with pytest.raises(TypeError):
        canvas.clear_depth(0)
    assert canvas.depth is not None
    canvas.clear_depth()
    assert canvas.depth is None and np.array_equal(big, before)


def test_read_only_after_wrap_then_writable_again():
    """A canvas refuses while its array is read-only, and draws again once
    it is writable: the check is made at each call."""
    a = np.zeros((6, 8), np.uint8)
    c = rastrum.Canvas.wrap(a)
    a.setflags(write=False)
    with pytest.raises(rastrum.InputError, match="read-only"):
        c.fill_polygon([(0, 0), (8, 0), (0, 6)], 1)
    assert not a.any()
    a.setflags(write=True)
    c.fill_polygon([(0, 0), (8, 0), (0, 6)], 1)
    assert a.any()


def test_to_image_of_a_read_only_canvas():
    a = np.full((2, 3), 7, np.uint8)
    c = rastrum.Canvas.wrap(a)
    a.setflags(write=False)
    assert c.to_image().getpixel((0, 0)) == 7


def test_table_size():
    # Every entry gets every generic row; the table is the documentation.
    assert len(TABLE) >= len(ENTRIES) * (len(GEOMETRY) + len(INT_ROWS))
    assert not math.isnan(AT_RANGE)
