#!/usr/bin/env python3
"""tests/browser/page_test.py — the report page in a real browser (ctest label `browser`).

Writes the report of the embedded scene, then opens report.html from disk (file://) in headless
Chromium (--dump-dom after the page's scripts ran, --screenshot) and checks: no console message and
no script error, every image loaded, the method picker switches the views (and its difference map
has as many non-zero pixels as this script counts), and the inspector shows, for a few fixed pixels
(set by the URL, and one by a dispatched mouse click), the values this script decodes itself from
report-pixels.js; then (first_screen.py) the first screen of the plain page and of two hash links, from
screenshots compared with the report's PNGs region by region. The exported data is checked
independently first: its error statistics against report.json, and per pixel the post filter's
modulo-256 sums, the ILP entry (section 3.4: level d + 1 for d = 0..127, else 0) and the LAB update
(MODULATE by the light colour given on the command line, added with a clamp at 255).

Exit 0: pass, 1: fail, 77: skipped (no Chromium on this machine; scripts/setup installs it).
"""
import argparse
import html.parser
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import socket
import tempfile
import threading
import time
import urllib.request
import zlib
import base64

import first_screen

LIGHTS = [("-2.2,1.4,2.2", (0x10, 0x98, 0x20)), ("2.6,-0.2,0.4", (0x10, 0x38, 0xB0))]
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars"]

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def read_pixels(path):
    """An independent reader of report-pixels.js (format 1, see pipeline/report_page.hpp)."""
    text = open(path, encoding="ascii").read()
    head = json.loads(text[text.index("{"):text.rindex("}") + 1])
    raw = zlib.decompress(base64.b64decode(head["deflate_base64"]))
    if len(raw) != head["bytes"]:
        fail(f"pixel payload has {len(raw)} bytes, header says {head['bytes']}")
    n = head["count"]
    fmt = {"u8": "B", "u16": "H", "u32": "I", "i32": "i", "f32": "f"}
    cols = {}
    for c in head["columns"]:
        if "const" in c:
            v = c["const"]
            cols[c["name"]] = [v] * n if not isinstance(v, list) else [tuple(v)] * n
        elif "same_as" in c:
            cols[c["name"]] = cols[c["same_as"]]
        else:
            w = c["width"]
            vals = struct.unpack_from(f"<{n * w}{fmt[c['type']]}", raw, c["offset"])
            cols[c["name"]] = list(vals) if w == 1 else [tuple(vals[i * w:(i + 1) * w]) for i in range(n)]
    return n, cols


def signed_dot(byte):
    return ((byte - 128) & 0xFF) - 256 if ((byte - 128) & 0xFF) >= 128 else (byte - 128) & 0xFF


def stats(errors):
    n = len(errors)
    return {"samples": n, "max_abs": max(abs(e) for e in errors), "rmse": math.sqrt(sum(e * e for e in errors) / n)}


def check_data(report, n, cols, passes):
    lights = report["scene"]["lights"]
    for name, m in report["methods"].items():
        gs = "seed" not in m
        errs = []
        for l in range(lights):
            d, ref = cols[f"{name}/dot{l}"], cols[f"reference/dot{l}"]
            for r in range(n):
                value = signed_dot(d[r]) if gs else d[r]
                target = ref[r] if gs or m["compared_with"] == "reference" else max(ref[r], 0.0)
                errs.append(value - target)
        got, want = stats(errs), m["vs_renormalised"]
        for k in got:
            if abs(got[k] - want[k]) > 1e-6 * max(1.0, abs(want[k])):
                fail(f"{name}: {k} from the exported pixels {got[k]} != report.json {want[k]}")
        if not gs:
            continue
        p = passes[name]
        lab_before = None
        for i, q in enumerate(p):
            if q["target"] == "LAB" and q["light"] < 0:
                lab_before = i
        for l in range(lights):
            dpb = [i for i, q in enumerate(p) if q["light"] == l and q["target"] == "DPB"]
            lab = [i for i, q in enumerate(p) if q["light"] == l and q["target"] == "LAB"]
            if len(dpb) < 4 or len(lab) != 1:
                fail(f"{name}: light {l}: expected the post filter's two DPB passes and one LAB pass, got {p}")
                continue
            before, plus_g, plus_b, ilp = dpb[-3], dpb[-2], dpb[-1], lab[0]
            bad = 0
            for r in range(n):
                w0, w1, w2 = (cols[f"{name}/{k}/word"][r] for k in (before, plus_g, plus_b))
                r0, g0, b0 = w0 & 0xFF, (w0 >> 8) & 0xFF, (w0 >> 16) & 0xFF
                s1 = (r0 + g0) & 0xFF
                s2 = (s1 + b0) & 0xFF
                ok = w1 == (w0 & ~0xFF) | s1 and w2 == (w0 & ~0xFF) | s2 and cols[f"{name}/dot{l}"][r] == s2
                dd = (s2 - 128) & 0xFF
                level = dd + 1 if dd < 128 else 0
                ok = ok and cols[f"{name}/{ilp}/texel"][r] == (0x80 << 24 | level << 16 | level << 8 | level)
                old, new = cols[f"{name}/{lab_before}/word"][r], cols[f"{name}/{ilp}/word"][r]
                for c in range(3):
                    want_c = min(255, ((old >> (8 * c)) & 0xFF) + ((level * LIGHTS[l][1][c]) >> 7))
                    ok = ok and ((new >> (8 * c)) & 0xFF) == want_c
                ok = ok and (new >> 24) == (old >> 24)
                bad += not ok
            if bad:
                fail(f"{name}: light {l}: {bad} of {n} pixels break the post filter / ILP / LAB arithmetic")
            lab_before = ilp


