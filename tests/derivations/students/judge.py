#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The independent judge of the students' derivation corpus (run it with Debian's /usr/bin/python3
and its python3-sympy; it is not part of the test suite).

Every display equation of every file in this folder carries a SymPy transcription written by hand
next to it, in an HTML comment the checker skips (README.md gives the format). The judge reads the
files' structure (which equation is a premise, which step follows from which, the facts in force),
never their LaTeX mathematics, and decides every step with SymPy:

  - the equations the step follows from are solved one symbol at a time (a symbol in which an
    equation is linear, or quadratic), every division by something the facts do not keep from
    zero being a case of its own; on every case the step is substituted and simplified;
  - a case where the step does not vanish is shown by an exact point: numbers for the free
    symbols, the solved ones computed from them, the facts and the equations before checked
    exactly, the step failing (or undefined) there;
  - the converse (the equations before from the step) decides follows against follows-one-way.

Verdicts: follows, follows-one-way, follows-if (the step holds on some cases and fails on others,
or is undefined where the facts allow a divisor to vanish; the symbols of that condition are
named), does-not-follow, dimensions (with units), undecided (neither proven nor refuted: the
corpus must have none).

  judge.py               print the verdicts, one line per equation line
  judge.py --write       ... and pin them in sympy-verdicts.txt
  judge.py --check       exit 1 when a file's <!-- expect --> pins or sympy-verdicts.txt differ
  judge.py FILE.md -v    one file, with how each step was decided
"""
import argparse
import itertools
import os
import random
import re
import sys
import time

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.parsing.sympy_parser import parse_expr, standard_transformations

HERE = os.path.dirname(os.path.abspath(__file__))
VERDICTS_FILE = os.path.join(HERE, "sympy-verdicts.txt")

# ---------------------------------------------------------------------------------------------
# Reading a file: its directives, display blocks, transcriptions and pins (structure only).
# ---------------------------------------------------------------------------------------------

DIRECTIVES = ("assume", "let", "given", "from", "vector", "units", "function", "target", "unit",
              "index")
ENVIRONMENTS = ("equation", "equation*", "align", "align*", "gather", "gather*", "multline",
                "multline*")


class FileError(Exception):
    pass


class Block:
    def __init__(self, start, end, lines):
        self.start, self.end, self.lines = start, end, lines  # 1-based lines, their text
        self.sympy = None
        self.given = False
        self.target = False


def read_markdown(path):
    """Events in file order: ('directive', kind, line, text) / ('block', Block) /
    ('sympy', line, text) / ('expect', text)."""
    text = open(path, encoding="utf-8").read()
    lines = text.split("\n")
    events = []
    i = 0
    fence = False
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if stripped.startswith("```"):
            fence = not fence
            i += 1
            continue
        if fence:
            i += 1
            continue
        if stripped.startswith("<!--"):
            j = i
            body = [line]
            while "-->" not in lines[j]:
                j += 1
                body.append(lines[j])
            comment = "\n".join(body).strip()
            inner = comment[4:comment.rindex("-->")].strip()
            if inner.startswith("sympy"):
                events.append(("sympy", i + 1, inner[len("sympy"):].lstrip()))
            elif inner.startswith("expect"):
                events.append(("expect", inner[len("expect"):]))
            i = j + 1
            continue
        m = re.match(r"^([a-z]+):(.*)$", stripped)
        if m and m.group(1) in DIRECTIVES:
            events.append(("directive", m.group(1), i + 1, m.group(2).strip()))
            i += 1
            continue
        env = re.match(r"^\\begin\{([a-z*]+)\}", stripped)
        if stripped.startswith("$$") or stripped.startswith("\\[") or (
                env and env.group(1) in ENVIRONMENTS):
            if stripped.startswith("$$"):
                closing = "$$"
                rest = stripped[2:]
            elif stripped.startswith("\\["):
                closing = "\\]"
                rest = stripped[2:]
            else:
                closing = "\\end{%s}" % env.group(1)
                rest = stripped[len(env.group(0)):]
            j = i
            if closing not in rest:
                j = i + 1
                while closing not in lines[j]:
                    j += 1
            events.append(("block", Block(i + 1, j + 1, lines[i:j + 1])))
            i = j + 1
            continue
        if "$$" in stripped or "\\[" in stripped:
            raise FileError("%s:%d: a display that does not start its line" % (path, i + 1))
        i += 1
    return events


def strip_latex_line(line):
    """The text of a display line that can hold '=' of an equation (delimiters, tags and text
    annotations removed)."""
    s = line
    for pat in (r"\$\$", r"\\\[", r"\\\]", r"\\begin\{[a-z*]+\}", r"\\end\{[a-z*]+\}",
                r"\\tag\{[^}]*\}", r"\\text\{[^}]*\}", r"\\label\{[^}]*\}"):
        s = re.sub(pat, " ", s)
    return s


def top_level_equals(s):
    """Positions of '=' at brace depth 0 (not in subscripts such as \\sum_{i=1})."""
    depth, out = 0, []
    for k, c in enumerate(s):
        if c == "{" and (k == 0 or s[k - 1] != "\\"):
            depth += 1
        elif c == "}" and (k == 0 or s[k - 1] != "\\"):
            depth -= 1
        elif c == "=" and depth == 0:
            out.append(k)
    return out


def split_top(s, seps):
    """Splits s at the separators (strings) found at parenthesis depth 0."""
    depth, out, cur, k = 0, [], "", 0
    while k < len(s):
        c = s[k]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        if depth == 0:
            hit = None
            for sep in seps:
                if s.startswith(sep, k):
                    hit = sep
                    break
            if hit is not None:
                out.append(cur)
                cur = ""
                k += len(hit)
                continue
        cur += c
        k += 1
    out.append(cur)
    return out


def split_sides(entry):
    """'a = b = c' -> ['a', 'b', 'c'] ('==', '<=', '>=', '!=' are not separators)."""
    depth, out, cur = 0, [], ""
    for k, c in enumerate(entry):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        if c == "=" and depth == 0:
            prev = entry[k - 1] if k else ""
            nxt = entry[k + 1] if k + 1 < len(entry) else ""
            if (not prev or prev not in "=<>!") and nxt != "=":
                out.append(cur.strip())
                cur = ""
                continue
        cur += c
    out.append(cur.strip())
    return out


class Equation:
    def __init__(self):
        self.line = 0
        self.index = 0  # among the equations of its line
        self.lhs = self.rhs = ""  # SymPy transcriptions of the two sides
        self.premise = False
        self.premises = []  # indices into the file's equations
        self.context = None
        self.tag = None
        self.target = False


class Context:
    """What is in force at an equation: facts, definitions, vectors, functions, units, names."""

    def __init__(self):
        self.facts = []  # transcriptions: 'm1 > 0', '0 <= e <= 1', 'unit n', ...
        self.lets = []  # (name, transcription)
        self.vectors = []
        self.functions = []
        self.units = {}  # name -> dimension transcription in M, L, T
        self.indexed = []  # IndexedBase names ('m+': positive entries)
        self.indices = []  # index symbols (positive integers)
        self.names = {}  # sympy name -> LaTeX name (for conditions)
        self.solve_hints = []

    def copy(self):
        c = Context()
        c.facts = list(self.facts)
        c.lets = list(self.lets)
        c.vectors = list(self.vectors)
        c.functions = list(self.functions)
        c.units = dict(self.units)
        c.indexed = list(self.indexed)
        c.indices = list(self.indices)
        c.names = dict(self.names)
        c.solve_hints = list(self.solve_hints)
        return c


def read_file(path):
    """The file's equations, with their roles, premises and contexts; and its pins."""
    events = read_markdown(path)
    ctx = Context()
    equations = []
    pins = None
    given_next = False
    target_next = False
    from_next = None
    previous = []
    tags = {}
    pending_directive = None
    last_block = None
    chain_start = None  # the left side of the chain a later '= c' row continues
    for ev in events:
        kind = ev[0]
        if kind == "expect":
            pins = parse_pins(ev[1])
            continue
        if kind == "sympy":
            line, body = ev[1], ev[2]
            if body.startswith(":"):
                body = body[1:]
            body = body.strip()
            if pending_directive is not None:
                apply_directive(ctx, pending_directive, body, path, line)
                pending_directive = None
            elif body.startswith("solve "):
                ctx.solve_hints = [x.strip() for x in body[len("solve "):].split(",") if x.strip()]
            elif body.startswith("indexed "):
                ctx.indexed += [x.strip() for x in body[len("indexed "):].split(",") if x.strip()]
            elif body.startswith("indices "):
                ctx.indices += [x.strip() for x in body[len("indices "):].split(",") if x.strip()]
            elif body.startswith("names:"):
                for item in body[len("names:"):].split(","):
                    if item.strip():
                        k, v = item.split("=", 1)
                        ctx.names[k.strip()] = v.strip()
            elif last_block is not None and last_block.sympy is None:
                last_block.sympy = body
                chain_start = add_block(path, last_block, ctx, equations, previous, tags,
                                        from_next, chain_start)
                from_next = None
                if last_block.given:
                    previous[:] = [e for e in range(len(equations))
                                   if equations[e].premise and equations[e].line >= last_block.start
                                   and equations[e].line <= last_block.end]
            else:
                raise FileError("%s:%d: a sympy comment with nothing to transcribe" % (path, line))
            continue
        if pending_directive is not None:
            raise FileError("%s:%d: the directive has no sympy transcription after it"
                            % (path, pending_directive[1]))
        if last_block is not None and last_block.sympy is None:
            raise FileError("%s:%d: the display block has no sympy transcription after it"
                            % (path, last_block.start))
        if kind == "directive":
            what, line, text = ev[1], ev[2], ev[3]
            if what == "given":
                given_next = True
            elif what == "target":
                target_next = True
            elif what == "from":
                from_next = re.findall(r"\(([^)]*)\)", text)
            else:
                pending_directive = (what, line, text)
        elif kind == "block":
            block = ev[1]
            block.given, block.target = given_next, target_next
            given_next = target_next = False
            last_block = block
    if pending_directive is not None or (last_block is not None and last_block.sympy is None):
        raise FileError("%s: the last directive or display has no sympy transcription" % path)
    return equations, pins


