// The GJK variants the runner knows: one table (variants.cpp) from a stable name to a scalar type
// and a gjk::Options. Adding a variant is one line in that table.
#pragma once

#include "common.hpp"

#include "gjk/distance.hpp"

#include <string>
#include <vector>

namespace gjkval
{

enum class Scalar
{
    Float,
    Double
};

struct VariantInfo
{
    std::string name; // stable: used on the command line and in every report
    Scalar scalar;
    gjk::Options options;
    std::string description;
};

const std::vector<VariantInfo>& variantTable();
// The default of `run --variants`.
inline constexpr const char* kDefaultVariants = "double,float";
// "all", or names separated by commas. Throws InputError naming the unknown one.
std::vector<const VariantInfo*> parseVariants(const std::string& list);
const VariantInfo* findVariant(const std::string& name);

const char* scalarName(Scalar s);
double unitRoundoff(Scalar s); // u = eps / 2 of the variant's type
int scalarDigits(Scalar s);    // significand bits (24, 53)
int scalarMinExponent(Scalar s);

// {"direction": ..., "stopping": ..., "frame": ..., "support": ..., "certified": ...}
Json optionsJson(const gjk::Options& o);
const char* directionName(gjk::SearchDirection d);
const char* stoppingName(gjk::StoppingRule r);
const char* frameName(gjk::Frame f);
const char* supportName(gjk::SupportStrategy s);

} // namespace gjkval
