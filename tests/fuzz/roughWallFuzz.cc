// libFuzzer target over the public entry points of the rough-wall core, built
// with clang++ -fsanitize=fuzzer,address,undefined (tests/fuzz/CMakeLists.txt).
//
// The first byte picks the entry point; the next bytes are read as raw
// doubles and mapped to valid inputs: a raw double already inside the valid
// range is used as it is (so mutations reach the exact boundaries), others
// are mapped into the range, and a selector byte picks the special values
// (0, the range ends, 1e-300, 90 deg, ...). Inputs the core documents as
// safe although the adapters reject them are fed too (muD > mu0, a bound of
// 0, a particle moving away from the wall). The bytes left over are the
// uniform random stream of the sampler (an adversarial stream: constant,
// stuck or extreme values are all reachable); when they run out a
// deterministic generator seeded from the input takes over.
//
// Every invariant violated aborts with the input printed in hex floats:
// outputs finite, the particle leaves the mean wall, kinetic energy not
// increased beyond round-off, the facet-collision bound and the bound on
// uniform draws respected, result reproducible from the stream; the
// distribution's probabilities in [0, 1] and summing to 1; samples inside
// the support.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "effectiveRestitution.hpp"
#include "wallHitInvariants.hh"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace roughWall;
using namespace roughWallStability;

namespace
{

constexpr double deg = pi/180;

[[noreturn]] void fail(const std::string& what, const std::string& input)
{
    std::fprintf(stderr, "\nroughWallFuzz: INVARIANT VIOLATED: %s\n  input: %s\n", what.c_str(), input.c_str());
    std::abort();
}

//- With ROUGHWALL_FUZZ_TRACE set, print each decoded input before it runs
//  (to see the input of a timeout, which has no message of its own)
void trace(const char* entry, const std::string& input)
{
    static const bool on = std::getenv("ROUGHWALL_FUZZ_TRACE") != nullptr;
    if (on) std::fprintf(stderr, "roughWallFuzz: %s: %s\n", entry, input.c_str());
}

std::string hex(double x)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}

//- Reads the fuzz input: parameters from the front, then the random stream
class Input
{
    const std::uint8_t* data_;
    std::size_t size_, pos_ = 0;
    std::uint64_t state_;   //!< splitmix64 once the bytes run out

    std::uint64_t splitmix()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27))*0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

public:

    Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size), state_(size)
    {
        for (std::size_t i = 0; i < size; ++i) state_ = state_*131 + data[i];
    }

    std::uint8_t byte()
    {
        return pos_ < size_ ? data_[pos_++] : static_cast<std::uint8_t>(splitmix());
    }

    std::uint64_t bits()
    {
        if (pos_ + 8 <= size_)
        {
            std::uint64_t b;
            std::memcpy(&b, data_ + pos_, 8);
            pos_ += 8;
            return b;
        }
        pos_ = size_;
        return splitmix();
    }

    //- In [0, 1) with every double of the form k 2^-53 reachable
    double unit() { return (bits() >> 11)*0x1p-53; }

    //- A value in [lo, hi]: a special value, the raw double if inside, or
    //  the raw bits mapped into the range
    double inRange(double lo, double hi, const std::vector<double>& specials)
    {
        const std::uint8_t selector = byte();
        const std::uint64_t b = bits();
        if (selector < specials.size()) return specials[selector];
        double x;
        std::memcpy(&x, &b, 8);
        if (std::isfinite(x) && x >= lo && x <= hi) return x;
        return lo + (hi - lo)*((b >> 11)*0x1p-53);
    }

    //- A magnitude 10^[eLo, eHi], or a special value, or the raw double
    double magnitude(double eLo, double eHi, const std::vector<double>& specials)
    {
        const std::uint8_t selector = byte();
        const std::uint64_t b = bits();
        if (selector < specials.size()) return specials[selector];
        double x;
        std::memcpy(&x, &b, 8);
        if (std::isfinite(x) && x >= std::pow(10.0, eLo) && x <= std::pow(10.0, eHi)) return x;
        return std::pow(10.0, eLo + (eHi - eLo)*((b >> 11)*0x1p-53));
    }

    //- A unit vector: a coordinate axis (either sign) or a normalised raw direction
    Vec3 direction()
    {
        const std::uint8_t selector = byte();
        if (selector < 6) return (selector % 2 ? -1.0 : 1.0)*Vec3::Unit(selector/2);
        Vec3 d(inRange(-1, 1, {}), inRange(-1, 1, {}), inRange(-1, 1, {}));
        const double n = d.norm();
        return n > 1e-3 ? Vec3(d/n) : Vec3(Vec3::UnitY());
    }

    //- The rest as the uniform stream, restartable for the reproducibility check
    struct Stream
    {
        const Input* in;
        std::size_t pos;
        std::uint64_t state;
        double operator()()
        {
            std::uint64_t b;
            if (pos + 8 <= in->size_)
            {
                std::memcpy(&b, in->data_ + pos, 8);
                pos += 8;
            }
            else
            {
                std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
                z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ull;
                z = (z ^ (z >> 27))*0x94d049bb133111ebull;
                b = z ^ (z >> 31);
            }
            return (b >> 11)*0x1p-53;
        }
    };

    Stream stream() const { return Stream{this, pos_, state_}; }
};

