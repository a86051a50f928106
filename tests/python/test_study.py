"""The automatic strategy study (hsmplanner.study): the grid refused by name before
anything runs, the ranking right on cases whose order is known, rows kept when a variant fails or the study is
cancelled, results read back from the cache, worker processes giving the rows one process gives."""
import os
import re
import time
import unittest

import FreeCAD

from hsmplanner import study
from hsmplanner.app import master_feature_object
from helpers import REPO, temporary_directory


class Grid(unittest.TestCase):
    def test_bad_ranges_are_refused_by_name(self):
        for kwargs, words in ((dict(k=(0.0,), p=(10,)), "K = 0.0 is outside ]0, 1["),
                              (dict(k=(1.5,), p=(10,)), "K = 1.5 is outside ]0, 1["),
                              (dict(k=(0.5,), p=(0,)), "P = 0 mm must be positive"),
                              (dict(k=(0.5,), p=()), "guide curves need both K"),
                              (dict(), "the grid is empty"),
                              (dict(planes_deg=(0,), feeds_mm_min=(0,)), "feed 0 mm/min must be positive"),
                              (dict(planes_deg=(0,), machines=("okuma-mb46",)), "machine 'okuma-mb46' is unknown"),
                              (dict(planes_deg=range(0, 100000)), "narrow the ranges"),
                              (dict(planes_deg=(1e300,)), "plane angle 1e+300° must lie within [-360, 360]"),
                              # each range under the limit, their product far over it: refused before any is made
                              (dict(k=[i / 10000 for i in range(1, 10000)], p=range(1, 10000)),
                               "199960002 variants (more than 10000)")):
            with self.subTest(words=words), self.assertRaisesRegex(ValueError, re.escape(words)):
                study.variants(**kwargs)

    def test_the_grid_of_the_issue(self):
        # planes every 15°, K × P × median or not, the 4-step method: 12 + 18 + 1 = 31 variants at one feed
        grid = study.variants(planes_deg=range(0, 180, 15), k=(0.25, 0.5, 0.75), p=(5, 10, 20), four_step=True)
        self.assertEqual(len(grid), 31)
        self.assertEqual(len({v["name"] for v in grid}), 31)
        # the paper's hand study: both median constructions beside B1 -> B2, 12 + 27 + 1 = 40 variants
        paper = study.paper_grid()
        self.assertEqual(len(paper), 40)
        self.assertEqual(sorted({v["mode"] for v in paper if v["strategy"] == "guide"}),
                         ["b1_to_b2", "boundaries_to_median", "median_to_boundaries"])
        twice = study.variants(planes_deg=(0, 45, 0), k=(0.5, 0.5), p=(10,), median=(False,))
        self.assertEqual([v["name"].split(" F")[0] for v in twice], ["planes 0°", "planes 45°", "guide B1→B2 K0.5 P10"])
        with self.assertRaisesRegex(ValueError, re.escape("net mode 'spiral' is unknown")):
            study.variants(k=(0.5,), p=(10,), net_modes=("spiral",))


