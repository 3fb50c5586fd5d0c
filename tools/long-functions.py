#!/usr/bin/env python3
"""Lists the C++ functions in app/ longer than the house limits and fails on
one over 100 lines that the allow-list does not name.

  tools/long-functions.py [--root DIR] [--allow FILE] [--list]

A function's length is its lines from the first line of its signature to
its closing brace. The allow-list (default tools/long-functions.allow)
holds "path name" lines, e.g. "app/live/viewer.cpp Viewer::run"; '#'
starts a comment. Prints the counts over 80 and over 100 lines, then each
function over 100 (--list: over 80 too). Exit 1 when a function over 100
is not allowed, 0 otherwise; an allowed entry that is no longer long is
reported so the list shrinks with the code.

The scanner knows C++ well enough for this code base: comments, string,
character and raw string literals are skipped; a '{' whose statement has a
parenthesis and no '=' outside it opens a function, unless it is a
constructor's member initializer; class and namespace bodies are searched
for functions, initializers and enums are not.
"""
import argparse
import os
import re
import sys

SOFT, HARD = 80, 100
SPECIFIERS = {"const", "noexcept", "override", "final", "mutable", "try", "volatile"}


def strip(text):
    """The text with comments and literals blanked, newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delim = text[i + 2:open_paren]
            j = text.find(")" + delim + '"', open_paren)
            j = n if j < 0 else j + len(delim) + 2
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(c)  # a digit separator: 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def outside_parens(header):
    """The header with everything inside (), <> of templates left out."""
    depth, out = 0, []
    for ch in header:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif depth == 0:
            out.append(ch)
    return "".join(out)


def function_name(header):
    flat = " ".join(header.split())
    flat = re.sub(r"^template\s*<.*?>\s*", "", flat)
    m = re.search(r"((?:[A-Za-z_~][\w]*\s*(?:<[^()]*?>)?\s*::\s*)*(?:operator\s*[^\s(]+|~?[A-Za-z_]\w*))\s*\(", flat)
    return re.sub(r"\s+", "", m.group(1)) if m else flat[:40]


def is_member_init(header):
    """'{' of `: a_{..}` in a constructor's initializer list."""
    if not re.search(r"\)\s*:(?!:)", re.sub(r"\s+", " ", header)):
        return False
    tail = header.rstrip()
    last = re.search(r"(\w+|>)$", tail)
    return bool(last) and last.group(1) not in SPECIFIERS


def functions(path, text):
    """(name, first line, last line) of every function defined in `text`."""
    src = strip(text)
    found = []
    stack = []  # 'scope' (namespace, class), 'data', ('fn', name, line), 'block'
    header_start = 0
    line = 1
    i = 0
    while i < len(src):
        ch = src[i]
        if ch == "\n":
            line += 1
        in_fn = any(isinstance(s, tuple) or s in ("data", "block") for s in stack)
        if ch == "{":
            if in_fn:
                stack.append("block")
            else:
                header = src[header_start:i]
                flat = outside_parens(header)
                if is_member_init(header):
                    stack.append("block")  # closes back into the same header
                    i += 1
                    continue
                if "(" in header and "=" not in flat.replace("==", "").replace("operator=", "") \
                        and not re.match(r"\s*(namespace|class|struct|union|enum)\b", header):
                    lead = header[:len(header) - len(header.lstrip())]
                    first = line - header.count("\n") + lead.count("\n")
                    stack.append(("fn", function_name(header), first))
                elif "=" in flat or re.match(r"\s*enum\b", header):
                    stack.append("data")
                else:
                    stack.append("scope")
            header_start = i + 1
        elif ch == "}":
            top = stack.pop() if stack else None
            if isinstance(top, tuple):
                found.append((top[1], top[2], line))
            still_in_header = top == "block" and not any(isinstance(s, tuple) or s in ("data", "block") for s in stack)
            if not still_in_header:
                header_start = i + 1
        elif ch == ";" and not in_fn:
            header_start = i + 1
        elif ch in "#" and not in_fn and src[header_start:i].strip() == "":
            j = src.find("\n", i)
            while j > 0 and src[j - 1] == "\\":
                j = src.find("\n", j + 1)
            j = len(src) if j < 0 else j
            header_start = j
        i += 1
    return found


# What the scanner must get right, checked by --self-test: a constructor's
# member initializers, raw strings with braces, comments, a lambda inside a
# function, class bodies, initializers and enums that are not functions.
SELF_TEST = r"""
namespace ms {
struct A {
  A(int x) : a_{x}, b_(x) {
    f();
  }
  int get() const { return a_; }
  int a_, b_;
};
enum class E { one, two };
const int table[] = {1, 2, 3};
std::string text() {
  const char* s = R"(} { "not a brace" )";
  // } a comment
  auto l = [] {
    return 1;
  };
  return s;
}
}  // namespace ms
"""
SELF_EXPECT = [("A", 4, 6), ("get", 7, 7), ("text", 12, 19)]  # lines from the leading newline


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    ap.add_argument("--allow", default=None)
    ap.add_argument("--list", action="store_true", help="list the functions over 80 lines too")
    ap.add_argument("--self-test", action="store_true", help="check the scanner on a built-in sample")
    args = ap.parse_args()
    if args.self_test:
        got = functions("sample.cpp", SELF_TEST)
        ok = got == SELF_EXPECT
        print(f"long-functions: self-test {'passed' if ok else 'FAILED'}: {got}")
        return 0 if ok else 1
    root = os.path.abspath(args.root)
    allow_file = args.allow or os.path.join(root, "tools", "long-functions.allow")
    allowed = set()
    if os.path.exists(allow_file):
        for raw in open(allow_file, encoding="utf-8"):
            entry = raw.split("#", 1)[0].split()
            if len(entry) == 2:
                allowed.add((entry[0], entry[1]))
    rows = []
    for dirpath, _, files in os.walk(os.path.join(root, "app")):
        for f in sorted(files):
            if f.endswith((".cpp", ".h")):
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, root)
                with open(path, encoding="utf-8", errors="replace") as fh:
                    for name, first, last in functions(rel, fh.read()):
                        rows.append((last - first + 1, rel, first, name))
    rows.sort(key=lambda r: (-r[0], r[1], r[2]))
    soft = [r for r in rows if r[0] > SOFT]
    hard = [r for r in rows if r[0] > HARD]
    print(f"long-functions: {len(rows)} functions in app/, {len(soft)} over {SOFT} lines, {len(hard)} over {HARD}")
    bad = 0
    for n, rel, first, name in (soft if args.list else hard):
        tag = ""
        if n > HARD:
            ok = (rel, name) in allowed
            tag = "allowed" if ok else "NOT ALLOWED"
            bad += 0 if ok else 1
        print(f"  {n:4d}  {rel}:{first}  {name}  {tag}".rstrip())
    long_names = {(r[1], r[3]) for r in hard}
    for rel, name in sorted(allowed - long_names):
        print(f"  allow-list: {rel} {name} is no longer over {HARD} lines: drop it")
    sys.stdout.flush()
    if bad:
        print(f"long-functions: {bad} function(s) over {HARD} lines: split them along their own steps, "
              f"or name them in {os.path.relpath(allow_file, root)} with the reason", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
