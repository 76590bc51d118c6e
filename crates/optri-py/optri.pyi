"""Exact optimal planar triangulations and proximity graphs (type stubs).

Every name and description comes from the library's registry, and every
result attribute is a field of the JSON document ``optri triangulate --json``
prints (schema version ``SCHEMA_VERSION``).
"""

from os import PathLike
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, TypedDict, Union, final

import numpy as np
import numpy.typing as npt

__version__: str
SCHEMA_VERSION: int

_ArrayLike = npt.ArrayLike
_StrPath = Union[str, "PathLike[str]"]
_IndexArray = npt.NDArray[np.int64]
_Int32Array = npt.NDArray[np.int32]
_PointArray = npt.NDArray[np.float64]

class _StatsAlways(TypedDict):
    max_edge_length: float
    longest_edge: List[int]
    total_edge_length: float
    min_area: float
    max_area: float
    smallest_triangle: List[int]
    largest_triangle: List[int]
    min_angle_deg: float
    max_angle_deg: float
    min_height: float
    min_height_triangle: List[int]
    max_eccentricity: float
    max_eccentricity_triangle: List[int]
    triangles: int
    edges: int
    hull_points: int

class _Stats(_StatsAlways, total=False):
    # Only for points with elevations.
    max_slope: float
    max_slope_triangle: List[int]

class _Bound(TypedDict):
    kind: str
    triangle: List[int]
    area: float

class _CriterionEntry(TypedDict):
    name: str
    description: str
    optimality: str
    inputs: List[str]
    options: List[str]
    reference: str
    needs_elevations: bool
    measure: Optional[str]
    guarantee: str

class _GraphKindEntry(TypedDict):
    name: str
    description: str
    options: List[str]

class _OptionEntry(TypedDict):
    name: str
    description: str
    values: str
    default: str
    every_run: bool

class _MeasureEntry(TypedDict):
    name: str
    label: str
    better: str

class _Registry(TypedDict):
    document: str
    schema_version: int
    optri_version: str
    criteria: List[_CriterionEntry]
    graphs: List[_GraphKindEntry]
    options: List[_OptionEntry]
    input_formats: List[str]
    measures: List[_MeasureEntry]

@final
class Triangulation:
    """An optimal (or, where ``exact`` is False, best known) triangulation.

    The arrays are read-only; indices are 0-based input indices (ring
    positions for a polygon). ``simplices``, ``neighbors``,
    ``vertex_to_simplex``, ``convex_hull`` and ``find_simplex`` follow
    ``scipy.spatial.Delaunay`` (int32, scipy's meanings).
    """

    @property
    def points(self) -> _PointArray:
        """(n, 2) float64: every input point, merged duplicates included."""
    @property
    def elevations(self) -> Optional[npt.NDArray[np.float64]]:
        """(n,) float64: every input point's elevation, or None without them."""
    @property
    def simplices(self) -> _Int32Array:
        """(m, 3) int32: the triangles, counter-clockwise."""
    @property
    def neighbors(self) -> _Int32Array:
        """(m, 3) int32: ``neighbors[i, j]`` is the triangle across the side
        opposite corner ``simplices[i, j]``, -1 on the boundary."""
    @property
    def vertex_to_simplex(self) -> _Int32Array:
        """(n,) int32: the smallest index of a triangle with each input point
        as a corner; a merged duplicate maps as the point it was merged into."""
    @property
    def convex_hull(self) -> _Int32Array:
        """(h, 2) int32: the boundary sides ``[a, b]`` of the triangulated
        domain (the hull, or the polygon), domain on the left, counter-clockwise
        from the smallest vertex index."""
    @property
    def edges(self) -> _IndexArray:
        """(k, 2) int64: every edge once, ``[a, b]`` with a < b, sorted."""
    @property
    def duplicates(self) -> _IndexArray:
        """(d, 2) int64: merged duplicates as ``[dropped, kept]``."""
    @property
    def criterion(self) -> str:
        """The criterion's registry name."""
    @property
    def exact(self) -> bool:
        """True iff the result is provably optimal."""
    @property
    def optimality(self) -> str:
        """"exact", "up-to-rounding" or "approximation"."""
    @property
    def bound(self) -> Optional[_Bound]:
        """A certified bound on the optimum, when the criterion gives one."""
    @property
    def approximation(self) -> Optional[Dict[str, Any]]:
        """maxmin-area / minmax-area on general point sets: the approximation
        chosen, the Delaunay smallest angle, the alpha used, the candidates,
        the flips and the guarantee; else None."""
    @property
    def algorithm(self) -> str:
        """The algorithm that ran, in words."""
    @property
    def domain(self) -> str:
        """"convex-hull" or "polygon"."""
    @property
    def distinct_points(self) -> int:
        """The number of distinct points."""
    @property
    def stats(self) -> _Stats:
        """Quality measures (the CLI's ``stats``)."""
    @property
    def diagnostics(self) -> Dict[str, int]:
        """Counters the algorithm reported."""
    @property
    def timing_ms(self) -> Dict[str, float]:
        """Milliseconds per phase: "validate", the library's phases, "total"."""
    @property
    def document(self) -> Dict[str, Any]:
        """The whole JSON document as a dict."""
    @property
    def __geo_interface__(self) -> Dict[str, Any]:
        """A GeoJSON-like MultiPolygon: one closed counter-clockwise ring per
        simplex, so ``shapely.geometry.shape(t)`` works."""
    def find_simplex(self, xi: _ArrayLike) -> _Int32Array:
        """The index of a triangle containing each query of ``xi`` (shape
        (..., 2)) as an int32 array of shape (...), -1 outside. Exact; a query
        on a shared side or corner gets the smallest index. For decimal input,
        a query whose reprs lie on the input's decimal grid is taken at those
        decimals, any other at its binary value. ValueError for NaN, infinite
        or non-zero coordinates below 2**-142 in magnitude."""
    def to_matplotlib(self) -> Any:
        """A ``matplotlib.tri.Triangulation`` of ``points`` and ``simplices``
        (ImportError naming matplotlib when it is missing)."""
    def to_json(self, pretty: bool = False) -> str:
        """The JSON document ``optri triangulate --json`` prints."""
    def write(self, path: _StrPath) -> List[Path]:
        """Writes .json, .svg, .geojson, .ele or .edge (+ .node), .obj, .ply or .off; returns the paths."""

