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
# NAME or NAME=VERT:FRAG:SCENE (the default: probe.vert, NAME.frag, NAME.toml).
PROBES=${PROBES:-"texfilter lod lodnorm lodrand lod3d texkinds tex3dw blendover mipgen cube funcs2 trilod tribias fma fma2 mandel
  $(for c in r g b; do echo "volslice_$c=../../bench/corpus/volume.vert:volslice.frag:volslice_$c.toml"; done)
  textured_lin=../../shaders/textured_pix.vert:../../shaders/textured_pix.frag:textured_lin.toml
  textured_texel=../../shaders/textured_pix.vert:textured_texel.frag:textured_probe.toml
  textured_lod=textured_400.vert:textured_lod.frag:textured_probe.toml
  textured_s=textured_400.vert:textured_coord.frag:textured_s.toml
  textured_t=textured_400.vert:textured_coord.frag:textured_t.toml
  bloom_s0=../../scenes/programs/bloom.vert:../../scenes/programs/bloom.frag:bloom_s0.toml
  bloom_s1=../../scenes/programs/bloom.vert:../../scenes/programs/bloom.frag:bloom_s1.toml
  bloom_s2=../../scenes/programs/bloom.vert:../../scenes/programs/bloom.frag:bloom_s2.toml
  bloom_s3=../../scenes/programs/bloom.vert:../../scenes/programs/bloom.frag:bloom_s3.toml
  trilin_w=trilin.vert:trilin.frag:trilin_w.toml trilin_1=trilin.vert:trilin.frag:trilin_1.toml
  trilin_2=trilin.vert:trilin.frag:trilin_2.toml trilin_3=trilin.vert:trilin.frag:trilin_3.toml
  trilin_4=trilin.vert:trilin.frag:trilin_4.toml
  $(for t in trimp_l*_m*_w*.toml; do echo "${t%.toml}=trilin.vert:trimp.frag:$t"; done)
  textured_raw_s=textured_400.vert:textured_raw.frag:textured_s.toml
  textured_raw_t=textured_400.vert:textured_raw.frag:textured_t.toml
  textured_qraw=textured_400.vert:textured_qraw.frag:textured_probe.toml
  trigrad=trilin.vert:trigrad.frag:trigrad.toml
  $(for w in 0 1 2 3 4 5; do echo "textured_grad_$w=textured_400.vert:textured_grad.frag:textured_grad_$w.toml"; done)"}
for job in $PROBES; do
  p=${job%%=*}; vert=probe.vert; frag=$p.frag; scene=$p.toml
  [[ $job == *=* ]] && IFS=: read -r vert frag scene <<<"${job#*=}"
  if "$G" --driver gpu "$vert" "$frag" "$scene" -o "$O/$p.png" >"$O/$p.log" 2>&1; then
    echo "$p OK: $(tail -n 2 "$O/$p.log" | tr '\n' ' ')" >>"$O/info.txt"
  else
    echo "$p FAILED: $(tr '\n' ' ' <"$O/$p.log" | tail -c 600)" >>"$O/info.txt"; rc=1
  fi
done
head -n 12 "$O/${PROBES%%[= ]*}.log" >>"$O/info.txt" 2>/dev/null
cat "$O/info.txt"
tar -cf "$D/probes.tar" -C "$O" .
exit $rc
