"""scipy.spatial.Delaunay's attributes on optri's triangulations: checked
against their definitions in exact rational arithmetic (fractions.Fraction),
and against scipy, matplotlib and shapely where they are installed."""

import itertools
import math
import random
from fractions import Fraction

import numpy as np
import pytest

import optri


def exact(v):
    return Fraction(float(v))


def orient(a, b, c):
    """The exact orientation sign of three points given as Fractions."""
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def contains(tri, q):
    """Whether the closed counter-clockwise triangle `tri` contains `q`."""
    return all(orient(tri[j], tri[(j + 1) % 3], q) >= 0 for j in range(3))


def smallest_containing(corners, q):
    """The smallest index of a triangle containing q, -1 for none: the
    brute-force reference of find_simplex."""
    for i, tri in enumerate(corners):
        xs = [p[0] for p in tri]
        ys = [p[1] for p in tri]
        if min(xs) <= q[0] <= max(xs) and min(ys) <= q[1] <= max(ys) and contains(tri, q):
            return i
    return -1


def grid():
    return [(x, y) for x in range(7) for y in range(6)]


def collinear_run_and_one_point():
    return [(x, 0) for x in range(30)] + [(13, 5)]


def cocircular():
    # Twelve integer points on the circle of radius 5, and its centre.
    ring = {(sx * a, sy * b) for a, b in [(3, 4), (4, 3), (5, 0), (0, 5)] for sx in (1, -1) for sy in (1, -1)}
    return sorted(ring) + [(0, 0)]


def with_duplicates():
    rnd = random.Random(4)
    pts = [(rnd.randrange(20), rnd.randrange(20)) for _ in range(60)]
    return pts + pts[:7] + [pts[3]]


def random_floats():
    return np.random.default_rng(5).random((150, 2)).tolist()


SETS = {
    "grid": grid,
    "collinear": collinear_run_and_one_point,
    "cocircular": cocircular,
    "duplicates": with_duplicates,
    "random": random_floats,
}


def twin_map(t):
    kept = {int(d): int(k) for d, k in t.duplicates}
    return lambda i: kept.get(i, i)


def check_scipy_attributes(t, points):
    """int32 dtypes, counter-clockwise simplices, and neighbors,
    vertex_to_simplex and convex_hull by their definitions."""
    s = t.simplices
    for name in ("simplices", "neighbors", "vertex_to_simplex", "convex_hull"):
        array = getattr(t, name)
        assert array.dtype == np.int32, name
        assert not array.flags.writeable, name
    p = [(exact(x), exact(y)) for x, y in points]
    tris = s.tolist()
    for a, b, c in tris:
        assert orient(p[a], p[b], p[c]) > 0
    uses = {}
    for i, tri in enumerate(tris):
        for j in range(3):
            uses.setdefault(frozenset(tri) - {tri[j]}, []).append(i)
    nb = t.neighbors
    assert nb.shape == s.shape
    for i, tri in enumerate(tris):
        for j in range(3):
            side = frozenset(tri) - {tri[j]}
            k = int(nb[i, j])
            if k >= 0:
                assert k != i and set(tris[k]) & set(tri) == side
                assert sorted(uses[side]) == sorted([i, k])
            else:
                assert uses[side] == [i]
    twin = twin_map(t)
    vts = t.vertex_to_simplex
    assert vts.shape == (len(points),)
    for v in range(len(points)):
        having = [i for i, tri in enumerate(tris) if twin(v) in tri]
        assert int(vts[v]) == min(having)
    boundary = [(tri[(j + 1) % 3], tri[(j + 2) % 3]) for i, tri in enumerate(tris) for j in range(3) if nb[i, j] < 0]
    hull = [tuple(e) for e in t.convex_hull.tolist()]
    assert sorted(hull) == sorted(boundary)
    assert hull[0][0] == min(a for a, _ in hull)
    assert all(hull[i][1] == hull[(i + 1) % len(hull)][0] for i in range(len(hull)))


def queries_for(points, tris):
    """Queries on every vertex, on edge midpoints that are doubles, at
    centroids, and scattered over and beyond the bounding box."""
    qs = [tuple(map(float, p)) for p in points]
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            mid = [(exact(points[u][k]) + exact(points[v][k])) / 2 for k in range(2)]
            if all(Fraction(float(m)) == m for m in mid):
                qs.append((float(mid[0]), float(mid[1])))
        qs.append(tuple(sum(float(points[i][k]) for i in (a, b, c)) / 3 for k in range(2)))
    xs = [float(x) for x, _ in points]
    ys = [float(y) for _, y in points]
    rnd = random.Random(6)
    for _ in range(150):
        qs.append(
            (
                rnd.uniform(min(xs) - 1, max(xs) + 1),
                rnd.uniform(min(ys) - 1, max(ys) + 1),
            )
        )
    return qs