class Dom(html.parser.HTMLParser):
    """Collects the inspector's data-k cells, the self-check text and the views' image sources."""

    def __init__(self):
        super().__init__()
        self.cells, self.selfcheck, self.srcs, self._key, self._text = {}, None, {}, None, []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img" and a.get("id") in ("img-a", "img-b"):
            self.srcs[a["id"]] = a.get("src")
        if "data-k" in a or a.get("id") == "selfcheck":
            self._key, self._text = a.get("data-k", "#selfcheck"), []

    def handle_data(self, data):
        if self._key is not None:
            self._text.append(data)

    def handle_endtag(self, tag):
        if self._key is not None and tag in ("td", "pre", "p"):
            text = "".join(self._text)
            if self._key == "#selfcheck":
                self.selfcheck = json.loads(text)
            else:
                self.cells.setdefault(self._key, []).append(text)
            self._key = None


class DevTools:
    """Chromium's DevTools protocol over a WebSocket (RFC 6455 client, text frames), standard library only."""

    def __init__(self, browser, profile_root):
        self.profile = tempfile.mkdtemp(prefix="profile-", dir=profile_root)
        self.proc = subprocess.Popen([browser, *FLAGS, f"--user-data-dir={self.profile}", "--remote-debugging-port=0",
                                      "--window-size=1500,2600", "about:blank"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        port = None
        deadline = time.time() + 60
        while port is None and time.time() < deadline:
            line = self.proc.stderr.readline()
            if not line and self.proc.poll() is not None:
                break
            if "DevTools listening on ws://" in line:
                port = int(line.split("ws://", 1)[1].split("/", 1)[0].rsplit(":", 1)[1])
        if port is None:
            raise RuntimeError("chromium did not open its DevTools port")
        threading.Thread(target=self._drain, daemon=True).start()
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=30))
        ws = next(t["webSocketDebuggerUrl"] for t in targets if t["type"] == "page")
        path = ws.split(str(port), 1)[1]
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=120)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                           f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
        reply = b""
        while b"\r\n\r\n" not in reply:
            reply += self.sock.recv(1)
        if b" 101 " not in reply.split(b"\r\n", 1)[0]:
            raise RuntimeError("DevTools WebSocket handshake failed: " + reply.decode(errors="replace"))
        self.next_id, self.events = 0, []
        for domain in ("Runtime", "Log", "Page"):
            self.call(domain + ".enable")

    def _drain(self):
        for _ in self.proc.stderr:
            pass

    def _recv_exact(self, n):
        b = b""
        while len(b) < n:
            chunk = self.sock.recv(n - len(b))
            if not chunk:
                raise RuntimeError("DevTools connection closed")
            b += chunk
        return b

    def _recv(self):
        message = b""
        while True:
            b0, b1 = self._recv_exact(2)
            n = b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._recv_exact(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._recv_exact(8))[0]
            payload = self._recv_exact(n)
            if b0 & 0x0F in (0x0, 0x1, 0x2):
                message += payload
                if b0 & 0x80:
                    return json.loads(message)

    def call(self, method, **params):
        self.next_id += 1
        data = json.dumps({"id": self.next_id, "method": method, "params": params}).encode()
        mask = os.urandom(4)
        n = len(data)
        head = bytes([0x81]) + (bytes([0x80 | n]) if n < 126 else bytes([0x80 | 126]) + struct.pack(">H", n) if n < 65536
                                  else bytes([0x80 | 127]) + struct.pack(">Q", n))
        self.sock.sendall(head + mask + bytes(c ^ mask[i % 4] for i, c in enumerate(data)))
        while True:
            m = self._recv()
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m["result"]
            self.events.append(m)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        return r["result"].get("value")

    def open(self, url):
        """Loads url afresh and waits until the page says it is ready; fails on any console message or error."""
        self.call("Page.navigate", url="about:blank")
        self.events.clear()
        self.call("Page.navigate", url=url)
        deadline = time.time() + 120
        while self.evaluate("document.readyState === 'complete' && document.body && document.body.getAttribute('data-ready')") != "1":
            if time.time() > deadline:
                fail(f"{url}: the page did not get ready in 120 s")
                break
            time.sleep(0.1)
        for e in self.events:
            m, p = e.get("method"), e.get("params", {})
            if m == "Runtime.consoleAPICalled":
                fail(f"console.{p.get('type')} from the page: {[a.get('value', a.get('description')) for a in p.get('args', [])]}")
            elif m == "Runtime.exceptionThrown":
                fail(f"exception in the page: {p.get('exceptionDetails', {}).get('text')} "
                     f"{p.get('exceptionDetails', {}).get('exception', {}).get('description')}")
            elif m == "Log.entryAdded":
                fail(f"browser log ({p['entry'].get('level')}): {p['entry'].get('text')} {p['entry'].get('url', '')}")
        return self.evaluate("document.documentElement.outerHTML")

    def close(self):
        self.sock.close()
        self.proc.terminate()
        try:
            self.proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def expected_cells(report, passes, cols, palette, r):
    """What the inspector must show at row r, formatted as the page does (hex words, 3-decimal floats)."""
    want = {"triangle": str(cols["triangle"][r]), "texel_index": None}
    u, v, ti = cols["u16"][r], cols["v16"][r], cols["texel_index"][r]
    want["uv"] = f"0x{u & 0xFFFFFFFF:05x} 0x{v & 0xFFFFFFFF:05x} = ({u / 16:.4f}, {v / 16:.4f})"
    want["texel_index"] = f"{ti} → (" + ", ".join(f"{q:.4f}" for q in palette[ti]) + ")"
    floats = {}
    for l in range(report["scene"]["lights"]):
        floats[f"reference/dot{l}"] = cols[f"reference/dot{l}"][r]
        floats[f"reference/unnormalised{l}"] = cols[f"reference/unnormalised{l}"][r]
    for name, m in report["methods"].items():
        if "seed" in m:
            for l in range(report["scene"]["lights"]):
                floats[f"{name}/dot{l}"] = cols[f"{name}/dot{l}"][r]
            continue
        for i, _ in enumerate(passes[name]):
            k = f"{name}/{i}/"
            shaded = cols[k + "shaded"][r]
            want[k + "word"] = f"0x{cols[k + 'word'][r]:08x}"
            want[k + "texel"] = f"0x{cols[k + 'texel'][r]:08x}" if shaded else "—"
            want[k + "colour"] = " ".join(f"0x{c:04x}" for c in cols[k + "colour"][r]) if shaded else "—"
        for l in range(report["scene"]["lights"]):
            s = cols[f"{name}/dot{l}"][r]
            lab = [i for i, q in enumerate(passes[name]) if q["target"] == "LAB" and q["light"] == l][0]
            want[f"{name}/sum{l}"] = f"0x{s:02x}"
            want[f"{name}/dotvalue{l}"] = str(signed_dot(s))
            want[f"{name}/ilp{l}"] = f"0x{cols[f'{name}/{lab}/texel'][r]:08x}"
            want[f"{name}/lab{l}"] = f"0x{cols[f'{name}/{lab}/word'][r]:08x}"
    return want, floats


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gsdot3", required=True)
    ap.add_argument("--out", required=True, help="directory for the report, the screenshot and profiles")
    a = ap.parse_args()
    browser = find_chromium()
    if browser is None:
        print("SKIPPED: no chromium in PATH (Debian: apt-get install chromium; scripts/setup installs it)")
        return 77
    out = os.path.abspath(a.out)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    report_dir = os.path.join(out, "report")
    cmd = [a.gsdot3, "report", "--cost", "--out", report_dir]
    for pos, col in LIGHTS:
        cmd += ["--light", f"{pos}:{col[0]:02X}{col[1]:02X}{col[2]:02X}"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    page_path = os.path.join(report_dir, "report.html")
    page_text = open(page_path, encoding="utf-8").read()
    for bad in ('src="http', "src='http", 'href="http', "@import", "url(http", "fonts.googleapis"):
        if bad in page_text:
            fail(f"report.html refers to the network ({bad})")
    report = json.load(open(os.path.join(report_dir, "report.json"), encoding="utf-8"))
    page = json.loads(page_text.split('<script type="application/json" id="gsdot3-page">', 1)[1].split("</script>", 1)[0])
    n, cols = read_pixels(os.path.join(report_dir, "report-pixels.js"))
    print(f"report.html {os.path.getsize(page_path)} bytes, report-pixels.js "
          f"{os.path.getsize(os.path.join(report_dir, 'report-pixels.js'))} bytes, {n} covered pixels")
    check_data(report, n, cols, page["passes"])

    width = report["scene"]["width"]
    names = list(report["methods"].keys())
    e = [abs(signed_dot(d) - ref) for d, ref in zip(cols[names[-1] + "/dot0"], cols["reference/dot0"])]
    rows = sorted({0, n // 2, n - 1, e.index(max(e))})
    url = "file://" + page_path
    tab = DevTools(browser, out)
    for i, r in enumerate(rows):
        px = cols["pixel"][r]
        x, y = px % width, px // width
        a_m, b_m = names[i % len(names)], names[(i + 1) % len(names)]
        dom = Dom()
        dom.feed(tab.open(f"{url}#a={a_m}&b={b_m}&x={x}&y={y}&selftest=1"))
        sc = dom.selfcheck
        if sc is None:
            fail(f"pixel ({x}, {y}): the page wrote no self-check (scripts did not finish)")
            continue
        if sc["errors"]:
            fail(f"script errors: {sc['errors']}")
        imgs = sc["images"]
        expected_images = sum(1 + 2 * report["scene"]["lights"] for _ in names) + 1 + report["scene"]["lights"] + 2
        expected_images += 1 if page.get("side_by_side") else 0
        expected_images += len({"two-pass", "four-pass"} & set(names)) + 2  # the overview: + the reference's, an error map
        expected_images += len(report.get("memory", {}).get("pictures", []))  # the GS local-memory section
        expected_images += len(report.get("memory", {}).get("dpb_pictures", {}).get("files", []))  # the rendered DPB
        if imgs["failed"] or imgs["loaded"] != imgs["total"] or imgs["total"] != expected_images:
            fail(f"images: {imgs}, expected {expected_images} loaded")
        priced = [m for m, v in report["methods"].items() if "cycles" in v.get("ps2", {})]
        gs_methods = [m for m, v in report["methods"].items() if "seed" not in v]
        if priced != gs_methods or sc.get("ps2_bars") != len(priced):
            fail(f"PS2 chart: {sc.get('ps2_bars')} bars drawn, report.json prices {priced} (the GS methods {gs_methods})")
        if not sc["pixels"].startswith(f"loaded {n} "):
            fail(f"per-pixel data: {sc['pixels']}")
        if dom.srcs.get("img-a") != f"{a_m}-lit.png" or dom.srcs.get("img-b") != f"{b_m}-lit.png":
            fail(f"views show {dom.srcs}, picked {a_m} and {b_m}")
        choices = names + ["reference"]
        if len(sc["picker"]) != len(choices):
            fail(f"picker self-test visited {len(sc['picker'])} pairs, expected {len(choices)}")
        for k, step in enumerate(sc["picker"]):
            pa, pb = choices[k], choices[(k + 1) % len(choices)]
            dot = lambda m, row: cols["reference/dot0"][row] if m == "reference" else (
                signed_dot(cols[m + "/dot0"][row]) if "seed" not in report["methods"][m] else cols[m + "/dot0"][row])
            nonzero = sum(1 for row in range(n) if dot(pa, row) - dot(pb, row) != 0)
            want = {"a": pa, "b": pb, "src_a": f"{pa}-lit.png", "src_b": f"{pb}-lit.png", "diff_nonzero": nonzero}
            for key, v in want.items():
                if step.get(key) != v:
                    fail(f"picker step {k}: {key} = {step.get(key)}, expected {v}")
            if not os.path.exists(os.path.join(report_dir, step["src_a"])):
                fail(f"picker shows {step['src_a']}, which the report did not write")
        # The memory section's table: every step of section 3.1 at register level on the memory path.
        steps = report.get("memory", {}).get("steps", [])
        if [st["step"] for st in steps] != ["1", "2.1", "2.2", "2.3", "2.4", "2.5", "2.6", "3", "4", "5"]:
            fail(f"memory steps: {[st['step'] for st in steps]}")
        for st in steps:
            shown = dom.cells.get("memory-step-" + st["step"])
            if shown != [st["memory_path"]] or not st["memory_path"].startswith("register level"):
                fail(f"memory step {st['step']}: page shows {shown}, report.json says {st['memory_path']!r}")
        want, floats = expected_cells(report, page["passes"], cols, page["palette"], r)
        for key, v in want.items():
            if dom.cells.get(key) != [v]:
                fail(f"pixel ({x}, {y}) {key}: page shows {dom.cells.get(key)}, expected {v}")
        for key, v in floats.items():
            got = dom.cells.get(key)
            if not got or abs(float(got[0]) - v) > 5.1e-4:
                fail(f"pixel ({x}, {y}) {key}: page shows {got}, expected {v:.4f}")
        print(f"pixel ({x}, {y}) row {r}: {len(want) + len(floats)} inspector values checked, views {a_m} | {b_m}")

    # An uncovered pixel: the inspector says so.
    covered = set(cols["pixel"])
    free = next(p for p in range(width * report["scene"]["height"]) if p not in covered)
    dom = Dom()
    dom.feed(tab.open(f"{url}#x={free % width}&y={free // width}"))
    if "uncovered" not in dom.cells:
        fail(f"pixel {free}: the inspector does not say it is uncovered")

    # A real click on view A (zoom 1) pins that pixel in the inspector.
    r = n // 3
    x, y = cols["pixel"][r] % width, cols["pixel"][r] // width
    # The view scrolled to its top-left corner first (it opens centred on the pinned worst pixel), then into the
    # viewport. DevTools takes whole CSS pixels: the click goes to the first whole position inside the pixel (the
    # image may sit at a fractional position).
    tab.open(f"{url}#a=two-pass&b=four-pass&zoom=1")
    rect = tab.evaluate("(() => { const s = document.getElementById('scroll-a'); s.scrollLeft = s.scrollTop = 0;"
                        " const e = document.getElementById('img-a'); e.scrollIntoView({block: 'start'});"
                        " const b = e.getBoundingClientRect(); return [b.left, b.top]; })()")
    for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
        tab.call("Input.dispatchMouseEvent", type=kind, x=math.ceil(rect[0] + x - 1e-9), y=math.ceil(rect[1] + y - 1e-9), button="left", clickCount=1)
    dom = Dom()
    dom.feed(tab.evaluate("document.documentElement.outerHTML"))
    want, _ = expected_cells(report, page["passes"], cols, page["palette"], r)
    clicked = [k for k in ("triangle", "uv", "two-pass/2/word", "two-pass/sum0") if dom.cells.get(k) != [want[k]]]
    if clicked:
        fail(f"click at pixel ({x}, {y}): the inspector shows {[(k, dom.cells.get(k)) for k in clicked]}, expected "
             f"{[want[k] for k in clicked]}")
    else:
        print(f"click on view A at pixel ({x}, {y}): the inspector shows its values")
    # The first screen: two-pass's worst pixel over every light (the first of equals in light then raster order).
    worst = max((abs(signed_dot(cols[f"two-pass/dot{l}"][r]) - cols[f"reference/dot{l}"][r]), -l, -r)
                for l in range(report["scene"]["lights"]) for r in range(n))
    wl, wr = -worst[1], -worst[2]
    other = cols["pixel"][n // 4]
    first_screen.check(tab, url, out, report_dir, (cols["pixel"][wr] % width, cols["pixel"][wr] // width, wl),
                       (other % width, other // width), fail)
    tab.close()
    print("FAILED: %d checks" % len(failures) if failures else "PASSED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
