# Sourced by tools/gpu/device_run.sh: how to start the lean bench on a GPU
# machine whose image is not the one it was built on (tools/gpu/pack.sh
# packs what this needs; docs/gpu-bench.md#gpu-figures).
#
#   gpu_environment DIR    the library path (DIR, the packed folder, first;
#                          the NVIDIA driver's mount after) and the EGL vendor;
#                          exports MARCH_GPU_ENV=1 so a script it runs keeps them
#   cmd=$(gpu_launcher BIN WORK) || exit 5
#                          a command that runs BIN with its arguments: BIN
#                          itself where it starts, else a wrapper written in
#                          WORK that starts it through DIR/glibc's loader
#   gpu_diagnosis          where the EGL vendors and libraries are, for a log
#
# GPU_LAUNCH=plain|bundled forces one way (the check in tests/gpu/ runs
# both on llvmpipe); GPU_EGL_VENDOR names glvnd's EGL vendor JSON outright.

# Where NVIDIA's container runtime mounts the driver: its libraries, and the
# vendor JSON that glvnd reads only from its own data folders.
GPU_NVIDIA_ROOT=${GPU_NVIDIA_ROOT:-/usr/local/nvidia}

gpu_environment() {
  local dir=$1 d f
  # bench_gpu.sh, run by device_run.sh, keeps what this set up.
  export MARCH_GPU_ENV=1
  # Undo what the llvmpipe scripts pin (tests/CMakeLists.txt's mesa vendor).
  unset __EGL_VENDOR_LIBRARY_FILENAMES LIBGL_ALWAYS_SOFTWARE GALLIUM_DRIVER || true
  LD_LIBRARY_PATH=$dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  for d in "$GPU_NVIDIA_ROOT/lib64" "$GPU_NVIDIA_ROOT/lib"; do
    [[ -d $d ]] && LD_LIBRARY_PATH+=:$d
  done
  export LD_LIBRARY_PATH
  if [[ -n ${GPU_EGL_VENDOR:-} ]]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES=$GPU_EGL_VENDOR
    return
  fi
  # glvnd finds NVIDIA's vendor by itself when the image installed it.
  for f in /usr/share/glvnd/egl_vendor.d/*nvidia*.json /etc/glvnd/egl_vendor.d/*nvidia*.json; do
    [[ -f $f ]] && return
  done
  for f in "$GPU_NVIDIA_ROOT"/share/glvnd/egl_vendor.d/*nvidia*.json; do
    if [[ -f $f ]]; then
      export __EGL_VENDOR_LIBRARY_FILENAMES=$f
      return
    fi
  done
}

# _gpu_starts CMD: CMD --help runs; what it printed on stderr stays in
# $_gpu_err for the message.
_gpu_starts() {
  _gpu_err=$("$1" --help 2>&1 >/dev/null)
}

gpu_launcher() {
  local bin=$1 work=$2 how=${GPU_LAUNCH:-}
  local glibc plain_err
  glibc=$(cd "$(dirname "$bin")" && pwd)/glibc
  if [[ $how != bundled ]]; then
    if _gpu_starts "$bin"; then
      echo "$bin"
      return 0
    fi
    plain_err=${_gpu_err%%$'\n'*}
    if [[ $how == plain ]]; then
      echo "launch.sh: $bin does not start: $plain_err" >&2
      return 1
    fi
  fi
  if [[ ! -x $glibc/ld-linux-x86-64.so.2 ]]; then
    echo "launch.sh: $bin does not start (${plain_err:-no glibc/ beside it}), and there is no $glibc/ld-linux-x86-64.so.2 to start it with (tools/gpu/pack.sh packs one)" >&2
    return 1
  fi
  mkdir -p "$work"
  local wrapper=$work/marchstudio-gpubench
  # --library-path replaces LD_LIBRARY_PATH for this process, so both go in.
  printf '#!/bin/sh\nexec %q --library-path %q %q "$@"\n' "$glibc/ld-linux-x86-64.so.2" \
    "$glibc:$LD_LIBRARY_PATH" "$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")" >"$wrapper"
  chmod +x "$wrapper"
  if _gpu_starts "$wrapper"; then
    echo "$wrapper"
    return 0
  fi
  echo "launch.sh: $bin does not start (${plain_err:-forced bundled}), nor through its packed glibc: ${_gpu_err%%$'\n'*}" >&2
  return 1
}

# gpu_diagnosis: where glvnd's vendor files and the EGL libraries are on this
# machine, for log.txt when the first run finds no GL (the next session reads
# why, not only that it failed).
gpu_diagnosis() {
  local d
  for d in /usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d "$GPU_NVIDIA_ROOT/share/glvnd/egl_vendor.d"; do
    [[ -d $d ]] && echo "launch.sh: EGL vendor files in $d: $(ls "$d" | tr '\n' ' ')"
  done
  echo "launch.sh: EGL libraries the loader cache knows: $(ldconfig -p 2>/dev/null |
    awk '/libEGL/ { printf "%s ", $NF }')"
  echo "launch.sh: /dev/dri: $(ls /dev/dri 2>/dev/null | tr '\n' ' '); /dev/nvidia*: $(ls -d /dev/nvidia* 2>/dev/null | wc -l)"
}
