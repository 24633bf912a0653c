%prog1
(PathScripts.post.uccnc_post --no-show-editor)
(Exported by FreeCAD for UC-CNC)
(Post Processor: PathScripts.post.uccnc_post, version 0.0.4)
(CAM file: )
(Output Time: 2026-12-06 16:22:31.212990)
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
G0 Z14.000
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
G0 Z14.000
G90
G98
G0 X19.800 Y24.300
G0 Z12.000
G81 Z0.000 R12.000 F6000.000
G0 X28.800 Y34.500
G0 Z12.000
G81 Z0.000 F6000.000
G0 X42.600 Y27.900
G0 Z12.000
G81 Z0.000 F6000.000
G0 X29.200 Y11.700
G0 Z12.000
G81 Z0.000 F6000.000
G0 X60.200 Y16.300
G0 Z12.000
G81 Z0.000 F6000.000
G0 X55.800 Y43.500
G0 Z12.000
G81 Z0.000 F6000.000
G0 X42.200 Y60.700
G0 Z12.000
G81 Z0.000 F6000.000
G0 X32.200 Y60.300
G0 Z12.000
G81 Z0.000 F6000.000
G0 X79.800 Y59.900
G0 Z12.000
G81 Z0.000 F6000.000
G0 X84.400 Y36.500
G0 Z12.000
G81 Z0.000 F6000.000
G0 X95.200 Y34.100
G0 Z12.000
G81 Z0.000 F6000.000
G0 X104.400 Y16.500
G0 Z12.000
G81 Z0.000 F6000.000
G0 X87.400 Y10.300
G0 Z12.000
G81 Z0.000 F6000.000
G80
G0 Z12.000
G0 Z14.000
(operation done: Drill1)
(operation finalised: Drill1)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z14.000
(operation done: G54)
(operation finalised: G54)
(operation initialise: TC: 6mm Endmill)
(operation start: TC: 6mm Endmill)
(TC: 6mm Endmill)
M6 T9
M3 S10000
(operation done: TC: 6mm Endmill)
(operation finalised: TC: 6mm Endmill)
(operation initialise: Profile)
(operation start: Profile)
(Profile)
(Compensated Tool Path. Diameter: 6.0)
G0 Z14.000
G0 X122.121 Y72.121
G0 Z12.000
G1 Z3.000 F6000.000
G2 X123.000 Y70.000 I-2.121 J-2.121 K0.000 F36000.000
G1 Y0.000
G2 X120.000 Y-3.000 I-3.000 J0.000
G1 X0.000
G2 X-3.000 Y0.000 I0.000 J3.000
G1 Y70.000
G2 X0.000 Y73.000 I3.000 J-0.000
G1 X120.000
G2 X122.121 Y72.121 I-0.000 J-3.000
G1 Z-1.000 F6000.000
G2 X123.000 Y70.000 I-2.121 J-2.121 F36000.000
G1 Y0.000
G2 X120.000 Y-3.000 I-3.000 J0.000
G1 X0.000
G2 X-3.000 Y0.000 I0.000 J3.000
G1 Y70.000
G2 X0.000 Y73.000 I3.000 J-0.000
G1 X120.000
G2 X122.121 Y72.121 I-0.000 J-3.000
G0 Z14.000
G0
(operation done: Profile)
(operation finalised: Profile)
(operation initialise: G54)
(operation start: G54)
G54
G0 Z14.000
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
G0 Z14.000
G90
G98
G0 X15.000 Y14.300
G0 Z12.000
G83 Z0.000 R12.000 F6000.000 Q4.950
G0 X10.200 Y37.500
G0 Z12.000
G83 Z0.000 F6000.000
G0 X45.600 Y10.500
G0 Z12.000
G83 Z0.000 F6000.000
G0 X73.400 Y39.900
G0 Z12.000
G83 Z0.000 F6000.000
G0 X90.000 Y52.500
G0 Z12.000
G83 Z0.000 F6000.000
G0 X111.600 Y50.900
G0 Z12.000
G83 Z0.000 F6000.000
G0 X107.800 Y34.700
G0 Z12.000
G83 Z0.000 F6000.000
G0 X53.200 Y56.500
G0 Z12.000
G83 Z0.000 F6000.000
G80
G0 Z12.000
G0 Z14.000
(operation done: Drill2)
(operation finalised: Drill2)
(postamble: begin)
M05 (stop spindle)
G17 (Default: XY-plane)
G54 (Default: First coordinate system)
G40 (Default: Cutter radius compensation none)
G90 (Default: Absolute distance mode selection)
G80 (Cancel canned cycle)
M30 (Stop program and rewind code)
(postamble: done)
