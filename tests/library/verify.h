// The library's claims and their verification (docs/shader-library.md).
//
// Every guarded function in sdf_shaders/ ends its comment with a claim tag,
// `[exact; L = 1]`, `[bound; L = 1.4142]`, `[noise; L = 3.03]`, `[index]`,
// ... library_claims() reads them. tests/library/cases.toml holds the
// configurations each function is checked in; verify_case() runs one on the
// GPU and measures it against its claim:
//   - Lipschitz: |f(a) - f(b)| <= L |a - b| over random pairs in the box;
//   - distance: against the zero set found by root finding along rays
//     (unsigned shapes: sampled directly), |f| within a sampling tolerance
//     of the distance to it (exact), or |f| <= L * that distance (bound);
//   - sign: f < 0 exactly where the case's independent membership test says
//     inside (unsigned: f >= 0; noise: |f| <= 1; index/helper: an identity).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gpu_eval.h"

namespace ms::test {

struct Claim {
  std::string function;  // e.g. "sdBoxFrame"
  std::string file;      // e.g. "primitives.glsl"
  std::string kind;      // exact | exact outside | bound | unsigned | noise | index | helper
  std::string lipschitz; // the tag's L as written ("1", "1.4142", a formula); empty for index/helper
  int line = 0;
};

// Every guarded function of the library files under shader_dir, in file order.
std::vector<Claim> library_claims(const std::string& shader_dir);

struct Case {
  std::string function;   // the library function it verifies
  std::string condition;  // when set, a configuration with a claim of its own
  std::string kind;       // the claim checked: the tag's, unless `condition` overrides it
  double lipschitz = 1.0; // the L checked (the tag's number, or the case's for formulas)
  Box box;
  int dims = 3;
  double tolerance = 0.0; // extra exactness tolerance on top of the sampling's
  CaseSource src;
};

// cases.toml, each case completed from its function's claim. Throws with the
// case's index on a malformed entry or a claim mismatch.
std::vector<Case> load_cases(const std::string& path, const std::vector<Claim>& claims);

struct CaseResult {
  int lipschitz_pairs = 0;
  double lipschitz_max = 0.0;      // largest |f(a) - f(b)| / |a - b| seen
  int lipschitz_violations = 0;
  int distance_points = 0;         // points compared with the zero set
  int surface_samples = 0;
  double distance_error = 0.0;     // exact: max |f| one |f| along the gradient; bound: max(|f| - L d, 0)
  int distance_violations = 0;
  int exact_points = 0;            // exact claims: points projected along the gradient
  int unresolved_points = 0;       // of those, where ridges meet: no trustworthy gradient (<= 0.3%)
  int sign_points = 0;
  int sign_violations = 0;         // sign/range/identity failures
  std::string first_failure;       // a description of one failure, for the message
  bool passed() const { return lipschitz_violations == 0 && distance_violations == 0 && sign_violations == 0; }
};

CaseResult verify_case(const Case& c, const std::string& shader_dir);

nlohmann::json to_json(const Case& c, const CaseResult& r);

}  // namespace ms::test
