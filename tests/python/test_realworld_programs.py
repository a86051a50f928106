"""The shared corpus of real programs (../shared/data/realworld_gcode: other CAMs' posts and shop-written code),
each read in its own dialect on the machine it was written for: simulated with no word that moves skipped, or
refused for a limit of the program itself, in one line that says what it is."""
import math
import os
import shutil
import tempfile
import unittest

import hsmplanner
from saved_documents import SHARED_DATA

CORPUS = os.path.join(SHARED_DATA, "realworld_gcode")

INCH_START = "linuxcnc-2.9 in G20"  # an inch LinuxCNC: its interpreter starts in G20, as the oracle's does
# the Cincinnati's 840D keeps inches as its basic system (NX's programs say G70, lengths in inches, and F9.8 in/min:
# on a metric 840D, G70 leaves F in mm/min): the A/C Mikron's figures, started in G700
INCH_840D = "mikron-ucp710-ac-840d in G700"

# program, machine, and None (simulated) or the start of the refusal. The machine is the preset closest to the one
# the program was posted for; where none fits, the refusal says which limit of ours or of the program stops it.
PROGRAMS = [
    ("linuxcnc/impeller_7blade_xyzac.ngc", "linuxcnc-2.9-xyzac-trt", None),
    ("linuxcnc/boat_xyzac.ngc", "linuxcnc-2.9-xyzac-trt", None),
    ("linuxcnc/xyzab_tdr_demo.ngc", "linuxcnc-2.9", "line 10: #<_hal[xyzab_tdr_kins.x-rot-point]> reads the machine's HAL"),
    ("linuxcnc/trochoidal_gcmc.ngc", "linuxcnc-2.9", None),
    ("linuxcnc/w130207lzw_xyzw.ngc", INCH_START, "line 3: 'W0' (an axis the simulator does not have)"),
    ("linuxcnc/cereal_vcarve.ngc", "linuxcnc-2.9", None),
    ("linuxcnc/mmount_mazak.ngc", INCH_START, None),
    ("linuxcnc/r8s_fusion_parallel.ngc", INCH_START, None),
    ("linuxcnc/hema_p016_fusion_adaptive.ngc", INCH_START, None),
    ("linuxcnc/crankyanker_estlcam.ngc", INCH_START, None),
    ("linuxcnc/vcarve_openvoronoi.ngc", INCH_START, None),
    ("grbl/blendercam_parallel.gcode", "grbl", None),
    ("grbl/freecad_bearingclamp_adaptive.nc", "grbl", None),
    ("fanuc/mori_nmv5000_g434.nc", "fanuc-31i-b5-vmc", None),
    # a 4-axis horizontal's continuous B on the trunnion's +-120 deg B; and an arc the post left without its centre
    ("fanuc/sundstrand_omnimill_4ax.nc", "fanuc-31i-b5-vmc", "line 17: B120.316 is outside the travel of B"),
    ("fanuc/kuraki_kbt11dx_w.nc", "fanuc-31i-b5-vmc", "line 8: 'W5.' (an axis the simulator does not have)"),
    ("haas/haas_vf2tr_5axis.nc", "haas-vf2-tr160", "line 2: 'O ENTER OP AND LAST 3 DI' is not a program number"),
    ("haas/haas_vf2_4axis_test.nc", "haas-vf2-hrt210", None),
    ("haas/haas_stepblock_o78241.nc", "haas-vf2", None),
    ("haas/haas_teammachine_engrave.nc", "haas-vf2", None),
    ("other/cameo_relief.nc", "linuxcnc-2.9", None),
    ("other/bear_relief.nc", "linuxcnc-2.9", None),
    ("other/cuq_dmu_5axis_ac.nc", "linuxcnc-2.9-xyzac-trt", "line 5: coordinates before any motion mode"),
    ("other/okuma_7000m.nc", "fanuc-31i-b5-vmc", "line 19: this is an Okuma OSP program"),
    ("other/dmc160u_millplus_5axis.nc", "fanuc-31i-b5-vmc", "line 11: this is a Heidenhain MillPlus program"),
    ("840d/cam_test_fusion_ac_3plus2.mpf", "mikron-ucp710-ac-840d", None),
    # TRAOOF (NX's post for this Cincinnati, maybe the maker's own cycle) is no 840D instruction: the control
    # would look for a subprogram of that name, so does the reader (see Siemens840dPrograms below)
    ("840d/cincinnati_ftv5_varcontour.mpf", INCH_840D, "line 13: subprogram TRAOOF is not found"),
    ("840d/cincinnati_ftv5_nx_traori.mpf", INCH_840D, "line 362: subprogram TRAOOF is not found"),
    ("840d/brys_oporniy_hand.mpf", "mikron-ucp710-840d", "line 13: subprogram L140 is not found"),
    ("840d/cycle_konus_sub.spf", "mikron-ucp710-840d", "line 21: this is subprogram CYCLE_KONUS, whose parameters"),
    ("heidenhain/dmc100_tnc_m128_5axis.h", "mikron-ucp710-840d", "line 1: this is a Heidenhain conversational"),
    ("heidenhain/dangarpt_test.h", "mikron-ucp710-840d", "line 1: this is a Heidenhain conversational"),
]


