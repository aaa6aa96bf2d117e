// SPDX-License-Identifier: GPL-3.0-or-later
// LeakSanitizer's suppressions for the programs that link the checker, compiled into each of
// them (an interface source of impulselab_checker, in sanitized builds only): LeakSanitizer
// reads them from the executable at exit.
//
// CLN, GiNaC's number library, allocates 26 bytes while it initialises (before main) and never
// frees them; LeakSanitizer's report of that at exit gave every such program (impulselab, the
// checker's and the command line's tests) a failing exit status. The allocation is CLN's, not
// ImpulseLab's, and happens once: it is suppressed by CLN's module name.
//
// GiNaC leaks the partial results of an evaluation that throws: (a b + c)/(a - b) evaluated at
// a = b = 2 throws "power::eval(): division by zero" and leaves about 240 bytes allocated in
// GiNaC::mul::combine_ex_with_coeff_to_pair and GiNaC::numeric::add_dyn (a ten-line program shows
// it under -fsanitize=address). The derivation checker meets such evaluations in students' files
// (a division by zero written out is refused with its place; an expression that is undefined
// only at some point is evaluated there while a counterexample is looked for, where it avoids
// the divisions it can see). GiNaC's expressions are reference-counted trees that ImpulseLab never
// allocates itself, so a leak inside libginac is GiNaC's: suppressed by its module name.
#if defined(__SANITIZE_ADDRESS__)
#define IMPULSELAB_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define IMPULSELAB_LSAN 1
#endif
#endif

#ifdef IMPULSELAB_LSAN
// NOLINTBEGIN(bugprone-reserved-identifier): the names LeakSanitizer looks for.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libcln.so\nleak:libginac.so\n";
}
// Without this, the count of suppressed leaks is printed on standard error at every exit, which
// the command-line tests read.
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
// NOLINTEND(bugprone-reserved-identifier)
#endif
