# Sourced by the tools/gpu scripts, what they share about bench's JSON.
#
# fields FILE POINTER... prints the values of bench's JSON at those JSON
# pointers (/frame_ms/gpu/median), one per line, with jq if there is one,
# else python3 (a GPU machine may have either).
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

# not_a_gpu FILE: true, with the reason on stdout, when the bench JSON in
# FILE ran on a software GL (llvmpipe, softpipe) or not through EGL's device
# platform; the scripts then stop unless ALLOW_SOFTWARE=1.
not_a_gpu() {
  local renderer backend
  { read -r renderer; read -r backend; } < <(fields "$1" /machine/gl_renderer /machine/backend)
  if [[ $renderer == *llvmpipe* || $renderer == *softpipe* || $backend != egl-device ]]; then
    echo "EGL gave '$renderer' ($backend), not a GPU"
    return 0
  fi
  return 1
}
