"""Every public name, used as a user's script would use it, with the types
written out: ``make typecheck`` runs ``mypy --strict`` on this file against
the installed package (its annotations and py.typed are what a user's mypy
sees), and pytest runs it, so the annotations are checked against what the
calls return."""

from typing import Any, Dict, List, Tuple

import numpy as np
import numpy.typing as npt

import rastrum
import rastrum.gis
from rastrum import coco, scene

SQUARE = [(1.0, 1.0), (5.0, 1.0), (5.0, 4.0), (1.0, 4.0)]
TRIS = [[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]]


def test_masks_and_coverage() -> None:
    m: npt.NDArray[np.bool_] = rastrum.polygon_mask(SQUARE, (6, 7), rule="nonzero", algorithm="edgeflag")
    t: npt.NDArray[np.bool_] = rastrum.triangles_mask(TRIS, (6, 7), algorithm="sweep")
    n: npt.NDArray[np.uint16] = rastrum.triangles_count(TRIS, (6, 7))
    c: npt.NDArray[Any] = rastrum.polygon_coverage(SQUARE, (6, 7), method="ss4", dtype=np.float32)
    tc: npt.NDArray[Any] = rastrum.triangles_coverage(TRIS, (6, 7), method="area")
    assert m.dtype == np.bool_ and t.dtype == np.bool_ and n.dtype == np.uint16
    assert c.dtype == np.float32 and tc.dtype == np.uint8
    px: npt.NDArray[np.int32] = rastrum.line_pixels((0, 0), (5, 2), algorithm="dda")
    inside: bool = rastrum.point_in_triangle((1, 1), TRIS[0], method="barycentric")
    assert px.dtype == np.int32 and inside is True
    algos: Dict[str, Any] = rastrum.ALGORITHMS
    aa: Dict[str, Any] = rastrum.AA_METHODS
    assert "aet" in algos["polygon_mask"] and "Canvas.fill_polygon" in aa
    assert isinstance(rastrum.__version__, str)


def test_canvas() -> None:
    c = rastrum.Canvas((6, 8), format="rgb888", background="white")
    c.fill_polygon(SQUARE, "red", rule="evenodd", aa="area")
    c.fill_triangle(TRIS[0], (0, 255, 0))
    c.fill_triangles(TRIS, vertex_colors=[[(255, 0, 0), (0, 255, 0), (0, 0, 255)]], shading="gouraud")
    c.fill_rect_gouraud((0, 0, 4, 4), [(0, 0, 0)] * 4, method="triangles")
    c.line((0, 0), (7, 5), "#00f")
    c.polyline([(0, 0), (3, 0), (3, 3)], 9, closed=True)
    c.flood_fill((7, 0), "black", connectivity=8)
    c.boundary_fill((7, 0), 5, 9)
    a: npt.NDArray[Any] = c.array
    w: int = c.width
    h: int = c.height
    f: str = c.format
    assert a.shape == (h, w, 3) and f == "rgb888"
    g = rastrum.Canvas.wrap(np.zeros((4, 4), np.int32), format="label")
    g.fill_polygon(SQUARE, 7)
    c.clear_depth()
    assert c.depth is None or c.depth.dtype == np.int32
    mono = rastrum.Canvas((4, 9), format="mono1")
    packed: npt.NDArray[np.uint8] = mono.packed
    assert packed.shape == (4, 2) and mono.to_image().mode == "1" and repr(mono).startswith("Canvas(")


def test_shaded_aa_rect() -> None:
    c = rastrum.Canvas((6, 8), format="rgba8888")
    c.fill_rect_gouraud((0.5, 0.5, 7.5, 5.5), [(0, 0, 0, 255)] * 4, aa="ss4", shading="flat", opacity=0.5)
    assert c.array[2, 2, 3] > 0


