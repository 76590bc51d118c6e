"""Tests of the Python bindings against an independent brute-force reference
(oracle.py), known optimal values, the CLI's JSON document and the library's
error messages."""

import itertools
import json
import math
import os
import pathlib
import random
from fractions import Fraction
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import optri
import oracle

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parents[2]

STATS_KEYS = {
    "max_edge_length",
    "longest_edge",
    "smallest_triangle",
    "largest_triangle",
    "total_edge_length",
    "min_area",
    "max_area",
    "min_angle_deg",
    "max_angle_deg",
    "min_height",
    "min_height_triangle",
    "max_eccentricity",
    "max_eccentricity_triangle",
    "triangles",
    "edges",
    "hull_points",
}

SQUARE_AND_CENTRE = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 1)]


def names():
    return [c["name"] for c in optri.criteria()]


def random_points(rnd, n, size=60):
    """n distinct integer points with pairwise distinct lengths, not all collinear."""
    while True:
        pts = list({(rnd.randrange(size), rnd.randrange(size)) for _ in range(n)})
        if len(pts) < n:
            continue
        lengths = [oracle.dist2(p, q) for p, q in itertools.combinations(pts, 2)]
        if len(set(lengths)) == len(lengths) and len(oracle.hull(pts)) >= 3:
            return pts


def convex_points(rnd, n):
    """n integer points in strictly convex position, in random order."""
    while True:
        angles = sorted(rnd.uniform(0, 2 * math.pi) for _ in range(3 * n))
        pts = [(round(1000 * math.cos(a)), round(1000 * math.sin(a))) for a in angles]
        ring = oracle.hull(pts)
        if len(ring) >= n:
            ring = ring[:n]
            if len(oracle.hull(ring)) == n:
                rnd.shuffle(ring)
                return ring


def check_triangulation(t, points):
    """Counter-clockwise simplices of input indices that exactly tile the
    convex hull of the distinct points, each of which is a vertex."""
    s = t.simplices
    assert s.dtype == np.int32 and s.ndim == 2 and s.shape[1] == 3
    dropped = {int(d) for d, _ in t.duplicates}
    distinct = {i for i in range(len(points)) if i not in dropped}
    for a, b, c in s.tolist():
        assert oracle.orient(points[a], points[b], points[c]) > 0, (a, b, c)
    assert set(s.ravel().tolist()) == distinct
    total = sum(oracle.orient(points[a], points[b], points[c]) for a, b, c in s.tolist())
    assert total == oracle.double_area(oracle.hull(points))
    assert t.stats["triangles"] == len(s)
    assert t.simplices.tolist() == t.document["triangles"]
    return s.tolist()


def measures(points, tris):
    edges = {tuple(sorted(e)) for a, b, c in tris for e in ((a, b), (b, c), (c, a))}
    areas = [oracle.orient(points[a], points[b], points[c]) for a, b, c in tris]
    return {
        "max_len2": max(oracle.dist2(points[i], points[j]) for i, j in edges),
        "weight": sum(math.sqrt(oracle.dist2(points[i], points[j])) for i, j in edges),
        "min_area2": min(areas),
        "max_area2": max(areas),
        "edges": edges,
    }


def optima(points):
    """The brute-force optimum of every measure over all triangulations."""
    all_measures = [measures(points, oracle.triangles(points, e)) for e in oracle.triangulations(points)]
    return {
        "max_len2": min(m["max_len2"] for m in all_measures),
        "weight": min(m["weight"] for m in all_measures),
        "maxmin_area2": max(m["min_area2"] for m in all_measures),
        "minmax_area2": min(m["max_area2"] for m in all_measures),
        "maxmin_angle": max(
            oracle.min_angle(points, oracle.triangles(points, e)) for e in oracle.triangulations(points)
        ),
        "count": len(all_measures),
    }


# --- known optimal values -------------------------------------------------


def compare_2d(points):
    """`optri.compare` on points without elevations: every criterion answers
    in registry order, and those that read elevations refuse them."""
    results = optri.compare(points)
    assert list(results) == names()
    for c in optri.criteria():
        if c["needs_elevations"]:
            refused = results.pop(c["name"])
            assert isinstance(refused, ValueError) and "needs an elevation" in str(refused)
    return results


def test_square_with_centre_has_one_triangulation_and_its_values():
    # The centre lies on both diagonals, so the fan of 4 triangles is the only
    # triangulation; every criterion that takes interior points returns it.
    assert optima(SQUARE_AND_CENTRE)["count"] == 1
    results = compare_2d(SQUARE_AND_CENTRE)
    exact_in_listing = {c["name"] for c in optri.criteria() if c["optimality"] == "exact"}
    for name, t in results.items():
        tris = check_triangulation(t, SQUARE_AND_CENTRE)
        assert sorted(tuple(sorted(x)) for x in tris) == [(0, 1, 4), (0, 3, 4), (1, 2, 4), (2, 3, 4)], name
        assert t.stats["max_edge_length"] == 2.0
        assert t.stats["total_edge_length"] == pytest.approx(8 + 4 * math.sqrt(2), rel=1e-15)
        assert t.stats["min_area"] == t.stats["max_area"] == 1.0
        assert t.stats["min_angle_deg"] == pytest.approx(45.0, rel=1e-12)
        assert t.stats["max_angle_deg"] == pytest.approx(90.0, rel=1e-12)
        assert t.stats["hull_points"] == 4 and t.stats["edges"] == 8
        # Exact wherever the registry promises it (the δ criteria do not on
        # sets that are not in convex position).
        assert t.exact or name not in exact_in_listing, name


