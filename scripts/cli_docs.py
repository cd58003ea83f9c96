#!/usr/bin/env python3
"""The manual page vplab(1) and bash's completion for vplab, made from the command line's own help.

Runs `vplab --version`, `vplab --help` and `--help` of every subcommand (and theirs, as `grade numbers`),
so the manual and the completion say what the built program takes, never a copy kept by hand.
CMake runs it at build time (app/CMakeLists.txt) and installs both.

Usage: cli_docs.py VPLAB_EXECUTABLE --man OUT.1[.gz] --bash OUT
A name ending in .gz is written gzip-compressed with no time stamp (the same bytes every build), as
Debian's policy wants manual pages.
"""
import argparse
import datetime
import gzip
import os
import re
import subprocess
import sys

SECTION = re.compile(r"^(Positionals|Options|Subcommands):$")
ENTRY = re.compile(r"^  (\S.*?)(?:\s{2,}(\S.*))?$")  # "  name   description", or the name alone


def run(exe, args):
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0")  # a sanitizer build's leak check is for the tests
    done = subprocess.run([exe, *args], capture_output=True, text=True, env=env, timeout=60)
    if done.returncode != 0:
        sys.exit(f"cli_docs.py: {exe} {' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout


def parse_help(text):
    """The help's description lines and its sections: {section: [(name, description)]}."""
    description, sections, current = [], {}, None
    for line in text.splitlines():
        if SECTION.match(line):
            current = SECTION.match(line).group(1)
            sections[current] = []
        elif current is None:
            if line and not line.startswith("Usage:"):
                description.append(line)
        elif line.startswith("  ") and not line.startswith("   "):
            m = ENTRY.match(line)
            sections[current].append([m.group(1).strip(), (m.group(2) or "").strip()])
        elif line.strip() and sections[current]:  # a description on the next line, or its continuation
            entry = sections[current][-1]
            entry[1] = (entry[1] + " " + line.strip()).strip()
    return description, sections


def commands(exe, path=()):
    """Every (sub)command as (path, help text), depth first."""
    text = run(exe, [*path, "--help"])
    found = [(path, text)]
    for name, _ in parse_help(text)[1].get("Subcommands", []):
        found += commands(exe, (*path, name))
    return found


def option_names(entry_name):
    """'-h,--help' -> ['-h', '--help']; '--scene TEXT:FILE Excludes: file' -> ['--scene']."""
    first = entry_name.split()[0]
    return [n for n in first.split(",") if n.startswith("-")]


def roff(text):
    return text.replace("\\", "\\e").replace("-", "\\-").replace("'", "\\(aq")


def man_page(exe, found):
    version = run(exe, ["--version"]).strip()
    date = datetime.datetime.utcfromtimestamp(int(os.environ.get("SOURCE_DATE_EPOCH", "0") or 0)).strftime("%Y-%m-%d")
    lines = [f'.TH VPLAB 1 "{date}" "{roff(version)}" "User Commands"', ".SH NAME",
             "vplab \\- Viewing Pipeline Lab: the 3D viewing pipeline, step by step",
             ".SH SYNOPSIS", ".B vplab", "[\\fIOPTIONS\\fR] [\\fIFILE\\fR]"]
    for path, _ in found[1:]:
        lines += [".br", f".B vplab {roff(' '.join(path))}", "[\\fIOPTIONS\\fR]"]
    for path, text in found:
        description, sections = parse_help(text)
        title = "DESCRIPTION" if not path else f"vplab {' '.join(path)}".upper()
        lines += [".SH " + roff(title)]
        lines += [roff(" ".join(d.strip() for d in description if d.strip()))]
        for section in ("Positionals", "Options"):
            for name, what in sections.get(section, []):
                lines += [".TP", f".B {roff(name)}", roff(what)]
        if sections.get("Subcommands"):
            lines += [".PP", "Subcommands:"]
            for name, what in sections["Subcommands"]:
                lines += [".TP", f".B {roff(name)}", roff(what)]
    lines += [".SH FILES", ".TP", ".I /usr/share/vplab/scenes",
              "The bundled scenes (\\fBvplab presets\\fR lists them) and, in \\fI/usr/share/vplab/meshes\\fR, their meshes.",
              ".TP", ".I /usr/share/vplab/lessons",
              "The bundled lessons in German and English (\\fBvplab lessons\\fR lists them; \\fBvplab --lesson\\fR \\fINAME\\fR presents one).",
              ".TP", ".I $XDG_STATE_HOME/vplab", "Autosaved unsaved changes, offered back after a crash.",
              ".SH EXIT STATUS", "0 on success, 1 on an error (named on standard error), 2 on a usage error.",
              ".SH SEE ALSO", "The README, the pages of docs/ and CHANGELOG.md of vplab's sources."]
    return "\n".join(lines) + "\n"


def completion(found):
    cases = []
    for path, text in found:
        _, sections = parse_help(text)
        words = [n for e, _ in sections.get("Options", []) for n in option_names(e)]
        words += [name for name, _ in sections.get("Subcommands", [])]
        cases.append(f'    "{" ".join(path)}") words="{" ".join(words)}" ;;')
    return f"""# bash completion for vplab, made from its --help by scripts/cli_docs.py
_vplab() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} prev=${{COMP_WORDS[COMP_CWORD-1]}} path="" w i words
  # The subcommands typed so far (words that are neither options nor their values).
  for ((i = 1; i < COMP_CWORD; i++)); do
    w=${{COMP_WORDS[i]}}
    case "$w" in -*) ;; *) [[ " $(_vplab_words "$path") " == *" $w "* ]] && path="${{path:+$path }}$w" ;; esac
  done
  case "$prev" in
    --scene|--out|--student|--assignment|--answers|--junit) COMPREPLY=($(compgen -f -- "$cur")); return ;;
  esac
  words=$(_vplab_words "$path")
  if [[ "$cur" == -* || -z "$path" ]]; then COMPREPLY=($(compgen -W "$words" -- "$cur")); fi
  [[ -z "$path" && "$cur" != -* ]] && COMPREPLY+=($(compgen -f -X '!*.json' -- "$cur"))
  return 0
}}
_vplab_words() {{
  local words=""
  case "$1" in
{chr(10).join(cases)}
  esac
  echo "$words"
}}
complete -o filenames -F _vplab vplab
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("exe")
    parser.add_argument("--man", required=True)
    parser.add_argument("--bash", required=True)
    args = parser.parse_args()
    found = commands(args.exe)
    for out, text in ((args.man, man_page(args.exe, found)), (args.bash, completion(found))):
        data = text.encode("utf-8")
        if out.endswith(".gz"):
            data = gzip.compress(data, compresslevel=9, mtime=0)
        with open(out + ".part", "wb") as f:
            f.write(data)
        os.replace(out + ".part", out)


if __name__ == "__main__":
    main()
