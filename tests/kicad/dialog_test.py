#!/usr/bin/python3
"""Issue 47: the plugin's dialog, as a user drives it, in a real window under
Xvfb (no screen needed): choices made, Plan pressed, the summary and the
setup sheet button; a failure shown in red with acodrill's own line.

    xvfb-run -a /usr/bin/python3 tests/kicad/dialog_test.py
With SCREENSHOT_DIR set it also saves the dialog before and after Plan (the README's pictures).
"""
import glob
import os
import shutil
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "plugins", "kicad"))
ACODRILL = os.environ.get("ACODRILL", os.path.join(ROOT, "build", "bin", "acodrill"))

try:
    import pcbnew
    import wx
except ImportError:
    pcbnew = wx = None
if os.environ.get("ACO_REQUIRE_KICAD") and (pcbnew is None or not os.environ.get("DISPLAY")):
    sys.exit("KiCad's pcbnew (apt install kicad kicad-demos) or a display (xvfb-run) is missing; scripts/test installs them")
# Issue 69: the same tests on KiCad 9 (ctest's kicad9.*): fail on any other pcbnew rather than test it.
if os.environ.get("ACO_REQUIRE_KICAD_MAJOR") and (pcbnew is None or
                                                   pcbnew.GetBuildVersion().split(".")[0] != os.environ["ACO_REQUIRE_KICAD_MAJOR"]):
    sys.exit(f"KiCad {os.environ['ACO_REQUIRE_KICAD_MAJOR']}'s pcbnew is not the one loaded "
             f"({pcbnew.GetBuildVersion() if pcbnew else 'none'}); scripts/test unpacks it into build-deps/kicad9")


def screenshot(window, path):
    """The window as it is on the (virtual) screen, as a PNG. GTK paints only
    from its event loop: one runs until the picture is taken."""
    loop = wx.GUIEventLoop()

    def shoot():
        # From the X server's root window: wx.ScreenDC under GTK 3 keeps showing the first frame.
        import gi

        gi.require_version("Gdk", "3.0")
        from gi.repository import Gdk

        rect = window.GetScreenRect()
        pixels = Gdk.pixbuf_get_from_window(Gdk.get_default_root_window(), rect.x, rect.y, rect.width, rect.height)
        pixels.savev(path, "png", [], [])
        loop.Exit()

    window.Refresh()
    wx.CallLater(500, shoot)
    loop.Run()


@unittest.skipIf(pcbnew is None or not os.environ.get("DISPLAY"), "needs KiCad's pcbnew, wxPython and a display (xvfb-run)")
class Dialog(unittest.TestCase):
    def test_plan_from_the_dialog(self):
        from acodrill_kicad.dialog import DrillDialog

        app = wx.App()
        found = glob.glob("/usr/share/kicad/demos/**/video.kicad_pcb", recursive=True)
        if not found:
            self.skipTest("kicad-demos not installed")
        shots = os.environ.get("SCREENSHOT_DIR")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "video.kicad_pcb")
            shutil.copy(found[0], path)
            board = pcbnew.LoadBoard(path)
            dialog = DrillDialog(None, board, path, acodrill=ACODRILL)
            dialog.Show()
            # The machine classes are acodrill's; the router is chosen, and its GRBL names the program.
            labels = [dialog.machine.GetString(k) for k in range(dialog.machine.GetCount())]
            self.assertTrue(any(l.startswith("router - ") for l in labels), labels)
            self.assertTrue(labels[dialog.machine.GetSelection()].startswith("router"))
            self.assertEqual(dialog.program.GetPath(), os.path.join(d, "video-drill.gcode"))
            dialog.budget.SetValue(2)
            if shots:
                screenshot(dialog, os.path.join(shots, "kicad-dialog.png"))
            dialog.on_plan(None)
            text = dialog.result.GetValue()
            self.assertIn("1720 holes, 11 tools", text)
            self.assertIn("Setup sheet: " + os.path.join(d, "video-drill-setup.html"), text)
            self.assertTrue(dialog.sheet_button.IsEnabled())
            self.assertTrue(os.path.exists(os.path.join(d, "video-drill.gcode")))
            if shots:
                screenshot(dialog, os.path.join(shots, "kicad-dialog-planned.png"))
            # Issue 53: the drills owned, an end mill, the back of the board and a touch plate.
            def bench(drills, end_mill, from_back, probe_plate):
                dialog.drills.SetValue(drills)
                dialog.end_mill.SetValue(end_mill)
                dialog.from_back.SetValue(from_back)
                dialog.probe_plate.SetValue(probe_plate)

            bench("0.4, 0.6,0.8,1.0", 1.0, True, 0.5)
            dialog.on_plan(None)
            text = dialog.result.GetValue()
            self.assertEqual(dialog.result.GetForegroundColour(), wx.BLACK, text)
            self.assertIn("milled with the 1.000 mm end mill", text)
            self.assertIn("0.400 mm drill", text)
            with open(os.path.join(d, "video-drill.gcode")) as f:
                program = f.read()
            self.assertIn("G38.2", program)
            self.assertIn("SIDE: BACK", program)
            self.assertIn("\nG2 ", program)
            if shots:
                screenshot(dialog, os.path.join(shots, "kicad-dialog-owned-tools.png"))
            bench("", 0, False, 0)
            # Another dialect renames the program while the user has not chosen a file.
            dialog.dialect.SetSelection(1 + ["haas", "fanuc", "linuxcnc", "grbl", "marlin"].index("linuxcnc"))
            dialog.on_machine(None)
            self.assertEqual(dialog.program.GetPath(), os.path.join(d, "video-drill.ngc"))
            # A machine file that is not there: acodrill's line, in red, and no sheet to open.
            dialog.machine.SetSelection(dialog.machine.GetCount() - 1)
            dialog.machine_file.SetPath(os.path.join(d, "nowhere.json"))
            dialog.on_machine(None)
            self.assertTrue(dialog.machine_file.IsEnabled())
            dialog.on_plan(None)
            self.assertTrue(dialog.result.GetValue().startswith("acodrill: error: "), dialog.result.GetValue())
            self.assertIn("nowhere.json", dialog.result.GetValue())
            self.assertEqual(dialog.result.GetForegroundColour(), wx.RED)
            self.assertFalse(dialog.sheet_button.IsEnabled())
            dialog.Destroy()
        app.Destroy()


if __name__ == "__main__":
    unittest.main(verbosity=2)
