// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/sample.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "file/decide.hpp"
#include "numeric.hpp"
#include "symbolic.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::is_a;

namespace {

ex scale_of(const ex& e) {
  // The size of the terms that cancel when e is evaluated in floating point: sums add the sizes
  // of their terms, products and whole powers multiply them, so that (F + dt) m at F = -dt is
  // measured against |F| + |dt|, not against its own rounding.
  if (is_a<GiNaC::add>(e)) {
    ex sum = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      sum += scale_of(e.op(i));
    }
    return sum;
  }
  if (is_a<GiNaC::mul>(e)) {
    ex product = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      product *= scale_of(e.op(i));
    }
    return product;
  }
  if (is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::posint)) {
    return GiNaC::pow(scale_of(e.op(0)), e.op(1));
  }
  return GiNaC::abs(e);
}

}  // namespace

ex term_scale(const ex& e) {
  if (e.nops() == 0) {
    return GiNaC::abs(e);  // a symbol or a number
  }
  // Remembered: the model evaluator asks for the sizes of the same statements' terms for each
  // model a check names and in each of its variants.
  thread_local sym::Remembered<ex> sizes;
  if (const ex* found = sizes.find(e)) {
    return *found;
  }
  return sizes.keep(e, scale_of(e));
}

namespace {

// One equation to be solved for one of its symbols.
struct Unknown {
  std::size_t premise;  // index into the equations
  std::size_t symbol;   // index into the symbol list
  // When the equation's numerator is a polynomial of degree ≤ 4 in the symbol: its
  // coefficients, lowest first, compiled as functions of all the symbols.
  std::vector<sym::Compiled> coefficients;
};

}  // namespace

struct Solver::State {
  State(const std::vector<ex>& equations, const std::vector<ex>& symbols, const Facts& facts,
        num::Random& random)
      : equations_(equations), symbols_(symbols), facts_(facts), random_(random) {
    for (const ex& e : equations_) {
      premises_.push_back(sym::compile(e, symbols_));
    }
  }

  bool solve() {
    if (unknowns_.empty()) {
      return true;
    }
    if (unknowns_.size() == 1) {
      return solve_one(unknowns_[0]);
    }
    return solve_many();
  }

  // Real roots of one premise in its unknown; one is taken at random.
  bool solve_one(const Unknown& u) {
    std::vector<double> roots;
    if (!u.coefficients.empty()) {
      std::vector<double> c;
      for (const sym::Compiled& k : u.coefficients) {
        c.push_back(k(values_));
      }
      while (c.size() > 1 && c.back() == 0.0) {
        c.pop_back();
      }
      if (c.size() == 2) {
        roots.push_back(-c[0] / c[1]);
      } else if (c.size() == 3) {
        double r0 = 0, r1 = 0;
        const int n = gsl_poly_solve_quadratic(c[2], c[1], c[0], &r0, &r1);
        if (n > 0) {
          roots.push_back(r0);
        }
        if (n > 1) {
          roots.push_back(r1);
        }
      } else if (c.size() > 3) {
        std::vector<double> z(2 * (c.size() - 1));
        std::unique_ptr<gsl_poly_complex_workspace, void (*)(gsl_poly_complex_workspace*)> w(
            gsl_poly_complex_workspace_alloc(c.size()), gsl_poly_complex_workspace_free);
        if (w && gsl_poly_complex_solve(c.data(), c.size(), w.get(), z.data()) == GSL_SUCCESS) {
          for (std::size_t i = 0; i + 1 < z.size(); i += 2) {
            if (std::abs(z[i + 1]) <= 1e-10 * std::max(1.0, std::abs(z[i]))) {
              roots.push_back(z[i]);
            }
          }
        }
      }
    } else {
      roots = bracketed_roots(u);
    }
    std::vector<double> usable;
    for (const double r : roots) {
      if (std::isfinite(r) && facts_.satisfied(symbols_[u.symbol], GiNaC::numeric(r))) {
        usable.push_back(r);
      }
    }
    if (usable.empty()) {
      return false;
    }
    values_[u.symbol] =
        usable[static_cast<std::size_t>(random_.integer(0, static_cast<int>(usable.size()) - 1))];
    return true;
  }

