// The correctly rounded distance's two kinds of error-free product (gjk/include/gjk2d/correct.hpp,
// "The error-free products"): Dekker's TwoProduct and one fused multiply-add give the same bits,
// product by product and for whole refinements, on the hard-case data (validation/cases/*.json),
// the hard families, engine and random cases, and the exact ties. Three refinements are compared:
// Dekker's (refineWith<Context>), the FMA's compiled here (refineWith<FmaContext>: without an FMA
// target, each fused product is a call to libm's fma, exact on any CPU), and, where the CPU has
// FMA, refineFma, the one the query dispatches to. The first two run everywhere: they check the
// arithmetic; the third checks the code the compiler made for the FMA target.
#include "implementations/prepared.hpp"
#include "inputs/cases.hpp"
#include "inputs/families.hpp"

#include <gjk2d/distance.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace gjkval;

namespace
{
bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Everything the refinement may change: the distance, the witness points, the normal, the path.
template <class T> bool sameOutput(const gjk::DistanceOutput<T>& a, const gjk::DistanceOutput<T>& b)
{
    return sameBits(a.distance, b.distance) && sameBits(a.pointA.x, b.pointA.x) &&
           sameBits(a.pointA.y, b.pointA.y) && sameBits(a.pointB.x, b.pointB.x) &&
           sameBits(a.pointB.y, b.pointB.y) && sameBits(a.normal.x, b.normal.x) &&
           sameBits(a.normal.y, b.normal.y) && a.path == b.path;
}

// The cases: every case file of the hard-case data (each with its provenance in the file), the
// hard families, and engine and random cases, as the runner prepares them.
std::vector<Case> hardCases()
{
    std::vector<Case> cases;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(GJK2D_SOURCE_DIR) + "/validation/cases"))
        for (const CaseEntry& e : readCaseFile(entry.path().string()).entries)
            if (e.rejected.empty())
                cases.push_back(e.c);
    for (const char* family :
         {"hard/near-zero-separation", "hard/mixed-scale", "hard/extreme-scale", "hard/ulp-gap",
          "hard/touching-edge", "hard/near-tied-support", "hard/offset-sweep", "hard/range",
          "engine/pyramid-toi:300", "engine:300", "random:2000"})
        for (const auto& f : generateFamilies(family, 29))
            cases.insert(cases.end(), f.cases.begin(), f.cases.end());
    return cases;
}

// A point translated by 2^-53 or 3 2^-53 from the origin, from a vertex and from an edge: exact
// ties between two doubles (tests/validation/test_correct.cpp, "exact ties round to even"), which
// the expansions decide.
std::vector<Case> exactTies()
{
    std::vector<Case> cases;
    for (const bool edge : {false, true})
        for (const double offset : {0x1p-53, 3 * 0x1p-53})
        {
            Case c;
            c.name = std::string(edge ? "edge" : "vertex") + " tie";
            c.a.points = edge ? std::vector<std::array<double, 2>>{{-1, 0}, {1, 0}}
                              : std::vector<std::array<double, 2>>{{0, 0}};
            c.b.points = {{0, 1}};
            c.b.py = offset;
            cases.push_back(c);
        }
    return cases;
}
} // namespace

TEMPLATE_TEST_CASE("correctly rounded: Dekker's and the FMA's products give the same bits",
                   "[correct][fma]", double)
{
    // Only double queries are refined (a float query reports NeedsExact on either path), so the
    // one type where this applies is double. Every pair of factors the points of Z multiply
    // (rotations against coordinates), in both lanes: where exactProduct's guard holds, Dekker's
    // trailing part and the FMA's are the same double.
    using namespace gjk::correct;
    using T = TestType;
    int products = 0, differ = 0;
    for (const Case& c : hardCases())
    {
        const PreparedCase p = prepare(c);
        const gjk::DistanceInput<T> in = p.input<T>();
        std::vector<double> factors;
        for (const auto& xf : {in.transformA, in.transformB})
            factors.insert(factors.end(), {xf.q.c, -xf.q.s, xf.q.s});
        for (const auto& poly : {in.proxyA, in.proxyB})
            for (int i = 0; i < poly.count; ++i)
                factors.insert(factors.end(), {poly.points[i].x, poly.points[i].y});
        for (std::size_t i = 0; i < factors.size(); ++i)
            for (std::size_t j = i; j < factors.size(); ++j)
            {
                const double a = factors[i], b = factors[j];
                const DD d = twoProduct(a, b), f = twoProductFma(a, b);
                if (!exactProduct(a, b, d.hi))
                    continue;
                ++products;
                const DD2 d2 = twoProduct(pair(a, b), pair(b, a)),
                          f2 = twoProductFma(pair(a, b), pair(b, a));
                const bool same = sameBits(d.hi, f.hi) && sameBits(d.lo, f.lo) &&
                                  sameBits(d2.lo[0], f2.lo[0]) && sameBits(d2.lo[1], f2.lo[1]);
                differ += !same;
                if (!same) // one CHECK per product would cost more than the products
                {
                    INFO(c.name << ": " << a << " * " << b << ": Dekker " << d.hi << " + " << d.lo
                                << ", FMA " << f.hi << " + " << f.lo);
                    CHECK(same);
                }
            }
    }
    INFO(products << " products");
    CHECK(differ == 0);
    CHECK(products > 100000);
}

