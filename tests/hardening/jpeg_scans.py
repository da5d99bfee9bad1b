"""JPEGs that ask a decoder for more work than their size suggests: one scan
of a progressive file repeated many times. Used by python/tests/
test_hardening.py (the reproducer) and run by hand to time the decode at
the scan limit (docs/limits.md):

    /usr/bin/python3 tests/hardening/jpeg_scans.py build/glslrun SIDE SCANS
"""
import io
import os
import resource
import subprocess
import sys
import tempfile


def segments(data):
    """(marker, start, end) of each marker segment; a scan's segment runs to
    the end of its entropy-coded data."""
    out, pos = [], 2
    while pos + 1 < len(data):
        marker = data[pos + 1]
        if marker == 0xD9:
            out.append((marker, pos, pos + 2))
            break
        length = data[pos + 2] << 8 | data[pos + 3]
        end = pos + 2 + length
        if marker == 0xDA:  # entropy data: up to a marker that is neither stuffing nor a restart
            while end + 1 < len(data) and not (data[end] == 0xFF and data[end + 1] != 0 and
                                               not 0xD0 <= data[end + 1] <= 0xD7):
                end += 1
        out.append((marker, pos, end))
        pos = end
    return out


def repeat_scan(data, scan, times):
    """The file with its scan number `scan` (0: the first) `times` times over."""
    parts = segments(data)
    scans = [p for p in parts if p[0] == 0xDA]
    _, start, end = scans[scan]
    return data[:start] + data[start:end] * times + data[end:]


def progressive(side, grey=False):
    """A flat progressive JPEG of side x side: its AC scans are a few end-of-band runs."""
    from PIL import Image
    buf = io.BytesIO()
    Image.new("L" if grey else "RGB", (side, side), 128).save(buf, "JPEG", progressive=True, subsampling=0)
    return buf.getvalue()


def time_decode(glslrun, path):
    """CPU seconds of a 1x1 render of a scene that samples the image: its decoding, mostly."""
    with tempfile.TemporaryDirectory() as d:
        scene = os.path.join(d, "s.toml")
        with open(scene, "w") as f:
            f.write(f'[output]\nsize = [1, 1]\n[textures.0]\nimage = "{path}"\n[[objects]]\nmesh = "quad"\n')
        vs, fs = os.path.join(d, "a.vert"), os.path.join(d, "a.frag")
        open(vs, "w").write("void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = gl_MultiTexCoord0; }\n")
        open(fs, "w").write("uniform sampler2D t; void main() { gl_FragColor = texture2D(t, gl_TexCoord[0].xy); }\n")
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        run = subprocess.run([glslrun, vs, fs, scene, "-o", os.path.join(d, "o.png")], capture_output=True, text=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
        return cpu, run.returncode, run.stderr.strip().splitlines()[-1]


def main():
    glslrun, side, scans = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    base = progressive(side)
    n = sum(1 for p in segments(base) if p[0] == 0xDA)
    for scan in range(n):
        data = repeat_scan(base, scan, scans - n + 1)
        with tempfile.NamedTemporaryFile(suffix=".jpg") as f:
            f.write(data)
            f.flush()
            seconds, rc, err = time_decode(glslrun, f.name)
        print(f"{side}x{side}, scan {scan} of {n} repeated to {scans} scans, {len(data)} bytes: "
              f"{seconds:.2f} s of CPU, exit {rc} {err[:100]}")


if __name__ == "__main__":
    main()