def test_rectangle_with_inner_point_minmax_length_is_the_long_side():
    t = optri.triangulate([[0, 0], [4, 0], [0, 3], [4, 3], [2, 1]], criterion="minmax-length")
    assert t.exact and t.criterion == "minmax-length"
    assert t.stats["max_edge_length"] == 4.0
    assert len(t.simplices) == 4


def test_pentagon_min_weight_is_a_fan_of_the_two_short_diagonals():
    # A regular pentagon: every triangulation uses two diagonals of the same
    # length, so the weight is 5 sides + 2 diagonals.
    pts = [(math.cos(2 * math.pi * k / 5), math.sin(2 * math.pi * k / 5)) for k in range(5)]
    t = optri.triangulate(pts, "min-weight")
    side = 2 * math.sin(math.pi / 5)
    diagonal = 2 * math.sin(2 * math.pi / 5)
    assert t.stats["total_edge_length"] == pytest.approx(5 * side + 2 * diagonal, rel=1e-12)
    # Exact: sums of lengths are compared exactly (the kernel's sum comparison).
    assert t.optimality == "exact" and t.exact is True


# --- against the brute-force oracle --------------------------------------


@pytest.mark.parametrize("seed", range(12))
def test_general_sets_match_the_brute_force_optima(seed):
    rnd = random.Random(seed)
    pts = random_points(rnd, 5 + seed % 3)
    best = optima(pts)
    results = compare_2d(pts)
    for name, t in results.items():
        m = measures(pts, check_triangulation(t, pts))
        if name == "min-weight":
            assert t.exact and m["weight"] == pytest.approx(best["weight"], rel=1e-12)
        elif name == "minmax-length":
            assert t.exact and m["max_len2"] == best["max_len2"]
            assert t.stats["max_edge_length"] == pytest.approx(math.sqrt(best["max_len2"]), rel=1e-15)
        elif name == "greedy":
            assert t.exact and m["edges"] == oracle.greedy(pts)
        elif name == "delaunay":
            assert t.stats["min_angle_deg"] == pytest.approx(best["maxmin_angle"], rel=1e-9)
        elif name == "maxmin-area":
            # Never better than the optimum; equal to it when it says exact,
            # and a certified upper bound on the optimum when it does not.
            assert m["min_area2"] <= best["maxmin_area2"]
            if t.exact:
                assert m["min_area2"] == best["maxmin_area2"]
            else:
                assert t.bound["kind"] == "upper" and 2 * t.bound["area"] >= best["maxmin_area2"]
        elif name == "minmax-area":
            assert m["max_area2"] >= best["minmax_area2"]
            if t.exact:
                assert m["max_area2"] == best["minmax_area2"]
            else:
                assert t.bound["kind"] == "lower" and 2 * t.bound["area"] <= best["minmax_area2"]


@pytest.mark.parametrize("seed", range(8))
def test_convex_sets_match_the_brute_force_optima(seed):
    rnd = random.Random(100 + seed)
    pts = convex_points(rnd, 5 + seed % 4)
    best = optima(pts)
    results = compare_2d(pts)
    for name, t in results.items():
        m = measures(pts, check_triangulation(t, pts))
        if name == "min-weight":
            assert m["weight"] == pytest.approx(best["weight"], rel=1e-12)
        elif name == "maxmin-area":
            assert t.exact and m["min_area2"] == best["maxmin_area2"]
        elif name == "minmax-area":
            assert t.exact and m["max_area2"] == best["minmax_area2"]
        elif name == "minmax-length":
            assert t.exact and m["max_len2"] == best["max_len2"]


# Inputs on which neither the Delaunay nor the greedy triangulation
# minimises the longest edge (found by search against the oracle).
LONGEST_EDGE_TRAPS = [
    [(24, 8), (18, 27), (21, 9), (25, 14), (0, 14), (13, 5)],
    [(15, 21), (11, 9), (29, 6), (28, 25), (23, 24)],
    [(4, 0), (2, 17), (24, 27), (27, 4), (27, 0), (15, 25)],
    [(27, 5), (8, 27), (19, 23), (1, 1), (27, 6), (28, 11)],
]


@pytest.mark.parametrize("pts", LONGEST_EDGE_TRAPS)
def test_minmax_length_beats_delaunay_and_greedy_where_they_differ(pts):
    best = optima(pts)["max_len2"]
    results = optri.compare(pts, criteria=["minmax-length", "delaunay", "greedy"])
    got = {name: measures(pts, check_triangulation(t, pts))["max_len2"] for name, t in results.items()}
    assert got["minmax-length"] == best
    assert got["delaunay"] > best and got["greedy"] > best


def test_delaunay_simplices_have_empty_circumcircles():
    rnd = random.Random(5)
    pts = [(rnd.randrange(-1000, 1000), rnd.randrange(-1000, 1000)) for _ in range(200)]
    t = optri.triangulate(pts, "delaunay")
    tris = check_triangulation(t, pts)

    def incircle(a, b, c, d):
        rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
        rows = [(x, y, x * x + y * y) for x, y in rows]
        (a1, a2, a3), (b1, b2, b3), (c1, c2, c3) = rows
        return a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)

    used = {p for tri in tris for p in tri}
    for a, b, c in tris:
        for d in used - {a, b, c}:
            assert incircle(pts[a], pts[b], pts[c], pts[d]) <= 0


