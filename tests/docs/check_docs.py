#!/usr/bin/env python3
"""The README and the pages of docs/ stay true to the tree and to the command line (issue 39 item 9).

For README.md and docs/*.md:

- every relative link, [text](path), [text](path#anchor), ![alt](path) and <img src="path">, names a
  file or directory of the repository that exists, and an #anchor a heading of that file (GitHub's
  anchors: the heading's text as shown, lowercased, keeping letters of any script, marks, digits, '_',
  '-' and spaces, each space a '-'; a repeated heading -1, -2, …) or an id="…" / name="…" in it;
- every line of a fenced code block that runs `vplab …` (after an optional "$ "), and every inline code
  span of the text that does, names a subcommand that exists (`vplab [SUB…] --help` of the built vplab
  answers), uses only options that subcommand's --help lists, gives an option with a fixed set of values
  ({a,b} in the help) only those values and a number within the help's range [lo - hi]; a line of a
  code block that is a concrete command (no [ ] or | of a synopsis) also names what an option needs
  (Needs:), nothing it excludes (Excludes:) and every option the help calls required (an inline span is
  a mention: `vplab exercise` needs no --out). Indented lines that go on with [ or -- continue the
  synopsis line above them, as does a trailing \\. Placeholders (FILE, DIR, N, WxH, …) and … stand for
  any value. vplab has no dry run (`exercise` and `grade` run in their subcommands' callbacks while
  CLI11 parses), so the lines are checked against --help, not run.
- every line of a fenced code block that runs `scripts/…` names an executable script of the tree;
  scripts/run.sh's arguments go to vplab and are checked as `vplab …`'s.

Prints FILE:LINE: what is broken, for each finding, and exits 1 when there is one.

  check_docs.py --root SOURCE_DIR --vplab BUILT_VPLAB    checks the tree
  check_docs.py --self-test --vplab BUILT_VPLAB          checks that the check finds what it should
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import unicodedata

FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
LINK = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
IMG_SRC = re.compile(r"<(?:img|a)\b[^>]*?\b(?:src|href)\s*=\s*\"([^\"]+)\"", re.I)
HTML_ID = re.compile(r"\b(?:id|name)\s*=\s*\"([^\"]+)\"", re.I)
OPTION = re.compile(r"(?<![\w/.=-])(--?[A-Za-z][\w-]*)")
INLINE_VPLAB = re.compile(r"(?<!`)`(?:\$ )?(vplab [^`]*)`(?!`)")  # `vplab render --theme light` in the text
PLACEHOLDER = re.compile(r"[A-Z]")  # FILE, DIR, N, WxH, FILE.png, ROSTER.csv: a value the reader chooses


def github_anchor(heading):
    """The anchor GitHub gives a heading (github-slugger on the heading's rendered text)."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link shows its text
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML shows nothing of its tags
    text = text.replace("`", "").replace("**", "").replace("__", "")
    text = re.sub(r"(?<!\w)[*_](\S.*?\S|\S)[*_](?!\w)", r"\1", text)  # *emphasis*, _emphasis_
    # GitHub keeps [\p{L}\p{M}\p{Nd}\p{Nl}\p{Pc}\- ]: letters of any script (ä, ß), marks, digits,
    # connector punctuation ('_'), '-' and the space; other punctuation (—, ., :, “), symbols (→, ×),
    # other numbers (², ½), other spaces and controls are dropped.
    kept = "".join(ch for ch in text.lower()
                   if ch in "- " or unicodedata.category(ch) in ("Nd", "Nl", "Pc") or unicodedata.category(ch)[0] in "LM")
    return kept.replace(" ", "-")


class Page:
    """A Markdown file: its lines, which of them are fenced code, and its anchors."""

    def __init__(self, path):
        self.path = path
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().split("\n")
        self.in_code = []
        fence = None
        for line in self.lines:
            m = FENCE.match(line)
            if fence is None and m:
                fence = m.group(1)
                self.in_code.append(True)
            elif fence is not None:
                self.in_code.append(True)
                if m and m.group(1) == fence and line.strip() == fence:
                    fence = None
            else:
                self.in_code.append(False)
        self.anchors = set()
        seen = {}
        for line, code in zip(self.lines, self.in_code):
            if code:
                continue
            m = HEADING.match(line)
            if m:
                base = github_anchor(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                self.anchors.add(base if n == 0 else "%s-%d" % (base, n))
            for ident in HTML_ID.findall(line):
                self.anchors.add(ident)

    def prose(self):
        """The text outside fenced code and inline code spans, line numbers kept."""
        text = "\n".join("" if code else line for line, code in zip(self.lines, self.in_code))
        return re.sub(r"(`+)(?:(?!\1).)+?\1", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)


def check_links(root, page, pages, findings):
    text = page.prose()
    base = os.path.dirname(page.path)
    for regex in (LINK, IMG_SRC):
        for m in regex.finditer(text):
            target = m.group(1)
            line = text.count("\n", 0, m.start(1)) + 1
            where = "%s:%d" % (os.path.relpath(page.path, root), line)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):  # https:, mailto:, …
                continue
            path, _, anchor = target.partition("#")
            file = os.path.normpath(os.path.join(base, path)) if path else page.path
            if not os.path.exists(file):
                findings.append("%s: link to %s: no such file" % (where, target))
                continue
            if not os.path.realpath(file).startswith(os.path.realpath(root) + os.sep):
                findings.append("%s: link to %s: outside the repository" % (where, target))
                continue
            if anchor:
                if not file.endswith(".md"):
                    findings.append("%s: link to %s: an anchor into a file that is not Markdown" % (where, target))
                    continue
                other = pages.get(file) or Page(file)
                pages[file] = other
                if anchor not in other.anchors:
                    close = sorted(a for a in other.anchors if anchor.split("-")[0] in a)[:5]
                    findings.append("%s: link to %s: %s has no heading with the anchor #%s%s" % (
                        where, target, os.path.relpath(file, root), anchor,
                        " (it has: %s)" % ", ".join("#" + a for a in close) if close else ""))


class Help:
    """What `vplab [SUB…] --help` says: the subcommands and the options with their values."""

    def __init__(self, text):
        self.subcommands = set()
        self.options = {}  # name -> {"set": [...] or None, "range": (lo, hi) or None, "needs": [], "excludes": [], "required": bool}
        section = None
        current = None
        for line in text.split("\n"):
            if re.match(r"^\S.*:$", line):
                section = line[:-1]
                current = None
                continue
            if section == "Subcommands":
                m = re.match(r"^  (\S+)", line)
                if m:
                    self.subcommands.add(m.group(1))
            elif section == "Options":
                m = re.match(r"^  (-[\w-]+(?:,\s*-[\w-]+)*)(.*)$", line)
                if m:
                    info = {"set": None, "range": None, "needs": [], "excludes": [], "required": False}
                    rest = m.group(2)
                    s = re.search(r":\{([^}]*)\}", rest)
                    if s:
                        info["set"] = s.group(1).split(",")
                    r = re.search(r"in \[(-?[\d.e+-]+) - (-?[\d.e+-]+)\]", rest)
                    if r:
                        info["range"] = (float(r.group(1)), float(r.group(2)))
                    n = re.search(r"Needs: ((?:-[\w-]+ ?)+)", rest)
                    if n:
                        info["needs"] = n.group(1).split()
                    x = re.search(r"Excludes: ((?:[\w-]+ ?)+)", rest)
                    if x:
                        info["excludes"] = [e for e in x.group(1).split() if e.startswith("-")]
                    info["required"] = bool(re.search(r"\((?:[^()]*; )?required\)|REQUIRED", rest))
                    current = info
                    for name in re.split(r",\s*", m.group(1)):
                        self.options[name] = info
                elif current is not None and line.startswith("    "):
                    if re.search(r"\((?:[^()]*; )?required\)", line):
                        current["required"] = True


class Vplab:
    def __init__(self, exe):
        self.exe = exe
        self.cache = {}

    def help(self, path):
        key = tuple(path)
        if key not in self.cache:
            try:
                run = subprocess.run([self.exe, *path, "--help"], capture_output=True, text=True, timeout=60)
                self.cache[key] = Help(run.stdout) if run.returncode == 0 else None
            except (OSError, subprocess.TimeoutExpired):
                self.cache[key] = None
        return self.cache[key]


def value_after(tokens, i):
    """The value written after the option at tokens[i], without a synopsis's brackets, or None."""
    if i + 1 >= len(tokens):
        return None
    v = tokens[i + 1]
    if v.startswith("-") and not re.match(r"^-[\d.]", v):
        return None
    v = v.strip("[]").rstrip("…").rstrip("]")
    return v or None


def check_vplab(words, vplab, where, findings, concrete):
    """words: the command line after `vplab`."""
    tokens = words
    path = []
    i = 0
    help_ = vplab.help(path)
    if help_ is None:
        findings.append("%s: `%s --help` fails" % (where, vplab.exe))
        return
    while i < len(tokens) and tokens[i] in help_.subcommands:
        path.append(tokens[i])
        i += 1
        help_ = vplab.help(path)
        if help_ is None:
            findings.append("%s: `vplab %s --help` fails" % (where, " ".join(path)))
            return
    name = "vplab" + "".join(" " + p for p in path)
    if i < len(tokens) and not path and re.fullmatch(r"[a-z][a-z-]*", tokens[i]) and help_.subcommands:
        findings.append("%s: vplab has no subcommand %r (it has: %s)" % (where, tokens[i], ", ".join(sorted(help_.subcommands))))
        return
    if i < len(tokens) and path and help_.subcommands and re.fullmatch(r"[a-z][a-z-]*", tokens[i]):
        findings.append("%s: %s has no subcommand %r (it has: %s)" % (where, name, tokens[i], ", ".join(sorted(help_.subcommands))))
        return
    used = []
    for j in range(i, len(tokens)):
        for opt in OPTION.findall(tokens[j]):
            if not tokens[j].lstrip("[").startswith(opt):
                continue
            used.append(opt)
            info = help_.options.get(opt)
            if info is None:
                findings.append("%s: %s has no option %s (its --help lists: %s)" % (
                    where, name, opt, " ".join(sorted(o for o in help_.options if o.startswith("--")))))
                continue
            value = value_after(tokens, j) if tokens[j].lstrip("[").rstrip("]") == opt else None
            if value is None:
                continue
            for alt in value.split("|"):
                alt = alt.strip("[]")
                if not alt or "…" in alt or PLACEHOLDER.search(alt):
                    continue
                if info["set"] is not None and alt not in info["set"]:
                    findings.append("%s: %s %s %s: not one of %s" % (where, name, opt, alt, ", ".join(info["set"])))
                if info["range"] is not None:
                    try:
                        x = float(alt)
                    except ValueError:
                        findings.append("%s: %s %s %s: not a number" % (where, name, opt, alt))
                        continue
                    lo, hi = info["range"]
                    if not lo <= x <= hi:
                        findings.append("%s: %s %s %s: out of range [%g, %g]" % (where, name, opt, alt, lo, hi))
    for opt in set(used):
        info = help_.options.get(opt)
        if info is None:
            continue
        for needed in info["needs"]:
            if needed not in used:
                findings.append("%s: %s %s needs %s" % (where, name, opt, needed))
        if concrete:
            for excluded in info["excludes"]:
                if excluded in used:
                    findings.append("%s: %s %s excludes %s" % (where, name, opt, excluded))
    if concrete and not any(t in ("--help", "-h") for t in tokens):
        required = sorted({o for o, info in help_.options.items() if info["required"] and o.startswith("--")})
        for opt in required:
            if opt not in used:
                findings.append("%s: %s needs %s (required)" % (where, name, opt))


def commands(page):
    """(line number, command text, inline?) of every vplab or scripts/ line in the page's fenced code, and of
    every inline code span of the text that is a vplab command (a mention: `vplab exercise` needs no --out)."""
    out = []
    last = None
    for n, (line, code) in enumerate(zip(page.lines, page.in_code), 1):
        if not code:
            out.extend((n, m.group(1).strip(), True) for m in INLINE_VPLAB.finditer(line))
        if not code or FENCE.match(line):
            last = None
            continue
        body = re.split(r"\s#(?:\s|$)", line, maxsplit=1)[0].rstrip()  # a shell comment after the command
        stripped = body.strip()
        if last is not None and line[:1] in (" ", "\t") and (stripped.startswith("[") or stripped.startswith("-")):
            out[last] = (out[last][0], out[last][1] + " " + stripped, False)
            continue
        if last is not None and out[last][1].endswith("\\"):
            out[last] = (out[last][0], out[last][1][:-1] + " " + stripped, False)
            continue
        last = None
        if stripped.startswith("$ "):
            stripped = stripped[2:].lstrip()
        if stripped == "vplab" or stripped.startswith("vplab ") or stripped.startswith("scripts/"):
            out.append((n, stripped, False))
            last = len(out) - 1
    return out


def check_commands(root, page, vplab, findings):
    count = 0
    for n, cmd, inline in commands(page):
        where = "%s:%d" % (os.path.relpath(page.path, root), n)
        words = cmd.split()
        count += 1
        concrete = not inline and "[" not in cmd and "|" not in cmd
        if words[0] == "vplab":
            check_vplab(words[1:], vplab, where, findings, concrete)
        else:
            script = os.path.join(root, words[0])
            if not os.path.isfile(script):
                findings.append("%s: %s: no such script" % (where, words[0]))
            elif not os.access(script, os.X_OK):
                findings.append("%s: %s is not executable" % (where, words[0]))
            elif words[0] == "scripts/run.sh":  # its arguments go to vplab
                check_vplab(words[1:], vplab, where, findings, concrete=False)
    return count


def check(root, vplab):
    files = [os.path.join(root, "README.md")] + sorted(
        os.path.join(root, "docs", f) for f in os.listdir(os.path.join(root, "docs")) if f.endswith(".md"))
    pages = {f: Page(f) for f in files}
    findings = []
    links = 0
    commands_checked = 0
    for f in files:
        check_links(root, pages[f], pages, findings)
        links += len(LINK.findall(pages[f].prose())) + len(IMG_SRC.findall(pages[f].prose()))
        commands_checked += check_commands(root, pages[f], vplab, findings)
    return findings, len(files), links, commands_checked


SAMPLE_README = """# Sample — a title with `code` and “quotes”

See [the page](docs/page.md), [its part](docs/page.md#größe-und-maße), [a lost page](docs/lost.md),
[a lost part](docs/page.md#no-such-part), [here](#sample--a-title-with-code-and-quotes) and
![a lost picture](docs/images/lost.png). `vplab render --theme light` is fine, `vplab render --them dark` not, `vplab exercise` is a mention.

```sh
scripts/run.sh --scene assets/x.json
scripts/lost.sh
vplab render --view camera --style flat --out x.png
vplab render --view nowhere --out x.png
vplab render --no-such-option
vplab nosuchcommand
vplab render --ui-scale 9 --out x.png
vplab render --format svg --out x/
vplab grade numbers --assignment A.json
vplab dump   [--scene FILE] [--strategy npc|wc|diagonal]
vplab render [--scene FILE]
             [--bogus N]
```
"""
SAMPLE_PAGE = """# Größe und Maße

Back to the [README](../README.md#sample--a-title-with-code-and-quotes), or [nowhere](../README.md#nowhere).

## Größe und Maße
"""
EXPECTED = [
    ("README.md:3", "docs/lost.md: no such file"),
    ("README.md:4", "#no-such-part"),
    ("README.md:5", "docs/images/lost.png: no such file"),
    ("README.md:5", "has no option --them"),
    ("README.md:9", "scripts/lost.sh: no such script"),
    ("README.md:11", "nowhere: not one of"),
    ("README.md:12", "has no option --no-such-option"),
    ("README.md:13", "no subcommand 'nosuchcommand'"),
    ("README.md:14", "--ui-scale 9: out of range"),
    ("README.md:15", "--format needs --lesson"),
    ("README.md:16", "needs --student (required)"),
    ("README.md:17", "--strategy diagonal: not one of"),
    ("README.md:18", "has no option --bogus"),
    ("docs/page.md:3", "#nowhere"),
]


def self_test(vplab):
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        os.makedirs(os.path.join(root, "scripts"))
        with open(os.path.join(root, "scripts", "run.sh"), "w") as f:
            f.write("#!/bin/sh\n")
        os.chmod(os.path.join(root, "scripts", "run.sh"), 0o755)
        with open(os.path.join(root, "README.md"), "w", encoding="utf-8") as f:
            f.write(SAMPLE_README)
        with open(os.path.join(root, "docs", "page.md"), "w", encoding="utf-8") as f:
            f.write(SAMPLE_PAGE)
        findings, _, _, _ = check(root, vplab)
    ok = True
    for where, what in EXPECTED:
        if not any(f.startswith(where + ":") and what in f for f in findings):
            print("check_docs.py --self-test: no finding %s: …%s…" % (where, what))
            ok = False
    unexpected = [f for f in findings if not any(f.startswith(w + ":") and x in f for w, x in EXPECTED)]
    for f in unexpected:
        print("check_docs.py --self-test: unexpected finding: %s" % f)
    if not ok or unexpected:
        return 1
    print("check_docs.py --self-test: finds the %d broken links and commands of the sample and nothing else"
          % len(EXPECTED))
    return 0


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", help="the source tree (README.md, docs/)")
    parser.add_argument("--vplab", required=True, help="the built vplab, whose --help the commands are checked against")
    parser.add_argument("--self-test", action="store_true", help="check that the check finds what it should")
    args = parser.parse_args(argv[1:])
    vplab = Vplab(args.vplab)
    if vplab.help([]) is None:
        print("check_docs.py: `%s --help` fails" % args.vplab)
        return 2
    if args.self_test:
        return self_test(vplab)
    if not args.root or not os.path.isfile(os.path.join(args.root, "README.md")):
        parser.error("--root must be the source tree (with README.md)")
    findings, files, links, count = check(os.path.abspath(args.root), vplab)
    for f in findings:
        print(f)
    if findings:
        print("check_docs.py: %d broken links or commands in README.md and docs/" % len(findings))
        return 1
    print("check_docs.py: %d files, %d links and %d commands, all good" % (files, links, count))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
