#!/usr/bin/env python3
"""The Debian changelog of the vplab package (usr/share/doc/vplab/changelog.gz), made from CHANGELOG.md.

vplab is packaged by its own project (a native package, version = the release), so its Debian changelog
tells the same story as CHANGELOG.md, in the format dpkg-parsechangelog and lintian read:

    vplab (0.1.0) UNRELEASED; urgency=medium

      * The lab:
        - The five stages on the CPU ...

     -- Maintainer <address>  Thu, 26 Nov 2026 18:00:00 +0000

A release whose heading says "not yet released" goes to the distribution UNRELEASED. The date is
SOURCE_DATE_EPOCH (CMake passes the commit's time), so the same commit gives the same bytes.

Usage: debian_changelog.py CHANGELOG.md --maintainer 'Name <address>' --out changelog.gz
"""
import argparse
import gzip
import os
import re
import sys
import textwrap
import time

RELEASE = re.compile(r"^## (\d+\.\d+\.\d+)\s+—\s+(.*)$")


def releases(markdown):
    """[(version, released?, [(section, [bullet text])])], newest first, as CHANGELOG.md lists them."""
    found, bullet = [], None
    for line in markdown.splitlines():
        if m := RELEASE.match(line):
            found.append((m.group(1), "not yet released" not in m.group(2), []))
            bullet = None
        elif found and line.startswith("### "):
            found[-1][2].append((line[4:].strip(), []))
            bullet = None
        elif found and found[-1][2] and line.startswith("- "):
            bullet = [line[2:].strip()]
            found[-1][2][-1][1].append(bullet)
        elif bullet is not None and line.startswith("  ") and line.strip():
            bullet.append(line.strip())
        else:
            bullet = None
    return [(v, done, [(s, [" ".join(b) for b in bullets]) for s, bullets in sections]) for v, done, sections in found]


def entry(version, released, sections, maintainer, date):
    lines = [f"vplab ({version}) {'unstable' if released else 'UNRELEASED'}; urgency=medium", ""]
    for section, bullets in sections:
        lines.append(f"  * {section}:")
        for text in bullets:
            lines += textwrap.wrap(text.replace("`", ""), 78, initial_indent="    - ", subsequent_indent="      ",
                               break_on_hyphens=False)
    lines += ["", f" -- {maintainer}  {date}", ""]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("changelog")
    parser.add_argument("--maintainer", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    with open(args.changelog, encoding="utf-8") as f:
        found = releases(f.read())
    if not found:
        sys.exit(f"debian_changelog.py: {args.changelog} names no release (a heading '## X.Y.Z — date')")
    seconds = int(os.environ.get("SOURCE_DATE_EPOCH", "0") or 0)
    date = time.strftime("%a, %d %b %Y %H:%M:%S +0000", time.gmtime(seconds))  # RFC 5322, as dpkg wants it
    text = "\n".join(entry(v, done, sections, args.maintainer, date) for v, done, sections in found)
    with open(args.out + ".part", "wb") as f:
        f.write(gzip.compress(text.encode("utf-8"), compresslevel=9, mtime=0))
    os.replace(args.out + ".part", args.out)


if __name__ == "__main__":
    main()
