"""GIS rasterisation: :func:`rasterize`, with rasterio's semantics.

Shapes (shapely geometries, ``__geo_interface__`` objects, GeoJSON-like
mappings, GeoSeries and GeoDataFrames) are burnt into a 2-D array through
an affine geo transform.  Polygons follow the library's exact rule (pixel
centres, spans left closed and right open, rows top closed and bottom
open) evaluated on the float64 pixel coordinates that the inverse
transform gives; lines and points burn what GDAL burns for them.  See
docs/gis.md.
"""

from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass
from operator import itemgetter
from typing import Any, Callable, Iterable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import InputError
from . import _burn

__all__ = ["rasterize", "IDENTITY", "DTYPES", "geometry_mask", "geometry_window", "grid", "Window",
           "ShapeSkipWarning"]

#: The identity transform in Affine order (a, b, c, d, e, f):
#: x = a*col + b*row + c, y = d*col + e*row + f.
IDENTITY: Tuple[float, ...] = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0)

#: The dtypes rasterize burns into.
DTYPES = ("uint8", "int8", "uint16", "int16", "uint32", "int32", "int64", "uint64", "float32", "float64")

_KIND_POLYGON, _KIND_LINE, _KIND_POINT = 0, 1, 2
_FIRST, _SECOND = itemgetter(0), itemgetter(1)

Transform = Union[Sequence[float], Any]
ShapeItem = Union[Any, Tuple[Any, Union[int, float, None]]]


# ---- transform -------------------------------------------------------------------

def _transform6(transform) -> Tuple[float, ...]:
    """(a, b, c, d, e, f) as floats from an affine.Affine or a 6-sequence,
    or InputError."""
    try:
        values = list(transform)
    except TypeError:
        raise InputError("transform must be an affine.Affine or 6 numbers (a, b, c, d, e, f) in Affine "
                         "order, not %r (a GDAL geotransform: affine.Affine.from_gdal(*gt))"
                         % (transform,)) from None
    if len(values) == 9:
        if [float(v) if isinstance(v, numbers.Real) else v for v in values[6:]] != [0.0, 0.0, 1.0]:
            raise InputError("transform: the last row of a 3x3 affine matrix must be (0, 0, 1), not %r"
                             % (tuple(values[6:]),))
        values = values[:6]
    if len(values) != 6:
        raise InputError("transform must be 6 numbers (a, b, c, d, e, f) in Affine order, not %d "
                         "(a GDAL geotransform: affine.Affine.from_gdal(*gt))" % len(values))
    if (len(values) == 6 and not hasattr(transform, "to_gdal") and values[2] == values[4] == 0
            and values[1] > 0 and values[5] < 0):
        # rasterio's guard_transform: (c, a, b, f, d, e) in GDAL's order
        # would burn nothing (column scale 0), silently
        raise InputError("transform %r looks like a GDAL geotransform (c, a, b, f, d, e); rastrum, as "
                         "rasterio, takes Affine order (a, b, c, d, e, f): "
                         "affine.Affine.from_gdal(*gt)" % (tuple(values),))
    out = []
    for v in values:
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, numbers.Real):
            raise InputError("transform: %r is not a real number" % (v,))
        v = float(v)
        if not math.isfinite(v):
            raise InputError("transform: %r is not finite" % (v,))
        out.append(v)
    return tuple(out)


def _inverse(t6):
    """GDAL's inverse geotransform (GDALInvGeoTransform) of Affine (a..f),
    as (c0, cx, cy, r0, rx, ry): col = c0 + x*cx + y*cy, row = r0 + x*rx +
    y*ry, each evaluated left to right in float64."""
    a, b, c, d, e, f = t6
    if b == 0.0 and d == 0.0 and a != 0.0 and e != 0.0:  # north-up: no determinant
        out = (-c / a, 1.0 / a, 0.0, -f / e, 0.0, 1.0 / e)
        if not all(math.isfinite(v) for v in out):  # a = 1e-320: 1 / a is infinite
            raise InputError("transform %r: its inverse is not finite" % (t6,))
        return out
    det = a * e - b * d
    mag = max(abs(a), abs(b), abs(d), abs(e))
    if not abs(det) > 1e-10 * mag * mag:
        raise InputError("transform %r is not invertible (determinant %r)" % (t6, det))
    inv = 1.0 / det
    out = (
        (b * f - c * e) * inv, e * inv, -b * inv,
        (-a * f + c * d) * inv, -d * inv, a * inv,
    )
    if not all(math.isfinite(v) for v in out):
        raise InputError("transform %r: its inverse is not finite" % (t6,))
    return out


def pixel_coordinates(xy: np.ndarray, transform: Transform = IDENTITY) -> np.ndarray:
    """World (x, y) -> float64 pixel (col, row), as rasterize computes them
    (GDAL's inverse geotransform, applied in float64).  These are the
    coordinates on which rasterize's polygons are exact."""
    inv = _inverse(_transform6(transform))
    xy = np.asarray(xy, np.float64)
    out = np.empty(xy.shape, np.float64)
    x, y = xy[..., 0], xy[..., 1]
    out[..., 0] = inv[0] + x * inv[1] + y * inv[2]
    out[..., 1] = inv[3] + x * inv[4] + y * inv[5]
    return out


# ---- values and dtypes ------------------------------------------------------------

def _dtype(dtype, what):
    try:
        dt = np.dtype(dtype)
    except TypeError:
        raise InputError("%s %r is not a numpy dtype; choose one of: %s" % (what, dtype, ", ".join(DTYPES))) from None
    if dt.name not in DTYPES or not dt.isnative:
        raise InputError("%s %s is not supported; choose one of: %s" % (what, dt, ", ".join(DTYPES)))
    return dt


def _real(v, what):
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (numbers.Real, np.integer, np.floating)):
        raise InputError("%s %r is not a real number (int or float)" % (what, v))
    return v


