"""The five-strategy roughing study (the roughing paper's Table 1 and what it could not give), as functions the
example, the FreeCAD panel and scripts share: each strategy's sweeps of every region joined into one program,
simulated by the material-removal model and, posted for a 5-axis machine, by the feed-rate simulator.

Needs FreeCAD's Path module (the posts read Path commands); no document object is created here."""
import inspect
import os
import tempfile
import time

from hsmplanner import feedsim, roughing
from hsmplanner._core import roughing as core

from ..posts import siemens840d_post
from .commands import ProgramSource, sweep_commands

# The paper's Table 1 (impeller, Ø8 r1 torus): V_r %, path mm, in material %, stick-out mm.
PAPER_TABLE = {"S1": (43.1, 3332, 44.1, 57), "S2": (14.1, 2987, 54.4, 49), "S3": (16.0, 3863, 45.6, 47),
         "S4": (19.4, 2758, 56.2, 39), "S5": (9.3, 3343, 66.5, 44)}
COLUMNS = ["strategy", "variant", "paper_vr", "vr", "vr_beyond_allowance", "paper_path_mm", "path_mm", "feed_mm",
           "paper_in_material", "in_material", "in_material_path", "paper_stick_out_mm", "stick_out_mm", "gouge_mm3", "time_s",
           "length_over_feed_s", "rest_time_s", "held_by", "stock_mean_mm", "stock_max_mm", "stock_std_mm", "rapids_fed",
           "rapid_faults", "regions", "step_mm", "resolution_mm", "seconds", "note"]
DEFAULT_MACHINE = "mikron-ucp710-ac-840d"
DEFAULT_FEED_MM_MIN = 2000.0
# The study's variants of a strategy: the paper's one level per slice, step-up levels inside the slices (the
# sweep's default), and step-up followed by a rest roughing with a smaller tool.
PAPER, STEP_UP = "paper", "step-up"


# roughing.sweep's keywords a Rest may set: the others are the study's (the tool, the stock left, the progress).
REST_SWEEP_KEYWORDS = tuple(name for name, p in inspect.signature(roughing.sweep).parameters.items()
                            if p.default is not inspect.Parameter.empty and name not in ("tool", "rest", "progress"))


class Rest:
    """A rest-roughing operation after the first: its cutter (default a Ø4 r0.5 torus), its strategy (default S3,
    its setup direction searched on the stock the first left) and step (default 4 mm, 100 % of Ø4), the spacing
    of the stock-left points it reads (mm), and roughing.sweep's keywords for its sweep (`sweep_settings`, e.g.
    step_up_minimum, step_up_scallop, mesh_deflection: finer levels and mesh leave less for a longer program).
    ValueError for a keyword roughing.sweep does not take."""

    def __init__(self, tool=None, strategy="S3", step=4.0, spacing=0.4, sweep_settings=None):
        self.tool = tool if tool is not None else roughing.cutter("torus", diameter=4.0, corner_radius=0.5,
                                                                  flute_length=15.0, stick_out=30.0)
        self.strategy, self.step, self.spacing = strategy, step, spacing
        if sweep_settings is not None and not isinstance(sweep_settings, dict):
            raise TypeError("rest roughing: sweep_settings must be a dict of roughing.sweep's keywords, not %r"
                            % (sweep_settings,))
        self.sweep_settings = {k: v for k, v in (sweep_settings or {}).items() if v is not None}  # None: default
        unknown = sorted(set(self.sweep_settings) - set(REST_SWEEP_KEYWORDS))
        if unknown:
            raise ValueError("rest roughing: %s is not a sweep setting a rest may set: use %s"
                             % (", ".join(unknown), ", ".join(REST_SWEEP_KEYWORDS)))

    @property
    def label(self):
        settings = ", ".join("%s %s" % (k, "%g" % v if isinstance(v, (int, float)) else v)
                             for k, v in sorted(self.sweep_settings.items()))
        return "step-up + rest %s Ø%g%s" % (self.strategy, self.tool.diameter, " (%s)" % settings if settings else "")


class StrategyResult:
    """One strategy of a study: its table row (COLUMNS), the stock-left map (points, thickness, weight) and the
    stock left as a mesh (points, triangles; empty without a stride)."""

    def __init__(self, row, removal=None):
        self.row = row
        self.removal = removal

    @property
    def stock_map(self):
        r = self.removal
        return (self.row["strategy"], r.surface_points, r.thickness, r.weight) if r is not None else None


