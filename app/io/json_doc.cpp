#include "io/json_doc.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "core/format.h"
#include "core/memory_budget.h"

namespace ms {

namespace {

std::uint32_t stored(std::string& pool, std::string_view s) {
  const auto at = static_cast<std::uint32_t>(pool.size());
  pool.append(s);
  return at;
}

}  // namespace

void JsonDoc::set_text(JsonValue& v, std::string_view s) {
  v.text_at = stored(strings, s);
  v.text_size = static_cast<std::uint32_t>(s.size());
}

void JsonDoc::set_key(JsonValue& v, std::string_view s) {
  v.key_at = stored(strings, s);
  v.key_size = static_cast<std::uint32_t>(s.size());
}

int JsonDoc::member(int obj, std::string_view name) const {
  for (int c = at(obj).first; c != -1; c = at(c).next)
    if (key(c) == name) return c;
  return -1;
}

std::string JsonDoc::pointer(int i) const {
  constexpr std::size_t kHead = 4, kTail = 8;
  std::vector<int> steps;  // from the value up
  for (; at(i).parent != -1; i = at(i).parent) steps.push_back(i);
  std::string out;
  for (std::size_t n = 0; n < steps.size(); ++n) {
    if (steps.size() > kHead + kTail + 1 && n == kHead) {
      out += "/...";
      n = steps.size() - kTail - 1;
      continue;
    }
    const int s = steps[steps.size() - 1 - n];
    if (at(at(s).parent).kind == JsonKind::array) {
      out += "/" + std::to_string(at(s).index);
      continue;
    }
    std::string k;  // RFC 6901: '~' as "~0", '/' as "~1"
    for (char c : key(s)) k += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    out += "/" + printable(k);
  }
  return out;
}

namespace {

// A first pass over any text, valid or not: at most how many values it
// holds (the document's, and each one first in a container or after a
// comma), how deep it nests and how many bytes its strings take (escapes
// only shrink), so the parse can be sized, and refused, before it starts.
struct Shape {
  std::size_t values = 1, depth = 0, string_bytes = 0;
};

Shape shape_of(std::string_view t) {
  Shape s;
  std::size_t depth = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '"') {
      const std::size_t start = ++i;
      for (; i < t.size() && t[i] != '"'; ++i)
        if (t[i] == '\\') ++i;
      s.string_bytes += std::min(i, t.size()) - start;
    } else if (c == '[' || c == '{') {
      ++s.values;
      s.depth = std::max(s.depth, ++depth);
    } else if (c == ']' || c == '}') {
      if (depth > 0) --depth;
    } else if (c == ',') {
      ++s.values;
    }
  }
  return s;
}

// An open container: its value and its last member so far.
struct Open {
  int id = -1;
  int last = -1;
};

// The document's bytes for `s` with the caller's `extra`: each value, its
// slot in a duplicate-key sort, each open container, and the strings.
double bytes_for(const Shape& s, JsonCost extra) {
  return static_cast<double>(s.values) * static_cast<double>(sizeof(JsonValue) + sizeof(int) + extra.per_value) +
         static_cast<double>(s.depth) * static_cast<double>(sizeof(Open) + extra.per_level) +
         static_cast<double>(s.string_bytes);
}

