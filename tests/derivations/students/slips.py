#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Seeded random slips in the correct steps of the corpus (run with /usr/bin/python3; not part
of the test suite).

Each slip is one change to one correct step (pinned follows or follows-one-way), made the same
way in the step's LaTeX line and in its SymPy transcription:

  sign            a binary + becomes - or the other way round (the k-th of the side, in both)
  subscript       a subscript 1 becomes 2 or the other way round (m_1 / m1)
  prime           a prime dropped (v_1' / v1p becomes v_1 / v1)
  square          a square lost (^2 / **2)
  factor          a number changed, n to n + 1 or 2n (not in a subscript or an exponent)
  term            a term of a side dropped

A change is made only where the two texts agree on what it touches: the same sequence of
operators (sign, term), of subscripted letters (subscript), of primed letters (prime), of squares
(square) or of numbers (factor) in the side of the LaTeX and in its transcription; so the k-th
in one is the k-th in the other. The judge (judge.py) then decides the changed step from the same
premises and facts; a change that SymPy still finds to follow (follows, follows-one-way or
follows-if: a slip that is no slip) is discarded and counted, as is one it cannot decide.

  slips.py            write slips.tsv (seed 23, at least 1000 rows) and print the counts
  slips.py --seed N --per-step K
"""
import argparse
import os
import random
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import judge  # noqa: E402

HERE = judge.HERE
OUT = os.path.join(HERE, "slips.tsv")

# ---- the LaTeX of a line: which characters may change -------------------------------------------


def protected_mask(line):
    """True for characters no slip may touch: delimiters, tags, labels, text, alignment."""
    mask = [False] * len(line)
    for pat in (r"\$\$", r"\\\[", r"\\\]", r"\\begin\{[a-z*]+\}", r"\\end\{[a-z*]+\}",
                r"\\tag\{[^}]*\}", r"\\text\{[^}]*\}", r"\\label\{[^}]*\}", r"&", r"\\\\",
                r"\\(?:Rightarrow|implies|therefore|iff|quad|qquad)\b", r"\\[,;!]"):
        for m in re.finditer(pat, line):
            for i in range(m.start(), m.end()):
                mask[i] = True
    return mask


def side_spans(line):
    """The spans of the left and right side of the one equation of a line (the left one empty
    for a row that continues a chain)."""
    mask = protected_mask(line)
    masked = "".join(" " if mask[i] else c for i, c in enumerate(line))
    eqs = judge.top_level_equals(masked)
    if len(eqs) != 1:
        return None
    k = eqs[0]
    # the math of the line: from the first unprotected character to the last
    chars = [i for i, c in enumerate(masked) if not c.isspace()]
    start, end = chars[0], chars[-1] + 1
    # a side ends at the annotation or delimiter that follows it
    return (start, k), (k + 1, end), mask


def script_mask(text):
    """True for characters inside a subscript or superscript (_x, _{...}, ^x, ^{...})."""
    mask = [False] * len(text)
    i = 0
    while i < len(text):
        if text[i] in "_^" and i + 1 < len(text):
            j = i + 1
            if text[j] == "{":
                depth = 0
                while j < len(text):
                    if text[j] == "{":
                        depth += 1
                    elif text[j] == "}":
                        depth -= 1
                        if depth == 0:
                            break
                    j += 1
            elif text[j] == "\\":
                j += 1
                while j < len(text) and text[j].isalpha():
                    j += 1
                j -= 1
            for x in range(i, min(j + 1, len(text))):
                mask[x] = True
            i = j + 1
            continue
        i += 1
    return mask


# ---- occurrences, in the LaTeX and in the transcription -------------------------------------------


def latex_ops(text, ok):
    return [(m.start() + 1, m.group(1)) for m in re.finditer(r" ([+-]) ", text)
            if ok[m.start() + 1]]


def sympy_ops(text):
    return [(m.start() + 1, m.group(1)) for m in re.finditer(r" ([+-]) ", text)]


def latex_subscripts(text, ok):
    out = []
    for m in re.finditer(r"(\\?[A-Za-z]+)_(\{)?([12])(\})?(?![0-9])", text):
        if ok[m.start(3)]:
            out.append((m.start(3), m.group(1).lstrip("\\").lower(), m.group(3)))
    return out


def sympy_subscripts(text):
    return [(m.start(2), m.group(1).lower(), m.group(2))
            for m in re.finditer(r"(?<![\w.])([A-Za-z]+)([12])(p?)(?![\w(])", text)]


def latex_primes(text, ok):
    out = []
    for m in re.finditer(r"'", text):
        if not ok[m.start()]:
            continue
        before = text[:m.start()].rstrip("}")
        b = re.search(r"(\\?[A-Za-z]+)(?:_\{?[0-9A-Za-z]+\}?)?$", before)
        if not b:
            return None
        out.append((m.start(), b.group(1).lstrip("\\").lower()))
    return out


def sympy_primes(text, names):
    out = []
    for m in re.finditer(r"(?<![\w.])([A-Za-z_]+?)([0-9]*)p(?![\w(])", text):
        name = m.group(0)
        if name[:-1] in names:
            out.append((m.start(), m.end(), m.group(1).lower().rstrip("_")))
    return out


def latex_squares(text, ok):
    return [(m.start(), m.end()) for m in re.finditer(r"\^(?:2|\{2\})(?![0-9])", text)
            if ok[m.start()]]


def sympy_squares(text):
    return [(m.start(), m.end()) for m in re.finditer(r"\*\*2(?![0-9])", text)]


def latex_numbers(text, ok, scripts):
    out = []
    for m in re.finditer(r"(?<![A-Za-z0-9.])(\d+)(?![0-9.])", text):
        if ok[m.start()] and not scripts[m.start()]:
            out.append((m.start(), m.end(), int(m.group(1))))
    return out


def sympy_numbers(text):
    out = []
    for m in re.finditer(r"(?<![\w.])(\d+)(?![\w.])", text):
        if text[:m.start()].endswith("**"):
            continue
        out.append((m.start(), m.end(), int(m.group(1))))
    return out


def latex_terms(text, ok):
    """Top-level + and - of a side (not inside braces, parentheses or brackets)."""
    depth = 0
    out = []
    i = 0
    while i < len(text):
        if text.startswith("\\left", i) or re.match(r"\\[Bb]ig+l", text[i:]):
            depth += 1
        elif text.startswith("\\right", i) or re.match(r"\\[Bb]ig+r", text[i:]):
            depth -= 1
        c = text[i]
        if c in "{([":
            depth += 1
        elif c in "})]":
            depth -= 1
        elif c in "+-" and depth == 0 and ok[i] and i > 0 and text[i - 1] == " " and \
                i + 1 < len(text) and text[i + 1] == " ":
            out.append((i, c))
        i += 1
    return out


def sympy_terms(text):
    depth = 0
    out = []
    for i, c in enumerate(text):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c in "+-" and depth == 0 and 0 < i < len(text) - 1 and text[i - 1] == " " and \
                text[i + 1] == " ":
            out.append((i, c))
    return out


# ---- mutations of one side -----------------------------------------------------------------------------


def mutations(ltx, ok, spy, names):
    """Every change of the side that the LaTeX and the transcription agree on:
    (kind, new LaTeX, new transcription)."""
    out = []
    scripts = script_mask(ltx)
    # sign
    lo, so = latex_ops(ltx, ok), sympy_ops(spy)
    lo = [x for x in lo if not scripts[x[0]]]
    if [c for _, c in lo] == [c for _, c in so]:
        for (li, c), (si, _) in zip(lo, so):
            f = "-" if c == "+" else "+"
            out.append(("sign", ltx[:li] + f + ltx[li + 1:], spy[:si] + f + spy[si + 1:]))
    # subscript
    ls, ss = latex_subscripts(ltx, ok), sympy_subscripts(spy)
    if [(b, d) for _, b, d in ls] == [(b, d) for _, b, d in ss]:
        for (li, _, d), (si, _, _) in zip(ls, ss):
            f = "2" if d == "1" else "1"
            out.append(("subscript", ltx[:li] + f + ltx[li + 1:], spy[:si] + f + spy[si + 1:]))
    # prime
    lp, sp_ = latex_primes(ltx, ok), sympy_primes(spy, names)
    if lp is not None and [b for _, b in lp] == [b for _, _, b in sp_]:
        for (li, _), (s0, s1, _) in zip(lp, sp_):
            out.append(("prime", ltx[:li] + ltx[li + 1:], spy[:s1 - 1] + spy[s1:]))
    # square
    lq, sq = latex_squares(ltx, ok), sympy_squares(spy)
    if len(lq) == len(sq):
        for (l0, l1), (s0, s1) in zip(lq, sq):
            out.append(("square", ltx[:l0] + ltx[l1:], spy[:s0] + spy[s1:]))
    # factor
    ln, sn = latex_numbers(ltx, ok, scripts), sympy_numbers(spy)
    if [n for _, _, n in ln] == [n for _, _, n in sn]:
        for (l0, l1, n), (s0, s1, _) in zip(ln, sn):
            if n == 0:
                continue
            out.append(("factor", ltx[:l0] + str(n + 1) + ltx[l1:], spy[:s0] + str(n + 1) +
                        spy[s1:]))
            if n >= 2:
                out.append(("factor", ltx[:l0] + str(2 * n) + ltx[l1:], spy[:s0] + str(2 * n) +
                            spy[s1:]))
    # term
    lt, st = latex_terms(ltx, ok), sympy_terms(spy)
    if lt and [c for _, c in lt] == [c for _, c in st]:
        for k in range(len(lt) + 1):
            out.append(("term", drop_term(ltx, lt, k), drop_term(spy, st, k)))
    return out


def drop_term(text, ops, k):
    """The side without its k-th top-level term (ops: the positions of its + and -)."""
    lead = text[:len(text) - len(text.lstrip())]
    trail = text[len(text.rstrip()):]
    if k == 0:
        pos, c = ops[0]
        return lead + ("-" if c == "-" else "") + text[pos + 1:].strip() + trail
    before = text[:ops[k - 1][0]].rstrip()
    if k < len(ops):
        return before + " " + text[ops[k][0]:].strip() + trail
    return before + trail


# ---- the corpus -------------------------------------------------------------------------------------


def candidates(path, pins):
    """(equation index, line, original line, mutated line, kind, mutated lhs, mutated rhs)."""
    lines = open(path, encoding="utf-8").read().split("\n")
    equations, _ = judge.read_file(path)
    per_line = {}
    for e in equations:
        per_line[e.line] = per_line.get(e.line, 0) + 1
    out = []
    for k, e in enumerate(equations):
        if e.premise or per_line[e.line] != 1:
            continue
        verdicts = pins.get(e.line, ([], []))[0]
        if verdicts not in (["follows"], ["follows-one-way"]):
            continue
        raw = lines[e.line - 1]
        spans = side_spans(raw)
        if spans is None:
            continue
        (l0, l1), (r0, r1), mask = spans
        ok = [not m for m in mask]
        names = set(judge.identifiers(e.lhs + " " + e.rhs))
        continues = not raw[l0:l1].strip()
        sides = [("rhs", r0, r1, e.rhs)] + ([] if continues else [("lhs", l0, l1, e.lhs)])
        for which, a, b, spy in sides:
            ltx = raw[a:b]
            for kind, nl, ns in mutations(ltx, ok[a:b], spy, names):
                if nl == ltx or ns == spy or not nl.strip() or not ns.strip():
                    continue
                new_line = raw[:a] + nl + raw[b:]
                lhs, rhs = (e.lhs, ns) if which == "rhs" else (ns, e.rhs)
                out.append((k, e.line, raw, new_line, kind, lhs, rhs))
    return equations, out


def judge_mutation(equations, k, lhs, rhs, seed):
    e = equations[k]
    saved = (e.lhs, e.rhs)
    e.lhs, e.rhs = lhs, rhs
    try:
        return judge.decide(equations, k, seed)
    except Exception as err:  # a transcription the change made unreadable
        return ("unreadable", [], str(err))
    finally:
        e.lhs, e.rhs = saved


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=23)
    ap.add_argument("--per-step", type=int, default=20)
    ap.add_argument("--output", default=OUT)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    rows = []
    discarded = {}
    tried = 0
    t0 = time.time()
    for path in judge.corpus_files():
        rel = os.path.relpath(path, HERE)
        _, pins = judge.read_file(path)
        equations, cands = candidates(path, pins)
        by_eq = {}
        for c in cands:
            by_eq.setdefault(c[0], []).append(c)
        for k in sorted(by_eq):
            chosen = by_eq[k]
            rng.shuffle(chosen)
            for (k_, line, raw, new_line, kind, lhs, rhs) in chosen[:args.per_step]:
                tried += 1
                verdict, _, how = judge_mutation(equations, k_, lhs, rhs, seed=2000 + tried)
                if verdict in ("does-not-follow", "dimensions"):
                    rows.append((rel, line, equations[k_].index, raw, new_line, kind, verdict))
                else:
                    discarded[verdict] = discarded.get(verdict, 0) + 1
    text = "file\tline\tindex\tlatex\tmutated\tkind\tsympy\n" + "".join(
        "%s\t%d\t%d\t%s\t%s\t%s\t%s\n" % r for r in rows)
    tmp = args.output + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, args.output)
    kinds = {}
    for r in rows:
        kinds[r[5]] = kinds.get(r[5], 0) + 1
    sys.stderr.write("%d changes tried, %d kept (%s); discarded: %s; %.0f s\n" % (
        tried, len(rows), ", ".join("%s %d" % kv for kv in sorted(kinds.items())),
        ", ".join("%s %d" % kv for kv in sorted(discarded.items())) or "none",
        time.time() - t0))
    return 0 if len(rows) >= 1000 else 1


if __name__ == "__main__":
    sys.exit(main())
