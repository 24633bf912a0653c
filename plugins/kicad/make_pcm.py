#!/usr/bin/python3
"""Builds the Plugin and Content Manager package of the KiCad plugin:

    make_pcm.py OUT.zip [--platform windows --binary acodrill.exe]

The archive holds metadata.json (this folder's, as KiCad's pcm.v1 schema
wants it), plugins/ (the acodrill_kicad package's files: KiCad installs them
as a plugin folder of their own) and resources/icon.png. Its bytes depend only
on those files (fixed timestamps, sorted names), so a rebuild is identical.
Install it in KiCad: Plugin and Content Manager > Install from File.

With --platform windows and --binary, the package is for Windows and carries
acodrill.exe in plugins/, where the plugin finds it beside itself.
"""
import argparse
import json
import os
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))


def metadata(platform, binary):
    """This folder's metadata.json, for another platform: its platforms, and a description that says what it carries."""
    with open(os.path.join(HERE, "metadata.json"), encoding="utf-8") as f:
        data = json.load(f)
    if platform != "linux":
        for v in data["versions"]:
            v["platforms"] = [platform]
        data["description_full"] = data["description_full"].replace(
            "Needs acodrill itself installed (the plugin only calls it): build it from source and install its Debian package.",
            "Carries acodrill" + (".exe" if binary.endswith(".exe") else "") + " itself, beside the plugin: nothing else to install.")
    return (json.dumps(data, indent=2, ensure_ascii=False) + "\n").encode("utf-8")


def members(binary=None):
    yield "metadata.json", None
    package = os.path.join(HERE, "acodrill_kicad")
    for name in sorted(os.listdir(package)):
        path = os.path.join(package, name)
        if os.path.isfile(path) and (name.endswith(".py") or name.endswith(".png")):
            yield "plugins/" + name, path
    if binary:
        yield "plugins/" + os.path.basename(binary), binary
    yield "resources/icon.png", os.path.join(HERE, "resources", "icon.png")


def main(out, platform="linux", binary=None):
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for arcname, path in members(binary):
            info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (0o755 if path == binary else 0o644) << 16
            if path is None:
                z.writestr(info, metadata(platform, binary or ""))
                continue
            with open(path, "rb") as f:
                z.writestr(info, f.read())
    os.replace(tmp, out)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Builds the KiCad PCM package of the acodrill plugin.")
    parser.add_argument("out")
    parser.add_argument("--platform", default="linux", choices=["linux", "windows", "macos"])
    parser.add_argument("--binary", help="acodrill's program to carry beside the plugin")
    args = parser.parse_args()
    if args.platform != "linux" and not args.binary:
        parser.error("--platform windows carries acodrill: give --binary")
    main(args.out, args.platform, args.binary)
