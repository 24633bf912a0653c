%prog1
(PathScripts.post.uccnc_post --no-show-editor)
(Exported by FreeCAD for UC-CNC)
(Post Processor: PathScripts.post.uccnc_post, version 0.0.4)
(CAM file: )
(Output Time: 2026-12-06 11:10:53.876794)
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
G0 Z26.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 5mm Drill)
(operation start: TC: 5mm Drill)
(TC: 5mm Drill)
M6 T1
M3 S1200
(operation done: TC: 5mm Drill)
(operation finalised: TC: 5mm Drill)
(operation initialise: Drill1)
(operation start: Drill1)
(Drill1)
(Begin Drilling)
G0 Z26.000
G90
G98
G0 X10.000 Y15.000
G0 Z24.000
G81 Z0.000 R24.000 F6000.000
G0 Y30.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 X25.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 Y15.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 X40.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 Y30.000
G0 Z24.000
G81 Z0.000 F6000.000
G80
G0 Z24.000
G0 Z26.000
(operation done: Drill1)
(operation finalised: Drill1)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z26.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 5mm Drill)
(operation start: TC: 5mm Drill)
(TC: 5mm Drill)
M6 T1
M3 S1200
(operation done: TC: 5mm Drill)
(operation finalised: TC: 5mm Drill)
(operation initialise: Drill1001)
(operation start: Drill1001)
(Drill1001)
(Begin Drilling)
G0 Z26.000
G90
G98
G0 X60.000 Y15.000
G0 Z24.000
G81 Z0.000 R24.000 F6000.000
G0 Y30.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 X75.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 Y15.000
G0 Z24.000
G81 Z0.000 F6000.000
G0 X90.000
G0 Z24.000
G81 Z0.000 F6000.000
G80
G0 Z24.000
G0 Z26.000
(operation done: Drill1001)
(operation finalised: Drill1001)
(postamble: begin)
M05 (stop spindle)
G17 (Default: XY-plane)
G54 (Default: First coordinate system)
G40 (Default: Cutter radius compensation none)
G90 (Default: Absolute distance mode selection)
G80 (Cancel canned cycle)
M30 (Stop program and rewind code)
(postamble: done)