const std::vector<double> alphaSpecials{0, 1e-300, 1e-12, 1e-6, 1*deg, 45*deg, 0.5*pi - 1e-12, 0.5*pi};
const std::vector<double> DeltaSpecials{0, 1e-300, 1e-12, 1*deg, 8*deg, 30*deg, 45*deg};

RoughWallParameters parameters(Input& in)
{
    RoughWallParameters p;
    p.material.e = in.inRange(0, 1, {0, 1, 0.5});
    p.material.mu0 = in.inRange(0, 1e3, {0, 0.4, 10, 1e300});
    // muD <= mu0 as the adapters require, or above it (the core caps it)
    const std::uint8_t muMode = in.byte();
    p.material.muD = muMode % 4 == 0 ? in.inRange(0, 1e3, {0, 0.4, 10})
                                     : p.material.mu0*in.inRange(0, 1, {0, 1});
    p.roughnessAngle = in.inRange(0, 0.25*pi, DeltaSpecials);
    const std::uint8_t flags = in.byte();
    p.lateralTilt = flags & 1;
    // the dictionary allows [1, 1000]; 0 means the mean-wall rebound at once
    p.maxFacetCollisions = static_cast<int>(in.inRange(0, 1000, {1, 10, 0, 1000}));
    return p;
}

//- Entry 0: the rough-wall operator
void fuzzWallHit(Input& in)
{
    WallHitInput hit;
    hit.parameters = parameters(in);
    const std::uint8_t flags = in.byte();
    hit.withSpin = flags & 1;
    const bool twoD = flags & 2;

    const double speed = in.magnitude(-300, 150, {0, 1e-12, 1, 1e4, std::numeric_limits<double>::denorm_min()});
    const double alpha = in.inRange(0, 0.5*pi, alphaSpecials);
    const double azimuth = in.inRange(0, 2*pi, {0});
    hit.radius = 0.5*in.magnitude(-100, 100, {1e-7, 1e-4, 1e-2});
    const double A = (flags & 4 ? -1 : 1)*in.magnitude(-12, 8, {0, 1, 1e3, 1e6});
    const std::uint8_t incidence = in.byte();

    Vec3 N = in.direction(), t, E = Vec3::Zero();
    if (twoD)
    {
        // The empty direction is an axis, the wall normal in the plane
        const int axis = in.byte() % 3;
        E = Vec3::Unit(axis);
        N[axis] = 0;
        N = N.norm() > 1e-3 ? Vec3(N.normalized()) : Vec3(Vec3::Unit((axis + 1) % 3));
        N[axis] = 0;
        t = E.cross(N).normalized();
        t[axis] = 0;
    }
    else
    {
        t = Eigen::AngleAxisd(azimuth, N)*N.unitOrthogonal();
    }
    hit.wallNormal = N;
    hit.emptyDirection = E;

    // Along the wall, exactly normal, moving away, or at alpha
    switch (incidence % 8)
    {
        case 0: hit.velocity = speed*t; break;
        case 1: hit.velocity = -speed*N; break;
        case 2: hit.velocity = speed*(std::cos(alpha)*t + std::sin(alpha)*N); break;
        default: hit.velocity = speed*(std::cos(alpha)*t - std::sin(alpha)*N); break;
    }
    const Vec3 axis = twoD ? E : in.direction();
    if (incidence & 8)
    {
        // rolling on the mean wall: zero slip
        hit.spin = N.cross(hit.velocity - hit.velocity.dot(N)*N)/hit.radius;
    }
    else
    {
        hit.spin = (A*speed/hit.radius)*axis;
    }
    // The spin a hit gives is of order |v|/r: it must be representable
    if (!hit.spin.allFinite() || !(speed/hit.radius < 1e300)
     || !(std::abs(A)*speed < 1e300) || !hit.velocity.allFinite())
    {
        return;
    }
    if (!hit.withSpin)
    {
        hit.spin = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    }

    trace("wall hit", describe(hit));
    auto source = in.stream();
    const WallHitResult out = hitWall(hit, source);
    const std::string what = violation(hit, out, drawsPerFacetHardLimit);
    if (!what.empty())
    {
        fail(what, describe(hit));
    }
    auto again = in.stream();
    if (!sameResult(out, hitWall(hit, again)))
    {
        fail("not reproducible from the random stream", describe(hit));
    }
}

