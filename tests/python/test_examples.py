"""The examples run from freecadcmd as a user runs them, and write what they promise."""
import json
import re
import os
import unittest

import Part

import hsmplanner

from helpers import REPO, run, temporary_directory


class MasterBottomFeatureExample(unittest.TestCase):
    def test_writes_document_step_brep_summary_and_picture(self):
        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "master_bottom_feature.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-2000:])
        base = os.path.join(out, "master_bottom_feature")
        with open(base + ".json") as stream:
            summary = json.load(stream)
        self.assertLess(summary["boundary_1_detail"]["min_plan_radius_mm"], 10.0)
        self.assertTrue(summary["boundary_1_detail"]["inflections_at_mm"])
        step = Part.read(base + ".step")
        self.assertAlmostEqual(hsmplanner.shape_summary(step).volume, summary["volume_mm3"], delta=1.0)
        brep = Part.Shape()
        brep.read(base + ".brep")
        self.assertAlmostEqual(brep.getElement(summary["bottom_face"]).Area, summary["bottom_area_mm2"], delta=0.1)
        with open(base + ".png", "rb") as stream:
            self.assertEqual(stream.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertGreater(os.path.getsize(base + ".FCStd"), 10000)

    def test_unwritable_output_folder_fails_with_a_message(self):
        blocker = os.path.join(temporary_directory(self), "a-file")
        open(blocker, "w").close()
        result = run(["freecadcmd", os.path.join(REPO, "examples", "master_bottom_feature.py"),
                      os.path.join(blocker, "out")])
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("error:", result.stderr + result.stdout)


class CurveNetsExample(unittest.TestCase):
    def test_writes_the_tables_as_csv_and_pictures(self):
        import csv

        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "curve_nets.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-2000:])
        with open(os.path.join(out, "curve_nets.csv")) as stream:
            rows = list(csv.DictReader(stream))
        by_key = {(r["building_direction"], r["K"], r["P_mm"]): r for r in rows}
        self.assertEqual(by_key[("b1_to_b2", "0.25", "5.0")]["intermediate_curves"], "9")
        self.assertEqual(by_key[("boundaries_to_median", "0.25", "5.0")]["composed_areas"], "2 4 6 8 10 12 14")
        self.assertEqual(by_key[("4-step method", "0.5 / 0.75", "adapted")]["elementary_areas"], "4")
        for name in ("curve_nets_table1.png", "curve_nets_table2.png", "curve_nets_4step.png"):
            with open(os.path.join(out, name), "rb") as stream:
                self.assertEqual(stream.read(4), b"\x89PNG")


class GuidanceStudyExample(unittest.TestCase):
    def test_the_main_job_writes_programs_table_and_pictures(self):
        import csv

        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "guidance_study.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-3000:] + result.stderr[-2000:])
        with open(os.path.join(out, "study.csv")) as stream:
            rows = list(csv.DictReader(stream))
        self.assertEqual(len(rows), 15)  # 5 strategies x 3 feeds
        by = {(r["strategy"], r["feed_mm_min"]): r for r in rows}
        self.assertEqual(by[("guide_4_areas", "4000")]["areas"], "4")
        self.assertEqual(by[("guide_14_areas", "4000")]["areas"], "14")
        for strategy in ("parallel_planes", "guide_1_area"):
            times = [float(by[(strategy, f)]["machining_time_s"]) for f in ("2000", "4000", "6000")]
            self.assertTrue(times[0] > times[1] > times[2], times)  # faster feeds, less time
            for f in ("2000", "4000", "6000"):  # never faster than length / feed
                self.assertGreater(float(by[(strategy, f)]["machining_time_s"]),
                                   float(by[(strategy, f)]["length_over_feed_s"]))
            with open(os.path.join(out, "study_%s_F4000.mpf" % strategy)) as stream:
                self.assertIn("CYCLE832(0.01,1,1)", stream.read(2000))
        for name in ("study_times.png", "study_guide_4_areas_map.png", "study_parallel_planes_histograms.png"):
            with open(os.path.join(out, name), "rb") as stream:
                self.assertEqual(stream.read(4), b"\x89PNG")


class MachiningDirectionExample(unittest.TestCase):
    def test_both_cases_with_the_validation(self):
        import csv
        import math

        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "machining_direction.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-3000:] + result.stderr[-2000:])
        with open(os.path.join(out, "direction_case1_feeds.csv")) as stream:
            case1 = [(float(r["feed_mm_min"]), float(r["optimal_deg"])) for r in csv.DictReader(stream)]
        switching = math.sqrt(15.0 * 3000.0) * 60.0  # √((R + Ro)·a), mm/min
        self.assertTrue(all(angle == 0.0 for feed, angle in case1 if feed < switching), case1)
        self.assertTrue(all(angle != 0.0 for feed, angle in case1 if feed > switching), case1)
        with open(os.path.join(out, "direction_case2_validation.csv")) as stream:
            case2 = list(csv.DictReader(stream))
        self.assertEqual([float(r["angle_deg"]) for r in case2], [float(a) for a in range(0, 181, 10)])
        for row in case2:
            self.assertGreater(float(row["simulated_s"]), float(row["length_over_feed_s"]))
        fastest = min(case2, key=lambda r: float(r["simulated_s"]))
        self.assertIn("fastest simulated %.0f°" % float(fastest["angle_deg"]), result.stdout)
        for name in ("direction_case1_feeds.png", "direction_case2.png", "direction_case2_validation.png"):
            with open(os.path.join(out, name), "rb") as stream:
                self.assertEqual(stream.read(4), b"\x89PNG")


if __name__ == "__main__":
    unittest.main()


class RoughingStudyExample(unittest.TestCase):
    def test_strategies_as_the_paper_with_step_up_and_rest_roughing_simulated(self):
        # The example's own quick options: one channel of the impeller, S1 and S5, at 0.4 mm (make demo runs
        # every channel and strategy at 0.2 mm; regions joined into one program are the GUI tests' and
        # RoughingPathsExample's).
        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "roughing_study.py"), out, "channels=1",
                      "strategies=S1,S5", "resolution=0.4"])
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-2000:])
        import csv
        with open(os.path.join(out, "roughing_study.csv")) as stream:
            rows = list(csv.DictReader(stream))
        rest = "step-up + rest S3 Ø4"
        self.assertEqual([(r["strategy"], r["variant"]) for r in rows],
                         [(s, v) for s in ("S1", "S5") for v in ("paper", "step-up", rest)])
        for row in rows:
            self.assertEqual(float(row["gouge_mm3"]), 0.0, row)
            self.assertEqual(float(row["resolution_mm"]), 0.4, row)
            self.assertTrue(0.0 < float(row["vr_beyond_allowance"]) < float(row["vr"]) < 100.0, row)
            self.assertGreater(float(row["stick_out_mm"]), 0.0, row)
            self.assertTrue(0.0 < float(row["in_material"]) <= 100.0, row)
            self.assertTrue(0.0 < float(row["in_material_path"]) < float(row["in_material"]), row)
            self.assertGreater(float(row["time_s"]), float(row["length_over_feed_s"]) * 0.99, row)
            self.assertGreaterEqual(float(row["stock_mean_mm"]), 0.45, row)
            # No rapid of the joined programs takes material out of the stock left (the approaches that would
            # have are fed in), the rest roughing's on what the first left.
            self.assertEqual(int(row["rapid_faults"]), 0, row)
            self.assertEqual(int(row["regions"]), 1, row)
        by = {(r["strategy"], r["variant"]): r for r in rows}
        for strategy in ("S1", "S5"):  # a rest row's length / feed is both programs', as its time is
            self.assertGreater(float(by[(strategy, rest)]["length_over_feed_s"]),
                               float(by[(strategy, "step-up")]["length_over_feed_s"]))
        for strategy in ("S1", "S5"):
            paper, stepped, rested = [r for r in rows if r["strategy"] == strategy]
            # Each variant leaves less beyond the allowance than the one before, and costs more time.
            self.assertLess(float(stepped["vr_beyond_allowance"]), float(paper["vr_beyond_allowance"]), strategy)
            self.assertLess(float(rested["vr_beyond_allowance"]), float(stepped["vr_beyond_allowance"]), strategy)
            self.assertGreater(float(stepped["time_s"]), float(paper["time_s"]), strategy)
            self.assertGreater(float(rested["rest_time_s"]), 0.0, strategy)
            self.assertAlmostEqual(float(rested["time_s"]) - float(rested["rest_time_s"]), float(stepped["time_s"]),
                                   delta=0.15, msg=strategy)
        # The continuous 5-axis strategy needs less stick-out than Z-level roughing (the paper's S5: 44 mm, S1 57).
        stick = {(r["strategy"], r["variant"]): float(r["stick_out_mm"]) for r in rows}
        self.assertLess(stick[("S5", "paper")], stick[("S1", "paper")])
        import Mesh
        left = Mesh.Mesh(os.path.join(out, "roughing_study_S5_stock.stl"))
        self.assertGreater(left.CountFacets, 1000)
        self.assertGreater(left.Volume, 0.0)
        self.assertTrue(os.path.getsize(os.path.join(out, "roughing_study.FCStd")) > 10000)
        for picture in ("roughing_study_stock.png", "roughing_study_bars.png", "roughing_study_pareto.png"):
            with open(os.path.join(out, picture), "rb") as stream:
                self.assertEqual(stream.read(8), b"\x89PNG\r\n\x1a\n")
        bad = run(["freecadcmd", os.path.join(REPO, "examples", "roughing_study.py"), out, "chanels=2"])
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn("unknown option chanels", bad.stdout + bad.stderr)


