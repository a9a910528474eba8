// SPDX-License-Identifier: BSL-1.0
// odestep: every table against the Runge-Kutta order conditions, one per rooted tree (Butcher 1963).
//
// The trees are generated, not written out: canonical level sequences (Beyer & Hedetniemi 1980, "Constant time
// generation of rooted trees", SIAM J. Comput. 9, 706-712), every order from 1 to 9 (order 9 only for the
// "next order fails" check of the eighth-order tables). For a tree t with elementary weight Phi(t) and density
// gamma(t) a weight vector w has order p iff sum_i w_i Phi_i(t) = 1 / gamma(t) for every t with |t| <= p.
// Everything is iterative and in fixed-size arrays on the stack: this file also runs on bare-metal targets.
#include <doctest/doctest.h>

#include <odestep/tables/adams.hpp>
#include <odestep/tables/implicit_rk.hpp>
#include <odestep/tables/runge_kutta.hpp>
#include <odestep/tables/splitting.hpp>

#include <array>
#include <cfloat>
#include <cstddef>
#include <type_traits>

namespace {

using real = long double;
namespace tab = odestep::tableaux;

constexpr std::size_t max_nodes = 9;

real magnitude(real x) { return x < real(0) ? -x : x; }

// One rooted tree as a level sequence: node 0 is the root at level 0, the nodes follow in depth-first preorder,
// and a node's parent is the nearest earlier node one level up. Canonical means the subtrees of every node are in
// non-increasing lexicographic order, so each unlabelled tree has exactly one sequence. The trees of one order are
// walked in decreasing lexicographic order, from the tall tree (0, 1, ..., n-1) to the bush (0, 1, 1, ..., 1).
class tree_walker {
public:
    explicit tree_walker(std::size_t order) : nodes_(order < max_nodes ? order : max_nodes) {
        for (std::size_t i = 0; i < max_nodes; ++i) level_[i] = i;
    }

    std::size_t nodes() const { return nodes_; }

    /// One past the last node of the subtree rooted at `node`.
    std::size_t subtree_end(std::size_t node) const {
        std::size_t end = node + 1;
        while (end < nodes_ && level_[end] > level_[node]) ++end;
        return end;
    }

    /// Beyer-Hedetniemi successor: take the last node p that is not a child of the root, find its parent q, and
    /// refill everything from p on by repeating the pattern that starts at q. False once the bush is reached.
    bool next() {
        std::size_t p = 0;
        for (std::size_t i = nodes_; i-- > 1;) {
            if (level_[i] > 1) {
                p = i;
                break;
            }
        }
        if (p == 0) return false;
        std::size_t q = p - 1;
        while (level_[q] + 1 != level_[p]) --q;
        const std::size_t shift = p - q;
        for (std::size_t i = p; i < nodes_; ++i) level_[i] = level_[i - shift];
        return true;
    }

    /// gamma(t): the product over all nodes of the size of the subtree they root.
    unsigned long density() const {
        unsigned long gamma = 1;
        for (std::size_t v = 0; v < nodes_; ++v) gamma *= static_cast<unsigned long>(subtree_end(v) - v);
        return gamma;
    }

    /// Every node's subtrees come in non-increasing lexicographic order (the canonical form).
    bool canonical() const {
        for (std::size_t v = 0; v < nodes_; ++v) {
            const std::size_t end = subtree_end(v);
            std::size_t first = v + 1;
            if (first >= end) continue;
            for (std::size_t second = subtree_end(first); second < end; second = subtree_end(second)) {
                if (compare(first, second) < 0) return false;
                first = second;
            }
        }
        return true;
    }

    /// Lexicographic order of the whole sequence, for checking that the walk is strictly decreasing.
    int compare_to(const tree_walker& other) const {
        for (std::size_t i = 0; i < nodes_ && i < other.nodes_; ++i) {
            if (level_[i] != other.level_[i]) return level_[i] < other.level_[i] ? -1 : 1;
        }
        return nodes_ == other.nodes_ ? 0 : (nodes_ < other.nodes_ ? -1 : 1);
    }

private:
    // Lexicographic comparison of the subtrees rooted at sibling nodes x and y (a proper prefix is smaller).
    int compare(std::size_t x, std::size_t y) const {
        const std::size_t x_end = subtree_end(x);
        const std::size_t y_end = subtree_end(y);
        for (; x < x_end && y < y_end; ++x, ++y) {
            if (level_[x] != level_[y]) return level_[x] < level_[y] ? -1 : 1;
        }
        if (x == x_end && y == y_end) return 0;
        return x == x_end ? -1 : 1;
    }

