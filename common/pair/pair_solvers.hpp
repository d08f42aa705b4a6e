#pragma once
// The pair solvers' definitions (pair/pair_geometry.hpp declares them; docs/design.md §2), for
// the files that build them for a body: pair/pair_geometry.cpp for ParticleShape (the analyses,
// any family) and each family's own for its body where a program solves its pairs directly
// (pair/superball_pair_solvers.cpp: sbgen's superball engine). Include nowhere else.

#include "pair/pair_geometry.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace sbpack {

namespace pair_solvers { // the solvers' parts, for the definitions below only

using Vector2d = Eigen::Vector2d;
using Matrix2d = Eigen::Matrix2d;

/// H(u) = h_A(u) + h_B(u) and its derivatives in the lab frame (u need not be unit).
template <ConvexBody Body> class MinkowskiSum {
  public:
    explicit MinkowskiSum(const BodyPair<Body>& pair)
        : pair_(pair), shapeB_(sbpack::shapeB(pair)) {}

    double support(const Vector3d& u) const {
        ++evaluations;
        return shape().support(ra().transpose() * u) + shapeB_.support(rb().transpose() * u);
    }
    /// grad H = s_A(u) + s_B(u): the sum of the support points.
    Vector3d supportPoint(const Vector3d& u) const {
        ++evaluations;
        return supportPointA(u) + supportPointB(u);
    }
    Vector3d supportPointA(const Vector3d& u) const {
        return ra() * shape().supportPoint(ra().transpose() * u);
    }
    Vector3d supportPointB(const Vector3d& u) const {
        return rb() * shapeB_.supportPoint(rb().transpose() * u);
    }
    Matrix3d supportHessian(const Vector3d& u) const {
        return ra() * shape().supportHessian(ra().transpose() * u) * ra().transpose() +
               rb() * shapeB_.supportHessian(rb().transpose() * u) * rb().transpose();
    }
    /// The gauges of A and B at x (lab frame, relative to their centres).
    double gaugeA(const Vector3d& x) const { return shape().gauge(ra().transpose() * x); }
    double gaugeB(const Vector3d& x) const { return shapeB_.gauge(rb().transpose() * x); }
    /// A's and B's semi-axes summed: the pair's contact distance of spheres, its diameter.
    double pairDiameter() const { return shape().semiAxis() + shapeB_.semiAxis(); }

    const Body& shape() const { return pair_.shape; }
    const Body& shapeB() const { return shapeB_; }
    const Matrix3d& ra() const { return pair_.rotationA; }
    const Matrix3d& rb() const { return pair_.rotationB; }
    const Vector3d& displacement() const { return pair_.displacement; }
    const BodyPair<Body>& pair() const { return pair_; }

    mutable int evaluations = 0;

  private:
    const BodyPair<Body>& pair_;
    Body shapeB_;
};

/// A bracket [lo, hi] of the root of phi', phi'(lo) = dlo < 0 <= dhi = phi'(hi), refined by
/// Illinois regula falsi with bisection safeguards.
struct Bracket {
    double lo, dlo, hi, dhi;
    int side = 0; ///< Illinois: which end was kept last time

