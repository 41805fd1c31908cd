// A small tree grammar for the scoring and search tests (trunk, branches that branch again, a
// leaf sphere at each branch's end): every primitive kind of a tree, a few genes per model.
#pragma once

namespace shapevo::test {

inline constexpr const char* kSmallTree = R"(
start Trunk
rule Trunk {
  size (0.6, 3, 0.6)
  cylinder
  child Branch prob 0.6 max 3
}
rule Branch {
  param turn = uniform(0, 360)
  param tilt = uniform(25, 70)
  translate (0, parent.size.y * 0.3, 0)
  rotate y turn
  rotate x tilt
  scale (0.7, 0.75, 0.7)
  translate (0, scope.size.y * 0.5, 0)
  cone top 0.7
  child Branch prob 0.5 max 2
  terminal {
    translate (0, scope.size.y * 0.5, 0)
    size (0.8, 0.8, 0.8)
    sphere
  }
}
)";

}  // namespace shapevo::test
