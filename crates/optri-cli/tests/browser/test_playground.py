"""The web playground in a real headless Chromium (Playwright for Python).

Starts `optri serve --port 0` (the binary from $OPTRI_BIN, default
target/debug/optri), opens the page, adds points by clicking the editor,
switches criteria, drags and deletes a point, triggers bad requests, and
checks what is drawn against an independent count: a triangulation of n
points with h on the convex hull has 2n - h - 2 triangles. Each criterion
is its own request: a panel is busy until its answer arrives, and one
stopped by the server's time limit says so while the others are drawn.
A link (the view in the URL's fragment) restores the points, criteria and
options and draws what the API answers for the same request; the metric
reaches only the criteria and graphs that take it; a graph is drawn; a
result that is not exact shows its certified bound.

Run by .ci/run:  python -m pytest crates/optri-cli/tests/browser
A screenshot goes to $OPTRI_SCREENSHOT (default: a temporary file).
"""

import json
import math
import os
import re
import subprocess
import tempfile
import urllib.request
from pathlib import Path

import pytest
from playwright.sync_api import expect, sync_playwright

ROOT = Path(__file__).resolve().parents[4]
BIN = os.environ.get("OPTRI_BIN", str(ROOT / "target" / "debug" / "optri"))
CHROMIUM = os.environ.get("OPTRI_CHROMIUM", "/usr/bin/chromium")
ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
]

# Clicks in the 1000 x 1000 editor box (fractions of its width/height): a
# pentagon and two interior points, no three collinear.
CLICKS = [(0.5, 0.1), (0.9, 0.4), (0.75, 0.9), (0.25, 0.9), (0.1, 0.4), (0.45, 0.45), (0.6, 0.65)]


def hull_size(points):
    """Vertices of the strict convex hull (Andrew's monotone chain)."""
    pts = sorted(set(points))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and cross(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]

    return len(chain(pts)) + len(chain(reversed(pts)))


def serve(*options):
    """Starts `optri serve` with `options`; yields its URL, then stops it."""
    proc = subprocess.Popen([BIN, "serve", "--port", "0", *options], stdout=subprocess.PIPE, text=True)
    line = proc.stdout.readline()
    url = re.search(r"http://\S+/", line)
    assert url, f"no address in {line!r}"
    yield url.group(0)
    proc.kill()
    proc.wait()


@pytest.fixture(scope="module")
def server():
    yield from serve()


@pytest.fixture
def hurried_server():
    """A server with a time limit of 2 s, stopped after its test (the
    computation it stops may run on until its next check)."""
    yield from serve("--time-limit", "2")


@pytest.fixture(scope="module")
def browser():
    with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
        context = p.chromium.launch_persistent_context(
            profile, executable_path=CHROMIUM, headless=True, args=ARGS,
            viewport={"width": 1380, "height": 860}, accept_downloads=True,
        )
        yield context
        context.close()


def open_page(browser, url):
    """The page at `url`, ready; yields it, then checks it raised no error
    and its Content-Security-Policy blocked nothing."""
    page = browser.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: "Content Security Policy" in m.text and errors.append(m.text))
    page.goto(url)
    page.wait_for_selector("body[data-ready=yes]")
    yield page
    page.close()
    assert not errors, errors


@pytest.fixture
def page(server, browser):
    yield from open_page(browser, server)


@pytest.fixture
def hurried_page(hurried_server, browser):
    yield from open_page(browser, hurried_server)


def settle(page):
    page.wait_for_selector("body[data-state=done]")


def click_points(page, clicks, wait=True):
    # Ticking checkboxes may have scrolled the editor (at the top) away.
    page.evaluate("window.scrollTo(0, 0)")
    box = page.locator("#editor").bounding_box()
    spots = []
    for fx, fy in clicks:
        x, y = box["x"] + fx * box["width"], box["y"] + fy * box["height"]
        page.mouse.click(x, y)
        spots.append((round(x), round(y)))
    if wait:
        settle(page)
    return spots


def set_criteria(page, names):
    for box in page.locator("#criteria input").all():
        want = box.get_attribute("value") in names
        if box.is_checked() != want:
            box.click()
    settle(page)