def apply_directive(ctx, directive, body, path, line):
    what = directive[0]
    if what in ("assume", "unit"):
        ctx.facts.extend(x.strip() for x in split_top(body, [","]) if x.strip())
    elif what == "let":
        m = re.match(r"^let\s+([A-Za-z_][A-Za-z_0-9]*)\s*=(.*)$", body)
        if not m:
            raise FileError("%s:%d: expected 'let NAME = ...'" % (path, line))
        ctx.lets.append((m.group(1), m.group(2).strip()))
    elif what == "vector":
        ctx.vectors.extend(x.strip() for x in body.replace("vector", "", 1).split(",") if x.strip())
    elif what == "function":
        ctx.functions.extend(x.strip() for x in body.replace("function", "", 1).split(",")
                             if x.strip())
    elif what == "units":
        for item in split_top(body.replace("units", "", 1), [","]):
            if item.strip():
                k, v = item.split("=", 1)
                ctx.units[k.strip()] = v.strip()
    elif what == "index":
        pass  # the transcription writes the sums out itself
    else:
        raise FileError("%s:%d: directive %s is not transcribed by the judge" % (path, line, what))


def add_block(path, block, ctx, equations, previous, tags, from_tags, chain_start):
    # Where the equations are: one per top-level '=' of each line.
    places = []
    for k, text in enumerate(block.lines):
        s = strip_latex_line(text)
        for _ in top_level_equals(s):
            places.append(block.start + k)
    entries = [e.strip() for e in split_top(block.sympy, [";", "\n"]) if e.strip()]
    links = []  # (entry number, left, right, continues)
    for n, entry in enumerate(entries):
        sides = split_sides(entry)
        continues = sides[0] == ""
        for k in range(1, len(sides)):
            links.append((n, sides[k - 1], sides[k], continues and k == 1))
    if len(links) != len(places):
        raise FileError("%s:%d: %d equations in the LaTeX, %d in the transcription"
                        % (path, block.start, len(places), len(links)))
    first_of_entry = {}
    last_of_entry = {}
    for k, (n, left, right, cont) in enumerate(links):
        e = Equation()
        e.line = places[k]
        e.index = sum(1 for p in places[:k] if p == e.line)
        e.context = ctx.copy()
        e.target = block.target
        first_link = k == 0 or links[k - 1][0] != n
        if first_link and not cont:
            chain_start = left
            e.lhs, e.rhs = left, right
            premises = list(from_tags_premises(path, block, from_tags, tags)) if (
                from_tags and n == links[0][0]) else list(previous)
        else:
            # a = b = c: the link b = c is the equation a = c, from a = b.
            e.lhs, e.rhs = chain_start, right
            premises = [len(equations) - 1] if equations else []
        e.premise = block.given or not equations or block.target
        e.premises = [] if e.premise else premises
        if not e.premise and not e.premises:
            e.premise = True
        equations.append(e)
        first_of_entry.setdefault(n, len(equations) - 1)
        last_of_entry[n] = len(equations) - 1
        if k + 1 == len(links) or links[k + 1][0] != n:
            previous[:] = [len(equations) - 1]
    # Tags: \tag{k} on a line names the last equation of that line.
    for k, text in enumerate(block.lines):
        for t in re.findall(r"\\tag\{([^}]*)\}", text):
            line = block.start + k
            on_line = [i for i, e in enumerate(equations) if e.line == line]
            if not on_line:
                raise FileError("%s:%d: a tag on a line without an equation" % (path, line))
            equations[on_line[-1]].tag = t
            tags[t] = on_line[-1]
    return chain_start


def from_tags_premises(path, block, from_tags, tags):
    for t in from_tags:
        if t not in tags:
            raise FileError("%s:%d: from: names tag (%s), which no equation carries"
                            % (path, block.start, t))
        yield tags[t]


def parse_pins(text):
    pins = {}
    for line in text.split("\n"):
        m = re.match(r"^\s*(\d+)\s+(.*)$", line)
        if not m:
            continue
        words = m.group(2).split()
        verdicts = []
        for w in words:
            if w in VERDICTS:
                verdicts.append(w)
            else:
                break
        where = []
        rest = m.group(2)
        if "where:" in rest:
            for w in rest[rest.index("where:") + 6:].split():
                if w.startswith("("):
                    break
                where.append(w)
        pins[int(m.group(1))] = (verdicts, sorted(where))
    return pins


VERDICTS = ("premise", "follows", "follows-one-way", "follows-if", "does-not-follow", "dimensions",
            "undecided")

# ---------------------------------------------------------------------------------------------
# Meaning: a namespace of symbols for the facts in force; transcriptions parsed in it.
# ---------------------------------------------------------------------------------------------

KNOWN = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec, "csc": sp.csc,
    "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "exp": sp.exp, "ln": sp.log,
    "log": sp.log, "sqrt": sp.sqrt, "pi": sp.pi, "Rational": sp.Rational, "Abs": sp.Abs,
    "Integral": sp.Integral, "Derivative": sp.Derivative, "Sum": sp.Sum, "Product": sp.Product,
    "factorial": sp.factorial, "oo": sp.oo, "Matrix": sp.Matrix,
    "binomial": sp.binomial, "Function": sp.Function,
}
HELPERS = ("dot", "cross", "det", "norm", "vec", "bar", "deriv", "Int")


class Space:
    """Symbols of one context: names -> SymPy objects, with the sign facts as assumptions."""

    def __init__(self, ctx, extra_names=()):
        self.ctx = ctx
        self.ns = dict(KNOWN)
        self.ns.update(helpers(self))
        self.intervals = {}
        self.relations = []  # (expr, op) meaning expr op 0, op in > >= < <= !=
        self.equalities = []  # facts that are equations (unit vectors)
        self.indexed = {}
        names = set(extra_names)
        for f in ctx.facts:
            names |= set(identifiers(f))
        for _, v in ctx.lets:
            names |= set(identifiers(v))
        self.sign = {}
        simple = []
        for f in ctx.facts:
            if f.startswith("unit "):
                continue
            parts = re.split(r"(<=|>=|!=|<|>|==)", f.replace(" = ", " == "))
            for k in range(1, len(parts), 2):
                a, op, b = parts[k - 1].strip(), parts[k], parts[k + 1].strip()
                simple.append((a, op, b))
        # single-symbol facts become SymPy assumptions
        assumptions = {}
        for a, op, b in simple:
            for sym, o, val in ((a, op, b), (b, flip(op), a)):
                if re.fullmatch(r"[A-Za-z_][A-Za-z_0-9]*", sym) and re.fullmatch(r"-?\d+", val) \
                        and int(val) == 0:
                    assumptions.setdefault(sym, set()).add(o)
        for name in sorted(names | set(self.all_names())):
            if name in KNOWN or name in HELPERS or name in ctx.vectors or name in ctx.functions:
                continue
            if name.rstrip("+") in [x.rstrip("+") for x in ctx.indexed] or name in ctx.indices:
                continue
            self.ns[name] = make_symbol(name, assumptions.get(name, set()))
        for v in ctx.vectors:
            x = make_symbol(v + "_x", set())
            y = make_symbol(v + "_y", set())
            self.ns[v] = sp.Matrix([x, y])
            self.ns[v + "_x"], self.ns[v + "_y"] = x, y
        for f in ctx.functions:
            self.ns[f] = sp.Function(f, real=True)
        for name in ctx.indexed:
            pos = name.endswith("+")
            base = name.rstrip("+")
            self.ns[base] = sp.IndexedBase(base, **({"positive": True} if pos else {"real": True}))
        for name in ctx.indices:
            self.ns[name] = sp.Symbol(name, integer=True, positive=True)
        # relations and intervals
        for a, op, b in simple:
            ea, eb = self.parse(a), self.parse(b)
            if op == "==":
                self.equalities.append(sp.expand(ea - eb))
                continue
            self.relations.append((sp.expand(ea - eb), op))
        self.unit_vectors, self.unit_equalities = [], []
        for f in ctx.facts:
            if f.startswith("unit "):
                v = self.ns[f.split()[1]]
                self.equalities.append(v[0] ** 2 + v[1] ** 2 - 1)
                self.unit_equalities.append(v[0] ** 2 + v[1] ** 2 - 1)
                self.unit_vectors.append((v[0], v[1]))
        for sym in list(self.ns.values()):
            if isinstance(sym, sp.Symbol):
                self.intervals[sym] = self.symbol_interval(sym)
        # lets: parsed in order, each in the namespace of those before it
        self.raw_lets = {}
        for name, value in ctx.lets:
            raw = self.parse(value, evaluate=False)
            self.ns[name] = self.parse(value, evaluate=True)
            self.raw_lets[name] = raw

    def all_names(self):
        out = []
        for _, v in self.ctx.lets:
            out += identifiers(v)
        return out

    def symbol_interval(self, sym):
        lo, hi = Bound(-sp.oo, True), Bound(sp.oo, True)
        for expr, op in self.relations:
            # expr op 0 with expr = c*sym + d (c, d numbers)
            if expr.free_symbols != {sym}:
                continue
            try:
                p = sp.Poly(expr, sym)
            except sp.PolynomialError:
                continue
            if p.degree() != 1:
                continue
            c, d = p.all_coeffs()
            if not (c.is_number and d.is_number):
                continue
            val = -d / c
            o = op if c > 0 else flip(op)
            if o == ">":
                lo = max_bound(lo, Bound(val, True))
            elif o == ">=":
                lo = max_bound(lo, Bound(val, False))
            elif o == "<":
                hi = min_bound(hi, Bound(val, True))
            elif o == "<=":
                hi = min_bound(hi, Bound(val, False))
        return Interval(lo, hi)

    def parse(self, text, evaluate=True):
        ns = self.ns
        for name in identifiers(text):
            if name not in ns:
                ns[name] = make_symbol(name, set())
                self.intervals[ns[name]] = Interval.real()
        if not evaluate and getattr(self, "raw_lets", None):
            ns = dict(ns)
            ns.update(self.raw_lets)
        return parse_expr(text, local_dict=ns, transformations=standard_transformations,
                          evaluate=evaluate)


