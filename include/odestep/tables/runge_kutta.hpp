// SPDX-License-Identifier: BSL-1.0
// odestep: the table library. Each method is a tag type whose `table<T>` is a constexpr Butcher table
// typed in T, so float code never touches a double coefficient. Coefficients are written as exact
// rationals T(p) / T(q) where the source gives them so; decimal-only sources use long double literals.
#ifndef ODESTEP_TABLES_RUNGE_KUTTA_HPP
#define ODESTEP_TABLES_RUNGE_KUTTA_HPP

#include "butcher.hpp"

#include <limits>

namespace odestep::tables {
// clang-format off  (the tables keep their published layout)

/// Classic fourth-order Runge-Kutta (Kutta 1901; Hairer, Norsett & Wanner, Solving ODE I, Table II.1.2).
struct rk4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "classic RK4";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 4> table{{{{}, {T(1) / T(2)}, {T(0), T(1) / T(2)}, {T(0), T(0), T(1)}}},
                                                 {T(1) / T(6), T(1) / T(3), T(1) / T(3), T(1) / T(6)},
                                                 {T(0), T(1) / T(2), T(1) / T(2), T(1)},
                                                 {},
                                                 4,
                                                 {}};
};

/// Forward Euler (Euler 1768, Institutiones Calculi Integralis; Hairer, Norsett & Wanner, Solving ODE I,
/// Sec. II.1). Order 1.
struct euler {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "forward Euler";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 1> table{{{{}}}, {T(1)}, {T(0)}, {}, 1, {}};
};

/// Explicit midpoint rule = Euler-Richardson (Runge 1895, Math. Ann. 46, 167-178; Hairer, Norsett & Wanner,
/// Solving ODE I, Sec. II.1). Order 2. The embedded vector is forward Euler (order 1), so the error
/// estimate is h (k2 - k1).
struct midpoint {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "explicit midpoint (Euler-Richardson) with Euler estimate";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 2, 1> table{
        {{{}, {T(1) / T(2)}}}, {T(0), T(1)}, {T(0), T(1) / T(2)}, {{{T(1), T(0)}}}, 2, {1}};
};

/// Heun's method = modified Euler / explicit trapezoidal rule (Heun 1900, Z. Math. Phys. 45, 23-38;
/// Hairer, Norsett & Wanner, Solving ODE I, Sec. II.1). Order 2.
struct heun {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Heun (explicit trapezoidal)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 2> table{{{{}, {T(1)}}}, {T(1) / T(2), T(1) / T(2)}, {T(0), T(1)}, {}, 2, {}};
};

/// Ralston's second-order method, the minimum error bound member of the two-stage family (Ralston 1962,
/// "Runge-Kutta methods with minimum error bounds", Math. Comp. 16, 431-437). Order 2.
struct ralston2 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Ralston 2";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 2> table{
        {{{}, {T(2) / T(3)}}}, {T(1) / T(4), T(3) / T(4)}, {T(0), T(2) / T(3)}, {}, 2, {}};
};

/// Kutta's third-order method (Kutta 1901, Z. Math. Phys. 46, 435-453; Hairer, Norsett & Wanner,
/// Solving ODE I, Sec. II.1). Order 3.
struct kutta3 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Kutta 3";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 3> table{{{{}, {T(1) / T(2)}, {T(-1), T(2)}}},
                                                 {T(1) / T(6), T(2) / T(3), T(1) / T(6)},
                                                 {T(0), T(1) / T(2), T(1)},
                                                 {},
                                                 3,
                                                 {}};
};

/// Strong-stability-preserving RK3 (Shu & Osher 1988, "Efficient implementation of essentially
/// non-oscillatory shock-capturing schemes", J. Comput. Phys. 77, 439-471; Butcher form in
/// Gottlieb & Shu 1998, Math. Comp. 67, 73-85). Order 3.
struct ssprk3 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "SSP RK3 (Shu-Osher)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 3> table{{{{}, {T(1)}, {T(1) / T(4), T(1) / T(4)}}},
                                                 {T(1) / T(6), T(1) / T(6), T(2) / T(3)},
                                                 {T(0), T(1), T(1) / T(2)},
                                                 {},
                                                 3,
                                                 {}};
};

