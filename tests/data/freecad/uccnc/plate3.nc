%prog1
(PathScripts.post.uccnc_post --no-show-editor)
(Exported by FreeCAD for UC-CNC)
(Post Processor: PathScripts.post.uccnc_post, version 0.0.4)
(CAM file: )
(Output Time: 2026-12-06 11:10:53.241269)
(Units: 'mm' and 'mm/min')
(preamble: begin)
G17 (Default: XY-plane)
G54 (Default: First coordinate system)
G40 (Default: Cutter radius compensation none)
G49 (Default: Tool Length Offsets: cancel tool length)
G90 (Default: Absolute distance mode selection)
G80 (Cancel canned cycle)
(preamble: done)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z16.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 3.5mm Drill)
(operation start: TC: 3.5mm Drill)
(TC: 3.5mm Drill)
M6 T1
M3 S1200
(operation done: TC: 3.5mm Drill)
(operation finalised: TC: 3.5mm Drill)
(operation initialise: Drill1)
(operation start: Drill1)
(Drill1)
(Begin Drilling)
G0 Z16.000
G90
G98
G0 X10.000 Y10.000
G0 Z14.000
G81 Z0.000 R14.000 F6000.000
G0 Y30.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 X30.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 Y10.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 X50.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 Y30.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 X70.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 Y10.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 X90.000
G0 Z14.000
G81 Z0.000 F6000.000
G0 Y30.000
G0 Z14.000
G81 Z0.000 F6000.000
G80
G0 Z14.000
G0 Z16.000
(operation done: Drill1)
(operation finalised: Drill1)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z16.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 6.6mm Drill)
(operation start: TC: 6.6mm Drill)
(TC: 6.6mm Drill)
M6 T2
M3 S1400
(operation done: TC: 6.6mm Drill)
(operation finalised: TC: 6.6mm Drill)
(operation initialise: Drill2)
(operation start: Drill2)
(Drill2)
(Begin Drilling)
G0 Z16.000
G90
G98
G0 X15.000 Y45.000
G0 Z14.000
G82 Z0.000 R14.000 F6000.000
G0 Y67.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 X37.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 Y45.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 X59.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 Y67.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 X81.000
G0 Z14.000
G82 Z0.000 F6000.000
G0 Y45.000
G0 Z14.000
G82 Z0.000 F6000.000
G80
G0 Z14.000
G0 Z16.000
(operation done: Drill2)
(operation finalised: Drill2)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z16.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 10mm Drill)
(operation start: TC: 10mm Drill)
(TC: 10mm Drill)
M6 T3
M3 S1600
(operation done: TC: 10mm Drill)
(operation finalised: TC: 10mm Drill)
(operation initialise: Drill3)
(operation start: Drill3)
(Drill3)
(Begin Drilling)
G0 Z16.000
G90
G98
G0 X100.000 Y40.000
G0 Z14.000
G83 Z0.000 R14.000 F6000.000 Q7.500
G80
G0 Z14.000
G0 Z16.000
(operation done: Drill3)
(operation finalised: Drill3)
(postamble: begin)
M05 (stop spindle)
G17 (Default: XY-plane)
G54 (Default: First coordinate system)
G40 (Default: Cutter radius compensation none)
G90 (Default: Absolute distance mode selection)
G80 (Cancel canned cycle)
M30 (Stop program and rewind code)
(postamble: done)