    std::size_t nodes_;
    std::array<std::size_t, max_nodes> level_{};
};

/// Phi(t) (one value per stage) and the same weight built from |a_ij| and |c_i|, which is the size of the terms whose
/// rounding errors end up in Phi and so scales the tolerance. (Scaling by sum_i |w_i Phi_i| alone misses the
/// cancellation inside Phi: dop853 then shows residuals of 39 x LDBL_EPSILON with x86's 80-bit long double and 118 x
/// eps with a 64-bit one.) Computed leaves first: node v other than the root contributes u_v = A g_v to its parent,
/// where g_v is the product of its children's contributions; a leaf contributes c.
template <std::size_t S, std::size_t E>
void elementary_weight(const odestep::butcher_tableau<real, S, E>& tab, const tree_walker& tree,
                       std::array<real, S>& phi, std::array<real, S>& phi_size) {
    std::array<std::array<real, S>, max_nodes> u{};
    std::array<std::array<real, S>, max_nodes> u_size{};
    for (std::size_t v = tree.nodes(); v-- > 0;) {
        std::array<real, S> g{};
        std::array<real, S> g_size{};
        g.fill(real(1));
        g_size.fill(real(1));
        bool leaf = true;
        const std::size_t end = tree.subtree_end(v);
        for (std::size_t w = v + 1; w < end; w = tree.subtree_end(w)) {
            leaf = false;
            for (std::size_t i = 0; i < S; ++i) {
                g[i] *= u[w][i];
                g_size[i] *= u_size[w][i];
            }
        }
        if (v == 0) {
            phi = g;
            phi_size = g_size;
        } else if (leaf) {
            for (std::size_t i = 0; i < S; ++i) {
                u[v][i] = tab.c[i];
                u_size[v][i] = magnitude(tab.c[i]);
            }
        } else {
            for (std::size_t i = 0; i < S; ++i) {
                real sum = real(0);
                real size = real(0);
                for (std::size_t j = 0; j < S; ++j) {  // the whole row: implicit tables too
                    sum += tab.a[i][j] * g[j];
                    size += magnitude(tab.a[i][j]) * g_size[j];
                }
                u[v][i] = sum;
                u_size[v][i] = size;
            }
        }
    }
}

/// How well one weight vector meets the conditions of one order.
struct order_summary {
    std::size_t trees = 0;     // conditions checked
    std::size_t violated = 0;  // of those, the ones whose residual is above the round-off tolerance
    real worst_residual = 0;   // largest |sum_i w_i Phi_i(t) - 1/gamma(t)|
    real worst_ratio = 0;      // largest residual / (effective epsilon x magnitude of the terms)
};

// A condition holds when its residual is within `round_off_factor` effective epsilons of the magnitude of the
// terms, and is violated otherwise. The effective epsilon is LDBL_EPSILON, or the relative precision of the
// published digits when those are coarser than long double (IEEE quad long double on AArch64 or RISC-V against
// dop853.f's 28-30 digit decimals).
constexpr real round_off_factor = 32;
// "Violates a condition of the next order" must not be noise either: the worst violation has to exceed the
// round-off tolerance by this factor. (Measured on x86 80-bit long double, the smallest violation of any table
// is about 5e6 tolerances and the worst violations are 1e9 to 1e18 tolerances; with a 64-bit long double the
// ratios shrink by 2^11.)
constexpr real clear_violation_factor = 1.0e4L;

template <std::size_t S, std::size_t E>
order_summary check_order(const odestep::butcher_tableau<real, S, E>& tab, const std::array<real, S>& w,
                          std::size_t order, real data_precision) {
    const real eps = LDBL_EPSILON > data_precision ? real(LDBL_EPSILON) : data_precision;
    order_summary summary;
    tree_walker tree(order);
    do {
        std::array<real, S> phi{};
        std::array<real, S> phi_size{};
        elementary_weight(tab, tree, phi, phi_size);
        const real target = real(1) / static_cast<real>(tree.density());
        real sum = real(0);
        real size = target;
        for (std::size_t i = 0; i < S; ++i) {
            sum += w[i] * phi[i];
            size += magnitude(w[i]) * phi_size[i];
        }
        const real residual = magnitude(sum - target);
        const real ratio = residual / (eps * size);
        ++summary.trees;
        if (ratio > round_off_factor) ++summary.violated;
        if (residual > summary.worst_residual) summary.worst_residual = residual;
        if (ratio > summary.worst_ratio) summary.worst_ratio = ratio;
    } while (tree.next());
    return summary;
}

/// All conditions of orders 1..order together.
template <std::size_t S, std::size_t E>
order_summary check_up_to(const odestep::butcher_tableau<real, S, E>& tab, const std::array<real, S>& w,
                          std::size_t order, real data_precision) {
    order_summary total;
    for (std::size_t n = 1; n <= order; ++n) {
        const order_summary one = check_order(tab, w, n, data_precision);
        total.trees += one.trees;
        total.violated += one.violated;
        if (one.worst_residual > total.worst_residual) total.worst_residual = one.worst_residual;
        if (one.worst_ratio > total.worst_ratio) total.worst_ratio = one.worst_ratio;
    }
    return total;
}

// The relative precision of a table's published digits: 0 for exact rationals (long double rounding governs),
// the last published digit for decimal-only sources. dop853.f prints 28 to 30 significant digits (the ER
// coefficients have 28).
template <class Tag>
constexpr real published_precision = 0;
template <>
constexpr real published_precision<tab::dop853> = 1.0e-27L;

template <class... Tags>
struct table_list {};

// The explicit tables, then the implicit ones (their conditions read the whole of a; the irrational
// coefficients, sqrt 3, sqrt 6 and Alexander's gamma, are 40-digit literals, finer than any long double).
using all_tables = table_list<tab::euler, tab::midpoint, tab::heun, tab::ralston2, tab::kutta3, tab::ssprk3, tab::rk4,
                              tab::rk38, tab::bogacki_shampine32, tab::fehlberg45, tab::cash_karp54,
                              tab::dormand_prince54, tab::fehlberg78, tab::dop853, tab::backward_euler, tab::trapezoid,
                              tab::implicit_midpoint, tab::gauss4, tab::sdirk3, tab::radau_iia5, tab::sdirk4>;

template <class... Tags, class F>
void for_each_table(table_list<Tags...>, F&& f) {
    (f(Tags{}), ...);
}

std::size_t as_size(int order) { return static_cast<std::size_t>(order); }

// One line of the report: "<table>[, embedded vector e]: ...".
template <class Tag>
doctest::String vector_name(std::size_t e, bool embedded) {
    doctest::String text(Tag::name);
    if (embedded) text += doctest::toString(", embedded vector ") + doctest::toString(e);
    return text;
}

// Every weight vector of a table: b at `order`, then bhat[e] at `embedded_order[e]`.
template <class Tag, class F>
void for_each_weight_vector(F&& f) {
    const auto& t = Tag::template table<real>;
    f(t, t.b, as_size(t.order), vector_name<Tag>(0, false));
    for (std::size_t e = 0; e < t.embedded; ++e)
        f(t, t.bhat[e], as_size(t.embedded_order[e]), vector_name<Tag>(e, true));
}

std::size_t factorial(std::size_t n) {
    std::size_t f = 1;
    for (std::size_t k = 2; k <= n; ++k) f *= k;
    return f;
}

}  // namespace

