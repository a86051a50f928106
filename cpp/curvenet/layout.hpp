// Internal: what every curve of one net shares: the frame, the planes (stations), the boundaries cut by
// those planes, the contact planes, the face to drop points on, and the stop rule.
#pragma once

#include "curvenet/fitting.hpp"
#include "geometry/face_drop.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsm::curvenet::detail {

class Layout {
public:
  // Validates the settings and the boundaries (InputError names the bad one) and places the planes:
  // `stations` if given, else evenly spaced by at most settings.step over the common extent.
  Layout(const Boundaries& boundaries, const NetSettings& settings, std::vector<std::string>& warnings,
         std::optional<std::vector<double>> stations = std::nullopt);

  const Frame& frame() const { return frame_; }
  const NetSettings& settings() const { return settings_; }
  const std::vector<double>& stations() const { return stations_; }
  const PlaneCutter& boundary(int which) const { return which == 1 ? *b1_ : *b2_; }
  std::pair<double, double> commonExtent() const { return {from_, to_}; }
  // Largest distance between the boundaries in the planes, mm.
  double widest() const { return widest_; }

  // Points of a curve of this net in the given planes (the construction points when they match).
  PointArray pointsOn(const NetCurve& curve, const std::vector<double>& stations,
                      std::vector<std::string>& warnings) const;
  // Drops points on the bottom face along the tool axis, if the settings name a face.
  void dropOnFace(PointArray& points, std::vector<std::string>& warnings) const;
  // Stop rule: the candidate comes closer than the minimum gap to the target, or passes it, in a plane
  // where the boundaries do not pinch.
  bool tooClose(const PointArray& start, const PointArray& candidate, const PointArray& target) const;

private:
  Frame makeFrame(std::vector<std::string>& warnings) const;
  void placeStations(std::optional<std::vector<double>> stations);
  void checkBoundaries(std::vector<std::string>& warnings);
  void putBoundariesOnFace(std::vector<std::string>& warnings);

  NetSettings settings_;
  Frame frame_;
  Boundaries input_;
  std::unique_ptr<PlaneCutter> b1_, b2_;
  double from_ = 0.0, to_ = 0.0, widest_ = 0.0;
  std::vector<double> stations_;
  PointArray b1Points_, b2Points_;
  std::vector<char> contact_;  // per station: the boundaries pinch there (ignored by the stop rule)
  std::unique_ptr<geometry::FaceDropper> dropper_;
};

// K must lie in ]0,1[ (InputError names `name` and the fix).
void checkRatio(double k, const char* name);
// Boundary `which` (1 or 2) of the layout as a curve of the net.
NetCurve boundaryCurve(const Layout& layout, int which);
// Eq. 2 in the given planes: P = Pa + K·(Pb − Pa), dropped on the face, fitted.
NetCurve buildCurve(const Layout& layout, const NetCurve& start, const NetCurve& target, double k,
                    const std::vector<double>& stations, std::vector<std::string>& warnings);

// Plane positions evenly spaced by at most `step` over [from, to], both ends included.
std::vector<double> evenStations(double from, double to, double step);

}  // namespace hsm::curvenet::detail
