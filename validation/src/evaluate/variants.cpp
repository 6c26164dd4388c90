#include "evaluate/variants.hpp"

#include <fmt/format.h>

#include <limits>

namespace gjkval
{

// clang-format off
const std::vector<VariantInfo>& variantTable()
{
    using gjk::Options;
    using D = gjk::SearchDirection;
    using S = gjk::StoppingRule;
    using F = gjk::Frame;
    using P = gjk::SupportStrategy;
    static const std::vector<VariantInfo> table = {
        // name, type, options, description, judged (false: comparison variant), warm, every start
        {"double",                Scalar::Double, gjk::referenceOptions,                 "reference options (talk's edge-perpendicular direction, repeated-support stop, A's local frame)", true},
        {"float",                 Scalar::Float,  gjk::referenceOptions,                 "reference options in single precision", true},
        {"double-closest-point",  Scalar::Double, Options{.direction = D::ClosestPoint}, "naive search direction d = -P (talk: inaccurate on long edges)", false},
        {"double-world-frame",    Scalar::Double, Options{.frame = F::World},            "compute in world coordinates (loses small gaps far from the origin)", false},
        {"double-duality-gap",    Scalar::Double, Options{.stopping = S::DualityGap},    "also stop on the duality gap", false},
        {"float-closest-point",   Scalar::Float,  Options{.direction = D::ClosestPoint}, "naive search direction in single precision", false},
        {"float-world-frame",     Scalar::Float,  Options{.frame = F::World},            "world-frame computation in single precision", false},
        {"double-certified",      Scalar::Double, Options{.certify = true},              "reference options plus a certified interval [lower, upper]", true},
        {"float-certified",       Scalar::Float,  Options{.certify = true},              "certified interval in single precision", true},
        {"double-binary-support", Scalar::Double, Options{.support = P::BinarySearch},   "reference options with the O(log n) binary-search support (shapes in convex order only)", true},
        {"float-binary-support",  Scalar::Float,  Options{.support = P::BinarySearch},   "binary-search support in single precision (shapes in convex order only)", true},
        {"double-warm",           Scalar::Double, gjk::referenceOptions,                 "reference options, warm-started: the query repeated with the cache of the first", true, true},
        {"float-warm",            Scalar::Float,  gjk::referenceOptions,                 "warm-started reference options in single precision", true, true},
        {"double-every-start",    Scalar::Double, gjk::referenceOptions,                 "reference options started from every initial vertex pair and several multi-vertex caches; the worst answer is judged", true, false, true},
        {"float-every-start",     Scalar::Float,  gjk::referenceOptions,                 "every start in single precision", true, false, true},
    };
    return table;
}
// clang-format on

const VariantInfo* findVariant(const std::string& name)
{
    for (const auto& v : variantTable())
        if (v.name == name)
            return &v;
    return nullptr;
}

std::vector<const VariantInfo*> parseVariants(const std::string& list)
{
    std::vector<const VariantInfo*> out;
    if (list == "all")
    {
        for (const auto& v : variantTable())
            out.push_back(&v);
        return out;
    }
    std::size_t start = 0;
    while (start <= list.size())
    {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        start = comma + 1;
        if (name.empty())
            continue;
        const VariantInfo* v = findVariant(name);
        if (!v)
        {
            std::string known;
            for (const auto& k : variantTable())
                known += (known.empty() ? "" : ", ") + k.name;
            throw InputError(fmt::format("unknown variant '{}' (known: {}, or all)", name, known));
        }
        bool dup = false;
        for (auto* p : out)
            dup = dup || p == v;
        if (!dup)
            out.push_back(v);
    }
    if (out.empty())
        throw InputError("no variant selected");
    return out;
}

bool needsConvexOrder(const VariantInfo& v)
{
    return v.options.support == gjk::SupportStrategy::BinarySearch;
}

const char* scalarName(Scalar s)
{
    return s == Scalar::Float ? "float" : "double";
}

double unitRoundoff(Scalar s)
{
    return s == Scalar::Float ? double(std::numeric_limits<float>::epsilon()) / 2
                              : std::numeric_limits<double>::epsilon() / 2;
}

double smallestSubnormal(Scalar s)
{
    return s == Scalar::Float ? double(std::numeric_limits<float>::denorm_min())
                              : std::numeric_limits<double>::denorm_min();
}

int scalarDigits(Scalar s)
{
    return s == Scalar::Float ? std::numeric_limits<float>::digits
                              : std::numeric_limits<double>::digits;
}

int scalarMinExponent(Scalar s)
{
    return s == Scalar::Float ? std::numeric_limits<float>::min_exponent
                              : std::numeric_limits<double>::min_exponent;
}

const char* directionName(gjk::SearchDirection d)
{
    switch (d)
    {
    case gjk::SearchDirection::EdgePerpendicular:
        return "edge-perpendicular";
    case gjk::SearchDirection::ClosestPoint:
        return "closest-point";
    }
    return "?";
}

const char* stoppingName(gjk::StoppingRule r)
{
    switch (r)
    {
    case gjk::StoppingRule::RepeatedSupport:
        return "repeated-support";
    case gjk::StoppingRule::DualityGap:
        return "duality-gap";
    }
    return "?";
}

const char* frameName(gjk::Frame f)
{
    switch (f)
    {
    case gjk::Frame::LocalA:
        return "local-a";
    case gjk::Frame::World:
        return "world";
    }
    return "?";
}

const char* supportName(gjk::SupportStrategy s)
{
    switch (s)
    {
    case gjk::SupportStrategy::Linear:
        return "linear";
    case gjk::SupportStrategy::BinarySearch:
        return "binary-search";
    }
    return "?";
}

Json optionsJson(const gjk::Options& o)
{
    Json j;
    j["direction"] = directionName(o.direction);
    j["stopping"] = stoppingName(o.stopping);
    j["frame"] = frameName(o.frame);
    j["support"] = supportName(o.support);
    j["certified"] = o.certify;
    j["max_iterations"] = o.maxIterations;
    j["use_radii"] = o.useRadii;
    return j;
}

} // namespace gjkval
