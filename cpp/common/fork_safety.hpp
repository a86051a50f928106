#pragma once
// Whether OCCT may run its own thread pool here.
//
// OCCT's parallel algorithms (BRepMesh's face-parallel meshing) run on a TBB arena. A process forked after
// TBB started — FreeCAD 1.0's booleans start it — inherits an arena whose worker threads did not survive the
// fork, and the first parallel mesh in the child waits for them for ever (the strategy study's worker
// processes hung so). In a forked child OCCT runs serially; our own threads (common/parallel.hpp) are made
// per call and are safe there.
namespace hsm {

// True in a process forked from the one that loaded the core.
bool inForkedChild();

// OCCT's "in parallel" flag for this process.
inline bool occtMayRunInParallel() { return !inForkedChild(); }

}  // namespace hsm
