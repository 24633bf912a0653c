#!/usr/bin/python3
"""Draws the plugin's icons (run by hand; the PNGs are committed): a green
board with drilled holes joined by the route. 24 px for pcbnew's toolbar,
64 px for the Plugin and Content Manager (resources/icon.png).

    /usr/bin/python3 plugins/kicad/make_icons.py
"""
import os

from PIL import Image, ImageDraw

HOLES = [(0.2, 0.75), (0.35, 0.3), (0.62, 0.22), (0.8, 0.5), (0.55, 0.8)]


def icon(size):
    scale = 4  # drawn large, then reduced: smooth edges
    s = size * scale
    img = Image.new("RGBA", (s, s), (0, 0, 0, 0))
    d = ImageDraw.Draw(img)
    d.rounded_rectangle([s * 0.04, s * 0.04, s * 0.96, s * 0.96], radius=s * 0.12, fill=(20, 110, 60, 255))
    pts = [(x * s, y * s) for x, y in HOLES]
    d.line(pts, fill=(255, 170, 0, 255), width=max(2, int(s * 0.06)), joint="curve")
    r = s * 0.085
    for x, y in pts:
        d.ellipse([x - r, y - r, x + r, y + r], fill=(235, 235, 235, 255), outline=(60, 60, 60, 255), width=max(1, int(s * 0.02)))
    return img.resize((size, size), Image.LANCZOS)


here = os.path.dirname(os.path.abspath(__file__))
icon(24).save(os.path.join(here, "acodrill_kicad", "icon.png"))
icon(64).save(os.path.join(here, "resources", "icon.png"))