//- Entry 1: one facet collision
void fuzzFacetCollision(Input& in)
{
    FacetMaterial m;
    m.e = in.inRange(0, 1, {0, 1});
    m.mu0 = in.inRange(0, 1e3, {0, 0.4, 10});
    m.muD = in.inRange(0, 1e3, {0, 0.4, 10});   // also above mu0: capped
    const Vec3 n = in.direction();
    Vec3 v = in.magnitude(-150, 150, {1, 1e-12, 1e4})*in.direction();
    const double r = in.magnitude(-50, 50, {5e-5});
    const Vec3 w = (in.inRange(-1e6, 1e6, {0, 1, -1})*v.norm()/r)*in.direction();
    if (v.dot(n) > 0) v = -v;
    if (!(v.dot(n) < 0) || !w.allFinite() || !(v.norm()/r < 1e300)) return;

    const bool withSpin = in.byte() & 1;
    const std::string input = "v=(" + hex(v.x()) + "," + hex(v.y()) + "," + hex(v.z()) + ") n=("
        + hex(n.x()) + "," + hex(n.y()) + "," + hex(n.z()) + ") r=" + hex(r) + " e=" + hex(m.e)
        + " mu0=" + hex(m.mu0) + " muD=" + hex(m.muD) + " withSpin=" + std::to_string(withSpin);
    trace("facet collision", input);
    Vec3 v2 = v, w2 = w;
    const Regime regime = withSpin ? collideWithFacet<true>(v2, w2, n, r, m)
                                   : collideWithFacet<false>(v2, w2, n, r, m);
    if (!v2.allFinite() || !w2.allFinite()) fail("facet collision: output not finite", input);
    if (regime != Regime::noSlip && regime != Regime::sliding) fail("facet collision: no regime", input);
    const double s = std::max(v.cwiseAbs().maxCoeff(), withSpin ? (r*w).cwiseAbs().maxCoeff() : 0.0);
    const double E1 = scaledEnergy(v, w, r, withSpin, s), E2 = scaledEnergy(v2, w2, r, withSpin, s);
    if (!(E2 <= E1*(1 + energyTolerance))) fail("facet collision: energy increased by " + hex(E2/E1 - 1), input);
    // normal restitution on the facet: v''.n = -e v.n, the particle leaves the facet
    if (!(std::abs(v2.dot(n) + m.e*v.dot(n)) <= 1e-12*v.norm()))
    {
        fail("facet collision: v''.n != -e v.n", input);
    }
}

//- Entry 2: the samplers
void fuzzSamplers(Input& in)
{
    const double alpha = in.inRange(0, 0.5*pi, alphaSpecials);
    const double Delta = in.inRange(0, 0.25*pi, DeltaSpecials);
    const std::string input = "alpha=" + hex(alpha) + " Delta=" + hex(Delta);
    trace("samplers", input);
    auto stream = in.stream();
    for (int i = 0; i < 4; ++i)
    {
        const double g1 = sampleFacetAngle(alpha, Delta, stream);
        if (!std::isfinite(g1) || g1 < -alpha) fail("sampleFacetAngle outside the support: " + hex(g1), input);
        const double g2 = sampleFacetAngleByInversion(alpha, Delta, stream);
        if (!std::isfinite(g2) || g2 < -alpha) fail("sampleFacetAngleByInversion outside the support: " + hex(g2), input);
        const double z = standardNormal(stream);
        if (!std::isfinite(z)) fail("standardNormal not finite: " + hex(z), input);
    }
}