# --- graphs ----------------------------------------------------------------

GRID = [(x, y) for x in range(3) for y in range(3)]


@pytest.mark.parametrize(
    "kind,count",
    # Gabriel uses the closed disc, so the grid's diagonals are not edges.
    [("gabriel", 12), ("rng", 12), ("mst", 8), ("hull", 8), ("delaunay", 16)],
)
def test_graph_edge_counts_on_a_3x3_grid(kind, count):
    edges = optri.graph(np.array(GRID, dtype=float), kind=kind)
    assert edges.dtype == np.int64 and edges.shape == (count, 2)


def test_gabriel_grid_edges_are_the_unit_edges():
    edges = optri.graph(GRID, kind="gabriel").tolist()
    assert all(oracle.dist2(GRID[a], GRID[b]) == 1 for a, b in edges)


@pytest.mark.parametrize("seed", range(6))
def test_graphs_match_their_definitions(seed):
    rnd = random.Random(200 + seed)
    pts = random_points(rnd, 12, size=40)
    as_set = lambda kind: {tuple(e) for e in optri.graph(pts, kind).tolist()}  # noqa: E731
    assert as_set("gabriel") == oracle.gabriel(pts)
    assert as_set("rng") == oracle.rng(pts)
    assert as_set("mst") == oracle.mst(pts)
    # The hull: a closed counter-clockwise cycle with every point on or left
    # of every edge, and no point inside an edge (collinear boundary points
    # are vertices).
    ring = optri.graph(pts, "hull").tolist()
    assert [b for _, b in ring] == [a for a, _ in ring[1:] + ring[:1]]
    for a, b in ring:
        assert all(oracle.orient(pts[a], pts[b], p) >= 0 for p in pts)
        assert not any(oracle.on_open_segment(p, pts[a], pts[b]) for p in pts)
    assert {pts[a] for a, _ in ring} >= set(oracle.hull(pts))


def test_graph_document_is_the_clis_graph_document():
    doc = optri.graph_document(GRID + [GRID[4]], "rng")
    assert doc["document"] == "graph" and doc["kind"] == "rng"
    assert doc["schema_version"] == optri.SCHEMA_VERSION
    assert doc["duplicates"] == [[9, 4]] and doc["distinct_points"] == 9
    assert len(doc["edges"]) == 12
    assert list(doc["timing_ms"]) == ["rng", "total"]


# --- the document and the CLI ---------------------------------------------


def test_attributes_are_the_documents_fields():
    pts = [(0, 0), (4, 0), (0, 3), (4, 3), (2, 1), (4, 0)]
    t = optri.triangulate(pts, criterion="greedy")
    doc = t.document
    assert doc == json.loads(t.to_json()) == json.loads(t.to_json(pretty=True))
    assert doc["schema_version"] == optri.SCHEMA_VERSION and doc["document"] == "triangulation"
    for name in ("criterion", "exact", "optimality", "algorithm", "domain", "stats", "diagnostics", "timing_ms"):
        assert getattr(t, name) == doc[name], name
    assert set(t.stats) == STATS_KEYS
    assert list(t.timing_ms)[0] == "validate" and list(t.timing_ms)[-1] == "total"
    assert t.duplicates.tolist() == doc["duplicates"] == [[5, 1]]
    assert t.edges.tolist() == doc["edges"]
    assert t.points.tolist() == doc["coordinates"]
    assert t.distinct_points == 5 and doc["points"] == 6
    assert 5 not in t.simplices
    assert t.bound is None
    with pytest.raises(ValueError):
        t.simplices[0, 0] = 1  # the arrays are read-only
    assert "greedy" in repr(t)


def cli():
    """The optri binary: $OPTRI_CLI (which must exist; CI sets it), else the
    workspace's debug build if there is one."""
    path = os.environ.get("OPTRI_CLI")
    if path:
        assert os.path.exists(path), f"OPTRI_CLI={path} does not exist"
        return path
    path = str(REPO / "target" / "debug" / "optri")
    if not os.path.exists(path):
        pytest.skip("no optri binary (set OPTRI_CLI)")
    return path