def machine_of(name):
    """A preset's name, or for INCH_START the linuxcnc-2.9 preset starting in G20 (LinuxCNC reads a line's F
    before its G20: `G20 F6` is 6 mm/min on a machine that starts in mm, 6 in/min on one that starts in inches)."""
    if name not in (INCH_START, INCH_840D):
        return name
    machine = hsmplanner.load_machine(name.split(" ")[0])
    machine.power_on_codes = "G20" if name == INCH_START else "G700"
    return machine


class RealWorldPrograms(unittest.TestCase):
    def setUp(self):
        if not os.path.isdir(CORPUS):
            self.fail("%s is missing: the shared corpus lives in ../shared/data beside the repository" % CORPUS)

    def test_every_program_is_simulated_or_refused_for_what_it_is(self):
        rows = []
        for name, machine, refusal in PROGRAMS:
            path = os.path.join(CORPUS, name)
            with self.subTest(program=name):
                if refusal is not None:
                    with self.assertRaises(ValueError) as raised:
                        hsmplanner.simulate(path, machine_of(machine))
                    self.assertTrue(str(raised.exception).startswith(refusal), str(raised.exception))
                    rows.append("%-40s %-24s refused: %s" % (name, machine, str(raised.exception)[:90]))
                    continue
                summary = hsmplanner.simulate(path, machine_of(machine)).summary
                self.assertTrue(math.isfinite(summary.total_time) and summary.total_time > 0, name)
                self.assertGreater(summary.block_count, 10, name)
                # no word that moves was skipped (it would have stopped the reading); what is left is M codes
                moving = [w for w in summary.unknown_word_counts if w[0] in "GUVWXYZABC" and w != "CYCLE800"]
                self.assertEqual(moving, [], name)
                # a machine takes at least length/feed; the rapids' share may make it a little less
                ratio = summary.total_time / summary.naive_time
                self.assertGreater(ratio, 0.9, name)
                rows.append("%-40s %-24s %9.1f s  length/feed %9.1f s  x%.2f  unknown %s"
                            % (name, machine, summary.total_time, summary.naive_time, ratio,
                               dict(summary.unknown_word_counts) or "-"))
        print("\n" + "\n".join(rows))

    def test_a_lines_feed_is_read_before_its_g20_as_linuxcnc_does(self):
        """vcarve_openvoronoi's line 5 is `G20 F6`: LinuxCNC 2.9 takes 29.3 s when its interpreter starts in G20,
        about 563 s when it starts in G21 (F6 read as 6 mm/min), measured by the oracle on 7 December 2026."""
        path = os.path.join(CORPUS, "linuxcnc", "vcarve_openvoronoi.ngc")
        inch = hsmplanner.simulate(path, machine_of(INCH_START)).summary.total_time
        metric = hsmplanner.simulate(path, "linuxcnc-2.9").summary.total_time
        self.assertAlmostEqual(inch, 29.3, delta=29.3 * 0.02)
        self.assertAlmostEqual(metric, 563.0, delta=563.0 * 0.02)


