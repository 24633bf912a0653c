"""The pcbnew action: Tools > External Plugins > "Drill with acodrill"."""
import os

import pcbnew


class DrillWithAcodrill(pcbnew.ActionPlugin):
    def defaults(self):
        self.name = "Drill with acodrill"
        self.category = "Fabrication"
        self.description = ("Orders the board's drill holes for the shortest spindle travel and writes the "
                            "drilling program (HAAS, Fanuc, LinuxCNC, GRBL, Marlin) and its setup sheet")
        self.show_toolbar_button = True
        self.icon_file_name = os.path.join(os.path.dirname(__file__), "icon.png")

    def Run(self):
        import wx

        from .dialog import DrillDialog

        board = pcbnew.GetBoard()
        parent = wx.FindWindowByName("PcbFrame")
        if not board.GetFileName():
            wx.MessageBox("Save the board first: the program and its setup sheet are written beside it.",
                          "Drill with acodrill", wx.OK | wx.ICON_INFORMATION, parent)
            return
        dialog = DrillDialog(parent, board, board.GetFileName())
        try:
            dialog.ShowModal()
        finally:
            dialog.Destroy()
