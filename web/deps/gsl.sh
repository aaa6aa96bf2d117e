# GSL for WebAssembly (sourced by scripts/build-wasm-deps): every part of the library, not its
# manual (Debian's source package leaves the manual's sources out, so doc/ cannot be built).
# Installs into $stage (DESTDIR) under the prefix $prefix.
build_gsl() {
  unpack gsl "$1"
  cd "$work/gsl"
  step "configuring GSL" emconfigure ./configure --host=none --prefix="$prefix" \
    --disable-shared --enable-static CFLAGS="$cflags"
  local parts
  parts="$(sed -n 's/^SUBDIRS = //p' Makefile.am | tr ' ' '\n' | grep -vx doc | tr '\n' ' ')"
  step "building GSL" emmake make -j"$jobs" SUBDIRS="$parts"
  step "installing GSL" emmake make install SUBDIRS="$parts" DESTDIR="$stage"
}
