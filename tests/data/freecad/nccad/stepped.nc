;Exported by FreeCAD
;Post Processor: PathScripts.post.nccad_post
;CAM file: 
;Output Time: 2026-12-06 11:10:53.860727
G54
G0 Z26.0
(TC: 5mm Drill)
G77      ; Move to release position
M10 O6.0 ; Stop spindle
M01 Insert tool 1
G76      ; Move to reference point to ensure correct coordinates after tool change
M10 O6.1 ; Start spindle
M01 Set spindle speed to 1200 rounds per minute
(Drill1)
(Begin Drilling)
G0 F0.0 Z26.0
G90
G98
G0 F0.0 X10.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X10.0 Y15.0 Z0.0
G0 F0.0 X10.0 Y30.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X10.0 Y30.0 Z0.0
G0 F0.0 X25.0 Y30.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X25.0 Y30.0 Z0.0
G0 F0.0 X25.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X25.0 Y15.0 Z0.0
G0 F0.0 X40.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X40.0 Y15.0 Z0.0
G0 F0.0 X40.0 Y30.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X40.0 Y30.0 Z0.0
G80
G0 F0.0 Z24.0
G0 Z26.0
G54
G0 Z26.0
(TC: 5mm Drill)
G77      ; Move to release position
M10 O6.0 ; Stop spindle
M01 Insert tool 1
G76      ; Move to reference point to ensure correct coordinates after tool change
M10 O6.1 ; Start spindle
M01 Set spindle speed to 1200 rounds per minute
(Drill1001)
(Begin Drilling)
G0 F0.0 Z26.0
G90
G98
G0 F0.0 X60.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X60.0 Y15.0 Z0.0
G0 F0.0 X60.0 Y30.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X60.0 Y30.0 Z0.0
G0 F0.0 X75.0 Y30.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X75.0 Y30.0 Z0.0
G0 F0.0 X75.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X75.0 Y15.0 Z0.0
G0 F0.0 X90.0 Y15.0
G0 F0.0 Z24.0
G81 F1000.0 R24.0 X90.0 Y15.0 Z0.0
G80
G0 F0.0 Z24.0
G0 Z26.0
G77      ; Move to release position
M10 O6.0 ; Stop spindle
