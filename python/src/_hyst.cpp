/* SPDX-License-Identifier: MIT */
/*
 * hyst._hyst: the C library as Python objects (nanobind). Every number is
 * computed by the library in src/; this file only owns the memory (the
 * instances, their turning-point arrays, curves, PI parameters), maps numpy
 * arrays onto the library's pointers without copies, and turns error codes
 * into hyst.HystError; the creep term's fit is scored here as the `hyst`
 * tool scores it (holdout(), creep_score(): tools/cli/fit_select.c and
 * fit_creep.c), on the library's lags and fit. The friendly layer (dtype
 * choice, fit(), plot()) is python/hyst/.
 */
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/unique_ptr.h>
#include <nanobind/stl/vector.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "hyst/hyst.h"
#include "hyst/version.h"

/* Host modules shared with the `hyst` tool and the MEX gateway: the model
 * file format (tools/model_text) and fit's hold-out choice (tools/cli). */
extern "C" {
#include "fit_select.h"
#include "model_text.h"
}

namespace nb = nanobind;
using namespace nb::literals;

namespace {

/* Raises hyst.HystError(status, context); the class lives in Python. */
[[noreturn]] void raise_status(int status, const char *context)
{
    nb::object cls = nb::module_::import_("hyst._errors").attr("HystError");
    PyErr_SetObject(cls.ptr(), nb::make_tuple(status, context).ptr());
    throw nb::python_error();
}

/* Errors (negative codes) raise; OK and warnings are returned. */
int check(int status, const char *context)
{
    if (status < 0) {
        raise_status(status, context);
    }
    return status;
}

/* A polynomial f0 from its coefficients, highest power first. */
hyst_poly_t make_poly(const std::vector<double> &coeffs, double lo, double hi)
{
    hyst_poly_t f0{};
    if (coeffs.size() < 2u || coeffs.size() > HYST_MAX_DEGREE + 1u) {
        raise_status(HYST_ERR_DEGREE, "f0 needs 2 .. HYST_MAX_DEGREE + 1 coefficients");
    }
    f0.degree = static_cast<unsigned>(coeffs.size() - 1u);
    f0.lo = lo;
    f0.hi = hi;
    std::memcpy(f0.coeffs, coeffs.data(), coeffs.size() * sizeof(double));
    return f0;
}

/* Coefficients of E at total degree n: w^i t^j, i >= 1, i + j <= n. */
size_t everett_terms(unsigned degree) { return static_cast<size_t>(degree) * (degree + 1u) / 2u; }

/* A branch function E from its terms, ordered i = 1..degree, then
 * j = 0..degree - i (the model file's order). */
hyst_everett_t make_everett(unsigned degree, double lo, double hi, double y_lo,
                            const std::vector<double> &terms)
{
    hyst_everett_t e{};
    if (degree < 1u || degree > HYST_EVERETT_MAX_DEGREE) {
        raise_status(HYST_ERR_DEGREE, "E needs a degree of 1 .. HYST_EVERETT_MAX_DEGREE");
    }
    if (terms.size() != everett_terms(degree)) {
        raise_status(HYST_ERR_ARG, "E of degree n needs n (n + 1) / 2 terms");
    }
    e.degree = degree;
    e.lo = lo;
    e.hi = hi;
    e.y_lo = y_lo;
    size_t k = 0u;
    for (unsigned i = 1u; i <= degree; ++i) {
        for (unsigned j = 0u; i + j <= degree; ++j) {
            e.e[i - 1u][j] = terms[k++];
        }
    }
    return e;
}

/* The limits the library puts on a compensator table (curve.h): checked
 * here too, before the table is allocated. */
constexpr long long MAX_TABLE_INTERVALS = 1LL << 20;
constexpr long long MIN_TABLE_ROWS = 3, MAX_TABLE_ROWS = 4096;

/* A compensator's table intervals: 0 (the exact compensator) or 1 .. 2^20. */
size_t table_intervals(long long intervals)
{
    if (intervals < 0 || intervals > MAX_TABLE_INTERVALS) {
        raise_status(HYST_ERR_ARG, "intervals outside 1 .. 2^20 (0: the exact compensator)");
    }
    return static_cast<size_t>(intervals);
}

/* The asymmetric compensator's table rows: none without a table, else
 * 3 .. 4096 (HYST_EVERETT_INV_ROWS when not given). */
size_t table_rows(std::optional<long long> rows, size_t intervals)
{
    if (!rows) {
        return intervals > 0u ? static_cast<size_t>(HYST_EVERETT_INV_ROWS) : 0u;
    }
    if (intervals == 0u) {
        raise_status(HYST_ERR_ARG, "rows needs intervals > 0 (the exact compensator has no table)");
    }
    if (*rows < MIN_TABLE_ROWS || *rows > MAX_TABLE_ROWS) {
        raise_status(HYST_ERR_ARG, "rows outside 3 .. 4096");
    }
    return static_cast<size_t>(*rows);
}

/* A creep term's time constants and weights (creep.h) as the library
 * takes them: as many of each, 1 .. HYST_CREEP_MAX_TERMS; the values are
 * the library's to check (hyst_*_creep_init()). */
std::pair<std::vector<hyst_wide_t>, std::vector<hyst_wide_t>>
creep_params(const std::vector<double> &tau, const std::vector<double> &weight)
{
    if (tau.size() != weight.size()) {
        raise_status(HYST_ERR_ARG, "creep_tau and creep_weight differ in length");
    }
    if (tau.empty() || tau.size() > HYST_CREEP_MAX_TERMS) {
        raise_status(HYST_ERR_ARG, "a creep term has 1 .. HYST_CREEP_MAX_TERMS lags");
    }
    return {std::vector<hyst_wide_t>(tau.begin(), tau.end()),
            std::vector<hyst_wide_t>(weight.begin(), weight.end())};
}

/* The library's functions of one real variant, by number type. */
template <class T> struct Ops;
#define HYST_PY_OPS(T, P, NAME)                                             \
    template <> struct Ops<T> {                                             \
        static constexpr auto init = hyst_##P##_init_;                      \
        static constexpr auto init_inverse = hyst_##P##_init_inverse_exact_; \
        static constexpr auto init_inverse_table = hyst_##P##_init_inverse_table_; \
        static constexpr auto init_curve = hyst_##P##_init_curve_;          \
        static constexpr auto curve_from_pwl = hyst_##P##_curve_from_pwl_;  \
        static constexpr auto curve_from_everett = hyst_##P##_curve_from_everett_; \
        static constexpr auto curve_everett_inverse_table = hyst_##P##_curve_everett_inverse_table; \
        static constexpr auto curve_from_everett_grid = hyst_##P##_curve_from_everett_grid_; \
        static constexpr auto curve_everett_grid_inverse = hyst_##P##_curve_everett_grid_inverse; \
        static constexpr auto curve_from_spline = hyst_##P##_curve_from_spline_; \
        static constexpr auto curve_spline_inverse_table = hyst_##P##_curve_spline_inverse_table; \
        static constexpr auto step = hyst_##P##_step;                       \
        static constexpr auto process = hyst_##P##_process;                 \
        static constexpr auto set_deadband = hyst_##P##_set_deadband;       \
        static constexpr auto output = hyst_##P##_output;                   \
        static constexpr auto input = hyst_##P##_input;                     \
        static constexpr auto error_bound = hyst_##P##_error_bound;         \
        static constexpr auto rounding_bound = hyst_##P##_rounding_bound;   \
        static constexpr auto pi_init = hyst_##P##_pi_init_;                \
        static constexpr auto pi_init_inverse = hyst_##P##_pi_init_inverse_; \
        static constexpr auto pi_step = hyst_##P##_pi_step;                 \
        static constexpr auto pi_process = hyst_##P##_pi_process;           \
        static constexpr auto pi_output = hyst_##P##_pi_output;             \
        static constexpr auto creep_init = hyst_##P##_creep_init_;          \
        static constexpr auto creep_reset = hyst_##P##_creep_reset;         \
        static constexpr auto creep_step = hyst_##P##_creep_step;           \
        static constexpr auto creep_output = hyst_##P##_creep_output;       \
        static constexpr auto rate_init = hyst_##P##_rate_init_;            \
        static constexpr auto rate_reset = hyst_##P##_rate_reset;           \
        static constexpr auto rate_step = hyst_##P##_rate_step;             \
        static constexpr auto rate_output = hyst_##P##_rate_output;         \
        static constexpr const char *dtype = NAME;                          \
    };
HYST_PY_OPS(float, f32, "float32")
HYST_PY_OPS(double, f64, "float64")
#undef HYST_PY_OPS

template <class T> using In = nb::ndarray<const T, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
template <class T>
using Out = nb::ndarray<nb::numpy, T, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

/*
 * Runs a block call fn(x, y, n) over x into `out` (an array of the output
 * type, written in place and returned) or into a new array.
 */
template <class X, class Y, class Fn> nb::object block(const In<X> &x, nb::handle out, Fn fn)
{
    const size_t n = x.shape(0);
    if (!out.is_none()) {
        Out<Y> o;
        if (!nb::try_cast(out, o, false)) {
            throw nb::type_error("out must be a contiguous 1-d numpy array of the output dtype");
        }
        if (o.shape(0) != n) {
            throw nb::value_error("out must have as many entries as the input");
        }
        /* y may be x itself (the library reads each sample before it writes
         * its output), never another view into it: a sample would be
         * computed from an output already written over it */
        const char *xb = reinterpret_cast<const char *>(x.data());
        const char *ob = reinterpret_cast<const char *>(o.data());
        if (n > 0u && ob < xb + n * sizeof(X) && xb < ob + n * sizeof(Y) &&
            !(ob == xb && sizeof(X) == sizeof(Y))) {
            throw nb::value_error("out overlaps the input without being the input itself: its "
                                  "outputs would overwrite inputs not yet read (pass out=x, or "
                                  "an array of its own)");
        }
        fn(x.data(), o.data(), n);
        return nb::borrow(out);
    }
    std::unique_ptr<Y[]> y(new Y[n > 0u ? n : 1u]);
    fn(x.data(), y.get(), n);
    Y *p = y.release();
    nb::capsule owner(p, [](void *q) noexcept { delete[] static_cast<Y *>(q); });
    return nb::cast(Out<Y>(p, {n}, owner));
}

/* What every TCM variant shares: one instance and the calls written once. */
struct Tcm {
    hyst_tcm_t S{};
    int block_status = HYST_OK; /* returned by the last process() */
    const char *kind = "poly";  /* the curve's kind: poly, pwl, everett, everett_grid or spline */
    std::vector<double> coeffs; /* poly: f0, highest power first */
    std::vector<double> terms;  /* everett: E's coefficients, as make_everett() takes them */
    double lo = 0.0, hi = 0.0;
    double y_lo = 0.0;          /* everett, everett_grid: the output at lo */
    std::vector<double> knots, weights; /* everett_grid: its knots and cells' masses */
    std::vector<double> values, slopes; /* spline: f0 and its slope at the uniform knots */

    Tcm() = default;
    Tcm(const Tcm &) = delete;
    Tcm &operator=(const Tcm &) = delete;
    virtual ~Tcm() = default;

    /* Back at rest: A0, and a creep term's lags at lo (Real). */
    virtual void reset() { hyst_reset(&S); }

    /* The creep term's lags, when the instance has one (Real). */
    virtual const hyst_creep_t *creep_of() const { return nullptr; }
    virtual void set_creep_state(const hyst_creep_t &) {}
    /* The rate term's state, when the instance has one (Real). */
    virtual const hyst_rate_t *rate_of() const { return nullptr; }
    virtual void set_rate_state(const hyst_rate_t &) {}

