"""tests/browser/first_screen.py — the report page's first screen, seen as a user sees it (page_test.py runs it).

Screenshots of a 1400x1000 window compared region by region with the PNGs the report wrote, read here by an
independent PNG decoder: the plain page must show the paper's methods' lit frames, the float reference's and
two-pass's error map (each 4x4 regions' mean colour near the PNG's), the tables below them, two-pass against the
reference with its worst pixel pinned and centred in the zoomed views; a hash link's zoomed views must show its
pixel (x, y) and those around it, magnified, in their centre.
"""
import base64
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from png_read import read_png  # noqa: E402

SCREEN = (1400, 1000)
GEOMETRY = """(() => {
  const box = e => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.width, b.height]; };
  const client = id => { const e = document.getElementById(id), b = e.getBoundingClientRect();
                         return [b.left + e.clientLeft, b.top + e.clientTop, e.clientWidth, e.clientHeight]; };
  return {overview: [...document.querySelectorAll('#overview img')].map(i => [i.getAttribute('src'), box(i)]),
          panes: [['img-a', client('scroll-a')], ['img-b', client('scroll-b')]].map(([i, c]) =>
                   [document.getElementById(i).getAttribute('src'), c]),
          tables: box(document.getElementById('tables'))[1],
          a: document.getElementById('pick-a').value, b: document.getElementById('pick-b').value,
          inspected: document.querySelector('#inspector p').textContent};
})()"""


def region_means(rows, x0, y0, w, h, cells):
    """Mean colour of each of cells x cells equal parts of the rectangle (x0, y0, w, h) of rows."""
    means = []
    for cy in range(cells):
        for cx in range(cells):
            xs = range(round(x0 + w * cx / cells), round(x0 + w * (cx + 1) / cells))
            ys = range(round(y0 + h * cy / cells), round(y0 + h * (cy + 1) / cells))
            px = [rows[y][x] for y in ys for x in xs]
            means.append(tuple(sum(p[c] for p in px) / len(px) for c in range(3)))
    return means


def first_screen(tab, url, path):
    """Opens url in a 1400x1000 window and takes its first screen: (the page's geometry, the screenshot's rows)."""
    tab.call("Emulation.setDeviceMetricsOverride", width=SCREEN[0], height=SCREEN[1], deviceScaleFactor=1, mobile=False)
    tab.open(url)
    with open(path, "wb") as f:
        f.write(base64.b64decode(tab.call("Page.captureScreenshot", format="png")["data"]))
    return tab.evaluate(GEOMETRY), read_png(path)


def on_screen(what, box, fail):
    x, y, w, h = box
    if not (0 <= x and 0 <= y and x + w <= SCREEN[0] and y + h <= SCREEN[1] and w >= 100 and h >= 100):
        fail(f"{what} at {box} is not a picture on the first screen ({SCREEN[0]}x{SCREEN[1]})")
        return False
    return True