  // Sign changes of the premise along its unknown, refined by Brent's method.
  std::vector<double> bracketed_roots(const Unknown& u) {
    const auto f = [&](double x) {
      values_[u.symbol] = x;
      return premises_[u.premise](values_);
    };
    std::vector<double> roots;
    double previous_x = -50.0;
    double previous = f(previous_x);
    for (int k = 1; k <= 400; ++k) {
      const double x = -50.0 + 100.0 * k / 400.0;
      const double y = f(x);
      if (std::isfinite(previous) && std::isfinite(y) && previous * y < 0) {
        roots.push_back(brent(f, previous_x, x));
      }
      previous_x = x;
      previous = y;
    }
    return roots;
  }

  static double brent(const std::function<double(double)>& f, double low, double high) {
    gsl_function g;
    g.function = [](double x, void* p) {
      return (*static_cast<const std::function<double(double)>*>(p))(x);
    };
    g.params = const_cast<std::function<double(double)>*>(&f);
    std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> s(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
    if (!s || gsl_root_fsolver_set(s.get(), &g, low, high) != GSL_SUCCESS) {
      return std::nan("");
    }
    for (int i = 0; i < 200; ++i) {
      if (gsl_root_fsolver_iterate(s.get()) != GSL_SUCCESS) {
        break;
      }
      const double a = gsl_root_fsolver_x_lower(s.get());
      const double b = gsl_root_fsolver_x_upper(s.get());
      if (gsl_root_test_interval(a, b, 0.0, 1e-15) == GSL_SUCCESS) {
        break;
      }
    }
    return gsl_root_fsolver_root(s.get());
  }

  // Several premises at once: Powell's hybrid method with the exact Jacobian.
  bool solve_many() {
    if (jacobian_.empty()) {
      for (const Unknown& u : unknowns_) {
        std::vector<sym::Compiled> row;
        for (const Unknown& v : unknowns_) {
          row.push_back(sym::compile(
              equations_[u.premise].diff(GiNaC::ex_to<GiNaC::symbol>(symbols_[v.symbol])),
              symbols_));
        }
        jacobian_.push_back(std::move(row));
      }
    }
    const std::size_t n = unknowns_.size();
    gsl_multiroot_function_fdf system;
    system.n = n;
    system.params = this;
    system.f = [](const gsl_vector* x, void* p, gsl_vector* f) -> int {
      auto* self = static_cast<Solver::State*>(p);
      self->set(x);
      for (std::size_t i = 0; i < self->unknowns_.size(); ++i) {
        gsl_vector_set(f, i, self->premises_[self->unknowns_[i].premise](self->values_));
      }
      return GSL_SUCCESS;
    };
    system.df = [](const gsl_vector* x, void* p, gsl_matrix* j) -> int {
      auto* self = static_cast<Solver::State*>(p);
      self->set(x);
      for (std::size_t r = 0; r < self->unknowns_.size(); ++r) {
        for (std::size_t c = 0; c < self->unknowns_.size(); ++c) {
          gsl_matrix_set(j, r, c, self->jacobian_[r][c](self->values_));
        }
      }
      return GSL_SUCCESS;
    };
    system.fdf = [](const gsl_vector* x, void* p, gsl_vector* f, gsl_matrix* j) -> int {
      auto* self = static_cast<Solver::State*>(p);
      self->set(x);
      for (std::size_t r = 0; r < self->unknowns_.size(); ++r) {
        gsl_vector_set(f, r, self->premises_[self->unknowns_[r].premise](self->values_));
        for (std::size_t c = 0; c < self->unknowns_.size(); ++c) {
          gsl_matrix_set(j, r, c, self->jacobian_[r][c](self->values_));
        }
      }
      return GSL_SUCCESS;
    };
    std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> start(gsl_vector_alloc(n), gsl_vector_free);
    for (std::size_t i = 0; i < n; ++i) {
      gsl_vector_set(start.get(), i, values_[unknowns_[i].symbol]);
    }
    std::unique_ptr<gsl_multiroot_fdfsolver, void (*)(gsl_multiroot_fdfsolver*)> solver(
        gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, n),
        gsl_multiroot_fdfsolver_free);
    if (!solver || gsl_multiroot_fdfsolver_set(solver.get(), &system, start.get()) != GSL_SUCCESS) {
      return false;
    }
    for (int i = 0; i < 100; ++i) {
      if (gsl_multiroot_fdfsolver_iterate(solver.get()) != GSL_SUCCESS) {
        break;
      }
      if (gsl_multiroot_test_residual(solver.get()->f, 1e-13) == GSL_SUCCESS) {
        break;
      }
    }
    set(solver.get()->x);
    for (const Unknown& u : unknowns_) {
      if (!facts_.satisfied(symbols_[u.symbol], GiNaC::numeric(values_[u.symbol]))) {
        return false;
      }
    }
    return true;
  }

