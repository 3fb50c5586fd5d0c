#include "live/view_state.h"

namespace ms::live {

const char* debug_view_name(int view) {
  static const char* const kNames[kDebugViews] = {"lit", "steps heat map", "normals", "depth",
                                                  "AO only", "shadow only", "material id"};
  return view >= 0 && view < kDebugViews ? kNames[view] : "?";
}

}  // namespace ms::live