def test_batches_coco_gis_scene() -> None:
    polys = coco.polygons([[[1.0, 1.0, 5.0, 1.0, 3.0, 4.0]], [[0.0, 0.0, 2.0, 0.0, 0.0, 2.0]]])
    batch: rastrum.Polygons = polys
    rings: List[npt.NDArray[np.float64]] = batch[0]
    assert len(batch) == 2 and rings[0].shape == (3, 2)
    ms: npt.NDArray[np.bool_] = rastrum.masks(batch, (6, 6))
    lab: npt.NDArray[Any] = rastrum.labels(batch, (6, 6), values=[3, 4], dtype=np.uint8)
    assert ms.shape == (2, 6, 6) and lab.dtype == np.uint8
    rle: Dict[str, Any] = coco.frPyObjects([1.0, 1.0, 5.0, 1.0, 3.0, 4.0], 6, 6)
    rles: List[Dict[str, Any]] = coco.frPyObjects([[1.0, 1.0, 5.0, 1.0, 3.0, 4.0]], 6, 6)
    d: npt.NDArray[np.uint8] = coco.decode(rle)
    enc = coco.encode(np.asfortranarray(d))
    assert coco.area(rle) == coco.area(rles)[0] == d.sum() and enc["counts"] == rle["counts"]
    box: npt.NDArray[np.float64] = coco.toBbox(rles)
    merged: Dict[str, Any] = coco.merge(rles + rles, intersect=True)
    assert box.shape == (1, 4) and coco.iou([merged], rles, [0])[0][0] == 1.0
    assert len(coco.rings([1.0, 1.0, 5.0, 1.0, 3.0, 4.0])) == 1
    r: npt.NDArray[Any] = rastrum.rasterize([({"type": "Polygon", "coordinates": [SQUARE]}, 2)],
                                            out_shape=(6, 7), transform=rastrum.IDENTITY)
    frac: npt.NDArray[Any] = rastrum.rasterize([{"type": "Polygon", "coordinates": [SQUARE]}], out_shape=(6, 7),
                                               coverage="area", merge_alg="max")
    per: List[Tuple[npt.NDArray[Any], npt.NDArray[Any]]] = rastrum.coverage_fractions(
        [{"type": "Polygon", "coordinates": [SQUARE]}], (6, 7))
    flat: Tuple[npt.NDArray[Any], npt.NDArray[Any], npt.NDArray[Any]] = rastrum.coverage_fractions(
        [{"type": "Polygon", "coordinates": [SQUARE]}], (6, 7), flat=True)
    assert frac.sum() == per[0][1].sum() == flat[2].sum()
    xy: npt.NDArray[Any] = rastrum.gis.pixel_coordinates(np.array([[1.0, 2.0]]))
    assert r.sum() == 2 * 12 and xy.shape == (1, 2)
    v, f, _ = scene.sphere(6, 8)
    pic: rastrum.Canvas = rastrum.render_mesh(v, f, shape=(32, 32), shading="gouraud",
                                              rotation=scene.rotation(yaw=20.0))
    assert pic.array.any()


def test_errors() -> None:
    try:
        rastrum.polygon_mask(SQUARE, (-1, 2))
    except ValueError as e:
        assert isinstance(e, rastrum.InputError) and isinstance(e, rastrum.RastrumError)
    else:
        raise AssertionError("no InputError")


def test_option_literals_list_what_the_code_accepts() -> None:
    """Each Literal of the annotations names exactly the options the code
    takes (a new algorithm or method must be added to both)."""
    from typing import get_args

    from rastrum import _core, _coverage, _ml, _shading, _typing

    def names(alias: Any) -> List[str]:
        return sorted(get_args(alias))

    assert names(_typing.PolygonAlgorithm) == sorted(rastrum.ALGORITHMS["polygon_mask"])
    assert names(_typing.TriangleAlgorithm) == sorted(rastrum.ALGORITHMS["triangles_mask"])
    assert names(_typing.LineAlgorithm) == sorted(rastrum.ALGORITHMS["Canvas.line"])
    assert names(_typing.CoverageMethod) == sorted(_coverage.METHODS)
    assert names(_typing.Rule) == sorted(_core.RULES)
    assert names(_typing.Rounding) == sorted(_core.ROUNDINGS)
    assert names(_typing.Boundary) == sorted(_core.BOUNDARIES)
    assert names(_typing.Format) == sorted(_core.FORMATS)
    assert names(_typing.BatchRule) == sorted(_ml._RULES)
    assert names(_typing.Precision) + ["flat"] == sorted(_shading.PRECISIONS)  # "flat" is shading="flat"


def test_labels_overlap_overloads() -> None:
    sq = [SQUARE, [(2.0, 2.0), (6.0, 2.0), (6.0, 5.0)]]
    lab, count = rastrum.labels(sq, (6, 7), overlap=True, rule="coco")
    n: npt.NDArray[np.uint16] = count
    one: npt.NDArray[Any] = rastrum.labels(sq, (6, 7))
    assert n.dtype == np.uint16 and lab.shape == one.shape == (6, 7)


def test_the_api_reference_lists_every_public_name() -> None:
    import os

    import rastrum.dask

    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "api.md")
    with open(path, encoding="utf-8") as f:
        entries = {line[4:].strip() for line in f if line.startswith("::: ")}
    modules = {"scene": scene, "coco": coco}
    want = {"rastrum." + n for n in rastrum.__all__ if n not in modules and n != "__version__"}
    want |= {"rastrum.%s.%s" % (m, n) for m, mod in modules.items() for n in mod.__all__
             if n not in rastrum.__all__}  # rastrum.scene.render_mesh is rastrum.render_mesh
    want |= {"rastrum.dask.rasterize", "rastrum.dask.to_xarray", "rastrum.dask.zonal_stats",
             "rastrum.gis.pixel_coordinates"}
    assert want - entries == set()