def drawn_triangles(page, criterion):
    return page.locator(f'svg.panel-svg[data-criterion="{criterion}"] polygon.tri').count()


def test_clicked_points_are_triangulated_by_every_criterion(page):
    names = [c.get_attribute("value") for c in page.locator("#criteria input").all()]
    criteria = json.loads(page.evaluate("fetch('/api/criteria').then(r => r.text())"))["criteria"]
    assert names == [c["name"] for c in criteria], "the checkboxes are the registry"
    spots = click_points(page, CLICKS)
    assert page.locator("#editor circle").count() == len(CLICKS)
    n, h = len(spots), hull_size(spots)
    expected = 2 * n - h - 2
    assert (n, h, expected) == (7, 5, 7)
    panels = page.locator("#panels .panel")
    assert panels.count() == len(names)
    drawn = 0
    for name in names:
        panel = page.locator(f'#panels .panel[data-criterion="{name}"]')
        if panel.locator("svg").count():
            assert drawn_triangles(page, name) == expected, name
            # The highlights: one longest edge, the smallest and largest triangles.
            for cls in ["line.longest", "polygon.smallest", "polygon.largest"]:
                assert panel.locator(cls).count() == 1, (name, cls)
            row = page.locator(f'#stats tbody tr[data-criterion="{name}"]')
            expect(row.locator("td").nth(2)).to_have_text(str(expected))
            drawn += 1
        elif name == "minmax-slope":
            # Clicked points have no elevations.
            expect(panel.locator(".refused")).to_contain_text("needs an elevation")
        else:
            expect(panel.locator(".refused")).to_contain_text("convex position")
    assert drawn >= 4, "delaunay, minmax-length, greedy and the area criteria draw"
    assert page.locator("#stats td.best").count() >= 7, "each measure has a best value"
    assert page.locator("#error").is_hidden()


def test_switching_criteria_redraws_only_the_chosen_ones(page):
    click_points(page, CLICKS)
    set_criteria(page, {"greedy", "minmax-length"})
    shown = [p.get_attribute("data-criterion") for p in page.locator("#panels .panel").all()]
    assert shown == ["minmax-length", "greedy"]
    rows = [r.get_attribute("data-criterion") for r in page.locator("#stats tbody tr").all()]
    assert rows == shown
    expect(page.locator("#stats tbody")).to_contain_text("greedy")
    set_criteria(page, {"delaunay"})
    assert [p.get_attribute("data-criterion") for p in page.locator("#panels .panel").all()] == ["delaunay"]
    assert drawn_triangles(page, "delaunay") == 7


def test_drag_moves_and_right_click_and_shift_click_delete(page):
    set_criteria(page, {"delaunay"})
    click_points(page, CLICKS)
    circle = page.locator("#editor circle").nth(5)
    before = (circle.get_attribute("cx"), circle.get_attribute("cy"))
    b = circle.bounding_box()
    page.mouse.move(b["x"] + b["width"] / 2, b["y"] + b["height"] / 2)
    page.mouse.down()
    page.mouse.move(b["x"] + 30, b["y"] + 20, steps=5)
    page.mouse.up()
    settle(page)
    after = page.locator("#editor circle").nth(5)
    assert (after.get_attribute("cx"), after.get_attribute("cy")) != before
    assert page.locator("#editor circle").count() == 7
    # Right-click deletes an interior point: 6 points, 5 on the hull.
    page.locator("#editor circle").nth(6).click(button="right")
    settle(page)
    assert page.locator("#editor circle").count() == 6
    assert drawn_triangles(page, "delaunay") == 2 * 6 - 5 - 2
    # Shift-click deletes a hull point: 5 points, 4 on the hull.
    page.locator("#editor circle").nth(0).click(modifiers=["Shift"])
    settle(page)
    assert page.locator("#editor circle").count() == 5
    assert drawn_triangles(page, "delaunay") == 2 * 5 - 4 - 2


