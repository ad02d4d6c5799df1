"""gsdot3 cost on the three methods' dumps: the JSON's shape, and what the model gives by construction.

Usage: check_methods.py GSDOT3 DIR. Writes DIR/{two-pass,four-pass,baseline}.gs.zst with `gsdot3 dump`
at a small size, prices each with `gsdot3 cost --json`, checks every frame and pass has its timing and
breakdown, that the breakdown sums to the total, and that four-pass, which draws the mesh in more passes,
draws more pixels and so spends more pixel cycles than two-pass. Then `gsdot3 render --cost` at the same
size, which prices each frame in process: its report.json must hold, per method, exactly the cycles,
breakdown and counts the dump file gave (two routes to one figure: the file written, compressed, read
back and replayed by another command). Prints one line per method.
"""
import json
import subprocess
import sys

gsdot3, out = sys.argv[1], sys.argv[2]
keys = ["pixels", "page_breaks", "texture_misses", "uploads", "clut_loads", "setup"]
figures = {}
for method in ["two-pass", "four-pass", "baseline"]:
    dump = f"{out}/{method}.gs.zst"
    subprocess.run([gsdot3, "dump", "--method", method, "--size", "128x96", "--out", dump],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    j = json.loads(subprocess.run([gsdot3, "cost", dump, "--json"], check=True, capture_output=True, text=True).stdout)
    assert j["clock_hz"] == 147456000.0, j["clock_hz"]
    assert len(j["frames"]) == 1, len(j["frames"])
    f = j["frames"][0]
    for item in [f] + f["passes"]:
        b = item["breakdown"]
        assert sum(b[k] for k in keys) == b["total"] == item["cycles"], item
        assert abs(item["seconds"] - item["cycles"] / 147456000.0) < 1e-12
        assert item["ntsc"]["fps_locked"] > 0 and item["pal"]["fps_locked"] > 0
    assert sum(p["cycles"] for p in f["passes"]) == f["cycles"]
    assert sum(p["counts"]["pixels"] for p in f["passes"]) == f["counts"]["pixels"]
    figures[method] = f
    print(f"{method}: {f['cycles']} cycles, {f['counts']['pixels']} pixels, {len(f['passes'])} passes, "
          f"pixel cycles {f['breakdown']['pixels']}")
two, four = figures["two-pass"], figures["four-pass"]
assert four["counts"]["pixels"] > two["counts"]["pixels"], (four["counts"], two["counts"])
assert four["breakdown"]["pixels"] > two["breakdown"]["pixels"], (four["breakdown"], two["breakdown"])
print("four-pass draws more pixels and spends more pixel cycles than two-pass")

subprocess.run([gsdot3, "render", "--cost", "--method", "gs", "--size", "128x96", "--out", f"{out}/render-cost"],
               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
with open(f"{out}/render-cost/report.json") as fh:
    report = json.load(fh)
for method, f in figures.items():
    p = report["methods"][method]["ps2"]
    for k in ["cycles", "breakdown", "counts"]:
        assert p[k] == f[k], (method, k, p[k], f[k])
    assert p["pass_count"] == len(f["passes"]), (method, p["pass_count"], len(f["passes"]))
assert report["ps2"]["options"]["page_break_cycles"] == 10, report["ps2"]
print("render --cost prices every method as gsdot3 cost prices its dump")
