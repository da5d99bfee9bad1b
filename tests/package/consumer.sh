#!/bin/sh
# The installed package as a user's own project sees it: `cmake --install`
# into a staging prefix under the build directory, then examples/ built
# outside this project, once with find_package(glslrun) and once with
# pkg-config, and run. The spot scene rendered through the package must be
# byte-identical to the command line's PNG; the Python module must import
# from the staged prefix; a C++17 project must compile against glslrun.h.
# The install must be stripped and under 60 MB, its components must hold
# what they say, the man page and the bash completion must work. Then a
# project that adds this tree with add_subdirectory() must configure, and
# the uninstall target must leave the staged prefix empty.
#   consumer.sh SOURCE_DIR BUILD_DIR GLSLRUN_BINARY [PYTHON]
set -eu
src=$1 build=$2 cli=$3 python=${4:-python3}
stage=$build/package/stage out=$build/package
rm -rf "$out"
mkdir -p "$out"
cmake --install "$build" --prefix "$stage" > "$out/install.log"

# Stripped by default (cmake/install_strip.cmake): 355 MB before, unstripped.
size_kb=$(du -sk "$stage" | cut -f1)
echo "installed size: $((size_kb / 1024)) MB"
if [ "$size_kb" -ge $((60 * 1024)) ]; then
    echo "the install is $size_kb KB, over 60 MB: is it stripped?" >&2
    exit 1
fi
if file -L "$stage/bin/glslrun" "$stage"/lib/libglslrun.so.0 | grep "not stripped"; then exit 1; fi

# Components: what each holds, and nothing of the others.
for component in runtime development python; do
    cmake --install "$build" --prefix "$out/$component" --component $component > /dev/null
done
has() { test -e "$1" || test -L "$1" || { echo "missing from the install: $1" >&2; exit 1; }; }
lacks() { test ! -e "$1" || { echo "should not be installed: $1" >&2; exit 1; }; }
has "$out/runtime/bin/glslrun"
has "$out/runtime/lib/libglslrun.so.0"
has "$out/runtime/share/man/man1/glslrun.1"
has "$out/runtime/share/doc/glslrun/LICENSE"
has "$out/runtime/share/bash-completion/completions/glslrun"
has "$out/runtime/share/glslrun/serve/index.html"
lacks "$out/runtime/include"
lacks "$out/runtime/lib/libglslrun.a"
has "$out/development/include/glslrun/glslrun.h"
has "$out/development/lib/libglslrun.a"
has "$out/development/lib/libglslrun.so"
has "$out/development/lib/cmake/glslrun/glslrunConfig.cmake"
lacks "$out/development/bin"
if [ -d "$out/python/lib" ]; then
    has "$(echo "$out"/python/lib/python3*/dist-packages/glslrun)/__init__.pyi"
    lacks "$out/python/bin"
fi
echo "components runtime, development, python: as documented"

# The man page (help2man over the built command's --help) names every
# subcommand and the options of the help it came from.
man_page=$stage/share/man/man1/glslrun.1
for command in test trace batch serve; do
    grep -q "glslrun $command" "$man_page" || { echo "the man page lacks glslrun $command" >&2; exit 1; }
done
sed 's/\\-/-/g' "$man_page" > "$out/man.txt"  # roff's \- is a plain hyphen
for option in $("$stage/bin/glslrun" --help | grep -oE -- '--[a-z][a-z-]*' | sort -u); do
    grep -qF -- "$option" "$out/man.txt" || { echo "the man page lacks $option" >&2; exit 1; }
