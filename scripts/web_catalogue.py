#!/usr/bin/env python3
"""The page's texts for its JavaScript (docs/lecturers.md "German and English"), made at build time.

app/text/page.inc is the one list of the page's texts in English and German (C++ reads it through
app/text/catalogue.h). index.html shows texts before the WebAssembly has loaded (loading, a browser
that cannot run vplab, a lost graphics context), so its JavaScript needs them too: this script reads
page.inc and writes the page's index.html with the German of every entry in place of the marker
`/* @page.inc@ */ {}`. index.html looks its texts up by their English, t("Loading vplab…"), as the
C++ does; like the C++, a t("…") whose English is not in page.inc fails the build.

Usage: web_catalogue.py PAGE_INC INDEX_HTML OUT_HTML
"""
import json
import re
import sys
from pathlib import Path

MARKER = "/* @page.inc@ */ {}"
ESCAPES = {"\\": "\\", '"': '"', "'": "'", "?": "?", "n": "\n", "t": "\t"}


def fail(where: str, message: str):
    sys.exit(f"{where}: {message}")


def literal(text: str, i: int, where: str):
    """The C++ or JavaScript string literal starting at text[i] ('"'): (its value, the index after it)."""
    out = []
    i += 1
    while i < len(text):
        c = text[i]
        if c == '"':
            return "".join(out), i + 1
        if c == "\n":
            fail(where, "a string literal runs past the end of its line")
        if c == "\\":
            e = text[i + 1:i + 2]
            if e not in ESCAPES:
                fail(where, f"an escape the page's table does not read: \\{e}")
            out.append(ESCAPES[e])
            i += 2
            continue
        out.append(c)
        i += 1
    fail(where, "a string literal without its end")


def read_catalogue(path: Path) -> dict:
    """page.inc's entries {"English", "German"}, (adjacent literals joined, // comments skipped): English → German."""
    text = path.read_text(encoding="utf-8")
    entries = {}
    i, line = 0, 1
    entry = None    # the literals of the entry being read
    current = None  # the literal being joined from adjacent pieces
    while i < len(text):
        c = text[i]
        where = f"{path}:{line}"
        if c == "\n":
            line += 1
            i += 1
        elif c.isspace():
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = len(text) if end < 0 else end
        elif c == "{" and entry is None:
            entry, current = [], None
            i += 1
        elif c == '"' and entry is not None:
            value, i = literal(text, i, where)
            current = value if current is None else current + value
        elif c == "," and entry is not None:
            if current is None:
                fail(where, "an empty part of an entry")
            entry.append(current)
            current = None
            i += 1
        elif c == "}" and entry is not None:
            if current is not None:
                entry.append(current)
            if len(entry) != 2:
                fail(where, f"an entry of {len(entry)} texts, not {{\"English\", \"German\"}}")
            if entry[0] in entries:
                fail(where, f"\"{entry[0]}\" is given twice")
            entries[entry[0]] = entry[1]
            entry = None
            i += 1
        elif c == "," and entry is None:
            i += 1
        else:
            fail(where, f"unexpected {c!r} (an entry is {{\"English\", \"German\"}},)")
    if entry is not None:
        fail(str(path), "the last entry has no end")
    return entries


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    inc, page, out = (Path(a) for a in sys.argv[1:])
    german = read_catalogue(inc)
    html = page.read_text(encoding="utf-8")
    if html.count(MARKER) != 1:
        fail(str(page), f"the marker {MARKER} is not there once")
    # Every lookup names its text by a literal, and the literal is an entry of page.inc.
    for m in re.finditer(r"(?<!function )\bt\(", html):
        where = f"{page}:{html.count(chr(10), 0, m.start()) + 1}"
        j = m.end()
        while j < len(html) and html[j].isspace():
            j += 1
        if html[j:j + 1] != '"':
            fail(where, "t( takes the English as a string literal in double quotes")
        english, _ = literal(html, j, where)
        if english not in german:
            fail(where, f"\"{english}\" is not in {inc.name}: add {{\"{english}\", \"…\"}} there")
    # Inside <script>: no "</" (it could end the element), and no line separators JavaScript reads
    # as the end of a line.
    table = json.dumps(german, ensure_ascii=False, indent=None, sort_keys=True)
    table = table.replace("</", "<\\/").replace("\u2028", "\\u2028").replace("\u2029", "\\u2029")
    text = html.replace(MARKER, table)
    out.write_text(text, encoding="utf-8")


if __name__ == "__main__":
    main()
