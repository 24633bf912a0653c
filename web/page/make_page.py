#!/usr/bin/env python3
"""Writes the page (issue 65): page.html with its CSS, the chart library
(uPlot, from npm), the worker (the Emscripten module, WebAssembly inside,
then worker.js) and the sample plate inlined, so that one file works opened
from disk with nothing fetched. Refuses a page over 3 MB."""
import argparse
import json
import os
import sys

LIMIT = 3 * 1024 * 1024


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--module", required=True, help="acodrill_web.js (Emscripten, SINGLE_FILE)")
    ap.add_argument("--node-modules", required=True)
    ap.add_argument("--sample", required=True, help="the sample plate (DXF)")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    uplot = os.path.join(a.node_modules, "uplot", "dist")
    worker = read(a.module) + "\n" + read(os.path.join(here, "worker.js"))
    page_js = read(os.path.join(here, "page.js"))
    uplot_js = read(os.path.join(uplot, "uPlot.iife.min.js"))
    # Inline scripts end at the first "</script": none may hold one.
    for name, text in (("worker", worker), ("page.js", page_js), ("uPlot", uplot_js)):
        if "</script" in text.lower():
            sys.exit(f"make_page.py: {name} holds '</script' and cannot be inlined")
    sample = json.dumps(read(a.sample)).replace("</", "<\\/")
    html = read(os.path.join(here, "page.html"))
    for key, value in (("/*@UPLOT_CSS@*/", read(os.path.join(uplot, "uPlot.min.css"))),
                       ("/*@PAGE_CSS@*/", read(os.path.join(here, "page.css"))),
                       ("/*@SAMPLE@*/", sample), ("/*@WORKER@*/", worker),
                       ("/*@UPLOT_JS@*/", uplot_js), ("/*@PAGE_JS@*/", page_js)):
        if key not in html:
            sys.exit(f"make_page.py: {key} missing from page.html")
        html = html.replace(key, value, 1)
    size = len(html.encode("utf-8"))
    if size > LIMIT:
        sys.exit(f"make_page.py: the page is {size} bytes, over the 3 MB it may be")
    tmp = a.out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(html)
    os.replace(tmp, a.out)
    print(f"acodrill: the page: {os.path.relpath(a.out)} ({size / 1e6:.2f} MB)")


if __name__ == "__main__":
    main()
