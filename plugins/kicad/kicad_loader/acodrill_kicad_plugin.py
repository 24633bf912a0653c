# pcbnew loads this file from its plugin folder; the Debian package installs the
# plugin itself as the Python package acodrill_kicad (so that
# `python3 -m acodrill_kicad` works from anywhere), and importing it registers
# "Drill with acodrill". When pcbnew reloads its plugins the package is already
# imported: register it again.
import sys

_loaded_before = "acodrill_kicad" in sys.modules
import acodrill_kicad  # noqa: E402

if _loaded_before:
    acodrill_kicad.register()
