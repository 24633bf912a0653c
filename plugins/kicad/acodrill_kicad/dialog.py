"""The dialog of "Drill with acodrill". It only shows choices and results:
what Plan does is job.plan_for_dialog, tested without a window."""
import os

import wx

from . import job
from .board import board_drills, drill_origin


class DrillDialog(wx.Dialog):
    def __init__(self, parent, board, board_path, acodrill="acodrill"):
        super().__init__(parent, title="Drill with acodrill", style=wx.DEFAULT_DIALOG_STYLE | wx.RESIZE_BORDER)
        self.board, self.board_path, self.acodrill = board, board_path, acodrill
        self.outcome = None
        try:
            self.classes = job.machine_classes(acodrill)
        except job.PlanError as e:
            self.classes = []
            wx.MessageBox(e.line, "Drill with acodrill", wx.OK | wx.ICON_ERROR, self)
        names = [n for n, _ in self.classes]

        grid = wx.FlexGridSizer(cols=2, vgap=6, hgap=8)
        grid.AddGrowableCol(1)

        def row(label, control):
            grid.Add(wx.StaticText(self, label=label), 0, wx.ALIGN_CENTER_VERTICAL)
            grid.Add(control, 1, wx.EXPAND)
            return control

        self.machine = row("Machine", wx.Choice(self, choices=[f"{n} - {d}" for n, d in self.classes] + ["Machine file..."]))
        self.machine.SetSelection(names.index("router") if "router" in names else 0)
        self.machine_file = row("Machine file", wx.FilePickerCtrl(self, wildcard="Machine profile (*.json)|*.json"))
        self.dialect = row("Dialect", wx.Choice(self, choices=["the machine's"] + job.DIALECTS))
        self.dialect.SetSelection(0)
        self.origin = row("Program zero", wx.Choice(self, choices=[label for _, label in job.ORIGINS]))
        self.origin.SetSelection(0)
        self.apart = row("Plated / non-plated", wx.RadioBox(self, choices=["together (a drill per diameter)",
                                                                            "apart (plated first)"]))
        self.budget = row("Time budget (s)", wx.SpinCtrlDouble(self, min=0.5, max=3600, initial=10, inc=1))
        # The tools on the bench: empty or 0 leaves them to acodrill (one drill per diameter) and the machine file.
        self.drills = row("Drills you own (mm)", wx.TextCtrl(self, value=""))
        self.drills.SetHint("e.g. 0.6,0.8,1.0,1.2 (empty: a drill per diameter)")
        self.end_mill = row("End mill (mm, 0: none)", wx.SpinCtrlDouble(self, min=0, max=10, initial=0, inc=0.1))
        self.end_mill.SetDigits(2)
        self.from_back = row("", wx.CheckBox(self, label="Drill from the back (holes mirrored)"))
        self.probe_plate = row("Touch plate (mm, 0: none)", wx.SpinCtrlDouble(self, min=0, max=20, initial=0, inc=0.1))
        self.probe_plate.SetDigits(2)
        program = job.default_program(board_path, "grbl")
        self.program = row("Program", wx.FilePickerCtrl(self, path=program, style=wx.FLP_SAVE | wx.FLP_USE_TEXTCTRL))
        self.write_sheet = row("", wx.CheckBox(self, label="Write the setup sheet beside the program"))
        self.write_sheet.SetValue(True)
        self.result = wx.TextCtrl(self, style=wx.TE_MULTILINE | wx.TE_READONLY, size=(620, 130))

        buttons = wx.BoxSizer(wx.HORIZONTAL)
        self.plan_button = wx.Button(self, wx.ID_OK, "Plan")
        self.sheet_button = wx.Button(self, label="Open setup sheet")
        self.sheet_button.Disable()
        buttons.Add(self.plan_button)
        buttons.Add(self.sheet_button, 0, wx.LEFT, 8)
        buttons.AddStretchSpacer()
        buttons.Add(wx.Button(self, wx.ID_CANCEL, "Close"))

        top = wx.BoxSizer(wx.VERTICAL)
        top.Add(wx.StaticText(self, label=f"Board: {board_path}"), 0, wx.ALL, 8)
        top.Add(grid, 0, wx.EXPAND | wx.LEFT | wx.RIGHT, 8)
        top.Add(self.result, 1, wx.EXPAND | wx.ALL, 8)
        top.Add(buttons, 0, wx.EXPAND | wx.ALL, 8)
        self.SetSizerAndFit(top)

        self.plan_button.Bind(wx.EVT_BUTTON, self.on_plan)
        self.sheet_button.Bind(wx.EVT_BUTTON, lambda _: wx.LaunchDefaultBrowser(job.file_url(self.outcome.setup_sheet)))
        self.machine.Bind(wx.EVT_CHOICE, self.on_machine)
        self.dialect.Bind(wx.EVT_CHOICE, self.on_machine)
        self.on_machine(None)

    def choices(self):
        k = self.machine.GetSelection()
        machine = self.classes[k][0] if k < len(self.classes) else self.machine_file.GetPath()
        d = self.dialect.GetSelection()
        return job.Choices(machine=machine, dialect="" if d <= 0 else job.DIALECTS[d - 1],
                           origin=job.ORIGINS[self.origin.GetSelection()][0],
                           plated_apart=self.apart.GetSelection() == 1, time_limit_s=self.budget.GetValue(),
                           program=self.program.GetPath(), write_setup_sheet=self.write_sheet.GetValue(),
                           drills=self.drills.GetValue(), end_mill_mm=self.end_mill.GetValue(),
                           from_back=self.from_back.GetValue(), probe_plate_mm=self.probe_plate.GetValue())

    def on_machine(self, _event):
        c = self.choices()
        self.machine_file.Enable(self.machine.GetSelection() >= len(self.classes))
        # The program's extension follows the dialect while the user has not named a file of their own.
        dialect = c.dialect or job.machine_dialect(c.machine, self.acodrill)
        current = self.program.GetPath()
        stem = os.path.splitext(self.board_path)[0] + "-drill"
        if not current or os.path.splitext(current)[0] == stem:
            self.program.SetPath(job.default_program(self.board_path, dialect))

    def on_plan(self, _event):
        with wx.BusyInfo("acodrill is planning the drilling..."):
            drills, warnings = board_drills(self.board)
            self.outcome = job.plan_for_dialog(drills, warnings, drill_origin(self.board), self.board_path,
                                               self.choices(), self.acodrill)
        self.result.SetForegroundColour(wx.BLACK if self.outcome.ok else wx.RED)
        self.result.SetValue(self.outcome.text)
        self.sheet_button.Enable(bool(self.outcome.ok and self.outcome.setup_sheet))