def triangulate(
    points: _ArrayLike,
    criterion: str = "delaunay",
    *,
    elevations: Optional[_ArrayLike] = None,
    **options: Any,
) -> Triangulation:
    """Triangulates the convex hull of an (n, 2) point array by ``criterion``.

    An (n, 3) array, or ``elevations=`` with one float per point, gives each
    point an elevation (kept as ``elevations``; read by the criteria that
    need one, ignored by the others).

    Floats are taken at the decimals their reprs show when every coordinate's
    repr has at most 15 significant digits (``coordinate_arithmetic`` is then
    "decimal-exact"), else at their binary values ("binary64")."""

def triangulate_polygon(
    vertices: _ArrayLike,
    criterion: str = "delaunay",
    *,
    elevations: Optional[_ArrayLike] = None,
    **options: Any,
) -> Triangulation:
    """Triangulates the interior of a simple polygon given as an (n, 2) ring
    (or (n, 3) with elevations, or ``elevations=``)."""

def compare(
    points: _ArrayLike,
    criteria: Optional[Sequence[str]] = None,
    *,
    elevations: Optional[_ArrayLike] = None,
    **options: Any,
) -> Dict[str, Union[Triangulation, ValueError]]:
    """Every criterion (or those named) on one input, by criterion name; a
    criterion that refuses the input maps to its (unraised) ValueError."""

def graph(points: _ArrayLike, kind: str, **options: Any) -> _IndexArray:
    """The (k, 2) int64 edges of a proximity graph: hull, delaunay, rng, gabriel, mst
    (rng and mst also under ``metric=``: "l1", "linf", "lp:P", "polygon:x1,y1,...").
    Two points and collinear points give the path through them."""

def graph_document(points: _ArrayLike, kind: str, **options: Any) -> Dict[str, Any]:
    """The JSON document ``optri graph --json`` prints, as a dict."""

def decide(
    points: _ArrayLike,
    criterion: str,
    *,
    at_least: Optional[Union[float, int, str]] = None,
    at_most: Optional[Union[float, int, str]] = None,
    polygon: bool = False,
    **options: Any,
) -> Dict[str, Any]:
    """Is there a triangulation whose every triangle has area at least ``at_least``
    ("maxmin-area") or at most ``at_most`` ("minmax-area")? Areas are not doubled, in the
    input's units; a threshold is taken exactly as the decimal it prints as. Returns the
    decision document: "answer" (True, False, or None for unknown), "method", "exact",
    "witness" (a triangulation document when True), "threshold", "threshold_decimal",
    "timing_ms". ``polygon=True`` decides the interior of the simple polygon whose ring
    ``points`` is. Raises ValueError on a bad criterion, bound or threshold."""

def registry() -> _Registry:
    """The registry listing: the JSON document of ``optri criteria --json``."""

def criteria() -> List[_CriterionEntry]:
    """Every criterion of the registry, in display order."""

def graph_kinds() -> List[_GraphKindEntry]:
    """Every proximity graph kind of the registry."""

def read_points(path: _StrPath, format: Optional[str] = None) -> _PointArray:
    """Reads a point file (text, node, poly, tsplib, geojson, ply, obj) as an (n, 2) array."""

def read_polygon(path: _StrPath, format: Optional[str] = None) -> _PointArray:
    """Reads a simple polygon's ring (.poly or GeoJSON Polygon) as an (n, 2) array."""