def test_generators_paste_and_downloads(page):
    set_criteria(page, {"delaunay", "minmax-length"})
    page.select_option("#generator", "grid")
    page.fill("#n", "16")
    page.click("#generate")
    settle(page)
    # A 4 x 4 grid: 12 boundary points, 2*16 - 12 - 2 = 18 triangles (the
    # cocircular squares are split without flat triangles).
    assert page.locator("#editor circle").count() == 16
    assert drawn_triangles(page, "delaunay") == 18
    page.select_option("#generator", "circle")
    page.fill("#n", "12")
    page.click("#generate")
    settle(page)
    assert drawn_triangles(page, "minmax-length") == 12 - 2
    page.fill("#paste", "x,y\n0,0\n10,0\n10,10\n0,10\n3,4\n")
    page.click("#load-text")
    settle(page)
    assert page.locator("#editor circle").count() == 5
    assert drawn_triangles(page, "delaunay") == 4
    # Upload: the server reads the file by its extension (TSPLIB here).
    with tempfile.TemporaryDirectory() as tmp:
        tsp = Path(tmp) / "six.tsp"
        tsp.write_text("NAME: six\nTYPE: TSP\nDIMENSION: 6\nEDGE_WEIGHT_TYPE: EUC_2D\n"
                       "NODE_COORD_SECTION\n1 0 0\n2 8 0\n3 8 6\n4 0 6\n5 3 2\n6 5 4\nEOF\n")
        page.set_input_files("#file", str(tsp))
        settle(page)
    assert page.locator("#editor circle").count() == 6
    assert drawn_triangles(page, "delaunay") == 2 * 6 - 4 - 2
    page.fill("#paste", "x,y\n0,0\n10,0\n10,10\n0,10\n3,4\n")
    page.click("#load-text")
    settle(page)
    with page.expect_download() as d:
        page.click("#download-json")
    doc = json.loads(Path(d.value.path()).read_text())
    assert doc["document"] == "comparison"
    assert [r["criterion"] for r in doc["results"]] == ["delaunay", "minmax-length"]
    with page.expect_download() as d:
        page.click("#download-svg")
    svg = Path(d.value.path()).read_text()
    assert svg.startswith("<svg") and svg.count('class="tri"') == 2 * 4


def test_bad_input_shows_the_servers_message(page):
    page.fill("#paste", "0 0\n1 1\nfoo bar\n")
    page.click("#load-text")
    expect(page.locator("#error")).to_be_visible()
    expect(page.locator("#error")).to_contain_text("422")
    expect(page.locator("#error")).to_contain_text("line 3: 'foo' is not a number")
    page.fill("#paste", "0 0\n1 1\n2 2\n")
    page.click("#load-text")
    settle(page)
    expect(page.locator("#error")).to_contain_text("collinear")
    assert page.locator("#panels .panel").count() == 0
    # A good input clears the message.
    page.click("#clear")
    click_points(page, CLICKS[:4])
    expect(page.locator("#error")).to_be_hidden()
    assert page.locator("#panels svg").count() >= 1


def test_a_panel_is_busy_until_its_answer_arrives(page):
    set_criteria(page, {"delaunay", "greedy"})
    held = []

    def hold_greedy(route):
        if json.loads(route.request.post_data)["criterion"] == "greedy":
            held.append(route)
        else:
            route.continue_()

    page.route("**/api/triangulate", hold_greedy)
    click_points(page, CLICKS, wait=False)
    # Delaunay is drawn while greedy's request is held: its panel is busy.
    expect(page.locator('svg.panel-svg[data-criterion="delaunay"] polygon.tri')).to_have_count(7)
    greedy = page.locator('#panels .panel[data-criterion="greedy"]')
    assert greedy.get_attribute("data-state") == "busy"
    expect(greedy).to_contain_text("computing")
    assert page.locator("body").get_attribute("data-state") == "busy"
    assert drawn_triangles(page, "delaunay") == 7
    expect(page.locator('#stats tbody tr[data-criterion="delaunay"]')).to_be_visible()
    # Only the latest request is held; older ones were aborted.
    assert held, "greedy's request was sent"
    held[-1].continue_()
    settle(page)
    page.unroute("**/api/triangulate")
    assert greedy.get_attribute("data-state") == "done"
    assert drawn_triangles(page, "greedy") == 7
    rows = [r.get_attribute("data-criterion") for r in page.locator("#stats tbody tr").all()]
    assert rows == ["delaunay", "greedy"]


