# GSL for WebAssembly (sourced by scripts/build-wasm-deps): the parts of the library the checker
# calls and the parts those call, not the rest (the whole library is about three times the work,
# on the critical path of a fresh machine's CI run). The checker uses vectors and matrices, random
# numbers, roots of a function and of a polynomial, Gauss-Legendre quadrature, the hybrid solver
# of a system (which factorises with linalg and BLAS) and the ODE driver; a call outside these
# parts fails the wasm preset's link (an undefined symbol is an error there), never at run time.
# Installs into $stage (DESTDIR) under the prefix $prefix.
build_gsl() {
  unpack gsl "$1"
  cd "$work/gsl"
  step "configuring GSL" emconfigure ./configure --host=none --prefix="$prefix" \
    --disable-shared --enable-static CFLAGS="$cflags"
  # gsl/ links every part's headers; utils/, sys/ and err/ are what every part uses.
  local parts="gsl utils sys err ieee-utils complex block vector matrix permutation cblas blas
               linalg rng roots poly integration multiroots ode-initval2"
  local part libs="" lib
  for part in $parts; do
    # A part's library is named in the top Makefile's list of them (SUBLIBS), e.g. libgslodeiv2.
    lib="$(sed -n 's/^SUBLIBS = //p' Makefile.am | tr ' ' '\n' | grep "^$part/" || true)"
    libs="$libs $lib"
  done
  parts="$(echo $parts)"
  # (and not its two programs, gsl-randist and gsl-histogram, which need parts left out)
  step "building GSL (parts: $parts)" \
    emmake make -j"$jobs" SUBDIRS="$parts" SUBLIBS="$libs" bin_PROGRAMS=
  step "installing GSL" \
    emmake make install SUBDIRS="$parts" SUBLIBS="$libs" bin_PROGRAMS= DESTDIR="$stage"
  # The headers of every part, as the whole library installs them (CMake's FindGSL looks for
  # gsl_sf.h): gsl/ links them all.
  step "installing every part's headers" cp -fL gsl/gsl*.h "$stage$prefix/include/gsl/"
}
