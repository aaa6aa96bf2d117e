# What the builds of the checker's libraries for WebAssembly share (sourced by
# scripts/build-wasm-deps; this file is part of every library's key). Uses $sources (the source
# packages), $work (a scratch folder), $log and $start.

# WebAssembly's own exceptions: GiNaC and CLN throw C++ exceptions that the checker catches (a
# division by zero in a step is a verdict, not a crash), so every C++ library is built with the
# module's exception model.
cxxflags="-O2 -fwasm-exceptions"
cflags="-O2"
jobs=2  # the machine's two cores

# Emscripten's JavaScript optimiser needs Debian's acorn (node-acorn, in /usr/share/nodejs), which
# a Node not installed from Debian does not look for.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"

# Runs a step with its output in the log; on failure shows the log's end.
step() {
  local what="$1"
  shift
  echo "build-wasm-deps: $what ($(($(date +%s) - start)) s)"
  if ! "$@" >> "$log" 2>&1; then
    echo "build-wasm-deps: $what failed; the end of its log ($log):" >&2
    tail -n 40 "$log" >&2
    exit 1
  fi
}

# Unpacks a source package into $work/NAME (Debian's own patches applied), then applies ours,
# web/deps/patches/NAME/*.patch.
unpack() {
  local name="$1" version="$2" patch
  # apt-get source checked the files against the archive's signed index already.
  step "unpacking $name $version" dpkg-source --no-check -x \
    "$sources/${name}_$version/${name}_$version.dsc" "$work/$name"
  for patch in "$recipes/patches/$name"/*.patch; do
    [ -f "$patch" ] || continue
    step "applying $(basename "$patch")" patch -d "$work/$name" -p1 --forward -i "$patch"
  done
}

# After `make install` into $stage: libtool's archives name the scratch folder (static libraries
# and pkg-config need none of them), and the .pc files name their folder relative to themselves,
# so that the three libraries can be put together in another folder.
finish_install() {
  find "$stage$prefix" -name '*.la' -delete
  sed -i "s|^prefix=$prefix\$|prefix=\${pcfiledir}/../..|" "$stage$prefix"/lib/pkgconfig/*.pc
}