struct Str {
  std::uint32_t at = 0, size = 0;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& display, const Shape& s) : t_(text), display_(display) {
    doc_.values.reserve(s.values);
    doc_.strings.reserve(s.string_bytes);
    stack_.reserve(s.depth);
  }

  JsonDoc run() {
    skip_space();
    value(-1, {});
    // Each open container on the stack waits for its next member or its end.
    while (!stack_.empty()) {
      const int c = stack_.back().id;
      const JsonKind kind = doc_.at(c).kind;
      skip_space();
      if (peek() == (kind == JsonKind::array ? ']' : '}')) {
        ++i_;
        if (kind == JsonKind::object) check_duplicates(c);
        stack_.pop_back();
        continue;
      }
      if (doc_.at(c).count > 0) {
        expect(',', kind == JsonKind::array ? "',' or ']' in an array" : "',' or '}' in an object");
        skip_space();
      }
      Str key;
      if (kind == JsonKind::object) {
        if (peek() != '"') fail("expected a member name in quotes");
        key = string();
        skip_space();
        expect(':', "':' after a member name");
        skip_space();
      }
      value(c, key);
    }
    skip_space();
    if (i_ < t_.size()) fail("text after the JSON value");
    return std::move(doc_);
  }

 private:
  [[noreturn]] void fail(const std::string& what, int line = 0) {
    fail_input("malformed JSON: " + what, display_, line > 0 ? line : line_);
  }
  char peek() const { return i_ < t_.size() ? t_[i_] : '\0'; }
  void expect(char c, const char* what) {
    if (peek() != c) fail(std::string("expected ") + what);
    ++i_;
  }
  void skip_space() {
    for (; i_ < t_.size(); ++i_) {
      const char c = t_[i_];
      if (c == '\n') ++line_;
      else if (c != ' ' && c != '\t' && c != '\r') break;
    }
  }

  // Appends a value to the open container `parent` (or as the document)
  // and reads it; an array or object is pushed to be filled by run()'s loop.
  void value(int parent, Str key) {
    const int id = static_cast<int>(doc_.values.size());
    JsonValue v;
    v.line = line_;
    v.parent = parent;
    v.key_at = key.at;
    v.key_size = key.size;
    const char c = peek();
    if (c == '{' || c == '[') {
      v.kind = c == '{' ? JsonKind::object : JsonKind::array;
      ++i_;
    } else if (c == '"') {
      v.kind = JsonKind::string;
      const Str s = string();
      v.text_at = s.at;
      v.text_size = s.size;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonKind::number;
      v.number = number();
    } else if (word("true") || word("false")) {
      v.kind = JsonKind::boolean;
      v.number = t_[i_ - 1] == 'e' && t_[i_ - 2] == 'u' ? 1.0 : 0.0;
    } else if (word("null")) {
      v.kind = JsonKind::null;
    } else {
      fail(c == '\0' ? "the text ends where a value should be" : "unexpected character " + quote(std::string(1, c)));
    }
    if (parent != -1) {
      Open& p = stack_.back();
      JsonValue& pv = doc_.values[static_cast<std::size_t>(parent)];
      v.index = pv.count++;
      if (p.last == -1) pv.first = id;
      else doc_.values[static_cast<std::size_t>(p.last)].next = id;
      p.last = id;
    }
    const bool container = v.kind == JsonKind::object || v.kind == JsonKind::array;
    doc_.values.push_back(v);
    if (container) stack_.push_back({id, -1});
  }

  // Member names sorted (ties by position): the first value whose name an
  // earlier member has is the duplicate.
  void check_duplicates(int obj) {
    if (doc_.at(obj).count < 2) return;
    ids_.clear();
    for (int c = doc_.at(obj).first; c != -1; c = doc_.at(c).next) ids_.push_back(c);
    std::sort(ids_.begin(), ids_.end(), [&](int a, int b) {
      const std::string_view ka = doc_.key(a), kb = doc_.key(b);
      return ka < kb || (ka == kb && a < b);
    });
    int dup = -1;
    for (std::size_t k = 1; k < ids_.size(); ++k)
      if (doc_.key(ids_[k]) == doc_.key(ids_[k - 1]) && (dup == -1 || ids_[k] < dup)) dup = ids_[k];
    if (dup != -1) fail("duplicate key " + quote(doc_.key(dup)), doc_.at(dup).line);
  }

  bool word(std::string_view w) {
    if (t_.substr(i_, w.size()) != w) return false;
    i_ += w.size();
    return true;
  }

  double number() {
    const std::size_t start = i_;
    if (peek() == '-') ++i_;
    if (peek() == '0') ++i_;
    else if (peek() >= '1' && peek() <= '9') while (peek() >= '0' && peek() <= '9') ++i_;
    else fail("a number needs digits");
    if (peek() == '.') {
      ++i_;
      if (!(peek() >= '0' && peek() <= '9')) fail("a number needs digits after '.'");
      while (peek() >= '0' && peek() <= '9') ++i_;
    }
    if (peek() == 'e' || peek() == 'E') {
      ++i_;
      if (peek() == '+' || peek() == '-') ++i_;
      if (!(peek() >= '0' && peek() <= '9')) fail("a number needs digits in its exponent");
      while (peek() >= '0' && peek() <= '9') ++i_;
    }
    const std::string s(t_.substr(start, i_ - start));
    const double d = std::strtod(s.c_str(), nullptr);
    if (!std::isfinite(d)) fail("the number " + printable(s) + " is out of range");
    return d;
  }

  void put_utf8(unsigned cp) {
    std::string& out = doc_.strings;
    if (cp < 0x80) out += static_cast<char>(cp);
    else if (cp < 0x800) out += {static_cast<char>(0xC0 | (cp >> 6)), static_cast<char>(0x80 | (cp & 0x3F))};
    else if (cp < 0x10000)
      out += {static_cast<char>(0xE0 | (cp >> 12)), static_cast<char>(0x80 | ((cp >> 6) & 0x3F)),
              static_cast<char>(0x80 | (cp & 0x3F))};
    else
      out += {static_cast<char>(0xF0 | (cp >> 18)), static_cast<char>(0x80 | ((cp >> 12) & 0x3F)),
              static_cast<char>(0x80 | ((cp >> 6) & 0x3F)), static_cast<char>(0x80 | (cp & 0x3F))};
  }

  unsigned hex4() {
    if (i_ + 4 > t_.size()) fail("a \\u escape needs four hex digits");
    unsigned v = 0;
    const auto [p, ec] = std::from_chars(t_.data() + i_, t_.data() + i_ + 4, v, 16);
    if (ec != std::errc{} || p != t_.data() + i_ + 4) fail("a \\u escape needs four hex digits");
    i_ += 4;
    return v;
  }

  // Reads a string into the document's pool: where it starts and its size.
  Str string() {
    ++i_;  // the opening quote
    std::string& out = doc_.strings;
    Str s;
    s.at = static_cast<std::uint32_t>(out.size());
    for (;;) {
      if (i_ >= t_.size()) fail("a string is not closed");
      const char c = t_[i_++];
      if (c == '"') break;
      if (static_cast<unsigned char>(c) < 0x20) fail("a control character inside a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      const char e = peek();
      ++i_;
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00 && word("\\u")) {
            const unsigned lo = hex4();
            if (lo < 0xDC00 || lo > 0xDFFF) fail("a \\u surrogate pair is broken");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          }
          put_utf8(cp);
          break;
        }
        default: fail("unknown escape " + quote("\\" + std::string(1, e)));
      }
    }
    s.size = static_cast<std::uint32_t>(out.size() - s.at);
    return s;
  }

  std::string_view t_;
  const std::string& display_;
  std::size_t i_ = 0;
  int line_ = 1;
  JsonDoc doc_;
  std::vector<Open> stack_;
  std::vector<int> ids_;  // an object's members, for check_duplicates()
};

}  // namespace

JsonDoc parse_json_doc(std::string_view text, const std::string& display, JsonCost extra, double budget) {
  if (text.size() >= static_cast<std::size_t>(INT_MAX))
    fail_input("the JSON text is over 2 GiB", display);
  const Shape s = shape_of(text);
  if (budget <= 0) budget = memory_budget();
  if (const double need = bytes_for(s, extra); need > budget)
    fail_input("the JSON needs " + format_bytes(need) + " to read (up to " + std::to_string(s.values) +
                   " JSON values, nested up to " + std::to_string(s.depth) + " deep), over the " +
                   format_bytes(budget) + " memory budget",
               display);
  return Parser(text, display, s).run();
}

bool looks_like_json(std::string_view text) {
  const std::size_t at = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  return at != std::string_view::npos && (text[at] == '{' || text[at] == '[');
}

}  // namespace ms