/// Kutta's 3/8 rule (Kutta 1901, Z. Math. Phys. 46, 435-453; Hairer, Norsett & Wanner, Solving ODE I,
/// Table II.1.2). Order 4.
struct rk38 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Kutta 3/8 rule";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 4> table{{{{}, {T(1) / T(3)}, {T(-1) / T(3), T(1)}, {T(1), T(-1), T(1)}}},
                                                 {T(1) / T(8), T(3) / T(8), T(3) / T(8), T(1) / T(8)},
                                                 {T(0), T(1) / T(3), T(2) / T(3), T(1)},
                                                 {},
                                                 4,
                                                 {}};
};

/// Bogacki-Shampine 3(2) pair, FSAL (Bogacki & Shampine 1989, "A 3(2) pair of Runge-Kutta formulas",
/// Appl. Math. Lett. 2(4), 321-325). b: order 3 (b4 = 0, the last row of a); bhat: order 2.
struct bogacki_shampine32 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Bogacki-Shampine 3(2)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 4, 1> table{
        {{{}, {T(1) / T(2)}, {T(0), T(3) / T(4)}, {T(2) / T(9), T(1) / T(3), T(4) / T(9)}}},
        {T(2) / T(9), T(1) / T(3), T(4) / T(9), T(0)},
        {T(0), T(1) / T(2), T(3) / T(4), T(1)},
        {{{T(7) / T(24), T(1) / T(4), T(1) / T(3), T(1) / T(8)}}},
        3,
        {2}};
};

/// Runge-Kutta-Fehlberg 4(5) (Fehlberg 1969, "Low-order classical Runge-Kutta formulas with stepsize
/// control and their application to some heat transfer problems", NASA TR R-315; Hairer,
/// Norsett & Wanner, Solving ODE I, Sec. II.5). Stepped with the fifth-order weights (local extrapolation):
/// b: order 5; bhat: Fehlberg's fourth-order weights.
struct fehlberg45 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Runge-Kutta-Fehlberg 4(5)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 6, 1> table{
        {{{},
          {T(1) / T(4)},
          {T(3) / T(32), T(9) / T(32)},
          {T(1932) / T(2197), T(-7200) / T(2197), T(7296) / T(2197)},
          {T(439) / T(216), T(-8), T(3680) / T(513), T(-845) / T(4104)},
          {T(-8) / T(27), T(2), T(-3544) / T(2565), T(1859) / T(4104), T(-11) / T(40)}}},
        {T(16) / T(135), T(0), T(6656) / T(12825), T(28561) / T(56430), T(-9) / T(50), T(2) / T(55)},
        {T(0), T(1) / T(4), T(3) / T(8), T(12) / T(13), T(1), T(1) / T(2)},
        {{{T(25) / T(216), T(0), T(1408) / T(2565), T(2197) / T(4104), T(-1) / T(5), T(0)}}},
        5,
        {4}};
};

/// Cash-Karp 5(4) (Cash & Karp 1990, "A variable order Runge-Kutta method for initial value problems with
/// rapidly varying right-hand sides", ACM Trans. Math. Softw. 16(3), 201-222; also Press et al., Numerical
/// Recipes, 2nd ed., Sec. 16.2). b: fifth-order weights; bhat: fourth-order weights.
struct cash_karp54 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Cash-Karp 5(4)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 6, 1> table{
        {{{},
          {T(1) / T(5)},
          {T(3) / T(40), T(9) / T(40)},
          {T(3) / T(10), T(-9) / T(10), T(6) / T(5)},
          {T(-11) / T(54), T(5) / T(2), T(-70) / T(27), T(35) / T(27)},
          {T(1631) / T(55296), T(175) / T(512), T(575) / T(13824), T(44275) / T(110592), T(253) / T(4096)}}},
        {T(37) / T(378), T(0), T(250) / T(621), T(125) / T(594), T(0), T(512) / T(1771)},
        {T(0), T(1) / T(5), T(3) / T(10), T(3) / T(5), T(1), T(7) / T(8)},
        {{{T(2825) / T(27648), T(0), T(18575) / T(48384), T(13525) / T(55296), T(277) / T(14336), T(1) / T(4)}}},
        5,
        {4}};
};

