#include "bindings/bindings.hpp"

#include "common/error.hpp"
#include "geometry/brep.hpp"
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace hsm::bindings {

namespace {
using namespace roughing;

std::string compoundBrep(const VolumeToRemove& v) {
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const RemovalSolid& s : v.solids) builder.Add(compound, s.solid);
  return geometry::writeBrep(compound);
}

void bindEnums(py::module_& m) {
  py::enum_<FaceClass>(m, "FaceClass", "What the tool may do with a face of the volume to remove")
      .value("crossable", FaceClass::Crossable, "stock skin: the tool may pass through it")
      .value("facing_crossable", FaceClass::FacingCrossable, "part face vis-à-vis a crossable face (the hub)")
      .value("not_crossable", FaceClass::NotCrossable, "part face (blade sides, walls)");
  py::enum_<SurfaceKind>(m, "SurfaceKind")
      .value("plane", SurfaceKind::Plane)
      .value("cylinder", SurfaceKind::Cylinder)
      .value("revolution", SurfaceKind::Revolution)
      .value("other", SurfaceKind::Other);
  py::enum_<Strategy>(m, "Strategy", "The roughing paper's five slicings of the volume")
      .value("S1", Strategy::PlanesParallelToFace, "planes parallel to a planar crossable face (3 axes)")
      .value("S2", Strategy::CoaxialCylinders, "cylinders coaxial with a cylindrical crossable face (4 axes)")
      .value("S3", Strategy::SetupPlanes, "planes normal to the computed setup direction (3+2 axes)")
      .value("S4", Strategy::StockOffsets, "offsets of the stock skin (5 axes)")
      .value("S5", Strategy::HubOffsets, "offsets of the facing_crossable face, the hub (5 axes)");
}

void bindVolume(py::module_& m) {
  py::class_<RemovalSolid>(m, "RemovalSolid", "One solid of the volume to remove, its faces and their classes")
      .def_readonly("volume", &RemovalSolid::volume, "mm³")
      .def_readonly("face_classes", &RemovalSolid::faceClasses, "per face (Face1, Face2…)")
      .def_readonly("face_kinds", &RemovalSolid::faceKinds, "per face")
      .def_readonly("face_areas", &RemovalSolid::faceAreas, "per face, mm²")
      .def_readonly("face_groups", &RemovalSolid::faceGroups, "per face: its surface, 0, 1, …")
      .def_property_readonly("group_count", &RemovalSolid::groupCount, "surfaces (the paper's faces)")
      .def("group_area", &RemovalSolid::groupArea, py::arg("group"), "mm²")
      .def_property_readonly("brep", [](const RemovalSolid& s) { return geometry::writeBrep(s.solid); });
  py::class_<VolumeToRemove>(m, "VolumeToRemove", "stock − part, one solid per region, largest first")
      .def_readonly("solids", &VolumeToRemove::solids)
      .def_readonly("volume", &VolumeToRemove::volume, "mm³, Σ solids")
      .def_readonly("stock_volume", &VolumeToRemove::stockVolume, "mm³")
      .def_readonly("part_volume", &VolumeToRemove::partVolume, "mm³")
      .def_readonly("fuzzy_retry", &VolumeToRemove::fuzzyRetry, "the plain cut failed its checks, the fuzzy one passed")
      .def_readonly("warnings", &VolumeToRemove::warnings)
      .def_property_readonly("brep", &compoundBrep, "the solids as one compound");
  m.def(
      "volume_to_remove",
      [](const std::string& stockBrep, const std::string& partBrep, const py::object& progress) {
        const TopoDS_Shape stock = geometry::readBrep(stockBrep), part = geometry::readBrep(partBrep);
        const ProgressCallback callback = progressCallback(progress);
        py::gil_scoped_release release;
        return guarded("stock − part", [&] { return volumeToRemove(stock, part, callback); });
      },
      py::arg("stock_brep"), py::arg("part_brep"), py::arg("progress") = py::none(),
      "stock − part, checked (volumes, validity, one fuzzy retry), faces classed");
  m.def("cut_problem", [](const std::string& resultBrep, double expected) {
    return cutProblem(geometry::readBrep(resultBrep), expected); }, py::arg("result_brep"), py::arg("expected_volume"),
        "What is wrong with a boolean's result that should be `expected_volume` mm³ of solids ('' when nothing)");
}

void bindPartition(py::module_& m) {
  py::class_<PartitionSettings>(m, "PartitionSettings", "Slicing of the volume (mm, degrees)")
      .def(py::init<>())
      .def_readwrite("step", &PartitionSettings::step, "mm between slicing surfaces (axial engagement)")
      .def_readwrite("setup_resolution_deg", &PartitionSettings::setupResolutionDeg, "S3: directions every …°")
      .def_readwrite("setup_grid", &PartitionSettings::setupGrid, "S3: points of the volume every … mm")
      .def_readwrite("threads", &PartitionSettings::threads, "S3's search: threads (0: all cores)")
      .def_readwrite("rest", &PartitionSettings::rest, "S3: the direction reaching the most of this rest stock");
  py::class_<SlicingSurface>(m, "SlicingSurface", "The surface a sub-volume starts on")
      .def_readonly("kind", &SlicingSurface::kind)
      .def_readonly("origin", &SlicingSurface::origin, "mm")
      .def_readonly("direction", &SlicingSurface::direction, "plane normal or cylinder axis")
      .def_readonly("radius", &SlicingSurface::radius, "cylinder, mm")
      .def_readonly("reference_face", &SlicingSurface::referenceFace, "1-based face the offsets follow")
      .def_readonly("offset", &SlicingSurface::offset, "mm from the reference surface");
  py::class_<SubVolume>(m, "SubVolume")
      .def_readonly("volume", &SubVolume::volume, "mm³")
      .def_readonly("slice", &SubVolume::slice, "0 at the reference surface, then inwards")
      .def_readonly("surface", &SubVolume::surface)
      .def_readonly("axis_points", &SubVolume::axisPoints, "mm")
      .def_readonly("axis_directions", &SubVolume::axisDirections, "unit tool axes at axis_points")
      .def_property_readonly("brep", [](const SubVolume& s) { return geometry::writeBrep(s.shape); });
  py::class_<Partition>(m, "Partition")
      .def_readonly("strategy", &Partition::strategy)
      .def_readonly("step", &Partition::step, "mm")
      .def_readonly("reference_face", &Partition::referenceFace, "1-based, 0 for S3")
      .def_readonly("setup_direction", &Partition::setupDirection, "S3: the tool axis")
      .def_readonly("setup_reach", &Partition::setupReach, "S3: share of the volume reached along it")
      .def_readonly("sub_volumes", &Partition::subVolumes)
      .def_readonly("volume", &Partition::volume, "mm³, Σ sub-volumes")
      .def_readonly("warnings", &Partition::warnings);
  auto withProgress = [](PartitionSettings settings, const py::object& progress) {
    settings.progress = progressCallback(progress);
    return settings;
  };
  m.def(
      "partition",
      [withProgress](const RemovalSolid& solid, const std::string& partBrep, Strategy strategy,
                     const PartitionSettings& settings, const py::object& progress) {
        const TopoDS_Shape part = geometry::readBrep(partBrep);
        const PartitionSettings s = withProgress(settings, progress);
        py::gil_scoped_release release;
        return guarded("partition", [&] { return partition(solid, part, strategy, s); });
      },
      py::arg("solid"), py::arg("part_brep"), py::arg("strategy"), py::arg("settings"), py::arg("progress") = py::none());
  m.def(
      "setup_direction",
      [withProgress](const RemovalSolid& solid, const std::string& partBrep, const PartitionSettings& settings,
                     const py::object& progress) {
        const TopoDS_Shape part = geometry::readBrep(partBrep);
        const PartitionSettings s = withProgress(settings, progress);
        py::gil_scoped_release release;
        return guarded("setup direction", [&] { return setupDirection(solid, part, s); });
      },
      py::arg("solid"), py::arg("part_brep"), py::arg("settings"), py::arg("progress") = py::none(),
      "(direction, reached share): S3's fixed tool axis");
  m.def(
      "reachable_share",
      [](const RemovalSolid& solid, const std::string& partBrep, const Eigen::Vector3d& direction,
         const PartitionSettings& settings) {
        const TopoDS_Shape part = geometry::readBrep(partBrep);
        py::gil_scoped_release release;
        return guarded("reach", [&] { return reachableShare(solid, part, direction, settings); });
      },
      py::arg("solid"), py::arg("part_brep"), py::arg("direction"), py::arg("settings"));
}

void bindTestParts(py::module_& m) {
  py::class_<PartAndStock>(m, "PartAndStock")
      .def_property_readonly("part_brep", [](const PartAndStock& p) { return geometry::writeBrep(p.part); })
      .def_property_readonly("stock_brep", [](const PartAndStock& p) { return geometry::writeBrep(p.stock); });
  py::class_<SlantedSlotParameters>(m, "SlantedSlotParameters", "mm and degrees")
      .def(py::init<>())
      .def_readwrite("length", &SlantedSlotParameters::length)
      .def_readwrite("width", &SlantedSlotParameters::width)
      .def_readwrite("height", &SlantedSlotParameters::height)
      .def_readwrite("slot_width", &SlantedSlotParameters::slotWidth)
      .def_readwrite("slot_depth", &SlantedSlotParameters::slotDepth)
      .def_readwrite("tilt_deg", &SlantedSlotParameters::tiltDeg);
  py::class_<ImpellerParameters>(m, "ImpellerParameters", "mm and degrees")
      .def(py::init<>())
      .def_readwrite("blades", &ImpellerParameters::blades)
      .def_readwrite("hub_inlet_radius", &ImpellerParameters::hubInletRadius)
      .def_readwrite("outlet_radius", &ImpellerParameters::outletRadius)
      .def_readwrite("height", &ImpellerParameters::height)
      .def_readwrite("channel_height", &ImpellerParameters::channelHeight)
      .def_readwrite("lean_deg", &ImpellerParameters::leanDeg)
      .def_readwrite("wrap_deg", &ImpellerParameters::wrapDeg)
      .def_readwrite("thickness", &ImpellerParameters::thickness)
      .def_readwrite("base_thickness", &ImpellerParameters::baseThickness);
  m.def("slanted_slot_block", [](const SlantedSlotParameters& p) {
    return guarded("slanted slot block", [&] { return slantedSlotBlock(p); }); }, py::arg("parameters"));
  m.def("slanted_slot_volume", &slantedSlotVolume, py::arg("parameters"), "its volume to remove in closed form, mm³");
  m.def("impeller", [](const ImpellerParameters& p) {
    py::gil_scoped_release release;
    return guarded("impeller", [&] { return impeller(p); }); }, py::arg("parameters"));
}
}  // namespace

void bindRoughing(py::module_& module) {
  py::module_ m = module.def_submodule("roughing", "5-axis roughing by volume partitioning (cpp/roughing)");
  bindEnums(m);
  bindVolume(m);
  bindPartition(m);
  bindTestParts(m);
  bindSweep(m);
}

}  // namespace hsm::bindings
