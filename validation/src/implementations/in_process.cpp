// Implementations that answer in this process from a registered callback (the Python package's
// gjk2d.validate): called in this thread, every exception counted against its case.
#include "implementations/in_process.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>

namespace gjkval
{
namespace
{
// A task the callback failed on: an error, its message the detail; the variant's first error also
// gets a line on stderr (every one is counted in the report: plugin_errors, failures).
void recordError(const PluginTask& t, InProcessCalls& calls, const std::string& what)
{
    t.out->status = PluginStatus::Error;
    t.out->detail = what;
    if (calls.toldFirstError)
        return;
    calls.toldFirstError = true;
    std::fprintf(stderr,
                 "gjk-validate: in-process variant '%s' (%s) raised on case '%s': %s; counted as "
                 "an error, the other cases go on (this line is printed for its first error "
                 "only)\n",
                 t.v->name.c_str(), t.v->plugin->path.c_str(),
                 t.caseName ? t.caseName->c_str() : "?", what.c_str());
}

void answerEach(const std::vector<PluginTask>& tasks, InProcessCalls& calls)
{
    for (const PluginTask& t : tasks)
    {
        ExternalAnswer a;
        try
        {
            calls.perCase(*t.p, a);
        }
        catch (const std::exception& e)
        {
            recordError(t, calls, e.what());
            continue;
        }
        a.status = PluginStatus::Ok;
        a.detail.clear();
        *t.out = std::move(a);
    }
}

void answerBatch(const std::vector<PluginTask>& tasks, InProcessCalls& calls)
{
    std::vector<const PreparedCase*> cases;
    for (const PluginTask& t : tasks)
        cases.push_back(t.p);
    std::vector<ExternalAnswer> out(tasks.size());
    std::string error;
    try
    {
        calls.perBatch(cases, out);
        if (out.size() != tasks.size())
            error = fmt::format("the batch call answered {} cases of {}", out.size(), tasks.size());
    }
    catch (const std::exception& e)
    {
        error = e.what();
    }
    for (std::size_t i = 0; i < tasks.size(); ++i)
        if (!error.empty())
            recordError(tasks[i], calls, error);
        else
        {
            out[i].status = PluginStatus::Ok;
            out[i].detail.clear();
            *tasks[i].out = std::move(out[i]);
        }
}
} // namespace

void answerInProcess(const std::vector<PluginTask>& tasks)
{
    // The tasks of each variant, in their order (a batch callback gets them in one call).
    std::vector<const VariantInfo*> order;
    for (const PluginTask& t : tasks)
        if (std::find(order.begin(), order.end(), t.v) == order.end())
            order.push_back(t.v);
    for (const VariantInfo* v : order)
    {
        std::vector<PluginTask> own;
        for (const PluginTask& t : tasks)
            if (t.v == v)
                own.push_back(t);
        InProcessCalls* calls = v->plugin->calls.get();
        if (calls == nullptr || (!calls->perCase && !calls->perBatch))
            throw std::logic_error(fmt::format(
                "in-process variant '{}' runs without its callback (released, not registered "
                "again)",
                v->name));
        if (calls->perBatch)
            answerBatch(own, *calls);
        else
            answerEach(own, *calls);
    }
}

} // namespace gjkval