TEST_CASE("trees: the walk yields 1, 1, 2, 4, 9, 20, 48, 115, 286 distinct canonical rooted trees of orders 1 to 9") {
    const std::array<std::size_t, max_nodes> expected{1, 1, 2, 4, 9, 20, 48, 115, 286};
    std::size_t cumulative = 0;
    for (std::size_t n = 1; n <= max_nodes; ++n) {
        INFO("order " << n);
        std::size_t count = 0;
        bool all_canonical = true;
        bool strictly_decreasing = true;  // so no tree comes twice
        bool densities_in_range = true;   // gamma lies between n (the bush) and n! (the tall tree)
        tree_walker tree(n);
        tree_walker previous(n);
        do {
            if (count > 0 && previous.compare_to(tree) <= 0) strictly_decreasing = false;
            if (!tree.canonical()) all_canonical = false;
            const unsigned long gamma = tree.density();
            if (gamma < n || gamma > factorial(n)) densities_in_range = false;
            previous = tree;
            ++count;
        } while (tree.next());
        CHECK(count == expected[n - 1]);
        CHECK(all_canonical);
        CHECK(strictly_decreasing);
        CHECK(densities_in_range);
        cumulative += count;
        if (n == 8) CHECK(cumulative == 200);  // the conditions of an eighth-order method
    }
    CHECK(cumulative == 486);
}

