#!/usr/bin/env python3
"""docs/sharding.md shows each script the cluster tests run (scripts/cluster/...) as a fenced block
after a line "<!-- file: PATH -->"; each block must be that file byte for byte, and the two recipes
(the job array's script and the GNU parallel one) must be shown. Usage: doc_recipes.py SOURCE_DIR"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1])
doc = (src / "docs/sharding.md").read_text()
shown = {}
for m in re.finditer(r"<!-- file: (\S+) -->\n```[a-z]*\n(.*?)```\n", doc, re.S):
    shown[m.group(1)] = m.group(2)
recipes = ["scripts/cluster/prove-shard.sbatch", "scripts/cluster/prove-parallel"]
errors = [f"{s}: not shown in docs/sharding.md" for s in recipes if s not in shown]
for path, text in shown.items():
    f = src / path
    if not f.is_file():
        errors.append(f"docs/sharding.md shows {path}, which does not exist")
    elif f.read_text() != text:
        errors.append(f"docs/sharding.md's {path} differs from the file")
if errors:
    sys.exit("\n".join(errors))
print(f"docs/sharding.md shows {len(shown)} scripts, each as it is: {', '.join(sorted(shown))}")