    /// One regula falsi step (its end's value halved when the same end is kept twice), and a
    /// bisection when the bracket shrank by less than half; the root if a step hit it exactly.
    template <class Derivative> std::optional<double> refine(Derivative& derivative) {
        double t = lo - dlo * (hi - lo) / (dhi - dlo);
        const double width = hi - lo;
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        const double dt = derivative(t);
        if (dt == 0.0) return t;
        if (dt < 0.0) {
            lo = t;
            dlo = dt;
            if (side == -1) dhi *= 0.5;
            side = -1;
        } else {
            hi = t;
            dhi = dt;
            if (side == 1) dlo *= 0.5;
            side = 1;
        }
        if (hi - lo > 0.5 * width) { // slow secant progress: bisect once
            const double mid = 0.5 * (lo + hi);
            const double dm = derivative(mid);
            if (dm == 0.0) return mid;
            (dm < 0.0 ? lo : hi) = mid;
            (dm < 0.0 ? dlo : dhi) = dm;
            side = 0;
        }
        return std::nullopt;
    }
};

/// Solves phi'(t) = 0 for 0 < t <= tMax along a search direction, given phi'(0) < 0 and
/// phi' nondecreasing past its root (convex phi, or a local maximum of -phi): the full
/// Newton step t = 1 is tried first; otherwise the root is bracketed and refined (Bracket).
/// tTolerance is absolute in t.
template <class Derivative>
double exactLineSearch(Derivative&& derivative, double slope0, double tTolerance, double tMax,
                       int maxIterations) {
    Bracket b{0.0, slope0, std::min(1.0, tMax), 0.0};
    b.dhi = derivative(b.hi);
    if (std::abs(b.dhi) <= 1e-2 * std::abs(slope0)) return b.hi; // Newton's step will do
    int iteration = 0;
    while (b.dhi < 0.0 && b.hi < tMax && iteration++ < maxIterations) { // bracket the root
        b.lo = b.hi;
        b.dlo = b.dhi;
        b.hi = std::min(2.0 * b.hi, tMax);
        b.dhi = derivative(b.hi);
    }
    if (b.dhi < 0.0) return b.hi;
    while (b.hi - b.lo > tTolerance && iteration++ < maxIterations)
        if (const std::optional<double> root = b.refine(derivative)) return *root;
    return 0.5 * (b.lo + b.hi);
}

/// Largest t with |c + t v| <= radius, for |c| <= radius.
inline double rayExit(const Vector2d& c, const Vector2d& v, double radius) {
    const double a = v.squaredNorm(), b = c.dot(v), e = c.squaredNorm() - radius * radius;
    return (-b + std::sqrt(std::max(0.0, b * b - a * e))) / a;
}

/// Newton direction for minimising a function with 2x2 Hessian h and gradient g; a tiny
/// shift keeps the octahedral (singular) Hessians solvable, steepest descent otherwise.
inline Vector2d newtonDirection(const Matrix2d& h, const Vector2d& g, double shift) {
    const Matrix2d m = h + shift * Matrix2d::Identity();
    const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    Vector2d direction(-(m(1, 1) * g[0] - m(0, 1) * g[1]) / det,
                       -(m(0, 0) * g[1] - m(1, 0) * g[0]) / det);
    if (!(direction.dot(g) < 0.0) || !direction.allFinite()) direction = -g;
    return direction;
}

// ---- Octahedron p = 0.5: K = A + B is a polytope --------------------------------------

/// Whether the body is the octahedron (only a body with isOctahedron() can be).
template <ConvexBody Body> bool isOctahedron(const Body& body) {
    if constexpr (requires { body.isOctahedron(); })
        return body.isOctahedron();
    else
        return false;
}

/// Unit vectors containing every face normal of K (faces of A, of B, and the cross
/// products of their edge directions), up to sign.
template <ConvexBody Body>
std::vector<Vector3d> octahedronFaceNormalCandidates(const MinkowskiSum<Body>& k) {
    static const std::array<Vector3d, 4> faces = {Vector3d(1, 1, 1), Vector3d(1, 1, -1),
                                                  Vector3d(1, -1, 1), Vector3d(-1, 1, 1)};
    static const std::array<Vector3d, 6> edges = {Vector3d(1, 1, 0), Vector3d(1, -1, 0),
                                                  Vector3d(1, 0, 1), Vector3d(1, 0, -1),
                                                  Vector3d(0, 1, 1), Vector3d(0, 1, -1)};
    std::vector<Vector3d> normals;
    for (const Vector3d& f : faces) {
        normals.push_back((k.ra() * f).normalized());
        normals.push_back((k.rb() * f).normalized());
    }
    for (const Vector3d& ea : edges)
        for (const Vector3d& eb : edges) {
            const Vector3d n = (k.ra() * ea).cross(k.rb() * eb);
            if (n.norm() > 1e-12) normals.push_back(n.normalized());
        }
    return normals;
}

template <ConvexBody Body> ScaleFactorResult octahedronScaleFactor(const MinkowskiSum<Body>& k) {
    // The gauge of a polytope is its largest n.d / h(n) over the face normals (exact).
    ScaleFactorResult result;
    const Vector3d& d = k.displacement();
    for (Vector3d n : octahedronFaceNormalCandidates(k)) {
        if (n.dot(d) < 0.0) n = -n;
        const double mu = n.dot(d) / k.support(n);
        if (mu > result.scaleFactor) {
            result.scaleFactor = mu;
            result.normal = n;
        }
    }
    result.evaluations = k.evaluations;
    return result;
}

/// s = max_n n.d - H(n) over directions that contain its maximiser: the face normals of K
/// (nearest feature a face, or d inside K), the directions to its vertices, and to the
/// nearest points of the segments between vertices (nearest feature an edge). Exact.
template <ConvexBody Body>
void octahedronSignedDistance(const MinkowskiSum<Body>& k, SignedDistanceResult& result) {
    const Vector3d& d = k.displacement();
    double best = -std::numeric_limits<double>::infinity();
    auto consider = [&](Vector3d n) {
        const double length = n.norm();
        if (!(length > 0.0)) return;
        n /= length;
        const double s = n.dot(d) - k.support(n);
        if (s > best) {
            best = s;
            result.normal = n;
        }
    };
    for (const Vector3d& n : octahedronFaceNormalCandidates(k))
        consider(n.dot(d) < 0 ? -n : n);
    if (result.scaleFactor > 1.0) {
        std::vector<Vector3d> vertices;
        const double r = k.shape().semiAxis(), rB = k.shapeB().semiAxis();
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                const Vector3d a = k.ra().col(i % 3) * (i < 3 ? r : -r);
                const Vector3d b = k.rb().col(j % 3) * (j < 3 ? rB : -rB);
                vertices.push_back(a + b);
            }
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            consider(d - vertices[i]);
            for (std::size_t j = i + 1; j < vertices.size(); ++j) {
                const Vector3d e = vertices[j] - vertices[i];
                const double t = std::clamp(e.dot(d - vertices[i]) / e.squaredNorm(), 0.0, 1.0);
                consider(d - vertices[i] - t * e);
            }
        }
    }
    result.signedDistance = best;
}