    /* The library's snapshot; with a creep term, its creep snapshot after
     * it, then with a rate term its rate snapshot (snapshot.h: each says its
     * own length). */
    nb::bytes save() const
    {
        std::vector<unsigned char> buf(HYST_SNAPSHOT_SIZE(hyst_capacity(&S)) +
                                       HYST_CREEP_SNAPSHOT_SIZE + HYST_RATE_SNAPSHOT_SIZE);
        size_t len = 0u, creep_len = 0u, rate_len = 0u;
        check(hyst_snapshot_save(&S, buf.data(), buf.size(), &len), "snapshot save");
        if (const hyst_creep_t *c = creep_of()) {
            check(hyst_creep_snapshot_save(c, buf.data() + len, buf.size() - len, &creep_len),
                  "creep snapshot save");
        }
        if (const hyst_rate_t *r = rate_of()) {
            check(hyst_rate_snapshot_save(r, buf.data() + len + creep_len,
                                          buf.size() - len - creep_len, &rate_len),
                  "rate snapshot save");
        }
        return nb::bytes(reinterpret_cast<const char *>(buf.data()), len + creep_len + rate_len);
    }
    /* Both parts checked before either is written: all or nothing. */
    void restore(const nb::bytes &b)
    {
        const auto *p = reinterpret_cast<const unsigned char *>(b.c_str());
        const size_t n = b.size();
        /* the model's part ends at its length field's value (octets 8..11) */
        const size_t len = n >= 12u ? (size_t)p[8] | (size_t)p[9] << 8 | (size_t)p[10] << 16 |
                                          (size_t)p[11] << 24
                                    : n;
        const bool creep_follows = n >= 4u && len <= n - 4u && p[len] == 0x48u &&
                                   p[len + 1u] == 0x59u && p[len + 2u] == 0x53u &&
                                   p[len + 3u] == 0x43u;
        /* a rate part after the creep part (its length at its octets 8..11), or after the model's */
        const size_t at = len + (creep_follows && n >= len + 12u
                                     ? (size_t)p[len + 8u] | (size_t)p[len + 9u] << 8 |
                                           (size_t)p[len + 10u] << 16 | (size_t)p[len + 11u] << 24
                                     : 0u);
        const bool rate_follows = n >= 4u && at <= n - 4u && p[at] == 0x48u &&
                                  p[at + 1u] == 0x59u && p[at + 2u] == 0x53u &&
                                  p[at + 3u] == 0x52u;
        const hyst_creep_t *c = creep_of();
        const hyst_rate_t *r = rate_of();
        hyst_creep_t lags{};
        hyst_rate_t term{};
        if (r != nullptr) {
            term = *r;
            if (len <= n && !rate_follows) {
                raise_status(HYST_ERR_FORMAT,
                             "snapshot restore: the model has a rate term, the snapshot none");
            }
            if (len <= n) {
                check(hyst_rate_snapshot_restore(&term, p + at, n - at), "rate snapshot restore");
            }
        } else if (rate_follows) {
            raise_status(HYST_ERR_FORMAT,
                         "snapshot restore: the snapshot has a rate term, the model none");
        }
        if (c != nullptr) {
            lags = *c;
            if (len <= n && !creep_follows) {
                raise_status(HYST_ERR_FORMAT,
                             "snapshot restore: the model has a creep term, the snapshot none");
            }
            if (len <= n) {
                check(hyst_creep_snapshot_restore(&lags, p + len, n - len),
                      "creep snapshot restore");
            }
        } else if (creep_follows) {
            raise_status(HYST_ERR_FORMAT,
                         "snapshot restore: the snapshot has a creep term, the model none");
        }
        check(hyst_snapshot_restore(&S, p, n), "snapshot restore");
        if (c != nullptr) {
            set_creep_state(lags);
        }
        if (r != nullptr) {
            set_rate_state(term);
        }
    }
};

/* An instance with its own four turning-point arrays (X inputs, Y outputs). */
template <class X, class Y> struct Owned : Tcm {
    std::vector<X> xl, xr;
    std::vector<Y> yl, yr;
    explicit Owned(size_t capacity)
        : xl(capacity > 0u ? capacity : 1u), xr(xl.size()), yl(xl.size()), yr(xl.size())
    {
    }
};

/* Model or compensator of a real variant. */
template <class T> struct Real : Owned<T, T> {
    using O = Ops<T>;
    hyst_curve_t inv{}; /* the compensator's inverse curve (the instance points at it) */
    hyst_curve_t fwd{}; /* a piecewise-linear f0 or an E (the model's curve; inv derives from it) */
    std::vector<T> bx, by; /* its breakpoints (fwd points at them) */
    std::vector<T> table;  /* the tabulated compensator's table (inv points at it) */
    std::vector<T> curve_table; /* a grid E's or a spline's table (fwd, and inv, point at it) */
    bool inverse;
    size_t intervals = 0u; /* the table's intervals (per row); 0: the exact compensator */
    size_t rows = 0u;      /* the asymmetric kind's table: rows per direction; 0: none */
    double deadband = 0.0;
    /* A creep term (creep.h), when set_creep() gave one: lags of the model's
     * input (of the drive, for a compensator), every lag at lo at rest */
    bool has_creep = false;
    hyst_creep_t creep{};
    std::vector<double> creep_tau, creep_weight;
    /* A rate term (rate.h), when set_rate() gave one: the low-pass of the
     * change of the same input as the creep's, at rest at lo */
    bool has_rate = false;
    hyst_rate_t rate{};
    std::optional<double> rate_tau, rate_weight;

    /* The instance on fwd, or on its inverse (the compensator): the one
     * invert() prepares (hyst_curve_inverse(), or the kind's own), or, invert
     * nullptr, the table inv already holds. */
    using Invert = hyst_status_t (*)(hyst_curve_t *, const hyst_curve_t *);
    void attach_curve(size_t capacity, Invert invert = hyst_curve_inverse)
    {
        const hyst_curve_t *c = &fwd;
        if (inverse) {
            if (invert != nullptr) {
                check(invert(&inv, &fwd), "inverse curve");
            }
            c = &inv;
        }
        check(O::init_curve(&this->S, c, this->xl.data(), this->yl.data(), this->xr.data(),
                            this->yr.data(), capacity, HYST_LAYOUT),
              inverse ? "compensator init" : "model init");
    }

    /* A piecewise-linear f0 through (xs, ys): its own copies of the points. */
    Real(const std::vector<double> &xs, const std::vector<double> &ys, size_t capacity,
         bool inverse_)
        : Owned<T, T>(capacity), bx(xs.begin(), xs.end()), by(ys.begin(), ys.end()),
          inverse(inverse_)
    {
        if (xs.size() != ys.size()) {
            raise_status(HYST_ERR_ARG, "xs and ys differ in length");
        }
        check(O::curve_from_pwl(&fwd, bx.data(), by.data(), bx.size(), HYST_LAYOUT), "curve");
        attach_curve(capacity);
        this->kind = "pwl";
        this->lo = xs.empty() ? 0.0 : xs.front();
        this->hi = xs.empty() ? 0.0 : xs.back();
    }

    /* The asymmetric kind: a branch function E (make_everett()), or its
     * compensator: solved per branch (intervals 0: HYST_CURVE_EVERETT_INV)
     * or tabulated as firmware runs it (HYST_CURVE_EVERETT_INV_TABLE: rows
     * per direction, HYST_EVERETT_INV_ROWS when not given, of intervals
     * intervals). The arguments are checked before the table is allocated. */
    Real(unsigned degree, double lo_, double hi_, double y_lo_, const std::vector<double> &terms_,
         size_t capacity, bool inverse_, long long intervals_, std::optional<long long> rows_)
        : Owned<T, T>(capacity), inverse(inverse_)
    {
        if (!inverse && (intervals_ != 0 || rows_)) {
            raise_status(HYST_ERR_ARG, "intervals and rows are the compensator's (inverse=True)");
        }
        intervals = table_intervals(intervals_);
        rows = table_rows(rows_, intervals);
        const hyst_everett_t e = make_everett(degree, lo_, hi_, y_lo_, terms_);
        check(O::curve_from_everett(&fwd, &e, HYST_LAYOUT), "curve");
        if (intervals > 0u) {
            table.resize(HYST_EVERETT_INV_TABLE_LEN(rows, intervals));
            check(O::curve_everett_inverse_table(&inv, &fwd, table.data(), rows, intervals),
                  "compensator table");
        }
        attach_curve(capacity, intervals > 0u ? nullptr : hyst_curve_inverse);
        this->kind = "everett";
        this->terms = terms_;
        this->lo = lo_;
        this->hi = hi_;
        this->y_lo = y_lo_;
    }

    /* The asymmetric kind on a grid (hyst_everett_grid_t: knots, the
     * cells' masses weight[i (i + 1) / 2 + j], y_lo), or its compensator
     * (HYST_CURVE_EVERETT_GRID_INV, each branch solved in closed form: no
     * table), as `hyst sim --model` and `hyst inv --model` build them. */
    Real(const std::vector<double> &knots_, const std::vector<double> &weights_, double y_lo_,
         size_t capacity, bool inverse_)
        : Owned<T, T>(capacity), inverse(inverse_)
    {
        if (knots_.size() < 2u || knots_.size() > HYST_EVERETT_GRID_MAX_INTERVALS + 1u) {
            raise_status(HYST_ERR_ARG, "a grid needs 2 .. HYST_EVERETT_GRID_MAX_INTERVALS + 1 "
                                       "knots");
        }
        const size_t k = knots_.size() - 1u;
        if (weights_.size() != HYST_EVERETT_GRID_CELLS(k)) {
            raise_status(HYST_ERR_ARG, "a grid of K knot intervals needs K (K + 1) / 2 weights");
        }
        hyst_everett_grid_t g{};
        g.intervals = static_cast<unsigned>(k);
        g.y_lo = static_cast<hyst_wide_t>(y_lo_);
        for (size_t i = 0u; i < knots_.size(); ++i) {
            g.knots[i] = static_cast<hyst_wide_t>(knots_[i]);
        }
        for (size_t i = 0u; i < weights_.size(); ++i) {
            g.weight[i] = static_cast<hyst_wide_t>(weights_[i]);
        }
        curve_table.resize(HYST_EVERETT_GRID_TABLE_LEN(k));
        check(O::curve_from_everett_grid(&fwd, &g, curve_table.data(), curve_table.size(),
                                         HYST_LAYOUT),
              "curve");
        attach_curve(capacity, O::curve_everett_grid_inverse);
        this->kind = "everett_grid";
        this->knots = knots_;
        this->weights = weights_;
        this->lo = knots_.front();
        this->hi = knots_.back();
        this->y_lo = y_lo_;
    }

    /* The symmetric kind whose f0 is a monotone cubic spline on uniform knots
     * (hyst_spline_t: f0 and its slope at lo + k (hi - lo) / K, k = 0..K), or
     * its compensator: solved per sample on f0's cubic piece (intervals 0:
     * HYST_CURVE_SPLINE_INV) or tabulated as firmware runs it
     * (HYST_CURVE_SPLINE_INV_TABLE), as `hyst sim --model` and `hyst inv
     * --model [--intervals N]` build them. The arguments are checked before
     * the table is allocated. */
    Real(double lo_, double hi_, const std::vector<double> &values_,
         const std::vector<double> &slopes_, size_t capacity, bool inverse_, long long intervals_)
        : Owned<T, T>(capacity), inverse(inverse_)
    {
        if (!inverse && intervals_ != 0) {
            raise_status(HYST_ERR_ARG, "intervals is the compensator's (inverse=True)");
        }
        intervals = table_intervals(intervals_);
        if (values_.size() < 2u || values_.size() > HYST_SPLINE_MAX_INTERVALS + 1u) {
            raise_status(HYST_ERR_DEGREE, "a spline needs 2 .. HYST_SPLINE_MAX_INTERVALS + 1 "
                                          "values (one per knot)");
        }
        if (slopes_.size() != values_.size()) {
            raise_status(HYST_ERR_ARG, "a spline needs as many slopes as values (one per knot)");
        }
        hyst_spline_t f0{};
        f0.intervals = static_cast<unsigned>(values_.size() - 1u);
        f0.lo = static_cast<hyst_wide_t>(lo_);
        f0.hi = static_cast<hyst_wide_t>(hi_);
        for (size_t i = 0u; i < values_.size(); ++i) {
            f0.value[i] = static_cast<hyst_wide_t>(values_[i]);
            f0.slope[i] = static_cast<hyst_wide_t>(slopes_[i]);
        }
        curve_table.resize(HYST_SPLINE_TABLE_LEN(f0.intervals));
        check(O::curve_from_spline(&fwd, &f0, curve_table.data(), curve_table.size(),
                                   HYST_LAYOUT),
              "curve");
        if (intervals > 0u) {
            table.resize(HYST_INV_TABLE_LEN(intervals));
            check(O::curve_spline_inverse_table(&inv, &fwd, table.data(), intervals),
                  "compensator table");
        }
        attach_curve(capacity, intervals > 0u ? nullptr : hyst_curve_spline_inverse);
        this->kind = "spline";
        this->values = values_;
        this->slopes = slopes_;
        this->lo = lo_;
        this->hi = hi_;
    }

    /* f0 as a polynomial; its compensator exact (intervals 0) or tabulated
     * as firmware runs it (HYST_INIT_INVERSE: intervals HYST_INV_TABLE). */
    Real(const std::vector<double> &c, double lo_, double hi_, size_t capacity, bool inverse_,
         long long intervals_)
        : Owned<T, T>(capacity), inverse(inverse_),
          intervals(inverse_ ? table_intervals(intervals_) : 0u)
    {
        const hyst_poly_t f0 = make_poly(c, lo_, hi_);
        int st;
        if (inverse && intervals > 0u) {
            table.resize(HYST_INV_TABLE_LEN(intervals));
            st = O::init_inverse_table(&this->S, &inv, &f0, table.data(), intervals,
                                       this->xl.data(), this->yl.data(), this->xr.data(),
                                       this->yr.data(), capacity, HYST_LAYOUT);
        } else if (inverse) {
            st = O::init_inverse(&this->S, &inv, &f0, this->xl.data(), this->yl.data(),
                                 this->xr.data(), this->yr.data(), capacity, HYST_LAYOUT);
        } else {
            st = O::init(&this->S, &f0, this->xl.data(), this->yl.data(), this->xr.data(),
                         this->yr.data(), capacity, HYST_LAYOUT);
        }
        check(st, inverse ? "compensator init" : "model init");
        this->coeffs = c;
        this->lo = lo_;
        this->hi = hi_;
    }
    /* One sample, with the creep term when there is one, as `hyst sim
     * --model` and `hyst inv --model` run it (tools/cli/cli_tcm.c): the
     * model's output plus the creep of its input as the model took it
     * (clamped); the compensator inverts the hysteresis model for the
     * desired output less the creep's share, whose lags then take the drive
     * in. */
    T step(T x)
    {
        if (!has_creep && !has_rate) {
            return O::step(&this->S, x);
        }
        if (inverse) {
            const T v = x - terms_output();
            const T drive = O::step(&this->S, v);
            (void)terms_step(drive);
            return drive;
        }
        const T y = O::step(&this->S, x);
        return y + terms_step(O::input(&this->S));
    }
    /* The creep and rate terms' contribution to the next sample, and the
     * same as they take input u in: summed as the CLI sums them, in double. */
    T terms_output() const
    {
        return static_cast<T>((has_creep ? static_cast<double>(O::creep_output(&creep)) : 0.0) +
                              (has_rate ? static_cast<double>(O::rate_output(&rate)) : 0.0));
    }
    T terms_step(T u)
    {
        return static_cast<T>((has_creep ? static_cast<double>(O::creep_step(&creep, u)) : 0.0) +
                              (has_rate ? static_cast<double>(O::rate_step(&rate, u)) : 0.0));
    }
    /* The block call; with a creep term sample by sample (step(), the same
     * numbers as the library's block call for the hysteresis model) and
     * the statuses folded as the block call folds them. */
    void run_block(const T *px, T *py, size_t n)
    {
        if (!has_creep && !has_rate) {
            this->block_status = O::process(&this->S, px, py, n);
            return;
        }
        int worst = HYST_OK;
        bool failed = false;
        for (size_t i = 0u; i < n; ++i) {
            py[i] = step(px[i]);
            const int st = hyst_status(&this->S);
            if (st < 0) {
                failed = true;
            } else if (st > worst) {
                worst = st;
            }
        }
        this->block_status = failed ? HYST_ERR_NONFINITE : worst;
    }
    nb::object process(const In<T> &x, nb::handle out)
    {
        return block<T, T>(x, out,
                           [this](const T *px, T *py, size_t n) { run_block(px, py, n); });
    }
    void set_deadband(double w)
    {
        check(O::set_deadband(&this->S, static_cast<T>(w)), "deadband");
        deadband = static_cast<double>(static_cast<T>(w));
    }
    /* A creep term of lags of time constants tau (samples) and weights
     * weight (hyst_*_creep_init(), every lag at lo); empty lists remove it.
     * Also puts the model back at rest, so that both start together. */
    void set_creep(const std::vector<double> &tau, const std::vector<double> &weight)
    {
        if (tau.empty() && weight.empty()) {
            has_creep = false;
            creep_tau.clear();
            creep_weight.clear();
            reset();
            return;
        }
        const auto p = creep_params(tau, weight);
        hyst_creep_t c{};
        check(O::creep_init(&c, p.first.size(), p.first.data(), p.second.data(),
                            static_cast<hyst_wide_t>(this->lo), HYST_LAYOUT),
              "creep init");
        creep = c;
        has_creep = true;
        creep_tau = tau;
        creep_weight = weight;
        reset();
    }
    /* A rate term of time constant tau (samples) and weight weight
     * (hyst_*_rate_init(), at rest at lo); both None remove it. Also puts
     * the model back at rest, so that both start together. */
    void set_rate(std::optional<double> tau, std::optional<double> weight)
    {
        if (!tau && !weight) {
            has_rate = false;
            rate_tau.reset();
            rate_weight.reset();
            reset();
            return;
        }
        if (!tau || !weight) {
            raise_status(HYST_ERR_ARG, "a rate term needs rate_tau and rate_weight (both or "
                                       "neither)");
        }
        hyst_rate_t r{};
        check(O::rate_init(&r, static_cast<hyst_wide_t>(*tau), static_cast<hyst_wide_t>(*weight),
                           static_cast<hyst_wide_t>(this->lo), HYST_LAYOUT),
              "rate init");
        rate = r;
        has_rate = true;
        rate_tau = tau;
        rate_weight = weight;
        reset();
    }
    const hyst_rate_t *rate_of() const override { return has_rate ? &rate : nullptr; }
    void set_rate_state(const hyst_rate_t &r) override { rate = r; }
    const hyst_creep_t *creep_of() const override { return has_creep ? &creep : nullptr; }
    void set_creep_state(const hyst_creep_t &c) override { creep = c; }
    void reset() override
    {
        hyst_reset(&this->S);
        if (has_creep) {
            (void)O::creep_reset(&creep, static_cast<T>(this->lo));
        }
        if (has_rate) {
            (void)O::rate_reset(&rate, static_cast<T>(this->lo));
        }
    }
};

/* A creep term alone (creep.h) of a real variant: the lags of a drive and
 * their weighted sum, the library's numbers. */
template <class T> struct Creep {
    using O = Ops<T>;
    hyst_creep_t C{};
    std::vector<double> tau, weight;
    double x_rest;
    int block_status = HYST_OK;

    Creep(const std::vector<double> &tau_, const std::vector<double> &weight_, double x_rest_)
        : tau(tau_), weight(weight_), x_rest(x_rest_)
    {
        const auto p = creep_params(tau_, weight_);
        check(O::creep_init(&C, p.first.size(), p.first.data(), p.second.data(),
                            static_cast<hyst_wide_t>(x_rest_), HYST_LAYOUT),
              "creep init");
    }
    T step(T x) { return O::creep_step(&C, x); }
    nb::object process(const In<T> &x, nb::handle out)
    {
        return block<T, T>(x, out, [this](const T *px, T *py, size_t n) {
            bool failed = false;
            for (size_t i = 0u; i < n; ++i) {
                py[i] = O::creep_step(&C, px[i]);
                failed = failed || hyst_creep_status(&C) < 0;
            }
            block_status = failed ? HYST_ERR_NONFINITE : HYST_OK;
        });
    }
    void reset(std::optional<double> at)
    {
        check(O::creep_reset(&C, static_cast<T>(at ? *at : x_rest)), "creep reset");
    }
};

/* A creep term as a dict: tau (0: none could be fitted), weight, offset,
 * holdout_rms, fit_rms, max_abs. */
nb::dict creep_dict(const fit_creep_t &c)
{
    nb::dict d;
    d["tau"] = c.tau;
    d["weight"] = c.weight;
    d["offset"] = c.offset;
    d["holdout_rms"] = c.holdout_rms;
    d["fit_rms"] = c.fit_rms;
    d["max_abs"] = c.max_abs;
    d["rate_tau"] = c.rate_tau;
    d["rate_weight"] = c.rate_tau > 0 ? c.rate_weight : NAN;
    return d;
}

/* The creep term `hyst fit` fits to a model's run (fit_creep_score(): u the
 * model's inputs, r its residual, fitted on [0, train) and scored after;
 * tau > 0 that time constant, 0 the best of the tool's series). */
nb::dict creep_score(const std::vector<double> &u, const std::vector<double> &r, size_t train,
                     double x_rest, double tau)
{
    if (r.size() != u.size()) {
        raise_status(HYST_ERR_ARG, "u and r differ in length");
    }
    fit_creep_t c;
    fit_creep_score(u.data(), r.data(), u.size(), train < u.size() ? train : u.size(), x_rest,
                    tau, &c);
    return creep_dict(c);
}

/*
 * A model of double run over a record as `hyst fit` scores it
 * (fit_model_run_creep(), tools/cli/fit_select.c): from rest, x[k] paired
 * with y[k + delay] for skip <= k < n - delay; its RMS error over k >= from
 * (NaN when none), and, creep_tau >= 0, the creep term fitted to its
 * residual on the samples before `from` and scored after.
 */
nb::dict holdout(Real<double> &m, const In<double> &x, const In<double> &y, size_t skip,
                 size_t delay, size_t from, double creep_tau, double rate_tau)
{
    const size_t n = x.shape(0);
    if (y.shape(0) != n) {
        raise_status(HYST_ERR_ARG, "x and y differ in length");
    }
    if (m.has_creep || m.inverse || std::strcmp(m.kind, "pwl") == 0) {
        raise_status(HYST_ERR_ARG, "holdout runs a model of kind poly, everett, everett_grid or "
                                   "spline, without a creep term");
    }
    hyst_poly_t f0{};
    const bool poly = std::strcmp(m.kind, "poly") == 0;
    if (poly) {
        f0 = make_poly(m.coeffs, m.lo, m.hi);
    }
    fit_creep_t c{};
    const bool terms = creep_tau >= 0 || rate_tau > 0;
    c.tau = creep_tau >= 0 ? creep_tau : 0.0;
    c.rate_tau = rate_tau > 0 ? rate_tau : 0.0;
    const double rms = fit_model_run_creep(poly ? &f0 : nullptr, poly ? nullptr : &m.fwd,
                                           x.data(), y.data(), n, skip, delay, from, nullptr,
                                           nullptr, terms ? &c : nullptr);
    nb::dict d;
    d["rms"] = rms;
    d["creep"] = terms && n > skip + delay ? nb::object(creep_dict(c)) : nb::none();
    return d;
}

/* The code variant: integer DAC codes in, float out. */
struct Code : Owned<hyst_code_word_t, float> {
    unsigned long code_lo, code_hi;
    unsigned long deadband = 0u;
    Code(const std::vector<double> &c, double lo_, double hi_, unsigned long clo,
         unsigned long chi, size_t capacity)
        : Owned(capacity), code_lo(clo), code_hi(chi)
    {
        const hyst_poly_t f0 = make_poly(c, lo_, hi_);
        if (clo > HYST_CODE_MAX || chi > HYST_CODE_MAX) {
            raise_status(HYST_ERR_DOMAIN, "codes wider than HYST_CODE_BITS");
        }
        check(hyst_code_init_(&S, &f0, static_cast<uint_least32_t>(clo),
                              static_cast<uint_least32_t>(chi), xl.data(), yl.data(), xr.data(),
                              yr.data(), capacity, HYST_LAYOUT),
              "code model init");
        coeffs = c;
        lo = lo_;
        hi = hi_;
    }
    float step(unsigned long code)
    {
        return hyst_code_step(&S, static_cast<uint_least32_t>(code > HYST_CODE_MAX ? HYST_CODE_MAX : code));
    }
    nb::object process(const In<hyst_code_word_t> &x, nb::handle out)
    {
        return block<hyst_code_word_t, float>(
            x, out, [this](const hyst_code_word_t *px, float *py, size_t n) {
                block_status = hyst_code_process(&S, px, py, n);
            });
    }
    void set_deadband(unsigned long codes)
    {
        if (codes > HYST_CODE_MAX) {
            raise_status(HYST_ERR_ARG, "deadband wider than HYST_CODE_BITS");
        }
        check(hyst_code_set_deadband(&S, static_cast<uint_least32_t>(codes)), "deadband");
        deadband = codes;
    }
};

/* The Prandtl-Ishlinskii model of a real variant, owning its parameters. */
template <class T> struct Pi {
    using O = Ops<T>;
    hyst_pi_t P{};
    std::vector<T> r, w, z;
    int block_status = HYST_OK;

    explicit Pi(size_t n) : r(n > 0u ? n : 1u), w(r.size()), z(r.size()) {}
    Pi(const std::vector<double> &r_, const std::vector<double> &w_) : Pi(r_.size())
    {
        if (r_.size() != w_.size()) {
            raise_status(HYST_ERR_ARG, "thresholds and weights differ in length");
        }
        for (size_t i = 0; i < r_.size(); ++i) {
            r[i] = static_cast<T>(r_[i]);
            w[i] = static_cast<T>(w_[i]);
        }
        check(O::pi_init(&P, r.data(), w.data(), z.data(), r_.size(), HYST_LAYOUT), "PI init");
    }
    Pi(const Pi &) = delete;
    Pi &operator=(const Pi &) = delete;

    std::unique_ptr<Pi> inverse() const
    {
        std::unique_ptr<Pi> inv(new Pi(P.n));
        check(O::pi_init_inverse(&inv->P, &P, inv->r.data(), inv->w.data(), inv->z.data(),
                                 HYST_LAYOUT),
              "PI inverse");
        return inv;
    }
    T step(T x) { return O::pi_step(&P, x); }
    nb::object process(const In<T> &x, nb::handle out)
    {
        return block<T, T>(x, out, [this](const T *px, T *py, size_t n) {
            block_status = O::pi_process(&P, px, py, n);
        });
    }
    std::vector<double> thresholds() const { return std::vector<double>(r.begin(), r.begin() + static_cast<long>(P.n)); }
    std::vector<double> weights() const { return std::vector<double>(w.begin(), w.begin() + static_cast<long>(P.n)); }
};

/* A fit's configuration (ident.h) from fit()'s and select()'s arguments. */
hyst_ident_config_t ident_config(const In<double> &x, const In<double> &y, unsigned degree,
                                 int method, double lo, double hi, size_t skip, size_t delay)
{
    if (x.shape(0) != y.shape(0)) {
        raise_status(HYST_ERR_ARG, "x and y differ in length");
    }
    hyst_ident_config_t cfg{};
    cfg.degree = degree;
    cfg.method = method;
    cfg.lo = lo;
    cfg.hi = hi;
    cfg.skip = skip;
    cfg.delay = delay;
    return cfg;
}

/* Identification of f0 from recorded arrays (hyst_ident_fit()). */
nb::dict fit(const In<double> &x, const In<double> &y, unsigned degree, int method, double lo,
             double hi, size_t skip, size_t delay)
{
    const hyst_ident_config_t cfg = ident_config(x, y, degree, method, lo, hi, skip, delay);
    hyst_ident_t work;
    hyst_ident_result_t res;
    check(hyst_ident_fit(&cfg, x.data(), y.data(), x.shape(0), &work, &res), "fit");
    nb::dict d;
    d["coeffs"] = std::vector<double>(res.coeffs, res.coeffs + res.degree + 1u);
    d["degree"] = res.degree;
    d["method"] = res.method;
    d["lo"] = res.lo;
    d["hi"] = res.hi;
    d["rms"] = res.rms;
    d["max_abs"] = res.max_abs;
    d["y_lo_est"] = res.y_lo_est;
    d["y_hi_est"] = res.y_hi_est;
    d["used"] = res.used;
    d["rising"] = res.rising;
    d["falling"] = res.falling;
    d["increasing"] = res.increasing != 0;
    d["turn"] = res.turn;
    return d;
}

/*
 * Identification of the asymmetric kind's E (hyst_everett_fit_*) from
 * recorded arrays, as fit() does f0: sample i (skip <= i < n - delay) pairs
 * x[i] with y[i + delay], the record starting from rest at sample skip (its
 * outputs fitted from the first input near an end of their range on:
 * fit_settled(), before it the model's state is not the record's); the
 * domain is [lo, hi] or, when lo == hi, the range of those x. Inputs are
 * clamped to the domain, as the model clamps them. Only the terms w^i t^j
 * with j <= t_degree are fitted (hyst_everett_fit_init_terms(); the others
 * 0); t_degree < 0 means degree - 1, all of them. curve_status is what
 * hyst_f64_curve_from_everett() says of the result (HYST_ERR_NOT_MONOTONE:
 * not a usable E).
 */
nb::dict fit_everett(const In<double> &x, const In<double> &y, unsigned degree, double lo,
                     double hi, size_t skip, size_t delay, int t_degree)
{
    const unsigned t_deg =
        t_degree < 0 ? (degree > 0u ? degree - 1u : 0u) : static_cast<unsigned>(t_degree);
    const size_t n = x.shape(0);
    if (y.shape(0) != n) {
        raise_status(HYST_ERR_ARG, "x and y differ in length");
    }
    if (skip >= n || delay >= n - skip) {
        raise_status(HYST_ERR_ARG, "skip + delay leaves no sample");
    }
    const size_t count = n - skip - delay;
    const double *px = x.data() + skip, *py = y.data() + skip + delay;
    if (lo == hi) {
        check(hyst_ident_domain(px, count, &lo, &hi), "fit");
    }
    /* a record of count samples stacks at most count + 1 turning points */
    std::vector<hyst_wide_t> work(HYST_EVERETT_FIT_WORK(count + 2u));
    hyst_everett_fit_t fit;
    check(hyst_everett_fit_init_terms(&fit, degree, t_deg, lo, hi, work.data(), work.size()),
          "fit");
    size_t used = 0u;
    check(fit_everett_add_clamped(&fit, px, py, count, lo, hi, &used), "fit");
    hyst_everett_t e;
    hyst_wide_t rms = 0.0;
    check(hyst_everett_fit_solve(&fit, &e, &rms), "fit");
    hyst_curve_t curve;
    std::vector<double> terms;
    for (unsigned i = 1u; i <= e.degree; ++i) {
        for (unsigned j = 0u; i + j <= e.degree; ++j) {
            terms.push_back(e.e[i - 1u][j]);
        }
    }
    nb::dict d;
    d["kind"] = "everett";
    d["degree"] = e.degree;
    d["t_degree"] = t_deg;
    d["lo"] = e.lo;
    d["hi"] = e.hi;
    d["y_lo"] = e.y_lo;
    d["terms"] = terms;
    d["rms"] = rms;
    d["used"] = used;
    d["curve_status"] = static_cast<int>(hyst_f64_curve_from_everett(&curve, &e));
    return d;
}

/*
 * E of t-degree 0 written as the symmetric model's f0, in powers of x,
 * highest first, as `hyst fit` writes the E of t-degree 0 it chooses
 * (fit_poly_from_everett(), tools/cli/fit_everett.c); None when E has a
 * term of t, the powers of x cancel or f0 does not increase.
 */
nb::object poly_from_everett(unsigned degree, double lo, double hi, double y_lo,
                             const std::vector<double> &terms)
{
    const hyst_everett_t e = make_everett(degree, lo, hi, y_lo, terms);
    hyst_poly_t f0;
    if (!fit_poly_from_everett(&e, &f0)) {
        return nb::none();
    }
    std::vector<double> coeffs(f0.coeffs, f0.coeffs + f0.degree + 1u);
    return nb::cast(coeffs);
}

/* A kind of k knot intervals fitted to a record by the `hyst` tool's fit of
 * it (fit_grid_record(), fit_spline_record()), on [lo, hi] or the inputs'
 * range when lo == hi: its result, and into d what every such kind's dict
 * has (rms the model's run over the samples fitted, or the least-squares
 * residual when the library refuses the curve: curve_status). */
using RecordFit = hyst_status_t (*)(const hyst_ident_config_t *, unsigned, const double *,
                                    const double *, size_t, fit_everett_result_t *);
fit_everett_result_t fit_intervals(RecordFit record_fit, const In<double> &x,
                                   const In<double> &y, unsigned k, double lo, double hi,
                                   size_t skip, size_t delay, nb::dict &d)
{
    const size_t n = x.shape(0);
    if (y.shape(0) != n) {
        raise_status(HYST_ERR_ARG, "x and y differ in length");
    }
    if (skip >= n || delay >= n - skip) {
        raise_status(HYST_ERR_ARG, "skip + delay leaves no sample");
    }
    const hyst_ident_config_t cfg = ident_config(x, y, k, 0, lo, hi, skip, delay);
    fit_everett_result_t r;
    check(record_fit(&cfg, k, x.data(), y.data(), n, &r), "fit");
    d["rms"] = r.curve_status == HYST_OK ? r.rms : r.ls_rms;
    d["max_abs"] = r.max_abs;
    d["used"] = r.used;
    d["curve_status"] = static_cast<int>(r.curve_status);
    return r;
}

/*
 * The asymmetric kind on a grid of k knot intervals fitted to a record as
 * `hyst fit --kind everett_grid` fits it (fit_grid_record(),
 * tools/cli/fit_grid.c): the knots where the output steps, the cells'
 * masses by least squares; on [lo, hi], or the inputs' range when lo == hi.
 * A dict as fit_everett() gives (knots, weights instead of terms; rms as
 * fit_intervals() says; determined: whether the record determines every
 * mass, hyst_everett_grid_fit_determined()).
 */
nb::dict fit_grid(const In<double> &x, const In<double> &y, unsigned k, double lo, double hi,
                  size_t skip, size_t delay)
{
    nb::dict d;
    const fit_everett_result_t r = fit_intervals(fit_grid_record, x, y, k, lo, hi, skip, delay, d);
    const hyst_everett_grid_t &g = r.grid;
    d["kind"] = "everett_grid";
    d["degree"] = g.intervals;
    d["lo"] = static_cast<double>(g.knots[0]);
    d["hi"] = static_cast<double>(g.knots[g.intervals]);
    d["y_lo"] = static_cast<double>(g.y_lo);
    d["knots"] = std::vector<double>(g.knots, g.knots + g.intervals + 1u);
    d["weights"] = std::vector<double>(g.weight, g.weight + HYST_EVERETT_GRID_CELLS(g.intervals));
    d["determined"] = r.determined != 0;
    return d;
}

/*
 * The symmetric kind whose f0 is a monotone cubic spline of k uniform knot
 * intervals fitted to a record as `hyst fit --kind spline` fits it
 * (fit_spline_record(), tools/cli/fit_spline.c): along every branch, minor
 * loops included, on [lo, hi] or the inputs' range when lo == hi. A dict:
 * kind, degree and intervals (k), lo, hi, values and slopes (f0 and its
 * slope at the k + 1 knots), and what fit_intervals() says.
 */
nb::dict fit_spline(const In<double> &x, const In<double> &y, unsigned k, double lo, double hi,
                    size_t skip, size_t delay)
{
    nb::dict d;
    const fit_everett_result_t r =
        fit_intervals(fit_spline_record, x, y, k, lo, hi, skip, delay, d);
    const hyst_spline_t &f0 = r.spline;
    d["kind"] = "spline";
    d["degree"] = f0.intervals;
    d["intervals"] = f0.intervals;
    d["lo"] = static_cast<double>(f0.lo);
    d["hi"] = static_cast<double>(f0.hi);
    d["values"] = std::vector<double>(f0.value, f0.value + f0.intervals + 1u);
    d["slopes"] = std::vector<double>(f0.slope, f0.slope + f0.intervals + 1u);
    return d;
}

/* ---- the model file format, one implementation (tools/model_text) ---- */

/* The kinds by name (a model file's key `kind`, fit()'s kind): the model
 * file's (MODEL_TEXT_*) and fit's (FIT_*). */
struct KindName {
    const char *name;
    int model_text, fit;
};
constexpr KindName KIND_NAMES[] = {{"poly", MODEL_TEXT_POLY, FIT_POLY},
                                   {"everett", MODEL_TEXT_EVERETT, FIT_EVERETT},
                                   {"everett_grid", MODEL_TEXT_GRID, FIT_GRID},
                                   {"spline", MODEL_TEXT_SPLINE, FIT_SPLINE}};

/* The kind of that name, or nullptr. */
const KindName *kind_named(const std::string &name)
{
    for (const KindName &k : KIND_NAMES) {
        if (name == k.name) {
            return &k;
        }
    }
    return nullptr;
}

/* A fit kind as fit_select.h takes it: FIT_EVERETT, FIT_GRID or FIT_SPLINE,
 * else FIT_POLY. */
int fit_kind(int kind)
{
    return kind == FIT_EVERETT || kind == FIT_GRID || kind == FIT_SPLINE ? kind : FIT_POLY;
}

/* The load_model() dict of a model as the reader gives it. */
nb::dict model_dict(const model_text_t &m)
{
    nb::dict d;
    d["kind"] = "poly";
    for (const KindName &k : KIND_NAMES) {
        if (m.kind == k.model_text) {
            d["kind"] = k.name;
        }
    }
    d["lo"] = m.lo;
    d["hi"] = m.hi;
    if (m.delay_fraction > 0.0) { /* a sub-sample delay: a float, else an int */
        d["delay"] = model_text_delay(&m);
    } else {
        d["delay"] = m.delay;
    }
    if (m.has_identified) {
        d["identified"] = nb::make_tuple(m.id_lo, m.id_hi);
    }
    if (m.kind == MODEL_TEXT_EVERETT) {
        d["y_lo"] = m.y_lo;
        d["degree"] = m.degree;
        d["terms"] = std::vector<double>(m.terms, m.terms + m.nterms);
    } else if (m.kind == MODEL_TEXT_GRID) {
        d["y_lo"] = m.y_lo;
        d["knots"] = std::vector<double>(m.knots, m.knots + m.nknots);
        d["weights"] = std::vector<double>(m.weights, m.weights + m.nweights);
    } else if (m.kind == MODEL_TEXT_SPLINE) {
        d["values"] = std::vector<double>(m.values, m.values + m.nvalues);
        d["slopes"] = std::vector<double>(m.slopes, m.slopes + m.nslopes);
    } else {
        d["coeffs"] = std::vector<double>(m.coeffs, m.coeffs + m.ncoef);
    }
    if (m.ncreep > 0u) {
        d["creep_tau"] = std::vector<double>(m.creep_tau, m.creep_tau + m.ncreep);
        d["creep_weight"] = std::vector<double>(m.creep_weight, m.creep_weight + m.ncreep);
    }
    if (m.has_rate) {
        d["rate_tau"] = m.rate_tau;
        d["rate_weight"] = m.rate_weight;
    }
    return d;
}

/* A whole file's bytes read as a model: its dict, or the reader's message
 * (a str) naming path, line and field. */
nb::object model_parse(const nb::bytes &data, const std::string &path)
{
    model_text_t m;
    char msg[MODEL_TEXT_MSG_SIZE];
    if (model_text_parse(data.c_str(), data.size(), path.c_str(), &m, msg, sizeof msg) != 0) {
        return nb::str(msg);
    }
    return model_dict(m);
}

/* Copies v into a[0..cap) and sets *n to its length (the checks refuse a
 * length beyond cap before they read a). */
void copy_numbers(const std::vector<double> &v, double *a, size_t cap, size_t *n)
{
    std::memcpy(a, v.data(), (v.size() < cap ? v.size() : cap) * sizeof(double));
    *n = v.size();
}

/* A model from its parts, checked as the reader checks a file (ValueError
 * with the reason otherwise). */
model_text_t model_of(const std::string &kind, double lo, double hi, double delay,
                      const std::vector<double> &coeffs, double degree, double y_lo,
                      const std::vector<double> &terms, const std::vector<double> &creep_tau,
                      const std::vector<double> &creep_weight,
                      const std::vector<double> &identified = {},
                      const std::vector<double> &rate = {},
                      const std::vector<double> &knots = {},
                      const std::vector<double> &weights = {},
                      const std::vector<double> &values = {},
                      const std::vector<double> &slopes = {})
{
    model_text_t m;
    char msg[MODEL_TEXT_MSG_SIZE];
    std::memset(&m, 0, sizeof m);
    const KindName *named = kind_named(kind);
    if (named == nullptr) {
        throw nb::value_error("kind must be 'poly', 'everett', 'everett_grid' or 'spline'");
    }
    if (!(delay >= 0.0 && delay <= static_cast<double>(MODEL_TEXT_MAX_DELAY))) {
        throw nb::value_error("delay is not a delay of 0 to 1000000000 samples");
    }
    if (identified.size() != 0u && identified.size() != 2u) {
        throw nb::value_error("identified needs two values (LO HI)");
    }
    if (rate.size() != 0u && rate.size() != 2u) {
        throw nb::value_error("a rate term needs rate_tau and rate_weight (both or neither)");
    }
    if (rate.size() == 2u) { /* checked with the rest by model_text_check() */
        m.has_rate = 1;
        m.rate_tau = rate[0];
        m.rate_weight = rate[1];
    }
    m.kind = named->model_text;
    m.lo = lo;
    m.hi = hi;
    m.delay = static_cast<unsigned long>(delay);
    m.delay_fraction = delay - std::floor(delay);
    if (identified.size() == 2u) {
        m.has_identified = 1;
        m.id_lo = identified[0];
        m.id_hi = identified[1];
    }
    if (m.kind == MODEL_TEXT_EVERETT) {
        if (!(degree >= 1.0 && degree <= HYST_EVERETT_MAX_DEGREE) || degree != std::floor(degree)) {
            throw nb::value_error("degree is not a degree in 1..4");
        }
        m.degree = static_cast<unsigned>(degree);
        m.y_lo = y_lo;
        copy_numbers(terms, m.terms, HYST_EVERETT_TERMS, &m.nterms);
    } else if (m.kind == MODEL_TEXT_GRID) {
        m.y_lo = y_lo;
        copy_numbers(knots, m.knots, HYST_EVERETT_GRID_MAX_INTERVALS + 1u, &m.nknots);
        copy_numbers(weights, m.weights,
                     HYST_EVERETT_GRID_CELLS(HYST_EVERETT_GRID_MAX_INTERVALS), &m.nweights);
    } else if (m.kind == MODEL_TEXT_SPLINE) {
        copy_numbers(values, m.values, HYST_SPLINE_MAX_INTERVALS + 1u, &m.nvalues);
        copy_numbers(slopes, m.slopes, HYST_SPLINE_MAX_INTERVALS + 1u, &m.nslopes);
    } else {
        copy_numbers(coeffs, m.coeffs, HYST_MAX_DEGREE + 1u, &m.ncoef);
    }
    copy_numbers(creep_tau, m.creep_tau, MODEL_TEXT_CREEP_MAX_TERMS, &m.ncreep);
    copy_numbers(creep_weight, m.creep_weight, MODEL_TEXT_CREEP_MAX_TERMS, &m.ncreep_weights);
    if (model_text_check(&m, msg, sizeof msg) != 0) {
        throw nb::value_error(msg);
    }
    return m;
}

/* The file's text of a model (model_text_write()). */
std::string model_write(const std::string &kind, double lo, double hi, double delay,
                        const std::vector<double> &coeffs, double degree, double y_lo,
                        const std::vector<double> &terms, const std::vector<double> &creep_tau,
                        const std::vector<double> &creep_weight,
                        const std::vector<double> &identified, const std::vector<double> &rate,
                        const std::vector<double> &knots, const std::vector<double> &weights,
                        const std::vector<double> &values, const std::vector<double> &slopes)
{
    const model_text_t m = model_of(kind, lo, hi, delay, coeffs, degree, y_lo, terms, creep_tau,
                                    creep_weight, identified, rate, knots, weights, values,
                                    slopes);
    std::vector<char> buf(16384u);
    const size_t len = model_text_write(&m, buf.data(), buf.size());
    if (len == 0u) {
        raise_status(HYST_ERR_NOSPACE, "model file text too long");
    }
    return std::string(buf.data(), len);
}

/* A header's parts around a compensator's table: open (the guard, the
 * model's declaration and its creep term) or, open false, the close. */
std::string model_header(const std::string &name, bool open, const std::string &kind, double lo,
                         double hi, const std::vector<double> &coeffs, double degree,
                         double y_lo, const std::vector<double> &terms,
                         const std::vector<double> &creep_tau,
                         const std::vector<double> &creep_weight, const std::vector<double> &rate,
                         const std::vector<double> &knots, const std::vector<double> &weights,
                         const std::vector<double> &values, const std::vector<double> &slopes)
{
    if (!model_text_identifier(name.c_str()) || name.size() != std::strlen(name.c_str())) {
        throw nb::value_error(("'" + name + "' is not a C identifier").c_str());
    }
    std::vector<char> buf(32768u);
    size_t len = 0u;
    int over;
    if (open) {
        const model_text_t m =
            model_of(kind, lo, hi, 0.0, coeffs, degree, y_lo, terms, creep_tau, creep_weight, {},
                     rate, knots, weights, values, slopes);
        over = model_text_header_open(buf.data(), buf.size(), &len, name.c_str(), &m);
    } else {
        over = model_text_header_close(buf.data(), buf.size(), &len, name.c_str());
    }
    if (over != 0) {
        raise_status(HYST_ERR_NOSPACE, "header text too long");
    }
    return std::string(buf.data(), len);
}

/* A header's compensator table (model_text_header_table()), as `hyst header
 * --compensator` writes it between the header's open and close; rows: kind
 * everett only. Sizes beyond the tool's (intervals 2^20, rows 4096) are
 * refused before anything is allocated, the rest by the library. */
std::string model_header_table(const std::string &name, const std::string &kind, double lo,
                               double hi, const std::vector<double> &coeffs, double degree,
                               double y_lo, const std::vector<double> &terms, size_t intervals,
                               size_t rows, const std::vector<double> &values,
                               const std::vector<double> &slopes)
{
    if (!model_text_identifier(name.c_str()) || name.size() != std::strlen(name.c_str())) {
        throw nb::value_error(("'" + name + "' is not a C identifier").c_str());
    }
    if (intervals > (1u << 20) || rows > 4096u) {
        throw nb::value_error("intervals: at most 1048576 (per row); rows: at most 4096");
    }
    const model_text_t m =
        model_of(kind, lo, hi, 0.0, coeffs, degree, y_lo, terms, {}, {}, {}, {}, {}, {}, values,
                 slopes);
    std::vector<char> buf(model_text_header_table_size(&m, rows, intervals));
    size_t len = 0u;
    hyst_status_t st = HYST_OK;
    if (model_text_header_table(buf.data(), buf.size(), &len, name.c_str(), &m, rows, intervals,
                                0, &st) != 0) {
        raise_status(st != HYST_OK ? st : HYST_ERR_NOSPACE, "the compensator's table");
    }
    return std::string(buf.data(), len);
}

/* ---- fit's hold-out choice, the `hyst` tool's (tools/cli/fit_select.c) ---- */

/* A scored candidate as the dict fit() lists. */
nb::dict candidate_dict(const fit_candidate_t &c)
{
    const bool everett = c.kind == FIT_EVERETT;
    nb::dict d;
    d["kind"] = fit_kind_name(c.kind);
    d["degree"] = c.degree;
    d["t_degree"] = everett ? nb::cast(c.t_degree) : nb::none();
    d["delay"] = c.delay;
    d["widened"] = c.widened != 0;
    d["params"] = fit_parameters(c.kind, c.degree, c.t_degree);
    d["holdout_rms"] = c.holdout_rms;
    d["fit_rms"] = c.fit_rms;
    d["status_code"] = static_cast<int>(c.status);
    d["increasing"] = c.kind != FIT_POLY || c.fit.increasing != 0;
    d["creep_tau"] = c.creep.tau;
    d["creep_weight"] = c.creep.tau > 0 ? c.creep.weight : NAN;
    d["creep_holdout_rms"] = c.creep.tau > 0 ? c.creep.holdout_rms : NAN;
    return d;
}

/* The validation record (vx, vy) as fit_select.h takes it, from row skip
 * on (nullptr, the hold-out, when vx is empty): its drive copied into
 * vdrive, which the search interpolates in place by a fraction chosen. */
const fit_validation_t *validation(const In<double> &vx, const In<double> &vy, size_t skip,
                                   std::vector<double> &vdrive, fit_validation_t &v)
{
    if (vx.shape(0) == 0) {
        return nullptr;
    }
    if (vx.shape(0) != vy.shape(0)) {
        raise_status(HYST_ERR_ARG, "the validation record's x and y differ in length");
    }
    vdrive.assign(vx.data(), vx.data() + vx.shape(0));
    v.x = vdrive.data();
    v.y = vy.data();
    v.n = vx.shape(0);
    v.skip = skip;
    return &v;
}

/* One candidate (kind FIT_POLY, FIT_EVERETT, FIT_GRID or FIT_SPLINE (degree:
 * their intervals), degree, t_degree, delay)
 * scored as the automatic choice scores it (fit_score(): the hold-out
 * splits, or the validation record vx, vy when not empty), with its creep
 * term unless creep_tau < 0 (0: chosen). */
nb::dict score_candidate(const In<double> &x, const In<double> &y, int kind, unsigned degree,
                         unsigned t_degree, int method, double lo, double hi, size_t skip,
                         size_t delay, double creep_tau, const In<double> &vx,
                         const In<double> &vy)
{
    const hyst_ident_config_t base = ident_config(x, y, 0u, method, lo, hi, skip, 0u);
    std::vector<double> vdrive;
    fit_validation_t v;
    const fit_validation_t *val = validation(vx, vy, skip, vdrive, v);
    fit_candidate_t c;
    std::memset(&c, 0, sizeof c);
    c.kind = fit_kind(kind);
    c.degree = degree;
    c.t_degree = t_degree;
    c.delay = delay;
    fit_score(&base, x.data(), y.data(), x.shape(0), val, creep_tau, &c);
    return candidate_dict(c);
}

/* Every candidate of the kinds (FIT_POLY | FIT_EVERETT | FIT_GRID | FIT_SPLINE) at the delay given
 * or, delay < 0, at the delays fit_search() chooses among, scored on the
 * hold-out splits (or the validation record vx, vy when not empty): a list
 * of dicts, the index chosen (None: none), whether with its creep term, the
 * chosen one's domain when widened (fit_chosen_domain(), else None) and the
 * search's figures (with a validation record, "vx": its drive interpolated
 * by the fraction chosen, or None). */
nb::tuple select_candidates(const In<double> &x, const In<double> &y, int kinds, int method, double lo,
                 double hi, size_t skip, long delay, long t_degree, double creep_tau,
                 double rate_tau, const In<double> &vx, const In<double> &vy)
{
    const size_t n = x.shape(0);
    const hyst_ident_config_t base =
        ident_config(x, y, 0u, method, lo, hi, skip, delay < 0 ? 0u : static_cast<size_t>(delay));
    std::vector<fit_candidate_t> cand(FIT_SEARCH_CANDIDATES);
    std::vector<double> drive(x.data(), x.data() + n); /* interpolated by a fraction chosen */
    std::vector<double> vdrive;
    fit_validation_t v;
    const fit_validation_t *val = validation(vx, vy, skip, vdrive, v);
    fit_found_t found;
    check(fit_search(&base, kinds,
                     t_degree < 0 ? FIT_ANY_T_DEGREE : static_cast<unsigned>(t_degree), creep_tau,
                     delay < 0, drive.data(), y.data(), n, val, cand.data(), cand.size(),
                     &found),
          "select");
    const size_t count = found.count, best = found.best;
    const int with_creep = found.with_creep;
    nb::list out;
    for (size_t i = 0u; i < count; ++i) {
        out.append(candidate_dict(cand[i]));
    }
    double dom_lo = 0.0, dom_hi = 0.0; /* the chosen one's domain when widened */
    const bool widened = best != (size_t)-1 &&
                         fit_chosen_domain(&cand[best], drive.data(), skip, n, &dom_lo, &dom_hi);
    nb::dict search;
    search["max_delay"] = found.max_delay;
    search["delay_fraction"] = found.delay_fraction;
    search["integer_delay"] = found.integer_delay;
    search["integer_holdout"] = found.integer_holdout;
    search["x"] = found.delay_fraction > 0.0 ? nb::cast(drive) : nb::none();
    search["vx"] = found.delay_fraction > 0.0 && val != nullptr ? nb::cast(vdrive) : nb::none();
    /* a rate term scored on the choice's hold-out, as hyst fit --rate scores it */
    search["with_rate"] = false;
    if (rate_tau >= 0 && best != (size_t)-1) {
        fit_candidate_t with_rate;
        const int kept = fit_rate_search(&base, drive.data(), y.data(), n, val, &cand[best],
                                         with_creep, rate_tau, &with_rate);
        search["with_rate"] = kept != 0;
        search["rate_tau"] = with_rate.creep.rate_tau;
        search["rate_holdout_rms"] = with_rate.creep.holdout_rms;
        search["rate_without"] = fit_option_rms(&cand[best], with_creep);
    }
    return nb::make_tuple(out, best == (size_t)-1 ? nb::none() : nb::cast(best),
                          with_creep != 0,
                          widened ? nb::object(nb::make_tuple(dom_lo, dom_hi)) : nb::none(),
                          search);
}

/* The delay of one model (kind FIT_POLY, FIT_EVERETT (t_degree), FIT_GRID or FIT_SPLINE,
 * degree, no creep term) as `hyst fit --degree D` without --delay chooses it
 * (fit_given_delay()): delay (whole samples), delay_fraction, max_delay,
 * integer_holdout, and x: the drive interpolated by the fraction, or None
 * (scored on the validation record vx, vy when not empty; vx: its drive
 * interpolated, or None). */
nb::dict given_delay(const In<double> &x, const In<double> &y, int kind, unsigned degree,
                     unsigned t_degree, int method, double lo, double hi, size_t skip,
                     const In<double> &vx, const In<double> &vy)
{
    const size_t n = x.shape(0);
    const hyst_ident_config_t base = ident_config(x, y, degree, method, lo, hi, skip, 0u);
    std::vector<double> drive(x.data(), x.data() + n);
    std::vector<double> vdrive;
    fit_validation_t v;
    const fit_validation_t *val = validation(vx, vy, skip, vdrive, v);
    fit_found_t found;
    size_t delay = 0u;
    check(fit_given_delay(&base, fit_kind(kind), t_degree, drive.data(), y.data(), n, val,
                          &delay, &found),
          "given_delay");
    nb::dict d;
    d["delay"] = delay;
    d["delay_fraction"] = found.delay_fraction;
    d["max_delay"] = found.max_delay;
    d["integer_holdout"] = found.integer_holdout;
    d["x"] = found.delay_fraction > 0.0 ? nb::cast(drive) : nb::none();
    d["vx"] = found.delay_fraction > 0.0 && val != nullptr ? nb::cast(vdrive) : nb::none();
    return d;
}

/* What the hold-out's last third of x[skip .. end) tests a choice on
 * (fit_holdout_excitation()): dict fitted_lo, fitted_hi, holdout_n, beyond, span,
 * minor, noise (None: not resolved). */
nb::dict excitation_dict(const fit_excitation_t &e)
{
    nb::dict d;
    d["fitted_lo"] = e.fitted_lo;
    d["fitted_hi"] = e.fitted_hi;
    d["holdout_n"] = e.holdout_n;
    d["beyond"] = e.beyond;
    d["span"] = e.span;
    d["minor"] = e.minor;
    d["noise"] = std::isfinite(e.noise) ? nb::cast(e.noise) : nb::none();
    return d;
}

/* hyst fit's check of the record x, y before fitting, pairs x[skip + i] with
 * y[skip + delay + i] (fit_record_check()): dict fault (what is wrong: "ok",
 * "infinite_input", "infinite_output", "no_sample", "constant_input",
 * "constant_output" or "falling"), pairs, at, value, correlation, minor. */
nb::dict record_check(const In<double> &x, const In<double> &y, size_t skip, size_t delay)
{
    fit_record_t r;
    const int fault = fit_record_check(x.data(), x.shape(0), y.data(), y.shape(0), skip, delay,
                                       &r);
    nb::dict d;
    d["fault"] = fit_record_fault_name(fault);
    d["pairs"] = r.pairs;
    d["at"] = r.at;
    d["value"] = r.value;
    d["correlation"] = r.correlation;
    d["minor"] = r.minor;
    return d;
}

nb::dict excitation(const In<double> &x, const In<double> &y, size_t skip, size_t end,
                    size_t delay)
{
    fit_excitation_t e;
    if (end > x.shape(0) || skip > end || end + delay > y.shape(0)) {
        throw nb::value_error("excitation: skip <= end <= len(x), end + delay <= len(y) needed");
    }
    fit_holdout_excitation(x.data(), y.data(), skip, end, delay, &e);
    return excitation_dict(e);
}

/* What a validation record (vx, vy from row skip, the output delay rows
 * later) tests the choice on against x[skip .. end), the record fitted
 * (fit_validation_excitation()): the same dict. */
nb::dict validation_excitation(const In<double> &x, size_t skip, size_t end,
                               const In<double> &vx, const In<double> &vy, size_t delay)
{
    std::vector<double> vdrive;
    fit_validation_t v;
    fit_excitation_t e;
    if (end > x.shape(0) || skip > end || vx.shape(0) == 0) {
        throw nb::value_error("validation_excitation: skip <= end <= len(x), a record needed");
    }
    fit_validation_excitation(x.data(), skip, end, validation(vx, vy, skip, vdrive, v), delay,
                              &e);
    return excitation_dict(e);
}

/* fit_choose() over candidates given as dicts (kind, degree, t_degree,
 * holdout_rms and, optionally, widened, creep_tau, creep_holdout_rms): the rule
 * select() applies, alone. */
nb::tuple choose(const nb::list &cands, double creep_tau)
{
    std::vector<fit_candidate_t> cand(nb::len(cands));
    for (size_t i = 0u; i < cand.size(); ++i) {
        const nb::dict d = nb::cast<nb::dict>(cands[i]);
        fit_candidate_t &c = cand[i];
        std::memset(&c, 0, sizeof c);
        const KindName *kind = kind_named(nb::cast<std::string>(d["kind"]));
        c.kind = kind != nullptr ? kind->fit : FIT_POLY;
        c.degree = nb::cast<unsigned>(d["degree"]);
        c.t_degree = d.contains("t_degree") && !d["t_degree"].is_none()
                         ? nb::cast<unsigned>(d["t_degree"])
                         : 0u;
        c.holdout_rms = nb::cast<double>(d["holdout_rms"]);
        c.widened = d.contains("widened") && nb::cast<bool>(d["widened"]) ? 1 : 0;
        c.creep.tau = d.contains("creep_tau") ? nb::cast<double>(d["creep_tau"]) : 0.0;
        c.creep.holdout_rms =
            d.contains("creep_holdout_rms") ? nb::cast<double>(d["creep_holdout_rms"]) : NAN;
    }
    size_t best = 0u;
    int with_creep = 0;
    fit_choose(cand.data(), cand.size(), creep_tau, &best, &with_creep);
    return nb::make_tuple(best == (size_t)-1 ? nb::none() : nb::cast(best), with_creep != 0);
}

/*
 * Binds process(x, out=None) of class C: numpy arrays of the input dtype map
 * without a copy, other arrays and sequences go through numpy.asarray.
 */
template <class X, class C, class Cls> void def_process(Cls &cls)
{
    cls.def("process", &C::process, "x"_a, "out"_a = nb::none(),
            "A block of samples (bit-identical to step()); returns the outputs, in `out` if "
            "given. The status the block call returned is `block_status`.");
    cls.def(
        "process",
        [](C &self, nb::handle x, nb::handle out) {
            const char *dtype = std::is_floating_point_v<X>
                                    ? (sizeof(X) == 4u ? "float32" : "float64")
                                    : (sizeof(X) == 2u ? "uint16" : "uint32");
            nb::module_ np = nb::module_::import_("numpy");
            nb::object a = np.attr("asarray")(x);
            const int ndim = nb::cast<int>(a.attr("ndim"));
            if (ndim != 1) {
                throw nb::value_error(("process takes a 1-d array of samples, not a " +
                                       std::to_string(ndim) + "-d one")
                                          .c_str());
            }
            if constexpr (!std::is_floating_point_v<X>) {
                /* codes: whole numbers the code type holds, as step() takes
                 * them; numpy's cast would wrap -1 to full scale and NaN to 0 */
                nb::object f = np.attr("asarray")(a, "dtype"_a = "float64");
                nb::object ok = np.attr("isfinite")(f) & (f.attr("__eq__")(np.attr("floor")(f))) &
                                (f.attr("__ge__")(0)) &
                                (f.attr("__le__")(static_cast<double>(std::numeric_limits<X>::max())));
                /* numpy's scalars to Python's: bool, int */
                if (!nb::cast<bool>(np.attr("all")(ok).attr("__bool__")())) {
                    const size_t i = nb::cast<size_t>(np.attr("argmin")(ok).attr("__index__")());
                    const double v =
                        nb::cast<double>(f.attr("__getitem__")(i).attr("__float__")());
                    char msg[128];
                    (void)std::snprintf(msg, sizeof msg,
                                        "code %.17g at index %zu is not a whole number in 0..%lu",
                                        v, i,
                                        static_cast<unsigned long>(std::numeric_limits<X>::max()));
                    throw nb::value_error(msg);
                }
            }
            a = np.attr("ascontiguousarray")(a, "dtype"_a = dtype);
            return self.process(nb::cast<In<X>>(a), out);
        },
        "x"_a, "out"_a = nb::none());
}

template <class T> void bind_real(nb::module_ &m, const char *model, const char *pi)
{
    using R = Real<T>;
    nb::class_<R, Tcm> model_cls(m, model);
    model_cls
        .def(nb::init<const std::vector<double> &, double, double, size_t, bool, long long>(),
             "coeffs"_a, "lo"_a, "hi"_a, "capacity"_a, "inverse"_a, "intervals"_a = 0)
        .def(nb::init<const std::vector<double> &, const std::vector<double> &, size_t, bool>(),
             "xs"_a, "ys"_a, "capacity"_a, "inverse"_a)
        .def(nb::init<unsigned, double, double, double, const std::vector<double> &, size_t,
                      bool, long long, std::optional<long long>>(),
             "degree"_a, "lo"_a, "hi"_a, "y_lo"_a, "terms"_a, "capacity"_a, "inverse"_a = false,
             "intervals"_a = 0, "rows"_a = nb::none())
        .def(nb::init<const std::vector<double> &, const std::vector<double> &, double, size_t,
                      bool>(),
             "knots"_a, "weights"_a, "y_lo"_a, "capacity"_a, "inverse"_a = false)
        .def(nb::init<double, double, const std::vector<double> &, const std::vector<double> &,
                      size_t, bool, long long>(),
             "lo"_a, "hi"_a, "values"_a, "slopes"_a, "capacity"_a, "inverse"_a = false,
             "intervals"_a = 0)
        .def("step", &R::step, "x"_a, "One sample in, one output out.")
        .def_prop_rw("deadband", [](const R &s) { return s.deadband; }, &R::set_deadband)
        .def_prop_ro("output", [](const R &s) { return Ops<T>::output(&s.S); })
        .def_prop_ro("input", [](const R &s) { return Ops<T>::input(&s.S); })
        .def_prop_ro("error_bound", [](const R &s) { return Ops<T>::error_bound(&s.S); })
        .def_prop_ro("rounding_bound", [](const R &s) { return Ops<T>::rounding_bound(&s.S); })
        .def_ro("inverse", &R::inverse)
        .def_ro("intervals", &R::intervals)
        .def_ro("rows", &R::rows)
        .def_prop_ro("inverse_error",
                     [](const R &s) {
                         return s.intervals > 0u ? static_cast<double>(hyst_curve_inverse_error(&s.inv))
                                                 : 0.0;
                     })
        .def_prop_ro(
            "table",
            [](const R &s) {
                if (s.intervals == 0u) {
                    raise_status(HYST_ERR_ARG, "no table: only a tabulated compensator has one");
                }
                return std::vector<double>(s.table.begin(), s.table.end());
            },
            "The tabulated compensator's table as firmware holds it (its numbers as float64: "
            "exact).")
        .def_prop_ro(
            "table_seal",
            [](const R &s) {
                hyst_table_seal_t seal;
                if (s.intervals == 0u) {
                    raise_status(HYST_ERR_ARG, "no table: only a tabulated compensator has one");
                }
                check(hyst_curve_table_seal(&s.inv, &seal), "table seal");
                return std::make_pair(static_cast<unsigned long>(seal.crc & 0xFFFFFFFFul),
                                      static_cast<double>(seal.max_err));
            },
            "hyst_curve_table_seal() of the table: (crc, max_err).")
        .def("set_creep", &R::set_creep, "tau"_a, "weight"_a,
             "A creep term (hyst/creep.h): lags of the model's input of time constants tau "
             "(samples) and weights weight, every lag at lo; empty lists remove it. Puts the "
             "model back at rest.")
        .def("set_rate", &R::set_rate, "tau"_a.none(), "weight"_a.none(),
             "A rate term (hyst/rate.h): the output plus weight times a low-pass, of time "
             "constant tau samples, of the model input's change per sample, at rest at lo; "
             "both None remove it. Puts the model back at rest.")
        .def_ro("rate_tau", &R::rate_tau)
        .def_ro("rate_weight", &R::rate_weight)
        .def_ro("creep_tau", &R::creep_tau)
        .def_ro("creep_weight", &R::creep_weight)
        .def_prop_ro("creep_output",
                     [](const R &s) { return s.has_creep ? Ops<T>::creep_output(&s.creep) : T(0); },
                     "The creep's contribution to the next sample (0 without a creep term).")
        .def_prop_ro("dtype", [](const R &) { return Ops<T>::dtype; });
    def_process<T, R>(model_cls);

    using P = Pi<T>;
    nb::class_<P> pi_cls(m, pi);
    pi_cls
        .def(nb::init<const std::vector<double> &, const std::vector<double> &>(),
             "thresholds"_a, "weights"_a)
        .def("inverse", &P::inverse, "The inverse PI model (maps outputs back to inputs).")
        .def("step", &P::step, "x"_a)
        .def("reset", [](P &s) { hyst_pi_reset(&s.P); })
        .def("clear_events", [](P &s) { hyst_pi_clear_events(&s.P); })
        .def_prop_ro("status", [](const P &s) { return hyst_pi_status(&s.P); })
        .def_prop_ro("events", [](const P &s) { return hyst_pi_events(&s.P); })
        .def_prop_ro("output", [](const P &s) { return Ops<T>::pi_output(&s.P); })
        .def_prop_ro("size", [](const P &s) { return hyst_pi_size(&s.P); })
        .def_prop_ro("thresholds", &P::thresholds)
        .def_prop_ro("weights", &P::weights)
        .def_ro("block_status", &P::block_status)
        .def_prop_ro("dtype", [](const P &) { return Ops<T>::dtype; });
    def_process<T, P>(pi_cls);
}

template <class T> void bind_creep(nb::module_ &m, const char *name)
{
    using C = Creep<T>;
    nb::class_<C> cls(m, name, "A creep term alone (hyst/creep.h): lags of a drive, weighted.");
    cls.def(nb::init<const std::vector<double> &, const std::vector<double> &, double>(),
            "tau"_a, "weight"_a, "x_rest"_a)
        .def("step", &C::step, "x"_a,
             "The contribution c[n] (from the drives before x), then takes x in.")
        .def("reset", &C::reset, "x_rest"_a = nb::none(),
             "Every lag at x_rest (the one given at init when None).")
        .def("clear_events", [](C &s) { hyst_creep_clear_events(&s.C); })
        .def_prop_ro("output", [](const C &s) { return Ops<T>::creep_output(&s.C); },
                     "c[n] of the next sample, whatever drive it takes.")
        .def_prop_ro("status", [](const C &s) { return hyst_creep_status(&s.C); })
        .def_prop_ro("events", [](const C &s) { return hyst_creep_events(&s.C); })
        .def_prop_ro("size", [](const C &s) { return hyst_creep_size(&s.C); })
        .def_ro("tau", &C::tau)
        .def_ro("weight", &C::weight)
        .def_ro("x_rest", &C::x_rest)
        .def_ro("block_status", &C::block_status)
        .def_prop_ro("dtype", [](const C &) { return Ops<T>::dtype; });
    def_process<T, C>(cls);
}

} // namespace