  void set(const gsl_vector* x) {
    for (std::size_t i = 0; i < unknowns_.size(); ++i) {
      values_[unknowns_[i].symbol] = gsl_vector_get(x, i);
    }
  }

  std::vector<ex> equations_;
  std::vector<ex> symbols_;
  const Facts& facts_;
  num::Random& random_;
  std::vector<sym::Compiled> premises_;
  std::vector<Unknown> unknowns_;
  std::vector<std::vector<sym::Compiled>> jacobian_;
  std::vector<double> values_;
};

Solver::Solver(const std::vector<ex>& equations, const std::vector<ex>& unknowns,
               const std::vector<ex>& symbols, const Facts& facts, num::Random& random)
    : state_(std::make_unique<State>(equations, symbols, facts, random)) {
  for (std::size_t i = 0; i < equations.size(); ++i) {
    const auto at = std::find_if(symbols.begin(), symbols.end(),
                                 [&](const ex& s) { return s.is_equal(unknowns[i]); });
    const auto k = static_cast<std::size_t>(at - symbols.begin());
    Unknown u{i, k, {}};
    const ex numerator = safe_numerator(equations[i]);
    const ex& s = unknowns[i];
    if (numerator.is_polynomial(s) && numerator.degree(s) <= 4 && numerator.degree(s) >= 1) {
      for (int d = 0; d <= numerator.degree(s); ++d) {
        u.coefficients.push_back(sym::compile(numerator.coeff(s, d), symbols));
      }
    }
    state_->unknowns_.push_back(std::move(u));
  }
}

Solver::~Solver() = default;
Solver::Solver(Solver&&) noexcept = default;
Solver& Solver::operator=(Solver&&) noexcept = default;

bool Solver::solve(std::vector<double>& values) {
  state_->values_ = values;
  const bool solved = state_->solve();
  values = state_->values_;
  return solved;
}

namespace {
class Sampler {
 public:
  Sampler(const NumericProblem& problem, const Facts& facts, std::uint64_t seed)
      : problem_(problem), facts_(facts), random_(seed) {
    std::vector<ex> all{problem.target, problem.target_scale};
    all.insert(all.end(), problem.premises.begin(), problem.premises.end());
    all.insert(all.end(), problem.denominators.begin(), problem.denominators.end());
    symbols_ = symbols_of(all);
    // The symbols of facts that share one with these (b of a < b < c) are drawn too, so that a
    // point satisfies those facts whole: a = 1, c = -1 passed for a counterexample of d = c - a
    // from d = |a - c|.
    const auto known = [&](const ex& x) {
      return std::any_of(symbols_.begin(), symbols_.end(),
                         [&](const ex& y) { return y.is_equal(x); });
    };
    for (bool grew = true; grew;) {
      grew = false;
      for (const auto& relation : facts.relations()) {
        const std::vector<ex> in = symbols_of(relation.first);
        if (std::any_of(in.begin(), in.end(), known)) {
          for (const ex& x : in) {
            if (!known(x)) {
              symbols_.push_back(x);
              grew = true;
            }
          }
        }
      }
    }
    values_.assign(symbols_.size(), 0.0);
    for (const ex& x : symbols_) {
      ranges_.push_back(range_of(x));
    }
  }

  NumericOpinion run(std::size_t wanted, WorkClock::time_point deadline) {
    NumericOpinion opinion;
    try {
      compile_all();
    } catch (const std::exception& e) {
      opinion.how =
          std::string("the expressions cannot be evaluated numerically (") + e.what() + ")";
      return opinion;
    }
    if (!choose_unknowns()) {
      opinion.how = "no symbol could be chosen to solve each equation before for";
      return opinion;
    }
    const std::size_t attempts = 6 * wanted + 20;
    bool stopped = false;
    for (std::size_t attempt = 0; attempt < attempts && opinion.points < wanted; ++attempt) {
      if (past(deadline)) {
        stopped = true;
        break;
      }
      draw();
      if (!solver_->solve(values_)) {
        continue;
      }
      const Validity validity = valid();
      const double value = validity == Validity::valid ? target_(values_) : 0.0;
      if (validity == Validity::step_not_real || std::isnan(value)) {
        ++opinion.not_real;
        if (!opinion.not_real_point) {
          opinion.not_real_point = here();
        }
        continue;
      }
      if (validity != Validity::valid) {
        continue;
      }
      const double residual = target_residual(value);
      if (!std::isfinite(residual)) {
        continue;
      }
      ++opinion.points;
      opinion.worst = std::max(opinion.worst, residual);
      if (residual > numeric_fails_above && !opinion.counterexample) {
        opinion.counterexample = here();
        opinion.counterexample_residual = residual;
      }
    }
    opinion.how =
        std::to_string(opinion.points) + " random points" +
        (problem_.premises.empty()
             ? ""
             : std::string(" on the equations before (each solved for ") + solved_names() + ")");
    if (opinion.points == 0) {
      opinion.how = "no point satisfying the equations before and the facts was found in " +
                    std::to_string(attempts) + " attempts";
    }
    if (stopped) {
      opinion.how += " (stopped at the step's time limit)";
    }
    return opinion;
  }

