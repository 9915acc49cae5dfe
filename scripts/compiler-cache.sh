# Sourced by the build scripts: `compiler_cache` holds the cmake arguments that put ccache in front of the
# compilers when the machine has it (rebuilds of other checkouts and of sanitizer builds are then quick);
# nothing needs it.
compiler_cache=()
if command -v ccache >/dev/null 2>&1; then
  compiler_cache=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
