#!/usr/bin/python3
"""Builds the Plugin and Content Manager package of the KiCad plugin:

    make_pcm.py OUT.zip

The archive holds metadata.json (this folder's, as KiCad's pcm.v1 schema
wants it), plugins/ (the acodrill_kicad package's files: KiCad installs them
as a plugin folder of their own) and resources/icon.png. Its bytes depend only
on those files (fixed timestamps, sorted names), so a rebuild is identical.
Install it in KiCad: Plugin and Content Manager > Install from File.
"""
import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))


def members():
    yield "metadata.json", os.path.join(HERE, "metadata.json")
    package = os.path.join(HERE, "acodrill_kicad")
    for name in sorted(os.listdir(package)):
        path = os.path.join(package, name)
        if os.path.isfile(path) and (name.endswith(".py") or name.endswith(".png")):
            yield "plugins/" + name, path
    yield "resources/icon.png", os.path.join(HERE, "resources", "icon.png")


def main(out):
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for arcname, path in members():
            info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            with open(path, "rb") as f:
                z.writestr(info, f.read())
    os.replace(tmp, out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_pcm.py OUT.zip")
    main(sys.argv[1])