def _fits(v, dt, what):
    """`v` as the Python number burnt into dtype `dt`, or InputError."""
    if dt.kind == "f":
        try:
            v = float(v)
        except OverflowError:
            raise InputError("%s %r does not fit dtype %s" % (what, v, dt)) from None
        if math.isfinite(v) and dt.itemsize == 4 and abs(v) > float(np.finfo(np.float32).max):
            raise InputError("%s %r does not fit dtype float32" % (what, v))
        return v
    if isinstance(v, (float, np.floating)):
        if not math.isfinite(v) or v != math.floor(v):
            raise InputError("%s %r does not fit dtype %s (not a whole number)" % (what, v, dt))
    v = int(v)
    info = np.iinfo(dt)
    if not info.min <= v <= info.max:
        raise InputError("%s %r does not fit dtype %s (%d..%d)" % (what, v, dt, info.min, info.max))
    return v


def _values(vals, dt):
    """The values as an array of dtype dt, checked as _fits checks them
    (vectorised; the first bad one is reported by _fits)."""
    if not vals:
        return np.zeros(0, dt)
    types = set(map(type, vals))
    ints = all(issubclass(t, (int, np.integer)) and not issubclass(t, (bool, np.bool_)) for t in types)
    if ints or all(issubclass(t, (float, np.floating)) for t in types):
        a = np.asarray(vals)
        if a.dtype.kind == "f":
            ok = np.isfinite(a) | (dt.kind == "f")
            if dt.kind == "f":
                if dt.itemsize == 4:
                    ok &= ~(np.abs(a) > float(np.finfo(np.float32).max)) | ~np.isfinite(a)
            else:
                info = np.iinfo(dt)
                # max + 1 (a power of two) is exact in float64; info.max is
                # not for 64 bits (2^63 - 1 rounds to 2^63, which wrapped)
                ok &= (a == np.floor(a)) & (a >= info.min) & (a < info.max + 1)
            if ok.all():
                return a.astype(dt)
        elif a.dtype.kind in "iu":
            if dt.kind == "f" or (a.min() >= np.iinfo(dt).min and a.max() <= np.iinfo(dt).max):
                return a.astype(dt)
    out = np.empty(len(vals), dt)
    for k, v in enumerate(vals):
        out[k] = _fits(_real(v, "shapes: feature %d: value" % k), dt, "shapes: feature %d: value" % k)
    return out


# ---- shapes -> flat arrays -------------------------------------------------------------

class _Flat:
    """Parts in burning order: a part is one Polygon (rings), one
    LineString or one Point.  xy holds every position; ring_sizes the
    positions of each ring (a line is one ring, a point a ring of one);
    part_rings the rings of each part; kind, feature (index in `shapes`)
    and value per part."""

    def __init__(self):
        self.xy = []
        self.ring_sizes = []
        self.part_rings = []
        self.kind = []
        self.feature = []
        self.geom = []  # which geometry: a collection's members are geometries
        self.ngeoms = 0


