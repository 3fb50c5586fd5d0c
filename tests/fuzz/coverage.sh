#!/usr/bin/env bash
# Line coverage of the code each fuzz target exercises, from a corpus (the
# figures in docs/reliability.md). Builds the targets with clang's
# source-based coverage and the replay driver, replays CORPUS_ROOT/<target>/
# (default: the seed corpora) and prints llvm-cov's summary for the files
# under test.
#
#   tests/fuzz/coverage.sh [CORPUS_ROOT] [OUT_DIR]
#
# Needs clang-14 and llvm-14 (llvm-profdata-14, llvm-cov-14).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/../.." && pwd)
CORPUS=${1:-$SRC/tests/fuzz/corpus}
OUT=${2:-$(mktemp -d /tmp/marchcov-XXXXXX)}
mkdir -p "$OUT"
FLAGS=(-std=c++20 -O1 -g -fprofile-instr-generate -fcoverage-mapping -I"$SRC/app" -I"$SRC/tests/fuzz"
       "-DMARCH_SOURCE_SHADER_DIR=\"$SRC/sdf_shaders\"" $(pkg-config --cflags tomlplusplus))
LIBS=($(pkg-config --libs tomlplusplus) -lpthread)
LIB_SOURCES=("$SRC"/app/core/*.cpp "$SRC"/app/scene/*.cpp "$SRC"/app/shader/*.cpp "$SRC/app/live/param_reload.cpp")
# What each target is about (the rest of the library is linked, not measured).
declare -A FILES=(
  [scene]="app/scene/load.cpp app/scene/load_geometry.cpp app/scene/quality.cpp app/scene/toml_read.cpp app/scene/toml_guard.cpp app/scene/animation.cpp"
  [preprocess]="app/preprocess/preprocess.cpp app/preprocess/log_map.cpp app/shader/scene_params.cpp"
  [shadertoy]="app/importers/shadertoy.cpp app/preprocess/preprocess.cpp"
  [animation]="app/scene/animation.cpp"
)
objs=()
for s in "${LIB_SOURCES[@]}"; do
  o="$OUT/obj/$(basename "${s%.cpp}").o"
  mkdir -p "$OUT/obj"
  clang++-14 "${FLAGS[@]}" -c "$s" -o "$o"
  objs+=("$o")
done
for t in scene preprocess shadertoy animation; do
  clang++-14 "${FLAGS[@]}" "$SRC/tests/fuzz/fuzz_$t.cpp" "$SRC/tests/fuzz/replay_main.cpp" "${objs[@]}" "${LIBS[@]}" \
    -o "$OUT/cov_$t"
  LLVM_PROFILE_FILE="$OUT/$t.profraw" "$OUT/cov_$t" "$CORPUS/$t" "$SRC/tests/fuzz/regressions/$t" >/dev/null
  llvm-profdata-14 merge -sparse "$OUT/$t.profraw" -o "$OUT/$t.profdata"
  echo "== $t ($(find "$CORPUS/$t" -type f | wc -l) inputs)"
  files=()
  for f in ${FILES[$t]}; do files+=("$SRC/$f"); done
  llvm-cov-14 report "$OUT/cov_$t" -instr-profile="$OUT/$t.profdata" "${files[@]}" | sed "s|$SRC/||"
done
echo "coverage data in $OUT"
