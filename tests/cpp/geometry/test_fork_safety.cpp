// A forked child knows it is one (and so runs OCCT serially) and still meshes; the parent is not flagged.
// The hang itself needs FreeCAD's state before the fork: tests/python/test_study.py reproduces it.
#include "common/fork_safety.hpp"
#include "geometry/mesh.hpp"

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace {

TEST(ForkSafety, AForkedChildMeshesAndKnowsItIsOne) {
  EXPECT_FALSE(hsm::inForkedChild());
  // the parent's parallel mesh starts OCCT's thread pool, as FreeCAD's own work does before a study forks
  ASSERT_FALSE(hsm::geometry::meshFaces(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), 0.1).triangles.empty());
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(60);  // a hung mesh ends the child with SIGALRM, which the parent reports
    const bool flagged = hsm::inForkedChild();
    const auto mesh = hsm::geometry::meshFaces(BRepPrimAPI_MakeSphere(5.0).Shape(), 0.01);
    _exit(flagged && !mesh.triangles.empty() ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the forked child did not end by itself (signal "
                                 << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << ")";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the child was not flagged as forked, or gave no mesh";
  EXPECT_FALSE(hsm::inForkedChild());
}

}  // namespace
