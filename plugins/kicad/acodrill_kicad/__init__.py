"""acodrill's KiCad action plugin: Tools > External Plugins > "Drill with acodrill".

pcbnew imports this package when it loads its plugins (pcbnew itself is then
imported already) and the action registers; `python3 -m acodrill_kicad` and the
tests import it without pcbnew, and nothing registers.
"""
import sys


def register():
    """Registers the action with pcbnew (again, when pcbnew reloads its plugins)."""
    from .action import DrillWithAcodrill

    DrillWithAcodrill().register()


if "pcbnew" in sys.modules:
    register()
