#!/bin/sh
# `glslrun test` as a user meets it: probe regions out of int's range fail
# instead of passing unchecked, compile errors cite the test file's own lines
# (a one-line section too), one line per test that does not pass (--verbose:
# every test, --quiet: none), a counter and ETA on a terminal, and unlisted
# skips under --expect counted as regressions.
#
#   tests/cli/test_command.sh SOURCE_DIR GLSLRUN
set -u
src=$1
glslrun=$2
. "$src/tests/cli/common.sh"
cd "$tmp" || exit 1

# shader_test NAME FRAGMENT_LINE TEST_LINES: a test that draws the fragment shader's one line.
shader_test() {
    printf '[require]\nGLSL >= 1.10\n\n[vertex shader passthrough]\n\n[fragment shader]\n%s\n\n[test]\ndraw rect -1 -1 2 2\n%s\n' \
        "$2" "$3" > "$1.shader_test"
}
green='void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }'

# Float probe coordinates past int's range: the region wrapped and nothing was probed.
shader_test wide "$green" 'probe rect rgba (0, 0, 3e9, 10) (1.0, 0.0, 0.0, 1.0)'
shader_test relwide "$green" 'relative probe rect rgba (0, 0, 1e30, 0.5) (1.0, 0.0, 0.0, 1.0)'
shader_test far "$green" 'probe rect rgba (3e9, 0, 10, 10) (1.0, 0.0, 0.0, 1.0)'
shader_test nan "$green" 'probe rgba (nan, 0) (1.0, 0.0, 0.0, 1.0)'
for t in wide relwide far; do
    "$glslrun" test $t.shader_test > $t.txt
    [ $? = 1 ] && grep -q "line 11: probe region .* is outside the 250x250 window" $t.txt ||
        fail "$t: a probe outside the window did not fail: $(cat $t.txt)"
done
"$glslrun" test nan.shader_test > nan.txt && fail "a probe at NaN passed: $(cat nan.txt)"
shader_test good "$green" 'probe rect rgba (0, 0, 250, 250) (0.0, 1.0, 0.0, 1.0)'
"$glslrun" test good.shader_test > good.txt || fail "a good probe failed: $(cat good.txt)"

# Compile errors at the file's lines: the section starts on line 7.
shader_test undeclared 'void main() { gl_FragColor = vec4(1.0) + undefined_name; }' ''
"$glslrun" test undeclared.shader_test > undeclared.txt
grep -q "undeclared.shader_test:7: error: 'undefined_name'" undeclared.txt ||
    fail "the error is not at the file's line 7: $(cat undeclared.txt)"
shader_test one 'void main() { gl_FragColor = vec4(1.0) }' ''
"$glslrun" test one.shader_test > one.txt
grep -q "one.shader_test:7: error:" one.txt || fail "a one-line section's error is not on its line 7: $(cat one.txt)"
printf '[require]\nGLSL >= 1.10\n\n[vertex shader]\nvoid main() {\n    gl_Position = gl_Vertex;\n    float x = 1.0\n}\n\n[fragment shader]\n%s\n' \
    "$green" > multi.shader_test
"$glslrun" test multi.shader_test > multi.txt
grep -q "multi.shader_test:7: error: missing ';'" multi.txt || fail "multi-line section: $(cat multi.txt)"

# Output: a line per test that does not pass; --verbose every test; --quiet none; the summary always.
"$glslrun" test good.shader_test wide.shader_test > default.txt
grep -q "^pass" default.txt && fail "a passing test got a line by default: $(cat default.txt)"
grep -q "^fail  wide.shader_test" default.txt || fail "a failing test got no line: $(cat default.txt)"
grep -q "^1 passed, 1 failed, 0 skipped" default.txt || fail "no summary: $(cat default.txt)"
"$glslrun" test -v good.shader_test wide.shader_test | grep -q "^pass  good.shader_test" || fail "--verbose"
"$glslrun" test --quiet good.shader_test wide.shader_test > quiet.txt
[ "$(grep -c "shader_test" quiet.txt)" = 0 ] && grep -q "^1 passed, 1 failed" quiet.txt || fail "--quiet: $(cat quiet.txt)"
if command -v script > /dev/null; then
    script -qec "$glslrun test --quiet good.shader_test wide.shader_test" /dev/null > tty.txt 2>&1
    grep -q "2/2 tests, 1 failed" tty.txt || fail "no counter on a terminal: $(cat tty.txt)"
fi

# --expect: unlisted tests must pass; an unlisted skip is a regression, a listed one is not.
printf '[require]\nGLSL >= 1.30\n\n[fragment shader]\n%s\n' "$green" > skip.shader_test
: > none.txt
"$glslrun" test --expect none.txt good.shader_test skip.shader_test > expect.txt
[ $? = 1 ] && grep -q "skip.shader_test: expected pass, got skip" expect.txt || fail "unlisted skip: $(cat expect.txt)"
echo "skip.shader_test  skip  # GLSL 1.30" > listed.txt
"$glslrun" test --expect listed.txt good.shader_test skip.shader_test > listed.out || fail "listed skip: $(cat listed.out)"

finish "glslrun test: probes range-checked, file lines, quiet/verbose, progress, expectations"