// ---- General superballs 0.5 < p < inf ---------------------------------------------------

/// The part of a convex polygon with a . x <= b (one Sutherland-Hodgman pass), into `kept`
/// (reused storage: the search clips up to 200 times per call).
inline void clipPolygon(const std::vector<Vector2d>& polygon, const Vector2d& a, double b,
                        std::vector<Vector2d>& kept) {
    kept.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vector2d& p = polygon[i];
        const Vector2d& q = polygon[(i + 1) % polygon.size()];
        const double fp = a.dot(p) - b, fq = a.dot(q) - b;
        if (fp <= 0.0) kept.push_back(p);
        if ((fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0))
            kept.push_back(p + (fp / (fp - fq)) * (q - p));
    }
}

/// Centre of gravity of a convex polygon (the vertex mean where its area is lost to rounding).
inline Vector2d centroid(const std::vector<Vector2d>& polygon) {
    const Vector2d& o = polygon[0];
    Vector2d weighted = Vector2d::Zero(), mean = Vector2d::Zero();
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        mean += polygon[i] - o;
        if (i + 1 == polygon.size() || i == 0) continue;
        const Vector2d a = polygon[i] - o, b = polygon[i + 1] - o;
        const double twiceArea = a.x() * b.y() - a.y() * b.x();
        area += twiceArea;
        weighted += twiceArea * (a + b) / 3.0;
    }
    return area > 0.0 ? Vector2d(o + weighted / area) : Vector2d(o + mean / polygon.size());
}

/// Lower bound on a convex F over a convex polygon from supporting planes F >= F_k + g_k . (x -
/// c_k) (the last kPlanes given): the largest of the planes' minima, each at a vertex.
class PlaneMinorant {
  public:
    void add(double value, const Vector2d& gradient, const Vector2d& at) {
        planes_[next_ % kPlanes] = {value - gradient.dot(at), gradient};
        ++next_;
    }
    double minimumOver(const std::vector<Vector2d>& polygon) const {
        double bound = -std::numeric_limits<double>::infinity();
        for (int k = 0; k < std::min(next_, kPlanes); ++k) {
            double lowest = std::numeric_limits<double>::infinity();
            for (const Vector2d& vertex : polygon)
                lowest = std::min(lowest, planes_[k].offset + planes_[k].gradient.dot(vertex));
            bound = std::max(bound, lowest);
        }
        return bound;
    }

