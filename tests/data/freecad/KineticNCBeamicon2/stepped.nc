(Exported by FreeCAD)
(Post Processor: PathScripts.post.KineticNCBeamicon2_post)
(Output Time:2026-12-06 11:10:53.845233)
(begin preamble)
% 
G17 G21 G40 G49 G80 G90 
M08
G21
(begin operation: G54)
(machine: not set, mm/min)
G54
G0 Z26.000
(finish operation: G54)
(begin operation: TC: 5mm Drill)
(machine: not set, mm/min)
(TC: 5mm Drill)
M05 
M09M6 T1
M3 S1200
(finish operation: TC: 5mm Drill)
(begin operation: Drill1)
(machine: not set, mm/min)
(Drill1)
(Begin Drilling)
G0 Z26.000
G90
G98
G0 X10.000 Y15.000
G0 Z24.000
G81 X10.000 Y15.000 Z0.000 F6000.000 R24.000
G0 X10.000 Y30.000
G0 Z24.000
G81 X10.000 Y30.000 Z0.000 F6000.000 R24.000
G0 X25.000 Y30.000
G0 Z24.000
G81 X25.000 Y30.000 Z0.000 F6000.000 R24.000
G0 X25.000 Y15.000
G0 Z24.000
G81 X25.000 Y15.000 Z0.000 F6000.000 R24.000
G0 X40.000 Y15.000
G0 Z24.000
G81 X40.000 Y15.000 Z0.000 F6000.000 R24.000
G0 X40.000 Y30.000
G0 Z24.000
G81 X40.000 Y30.000 Z0.000 F6000.000 R24.000
G80
G0 Z24.000
G0 Z26.000
(finish operation: Drill1)
(begin operation: G54)
(machine: not set, mm/min)
G54
G0 Z26.000
(finish operation: G54)
(begin operation: TC: 5mm Drill)
(machine: not set, mm/min)
(TC: 5mm Drill)
M05 
M09M6 T1
M3 S1200
(finish operation: TC: 5mm Drill)
(begin operation: Drill1001)
(machine: not set, mm/min)
(Drill1001)
(Begin Drilling)
G0 Z26.000
G90
G98
G0 X60.000 Y15.000
G0 Z24.000
G81 X60.000 Y15.000 Z0.000 F6000.000 R24.000
G0 X60.000 Y30.000
G0 Z24.000
G81 X60.000 Y30.000 Z0.000 F6000.000 R24.000
G0 X75.000 Y30.000
G0 Z24.000
G81 X75.000 Y30.000 Z0.000 F6000.000 R24.000
G0 X75.000 Y15.000
G0 Z24.000
G81 X75.000 Y15.000 Z0.000 F6000.000 R24.000
G0 X90.000 Y15.000
G0 Z24.000
G81 X90.000 Y15.000 Z0.000 F6000.000 R24.000
G80
G0 Z24.000
G0 Z26.000
(finish operation: Drill1001)
(begin postamble)
M05 M09
G17 G90 G80 G40
M30
