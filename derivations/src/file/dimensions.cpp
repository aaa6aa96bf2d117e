// SPDX-License-Identifier: GPL-3.0-or-later
// The dimensions of a tree, from the units its symbols are declared with (`units:`): one method
// per kind of node. Where two terms of a sum disagree, the first such place is the issue.
#include <functional>

#include "file/meaning.hpp"

namespace impulse::derivations::file {

using GiNaC::ex;
using GiNaC::numeric;

Dimension operator+(const Dimension& a, const Dimension& b) {
  return {a.mass + b.mass, a.length + b.length, a.time + b.time};
}
Dimension operator-(const Dimension& a, const Dimension& b) {
  return {a.mass - b.mass, a.length - b.length, a.time - b.time};
}

namespace {

Dimension scaled(const Dimension& a, const numeric& k) {
  return {a.mass * k, a.length * k, a.time * k};
}
bool dimensionless(const Dimension& a) {
  return a.mass.is_zero() && a.length.is_zero() && a.time.is_zero();
}

}  // namespace

std::optional<Dimension> Symbols::symbol_dimension(const SymbolName& written) const {
  const SymbolName name = resolve(written);
  if (name.differential) {  // dX has the dimension of X
    SymbolName base = name;
    base.differential = false;
    return symbol_dimension(base);
  }
  if (const auto found = units_.find(name.latex()); found != units_.end()) {
    return found->second;
  }
  if (const auto found = defined_dimensions_.find(name.latex());
      found != defined_dimensions_.end()) {
    return found->second;
  }
  if (name.primes > 0) {
    return symbol_dimension(name.unprimed());
  }
  if (name.delta) {
    SymbolName base = name;
    base.delta = false;
    return symbol_dimension(base);
  }
  if (const auto parent = component_of(name)) {
    return symbol_dimension(parent->first);
  }
  if (name.base == "dt" && name.subscript.empty() && has_units()) {
    return Dimension{0, 0, 1};
  }
  return std::nullopt;
}

class DimensionWalk {
 public:
  explicit DimensionWalk(Symbols& symbols) : s_(symbols) {}

  Symbols::DimensionResult run(const Node& node) {
    Maybe d;
    if (node.kind == NodeKind::sum) {
      d = sum(node, true);
    } else if (!logarithm(node, 1)) {
      d = walk(node);
    } else {
      d = Dimension{};
    }
    return {issue_ ? std::nullopt : d, issue_, logarithms_, logarithm_at_};
  }

 private:
  using Maybe = std::optional<Dimension>;

  Maybe walk(const Node& n) {
    if (issue_) {
      return std::nullopt;
    }
    switch (n.kind) {
      case NodeKind::number:
        // Zero has every dimension: "… = 0" and "+ 0" agree with any term.
        if (n.text.find_first_not_of("0.") == std::string::npos) {
          return std::nullopt;
        }
        return Dimension{};
      case NodeKind::pi:
      case NodeKind::factorial:
        return Dimension{};
      case NodeKind::symbol:
        return s_.symbol_dimension(n.symbol);
      case NodeKind::sum:
        return sum(n, false);
      case NodeKind::product:
        return product(n);
      case NodeKind::call:
        return call(n);
      case NodeKind::sum_over:
      case NodeKind::product_over:
        return over_index(n);
      case NodeKind::integral:
        return integral(n);
      case NodeKind::derivative:
        return derivative(n);
      case NodeKind::bar:
      case NodeKind::norm:
      case NodeKind::abs:
        return walk(n.children[0]);
      case NodeKind::dots:
        return std::nullopt;
      case NodeKind::fraction:
        return combined(n.children[0], n.children[1], false);
      case NodeKind::det:
        return combined(n.children[0], n.children[1], true);
      case NodeKind::power:
        return power(n);
      case NodeKind::function:
        must_be_dimensionless(n.children[0], "the argument of \\" + n.text);
        return Dimension{};
      case NodeKind::root:
        return root(n);
      case NodeKind::vector:
        return vector(n);
    }
    return std::nullopt;
  }

  void must_be_dimensionless(const Node& child, const std::string& where) {
    const auto d = walk(child);
    if (d && !dimensionless(*d) && !issue_) {
      issue_ = DimensionIssue{child.offset, Dimension{}, *d,
                              where + " has dimension " + d->text() + ", expected 1"};
    }
  }

  // A term of a side that is a logarithm, or a number times one: ln X is ln(X / u) + ln u for
  // a unit u of X, so the logarithm of a quantity with a dimension is a number plus a constant
  // that the units choose; the constants of a side's logarithms are kept (their arguments'
  // dimensions, with signs and coefficients) for the equation to cancel (ln h_n - ln h_0 =
  // 2 n ln e), and the term counts as a number. Whether it is one: nothing recorded otherwise.
  bool logarithm(const Node& term, const numeric& sign) {
    numeric coefficient = sign;
    const Node* log = &term;
    const std::vector<std::pair<Node, char>> factors =
        term.kind == NodeKind::product ? s_.factors(term) : std::vector<std::pair<Node, char>>{};
    if (term.kind == NodeKind::product) {
      log = nullptr;
      for (const auto& [factor, op] : factors) {
        const ex k = factor.kind == NodeKind::number ? s_.meaning(factor).value.x : ex(0);
        if (op != '/' && factor.kind == NodeKind::function && factor.text == "ln" && !log) {
          log = &factor;
        } else if (GiNaC::is_a<numeric>(k) && !k.is_zero()) {
          coefficient = op == '/' ? coefficient / GiNaC::ex_to<numeric>(k)
                                  : coefficient * GiNaC::ex_to<numeric>(k);
        } else {
          return false;
        }
      }
    }
    if (log == nullptr || log->kind != NodeKind::function || log->text != "ln") {
      return false;
    }
    const auto d = walk(log->children[0]);
    if (issue_) {
      return true;
    }
    if (d && !dimensionless(*d)) {
      logarithms_ = logarithms_ + scaled(*d, coefficient);
      if (!logarithm_at_) {
        logarithm_at_ = log->children[0].offset;
      }
    }
    return true;
  }