  private:
    static constexpr int kPlanes = 8;
    struct Plane {
        double offset; ///< F_k - g_k . c_k
        Vector2d gradient;
    };
    std::array<Plane, kPlanes> planes_{};
    int next_ = 0;
};

/// Minimum of f over the square |c_i| <= radius by the centre-of-gravity cutting-plane method:
/// a subgradient g at the centroid c of the polygon known to hold the minimiser keeps only
/// g . (x - c) <= 0, which loses no minimiser of a quasi-convex f whatever its kinks (the support
/// points of near-cubes and near-octahedra are subgradients where Newton stalls), and each cut
/// takes at least 4/9 of the polygon's area (Grunbaum), so ~150 evaluations reach rounding, far
/// fewer than nested golden sections (bench/RESULTS.md, "Results after the cutting-plane finish
/// and the mismatch certificate"). For convex f the cut deepens to
/// g . (x - c) <= f_best - f(c). `valueAndGradient(c, g)` returns f(c) and writes g.
/// The search stops when the polygon is within `resolution` of its centroid, or as soon as
/// `lowerBound(polygon)`, a lower bound on f over the polygon, reaches the best f: then that is
/// the minimum to rounding. Across a kink line of f the polygon narrows fast, along it (f smooth
/// there) it need not narrow to the resolution (docs/design.md §3, "Near-cubes").
template <class F, class Bound>
Vector2d cuttingPlaneMinimum(F&& valueAndGradient, Bound&& lowerBound, double radius,
                             double resolution, bool convex, int iterations, double& value) {
    std::vector<Vector2d> polygon = {Vector2d(-radius, -radius), Vector2d(radius, -radius),
                                     Vector2d(radius, radius), Vector2d(-radius, radius)};
    std::vector<Vector2d> clipped;
    polygon.reserve(16);
    clipped.reserve(16);
    Vector2d best = Vector2d::Zero(), gradient;
    value = std::numeric_limits<double>::infinity();
    for (int i = 0; i < iterations && polygon.size() >= 3; ++i) {
        const Vector2d c = centroid(polygon);
        double extent = 0.0;
        for (const Vector2d& vertex : polygon)
            extent = std::max(extent, (vertex - c).norm());
        if (extent <= resolution) break;
        const double fc = valueAndGradient(c, gradient);
        if (fc < value) {
            value = fc;
            best = c;
        }
        if (gradient.isZero(0.0) || !gradient.allFinite()) break;
        clipPolygon(polygon, gradient, gradient.dot(c) + (convex ? value - fc : 0.0), clipped);
        polygon.swap(clipped);
        if (polygon.size() >= 3 && lowerBound(polygon) >= value) break;
    }
    return best;
}

/// Certificate of the scale factor mu at u: the bodies scaled by mu meet at mu s_A(u) or at
/// d - mu s_B(u) (primal points; where one body presents a face its support point is
/// ill-conditioned, the other's is not).
template <ConvexBody Body>
bool scaledBodiesMeet(const MinkowskiSum<Body>& k, const Vector3d& u, double mu,
                      const PairTolerances& tolerances) {
    const Vector3d& d = k.displacement();
    const double limit = mu * (1.0 + tolerances.certificateTolerance);
    return k.gaugeB(mu * k.supportPointA(u) - d) <= limit ||
           k.gaugeA(d - mu * k.supportPointB(u)) <= limit;
}

