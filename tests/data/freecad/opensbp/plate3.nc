'Exported by FreeCAD
'Post Processor: PathScripts.post.opensbp_post
'Output Time:2026-12-06 11:10:53.257203
JZ,16.0000
' (TC: 3.5mm Drill)
&ToolName=1
&Tool=1
TR,1200.0
C6
PAUSE 2
' (Drill1)
' (Begin Drilling)
J2,10.0000,10.0000
JZ,14.0000
JY,30.0000
JX,30.0000
JY,10.0000
JX,50.0000
JY,30.0000
JX,70.0000
JY,10.0000
JX,90.0000
JY,30.0000
JZ,16.0000
' (TC: 6.6mm Drill)
&ToolName=2
&Tool=2
TR,1400.0
C6
PAUSE 2
' (Drill2)
' (Begin Drilling)
J2,15.0000,45.0000
JZ,14.0000
JY,67.0000
JX,37.0000
JY,45.0000
JX,59.0000
JY,67.0000
JX,81.0000
JY,45.0000
JZ,16.0000
' (TC: 10mm Drill)
&ToolName=3
&Tool=3
TR,1600.0
C6
PAUSE 2
' (Drill3)
' (Begin Drilling)
J2,100.0000,40.0000
JZ,14.0000
JZ,16.0000
