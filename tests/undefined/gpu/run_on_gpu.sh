#!/bin/bash
# usage (on the GPU machine, from the checkout's root): bash tests/undefined/gpu/run_on_gpu.sh PROBE OUTDIR
#   PROBE: gpu_probe.cpp built here (g++ -O1 -o PROBE gpu_probe.cpp -lEGL -lGL), carried in an ignored folder
#   with .gl/ (the glvnd loader .debs: ../shared/tools/gpu/README.md). Writes OUTDIR/gpu.txt (decode.py's
#   input) and OUTDIR/gpu-info.txt (the GPU, the driver, the GL strings).
set -euo pipefail
[[ $# -eq 2 ]] || { echo "usage: run_on_gpu.sh PROBE OUTDIR" >&2; exit 2; }
P=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
mkdir -p "$2"
O=$(cd "$2" && pwd)
shopt -s nullglob
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
if [[ ! -e /usr/share/glvnd/egl_vendor.d/10_nvidia.json && -e /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true; } >"$O/gpu-info.txt"
cd "$(dirname "${BASH_SOURCE[0]}")"
"$P" probe.vert undefined.frag 40 >"$O/gpu.txt" 2>>"$O/gpu-info.txt"
# Twice more: the same bits every time?
for k in 1 2; do "$P" probe.vert undefined.frag 40 >"$O/again$k.txt" 2>/dev/null; done
md5sum "$O/gpu.txt" "$O/again1.txt" "$O/again2.txt" | awk '{print $1}' | sort -u | wc -l | sed 's/^/distinct results of 3 runs: /' >>"$O/gpu-info.txt"