NB_MODULE(_hyst, m)
{
    m.doc() = "The hyst C library (instances owning their memory); see the package hyst.";
    m.attr("__version__") = HYST_VERSION_STRING;
    m.attr("MAX_DEGREE") = HYST_MAX_DEGREE;
    m.attr("EVERETT_MAX_DEGREE") = HYST_EVERETT_MAX_DEGREE;
    m.attr("SPLINE_MAX_INTERVALS") = HYST_SPLINE_MAX_INTERVALS;
    m.attr("CODE_MAX") = static_cast<unsigned long>(HYST_CODE_MAX);
    m.attr("INV_TABLE") = static_cast<unsigned long>(HYST_INV_TABLE);
    m.attr("EVERETT_INV_ROWS") = static_cast<unsigned long>(HYST_EVERETT_INV_ROWS);
    m.attr("EVERETT_INV_INTERVALS") = static_cast<unsigned long>(HYST_EVERETT_INV_INTERVALS);
    m.attr("SNAPSHOT_VERSION") = HYST_SNAPSHOT_VERSION;
    m.attr("EVENT_NONFINITE") = HYST_EVENT_NONFINITE;
    m.attr("EVENT_CLAMPED") = HYST_EVENT_CLAMPED;
    m.attr("EVENT_FULL") = HYST_EVENT_FULL;
    m.def("status_str", &hyst_status_str, "status"_a, "The library's name of a status code.");

    nb::enum_<hyst_status_t>(m, "Status", nb::is_arithmetic())
        .value("OK", HYST_OK)
        .value("WARN_CLAMPED", HYST_WARN_CLAMPED)
        .value("WARN_FULL", HYST_WARN_FULL)
        .value("ERR_NULL", HYST_ERR_NULL)
        .value("ERR_DOMAIN", HYST_ERR_DOMAIN)
        .value("ERR_DEGREE", HYST_ERR_DEGREE)
        .value("ERR_CAPACITY", HYST_ERR_CAPACITY)
        .value("ERR_COEFF", HYST_ERR_COEFF)
        .value("ERR_NOT_INCREASING", HYST_ERR_NOT_INCREASING)
        .value("ERR_NONFINITE", HYST_ERR_NONFINITE)
        .value("ERR_ARG", HYST_ERR_ARG)
        .value("ERR_NOSPACE", HYST_ERR_NOSPACE)
        .value("ERR_SINGULAR", HYST_ERR_SINGULAR)
        .value("ERR_FORMAT", HYST_ERR_FORMAT)
        .value("ERR_CRC", HYST_ERR_CRC)
        .value("ERR_VERSION", HYST_ERR_VERSION)
        .value("ERR_CURVE", HYST_ERR_CURVE)
        .value("ERR_BREAKPOINTS", HYST_ERR_BREAKPOINTS)
        .value("ERR_WEIGHTS", HYST_ERR_WEIGHTS)
        .value("ERR_NOT_INVERTIBLE", HYST_ERR_NOT_INVERTIBLE)
        .value("ERR_LAYOUT", HYST_ERR_LAYOUT)
        .value("ERR_OVERLAP", HYST_ERR_OVERLAP)
        .value("ERR_BUSY", HYST_ERR_BUSY)
        .value("ERR_ILL_CONDITIONED", HYST_ERR_ILL_CONDITIONED)
        .value("ERR_NOT_MONOTONE", HYST_ERR_NOT_MONOTONE);

    nb::class_<Tcm>(m, "Tcm", "What every TCM instance has (model, compensator, code model).")
        .def("reset", &Tcm::reset,
             "Back at rest: A0 = (lo, f0(lo)), and a creep term's lags at lo.")
        .def("clear_events", [](Tcm &s) { hyst_clear_events(&s.S); })
        .def("save", &Tcm::save,
             "Snapshot of the memory (bytes, the library's format; with a creep term, its "
             "lags' snapshot after it).")
        .def("restore", &Tcm::restore, "b"_a,
             "Restores a snapshot taken with the same curve (and creep term): all or nothing.")
        .def_prop_ro("status", [](const Tcm &s) { return hyst_status(&s.S); })
        .def_prop_ro("events", [](const Tcm &s) { return hyst_events(&s.S); })
        .def_prop_ro("tp_count", [](const Tcm &s) { return hyst_tp_count(&s.S); })
        .def_prop_ro("ltp_count", [](const Tcm &s) { return hyst_ltp_count(&s.S); })
        .def_prop_ro("rtp_count", [](const Tcm &s) { return hyst_rtp_count(&s.S); })
        .def_prop_ro("rising", [](const Tcm &s) { return hyst_rising(&s.S) != 0; })
        .def_prop_ro("capacity", [](const Tcm &s) { return hyst_capacity(&s.S); })
        .def_ro("block_status", &Tcm::block_status)
        .def_prop_ro("kind", [](const Tcm &s) { return s.kind; })
        .def_ro("coeffs", &Tcm::coeffs)
        .def_ro("terms", &Tcm::terms)
        .def_ro("knots", &Tcm::knots)
        .def_ro("weights", &Tcm::weights)
        .def_ro("values", &Tcm::values)
        .def_ro("slopes", &Tcm::slopes)
        .def_ro("lo", &Tcm::lo)
        .def_ro("hi", &Tcm::hi)
        .def_ro("y_lo", &Tcm::y_lo);

    bind_real<float>(m, "ModelF32", "PIF32");
    bind_real<double>(m, "ModelF64", "PIF64");
    bind_creep<float>(m, "CreepF32");
    bind_creep<double>(m, "CreepF64");
    m.attr("CREEP_MAX_TERMS") = static_cast<unsigned long>(HYST_CREEP_MAX_TERMS);

    nb::class_<Code, Tcm> code_cls(m, "CodeModel");
    code_cls
        .def(nb::init<const std::vector<double> &, double, double, unsigned long, unsigned long,
                      size_t>(),
             "coeffs"_a, "lo"_a, "hi"_a, "code_lo"_a, "code_hi"_a, "capacity"_a)
        .def("step", &Code::step, "code"_a)
        .def_prop_rw("deadband", [](const Code &s) { return s.deadband; }, &Code::set_deadband)
        .def_prop_ro("output", [](const Code &s) { return hyst_code_output(&s.S); })
        .def_prop_ro("input", [](const Code &s) { return hyst_code_input(&s.S); })
        .def_prop_ro("error_bound", [](const Code &s) { return hyst_code_error_bound(&s.S); })
        .def_prop_ro("rounding_bound", [](const Code &s) { return hyst_code_rounding_bound(&s.S); })
        .def_ro("code_lo", &Code::code_lo)
        .def_ro("code_hi", &Code::code_hi)
        .def_prop_ro("dtype", [](const Code &) { return "float32"; });
    def_process<hyst_code_word_t, Code>(code_cls);

    m.def("fit", &fit, "x"_a, "y"_a, "degree"_a, "method"_a, "lo"_a, "hi"_a, "skip"_a,
          "delay"_a);
    m.def("holdout", &holdout, "model"_a, "x"_a, "y"_a, "skip"_a, "delay"_a, "first"_a,
          "creep_tau"_a = -1.0, "rate_tau"_a = -1.0,
          "A fresh float64 model run over the record as hyst fit scores it: its RMS error from "
          "sample first on and, creep_tau >= 0 (0: no lag) or rate_tau > 0, the creep lag and "
          "rate term fitted to its residual.");
    m.def("creep_score", &creep_score, "u"_a, "r"_a, "train"_a, "x_rest"_a, "tau"_a,
          "The creep term hyst fit fits to a model's inputs u and residual r.");
    m.def("model_parse", &model_parse, "data"_a, "path"_a,
          "A model file's bytes read by the format's one reader: its dict, or the message.");
    m.def("model_write", &model_write, "kind"_a, "lo"_a, "hi"_a, "delay"_a, "coeffs"_a,
          "degree"_a, "y_lo"_a, "terms"_a, "creep_tau"_a, "creep_weight"_a,
          "identified"_a = std::vector<double>(), "rate"_a = std::vector<double>(),
          "knots"_a = std::vector<double>(), "weights"_a = std::vector<double>(),
          "values"_a = std::vector<double>(), "slopes"_a = std::vector<double>(),
          "A model file's text (ValueError for what the reader would refuse); rate: "
          "(rate_tau, rate_weight), or empty; knots, weights: kind everett_grid's; values, "
          "slopes: kind spline's.");
    m.def("model_header", &model_header, "name"_a, "open"_a, "kind"_a, "lo"_a, "hi"_a,
          "coeffs"_a, "degree"_a, "y_lo"_a, "terms"_a, "creep_tau"_a, "creep_weight"_a,
          "rate"_a = std::vector<double>(), "knots"_a = std::vector<double>(),
          "weights"_a = std::vector<double>(), "values"_a = std::vector<double>(),
          "slopes"_a = std::vector<double>(),
          "A firmware header's opening (the model) or close, as `hyst header` writes them.");
    m.def("model_header_table", &model_header_table, "name"_a, "kind"_a, "lo"_a, "hi"_a,
          "coeffs"_a, "degree"_a, "y_lo"_a, "terms"_a, "intervals"_a, "rows"_a,
          "values"_a = std::vector<double>(), "slopes"_a = std::vector<double>(),
          "A firmware header's compensator table, as `hyst header --compensator` writes it "
          "(kind spline: values, slopes; how firmware builds it, its size).");
    m.def("select", &select_candidates, "x"_a, "y"_a, "kinds"_a, "method"_a, "lo"_a, "hi"_a, "skip"_a,
          "delay"_a, "t_degree"_a, "creep_tau"_a, "rate_tau"_a, "vx"_a, "vy"_a,
          "hyst fit's automatic choice (fit_search(); delay < 0: chosen, scaled to the drive and "
          "to a fraction of a sample): (candidates, index chosen, with creep, the chosen one's "
          "domain (lo, hi) when widened, else None, and the search: max_delay, delay_fraction, "
          "integer_delay, integer_holdout, x: the drive interpolated by the fraction, or None; "
          "scored on the validation record vx, vy unless empty, vx its drive interpolated).");
    m.def("score", &score_candidate, "x"_a, "y"_a, "kind"_a, "degree"_a, "t_degree"_a, "method"_a,
          "lo"_a, "hi"_a, "skip"_a, "delay"_a, "creep_tau"_a, "vx"_a, "vy"_a,
          "One candidate scored as hyst fit scores it (fit_score(); on the validation record "
          "vx, vy unless empty): its dict.");
    m.def("given_delay", &given_delay, "x"_a, "y"_a, "kind"_a, "degree"_a, "t_degree"_a,
          "method"_a, "lo"_a, "hi"_a, "skip"_a, "vx"_a, "vy"_a,
          "The delay of one model as hyst fit --degree D without --delay chooses it "
          "(fit_given_delay(); on the validation record vx, vy unless empty): dict delay, "
          "delay_fraction, max_delay, integer_holdout, x, vx.");
    m.def("excitation", &excitation, "x"_a, "y"_a, "skip"_a, "end"_a, "delay"_a,
          "What hyst fit's hold-out tests the choice on (fit_holdout_excitation(); the output "
          "of x[k] is y[k + delay]): dict fitted_lo, fitted_hi, holdout_n, beyond, span, minor, "
          "noise (the outputs' noise floor, fit_noise_floor(); None: not resolved).");
    m.def("validation_excitation", &validation_excitation, "x"_a, "skip"_a, "end"_a, "vx"_a,
          "vy"_a, "delay"_a,
          "What a validation record tests the choice on (fit_validation_excitation()): the "
          "same dict.");
    m.attr("FIT_HOLDOUT_MIN_SPAN") = FIT_HOLDOUT_MIN_SPAN;
    m.def("record_check", &record_check, "x"_a, "y"_a, "skip"_a, "delay"_a,
          "hyst fit's check of a record before fitting (fit_record_check()): dict fault "
          "(\"ok\", \"infinite_input\", \"infinite_output\", \"no_sample\", "
          "\"constant_input\", \"constant_output\", \"falling\"), pairs, at, value, "
          "correlation, minor.");
    m.def("choose", &choose, "candidates"_a, "creep_tau"_a = -1.0,
          "hyst fit's rule (fit_choose()) over scored candidates: (index or None, with creep).");
    m.attr("FIT_POLY") = static_cast<int>(FIT_POLY);
    m.attr("FIT_EVERETT") = static_cast<int>(FIT_EVERETT);
    m.attr("FIT_GRID") = static_cast<int>(FIT_GRID);
    m.attr("FIT_SPLINE") = static_cast<int>(FIT_SPLINE);
    m.attr("FIT_MAX_DELAY") = static_cast<unsigned long>(FIT_MAX_DELAY);
    m.attr("FIT_PARSIMONY") = FIT_PARSIMONY;
    m.attr("FIT_RESOLUTION") = FIT_RESOLUTION;
    m.attr("FIT_CREEP_PARAMETERS") = static_cast<unsigned>(FIT_CREEP_PARAMETERS);
    m.def("fit_everett", &fit_everett, "x"_a, "y"_a, "degree"_a, "lo"_a, "hi"_a, "skip"_a,
          "delay"_a, "t_degree"_a = -1);
    m.def("poly_from_everett", &poly_from_everett, "degree"_a, "lo"_a, "hi"_a, "y_lo"_a,
          "terms"_a);
    m.attr("FIT_GRID_UNDETERMINED") = nb::str(fit_grid_undetermined);
    m.def("fit_grid", &fit_grid, "x"_a, "y"_a, "intervals"_a, "lo"_a, "hi"_a, "skip"_a,
          "delay"_a);
    m.def("fit_spline", &fit_spline, "x"_a, "y"_a, "intervals"_a, "lo"_a, "hi"_a, "skip"_a,
          "delay"_a);
}
