// The smallest useful `marchstudio test` suite (docs/testing.md): one case,
// seven lines. The unit tests parse it; the CLI tests run it.
#pragma once

namespace ms::test {

constexpr const char* kMinimalSuite =
    "[[case]]\n"
    "name = \"seed\"\n"
    "scene = \"scenes/seed.toml\"\n"
    "reference = \"refs/seed.png\"\n"
    "size = [160, 90]\n"
    "metric = \"psnr\"\n"
    "threshold = 40\n";

}  // namespace ms::test