def make_symbol(name, ops):
    kw = {"real": True}
    if ">" in ops:
        kw["positive"] = True
    elif ">=" in ops:
        kw["nonnegative"] = True
    if "<" in ops:
        kw["negative"] = True
    elif "<=" in ops:
        kw["nonpositive"] = True
    if "!=" in ops:
        kw["nonzero"] = True
    return sp.Symbol(name, **kw)


def flip(op):
    return {">": "<", "<": ">", ">=": "<=", "<=": ">=", "!=": "!=", "==": "=="}[op]


def identifiers(text):
    out = []
    for m in re.finditer(r"(?<![\w.])([A-Za-z_][A-Za-z_0-9]*)", text):
        name = m.group(1)
        if name in KNOWN or name in HELPERS or name in ("unit", "real"):
            continue
        # keyword arguments and attribute names are not symbols
        rest = text[m.end():].lstrip()
        if rest.startswith("=") and not rest.startswith("=="):
            if re.search(r"[(,]\s*$", text[:m.start()]):
                continue
        out.append(name)
    return out


def helpers(space):
    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1]

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    def norm(a):
        return sp.sqrt(a[0] ** 2 + a[1] ** 2)

    def V(x, y):
        return sp.Matrix([x, y])

    def bar(expr, var, lo, hi):
        # the evaluation bar [expr]_lo^hi
        return BarMarker(expr, var, lo, hi)

    def D(expr, var, n=1):
        return sp.Derivative(expr, var, n)

    def Int(expr, *limits):
        return sp.Integral(expr, *limits)

    def Idx(name):
        return sp.Symbol(name, integer=True, positive=True)

    def Ib(name, *ops):
        base = sp.IndexedBase(name, **({"positive": True} if "pos" in ops else {"real": True}))
        return base

    return {"dot": dot, "cross": cross, "det": cross, "norm": norm, "vec": V, "bar": bar,
            "deriv": D, "Int": Int}


def BarMarker(expr, var, lo, hi):
    return sp.Subs(expr, var, hi) - sp.Subs(expr, var, lo)


# ---------------------------------------------------------------------------------------------
# Intervals (exact ends, open or closed): which expressions the facts keep from zero.
# ---------------------------------------------------------------------------------------------

class Bound:
    def __init__(self, value, strict):
        self.value, self.strict = sp.sympify(value), strict


def max_bound(a, b):
    if a.value == b.value:
        return Bound(a.value, a.strict or b.strict)
    return a if bool(a.value > b.value) else b


def min_bound(a, b):
    if a.value == b.value:
        return Bound(a.value, a.strict or b.strict)
    return a if bool(a.value < b.value) else b


class Interval:
    def __init__(self, lo, hi):
        self.lo, self.hi = lo, hi

    @staticmethod
    def real():
        return Interval(Bound(-sp.oo, True), Bound(sp.oo, True))

    @staticmethod
    def point(v):
        return Interval(Bound(v, False), Bound(v, False))

    def excludes_zero(self):
        lo, hi = self.lo, self.hi
        if lo.value > 0 or (lo.value == 0 and lo.strict):
            return True
        if hi.value < 0 or (hi.value == 0 and hi.strict):
            return True
        return False

    def positive(self):
        return bool(self.lo.value > 0) or (self.lo.value == 0 and self.lo.strict)

    def nonnegative(self):
        return bool(self.lo.value >= 0)

    def negative(self):
        return bool(self.hi.value < 0) or (self.hi.value == 0 and self.hi.strict)

    def nonpositive(self):
        return bool(self.hi.value <= 0)


def _mul_end(a, b):
    if (a.value == 0 and not a.strict) or (b.value == 0 and not b.strict):
        return Bound(0, False)
    if a.value == 0 or b.value == 0:
        if a.value.is_infinite or b.value.is_infinite:
            return Bound(0, True)
        return Bound(0, a.strict or b.strict)
    return Bound(a.value * b.value, a.strict or b.strict)


def iv_add(a, b):
    return Interval(Bound(a.lo.value + b.lo.value, a.lo.strict or b.lo.strict),
                    Bound(a.hi.value + b.hi.value, a.hi.strict or b.hi.strict))


def iv_mul(a, b):
    ends = [_mul_end(x, y) for x in (a.lo, a.hi) for y in (b.lo, b.hi)]
    lo = ends[0]
    hi = ends[0]
    for e in ends[1:]:
        if bool(e.value < lo.value) or (e.value == lo.value and not e.strict):
            lo = e
        if bool(e.value > hi.value) or (e.value == hi.value and not e.strict):
            hi = e
    return Interval(Bound(lo.value, lo.strict), Bound(hi.value, hi.strict))


def iv_pow(a, n):
    if n == 0:
        return Interval.point(1)
    if n < 0:
        if not a.excludes_zero():
            return Interval.real()
        if a.positive():
            lo = Bound(0, True) if a.hi.value.is_infinite else Bound(1 / a.hi.value, a.hi.strict)
            hi = Bound(sp.oo, True) if a.lo.value == 0 else Bound(1 / a.lo.value, a.lo.strict)
        else:
            lo = Bound(-sp.oo, True) if a.hi.value == 0 else Bound(1 / a.hi.value, a.hi.strict)
            hi = Bound(0, True) if a.lo.value.is_infinite else Bound(1 / a.lo.value, a.lo.strict)
        return iv_pow(Interval(lo, hi), -n)
    if n % 2 == 1:
        return Interval(Bound(a.lo.value ** n, a.lo.strict), Bound(a.hi.value ** n, a.hi.strict))
    # even power
    if a.positive() or a.nonnegative():
        return Interval(Bound(a.lo.value ** n, a.lo.strict), Bound(a.hi.value ** n, a.hi.strict))
    if a.negative() or a.nonpositive():
        return Interval(Bound(a.hi.value ** n, a.hi.strict), Bound(a.lo.value ** n, a.lo.strict))
    top = max_bound(Bound(a.lo.value ** n, a.lo.strict), Bound(a.hi.value ** n, a.hi.strict))
    return Interval(Bound(0, False), top)


def _inv(b):
    if b.value.is_infinite:
        return Bound(0, True)
    return Bound(1 / b.value, b.strict)


