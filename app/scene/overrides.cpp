#include "scene/overrides.h"

#include <algorithm>

#include "core/suggest.h"
#include "scene/toml_read.h"

namespace ms {
namespace {

std::string kind_of(const toml::node& n) {
  if (n.is_table()) return "a table";
  if (n.is_array()) return "an array";
  if (n.is_string()) return "a string";
  if (n.is_integer()) return "an integer";
  if (n.is_floating_point()) return "a float";
  if (n.is_boolean()) return "a boolean";
  return "a value";
}

bool all_tables(const toml::array& a) {
  return !a.empty() && std::all_of(a.begin(), a.end(), [](const toml::node& n) { return n.is_table(); });
}

// The entry of an array of tables whose `name` is `name`.
std::size_t entry_named(const toml::array& a, const std::string& name, const std::string& dotted,
                        const SceneOverride& o) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const toml::value<std::string>* n = a[i].as_table()->get_as<std::string>("name");
    if (n && n->get() == name) return i;
    if (n) names.push_back(n->get());
  }
  if (names.empty())
    fail_input("no entry of " + quote(dotted) + " is named " + quote(name), {}, 0, o.flag,
               "its entries have no names: select one by index, e.g. " + dotted + "[0]");
  const std::vector<std::string_view> views(names.begin(), names.end());
  std::string hint = did_you_mean(name, views), list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  hint += (hint.empty() ? "names: " : " names: ") + list;
  fail_input("no entry of " + quote(dotted) + " is named " + quote(name), {}, 0, o.flag, hint);
}

std::string apply_one(toml::table& root, const SceneOverride& o) {
  if (o.path.empty() || o.value.size() != 1) fail_input("an override needs a key and one value", {}, 0, o.flag);
  const toml::node& value = o.value[0];
  toml::node* here = &root;
  std::string dotted;
  for (std::size_t i = 0; i < o.path.size(); ++i) {
    const KeyStep& s = o.path[i];
    const bool last = i + 1 == o.path.size();
    const std::string index = "[" + std::to_string(s.index) + "]";
    if (toml::table* t = here->as_table()) {
      if (s.by_index)
        fail_input(quote(dotted) + " is a table, not an array: " + index + " selects nothing", {}, 0, o.flag,
                   "name a key of it instead");
      dotted = join_key(dotted, s.key);
      if (last) {
        value.visit([&](const auto& v) { t->insert_or_assign(s.key, v); });
        return dotted;
      }
      if (!t->contains(s.key)) {
        if (o.path[i + 1].by_index)
          fail_input(quote(dotted) + " is not in the scene: there is nothing to index", {}, 0, o.flag,
                     "an override can change an entry of an array of tables, not add one");
        t->insert(s.key, toml::table{});  // a missing table: the schema judges the key
      }
      here = t->get(s.key);
      continue;
    }
    if (toml::array* a = here->as_array()) {
      const bool tables = all_tables(*a);
      if (!s.by_index && !tables)
        fail_input(quote(dotted) + " is an array: " + quote(s.key) + " selects nothing", {}, 0, o.flag,
                   "select an element by index, e.g. " + dotted + "[0]");
      const std::size_t at = s.by_index ? s.index : entry_named(*a, s.key, dotted, o);
      if (at >= a->size())
        fail_input(quote(dotted) + " has " + std::to_string(a->size()) + (a->size() == 1 ? " entry" : " entries") +
                       ": " + index + " is past its end",
                   {}, 0, o.flag, "indices start at 0; an override changes an entry, it does not add one");
      dotted += "[" + std::to_string(at) + "]";
      if (last) {
        value.visit([&](const auto& v) { a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(at), v); });
        return dotted;
      }
      here = a->get(at);
      continue;
    }
    fail_input(quote(dotted) + " is " + kind_of(*here) + ", not a table: it has no " +
                   quote(s.by_index ? index : s.key),
               {}, 0, o.flag);
  }
  return dotted;  // not reached: the last step returns
}

bool under(const std::string& key, const std::string& base) {
  return key.size() > base.size() && key.compare(0, base.size(), base) == 0 &&
         (key[base.size()] == '.' || key[base.size()] == '[');
}

// The last override of `key`, of a part of it or of a table holding it (the
// one whose value the scene holds), or keys.size() when none touches it.
std::size_t override_of(const std::string& key, const std::vector<std::string>& keys) {
  for (std::size_t i = keys.size(); i-- > 0;)
    if (keys[i] == key || under(key, keys[i]) || under(keys[i], key)) return i;
  return keys.size();
}

}  // namespace

std::vector<std::string> apply_overrides(toml::table& root, const SceneOverrides& overrides) {
  std::vector<std::string> keys;
  for (const SceneOverride& o : overrides) keys.push_back(apply_one(root, o));
  return keys;
}

void drop_overridden_tracks(Scene& scene, const SceneOverrides& overrides, const std::vector<std::string>& keys) {
  std::vector<AnimationTrack>& tracks = scene.animation;
  for (auto t = tracks.begin(); t != tracks.end();) {
    const std::size_t i = override_of(t->target, keys);
    if (i == keys.size()) {
      ++t;
      continue;
    }
    scene.notes.push_back(overrides[i].flag + " replaces the [[animation]] of " + quote(t->target) + " at line " +
                          std::to_string(t->line) + ": the set value holds at every time");
    t = tracks.erase(t);
  }
}

ErrorInfo blame_override(ErrorInfo e, const SceneOverrides& overrides, const std::vector<std::string>& keys) {
  const std::size_t i = override_of(e.key, keys);
  if (i == keys.size()) return e;
  e.file.clear();
  e.line = 0;
  e.key = overrides[i].flag;
  return e;
}

}  // namespace ms