def sweep_regions(name, part_brep, stock_brep, solids, tool=None, partition_settings=None, step_up=True, rest=None,
                  progress=None, sweep_settings=None):
    """The strategy `name` swept on every solid (roughing.partition's keywords in `partition_settings`,
    roughing.sweep's in `sweep_settings`), step-up levels or not, cutting only the RestStock `rest` when given:
    the SweepResults. ValueError when a solid lacks the strategy's reference face."""
    settings = dict(partition_settings or {})
    if rest is not None and name == "S3":
        settings["rest"] = rest  # the setup direction that reaches the most of what is left
    swept = []
    for k, solid in enumerate(solids):
        share = (lambda done, k=k: progress((k + done) / len(solids))) if progress else None
        partition = roughing.partition(solid, part_brep, name, progress=share, **settings)
        keywords = {"step_up_minimum": None if step_up else 0.0, **(sweep_settings or {})}
        swept.append(roughing.sweep(partition, solid, part_brep, stock_brep, tool=tool, rest=rest, **keywords))
    return swept


def simulated_time(name, moves, machine, feed_mm_min, program=None):
    """The moves posted for `machine` (our 840D post, TRAORI) and run by the feed-rate simulator: its result.
    `program`: where the posted program is written (a temporary file otherwise)."""
    model = feedsim.load_machine(machine)
    temporary = program is None
    if temporary:
        handle, program = tempfile.mkstemp(suffix=".mpf")
        os.close(handle)
    try:
        siemens840d_post.export([ProgramSource(name, sweep_commands(moves, model, feed_mm_min))], program,
                                "--machine=%s" % machine)
        return feedsim.simulate(program, model)
    finally:
        if temporary:
            os.remove(program)