def check_zoomed_pane(what, shot, pane, png, x, y, zoom, fail):
    """The pane's centre shows pixel (x, y) of png magnified zoom times, and around it the pixels beside it."""
    left, top, w, h = pane
    cx, cy = left + w / 2, top + h / 2  # the middle of pixel (x, y)'s zoom x zoom square when it is centred
    bad = []
    for dy in range(-6, 7):
        for dx in range(-6, 7):
            if max(abs(dx), abs(dy)) == 1 or not (0 <= x + dx < len(png[0]) and 0 <= y + dy < len(png)):
                continue  # the squares the pinned pixel's mark borders
            offsets = [(o, o) for o in range(1 - zoom // 2, zoom // 2)] if dx == dy == 0 else [(0, 0)]
            for ox, oy in offsets:
                sx, sy = math.floor(cx + dx * zoom) + ox, math.floor(cy + dy * zoom) + oy
                if shot[sy][sx] != png[y + dy][x + dx]:
                    bad.append((dx, dy, shot[sy][sx], png[y + dy][x + dx]))
    if bad:
        fail(f"{what}: {len(bad)} squares around the pane's centre differ from the PNG's pixels around ({x}, {y}), "
             f"e.g. (dx, dy, screen, PNG) {bad[:4]}")


def check(tab, url, out, report_dir, worst, other, fail):
    """worst: two-pass's worst pixel (x, y, light) against the reference; other: a covered pixel (x, y) for a second
    link, elsewhere on the mesh."""
    png = {}
    load = lambda name: png.setdefault(name, read_png(os.path.join(report_dir, name)))
    wx, wy, wl = worst
    geo, shot = first_screen(tab, url, os.path.join(out, "first-screen.png"))
    want = ["two-pass-lit.png", "four-pass-lit.png", "reference-lit.png", f"two-pass-error-light{wl}.png"]
    if [src for src, _ in geo["overview"]] != want:
        fail(f"first screen shows {[src for src, _ in geo['overview']]}, expected {want}")
    if (geo["a"], geo["b"]) != ("two-pass", "reference"):
        fail(f"default pair {geo['a']} | {geo['b']}, expected two-pass | reference")
    if geo["inspected"] != f"pixel x {wx}, y {wy}":
        fail(f"the inspector shows '{geo['inspected']}', expected two-pass's worst pixel ({wx}, {wy}), light {wl}")
    pictures = [box for _, box in geo["overview"]] + [box for _, box in geo["panes"]]
    if geo["tables"] < max(y + h for _, y, _, h in pictures):
        fail(f"the error tables start at y {geo['tables']}, above the pictures' bottom")
    for src, box in geo["overview"]:
        if not on_screen(src, box, fail) or src not in want:
            continue
        rows = load(src)
        got, expect = region_means(shot, *box, 4), region_means(rows, 0, 0, len(rows[0]), len(rows), 4)
        far = max(abs(g - e) for gc, ec in zip(got, expect) for g, e in zip(gc, ec))
        colours = len({shot[y][x] for y in range(round(box[1]), round(box[1] + box[3]))
                       for x in range(round(box[0]), round(box[0] + box[2]))})
        if far > 12 or colours < 64:
            fail(f"first screen: {src} at {box}: {colours} colours, its 4x4 regions' mean colours differ from the "
                 f"PNG's by up to {far:.1f}")
    for src, pane in geo["panes"]:
        if on_screen(src + "'s pane", pane, fail):
            check_zoomed_pane(f"first screen, {src} at zoom 2", shot, pane, load(src), wx, wy, 2, fail)
    print(f"first screen: {len(geo['overview'])} pictures and 2 zoomed views checked against the PNGs, "
          f"two-pass's worst pixel ({wx}, {wy})")

    # The README's link, and a second one elsewhere on the mesh.
    for x, y, zoom, layer, a_m in ((296, 206, 4, "error", "two-pass"), (*other, 8, "lit", "four-pass")):
        geo, shot = first_screen(tab, f"{url}#a={a_m}&b=reference&layer={layer}&zoom={zoom}&x={x}&y={y}",
                                 os.path.join(out, f"link-{a_m}-{layer}.png"))
        names = [f"{a_m}-lit.png", "reference-lit.png"] if layer == "lit" else [f"{a_m}-error-light0.png",
                                                                                 "reference-dot-light0.png"]
        if [src for src, _ in geo["panes"]] != names:
            fail(f"link to ({x}, {y}): panes show {[src for src, _ in geo['panes']]}, expected {names}")
            continue
        for src, pane in geo["panes"]:
            if on_screen(src + "'s pane", pane, fail):
                check_zoomed_pane(f"link to ({x}, {y}) zoom {zoom}, {src}", shot, pane, load(src), x, y, zoom, fail)
        print(f"link to ({x}, {y}), {layer} at zoom {zoom}: the views' centres checked against the PNGs' pixels")
