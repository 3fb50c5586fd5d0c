// The scene the graph render tests wrap a g.json in: a camera, a floor
// plane, a point light with a soft shadow, and materials "a" (matte) and
// "b" (a little reflective), so shadows, AO and reflections all call map().
//
//   write_file(dir / "s.toml", graph_test_scene("[1.6, 1.4, -2.6]", "[0.0, 0.2, 0.0]", 45.0, 1.2));
#pragma once
#include <string>

namespace ms::test {

inline std::string graph_test_scene(const std::string& eye, const std::string& target, double fov, double floor) {
  return "[scene]\ngraph = \"g.json\"\n[camera]\nposition = " + eye + "\ntarget = " + target +
         "\nfov = " + std::to_string(fov) + "\n[[planes]]\nnormal = [0.0, 1.0, 0.0]\noffset = " + std::to_string(floor) +
         "\nmaterial = \"a\"\n[[lights]]\ntype = \"point\"\nposition = [2.0, 3.0, -1.0]\nintensity = 2.0\nsize = 0.3\n"
         "[[materials]]\nname = \"a\"\ncolor = [0.8, 0.3, 0.2]\n[[materials]]\nname = \"b\"\ncolor = [0.2, 0.5, 0.8]\n"
         "reflectivity = 0.2\n";
}

}  // namespace ms::test