def test_a_criterion_out_of_time_says_so_and_the_others_are_drawn(hurried_page):
    page = hurried_page
    # 200 points on a circle: min-weight takes far longer than the 2 s the
    # server allows; Delaunay and greedy answer at once.
    set_criteria(page, {"delaunay", "greedy", "min-weight"})
    page.select_option("#generator", "circle")
    page.fill("#n", "200")
    page.click("#generate")
    settle(page)
    for name in ["delaunay", "greedy"]:
        assert drawn_triangles(page, name) == 200 - 2, name
    stopped = page.locator('#panels .panel[data-criterion="min-weight"]')
    assert stopped.get_attribute("data-state") == "stopped"
    expect(stopped.locator(".refused")).to_contain_text("stopped")
    expect(stopped.locator(".refused")).to_contain_text("limit of 2 s")
    expect(page.locator('#stats tbody tr[data-criterion="min-weight"]')).to_contain_text("stopped")
    assert page.locator("#error").is_hidden()
    with page.expect_download() as d:
        page.click("#download-json")
    doc = json.loads(Path(d.value.path()).read_text())
    assert [r["criterion"] for r in doc["results"]] == ["delaunay", "greedy", "min-weight"]
    assert "limit of 2 s" in doc["results"][2]["error"]


def test_screenshot(page):
    set_criteria(page, {"delaunay", "minmax-length", "minmax-area"})
    page.select_option("#graph", "mst")
    page.select_option("#generator", "clustered")
    page.fill("#n", "36")
    page.fill("#seed", "3")
    page.click("#generate")
    settle(page)
    page.evaluate("window.scrollTo(0, 0)")
    path = os.environ.get("OPTRI_SCREENSHOT") or str(Path(tempfile.gettempdir()) / "optri-playground.png")
    page.screenshot(path=path)
    size = Path(path).stat().st_size
    assert 10_000 < size < 200_000, size


# ---- links, metric, graphs, bounds -------------------------------------------

# Points whose decimals are not binary fractions, so a link that rounded them
# would be caught: x,y for a pentagon and two interior points.
LINK_POINTS = [[0.1, 0.2], [10.3, 0.7], [12.55, 8.125], [5.0000001, 13.3], [-2.9, 7.1], [4.2, 5.4], [6.6, 3.3]]


def api(url, path, body):
    request = urllib.request.Request(url + path.lstrip("/"), data=json.dumps(body).encode(),
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request) as answer:
        return json.load(answer)


def link(criteria, points, **keys):
    """A fragment in the page's format: v=1, c, the other keys, p, end."""
    items = ["v=1", "c=" + ",".join(criteria)]
    items += [f"{k}={v}" for k, v in keys.items()]
    items.append("p=" + ";".join(",".join(repr(float(v)) if v != int(v) else str(int(v)) for v in p) for p in points))
    return "#" + "&".join(items + ["end"])


def record_posts(page):
    """Every API POST body the page sends, as (path, body)."""
    posts = []
    page.on("request", lambda r: r.method == "POST" and posts.append((r.url.split("/", 3)[3], r.post_data_json)))
    return posts


def drawn(page, criterion):
    """The triangles drawn in a criterion's panel, as sorted index triples."""
    shown = page.locator(f'svg.panel-svg[data-criterion="{criterion}"] polygon.tri')
    return sorted(tuple(sorted(map(int, t.split()))) for t in shown.evaluate_all("ps => ps.map(p => p.dataset.triangle)"))


def fact(page, criterion, name):
    return page.locator(f'#panels .panel[data-criterion="{criterion}"] dd[data-fact="{name}"]')


def checked(page):
    return [b.get_attribute("value") for b in page.locator("#criteria input:checked").all()]


