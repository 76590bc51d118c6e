"""The web playground in a real headless Chromium (Playwright for Python).

Starts `optri serve --port 0` (the binary from $OPTRI_BIN, default
target/debug/optri), opens the page, adds points by clicking the editor,
switches criteria, drags and deletes a point, triggers bad requests, and
checks what is drawn against an independent count: a triangulation of n
points with h on the convex hull has 2n - h - 2 triangles. Each criterion
is its own request: a panel is busy until its answer arrives, and one
stopped by the server's time limit says so while the others are drawn.

Run by .ci/run:  python -m pytest crates/optri-cli/tests/browser
A screenshot goes to $OPTRI_SCREENSHOT (default: a temporary file).
"""

import json
import os
import re
import subprocess
import tempfile
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
    set_criteria(page, {"delaunay", "greedy", "minmax-area"})
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