def interval(expr, space):
    """An interval holding every value of expr where the facts hold."""
    expr = sp.sympify(expr)
    if expr.is_number:
        if expr.is_real is False:
            return Interval.real()
        try:
            v = sp.nsimplify(expr) if expr.is_Rational else expr
            return Interval.point(v)
        except Exception:
            return Interval.real()
    if isinstance(expr, sp.Symbol):
        iv = space.intervals.get(expr)
        if iv is None:
            iv = Interval.real()
        if expr.is_positive:
            iv = Interval(max_bound(iv.lo, Bound(0, True)), iv.hi)
        elif expr.is_nonnegative:
            iv = Interval(max_bound(iv.lo, Bound(0, False)), iv.hi)
        if expr.is_negative:
            iv = Interval(iv.lo, min_bound(iv.hi, Bound(0, True)))
        elif expr.is_nonpositive:
            iv = Interval(iv.lo, min_bound(iv.hi, Bound(0, False)))
        return iv
    if isinstance(expr, sp.Indexed):
        if expr.is_positive:
            return Interval(Bound(0, True), Bound(sp.oo, True))
        return Interval.real()
    if isinstance(expr, sp.Add):
        out = Interval.point(0)
        for a in expr.args:
            out = iv_add(out, interval(a, space))
        return out
    if isinstance(expr, sp.Mul):
        out = Interval.point(1)
        for a in expr.args:
            out = iv_mul(out, interval(a, space))
        return out
    if isinstance(expr, sp.Pow):
        b, e = expr.args
        if e.is_Integer:
            return iv_pow(interval(b, space), int(e))
        if e == sp.Rational(1, 2):
            ib = interval(b, space)
            if ib.nonnegative():
                return Interval(Bound(sp.sqrt(ib.lo.value), ib.lo.strict),
                                Bound(sp.sqrt(ib.hi.value) if not ib.hi.value.is_infinite
                                      else sp.oo, ib.hi.strict))
            return Interval(Bound(0, False), Bound(sp.oo, True))
        if e == sp.Rational(-1, 2):
            ib = interval(b, space)
            if ib.positive():
                return Interval(Bound(0, True), Bound(sp.oo, True))
        return Interval.real()
    if isinstance(expr, (sp.sin, sp.cos)):
        return Interval(Bound(-1, False), Bound(1, False))
    if isinstance(expr, sp.exp):
        return Interval(Bound(0, True), Bound(sp.oo, True))
    if isinstance(expr, sp.log):
        a = interval(expr.args[0], space)
        if a.positive():
            lo = Bound(-sp.oo, True) if a.lo.value == 0 else Bound(sp.log(a.lo.value), a.lo.strict)
            hi = Bound(sp.oo, True) if a.hi.value.is_infinite else Bound(sp.log(a.hi.value),
                                                                         a.hi.strict)
            return Interval(lo, hi)
        return Interval.real()
    if isinstance(expr, sp.Abs):
        a = interval(expr.args[0], space)
        if a.excludes_zero():
            return Interval(Bound(0, True), Bound(sp.oo, True))
        return Interval(Bound(0, False), Bound(sp.oo, True))
    if isinstance(expr, sp.Sum):
        f, (i, a, b) = expr.args[0], expr.args[1]
        if interval(f, space).positive() and sp.simplify(b - a).is_nonnegative:
            return Interval(Bound(0, True), Bound(sp.oo, True))
        return Interval.real()
    return Interval.real()


def nonzero_by_facts(q, space):
    """Whether the facts in force keep q from zero (intervals, or q a fact's own expression)."""
    q = sp.sympify(q)
    if q.is_number:
        return q != 0
    if interval(q, space).excludes_zero():
        return True
    n, d = num_den(q)
    if d != 1:
        return nonzero_by_facts(n, space)
    if interval(q, space).excludes_zero():
        return True
    for f in (sp.factor(q),):
        if interval(f, space).excludes_zero():
            return True
    qe = sp.expand(q)
    if qe.is_number:
        return qe != 0
    for expr, op in space.relations:
        if op in (">", "<", "!="):
            ratio = sp.cancel(qe / expr)
            if ratio.is_number and ratio != 0:
                return True
    # a product: every factor kept from zero
    try:
        _, factors = sp.factor_list(qe)
    except sp.PolynomialError:
        return False
    if len(factors) > 1 or (factors and factors[0][1] > 1):
        return all(nonzero_by_facts(f, space) for f, _ in factors)
    return False


# ---------------------------------------------------------------------------------------------
# An equation's meaning: residuals (one per component), the divisors it writes, its atoms.
# ---------------------------------------------------------------------------------------------

def divisors(expr):
    """What expr divides by, as written (before any cancelling), and what its roots need."""
    out, roots = [], []

    def walk(e):
        if isinstance(e, sp.MatrixBase):
            for x in e:
                walk(x)
            return
        if not isinstance(e, sp.Basic):
            return
        if isinstance(e, sp.Pow):
            b, x = e.args
            if x.is_number and x.is_negative:
                out.append(b)
            if x.is_Rational and not x.is_Integer and x.q % 2 == 0:
                roots.append(b)
        if isinstance(e, (sp.tan, sp.sec)):
            out.append(sp.cos(e.args[0]))
        if isinstance(e, (sp.cot, sp.csc)):
            out.append(sp.sin(e.args[0]))
        if isinstance(e, sp.log):
            roots.append(e.args[0])
        for a in e.args:
            walk(a)

    walk(expr)
    bound = set()
    if isinstance(expr, sp.Basic):
        for a in expr.atoms(sp.Integral, sp.Sum, sp.Subs, sp.Product):
            if isinstance(a, sp.Subs):
                bound |= set(a.variables)
            else:
                bound |= {l[0] for l in a.limits}
    out = [q for q in out if not (sp.sympify(q).free_symbols & bound)]
    roots = [q for q in roots if not (sp.sympify(q).free_symbols & bound)]
    return out, roots


class Meaning:
    """One equation, read: residual components and divisors, under a Space."""

    def __init__(self, space, lhs, rhs):
        self.space = space
        raw_l, raw_r = parse_both(space, lhs), parse_both(space, rhs)
        self.raw = (raw_l[0], raw_r[0])
        self.divs, self.roots = [], []
        for raw in (raw_l[0], raw_r[0]):
            d, r = divisors(raw)
            self.divs += d
            self.roots += r
        left, right = raw_l[1], raw_r[1]
        if isinstance(left, sp.MatrixBase) != isinstance(right, sp.MatrixBase):
            raise FileError("a vector equated to a scalar: %s = %s" % (lhs, rhs))
        if isinstance(left, sp.MatrixBase):
            self.components = [left[k] - right[k] for k in range(left.shape[0])]
        else:
            self.components = [left - right]
        self.components = [prepare(c) for c in self.components]
        self.divs = [prepare(d) for d in self.divs]
        self.roots = [prepare(d) for d in self.roots]


def parse_both(space, text):
    evaluated = space.parse(text, evaluate=True)
    try:
        raw = space.parse(text, evaluate=False)
    except Exception:
        raw = evaluated
    return raw, evaluated


def prepare(e):
    """Evaluates derivatives, integrals, bars; splits sums into sums of terms."""
    e = sp.sympify(e)
    e = e.doit()
    e = split_sums(e)
    return e


def split_sums(e):
    if not isinstance(e, sp.Basic) or e.is_Atom:
        return e
    if isinstance(e, sp.Sum) and len(e.args) == 2:
        f, (i, a, b) = e.args[0], e.args[1]
        k = sp.Symbol("k_", integer=True, positive=True)
        if i != k:
            return split_sums(sp.Sum(f.xreplace({i: k}), (k, a, b)))
        # a sum to N - c is the sum to N less its last c terms; one from c + 1, the first c
        # terms less
        off = sp.expand(b - sp.Symbol("N_", integer=True))
        for x in b.free_symbols:
            c = sp.expand(b - x)
            if c.is_Integer and c < 0:
                return split_sums(sp.Sum(f, (k, a, x)) - sum(f.subs(k, x - j) for j in range(-c)))
        if a.is_Integer and a > 1 and b.free_symbols:
            return split_sums(sp.Sum(f, (k, 1, b)) - sum(f.subs(k, j) for j in range(1, a)))
    if isinstance(e, sp.Sum):
        f = sp.expand(split_sums(e.args[0]))
        limits = e.args[1:]
        idx = {l[0] for l in limits}
        out = 0
        for term in sp.Add.make_args(f):
            const, rest = 1, 1
            for factor in sp.Mul.make_args(term):
                if factor.free_symbols & idx:
                    rest *= factor
                else:
                    const *= factor
            out += const * (sp.Sum(rest, *limits) if rest != 1 else sp.Sum(1, *limits).doit())
        return out
    return e.func(*[split_sums(a) for a in e.args])


def atoms_to_symbols(exprs, table):
    """Function values, derivatives, integrals, sums and bars left unevaluated become symbols
    of their own (the same atom the same symbol everywhere)."""
    out = []
    for e in exprs:
        reps = {}
        for a in sorted(sp.sympify(e).atoms(AppliedUndef, sp.Derivative, sp.Integral, sp.Sum,
                                             sp.Subs, sp.Product, sp.Indexed),
                        key=lambda x: (sp.count_ops(x), str(x)), reverse=True):
            if a not in table:
                positive = a.is_positive is True or (
                    isinstance(a, sp.Sum) and a.is_positive is not False and False)
                table[a] = sp.Symbol("atom%d" % len(table), real=True,
                                     **({"positive": True} if positive else {}))
            reps[a] = table[a]
        out.append(sp.sympify(e).xreplace(reps) if reps else sp.sympify(e))
    return out


# ---------------------------------------------------------------------------------------------
# Deciding: cases of the equations before, the step on each.
# ---------------------------------------------------------------------------------------------

class Undecided(Exception):
    pass