@pytest.mark.parametrize("criterion", ["minmax-length", "maxmin-area"])
def test_document_equals_the_clis_json(tmp_path, criterion):
    rnd = random.Random(9)
    pts = [(rnd.uniform(-5, 5), rnd.uniform(-5, 5)) for _ in range(60)] + [(0.5, 0.25)] * 2
    path = tmp_path / "points.txt"
    path.write_text("".join(f"{x!r} {y!r}\n" for x, y in pts))
    out = subprocess.run(
        [cli(), "triangulate", str(path), "--criterion", criterion, "--json"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    theirs = json.loads(out)
    # Decimals with 17 significant digits do not scale to integers below 2^53:
    # the CLI ran on the doubles, and so do the bindings (the floats' reprs
    # have more than 15 significant digits).
    assert theirs["coordinate_arithmetic"] == "binary64"
    ours = optri.triangulate(optri.read_points(path), criterion).document
    assert list(ours) == list(theirs)
    assert list(ours["stats"]) == list(theirs["stats"])
    for doc in (ours, theirs):
        del doc["timing_ms"]
    assert ours == theirs


def test_write_and_read_back(tmp_path):
    pts = SQUARE_AND_CENTRE + [(3, 1)]
    t = optri.triangulate(pts, "minmax-area")
    written = t.write(tmp_path / "t.json")
    assert [pathlib.Path(p) for p in written] == [tmp_path / "t.json"]
    assert json.loads((tmp_path / "t.json").read_text())["triangles"] == t.simplices.tolist()
    assert optri.read_points(tmp_path / "t.json").tolist() == [list(map(float, p)) for p in pts]
    assert len(t.write(str(tmp_path / "t.ele"))) == 2
    with pytest.raises(OSError, match="t.png"):
        t.write(tmp_path / "t.png")


# --- polygons ----------------------------------------------------------------

L_SHAPE = [(0, 0), (0, 2), (1, 2), (1, 1), (2, 1), (2, 0)]  # clockwise


@pytest.mark.parametrize(
    "criterion",
    [c["name"] for c in optri.criteria() if "polygon" in c["inputs"] and not c["needs_elevations"]],
)
def test_polygon_interior(criterion):
    t = optri.triangulate_polygon(L_SHAPE, criterion=criterion)
    assert t.domain == "polygon" and len(t.simplices) == len(L_SHAPE) - 2
    total = 0
    for a, b, c in t.simplices.tolist():
        o = oracle.orient(L_SHAPE[a], L_SHAPE[b], L_SHAPE[c])
        assert o > 0
        total += o
    assert total == -oracle.double_area(L_SHAPE)
    # The chord 2-4 leaves the polygon.
    assert [2, 4] not in t.edges.tolist()


def test_self_intersecting_polygon_is_refused_naming_the_edges():
    with pytest.raises(ValueError, match="not a simple polygon"):
        optri.triangulate_polygon([(0, 0), (2, 2), (2, 0), (0, 2)])


# --- the registry ------------------------------------------------------------


def test_criteria_and_kinds_come_from_the_registry():
    entries = optri.criteria()
    assert names()[:3] == ["delaunay", "minmax-length", "greedy"]
    for e in entries:
        assert set(e) == {
            "name",
            "description",
            "optimality",
            "inputs",
            "options",
            "reference",
            "needs_elevations",
            "measure",
            "guarantee",
        }
        assert e["description"] and e["reference"]
    assert [k["name"] for k in optri.graph_kinds()] == ["hull", "delaunay", "rng", "gabriel", "mst"]
    registry = optri.registry()
    assert registry["document"] == "criteria" and registry["criteria"] == entries
    # Names are case-insensitive, as in the CLI.
    assert optri.triangulate(SQUARE_AND_CENTRE, "DELAUNAY").criterion == "delaunay"


def test_compare_named_criteria_runs_exactly_those():
    r = optri.compare(SQUARE_AND_CENTRE, criteria=["greedy", "delaunay"])
    assert list(r) == ["greedy", "delaunay"]
    with pytest.raises(ValueError, match="unknown option 'metric' for these criteria"):
        optri.compare(SQUARE_AND_CENTRE, criteria=["delaunay"], metric="l1")
    # A refusal is reported as the error it would raise, not dropped.
    r = optri.compare(SQUARE_AND_CENTRE, metric="l1")
    assert list(r) == names()
    assert isinstance(r["minmax-length"], optri.Triangulation)
    assert isinstance(r["delaunay"], ValueError)
    assert "delaunay does not take a metric other than euclidean" in str(r["delaunay"])


# --- bad input -----------------------------------------------------------------


@pytest.mark.parametrize(
    "points,message",
    [
        ([[0, 0], [1, float("nan")], [2, 3]], "point 1 has a non-finite coordinate"),
        ([[0, 0], [1, float("inf")], [2, 3]], "point 1 has a non-finite coordinate"),
        ([[0, 0], [1e300, 1], [2, 3]], "outside the exact range"),
        ([[0, 0], [1, 1]], "at least 3 distinct points, the input has 2"),
        ([[0, 0], [1, 1], [0, 0], [1, 1]], "at least 3 distinct points, the input has 2"),
        ([[0, 0], [1, 1], [2, 2], [3, 3]], "all 4 distinct points are collinear"),
        ([[0, 0, 0, 0], [1, 1, 1, 1], [2, 0, 1, 1]], r"shape \(n, 2\) or \(n, 3\), got \(3, 4\)"),
        ([0, 1, 2], r"shape \(n, 2\) or \(n, 3\), got \(3,\)"),
        ([], r"shape \(n, 2\) or \(n, 3\), got \(0,\)"),
        (np.zeros((2, 3, 2)), r"shape \(n, 2\) or \(n, 3\), got \(2, 3, 2\)"),
        ([["a", "b"], ["c", "d"], ["e", "f"]], "could not convert"),
        ([[0, 0], [1], [2, 3]], "array-like of numbers"),
    ],
)
def test_bad_points_raise_value_error_with_the_librarys_message(points, message):
    with pytest.raises(ValueError, match=message):
        optri.triangulate(points, criterion="delaunay")


# --- elevations ----------------------------------------------------------------

TERRAIN = [(0, 0, 1.5), (4, 0, 2), (4, 3, -1), (0, 3, 0), (2, 1, 7), (4, 0, 2)]


def test_a_third_column_or_elevations_keyword_is_kept_as_elevations(tmp_path):
    by_column = optri.triangulate(np.array(TERRAIN, dtype=float))
    by_keyword = optri.triangulate([p[:2] for p in TERRAIN], elevations=[p[2] for p in TERRAIN])
    for t in (by_column, by_keyword):
        assert t.points.shape == (6, 2)
        assert t.elevations.tolist() == [p[2] for p in TERRAIN]
        assert not t.elevations.flags.writeable
        assert t.document["elevations"] == [p[2] for p in TERRAIN]
    assert by_column.simplices.tolist() == by_keyword.simplices.tolist()
    assert optri.triangulate([p[:2] for p in TERRAIN]).elevations is None
    assert "elevations" not in optri.triangulate([p[:2] for p in TERRAIN]).document
    # The same x y z file through the CLI gives the same document.
    path = tmp_path / "terrain.txt"
    path.write_text("".join(f"{x} {y} {z}\n" for x, y, z in TERRAIN))
    theirs = json.loads(
        subprocess.run(
            [cli(), "triangulate", str(path), "--json"], check=True, capture_output=True, text=True
        ).stdout
    )
    ours = by_column.document
    for doc in (ours, theirs):
        del doc["timing_ms"]
    assert ours == theirs
    # Polygons and comparisons take them too.
    ring = optri.triangulate_polygon([(0, 0, 1), (2, 0, 2), (1, 2, 3)])
    assert ring.elevations.tolist() == [1, 2, 3]
    results = optri.compare(TERRAIN, ["delaunay", "greedy"])
    assert all(r.document["elevations"] == [p[2] for p in TERRAIN] for r in results.values())


@pytest.mark.parametrize(
    "points,elevations,message",
    [
        ([(0, 0, 1), (1, 0, float("nan")), (0, 1, 2)], None, r"point 1 has a non-finite elevation"),
        ([(0, 0), (1, 0), (0, 1)], [1, 2], r"2 elevations for 3 points"),
        ([(0, 0), (1, 0), (0, 1)], [1, 2, float("inf")], r"point 2 has a non-finite elevation"),
        ([(0, 0, 1), (1, 0, 2), (0, 1, 3), (1, 0, 5)], None, r"point 3 repeats point 1 with another elevation"),
        ([(0, 0, 1), (1, 0, 2), (0, 1, 3)], [1, 2, 3], r"elevations= is given too"),
        ([(0, 0), (1, 0), (0, 1)], ["a", "b", "c"], r"elevations must be .* numbers"),
        ([(0, 0, 1e300), (1, 0, 2), (0, 1, 3)], None, r"outside the exact range"),
    ],
)
def test_bad_elevations_raise_value_error_with_the_message(points, elevations, message):
    with pytest.raises(ValueError, match=message):
        optri.triangulate(points, elevations=elevations)


def test_graphs_take_no_elevations():
    with pytest.raises(ValueError, match=r"shape \(n, 2\), got \(3, 3\)"):
        optri.graph([(0, 0, 1), (1, 0, 2), (0, 1, 3)], "mst")


def test_unknown_names_list_what_is_available():
    with pytest.raises(ValueError) as e:
        optri.triangulate(SQUARE_AND_CENTRE, criterion="fastest")
    assert "unknown criterion 'fastest'; available: " + ", ".join(names()) in str(e.value)
    with pytest.raises(ValueError, match="unknown graph kind 'voronoi'; available: hull, delaunay, rng, gabriel, mst"):
        optri.graph(SQUARE_AND_CENTRE, kind="voronoi")
    with pytest.raises(ValueError, match="unknown option 'metric' for criterion delaunay; available: time_limit"):
        optri.triangulate(SQUARE_AND_CENTRE, criterion="delaunay", metric="l1")
    with pytest.raises(ValueError, match="unknown option 'colour' for criterion minmax-length; available: metric, time_limit"):
        optri.triangulate(SQUARE_AND_CENTRE, criterion="minmax-length", colour="red")
    with pytest.raises(ValueError, match="invalid metric: "):
        optri.triangulate(SQUARE_AND_CENTRE, criterion="minmax-length", metric="lp:0")
    with pytest.raises(ValueError, match="invalid metric: "):
        optri.triangulate(SQUARE_AND_CENTRE, criterion="minmax-length", metric=1)
    with pytest.raises(TypeError, match="option metric takes a string or a number"):
        optri.triangulate(SQUARE_AND_CENTRE, criterion="minmax-length", metric=[1])
    with pytest.raises(ValueError, match="time_limit: '-1' is not a positive number of seconds"):
        optri.triangulate(SQUARE_AND_CENTRE, time_limit=-1)
    with pytest.raises(ValueError, match="unknown input format 'xls'"):
        optri.read_points("points.xls", format="xls")


def test_unsupported_input_names_the_criterion():
    with pytest.raises(ValueError, match="unknown option 'metric' for graph gabriel"):
        optri.graph(SQUARE_AND_CENTRE, "gabriel", metric="l1")


def test_graphs_take_two_and_collinear_points_as_the_cli_does():
    assert optri.graph([[5, 1], [-1, 1]], "mst").tolist() == [[0, 1]]
    line = [[2, 4], [0, 0], [3, 6], [1, 2], [0, 0]]
    assert optri.graph(line, "rng").tolist() == [[0, 2], [0, 3], [1, 3]]
    assert optri.graph_document(line, "gabriel")["duplicates"] == [[4, 1]]
    with pytest.raises(ValueError, match="a graph needs at least 2 distinct points"):
        optri.graph([[1, 1], [1, 1]], "mst")


def test_read_points_formats_and_errors(tmp_path):
    text = tmp_path / "pts.txt"
    text.write_text("# x y\n0 0\n1 0\n0.5 2.5\n")
    assert optri.read_points(text).tolist() == [[0, 0], [1, 0], [0.5, 2.5]]
    tsp = tmp_path / "a.tsp"
    tsp.write_text("NAME: a\nTYPE: TSP\nDIMENSION: 3\nNODE_COORD_SECTION\n1 0 0\n2 3 0\n3 0 4\nEOF\n")
    assert optri.read_points(tsp).shape == (3, 2)
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0\n1 0\n1 x\n")
    with pytest.raises(ValueError, match=r"bad.txt:3: 'x' is not a number"):
        optri.read_points(bad)
    with pytest.raises(OSError, match="cannot read"):
        optri.read_points(tmp_path / "missing.txt")
    poly = tmp_path / "l.geojson"
    poly.write_text(json.dumps({"type": "Polygon", "coordinates": [[list(p) for p in L_SHAPE + L_SHAPE[:1]]]}))
    assert optri.read_polygon(poly).tolist() == [list(map(float, p)) for p in L_SHAPE]
    with pytest.raises(ValueError, match="holds points, not a polygon"):
        optri.read_polygon(text)


def test_read_points_takes_csv_headers_latin1_comments_and_sniffs_only_on_evidence(tmp_path):
    cities = tmp_path / "cities.csv"
    cities.write_text("name,lat,lon\nNew York,40.7,-74\nBern,46.95,7.45\n", encoding="utf-8")
    assert optri.read_points(cities).tolist() == [[-74, 40.7], [7.45, 46.95]]
    latin1 = tmp_path / "latin1.txt"
    latin1.write_bytes(b"# Gen\xe8ve\n0 0\n1 0 # caf\xe9\n0 1\n")
    assert optri.read_points(latin1).tolist() == [[0, 0], [1, 0], [0, 1]]
    # Without an extension, a cloud whose first row reads as a Triangle
    # header is text.
    cloud = tmp_path / "cloud"
    cloud.write_text("3 2 0\n1 0 0\n2 1 0\n3 0 1\n")
    assert optri.read_points(cloud).tolist() == [[3, 2], [1, 0], [2, 1], [3, 0]]
    assert optri.read_points(cloud, format="node").tolist() == [[0, 0], [1, 0], [0, 1]]
    huge = tmp_path / "huge.txt"
    huge.write_text("0 0\n1 " + "9" * 1_000_000 + "x\n")
    with pytest.raises(ValueError) as error:
        optri.read_points(huge)
    assert len(str(error.value)) < 200
    assert "(1000001 bytes)" in str(error.value)


# --- threads -------------------------------------------------------------------


def test_the_gil_is_released_while_the_library_works():
    # While a worker thread triangulates, this thread keeps running Python:
    # if the GIL were held, one gap between two of its iterations would span
    # the whole computation.
    rnd = np.random.default_rng(1)
    pts = rnd.random((300_000, 2))
    span = {}

    def work():
        span["start"] = time.perf_counter()
        optri.triangulate(pts, "delaunay")
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    inside = [s for s in stamps if span["start"] <= s <= span["end"]]
    duration = span["end"] - span["start"]
    gaps = np.diff([span["start"]] + inside + [span["end"]])
    assert gaps.max() < 0.5 * duration, (gaps.max(), duration)


def test_concurrent_calls_give_the_sequential_results():
    rnd = np.random.default_rng(2)
    inputs = [rnd.random((2000, 2)) for _ in range(4)]
    expected = [optri.triangulate(p, "minmax-length").simplices.tolist() for p in inputs]
    got = [None] * len(inputs)

    def work(i):
        got[i] = optri.triangulate(inputs[i], "minmax-length").simplices.tolist()

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(inputs))]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert got == expected


