// gjk2d's variants: the table from a stable name to a scalar type and gjk::Options, their
// parsing from the command line, and the scalar types' constants.
#include "implementations/variants.hpp"

#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <limits>

namespace gjkval
{

// A data table, one row per variant: long, and kept whole so that the variants read side by side.
const std::vector<VariantInfo>& variantTable()
{
    using gjk::Options;
    using D = gjk::SearchDirection;
    using S = gjk::StoppingRule;
    using F = gjk::Frame;
    using P = gjk::SupportStrategy;
    static const std::vector<VariantInfo> table = {
        {.name = "double",
         .scalar = Scalar::Double,
         .options = gjk::referenceOptions,
         .description = "reference options (talk's edge-perpendicular direction, repeated-support "
                        "stop, A's local frame)",
         .judged = true,
         .start = Start::Cold},
        {.name = "float",
         .scalar = Scalar::Float,
         .options = gjk::referenceOptions,
         .description = "reference options in single precision",
         .judged = true,
         .start = Start::Cold},
        {.name = "double-closest-point",
         .scalar = Scalar::Double,
         .options = Options{.direction = D::ClosestPoint},
         .description = "naive search direction d = -P (talk: inaccurate on long edges)",
         .judged = false,
         .start = Start::Cold},
        {.name = "double-world-frame",
         .scalar = Scalar::Double,
         .options = Options{.frame = F::World},
         .description = "compute in world coordinates (loses small gaps far from the origin)",
         .judged = false,
         .start = Start::Cold},
        {.name = "double-duality-gap",
         .scalar = Scalar::Double,
         .options = Options{.stopping = S::DualityGap},
         .description = "also stop on the duality gap",
         .judged = false,
         .start = Start::Cold},
        {.name = "float-closest-point",
         .scalar = Scalar::Float,
         .options = Options{.direction = D::ClosestPoint},
         .description = "naive search direction in single precision",
         .judged = false,
         .start = Start::Cold},
        {.name = "float-world-frame",
         .scalar = Scalar::Float,
         .options = Options{.frame = F::World},
         .description = "world-frame computation in single precision",
         .judged = false,
         .start = Start::Cold},
        {.name = "double-certified",
         .scalar = Scalar::Double,
         .options = Options{.certify = true},
         .description = "reference options plus a certified interval [lower, upper]",
         .judged = true,
         .start = Start::Cold},
        {.name = "float-certified",
         .scalar = Scalar::Float,
         .options = Options{.certify = true},
         .description = "certified interval in single precision",
         .judged = true,
         .start = Start::Cold},
        {.name = "double-correct",
         .scalar = Scalar::Double,
         .options = Options{.correctlyRounded = true},
         .description = "correctly rounded distance (gjk/correct.hpp; undecided queries completed "
                        "exactly): judged with zero tolerance",
         .judged = true,
         .start = Start::Cold},
        {.name = "double-binary-support",
         .scalar = Scalar::Double,
         .options = Options{.support = P::BinarySearch},
         .description = "reference options with the O(log n) binary-search support (shapes in "
                        "convex order only)",
         .judged = true,
         .start = Start::Cold},
        {.name = "float-binary-support",
         .scalar = Scalar::Float,
         .options = Options{.support = P::BinarySearch},
         .description = "binary-search support in single precision (shapes in convex order only)",
         .judged = true,
         .start = Start::Cold},
        {.name = "double-warm",
         .scalar = Scalar::Double,
         .options = gjk::referenceOptions,
         .description =
             "reference options, warm-started: the query repeated with the cache of the first",
         .judged = true,
         .start = Start::Warm},
        {.name = "float-warm",
         .scalar = Scalar::Float,
         .options = gjk::referenceOptions,
         .description = "warm-started reference options in single precision",
         .judged = true,
         .start = Start::Warm},
        {.name = "double-every-start",
         .scalar = Scalar::Double,
         .options = gjk::referenceOptions,
         .description = "reference options started from every initial vertex pair and several "
                        "multi-vertex caches; the worst answer is judged",
         .judged = true,
         .start = Start::EveryStart},
        {.name = "float-every-start",
         .scalar = Scalar::Float,
         .options = gjk::referenceOptions,
         .description = "every start in single precision",
         .judged = true,
         .start = Start::EveryStart},
        {.name = "double-signed",
         .scalar = Scalar::Double,
         .options = Options{.signedDistance = true},
         .description = "reference options plus the signed distance: minus the penetration depth "
                        "on overlap (EPA, gjk2d/expand.hpp), judged against the exact depth",
         .judged = true,
         .start = Start::Cold},
        {.name = "float-signed",
         .scalar = Scalar::Float,
         .options = Options{.signedDistance = true},
         .description = "signed distance in single precision",
         .judged = true,
         .start = Start::Cold},
        {.name = "double-batch",
         .scalar = Scalar::Double,
         .options = gjk::referenceOptions,
         .description =
             "reference options through gjk::distanceBatch (SIMD lanes): bit for bit double",
         .judged = true,
         .start = Start::Cold,
         .batch = true},
        {.name = "float-batch",
         .scalar = Scalar::Float,
         .options = gjk::referenceOptions,
         .description =
             "reference options through gjk::distanceBatch in single precision: bit for bit float",
         .judged = true,
         .start = Start::Cold,
         .batch = true},
    };
    return table;
}

const VariantInfo* findVariant(const std::string& name)
{
    for (const auto& v : variantTable())
        if (v.name == name)
            return &v;
    return findPluginVariant(name);
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

bool hasPreparedForm(const VariantInfo& v)
{
    return v.plugin == nullptr && !v.batch && v.options == gjk::referenceOptions;
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

Json optionsJson(const gjk::Options& o)
{
    Json j;
    j["direction"] = gjk::searchDirectionName(o.direction);
    j["stopping"] = gjk::stoppingRuleName(o.stopping);
    j["frame"] = gjk::frameName(o.frame);
    j["support"] = gjk::supportStrategyName(o.support);
    j["certified"] = o.certify;
    j["max_iterations"] = o.maxIterations;
    j["use_radii"] = o.useRadii;
    j["correctly_rounded"] = o.correctlyRounded;
    j["signed_distance"] = o.signedDistance;
    return j;
}

} // namespace gjkval