def numeric_nonzero(e):
    """True when e is clearly not zero at a random point (the symbols' signs respected)."""
    syms = sorted(e.free_symbols, key=str)
    rng = random.Random(hash(str(e)) & 0xffff)
    for _ in range(2):
        vals = {}
        for x in syms:
            v = sp.Float(rng.uniform(0.3, 2.7), 30)
            if x.is_negative or x.is_nonpositive:
                v = -v
            vals[x] = v
        try:
            x = sp.N(e.xreplace(vals), 30)
        except Exception:
            return False
        if x.has(sp.zoo, sp.nan, sp.oo) or not x.is_number:
            continue
        if abs(x) > 1e-12 * (1 + max([abs(sp.N(a.xreplace(vals), 30)) for a in
                                      sp.Add.make_args(sp.expand(e))] or [0])):
            return True
        return False
    return False


def is_zero(e):
    e = sp.sympify(e)
    if e == 0:
        return True
    if not e.has(sp.Integral, sp.Sum, sp.Derivative, AppliedUndef) and numeric_nonzero(e):
        return False
    for f in (lambda x: sp.cancel(sp.together(sp.expand(x))),
              sp.simplify,
              lambda x: sp.simplify(sp.expand_trig(x)),
              lambda x: sp.simplify(sp.powsimp(sp.expand(x), force=False)),
              lambda x: sp.simplify(sp.expand_log(sp.expand(x), force=True)),
              lambda x: sp.simplify(x.replace(
                  lambda a: isinstance(a, sp.Pow) and a.exp.is_Rational and a.exp.q == 2,
                  lambda a: sp.Pow(sp.factor(a.base), a.exp)))):
        try:
            if f(e) == 0:
                return True
        except Exception:
            pass
    return False


def sum_of_squares(n):
    """[x, y] when n is a x^(2i) + b y^(2j) + ... with positive a, b (zero only if x = y = 0)."""
    try:
        p = sp.Poly(n, *sorted(n.free_symbols, key=str))
    except sp.PolynomialError:
        return None
    out = []
    if len(p.terms()) < 2:
        return None
    for monom, c in p.terms():
        nonzero = [k for k, x in enumerate(monom) if x]
        if not (c > 0) or len(nonzero) != 1 or monom[nonzero[0]] % 2:
            return None
        out.append(p.gens[nonzero[0]])
    if not all(g.is_real for g in out):
        return None
    return out


def num_den(e):
    n, d = sp.fraction(sp.cancel(sp.together(e)))
    return sp.expand(n), d


class Leaf:
    def __init__(self, subs, nonzero, depth, cases, branch):
        self.subs = subs  # solved symbol -> expression in the free ones
        self.nonzero = nonzero  # what must not vanish on this case
        self.depth = depth
        self.cases = cases  # the divisors set to zero to reach this case
        self.branch = branch  # root branches: the equation chosen (symbol - root)
        self.roots = []  # expressions that must be >= 0 (square roots taken)


def coefficient_status(coef, space):
    if coef.is_number:
        return 0 if coef != 0 else None
    if nonzero_by_facts(coef, space):
        return 1
    return 2


def solve_system(eqs, space, hints, depth=0, budget=None):
    """Covers the points where every eq vanishes by leaves (cases)."""
    if budget is not None:
        budget[0] -= 1
        if budget[0] < 0:
            raise Undecided("too many cases")
    work = []
    for e in eqs:
        e = sp.expand(e)
        if e == 0:
            continue
        n, _ = num_den(e)
        if n == 0:
            continue
        if n.is_number:
            return []  # inconsistent
        squares = sum_of_squares(n)
        if squares:
            work.extend(squares)  # a sum of squares of reals vanishes with each of them
        else:
            work.append(n)
    if not work:
        return [Leaf({}, [], depth, [], [])]
    best = None
    for i, e in enumerate(work):
        for s in sorted(e.free_symbols, key=str):
            try:
                p = sp.Poly(e, s)
            except sp.PolynomialError:
                continue
            if any(s in c.free_symbols for c in p.coeffs()):
                continue
            deg = p.degree()
            if deg == 1:
                status = coefficient_status(p.coeff_monomial(s), space)
                score = status
            elif deg == 2 and len(p.terms()) <= 3:
                status = coefficient_status(p.coeff_monomial(s ** 2), space)
                score = 3 + status
            else:
                continue
            if str(s) in hints:
                score -= 10 - hints.index(str(s)) * 0.01
            if str(s).startswith("atom"):
                score += 0.5
            key = (score, len(e.free_symbols), str(s))
            if best is None or key < best[0]:
                best = (key, i, s, p)
    if best is None:
        # not polynomial in any single symbol: let SymPy try
        for i, e in enumerate(work):
            for s in sorted(e.free_symbols, key=str):
                try:
                    sols = sp.solve(e, s, dict=False)
                except Exception:
                    continue
                if sols:
                    return branch_on(work, i, s, sols, space, hints, depth, budget, None)
        raise Undecided("cannot solve %s" % work)
    _, i, s, p = best
    deg = p.degree()
    if deg == 1:
        coef = p.coeff_monomial(s)
        sol = sp.cancel(-(p.as_expr() - coef * s) / coef)
        leaves = []
        rest = [w.subs(s, sol) for k, w in enumerate(work) if k != i]
        for leaf in solve_system(rest, space, hints, depth, budget):
            subs = dict(leaf.subs)
            subs[s] = sp.cancel(sol.subs(leaf.subs))
            nz = leaf.nonzero + ([coef.subs(leaf.subs)] if not coef.is_number else [])
            leaf2 = Leaf(subs, nz, leaf.depth, leaf.cases, leaf.branch)
            leaf2.roots = leaf.roots
            leaves.append(leaf2)
        return leaves + leading_vanishes(work, i, p, coef * s, space, hints, depth, budget)
    # quadratic
    a = p.coeff_monomial(s ** 2)
    sols = list(sp.roots(p, s, multiple=True))
    if len(sols) != 2:
        raise Undecided("no roots of %s" % p)
    if sols[0] == sols[1]:
        sols = sols[:1]
    leaves = branch_on(work, i, s, sols, space, hints, depth, budget, p)
    return leaves + leading_vanishes(work, i, p, a * s ** 2, space, hints, depth, budget)


def leading_vanishes(work, i, p, leading, space, hints, depth, budget):
    """The cases where the coefficient of the leading term of equation i vanishes (a factor of
    it at a time): there the equation is what is left without that term."""
    coef = sp.cancel(leading / p.gens[0] ** sp.Poly(leading, p.gens[0]).degree())
    if coef.is_number or coefficient_status(coef, space) != 2 or depth >= 3:
        return []
    leaves = []
    _, factors = sp.factor_list(coef)
    for f, _ in factors:
        if f.is_number or nonzero_by_facts(f, space):
            continue
        reduced = [w for k, w in enumerate(work) if k != i] + [
            f, sp.expand(p.as_expr() - leading)]
        for leaf in solve_system(reduced, space, hints, depth + 1, budget):
            leaf.cases = [f] + leaf.cases
            leaves.append(leaf)
    return leaves


def branch_on(work, i, s, sols, space, hints, depth, budget, poly):
    leaves = []
    for sol in sols:
        rest = [w.subs(s, sol) for k, w in enumerate(work) if k != i]
        for leaf in solve_system(rest, space, hints, depth, budget):
            subs = dict(leaf.subs)
            subs[s] = sol.subs(leaf.subs)
            leaf2 = Leaf(subs, list(leaf.nonzero), leaf.depth, leaf.cases,
                         leaf.branch + ([s - sol] if len(sols) > 1 else []))
            leaf2.roots = leaf.roots + [b for b in divisors(sol)[1]]
            if poly is not None:
                a = poly.coeff_monomial(s ** 2)
                if not a.is_number:
                    leaf2.nonzero.append(a.subs(leaf.subs))
            leaves.append(leaf2)
    return leaves


def substitute(e, subs):
    """Substitutes the solved symbols (repeatedly: a solution may name another solved symbol)."""
    for _ in range(4):
        new = e.subs(subs)
        if new == e:
            break
        e = new
    return e


# --- exact points -----------------------------------------------------------------------------

VALUES_POS = [sp.Rational(x) for x in ("1", "2", "3", "1/2", "3/2", "5/2", "1/3", "4", "5/3", "7")]
VALUES_ANY = [sp.Rational(x) for x in ("1", "-1", "2", "-2", "1/2", "3", "-1/2", "-3", "5/2",
                                        "-3/2", "0", "7", "1/3", "-5")]


def candidate_values(sym, space, rng):
    iv = space.intervals.get(sym) or Interval.real()
    if sym.is_positive or iv.positive():
        base = [v for v in VALUES_POS]
    elif sym.is_nonnegative or iv.nonnegative():
        base = [sp.Integer(0)] + VALUES_POS
    elif sym.is_negative or iv.negative():
        base = [-v for v in VALUES_POS]
    elif sym.is_nonpositive:
        base = [sp.Integer(0)] + [-v for v in VALUES_POS]
    else:
        base = list(VALUES_ANY)
    if sym.is_nonzero:
        base = [v for v in base if v != 0]
    ok = []
    for v in base:
        if in_interval(v, iv):
            ok.append(v)
    if not ok and iv.lo.value.is_finite and iv.hi.value.is_finite:
        lo, hi = iv.lo.value, iv.hi.value
        ok = [lo + (hi - lo) * sp.Rational(k, 7) for k in range(1, 7)]
        if not iv.lo.strict:
            ok.append(lo)
        if not iv.hi.strict:
            ok.append(hi)
    rng.shuffle(ok)
    return ok


