#!/usr/bin/env python3
"""Issue 86: small IPC-2581 and ODB++ jobs, the fuzzers' seeds (tests/fuzz):
a two-hole board placed 2 x 3 on a panel, turned 90 degrees, with a plated
slot; the ODB++ one as a tar, a .tgz and a .zip.  python3 make_small.py"""
import io
import os
import tarfile
import zipfile

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "small")

IPC = """<?xml version="1.0"?>
<IPC-2581 revision="B" xmlns="http://webstds.ipc.org/2581">
<Ecad name="x"><CadHeader units="MILLIMETER"/><CadData>
<Layer name="TOP" layerFunction="CONDUCTOR" side="TOP"/>
<Layer name="BOT" layerFunction="CONDUCTOR" side="BOTTOM"/>
<Layer name="D" layerFunction="DRILL" side="ALL"><Span fromLayer="TOP" toLayer="BOT"/></Layer>
<Layer name="R" layerFunction="ROUT" side="ALL"/>
<Step name="board" type="BOARD"><Datum x="5" y="5"/>
<Profile><Polygon><PolyBegin x="0" y="0"/><PolyStepSegment x="40" y="0"/><PolyStepCurve x="40" y="30" centerX="40" centerY="15" clockwise="false"/><PolyStepSegment x="0" y="30"/><PolyStepSegment x="0" y="0"/></Polygon></Profile>
<LayerFeature layerRef="D">
<Set><Hole name="H1" diameter="1" platingStatus="PLATED" x="10" y="5"/></Set>
<Set><Hole name="H2" diameter="3.2" platingStatus="NONPLATED" x="20" y="15"/></Set>
</LayerFeature>
<LayerFeature layerRef="R"><Set><SlotCavity name="S1" platingStatus="PLATED"><Location x="30" y="20"/><Xform rotation="90"/><Oval width="3" height="1"/></SlotCavity></Set></LayerFeature>
</Step>
<Step name="panel" type="PANEL"><Datum x="0" y="0"/>
<StepRepeat stepRef="board" x="100" y="50" nx="2" ny="3" dx="60" dy="40" angle="90" mirror="false"/>
</Step>
</CadData></Ecad>
</IPC-2581>
"""

ODB = {
    "job/matrix/matrix": "STEP {\n COL=1\n NAME=PCB\n}\nSTEP {\n COL=2\n NAME=PANEL\n}\n"
    "LAYER {\n ROW=1\n CONTEXT=BOARD\n TYPE=SIGNAL\n NAME=TOP\n}\n"
    "LAYER {\n ROW=2\n CONTEXT=BOARD\n TYPE=SIGNAL\n NAME=BOTTOM\n}\n"
    "LAYER {\n ROW=3\n CONTEXT=BOARD\n TYPE=DRILL\n NAME=DRILL\n START_NAME=TOP\n END_NAME=BOTTOM\n}\n",
    "job/steps/pcb/stephdr": "UNITS=MM\nX_DATUM=5\nY_DATUM=5\n",
    "job/steps/pcb/profile": "UNITS=MM\nS P 0\nOB 0 0 I\nOS 40 0\nOS 40 30\nOS 0 30\nOS 0 0\nOE\nSE\n",
    "job/steps/panel/stephdr": "UNITS=MM\nSTEP-REPEAT {\n NAME=PCB\n X=100\n Y=50\n DX=60\n DY=40\n NX=2\n NY=3\n ANGLE=270\n MIRROR=NO\n}\n",
    "job/steps/pcb/layers/drill/features": "UNITS=MM\n$0 r1000\n$1 r3200\n$2 oval1000x3000\n@0 .drill\n#\n"
    "P 10 5 0 P 0 0 ;0=0\nP 20 15 1 P 0 8 45.0 ;0=1\nP 30 20 2 P 0 8 90.0 ;0=0\nL 1 1 3 1 0 P 0 ;0=0\n",
}


def main():
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, "panel.ipc2581.xml"), "w") as f:
        f.write(IPC)
    for name, mode in (("panel-odb.tar", "w"), ("panel-odb.tgz", "w:gz")):
        with tarfile.open(os.path.join(HERE, name), mode, format=tarfile.USTAR_FORMAT) as tar:
            for path, text in ODB.items():
                data = text.encode()
                info = tarfile.TarInfo(path)
                info.size, info.mtime = len(data), 0
                tar.addfile(info, io.BytesIO(data))
    with zipfile.ZipFile(os.path.join(HERE, "panel-odb.zip"), "w", zipfile.ZIP_DEFLATED) as z:
        for path, text in ODB.items():
            z.writestr(zipfile.ZipInfo(path, (1980, 1, 1, 0, 0, 0)), text)


if __name__ == "__main__":
    main()
