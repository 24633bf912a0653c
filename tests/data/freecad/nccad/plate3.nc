;Exported by FreeCAD
;Post Processor: PathScripts.post.nccad_post
;CAM file: 
;Output Time: 2026-12-06 11:10:53.209709
G54
G0 Z16.0
(TC: 3.5mm Drill)
G77      ; Move to release position
M10 O6.0 ; Stop spindle
M01 Insert tool 1
G76      ; Move to reference point to ensure correct coordinates after tool change
M10 O6.1 ; Start spindle
M01 Set spindle speed to 1200 rounds per minute
(Drill1)
(Begin Drilling)
G0 F0.0 Z16.0
G90
G98
G0 F0.0 X10.0 Y10.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X10.0 Y10.0 Z0.0
G0 F0.0 X10.0 Y30.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X10.0 Y30.0 Z0.0
G0 F0.0 X30.0 Y30.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X30.0 Y30.0 Z0.0
G0 F0.0 X30.0 Y10.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X30.0 Y10.0 Z0.0
G0 F0.0 X50.0 Y10.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X50.0 Y10.0 Z0.0
G0 F0.0 X50.0 Y30.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X50.0 Y30.0 Z0.0
G0 F0.0 X70.0 Y30.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X70.0 Y30.0 Z0.0
G0 F0.0 X70.0 Y10.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X70.0 Y10.0 Z0.0
G0 F0.0 X90.0 Y10.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X90.0 Y10.0 Z0.0
G0 F0.0 X90.0 Y30.0
G0 F0.0 Z14.0
G81 F1000.0 R14.0 X90.0 Y30.0 Z0.0
G80
G0 F0.0 Z14.0
G0 Z16.0
G54
G0 Z16.0
(TC: 6.6mm Drill)
G77      ; Move to release position
M10 O6.0 ; Stop spindle
M01 Insert tool 2
G76      ; Move to reference point to ensure correct coordinates after tool change
M10 O6.1 ; Start spindle
M01 Set spindle speed to 1400 rounds per minute
(Drill2)
(Begin Drilling)
G0 F0.0 Z16.0
G90
G98
G0 F0.0 X15.0 Y45.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X15.0 Y45.0 Z0.0
G0 F0.0 X15.0 Y67.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X15.0 Y67.0 Z0.0
G0 F0.0 X37.0 Y67.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X37.0 Y67.0 Z0.0
G0 F0.0 X37.0 Y45.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X37.0 Y45.0 Z0.0
G0 F0.0 X59.0 Y45.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X59.0 Y45.0 Z0.0
G0 F0.0 X59.0 Y67.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X59.0 Y67.0 Z0.0
G0 F0.0 X81.0 Y67.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X81.0 Y67.0 Z0.0
G0 F0.0 X81.0 Y45.0
G0 F0.0 Z14.0
G82 F1000.0 P0.5 R14.0 X81.0 Y45.0 Z0.0
G80
G0 F0.0 Z14.0
G0 Z16.0
G54
G0 Z16.0
(TC: 10mm Drill)
G77      ; Move to release position
M10 O6.0 ; Stop spindle
M01 Insert tool 3
G76      ; Move to reference point to ensure correct coordinates after tool change
M10 O6.1 ; Start spindle
M01 Set spindle speed to 1600 rounds per minute
(Drill3)
(Begin Drilling)
G0 F0.0 Z16.0
G90
G98
G0 F0.0 X100.0 Y40.0
G0 F0.0 Z14.0
G83 F1000.0 Q7.5 R14.0 X100.0 Y40.0 Z0.0
G80
G0 F0.0 Z14.0
G0 Z16.0
G77      ; Move to release position
M10 O6.0 ; Stop spindle
