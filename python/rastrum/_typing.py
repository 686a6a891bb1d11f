"""The types of the public API's arguments, named once (for the
annotations; mypy --strict checks them, tests/test_typing.py checks that
each option Literal lists exactly the names the code accepts)."""

from typing import TYPE_CHECKING, Any, Literal, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from ._path import Path

#: (height, width), as numpy writes a shape.
Shape = Tuple[int, int]
#: A polygon: one (N, 2) array-like of (x, y) vertices or a list of them.
Rings = npt.ArrayLike
#: What polygon_mask and polygon_coverage take: rings, or a Path (its
#: curves flattened within its tolerance).
PathRings = Union[npt.ArrayLike, "Path"]
#: A pixel value: an int (gray, label, packed), a tuple of channels, or a
#: colour name or "#rgb" / "#rrggbb[aa]" string (Pillow's ImageColor).
Color = Union[int, str, Sequence[int], npt.NDArray[np.integer[Any]]]
#: A point (x, y) in pixels.
Point = Union[Tuple[float, float], Sequence[float], npt.NDArray[Any]]

Rule = Literal["evenodd", "nonzero"]
PolygonAlgorithm = Literal["aet", "crossing", "edgefill", "edgeflag", "fence", "winding", "xscan"]
TriangleAlgorithm = Literal["edge", "edgeflag", "sweep"]
LineAlgorithm = Literal["bresenham", "dda"]
CoverageMethod = Literal["area", "ss2", "ss4", "ss8", "ss16", "accumulate"]
Rounding = Literal["exact", "textbook"]
Boundary = Literal["exact", "closed", "conservative"]
Format = Literal["gray8", "rgb888", "rgba8888", "rgb565", "mono1"]
Shading = Literal["gouraud", "flat"]
Precision = Literal["exact", "fixed"]
#: The fill rules of masks() and labels().
BatchRule = Literal["union", "evenodd", "nonzero", "coco"]