 private:
  // The point drawn and solved: every symbol's value.
  [[nodiscard]] std::vector<std::pair<ex, double>> here() const {
    std::vector<std::pair<ex, double>> point;
    for (std::size_t i = 0; i < symbols_.size(); ++i) {
      point.emplace_back(symbols_[i], values_[i]);
    }
    return point;
  }

  void compile_all() {
    for (const ex& p : problem_.premises) {
      premises_.push_back(sym::compile(p, symbols_));
    }
    for (const ex& s : problem_.premise_scales) {
      premise_scales_.push_back(sym::compile(s, symbols_));
    }
    for (const ex& d : problem_.denominators) {
      denominators_.push_back(sym::compile(d, symbols_));
    }
    target_ = sym::compile(problem_.target, symbols_);
    target_scale_ = sym::compile(problem_.target_scale, symbols_);
    try {
      for (const ex& s : symbols_) {
        if (GiNaC::is_a<GiNaC::symbol>(s)) {
          gradient_.push_back(
              sym::compile(problem_.target.diff(GiNaC::ex_to<GiNaC::symbol>(s)), symbols_));
        }
      }
    } catch (const std::exception&) {
      gradient_.clear();  // the step's size alone then
    }
  }

  std::size_t index_of(const ex& s) const {
    for (std::size_t i = 0; i < symbols_.size(); ++i) {
      if (symbols_[i].is_equal(s)) {
        return i;
      }
    }
    return symbols_.size();
  }

  // One distinct symbol per premise: preferably one without a sign fact (its value is then
  // free to come out as it must), of low degree, in few other premises.
  bool choose_unknowns() {
    std::vector<bool> taken(symbols_.size(), false);
    for (std::size_t i = 0; i < problem_.premises.size(); ++i) {
      const ex numerator = safe_numerator(problem_.premises[i]);
      double best_score = -1e9;
      std::optional<std::size_t> best;
      for (const ex& s : symbols_of(problem_.premises[i])) {
        const std::size_t k = index_of(s);
        if (taken[k]) {
          continue;
        }
        double score = facts_.of_symbol(s) == Sign::unknown ? 10 : 0;
        if (numerator.is_polynomial(s)) {
          score += 8 - 2.0 * std::min(numerator.degree(s), 4);
        }
        for (std::size_t j = 0; j < problem_.premises.size(); ++j) {
          score -= j != i && problem_.premises[j].has(s) ? 1 : 0;
        }
        if (score > best_score) {
          best_score = score;
          best = k;
        }
      }
      if (!best) {
        return false;
      }
      taken[*best] = true;
      unknowns_.push_back(*best);
    }
    std::vector<ex> unknown_symbols;
    for (const std::size_t k : unknowns_) {
      unknown_symbols.push_back(symbols_[k]);
    }
    solver_.emplace(problem_.premises, unknown_symbols, symbols_, facts_, random_);
    return true;
  }

  std::string solved_names() const {
    std::string names;
    for (const std::size_t k : unknowns_) {
      names += (names.empty() ? "" : ", ") + GiNaC::ex_to<GiNaC::symbol>(symbols_[k]).get_name();
    }
    return names;
  }

  // A symbol with both ends of a range (0 ≤ e ≤ 1, 0 < θ < π/2; an end from its sign too): half
  // its values spread evenly over the range, and one in eight at each closed end itself
  // (arcsin(sin θ) = θ fails only past π/2, on θ ≤ 1.571); the other values by its sign, as every
  // other symbol's.
  double draw_value(std::size_t i) {
    const Range& range = ranges_[i];
    if (range.low < range.high && random_.coin()) {
      const int end = random_.integer(0, 3);
      if (end == 0 && !range.low_open) {
        return range.low;
      }
      if (end == 1 && !range.high_open) {
        return range.high;
      }
      return random_.uniform(range.low, range.high);
    }
    return draw_with_sign(random_, facts_.of_symbol(symbols_[i]));
  }