def test_minmax_length_and_rng_under_l1_and_linf_match_brute_force():
    """The metric keyword reaches the library: the optimum's longest edge
    under the norm equals the exhaustive minimum over all triangulations."""
    norms = {
        "l1": lambda a, b: abs(a[0] - b[0]) + abs(a[1] - b[1]),
        "linf": lambda a, b: max(abs(a[0] - b[0]), abs(a[1] - b[1])),
    }
    rnd = random.Random(11)
    for trial in range(12):
        pts = [[rnd.randint(-20, 20), rnd.randint(-20, 20)] for _ in range(7)]
        if len({tuple(p) for p in pts}) < 7:
            continue
        tris = oracle.triangulations(pts)
        for name, norm in norms.items():
            t = optri.triangulate(pts, criterion="minmax-length", metric=name)
            best = min(max(norm(pts[a], pts[b]) for a, b in edges) for edges in tris)
            assert t.document["metric"]["name"] == name
            assert t.document["metric"]["max_edge_length"] == best
            assert optri.graph(pts, "mst", metric=name).shape == (6, 2)


TENTHS = [(0.1, 0.3), (0.2, 0.6), (0.3, 0.9), (0.3, 0.1)]


@pytest.mark.parametrize("criterion", ["delaunay", "minmax-length", "greedy"])
def test_floats_are_taken_at_the_decimals_they_show(criterion):
    # Collinear as written (y = 3x), not as doubles: as decimals (0.2, 0.6)
    # is a hull vertex and the triangle that would be flat is absent.
    t = optri.triangulate(TENTHS, criterion)
    doc = t.document
    assert doc["coordinate_arithmetic"] == "decimal-exact"
    assert len(t.simplices) == 2
    assert t.stats["hull_points"] == 4
    # The user's values and units, not the scaled integers.
    assert t.points.tolist() == [list(p) for p in TENTHS]
    assert doc["coordinates"][2] == [0.3, 0.9]
    assert abs(t.stats["max_edge_length"] - 0.8) < 1e-12
    # A computed float (0.1 + 0.2 has 17 significant digits) keeps the
    # whole input binary64.
    odd = TENTHS + [(0.1 + 0.2, 0.5)]
    assert optri.triangulate(odd, criterion).document["coordinate_arithmetic"] == "binary64"


