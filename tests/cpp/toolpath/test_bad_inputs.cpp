// Finishing on inputs that once crashed, hung or gouged: each must end in an error that names the
// input, or in a toolpath the independent checks accept.
#include "common/error.hpp"
#include "support/master_feature.hpp"
#include "toolpath/finishing.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace hsm;
using namespace hsm::geometry;
using namespace hsm::toolpath;

namespace {
constexpr auto feature = test::masterFeature;

FinishingSettings ball(double diameter = 4.0) {
  FinishingSettings s;
  s.toolRadius = 0.5 * diameter;
  return s;
}

// The message of the InputError `call` throws (fails the test when it throws nothing or something else).
template <class Call>
std::string inputError(Call&& call) {
  try {
    call();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not an InputError: " << error.what();
    return {};
  }
  ADD_FAILURE() << "no error";
  return {};
}
}  // namespace

TEST(FinishingBadInputs, VerticalWallsAreRefusedByName) {
  for (int wall : {1, 7, 9, 10}) {
    const std::string message = inputError([&] { parallelPlaneFinishing(feature().shape, wall, 0.0, ball()); });
    EXPECT_NE(message.find("Face" + std::to_string(wall)), std::string::npos) << message;
    EXPECT_NE(message.find("vertical"), std::string::npos) << message;
  }
}

TEST(FinishingBadInputs, LargeBallsAreComputedOrRefused) {
  for (double diameter : {60.0}) {  // 55 mm fits between the walls; 60 no longer (it crashed)
    try {
      const Toolpath path = parallelPlaneFinishing(feature().shape, 4, 0.0, ball(diameter));
      for (const Move& m : path.moves) ASSERT_TRUE(m.point.allFinite());
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("tool"), std::string::npos) << error.what();
    }
  }
}

TEST(FinishingBadInputs, TheUnderside8IsRefusedAndProgressCanCancel) {
  const std::string message = inputError([&] { parallelPlaneFinishing(feature().shape, 8, 0.0, ball()); });
  EXPECT_NE(message.find("Face8 faces down"), std::string::npos) << message;
  FinishingSettings s = ball();
  std::vector<double> seen;
  s.progress = [&](double done) {
    seen.push_back(done);
    return done < 0.25;
  };
  EXPECT_THROW(parallelPlaneFinishing(feature().shape, 4, 0.0, s), hsm::Cancelled);
  ASSERT_FALSE(seen.empty());
  EXPECT_GE(seen.back(), 0.25);
  for (size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k], seen[k - 1]) << "progress goes back";
}