def test_a_link_restores_the_view_and_draws_what_the_api_answers(server, browser):
    fragment = link(["minmax-length", "greedy"], LINK_POINTS, m="lp:3", g="rng")
    page = browser.new_page()
    posts = record_posts(page)
    page.goto(server + fragment)
    page.wait_for_selector("body[data-ready=yes]")
    settle(page)
    assert checked(page) == ["minmax-length", "greedy"]
    assert page.locator("#metric").input_value() == "lp"
    assert page.locator("#lp").input_value() == "3"
    assert page.locator("#graph").input_value() == "rng"
    assert page.locator("#editor circle").count() == len(LINK_POINTS)
    assert page.evaluate("location.hash") == fragment, "the link is already the page's own"
    # The requests carry the link's numbers (the same doubles), and the
    # metric only where the criterion takes one.
    bodies = {b.get("criterion", b.get("kind")): b for path, b in posts if path.startswith("api/")}
    assert bodies["minmax-length"] == {"points": LINK_POINTS, "criterion": "minmax-length", "polygon": False,
                                       "options": {"metric": "lp:3"}}
    assert bodies["greedy"] == {"points": LINK_POINTS, "criterion": "greedy", "polygon": False}
    assert bodies["rng"] == {"points": LINK_POINTS, "kind": "rng", "options": {"metric": "lp:3"}}
    # What is drawn is what the API answers for the same request.
    for name, body in [("minmax-length", bodies["minmax-length"]), ("greedy", bodies["greedy"])]:
        doc = api(server, "/api/triangulate", body)
        assert drawn(page, name) == sorted(tuple(sorted(t)) for t in doc["triangles"]), name
        assert len(doc["triangles"]) == 2 * 7 - hull_size([tuple(p) for p in LINK_POINTS]) - 2
    graph = api(server, "/api/graph", bodies["rng"])
    shown = page.locator('svg.graph-svg[data-kind="rng"] line.edge').evaluate_all("ls => ls.map(l => l.dataset.edge)")
    assert sorted(shown) == sorted(f"{a} {b}" for a, b in graph["edges"])
    expect(fact(page, "minmax-length", "measure")).to_have_text(re.compile(r"^\d"))
    expect(page.locator('#panels .panel[data-criterion="minmax-length"] dt').nth(1)).to_have_text("max edge (lp:3)")
    assert page.locator("#link-error").is_hidden()
    page.close()


def test_a_link_restores_a_polygon_with_elevations(server, browser):
    # A non-convex ring (an L), each point with an elevation.
    ring = [[0, 0, 1], [6, 0, 2.5], [6, 2, 3], [2, 2, 0.1], [2, 5, -4], [0, 5, 7]]
    page = browser.new_page()
    posts = record_posts(page)
    page.goto(server + link(["minmax-slope", "delaunay"], ring, poly=1))
    page.wait_for_selector("body[data-ready=yes]")
    settle(page)
    assert page.locator("#polygon").is_checked()
    expect(page.locator("#status")).to_have_text("6 points with elevations (polygon ring)")
    bodies = {b["criterion"]: b for path, b in posts if path == "api/triangulate"}
    for name in ["delaunay", "minmax-slope"]:
        assert bodies[name] == {"points": ring, "criterion": name, "polygon": True}
        doc = api(server, "/api/triangulate", bodies[name])
        assert doc["domain"] == "polygon" and doc["elevations"] == [p[2] for p in ring]
        assert drawn(page, name) == sorted(tuple(sorted(t)) for t in doc["triangles"])
        assert len(doc["triangles"]) == len(ring) - 2
    page.close()


def test_edits_rewrite_the_link_in_place_and_the_link_reproduces_them(page, browser):
    set_criteria(page, {"delaunay", "minmax-length"})
    history = page.evaluate("history.length")
    click_points(page, CLICKS)
    page.select_option("#metric", "l1")
    settle(page)
    page.check("#polygon")
    settle(page)
    page.uncheck("#polygon")
    settle(page)
    assert page.evaluate("history.length") == history, "replaceState: no history entry per edit"
    fragment = page.evaluate("location.hash")
    assert fragment.startswith("#v=1&c=delaunay,minmax-length&m=l1&p=") and fragment.endswith("&end")
    points = [[float(v) for v in p.split(",")] for p in re.search(r"&p=([^&]*)", fragment).group(1).split(";")]
    assert len(points) == len(CLICKS)
    # A second tab opened on the link draws the same triangles.
    before = {name: drawn(page, name) for name in ["delaunay", "minmax-length"]}
    other = browser.new_page()
    other.goto(page.url)
    other.wait_for_selector("body[data-ready=yes]")
    settle(other)
    assert other.evaluate("location.hash") == fragment
    assert {name: drawn(other, name) for name in before} == before
    assert other.locator("#metric").input_value() == "l1"
    other.close()


