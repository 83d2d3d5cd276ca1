// The example scenes shipped in scenes/ must all parse, build, and be worth looking at.
#include <gtest/gtest.h>

#include <set>

#include "io/scene.hpp"
#include "shape/shape.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(S4D_SOURCE_DIR) / "scenes";

template <int D>
bool finite(const std::vector<Vec<D>>& pts) {
  for (const auto& p : pts)
    if (!p.allFinite()) return false;
  return true;
}

std::size_t element_count(const Shape& s) {
  return std::visit(
      [](const auto& x) -> std::size_t {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
          return finite(x.vertices) ? x.triangles.size() : 0;
        } else {
          for (const auto& c : x.components)
            if (!finite(c.points)) return 0;
          return x.segment_count();
        }
      },
      s);
}

TEST(ExampleScenes, TheDocumentedOnesExist) {
  for (const char* name : {"clifford-torus", "spun-trefoil", "trefoil-ribbon-4d", "trefoil-ribbon-3d",
                           "sphere-and-ribbon", "chain", "trefoil-knot", "cloth"})
    EXPECT_TRUE(std::filesystem::exists(kScenes / (std::string(name) + ".json"))) << name;
}

TEST(ExampleScenes, EveryOneLoadsAndBuilds) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    Scene s;
    try {
      s = load_scene(entry.path());
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ASSERT_FALSE(s.objects.empty());
    std::set<std::string> names;
    for (const SceneObject& o : s.objects) {
      EXPECT_TRUE(names.insert(o.name).second) << "duplicate name " << o.name;
      EXPECT_GT(element_count(o.shape), 0u) << o.name << " is empty or not finite";
    }
    // A nice view of what is in R^4: not the identity frame (the point is to look from an
    // informative angle). Objects of R^3 are drawn as they are, whatever the frame.
    bool in_r4 = false;
    for (const SceneObject& o : s.objects) in_r4 = in_r4 || ambient_dim(o.shape) == 4;
    if (in_r4) {
      EXPECT_GT((s.frame.matrix() - Mat<4>::Identity()).norm(), 0.1);
    }
    EXPECT_LT(s.frame.orthonormality_error(), 1e-12);
  }
  EXPECT_GE(count, 8);
}

}  // namespace
}  // namespace s4d