class Study(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.document = FreeCAD.newDocument("Study")
        cls.part = master_feature_object.create(cls.document)
        cls.b1, cls.b2 = (cls.part.Shape.getElement(n) for n in (cls.part.Boundary1, cls.part.Boundary2))
        cls.face = cls.part.BottomFace
        # coarse finishing (Ø10 ball, 0.1 mm cusp): the study's logic, not the paper's paths
        cls.finishing = dict(tool_diameter=10.0, cusp_height=0.1, tolerance=0.05)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.document.Name)

    def run_study(self, grid, **kwargs):
        return study.study(self.part.Shape, self.face, self.b1, self.b2, grid, finishing=self.finishing, **kwargs)

    def test_the_same_path_at_two_feeds_ranks_the_faster_first_and_processes_agree(self):
        grid = study.variants(planes_deg=(0,), feeds_mm_min=(1000, 6000))
        folder = temporary_directory(self)
        rows = self.run_study(grid, workers=2, cache_dir=folder)
        self.assertEqual([r["error"] for r in rows], ["", ""])
        self.assertEqual(study.rank(rows, "time")[0]["feed_mm_min"], 6000.0)
        self.assertLess(rows[0]["slowdown_share"], rows[1]["slowdown_share"], "F1000 is rarely slowed to half")
        self.assertEqual(rows[0]["path_mm"], rows[1]["path_mm"])
        worst = rows[1]["worst_slowdowns"]  # F6000: the regions losing most, in order, each somewhere on the part
        self.assertTrue(0 < len(worst) <= 3, worst)
        self.assertEqual([w["lost_s"] for w in worst], sorted((w["lost_s"] for w in worst), reverse=True))
        for region in worst:
            self.assertTrue(0.0 < region["lost_s"] < region["time_s"], region)
            self.assertTrue(-10.0 <= region["x_mm"] <= 150.0 and -10.0 <= region["y_mm"] <= 70.0, region)
        # the same inputs again: read back from the cache, the same figures
        again = self.run_study(grid, workers=1, cache_dir=folder)
        self.assertEqual([r["cached"] for r in again], [True, True])
        self.assertEqual([r["time_s"] for r in again], [r["time_s"] for r in rows])
        study.write_csv(rows, os.path.join(folder, "rows.csv"))
        study.write_json(rows, os.path.join(folder, "rows.json"))
        self.assertTrue(os.path.getsize(os.path.join(folder, "rows.csv")) > 100)

    def test_a_failed_and_a_cancelled_variant_keep_the_others(self):
        grid = study.variants(planes_deg=(0, 45, 90))
        grid[1]["angle_deg"] = float("nan")  # fails in the core, after the grid's checks
        seen = []
        rows = self.run_study(grid, workers=1, progress=lambda done, row: seen.append(row["name"]) or len(seen) < 2)
        self.assertEqual(rows[0]["error"], "")
        self.assertIn("ValueError", rows[1]["error"])
        self.assertEqual(rows[2]["error"], "cancelled")
        self.assertEqual([r["name"] for r in study.rank(rows)], [rows[0]["name"]])
        with self.assertRaisesRegex(ValueError, "rank by 'speed'"):
            study.rank(rows, "speed")

    def test_idle_cancels_mid_variant_and_a_dead_worker_fails_rows_not_the_study(self):
        grid = study.variants(planes_deg=(0, 45, 90, 135))
        ticks = []
        rows = self.run_study(grid, workers=2, idle=lambda: ticks.append(1) or len(ticks) < 2)
        self.assertEqual([r["error"] for r in rows], ["cancelled"] * 4, "cancelled before any variant ended")
        self.assertEqual(len(ticks), 2)
        # A worker process that dies (as a crash in the core would kill it): the rows finished before are
        # kept, the others say a worker died; the study returns.
        real = study._run_cached

        def dies_on_90(variant, *args):
            if variant.get("angle_deg") == 90.0:
                time.sleep(1.0)  # the variants before it end first
                os._exit(3)
            return real(variant, *args)

        # forked workers run the module's function as it is now (pickled by its name)
        dies_on_90.__module__, dies_on_90.__qualname__ = study.__name__, "_run_cached"
        study._run_cached = dies_on_90
        try:
            rows = self.run_study(grid, workers=2)
        finally:
            study._run_cached = real
        errors = [r["error"] for r in rows]
        self.assertIn("a worker process died", errors[2])
        self.assertEqual(errors[0], "", errors)
        self.assertGreater(rows[0]["time_s"], 0.0)

    def test_a_local_dask_cluster_gives_the_rows_the_process_pool_gives(self):
        grid = study.variants(planes_deg=(0,), k=(0.5,), p=(20,), median=(True,))
        cluster, address = study.local_cluster(2)
        try:
            on_dask = self.run_study(grid, scheduler=address)
        finally:
            cluster.close()
        on_pool = self.run_study(grid, workers=2)
        self.assertEqual([r["error"] for r in on_dask], ["", ""])
        self.assertEqual([r["time_s"] for r in on_dask], [r["time_s"] for r in on_pool])
        self.assertEqual([r["passes"] for r in on_dask], [r["passes"] for r in on_pool])
        with self.assertRaisesRegex(ValueError, re.escape("scheduler 'localhost:8786' must be a Dask scheduler's "
                                                          "address such as 'tcp://host:8786'")):
            self.run_study(grid, scheduler="localhost:8786")

    def test_k_refinement_finds_the_best_k_it_evaluated_within_its_bounds(self):
        best, rows = study.refine_k(self.part.Shape, self.face, self.b1, self.b2, p=10.0, tolerance=0.2,
                                    max_evaluations=5, finishing=self.finishing, net_mode="median_to_boundaries",
                                    start=0.75)
        self.assertEqual((rows[0]["k"], rows[0]["mode"]), (0.75, "median_to_boundaries"), "the start K first")
        self.assertLessEqual(best["time_s"], rows[0]["time_s"], "never worse than the start")
        self.assertLessEqual(len(rows), 5)
        self.assertGreaterEqual(len(rows), 3)
        ks = [r["k"] for r in rows]
        self.assertTrue(all(0.1 <= k <= 0.9 for k in ks), ks)
        self.assertEqual(best["time_s"], min(r["time_s"] for r in rows if not r["error"]))
        for kwargs, words in ((dict(low=0.0), "K bounds"), (dict(low=0.6, high=0.4), "K bounds"),
                              (dict(tolerance=0.0), "K tolerance 0.0"), (dict(max_evaluations=1), "max evaluations 1"),
                              (dict(by="length"), "refine K by 'length'"), (dict(start=1.0), "start K 1.0")):
            with self.subTest(words=words), self.assertRaisesRegex(ValueError, re.escape(words)):
                study.refine_k(self.part.Shape, self.face, self.b1, self.b2, **kwargs)

    def test_along_the_axis_of_a_cylinder_ranks_first_the_direction_papers_case_1(self):
        # the machining-direction paper's case 1 (R10 about Y, Ø10 ball, Sz 0.01 mm): passes along the axis are
        # straight and reach the feed; across it they follow the curvature and short passes brake at each end
        from hsmplanner.app import surfaces

        face = surfaces.cylinder_top()
        grid = study.variants(planes_deg=(0, 90), feeds_mm_min=(2000, 10000))
        rows = study.study(face, "Face1", None, None, grid, workers=1,
                           finishing=dict(tool_diameter=10.0, cusp_height=0.01))
        for feed in (2000.0, 10000.0):
            ranked = study.rank([r for r in rows if r["feed_mm_min"] == feed], "time")
            self.assertEqual([r["angle_deg"] for r in ranked], [90.0, 0.0], "F%g" % feed)
            self.assertLess(ranked[0]["slowdown_share"], ranked[1]["slowdown_share"])
        with self.assertRaisesRegex(ValueError, "cusp height 6 mm must be .* below the tool radius 5 mm"):
            study.study(face, "Face1", None, None, grid, workers=1, finishing=dict(tool_diameter=10.0, cusp_height=6.0))
        with self.assertRaisesRegex(ValueError, "guide-curve and 4-step variants need the boundaries b1 and b2"):
            study.study(face, "Face1", None, None, study.variants(four_step=True), workers=1)

    def test_the_command_line_ranks_and_names_a_bad_argument(self):
        import subprocess

        folder = temporary_directory(self)
        brep = os.path.join(folder, "master.brep")
        self.part.Shape.exportBrep(brep)
        b1, b2 = self.part.Boundary1, self.part.Boundary2
        env = dict(os.environ, PYTHONPATH=os.path.join(REPO, "python"))
        command = ["/usr/bin/python3", "-m", "hsmplanner.study_cli", brep, "--face", self.face, "--b1", b1, "--b2", b2,
                   "--planes", "0,90", "--feeds", "6000,2000", "--workers", "2", "--csv", os.path.join(folder, "s.csv")]
        done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        lines = [l for l in done.stdout.splitlines() if l.startswith("planes")]
        self.assertEqual(len(lines), 4, done.stdout)
        self.assertIn("F6000", lines[0], "the fastest first")
        self.assertTrue(os.path.getsize(os.path.join(folder, "s.csv")) > 100)
        bad = subprocess.run(command[:7] + ["Edge999"] + command[8:], env=env, capture_output=True, text=True, timeout=120)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("edge 'Edge999' is not an element of the part", bad.stderr)
        mode = subprocess.run(command + ["--k", "0.5", "--p", "20", "--net-modes", "b1_to_b2,spiral"], env=env,
                              capture_output=True, text=True, timeout=120)
        self.assertEqual(mode.returncode, 2)
        self.assertIn("net mode 'spiral' is unknown", mode.stderr)
        # Files that are not STEP though named so, and schedulers that do not answer or have no worker: exit 2
        # with one line naming the argument, no traceback.
        text_file, noise_file = os.path.join(folder, "notes.step"), os.path.join(folder, "noise.step")
        with open(text_file, "w") as stream:
            stream.write("this is not a STEP file\n")
        with open(noise_file, "wb") as stream:
            stream.write(os.urandom(4096))
        import distributed

        cluster = distributed.LocalCluster(n_workers=0, processes=False, protocol="tcp://", dashboard_address=None)
        address = cluster.scheduler_address
        try:
            for argument, words in (([text_file], "is not a BREP or STEP file FreeCAD can read"),
                                    ([noise_file], "is not a BREP or STEP file FreeCAD can read"),
                                    ([brep, "--scheduler", "tcp://127.0.0.1:9", "--scheduler-timeout", "2"],
                                     "did not answer within 2 s"),
                                    ([brep, "--scheduler", address, "--scheduler-timeout", "2"], "has no workers after 2 s")):
                with self.subTest(argument=argument):
                    done = subprocess.run(command[:3] + argument + command[4:], env=env, capture_output=True, text=True,
                                          timeout=120)
                    self.assertEqual(done.returncode, 2, done.stderr[-2000:])
                    self.assertIn(words, done.stderr)
                    self.assertNotIn("Traceback", done.stderr)
        finally:
            cluster.close()


