"""LinuxCNC's own interpreter as the oracle of the reading: rs274 (Debian's linuxcnc-uspace) and hsm-feedsim's
reader make the same moves, in order, of every LinuxCNC program of the shared corpus and of tests/oracle
(tests/oracle/compare_rs274.py: kinds, ends, arc centres, rotary axes, feeds, to rs274's 4 printed decimals)."""
import os
import shutil
import subprocess
import unittest

from hsmplanner.scripting import build_program

from helpers import REPO, SYSTEM_PYTHON, only_on_freecad

FEEDSIM = build_program(REPO, "hsm-feedsim")
COMPARE = os.path.join(REPO, "tests", "oracle", "compare_rs274.py")
# What rs274 itself cannot run: remapped M-codes and HAL pins of one LinuxCNC configuration, a W axis.
REFUSED_BY_RS274 = {"boat_xyzac.ngc", "impeller_7blade_xyzac.ngc", "w130207lzw_xyzw.ngc", "xyzab_tdr_demo.ngc"}


@only_on_freecad("1.0", "Debian 13 has linuxcnc-uspace and its rs274; forky does not")
class ReadingAsRs274(unittest.TestCase):
    def test_every_linuxcnc_program_is_read_as_rs274_reads_it(self):
        self.assertIsNotNone(shutil.which("rs274"), "linuxcnc-uspace is missing: make deps installs it")
        result = subprocess.run([SYSTEM_PYTHON, COMPARE, "--feedsim", FEEDSIM], capture_output=True, text=True,
                                timeout=900)
        print("\n" + result.stdout)
        rows = {line.split()[0]: line for line in result.stdout.splitlines()[1:] if line.strip()}
        compared = [name for name, line in rows.items() if "same moves" in line]
        refused = {name for name, line in rows.items() if "rs274 refuses it" in line}
        self.assertEqual(result.returncode, 0, result.stdout[-3000:] + result.stderr[-2000:])
        self.assertEqual(refused, REFUSED_BY_RS274, result.stdout)
        self.assertGreaterEqual(len(compared), 40, result.stdout)
        self.assertIn("mmount_mazak.ngc", compared, "the corpus's program of subroutines, loops and parameters")


if __name__ == "__main__":
    unittest.main()
