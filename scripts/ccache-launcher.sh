# Sourced by build.sh, sanitize.sh and fuzz.sh from the checkout's root: sets `launcher` (the
# CMake argument that compiles through ccache, when it is installed) and one cache for every
# clone of the project (paths relative to the checkout; with -g ccache would otherwise put the
# folder into the hash).
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
export CCACHE_BASEDIR="$PWD"
export CCACHE_NOHASHDIR=1