  void draw() {
    for (std::size_t i = 0; i < symbols_.size(); ++i) {
      values_[i] = draw_value(i);
    }
  }

  // Whether the point satisfies the facts and every premise to rounding, with every denominator
  // clear of zero: valid; a point that does, but where one of the step's denominators is not
  // real (√(sin θ) at sin θ < 0), is one where the step has no real value.
  enum class Validity { invalid, valid, step_not_real };

  Validity valid() {
    for (double v : values_) {
      if (!std::isfinite(v)) {
        return Validity::invalid;
      }
    }
    if (!facts_.satisfied_numerically(symbols_, values_)) {
      return Validity::invalid;  // a fact on an expression (m_1 + m_2 > 0, e \leq 1)
    }
    for (std::size_t i = 0; i < premises_.size(); ++i) {
      const double value = premises_[i](values_);
      const double scale = premise_scales_[i](values_);
      if (!std::isfinite(value) || std::abs(value) > 1e-10 * std::max(scale, 1e-300)) {
        return Validity::invalid;
      }
    }
    bool step_real = true;
    for (std::size_t k = 0; k < denominators_.size(); ++k) {
      const double value = denominators_[k](values_);
      if (std::isnan(value) && k >= problem_.premise_denominators) {
        step_real = false;
      } else if (!std::isfinite(value) || std::abs(value) < 1e-9) {
        return Validity::invalid;
      }
    }
    return step_real ? Validity::valid : Validity::step_not_real;
  }

  // The step's value against the size of its terms and against what a change of its symbols
  // moves it by: each symbol's rate of change times its value, or times 1e-3 (of the drawn
  // values' 0.2 to 5) where it is near zero. Against its terms alone, v_1 v_2 = 0 at a point
  // solved to v_1 = 1e-17 (the premises allow v_1 = 0 exactly) was relative 1, a failure where
  // the step holds.
  double target_residual(double value) {
    if (value == 0.0) {
      return 0.0;
    }
    double scale = target_scale_(values_);
    if (gradient_.size() == values_.size()) {
      for (std::size_t i = 0; i < values_.size(); ++i) {
        const double r = std::abs(gradient_[i](values_)) * std::max(std::abs(values_[i]), 1e-3);
        scale += std::isfinite(r) ? r : 0.0;
      }
    }
    return std::abs(value) / std::max(scale, 1e-300);
  }

  // A symbol's ends as the facts give them (Facts::exact_ends), as doubles; low = high = 0 when
  // it has not both.
  struct Range {
    double low = 0.0;
    double high = 0.0;
    bool low_open = true;
    bool high_open = true;
  };
  [[nodiscard]] Range range_of(const ex& symbol) const {
    const auto [low, high] = facts_.exact_ends(symbol);
    if (!low || !high) {
      return {};
    }
    const std::optional<GiNaC::numeric> a = value_in_40_digits(low->at);
    const std::optional<GiNaC::numeric> b = value_in_40_digits(high->at);
    if (!a || !b || !a->is_real() || !b->is_real()) {
      return {};
    }
    return {a->to_double(), b->to_double(), low->strict, high->strict};
  }

  const NumericProblem& problem_;
  const Facts& facts_;
  num::Random random_;
  std::vector<ex> symbols_;
  std::vector<double> values_;
  std::vector<Range> ranges_;  // of each symbol
  std::vector<sym::Compiled> premises_;
  std::vector<sym::Compiled> premise_scales_;
  std::vector<sym::Compiled> denominators_;
  sym::Compiled target_;
  sym::Compiled target_scale_;
  std::vector<sym::Compiled> gradient_;  // the step's rate of change in each symbol
  std::vector<std::size_t> unknowns_;
  std::optional<Solver> solver_;
};

}  // namespace

NumericOpinion sample(const NumericProblem& problem, const Facts& facts, std::uint64_t seed,
                      std::size_t points, WorkClock::time_point deadline) {
  num::quiet_gsl();
  Sampler sampler(problem, facts, seed);
  return sampler.run(points, deadline);
}

double draw_with_sign(num::Random& random, Sign sign) {
  const double magnitude = random.log_uniform(0.2, 5.0);
  switch (sign) {
    case Sign::positive:
    case Sign::nonnegative:
      return magnitude;
    case Sign::negative:
    case Sign::nonpositive:
      return -magnitude;
    default:
      return random.coin() ? magnitude : -magnitude;
  }
}

}  // namespace impulse::derivations::file