TEMPLATE_TEST_CASE("correctly rounded: the refinement on FMA gives Dekker's bits", "[correct][fma]",
                   double)
{
    using namespace gjk::correct;
    using T = TestType;
    const bool hardware = fmaAvailable();
    std::vector<Case> cases = hardCases();
    const std::vector<Case> ties = exactTies();
    cases.insert(cases.end(), ties.begin(), ties.end());
    std::map<gjk::CorrectPath, int> paths;
    int differ = 0;
    for (const Case& c : cases)
    {
        const PreparedCase p = prepare(c);
        const gjk::DistanceInput<T> in = p.input<T>();
        const gjk::Options options{.correctlyRounded = true};
        gjk::SimplexCache cache;
        const gjk::DistanceOutput<T> plain = gjk::distance(in, cache); // the features
        gjk::DistanceOutput<T> dekker = plain, fma = plain, target = plain;
        refineWith<Context>(in, cache, options, dekker);
        refineWith<FmaContext>(in, cache, options, fma);
        if (hardware)
            refineWithProducts(Products::Fma, in, cache, options, target);
        ++paths[dekker.path];
        INFO(c.name << ": distance " << dekker.distance << " (path " << int(dekker.path)
                    << ") against " << fma.distance << " (path " << int(fma.path) << "), "
                    << target.distance << " (path " << int(target.path) << ")");
        const bool same = sameOutput(dekker, fma) && (!hardware || sameOutput(dekker, target));
        differ += !same;
        CHECK(same);
        // The query itself refines with the products it chose: the same bits.
        CHECK(sameOutput(gjk::distance(in, options), dekker));
    }
    // Every stage ran: the cases test the double-double tail and the exact ties, not only the
    // extended stage and containment.
    INFO(cases.size() << " cases; FMA hardware: " << hardware << "; containment "
                      << paths[gjk::CorrectPath::Double] << ", extended "
                      << paths[gjk::CorrectPath::Extended] << ", double-double "
                      << paths[gjk::CorrectPath::DoubleDouble] << ", exact needed "
                      << paths[gjk::CorrectPath::NeedsExact]);
    CHECK(differ == 0);
    CHECK(paths[gjk::CorrectPath::Double] > 0);
    CHECK(paths[gjk::CorrectPath::DoubleDouble] > 0);
    CHECK(paths[gjk::CorrectPath::NeedsExact] > 0);
    if constexpr (kExtended)
        CHECK(paths[gjk::CorrectPath::Extended] > 0);
}

TEST_CASE("correctly rounded: GJK2D_NO_FMA forces Dekker's products", "[correct][fma]")
{
    // chooseProducts reads the variable (productsInUse keeps its first answer for the program):
    // set and neither empty nor "0", Dekker's products; otherwise the FMA's where the CPU has them.
    using namespace gjk::correct;
    const char* saved = std::getenv("GJK2D_NO_FMA");
    const std::string kept = saved ? saved : "";
    const Products available = fmaAvailable() ? Products::Fma : Products::Dekker;
    ::unsetenv("GJK2D_NO_FMA");
    CHECK(chooseProducts() == available);
    for (const auto& [value, expected] :
         {std::pair{"1", Products::Dekker}, std::pair{"yes", Products::Dekker},
          std::pair{"0", available}, std::pair{"", available}})
    {
        ::setenv("GJK2D_NO_FMA", value, 1);
        INFO("GJK2D_NO_FMA=" << value);
        CHECK(chooseProducts() == expected);
    }
    if (saved)
        ::setenv("GJK2D_NO_FMA", kept.c_str(), 1);
    else
        ::unsetenv("GJK2D_NO_FMA");
    // The program's choice is the rule's answer for its environment.
    CHECK(productsInUse() == (saved && kept != "" && kept != "0" ? Products::Dekker : available));
}
