"""Regenerates tests/data/ from the generators (run with freecadcmd after changing the master feature).

    freecadcmd scripts/make_test_data.py
"""
import sys
import json
import os

from hsmplanner.app.master_feature import make_master_bottom_feature

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data")

feature = make_master_bottom_feature()
feature.shape.exportBrep(os.path.join(DATA, "master_bottom_feature.brep"))
with open(os.path.join(DATA, "master_bottom_feature.json"), "w") as stream:
    json.dump({"bottom_face": feature.bottom_face, "boundary_1": feature.boundary_1,
               "boundary_2": feature.boundary_2, "volume_mm3": round(feature.shape.Volume, 3)}, stream, indent=2)
print("test data written to", os.path.normpath(DATA))
sys.stdout.flush()  # freecadcmd 1.0 drops unflushed output on SystemExit
raise SystemExit(0)
