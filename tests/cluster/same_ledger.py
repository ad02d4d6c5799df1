#!/usr/bin/env python3
"""Exit 0 when two `gsdot3 prove --json` ledgers are the same run: equal in everything but the
per-claim "seconds" (wall time). Otherwise name the first difference and exit 1."""
import json
import sys


def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k != "seconds"}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x


def first_difference(a, b, path="$"):
    if type(a) is not type(b):
        return f"{path}: {a!r} vs {b!r}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}.{k}: only in {'the second' if k not in a else 'the first'}"
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path}: {len(a)} vs {len(b)} items"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{path}: {a!r} vs {b!r}"


if len(sys.argv) != 3:
    sys.exit("usage: same_ledger.py A.json B.json")
with open(sys.argv[1]) as fa, open(sys.argv[2]) as fb:
    a, b = strip(json.load(fa)), strip(json.load(fb))
if not a.get("claims"):
    sys.exit(f"{sys.argv[1]}: no claims")
diff = first_difference(a, b)
if diff:
    sys.exit(f"the ledgers differ at {diff}")
print(f"same ledger: {', '.join(c['id'] + ' ' + c['verdict'] for c in a['claims'])}")