class Siemens840dPrograms(unittest.TestCase):
    """The corpus's 840D programs run with what they call: the shop's subprograms L140 / L143 (a head or table
    positioning the corpus does not hold: stand-ins that move nothing), CYCLE_KONUS called with a cone's
    parameters, TRAOOF skipped and counted."""

    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="hsm_840d_")

    def tearDown(self):
        shutil.rmtree(self.folder, ignore_errors=True)

    def write(self, name, text):
        with open(os.path.join(self.folder, name), "w") as stream:
            stream.write(text)

    def test_hand_written_program_with_its_subprograms_loops_over_its_depths(self):
        self.write("L140.SPF", "PROC L140(INT MODE)\nRET\n")
        self.write("L143.SPF", "PROC L143(REAL ANGLE)\nRET\n")
        path = os.path.join(CORPUS, "840d", "brys_oporniy_hand.mpf")
        result = hsmplanner.simulate(path, "mikron-ucp710-840d", blocks=True, subroutine_folders=[self.folder])
        # ROT Y-90 puts the program's Z along the machine's -X: each `IF R6>=R3 GOTOB METKA_START` pass goes
        # 3 mm deeper (Z=R6: 1586, 1583 ... 1544), then `LAST:` the last at 1543
        x = result.blocks["end"][:, 0]
        for depth in (1586.0, 1583.0, 1544.0, 1543.0):
            self.assertTrue(any(abs(v + depth) < 1e-6 for v in x), depth)
        self.assertFalse(any(abs(v + 1541.0) < 1e-6 for v in x))
        self.assertEqual(result.summary.unknown_word_counts.get("L140", 0), 0)

    def test_a_parametrised_subprogram_runs_from_the_program_that_calls_it(self):
        shutil.copy(os.path.join(CORPUS, "840d", "cycle_konus_sub.spf"), os.path.join(self.folder, "CYCLE_KONUS.SPF"))
        self.write("KONUS.MPF", "G54 G17 G90 G71\nT1 D1 M6\nS1000 M3 F500\n"
                                "CYCLE_KONUS(50, 40, 5, 2, 10, 20, 8, 0.8, -5, 0, 0)\nM30\n")
        result = hsmplanner.simulate(os.path.join(self.folder, "KONUS.MPF"), "mikron-ucp710-840d", blocks=True)
        radius = [math.hypot(p[0], p[1]) for p in result.blocks["end"]]
        # the spiral from radius 40 - 8 inwards ... to the end radius 20 - 8, one point each 5 degrees
        self.assertGreater(result.summary.block_count, 1000)
        self.assertAlmostEqual(max(radius[3:]), 32.0, delta=0.2)
        self.assertLess(min(radius[3:-2]), 12.5)

    def test_the_nx_programs_run_with_their_unknown_call_skipped_and_named(self):
        for name in ("cincinnati_ftv5_varcontour.mpf", "cincinnati_ftv5_nx_traori.mpf"):
            summary = hsmplanner.simulate(os.path.join(CORPUS, "840d", name), machine_of(INCH_840D),
                                          skip_unknown=True).summary
            self.assertIn("TRAOOF", summary.unknown_word_counts, name)
            self.assertGreater(summary.total_time, summary.naive_time * 0.9, name)

    def test_a_swivel_turns_the_table_before_the_planes_moves(self):
        """CYCLE800 axis by axis, 30 deg about Y, on the A/C trunnion: the table tilts A 30 deg and turns C 90 deg
        (the tool along the plane's Z) with X Y Z standing, at C's rapid (7200 deg/min: 0.75 s at least); then the
        plane's points are the tool tip on the part."""
        program = ("G17 G90 G0 X10 Y0 Z50\nCYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,1)\nG0 X0 Y0 Z20\n"
                   "G1 F1000 X10\nCYCLE800()\nG0 X0\n")
        blocks = hsmplanner.simulate(program, "mikron-ucp710-ac-840d", blocks=True).blocks
        swivel = list(blocks["line"]).index(2)
        self.assertAlmostEqual(abs(blocks["rotary_end"][swivel][0]), 30.0, places=6)
        self.assertAlmostEqual(abs(blocks["rotary_end"][swivel][1]), 90.0, places=6)
        self.assertGreaterEqual(blocks["time"][swivel], 0.75)
        for axis in range(3):
            self.assertAlmostEqual(blocks["machine_start"][swivel][axis], blocks["machine_end"][swivel][axis])
        tip = blocks["end"][swivel + 1]
        for got, want in zip(tip, (10.0, 0.0, 20.0 * math.cos(math.radians(30)))):
            self.assertAlmostEqual(got, want, places=6)

    def test_a_subroutine_folder_that_is_not_one_is_refused(self):
        with self.assertRaises(ValueError) as raised:
            hsmplanner.simulate("G1 X1 F100\n", "mikron-ucp710-840d", subroutine_folders=["/no/such/folder"])
        self.assertIn("/no/such/folder", str(raised.exception))
        for wrong in (5, float("nan"), [1e9]):
            with self.assertRaises(TypeError) as raised:
                hsmplanner.simulate("G1 X1 F100\n", "mikron-ucp710-840d", subroutine_folders=wrong)
            self.assertIn("subroutine", str(raised.exception))


if __name__ == "__main__":
    unittest.main()