def test_decimal_files_through_read_points_match_the_cli(tmp_path):
    path = tmp_path / "tenths.txt"
    path.write_text("".join(f"{x} {y}\n" for x, y in TENTHS + [(0.15, 0.55), (0.25, 0.35)]))
    theirs = json.loads(
        subprocess.run(
            [cli(), "triangulate", str(path), "--criterion", "minmax-length", "--json"],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    )
    ours = optri.triangulate(optri.read_points(path), "minmax-length").document
    assert theirs["coordinate_arithmetic"] == ours["coordinate_arithmetic"] == "decimal-exact"
    for doc in (ours, theirs):
        del doc["timing_ms"]
    assert ours == theirs
    # Graphs and comparisons decide on the decimals too.
    assert optri.graph_document(TENTHS, "hull")["coordinate_arithmetic"] == "decimal-exact"
    assert len(optri.graph(TENTHS, "hull")) == 4
    for name, result in compare_2d(TENTHS).items():
        assert len(result.simplices) == 2, name


# --- input that is never changed silently ---------------------------------------


def test_values_no_double_represents_are_refused_naming_the_point():
    big = 2**53
    ok = optri.triangulate(np.array([[0, 0], [big, 0], [0, big]], dtype=np.int64))
    assert ok.points.tolist() == [[0, 0], [big, 0], [0, big]]
    with pytest.raises(ValueError, match=r"point 1 has coordinate 9007199254740993 that no double"):
        optri.triangulate(np.array([[0, 0], [big + 1, 0], [0, 5]], dtype=np.int64))
    with pytest.raises(ValueError, match=r"point 2 has coordinate .* that no double"):
        optri.triangulate([[0, 0], [1, 0], [Fraction(1, 3), 1]])
    with pytest.raises(ValueError, match="no double represents exactly"):
        optri.triangulate([[0, 0], [1, 0], [10**30 + 1, 1]])
    with pytest.raises(ValueError, match="point 1 has coordinate"):
        optri.graph(np.array([[0, 0], [2**63 - 1, 0]], dtype=np.uint64), "mst")
    # Exact conversions pass: float32, small integers, exact Fractions.
    optri.triangulate(np.array([[0, 0], [1.5, 0], [0, 0.25]], dtype=np.float32))
    optri.triangulate([[0, 0], [Fraction(3, 4), 0], [0, 1]])


def test_complex_and_masked_arrays_are_refused():
    with pytest.raises(TypeError, match="must be real numbers, got complex128 values"):
        optri.triangulate(np.array([[0, 0], [1, 0], [0, 1j]]))
    masked = np.ma.masked_array([[0, 0], [1, 0], [0, 1], [5, 5]], mask=[[0, 0], [0, 0], [0, 0], [1, 0]])
    with pytest.raises(TypeError, match="masked array with masked entries"):
        optri.triangulate(masked)
    unmasked = np.ma.masked_array([[0, 0], [1, 0], [0, 1]], mask=False)
    assert optri.triangulate(unmasked).simplices.shape == (1, 3)


def test_an_array_beyond_memory_raises_memory_error():
    huge = np.broadcast_to(np.zeros(2), (2**36, 2))
    with pytest.raises(MemoryError):
        optri.triangulate(huge)


def test_a_time_limit_stops_the_run_with_timeout_error():
    rng = np.random.default_rng(7)
    points = rng.random((200_000, 2))
    with pytest.raises(TimeoutError, match="stopped: the time limit of .* s passed"):
        optri.triangulate(points, "min-weight", time_limit=1e-9)


def test_ctrl_c_stops_a_long_run_within_seconds():
    """SIGINT half a second into a long run (Klincsek's cubic program on a
    3000-gon takes minutes) raises KeyboardInterrupt at once; the run's
    thread stops at its next check."""
    code = textwrap.dedent(
        """
        import math, os, signal, threading, time
        import optri
        ring = [[round(1e6 * math.cos(2 * math.pi * k / 3000)), round(1e6 * math.sin(2 * math.pi * k / 3000))]
                for k in range(3000)]
        sent = []
        def interrupt():
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)
        threading.Timer(0.5, interrupt).start()
        try:
            optri.triangulate_polygon(ring, "min-weight")
            print("finished", 0)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic() - sent[0])
        """
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    word, seconds = out.stdout.split()
    assert word == "interrupted", out.stdout
    assert float(seconds) < 2.0, out.stdout


def half_text(doubled):
    """The exact decimal text of the integer ``doubled`` halved."""
    return str(doubled // 2) + (".5" if doubled % 2 else "")


def check_decision_witness(doc, pts, doubled_threshold, at_least):
    """The witness is a triangulation of the points whose every doubled area
    meets the threshold (exact integer arithmetic)."""
    w = doc["witness"]
    assert w["document"] == "triangulation"
    for a, b, c in w["triangles"]:
        area2 = abs(oracle.orient(pts[a], pts[b], pts[c]))
        assert area2 >= doubled_threshold if at_least else area2 <= doubled_threshold


@pytest.mark.parametrize("seed", range(6))
def test_decide_is_yes_at_the_brute_force_optimum_and_no_just_past_it(seed):
    rnd = random.Random(300 + seed)
    pts = convex_points(rnd, 6 + seed % 3) if seed % 2 == 0 else random_points(rnd, 7)
    best = optima(pts)
    for criterion, key, bound in (
        ("maxmin-area", "maxmin_area2", "at_least"),
        ("minmax-area", "minmax_area2", "at_most"),
    ):
        at_least = bound == "at_least"
        opt = best[key]
        at = half_text(opt)
        past = Fraction(opt, 2) + (Fraction(1, 10**9) if at_least else -Fraction(1, 10**9))
        past_text = f"{past.numerator / past.denominator!r}"
        for threshold, truth in ((at, True), (float(at), True), (past_text, False)):
            doc = optri.decide(pts, criterion, **{bound: threshold})
            assert doc["document"] == "decision" and doc["criterion"] == criterion
            if doc["answer"] is None:
                # A general set the approximation did not settle.
                assert seed % 2 == 1 and not doc["exact"]
                continue
            assert doc["answer"] is truth, (threshold, doc)
            if truth:
                check_decision_witness(doc, pts, opt, at_least)
            else:
                assert doc["witness"] is None
        if seed % 2 == 0:
            # Convex position is always decided, with the next double past
            # the optimum refused.
            value = opt / 2
            nxt = math.nextafter(value, math.inf if at_least else -math.inf)
            assert optri.decide(pts, criterion, **{bound: nxt})["answer"] is False


def test_decide_polygons_and_bad_input():
    l_shape = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 3), (0, 3)]
    t = optri.triangulate_polygon(l_shape, "maxmin-area")
    smallest = t.stats["min_area"]
    yes = optri.decide(l_shape, "maxmin-area", at_least=smallest, polygon=True)
    assert yes["answer"] is True and yes["witness"]["domain"] == "polygon"
    no = optri.decide(l_shape, "maxmin-area", at_least=str(smallest) + "000000001", polygon=True)
    assert no["answer"] is False
    square = [(0, 0), (2, 0), (2, 2), (0, 2)]
    for kwargs, message in (
        ({"at_least": -1}, "negative"),
        ({"at_least": float("nan")}, "not a finite number"),
        ({"at_least": "abc"}, "not a decimal number"),
        ({"at_most": 1}, "at_least"),
        ({"at_least": 1, "at_most": 2}, "not both"),
        ({}, "at_least"),
    ):
        with pytest.raises(ValueError, match=message):
            optri.decide(square, "maxmin-area", **kwargs)
    with pytest.raises(ValueError, match="delaunay"):
        optri.decide(square, "delaunay", at_least=1)
    with pytest.raises(TypeError):
        optri.decide(square, "maxmin-area", at_least=True)
def _angles_at_least(points, triangles, degrees):
    """Every angle of the triangles at least ``degrees`` (exact rationals
    for the dot and cross products, the tangent with a 1e-9 margin)."""
    tan = math.tan(math.radians(degrees))
    for t in triangles:
        for k in range(3):
            o, a, b = (points[t[(k + j) % 3]] for j in range(3))
            u = (Fraction(a[0]) - Fraction(o[0]), Fraction(a[1]) - Fraction(o[1]))
            v = (Fraction(b[0]) - Fraction(o[0]), Fraction(b[1]) - Fraction(o[1]))
            dot = u[0] * v[0] + u[1] * v[1]
            cross = abs(u[0] * v[1] - u[1] * v[0])
            if dot > 0 and cross < Fraction(tan * (1 - 1e-9)) * dot:
                return False
    return True


def test_alpha_and_approximation_options_of_the_area_criteria():
    rng = random.Random(0xA1FA)
    points = [[rng.randint(0, 60), rng.randint(0, 60)] for _ in range(40)]
    base = optri.triangulate(points, criterion="minmax-area")
    star = base.approximation["delaunay_smallest_angle"]["degrees"]
    assert base.approximation["choice"] == "best" and base.approximation["alpha"] is None
    alpha = math.floor(star * 500) / 1000  # half of α*, a thousandth below
    t = optri.triangulate(points, criterion="minmax-area", alpha=alpha, approximation="thesis-76")
    assert t.approximation["alpha"] == alpha
    assert t.approximation["candidate"].startswith("Vassilev Algorithm 76")
    assert _angles_at_least(t.points.tolist(), t.simplices.tolist(), alpha)
    guarantee = t.approximation["guarantee"]
    assert guarantee["kind"] in ("optimal", "approximation")
    if guarantee["kind"] == "approximation":
        assert "Theorem 81" in guarantee["statement"] and guarantee["theorem_81"]
    with pytest.raises(ValueError, match=r"α\* = "):
        optri.triangulate(points, criterion="maxmin-area", alpha=star + 0.01)
    with pytest.raises(ValueError, match="approximation"):
        optri.triangulate(points, criterion="maxmin-area", approximation="thesis-77")
    with pytest.raises(ValueError, match="unknown option 'alpha' for criterion delaunay"):
        optri.triangulate(points, criterion="delaunay", alpha=10)