/// Dormand-Prince 5(4), DOPRI5, FSAL (Dormand & Prince 1980, "A family of embedded Runge-Kutta formulae",
/// J. Comput. Appl. Math. 6(1), 19-26; Hairer, Norsett & Wanner, Solving ODE I, Sec. II.5). b: fifth-order
/// weights (b7 = 0; row 7 of a equals b); bhat: fourth-order weights.
struct dormand_prince54 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Dormand-Prince 5(4)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 7, 1> table{
        {{{},
          {T(1) / T(5)},
          {T(3) / T(40), T(9) / T(40)},
          {T(44) / T(45), T(-56) / T(15), T(32) / T(9)},
          {T(19372) / T(6561), T(-25360) / T(2187), T(64448) / T(6561), T(-212) / T(729)},
          {T(9017) / T(3168), T(-355) / T(33), T(46732) / T(5247), T(49) / T(176), T(-5103) / T(18656)},
          {T(35) / T(384), T(0), T(500) / T(1113), T(125) / T(192), T(-2187) / T(6784), T(11) / T(84)}}},
        {T(35) / T(384), T(0), T(500) / T(1113), T(125) / T(192), T(-2187) / T(6784), T(11) / T(84), T(0)},
        {T(0), T(1) / T(5), T(3) / T(10), T(4) / T(5), T(8) / T(9), T(1), T(1)},
        {{{T(5179) / T(57600), T(0), T(7571) / T(16695), T(393) / T(640), T(-92097) / T(339200), T(187) / T(2100),
           T(1) / T(40)}}},
        5,
        {4}};
};

/// Runge-Kutta-Fehlberg 7(8), 13 stages (Fehlberg 1968, "Classical fifth-, sixth-, seventh-, and
/// eighth-order Runge-Kutta formulas with stepsize control", NASA TR R-287, Table X). Stepped with the
/// eighth-order weights (Fehlberg's c-hat row, stages 1..13 with c-hat_1 = c-hat_11 = 0); bhat: the
/// seventh-order weights (Fehlberg's c row, stages 1..11). Note b - bhat = 41/840 (-1, 0,...,0, -1, 1, 1)
/// vanishes on quadrature problems y' = f(t), a known weakness of this error estimate.
struct fehlberg78 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Runge-Kutta-Fehlberg 7(8)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 13, 1> table{
        {{{},
          {T(2) / T(27)},
          {T(1) / T(36), T(1) / T(12)},
          {T(1) / T(24), T(0), T(1) / T(8)},
          {T(5) / T(12), T(0), T(-25) / T(16), T(25) / T(16)},
          {T(1) / T(20), T(0), T(0), T(1) / T(4), T(1) / T(5)},
          {T(-25) / T(108), T(0), T(0), T(125) / T(108), T(-65) / T(27), T(125) / T(54)},
          {T(31) / T(300), T(0), T(0), T(0), T(61) / T(225), T(-2) / T(9), T(13) / T(900)},
          {T(2), T(0), T(0), T(-53) / T(6), T(704) / T(45), T(-107) / T(9), T(67) / T(90), T(3)},
          {T(-91) / T(108), T(0), T(0), T(23) / T(108), T(-976) / T(135), T(311) / T(54), T(-19) / T(60), T(17) / T(6),
           T(-1) / T(12)},
          {T(2383) / T(4100), T(0), T(0), T(-341) / T(164), T(4496) / T(1025), T(-301) / T(82), T(2133) / T(4100),
           T(45) / T(82), T(45) / T(164), T(18) / T(41)},
          {T(3) / T(205), T(0), T(0), T(0), T(0), T(-6) / T(41), T(-3) / T(205), T(-3) / T(41), T(3) / T(41),
           T(6) / T(41), T(0)},
          {T(-1777) / T(4100), T(0), T(0), T(-341) / T(164), T(4496) / T(1025), T(-289) / T(82), T(2193) / T(4100),
           T(51) / T(82), T(33) / T(164), T(12) / T(41), T(0), T(1)}}},
        {T(0), T(0), T(0), T(0), T(0), T(34) / T(105), T(9) / T(35), T(9) / T(35), T(9) / T(280), T(9) / T(280), T(0),
         T(41) / T(840), T(41) / T(840)},
        {T(0), T(2) / T(27), T(1) / T(9), T(1) / T(6), T(5) / T(12), T(1) / T(2), T(5) / T(6), T(1) / T(6), T(2) / T(3),
         T(1) / T(3), T(1), T(0), T(1)},
        {{{T(41) / T(840), T(0), T(0), T(0), T(0), T(34) / T(105), T(9) / T(35), T(9) / T(35), T(9) / T(280),
           T(9) / T(280), T(41) / T(840), T(0), T(0)}}},
        8,
        {7}};
};