class RoughingPathsExample(unittest.TestCase):
    def test_sweeps_checks_posts_and_simulates_each_strategy(self):
        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "roughing_paths.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-2000:])
        import csv
        with open(os.path.join(out, "roughing_paths.csv")) as stream:
            rows = list(csv.DictReader(stream))
        self.assertEqual([(r["part"], r["strategy"]) for r in rows],
                         [(part, s) for part in ("impeller", "slot") for s in ("S1", "S2", "S3", "S4", "S5")])
        swept = [r for r in rows if r["passes"]]
        self.assertEqual(len(swept), 9, "all but S2 on the slot block (no cylindrical crossable face)")
        self.assertIn("S2 needs a cylindrical crossable face", rows[6]["note"])
        for row in swept:
            self.assertEqual(row["too_close"], "0", row)
            self.assertGreaterEqual(float(row["closest_mm"]), 0.49, row)
            self.assertGreater(float(row["840d_time_s"]), float(row["840d_length_over_feed_s"]) * 0.99, row)
            for key, suffix in (("840d", ".mpf"), ("linuxcnc", ".ngc")):
                name = "roughing_%s_%s_%s%s" % (row["part"], row["strategy"], key, suffix)
                self.assertTrue(os.path.getsize(os.path.join(out, name)) > 500, name)
        self.assertIn("C ", rows[1]["840d_held_by"], "S2 turns C about the impeller's axis")
        # S4 and S5 on the impeller are continuous 5-axis paths: the axis turns tens of degrees, and the rotary
        # axes hold the speed; S1 and S3 keep one axis.
        for row in rows[3:5]:
            self.assertGreater(float(row["axis_spread_deg"]), 20.0, row)
            self.assertIn("A ", row["840d_held_by"], row)
        for row in (rows[0], rows[2]):
            self.assertEqual(float(row["axis_spread_deg"]), 0.0, row)
        for picture in ("roughing_paths.png", "roughing_paths_slot.png"):
            with open(os.path.join(out, picture), "rb") as stream:
                self.assertEqual(stream.read(8), b"\x89PNG\r\n\x1a\n")


