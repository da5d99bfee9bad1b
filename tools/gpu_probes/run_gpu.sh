#!/bin/bash
# usage: bash tools/gpu_probes/run_gpu.sh GLREF OUTDIR
# On a machine with a GPU driver (see ../shared/tools/gpu/README.md: the glvnd loader .debs in .gl/
# and a glref built with --driver gpu, its libraries in LD_LIBRARY_PATH): renders every probe here
# with `GLREF --driver gpu` into OUTDIR/probes.tar (NAME.png, NAME.log, info.txt: the GL strings and
# one line per probe). From the checkout's root.
set -uo pipefail
[[ $# -eq 2 ]] || { echo "usage: bash tools/gpu_probes/run_gpu.sh GLREF OUTDIR" >&2; exit 2; }
G=$(realpath "$1"); D=$(mkdir -p "$2" && cd "$2" && pwd); O=$(mktemp -d)
shopt -s nullglob
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
if [[ ! -e /usr/share/glvnd/egl_vendor.d/10_nvidia.json && -e /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
cd tools/gpu_probes || exit 1
rc=0
for p in texfilter lod lodnorm lodrand lod3d texkinds mipgen cube funcs2 textured_lin; do
  frag=$p.frag; [[ $p == textured_lin ]] && frag=../../shaders/textured_pix.frag
  vert=probe.vert; [[ $p == textured_lin ]] && vert=../../shaders/textured_pix.vert
  if "$G" --driver gpu "$vert" "$frag" "$p.toml" -o "$O/$p.png" >"$O/$p.log" 2>&1; then
    echo "$p OK: $(tail -n 2 "$O/$p.log" | tr '\n' ' ')" >>"$O/info.txt"
  else
    echo "$p FAILED: $(tr '\n' ' ' <"$O/$p.log" | tail -c 600)" >>"$O/info.txt"; rc=1
  fi
done
head -n 12 "$O/texfilter.log" >>"$O/info.txt"
cat "$O/info.txt"
tar -cf "$D/probes.tar" -C "$O" .
exit $rc