//- Entry 3: the distribution, at any finite tilt
void fuzzDistribution(Input& in)
{
    const double alpha = in.inRange(0, 0.5*pi, alphaSpecials);
    const double Delta = in.inRange(0, 0.25*pi, DeltaSpecials);
    double g1, g2;
    const std::uint64_t b1 = in.bits(), b2 = in.bits();
    std::memcpy(&g1, &b1, 8);
    std::memcpy(&g2, &b2, 8);
    if (!std::isfinite(g1) || !std::isfinite(g2)) return;
    if (g2 < g1) std::swap(g1, g2);
    const std::string input = "alpha=" + hex(alpha) + " Delta=" + hex(Delta)
        + " gamma1=" + hex(g1) + " gamma2=" + hex(g2);
    trace("distribution", input);

    const CollisionAngleDistribution P(Delta);
    for (double g : {g1, g2})
    {
        const double pdf = P.pdf(g, alpha), cdf = P.cdf(g, alpha), sf = P.sf(g, alpha);
        if (!(pdf >= 0)) fail("pdf negative or NaN: " + hex(pdf), input);
        if (!(cdf >= 0 && cdf <= 1)) fail("cdf outside [0, 1]: " + hex(cdf), input);
        if (!(sf >= 0 && sf <= 1)) fail("sf outside [0, 1]: " + hex(sf), input);
        if (!(std::abs(cdf + sf - 1) <= 1e-12)) fail("cdf + sf != 1: " + hex(cdf + sf - 1), input);
    }
    if (!(P.cdf(g1, alpha) <= P.cdf(g2, alpha) + 1e-13)) fail("cdf decreasing", input);
    const double m1 = P.mean(alpha), m2 = P.meanSquare(alpha), sd = P.standardDeviation(alpha);
    if (!std::isfinite(m1) || !std::isfinite(m2) || !std::isfinite(sd)) fail("moments not finite", input);
    // (subnormal moments, Delta < 1e-154, carry an absolute round-off)
    const double tiny = 1e3*std::numeric_limits<double>::denorm_min();
    if (!(m2*(1 + 1e-12) + tiny >= m1*m1)) fail("<gamma^2> < <gamma>^2", input);
    const double mass = gaussianMass(g1, g2);
    if (!(mass >= 0 && mass <= 1 + 4*std::numeric_limits<double>::epsilon()))
    {
        fail("gaussianMass outside [0, 1]: " + hex(mass), input);
    }
}

//- Entry 4: the closed forms (2.6)/(2.7), the oracle of the tests
void fuzzClosedForms(Input& in)
{
    const double alpha = in.inRange(1e-300, 0.5*pi - 1e-12, {1e-300, 1e-12, 1*deg, 45*deg, 0.5*pi - 1e-12});
    const double beta = in.inRange(1e-12, 0.5*pi, {1e-12, 1*deg, 45*deg});   // alpha + gamma
    const double gamma = std::min(beta - alpha, 0.5*pi);
    const double A = in.inRange(-1e6, 1e6, {0, 1, -1, 1e6, -1e6});
    FacetMaterial m;
    m.e = in.inRange(0, 1, {0, 1});
    m.mu0 = in.inRange(0, 1e3, {0, 0.4, 10});
    m.muD = m.mu0*in.inRange(0, 1, {0, 1});
    if (!(gamma > -alpha)) return;
    const std::string input = "alpha=" + hex(alpha) + " gamma=" + hex(gamma)
        + " A=" + hex(A) + " e=" + hex(m.e) + " mu0=" + hex(m.mu0) + " muD=" + hex(m.muD);
    trace("closed forms", input);
    const auto k = closedFormRestitution(gamma, alpha, A, m).k;
    if (!std::isfinite(k.kn) || !std::isfinite(k.kt) || !std::isfinite(k.kOmega))
    {
        fail("closed-form restitution not finite", input);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 1) return 0;
    Input in(data, size);
    switch (in.byte() % 8)
    {
        case 0: case 1: case 2: case 3: fuzzWallHit(in); break;   // the main entry
        case 4: fuzzFacetCollision(in); break;
        case 5: fuzzSamplers(in); break;
        case 6: fuzzDistribution(in); break;
        case 7: fuzzClosedForms(in); break;
    }
    return 0;
}