done
# bash completion: options from the command's help, values, subcommands.
bash -c '
    . "$1"
    complete_line() { COMP_WORDS=("$2" "${@:3}"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _glslrun; echo "${COMPREPLY[*]}"; }
    set -e
    complete_line x "$2" --prec | grep -qx -- "--precision"
    complete_line x "$2" --precision f | grep -qx "fast"
    complete_line x "$2" tr | grep -qw "trace"
    complete_line x "$2" test --jun | grep -qx -- "--junit"
    complete_line x "$2" serve --po | grep -qx -- "--port"
' sh "$stage/share/bash-completion/completions/glslrun" "$stage/bin/glslrun"
# zsh completion, where zsh is installed (tools/setup.sh test installs it):
# compadd and _files stand in for the completion system's, printing what they get.
if command -v zsh > /dev/null; then
    zsh -c '
        compadd() { if [[ $1 == -a ]]; then print -r -- "${(P)2}"; else print -r -- "$*"; fi }
        _files() { print -r -- _files; }
        try() { local file=$1; shift; words=("$@"); CURRENT=${#words}; (source $file) }
        try_all() {
            try "$1" "$2" --prec | tr " " "\n" | grep -qx -- --precision &&
            try "$1" "$2" --precision f | grep -qw fast &&
            try "$1" "$2" tr | grep -qw trace &&
            try "$1" "$2" test --jun | tr " " "\n" | grep -qx -- --junit &&
            try "$1" "$2" serve --po | tr " " "\n" | grep -qx -- --port &&
            try "$1" "$2" a.vert sc | grep -qx _files
        }
        try_all "$1" "$2"
    ' zsh "$stage/share/zsh/site-functions/_glslrun" "$stage/bin/glslrun" ||
        { echo "the zsh completion does not complete as it should" >&2; exit 1; }
fi
echo "man page, bash and zsh completion: from glslrun --help"

spot="$src/shaders/spot_pix_fixed.vert $src/shaders/spot_pix_fixed.frag $src/scenes/spot.toml"
"$cli" $spot -o "$out/spot-cli.png" > /dev/null

echo "find_package(glslrun):"
cmake -S "$src/examples" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$stage" \
    > "$out/cmake.log"
cmake --build "$out/cmake" > "$out/cmake-build.log"
"$out/cmake/render_quad" "$out/quad-cmake.png"
"$out/cmake/render_scene" $spot "$out/spot-cmake.png"
cmp "$out/spot-cli.png" "$out/spot-cmake.png"

echo "pkg-config glslrun: $(PKG_CONFIG_PATH=$stage/lib/pkgconfig pkg-config --cflags --libs glslrun)"
export PKG_CONFIG_PATH="$stage/lib/pkgconfig"
libdir=$(pkg-config --variable=libdir glslrun)
c++ -std=c++20 "$src/examples/render_quad.cpp" -o "$out/render_quad_pc" \
    $(pkg-config --cflags --libs glslrun) -Wl,-rpath,"$libdir"
"$out/render_quad_pc" "$out/quad-pc.png"
# The shared library, with its SONAME.
ldd "$out/render_quad_pc" | grep -q 'libglslrun\.so\.0 '
c++ -std=c++20 "$src/examples/render_scene.cpp" -o "$out/render_scene_pc" \
    $(pkg-config --cflags --libs glslrun-scene) -Wl,-rpath,"$libdir"
"$out/render_scene_pc" $spot "$out/spot-pc.png"
cmp "$out/spot-cli.png" "$out/spot-pc.png"

# C++17: the public header compiles and links (the library stays C++20).
cat > "$out/cpp17.cpp" <<'CPP'
#include <cstdio>
#include <vector>
#include "glslrun/glslrun.h"
int main() {
    auto program = glslrun::Program::compile({{"a.vert", "void main() { gl_Position = gl_Vertex; }"}},
                                             {{"a.frag", "uniform float w[2]; void main() { gl_FragColor = vec4(w[0], w[1], 0, 1); }"}});
    if (!program) return std::fputs(program.error().str().c_str(), stderr), 1;
    std::vector<float> w = {1.0f, 0.5f};
    if (!program->set_uniform("w", w)) return 1;
    glslrun::Framebuffer fb(4, 4);
    std::vector<glslrun::VertexAttrib> quad = {{"gl_Vertex", 2, {-1, -1, 1, -1, -1, 1, 1, 1}}};
    auto drawn = glslrun::draw(*program, glslrun::GLState(), fb, glslrun::Primitive::TriangleStrip, quad, 4);
    glslrun::Span<const uint8_t> rgba = fb.color_data<uint8_t>();
    if (!drawn || rgba.size() != 64 || rgba[0] != 255 || rgba[1] != 128) return 1;
    std::puts("  C++17 consumer: drew (255, 128, 0, 255)");
    return 0;
}
CPP
c++ -std=c++17 -Wall -Wextra -Werror -pedantic "$out/cpp17.cpp" -o "$out/cpp17" $(pkg-config --cflags --libs glslrun) \
    -Wl,-rpath,"$libdir"
"$out/cpp17"

if ls "$stage"/lib/python3*/dist-packages/glslrun/__init__*.so > /dev/null 2>&1; then
    echo "python3 -c 'import glslrun' from the staged prefix:"
    PYTHONPATH=$(echo "$stage"/lib/python3*/dist-packages) "$python" -c \
        "import glslrun; a = glslrun.render('$src/shaders/minimal.vert', '$src/shaders/minimal.frag', '$src/scenes/quad.toml'); print(' ', glslrun.__version__, a.shape, a.dtype)"
fi

echo "add_subdirectory(glslrun):"
mkdir -p "$out/sub"
cat > "$out/sub/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.20)
project(user CXX)
add_subdirectory("$src" glslrun)
add_executable(user "$src/examples/render_scene.cpp")
target_link_libraries(user PRIVATE glslrun::scene)
CMAKE
cmake -S "$out/sub" -B "$out/sub/build" -G Ninja > "$out/sub.log"
echo "  configures"

# uninstall: every file the install above wrote, and glslrun's own directories.
cmake --build "$build" --target uninstall > "$out/uninstall.log"
left=$(find "$stage" -type f -o -type l)
if [ -n "$left" ]; then
    echo "uninstall left files behind:" >&2
    echo "$left" >&2
    exit 1
fi
echo "uninstall: $stage holds no file"
