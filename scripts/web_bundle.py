#!/usr/bin/env python3
"""The web bundle for course pages (docs/course-staff.md "The page on a course page"):
build-web/vplab-web-VERSION.zip.

It holds the page's eight files in a folder vplab-web-VERSION/, each with a gzip copy (.gz) and,
where Debian's `brotli` is installed, a Brotli copy (.br), for servers that send precompressed files,
and README.md, which says what to put where and which headers to set. The archive is the same for the
same files: entries sorted, times fixed, gzip without a name or time.

Usage: web_bundle.py BUILD_WEB_DIR VERSION
"""
import gzip
import io
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

PAGE_FILES = ["index.html", "vplab.js", "vplab.wasm", "vplab.data",
              "loader-worker.js", "vplab-loader.js", "vplab-loader.wasm", "vplab-loader.data"]
FIXED_TIME = (1980, 1, 1, 0, 0, 0)  # the earliest a zip can hold: the archive does not change with the clock


def gzipped(data: bytes) -> bytes:
    out = io.BytesIO()
    with gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=out, mtime=0) as f:
        f.write(data)
    return out.getvalue()


def brotli(path: Path):
    """The Brotli copy by Debian's `brotli` (quality 11), or None where it is not installed."""
    if not shutil.which("brotli"):
        return None
    return subprocess.run(["brotli", "-q", "11", "-c", str(path)], check=True, capture_output=True).stdout


def size(n: int) -> str:
    return f"{n / 1024:.0f} KiB" if n < 1024 * 1024 else f"{n / 1048576:.1f} MiB"


def course_readme(version: str, sizes: dict, with_brotli: bool) -> str:
    plain = sum(s[0] for s in sizes.values())
    gz = sum(s[1] for s in sizes.values())
    rows = "\n".join(
        f"| `{name}` | {size(s[0])} | {size(s[1])} |" + (f" {size(s[2])} |" if with_brotli else "")
        for name, s in sizes.items())
    br_head = " Brotli (`.br`) |" if with_brotli else ""
    br_rule = "---|" if with_brotli else ""
    br_total = f" {size(sum(s[2] for s in sizes.values()))} |" if with_brotli else ""
    br_copies = " and `.br`" if with_brotli else ""
    br_nginx = " and, with its Brotli module, `brotli_static on;`" if with_brotli else ""
    return f"""# vplab {version} for a course page

vplab, the Viewing Pipeline Lab, in the browser: the desktop viewer compiled to WebAssembly, drawing
with WebGL2. Put the files of this folder into one folder of your web server and link to its
`index.html`. Any static hosting serves it; nothing runs on the server.

| file | size | gzip (`.gz`) |{br_head}
|---|---|---|{br_rule}
{rows}
| together | {size(plain)} | {size(gz)} |{br_total}

## Headers

- `vplab.wasm` as `Content-Type: application/wasm` lets the browser compile it while it downloads
  (other types work, more slowly).
- No cross-origin isolation headers are needed (the page uses no threads; a large scene's meshes are
  built in a Web Worker, `loader-worker.js` with `vplab-loader.*`, which needs none), and no cookies are set.
- The `.gz`{br_copies} copies are for servers that send precompressed files: send
  `vplab.wasm.gz` for `vplab.wasm` with `Content-Encoding: gzip` (nginx: `gzip_static on;`{br_nginx};
  Apache: `mod_rewrite` rules for `Accept-Encoding`). Servers that compress on the fly, or do not
  compress, need only the eight plain files.
- `vplab.data`, `vplab-loader.data` (the bundled scenes and meshes) and the `.wasm` files change only with
  a new version: they may be cached for long.

## Linking what you show

The address's fragment is the state shown, so a link reproduces a picture exactly:

- `index.html#scene=perspective` opens a bundled scene (the File menu lists them);
- `index.html#scene=perspective&vrp=0.8,0,0&projection=parallel` changes parts of its camera;
- any state: open the page, set it up, and copy the address (it follows what is shown).

Unsaved changes are kept in the browser (localStorage) per tab and offered back at the next visit.
"""


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    build, version = Path(sys.argv[1]), sys.argv[2]
    folder = f"vplab-web-{version}"
    archive = build / f"{folder}.zip"
    with_brotli = shutil.which("brotli") is not None
    entries, sizes = {}, {}
    for name in PAGE_FILES:
        path = build / name
        if not path.is_file():
            print(f"web_bundle.py: {path} is missing: build the page first (scripts/web.sh)", file=sys.stderr)
            return 1
        data = path.read_bytes()
        entries[name] = (data, zipfile.ZIP_DEFLATED)
        gz = gzipped(data)
        entries[name + ".gz"] = (gz, zipfile.ZIP_STORED)
        br = brotli(path)
        if br is not None:
            entries[name + ".br"] = (br, zipfile.ZIP_STORED)
        sizes[name] = (len(data), len(gz), len(br) if br is not None else 0)
    entries["README.md"] = (course_readme(version, sizes, with_brotli).encode(), zipfile.ZIP_DEFLATED)
    partial = archive.with_suffix(".zip.part")
    with zipfile.ZipFile(partial, "w") as z:
        for name in sorted(entries):
            data, method = entries[name]
            info = zipfile.ZipInfo(f"{folder}/{name}", date_time=FIXED_TIME)
            info.compress_type = method
            info.external_attr = 0o644 << 16
            z.writestr(info, data)
    partial.replace(archive)
    print(f"web_bundle.py: wrote {archive} ({size(archive.stat().st_size)}; the page's files "
          f"{size(sum(s[0] for s in sizes.values()))}, gzipped {size(sum(s[1] for s in sizes.values()))}"
          + (f", Brotli {size(sum(s[2] for s in sizes.values()))}" if with_brotli else "") + ")", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
