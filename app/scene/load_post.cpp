#include "scene/load_post.h"

#include <string_view>
#include <vector>

namespace ms {

void read_post(const Reader& r, const toml::table& root, Bloom& bloom) {
  const toml::table* post = r.table(root, {}, "post");
  if (!post) return;
  static const std::string_view kPostKeys[] = {"bloom"};
  r.check_keys(*post, "post", kPostKeys);
  const toml::table* t = r.table(*post, "post", "bloom");
  if (!t) return;
  r.check_keys(*t, "post.bloom", keys_of(kBloomFields));
  r.read_fields(*t, "post.bloom", kBloomFields, bloom);
  bloom.enabled = true;
}

}  // namespace ms
