// The generator registry: names, defaults, validation messages and the "name:k=v" syntax.
#include "shape/generators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "core/error.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

std::string error_of(std::string_view name, const Params& p) {
  try {
    generate(name, p);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Generators, CatalogueHasTheAgreedNamesInMenuOrder) {
  std::vector<std::string> names;
  for (const auto& g : generator_catalogue()) names.push_back(g.name);
  const std::vector<std::string> expected{"torus-knot", "figure-eight",   "trefoil-ribbon",
                                          "trefoil-ribbon-3d", "cloth", "clifford-torus",
                                          "sphere",     "spun-trefoil",  "ribbon-loop", "chain"};
  EXPECT_EQ(names, expected);
  EXPECT_NE(find_generator("spun-trefoil"), nullptr);
  EXPECT_EQ(find_generator("spun-trefoil")->dim, 4);
  EXPECT_EQ(find_generator("nope"), nullptr);
}

TEST(Generators, SpecsAreSane) {
  for (const auto& g : generator_catalogue()) {
    std::set<std::string> seen;
    EXPECT_FALSE(g.description.empty()) << g.name;
    for (const auto& p : g.params) {
      EXPECT_TRUE(seen.insert(p.name).second) << g.name << "." << p.name;
      EXPECT_LE(p.min, p.default_value) << g.name << "." << p.name;
      EXPECT_LE(p.default_value, p.max) << g.name << "." << p.name;
      if (p.integer) {
        EXPECT_EQ(p.default_value, std::floor(p.default_value));
      }
      EXPECT_FALSE(p.help.empty());
    }
  }
}

TEST(Generators, EveryDefaultBuildsTheAdvertisedKind) {
  for (const auto& g : generator_catalogue()) {
    const Shape s = generate(g.name);
    EXPECT_EQ(ambient_dim(s), g.dim) << g.name;
    EXPECT_EQ(is_surface(s), g.surface) << g.name;
    if (const auto* surf = std::get_if<Surface<4>>(&s)) {
      const auto t = summarize_topology(*surf);
      EXPECT_TRUE(t.manifold) << g.name;
    }
  }
}

TEST(Generators, ExpectedTopologyOfEachSurface) {
  auto chi = [](const Shape& s) {
    return std::visit(
        [](const auto& x) -> int {
          if constexpr (requires { x.triangles; }) return summarize_topology(x).euler_characteristic;
          else return -100;
        },
        s);
  };
  EXPECT_EQ(chi(generate("clifford-torus")), 0);
  EXPECT_EQ(chi(generate("sphere")), 2);
  EXPECT_EQ(chi(generate("spun-trefoil")), 2);
  EXPECT_EQ(chi(generate("ribbon-loop")), 0);
  EXPECT_EQ(chi(generate("trefoil-ribbon")), 1);
  EXPECT_EQ(chi(generate("cloth")), 1);
  EXPECT_EQ(chi(generate("chain", {{"links", 3}})), 4);
}

TEST(Generators, ParamsReachTheBuilder) {
  const auto s = std::get<Surface<4>>(generate("clifford-torus", {{"n", 10}, {"m", 7}}));
  EXPECT_EQ(s.vertex_count(), 70u);
  const auto c = std::get<Curve<3>>(generate("torus-knot", {{"p", 2}, {"q", 4}, {"n", 100}}));
  EXPECT_EQ(c.components.size(), 2u);
  const auto sph = std::get<Surface<4>>(generate("sphere", {{"radius", 3}}));
  EXPECT_NEAR(sph.vertices[0].norm(), 3.0, 1e-12);
}

TEST(Generators, ValidationErrorsNameTheCulprit) {
  EXPECT_NE(error_of("no-such-thing", {}).find("unknown generator 'no-such-thing'"), std::string::npos);
  EXPECT_NE(error_of("sphere", {{"colour", 1}}).find("unknown parameter 'colour'"), std::string::npos);
  EXPECT_NE(error_of("sphere", {{"n", std::nan("")}}).find("finite"), std::string::npos);
  EXPECT_NE(error_of("sphere", {{"radius", std::numeric_limits<double>::infinity()}}).find("finite"),
            std::string::npos);
  EXPECT_NE(error_of("cloth", {{"n", 100000}}).find("outside [2, 2048]"), std::string::npos);
  EXPECT_NE(error_of("cloth", {{"n", 1}}).find("outside"), std::string::npos);
  EXPECT_NE(error_of("cloth", {{"n", 12.5}}).find("whole number"), std::string::npos);
  EXPECT_NE(error_of("trefoil-ribbon", {{"width", 3}}).find("width"), std::string::npos);
  // Cross-parameter checks from the builders carry the generator's name.
  EXPECT_EQ(error_of("torus-knot", {{"R", 1}, {"r", 2}}).rfind("torus-knot:", 0), 0u);
  EXPECT_EQ(error_of("ribbon-loop", {{"radius", 0.1}, {"width", 1}}).rfind("ribbon-loop:", 0), 0u);
  EXPECT_NE(error_of("torus-knot", {{"p", 7}, {"q", 9}, {"n", 20}}).find("n >= 128"), std::string::npos);
  // Negative q is allowed (mirror image).
  EXPECT_NO_THROW(generate("torus-knot", {{"q", -3}}));
}

TEST(ParseGeneratorCall, NameOnlyAndWithParams) {
  const auto a = parse_generator_call("sphere");
  EXPECT_EQ(a.name, "sphere");
  EXPECT_TRUE(a.params.empty());
  const auto b = parse_generator_call("clifford-torus:n=24,m=24");
  EXPECT_EQ(b.name, "clifford-torus");
  EXPECT_EQ(b.params, (Params{{"n", 24}, {"m", 24}}));
  const auto c = parse_generator_call(" torus-knot : p = 3 , q=-7, R=2.5e0 ");
  EXPECT_EQ(c.name, "torus-knot");
  EXPECT_EQ(c.params, (Params{{"p", 3}, {"q", -7}, {"R", 2.5}}));
  // Parse then generate: the round trip the CLI does.
  EXPECT_EQ(std::get<Surface<4>>(generate(b.name, b.params)).vertex_count(), 576u);
}

TEST(ParseGeneratorCall, MalformedTextIsRejected) {
  for (const char* bad : {"", ":n=3", "sphere:", "sphere:n", "sphere:n=", "sphere:=3",
                          "sphere:n=abc", "sphere:n=3x", "sphere:n=3,,m=2", "sphere:n=3,n=4",
                          "sphere:n=1e999"})
    EXPECT_THROW(parse_generator_call(bad), Error) << "'" << bad << "'";
}

}  // namespace
}  // namespace s4d
