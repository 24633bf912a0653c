'Exported by FreeCAD
'Post Processor: PathScripts.post.opensbp_post
'Output Time:2026-12-06 11:10:53.884493
JZ,26.0000
' (TC: 5mm Drill)
&ToolName=1
&Tool=1
TR,1200.0
C6
PAUSE 2
' (Drill1)
' (Begin Drilling)
J2,10.0000,15.0000
JZ,24.0000
JY,30.0000
JX,25.0000
JY,15.0000
JX,40.0000
JY,30.0000
JZ,26.0000
' (TC: 5mm Drill)
&ToolName=1
&Tool=1
TR,1200.0
C6
PAUSE 2
' (Drill1001)
' (Begin Drilling)
J2,60.0000,15.0000
JZ,24.0000
JY,30.0000
JX,75.0000
JY,15.0000
JX,90.0000
JZ,26.0000