/// DOP853: Dormand-Prince 8(5,3) as described in Hairer, Norsett & Wanner, Solving ODE I, 2nd ed. (1993),
/// Sec. II.5 and II.10, with the coefficients as published in E. Hairer's dop853.f (unige.ch/~hairer/software.html,
/// parameter blocks c, a, b, bhh, er), which gives them as 30-digit decimals (c4, c5 = (6 -+ sqrt 6) / 30
/// are irrational). Only the 12 stages of the eighth-order solution (c12 = 1, the "XPH" stage) are here;
/// the dense-output stages 14-16 are not. b: eighth-order weights.
///   bhat[0] = b - er (Hairer's ER1..ER12), the fifth-order solution.
///   bhat[1] = bhh1 k1 + bhh2 k9 + bhh3 k12, the third-order solution: in dop853.f the error line reads
///             K4 - BHH1*K1 - BHH2*K9 - BHH3*K3, where K4 holds the b-combination and the reused array K3
///             holds stage 12 (K2 holds stage 11). (bhh1 = 31/127, bhh3 = 3/136 to the digits given.)
struct dop853 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Dormand-Prince 8(5,3) (DOP853)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 12, 2> table{
        {{{},
          {T(5.26001519587677318785587544488e-2L)},
          {T(1.97250569845378994544595329183e-2L), T(5.91751709536136983633785987549e-2L)},
          {T(2.95875854768068491816892993775e-2L), T(0), T(8.87627564304205475450678981324e-2L)},
          {T(2.41365134159266685502369798665e-1L), T(0), T(-8.84549479328286085344864962717e-1L),
           T(9.24834003261792003115737966543e-1L)},
          {T(3.7037037037037037037037037037e-2L), T(0), T(0), T(1.70828608729473871279604482173e-1L),
           T(1.25467687566822425016691814123e-1L)},
          {T(3.7109375e-2L), T(0), T(0), T(1.70252211019544039314978060272e-1L), T(6.02165389804559606850219397283e-2L),
           T(-1.7578125e-2L)},
          {T(3.70920001185047927108779319836e-2L), T(0), T(0), T(1.70383925712239993810214054705e-1L),
           T(1.07262030446373284651809199168e-1L), T(-1.53194377486244017527936158236e-2L),
           T(8.27378916381402288758473766002e-3L)},
          {T(6.24110958716075717114429577812e-1L), T(0), T(0), T(-3.36089262944694129406857109825e0L),
           T(-8.68219346841726006818189891453e-1L), T(2.75920996994467083049415600797e1L),
           T(2.01540675504778934086186788979e1L), T(-4.34898841810699588477366255144e1L)},
          {T(4.77662536438264365890433908527e-1L), T(0), T(0), T(-2.48811461997166764192642586468e0L),
           T(-5.90290826836842996371446475743e-1L), T(2.12300514481811942347288949897e1L),
           T(1.52792336328824235832596922938e1L), T(-3.32882109689848629194453265587e1L),
           T(-2.03312017085086261358222928593e-2L)},
          {T(-9.3714243008598732571704021658e-1L), T(0), T(0), T(5.18637242884406370830023853209e0L),
           T(1.09143734899672957818500254654e0L), T(-8.14978701074692612513997267357e0L),
           T(-1.85200656599969598641566180701e1L), T(2.27394870993505042818970056734e1L),
           T(2.49360555267965238987089396762e0L), T(-3.0467644718982195003823669022e0L)},
          {T(2.27331014751653820792359768449e0L), T(0), T(0), T(-1.05344954667372501984066689879e1L),
           T(-2.00087205822486249909675718444e0L), T(-1.79589318631187989172765950534e1L),
           T(2.79488845294199600508499808837e1L), T(-2.85899827713502369474065508674e0L),
           T(-8.87285693353062954433549289258e0L), T(1.23605671757943030647266201528e1L),
           T(6.43392746015763530355970484046e-1L)}}},
        {T(5.42937341165687622380535766363e-2L), T(0), T(0), T(0), T(0), T(4.45031289275240888144113950566e0L),
         T(1.89151789931450038304281599044e0L), T(-5.8012039600105847814672114227e0L),
         T(3.1116436695781989440891606237e-1L), T(-1.52160949662516078556178806805e-1L),
         T(2.01365400804030348374776537501e-1L), T(4.47106157277725905176885569043e-2L)},
        {T(0), T(0.526001519587677318785587544488e-1L), T(0.789002279381515978178381316732e-1L),
         T(0.118350341907227396726757197510e0L), T(0.281649658092772603273242802490e0L),
         T(0.333333333333333333333333333333e0L), T(0.25e0L), T(0.307692307692307692307692307692e0L),
         T(0.651282051282051282051282051282e0L), T(0.6e0L), T(0.857142857142857142857142857142e0L), T(1)},
        // bhat[0]: b_i - er_i, digit for digit from dop853.f; bhat[1]: bhh1 (stage 1), bhh2 (stage 9), bhh3 (stage 12).
        {{{T(5.42937341165687622380535766363e-2L - 0.1312004499419488073250102996e-1L), T(0), T(0), T(0), T(0),
           T(4.45031289275240888144113950566e0L - (-0.1225156446376204440720569753e1L)),
           T(1.89151789931450038304281599044e0L - (-0.4957589496572501915214079952e0L)),
           T(-5.8012039600105847814672114227e0L - 0.1664377182454986536961530415e1L),
           T(3.1116436695781989440891606237e-1L - (-0.3503288487499736816886487290e0L)),
           T(-1.52160949662516078556178806805e-1L - 0.3341791187130174790297318841e0L),
           T(2.01365400804030348374776537501e-1L - 0.8192320648511571246570742613e-1L),
           T(4.47106157277725905176885569043e-2L - (-0.2235530786388629525884427845e-1L))},
          {T(0.244094488188976377952755905512e0L), T(0), T(0), T(0), T(0), T(0), T(0), T(0),
           T(0.733846688281611857341361741547e0L), T(0), T(0), T(0.220588235294117647058823529412e-1L)}}},
        8,
        {5, 3}};
};

