// Test parts of the roughing tests, each built once per test program: a part, its stock and the volume to
// remove between them.
#pragma once

#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"

namespace hsm::roughing::fixtures {

struct PartCase {
  PartAndStock shapes;
  VolumeToRemove volume;
  explicit PartCase(PartAndStock s) : shapes(std::move(s)), volume(volumeToRemove(shapes.stock, shapes.part)) {}
};

// A slot wide enough for two rings of passes at the paper's engagement (30 mm: 21 mm for the tool's centre).
inline const PartCase& wideSlot() {
  static const PartCase c([] {
    SlantedSlotParameters p;
    p.slotWidth = 30.0;
    p.length = 100.0;
    return slantedSlotBlock(p);
  }());
  return c;
}

inline const PartCase& plainSlot() {
  static const PartCase c(slantedSlotBlock());
  return c;
}

inline const PartCase& impellerCase() {
  static const PartCase c(impeller());
  return c;
}

}  // namespace hsm::roughing::fixtures
