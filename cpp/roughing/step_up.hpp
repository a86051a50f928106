// Intermediate levels inside a slice (internal to the sweep): where the part's wall or floor within a slice is
// not parallel to the slicing surface, the tool's domain widens from the slice's main level (its far side) up
// to its near side, and a tool that stays on the main level leaves a step of material the height of the slice
// on every leaning wall. CAM's "step-up" (or adaptive depth) adds levels between, each cutting only what the
// levels below it left.
#pragma once

#include "roughing/projection.hpp"

#include <functional>
#include <vector>

namespace hsm::roughing {

// The tool's domain at a tip height (the slice's own region less the part's keep-out there). It grows with
// the height: what keeps the tool out at one height keeps it out at every lower one.
using DomainAt = std::function<const cl::Paths&(double tipHeight)>;

// Heights strictly between `low` (the main level) and `high` (the slice's near side) at which intermediate
// levels are cut, highest first: the interval is halved while its halves are at least `minimum` apart and the
// domain grows across it by a band wider than the step it would leave: a band of width w over a height s
// leaves a staircase whose thickness across the wall is s·w/√(s² + w²), kept within `scallop` (mm).
std::vector<double> stepUpHeights(double low, double high, const DomainAt& domainAt, double minimum, double scallop,
                                  double tolerance);

// A pass laid flat: a closed loop, or an open path cut from its first point to its last.
struct FlatPass {
  cl::Path points;
  bool closed = true;
  int ring = 0;
  double depth = 0.0;  // flat mm inward from the domain's boundary: the ring's offset
};

// A level's loops (outside in) and how far inward from the domain's boundary each ring lies.
struct Rings {
  std::vector<cl::Paths> loops;
  std::vector<double> depths;
};

// The loops of a level (`rings`) kept where they run more than `width` mm beyond `cleared` (the
// domain of a level below, already cut: the material above it is gone) and inside `within` (where the tool
// finds stock a previous operation left; null: everywhere): the pieces of each loop there, each lengthened by
// `lead` mm at both ends along the loop into the cleared side (the tool enters and leaves there, out of the
// material), pieces nearer than that joined, a loop wholly there kept closed. Loops are read at points
// `spacing` mm apart.
std::vector<FlatPass> passesBeyond(const Rings& rings, const cl::Paths& cleared, double width, double lead,
                                   double spacing, double tolerance, const cl::Paths* within = nullptr);

}  // namespace hsm::roughing
