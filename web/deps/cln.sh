# CLN for WebAssembly (sourced by scripts/build-wasm-deps): its integers in portable C++, without
# GMP and without assembly. Installs into $stage (DESTDIR) under the prefix $prefix.
build_cln() {
  unpack cln "$1"
  cd "$work/cln"
  # Cross-compiling, configure cannot run CLN's two probes of the machine (its integer types and
  # its floating-point types) and guesses instead: minutes of test compilations, and for the
  # integers a wrong include/cln/intparam.h for wasm32 (31-bit ints and #error lines). It is told
  # the files are made (cl_cv_file_*), and the probes are run below as configure runs them on the
  # machine it builds for: compiled for WebAssembly, run in Node.
  step "configuring CLN" env cl_cv_file_intparam_h=1 cl_cv_file_floatparam_h=1 \
    emconfigure ./configure --host=none --prefix="$prefix" --disable-shared --enable-static \
    --without-gmp CXXFLAGS="$cxxflags -DNO_ASM" CFLAGS="$cflags"
  step "probing wasm32's integer types for CLN (include/cln/intparam.h)" cln_intparam
  step "probing wasm32's floating-point types for CLN (include/cln/floatparam.h)" cln_floatparam
  step "building CLN" emmake make -j"$jobs" SUBDIRS=src
  step "installing CLN" emmake make install SUBDIRS=src DESTDIR="$stage"
}

# cln_probe NAME DEFINE: CLN's autoconf/NAME.c, compiled for WebAssembly and run in Node, writes
# include/cln/NAME.h.
cln_probe() {
  { printf '#define %s 1\n' "$2"; cat "autoconf/$1.c"; } > "$work/$1.c"
  emcc -O0 -sSINGLE_FILE=1 "$work/$1.c" -o "$work/$1.js"  # Node 20 cannot fetch a .wasm beside it
  node "$work/$1.js" > "include/cln/$1.h"
  ! grep -q '#error' "include/cln/$1.h"
}

# What wasm32 is (the WebAssembly specification, clang's wasm32 target): int, long and pointers of
# 32 bits, long long of 64; float and double IEEE 754 binary32 and binary64.
cln_intparam() {
  cln_probe intparam HAVE_LONGLONG &&
    grep -q '^#define int_bitsize 32$' include/cln/intparam.h &&
    grep -q '^#define long_bitsize 32$' include/cln/intparam.h &&
    grep -q '^#define long_long_bitsize 64$' include/cln/intparam.h &&
    grep -q '^#define pointer_bitsize 32$' include/cln/intparam.h
}
cln_floatparam() {
  cln_probe floatparam HAVE_LONGDOUBLE &&
    grep -q '^#define float_mant_bits 24$' include/cln/floatparam.h &&
    grep -q '^#define double_mant_bits 53$' include/cln/floatparam.h
}