if __name__ == "__main__":
    unittest.main()


class ForkedWorkers(unittest.TestCase):
    """A worker forked from FreeCAD 1.0 meshes a part the parent never meshed: OCCT's parallel mesh waited
    for ever there on the thread pool the parent's TBB arena had before the fork (the study hung)."""

    def test_a_forked_child_finishes_a_part_meshed_nowhere_before(self):
        import signal

        import hsmplanner
        from hsmplanner.app.master_feature import MasterFeatureParameters, make_master_bottom_feature

        feature = make_master_bottom_feature(MasterFeatureParameters(length=131.0, sag=4.5))  # no kept mesh
        child = os.fork()
        if child == 0:  # pragma: no cover - the child's verdict is its exit code
            code = 1
            try:
                signal.alarm(60)  # a hung mesh ends the child with SIGALRM
                moves, stats = hsmplanner.parallel_finishing(feature.shape, feature.bottom_face, angle_deg=20.0,
                                                             tool_diameter=10.0, cusp_height=0.1)
                code = 0 if stats["passes"] > 5 and len(moves) > 100 else 2
            finally:
                os._exit(code)
        _, status = os.waitpid(child, 0)
        self.assertFalse(os.WIFSIGNALED(status), "the forked child hung and was stopped by signal %d"
                         % (os.WTERMSIG(status) if os.WIFSIGNALED(status) else 0))
        self.assertEqual(os.WEXITSTATUS(status), 0, "the forked child failed to finish the part")
