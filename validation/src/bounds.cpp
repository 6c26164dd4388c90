#include "bounds.hpp"

#include <fmt/format.h>

namespace gjkval
{

double errorBound(const VariantInfo& /*variant*/, const CaseMetrics& m)
{
    return kBoundConstant * m.unitRoundoff * m.R;
}

std::string boundFormula(const VariantInfo& /*variant*/)
{
    return fmt::format("{:g} * u * R (provisional; R = max|coord of A| + max|coord of B| + rA + rB "
                       "in the compute frame)",
                       kBoundConstant);
}

} // namespace gjkval