  Maybe sum(const Node& n, bool side) {
    Maybe known;
    std::size_t known_at = 0;
    for (std::size_t i = 0; i < n.children.size(); ++i) {
      const bool log = side && logarithm(n.children[i], n.ops[i] == '-' ? -1 : 1);
      const auto d = log ? Maybe(Dimension{}) : walk(n.children[i]);
      if (issue_) {
        return std::nullopt;
      }
      if (!d) {
        continue;
      }
      if (!known) {
        known = d;
        known_at = i;
      } else if (!(*known == *d)) {
        issue_ = DimensionIssue{n.children[i].offset, *known, *d,
                                "a term of dimension " + d->text() + " is added to one of " +
                                    known->text() + " (term " + std::to_string(known_at + 1) +
                                    " of the sum)"};
        return std::nullopt;
      }
    }
    return known;
  }

  Maybe product(const Node& n) {
    Maybe total = Dimension{};
    const auto factors = s_.factors(n);
    for (const auto& [factor, op] : factors) {
      const auto d = walk(factor);
      if (!d || !total) {
        total = std::nullopt;
        continue;
      }
      total = op == '/' ? *total - *d : *total + *d;
    }
    return total;
  }

  // F(t) of a declared function: F's units (resolved() made every other call a product).
  Maybe call(const Node& n) { return s_.symbol_dimension(n.children[0].symbol); }

  Maybe over_index(const Node& n) {
    if (n.ops.empty()) {
      const auto range = s_.indices_.find(n.text);
      if (range == s_.indices_.end() || range->second.empty()) {
        return std::nullopt;
      }
      return walk(with_index(n.children[0], n.text, range->second.front()));
    }
    const auto d = walk(n.children[0]);
    if (n.kind == NodeKind::product_over && d && !dimensionless(*d)) {
      return std::nullopt;  // a product of a number of terms the checker does not know
    }
    return d;
  }

  Maybe integral(const Node& n) {
    const auto d = walk(n.children[0]);
    if (n.ops.find('d') == std::string::npos) {
      return d;  // a 1-form: its differential carries the time
    }
    const auto variable = s_.symbol_dimension(n.symbol);
    if (!d || !variable) {
      return std::nullopt;
    }
    return *d + *variable;
  }

  Maybe derivative(const Node& n) {
    const auto d = walk(n.children[0]);
    const auto variable = s_.symbol_dimension(n.symbol);
    if (!d || !variable) {
      return std::nullopt;
    }
    return *d - scaled(*variable, numeric(std::stol(n.text)));
  }

  Maybe combined(const Node& a, const Node& b, bool times) {
    const auto first = walk(a);
    const auto second = walk(b);
    if (!first || !second) {
      return std::nullopt;
    }
    return times ? *first + *second : *first - *second;
  }

  Maybe power(const Node& n) {
    const auto base = walk(n.children[0]);
    must_be_dimensionless(n.children[1], "an exponent");
    if (!base) {
      return std::nullopt;
    }
    if (dimensionless(*base)) {
      return Dimension{};
    }
    const ex e = s_.meaning(n.children[1]).value.x;
    if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) {
      return scaled(*base, GiNaC::ex_to<numeric>(e));
    }
    if (!issue_) {
      issue_ = DimensionIssue{
          n.offset, Dimension{}, *base,
          "a quantity of dimension " + base->text() + " is raised to a power that is not a number"};
    }
    return std::nullopt;
  }

  Maybe root(const Node& n) {
    const auto d = walk(n.children[0]);
    if (!d) {
      return std::nullopt;
    }
    numeric index = 2;
    if (n.children.size() == 2) {
      const ex e = s_.meaning(n.children[1]).value.x;
      if (!GiNaC::is_a<numeric>(e) || GiNaC::ex_to<numeric>(e).is_zero()) {
        return std::nullopt;  // not a whole number: the meaning refuses it
      }
      index = GiNaC::ex_to<numeric>(e);
    }
    return scaled(*d, 1 / index);
  }

  Maybe vector(const Node& n) {
    const auto a = walk(n.children[0]);
    const auto b = walk(n.children[1]);
    if (a && b && !(*a == *b) && !issue_) {
      issue_ = DimensionIssue{
          n.children[1].offset, *a, *b,
          "the components of the vector have dimensions " + a->text() + " and " + b->text()};
      return std::nullopt;
    }
    return a ? a : b;
  }

  Symbols& s_;
  std::optional<DimensionIssue> issue_;
  Dimension logarithms_;                     // what the side's logarithms leave (see logarithm)
  std::optional<std::size_t> logarithm_at_;  // the argument of the first that leaves one
};

Symbols::DimensionResult Symbols::dimension(const Node& node) {
  return DimensionWalk(*this).run(resolved(node));
}

}  // namespace impulse::derivations::file
