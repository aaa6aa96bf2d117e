#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Task files for ten of the students' problems, their submissions and what each must give
(run with /usr/bin/python3; not part of the test suite).

For each problem, in tasks/<problem>/:
  task.md            the assignment: `given:` premises, facts, and `target:` one equation
  correct-a.md, correct-b.md    two different correct derivations that reach the target
  assumes-target.md  states the target as a premise and rewrites it
  extra-premise.md   uses a premise the task does not give (a special case made general)
  stops-short.md     correct steps that never reach the target

expect.tsv gives, per submission, target_reached (true/false), the line of the equation that
reaches the target (or -), the lines of the premises the task does not give (or -), and a word
of the reason. The lines are the structure of the files this script writes; the rest was worked
out by hand, and `make.py --check` confirms it with SymPy (students/judge.py): every step of a
correct submission follows, the equation named reaches the target (it is equivalent to it under
the task's facts), no earlier equation does, an extra premise does not follow from the task's
premises, and a submission that stops short has no equation equivalent to the target.

  make.py            write the files and expect.tsv
  make.py --check    also confirm every expectation with SymPy; exit 1 on a difference
"""
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "students"))
import judge  # noqa: E402

# A problem: facts (LaTeX, SymPy), lets, premises [(LaTeX, SymPy)], target (LaTeX, SymPy), two
# correct derivations (steps [(prose, LaTeX, SymPy)]), an extra premise and the steps it allows,
# and the steps of a derivation that stops short.
PROBLEMS = [
    {
        "name": "inelastic-energy-lost",
        "title": "Two trolleys couple: the kinetic energy lost",
        "text": "Trolley 1 (mass $m_1$, velocity $v_1$) runs into trolley 2 (mass $m_2$, velocity "
                "$v_2$); they couple and move on at $u$, and the kinetic energy $\\Delta K$ is "
                "lost. Find $\\Delta K$.",
        "facts": [("assume: m_1, m_2 > 0", "m1 > 0, m2 > 0")],
        "premises": [(r"m_1 v_1 + m_2 v_2 = (m_1 + m_2) u", "m1*v1 + m2*v2 = (m1 + m2)*u"),
                     (r"\Delta K = \tfrac{1}{2} m_1 v_1^2 + \tfrac{1}{2} m_2 v_2^2 - "
                      r"\tfrac{1}{2} (m_1 + m_2) u^2",
                      "DK = 1/2*m1*v1**2 + 1/2*m2*v2**2 - 1/2*(m1 + m2)*u**2")],
        "target": (r"\Delta K = \frac{m_1 m_2 (v_1 - v_2)^2}{2 (m_1 + m_2)}",
                   "DK = m1*m2*(v1 - v2)**2/(2*(m1 + m2))"),
        "a": [("Put in $u = (m_1 v_1 + m_2 v_2) / (m_1 + m_2)$:",
               r"\Delta K = \tfrac{1}{2} m_1 v_1^2 + \tfrac{1}{2} m_2 v_2^2 - "
               r"\frac{(m_1 v_1 + m_2 v_2)^2}{2 (m_1 + m_2)}",
               "DK = 1/2*m1*v1**2 + 1/2*m2*v2**2 - (m1*v1 + m2*v2)**2/(2*(m1 + m2))"),
              ("Over one denominator the cross terms make a square:",
               r"\Delta K = \frac{m_1 m_2 (v_1 - v_2)^2}{2 (m_1 + m_2)}",
               "DK = m1*m2*(v1 - v2)**2/(2*(m1 + m2))")],
        "b": [("The same at once, times $2 (m_1 + m_2)$:",
               r"2 (m_1 + m_2) \Delta K = m_1 m_2 (v_1 - v_2)^2",
               "2*(m1 + m2)*DK = m1*m2*(v1 - v2)**2")],
        "extra": ((r"v_2 = 0", "v2 = 0"),
                  [("With trolley 2 at rest:",
                    r"\Delta K = \frac{m_1 m_2 v_1^2}{2 (m_1 + m_2)}",
                    "DK = m1*m2*v1**2/(2*(m1 + m2))")]),
        "short": [("The common velocity:", r"u = \frac{m_1 v_1 + m_2 v_2}{m_1 + m_2}",
                   "u = (m1*v1 + m2*v2)/(m1 + m2)")],
    },
    {
        "name": "restitution-impulse",
        "title": "The impulse of a collision with restitution",
        "text": "Bodies of masses $m_1$ and $m_2$ collide on a line with the coefficient of "
                "restitution $e$; $J$ is the impulse. Find $J$.",
        "facts": [("assume: m_1, m_2 > 0, 0 \\le e \\le 1", "m1 > 0, m2 > 0, 0 <= e <= 1")],
        "premises": [(r"v_1' = v_1 - \frac{J}{m_1}", "v1p = v1 - J/m1"),
                     (r"v_2' = v_2 + \frac{J}{m_2}", "v2p = v2 + J/m2"),
                     (r"v_2' - v_1' = e (v_1 - v_2)", "v2p - v1p = e*(v1 - v2)")],
        "target": (r"J = (1 + e) \frac{m_1 m_2}{m_1 + m_2} (v_1 - v_2)",
                   "J = (1 + e)*m1*m2/(m1 + m2)*(v1 - v2)"),
        "a": [("Put the velocities after into the law of restitution:",
               r"v_2 + \frac{J}{m_2} - v_1 + \frac{J}{m_1} = e (v_1 - v_2)",
               "v2 + J/m2 - v1 + J/m1 = e*(v1 - v2)"),
              ("Gather the impulse:",
               r"J \Bigl( \frac{1}{m_1} + \frac{1}{m_2} \Bigr) = (1 + e)(v_1 - v_2)",
               "J*(1/m1 + 1/m2) = (1 + e)*(v1 - v2)"),
              ("The bracket is positive:",
               r"J = (1 + e) \frac{m_1 m_2}{m_1 + m_2} (v_1 - v_2)",
               "J = (1 + e)*m1*m2/(m1 + m2)*(v1 - v2)")],
        "b": [("Everything over $m_1 m_2$ at once:",
               r"m_1 m_2 (v_2 - v_1) + J (m_1 + m_2) = e\, m_1 m_2 (v_1 - v_2)",
               "m1*m2*(v2 - v1) + J*(m1 + m2) = e*m1*m2*(v1 - v2)"),
              ("Solve for $J$; the total mass is positive:",
               r"J = \frac{(1 + e)\, m_1 m_2 (v_1 - v_2)}{m_1 + m_2}",
               "J = (1 + e)*m1*m2*(v1 - v2)/(m1 + m2)")],
        "extra": ((r"e = 1", "e = 1"),
                  [("For an elastic collision:",
                    r"J = \frac{2 m_1 m_2}{m_1 + m_2} (v_1 - v_2)",
                    "J = 2*m1*m2/(m1 + m2)*(v1 - v2)")]),
        "short": [("Solve the law of restitution for $v_2'$:",
                   r"v_2' = v_1' + e (v_1 - v_2)", "v2p = v1p + e*(v1 - v2)")],
    },
    {
        "name": "ballistic-pendulum",
        "title": "The ballistic pendulum: the speed of the bullet",
        "text": "A bullet (mass $m$, speed $u$) lodges in a block (mass $M$) that swings up by "
                "$h$; $V > 0$ is their speed just after the impact. Find $u$.",
        "facts": [("assume: m, M, g, h, V, u > 0", "m > 0, M > 0, g > 0, h > 0, V > 0, u > 0")],
        "premises": [(r"m u = (m + M) V", "m*u = (m + M)*V"),
                     (r"\tfrac{1}{2} (m + M) V^2 = (m + M) g h",
                      "1/2*(m + M)*V**2 = (m + M)*g*h")],
        "target": (r"u = \frac{m + M}{m} \sqrt{2 g h}", "u = (m + M)/m*sqrt(2*g*h)"),
        "a": [("The speed after the impact is $\\sqrt{2 g h}$ ($V > 0$); into the momentum:",
               r"m u = (m + M) \sqrt{2 g h}", "m*u = (m + M)*sqrt(2*g*h)"),
              ("Divide by $m$:",
               r"u = \frac{m + M}{m} \sqrt{2 g h}", "u = (m + M)/m*sqrt(2*g*h)")],
        "b": [("Square the momentum and use the energy:",
               r"m^2 u^2 = (m + M)^2 \, 2 g h", "m**2*u**2 = (m + M)**2*2*g*h"),
              ("The bullet moves forward, $u > 0$:",
               r"u = \frac{m + M}{m} \sqrt{2 g h}", "u = (m + M)/m*sqrt(2*g*h)")],
        "extra": ((r"M = 9 m", "M = 9*m"),
                  [("A block nine times as heavy as the bullet:",
                    r"u = 10 \sqrt{2 g h}", "u = 10*sqrt(2*g*h)")]),
        "short": [("The speed after the impact, from the energy ($V > 0$):",
                   r"V = \sqrt{2 g h}", "V = sqrt(2*g*h)")],
    },
    {
        "name": "rod-struck-end",
        "title": "A rod struck at its end: the coefficient of the end",
        "text": "A uniform rod (mass $m$, length $L$, $I = m L^2 / 12$ about its centre) is "
                "struck at one end, square to it. Show that the end's coefficient is $4/m$.",
        "facts": [("assume: m, L > 0", "m > 0, L > 0")],
        "premises": [(r"A = \frac{1}{m} + \frac{(L/2)^2}{I}", "A = 1/m + (L/2)**2/I"),
                     (r"I = \frac{m L^2}{12}", "I = m*L**2/12")],
        "target": (r"A = \frac{4}{m}", "A = 4/m"),
        "a": [("Put in the moment of inertia:",
               r"A = \frac{1}{m} + \frac{3}{m}", "A = 1/m + 3/m"),
              ("Add:", r"A = \frac{4}{m}", "A = 4/m")],
        "b": [("Multiply by $m$ and put in the moment of inertia:", r"m A = 1 + 3",
               "m*A = 1 + 3"),
              ("", r"m A = 4", "m*A = 4")],
        "extra": ((r"m = 2", "m = 2"),
                  [("For a rod of two kilograms:", r"A = 2", "A = 2")]),
        "short": [("Square the arm:",
                   r"A = \frac{1}{m} + \frac{L^2}{4 I}", "A = 1/m + L**2/(4*I)")],
    },
    {
        "name": "centre-of-percussion",
        "title": "Where to strike a hanging rod so that the pivot feels nothing",
        "text": "A uniform rod (mass $m$, length $L$) hangs from a pivot at its top end and is "
                "struck at the depth $d$; the pivot gives no impulse. Find $d$.",
        "facts": [("assume: m, L, u > 0", "m > 0, L > 0, u > 0")],
        "premises": [(r"m u = J", "m*u = J"),
                     (r"\tfrac{1}{3} m L^2 \omega = J d", "1/3*m*L**2*omega = J*d"),
                     (r"u = \omega \frac{L}{2}", "u = omega*L/2")],
        "target": (r"d = \frac{2}{3} L", "d = 2/3*L"),
        "a": [("Put the momentum and $\\omega = 2u/L$ into the angular momentum:",
               r"\tfrac{2}{3} m L u = m u d", "2/3*m*L*u = m*u*d"),
              ("Divide by $m u > 0$:", r"d = \frac{2}{3} L", "d = 2/3*L")],
        "b": [("The same, divided by $m / 3$ at once:", r"3 u d = 2 L u", "3*u*d = 2*L*u"),
              ("Cancel $u > 0$:", r"3 d = 2 L", "3*d = 2*L")],
        "extra": ((r"L = 3", "L = 3"),
                  [("For a rod three metres long:", r"d = 2", "d = 2")]),
        "short": [("Put the momentum into the angular momentum:",
                   r"\tfrac{1}{3} m L^2 \omega = m u d", "1/3*m*L**2*omega = m*u*d"),
],
    },
    {
        "name": "wall-normal-rebound",
        "title": "A ball off a wall at an angle: the normal velocity after",
        "text": "A ball with velocity $\\vec v$ bounces off a smooth wall with unit normal "
                "$\\hat n$ and coefficient of restitution $e$. Show that its normal velocity is "
                "reversed and scaled by $e$.",
        "facts": [("vector: v, v', n", "vector v, vp, n"),
                  ("assume: \\|\\hat n\\| = 1, 0 \\le e \\le 1", "unit n, 0 <= e <= 1")],
        "premises": [(r"\vec v' = \vec v - (1 + e) (\vec v \cdot \hat n)\, \hat n",
                      "vp = v - (1 + e)*dot(v, n)*n")],
        "target": (r"\vec v' \cdot \hat n = -e\, \vec v \cdot \hat n",
                   "dot(vp, n) = -e*dot(v, n)"),
        "a": [("Dot with $\\hat n$:",
               r"\vec v' \cdot \hat n = \vec v \cdot \hat n - (1 + e) (\vec v \cdot \hat n)"
               r"(\hat n \cdot \hat n)",
               "dot(vp, n) = dot(v, n) - (1 + e)*dot(v, n)*dot(n, n)"),
              ("With $\\hat n \\cdot \\hat n = 1$:",
               r"\vec v' \cdot \hat n = -e\, \vec v \cdot \hat n", "dot(vp, n) = -e*dot(v, n)")],
        "b": [("In components, the normal part of the velocity after:",
               r"v'_x n_x + v'_y n_y = -e (v_x n_x + v_y n_y)",
               "vp_x*n_x + vp_y*n_y = -e*(v_x*n_x + v_y*n_y)")],
        "extra": ((r"\hat n = [0, 1]", "n = vec(0, 1)"),
                  [("For a floor:", r"v'_y = -e v_y", "vp_y = -e*v_y")]),
        "short": [("The change of velocity:",
                   r"\vec v' - \vec v = -(1 + e) (\vec v \cdot \hat n)\, \hat n",
                   "vp - v = -(1 + e)*dot(v, n)*n")],
    },
    {
        "name": "half-sine-impulse",
        "title": "The impulse of a half-sine pulse",
        "text": "A wall pushes a ball with $F_0 \\sin\\frac{\\pi t}{T}$ from $t = 0$ to $T$. "
                "Find the impulse $J$.",
        "facts": [("assume: F_0, T > 0", "F_0 > 0, T > 0")],
        "premises": [(r"J = \int_0^T F_0 \sin\frac{\pi t}{T} \, \mathrm{d}t",
                      "J = Integral(F_0*sin(pi*t/T), (t, 0, T))")],
        "target": (r"J = \frac{2 F_0 T}{\pi}", "J = 2*F_0*T/pi"),
        "a": [("The antiderivative between the ends:",
               r"J = \left. -\frac{F_0 T}{\pi} \cos\frac{\pi t}{T} \right|_0^T",
               "J = bar(-F_0*T/pi*cos(pi*t/T), t, 0, T)"),
              ("With $\\cos\\pi = -1$:", r"J = \frac{2 F_0 T}{\pi}", "J = 2*F_0*T/pi")],
        "b": [("Change the variable to $s = \\pi t / T$:",
               r"J = \frac{F_0 T}{\pi} \int_0^{\pi} \sin s \, \mathrm{d}s",
               "J = F_0*T/pi*Integral(sin(s), (s, 0, pi))"),
              ("The integral of the sine over half a turn is 2:",
               r"\pi J = 2 F_0 T", "pi*J = 2*F_0*T")],
        "extra": ((r"F_0 T = 1", "F_0*T = 1"),
                  [("For a unit pulse:", r"J = \frac{2}{\pi}", "J = 2/pi")]),
        "short": [("Check the antiderivative:",
                   r"\frac{\mathrm{d}}{\mathrm{d}t} \Bigl( -\frac{T}{\pi} \cos\frac{\pi t}{T} "
                   r"\Bigr) = \sin\frac{\pi t}{T}",
                   "Derivative(-T/pi*cos(pi*t/T), t) = sin(pi*t/T)")],
    },
    {
        "name": "falling-rod-spin",
        "title": "A falling rod lands on one end: its spin",
        "text": "A uniform rod (mass $m$, length $L$) falls flat at speed $v$ and pivots about "
                "the end that hits a ledge; angular momentum about the ledge is kept. Find "
                "$\\omega$.",
        "facts": [("assume: m, L, v > 0", "m > 0, L > 0, v > 0")],
        "premises": [(r"m v \frac{L}{2} = I_O\, \omega", "m*v*L/2 = I_O*omega"),
                     (r"I_O = \tfrac{1}{3} m L^2", "I_O = 1/3*m*L**2")],
        "target": (r"\omega = \frac{3 v}{2 L}", "omega = 3*v/(2*L)"),
        "a": [("Put in the moment of inertia about the end:",
               r"m v \frac{L}{2} = \tfrac{1}{3} m L^2 \omega", "m*v*L/2 = 1/3*m*L**2*omega"),
              ("Divide by $m L / 3$:", r"\omega = \frac{3 v}{2 L}", "omega = 3*v/(2*L)")],
        "b": [("Cancel $m L$ and multiply by 6:", r"3 v = 2 L \omega", "3*v = 2*L*omega")],
        "extra": ((r"L = 1", "L = 1"),
                  [("For a rod a metre long:", r"\omega = \tfrac{3}{2} v", "omega = 3/2*v")]),
        "short": [("Solve for $\\omega$:", r"\omega = \frac{m v L}{2 I_O}",
                   "omega = m*v*L/(2*I_O)")],
    },
    {
        "name": "spring-work",
        "title": "The work done compressing a spring",
        "text": "A buffer spring of stiffness $k$ is compressed by $x$; the force at the "
                "compression $s$ is $k s$. Find the work $W$.",
        "facts": [("assume: k, x > 0", "k > 0, x > 0")],
        "premises": [(r"W = \int_0^x k s \, \mathrm{d}s", "W = Integral(k*s, (s, 0, x))")],
        "target": (r"W = \tfrac{1}{2} k x^2", "W = 1/2*k*x**2"),
        "a": [("The antiderivative between the ends:",
               r"W = \left[ \tfrac{1}{2} k s^2 \right]_0^x", "W = bar(1/2*k*s**2, s, 0, x)"),
              ("", r"W = \tfrac{1}{2} k x^2", "W = 1/2*k*x**2")],
        "b": [("The area under the force is a triangle of base $x$ and height $k x$:",
               r"2 W = k x^2", "2*W = k*x**2")],
        "extra": ((r"k x = F", "k*x = F"),
                  [("With the largest force $F$:", r"W = \tfrac{1}{2} F x", "W = 1/2*F*x")]),
        "short": [("Check the antiderivative:",
                   r"\frac{\mathrm{d}}{\mathrm{d}s} \Bigl( \tfrac{1}{2} k s^2 \Bigr) = k s",
                   "Derivative(1/2*k*s**2, s) = k*s")],
    },
    {
        "name": "bounce-height",
        "title": "How high a ball bounces",
        "text": "A ball falls from $h$ and hits the floor at speed $v$; it leaves at $v' = e v$ "
                "and rises to $h'$. Show that $h' = e^2 h$.",
        "facts": [("assume: g, h, v > 0, 0 < e \\le 1", "g > 0, h > 0, v > 0, 0 < e <= 1")],
        "premises": [(r"v^2 = 2 g h", "v**2 = 2*g*h"), (r"v' = e v", "vp = e*v"),
                     (r"v'^2 = 2 g h'", "vp**2 = 2*g*hp")],
        "target": (r"h' = e^2 h", "hp = e**2*h"),
        "a": [("Square the law of restitution and use the two energies:",
               r"2 g h' = 2 e^2 g h", "2*g*hp = 2*e**2*g*h"),
              ("Divide by $2 g$:", r"h' = e^2 h", "hp = e**2*h")],
        "b": [("The ratio of the heights is the ratio of the squared speeds, $e^2 v^2 / v^2$:",
               r"\frac{h'}{h} = \frac{e^2 v^2}{v^2}", "hp/h = e**2*v**2/v**2"),
              ("Cancel $v^2 > 0$:", r"\frac{h'}{h} = e^2", "hp/h = e**2")],
        "extra": ((r"e = \tfrac{1}{2}", "e = 1/2"),
                  [("For a ball that keeps half its speed:", r"h' = \frac{h}{4}", "hp = h/4")]),
        "short": [("Square the law of restitution:", r"v'^2 = e^2 v^2", "vp**2 = e**2*v**2")],
    },
]


class Writer:
    def __init__(self):
        self.lines = []

    def add(self, text=""):
        self.lines.extend(text.split("\n"))

    def display(self, latex, sympy):
        self.add("$$%s$$" % latex)
        line = len(self.lines)
        self.add("<!-- sympy: %s -->" % sympy)
        self.add()
        return line

    def text(self):
        return "\n".join(self.lines).rstrip("\n") + "\n"


def header(w, p, title):
    w.add("# %s" % title)
    w.add()
    w.add(p["text"])
    w.add()
    for latex, sympy in p["facts"]:
        w.add(latex)
        w.add("<!-- sympy: %s -->" % sympy)
    w.add()


def premises(w, p, extra=None):
    w.add("given:")
    w.add()
    rows = list(p["premises"]) + ([extra] if extra else [])
    start = len(w.lines) + 1
    w.add("$$" + " \\\\\n".join(latex for latex, _ in rows) + "$$")
    w.add("<!-- sympy:\n%s\n-->" % "\n".join(sympy for _, sympy in rows))
    w.add()
    return list(range(start, start + len(rows)))


def steps(w, seq):
    lines = []
    for prose, latex, sympy in seq:
        if prose:
            w.add(prose)
            w.add()
        lines.append(w.display(latex, sympy))
    return lines


def write_problem(p):
    files = {}
    rows = []
    w = Writer()
    header(w, p, "Task: " + p["title"])
    premises(w, p)
    w.add("target:")
    w.add()
    w.display(*p["target"])
    files["task.md"] = w.text()
    for key, name in (("a", "correct-a.md"), ("b", "correct-b.md")):
        w = Writer()
        header(w, p, p["title"] + " (a correct submission)")
        premises(w, p)
        lines = steps(w, p[key])
        files[name] = w.text()
        rows.append((name, "true", str(lines[0]), "-", "reached"))
    # the target assumed: stated as a premise, then rewritten
    w = Writer()
    header(w, p, p["title"] + " (the target assumed)")
    w.add("given:")
    w.add()
    line = w.display(*p["target"])
    w.add("Which is what was to be shown:")
    w.add()
    w.display(*p["target"])
    files["assumes-target.md"] = w.text()
    rows.append(("assumes-target.md", "false", "-", str(line), "target-assumed"))
    # a premise the task does not give
    w = Writer()
    header(w, p, p["title"] + " (a premise the task does not give)")
    lines = premises(w, p, p["extra"][0])
    steps(w, p["extra"][1])
    files["extra-premise.md"] = w.text()
    rows.append(("extra-premise.md", "false", "-", str(lines[-1]), "extra-premise"))
    # stops short
    w = Writer()
    header(w, p, p["title"] + " (stops short)")
    premises(w, p)
    steps(w, p["short"])
    files["stops-short.md"] = w.text()
    rows.append(("stops-short.md", "false", "-", "-", "not-reached"))
    return files, rows


# ---- SymPy's confirmation ------------------------------------------------------------------------


def equivalent(space, eq_a, eq_b, seed):
    """Whether two equations are equivalent under the facts alone (each implies the other)."""
    rng = random.Random(seed)
    a = judge.Meaning(space, *eq_a)
    b = judge.Meaning(space, *eq_b)
    try:
        fw = judge.implies([a], space, b, [], rng)
        bw = judge.implies([b], space, a, [], rng)
    except judge.Undecided as err:
        return None, str(err)
    return fw[0] == "holds" and bw[0] == "holds", ""


def follows_from(space, premises, eq, seed):
    rng = random.Random(seed)
    ms = [judge.Meaning(space, *p) for p in premises]
    try:
        r = judge.implies(ms, space, judge.Meaning(space, *eq), [], rng)
    except judge.Undecided as err:
        return None
    return r[0] == "holds"


def confirm(folder, p, rows):
    problems = []
    task_eqs, _ = judge.read_file(os.path.join(folder, "task.md"))
    target = [e for e in task_eqs if e.target][0]
    given = [(e.lhs, e.rhs) for e in task_eqs if e.premise and not e.target]
    for name, reached, line, extra, why in rows:
        path = os.path.join(folder, name)
        eqs, _ = judge.read_file(path)
        first = None
        for k, e in enumerate(eqs):
            names = set(judge.identifiers(e.lhs + e.rhs + target.lhs + target.rhs))
            for g in given:
                names |= set(judge.identifiers(g[0] + g[1]))
            space = judge.Space(e.context, names)
            eq_ok, err = equivalent(space, (e.lhs, e.rhs), (target.lhs, target.rhs), 7 + k)
            if eq_ok is None:
                problems.append("%s:%d: SymPy cannot tell whether it is the target: %s"
                                % (name, e.line, err))
            if eq_ok and first is None and not e.premise:
                first = e.line
            if e.premise:
                fine = any(equivalent(space, (e.lhs, e.rhs), g, 11)[0] for g in given) or \
                    follows_from(space, given, (e.lhs, e.rhs), 13)
                is_target = eq_ok
                extra_here = str(e.line) == extra
                if why == "target-assumed" and extra_here and not is_target:
                    problems.append("%s:%d: the assumed premise is not the target" % (name,
                                                                                      e.line))
                if why == "extra-premise" and extra_here and fine:
                    problems.append("%s:%d: the extra premise follows from the task's" % (
                        name, e.line))
                if not extra_here and not fine:
                    problems.append("%s:%d: a premise the task does not give, not expected" % (
                        name, e.line))
            else:
                v = judge.decide(eqs, k, 100 + k)[0]
                if why == "reached" and v not in ("follows", "follows-one-way"):
                    problems.append("%s:%d: a step of a correct submission is %s" % (
                        name, e.line, v))
        want = None if line == "-" else int(line)
        if why in ("reached", "not-reached") and first != want:
            problems.append("%s: the target is first reached at line %s, expected %s" % (
                name, first, line))
    return problems


def main():
    check = "--check" in sys.argv
    manifest = "task\tfile\ttarget_reached\tline\textra_premises\treason\n"
    problems = []
    for p in PROBLEMS:
        folder = os.path.join(HERE, p["name"])
        os.makedirs(folder, exist_ok=True)
        files, rows = write_problem(p)
        for name, text in files.items():
            path = os.path.join(folder, name)
            with open(path + ".tmp", "w", encoding="utf-8") as f:
                f.write(text)
            os.replace(path + ".tmp", path)
        for r in rows:
            manifest += "%s\t%s\n" % (p["name"], "\t".join(r))
        if check:
            found = confirm(folder, p, rows)
            problems += ["%s/%s" % (p["name"], x) for x in found]
            sys.stderr.write("%s: %s\n" % (p["name"], "confirmed" if not found else
                                           "%d problems" % len(found)))
    path = os.path.join(HERE, "expect.tsv")
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(manifest)
    os.replace(path + ".tmp", path)
    for x in problems:
        sys.stderr.write(x + "\n")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
