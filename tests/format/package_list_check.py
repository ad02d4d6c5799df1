#!/usr/bin/env python3
"""docs/guide.md names every Debian package scripts/setup installs, and no other (issue 54).

usage: package_list_check.py SOURCE_DIR

scripts/setup: the words of its `packages=(...)` array, comments left out. docs/guide.md: the paragraph
that begins "`scripts/setup` is the only thing that installs anything", read as a list: parenthesised
remarks dropped, split at commas and "and", each item's first word. Prints both differences; exit 1 if
either is not empty.
"""
import re
import sys


def setup_packages(text):
    body = re.search(r'^packages=\(\n(.*?)^\)', text, re.S | re.M)
    if not body:
        sys.exit('scripts/setup: no packages=( ... ) array')
    return {w for line in body.group(1).splitlines() for w in line.split('#', 1)[0].split()}


def guide_packages(text):
    start = text.find('`scripts/setup` is the only thing that installs anything')
    if start < 0:
        sys.exit('docs/guide.md: no paragraph on scripts/setup')
    para = text[start:text.find('\n\n', start)]
    listed = para[para.index('the Debian packages') + len('the Debian packages'):]
    listed = listed[:listed.index('.\n') if '.\n' in listed else len(listed)]
    while re.search(r'\([^()]*\)', listed):
        listed = re.sub(r'\([^()]*\)', '', listed)
    items = re.split(r',|\band\b', listed.replace('\n', ' '))
    return {i.split()[0] for i in items if i.split()}


def main():
    src = sys.argv[1]
    setup = setup_packages(open(f'{src}/scripts/setup').read())
    guide = guide_packages(open(f'{src}/docs/guide.md').read())
    missing, extra = sorted(setup - guide), sorted(guide - setup)
    print(f'scripts/setup: {len(setup)} packages; docs/guide.md: {len(guide)}')
    if missing:
        print('in scripts/setup, not in docs/guide.md: ' + ' '.join(missing))
    if extra:
        print('in docs/guide.md, not in scripts/setup: ' + ' '.join(extra))
    return 1 if missing or extra else 0


if __name__ == '__main__':
    sys.exit(main())