TEST_CASE("trees: the walk starts at the tall tree with density n! and ends at the bush with density n") {
    for (std::size_t n = 1; n <= max_nodes; ++n) {
        INFO("order " << n);
        tree_walker tree(n);
        CHECK(tree.density() == factorial(n));
        while (tree.next()) {
        }
        CHECK(tree.density() == n);
    }
}

TEST_CASE("tables: every table (and embedded vector) satisfies all rooted-tree conditions up to its order") {
    for_each_table(all_tables{}, [](auto tag) {
        using Tag = decltype(tag);
        for_each_weight_vector<Tag>([](const auto& t, const auto& w, std::size_t order, const doctest::String& name) {
            const order_summary s = check_up_to(t, w, order, published_precision<Tag>);
            MESSAGE(name << ": order " << order << ", " << s.trees << " conditions, largest residual "
                         << static_cast<double>(s.worst_residual) << " = " << static_cast<double>(s.worst_ratio)
                         << " x eps x magnitude");
            INFO(name);
            CHECK(s.violated == 0);
            CHECK(s.worst_ratio <= round_off_factor);
        });
    });
}

// No table satisfies all conditions of the next order, so every claimed order is the true order. Several meet part
// of the next order (the report counts the failures). Notably the seventh-order vector of fehlberg78 meets 75 of
// the 115 conditions of order 8, among them every quadrature (bushy-tree) condition: b - bhat is
// 41/840 (-1, 0, ..., 0, -1, 1, 1) on the nodes (0, ..., 1, 0, 1), which integrates every polynomial exactly.
TEST_CASE("tables: every weight vector violates at least one condition of the next order, so its order is exact") {
    for_each_table(all_tables{}, [](auto tag) {
        using Tag = decltype(tag);
        for_each_weight_vector<Tag>([](const auto& t, const auto& w, std::size_t order, const doctest::String& name) {
            const order_summary s = check_order(t, w, order + 1, published_precision<Tag>);
            MESSAGE(name << ": " << s.violated << " of " << s.trees << " conditions of order " << order + 1
                         << " fail, largest residual " << static_cast<double>(s.worst_residual));
            INFO(name);
            CHECK(s.violated >= 1);
            CHECK(s.worst_ratio > clear_violation_factor * round_off_factor);
        });
    });
}

TEST_CASE("tables: a single coefficient off by one part in a million breaks the conditions it enters") {
    odestep::butcher_tableau<real, 4> t = tab::rk4::table<real>;
    t.a[2][1] *= real(1) + real(1.0e-6L);  // c3 is left alone, so only the trees through a32 notice
    const order_summary s = check_up_to(t, t.b, 4, real(0));
    CHECK(s.violated >= 1);
    CHECK(s.worst_ratio > clear_violation_factor * round_off_factor);
}

// The deprecated namespace aliases (CHANGELOG, Deprecated; removed in 1.0.0) name the same tables until then.
// The project itself uses odestep::tables; these lines are the aliases' only use, to keep them working.
static_assert(std::is_same_v<odestep::tableaux::rk4, odestep::tables::rk4>);
static_assert(std::is_same_v<odestep::adams_tables::bashforth4, odestep::tables::bashforth4>);
static_assert(std::is_same_v<odestep::splittings::velocity_verlet, odestep::tables::velocity_verlet>);