/// Where Newton stalled on a kink: H minimised exactly over the square of half-width `radius`
/// in the tangent coordinates of d_hat (cutting planes: H is convex, so its subgradient cuts are
/// supporting planes); (u, h) replaced where that is lower.
template <ConvexBody Body>
void minimiseOverSquare(const MinkowskiSum<Body>& k, const Vector3d& dHat,
                        const Eigen::Matrix<double, 3, 2>& basis, double radius,
                        const PairTolerances& tolerances, Vector3d& u, double& h) {
    double best = 0.0;
    PlaneMinorant planes;
    const Vector2d cBest = cuttingPlaneMinimum(
        [&](const Vector2d& x, Vector2d& gradient) {
            const Vector3d v = dHat + basis * x, point = k.supportPoint(v);
            gradient = basis.transpose() * point;
            const double hv = v.dot(point); // H(v) = v . grad H(v): homogeneous of degree one
            planes.add(hv, gradient, x);
            return hv;
        },
        [&](const std::vector<Vector2d>& polygon) { return planes.minimumOver(polygon); }, radius,
        1e-16 * radius, true, tolerances.maxCuttingPlaneIterations, best);
    if (best < h) {
        u = dHat + basis * cBest;
        h = best;
    }
}

/// 1/mu = min H(u) / |d| over the plane u . d_hat = 1 (docs/design.md §2): a convex problem in
/// the two tangent coordinates c, u = d_hat + P c.
template <ConvexBody Body>
ScaleFactorResult generalScaleFactor(const MinkowskiSum<Body>& k, const Vector3d& warmNormal,
                                     const PairTolerances& tolerances) {
    const Vector3d& d = k.displacement();
    const double distance = d.norm();
    const Vector3d dHat = d / distance;
    const Eigen::Matrix<double, 3, 2> basis = tangentBasis(dHat);

    Vector2d c = Vector2d::Zero();
    const double cosine = warmNormal.dot(dHat);
    if (cosine > 0.1 * warmNormal.norm()) c = basis.transpose() * (warmNormal / cosine);

    ScaleFactorResult result;
    const double curvatureShift = 1e-12 * k.shape().semiAxis();
    // The minimiser lies in the disc |c| <= sqrt(2): H(u) >= 2 r_in |u|, H(d_hat) <= 2 r_out
    // and r_out / r_in <= sqrt(3). Steps stay inside a slightly larger disc, which also
    // bounds them on the flat stretches of H (cube vertices seen along their diagonal).
    const double radius = 1.5;
    if (c.norm() > radius) c.setZero();
    for (result.iterations = 0; result.iterations < tolerances.maxNewtonIterations;) {
        ++result.iterations;
        const Vector3d u = dHat + basis * c;
        const Vector2d gradient = basis.transpose() * k.supportPoint(u);
        if (gradient.isZero(0.0)) break;
        const Matrix2d hessian = basis.transpose() * k.supportHessian(u) * basis;
        const Vector2d direction = newtonDirection(hessian, gradient, curvatureShift);
        const double length = direction.norm();
        const double t = exactLineSearch(
            [&](double s) {
                return direction.dot(basis.transpose() *
                                     k.supportPoint(u + basis * (s * direction)));
            },
            direction.dot(gradient), tolerances.normalTolerance / length,
            rayExit(c, direction, radius), tolerances.maxLineSearchIterations);
        c += t * direction;
        if (t * length <= tolerances.normalTolerance * (1.0 + c.norm())) break;
    }
    Vector3d u = dHat + basis * c;
    double h = k.support(u);
    if (!scaledBodiesMeet(k, u, distance / h, tolerances)) {
        ++result.fallbacks;
        minimiseOverSquare(k, dHat, basis, radius, tolerances, u, h);
    }
    result.scaleFactor = distance / h;
    result.normal = u.normalized();
    result.evaluations = k.evaluations;
    return result;
}

