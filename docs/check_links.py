"""Checks every link inside a built HTML site: each relative href/src must name a file of the site,
and each #fragment an id (or name) in that file. External links (http, https, mailto) are counted,
not fetched: the build runs offline.

    /usr/bin/python3 docs/check_links.py SITE_DIR

Prints one line per broken link (page: link: why) and exits 1 if there is any, 2 on bad usage."""
import html.parser
import os
import pathlib
import sys
import urllib.parse

EXTERNAL = ("http:", "https:", "mailto:", "ftp:", "data:", "javascript:")


class Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for name in ("id", "name") if tag == "a" else ("id",):
            if a.get(name):
                self.ids.add(a[name])
        for name in ("href", "src"):
            if a.get(name) and not (tag == "link" and a.get("rel") in ("canonical",)):
                self.links.append(a[name])


def parse(path, cache):
    if path not in cache:
        p = Links()
        if path.is_file():  # a FIFO named *.html would block the read: a page is a regular file
            p.feed(path.read_text(encoding="utf-8", errors="replace"))
        cache[path] = p
    return cache[path]


def broken_links(site):
    cache, broken, external = {}, [], 0
    for page in sorted(site.rglob("*.html")):
        for link in parse(page, cache).links:
            if link.startswith(EXTERNAL):
                external += 1
                continue
            url = urllib.parse.urlsplit(link)
            target = page if not url.path else (page.parent / urllib.parse.unquote(url.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            rel = page.relative_to(site)
            if not target.exists():
                broken.append(f"{rel}: {link}: no such file")
            elif url.fragment and target.suffix == ".html" and url.fragment not in parse(target, cache).ids:
                broken.append(f"{rel}: {link}: no anchor #{url.fragment} in {target.name}")
    return broken, external


def main(argv):
    if len(argv) != 2 or not pathlib.Path(argv[1]).is_dir():
        print("usage: check_links.py SITE_DIR (a built HTML site)", file=sys.stderr)
        return 2
    site = pathlib.Path(argv[1]).resolve()
    broken, external = broken_links(site)
    for b in broken:
        print(f"check_links: {b}", file=sys.stderr)
    pages = len(list(site.rglob("*.html")))
    print(f"links: {pages} pages, {len(broken)} broken internal links, {external} external links (not fetched)")
    return 1 if broken else 0


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(lambda: main(sys.argv))
