// A case as JSON: the per-case line of cases.jsonl and the CaseDetail of a worst case
// (docs/report-schema.md, "CaseDetail"), with each gjk2d variant's iteration trace, run again.
#include "evaluate/evaluate.hpp"

#include "inputs/geometry.hpp"

#include <fmt/format.h>

namespace gjkval
{
namespace
{

Json exactJson(const exact::Result& r)
{
    Json j;
    j["distance"] = num(r.distance);
    j["squared"] = r.squaredNum + "/" + r.squaredDen;
    j["overlap"] = r.overlap;
    return j;
}

Json shapeDetail(const ShapeIn& s)
{
    Json j;
    Json pts = Json::array();
    for (const auto& p : s.points)
        pts.push_back(pt(p[0], p[1]));
    j["points"] = std::move(pts);
    j["radius"] = num(s.radius);
    j["transform"] = {{"p", pt(s.px, s.py)}, {"q", pt(s.c, s.s)}};
    Json w = Json::array();
    for (const auto& p : worldPoints(s))
        w.push_back(pt(p[0], p[1]));
    j["world"] = std::move(w);
    return j;
}

template <class T> Json traceJson(const gjk::Trace<T>& tr)
{
    const gjk::Transform<double> f{{double(tr.frame.p.x), double(tr.frame.p.y)},
                                   {double(tr.frame.q.c), double(tr.frame.q.s)}};
    // A rescaled query's trace is in the scaled compute frame (Trace::scaleExponent).
    const int e = -tr.scaleExponent;
    auto point = [&f, e](gjk::Vec2<T> v)
    {
        const auto w = gjk::transformPoint(
            f, gjk::Vec2<double>{std::ldexp(double(v.x), e), std::ldexp(double(v.y), e)});
        return pt(w.x, w.y);
    };
    auto vec = [&f, e](gjk::Vec2<T> v)
    {
        const auto w = gjk::rotate(
            f.q, gjk::Vec2<double>{std::ldexp(double(v.x), e), std::ldexp(double(v.y), e)});
        return pt(w.x, w.y);
    };
    auto vertex = [&](const gjk::SimplexVertex<T>& sv, bool withWeight)
    {
        Json j;
        j["w"] = vec(sv.w);
        j["wA"] = point(sv.wA);
        j["wB"] = point(sv.wB);
        if (withWeight)
            j["a"] = num(double(sv.a));
        j["iA"] = sv.indexA;
        j["iB"] = sv.indexB;
        return j;
    };
    Json steps = Json::array();
    for (const auto& s : tr.steps)
    {
        Json j;
        Json simplex = Json::array();
        for (int i = 0; i < s.simplex.count; ++i)
            simplex.push_back(vertex(s.simplex.v[i], true));
        j["simplex"] = std::move(simplex);
        j["closest"] = vec(s.closest);
        j["direction"] = vec(s.direction);
        j["support"] = s.hasSupport ? vertex(s.support, false) : Json(nullptr);
        steps.push_back(std::move(j));
    }
    return steps;
}

template <class T> Json tracedRun(const Case& c, const VariantInfo& v, gjk::DistanceOutput<T>& out)
{
    const PreparedCase p = prepare(c);
    gjk::Trace<T> tr;
    out = query<T>(p, v, &tr);
    return traceJson(tr);
}

} // namespace

namespace
{
// The exact result as the case JSON gives it (CaseDetail and cases.jsonl alike).
Json exactDetail(const exact::Result& r)
{
    Json e = exactJson(r);
    e["witnessA"] = pt(r.witnessA.x, r.witnessA.y);
    e["witnessB"] = pt(r.witnessB.x, r.witnessB.y);
    e["lower"] = num(r.lower);
    e["upper"] = num(r.upper);
    if (r.hasSigned) // a run that judges a penetration depth (EvalContext::truthOptions)
    {
        e["signed_distance"] = num(r.signedDistance);
        e["signed_lower"] = num(r.signedLower);
        e["signed_upper"] = num(r.signedUpper);
        e["penetrationA"] = pt(r.penetrationA.x, r.penetrationA.y);
        e["penetrationB"] = pt(r.penetrationB.x, r.penetrationB.y);
    }
    return e;
}

// The answer's verdict by its implementation's contract: its class, the violation's reason and
// size, and the tolerances it was held to (docs/report-schema.md, CaseDetail "contract").
Json contractVerdictJson(const VariantInfo& vi, const VariantOutcome& v)
{
    const char* why = violationName(v.violation);
    return Json{{"own", contractOf(vi).own},
                {"class", answerClassName(v)},
                {"violation", why ? Json(why) : Json(nullptr)},
                {"excess", why ? num(v.violationExcess) : Json(nullptr)},
                {"tolerance", num(v.tolerance)},
                {"witness_tolerance", num(v.witnessTolerance)}};
}

// A penetration answer's depth on overlapping shapes (docs/report-schema.md, CaseDetail
// "penetration"): the exact signed distance, the answer's, its errors, gjk2d's depth bound and
// what the contract holds the depth to.
Json penetrationJson(const VariantOutcome& v)
{
    return Json{{"exact", num(v.signedTruth)},
                {"distance", num(v.distance)},
                {"abs", num(v.depthAbs)},
                {"rel", num(v.depthRel)},
                {"bound", num(v.depthBound)},
                {"bound_ratio", num(v.depthRatio)},
                {"tolerance", num(v.depthTolerance)},
                {"beyond_bound", v.beyondDepthBound}};
}

// One variant's result on a case, as the case JSON gives it (CaseDetail adds the trace).
Json variantResultJson(const VariantInfo& vi, const VariantOutcome& v)
{
    Json vj;
    vj["type"] = scalarName(vi.scalar);
    if (v.skipped)
    {
        vj["skipped"] = v.skipWhy ? v.skipWhy : kSkipNotRepresentable;
        return vj;
    }
    if (v.plugin != PluginStatus::NotRun && v.plugin != PluginStatus::Ok)
    {
        vj["plugin_status"] = pluginStatusName(v.plugin);
        vj["plugin_detail"] = v.pluginDetail;
        vj["failed"] = v.failed;
        vj["contract"] = contractVerdictJson(vi, v);
        return vj;
    }
    vj["distance"] = num(v.distance);
    vj["pointA"] = pt(v.pointA[0], v.pointA[1]);
    vj["pointB"] = pt(v.pointB[0], v.pointB[1]);
    vj["normal"] = pt(v.normal[0], v.normal[1]);
    vj["iterations"] = v.iterations;
    vj["stop"] = vi.plugin ? "plugin" : gjk::stopReasonName(v.stop); // a plugin gives no reason
    // The key of the truth it was judged on; a variant given world points, its world case's.
    vj["truth"] = v.worldInput ? fmt::format("world_input.{}.exact", scalarName(vi.scalar))
                  : vi.scalar == Scalar::Float ? "exact_float_input"
                                               : "exact";
    if (v.worldInput) // given the world case, not the case (the detail's world_input)
        vj["input"] = "world";
    vj["R"] = num(v.R);
    vj["bound"] = num(v.bound);
    vj["witness_bound"] = num(v.witnessBound);
    vj["errors"] = {{"abs", num(v.abs)},
                    {"rel", optNum(v.rel)},
                    {"ulps", optNum(v.ulps)},
                    {"normalized", num(v.normalized)},
                    {"bound_ratio", num(v.boundRatio)},
                    {"witness", optNum(v.witness)},
                    {"witness_gap", num(v.witnessGap)},
                    {"witness_ratio", optNum(v.witnessRatio)}};
    const char* mis = misclassName(v.mis);
    vj["misclassified"] = mis ? Json(mis) : Json(nullptr);
    const char* invalid = invalidName(v.invalid);
    vj["invalid"] = invalid ? Json(invalid) : Json(nullptr);
    vj["out_of_range"] = v.outOfRange;
    if (vi.options.correctlyRounded)
    {
        vj["path"] = gjk::correctPathName(v.path);
        vj["bit_mismatch"] = v.bitMismatch;
    }
    if (vi.options.certify || vi.options.signedDistance) // the expansion certifies the depth
    {
        vj["certified"] = v.certified;
        vj["lower"] = num(v.lower);
        vj["upper"] = num(v.upper);
        vj["interval_contains"] = v.intervalContains;
    }
    if (v.depthJudged)
        vj["penetration"] = penetrationJson(v);
    vj["failed"] = v.failed;
    vj["contract"] = contractVerdictJson(vi, v);
    return vj;
}

} // namespace

namespace
{
// The exact result of a case detail, with its squared rational: the campaign leaves it out where
// the filter decided (exact::Options::squaredRational), so it is asked for here, for the few
// cases whose details are written (the filter is deterministic: the same result, bit for bit).
Json truthDetail(const Case& c, const EvalContext& ctx, const exact::Result& r, bool floatInput)
{
    if (!r.squaredNum.empty())
        return exactDetail(r);
    exact::Options o = ctx.truthOptions();
    o.squaredRational = true;
    const exact::PreparedShape a(toExact(c.a, floatInput), "shape A");
    const exact::PreparedShape b(toExact(c.b, floatInput), "shape B");
    return exactDetail(ctx.truth(a, b, o));
}
} // namespace

// A cases.jsonl line, and what a CaseDetail starts from: name, family, and either the reason the
// case was rejected or the exact results and each variant's result.
Json perCaseJson(const Case& c, const std::string& family, const EvalContext& ctx,
                 const CaseOutcome& o)
{
    Json j;
    j["name"] = c.name;
    j["family"] = family;
    if (!o.rejected.empty())
    {
        j["rejected"] = o.rejected;
        return j;
    }
    j["exact"] = truthDetail(c, ctx, o.exact, false);
    if (o.hasFloatTruth)
    {
        j["exact_float_input"] = truthDetail(c, ctx, o.exactFloat, true);
        j["input_rounding"] = num(o.inputRounding);
    }
    for (const bool isFloat : {false, true}) // the world cases variants were given, with truths
        if (const auto& w = o.world[isFloat ? 1 : 0])
            j["world_input"][isFloat ? "float" : "double"] = {
                {"exact", truthDetail(w->c, ctx, w->exact, false)},
                {"input_rounding", num(w->inputRounding)}};
    Json vs = Json::object();
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
        vs[ctx.variants[k]->name] = variantResultJson(*ctx.variants[k], o.variants[k]);
    j["variants"] = std::move(vs);
    return j;
}

Json caseDetail(const Case& c, const std::string& family, const EvalContext& ctx,
                const CaseOutcome& o, const std::string& worstBy)
{
    Json j = perCaseJson(c, family, ctx, o);
    j["worst_by"] = worstBy;
    if (!c.source.empty())
        j["source"] = c.source;
    if (!c.comment.empty())
        j["comment"] = c.comment;
    j["a"] = shapeDetail(c.a);
    j["b"] = shapeDetail(c.b);
    Json mk = Json::array();
    for (const auto& p : minkowskiDifference(worldPoints(c.a), worldPoints(c.b)))
        mk.push_back(pt(p[0], p[1]));
    j["minkowski"] = std::move(mk);
    if (!o.rejected.empty())
        return j;
    for (const bool isFloat : {false, true}) // the shapes those variants were given
        if (const auto& w = o.world[isFloat ? 1 : 0])
        {
            Json& wj = j["world_input"][isFloat ? "float" : "double"];
            wj["a"] = shapeDetail(w->c.a);
            wj["b"] = shapeDetail(w->c.b);
        }
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        const VariantInfo& vi = *ctx.variants[k];
        if (o.variants[k].skipped)
            continue;
        Json& vj = j["variants"][vi.name];
        vj["contract"]["judged_by"] = judgedBy(vi); // what the distance was held to, in words
        if (vi.plugin)                              // a plugin gives no trace
            continue;
        if (vi.scalar == Scalar::Float)
        {
            gjk::DistanceOutput<float> out;
            vj["trace"] = tracedRun<float>(c, vi, out);
        }
        else
        {
            gjk::DistanceOutput<double> out;
            vj["trace"] = tracedRun<double>(c, vi, out);
        }
    }
    return j;
}

} // namespace gjkval