/// Ascent of f(n) = n.d - H(n) on the unit sphere from the normal of mu, which is exact
/// at contact: Newton on the tangent plane of the current normal, f(u/|u|) = f~(u)/|u|.
template <ConvexBody Body>
void generalSignedDistance(const MinkowskiSum<Body>& k, const PairTolerances& tolerances,
                           SignedDistanceResult& result) {
    const Vector3d& d = k.displacement();
    Vector3d n = result.normal;
    double f = n.dot(d) - k.support(n);
    // Derivative of f(normalize(u)) along direction v at u: (grad f~ - f~ u / |u|^2) . v / |u|.
    auto slope = [&](const Vector3d& u, const Vector3d& v) {
        const double r2 = u.squaredNorm();
        const double fu = u.dot(d) - k.support(u);
        return (d - k.supportPoint(u) - fu * u / r2).dot(v) / std::sqrt(r2);
    };
    const double curvatureShift = 1e-12 * k.shape().semiAxis();
    for (int iteration = 0; iteration < tolerances.maxNewtonIterations; ++iteration) {
        ++result.iterations;
        const Eigen::Matrix<double, 3, 2> basis = tangentBasis(n);
        const Vector2d gradient = basis.transpose() * (d - k.supportPoint(n)); // of f
        if (gradient.isZero(0.0)) break;
        // Tangent Hessian of -f: P^T d2H P + f I.
        const Matrix2d hessian =
            basis.transpose() * k.supportHessian(n) * basis + f * Matrix2d::Identity();
        Matrix2d shifted = hessian;
        const double smallest = Eigen::SelfAdjointEigenSolver<Matrix2d>(hessian).eigenvalues()[0];
        if (smallest < curvatureShift)
            shifted += (curvatureShift - smallest) * Matrix2d::Identity();
        const Vector2d direction = newtonDirection(shifted, -gradient, 0.0);
        const Vector3d v = basis * direction;
        const double length = direction.norm();
        const double t = exactLineSearch(
            [&](double s) { return -slope(n + s * v, v); }, -gradient.dot(direction),
            tolerances.normalTolerance / length, 1.0 / length, tolerances.maxLineSearchIterations);
        const Vector3d candidate = (n + t * v).normalized();
        const double fCandidate = candidate.dot(d) - k.support(candidate);
        if (!(fCandidate >= f)) break; // no further ascent at rounding level
        n = candidate;
        f = fCandidate;
        if (t * length <= tolerances.normalTolerance) break;
    }
    // Certificate: the contact points are separated by s along n (d - grad H(n) = s n), or,
    // where a face's support point is ill-conditioned, the supporting planes of n have a common
    // perpendicular between the bodies.
    const Vector3d residual = d - k.supportPoint(n) - f * n;
    const double size = k.pairDiameter();
    if (residual.norm() > tolerances.distanceCertificateTolerance * size &&
        supportPlaneMismatch(k.pair(), n, f, k.supportPointA(n), d - k.supportPointB(n)) >
            tolerances.mismatchTolerance * size) {
        // Newton stalled on a kink: maximise f over the tangent plane of n, where f is
        // quasi-concave for s >= 0 (a local maximum, i.e. a bound on the depth, below).
        ++result.fallbacks;
        const LocalMaximum best =
            tangentMaximum(k.pair(), n, 0.6, 6e-17, tolerances.maxCuttingPlaneIterations);
        k.evaluations += best.evaluations;
        if (best.value > f) {
            n = best.normal;
            f = best.value;
        }
    }
    result.normal = n;
    result.signedDistance = f;
}

} // namespace pair_solvers

template <ConvexBody Body>
double supportPlaneMismatch(const BodyPair<Body>& pair, const Vector3d& n, double f,
                            const Vector3d& contactA, const Vector3d& contactB) {
    using namespace pair_solvers;
    const Vector3d& d = pair.displacement;
    const Vector3d belowB = contactB - f * n, aboveA = contactA + f * n - d;
    const MinkowskiSum<Body> k(pair);
    const double gaugeA = std::max(1.0, k.gaugeA(belowB));
    const double gaugeB = std::max(1.0, k.gaugeB(aboveA));
    return std::min((contactB - belowB / gaugeA).norm(), (contactA - d - aboveA / gaugeB).norm()) -
           f;
}