@pytest.mark.parametrize("fragment, message", [
    ("#v=1&c=delaunay&p=0,0;4,0;0,3;4,", "cut short"),
    ("#v=1&c=delaunay&p=0,0;4,0;0,3;4,&end", "point 4"),
    ("#v=2&c=delaunay&p=0,0;4,0;0,3&end", "version v=2"),
    ("#v=1&c=delaunay,no-such-criterion&p=0,0;4,0;0,3&end", "no-such-criterion"),
    ("#v=1&c=minmax-length&m=lp:0&p=0,0;4,0;0,3&end", "lp:0"),
    ("#v=1&c=delaunay&p=0,0;4,0,1;0,3&end", "point 2 has 3 numbers"),
    ("#v=1&c=delaunay&zoom=2&p=0,0;4,0;0,3&end", "zoom=2"),
])
def test_a_bad_link_says_so_and_shows_the_default_view(server, browser, fragment, message):
    page = browser.new_page()
    page.goto(server + fragment)
    page.wait_for_selector("body[data-ready=yes]")
    settle(page)
    expect(page.locator("#link-error")).to_be_visible()
    expect(page.locator("#link-error")).to_contain_text("This link could not be read")
    expect(page.locator("#link-error")).to_contain_text(message)
    expect(page.locator("#link-error")).to_contain_text("default view")
    # The default view: every criterion, no points, a working editor.
    assert len(checked(page)) == page.locator("#criteria input").count() > 10
    assert page.locator("#editor circle").count() == 0
    click_points(page, CLICKS[:3])
    expect(page.locator("#link-error")).to_be_hidden()
    expect(page.locator('svg.panel-svg[data-criterion="delaunay"] polygon.tri')).to_have_count(1)
    # A good link pasted into the same tab (only the fragment changes).
    page.goto(server + link(["greedy"], LINK_POINTS))
    expect(page.locator("#editor circle")).to_have_count(7)
    settle(page)
    assert checked(page) == ["greedy"] and page.locator("#editor circle").count() == 7
    page.close()


def test_the_metric_reaches_only_the_criteria_that_take_it(page):
    posts = record_posts(page)
    set_criteria(page, {"delaunay"})
    assert page.locator("#metric").is_disabled()
    assert "minmax-length" in page.locator("#metric").get_attribute("title")
    set_criteria(page, {"delaunay", "minmax-length"})
    assert page.locator("#metric").is_enabled()
    click_points(page, CLICKS)
    euclidean = page.locator('#panels .panel[data-criterion="minmax-length"] dd[data-fact="measure"]').inner_text()
    posts.clear()
    page.select_option("#metric", "linf")
    settle(page)
    bodies = {b["criterion"]: b for path, b in posts if path == "api/triangulate"}
    assert bodies["minmax-length"]["options"] == {"metric": "linf"}
    assert "options" not in bodies["delaunay"]
    expect(fact(page, "delaunay", "metric")).to_contain_text("Euclidean")
    linf = fact(page, "minmax-length", "measure").inner_text()
    # |e|∞ ≤ |e|₂ for every edge, so the L∞ optimum is at most the Euclidean one.
    assert float(linf) <= float(euclidean)
    posts.clear()
    page.select_option("#metric", "lp")
    page.fill("#lp", "7")
    settle(page)
    bodies = {b["criterion"]: b for path, b in posts if path == "api/triangulate"}
    assert bodies["minmax-length"]["options"] == {"metric": "lp:7"}
    with page.expect_download() as d:
        page.click("#download-json")
    doc = json.loads(Path(d.value.path()).read_text())
    assert doc["results"][1]["metric"]["name"] == "lp:7"
    assert "m=lp:7" in page.evaluate("location.hash")