// clang-format on
}  // namespace odestep::tables

namespace odestep::tables {
// clang-format off  (the tables keep their published layout)

// Every table's nodes are the row sums of a and every weight vector sums to 1, in each floating type
// (explicit_rk also asserts that its table is explicit). The full order conditions (rooted trees) are checked by tests/order_conditions_test.cpp.
static_assert(detail::consistent_in_every_type<rk4>(), "tables::rk4 is not consistent");
static_assert(detail::consistent_in_every_type<euler>(), "tables::euler is not consistent");
static_assert(detail::consistent_in_every_type<midpoint>(), "tables::midpoint is not consistent");
static_assert(detail::consistent_in_every_type<heun>(), "tables::heun is not consistent");
static_assert(detail::consistent_in_every_type<ralston2>(), "tables::ralston2 is not consistent");
static_assert(detail::consistent_in_every_type<kutta3>(), "tables::kutta3 is not consistent");
static_assert(detail::consistent_in_every_type<ssprk3>(), "tables::ssprk3 is not consistent");
static_assert(detail::consistent_in_every_type<rk38>(), "tables::rk38 is not consistent");
static_assert(detail::consistent_in_every_type<bogacki_shampine32>(), "tables::bogacki_shampine32 is not consistent");
static_assert(detail::consistent_in_every_type<fehlberg45>(), "tables::fehlberg45 is not consistent");
static_assert(detail::consistent_in_every_type<cash_karp54>(), "tables::cash_karp54 is not consistent");
static_assert(detail::consistent_in_every_type<dormand_prince54>(), "tables::dormand_prince54 is not consistent");
static_assert(detail::consistent_in_every_type<fehlberg78>(), "tables::fehlberg78 is not consistent");
// dop853.f publishes 28 to 30 significant digits; is_consistent's tolerance floor (1e-26) admits that
// where long double is IEEE quad or double-double (AArch64/RISC-V Linux, PowerPC).
static_assert(detail::consistent_in_every_type<dop853>(), "tables::dop853 is not consistent");

// clang-format on
}  // namespace odestep::tables

namespace odestep {
/// The namespace of these tables before every table moved to odestep::tables; kept so that code written
/// against it still compiles.
namespace tableaux = tables;
}  // namespace odestep

#endif