def study_strategy(name, part_brep, stock_brep, volume, tool=None, resolution=0.2, machine=DEFAULT_MACHINE,
                   feed_mm_min=DEFAULT_FEED_MM_MIN, program=None, stock_mesh_stride=0, progress=None,
                   partition_settings=None, step_up=True, rest=None):
    """The strategy `name` on every region of `volume` (a VolumeToRemove of stock − part), joined into one
    program as a Volume roughing operation of all regions joins them, its rapids kept out of the stock left
    (keep_rapids_out_of_stock): a StrategyResult. `step_up`: intermediate levels inside the slices (False: one
    level per slice, the paper's); `rest` (a Rest): then a rest roughing of what that left, joined and fed the
    same way, simulated after it on the same stock; the time is both programs'. A region without the strategy's
    reference face (S2 without a cylinder) makes the row say why, with no figures. `partition_settings`:
    roughing.partition's keywords (step, setup_resolution_deg, setup_grid; a Roughing volume's own).
    `program`: where the posted 840D program is written (a temporary file otherwise). `progress(done)`, done
    in [0, 1], returns False to cancel (hsmplanner.Cancelled)."""
    start = time.perf_counter()
    row = dict.fromkeys(COLUMNS, "")
    paper = PAPER_TABLE.get(name, ("", "", "", ""))
    row.update(strategy=name, variant=rest.label if rest else STEP_UP if step_up else PAPER, paper_vr=paper[0],
               paper_path_mm=paper[1], paper_in_material=paper[2], paper_stick_out_mm=paper[3],
               resolution_mm=resolution)
    part_of = lambda a, b: (lambda done: progress(a + (b - a) * done)) if progress else None
    settings = dict(partition_settings or {})
    row.update(regions=len(volume.solids), step_mm=settings.get("step") or core.PartitionSettings().step)
    try:
        regions = sweep_regions(name, part_brep, stock_brep, volume.solids, tool, settings, step_up,
                                progress=part_of(0.0, 0.3))
    except ValueError as error:  # no face for this strategy: said in the row, the study goes on
        row["note"] = str(error)
        return StrategyResult(row)
    moves, fed = roughing.keep_rapids_out_of_stock(roughing.join_paths(regions, stock_brep), stock_brep, part_brep,
                                                   tool=tool, resolution=resolution, progress=part_of(0.3, 0.45))
    then, rest_fed = None, []
    if rest is not None:
        left = roughing.simulate_removal(moves, stock_brep, part_brep, tool=tool, resolution=resolution,
                                         rest_spacing=max(rest.spacing, resolution), progress=part_of(0.45, 0.55))
        rest_regions = sweep_regions(rest.strategy, part_brep, stock_brep, volume.solids, rest.tool,
                                     dict(settings, step=rest.step), True, left.rest, progress=part_of(0.55, 0.7),
                                     sweep_settings=rest.sweep_settings)
        rest_moves, rest_fed = roughing.keep_rapids_out_of_stock(
            roughing.join_paths(rest_regions, stock_brep), stock_brep, part_brep, tool=rest.tool,
            resolution=resolution, after=[(moves, tool)], progress=part_of(0.7, 0.8))
        then = [(rest_moves, rest.tool)]
        regions = regions + rest_regions
    removal = roughing.simulate_removal(moves, stock_brep, part_brep, tool=tool, resolution=resolution, then=then,
                                        stock_mesh_stride=stock_mesh_stride, progress=part_of(0.8, 0.95))
    simulated = simulated_time("%s %s" % (name, roughing.STRATEGY_LABELS[name]), moves, machine, feed_mm_min, program)
    total, naive = simulated.summary.total_time, simulated.summary.naive_time
    if then:
        rest_summary = simulated_time("rest %s" % rest.strategy, then[0][0], machine, feed_mm_min).summary
        row["rest_time_s"] = round(rest_summary.total_time, 1)
        # Both programs, as the simulated time is: a bar of the first alone beside both would compare unlike.
        total, naive = total + rest_summary.total_time, naive + rest_summary.naive_time
    shares = feedsim.speed_limit_shares(simulated.summary)
    row.update(vr=round(removal.remaining_share, 1), vr_beyond_allowance=round(removal.beyond_allowance_share, 1),
               path_mm=round(removal.path_length), feed_mm=round(removal.feed_length),
               in_material=round(removal.in_material_share, 1),
               in_material_path=round(removal.in_material_path_share, 1), stick_out_mm=round(removal.stick_out, 1),
               gouge_mm3=round(removal.gouge_volume, 2), time_s=round(total, 1),
               length_over_feed_s=round(naive, 1),
               held_by=", ".join("%s %.0f %%" % (k, 100 * v) for k, v in list(shares.items())[:3]),
               stock_mean_mm=round(removal.thickness_mean, 2), stock_max_mm=round(removal.thickness_max, 2),
               stock_std_mm=round(removal.thickness_std, 2), rapids_fed=len(fed) + len(rest_fed),
               rapid_faults=len(removal.rapid_faults), seconds=round(time.perf_counter() - start, 1),
               note="; ".join(notes_of(regions, fed + rest_fed, removal))[:300])
    if progress:
        progress(1.0)
    return StrategyResult(row, removal)


def notes_of(regions, fed, removal):
    notes = sorted({w for r in regions for w in r.warnings})
    if fed:
        notes.insert(0, roughing.rapid_note(fed))
    if removal.rapid_faults:
        notes.insert(0, "FAULT: %d rapids still cut the stock left (%.2f mm³)" % (len(removal.rapid_faults),
                                                                               removal.rapid_volume))
    return notes


def study(part_brep, stock_brep, strategies=("S1", "S2", "S3", "S4", "S5"), progress=None, **settings):
    """Every strategy of `strategies` (study_strategy's settings), in order: a list of StrategyResult."""
    volume = roughing.volume_to_remove(stock_brep, part_brep)
    results = []
    for k, name in enumerate(strategies):
        low, high = k / len(strategies), (k + 1) / len(strategies)
        share = (lambda done, low=low, high=high: progress(low + (high - low) * done)) if progress else None
        results.append(study_strategy(name, part_brep, stock_brep, volume, progress=share, **settings))
    return results



def add_stock_mesh(document, name, mesh, label=None):
    """The stock left (a RemovalResult's stock_mesh: points, triangles) as a Mesh feature of `document`."""
    import Mesh
    import numpy as np

    points, triangles = (np.asarray(a) for a in mesh)
    feature = document.addObject("Mesh::Feature", name)
    feature.Label = label or name
    feature.Mesh = Mesh.Mesh(points[triangles.reshape(-1, 3)].reshape(-1, 3, 3).tolist())
    return feature
