// The cutter grown by the allowance, as the sweep keeps the part away from it (internal to the roughing): its
// width at a height above its tip, and what that asks of a part point whose height is measured along its own
// normal where the slicing surface curves up towards the tool (a concave hub: a point ρ from the tool's axis
// stands ρ²·κ/2 higher along the axis than along its own normal).
#pragma once

#include "roughing/flat.hpp"
#include "roughing/sweep.hpp"

#include <vector>

namespace hsm::roughing {

class GrownCutter {
public:
  // `concavity` κ, 1/mm: how the surface curves up towards the tool (0 on planes), the most any way.
  GrownCutter(const Cutter& cutter, double allowance, double concavity);
  // With `concavityAcross`, how it curves up across the plane's x alone (at most κ): on a surface of
  // revolution whose tool axes lean out from its axis the meridian may curve up along y while round the axis
  // the surface falls away, and the ellipses of keepOut(z, convexity) take each way's own.
  GrownCutter(const Cutter& cutter, double allowance, double concavity, double concavityAcross);

  // Half the width of the grown cutter at height z above the tip: 0 below −allowance.
  double width(double z) const;
  // The lowest height above the tip of the cutter grown by `grow` at `rho` from its axis (+∞ beyond it).
  static double lowestAt(const Cutter& cutter, double grow, double rho);
  // The farthest from the axis (mm) a part point at height z (along its own normal) meets the grown cutter:
  // the centre keeps that far from it. 0 where it never does.
  double keepOut(double z) const;
  // Where the surface also falls away across the plane's x by `convexity` (1/mm): a point x across the tool's
  // line stands x²·convexity/2 lower along the axis, where the corner is narrower, so the points meeting the
  // grown cutter fill the disk keepOut(z) less and less towards its ends across (|y| ≤ a reach falling with
  // |x|). An ellipse that holds them all: together with that disk (their common part), the keep-out, nearly
  // exact across. The one whose common part with the disk is least; the disk where the surface does not fall
  // away across x faster than it curves up across x or no ellipse is narrower across.
  Ellipse keepOut(double z, double convexity) const;
  // The least height of the tip above a floor parallel to the slicing surface, beyond the allowance, at which
  // no point of the floor under the tool meets it: where κ > 0 the floor rises under the flat bottom's rim.
  double floorLift() const;
  // Bands of heights relative to the tip, [from, to[, each with the keep-out of its highest point, stepping
  // evenly in keep-out from the lowest point's to the flutes' (R + a), the last one open above; `slack` raises the lowest
  // (a floor lying exactly the allowance under the tip must not shadow the level), `extra` grows them all.
  // Where the level's tip surface falls away across x by up to `convexity`, the bands below the corner have
  // their ellipses for the convexity steps up to that, and are at most 0.25 mm thick.
  std::vector<Band> bands(int count, double slack, double extra, double convexity = 0.0) const;

private:
  // How far along y a point x across the tool's line meets the grown cutter, every kAcrossStep of x from the
  // line until none does (x the index times the step): falling, since across the surface falls away.
  std::vector<double> reachAlong(double z, double convexity) const;

  Cutter cutter_;
  double allowance_, concavity_, across_;
};

}  // namespace hsm::roughing
