"""Writes the seed inputs of the fuzz corpus (tests/fuzz/corpus/<harness>/seed_*): run with freecadcmd.

    freecadcmd scripts/make_fuzz_corpus.py

Seeds are real inputs the harnesses accept (the master bottom feature and small parts), and bad inputs
that once crashed or hung the core, so that fuzzing starts from both sides of the parsers. Inputs found by `make fuzz` are kept
beside them under their libFuzzer names; `make test` replays every file.
"""
import os
import sys

import FreeCAD
import Part

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CORPUS = os.path.join(REPO, "tests", "fuzz", "corpus")


def write(harness, name, text):
    folder = os.path.join(CORPUS, harness)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "seed_" + name), "w") as stream:
        stream.write(text)


def master_feature():
    shape = Part.Shape()
    shape.importBrepFromString(open(os.path.join(REPO, "tests", "data", "master_bottom_feature.brep")).read())
    return shape


def plate_with_hole():
    """A 30 x 20 x 5 mm plate with a 6 mm through hole: a bottom face (its top) with an inner wire."""
    return Part.makeBox(30, 20, 5).cut(Part.makeCylinder(3, 5, FreeCAD.Vector(15, 10, 0)))


def gcode_seeds():
    for name in ("linuxcnc_fixed.ngc", "siemens840d_fixed.mpf"):
        write("gcode", name, open(os.path.join(REPO, "tests", "golden", name)).read())
    cases = {
        "arcs_and_modes": "G21 G90 G17\nG64 P0.01\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG2 X10 Y0 R5\nG3 X0 Y0 I-5 J0\n"
                          "G91 G1 X1 Y1\nG90 G61 G1 X5\nG4 P0.5\nM30\n",
        "siemens": "CYCLE832(0.01,_ORI_FINISH,1)\nG642 SOFT\nG0 X0 Y0 Z10\nG1 Z0 F2000\nG2 X20 Y0 CR=10\n"
                   "TRANS X5\nG1 X30\nBRISK G60 G1 Y10\nM30\n",
        "siemens_flow": "DEF INT I\nR1=0\nMARK: R1=R1+1\nG1 F100 X=R1\nIF R1<3 GOTOB MARK\nIF R1==3\nG1 Y1\nELSE\n"
                        "G1 Y2\nENDIF\nFOR I=1 TO 2\nG1 Z=I\nENDFOR\nWHILE R1>0\nR1=R1-1\nENDWHILE\nREPEAT\n"
                        "R1=R1+1\nUNTIL R1>2\nROW: G91 X1\nG90\nREPEAT ROW P=2\nLOOP\nGOTOF OUT\nENDLOOP\n"
                        "OUT: G1 X0\nMISSING_SUB(1, 2)\nM30\n",
        "siemens_frames": "G17 G0 X0 Y0 Z10\nTRANS X10 Y5\nAROT RPL=30\nG1 F100 X10 Y0\nATRANS X1\nSCALE X2 Y2\n"
                          "G1 X5 Y5\nG2 X10 Y0 I0 J-5\nMIRROR X0\nG1 X5 Y0\nG3 X5 Y10 CR=5\nROT Y-90\n"
                          "G1 X100 Z20\nROT\nCYCLE800(1,\"TC\",0,57,0,0,5,10,30,45,0,0,1,1)\nG0 X0 Y0 Z20\n"
                          "CIP X10 Y10 Z0 I1=5 J1=8 K1=3\nCYCLE800()\nMCALL CYCLE83(10, 0, 1, -10, , , 4, 1, 0, 0, 1, 1)\n"
                          "G0 X20\nMCALL\nM30\n",
        "exponent": "G1 X1e400 F100\n",
        "nan": "G1 X0 F100\nG1 Y nan\nG1 X5\n",
        "inf": "G1 X inf F100\n",
        "bare_arc": "G2\n",
        "negative_dwell": "G4 P-5\n",
        "binary": "\x00\x01\xff\xfeG1\x80X\x81\n",
        "feed_zero": "G1 X10 F0\n",
    }
    for name, text in cases.items():
        write("gcode", name, text)


def brep_seeds():
    feature = master_feature()
    boundaries = Part.Compound([feature.Edge13, feature.Edge14, feature.Face4])
    write("brep_curvenet", "master_feature", "0.5 5 0 2\n" + boundaries.exportBrepToString())
    write("brep_curvenet", "master_feature_median", "0.75 2 4 2\n" + boundaries.exportBrepToString())
    lines = Part.Compound([Part.makeLine((0, 0, 0), (50, 0, 0)), Part.makeLine((0, 20, 0), (50, 22, 0))])
    write("brep_curvenet", "two_lines", "0.25 1 1 1\n" + lines.exportBrepToString())
    plate = plate_with_hole()
    top = [i for i, f in enumerate(plate.Faces, 1) if f.Surface.__class__.__name__ == "Plane"
           and abs(f.normalAt(0, 0).z - 1) < 1e-9][0]
    write("brep_finishing", "plate_with_hole", "%d 4 0.05 0\n" % top + plate.exportBrepToString())
    write("brep_finishing", "plate_underside", "%d 4 0.05 0\n" % [
        i for i, f in enumerate(plate.Faces, 1) if abs(f.normalAt(0, 0).z + 1) < 1e-9][0] + plate.exportBrepToString())
    write("brep_finishing", "master_feature", "4 4 0.05 30\n" + feature.exportBrepToString())


gcode_seeds()
brep_seeds()
print("fuzz corpus seeds written to %s" % CORPUS)
