#!/usr/bin/env python3
"""Checks that no module library calls a module above it.

Static libraries link in order, so an executable that links them all finds
an upward call's symbol anyway when a higher library already pulled it in.
This reads each library's symbols instead (nm): a symbol one library needs
and another defines (strongly: not an inline or template copy) must be
defined in the same module or one below it.

  check-layers.py --nm nm [--forbid=cli:render:REGEX] core=libmarch_core.a: gl=libmarch_gl.a:core ...

Each argument is module=archive:comma-separated modules it may use.
--forbid=M:N:REGEX also fails on any call from M to a symbol of N whose
mangled name matches REGEX, below or not (cli/ may not draw: it goes
through pipeline/).
"""
import argparse
import re
import subprocess
import sys


def symbols(nm, archive):
    out = subprocess.run([nm, "-A", "-P", archive], check=True, capture_output=True, text=True).stdout
    defined, needed = {}, {}
    for line in out.splitlines():
        # "lib.a[obj.o]: symbol TYPE value size"
        head, _, rest = line.rpartition(": ")
        parts = rest.split()
        if len(parts) < 2:
            continue
        sym, kind = parts[0], parts[1]
        obj = head[head.find("[") + 1:head.rfind("]")] if "[" in head else head
        if kind == "U":
            needed.setdefault(sym, obj)
        elif kind in "TDBRG":  # strong definitions; W/V (inline, templates) are everyone's
            defined[sym] = obj
    return defined, needed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nm", default="nm")
    ap.add_argument("--forbid", action="append", default=[])
    ap.add_argument("modules", nargs="+")
    args = ap.parse_args()
    below, defs, needs = {}, {}, {}
    for spec in args.modules:
        name, _, rest = spec.partition("=")
        archive, _, deps = rest.rpartition(":")
        below[name] = set(d for d in deps.split(",") if d)
        defs[name], needs[name] = symbols(args.nm, archive)
    # Everything a module may reach: itself and, transitively, those below.
    def reach(m, seen=None):
        seen = set() if seen is None else seen
        if m not in seen:
            seen.add(m)
            for d in below[m]:
                reach(d, seen)
        return seen
    bad = 0
    for m, needed in needs.items():
        ok = reach(m)
        for sym, obj in sorted(needed.items()):
            owners = [o for o, d in defs.items() if sym in d]
            if owners and not any(o in ok for o in owners):
                print(f"{m}: {obj} calls {owners[0]}'s {sym} (a module not below it)")
                bad += 1
    for rule in args.forbid:
        m, n, pattern = rule.split(":", 2)
        for sym, obj in sorted(needs.get(m, {}).items()):
            if sym in defs.get(n, {}) and re.search(pattern, sym):
                print(f"{m}: {obj} calls {n}'s {sym} (forbidden: {pattern})")
                bad += 1
    if bad:
        sys.exit(1)
    print(f"layers: {len(needs)} libraries, no upward calls, {len(args.forbid)} forbidden uses checked")


if __name__ == "__main__":
    main()
