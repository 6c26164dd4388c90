// Contracts (implementations/contract.hpp): names, gjk2d's own, the checks of a declared one, and
// report.json's form.
#include "implementations/contract.hpp"

#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <cmath>

namespace gjkval
{

namespace
{
constexpr const char* kOverlapNames[kOverlapKinds] = {"common-point", "zero", "midpoint",
                                                      "penetration", "perimeter"};
static_assert(int(Overlap::CommonPoint) == GJK2D_OVERLAP_COMMON_POINT &&
              int(Overlap::Zero) == GJK2D_OVERLAP_ZERO &&
              int(Overlap::Midpoint) == GJK2D_OVERLAP_MIDPOINT &&
              int(Overlap::Penetration) == GJK2D_OVERLAP_PENETRATION &&
              int(Overlap::Perimeter) == GJK2D_OVERLAP_PERIMETER);

Json orNull(double tolerance)
{
    return tolerance >= 0 ? Json(tolerance) : Json(nullptr);
}
} // namespace

const char* overlapName(Overlap o)
{
    return kOverlapNames[int(o)];
}

bool parseOverlap(const std::string& word, Overlap& out)
{
    for (int k = 0; k < kOverlapKinds; ++k)
        if (word == kOverlapNames[k])
        {
            out = Overlap(k);
            return true;
        }
    return false;
}

const char* inputFormName(InputForm f)
{
    return f == InputForm::World ? "world" : "case";
}

std::string givenInput(const VariantInfo& v)
{
    const Contract& c = contractOf(v);
    if (c.input == InputForm::Case)
        return "the case as given";
    return fmt::format("world points {} ({})",
                       v.scalar == Scalar::Float ? "rounded to float" : "in double", c.inputSource);
}

Contract ownContract(const gjk::Options& options)
{
    Contract c;
    c.own = true;
    c.overlap = options.signedDistance ? Overlap::Penetration : Overlap::CommonPoint;
    c.toleranceSource = "gjk2d's a-priori bound (docs/error-bound.md)";
    c.overlapSource = options.signedDistance ? "gjk2d/types.hpp, Options::signedDistance"
                                             : "gjk2d/distance.hpp, DistanceOutput";
    return c;
}

std::string checkContract(const Contract& c)
{
    if (int(c.overlap) < 0 || int(c.overlap) >= kOverlapKinds)
        return fmt::format("overlap {} is not a gjk2d_overlap (0..{})", int(c.overlap),
                           kOverlapKinds - 1);
    if (std::isnan(c.absTolerance) || std::isnan(c.relTolerance) || std::isinf(c.absTolerance) ||
        std::isinf(c.relTolerance))
        return "a distance tolerance is not finite (negative: none stated)";
    if (!std::isfinite(c.margin) || c.margin < 0)
        return fmt::format("margin {} is not a finite number >= 0", c.margin);
    if (!std::isfinite(c.depthAbsTolerance) || !std::isfinite(c.depthRelTolerance))
        return "a depth tolerance is not finite (negative: none stated)";
    if (c.statesDepthTolerance() && c.overlap != Overlap::Penetration)
        return fmt::format("a depth tolerance is stated, but the overlap is {}, which answers no "
                           "depth (only penetration does)",
                           overlapName(c.overlap));
    return "";
}

const Contract& contractOf(const VariantInfo& v)
{
    static const Contract own = ownContract(), ownSigned = ownContract({.signedDistance = true});
    if (v.plugin)
        return v.plugin->contract;
    return v.options.signedDistance ? ownSigned : own;
}

std::string judgedBy(const VariantInfo& v)
{
    const Contract& c = contractOf(v);
    if (c.own)
        return fmt::format("gjk2d's own contract: gjk2d's bound for {}", scalarName(v.scalar));
    if (!c.statesTolerance())
        return fmt::format("no tolerance stated: gjk2d's bound for {}", scalarName(v.scalar));
    return fmt::format("its stated tolerance: abs {}, rel {} ({})",
                       c.absTolerance >= 0 ? fmt::format("{:g}", c.absTolerance) : "none",
                       c.relTolerance >= 0 ? fmt::format("{:g}", c.relTolerance) : "none",
                       c.toleranceSource);
}

std::string judgedByDepth(const VariantInfo& v)
{
    const Contract& c = contractOf(v);
    if (c.overlap != Overlap::Penetration)
        return fmt::format("no depth answered (overlap {})", overlapName(c.overlap));
    if (c.own)
        return fmt::format("gjk2d's own contract: gjk2d's depth bound for {}",
                           scalarName(v.scalar));
    if (!c.statesDepthTolerance())
        return fmt::format("no depth tolerance stated: gjk2d's depth bound for {}",
                           scalarName(v.scalar));
    return fmt::format("its stated tolerance: abs {}, rel {} ({})",
                       c.depthAbsTolerance >= 0 ? fmt::format("{:g}", c.depthAbsTolerance) : "none",
                       c.depthRelTolerance >= 0 ? fmt::format("{:g}", c.depthRelTolerance) : "none",
                       c.depthSource);
}

Json contractJson(const VariantInfo& v)
{
    const Contract& c = contractOf(v);
    return Json{{"own", c.own},
                {"overlap", overlapName(c.overlap)},
                {"overlap_source", c.overlapSource},
                {"tolerance",
                 {{"abs", orNull(c.absTolerance)},
                  {"rel", orNull(c.relTolerance)},
                  {"source", c.toleranceSource}}},
                {"margin", c.margin},
                {"margin_source", c.marginSource},
                {"depth",
                 {{"abs", orNull(c.depthAbsTolerance)},
                  {"rel", orNull(c.depthRelTolerance)},
                  {"source", c.depthSource}}},
                {"input", {{"form", inputFormName(c.input)}, {"source", c.inputSource}}},
                {"judged_by", judgedBy(v)},
                {"judged_by_depth", judgedByDepth(v)}};
}

} // namespace gjkval