def in_interval(v, iv):
    if iv.lo.value.is_finite:
        if bool(v < iv.lo.value) or (v == iv.lo.value and iv.lo.strict):
            return False
    if iv.hi.value.is_finite:
        if bool(v > iv.hi.value) or (v == iv.hi.value and iv.hi.strict):
            return False
    return True


def sign_of_number(v):
    """-1, 0 or 1 for an exact real number (algebraic or with pi); None if unsure."""
    v = sp.sympify(v)
    if v.is_Rational:
        return int(bool(v > 0)) - int(bool(v < 0))
    if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        return None
    if v.is_real is False:
        return None
    try:
        if v.is_zero or sp.nsimplify(sp.simplify(v)) == 0:
            return 0
    except Exception:
        pass
    x = sp.N(v, 60)
    if not x.is_real:
        im = sp.im(x)
        if abs(im) > 1e-40:
            return None
        x = sp.re(x)
    if abs(x) < sp.Float("1e-40"):
        return 0 if is_zero(v) else None
    return 1 if x > 0 else -1


def fact_holds(expr, op, point):
    v = substitute(expr, point)
    if v.free_symbols:
        return None
    s = sign_of_number(v)
    if s is None:
        return None
    return {">": s > 0, ">=": s >= 0, "<": s < 0, "<=": s <= 0, "!=": s != 0}[op]


class Point:
    def __init__(self, values):
        self.values = values  # symbol -> exact number


def find_points(leaf, space, extra_free, premises_divs, want, rng, tries=80):
    """Exact points of the leaf where the facts hold and the premises are defined; `want` is a
    function point -> bool selecting the points sought. Returns the first, or None."""
    free = set()
    for v in leaf.subs.values():
        free |= v.free_symbols
    for e in list(extra_free) + [x for x, _ in space.relations] + list(leaf.nonzero) + list(
            premises_divs) + list(leaf.roots):
        free |= sp.sympify(e).free_symbols
    free -= set(leaf.subs)
    free = sorted(free, key=str)
    choices = {s: candidate_values(s, space, rng) for s in free}
    seen = 0
    combos = []
    for _ in range(tries):
        combos.append({s: choices[s][rng.randrange(len(choices[s]))] for s in free if choices[s]})
    for values in combos:
        if any(not choices[s] for s in free):
            return None
        point = dict(values)
        ok = True
        for s, expr in leaf.subs.items():
            v = substitute(expr, values)
            if v.has(sp.zoo, sp.nan) or v.free_symbols:
                ok = False
                break
            if sign_of_number(sp.im(v)) not in (0,):
                ok = False
                break
            point[s] = sp.nsimplify(v) if v.is_Rational else v
        if not ok:
            continue
        if not admissible(point, leaf, space, premises_divs):
            continue
        seen += 1
        if want(point):
            return point
    return None


def admissible(point, leaf, space, premises_divs):
    for expr, op in space.relations:
        if fact_holds(expr, op, point) is not True:
            return False
    for sym, iv in space.intervals.items():
        if sym in point:
            v = point[sym]
            s_lo = sign_of_number(v - iv.lo.value) if iv.lo.value.is_finite else 1
            s_hi = sign_of_number(iv.hi.value - v) if iv.hi.value.is_finite else 1
            if s_lo is None or s_hi is None or s_lo < 0 or s_hi < 0 or (
                    s_lo == 0 and iv.lo.strict) or (s_hi == 0 and iv.hi.strict):
                return False
            if sym.is_positive and sign_of_number(v) != 1:
                return False
            if sym.is_nonnegative and sign_of_number(v) not in (0, 1):
                return False
            if sym.is_negative and sign_of_number(v) != -1:
                return False
            if sym.is_nonzero and sign_of_number(v) == 0:
                return False
    for q in list(leaf.nonzero) + list(premises_divs):
        if fact_holds(q, "!=", point) is not True:
            return False
    for r in leaf.roots:
        if fact_holds(r, ">=", point) is not True:
            return False
    return True


def fails_at(components, divs, roots, point):
    """Whether the equation fails (or is undefined) at the exact point."""
    for q in divs:
        s = fact_holds(q, "!=", point)
        if s is False:
            return True
        if s is None:
            return None
    for r in roots:
        s = fact_holds(r, ">=", point)
        if s is False:
            return True
    for c in components:
        v = substitute(c, point)
        if v.free_symbols:
            return None
        s = sign_of_number(v)
        if s is None:
            return None
        if s != 0:
            return True
    return False


# --- a step, decided -----------------------------------------------------------------------------

class Finding:
    def __init__(self, verdict, how, where=(), point=None):
        self.verdict, self.how, self.where, self.point = verdict, how, list(where), point


def implies(premise_meanings, space, target, hints, rng, seconds=60):
    """Does `target` (a Meaning) hold wherever the premises (Meanings) and the facts hold?
    Returns ('holds', how) / ('holds-if', how, condition exprs, point) / ('fails', how, point)."""
    table = {}
    substitutions = function_definitions(premise_meanings, space)
    pre = []
    pdivs = []
    for m in premise_meanings:
        for c in m.components:
            pre.append(apply_functions(c, substitutions))
        pdivs += [apply_functions(d, substitutions) for d in m.divs]
    pre += identity_derivatives(pre, space)
    pre += [q for q in space.equalities if q not in space.unit_equalities]
    tcomp = [apply_functions(c, substitutions) for c in target.components]
    tdivs = [apply_functions(d, substitutions) for d in target.divs]
    troots = [apply_functions(d, substitutions) for d in target.roots]
    allx = atoms_to_symbols(pre + pdivs + tcomp + tdivs + troots, table)
    n1, n2, n3, n4 = len(pre), len(pdivs), len(tcomp), len(tdivs)
    pre, pdivs = allx[:n1], allx[n1:n1 + n2]
    tcomp = allx[n1 + n2:n1 + n2 + n3]
    tdivs = allx[n1 + n2 + n3:n1 + n2 + n3 + n4]
    troots = allx[n1 + n2 + n3 + n4:]
    for atom, sym in table.items():
        space.intervals[sym] = interval(atom, space)
    budget = [200]
    leaves, results = [], []
    # A unit vector n is [(1 - s^2)/(1 + s^2), 2s/(1 + s^2)] for a number s, or [-1, 0].
    unit_cases = [{}]
    for k, (nx, ny) in enumerate(space.unit_vectors):
        sk = sp.Symbol("s_%s" % str(nx)[:-2], real=True)
        space.intervals[sk] = Interval.real()
        unit_cases = [{**c, nx: (1 - sk ** 2) / (1 + sk ** 2), ny: 2 * sk / (1 + sk ** 2)}
                      for c in unit_cases] + [{**c, nx: sp.Integer(-1), ny: sp.Integer(0)}
                                              for c in unit_cases]
    for case in unit_cases:
        def on(xs):
            return [sp.sympify(x).xreplace(case) if case else x for x in xs]
        pre_c, pdivs_c, tcomp_c = on(pre), on(pdivs), on(tcomp)
        tdivs_c, troots_c = on(tdivs), on(troots)
        for leaf in solve_system(pre_c, space, hints, 0, budget):
            leaves.append(leaf)
            results.append(judge_leaf(leaf, space, pdivs_c, tcomp_c, tdivs_c, troots_c, rng))
    feasible = [(leaf, r) for leaf, r in zip(leaves, results) if r[0] != "empty"]
    if any(r[0] == "unknown" for _, r in feasible):
        bad = [r for _, r in feasible if r[0] == "unknown"]
        raise Undecided("a case could not be decided: " + bad[0][1])
    if not feasible:
        raise Undecided("no point satisfies the equations before and the facts")
    holds = [(l, r) for l, r in feasible if r[0] == "holds"]
    fails = [(l, r) for l, r in feasible if r[0] != "holds"]
    if not fails:
        return ("holds", "%d case(s), each simplified to zero" % len(feasible), [], None)
    depth0 = min(l.depth for l, _ in feasible)
    generic = [(l, r) for l, r in feasible if l.depth == depth0]
    generic_hold = [x for x in generic if x[1][0] == "holds" or x[1][0] == "undefined-at"]
    if not generic_hold:
        l, r = fails[0]
        return ("fails", r[1], [], r[2])
    # holds somewhere generic, fails elsewhere: a condition
    cond = []
    for l, r in fails:
        if r[0] == "undefined-at":
            cond += r[3]
        elif l.depth > depth0:
            cond += l.cases[:1] or l.branch
        else:
            cond += l.branch or l.cases
    point = fails[0][1][2]
    return ("holds-if", "; ".join(r[1] for _, r in fails), cond, point)