def _position_list(coords, what, need):
    """A ring or line's positions as an (N, 2) float64 array (a z is
    dropped), N >= need, or InputError."""
    try:
        a = np.asarray(coords, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError("%s: positions must be pairs of numbers" % what) from None
    if a.ndim != 2 or a.shape[1] not in (2, 3):
        if a.size == 0:
            raise InputError("%s is empty" % what)
        raise InputError("%s: positions must be (x, y) or (x, y, z), not shape %s" % (what, a.shape))
    if len(a) < need:
        raise InputError("%s has %d position(s); at least %d needed" % (what, len(a), need))
    return a[:, :2]


def _type_name(t):
    return t if isinstance(t, str) else repr(t)


_MAX_NESTING = 100  # GeometryCollections in GeometryCollections, far below Python's recursion limit


def _add_geometry(flat, geom, index, depth=0):
    what = "shapes: feature %d" % index
    if hasattr(geom, "__geo_interface__"):
        geom = geom.__geo_interface__
    if not hasattr(geom, "get"):
        raise InputError("%s: %r is not a geometry (no __geo_interface__, not a GeoJSON mapping)"
                         % (what, type(geom).__name__))
    gtype = geom.get("type")
    if gtype == "Feature" and depth == 0:
        return _add_geometry(flat, geom.get("geometry"), index, depth + 1)
    if gtype == "GeometryCollection":
        members = geom.get("geometries")
        if members is None:
            raise InputError("%s: GeometryCollection without 'geometries'" % what)
        members = list(members)
        if not members:
            raise InputError("%s: empty GeometryCollection" % what)
        if depth >= _MAX_NESTING:  # a collection holding itself, or nested past any real use
            raise InputError("%s: GeometryCollection nested more than %d deep (or holding itself)"
                             % (what, _MAX_NESTING))
        for g in members:
            _add_geometry(flat, g, index, depth + 1)
        return
    if gtype == "FeatureCollection":
        raise InputError("%s is %s" % (what, _core.FEATURE_COLLECTION))
    if gtype not in ("Polygon", "MultiPolygon", "LineString", "MultiLineString", "LinearRing",
                     "Point", "MultiPoint"):
        raise InputError("%s: unknown geometry type %s; rasterize burns Polygon, MultiPolygon, "
                         "LineString, MultiLineString, Point, MultiPoint and GeometryCollection"
                         % (what, _type_name(gtype)))
    coords = geom.get("coordinates")
    if coords is None:
        raise InputError("%s: %s without 'coordinates'" % (what, gtype))
    flat.ngeoms += 1
    before = len(flat.kind)
    try:
        coords = list(coords)
    except TypeError:
        raise InputError("%s: %s coordinates %r are not a sequence" % (what, gtype, coords)) from None
    if not coords:
        raise InputError("%s: empty %s" % (what, gtype))
    if gtype in ("Polygon", "MultiPolygon"):
        polys = [coords] if gtype == "Polygon" else coords
        for p, rings in enumerate(polys):
            try:
                rings = list(rings)
            except TypeError:
                raise InputError("%s: %s part %d is not a list of rings" % (what, gtype, p)) from None
            if not rings:
                raise InputError("%s: empty Polygon (%s part %d)" % (what, gtype, p))
            sizes = []
            for r, ring in enumerate(rings):
                a = _position_list(ring, "%s: %s%s ring %d" % (what, gtype, "" if gtype == "Polygon" else " part %d," % p, r), 3)
                flat.xy.append(a)
                sizes.append(len(a))
            flat.ring_sizes += sizes
            flat.part_rings.append(len(sizes))
            flat.kind.append(_KIND_POLYGON)
            flat.feature.append(index)
    elif gtype in ("LineString", "MultiLineString", "LinearRing"):
        lines = coords if gtype == "MultiLineString" else [coords]
        for p, line in enumerate(lines):
            a = _position_list(line, "%s: %s%s" % (what, gtype, " part %d" % p if gtype == "MultiLineString" else ""), 2)
            flat.xy.append(a)
            flat.ring_sizes.append(len(a))
            flat.part_rings.append(1)
            flat.kind.append(_KIND_LINE)
            flat.feature.append(index)
    else:
        points = [coords] if gtype == "Point" else coords
        a = _position_list(points, "%s: %s" % (what, gtype), 1)
        for k in range(len(a)):
            flat.xy.append(a[k:k + 1])
            flat.ring_sizes.append(1)
            flat.part_rings.append(1)
            flat.kind.append(_KIND_POINT)
            flat.feature.append(index)
    flat.geom += [flat.ngeoms] * (len(flat.kind) - before)


def _shapely_parts(geoms, index0=0):
    """The flat arrays of an array of shapely geometries, vectorised
    (shapely 2), or None when shapely is not there."""
    try:
        import shapely
    except ImportError:
        return None
    types = shapely.get_type_id(geoms)
    if (types < 0).any():  # None
        k = int(np.flatnonzero(types < 0)[0])
        raise InputError("shapes: feature %d is None, not a geometry" % (k + index0))
    parts, pidx = geoms, np.arange(len(geoms))
    gid = pidx  # the geometry a part belongs to: a collection's members are geometries
    t = types
    bad = np.zeros(len(geoms), bool)
    while (t >= 4).any():  # multi-geometries and collections: their parts, in order
        bad[pidx[(t >= 4) & (shapely.get_num_geometries(parts) == 0)]] = True  # an empty one
        parts, sub = shapely.get_parts(parts, return_index=True)
        pidx = pidx[sub]
        gid = np.where(t[sub] == 7, gid.max() + 1 + np.arange(len(sub)), gid[sub])
        t = shapely.get_type_id(parts)
    unknown = t > 3
    if unknown.any():
        k = int(np.flatnonzero(unknown)[0])
        raise InputError("shapes: feature %d: unknown geometry type %s" % (pidx[k] + index0, parts[k].geom_type))
    kind = np.where(t == 3, _KIND_POLYGON, np.where(t == 0, _KIND_POINT, _KIND_LINE))
    # Rings of each part, in part order: a polygon's rings, a line or point itself.
    poly = np.flatnonzero(t == 3)
    if not shapely.get_num_interior_rings(parts[poly]).any():
        # No holes: a polygon's coordinates are its exterior ring's.
        ring_geoms, ring_part = parts, np.arange(len(parts))
    else:
        rings, ridx = shapely.get_rings(parts[poly], return_index=True)
        other = np.flatnonzero(t != 3)
        ring_part = np.concatenate([poly[ridx], other])
        order = np.argsort(ring_part, kind="stable")
        ring_geoms = np.concatenate([rings, parts[other]])[order]
        ring_part = ring_part[order]
    xy, cidx = shapely.get_coordinates(ring_geoms, return_index=True)
    ring_sizes = np.bincount(cidx, minlength=len(ring_geoms))
    part_rings = np.bincount(ring_part, minlength=len(parts))
    # Empty geometries: a part without coordinates, or a feature without parts.
    bad[pidx[np.bincount(ring_part, weights=ring_sizes, minlength=len(parts)) == 0]] = True
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError("shapes: feature %d: empty %s" % (k + index0, geoms[k].geom_type))
    return xy, ring_sizes, part_rings, kind, pidx + index0, gid


def _is_shapely(g):
    mod = type(g).__module__
    return mod.startswith("shapely.")


def _flatten(items, index0=0):
    """(xy, ring_sizes, part_rings, kind, feature, geometry) of a list of
    geometries (geometry: which geometry each part belongs to, for GDAL's
    once-per-geometry rules)."""
    if items and _is_shapely(items[0]):
        arr = np.fromiter(items, dtype=object, count=len(items))
        try:
            import shapely
        except ImportError:  # pragma: no cover
            shapely = None
        if shapely is not None:
            try:
                return _shapely_parts(arr, index0)
            except TypeError:  # not all shapely geometries: the general path says which
                pass
    flat = _Flat()
    for k, g in enumerate(items):
        if g is None:
            raise InputError("shapes: feature %d is None, not a geometry" % (k + index0))
        _add_geometry(flat, g, k + index0)
    xy = np.concatenate(flat.xy) if flat.xy else np.zeros((0, 2))
    return (xy, np.asarray(flat.ring_sizes, np.int64), np.asarray(flat.part_rings, np.int64),
            np.asarray(flat.kind, np.int8), np.asarray(flat.feature, np.int64), np.asarray(flat.geom, np.int64))


def _split_shapes(shapes, default_value, fill, values):
    """([geometries], [values]) from the shapes argument."""
    if hasattr(shapes, "geometry") and hasattr(shapes, "columns"):  # GeoDataFrame
        geoms = list(np.asarray(shapes.geometry.values, dtype=object))
        if isinstance(values, str):
            if values not in shapes.columns:
                raise InputError("values=%r is not a column of the GeoDataFrame; columns: %s"
                                 % (values, ", ".join(map(str, shapes.columns))))
            values = list(shapes[values].tolist())
    elif type(shapes).__name__ == "GeoSeries":
        geoms = list(np.asarray(shapes.values, dtype=object))
    else:
        if _core.is_feature_collection(shapes):
            raise InputError("shapes is %s" % _core.FEATURE_COLLECTION)
        if isinstance(shapes, (str, bytes)) or hasattr(shapes, "__geo_interface__") or isinstance(shapes, dict):
            raise InputError("shapes must be an iterable of geometries or (geometry, value) pairs, "
                             "not one geometry; wrap it in a list")
        try:
            items = list(shapes)
        except TypeError:
            raise InputError("shapes must be an iterable of geometries or (geometry, value) pairs, "
                             "not %r" % type(shapes).__name__) from None
        if set(map(type, items)) == {tuple} and set(map(len, items)) == {2}:  # (geometry, value) pairs, quickly
            geoms, vals = list(map(_FIRST, items)), list(map(_SECOND, items))
            if None in vals:
                vals = [fill if v is None else v for v in vals]
        else:
            geoms, vals = [], []
            for item in items:
                if isinstance(item, (tuple, list)):
                    if len(item) != 2:
                        raise InputError("shapes: feature %d is a sequence of %s, not a (geometry, value) pair"
                                         % (len(geoms), _core.plural(len(item), "item")))
                    g, v = item
                    geoms.append(g)
                    vals.append(fill if v is None else v)
                else:
                    geoms.append(item)
                    vals.append(default_value)
        if values is None:
            return geoms, vals
    if values is None:
        return geoms, [default_value] * len(geoms)
    if isinstance(values, str):
        raise InputError("values=%r: a column name needs a GeoDataFrame" % (values,))
    values = list(values)
    if len(values) != len(geoms):
        raise InputError("values: %s for %s" % (_core.plural(len(values), "value"), _core.plural(len(geoms), "shape")))
    return geoms, [fill if v is None else v for v in values]


def _merge_name(merge_alg, coverage=False):
    name = merge_alg
    if not isinstance(name, str):
        name = getattr(merge_alg, "name", None)  # rasterio.enums.MergeAlg
    if isinstance(name, str) and name.lower() in (("replace", "add", "max") if coverage else ("replace", "add")):
        return name.lower()
    if isinstance(name, str) and name.lower() == "max":
        raise InputError("unknown merge_alg 'max' without coverage; choose one of: add, replace ('max' merges "
                         "coverage fractions: pass coverage='area')")
    raise InputError("unknown merge_alg %r; choose one of: add, replace%s (or rasterio's MergeAlg members)"
                     % (merge_alg, ", max" if coverage else ""))


def _out_array(out, out_shape, dtype, fill, values):
    """(array to burn into, whether it is new); checks only, writes nothing."""
    if out is not None:
        if not isinstance(out, np.ndarray):
            raise InputError("out must be a numpy array, not %s" % type(out).__name__)
        if out.ndim != 2:
            raise InputError("out must be 2-D (rows, columns), not %d-D" % out.ndim)
        _dtype(out.dtype, "out: dtype")
        if dtype is not None and _dtype(dtype, "dtype") != out.dtype:
            raise InputError("dtype %s differs from out's dtype %s" % (np.dtype(dtype), out.dtype))
        if not out.flags.writeable:
            raise InputError("out is read-only")
        if out_shape is not None and tuple(out_shape) != out.shape:
            raise InputError("out_shape %r differs from out's shape %r" % (tuple(out_shape), out.shape))
        if 0 in out.shape:
            raise InputError("out: width and height must be > 0, not shape %r" % (out.shape,))
        return out, False
    if out_shape is None:
        raise InputError("either out_shape or out must be given")
    try:
        n = len(out_shape)
    except TypeError:
        n = None
    if n != 2:
        raise InputError("Invalid out_shape %r: must be 2-D (height, width)" % (out_shape,))
    h, w = _core.int_pair(out_shape, "Invalid out_shape %r: must be 2-D (height, width)",
                          "out_shape must hold two ints, not %r")
    if h <= 0 or w <= 0 or h > _core.lib.RAST_MAX_DIM or w > _core.lib.RAST_MAX_DIM:
        raise InputError("out_shape %r: width and height must be > 0 and at most %d"
                         % (out_shape, _core.lib.RAST_MAX_DIM))
    if dtype is None:
        floats = any(isinstance(v, (float, np.floating)) for v in values)
        dt = np.dtype(np.float64 if floats else np.int64)
        if not floats and _past_int64(values):  # as numpy (and rasterio) type such values
            dt = np.dtype(np.uint64)
    else:
        dt = _dtype(dtype, "dtype")
    return (h, w, dt), True


def _past_int64(values) -> bool:
    """Whether the (integer) values are all >= 0 with one past int64's range."""
    try:
        return any(int(v) > 2 ** 63 - 1 for v in values) and all(int(v) >= 0 for v in values)
    except (TypeError, ValueError, OverflowError):
        return False


class _Progress:
    """progress= as a callable(done, total): True (tqdm), a callable, or None."""

    def __init__(self, progress, total):
        self.bar = None
        self.fn = None
        self.total = total
        self.done = 0
        if progress is None or progress is False:
            return
        if progress is True:
            try:
                import tqdm
            except ImportError:
                raise InputError("progress=True needs tqdm (pip install 'rastrum[gis]'), "
                                 "or pass a callable(done, total)") from None
            self.bar = tqdm.tqdm(total=total, unit="shape", desc="rasterize")
        elif callable(progress):
            self.fn = progress
        else:
            raise InputError("progress must be True, False, None or a callable(done, total), not %r" % (progress,))

    @property
    def active(self):
        return self.bar is not None or self.fn is not None

    def __call__(self, done):
        if self.bar is not None:
            self.bar.update(done - self.done)
        elif self.fn is not None:
            self.fn(done, self.total)
        self.done = done

    def close(self):
        if self.bar is not None:
            self.bar.close()


def rasterize(
    shapes: Iterable[ShapeItem],
    out_shape: Optional[Tuple[int, int]] = None,
    fill: Union[int, float] = 0,
    out: Optional[np.ndarray] = None,
    transform: Transform = IDENTITY,
    all_touched: bool = False,
    merge_alg: Any = "replace",
    default_value: Union[int, float] = 1,
    dtype: Any = None,
    *,
    rule: str = "evenodd",
    values: Union[str, Sequence[Union[int, float, None]], None] = None,
    progress: Union[bool, Callable[[int, int], Any], None] = None,
    nodata: Union[int, float, None] = None,
    masked: bool = False,
    skip_invalid: bool = False,
    tolerance: Optional[float] = None,
    coverage: Optional[str] = None,
) -> np.ndarray:
    """Burn shapes into a 2-D array, as ``rasterio.features.rasterize``.

    Parameters
    ----------
    shapes : iterable of geometries or of (geometry, value) pairs, a GeoSeries or a GeoDataFrame
        A geometry is a shapely geometry, anything with ``__geo_interface__``,
        or a GeoJSON-like mapping (a Feature's geometry is used): Polygon,
        MultiPolygon, LineString, MultiLineString, Point, MultiPoint,
        GeometryCollection.  A value of None burns `fill`.  Burnt in order;
        the parts of a multi-geometry or collection are burnt one by one,
        as rasterio does (so "add" adds overlapping parts twice).
    out_shape : (int, int)
        (height, width) of a new array; not needed with `out`.
    fill : number
        The background of a new array (`out` keeps its pixels).
    out : numpy.ndarray, optional
        A 2-D array to burn into, in place, and return.
    transform : affine.Affine or 6 numbers (a, b, c, d, e, f)
        Pixel (col, row) to world: x = a*col + b*row + c, y = d*col + e*row
        + f (Affine order; a GDAL geotransform gt is
        ``affine.Affine.from_gdal(*gt)``).  Any invertible affine: rotation,
        shear, flipped axes.  World coordinates are taken to pixels with
        GDAL's inverse geotransform in float64 (:func:`pixel_coordinates`).
    all_touched : bool
        False: a polygon burns the pixels whose centre is inside it, under
        the library's exact rule; True: also every pixel whose open square
        an edge meets (the conservative boundary mode); lines likewise burn
        every pixel they pass through.
    merge_alg : "replace" or "add" (or rasterio's MergeAlg members); "max" with `coverage`
        "add" adds each value, saturating at the dtype's limits (integers)
        or rounding the float64 sum to the dtype (floats), as GDAL does.
        With `coverage`: "replace" writes each shape's value * fraction on
        the cells it covers (fraction > 0; later shapes win), "add" adds
        it, "max" keeps the larger (a NaN cell takes the shape's).
    default_value : number
        The value of geometries given without one.
    dtype : one of DTYPES
        uint8, int8, uint16, int16, uint32, int32, int64, uint64, float32, float64;
        by default out's, else int64 for integer values and float64 if any
        value is a float (as rasterio; uint64 for integers past int64).
    rule : {"evenodd", "nonzero"}
        Polygon fill rule (GDAL's is even-odd).
    values : str or sequence, optional
        Values per shape: a column name of a GeoDataFrame, or a sequence.
    progress : bool or callable(done, total), optional
        True shows a tqdm bar (needs tqdm); a callable is called as
        batches of shapes are burnt.
    nodata : number, optional
        As rasterio: the value masked when `masked` is True (it does not
        change `fill`); checked against the dtype.  NaN masks the NaN
        pixels (rasterio's ``masked_equal`` masks none).
    masked : bool
        Return ``numpy.ma.masked_equal(out, nodata)`` (a masked array over
        the same memory; nothing masked without `nodata`), as rasterio.
    skip_invalid : bool
        True: a shape that is not a valid geometry (unknown or empty,
        too few positions, NaN or a position out of range) is skipped with
        a :class:`ShapeSkipWarning`, as rasterio does by default; False
        (the default): it is an InputError.
    tolerance : float or None
        A geometry may also be a ``rastrum.Path`` or a matplotlib ``Path``
        in world coordinates: one polygon of its subpaths (under `rule`),
        its curves flattened within `tolerance` PIXELS of the true ones
        (None: the Path's own, else ``Path.DEFAULT_TOLERANCE``;
        docs/paths.md).
    coverage : str, optional
        Burn coverage fractions instead of pixels: "area" (the exact area
        of each cell inside the shape, its vertices snapped to 2^-S px, S
        as fine as ``polygon_coverage`` takes for the shape's window) or a
        ``polygon_coverage`` method ("ss4", ...).  Each feature (a Polygon
        or MultiPolygon, its rings together under `rule`) burns value *
        fraction; dtype float64 (the default) or float32, or uint8/uint16
        levels (floor(a*255 + 1/2), floor(a*65535 + 1/2); values must be
        1).  `all_touched` must be False.  docs/gis.md, "Coverage".

    Returns
    -------
    numpy.ndarray (H, W): `out`, or a new array (a masked array with
    ``masked=True``).

    Raises
    ------
    InputError (a ValueError)
        Naming the feature index and the problem: an unknown or empty
        geometry, too few positions, NaN or infinite coordinates, a
        coordinate outside the range, a value that does not fit the dtype;
        or a bad out_shape, out, dtype, transform, merge_alg or rule.
        Nothing is written to `out` then.

    Examples
    --------
    >>> import rastrum
    >>> square = {"type": "Polygon", "coordinates": [[(1, 1), (4, 1), (4, 3), (1, 3), (1, 1)]]}
    >>> rastrum.rasterize([(square, 7)], out_shape=(4, 5), dtype="uint8")
    array([[0, 0, 0, 0, 0],
           [0, 7, 7, 7, 0],
           [0, 7, 7, 7, 0],
           [0, 0, 0, 0, 0]], dtype=uint8)
    """
    merge = _merge_name(merge_alg, coverage is not None)
    _core._name(rule, "fill rule", _core.RULES)
    if not isinstance(all_touched, (bool, np.bool_)):
        raise InputError("all_touched must be True or False, not %r" % (all_touched,))
    if coverage is not None:
        from . import _fractions
        coverage = _fractions._method(coverage)
        if all_touched:
            raise InputError("all_touched=True has no meaning with coverage= (every touched cell has its fraction)")
        if dtype is None and out is None:
            dtype = "float64"
        if dtype is not None:
            _fractions._coverage_dtype(dtype)
        if out is not None and isinstance(out, np.ndarray):
            _fractions._coverage_dtype(out.dtype, "out: dtype")
    t6 = _transform6(transform)
    inv = _inverse(t6)
    geoms, vals = _split_shapes(shapes, default_value, fill, values)
    geoms = _path_polygons(geoms, t6, inv, tolerance)
    flat = None
    if skip_invalid:
        geoms, vals, flat = _valid_only(geoms, vals, inv)
    _real(fill, "fill")
    target, new = _out_array(out, out_shape, dtype, fill, vals)
    dt = target.dtype if not new else target[2]
    fill_v = _fits(fill, dt, "fill")
    if nodata is not None:
        _fits(_real(nodata, "nodata"), dt, "nodata")
    if not isinstance(masked, (bool, np.bool_)):
        raise InputError("masked must be True or False, not %r" % (masked,))
    if coverage is not None:
        _fractions.check_values(vals, dt)
        vals = _values(vals, np.dtype(np.float64)) if dt.kind == "f" else vals
    else:
        vals = _values(vals, dt)
    xy, ring_sizes, part_rings, kind, feature, geom = flat if flat is not None else _flatten(geoms)
    px = _pixels(xy, inv, ring_sizes, part_rings, feature)
    bar = _Progress(progress, len(geoms))
    if new:
        h, w, dt = target
        # zeros (not -0.0): pages the kernel clears as they are first touched
        zero = fill_v == 0 and math.copysign(1.0, fill_v) > 0
        target = np.zeros((h, w), dt) if zero else np.full((h, w), fill_v, dt)
    try:
        if coverage is not None:
            _fractions.burn_coverage(target, px, ring_sizes, part_rings, kind, feature, len(geoms), vals, merge,
                                     rule, coverage, bar if bar.active else None)
        else:
            _burn.burn(target, px, ring_sizes, part_rings, kind, vals[feature], feature, geom, merge,
                       bool(all_touched), rule, bar)
    finally:
        bar.close()
    if masked:
        if nodata is not None and isinstance(nodata, (float, np.floating)) and math.isnan(nodata):
            return np.ma.masked_where(np.isnan(target), target, copy=False)
        return np.ma.masked_equal(target, nodata, copy=False)  # type: ignore[arg-type]  # None: nothing masked
    return target


def _path_polygons(geoms, t6, inv, tolerance):
    """Each Path (rastrum's or matplotlib's) among `geoms` as a Polygon
    mapping: flattened in pixel space (tolerance in pixels), its rings
    taken back to world coordinates."""
    from ._path import _tolerance, as_path

    if tolerance is not None:
        tolerance = _tolerance(tolerance)
    out = None
    for k, g in enumerate(geoms):
        p = as_path(g)
        if p is None:
            continue
        if out is None:
            out = list(geoms)
        c0, cx, cy, r0, rx, ry = inv
        a, b, c, d, e, f = t6
        rings = p.transformed((cx, cy, c0, rx, ry, r0)).flatten(8, tolerance)  # on the fill's grid
        out[k] = {"type": "Polygon", "coordinates": [
            np.column_stack([a * r[:, 0] + b * r[:, 1] + c, d * r[:, 0] + e * r[:, 1] + f]).tolist()
            for r in rings]}
    return geoms if out is None else out


class ShapeSkipWarning(UserWarning):
    """A shape rasterize(skip_invalid=True) skipped (rasterio's
    ``rasterio.errors.ShapeSkipWarning``)."""


def _valid_only(geoms, vals, inv):
    """(geometries, values, their _flatten) without the shapes that are not
    valid geometries, each skipped with a ShapeSkipWarning."""
    try:
        flat = _flatten(geoms)
        _pixels(flat[0], inv, flat[1], flat[2], flat[4])
        return geoms, vals, flat
    except InputError:
        pass
    keep_g, keep_v = [], []
    for k, (g, v) in enumerate(zip(geoms, vals)):
        try:
            one = _flatten([g], k)
            _pixels(one[0], inv, one[1], one[2], one[4])
        except InputError as e:
            warnings.warn("Invalid or empty shape at index %d will not be rasterized: %s" % (k, e),
                          ShapeSkipWarning, stacklevel=3)
            continue
        keep_g.append(g)
        keep_v.append(v)
    return keep_g, keep_v, None


def geometry_mask(
    geometries: Iterable[Any],
    out_shape: Tuple[int, int],
    transform: Transform,
    all_touched: bool = False,
    invert: bool = False,
) -> np.ndarray:
    """A boolean mask from shapes, as ``rasterio.features.geometry_mask``:
    False on the pixels the shapes burn (True with ``invert=True``), True
    elsewhere.  The pixels are rasterize's (same rule, `all_touched`).

    Examples
    --------
    >>> import rastrum
    >>> sq = {"type": "Polygon", "coordinates": [[(1, 1), (3, 1), (3, 2), (1, 2), (1, 1)]]}
    >>> rastrum.geometry_mask([sq], (3, 4), rastrum.IDENTITY, invert=True).astype(int)
    array([[0, 0, 0, 0],
           [0, 1, 1, 0],
           [0, 0, 0, 0]])
    """
    if not isinstance(invert, (bool, np.bool_)):
        raise InputError("invert must be True or False, not %r" % (invert,))
    fill, mask_value = (0, 1) if invert else (1, 0)
    return rasterize(geometries, out_shape=out_shape, transform=transform, all_touched=all_touched,
                     fill=fill, default_value=mask_value, dtype="uint8").view(bool)


@dataclass(frozen=True)
class Window:
    """A window of a raster in rasterio's terms (``rasterio.windows.Window``
    fields, whole pixels): columns col_off .. col_off + width - 1, rows
    row_off .. row_off + height - 1.  ``raster[w.toslices()]`` reads it
    from a numpy array; ``rasterio.windows.Window(*w.astuple())`` makes
    rasterio's, and ``dataset.read(window=w.toranges())`` reads it."""

    col_off: int
    row_off: int
    width: int
    height: int

    def toslices(self) -> Tuple[slice, slice]:
        """(rows, columns) slices."""
        return (slice(self.row_off, self.row_off + self.height), slice(self.col_off, self.col_off + self.width))

    def toranges(self) -> Tuple[Tuple[int, int], Tuple[int, int]]:
        """((row_start, row_stop), (col_start, col_stop)), rasterio's tuple form."""
        return ((self.row_off, self.row_off + self.height), (self.col_off, self.col_off + self.width))

    def astuple(self) -> Tuple[int, int, int, int]:
        return (self.col_off, self.row_off, self.width, self.height)


def _grid_of(dataset) -> Tuple[Tuple[int, int], Tuple[float, ...]]:
    """((height, width), transform) of a dataset-like or a (shape, transform) pair."""
    if hasattr(dataset, "rio") and hasattr(dataset, "dims"):  # rioxarray
        return (int(dataset.rio.height), int(dataset.rio.width)), _transform6(dataset.rio.transform())
    if hasattr(dataset, "transform") and hasattr(dataset, "width") and hasattr(dataset, "height"):
        return (int(dataset.height), int(dataset.width)), _transform6(dataset.transform)
    if isinstance(dataset, (tuple, list)) and len(dataset) == 2:
        shape, transform = dataset
        h, w = _core.int_pair(shape, "geometry_window: shape %r must be (height, width)",
                              "geometry_window: shape must hold two ints, not %r")
        if h <= 0 or w <= 0:
            raise InputError("geometry_window: shape %r: height and width must be > 0" % ((h, w),))
        return (h, w), _transform6(transform)
    raise InputError("geometry_window: dataset must have .transform, .width and .height (a rasterio dataset), "
                     "be a rioxarray DataArray, or a ((height, width), transform) pair; not %r"
                     % type(dataset).__name__)


def geometry_window(
    dataset: Any,
    shapes: Iterable[Any],
    pad_x: float = 0,
    pad_y: float = 0,
    pixel_precision: Any = None,
    boundless: bool = False,
) -> Window:
    """The window of a raster that holds the shapes, as
    ``rasterio.features.geometry_window``: every position of every shape
    taken to pixels with ``~transform`` (affine's inverse, as rasterio),
    padded by pad_x columns and pad_y rows (fractions of a pixel), from the
    floor of the least to the ceiling of the greatest; then cut to the
    raster unless `boundless`.

    Parameters
    ----------
    dataset : a rasterio dataset, a rioxarray DataArray, or ((height, width), transform)
        Anything with ``.transform``, ``.width`` and ``.height``.
    shapes : iterable of geometries
        As rasterize takes them (their values, if pairs, are ignored).
    pixel_precision : ignored
        As in rasterio 1.4, which ignores it too.

    Returns
    -------
    Window

    Raises
    ------
    InputError
        No shapes, a bad geometry or dataset, or (without `boundless`) a
        window that does not overlap the raster (rasterio: WindowError).

    Examples
    --------
    >>> import rastrum
    >>> sq = {"type": "Polygon", "coordinates": [[(1.5, 1), (3, 1), (3, 3.2), (1.5, 3.2), (1.5, 1)]]}
    >>> rastrum.geometry_window(((10, 10), (1, 0, 0, 0, -1, 10)), [sq], pad_x=0.5, pad_y=2)
    Window(col_off=1, row_off=4, width=3, height=6)
    """
    (h, w), t = _grid_of(dataset)
    for name, v in (("pad_x", pad_x), ("pad_y", pad_y)):
        if not math.isfinite(float(_real(v, name))):
            raise InputError("%s %r is not finite" % (name, v))
    geoms, _ = _split_shapes(shapes, 1, 0, None)
    if not geoms:
        raise InputError("geometry_window: no shapes")
    xy = _flatten(geoms)[0]
    sa, sb, sc, sd, se, sf = t
    det = sa * se - sb * sd
    if det == 0:
        raise InputError("transform %r is not invertible" % (t,))
    idet = 1.0 / det
    ra, rb, rd, re = se * idet, -sb * idet, -sd * idet, sa * idet
    rc, rf = -sc * ra - sf * rb, -sc * rd - sf * re
    x, y = xy[:, 0], xy[:, 1]
    cols = x * ra + y * rb + rc
    rows = x * rd + y * re + rf
    if not (np.isfinite(cols).all() and np.isfinite(rows).all()):
        raise InputError("geometry_window: a position is not finite in pixels")
    col_start = int(math.floor(cols.min() - pad_x))
    col_stop = int(math.ceil(cols.max() + pad_x))
    row_start = int(math.floor(rows.min() - pad_y))
    row_stop = int(math.ceil(rows.max() + pad_y))
    win = Window(col_start, row_start, max(col_stop - col_start, 0), max(row_stop - row_start, 0))
    if boundless:
        return win
    c0, r0 = max(win.col_off, 0), max(win.row_off, 0)
    width = min(win.col_off + win.width, w) - c0
    height = min(win.row_off + win.height, h) - r0
    if width <= 0 or height <= 0:
        raise InputError("geometry_window: the shapes' window %r does not overlap the %d x %d raster "
                         "(boundless=True returns it)" % (win, h, w))
    return Window(c0, r0, width, height)


def grid(
    bounds: Sequence[float],
    resolution: Union[float, Tuple[float, float]],
    tap: bool = False,
) -> Tuple[Tuple[int, int], Tuple[float, ...]]:
    """(out_shape, transform) of a north-up raster over `bounds` at
    `resolution`, as ``gdal_rasterize -te xmin ymin xmax ymax -tr xres yres
    [-tap]`` makes it.

    `bounds` is (xmin, ymin, xmax, ymax) (GDAL's -te order, shapely's and
    GeoPandas' ``total_bounds``); `resolution` one number or (xres, yres),
    both > 0.  With `tap` (target-aligned pixels) the bounds first grow to
    multiples of the resolution: xmin = floor(xmin / xres) * xres, xmax =
    ceil(xmax / xres) * xres, and so for y.  Then width = int(0.5 + (xmax
    - xmin) / xres), height = int(0.5 + (ymax - ymin) / yres), and the
    transform (Affine order) is (xres, 0, xmin, 0, -yres, ymax).

    Examples
    --------
    >>> import rastrum
    >>> rastrum.grid((0.3, 0.2, 2.9, 1.1), 0.5, tap=True)
    ((3, 6), (0.5, 0.0, 0.0, 0.0, -0.5, 1.5))
    """
    try:
        b = [float(_real(v, "bounds: value")) for v in bounds]
    except TypeError:
        raise InputError("bounds must be (xmin, ymin, xmax, ymax), not %r" % (bounds,)) from None
    if len(b) != 4 or not all(math.isfinite(v) for v in b):
        raise InputError("bounds must be 4 finite numbers (xmin, ymin, xmax, ymax), not %r" % (bounds,))
    xmin, ymin, xmax, ymax = b
    if not (xmax > xmin and ymax > ymin):
        raise InputError("bounds %r: xmax must be > xmin and ymax > ymin" % (tuple(bounds),))
    if isinstance(resolution, (tuple, list)):
        if len(resolution) != 2:
            raise InputError("resolution must be one number or (xres, yres), not %r" % (resolution,))
        xres, yres = (float(_real(v, "resolution")) for v in resolution)
    else:
        xres = yres = float(_real(resolution, "resolution"))
    if not (xres > 0 and yres > 0 and math.isfinite(xres) and math.isfinite(yres)):
        raise InputError("resolution %r must be > 0 and finite" % (resolution,))
    if not isinstance(tap, (bool, np.bool_)):
        raise InputError("tap must be True or False, not %r" % (tap,))
    if tap:
        xmin = math.floor(xmin / xres) * xres
        xmax = math.ceil(xmax / xres) * xres
        ymin = math.floor(ymin / yres) * yres
        ymax = math.ceil(ymax / yres) * yres
    width = int(0.5 + (xmax - xmin) / xres)
    height = int(0.5 + (ymax - ymin) / yres)
    if width < 1 or height < 1 or width > _core.lib.RAST_MAX_DIM or height > _core.lib.RAST_MAX_DIM:
        raise InputError("bounds %r at resolution %r give %d x %d pixels; each must be in 1..%d"
                         % (tuple(bounds), resolution, width, height, _core.lib.RAST_MAX_DIM))
    return (height, width), (xres, 0.0, float(xmin), 0.0, -yres, float(ymax))


def _pixels(xy, inv, ring_sizes, part_rings, feature):
    """The float64 pixel coordinates of world positions xy under the
    inverse transform inv (_inverse), or InputError naming the feature of
    the first one that is not finite or lies outside the range."""
    if not len(xy):
        return xy
    px = np.empty_like(xy)
    x, y = xy[:, 0], xy[:, 1]
    with np.errstate(invalid="ignore", over="ignore"):  # inf * 0: named below
        px[:, 0] = inv[0] + x * inv[1] + y * inv[2]
        px[:, 1] = inv[3] + x * inv[4] + y * inv[5]
    if not np.abs(px).max() <= _burn.COORD_LIMIT:  # also NaN
        bad = ~(np.isfinite(px).all(axis=1) & (np.abs(px) <= _burn.COORD_LIMIT).all(axis=1))
        _coordinate_error(xy, px, int(np.flatnonzero(bad)[0]), ring_sizes, part_rings, feature)
    return px


def _coordinate_error(xy, px, k, ring_sizes, part_rings, feature):
    ring = int(np.searchsorted(np.cumsum(ring_sizes), k, side="right"))
    part = int(np.searchsorted(np.cumsum(part_rings), ring, side="right"))
    x, y = xy[k].tolist()
    what = "shapes: feature %d: position (%r, %r)" % (feature[part], x, y)
    if not (math.isfinite(x) and math.isfinite(y)):
        raise InputError("%s is %s, not a finite number" % (what, "NaN" if math.isnan(x) or math.isnan(y) else "infinite"))
    raise InputError("%s is at pixel (%r, %r), outside the range +-%r pixels"
                     % (what, px[k, 0], px[k, 1], _burn.COORD_LIMIT))
