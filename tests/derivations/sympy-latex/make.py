#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""SymPy's parse_latex test corpus as derivation files (run with /usr/bin/python3, Debian's
python3-sympy 1.11; not part of the test suite).

The strings come from sympy/parsing/tests/test_latex.py: its GOOD_PAIRS (a LaTeX string and the
SymPy expression it means) and its BAD_STRINGS (LaTeX that must be refused). Every pair kept
becomes a file

    $$w = <the string>$$      (a premise)
    $$w = <its value>$$       (a step: it must follow)

with the value written here by hand in the contract's LaTeX (and, beside it, as a SymPy
expression: this script checks that it equals SymPy's expression for the pair, so a value
written wrong stops the script). The left side is `w` because the strings use x, y, z, a, b, c.
Every bad string becomes a file `$$w = <the string>$$` that must be refused.

manifest.tsv says, per file, what the checker must do:
  follows   the string is in notation the contract lists: the step must be `follows`
  refused   outside the contract (the reason says why): the file must be refused (exit 2)
  either    outside the contract, but unambiguous LaTeX the checker may read: it must be read
            right (the step `follows`) or refused, never misread

  make.py            write the files and manifest.tsv
  make.py --check    exit 1 when they differ from what this script writes
"""
import os
import sys

import sympy as sp
from sympy.parsing.tests import test_latex as T

HERE = os.path.dirname(os.path.abspath(__file__))
x, y, z, a, b, c, t, k, n, theta = sp.symbols("x y z a b c t k n theta")

F, R, E = "follows", "refused", "either"
NOT_CONTRACT = "outside the contract"

# (string, expect, reason, value in LaTeX, value in SymPy)
KEPT = [
    (r"0", F, "a number", r"0", "0"),
    (r"1", F, "a number", r"1", "1"),
    (r"-3.14", F, "a decimal number", r"-\frac{157}{50}", "-Rational(157, 50)"),
    (r"(-7.13)(1.5)", F, "decimals, a product", r"-\frac{2139}{200}", "-Rational(2139, 200)"),
    (r"x", F, "a symbol", r"x", "x"),
    (r"2x", F, "a product side by side", r"2 x", "2*x"),
    (r"x^2", F, "a power", r"x^2", "x**2"),
    (r"x^\frac{1}{2}", F, "a power of a fraction", r"\sqrt{x}", "sqrt(x)"),
    (r"x^{3 + 1}", F, "a power", r"x^4", "x**4"),
    (r"-c", F, "a minus sign", r"-c", "-c"),
    (r"a \cdot b", F, "\\cdot", r"a b", "a*b"),
    (r"a / b", F, "/", r"\frac{a}{b}", "a/b"),
    (r"a \div b", E, "\\div is " + NOT_CONTRACT + " (the docs accept it)", r"\frac{a}{b}",
     "a/b"),
    (r"a + b", F, "+", r"a + b", "a + b"),
    (r"a + b - a", F, "+ and -", r"b", "b"),
    (r"(x + y) z", F, "parentheses", r"x z + y z", "x*z + y*z"),
    (r"a'b+ab'", F, "primes", r"b a' + a b'", "Symbol(\"a'\")*b + a*Symbol(\"b'\")"),
    (r"y''_1", F, "primes before a subscript", r"y_1''", "Symbol(\"y_{1}''\")"),
    (r"y_1''", F, "primes after a subscript", r"y''_1", "Symbol(\"y_{1}''\")"),
    (r"\left(x + y\right) z", F, "\\left( \\right)", r"x z + y z", "x*z + y*z"),
    (r"\left( x + y\right ) z", F, "\\left( \\right) with spaces", r"x z + y z", "x*z + y*z"),
    (r"\left(  x + y\right ) z", F, "\\left( \\right) with spaces", r"x z + y z", "x*z + y*z"),
    (r"\left[x + y\right] z", F, "\\left[ \\right]", r"x z + y z", "x*z + y*z"),
    (r"\left\{x + y\right\} z", F, "\\left\\{ \\right\\}", r"x z + y z", "x*z + y*z"),
    (r"1+1", F, "numbers", r"2", "2"),
    (r"0+1", F, "numbers", r"1", "1"),
    (r"1*2", E, "* is " + NOT_CONTRACT + " (the docs accept it)", r"2", "2"),
    (r"0*1", E, "* is " + NOT_CONTRACT + " (the docs accept it)", r"0", "0"),
    (r"1 \times 2 ", F, "\\times between numbers", r"2", "2"),
    (r"\lfloor x \rfloor", R, "floor: " + NOT_CONTRACT, None, "floor(x)"),
    (r"\lceil x \rceil", R, "ceiling: " + NOT_CONTRACT, None, "ceiling(x)"),
    (r"\langle x |", R, "a bra of quantum mechanics: " + NOT_CONTRACT, None, None),
    (r"| x \rangle", R, "a ket of quantum mechanics: " + NOT_CONTRACT, None, None),
    (r"\sin \theta", F, "\\sin without parentheses", r"\sin(\theta)", "sin(theta)"),
    (r"\sin(\theta)", F, "\\sin", r"\sin\theta", "sin(theta)"),
    (r"\sin^{-1} a", R, "ambiguous: the arcsine, or 1 / sin a as \\sin^2 a is (sin a)^2", None,
     "asin(a)"),
    (r"\sin a \cos b", F, "functions without parentheses, side by side",
     r"\sin(a) \cos(b)", "sin(a)*cos(b)"),
    (r"\sin \cos \theta", F, "nested functions without parentheses", r"\sin(\cos(\theta))",
     "sin(cos(theta))"),
    (r"\sin(\cos \theta)", F, "nested functions", r"\sin(\cos(\theta))", "sin(cos(theta))"),
    (r"\frac{a}{b}", F, "\\frac", r"a b^{-1}", "a/b"),
    (r"\dfrac{a}{b}", F, "\\dfrac", r"\frac{a}{b}", "a/b"),
    (r"\tfrac{a}{b}", F, "\\tfrac", r"\frac{a}{b}", "a/b"),
    (r"\frac12", E, "\\frac without braces is " + NOT_CONTRACT, r"\frac{1}{2}",
     "Rational(1, 2)"),
    (r"\frac12y", E, "\\frac without braces is " + NOT_CONTRACT, r"\frac{y}{2}", "y/2"),
    (r"\frac1234", E, "\\frac without braces is " + NOT_CONTRACT, r"17", "17"),
    (r"\frac2{3}", E, "\\frac without braces is " + NOT_CONTRACT, r"\frac{2}{3}",
     "Rational(2, 3)"),
    (r"\frac{\sin{x}}2", E, "\\frac without braces is " + NOT_CONTRACT, r"\frac{\sin(x)}{2}",
     "sin(x)/2"),
    (r"\frac{a + b}{c}", F, "\\frac", r"\frac{a}{c} + \frac{b}{c}", "a/c + b/c"),
    (r"\frac{7}{3}", F, "\\frac of numbers", r"\frac{14}{6}", "Rational(7, 3)"),
    (r"(\csc x)(\sec y)", F, "\\csc and \\sec", r"\frac{1}{\sin(x) \cos(y)}",
     "1/(sin(x)*cos(y))"),
    (r"\frac{d}{dx} x", F, "a derivative", r"1", "1"),
    (r"\frac{d}{dt} x", R, "x is no declared function of t: a derivative that would be 0 is "
     "refused rather than guessed (declare x with function:)", None, None),
    (r"|x|", E, "|x| is " + NOT_CONTRACT + " (the docs accept it)", r"\left| x \right|",
     "Abs(x)"),
    (r"||x||", E, "bars are " + NOT_CONTRACT + " (a norm, or nested absolute values)",
     r"\left| x \right|", "Abs(x)"),
    (r"|x||y|", E, "bars are " + NOT_CONTRACT + " (where does each one close?)",
     r"\left| x y \right|", "Abs(x*y)"),
    (r"||x||y||", E, "bars are " + NOT_CONTRACT + " (where does each one close?)",
     r"\left| x y \right|", "Abs(x*y)"),
    (r"\int x dx", R, "an integral without limits is defined up to a constant", None, None),
    (r"\int x d\theta", R, "an integral without limits is defined up to a constant", None, None),
    (r"\int (x^2 - y)dx", R, "an integral without limits is defined up to a constant", None,
     None),
    (r"\int x + a dx", R, "an integral without limits is defined up to a constant", None, None),
    (r"\int da", R, "an integral without limits is defined up to a constant", None, None),
    (r"\int_0^7 dx", F, "an integral with limits", r"7", "7"),
    (r"\int\limits_{0}^{1} x dx", E, "\\limits is " + NOT_CONTRACT, r"\frac{1}{2}",
     "Rational(1, 2)"),
    (r"\int_a^b x dx", F, "an integral with limits", r"\frac{b^2 - a^2}{2}", "(b**2 - a**2)/2"),
    (r"\int^b_a x dx", E, "the upper limit first is " + NOT_CONTRACT, r"\frac{b^2 - a^2}{2}",
     "(b**2 - a**2)/2"),
    (r"\int_{a}^b x dx", F, "an integral with limits", r"\frac{b^2 - a^2}{2}",
     "(b**2 - a**2)/2"),
    (r"\int^{b}_a x dx", E, "the upper limit first is " + NOT_CONTRACT, r"\frac{b^2 - a^2}{2}",
     "(b**2 - a**2)/2"),
    (r"\int_{a}^{b} x dx", F, "an integral with limits", r"\frac{b^2 - a^2}{2}",
     "(b**2 - a**2)/2"),
    (r"\int^{b}_{a} x dx", E, "the upper limit first is " + NOT_CONTRACT,
     r"\frac{b^2 - a^2}{2}", "(b**2 - a**2)/2"),
    (r"\int (x+a)", R, "an integral without limits or differential", None, None),
    (r"\int a + b + c dx", R, "an integral without limits is defined up to a constant", None,
     None),
    (r"\int \frac{dz}{z}", R, "an integral without limits is defined up to a constant", None,
     None),
    (r"\int \frac{3 dz}{z}", R, "an integral without limits is defined up to a constant", None,
     None),
    (r"\int \frac{1}{x} dx", R, "an integral without limits is defined up to a constant", None,
     None),
    (r"\int \frac{1}{a} + \frac{1}{b} dx", R,
     "an integral without limits is defined up to a constant", None, None),
    (r"\int \frac{3 \cdot d\theta}{\theta}", R,
     "an integral without limits is defined up to a constant", None, None),
    (r"\int \frac{1}{x} + 1 dx", R, "an integral without limits is defined up to a constant",
     None, None),
    (r"x_0", F, "a subscript", r"x_{0}", "Symbol('x_{0}')"),
    (r"x_{1}", F, "a subscript", r"x_1", "Symbol('x_{1}')"),
    (r"x_a", F, "a subscript", r"x_{a}", "Symbol('x_{a}')"),
    (r"x_{b}", F, "a subscript", r"x_b", "Symbol('x_{b}')"),
    (r"h_\theta", F, "a Greek subscript", r"h_{\theta}", "Symbol('h_{theta}')"),
    (r"h_{\theta}", F, "a Greek subscript", r"h_\theta", "Symbol('h_{theta}')"),
    (r"100!", F, "the factorial of a whole number", str(sp.factorial(100)), "factorial(100)"),
    (r"5!7!", F, "factorials of whole numbers", r"604800", "604800"),
    (r"\sqrt{x}", F, "\\sqrt", r"x^{\frac{1}{2}}", "sqrt(x)"),
    (r"\sqrt{x + b}", F, "\\sqrt", r"(x + b)^{\frac{1}{2}}", "sqrt(x + b)"),
    (r"\sqrt[3]{\sin x}", E, "\\sqrt[n] is " + NOT_CONTRACT + " (the docs accept it)",
     r"(\sin x)^{\frac{1}{3}}", "sin(x)**Rational(1, 3)"),
    (r"\sqrt[y]{\sin x}", E, "\\sqrt[n] is " + NOT_CONTRACT + " (the docs accept it)",
     r"(\sin x)^{\frac{1}{y}}", "sin(x)**(1/y)"),
    (r"\sqrt[\theta]{\sin x}", E, "\\sqrt[n] is " + NOT_CONTRACT + " (the docs accept it)",
     r"(\sin x)^{\frac{1}{\theta}}", "sin(x)**(1/theta)"),
    (r"\sqrt{\frac{12}{6}}", F, "\\sqrt of a fraction", r"\sqrt{2}", "sqrt(2)"),
    (r"\overline{z}", R, "\\overline (a conjugate, or a mean): " + NOT_CONTRACT, None, None),
    (r"\overline{\overline{z}}", R, "\\overline (a conjugate, or a mean): " + NOT_CONTRACT, None,
     None),
    (r"\overline{x + y}", R, "\\overline (a conjugate, or a mean): " + NOT_CONTRACT, None, None),
    (r"\overline{x} + \overline{y}", R, "\\overline (a conjugate, or a mean): " + NOT_CONTRACT,
     None, None),
    (r"x \neq y", R, "a relation is not a value", None, None),
    (r"x < y", R, "a relation is not a value", None, None),
    (r"x > y", R, "a relation is not a value", None, None),
    (r"x \leq y", R, "a relation is not a value", None, None),
    (r"x \geq y", R, "a relation is not a value", None, None),
    (r"x \le y", R, "a relation is not a value", None, None),
    (r"x \ge y", R, "a relation is not a value", None, None),
    (r"\sum_{k = 1}^{3} c", F, "a sum with limits", r"3 c", "3*c"),
    (r"\sum_{k = 1}^3 c", F, "a sum with limits", r"3 c", "3*c"),
    (r"\sum^{3}_{k = 1} c", E, "the upper limit first is " + NOT_CONTRACT, r"3 c", "3*c"),
    (r"\sum^3_{k = 1} c", E, "the upper limit first is " + NOT_CONTRACT, r"3 c", "3*c"),
    (r"\sum_{k = 1}^{10} k^2", F, "a sum with limits", r"385", "385"),
    (r"\prod_{a = b}^{c} x", F, "a product with limits", r"x^{c - b + 1}", "x**(c - b + 1)"),
    (r"\prod_{a = b}^c x", F, "a product with limits", r"x^{c - b + 1}", "x**(c - b + 1)"),
    (r"\prod^{c}_{a = b} x", E, "the upper limit first is " + NOT_CONTRACT, r"x^{c - b + 1}",
     "x**(c - b + 1)"),
    (r"\prod^c_{a = b} x", E, "the upper limit first is " + NOT_CONTRACT, r"x^{c - b + 1}",
     "x**(c - b + 1)"),
    (r"\exp x", F, "\\exp without parentheses", r"\exp(x)", "exp(x)"),
    (r"\exp(x)", F, "\\exp", r"\exp x", "exp(x)"),
    (r"\lg x", E, "\\lg is " + NOT_CONTRACT, r"\log_{10} x", "log(x, 10)"),
    (r"\ln x", F, "\\ln", r"\ln(x)", "log(x)"),
    (r"\ln xy", F, "\\ln of a product without parentheses", r"\ln(x y)", "log(x*y)"),
    (r"\log x", R, "\\log alone is ambiguous (base e, 10 or 2?)", None, None),
    (r"\log xy", R, "\\log alone is ambiguous (base e, 10 or 2?)", None, None),
    (r"\log_{2} x", F, "\\log with a base", r"\frac{\ln x}{\ln 2}", "log(x)/log(2)"),
    (r"\log_{a} x", F, "\\log with a base", r"\frac{\ln x}{\ln a}", "log(x)/log(a)"),
    (r"\log_{11} x", F, "\\log with a base", r"\frac{\ln x}{\ln 11}", "log(x)/log(11)"),
    (r"\log_{a^2} x", F, "\\log with a base", r"\frac{\ln x}{\ln(a^2)}", "log(x)/log(a**2)"),
    (r"[x]", F, "brackets", r"x", "x"),
    (r"[a + b]", F, "brackets", r"a + b", "a + b"),
    (r"\frac{d}{dx} [ \tan x ]", F, "a derivative of an expression", r"\tan^2 x + 1",
     "tan(x)**2 + 1"),
    (r"\binom{n}{0}", E, "\\binom is " + NOT_CONTRACT, r"1", "1"),
    (r"a \, b", F, "\\,", r"a b", "a*b"),
    (r"a \thinspace b", E, "\\thinspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \: b", E, "\\: is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \medspace b", E, "\\medspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \; b", F, "\\;", r"a b", "a*b"),
    (r"a \thickspace b", E, "\\thickspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \quad b", F, "\\quad", r"a b", "a*b"),
    (r"a \qquad b", E, "\\qquad is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \! b", F, "\\!", r"a b", "a*b"),
    (r"a \negthinspace b", E, "\\negthinspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \negmedspace b", E, "\\negmedspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"a \negthickspace b", E, "\\negthickspace is " + NOT_CONTRACT, r"a b", "a*b"),
    (r"\int x \, dx", R, "an integral without limits is defined up to a constant", None, None),
    (r"\log_2 x", F, "\\log with a base", r"\frac{\ln x}{\ln 2}", "log(x)/log(2)"),
    (r"\log_a x", F, "\\log with a base", r"\frac{\ln x}{\ln a}", "log(x)/log(a)"),
    (r"5^0 - 4^0", F, "powers of numbers", r"0", "0"),
]

# Left out, as the issue says, with the reason.
LEFT_OUT = {
    "a limit": [r"\lim_{x \to 3} a", r"\lim_{x \rightarrow 3} a", r"\lim_{x \Rightarrow 3} a",
                r"\lim_{x \longrightarrow 3} a", r"\lim_{x \Longrightarrow 3} a",
                r"\lim_{x \to 3^{+}} a", r"\lim_{x \to 3^{-}} a", r"\lim_{x \to 3^+} a",
                r"\lim_{x \to 3^-} a", r"\infty", r"\lim_{x \to \infty} \frac{1}{x}"],
    "an infinite sum": [r"\sum_{n = 0}^{\infty} \frac{1}{n!}"],
    "the factorial of a symbol": [r"x!", r"\theta!", r"(x + 1)!", r"(x!)!", r"x!!!"],
    "a \\mathit name": [r"\mathit{x}", r"\mathit{test}", r"\mathit{TEST}",
                        r"\mathit{HELLO world}"],
    "a bare function value f(x)": [r"f(x)", r"f(x, y)", r"f(x, y, z)", r"f'_1(x)",
                                   r"f_{1}''(x+y)", r"\frac{d f(x)}{dx}",
                                   r"\frac{d\theta(x)}{dx}", r"h_{\theta}(x_0, x_1)",
                                   r"\int_{f(a)}^{f(b)} f(z) dz"],
    "an equation, not a value (w = a = b would be a chain)": [r"a^2 + b^2 = c^2", r"x = y"],
    "SymPy reads \\pi as a symbol; the contract as the number": [r"\pi^{|xy|}"],
    "a binomial coefficient of symbols, whose value the contract cannot write":
        [r"\binom{n}{k}", r"\tbinom{n}{k}", r"\dbinom{n}{k}", r"x^\binom{n}{k}"],
}


def slug(i, kind):
    return "%s-%03d.md" % (kind, i)


def good_file(s, value):
    return (
        "# SymPy's parse_latex pair: `%s`\n\n"
        "From SymPy's `sympy/parsing/tests/test_latex.py` (GOOD_PAIRS): the string, then the value\n"
        "SymPy gives it, written in the contract's notation.\n\n"
        "$$w = %s$$\n\n"
        "$$w = %s$$\n\n"
        "<!-- expect\n6 premise\n8 follows\n-->\n" % (s, s, value))


def refused_file(s, why):
    return (
        "# SymPy's parse_latex string: `%s`\n\n"
        "From SymPy's `sympy/parsing/tests/test_latex.py` (%s): the checker must refuse it.\n\n"
        "$$w = %s$$\n" % (s, why, s))


def files():
    """{name: text} and the manifest rows."""
    good = {s for s, _ in T.GOOD_PAIRS}
    left = {s for group in LEFT_OUT.values() for s in group}
    kept = {row[0] for row in KEPT}
    missing = good - left - kept
    extra = kept - good
    if missing or extra or left - good:
        raise SystemExit("the table does not cover GOOD_PAIRS: missing %s, unknown %s %s" % (
            sorted(missing), sorted(extra), sorted(left - good)))
    values = {}
    for s, v in T.GOOD_PAIRS:
        values.setdefault(s, v)
    out, rows = {}, []
    ns = {"x": x, "y": y, "z": z, "a": a, "b": b, "c": c, "t": t, "theta": theta, "k": k, "n": n}
    for i, (s, expect, reason, latex, sym) in enumerate(KEPT, 1):
        if expect != R:
            mine = sp.sympify(sym, locals=ns)
            theirs = values[s]
            theirs = theirs.doit() if hasattr(theirs, "doit") else theirs
            if sp.simplify(sp.expand_log(sp.sympify(theirs) - mine, force=True)) != 0:
                raise SystemExit("the value written for %r is not SymPy's: %s against %s"
                                 % (s, mine, theirs))
            name = slug(i, "good")
            out[name] = good_file(s, latex)
        else:
            name = slug(i, "good")
            out[name] = refused_file(s, "GOOD_PAIRS, outside the contract")
        rows.append((name, expect, reason, s))
    for i, s in enumerate(T.BAD_STRINGS, 1):
        name = slug(i, "bad")
        out[name] = refused_file(s, "BAD_STRINGS")
        rows.append((name, R, "SymPy's parser refuses it too", s))
    return out, rows


def manifest(rows):
    text = "file\texpect\treason\tlatex\n"
    for name, expect, reason, s in rows:
        text += "%s\t%s\t%s\t%s\n" % (name, expect, reason, s.replace("\t", " "))
    return text


def main():
    out, rows = files()
    out["manifest.tsv"] = manifest(rows)
    check = "--check" in sys.argv
    bad = []
    for name, text in sorted(out.items()):
        path = os.path.join(HERE, name)
        if check:
            if not os.path.exists(path) or open(path, encoding="utf-8").read() != text:
                bad.append(name)
            continue
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
    counts = {}
    for _, expect, _, _ in rows:
        counts[expect] = counts.get(expect, 0) + 1
    n_left = sum(len(v) for v in LEFT_OUT.values())
    sys.stderr.write("%d pairs (%d distinct strings): %d kept, %d left out (%s); %d bad strings; "
                     "manifest: %s\n" % (
                         len(T.GOOD_PAIRS), len({s for s, _ in T.GOOD_PAIRS}), len(KEPT), n_left,
                         ", ".join("%s %d" % (k_, len(v)) for k_, v in LEFT_OUT.items()),
                         len(T.BAD_STRINGS),
                         ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
    for name in bad:
        sys.stderr.write("differs: %s\n" % name)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
