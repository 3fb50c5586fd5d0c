# Sourced by the tools/gpu scripts: fields FILE POINTER... prints the values
# of bench's JSON at those JSON pointers (/frame_ms/gpu/median), one per
# line, with jq if there is one, else python3 (a GPU machine may have
# either).
fields() {
  local file=$1; shift
  if command -v jq >/dev/null 2>&1; then
    local p
    for p in "$@"; do jq -r "getpath(\"$p\" | ltrimstr(\"/\") | split(\"/\"))" "$file"; done
  else
    python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
for p in sys.argv[2:]:
    v = d
    for k in p.strip("/").split("/"):
        v = v[k]
    print(v)' "$file" "$@"
  fi
}
