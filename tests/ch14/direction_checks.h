// The checks every direction sampler of chapter 14 is held to (lights, and materials that can be
// evaluated; included as "ch14/direction_checks.h"): directions drawn from it are binned on the
// sphere of directions about a fixed axis, and compared by chi-square with the counts expected
// from its pdf() integrated numerically over each bin; the same integrals, summed, say whether
// the pdf integrates to 1 over the directions the sampler covers.
//
// Bins: x = 1 - cos theta in [0, x_max) (theta from the axis) times the azimuth phi in [0, 2 pi),
// nx by nphi cells, plus one last bin for directions beyond x_max. Since d omega = dx dphi, a
// bin's probability is the plain integral of pdf(x, phi) over its rectangle. x is computed as
// |w - axis|^2 / 2, which does not cancel for directions near the axis (a far sphere light's
// whole cone has x below 1e-4), and everything is done in double whatever rt::real is.
//
// Integration: a light's pdf jumps at its outline (to 0, or to the sky's density behind it),
// which a fixed rule cannot integrate well. So each bin is integrated by adaptive Simpson: a
// cell is split into quarters, recursively, until its 3 x 3 Simpson estimate agrees with the sum
// of its quarters' to 1e-4 (or it sees pdf 0 everywhere while a drawn direction lies in it: a
// light's corner poking in between the points), down to 1/256 of a bin's side. For every density
// tested with it the bins sum to 1 within 5e-5 (the check allows 1e-3): far below the
// chi-square's noise (a bin of 500 expected counts fluctuates by 4.5 %), and far below what a
// wrong constant (2 %, 5 %: caught) or a missing cosine changes.
#pragma once

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ch03/sampling_checks.h"
#include "rt/core/rng.h"
#include "rt/core/vec3.h"
#include "statistics.h"

