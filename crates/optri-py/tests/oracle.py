"""An independent reference for the Python tests: every triangulation of a
tiny integer point set, enumerated by brute force with exact integer
arithmetic, and the proximity graphs by their definitions.

Nothing here calls optri. A triangulation of a point set is a maximal set of
pairwise non-crossing segments, where a segment joins two points and holds
no third one; its triangles are the empty triangles of three of its edges.
"""

import itertools
import math


def orient(a, b, c):
    """Twice the signed area of abc: > 0 iff counter-clockwise (exact on ints)."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def dist2(a, b):
    return (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2


def on_open_segment(p, a, b):
    if orient(a, b, p) != 0:
        return False
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(
        a[1], b[1]
    ) and p != a and p != b


def segments(points):
    """Every segment (i, j), i < j, with no other point on it."""
    n = len(points)
    return [
        (i, j)
        for i, j in itertools.combinations(range(n), 2)
        if not any(on_open_segment(points[k], points[i], points[j]) for k in range(n))
    ]


def cross(s, t, points):
    """Do two segments cross? Segments hold no third point, so two that share
    an endpoint meet only there, and otherwise they meet iff they cross
    properly."""
    if set(s) & set(t):
        return False
    a, b = points[s[0]], points[s[1]]
    c, d = points[t[0]], points[t[1]]
    return orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0


def triangulations(points):
    """Every triangulation, as a frozenset of edges."""
    segs = segments(points)
    crossing = {s: {t for t in segs if cross(s, t, points)} for s in segs}
    found = set()

    def extend(k, chosen, blocked):
        if k == len(segs):
            # Maximal: every segment left out crosses a chosen one.
            if all(s in chosen or crossing[s] & chosen for s in segs):
                found.add(frozenset(chosen))
            return
        s = segs[k]
        if s in blocked:
            extend(k + 1, chosen, blocked)
            return
        extend(k + 1, chosen | {s}, blocked | crossing[s])
        # Leaving s out is only maximal if a later segment crosses it.
        if any(t in crossing[s] for t in segs[k + 1 :]):
            extend(k + 1, chosen, blocked)

    extend(0, frozenset(), frozenset())
    return found


def triangles(points, edges):
    """The counter-clockwise empty triangles of an edge set."""
    n = len(points)
    out = []
    for i, j, k in itertools.combinations(range(n), 3):
        if (i, j) in edges and (j, k) in edges and (i, k) in edges:
            a, b, c = points[i], points[j], points[k]
            o = orient(a, b, c)
            if o == 0:
                continue
            inside = any(
                m not in (i, j, k)
                and orient(a, b, points[m]) * o > 0
                and orient(b, c, points[m]) * o > 0
                and orient(c, a, points[m]) * o > 0
                for m in range(n)
            )
            if not inside:
                out.append((i, j, k) if o > 0 else (i, k, j))
    return out


def hull(points):
    """The strictly convex hull vertices, counter-clockwise (monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and orient(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = chain(pts), chain(reversed(pts))
    return lower[:-1] + upper[:-1]


def double_area(ring):
    """Twice the signed area of a polygon ring (shoelace, exact on ints)."""
    return sum(
        ring[i][0] * ring[(i + 1) % len(ring)][1] - ring[(i + 1) % len(ring)][0] * ring[i][1]
        for i in range(len(ring))
    )


def greedy(points):
    """The greedy triangulation: shortest segments first, each kept unless it
    crosses a kept one (for inputs whose lengths are all distinct)."""
    chosen = []
    for s in sorted(segments(points), key=lambda s: dist2(points[s[0]], points[s[1]])):
        if not any(cross(s, t, points) for t in chosen):
            chosen.append(s)
    return set(chosen)


def gabriel(points):
    """Edges pq with no other point in or on the circle with diameter pq."""
    n = len(points)

    def in_closed_disc(r, p, q):
        return (r[0] - p[0]) * (r[0] - q[0]) + (r[1] - p[1]) * (r[1] - q[1]) <= 0

    return {
        (i, j)
        for i, j in itertools.combinations(range(n), 2)
        if not any(in_closed_disc(points[k], points[i], points[j]) for k in range(n) if k not in (i, j))
    }


def rng(points):
    """Edges pq with no other point in the open lune of p and q."""
    n = len(points)
    return {
        (i, j)
        for i, j in itertools.combinations(range(n), 2)
        if not any(
            max(dist2(points[k], points[i]), dist2(points[k], points[j])) < dist2(points[i], points[j])
            for k in range(n)
            if k not in (i, j)
        )
    }


def mst(points):
    """Kruskal's tree (for inputs whose lengths are all distinct)."""
    parent = list(range(len(points)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    tree = set()
    pairs = itertools.combinations(range(len(points)), 2)
    for i, j in sorted(pairs, key=lambda e: dist2(points[e[0]], points[e[1]])):
        if find(i) != find(j):
            parent[find(i)] = find(j)
            tree.add((i, j))
    return tree


def min_angle(points, tris):
    """The smallest interior angle in degrees (floating point, for reporting)."""
    best = 180.0
    for t in tris:
        for k in range(3):
            a, b, c = (points[t[(k + m) % 3]] for m in range(3))
            u = (b[0] - a[0], b[1] - a[1])
            v = (c[0] - a[0], c[1] - a[1])
            ang = math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]))
            best = min(best, ang)
    return best