@pytest.mark.parametrize("criterion", ["delaunay", "minmax-length", "greedy"])
@pytest.mark.parametrize("name", sorted(SETS))
def test_attributes_and_find_simplex_by_their_definitions(name, criterion):
    points = SETS[name]()
    t = optri.triangulate(points, criterion)
    check_scipy_attributes(t, points)
    tris = t.simplices.tolist()
    qs = queries_for(points, tris)
    found = t.find_simplex(qs)
    assert found.dtype == np.int32 and found.shape == (len(qs),)
    corners = [[(exact(points[i][0]), exact(points[i][1])) for i in tri] for tri in tris]
    for q, f in zip(qs, found.tolist()):
        assert f == smallest_containing(corners, (exact(q[0]), exact(q[1]))), q
    # Every input point, duplicates included, is in the triangle found.
    assert (t.find_simplex(t.points) >= 0).all()


def test_polygon_attributes_and_location():
    # An L-shape: the notch is inside the hull, outside the polygon.
    ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]
    t = optri.triangulate_polygon(ring)
    check_scipy_attributes(t, ring)
    assert sorted(map(tuple, t.convex_hull.tolist())) == sorted((i, (i + 1) % 6) for i in range(6))
    qs = [(3, 3), (1, 1), (5, 5), (2, 3), (3, 2), (2.5, 2.5)]
    found = t.find_simplex(qs).tolist()
    assert [f >= 0 for f in found] == [False, True, False, True, True, False]
    corners = [[(exact(ring[i][0]), exact(ring[i][1])) for i in tri] for tri in t.simplices.tolist()]
    assert found == [smallest_containing(corners, (exact(x), exact(y))) for x, y in qs]


@pytest.mark.parametrize("criterion", ["delaunay", "min-weight"])
def test_location_in_a_comb_polygon_matches_brute_force(criterion):
    # Walks from a start near the query leave the comb through its notches;
    # the answer must still be the smallest triangle holding the query.
    teeth = 6
    ring = [(0, 0), (4 * teeth, 0)]
    for k in reversed(range(teeth)):
        ring += [(4 * k + 3, 8), (4 * k + 1, 8)]
        if k > 0:
            ring += [(4 * k + 1, 2), (4 * k - 1, 2)]
    t = optri.triangulate_polygon(ring, criterion)
    check_scipy_attributes(t, ring)
    corners = [[(exact(ring[i][0]), exact(ring[i][1])) for i in tri] for tri in t.simplices.tolist()]
    rnd = random.Random(8)
    qs = [(rnd.uniform(-1, 4 * teeth + 1), rnd.uniform(-1, 9)) for _ in range(400)]
    qs += [(x / 2, y / 2) for x in range(-1, 8 * teeth + 2) for y in range(-1, 18)]
    found = t.find_simplex(qs).tolist()
    assert found == [smallest_containing(corners, (exact(x), exact(y))) for x, y in qs]
    assert 0 < sum(f >= 0 for f in found) < len(qs)


def test_decimal_input_is_located_at_its_decimals():
    # 0.15, 0.05 is on the side from (0.1, 0) to (0.2, 0.1) as written, so
    # it is a hull vertex between them; located as decimals, every input
    # point is found, and a query beside a vertex at its binary value.
    points = [(0, 0), (0.1, 0), (0.2, 0.1), (0, 0.3), (0.15, 0.05)]
    t = optri.triangulate(points)
    assert t.document["coordinate_arithmetic"] == "decimal-exact"
    assert (t.find_simplex(points) >= 0).all()
    decimal = [(Fraction(repr(float(x))), Fraction(repr(float(y)))) for x, y in points]
    corners = [[decimal[i] for i in tri] for tri in t.simplices.tolist()]
    qs = [(0.05, 0.05), (0.125, 0.025), (0.15, 0.05), (0.1, 0.2), (0.3, 0.3)]
    expected = [smallest_containing(corners, (Fraction(repr(x)), Fraction(repr(y)))) for x, y in qs]
    assert t.find_simplex(qs).tolist() == expected
    beyond = math.nextafter(0.1, 1.0)
    binary = (Fraction(beyond), Fraction(0))
    assert t.find_simplex([beyond, 0.0]) == smallest_containing(corners, binary)