namespace rt_test::direction_checks {

using rt::real;
using rt::vec3;
using sampling_checks::two_pi;

using dvec = std::array<double, 3>;

inline dvec to_double(const vec3& v) {
    return {double(v.x()), double(v.y()), double(v.z())};
}
inline double ddot(const dvec& a, const dvec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline dvec dunit(const dvec& v) {
    double l = std::sqrt(ddot(v, v));
    return {v[0] / l, v[1] / l, v[2] / l};
}

// Directions about a unit axis, binned in (x = 1 - cos theta, phi).
class direction_bins {
  public:
    direction_bins(const vec3& axis_, double x_max_, int nx_, int nphi_)
        : axis(dunit(to_double(axis_))), x_max(x_max_), nx(nx_), nphi(nphi_) {
        // Any two unit vectors perpendicular to the axis and to each other (Duff et al.).
        double sign = std::copysign(1.0, axis[2]);
        double a    = -1 / (sign + axis[2]);
        double b    = axis[0] * axis[1] * a;
        e1          = {1 + sign * axis[0] * axis[0] * a, sign * b, -sign * axis[0]};
        e2          = {b, sign + axis[1] * axis[1] * a, -axis[1]};
    }

    int count() const { return nx * nphi + 1; }
    int outside() const { return nx * nphi; }  // the bin of directions beyond x_max

    // 1 - cos theta of a direction (any length), without cancellation near the axis.
    double x_of(const vec3& w) const {
        dvec u = dunit(to_double(w));
        dvec d = {u[0] - axis[0], u[1] - axis[1], u[2] - axis[2]};
        return ddot(d, d) / 2;
    }
    double phi_of(const vec3& w) const {
        dvec u     = to_double(w);
        double phi = std::atan2(ddot(u, e2), ddot(u, e1));
        return phi < 0 ? phi + two_pi : phi;
    }

    std::size_t index(const vec3& w) const {
        double x = x_of(w);
        if (!(x >= 0 && x < x_max)) return std::size_t(outside());
        std::size_t i = sampling_checks::cell(x / x_max, nx);
        std::size_t j = sampling_checks::cell(phi_of(w) / two_pi, nphi);
        return i * std::size_t(nphi) + j;
    }

    // Where drawn directions fell, as (x, phi), one list per bin: hints for the integration.
    using hints = std::vector<std::vector<std::array<double, 2>>>;

    // The integral of pdf(direction) over every bin (0 for the last one), in solid angle. A
    // part of a bin where Simpson's rule sees pdf 0 but a drawn direction (a hint) lies is split
    // further too: a corner of a light can poke into a bin between the points. The hints only
    // say where to look; what is integrated is pdf() alone, so a direction drawn where pdf() is
    // 0 still finds an expected count of 0 there.
    template <class Pdf>
    std::vector<double> integrate(Pdf pdf, const hints& drawn = {}) const {
        std::vector<double> integrals(std::size_t(count()), 0);
        double dx = x_max / nx, dphi = two_pi / nphi;
        static const std::vector<std::array<double, 2>> none;
        for (int i = 0; i < nx; ++i) {
            for (int j = 0; j < nphi; ++j) {
                auto b = std::size_t(i * nphi + j);
                cell c{i * dx, (i + 1) * dx, j * dphi, (j + 1) * dphi, 0};
                c.estimate   = simpson(pdf, c);
                integrals[b] = refine(pdf, b < drawn.size() ? drawn[b] : none, c, 0);
            }
        }
        return integrals;
    }

  private:
    static constexpr int min_depth             = 1;  // Simpson on quarters at least
    static constexpr int max_depth             = 8;  // 1/256 of a bin's side along an outline
    static constexpr double relative_tolerance = 1e-4;

    struct cell {
        double x0, x1, p0, p1;
        double estimate;  // Simpson's rule on its 3 x 3 points
    };

    // pdf at the n x n points of a grid over the cell (n odd, corners included), row by x.
    template <class Pdf, int n>
    void grid(Pdf& pdf, const cell& c, double (&values)[n][n]) const {
        double cos_p[n], sin_p[n];
        for (int b = 0; b < n; ++b) {
            double phi = c.p0 + (c.p1 - c.p0) * b / (n - 1);
            cos_p[b]   = std::cos(phi);
            sin_p[b]   = std::sin(phi);
        }
        for (int a = 0; a < n; ++a) {
            double x     = c.x0 + (c.x1 - c.x0) * a / (n - 1);
            double cos_t = 1 - x, sin_t = std::sqrt(std::fmax(0.0, x * (2 - x)));
            for (int b = 0; b < n; ++b) {
                double u = sin_t * cos_p[b], v = sin_t * sin_p[b];
                vec3 w(u * e1[0] + v * e2[0] + cos_t * axis[0],
                       u * e1[1] + v * e2[1] + cos_t * axis[1],
                       u * e1[2] + v * e2[2] + cos_t * axis[2]);
                values[a][b] = double(pdf(w));
            }
        }
    }

    // Simpson's rule on the 3 x 3 neighbouring points of values starting at (a, b).
    template <int n>
    static double simpson(const double (&values)[n][n], int a, int b, double area) {
        const double w[3] = {1, 4, 1};
        double sum        = 0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) sum += w[i] * w[j] * values[a + i][b + j];
        }
        return area * sum / 36;
    }

    template <class Pdf>
    double simpson(Pdf& pdf, const cell& c) const {
        double values[3][3];
        grid(pdf, c, values);
        return simpson(values, 0, 0, (c.x1 - c.x0) * (c.p1 - c.p0));
    }

