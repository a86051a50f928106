// The sweep's 2-D work on a level laid flat (internal to the roughing): Clipper's offsets and booleans, the
// projection of a mesh along the tool axis, and the keep-out of the tool's centre that the part makes.
#pragma once

#include "geometry/mesh.hpp"
#include "roughing/projection.hpp"

#include <limits>
#include <vector>

namespace hsm::roughing {

cl::Paths offset(const cl::Paths& paths, double mm, double tolerance);
cl::Paths boolean(cl::ClipType type, const cl::Paths& a, const cl::Paths& b);
cl::Paths united(const cl::Paths& pieces);
double area(const cl::Paths& paths);  // mm², holes subtracted
double pathLength(const cl::Path& path);  // mm, open
bool insidePaths(const cl::IntPoint& q, const cl::Paths& paths);
// Distance (mm) from q to the nearest point of the paths' boundaries.
double distanceToBoundary(const cl::IntPoint& q, const cl::Paths& paths);
// Whether the straight segment a–b lies in the paths (within the tolerance, mm).
bool segmentInside(const cl::IntPoint& a, const cl::IntPoint& b, const cl::Paths& paths, double tolerance);
// Points added along each edge longer than `longest` (mm; ∞: none), closed or open paths.
void densify(cl::Paths& paths, double longest, bool closed = true);
// Points of closed paths dropped while each path stays within `tolerance` (mm) of every point it had
// (Douglas–Peucker); paths left with fewer than three points go. Clipper's CleanPolygons drops a point against
// its neighbours of the moment, so on a gently curved outline its drops add up: a pushed-out boundary 0.25 mm
// apart on a blade came down to 19 mm chords cutting 0.1 mm into the clearance.
void simplify(cl::Paths& paths, double tolerance);

// A rectangle of the plane, in Clipper units: what is outside it does not matter for a level.
struct Window {
  double x0 = -std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  bool misses(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) const;
};
Window windowAround(const cl::Paths& paths, double margin);

// The union of the mesh's triangles laid flat, each cut to its part at or above `fromHeight` (−∞: whole).
cl::Paths projectedUnion(const geometry::TriangleMesh& mesh, const Projection& projection, double fromHeight,
                         const Window& window = {});

// An ellipse's semi-axes, true mm, across the plane's x and along its y.
struct Ellipse {
  double across, along;
};

// Steps of the convexity (1/mm) at which a band's keep-out is known: how fast the surface falls away from the
// tool across the plane's x (round the axis of a surface of revolution whose tool axes lean out from it).
inline constexpr double kConvexityStep = 0.005;
// The most steps a band keeps: beyond 0.32/mm (a fall-away radius under 3 mm, a sharp edge's, not a hub's) a
// triangle takes the last one, on the safe side, so a band's work stays bounded whatever the part's edges.
inline constexpr int kMostConvexitySteps = 64;

// A layer of heights along the tool axis, [from, to[, in which the part keeps the tool's centre `clearance`
// true mm away: what the tool (grown by the allowance) is wide at those heights above its tip. Where the surface
// falls away across x by at least k·kConvexityStep, the centre is kept only out of the common part of that disk
// and the ellipse `convex[k − 1]` (narrower across, longer along).
struct Band {
  double from, to, clearance;
  std::vector<Ellipse> convex = {};
};

// Where the tool's centre may not go (as paths to fill non-zero): the part's triangles in each band laid flat,
// grown by the band's keep-out in true mm — over the plane's scales along x and y where each triangle is, and
// where the surface falls away across x by the common part of its disk and ellipse (bins of scales 5 % apart
// and of convexity steps, each bin's union stretched along x to one metric, grown at its triangles' least
// scales and stretched back) — and cut to the bounding rectangle of `within`, the only place that matters.
cl::Paths keepOutOf(const geometry::TriangleMesh& mesh, const Projection& projection, const std::vector<Band>& bands,
                    const Window& window, double tolerance, const cl::Paths& within);

}  // namespace hsm::roughing
