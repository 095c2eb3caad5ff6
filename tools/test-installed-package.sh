#!/usr/bin/env bash
# The C++ package end to end (README "Linking an engine in process"): cyclecert installed into a
# staging prefix, examples/inprocess-engine configured and built against that prefix alone, and its
# GoogleTest suite run — every installed spec case registered as a test, the fuzz property, the
# direct test. Usage: tools/test-installed-package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
work=$build/package-test
stage=$work/stage
example=$work/example
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$stage" >"$work/install.log"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$source/examples/inprocess-engine" -B "$example" -DCMAKE_PREFIX_PATH="$stage" \
      -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >"$work/configure.log"
cmake --build "$example" -j 2 >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }

# Built against the staged package, not the source tree: no include path of the build names it.
if grep -qE -- "(-I|-isystem )$source(/include)?( |\$)" "$example/CMakeFiles/my_controller_tests.dir/flags.make"; then
  echo "the example's include paths name the source tree:"; cat "$example/CMakeFiles/my_controller_tests.dir/flags.make"
  exit 1
fi

# One test per installed spec case.
cases=$(find "$stage/share/cyclecert/specs/cases" -name '*.json' | wc -l)
registered=$("$example/my_controller_tests" --gtest_list_tests --gtest_filter='MyControllerSpecs.*' | grep -c '^  ' || true)
if [ "$cases" -eq 0 ] || [ "$cases" != "$registered" ]; then
  echo "the installed suite has $cases spec cases, the example registered $registered tests"; exit 1
fi

"$example/my_controller_tests" --gtest_brief=1
echo "package test: $registered spec-case tests and the fuzz property passed against the staged install"