def judge_leaf(leaf, space, pdivs, tcomp, tdivs, troots, rng):
    """('holds'|'fails'|'undefined-at'|'empty'|'unknown', how, point, conditions)."""
    # a case whose solved symbols break a fact for every value is empty
    for s, expr in leaf.subs.items():
        iv = interval(expr, space)
        siv = space.intervals.get(s)
        if siv is not None and disjoint(iv, siv):
            return ("empty", "a fact excludes it", None, [])
        if s.is_positive and (iv.negative() or iv.nonpositive()):
            return ("empty", "a fact excludes it", None, [])
        if s.is_negative and (iv.positive() or iv.nonnegative()):
            return ("empty", "a fact excludes it", None, [])
        if s.is_nonnegative and iv.negative():
            return ("empty", "a fact excludes it", None, [])
    for expr, op in space.relations:
        v = substitute(expr, leaf.subs)
        iv = interval(v, space)
        if (op == ">" and iv.nonpositive()) or (op == ">=" and iv.negative()) or (
                op == "<" and iv.nonnegative()) or (op == "<=" and iv.positive()):
            return ("empty", "a fact excludes it", None, [])
    pd = [substitute(d, leaf.subs) for d in pdivs]
    for d in pd:
        if is_zero(d):
            return ("empty", "the equations before are undefined there", None, [])
    for q in leaf.nonzero:
        if is_zero(q):
            return ("empty", "contradictory case", None, [])
    comps = [substitute(c, leaf.subs) for c in tcomp]
    zero = [is_zero(c) for c in comps]
    divs = [substitute(d, leaf.subs) for d in tdivs]
    roots = [substitute(r, leaf.subs) for r in troots]
    rng2 = random.Random(rng.random())
    if all(zero):
        # defined everywhere on the case?
        conds = []
        for q, q0 in zip(divs, tdivs):
            if is_zero(q):
                pt = find_points(leaf, space, [], pd, lambda p: True, rng2)
                if pt is None:
                    return ("unknown", "no exact point of a case where the step is undefined",
                            None, [])
                return ("fails", "the step divides by zero on a whole case", pt, [])
            if nonzero_by_facts(q, space):
                continue
            n, _ = num_den(q)
            # q = 0 excluded by the equations before (a divisor of theirs)?
            if any(sp.rem(sp.Poly(num_den(d)[0], *sorted(n.free_symbols, key=str)),
                          sp.Poly(n, *sorted(n.free_symbols, key=str))).is_zero
                   for d in pd if n.free_symbols and d.free_symbols >= n.free_symbols
                   and is_poly(num_den(d)[0], n.free_symbols)):
                continue
            sub = solve_system([n], space, [], leaf.depth + 1, [100])
            found = None
            for sl in sub:
                merged = Leaf({**{k: substitute(v, sl.subs) for k, v in leaf.subs.items()},
                               **sl.subs}, leaf.nonzero + sl.nonzero, sl.depth, [], [])
                merged.roots = leaf.roots + sl.roots
                found = find_points(merged, space, [], pd, lambda p: True, rng2)
                if found is not None:
                    break
            if found is not None:
                conds.append(q0)
                return ("undefined-at", "divides by %s, which can vanish" % q0, found, [q0])
            if sub:
                # q = 0 leaves points in principle but none was found admissible
                if all(empty_case(sl, leaf, space, pd) for sl in sub):
                    continue
                return ("unknown", "cannot tell whether %s can vanish" % q0, None, [])
        for r in roots:
            if interval(r, space).nonnegative():
                continue
            pt = find_points(leaf, space, [r], pd,
                             lambda p: fact_holds(r, ">=", p) is False, rng2)
            if pt is not None:
                return ("fails", "takes a root of a negative number", pt, [])
        return ("holds", "zero", None, [])
    # not zero: find a point where it fails
    extra = [c for c in comps]
    pt = find_points(leaf, space, extra, pd,
                     lambda p: fails_at(comps, divs, roots, p) is True, rng2, tries=200)
    if pt is not None:
        return ("fails", "fails at an exact point", pt, [])
    pt_any = find_points(leaf, space, extra, pd, lambda p: True, rng2)
    if pt_any is None:
        if case_empty_by_facts(leaf, space):
            return ("empty", "no admissible point", None, [])
        return ("unknown", "no admissible point found on a case where the step does not "
                           "simplify to zero (%s)" % comps, None, [])
    return ("unknown", "does not simplify to zero but holds at every point tried: %s" % comps,
            None, [])


def is_poly(e, syms):
    try:
        sp.Poly(e, *sorted(syms, key=str))
        return True
    except Exception:
        return False


def empty_case(sub_leaf, leaf, space, pd):
    merged = Leaf({**{k: substitute(v, sub_leaf.subs) for k, v in leaf.subs.items()},
                   **sub_leaf.subs}, leaf.nonzero + sub_leaf.nonzero, sub_leaf.depth, [], [])
    return case_empty_by_facts(merged, space) or any(
        is_zero(substitute(d, merged.subs)) for d in pd) or any(
        is_zero(substitute(q, merged.subs)) for q in merged.nonzero)


def case_empty_by_facts(leaf, space):
    for s, expr in leaf.subs.items():
        iv = interval(expr, space)
        siv = space.intervals.get(s)
        if siv is not None and disjoint(iv, siv):
            return True
        if s.is_positive and (iv.nonpositive()):
            return True
        if s.is_negative and iv.nonnegative():
            return True
    for expr, op in space.relations:
        v = substitute(expr, leaf.subs)
        iv = interval(v, space)
        if (op == ">" and iv.nonpositive()) or (op == ">=" and iv.negative()) or (
                op == "<" and iv.nonnegative()) or (op == "<=" and iv.positive()):
            return True
    return False


def disjoint(a, b):
    if a.hi.value.is_finite and b.lo.value.is_finite:
        if bool(a.hi.value < b.lo.value) or (a.hi.value == b.lo.value and (a.hi.strict or
                                                                            b.lo.strict)):
            return True
    if b.hi.value.is_finite and a.lo.value.is_finite:
        if bool(b.hi.value < a.lo.value) or (b.hi.value == a.lo.value and (b.hi.strict or
                                                                            a.lo.strict)):
            return True
    return False


def function_definitions(meanings, space):
    """Equations F(t) = g(t) of a declared function at a symbol: identities in t, used to
    substitute F everywhere (the integral and derivative of F then come from g)."""
    subs = {}
    for m in meanings:
        if len(m.components) != 1:
            continue
        c = m.components[0]
        for a in c.atoms(AppliedUndef):
            if len(a.args) == 1 and isinstance(a.args[0], sp.Symbol) and \
                    str(a.func) in space.ctx.functions:
                t = a.args[0]
                try:
                    sol = sp.solve(c, a)
                except Exception:
                    continue
                if len(sol) == 1 and not sol[0].has(a.func):
                    subs[a.func] = sp.Lambda(t, sol[0])
                    break
    return subs


def identity_derivatives(components, space):
    """An equation between declared functions at a free symbol t holds for every t: its
    derivatives in t hold too (x(t) = x_0 + v_0 t gives x'(t) = v_0)."""
    out = []
    for c in components:
        ts = set()
        for a in c.atoms(AppliedUndef):
            if str(a.func) in space.ctx.functions:
                ts |= {x for x in a.args if isinstance(x, sp.Symbol)}
        for d in c.atoms(sp.Derivative):
            ts |= {v for v, _ in d.variable_count}
        for t in ts:
            if t not in c.free_symbols:
                continue
            d1 = sp.diff(c, t)
            out += [d1, sp.diff(d1, t)]
    return [prepare(x) for x in out if x != 0]


def apply_functions(e, subs):
    if not subs:
        return e
    for f, lam in subs.items():
        e = e.replace(lambda x: isinstance(x, AppliedUndef) and x.func == f,
                      lambda x: lam(*x.args))
    return prepare(e)


# --- dimensions -------------------------------------------------------------------------------

DIM = {"M": sp.Symbol("M", positive=True), "L": sp.Symbol("L", positive=True),
       "T": sp.Symbol("T", positive=True)}


class DimensionError(Exception):
    pass


def dimension(e, units):
    if isinstance(e, sp.MatrixBase):
        ds = [dimension(x, units) for x in e]
        ds = [d for d in ds if d is not None]
        return ds[0] if ds else None
    if e.is_number:
        return None if e == 0 else sp.Integer(1)
    if isinstance(e, sp.Symbol):
        if e.name not in units:
            raise FileError("no units for %s" % e.name)
        return units[e.name]
    if isinstance(e, sp.Add):
        dims = [dimension(a, units) for a in e.args]
        dims = [d for d in dims if d is not None]
        for d in dims[1:]:
            if sp.simplify(d / dims[0]) != 1:
                raise DimensionError("%s and %s" % (dims[0], d))
        return dims[0] if dims else None
    if isinstance(e, sp.Mul):
        out = sp.Integer(1)
        for a in e.args:
            d = dimension(a, units)
            if d is None:
                return None
            out *= d
        return out
    if isinstance(e, sp.Pow):
        d = dimension(e.args[0], units)
        if d is None:
            return None
        if not e.args[1].is_number:
            if d != 1:
                raise DimensionError("a power of %s" % d)
            return sp.Integer(1)
        return d ** e.args[1]
    if isinstance(e, sp.Integral):
        d = dimension(e.args[0], units)
        v = e.args[1][0]
        dv = units.get(v.name, sp.Integer(1))
        return None if d is None else d * dv
    if isinstance(e, sp.Derivative):
        d = dimension(e.args[0], units)
        v = e.args[1][0]
        return None if d is None else d / units.get(v.name, sp.Integer(1))
    if isinstance(e, sp.Subs):
        return dimension(e.args[0], units)
    if isinstance(e, AppliedUndef):
        return units.get(str(e.func), sp.Integer(1))
    if isinstance(e, (sp.sin, sp.cos, sp.tan, sp.exp, sp.log)):
        d = dimension(e.args[0], units)
        if d not in (None, 1):
            raise DimensionError("%s of %s" % (e.func, d))
        return sp.Integer(1)
    raise FileError("no dimension rule for %s" % e)