def test_a_graph_view_draws_its_edges(page):
    posts = record_posts(page)
    set_criteria(page, set())
    click_points(page, CLICKS)
    assert page.locator("#panels .panel").count() == 0
    n, h = len(CLICKS), hull_size(click_points_spots(page))
    for kind, edges in [("mst", n - 1), ("hull", h), ("delaunay", 3 * n - h - 3)]:
        page.select_option("#graph", kind)
        settle(page)
        expect(page.locator(f'svg.graph-svg[data-kind="{kind}"] line.edge')).to_have_count(edges)
    # The Delaunay graph takes no metric; the RNG does, the Gabriel graph not.
    assert page.locator("#metric").is_disabled()
    page.select_option("#graph", "rng")
    page.select_option("#metric", "l1")
    for kind in ["rng", "gabriel"]:
        posts.clear()
        page.select_option("#graph", kind)
        settle(page)
        assert page.locator("#metric").is_disabled() == (kind == "gabriel")
        assert page.locator(f'svg.graph-svg[data-kind="{kind}"] line.edge').count() >= n - 1, "contains the MST"
        body = [b for path, b in posts if path == "api/graph"][-1]
        assert body.get("options") == ({"metric": "l1"} if kind == "rng" else None), kind
    page.select_option("#graph", "")
    settle(page)
    assert page.locator("#graph-view .panel").count() == 0


def click_points_spots(page):
    """The editor's points, as screen spots (the hull size is the same)."""
    return [(float(c.get_attribute("cx")), -float(c.get_attribute("cy"))) for c in page.locator("#editor circle").all()]


def test_a_result_that_is_not_exact_shows_its_bound(page):
    # maxmin-area on points not in convex position: Delaunay with a certified
    # upper bound; a δ criterion: the best of three, with its guarantee.
    set_criteria(page, {"maxmin-area", "minmax-delta-length"})
    click_points(page, CLICKS)
    expect(fact(page, "maxmin-area", "exact")).to_have_text(re.compile("^no"))
    with page.expect_download() as d:
        page.click("#download-json")
    area, delta = json.loads(Path(d.value.path()).read_text())["results"]
    assert area["exact"] is False and area["bound"]["kind"] == "upper"
    bound = fact(page, "maxmin-area", "bound").inner_text()
    assert bound.startswith("the optimum's smallest area ≤ ")
    assert " ".join(map(str, area["bound"]["triangle"])) in bound
    assert math.isclose(float(bound.split("≤ ")[1].split()[0]), area["bound"]["area"], rel_tol=1e-5)
    expect(fact(page, "maxmin-area", "guarantee")).to_have_text(area["optimality_bound"])
    assert delta["exact"] is False
    expect(fact(page, "minmax-delta-length", "guarantee")).to_have_text(delta["optimality_bound"])
    # The δ measure, checked against the document's own edges.
    coords = delta["coordinates"]
    lengths = [math.dist(coords[a], coords[b]) for a, b in delta["edges"]]
    shown = fact(page, "minmax-delta-length", "measure").inner_text()
    assert shown.startswith("≈ ") and math.isclose(float(shown[2:]), max(lengths) - min(lengths), rel_tol=1e-5)


def test_min_weight_with_a_tiny_time_limit_shows_its_lower_bound(page):
    set_criteria(page, {"min-weight"})
    page.fill("#time-limit", "0.01")
    page.select_option("#generator", "circle")
    page.fill("#n", "200")
    page.click("#generate")
    settle(page)
    assert "&t=0.01&" in page.evaluate("location.hash")
    expect(fact(page, "min-weight", "exact")).to_have_text(re.compile("^no"))
    expect(fact(page, "min-weight", "bound")).to_contain_text("the optimal total length ≥ ")
    expect(page.locator('#stats tbody tr[data-criterion="min-weight"]')).to_contain_text("(!)")