class StrategyStudyExample(unittest.TestCase):
    def test_forty_variants_ranked_with_the_pareto_front_and_k_refined(self):
        out = temporary_directory(self)
        result = run(["freecadcmd", os.path.join(REPO, "examples", "strategy_study.py"), out])
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-2000:])
        with open(os.path.join(out, "strategy_study.json")) as stream:
            rows = json.load(stream)
        self.assertEqual(len(rows), 40)
        self.assertEqual([r["name"] for r in rows if r["error"]], [])
        self.assertEqual({r["strategy"] for r in rows}, {"planes", "guide", "4-step"})
        for row in rows:  # the machine never beats length / feed, and the five classes share all the time
            self.assertGreater(row["time_s"], row["length_over_feed_s"], row["name"])
            shares = sum(row[k] for k in row if k.startswith("time_share_"))
            self.assertAlmostEqual(shares, 1.0, places=6, msg=row["name"])
        with open(os.path.join(out, "strategy_study_ranked.txt")) as stream:
            report = stream.read()
        self.assertIn("Pareto front", report)
        refined = [line for line in report.splitlines() if line.strip().startswith("best K =")]
        self.assertEqual(len(refined), 1, report[-1500:])
        best_s, start_s = (float(x) for x in re.findall(r": ([0-9.]+) s", refined[0]))
        self.assertLessEqual(best_s, start_s, "the refinement starts from the grid's best K: never worse")
        for picture in ("strategy_study.png", "strategy_study_maps.png"):
            with open(os.path.join(out, picture), "rb") as stream:
                self.assertEqual(stream.read(8), b"\x89PNG\r\n\x1a\n")