def dimensions_clash(eq, space):
    ctx = eq.context
    if not ctx.units:
        return None
    units = {k: sp.sympify(v, locals=DIM) for k, v in ctx.units.items()}
    try:
        raw_l = space.parse(eq.lhs, evaluate=False)
        raw_r = space.parse(eq.rhs, evaluate=False)
        dl, dr = dimension(raw_l, units), dimension(raw_r, units)
    except DimensionError as err:
        return str(err)
    if dl is not None and dr is not None and sp.simplify(dl / dr) != 1:
        return "%s against %s" % (dl, dr)
    return None


# --- the verdict of one equation ---------------------------------------------------------------

def latex_name(sym, ctx):
    name = str(sym)
    if name in ctx.names:
        return ctx.names[name]
    m = re.fullmatch(r"([A-Za-z]+?)(_?)([0-9a-z]*)", name)
    greek = ("alpha beta gamma delta epsilon theta omega phi psi mu nu rho sigma tau lambda "
             "Delta Omega Theta").split()
    base = name
    sub = ""
    mm = re.fullmatch(r"([A-Za-z]+)_([A-Za-z0-9]+)", name)
    if mm:
        base, sub = mm.group(1), mm.group(2)
    else:
        mm = re.fullmatch(r"([A-Za-z]+?)([0-9]+)p*", name)
        if mm:
            base, sub = mm.group(1), mm.group(2)
    if base in greek:
        base = "\\" + base
    return base + ("_" + sub if sub and len(sub) == 1 else ("_{%s}" % sub if sub else ""))


def base_symbols(exprs, ctx, atom_table=None):
    names = set()
    for e in exprs:
        for s in sp.sympify(e).free_symbols:
            n = str(s)
            for v in ctx.vectors:
                if n in (v + "_x", v + "_y"):
                    n = v
            if n.startswith("atom"):
                continue
            if n.endswith("p") and len(n) > 1 and not n in ctx.names:
                n = n[:-1]
            names.add(latex_name(sp.Symbol(n), ctx))
    return sorted(names)


def decide(equations, k, seed, verbose=False):
    """The judge's verdict of equation k: (verdict, where-names, how)."""
    eq = equations[k]
    space_names = set()
    for j in [k] + eq.premises:
        space_names |= set(identifiers(equations[j].lhs)) | set(identifiers(equations[j].rhs))
    space = Space(eq.context, space_names)
    clash = dimensions_clash(eq, space)
    if clash:
        return ("dimensions", [], "dimensions: " + clash)
    if eq.premise:
        return ("premise", [], "")
    rng = random.Random(seed)
    step = Meaning(space, eq.lhs, eq.rhs)
    pre = []
    for j in eq.premises:
        # a premise is read under the facts and definitions of the step
        pre.append(Meaning(space, equations[j].lhs, equations[j].rhs))
    hints = list(eq.context.solve_hints)
    try:
        r = implies(pre, space, step, hints, rng)
    except Undecided as err:
        return ("undecided", [], "forward: %s" % err)
    if r[0] == "fails":
        return ("does-not-follow", [], "%s at %s" % (r[1], show_point(r[3])))
    if r[0] == "holds-if":
        conds = []
        for c in r[2]:
            n, _ = num_den(sp.sympify(c))
            try:
                _, factors = sp.factor_list(n)
            except sp.PolynomialError:
                factors = [(n, 1)]
            kept = [f for f, _ in factors if not nonzero_by_facts(f, space)]
            conds += kept or [n]
        return ("follows-if", base_symbols(conds, eq.context),
                "condition %s; fails at %s" % (r[2], show_point(r[3])))
    # the converse: every equation before from the step
    for j, m in zip(eq.premises, pre):
        try:
            c = implies([step], space, m, hints, random.Random(seed + j + 1))
        except Undecided as err:
            return ("undecided", [], "converse: %s" % err)
        if c[0] != "holds":
            return ("follows-one-way", [], "forward: %s; converse fails at %s" % (
                r[1], show_point(c[3])))
    return ("follows", [], "forward: %s; converse too" % r[1])


def show_point(p):
    if not p:
        return "-"
    return "{" + ", ".join("%s: %s" % (k, v) for k, v in sorted(p.items(), key=lambda x: str(x[0]))
                           if not str(k).startswith("atom")) + "}"


def judge_file(path, verbose=False):
    equations, pins = read_file(path)
    out = []
    for k, eq in enumerate(equations):
        t0 = time.time()
        verdict, where, how = decide(equations, k, seed=1000 + k)
        out.append((eq.line, eq.index, verdict, where, how, time.time() - t0))
        if verbose:
            print("  %d.%d %s %s  [%s] (%.2fs)" % (eq.line, eq.index, verdict,
                                                   ("where: " + " ".join(where)) if where else "",
                                                   how, time.time() - t0))
    return out, pins


def by_line(results):
    lines = {}
    for line, index, verdict, where, how, _ in results:
        v, w = lines.setdefault(line, ([], []))
        v.append(verdict)
        for x in where:
            if x not in w:
                w.append(x)
    return {line: (v, sorted(w)) for line, (v, w) in lines.items()}


def format_line(rel, line, verdicts, where):
    s = "%s %d %s" % (rel, line, " ".join(verdicts))
    if where:
        s += " where: " + " ".join(where)
    return s


def corpus_files():
    return sorted(os.path.join(HERE, f) for f in os.listdir(HERE)
                  if f.endswith(".md") and f != "README.md")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--number", action="store_true",
                    help="number the pins written '- verdict ...' with the lines of the file's "
                         "equations, in order (structure only; the verdicts stay as written)")
    args = ap.parse_args()
    if args.number:
        for path in args.files:
            number_pins(path)
        return 0
    files = [os.path.abspath(f) for f in args.files] or corpus_files()
    lines = []
    problems = []
    counts = {}
    t0 = time.time()
    for path in files:
        rel = os.path.relpath(path, HERE)
        if args.verbose:
            print(rel)
        try:
            results, pins = judge_file(path, args.verbose)
        except FileError as err:
            problems.append("%s: %s" % (rel, err))
            continue
        for r in results:
            counts[r[2]] = counts.get(r[2], 0) + 1
        got = by_line(results)
        for line in sorted(got):
            lines.append(format_line(rel, line, *got[line]))
        if pins is None:
            problems.append("%s: no expect block" % rel)
            continue
        for line in sorted(set(got) | set(pins)):
            if got.get(line) != pins.get(line):
                problems.append("%s:%d: pinned %s, SymPy says %s" % (
                    rel, line, format_pin(pins.get(line)), format_pin(got.get(line))))
    elapsed = time.time() - t0
    text = "\n".join(lines) + "\n"
    if not args.check:
        sys.stdout.write(text)
    summary = ", ".join("%s %d" % (k, counts[k]) for k in VERDICTS if k in counts)
    sys.stderr.write("%d files, %s; %.1f s\n" % (len(files), summary, elapsed))
    if args.write and not args.files:
        tmp = VERDICTS_FILE + ".tmp"
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, VERDICTS_FILE)
    if args.check and not args.files:
        pinned = open(VERDICTS_FILE).read() if os.path.exists(VERDICTS_FILE) else ""
        if pinned != text:
            a, b = set(pinned.splitlines()), set(text.splitlines())
            for x in sorted(a - b):
                problems.append("sympy-verdicts.txt pins: " + x)
            for x in sorted(b - a):
                problems.append("SymPy now says: " + x)
    if "undecided" in counts:
        problems.append("%d equations undecided: fix the step or its transcription"
                        % counts["undecided"])
    for p in problems:
        sys.stderr.write(p + "\n")
    return 1 if problems and (args.check or args.write) else 0


def number_pins(path):
    equations, _ = read_file(path)
    lines = []
    for e in equations:
        if e.line not in lines:
            lines.append(e.line)
    text = open(path, encoding="utf-8").read()
    start = text.index("<!-- expect")
    end = text.index("-->", start)
    body = text[start:end].split("\n")
    k = 0
    for i, row in enumerate(body):
        if row.startswith("- "):
            body[i] = "%d %s" % (lines[k], row[2:])
            k += 1
    if k != len(lines):
        raise FileError("%s: %d pins for %d equation lines" % (path, k, len(lines)))
    with open(path, "w", encoding="utf-8") as f:
        f.write(text[:start] + "\n".join(body) + text[end:])


def format_pin(p):
    if p is None:
        return "nothing"
    v, w = p
    return " ".join(v) + ((" where: " + " ".join(w)) if w else "")


if __name__ == "__main__":
    sys.exit(main())