def edge_insertion_measures(doc):
    """Smallest height, largest eccentricity and largest slope over the
    document's triangles (Bern et al. 1993), computed here independently:
    the height from the area and the longest side, the eccentricity as the
    distance from the circumcentre to the farthest side's line when the
    circumcentre is outside, the slope from the plane's normal."""
    c, z = doc["coordinates"], doc.get("elevations")
    heights, eccentricities, slopes = [], [], []
    for t in doc["triangles"]:
        (ax, ay), (bx, by), (cx, cy) = (c[i] for i in t)
        area2 = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
        sides = [math.dist(c[t[1]], c[t[2]]), math.dist(c[t[0]], c[t[2]]), math.dist(c[t[0]], c[t[1]])]
        heights.append(area2 / max(sides))
        d = 2 * ((ax * (by - cy)) + bx * (cy - ay) + cx * (ay - by))
        ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
        uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
        k = sides.index(max(sides))
        p, q = [c[i] for j, i in enumerate(t) if j != k]
        opposite = c[t[k]]
        # The circumcentre lies outside exactly when it is across the longest side from its corner.
        side = lambda pt: (q[0] - p[0]) * (pt[1] - p[1]) - (q[1] - p[1]) * (pt[0] - p[0])
        outside = side((ux, uy)) * side(opposite) < 0
        eccentricities.append(abs(side((ux, uy))) / math.dist(p, q) if outside else 0.0)
        if z:
            (za, zb, zc) = (z[i] for i in t)
            nx = (by - ay) * (zc - za) - (zb - za) * (cy - ay)
            ny = (zb - za) * (cx - ax) - (bx - ax) * (zc - za)
            slopes.append(math.hypot(nx, ny) / area2)
    return min(heights), max(eccentricities), max(slopes) if slopes else None


def test_edge_insertion_measures_and_slope_with_elevations(page):
    set_criteria(page, {"maxmin-height", "minmax-eccentricity", "minmax-slope"})
    label = page.locator("#criteria label").filter(has=page.locator('input[value="minmax-slope"]'))
    expect(label.locator(".tag")).to_have_text("needs elevations")
    assert "elevation" in label.locator(".tag").get_attribute("title")
    click_points(page, CLICKS)
    slope = page.locator('#panels .panel[data-criterion="minmax-slope"]')
    expect(slope.locator(".refused")).to_contain_text("needs an elevation")
    expect(slope.locator(".hint")).to_contain_text("terrain")
    page.select_option("#generator", "terrain")
    page.fill("#n", "25")
    page.fill("#seed", "4")
    page.click("#generate")
    settle(page)
    assert re.search(r"&p=[^;]*,[^;]*,[^;]*;", page.evaluate("location.hash")), "the link keeps x,y,z"
    with page.expect_download() as d:
        page.click("#download-json")
    docs = {r["criterion"]: r for r in json.loads(Path(d.value.path()).read_text())["results"]}
    for name, index in [("maxmin-height", 0), ("minmax-eccentricity", 1), ("minmax-slope", 2)]:
        expected = edge_insertion_measures(docs[name])[index]
        # The page shows the document's exact stats (rounded once), not an
        # estimate of its own; the test's float recomputation agrees.
        shown = fact(page, name, "measure").inner_text()
        assert not shown.startswith("≈ "), name
        assert math.isclose(float(shown), expected, rel_tol=1e-5, abs_tol=1e-9), (name, shown, expected)
        key = {"maxmin-height": "min_height", "minmax-eccentricity": "max_eccentricity"}.get(name, "max_slope")
        assert math.isclose(docs[name]["stats"][key], expected, rel_tol=1e-9, abs_tol=1e-12), name


def test_copy_link_uses_the_clipboard_or_shows_the_link(page, browser, server):
    set_criteria(page, {"delaunay"})
    click_points(page, CLICKS[:4])
    browser.grant_permissions(["clipboard-read", "clipboard-write"], origin=server.rstrip("/"))
    page.click("#copy-link")
    expect(page.locator("#share-status")).to_have_text("link copied")
    assert page.evaluate("navigator.clipboard.readText()") == page.url
    assert page.locator("#share-url").is_hidden()
    # Without a clipboard: the link in a field, kept up to date.
    page.evaluate("Object.defineProperty(navigator, 'clipboard', { value: undefined })")
    page.click("#copy-link")
    expect(page.locator("#share-url")).to_be_visible()
    assert page.locator("#share-url").input_value() == page.url
    click_points(page, CLICKS[4:5])
    assert page.locator("#share-url").input_value() == page.url
    assert page.url.count(";") == 4