    // Adaptive Simpson in two dimensions: a cell's estimate is accepted when its four quarters
    // (on the 5 x 5 points that include the cell's own 3 x 3) agree with it to the relative
    // tolerance; otherwise each quarter is refined in turn.
    template <class Pdf>
    double refine(Pdf& pdf, const std::vector<std::array<double, 2>>& drawn, const cell& c,
                  int depth) const {
        double values[5][5];
        grid(pdf, c, values);
        const double xm = (c.x0 + c.x1) / 2, pm = (c.p0 + c.p1) / 2;
        const double area = (c.x1 - c.x0) * (c.p1 - c.p0) / 4;
        cell quarters[4]  = {{c.x0, xm, c.p0, pm, simpson(values, 0, 0, area)},
                             {xm, c.x1, c.p0, pm, simpson(values, 2, 0, area)},
                             {c.x0, xm, pm, c.p1, simpson(values, 0, 2, area)},
                             {xm, c.x1, pm, c.p1, simpson(values, 2, 2, area)}};
        double fine       = 0;
        for (const cell& q : quarters) fine += q.estimate;
        if (depth >= max_depth) return fine;
        bool settled = depth >= min_depth &&
                       std::fabs(fine - c.estimate) <= relative_tolerance * std::fabs(fine);
        if (settled && fine == 0) {
            for (const auto& d : drawn)
                settled =
                    settled && !(c.x0 <= d[0] && d[0] <= c.x1 && c.p0 <= d[1] && d[1] <= c.p1);
        }
        if (settled) return fine;
        double sum = 0;
        for (const cell& q : quarters) sum += refine(pdf, drawn, q, depth + 1);
        return sum;
    }

    dvec axis, e1, e2;
    double x_max;
    int nx, nphi;
};

struct direction_test {
    rt_test::chi_square_result chi_square;
    double total       = 0;  // the pdf integrated over all bins: 1 if it is a density
    long long drawn    = 0;  // directions the sampler returned
    long long refused  = 0;  // draws for which it returned false
    long long mismatch = 0;  // drawn directions whose reported pdf is not pdf() of them
    std::string summary;
};

// Draws n directions with draw(rng, wi, reported_pdf) -> bool, bins them, and tests them against
// pdf(wi) integrated over the bins (expected counts scaled to the number drawn, so that the
// chi-square judges the shape and `total` the normalization). The pdf a draw reports must be
// pdf() of its direction to a relative pdf_tolerance.
template <class Draw, class Pdf>
direction_test test_directions(const direction_bins& bins, Draw draw, Pdf pdf, int n,
                               std::uint64_t sequence, double pdf_tolerance) {
    direction_test t;
    std::vector<double> observed(std::size_t(bins.count()), 0);
    direction_bins::hints drawn(observed.size());
    rt::pcg32 rng(sequence, 7);
    for (int k = 0; k < n; ++k) {
        vec3 wi;
        real reported = 0;
        if (!draw(rng, wi, reported)) {
            ++t.refused;
            continue;
        }
        ++t.drawn;
        const std::size_t b = bins.index(wi);
        observed[b] += 1;
        drawn[b].push_back({bins.x_of(wi), bins.phi_of(wi)});
        double again = double(pdf(wi));
        if (!(std::fabs(double(reported) - again) <= pdf_tolerance * again)) {
            if (t.mismatch < 3)
                UNSCOPED_INFO("direction " << wi << ": reported pdf " << reported
                                           << ", pdf() gives " << again);
            ++t.mismatch;
        }
    }
    std::vector<double> integrals = bins.integrate(pdf, drawn);
    for (double v : integrals) t.total += v;
    std::vector<double> expected(integrals.size());
    for (std::size_t b = 0; b < integrals.size(); ++b)
        expected[b] = double(t.drawn) * integrals[b] / t.total;
    t.chi_square = rt_test::chi_square_test(observed, expected, sampling_checks::alpha);
    t.summary    = t.chi_square.summary + "; pdf integrates to " + std::to_string(t.total) + "; " +
                std::to_string(t.refused) + " draws refused, " + std::to_string(t.mismatch) +
                " reported pdfs differ from pdf()";
    return t;
}

// The usual verdict: the chi-square passes, the pdf integrates to 1 within `total_tolerance`,
// no draw was refused and every reported pdf is pdf() of its direction.
inline void check_directions(const direction_test& t, double total_tolerance = 1e-3) {
    INFO(t.summary);
    CHECK(t.chi_square.passed);
    CHECK(std::fabs(t.total - 1) <= total_tolerance);
    CHECK(t.refused == 0);
    CHECK(t.mismatch == 0);
}

}  // namespace rt_test::direction_checks