template <ConvexBody Body>
LocalMaximum tangentMaximum(const BodyPair<Body>& pair, const Vector3d& n, double radius,
                            double resolution, int iterations) {
    using namespace pair_solvers;
    const MinkowskiSum<Body> k(pair);
    const Vector3d& d = pair.displacement;
    const Eigen::Matrix<double, 3, 2> basis = tangentBasis(n);
    // -f~(n + P c) is convex in c (f~(u) = u . d - H(u), H convex): its supporting planes, from
    // the same support points, bound f = f~ / |u| from above (docs/design.md §3, "Near-cubes").
    PlaneMinorant minusFTilde;
    auto minusFOnSphere = [&](const Vector2d& c, Vector2d& gradient) {
        // f(u / |u|) = f~(u) / |u| at u = n + P c, f~(u) = u . (d - grad H(u)).
        const Vector3d u = n + basis * c, toGap = d - k.supportPoint(u);
        const double r2 = u.squaredNorm(), fu = u.dot(toGap);
        minusFTilde.add(-fu, -basis.transpose() * toGap, c);
        gradient = -basis.transpose() * (toGap - fu * u / r2) / std::sqrt(r2);
        return -fu / std::sqrt(r2);
    };
    // -f = -f~ / |u| >= L where -f~ >= L: L itself where L < 0 (|u| >= 1), else L / max |u|.
    auto minusFBound = [&](const std::vector<Vector2d>& polygon) {
        const double bound = minusFTilde.minimumOver(polygon);
        if (bound < 0.0) return bound;
        double largest = 0.0;
        for (const Vector2d& vertex : polygon)
            largest = std::max(largest, vertex.squaredNorm());
        return bound / std::sqrt(1.0 + largest); // |u|^2 = 1 + |c|^2, convex in c
    };
    double best = 0.0;
    const Vector2d c = cuttingPlaneMinimum(minusFOnSphere, minusFBound, radius, resolution, false,
                                           iterations, best);
    return {(n + basis * c).normalized(), -best, c.lpNorm<Eigen::Infinity>() < 0.5 * radius,
            k.evaluations};
}

template <ConvexBody Body>
ScaleFactorResult scaleFactor(const BodyPair<Body>& pair, const Vector3d& warmNormal,
                              const PairTolerances& tolerances) {
    using namespace pair_solvers;
    const Vector3d& d = pair.displacement;
    const double distance = d.norm();
    if (distance == 0.0) return {0.0, Vector3d::UnitX(), 0, 0, 0};
    const MinkowskiSum<Body> k(pair);
    if (pair.shape.isSphere()) return {distance / k.pairDiameter(), d / distance, 0, 0, 0};
    if (isOctahedron(pair.shape)) return octahedronScaleFactor(k);
    return generalScaleFactor(k, warmNormal, tolerances);
}

template <ConvexBody Body>
SignedDistanceResult signedDistance(const BodyPair<Body>& pair, const Vector3d& warmNormal,
                                    const PairTolerances& tolerances) {
    using namespace pair_solvers;
    const ScaleFactorResult mu = scaleFactor(pair, warmNormal, tolerances);
    SignedDistanceResult result;
    result.scaleFactor = mu.scaleFactor;
    result.normal = mu.normal;
    result.iterations = mu.iterations;
    result.fallbacks = mu.fallbacks;
    const MinkowskiSum<Body> k(pair);
    const Vector3d& d = pair.displacement;
    if (pair.shape.isSphere()) {
        result.signedDistance = d.norm() - k.pairDiameter();
    } else if (isOctahedron(pair.shape)) {
        octahedronSignedDistance(k, result);
    } else {
        generalSignedDistance(k, tolerances, result);
    }
    result.contactA = k.supportPointA(result.normal);
    result.contactB = d - k.supportPointB(result.normal);
    result.evaluations = mu.evaluations + k.evaluations;
    return result;
}

/// The solvers' explicit instantiation for a ConvexBody `Body`, at namespace sbpack.
#define SBPACK_PAIR_SOLVERS(Body)                                                                  \
    template double supportPlaneMismatch(const BodyPair<Body>&, const Vector3d&, double,           \
                                         const Vector3d&, const Vector3d&);                        \
    template LocalMaximum tangentMaximum(const BodyPair<Body>&, const Vector3d&, double, double,   \
                                         int);                                                     \
    template ScaleFactorResult scaleFactor(const BodyPair<Body>&, const Vector3d&,                 \
                                           const PairTolerances&);                                 \
    template SignedDistanceResult signedDistance(const BodyPair<Body>&, const Vector3d&,           \
                                                 const PairTolerances&);

} // namespace sbpack