def test_find_simplex_shapes_and_errors():
    t = optri.triangulate([(0, 0), (2, 0), (0, 2), (2, 2)])
    assert t.find_simplex([0.5, 0.5]).shape == ()
    assert t.find_simplex(np.zeros((3, 4, 2))).shape == (3, 4)
    assert t.find_simplex(np.zeros((0, 2))).shape == (0,)
    assert t.find_simplex([[1e300, 0.0], [-1e300, 1.0]]).tolist() == [-1, -1]
    for bad in ([float("nan"), 0.0], [[0.0, float("inf")]], [1e-300, 0.0]):
        with pytest.raises(ValueError):
            t.find_simplex(bad)
    with pytest.raises(ValueError, match=r"\(\.\.\., 2\)"):
        t.find_simplex(np.zeros((5, 3)))


def test_geo_interface_is_closed_counter_clockwise_triangles():
    points = with_duplicates()
    t = optri.triangulate(points)
    geo = t.__geo_interface__
    assert geo["type"] == "MultiPolygon"
    assert len(geo["coordinates"]) == len(t.simplices)
    for polygon, tri in zip(geo["coordinates"], t.simplices.tolist()):
        (ring,) = polygon
        assert len(ring) == 4 and ring[0] == ring[-1]
        assert [tuple(ring[k]) for k in range(3)] == [tuple(map(float, points[i])) for i in tri]
        assert orient(*[(exact(x), exact(y)) for x, y in ring[:3]]) > 0


def test_version_is_the_crates():
    assert optri.__version__ == optri.registry()["optri_version"]


# --- against scipy, matplotlib and shapely --------------------------------------


def general_position(seed, n=300):
    return np.random.default_rng(seed).random((n, 2))


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_delaunay_matches_scipy(seed):
    spatial = pytest.importorskip("scipy.spatial")
    points = general_position(seed)
    t = optri.triangulate(points)
    d = spatial.Delaunay(points)
    ours = [frozenset(s) for s in t.simplices.tolist()]
    theirs = [frozenset(s) for s in d.simplices.tolist()]
    assert set(ours) == set(theirs)
    # The same triangles, numbered differently: compare through them.
    index = {s: i for i, s in enumerate(ours)}
    to_ours = np.array([index[s] for s in theirs] + [-1])
    neighbors = to_ours[d.neighbors]
    for i, s in enumerate(d.simplices.tolist()):
        j = index[frozenset(s)]
        corner = {v: int(n) for v, n in zip(t.simplices[j].tolist(), t.neighbors[j].tolist())}
        assert {v: int(n) for v, n in zip(s, neighbors[i])} == corner
    assert {frozenset(e) for e in t.convex_hull.tolist()} == {frozenset(e) for e in d.convex_hull.tolist()}
    for v, k in enumerate(t.vertex_to_simplex.tolist()):
        assert v in t.simplices[k] and v in d.simplices[d.vertex_to_simplex[v]]
    queries = np.random.default_rng(seed + 10).random((2000, 2)) * 1.4 - 0.2
    ours_found = t.find_simplex(queries)
    theirs_found = d.find_simplex(queries)
    assert (ours_found >= 0).tolist() == (theirs_found >= 0).tolist()
    inside = theirs_found >= 0
    assert (ours_found[inside] == to_ours[theirs_found[inside]]).all()


def test_to_matplotlib_has_the_same_triangles():
    pytest.importorskip("matplotlib")
    points = with_duplicates()
    t = optri.triangulate(points, "minmax-length")
    m = t.to_matplotlib()
    assert m.triangles.tolist() == t.simplices.tolist()
    assert m.x.tolist() == t.points[:, 0].tolist() and m.y.tolist() == t.points[:, 1].tolist()


def test_shapely_shape_covers_the_hull():
    geometry = pytest.importorskip("shapely.geometry")
    points = general_position(7, 200)
    t = optri.triangulate(points, "greedy")
    shape = geometry.shape(t)
    assert shape.geom_type == "MultiPolygon" and len(shape.geoms) == len(t.simplices)
    hull = geometry.MultiPoint([tuple(p) for p in points]).convex_hull
    assert math.isclose(shape.area, hull.area, rel_tol=1e-12)
    assert all(g.exterior.is_ccw for g in shape.geoms)


def test_to_matplotlib_without_matplotlib_names_it(monkeypatch):
    import builtins

    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name.startswith("matplotlib"):
            raise ImportError("no matplotlib here")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    t = optri.triangulate([(0, 0), (1, 0), (0, 1)])
    with pytest.raises(ImportError, match="pip install matplotlib"):
        t.to_matplotlib()
