#include "io/json_doc.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <unordered_set>

#include "core/error.h"

namespace ms {

int JsonDoc::member(int obj, std::string_view key) const {
  for (int c = at(obj).first; c != -1; c = at(c).next)
    if (at(c).key == key) return c;
  return -1;
}

std::string JsonDoc::pointer(int i) const {
  std::vector<std::string> parts;
  for (; at(i).parent != -1; i = at(i).parent) {
    const JsonValue& v = at(i);
    if (at(v.parent).kind == JsonKind::array) {
      parts.push_back(std::to_string(v.index));
      continue;
    }
    std::string k;  // RFC 6901: '~' as "~0", '/' as "~1"
    for (char c : v.key) k += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    parts.push_back(std::move(k));
  }
  std::string out;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) out += "/" + *it;
  return out;
}

namespace {

class Parser {
 public:
  Parser(std::string_view text, const std::string& display) : t_(text), display_(display) {}

  JsonDoc run() {
    skip_space();
    value(-1, {});
    // Each open container on the stack waits for its next member or its end.
    while (!stack_.empty()) {
      const int c = stack_.back();
      JsonValue& v = doc_.values[static_cast<std::size_t>(c)];
      skip_space();
      const char close = v.kind == JsonKind::array ? ']' : '}';
      if (peek() == close) {
        ++i_;
        stack_.pop_back();
        keys_.pop_back();
        continue;
      }
      if (v.count > 0) {
        expect(',', v.kind == JsonKind::array ? "',' or ']' in an array" : "',' or '}' in an object");
        skip_space();
      }
      std::string key;
      if (v.kind == JsonKind::object) {
        if (peek() != '"') fail("expected a member name in quotes");
        key = string();
        if (!keys_.back().insert(key).second) fail("duplicate key '" + key + "'");
        skip_space();
        expect(':', "':' after a member name");
        skip_space();
      }
      value(c, std::move(key));
    }
    skip_space();
    if (i_ < t_.size()) fail("text after the JSON value");
    return std::move(doc_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) { fail_input("malformed JSON: " + what, display_, line_); }
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

  // Appends a value to container `parent` (or as the document) and reads
  // it; an array or object is pushed to be filled by run()'s loop.
  void value(int parent, std::string key) {
    const int id = static_cast<int>(doc_.values.size());
    JsonValue v;
    v.line = line_;
    v.parent = parent;
    v.key = std::move(key);
    const char c = peek();
    if (c == '{' || c == '[') {
      v.kind = c == '{' ? JsonKind::object : JsonKind::array;
      ++i_;
    } else if (c == '"') {
      v.kind = JsonKind::string;
      v.text = string();
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonKind::number;
      v.number = number();
    } else if (word("true") || word("false")) {
      v.kind = JsonKind::boolean;
      v.number = t_[i_ - 1] == 'e' && t_[i_ - 2] == 'u' ? 1.0 : 0.0;
    } else if (word("null")) {
      v.kind = JsonKind::null;
    } else {
      fail(c == '\0' ? "the text ends where a value should be" : "unexpected character '" + std::string(1, c) + "'");
    }
    if (parent != -1) {
      v.index = doc_.values[static_cast<std::size_t>(parent)].count;
      link(parent, id);
    }
    const bool container = v.kind == JsonKind::object || v.kind == JsonKind::array;
    doc_.values.push_back(std::move(v));
    if (container) {
      stack_.push_back(id);
      keys_.emplace_back();
    }
  }

  void link(int parent, int id) {
    JsonValue& p = doc_.values[static_cast<std::size_t>(parent)];
    if (last_.size() <= static_cast<std::size_t>(parent)) last_.resize(static_cast<std::size_t>(parent) + 1, -1);
    const int prev = last_[static_cast<std::size_t>(parent)];
    if (prev == -1) p.first = id;
    else doc_.values[static_cast<std::size_t>(prev)].next = id;
    last_[static_cast<std::size_t>(parent)] = id;
    ++p.count;
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
    if (!std::isfinite(d)) fail("the number " + s + " is out of range");
    return d;
  }

  static void put_utf8(std::string& out, unsigned cp) {
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

  std::string string() {
    ++i_;  // the opening quote
    std::string out;
    for (;;) {
      if (i_ >= t_.size()) fail("a string is not closed");
      const char c = t_[i_++];
      if (c == '"') return out;
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
          put_utf8(out, cp);
          break;
        }
        default: fail("unknown escape '\\" + std::string(1, e) + "'");
      }
    }
  }

  std::string_view t_;
  const std::string& display_;
  std::size_t i_ = 0;
  int line_ = 1;
  JsonDoc doc_;
  std::vector<int> stack_;
  std::vector<int> last_;
  std::vector<std::unordered_set<std::string>> keys_;  // per open container: its member names so far
};

}  // namespace

JsonDoc parse_json_doc(std::string_view text, const std::string& display) { return Parser(text, display).run(); }

}  // namespace ms
