# GiNaC for WebAssembly (sourced by scripts/build-wasm-deps): the library alone (not ginsh, the
# tools or the tests), against the CLN built before it in $cln_prefix. Installs into $stage
# (DESTDIR) under the prefix $prefix.
build_ginac() {
  unpack ginac "$1"
  cd "$work/ginac"
  # configure looks for CLN with pkg-config, which emconfigure's environment does not point at.
  step "configuring GiNaC" emconfigure ./configure --host=none --prefix="$prefix" \
    --disable-shared --enable-static \
    CLN_CFLAGS="-I$cln_prefix/include" CLN_LIBS="-L$cln_prefix/lib -lcln" \
    CXXFLAGS="$cxxflags" CFLAGS="$cflags"
  step "building GiNaC" emmake make -j"$jobs" SUBDIRS=ginac
  step "installing GiNaC" emmake make install SUBDIRS=ginac DESTDIR="$stage"
}
